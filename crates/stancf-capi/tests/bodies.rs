//! A free body's and a coupled point's mooring stiffness through the C
//! library (`stancf_body_stiffness`, `stancf_point_stiffness`,
//! docs/interface.md "C library"): the values are the Rust handle's
//! matrices row-major, to the bit, and every call that has no matrix to
//! give returns a code with a message and writes nothing.

mod common;

use common::{cstring, message, repo, scratch};
use stancf_c::error::*;
use stancf_c::*;
use std::ptr::null_mut;

/// examples/moored-buoy.toml with its anchors (points 4, 5, 6) coupled,
/// without the push it gives the buoy (initialization starts at rest),
/// and a fixed body 7 that no line holds; written into a scratch folder.
fn coupled_buoy(name: &str) -> std::path::PathBuf {
    let text = std::fs::read_to_string(repo("examples/moored-buoy.toml"))
        .unwrap()
        .replace("type = \"fixed\"", "type = \"coupled\"")
        .replace("velocity = [0.5, 0.0, 0.0]", "")
        .replace("angular_velocity = [0.0, 0.0, 0.2]", "")
        + "[[bodies]]\nid = 7\ntype = \"fixed\"\nposition = [5.0, 0.0, -20.0]\n";
    assert!(!text.contains("velocity = ["));
    let path = scratch(name).join("buoy.toml");
    std::fs::write(&path, text).unwrap();
    path
}

#[test]
fn the_buoys_stiffness_is_the_handles_matrix_row_major() {
    let path = coupled_buoy("stiffness");
    let s = unsafe { stancf_create(cstring(&path).as_ptr()) };
    assert!(!s.is_null(), "{}", message());
    let mut x = [0.0; 9];
    unsafe {
        assert_eq!(stancf_coupled_positions(s, x.as_mut_ptr()), STANCF_SUCCESS);
        assert_eq!(stancf_init(s, x.as_ptr(), null_mut()), STANCF_SUCCESS);
    }
    let mut out = [f64::NAN; 36];
    let code = unsafe { stancf_body_stiffness(s, 1, out.as_mut_ptr()) };
    assert_eq!(code, STANCF_SUCCESS, "{}", message());
    // The same system opened and initialized in Rust: the same matrix.
    let mut rust = stancf_scenario::coupling::open(&path).unwrap();
    rust.handle.initialize(&x, None).unwrap();
    let k = rust.handle.body_stiffness(0).unwrap();
    for i in 0..6 {
        for j in 0..6 {
            assert_eq!(out[6 * i + j], k[i][j], "row {i}, column {j}");
        }
    }
    // A translational block that resists (lines in tension).
    assert!(out[0] > 0.0 && out[7] > 0.0 && out[14] > 0.0, "{out:?}");
    unsafe { stancf_close(s) };
}

#[test]
fn no_stiffness_before_init_for_an_unknown_or_fixed_body_or_into_null() {
    let s = unsafe { stancf_create(cstring(&coupled_buoy("stiffness-refused")).as_ptr()) };
    assert!(!s.is_null(), "{}", message());
    let mut out = [-1.0; 36];
    let call = |id: i64, out: *mut f64| unsafe { stancf_body_stiffness(s, id, out) };
    assert_eq!(call(1, out.as_mut_ptr()), STANCF_INVALID_INPUT);
    assert!(message().contains("before stancf_init"), "{}", message());
    let mut x = [0.0; 9];
    unsafe {
        assert_eq!(stancf_coupled_positions(s, x.as_mut_ptr()), STANCF_SUCCESS);
        assert_eq!(stancf_init(s, x.as_ptr(), null_mut()), STANCF_SUCCESS);
    }
    assert_eq!(call(3, out.as_mut_ptr()), STANCF_INVALID_INPUT);
    assert!(message().contains("no body of id 3"), "{}", message());
    assert_eq!(call(7, out.as_mut_ptr()), STANCF_INVALID_INPUT);
    assert!(message().contains("body 7 is fixed"), "{}", message());
    assert_eq!(call(1, null_mut()), STANCF_INVALID_INPUT);
    assert!(message().contains("out is NULL"), "{}", message());
    assert!(out.iter().all(|&v| v == -1.0), "nothing written: {out:?}");
    assert_eq!(call(1, out.as_mut_ptr()), STANCF_SUCCESS);
    unsafe { stancf_close(s) };
    assert_eq!(call(1, out.as_mut_ptr()), STANCF_INVALID_INPUT);
}

/// The buoy's coupled anchor 4 (the system's point 3): its 9 values are
/// the Rust handle's 3 x 3, row-major, to the bit, a restoring diagonal
/// (the taut line pulls it back); a point on the buoy and a call before
/// `stancf_init` are refused, writing nothing.
#[test]
fn a_coupled_anchors_stiffness_is_the_handles_matrix_row_major() {
    let path = coupled_buoy("point-stiffness");
    let s = unsafe { stancf_create(cstring(&path).as_ptr()) };
    assert!(!s.is_null(), "{}", message());
    let mut out = [-1.0; 9];
    let call = |id: i64, out: *mut f64| unsafe { stancf_point_stiffness(s, id, out) };
    assert_eq!(call(4, out.as_mut_ptr()), STANCF_INVALID_INPUT);
    assert!(message().contains("before stancf_init"), "{}", message());
    let mut x = [0.0; 9];
    unsafe {
        assert_eq!(stancf_coupled_positions(s, x.as_mut_ptr()), STANCF_SUCCESS);
        assert_eq!(stancf_init(s, x.as_ptr(), null_mut()), STANCF_SUCCESS);
    }
    assert_eq!(call(1, out.as_mut_ptr()), STANCF_INVALID_INPUT);
    assert!(message().contains("not a coupled point"), "{}", message());
    assert!(out.iter().all(|&v| v == -1.0), "nothing written: {out:?}");
    assert_eq!(call(4, out.as_mut_ptr()), STANCF_SUCCESS, "{}", message());
    let mut rust = stancf_scenario::coupling::open(&path).unwrap();
    rust.handle.initialize(&x, None).unwrap();
    let k = rust.handle.point_stiffness(3).unwrap();
    for i in 0..3 {
        for j in 0..3 {
            assert_eq!(out[3 * i + j], k[i][j], "row {i}, column {j}");
        }
    }
    assert!(out[0] > 0.0 && out[4] > 0.0 && out[8] > 0.0, "{out:?}");
    unsafe { stancf_close(s) };
}
