//! The handles C holds (docs/interface.md, "C library"): the pointers
//! `stancf_create` and `stancf_save` return are tokens, never
//! dereferenced. A registry maps the live ones to their systems and
//! states, so a closed, freed or made-up handle is refused with a message
//! instead of a read of freed memory, and a handle closed twice is
//! refused the second time.
//!
//! A token is `TOKEN_BASE` plus 16 times a number drawn once from a
//! counter shared by systems and states: never reused, so a stale handle
//! never reaches a newer system, and a state's token is never a system's.
//! A system is locked for each call: calls on one handle from several
//! threads wait for each other.

use crate::error::{Error, STANCF_UNHANDLED_ERROR};
use std::collections::BTreeMap;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::{Arc, Mutex, MutexGuard, PoisonError};

/// Where tokens start: in a 64-bit process, high bits that no address
/// has (x86-64 and AArch64 addresses have at most 57 significant bits),
/// so a stray pointer is never taken for a handle.
const TOKEN_BASE: usize = if usize::BITS == 64 {
    0x5354_0000_0000_0000_u64 as usize
} else {
    0x5354_0000
};

/// The number of the next token.
static NEXT: AtomicUsize = AtomicUsize::new(1);

/// A token never handed out before.
fn new_token() -> Result<usize, Error> {
    let n = NEXT.fetch_add(1, Ordering::Relaxed);
    n.checked_mul(16)
        .and_then(|offset| TOKEN_BASE.checked_add(offset))
        .ok_or_else(|| {
            Error::input("this process has opened more handles than can be numbered; restart it")
        })
}

/// The live objects of one kind, by token.
pub struct Registry<T> {
    live: Mutex<BTreeMap<usize, Arc<T>>>,
}

impl<T> Registry<T> {
    pub const fn new() -> Self {
        Registry {
            live: Mutex::new(BTreeMap::new()),
        }
    }

    /// The map; a panic elsewhere cannot leave it half changed (each
    /// change is one call of the map), so a poisoned lock is taken as is.
    fn map(&self) -> MutexGuard<'_, BTreeMap<usize, Arc<T>>> {
        self.live.lock().unwrap_or_else(PoisonError::into_inner)
    }

    /// Registers `value` under a new token.
    pub fn insert(&self, value: T) -> Result<usize, Error> {
        let token = new_token()?;
        self.map().insert(token, Arc::new(value));
        Ok(token)
    }

    /// The object of a live token.
    pub fn get(&self, token: usize) -> Option<Arc<T>> {
        self.map().get(&token).cloned()
    }

    /// Takes the object of a live token out (dropped when the last call
    /// using it ends).
    pub fn remove(&self, token: usize) -> Option<Arc<T>> {
        self.map().remove(&token)
    }

    /// Whether a token is live here.
    pub fn contains(&self, token: usize) -> bool {
        self.map().contains_key(&token)
    }
}

impl<T> Default for Registry<T> {
    fn default() -> Self {
        Self::new()
    }
}

/// Locks a system for one call. A system whose lock a panicking call
/// poisoned is refused (its state may be half updated): it can only be
/// closed.
pub fn lock<T>(system: &Mutex<T>) -> Result<MutexGuard<'_, T>, Error> {
    system.lock().map_err(|_| {
        Error::new(
            STANCF_UNHANDLED_ERROR,
            "the system handle is unusable after an internal error in an earlier call (please \
             report it); close it with stancf_close and open the system again",
        )
    })
}
