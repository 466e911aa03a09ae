//! Ctrl-C (SIGINT) and SIGTERM end a run after its current step, with the
//! results up to that step written and `interrupted: true` in summary.json
//! (exit 130 or 143, 128 plus the signal's number, as a shell reports a
//! process killed by it).
//!
//! The handler only records the signal; runs poll [`received`] after every
//! step through their [`Cancel`]. It is installed with `SA_RESETHAND`, so a
//! second Ctrl-C ends the process at once the default way: the output
//! folder then keeps its previous complete set ([`crate::output::ResultFolder`]).

use crate::run::Cancel;
use std::sync::atomic::{AtomicI32, Ordering};
use std::sync::Arc;

/// The signal received, 0 for none.
static RECEIVED: AtomicI32 = AtomicI32::new(0);

#[cfg(unix)]
extern "C" fn record(signal: libc::c_int) {
    // Only an atomic store: async-signal-safe.
    RECEIVED.store(signal, Ordering::SeqCst);
}

/// Installs the handler for SIGINT and SIGTERM (the `stancf` binary does;
/// a library user such as the Python package keeps its own).
#[cfg(unix)]
pub fn install() {
    for signal in [libc::SIGINT, libc::SIGTERM] {
        // SAFETY: a zeroed sigaction is valid; the handler is an
        // `extern "C" fn(c_int)` that only stores to an atomic.
        unsafe {
            let mut action: libc::sigaction = std::mem::zeroed();
            action.sa_sigaction = record as extern "C" fn(libc::c_int) as libc::sighandler_t;
            action.sa_flags = libc::SA_RESETHAND | libc::SA_RESTART;
            libc::sigemptyset(&mut action.sa_mask);
            libc::sigaction(signal, &action, std::ptr::null_mut());
        }
    }
}

#[cfg(not(unix))]
pub fn install() {}

/// The signal that asked the process to stop, if one did.
pub fn received() -> Option<i32> {
    match RECEIVED.load(Ordering::SeqCst) {
        0 => None,
        s => Some(s),
    }
}

/// A [`Cancel`] that stops a run once a signal came.
pub fn cancel() -> Cancel {
    Cancel(Arc::new(|| received().is_some()))
}

/// The exit code of a run stopped by a signal: 128 + its number (130 for
/// SIGINT, 143 for SIGTERM); 130 when stopped otherwise.
pub fn exit_code() -> u8 {
    received().map_or(130, |s| (128 + s).clamp(0, 255) as u8)
}
