//! The C arguments as Rust references: every pointer is checked for NULL
//! and named in the error, arrays take the length the system expects.

use crate::error::Error;
use crate::StancfSystem;

/// The system behind a handle.
///
/// # Safety
/// `s` is NULL or a handle from `stancf_create` not yet closed.
pub unsafe fn system<'a>(s: *mut StancfSystem) -> Result<&'a mut StancfSystem, Error> {
    s.as_mut()
        .ok_or_else(|| Error::input("the system handle is NULL"))
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

/// Frees what `p` owns (from `Box::into_raw`); NULL is refused.
///
/// # Safety
/// `p` is NULL or from `Box::into_raw` of a `T`, not yet freed; it is not
/// used again.
pub unsafe fn free<T>(p: *mut T, what: &str) -> Result<(), Error> {
    if p.is_null() {
        return Err(Error::input(format!("{what} is NULL")));
    }
    drop(Box::from_raw(p));
    Ok(())
}
