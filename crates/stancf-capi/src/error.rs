//! Errors across the C boundary (docs/interface.md, "C library"): every
//! call returns a code, keeps its message for `stancf_error_message`
//! (per thread) and never unwinds into C: a panic is caught and becomes
//! `STANCF_UNHANDLED_ERROR` with its message.

use std::cell::RefCell;
use std::ffi::{c_char, c_int, CString};
use std::panic::{catch_unwind, AssertUnwindSafe};

/// Success.
pub const STANCF_SUCCESS: c_int = 0;
/// The scenario or deck cannot be read or is not valid (MoorDyn's
/// `MOORDYN_INVALID_INPUT_FILE`).
pub const STANCF_INVALID_INPUT_FILE: c_int = -1;
/// A call that cannot be made: a NULL pointer, a handle closed or freed
/// already or not from `stancf_create` / `stancf_save`, a line, node or
/// point that does not exist, a step before `stancf_init`, a time that is
/// not the time reached (MoorDyn's `MOORDYN_INVALID_INPUT`).
pub const STANCF_INVALID_INPUT: c_int = -3;
/// The solver did not converge; the message gives time, step and
/// residual, and the system stays at its last converged step (MoorDyn's
/// `MOORDYN_NAN_ERROR`: a numerical failure).
pub const STANCF_NUMERICAL_ERROR: c_int = -4;
/// A value the system refuses, untouched: a wrong number of coupled DOFs,
/// a value that is not finite, a state saved from another system, an
/// interval of more internal steps than the handle's bound (MoorDyn's
/// `MOORDYN_INVALID_VALUE`).
pub const STANCF_INVALID_VALUE: c_int = -6;
/// A panic inside the library, caught at the boundary; the handle of the
/// call is unusable from then on, but can be closed (MoorDyn's
/// `MOORDYN_UNHANDLED_ERROR`).
pub const STANCF_UNHANDLED_ERROR: c_int = -255;

/// An error: its code and message.
#[derive(Debug)]
pub struct Error {
    pub code: c_int,
    pub message: String,
}

impl Error {
    pub fn new(code: c_int, message: impl Into<String>) -> Self {
        Error {
            code,
            message: message.into(),
        }
    }

    pub fn input(message: impl Into<String>) -> Self {
        Error::new(STANCF_INVALID_INPUT, message)
    }
}

impl From<stancf::coupling::CouplingError> for Error {
    fn from(e: stancf::coupling::CouplingError) -> Self {
        use stancf::coupling::CouplingError;
        let code = match e {
            CouplingError::Input(_) => STANCF_INVALID_VALUE,
            CouplingError::Solver(_) => STANCF_NUMERICAL_ERROR,
            // The C library never asks a call to stop: one that stopped
            // is a bug of the library.
            CouplingError::Interrupted { .. } => STANCF_UNHANDLED_ERROR,
        };
        Error::new(code, e.to_string())
    }
}

thread_local! {
    static LAST: RefCell<CString> = RefCell::new(CString::default());
}

/// Keeps `message` as this thread's last error (interior NUL bytes, which
/// C cannot show, become spaces).
pub fn set_message(message: &str) {
    let clean = CString::new(message.replace('\0', " ")).expect("no NUL left");
    LAST.with(|m| *m.borrow_mut() = clean);
}

/// This thread's last error message (valid until its next call that
/// fails).
pub fn message_ptr() -> *const c_char {
    LAST.with(|m| m.borrow().as_ptr())
}

/// The message of a caught panic.
fn panic_message(payload: &(dyn std::any::Any + Send)) -> String {
    let what = payload
        .downcast_ref::<&str>()
        .map(|s| s.to_string())
        .or_else(|| payload.downcast_ref::<String>().cloned())
        .unwrap_or_else(|| "unknown panic".into());
    format!("internal error (please report): {what}")
}

/// Runs a call's body: its error or panic becomes a code and this
/// thread's message; success is `STANCF_SUCCESS`.
pub fn guard(body: impl FnOnce() -> Result<(), Error>) -> c_int {
    match catch_unwind(AssertUnwindSafe(body)) {
        Ok(Ok(())) => STANCF_SUCCESS,
        Ok(Err(e)) => {
            set_message(&e.message);
            e.code
        }
        Err(payload) => {
            set_message(&panic_message(payload.as_ref()));
            STANCF_UNHANDLED_ERROR
        }
    }
}

/// [`guard`] for a call that returns a pointer: NULL on error or panic.
pub fn guard_ptr<T>(body: impl FnOnce() -> Result<*mut T, Error>) -> *mut T {
    match catch_unwind(AssertUnwindSafe(body)) {
        Ok(Ok(p)) => p,
        Ok(Err(e)) => {
            set_message(&e.message);
            std::ptr::null_mut()
        }
        Err(payload) => {
            set_message(&panic_message(payload.as_ref()));
            std::ptr::null_mut()
        }
    }
}
