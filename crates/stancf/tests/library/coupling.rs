//! The coupling handle against a careless host (docs/method.md §13,
//! issue 28): a state is restored only into its own system, one call
//! takes a bounded number of internal steps, and a caller may stop a
//! call between two of them.

use crate::common::rope_systems::{independent_ropes, settings, three_to_a_point};
use stancf::coupling::{CoupledSystem, CouplingError, MAX_COUPLED_SPEED, MAX_INTERVAL_STEPS};
use stancf::system::System;
use stancf::StaticSettings;

/// The handle of `system` (seeded by itself, in air) and where its
/// coupled points are.
fn handle(system: System) -> (CoupledSystem, Vec<f64>) {
    let h = CoupledSystem::new(
        system.clone(),
        system,
        StaticSettings::default(),
        settings(),
    )
    .expect("handle");
    let x = h
        .coupled_points()
        .iter()
        .flat_map(|&p| h.system().points()[p].position)
        .collect();
    (h, x)
}

/// [`handle`] initialized where its coupled points are and stepped 3
/// times by `dt`, the points moving 1 mm along x each step.
fn stepped(system: System) -> (CoupledSystem, Vec<f64>) {
    let (mut h, mut x) = handle(system);
    h.initialize(&x, None).expect("initialize");
    for k in 1..=3 {
        x[0] += 1e-3;
        h.step_to(k as f64 * 1e-4, &x, None).expect("step");
    }
    (h, x)
}

/// Every line's node positions.
fn nodes(h: &CoupledSystem) -> Vec<Vec<[f64; 3]>> {
    (0..h.system().lines().len())
        .map(|i| h.line_nodes(i).expect("initialized"))
        .collect()
}

fn input_message(e: CouplingError) -> String {
    match e {
        CouplingError::Input(m) => m.to_string(),
        other => panic!("not an input error: {other}"),
    }
}

#[test]
fn a_state_of_another_system_is_refused_and_the_handle_is_untouched() {
    let (mut three, x) = stepped(three_to_a_point(4));
    let (one, _) = stepped(independent_ropes(&[0], 1, 4));
    let before = (three.time(), nodes(&three));
    let mut twin = three.clone();
    let m = input_message(three.restore(&one.save()).unwrap_err());
    assert!(
        m.contains(
            "a state saved from another system (1 line, 2 points) cannot be restored into \
             this one (3 lines, 4 points)"
        ),
        "{m}"
    );
    assert_eq!((three.time(), nodes(&three)), before);
    // It steps on as if nothing had been tried.
    let t = three.time() + 1e-4;
    assert_eq!(
        three.step_to(t, &x, None).unwrap(),
        twin.step_to(t, &x, None).unwrap()
    );
}

#[test]
fn a_state_of_a_system_of_as_many_lines_and_points_but_other_lines_is_refused() {
    let (mut four, _) = stepped(independent_ropes(&[0], 1, 4));
    let (six, _) = stepped(independent_ropes(&[0], 1, 6));
    let m = input_message(four.restore(&six.save()).unwrap_err());
    assert!(
        m.contains("(1 line, 2 points)") && m.contains("other lines"),
        "{m}"
    );
    assert_eq!(four.line_nodes(0).unwrap().len(), 5);
}

#[test]
fn a_state_of_another_handle_of_the_same_system_restores_to_the_same_bits() {
    let (first, x) = stepped(three_to_a_point(4));
    let (mut second, _) = handle(three_to_a_point(4));
    second.restore(&first.save()).expect("the same system");
    let mut first = first;
    let t = first.time() + 2.5e-4;
    assert_eq!(
        first.step_to(t, &x, None).unwrap(),
        second.step_to(t, &x, None).unwrap()
    );
    assert_eq!(nodes(&first), nodes(&second));
}

#[test]
fn a_state_saved_before_initialize_restores_into_its_own_system() {
    let (mut h, x) = handle(three_to_a_point(4));
    let fresh = h.save();
    h.initialize(&x, None).unwrap();
    h.step_to(1e-4, &x, None).unwrap();
    h.restore(&fresh).expect("its own state");
    assert!(h.simulation().is_none() && h.time() == 0.0);
    let m = input_message(h.step_to(1e-4, &x, None).unwrap_err());
    assert!(m.contains("initialize"), "{m}");
}

#[test]
fn an_interval_of_more_steps_than_the_bound_is_refused_before_anything_moves() {
    assert_eq!(MAX_INTERVAL_STEPS, 100_000);
    let (mut h, x) = stepped(three_to_a_point(4));
    let (before, mut twin) = ((h.time(), nodes(&h)), h.clone());
    let mut far = x.clone();
    far[0] += 1.0;
    // 1e6 s in steps of 1e-4 s: 1e10 steps.
    let m = input_message(h.step_to(1e6, &far, None).unwrap_err());
    for part in [
        "the interval of 1e6 s from 0.0003 s to 1e6 s takes 9999999997 steps of at most the \
         time step, 0.0001 s",
        "more than the 100000 one call may take",
        "set_max_interval_steps",
    ] {
        assert!(m.contains(part), "{part:?} not in {m}");
    }
    assert_eq!((h.time(), nodes(&h)), before);
    let t = h.time() + 1e-4;
    assert_eq!(
        h.step_to(t, &x, None).unwrap(),
        twin.step_to(t, &x, None).unwrap()
    );
}

#[test]
fn the_bound_on_internal_steps_is_set_per_handle_and_is_at_least_one() {
    let (mut h, x) = stepped(three_to_a_point(4));
    let m = h.set_max_interval_steps(0).unwrap_err().to_string();
    assert!(
        m.contains("max_interval_steps") && m.contains("at least 1"),
        "{m}"
    );
    assert_eq!(h.max_interval_steps(), MAX_INTERVAL_STEPS);
    h.set_max_interval_steps(10).unwrap();
    let t0 = h.time();
    let m = input_message(h.step_to(t0 + 11e-4, &x, None).unwrap_err());
    assert!(
        m.contains("takes 11 steps") && m.contains("the 10 one call"),
        "{m}"
    );
    assert_eq!(h.step_to(t0 + 10e-4, &x, None).unwrap().steps, 10);
}

#[test]
fn a_stopped_interval_stays_at_its_last_converged_step_and_the_next_call_continues() {
    let (mut h, x) = stepped(three_to_a_point(4));
    let mut whole = h.clone();
    let (t0, start) = (h.time(), x.clone());
    let mut end = x.clone();
    end[0] += 1e-2;
    let t1 = t0 + 10e-4;
    let mut asked = 0;
    let e = h
        .step_to_with(t1, &end, None, &mut || {
            asked += 1;
            asked > 3
        })
        .unwrap_err();
    let CouplingError::Interrupted { time } = e else {
        panic!("not an interruption: {e}")
    };
    // Asked after steps 1 to 4, stopped after the 4th.
    assert!((time - (t0 + 4e-4)).abs() < 1e-15, "{time}");
    assert_eq!(h.time(), time);
    // The coupled point (index 2) where the interval's line has it.
    let at = h.point(2).unwrap().position;
    let want = start[0] + 0.4 * (end[0] - start[0]);
    assert!((at[0] - want).abs() < 1e-15, "{} vs {want}", at[0]);
    // The rest of the interval from there: the forces of one call over
    // the whole interval, to round-off of the motion's sums.
    let rest = h.step_to(t1, &end, None).unwrap();
    let all = whole.step_to(t1, &end, None).unwrap();
    assert_eq!(rest.steps, 6);
    for (a, b) in rest.last_step.iter().zip(&all.last_step) {
        assert!((a - b).abs() <= 1e-9 * b.abs().max(1.0), "{a} vs {b}");
    }
}

#[test]
fn a_call_asked_to_stop_at_once_still_takes_one_step_and_asks_nothing_after_the_last() {
    let (mut h, x) = stepped(three_to_a_point(4));
    let t0 = h.time();
    let e = h
        .step_to_with(t0 + 5e-4, &x, None, &mut || true)
        .unwrap_err();
    assert_eq!(e, CouplingError::Interrupted { time: h.time() });
    assert!((h.time() - (t0 + 1e-4)).abs() < 1e-15);
    let mut asked = 0;
    let t1 = h.time() + 1e-4;
    let one = h.step_to_with(t1, &x, None, &mut || {
        asked += 1;
        true
    });
    assert_eq!((one.unwrap().steps, asked), (1, 0));
}

#[test]
fn a_stopped_static_solve_leaves_the_handle_as_it_was() {
    let (mut h, x) = handle(three_to_a_point(4));
    let e = h.initialize_with(&x, None, &mut || true).unwrap_err();
    assert_eq!(e, CouplingError::Interrupted { time: 0.0 });
    assert!(h.simulation().is_none());
    let (mut h, x) = stepped(three_to_a_point(4));
    let before = (h.time(), nodes(&h));
    assert!(h.initialize_with(&x, None, &mut || true).is_err());
    assert_eq!((h.time(), nodes(&h)), before);
}

/// Item 17 of issue 28: a host that moves a coupled point 1 km in 0.1 s
/// gave a wrong position (another unit or frame), not a motion.
#[test]
fn a_coupled_point_moved_faster_than_the_bound_is_refused_and_nothing_moves() {
    let (mut h, mut x) = stepped(three_to_a_point(4));
    let t = h.time();
    let before = nodes(&h);
    let mut far = x.clone();
    far[0] += 1000.0;
    let e = h.step_to(t + 0.1, &far, None).unwrap_err();
    let m = input_message(e);
    assert!(
        m.contains("x[0..3]") && m.contains("10000 m/s") && m.contains("100 m/s"),
        "{m}"
    );
    assert_eq!(h.time(), t);
    assert_eq!(nodes(&h), before);
    // Below the bound the motion is the solver's to follow (or fail).
    x[0] += 0.5 * MAX_COUPLED_SPEED * 1e-4;
    let r = h.step_to(t + 1e-4, &x, None);
    assert!(!matches!(r, Err(CouplingError::Input(_))), "{r:?}");
}

/// Velocities the host gives are bounded as its positions' jumps are: a
/// fairlead at 1e6 m/s (or 1e300) is a wrong value, refused before
/// anything moves; a position 1e300 m away too.
#[test]
fn a_coupled_velocity_or_position_beyond_the_bounds_is_refused_and_nothing_moves() {
    let (mut h, x) = stepped(three_to_a_point(4));
    let t = h.time();
    let before = nodes(&h);
    for speed in [1e300, 1e6, 150.0] {
        let xd = vec![speed, 0.0, 0.0];
        let m = input_message(h.step_to(t + 1e-4, &x, Some(&xd)).unwrap_err());
        assert!(m.contains("xd[0..3]") && m.contains("100 m/s"), "{m}");
    }
    let mut far = x.clone();
    far[2] = -1e300;
    let m = input_message(h.step_to(t + 1e-4, &far, None).unwrap_err());
    assert!(m.contains("x[2]") && m.contains("1e7 m"), "{m}");
    assert_eq!(h.time(), t);
    assert_eq!(nodes(&h), before);
    // And at initialize, the handle untouched.
    let (mut fresh, x0) = handle(three_to_a_point(4));
    let mut far = x0.clone();
    far[2] = -1e300;
    let m = input_message(fresh.initialize(&far, None).unwrap_err());
    assert!(m.contains("x[2]"), "{m}");
    assert!(fresh.simulation().is_none());
}

/// A next time a round-off after the time reached is told so, in short
/// numbers (it read "must come after the time reached" with 300 zeros).
#[test]
fn an_interval_too_short_to_step_is_told_so_in_short_numbers() {
    let (mut h, x) = stepped(three_to_a_point(4));
    let t = h.time();
    for dt in [1e-17, 1e-300, 5e-324] {
        let m = input_message(h.step_to(t + dt, &x, None).unwrap_err());
        assert!(m.len() < 300, "{m}");
        assert!(
            m.contains("too short to step") || m.contains("must come after"),
            "{m}"
        );
    }
    assert_eq!(h.time(), t);
}

#[test]
fn a_coupled_system_stepped_to_a_time_ends_there_in_equal_steps() {
    // dt 0.3 ms over 1 ms: the fewest equal steps no longer than dt, four
    // of 0.25 ms (§13.3), ending on the time asked for, as a run does.
    let system = three_to_a_point(4);
    let step = stancf::StepSettings {
        time_step: 3e-4,
        ..settings()
    };
    let mut h = CoupledSystem::new(system.clone(), system, StaticSettings::default(), step)
        .expect("handle");
    let x: Vec<f64> = h
        .coupled_points()
        .iter()
        .flat_map(|&p| h.system().points()[p].position)
        .collect();
    h.initialize(&x, None).expect("initialize");
    let t0 = h.time();
    let forces = h.step_to(t0 + 1e-3, &x, None).expect("step");
    assert_eq!(forces.steps, 4);
    assert!((h.time() - (t0 + 1e-3)).abs() <= 1e-18, "{}", h.time());
}
