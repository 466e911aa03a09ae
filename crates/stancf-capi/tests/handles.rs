//! A careless host cannot crash the library through its handles
//! (docs/interface.md, "C library"; issue 28): a closed, freed, stale or
//! made-up handle is refused with STANCF_INVALID_INPUT and nothing is
//! read or written; a state of another system is refused with
//! STANCF_INVALID_VALUE; an interval of too many internal steps is
//! refused before anything moves; a handle a panic left behind can still
//! be closed; calls from several threads on one handle wait for each
//! other.

mod common;

use common::{bridle, cstring, line_positions, message, repo};
use stancf_c::error::*;
use stancf_c::*;
use std::ffi::c_int;
use std::ptr::{null, null_mut};

const X: [f64; 3] = [6.0, 0.0, 1.0];
const SENTINEL: f64 = -7.25;

/// Calls every function that takes a system handle on `s`, each output
/// filled with a sentinel first: the name and code of each call. Panics
/// if any output changed.
fn every_call(s: *mut StancfSystem) -> Vec<(&'static str, c_int)> {
    let mut buf = [SENTINEL; 64];
    let (mut n, mut id, mut t, mut dt) = (77u32, 77i64, 0.0, 1e-3);
    let b = buf.as_mut_ptr();
    let x = X.as_ptr();
    let calls = unsafe {
        vec![
            ("stancf_ncoupled_dof", stancf_ncoupled_dof(s, &mut n)),
            ("stancf_coupled_ids", stancf_coupled_ids(s, &mut id)),
            ("stancf_coupled_positions", stancf_coupled_positions(s, b)),
            ("stancf_init", stancf_init(s, x, null())),
            ("stancf_init_n", stancf_init_n(s, 3, x, null())),
            ("stancf_init_force", stancf_init_force(s, b)),
            ("stancf_step", stancf_step(s, x, null(), b, &mut t, &mut dt)),
            (
                "stancf_step_n",
                stancf_step_n(s, 3, x, null(), b, &mut t, &mut dt),
            ),
            (
                "stancf_interval_mean_force",
                stancf_interval_mean_force(s, b),
            ),
            ("stancf_time", stancf_time(s, b)),
            ("stancf_last_steps", stancf_last_steps(s, &mut n)),
            (
                "stancf_set_max_interval_steps",
                stancf_set_max_interval_steps(s, 10),
            ),
            ("stancf_nlines", stancf_nlines(s, &mut n)),
            ("stancf_line_id", stancf_line_id(s, 0, &mut id)),
            ("stancf_line_nnodes", stancf_line_nnodes(s, 0, &mut n)),
            ("stancf_line_node_pos", stancf_line_node_pos(s, 0, 0, b)),
            ("stancf_line_node_vel", stancf_line_node_vel(s, 0, 0, b)),
            ("stancf_line_node_ten", stancf_line_node_ten(s, 0, 0, b)),
            ("stancf_line_node_curv", stancf_line_node_curv(s, 0, 0, b)),
            ("stancf_line_positions", stancf_line_positions(s, 0, b)),
            ("stancf_line_tensions", stancf_line_tensions(s, 0, b)),
            ("stancf_npoints", stancf_npoints(s, &mut n)),
            ("stancf_point_id", stancf_point_id(s, 0, &mut id)),
            (
                "stancf_point_state",
                stancf_point_state(s, 0, b, b.add(3), b.add(6)),
            ),
            ("stancf_wave_kin_init", stancf_wave_kin_init(s, &mut n)),
            ("stancf_wave_kin_n", stancf_wave_kin_n(s, &mut n)),
            (
                "stancf_wave_kin_coordinates",
                stancf_wave_kin_coordinates(s, b),
            ),
            ("stancf_wave_kin_set", stancf_wave_kin_set(s, x, x, 0.0)),
            ("stancf_close", stancf_close(s)),
        ]
    };
    let save = unsafe { stancf_save(s) };
    assert!(save.is_null(), "stancf_save gave a state");
    assert!(buf.iter().all(|&v| v == SENTINEL), "written: {buf:?}");
    assert_eq!((n, id, t, dt), (77, 77, 0.0, 1e-3));
    calls
}

/// Asserts that every call on `s` is refused as not open, `why` in each
/// message.
fn refused_by_every_call(s: *mut StancfSystem, why: &str) {
    for (name, code) in every_call(s) {
        assert_eq!(code, STANCF_INVALID_INPUT, "{name}: {}", message());
        assert!(message().contains(why), "{name}: {}", message());
    }
}

/// An initialized bridle stepped 3 times.
fn stepped_bridle() -> *mut StancfSystem {
    let s = bridle();
    let (mut f, mut t, mut dt) = ([0.0; 3], 0.0, 1e-3);
    unsafe {
        assert_eq!(stancf_init(s, X.as_ptr(), null()), STANCF_SUCCESS);
        for _ in 0..3 {
            let code = stancf_step(s, X.as_ptr(), null(), f.as_mut_ptr(), &mut t, &mut dt);
            assert_eq!(code, STANCF_SUCCESS, "{}", message());
        }
    }
    s
}

#[test]
fn a_closed_handle_is_refused_by_every_call_and_nothing_is_written() {
    let s = stepped_bridle();
    assert_eq!(unsafe { stancf_close(s) }, STANCF_SUCCESS);
    refused_by_every_call(s, "not open: closed already, or not from stancf_create");
    assert_eq!(unsafe { stancf_close(s) }, STANCF_INVALID_INPUT);
}

#[test]
fn a_stale_handle_never_reaches_a_newer_system() {
    let old = bridle();
    assert_eq!(unsafe { stancf_close(old) }, STANCF_SUCCESS);
    let new = bridle();
    assert_ne!(old, new);
    let mut n = 0u32;
    assert_eq!(
        unsafe { stancf_ncoupled_dof(old, &mut n) },
        STANCF_INVALID_INPUT
    );
    assert_eq!(unsafe { stancf_ncoupled_dof(new, &mut n) }, STANCF_SUCCESS);
    assert_eq!(unsafe { stancf_close(new) }, STANCF_SUCCESS);
}

#[test]
fn a_made_up_handle_is_refused_not_read() {
    let mut on_the_stack = [0u8; 64];
    for s in [
        0x1000 as *mut StancfSystem,
        usize::MAX as *mut StancfSystem,
        on_the_stack.as_mut_ptr().cast::<StancfSystem>(),
    ] {
        refused_by_every_call(s, "not from stancf_create");
    }
    let state = 0x1000 as *mut StancfState;
    assert_eq!(unsafe { stancf_free_state(state) }, STANCF_INVALID_INPUT);
    assert!(message().contains("not from stancf_save"), "{}", message());
}

#[test]
fn a_state_given_for_a_system_and_a_system_for_a_state_are_refused() {
    let s = stepped_bridle();
    let state = unsafe { stancf_save(s) };
    assert!(!state.is_null(), "{}", message());
    refused_by_every_call(
        state.cast(),
        "a saved state (from stancf_save), not a system",
    );
    let s = bridle();
    let code = unsafe { stancf_restore(s, s.cast()) };
    assert_eq!(code, STANCF_INVALID_INPUT);
    assert!(
        message().contains("the state is a system handle"),
        "{}",
        message()
    );
    assert_eq!(unsafe { stancf_free_state(s.cast()) }, STANCF_INVALID_INPUT);
    assert_eq!(unsafe { stancf_free_state(state) }, STANCF_SUCCESS);
    assert_eq!(unsafe { stancf_close(s) }, STANCF_SUCCESS);
}

#[test]
fn a_state_freed_twice_or_restored_after_freeing_is_refused() {
    let s = stepped_bridle();
    let state = unsafe { stancf_save(s) };
    assert_eq!(unsafe { stancf_free_state(state) }, STANCF_SUCCESS);
    assert_eq!(unsafe { stancf_free_state(state) }, STANCF_INVALID_INPUT);
    assert!(message().contains("freed already"), "{}", message());
    let before = line_positions(s, 1);
    assert_eq!(unsafe { stancf_restore(s, state) }, STANCF_INVALID_INPUT);
    assert!(message().contains("freed already"), "{}", message());
    assert_eq!(line_positions(s, 1), before);
    assert_eq!(
        unsafe { stancf_free_state(null_mut()) },
        STANCF_INVALID_INPUT
    );
    assert!(message().contains("the state is NULL"), "{}", message());
    assert_eq!(unsafe { stancf_close(s) }, STANCF_SUCCESS);
}

#[test]
fn a_state_of_another_system_is_an_invalid_value_and_the_system_is_untouched() {
    let s = stepped_bridle();
    let other = unsafe { stancf_create(cstring(&repo("examples/fairlead-graded.toml")).as_ptr()) };
    assert!(!other.is_null(), "{}", message());
    let mut x = [0.0; 3];
    unsafe {
        assert_eq!(stancf_coupled_positions(other, x.as_mut_ptr()), 0);
        assert_eq!(stancf_init(other, x.as_ptr(), null()), STANCF_SUCCESS);
    }
    let foreign = unsafe { stancf_save(other) };
    let before: Vec<_> = (0..2).map(|l| line_positions(s, l)).collect();
    assert_eq!(unsafe { stancf_restore(s, foreign) }, STANCF_INVALID_VALUE);
    let m = message();
    assert!(
        m.contains(
            "a state saved from another system (1 line, 2 points) cannot be restored into \
             this one (2 lines, 3 points)"
        ),
        "{m}"
    );
    let mut lines = 0u32;
    assert_eq!(unsafe { stancf_nlines(s, &mut lines) }, STANCF_SUCCESS);
    assert_eq!(lines, 2);
    assert_eq!(
        (0..2).map(|l| line_positions(s, l)).collect::<Vec<_>>(),
        before
    );
    unsafe {
        assert_eq!(stancf_free_state(foreign), STANCF_SUCCESS);
        assert_eq!(stancf_close(other), STANCF_SUCCESS);
        assert_eq!(stancf_close(s), STANCF_SUCCESS);
    }
}

#[test]
fn a_state_restores_into_a_second_handle_on_the_same_file_to_the_same_bits() {
    let first = stepped_bridle();
    let second = bridle();
    let state = unsafe { stancf_save(first) };
    assert_eq!(unsafe { stancf_restore(second, state) }, STANCF_SUCCESS);
    let step = |s| {
        let (mut f, mut t, mut dt) = ([0.0; 3], 0.0, 1e-3);
        unsafe {
            assert_eq!(stancf_time(s, &mut t), STANCF_SUCCESS);
            let code = stancf_step(s, X.as_ptr(), null(), f.as_mut_ptr(), &mut t, &mut dt);
            assert_eq!(code, STANCF_SUCCESS, "{}", message());
        }
        (f, line_positions(s, 1))
    };
    assert_eq!(step(first), step(second));
    unsafe {
        assert_eq!(stancf_free_state(state), STANCF_SUCCESS);
        assert_eq!(stancf_close(first), STANCF_SUCCESS);
        assert_eq!(stancf_close(second), STANCF_SUCCESS);
    }
}

#[test]
fn an_interval_of_too_many_internal_steps_is_an_invalid_value_until_the_bound_is_raised() {
    let s = stepped_bridle();
    let (mut f, mut t, mut dt) = ([SENTINEL; 3], 0.0, 1e6);
    let before = line_positions(s, 1);
    unsafe {
        assert_eq!(stancf_time(s, &mut t), STANCF_SUCCESS);
        let t0 = t;
        let code = stancf_step(s, X.as_ptr(), null(), f.as_mut_ptr(), &mut t, &mut dt);
        assert_eq!(code, STANCF_INVALID_VALUE);
        let m = message();
        assert!(
            m.contains("more than the 100000 one call may take")
                && m.contains("stancf_set_max_interval_steps"),
            "{m}"
        );
        assert_eq!((t, f, line_positions(s, 1)), (t0, [SENTINEL; 3], before));
        // The bridle's step is 0.15 ms: 0.003 s takes 20 steps.
        dt = 3e-3;
        assert_eq!(stancf_set_max_interval_steps(s, 19), STANCF_SUCCESS);
        let code = stancf_step(s, X.as_ptr(), null(), f.as_mut_ptr(), &mut t, &mut dt);
        assert_eq!(code, STANCF_INVALID_VALUE);
        assert!(message().contains("takes 20 steps"), "{}", message());
        assert_eq!(stancf_set_max_interval_steps(s, 20), STANCF_SUCCESS);
        let code = stancf_step(s, X.as_ptr(), null(), f.as_mut_ptr(), &mut t, &mut dt);
        assert_eq!(code, STANCF_SUCCESS, "{}", message());
        assert_eq!(stancf_set_max_interval_steps(s, 0), STANCF_INVALID_VALUE);
        assert!(message().contains("at least 1"), "{}", message());
        assert_eq!(stancf_close(s), STANCF_SUCCESS);
    }
}

#[test]
fn a_handle_a_panic_left_behind_is_refused_but_can_be_closed() {
    let s = stepped_bridle();
    let code =
        guard(|| args::with_system(s, |_| -> Result<(), Error> { panic!("a test's panic") }));
    assert_eq!(code, STANCF_UNHANDLED_ERROR);
    assert!(message().contains("a test's panic"), "{}", message());
    let mut t = SENTINEL;
    assert_eq!(unsafe { stancf_time(s, &mut t) }, STANCF_UNHANDLED_ERROR);
    assert!(message().contains("unusable") && message().contains("stancf_close"));
    assert_eq!(t, SENTINEL);
    assert_eq!(unsafe { stancf_close(s) }, STANCF_SUCCESS);
    assert_eq!(unsafe { stancf_close(s) }, STANCF_INVALID_INPUT);
}

#[test]
fn calls_on_one_handle_from_four_threads_wait_for_each_other() {
    let s = stepped_bridle() as usize;
    let threads: Vec<_> = (0..4)
        .map(|k| {
            std::thread::spawn(move || {
                let s = s as *mut StancfSystem;
                for _ in 0..20 {
                    if k == 0 {
                        assert_eq!(unsafe { stancf_init(s, X.as_ptr(), null()) }, 0);
                    }
                    let mut t = -1.0;
                    assert_eq!(unsafe { stancf_time(s, &mut t) }, STANCF_SUCCESS);
                    assert!(t >= 0.0);
                    assert_eq!(line_positions(s, 1).len(), 3 * 21);
                }
            })
        })
        .collect();
    for th in threads {
        th.join().expect("no thread failed");
    }
    assert_eq!(
        unsafe { stancf_close(s as *mut StancfSystem) },
        STANCF_SUCCESS
    );
}
