//! A coupled body through the C library (docs/method.md §13.6): its id
//! and count, its 6 numbers first in the coupling arrays, and stepping
//! it through C is the Rust handle's stepping, to the bit (the
//! equilibrium's force from stancf_init_force too); the force and moment
//! returned are its points' sums.

mod common;

use common::{cstring, message, repo};
use stancf_c::error::STANCF_SUCCESS;
use stancf_c::*;
use std::ffi::c_uint;

/// MoorDyn's example/body.txt: coupled body 1 at z = -70 m, three chains
/// from its points 4, 5, 6 (indices 3, 4, 5) to anchors.
const DECK: &str = "crates/stancf-cli/tests/fixtures/oc3-coupled-body-moordyn.txt";

/// The body's pose after interval k of 0.1 s: a surge of 0.2 m per
/// interval and a yaw of 0.01 rad.
fn pose(k: usize) -> [f64; 6] {
    [0.2 * k as f64, 0.0, -70.0, 0.0, 0.0, 0.01 * k as f64]
}

#[test]
fn a_coupled_body_steps_through_c_as_through_the_rust_handle() {
    let s = unsafe { stancf_create(cstring(&repo(DECK)).as_ptr()) };
    assert!(!s.is_null(), "{}", message());
    let (mut n, mut dof): (c_uint, c_uint) = (0, 0);
    let mut ids = [0i64; 1];
    unsafe {
        assert_eq!(stancf_coupled_body_count(s, &mut n), STANCF_SUCCESS);
        assert_eq!(stancf_coupled_body_ids(s, ids.as_mut_ptr()), STANCF_SUCCESS);
        assert_eq!(stancf_ncoupled_dof(s, &mut dof), STANCF_SUCCESS);
    }
    assert_eq!((n, ids, dof), (1, [1], 6));
    let mut x = [0.0; 6];
    assert_eq!(
        unsafe { stancf_coupled_positions(s, x.as_mut_ptr()) },
        STANCF_SUCCESS
    );
    assert_eq!(x, pose(0));
    assert_eq!(
        unsafe { stancf_init(s, x.as_ptr(), std::ptr::null()) },
        STANCF_SUCCESS,
        "{}",
        message()
    );
    let mut rust = stancf_scenario::coupling::open(&repo(DECK)).unwrap().handle;
    let start = rust.initialize(&x, None).unwrap();
    // The equilibrium's force and moment, as the Rust handle returns them.
    let mut f0 = [0.0; 6];
    assert_eq!(
        unsafe { stancf_init_force(s, f0.as_mut_ptr()) },
        STANCF_SUCCESS
    );
    assert_eq!(f0.to_vec(), start);
    let mut t = 0.0;
    for k in 1..=3 {
        let x = pose(k);
        let (mut f, mut dt) = ([0.0; 6], 0.1);
        let code = unsafe {
            stancf_step(
                s,
                x.as_ptr(),
                std::ptr::null(),
                f.as_mut_ptr(),
                &mut t,
                &mut dt,
            )
        };
        assert_eq!(code, STANCF_SUCCESS, "{}", message());
        let forces = rust.step_to(0.1 * k as f64, &x, None).unwrap();
        assert_eq!(forces.last_step, f.to_vec());
        // The force and moment are the sums over points 4, 5, 6: round-off
        // of a few ulps of the 9e5 N fairlead forces (on 5.2 m arms).
        let (mut force, mut moment) = ([0.0; 3], [0.0; 3]);
        for p in 3..6 {
            let (mut at, mut fp) = ([0.0; 3], [0.0; 3]);
            let code = unsafe {
                stancf_point_state(s, p, at.as_mut_ptr(), std::ptr::null_mut(), fp.as_mut_ptr())
            };
            assert_eq!(code, STANCF_SUCCESS, "{}", message());
            let r = [at[0] - x[0], at[1] - x[1], at[2] - x[2]];
            let m = [
                r[1] * fp[2] - r[2] * fp[1],
                r[2] * fp[0] - r[0] * fp[2],
                r[0] * fp[1] - r[1] * fp[0],
            ];
            for c in 0..3 {
                force[c] += fp[c];
                moment[c] += m[c];
            }
        }
        let scale = force[2].abs();
        for c in 0..3 {
            assert!((f[c] - force[c]).abs() <= 1e-12 * scale, "{f:?} {force:?}");
            assert!(
                (f[3 + c] - moment[c]).abs() <= 1e-12 * scale * 5.2,
                "{f:?} {moment:?}"
            );
        }
    }
    assert_eq!(unsafe { stancf_close(s) }, STANCF_SUCCESS);
}
