//! A host that sets the water's kinematics (docs/interface.md, "C
//! library"; docs/method.md §12.1, (W2f)-(W2h)): MoorDyn's external wave
//! kinematics (`WaveKin 1`, `MoorDyn_ExternalWaveKinInit`,
//! `..GetN`, `..GetCoordinates`, `..Set`), in its order of points: every
//! line's nodes, every rod's nodes, every point, then MoorDyn's ground
//! body at the origin and every body.

use crate::args;
use crate::error::{guard, Error, STANCF_INVALID_VALUE};
use crate::StancfSystem;
use std::ffi::{c_int, c_uint};

/// The number of points where the host is asked: refused before
/// `stancf_init` and for a system whose waves are not a host's.
fn host_count(sys: &StancfSystem) -> Result<usize, Error> {
    let handle = &sys.coupled.handle;
    if !handle.takes_host_waves() {
        return Err(Error::input(
            "the system's waves are not a host's (a deck's WaveKin 1, a scenario's \
             water.host_waves): there are no water kinematics to set",
        ));
    }
    handle
        .host_flow_count()
        .ok_or_else(|| Error::input("the host's water kinematics are set after stancf_init"))
}

/// The number of points where the host sets the water's velocity and
/// acceleration (`MoorDyn_ExternalWaveKinInit`): the lines' and rods'
/// nodes, the points, 1 (MoorDyn's ground body) and the bodies. After
/// `stancf_init`; until the
/// host sets them the water is still, as in MoorDyn.
///
/// # Safety
/// `s` is looked up, never read; `n` is NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn stancf_wave_kin_init(s: *mut StancfSystem, n: *mut c_uint) -> c_int {
    stancf_wave_kin_n(s, n)
}

/// The number of points of `stancf_wave_kin_init`
/// (`MoorDyn_ExternalWaveKinGetN`).
///
/// # Safety
/// `s` is looked up, never read; `n` is NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn stancf_wave_kin_n(s: *mut StancfSystem, n: *mut c_uint) -> c_int {
    guard(|| {
        args::with_system(s, |sys| {
            *args::place(n, "n")? = host_count(sys)? as c_uint;
            Ok(())
        })
    })
}

/// The points' positions now (m), 3 per point in the order of
/// `stancf_wave_kin_init` (`MoorDyn_ExternalWaveKinGetCoordinates`): where
/// the host evaluates its waves before each `stancf_wave_kin_set`.
///
/// # Safety
/// `s` is looked up, never read; `r` is NULL or has room for 3 n values.
#[no_mangle]
pub unsafe extern "C" fn stancf_wave_kin_coordinates(s: *mut StancfSystem, r: *mut f64) -> c_int {
    guard(|| {
        args::with_system(s, |sys| {
            let out = args::room(r, 3 * host_count(sys)?, "r")?;
            let points = sys.coupled.handle.host_flow_points().unwrap_or_default();
            for (o, v) in out.iter_mut().zip(points.iter().flatten()) {
                *o = *v;
            }
            Ok(())
        })
    })
}

/// Sets the water's velocity `u` (m/s) and local acceleration `ud`
/// (m/s^2) at the points of `stancf_wave_kin_init`, 3 per point in its
/// order (`MoorDyn_ExternalWaveKinSet`): added to the sea's current, held
/// for the steps from now until set again (docs/method.md (W2f)-(W2h)).
/// `t` is the time the values are for; as in MoorDyn it does not move
/// them in time, and must be finite. STANCF_INVALID_VALUE for a value
/// that is not finite; nothing is set on an error.
///
/// # Safety
/// `s` is looked up, never read; `u` and `ud` are NULL or hold 3 n
/// doubles.
#[no_mangle]
pub unsafe extern "C" fn stancf_wave_kin_set(
    s: *mut StancfSystem,
    u: *const f64,
    ud: *const f64,
    t: f64,
) -> c_int {
    guard(|| {
        args::with_system(s, |sys| {
            let count = host_count(sys)?;
            let triples = |v: &[f64]| -> Vec<[f64; 3]> {
                v.chunks_exact(3).map(|c| [c[0], c[1], c[2]]).collect()
            };
            let u = triples(args::values(u, 3 * count, "u")?);
            let ud = triples(args::values(ud, 3 * count, "ud")?);
            if !t.is_finite() {
                return Err(Error::new(STANCF_INVALID_VALUE, format!("t is {t}")));
            }
            sys.coupled.handle.set_host_flow(&u, &ud)?;
            Ok(())
        })
    })
}
