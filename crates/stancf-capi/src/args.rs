//! The C arguments as Rust references: a handle is looked up in the
//! registry of live ones ([`crate::handles`]) and locked for the call,
//! every pointer is checked for NULL and named in the error, arrays take
//! the length the system expects.

use crate::error::Error;
use crate::handles::{lock, Registry};
use crate::{StancfState, StancfSystem};
use std::sync::{Arc, Mutex};

/// The open systems.
static SYSTEMS: Registry<Mutex<StancfSystem>> = Registry::new();
/// The saved states not yet freed.
static STATES: Registry<StancfState> = Registry::new();

/// Registers an opened system; its handle.
pub fn open_system(system: StancfSystem) -> Result<*mut StancfSystem, Error> {
    SYSTEMS
        .insert(Mutex::new(system))
        .map(std::ptr::without_provenance_mut)
}

/// Runs `body` on the system behind handle `s`, locked for the call
/// (a call on the same handle from another thread waits for it).
pub fn with_system<R>(
    s: *mut StancfSystem,
    body: impl FnOnce(&mut StancfSystem) -> Result<R, Error>,
) -> Result<R, Error> {
    let system = SYSTEMS.get(s.addr()).ok_or_else(|| not_open(s))?;
    let mut guard = lock(&system)?;
    body(&mut guard)
}

/// Closes handle `s`: it is refused from now on; the system is freed
/// when a call on it from another thread ends. Works on a handle an
/// internal error left unusable.
pub fn close_system(s: *mut StancfSystem) -> Result<(), Error> {
    SYSTEMS
        .remove(s.addr())
        .map(drop)
        .ok_or_else(|| not_open(s))
}

/// The error for a handle that is NULL or not open.
fn not_open(s: *mut StancfSystem) -> Error {
    if s.is_null() {
        Error::input("the system handle is NULL")
    } else if STATES.contains(s.addr()) {
        Error::input(
            "the system handle is a saved state (from stancf_save), not a system from \
             stancf_create",
        )
    } else {
        Error::input(
            "the system handle is not open: closed already, or not from stancf_create; open \
             the system with stancf_create",
        )
    }
}

/// Registers a saved state; its handle.
pub fn save_state(state: StancfState) -> Result<*mut StancfState, Error> {
    STATES.insert(state).map(std::ptr::without_provenance_mut)
}

/// The saved state behind handle `p`.
pub fn state(p: *const StancfState) -> Result<Arc<StancfState>, Error> {
    STATES.get(p.addr()).ok_or_else(|| not_live(p))
}

/// Frees the saved state behind handle `p`: it is refused from now on.
pub fn free_state(p: *mut StancfState) -> Result<(), Error> {
    STATES.remove(p.addr()).map(drop).ok_or_else(|| not_live(p))
}

/// The error for a state handle that is NULL or not live.
fn not_live(p: *const StancfState) -> Error {
    if p.is_null() {
        Error::input("the state is NULL")
    } else if SYSTEMS.contains(p.addr()) {
        Error::input(
            "the state is a system handle (from stancf_create), not a state from stancf_save",
        )
    } else {
        Error::input(
            "the state is not live: freed already, or not from stancf_save; save one with \
             stancf_save",
        )
    }
}

/// `n` values read from `p`.
///
/// # Safety
/// `p` is NULL or points to at least `n` readable doubles.
pub unsafe fn values<'a>(p: *const f64, n: usize, what: &str) -> Result<&'a [f64], Error> {
    if p.is_null() {
        return Err(Error::input(format!("{what} is NULL")));
    }
    Ok(std::slice::from_raw_parts(p, n))
}

/// `n` values read from `p`, or None for NULL (an optional array).
///
/// # Safety
/// As [`values`].
pub unsafe fn optional_values<'a>(p: *const f64, n: usize) -> Option<&'a [f64]> {
    (!p.is_null()).then(|| std::slice::from_raw_parts(p, n))
}

/// Room for `n` values at `p`.
///
/// # Safety
/// `p` is NULL or points to at least `n` writable values.
pub unsafe fn room<'a, T>(p: *mut T, n: usize, what: &str) -> Result<&'a mut [T], Error> {
    if p.is_null() {
        return Err(Error::input(format!("{what} is NULL")));
    }
    Ok(std::slice::from_raw_parts_mut(p, n))
}

/// The place one value is written to.
///
/// # Safety
/// `p` is NULL or points to a writable `T`.
pub unsafe fn place<'a, T>(p: *mut T, what: &str) -> Result<&'a mut T, Error> {
    p.as_mut()
        .ok_or_else(|| Error::input(format!("{what} is NULL")))
}
