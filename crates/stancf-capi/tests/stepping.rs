//! Stepping through the C library is the Rust handle's stepping, to the
//! bit; save and restore repeat an interval to the bit; lines and points
//! read node by node or whole agree (docs/method.md §13).

mod common;

use common::{bridle, line_positions, message, repo, swing};
use stancf_c::error::STANCF_SUCCESS;
use stancf_c::*;
use std::ptr::null;

/// Steps `s` through `count` intervals of `dt` from its time; the forces
/// after each.
fn advance(s: *mut StancfSystem, count: usize, dt: f64) -> Vec<[f64; 3]> {
    advance_to(s, count, dt).0
}

/// [`advance`] with the time the calls reached (`*t` accumulated by
/// `stancf_step`: the end of the last interval exactly, where the
/// internal steps' sum may differ in the last bits).
fn advance_to(s: *mut StancfSystem, count: usize, dt: f64) -> (Vec<[f64; 3]>, f64) {
    let mut out = Vec::new();
    let mut t = 0.0;
    assert_eq!(unsafe { stancf_time(s, &mut t) }, STANCF_SUCCESS);
    for _ in 0..count {
        let (x, v) = swing(t + dt);
        let (mut f, mut h) = ([0.0; 3], dt);
        let code =
            unsafe { stancf_step(s, x.as_ptr(), v.as_ptr(), f.as_mut_ptr(), &mut t, &mut h) };
        assert_eq!(code, STANCF_SUCCESS, "{}", message());
        out.push(f);
    }
    (out, t)
}

#[test]
fn stepping_through_c_equals_the_rust_handle_to_the_bit() {
    let s = bridle();
    let start = [6.0, 0.0, 1.0];
    assert_eq!(
        unsafe { stancf_init(s, start.as_ptr(), [0.0; 3].as_ptr()) },
        STANCF_SUCCESS
    );
    let through_c = advance(s, 20, 2.5e-3);

    let mut rust = stancf_scenario::coupling::open(&repo("examples/bridle.toml"))
        .unwrap()
        .handle;
    rust.initialize(&start, Some(&[0.0; 3])).unwrap();
    let mut t = 0.0;
    let mut last = None;
    for f in &through_c {
        let (x, v) = swing(t + 2.5e-3);
        let forces = rust.step_to(t + 2.5e-3, &x, Some(&v)).unwrap();
        t += 2.5e-3;
        assert_eq!(forces.last_step, f.to_vec());
        last = Some(forces);
    }
    let nodes: Vec<f64> = rust.line_nodes(1).unwrap().into_iter().flatten().collect();
    assert_eq!(line_positions(s, 1), nodes);
    let mut mean = [0.0; 3];
    assert_eq!(
        unsafe { stancf_interval_mean_force(s, mean.as_mut_ptr()) },
        STANCF_SUCCESS
    );
    assert_eq!(mean.to_vec(), last.unwrap().interval_mean);
    assert_eq!(unsafe { stancf_close(s) }, STANCF_SUCCESS);
}

#[test]
fn save_step_restore_step_is_identical_to_the_bit() {
    let s = bridle();
    let start = [6.0, 0.0, 1.0];
    assert_eq!(
        unsafe { stancf_init(s, start.as_ptr(), null()) },
        STANCF_SUCCESS
    );
    advance(s, 5, 3.7e-3);
    let state = unsafe { stancf_save(s) };
    assert!(!state.is_null());
    let first = (advance(s, 5, 3.7e-3), line_positions(s, 0));
    assert_eq!(unsafe { stancf_restore(s, state) }, STANCF_SUCCESS);
    let second = (advance(s, 5, 3.7e-3), line_positions(s, 0));
    assert_eq!(first, second);
    assert_eq!(unsafe { stancf_free_state(state) }, STANCF_SUCCESS);
    assert_eq!(unsafe { stancf_close(s) }, STANCF_SUCCESS);
}

#[test]
fn lines_and_points_read_node_by_node_or_whole_agree() {
    let s = bridle();
    let start = [6.0, 0.0, 1.0];
    assert_eq!(
        unsafe { stancf_init(s, start.as_ptr(), null()) },
        STANCF_SUCCESS
    );
    let (f, t) = advance_to(s, 3, 1e-3);
    let (mut lines, mut points) = (0u32, 0u32);
    assert_eq!(unsafe { stancf_nlines(s, &mut lines) }, STANCF_SUCCESS);
    assert_eq!(unsafe { stancf_npoints(s, &mut points) }, STANCF_SUCCESS);
    assert_eq!((lines, points), (2, 3));
    for line in 0..lines {
        let mut id = 0i64;
        assert_eq!(unsafe { stancf_line_id(s, line, &mut id) }, STANCF_SUCCESS);
        assert_eq!(id, line as i64 + 1);
        let whole = line_positions(s, line);
        let mut tensions = vec![0.0; whole.len() / 3];
        assert_eq!(
            unsafe { stancf_line_tensions(s, line, tensions.as_mut_ptr()) },
            STANCF_SUCCESS
        );
        for node in 0..whole.len() / 3 {
            let (mut p, mut v, mut ten, mut curv) = ([0.0f64; 3], [0.0f64; 3], 0.0f64, 0.0f64);
            let n = node as u32;
            unsafe {
                assert_eq!(
                    stancf_line_node_pos(s, line, n, p.as_mut_ptr()),
                    STANCF_SUCCESS
                );
                assert_eq!(
                    stancf_line_node_vel(s, line, n, v.as_mut_ptr()),
                    STANCF_SUCCESS
                );
                assert_eq!(stancf_line_node_ten(s, line, n, &mut ten), STANCF_SUCCESS);
                assert_eq!(stancf_line_node_curv(s, line, n, &mut curv), STANCF_SUCCESS);
            }
            assert_eq!(p.to_vec(), whole[3 * node..3 * node + 3].to_vec());
            assert_eq!(ten, tensions[node]);
            assert!(ten > 0.0 && curv.is_finite() && v.iter().all(|c| c.is_finite()));
        }
    }
    // The fairlead (point index 1, id 2) where the step put it, with the
    // forces the step returned.
    let (mut pos, mut force, mut id) = ([0.0; 3], [0.0; 3], 0i64);
    unsafe {
        assert_eq!(stancf_point_id(s, 1, &mut id), STANCF_SUCCESS);
        assert_eq!(
            stancf_point_state(
                s,
                1,
                pos.as_mut_ptr(),
                std::ptr::null_mut(),
                force.as_mut_ptr()
            ),
            STANCF_SUCCESS
        );
    }
    assert_eq!(id, 2);
    assert_eq!(pos, swing(t).0);
    assert_eq!(force, f[2]);
    assert_eq!(unsafe { stancf_close(s) }, STANCF_SUCCESS);
}

/// The jumper's top as a host moves it, from rest: 10 m along x over its
/// 27 s period (examples/jumper-tolerance.toml).
fn top_from_rest(t: f64) -> ([f64; 3], [f64; 3]) {
    let w = 2.0 * std::f64::consts::PI / 27.0;
    (
        [5.0 * (1.0 - (w * t).cos()), 0.0, -5.0],
        [5.0 * w * (w * t).sin(), 0.0, 0.0],
    )
}

/// A scenario whose `analysis.force_tolerance` chooses the steps
/// (examples/jumper-tolerance.toml) steps through C as the Rust handle
/// of the same file does, to the bit, and the C library reports the
/// kept half steps each call took (an even number, at least 2).
#[test]
fn a_scenarios_force_tolerance_chooses_the_steps_through_c_as_in_rust() {
    let path = repo("examples/jumper-tolerance.toml");
    let s = unsafe { stancf_create(common::cstring(&path).as_ptr()) };
    assert!(!s.is_null(), "{}", message());
    let mut rust = stancf_scenario::coupling::open(&path).unwrap().handle;
    assert_eq!(rust.force_tolerance(), Some(1e-3));
    let (x0, v0) = top_from_rest(0.0);
    assert_eq!(
        unsafe { stancf_init(s, x0.as_ptr(), v0.as_ptr()) },
        STANCF_SUCCESS
    );
    rust.initialize(&x0, Some(&v0)).unwrap();
    let mut t = 0.0;
    for k in 1..=6 {
        let (x, v) = top_from_rest(k as f64);
        let (mut f, mut dt, mut steps) = ([0.0; 3], 1.0, 0u32);
        let code =
            unsafe { stancf_step(s, x.as_ptr(), v.as_ptr(), f.as_mut_ptr(), &mut t, &mut dt) };
        assert_eq!(code, STANCF_SUCCESS, "{}", message());
        let forces = rust.step_to(k as f64, &x, Some(&v)).unwrap();
        assert_eq!(forces.last_step, f.to_vec());
        assert_eq!(unsafe { stancf_last_steps(s, &mut steps) }, STANCF_SUCCESS);
        assert_eq!(steps as usize, forces.steps);
        assert!(steps >= 2 && steps % 2 == 0, "{steps}");
    }
    assert_eq!(unsafe { stancf_close(s) }, STANCF_SUCCESS);
}
