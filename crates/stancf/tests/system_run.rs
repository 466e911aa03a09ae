//! The run of a system (docs/method.md §11.15): the single cable's step
//! count, the last step shortened to land on the duration, an observer
//! after every converged step that may stop the run.

#[path = "common/rope_systems.rs"]
mod rope_systems;

use rope_systems::{settings, three_to_a_point};
use stancf::system::{run, straight_states, RunProgress, SystemSimulation};
use stancf::StepSettings;
use std::ops::ControlFlow;

/// Three ropes to a free point, from straight, in steps of `dt`.
fn simulation(dt: f64) -> SystemSimulation {
    let system = three_to_a_point(4);
    let start = straight_states(&system);
    let settings = StepSettings {
        time_step: dt,
        ..settings()
    };
    SystemSimulation::new(system, start, settings).unwrap()
}

#[test]
fn a_system_ends_on_its_duration_with_a_shortened_last_step() {
    let mut sim = simulation(3e-4);
    let mut seen = Vec::new();
    let done = run(&mut sim, 1e-3, |s, rep, at| {
        seen.push((at, s.time(), rep.t, s.time_step()));
        ControlFlow::Continue(())
    })
    .unwrap();
    assert!(done);
    assert_eq!(sim.steps(), 4);
    assert!((sim.time() - 1e-3).abs() <= 1e-18, "{}", sim.time());
    let steps: Vec<RunProgress> = seen.iter().map(|s| s.0).collect();
    assert_eq!(
        steps,
        (1..=4)
            .map(|step| RunProgress { step, steps: 4 })
            .collect::<Vec<_>>()
    );
    // Three steps of dt, the last one of what is left, 0.1 ms.
    for (at, t, _, h) in &seen[..3] {
        assert_eq!(*h, 3e-4, "step {}", at.step);
        assert!((t - at.step as f64 * 3e-4).abs() < 1e-18);
    }
    assert!((seen[3].3 - 1e-4).abs() < 1e-18, "{}", seen[3].3);
    assert!(seen[3].0.is_last());
}

#[test]
fn a_whole_number_of_steps_is_the_run_of_single_steps_to_the_bit() {
    let mut by_run = simulation(2e-4);
    let mut by_hand = simulation(2e-4);
    assert!(run(&mut by_run, 1e-3, |_, _, _| ControlFlow::Continue(())).unwrap());
    for _ in 0..5 {
        by_hand.step().unwrap();
    }
    assert_eq!(by_run.steps(), 5);
    assert_eq!(by_run.time_step(), 2e-4, "no step was shortened");
    for (a, b) in by_run.lines().iter().zip(by_hand.lines()) {
        assert_eq!(a.state().e, b.state().e);
        assert_eq!(a.state().v, b.state().v);
    }
    assert_eq!(by_run.point_state(3), by_hand.point_state(3));
}

#[test]
fn an_observer_that_breaks_stops_the_run_after_that_step() {
    let mut sim = simulation(1e-4);
    let done = run(&mut sim, 1e-3, |_, _, at| {
        if at.step == 3 {
            ControlFlow::Break(())
        } else {
            ControlFlow::Continue(())
        }
    })
    .unwrap();
    assert!(!done);
    assert_eq!(sim.steps(), 3);
}
