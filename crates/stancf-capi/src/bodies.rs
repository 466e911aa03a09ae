//! The bodies of a system (docs/interface.md, "C library"): a free
//! body's mooring stiffness at the static equilibrium of the last
//! `stancf_init` (docs/method.md §15.9, (B16)), by the body's id as the
//! scenario or deck gives it.

use crate::args;
use crate::error::{guard, Error, STANCF_NUMERICAL_ERROR};
use crate::StancfSystem;
use std::ffi::c_int;

/// Body `body_id`'s 6 x 6 mooring stiffness, row-major in `out` (36
/// values): rows the lines' force F_x, F_y, F_z and moment M_x, M_y,
/// M_z about its reference point (global axes), columns the reference
/// point's displacement and a small rotation about global x, y, z
/// through it; N/m, N/rad, N m/m, N m/rad; K = -d[F; M]/d[dr; dphi].
/// STANCF_INVALID_INPUT for an unknown id, a body that is not free, a
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
    if !handle.system().free_bodies().any(|f| f == b) {
        return Err(Error::input(format!(
            "body {body_id} is not free (fixed or coupled): only a free body has a mooring \
             stiffness"
        )));
    }
    if handle.simulation().is_none() {
        return Err(Error::input(format!(
            "no stiffness of body {body_id} before stancf_init"
        )));
    }
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
