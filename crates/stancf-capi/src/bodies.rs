//! The bodies of a system (docs/interface.md, "C library"): a free or
//! coupled body's mooring stiffness, and a coupled point's, at the static
//! equilibrium of the last `stancf_init` (docs/method.md §15.9, (B16)),
//! by the body's or point's id as the scenario or deck gives it.

use crate::args;
use crate::error::{guard, Error, STANCF_NUMERICAL_ERROR};
use crate::StancfSystem;
use std::ffi::c_int;

/// Body `body_id`'s 6 x 6 mooring stiffness, row-major in `out` (36
/// values): rows the lines' force F_x, F_y, F_z and moment M_x, M_y,
/// M_z about its reference point (global axes), columns the reference
/// point's displacement and a small rotation about global x, y, z
/// through it; N/m, N/rad, N m/m, N m/rad; K = -d[F; M]/d[dr; dphi].
/// STANCF_INVALID_INPUT for an unknown id, a fixed body, a
/// call before `stancf_init` or a NULL `out`; STANCF_NUMERICAL_ERROR
/// where the rest of the system is singular with the body held. Nothing
/// is written on an error.
///
/// # Safety
/// `s` is looked up, never read; `out` is NULL or has room for 36.
#[no_mangle]
pub unsafe extern "C" fn stancf_body_stiffness(
    s: *mut StancfSystem,
    body_id: i64,
    out: *mut f64,
) -> c_int {
    guard(|| {
        args::with_system(s, |sys| {
            let k = stiffness_of(sys, body_id)?;
            let out = args::room(out, 36, "out")?;
            for (o, v) in out.iter_mut().zip(k.iter().flatten()) {
                *o = *v;
            }
            Ok(())
        })
    })
}

/// The matrix of the body of id `body_id`, or the error saying why there
/// is none.
fn stiffness_of(sys: &StancfSystem, body_id: i64) -> Result<[[f64; 6]; 6], Error> {
    let ids = &sys.coupled.body_ids;
    let handle = &sys.coupled.handle;
    let Some(b) = ids.iter().position(|&id| id == body_id) else {
        return Err(Error::input(format!(
            "no body of id {body_id}: the system's bodies are {ids:?}"
        )));
    };
    if handle.system().bodies()[b].kind == stancf::system::BodyKind::Fixed {
        return Err(Error::input(format!(
            "body {body_id} is fixed: only a free or coupled body has a mooring stiffness"
        )));
    }
    if handle.simulation().is_none() {
        return Err(Error::input(format!(
            "no stiffness of body {body_id} before stancf_init"
        )));
    }
    no_equilibrium(handle, &format!("body {body_id}"))?;
    handle.body_stiffness(b).ok_or_else(|| {
        Error::new(
            STANCF_NUMERICAL_ERROR,
            format!(
                "body {body_id}: no mooring stiffness: the rest of the system is singular with \
                 the body held"
            ),
        )
    })
}

/// Refused (`STANCF_INVALID_INPUT`, naming `what`): a system started
/// from MoorDyn's start without initial conditions (a deck's TmaxIC 0),
/// which has no equilibrium to take a stiffness at.
fn no_equilibrium(handle: &stancf::coupling::CoupledSystem, what: &str) -> Result<(), Error> {
    if handle.starts_from_catenaries() {
        return Err(Error::input(format!(
            "{what}: no mooring stiffness: the system started from MoorDyn's start without \
             initial conditions (TmaxIC 0), not from an equilibrium"
        )));
    }
    Ok(())
}

/// Coupled point `point_id`'s 3 x 3 mooring stiffness, row-major in `out`
/// (9 values): K = -d f / d x of the lines' force on it (N/m, global
/// axes), the rest of the system in equilibrium. STANCF_INVALID_INPUT
/// for an unknown id, a point that is not coupled (or is on a body), a
/// call before `stancf_init` or a NULL `out`; STANCF_NUMERICAL_ERROR
/// where the rest of the system is singular with the point held.
/// Nothing is written on an error.
///
/// # Safety
/// `s` is looked up, never read; `out` is NULL or has room for 9.
#[no_mangle]
pub unsafe extern "C" fn stancf_point_stiffness(
    s: *mut StancfSystem,
    point_id: i64,
    out: *mut f64,
) -> c_int {
    guard(|| {
        args::with_system(s, |sys| {
            let k = point_stiffness_of(sys, point_id)?;
            let out = args::room(out, 9, "out")?;
            for (o, v) in out.iter_mut().zip(k.iter().flatten()) {
                *o = *v;
            }
            Ok(())
        })
    })
}

/// The matrix of the coupled point of id `point_id`, or the error saying
/// why there is none.
fn point_stiffness_of(sys: &StancfSystem, point_id: i64) -> Result<[[f64; 3]; 3], Error> {
    let ids = &sys.coupled.point_ids;
    let handle = &sys.coupled.handle;
    let Some(p) = ids.iter().position(|&id| id == point_id) else {
        return Err(Error::input(format!(
            "no point of id {point_id}: the system's points are {ids:?}"
        )));
    };
    let point = &handle.system().points()[p];
    let plain = matches!(point.kind, stancf::system::PointKind::Coupled(_))
        && !handle
            .system()
            .bodies()
            .iter()
            .enumerate()
            .any(|(b, _)| handle.system().body_points(b).iter().any(|&(q, _)| q == p));
    if !plain {
        return Err(Error::input(format!(
            "point {point_id} is not a coupled point of its own (fixed, free or on a body): only \
             a coupled point has a 3 x 3 mooring stiffness"
        )));
    }
    if handle.simulation().is_none() {
        return Err(Error::input(format!(
            "no stiffness of point {point_id} before stancf_init"
        )));
    }
    no_equilibrium(handle, &format!("point {point_id}"))?;
    handle.point_stiffness(p).ok_or_else(|| {
        Error::new(
            STANCF_NUMERICAL_ERROR,
            format!(
                "point {point_id}: no mooring stiffness: the rest of the system is singular with \
                 the point held"
            ),
        )
    })
}
