//! `libstancf_c`: the coupling API (docs/method.md §13) for C, Fortran
//! and every language that calls C, argument for argument as MoorDyn's
//! C API (`MoorDyn_Create`, `MoorDyn_NCoupledDOF`, `MoorDyn_Init`,
//! `MoorDyn_Step`, `MoorDyn_Close`), so that a code coupled to MoorDyn
//! can switch with little change. The header is `include/stancf.h`;
//! docs/interface.md ("C library") is the contract.
//!
//! A thin shell: the handle is `stancf_scenario::coupling::open`'s
//! [`stancf::coupling::CoupledSystem`], the same code as Rust's and
//! Python's `stancf.Simulation`. Every function returns a code (0 is
//! success, [`error`] lists the others) and keeps its message for
//! `stancf_error_message`; none unwinds into C. The pointers C holds are
//! tokens of a registry ([`handles`]): a closed, freed or made-up handle
//! is refused, never read.

pub mod args;
pub mod bodies;
pub mod error;
pub mod handles;
pub mod lines;
pub mod waves;

pub use bodies::*;
pub use lines::*;
pub use waves::*;

use error::{guard, guard_ptr, Error, STANCF_INVALID_INPUT, STANCF_INVALID_INPUT_FILE};
use stancf::coupling::{CoupledForces, CoupledState};
use stancf_scenario::coupling::Coupled;
use stancf_scenario::scenario::HostEnvironment;
use std::ffi::{c_char, c_int, c_uint, CStr};
use std::path::PathBuf;

/// A coupled system (opaque to C, which holds a token of it): the handle
/// and the forces of its last step.
pub struct StancfSystem {
    coupled: Coupled,
    last: Option<CoupledForces>,
    /// The forces of the last `stancf_init`'s equilibrium.
    start: Option<Vec<f64>>,
}

/// A saved state of a system (opaque to C, which holds a token of it),
/// from `stancf_save`.
pub struct StancfState(CoupledState);

/// The path of a C string.
///
/// # Safety
/// `path` is NULL or a NUL-terminated string.
unsafe fn path_of(path: *const c_char) -> Result<PathBuf, Error> {
    if path.is_null() {
        return Err(Error::new(STANCF_INVALID_INPUT_FILE, "the path is NULL"));
    }
    let bytes = CStr::from_ptr(path).to_bytes();
    #[cfg(unix)]
    {
        use std::os::unix::ffi::OsStrExt;
        Ok(PathBuf::from(std::ffi::OsStr::from_bytes(bytes)))
    }
    #[cfg(not(unix))]
    {
        std::str::from_utf8(bytes)
            .map(PathBuf::from)
            .map_err(|_| Error::new(STANCF_INVALID_INPUT_FILE, "the path is not UTF-8"))
    }
}

/// Opens the system scenario or MoorDyn v2 deck at `path`
/// (`MoorDyn_Create`): NULL if it cannot be read or is not valid, with
/// the reason, naming the file and the key or line, in
/// `stancf_error_message()`. Nothing is written to disk.
///
/// # Safety
/// `path` is NULL or a NUL-terminated string.
#[no_mangle]
pub unsafe extern "C" fn stancf_create(path: *const c_char) -> *mut StancfSystem {
    create(path, 0)
}

/// Opens a system without the element bound `stancf run` applies without
/// `--allow-large` ([`STANCF_ALLOW_LARGE`] in `flags`; 0 is
/// `stancf_create`). The hard bound on elements holds whatever the flags;
/// an unknown flag is refused.
pub const STANCF_ALLOW_LARGE: c_uint = 1;

/// `stancf_create` with `flags`: [`STANCF_ALLOW_LARGE`] opens a system of
/// more elements than `stancf run` takes without `--allow-large` (up to
/// the hard bound, docs/interface.md "Bounds"). NULL on error, as
/// `stancf_create`.
///
/// # Safety
/// `path` is NULL or a NUL-terminated string.
#[no_mangle]
pub unsafe extern "C" fn stancf_create_with(
    path: *const c_char,
    flags: c_uint,
) -> *mut StancfSystem {
    create(path, flags)
}

/// `stancf_create_with` in the host's sea (`MoorDyn_Create` after
/// OpenFAST's `InitInp%WtrDepth`, `rhoW`, `g`): `water_depth` (m),
/// `water_density` (kg/m^3) and `gravity` (m/s^2) fill what a MoorDyn
/// deck leaves out, the deck's own values winning; 0 for a value the host
/// does not give. A negative or non-finite value is refused (NULL).
///
/// # Safety
/// `path` is NULL or a NUL-terminated string.
#[no_mangle]
pub unsafe extern "C" fn stancf_create_in(
    path: *const c_char,
    flags: c_uint,
    water_depth: f64,
    water_density: f64,
    gravity: f64,
) -> *mut StancfSystem {
    let given = |v: f64| (v != 0.0).then_some(v);
    let host = HostEnvironment {
        water_depth: given(water_depth),
        water_density: given(water_density),
        gravity: given(gravity),
        turbines: None,
        sets_waves: false,
        run_length: None,
    };
    create_in(path, flags, &host)
}

/// The most turbines `stancf_create_farm` reads (a farm of a hundred
/// thousand turbines is far beyond any; a wrong count must not read the
/// host's memory without end).
const MAX_TURBINES: c_uint = 100_000;

/// `stancf_create_with` for a FAST.Farm farm-level deck whose turbines the
/// host places, as FAST.Farm gives MoorDyn-F its turbines' positions:
/// `positions` holds `n_turbines` triples x, y, z (m), turbine n's at
/// index 3 (n - 1) (docs/interface.md, "FAST.Farm's farm-level decks").
/// NULL `positions` with `n_turbines` > 0, more than 100 000 turbines, or
/// a position not finite: NULL, the message naming it.
///
/// # Safety
/// `path` is NULL or a NUL-terminated string; `positions` is NULL or
/// holds 3 `n_turbines` doubles.
#[no_mangle]
pub unsafe extern "C" fn stancf_create_farm(
    path: *const c_char,
    flags: c_uint,
    n_turbines: c_uint,
    positions: *const f64,
) -> *mut StancfSystem {
    if n_turbines > MAX_TURBINES || (n_turbines > 0 && positions.is_null()) {
        return guard_ptr(|| {
            Err(Error::new(
                STANCF_INVALID_INPUT,
                format!(
                    "positions: {n_turbines} turbines given with {} (at most {MAX_TURBINES}, \
                     each x, y, z)",
                    if positions.is_null() {
                        "no positions"
                    } else {
                        "positions"
                    }
                ),
            ))
        });
    }
    let turbines = (0..n_turbines as usize)
        .map(|k| std::array::from_fn(|c| *positions.add(3 * k + c)))
        .collect();
    let host = HostEnvironment {
        turbines: Some(turbines),
        ..HostEnvironment::NONE
    };
    create_in(path, flags, &host)
}

unsafe fn create(path: *const c_char, flags: c_uint) -> *mut StancfSystem {
    create_in(path, flags, &HostEnvironment::NONE)
}

unsafe fn create_in(
    path: *const c_char,
    flags: c_uint,
    host: &HostEnvironment,
) -> *mut StancfSystem {
    guard_ptr(|| {
        if flags & !STANCF_ALLOW_LARGE != 0 {
            return Err(Error::new(
                STANCF_INVALID_INPUT_FILE,
                format!("unknown flags {flags:#x} (known: STANCF_ALLOW_LARGE = 1)"),
            ));
        }
        let path = path_of(path)?;
        let allow_large = flags & STANCF_ALLOW_LARGE != 0;
        let coupled = stancf_scenario::coupling::open_in(&path, allow_large, host)
            .map_err(|e| Error::new(STANCF_INVALID_INPUT_FILE, e.to_string()))?;
        args::open_system(StancfSystem {
            coupled,
            last: None,
            start: None,
        })
    })
}

/// Frees a system (`MoorDyn_Close`); the handle is refused from then on.
/// NULL, a handle closed already or not from `stancf_create` is refused
/// with `STANCF_INVALID_INPUT` (nothing to free).
///
/// # Safety
/// None: `s` is looked up, never read.
#[no_mangle]
pub unsafe extern "C" fn stancf_close(s: *mut StancfSystem) -> c_int {
    guard(|| args::close_system(s))
}

/// The number of coupled degrees of freedom, 6 per coupled body (a
/// coupled rod is one; 3 pinned to the host) and 3 per coupled point
/// (`MoorDyn_NCoupledDOF`).
///
/// # Safety
/// `s` is looked up, never read; `n` is NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn stancf_ncoupled_dof(s: *mut StancfSystem, n: *mut c_uint) -> c_int {
    guard(|| {
        args::with_system(s, |sys| {
            *args::place(n, "n")? = sys.coupled.handle.coupled_dof() as c_uint;
            Ok(())
        })
    })
}

/// The coupled points' ids (not those on coupled bodies), in the order
/// of the coupling arrays after the bodies (`(ncoupled_dof - 6 nb) / 3`
/// values, nb from `stancf_coupled_body_count`, when no body is pinned
/// to the host; a CoupledPinned body takes 3 numbers, not 6).
///
/// # Safety
/// `s` is looked up, never read; `ids` is NULL or has room for
/// `(ncoupled_dof - 6 nb) / 3` values.
#[no_mangle]
pub unsafe extern "C" fn stancf_coupled_ids(s: *mut StancfSystem, ids: *mut i64) -> c_int {
    guard(|| {
        args::with_system(s, |sys| {
            let known = &sys.coupled.coupled_ids;
            args::room(ids, known.len(), "ids")?.copy_from_slice(known);
            Ok(())
        })
    })
}

/// The number of coupled bodies, whose 6 numbers each (3 for a body
/// pinned to the host, MoorDyn's CoupledPinned) come first in the
/// coupling arrays.
///
/// # Safety
/// `s` is looked up, never read; `n` is NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn stancf_coupled_body_count(s: *mut StancfSystem, n: *mut c_uint) -> c_int {
    guard(|| {
        args::with_system(s, |sys| {
            *args::place(n, "n")? = sys.coupled.coupled_body_ids.len() as c_uint;
            Ok(())
        })
    })
}

/// The coupled bodies' ids, in the order of the coupling arrays
/// (`stancf_coupled_body_count` values).
///
/// # Safety
/// `s` is looked up, never read; `ids` is NULL or has room for
/// `stancf_coupled_body_count` values.
#[no_mangle]
pub unsafe extern "C" fn stancf_coupled_body_ids(s: *mut StancfSystem, ids: *mut i64) -> c_int {
    guard(|| {
        args::with_system(s, |sys| {
            let known = &sys.coupled.coupled_body_ids;
            args::room(ids, known.len(), "ids")?.copy_from_slice(known);
            Ok(())
        })
    })
}

/// The coupled bodies' poses (m and radians) and the coupled points'
/// positions (m) where the scenario or deck puts them (`ncoupled_dof`
/// values): the start a coupling code may give `stancf_init`.
///
/// # Safety
/// `s` is looked up, never read; `x` is NULL or has room for
/// `ncoupled_dof` values.
#[no_mangle]
pub unsafe extern "C" fn stancf_coupled_positions(s: *mut StancfSystem, x: *mut f64) -> c_int {
    guard(|| {
        args::with_system(s, |sys| {
            let h = &sys.coupled.handle;
            args::room(x, h.coupled_dof(), "x")?.copy_from_slice(&h.initial_positions());
            Ok(())
        })
    })
}

/// Solves the static equilibrium with the coupled points at `x` and
/// starts the system at t = 0 (`MoorDyn_Init`); `xd` (may be NULL) their
/// velocities. Reads `ncoupled_dof` values from each; writes nothing
/// back. Call again to start over.
///
/// # Safety
/// `s` is looked up, never read; `x` (and `xd` unless NULL) hold
/// `ncoupled_dof` doubles.
#[no_mangle]
pub unsafe extern "C" fn stancf_init(s: *mut StancfSystem, x: *const f64, xd: *const f64) -> c_int {
    guard(|| {
        args::with_system(s, |sys| {
            let n = sys.coupled.handle.coupled_dof();
            init(sys, n, x, xd)
        })
    })
}

/// `stancf_init` with the arrays' length `n`, refused with
/// `STANCF_INVALID_VALUE` unless it is `ncoupled_dof`.
///
/// # Safety
/// `s` is looked up, never read; `x` (and `xd` unless NULL) hold `n`
/// doubles.
#[no_mangle]
pub unsafe extern "C" fn stancf_init_n(
    s: *mut StancfSystem,
    n: c_uint,
    x: *const f64,
    xd: *const f64,
) -> c_int {
    guard(|| args::with_system(s, |sys| init(sys, n as usize, x, xd)))
}

/// `stancf_init` on a locked system, with arrays of `n` values.
///
/// # Safety
/// `x` (and `xd` unless NULL) are NULL or hold `n` doubles.
unsafe fn init(
    sys: &mut StancfSystem,
    n: usize,
    x: *const f64,
    xd: *const f64,
) -> Result<(), Error> {
    let x = args::values(x, n, "x")?;
    let xd = args::optional_values(xd, n);
    sys.start = Some(sys.coupled.handle.initialize(x, xd)?);
    sys.last = None;
    Ok(())
}

/// The forces on the coupled points and bodies at the equilibrium the
/// last `stancf_init` solved (what `MoorDyn_Init` leaves for
/// `MoorDyn_GetFASTtens`; the Rust and Python `initialize` return them).
/// Refused before `stancf_init`.
///
/// # Safety
/// `s` is looked up, never read; `f` is NULL or has room for
/// `ncoupled_dof` doubles.
#[no_mangle]
pub unsafe extern "C" fn stancf_init_force(s: *mut StancfSystem, f: *mut f64) -> c_int {
    guard(|| {
        args::with_system(s, |sys| {
            let start = sys
                .start
                .as_ref()
                .ok_or_else(|| Error::input("no stancf_init yet"))?;
            args::room(f, start.len(), "f")?.copy_from_slice(start);
            Ok(())
        })
    })
}

/// Advances from `*t`, the time reached, to `*t + *dt` with the coupled
/// points moving to `x` (cubically in time, with the velocities `xd` or,
/// where `xd` is NULL, velocities estimated from this call's and the two
/// last calls' positions, docs/method.md (K2a)), and writes
/// into `f` the force of the lines on each coupled point (N; the mean
/// over the interval's last step), then `*t += *dt` (`MoorDyn_Step`).
/// The interval is split into the fewest equal steps no longer than the
/// scenario's time step. A `*t` that is not the time reached is refused.
/// On `STANCF_NUMERICAL_ERROR` the system stays at its last converged
/// step and `*t` is unchanged.
///
/// # Safety
/// `s` is looked up, never read; `x` (and `xd` unless NULL) hold and `f`
/// has room for `ncoupled_dof` doubles; `t` and `dt` are NULL or valid.
#[no_mangle]
pub unsafe extern "C" fn stancf_step(
    s: *mut StancfSystem,
    x: *const f64,
    xd: *const f64,
    f: *mut f64,
    t: *mut f64,
    dt: *mut f64,
) -> c_int {
    guard(|| {
        args::with_system(s, |sys| {
            let n = sys.coupled.handle.coupled_dof();
            step(sys, n, (x, xd, f), t, dt)
        })
    })
}

/// `stancf_step` with the arrays' length `n`, refused with
/// `STANCF_INVALID_VALUE` unless it is `ncoupled_dof`.
///
/// # Safety
/// As `stancf_step`, with `n` doubles in each array.
#[no_mangle]
pub unsafe extern "C" fn stancf_step_n(
    s: *mut StancfSystem,
    n: c_uint,
    x: *const f64,
    xd: *const f64,
    f: *mut f64,
    t: *mut f64,
    dt: *mut f64,
) -> c_int {
    guard(|| args::with_system(s, |sys| step(sys, n as usize, (x, xd, f), t, dt)))
}

type Arrays = (*const f64, *const f64, *mut f64);

/// `stancf_step` on a locked system, with arrays of `n` values.
///
/// # Safety
/// As `stancf_step`'s arrays and places.
unsafe fn step(
    sys: &mut StancfSystem,
    n: usize,
    (x, xd, f): Arrays,
    t: *mut f64,
    dt: *mut f64,
) -> Result<(), Error> {
    let x = args::values(x, n, "x")?;
    let xd = args::optional_values(xd, n);
    let f = args::room(f, n, "f")?;
    let t = args::place(t, "t")?;
    let dt = *args::place(dt, "dt")?;
    let h = &mut sys.coupled.handle;
    if h.simulation().is_none() {
        return Err(Error::input("stancf_step before stancf_init"));
    }
    let reached = h.time();
    if (*t - reached).abs() > 1e-9 * reached.abs().max(1.0) {
        return Err(Error::input(format!(
            "t = {} s is not the time reached, {reached} s",
            *t
        )));
    }
    // step_to refuses arrays of another length than ncoupled_dof.
    let forces = h.step_to(*t + dt, x, xd)?;
    f.copy_from_slice(&forces.last_step);
    sys.last = Some(forces);
    *t += dt;
    Ok(())
}

/// The mean force of the last `stancf_step` over its whole interval, its
/// impulse over its length (docs/method.md (K3); `ncoupled_dof` values).
/// Refused before the first step.
///
/// # Safety
/// `s` is looked up, never read; `f` is NULL or has room for
/// `ncoupled_dof` doubles.
#[no_mangle]
pub unsafe extern "C" fn stancf_interval_mean_force(s: *mut StancfSystem, f: *mut f64) -> c_int {
    guard(|| {
        args::with_system(s, |sys| {
            let last = last_step(sys)?;
            args::room(f, last.interval_mean.len(), "f")?.copy_from_slice(&last.interval_mean);
            Ok(())
        })
    })
}

/// The forces of the last `stancf_step`, refused before the first (and
/// after a restore).
fn last_step(sys: &StancfSystem) -> Result<&CoupledForces, Error> {
    sys.last
        .as_ref()
        .ok_or_else(|| Error::input("no step since stancf_init or stancf_restore"))
}

/// The internal steps the last `stancf_step` took: the interval's equal
/// steps, or, where the scenario's `analysis.force_tolerance` chooses
/// them, its kept half steps (docs/method.md §13.3, (M23c)). Refused
/// before the first step.
///
/// # Safety
/// `s` is looked up, never read; `n` is NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn stancf_last_steps(s: *mut StancfSystem, n: *mut c_uint) -> c_int {
    guard(|| {
        args::with_system(s, |sys| {
            let last = last_step(sys)?;
            *args::place(n, "n")? = c_uint::try_from(last.steps).unwrap_or(c_uint::MAX);
            Ok(())
        })
    })
}

/// The time reached (s; 0 before `stancf_init`).
///
/// # Safety
/// `s` is looked up, never read; `t` is NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn stancf_time(s: *mut StancfSystem, t: *mut f64) -> c_int {
    guard(|| {
        args::with_system(s, |sys| {
            *args::place(t, "t")? = sys.coupled.handle.time();
            Ok(())
        })
    })
}

/// The whole state of a system (docs/method.md §13.4): `stancf_restore`
/// brings it back and stepping on gives the same bits. NULL on error.
/// Free it with `stancf_free_state`.
///
/// # Safety
/// None: `s` is looked up, never read.
#[no_mangle]
pub unsafe extern "C" fn stancf_save(s: *mut StancfSystem) -> *mut StancfState {
    guard_ptr(|| {
        let state = args::with_system(s, |sys| Ok(StancfState(sys.coupled.handle.save())))?;
        args::save_state(state)
    })
}

/// Brings back a state saved from this system, or from a handle opened
/// on the same scenario or deck (a restart). A state of another system
/// is refused with `STANCF_INVALID_VALUE` and the system is untouched; a
/// NULL, freed or unknown state with `STANCF_INVALID_INPUT`.
///
/// # Safety
/// None: `s` and `state` are looked up, never read.
#[no_mangle]
pub unsafe extern "C" fn stancf_restore(s: *mut StancfSystem, state: *const StancfState) -> c_int {
    guard(|| {
        args::with_system(s, |sys| {
            let state = args::state(state)?;
            sys.coupled.handle.restore(&state.0)?;
            sys.last = None;
            Ok(())
        })
    })
}

/// Frees a state from `stancf_save`; the state is refused from then on.
/// NULL, a state freed already or not from `stancf_save` is refused with
/// `STANCF_INVALID_INPUT`.
///
/// # Safety
/// None: `state` is looked up, never read.
#[no_mangle]
pub unsafe extern "C" fn stancf_free_state(state: *mut StancfState) -> c_int {
    guard(|| args::free_state(state))
}

/// Lets one `stancf_step` take up to `n` internal steps (at least 1; by
/// default 100 000, `stancf::coupling::MAX_INTERVAL_STEPS`): the opt-in
/// for a host that steps over long intervals on purpose. 0 is refused
/// with `STANCF_INVALID_VALUE`.
///
/// # Safety
/// None: `s` is looked up, never read.
#[no_mangle]
pub unsafe extern "C" fn stancf_set_max_interval_steps(s: *mut StancfSystem, n: u64) -> c_int {
    guard(|| {
        args::with_system(s, |sys| {
            let n = usize::try_from(n).unwrap_or(usize::MAX);
            sys.coupled
                .handle
                .set_max_interval_steps(n)
                .map_err(|e| Error::new(error::STANCF_INVALID_VALUE, e.to_string()))
        })
    })
}

/// The message of this thread's last failed call ("" before any): valid
/// until its next failed call.
#[no_mangle]
pub extern "C" fn stancf_error_message() -> *const c_char {
    error::message_ptr()
}
