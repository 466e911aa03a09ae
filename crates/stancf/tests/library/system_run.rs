//! The run of a system (docs/method.md §11.15): the single cable's step
//! count, the last step shortened to land on the duration, an observer
//! after every converged step that may stop the run.

use crate::common::rope_systems::{settings, three_to_a_point};
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

/// The balance E - W (docs/method.md §8, §11.15) of the three ropes, the
/// free point and the swinging anchor: the energies of lines and point,
/// less the work of the moving anchor, drag, damping, water and bed,
/// `sim.energies().mechanical() - sim.external_work()`. With `scheme` at
/// steps of `dt` for 0.2 s from straight, its largest departure from
/// the start over the largest kinetic plus strain energy seen.
fn balance_drift(scheme: stancf::TimeScheme, dt: f64) -> f64 {
    let system = three_to_a_point(4);
    let settings = StepSettings {
        time_step: dt,
        time_scheme: scheme,
        ..settings()
    };
    let mut sim =
        SystemSimulation::new(system.clone(), straight_states(&system), settings).unwrap();
    let start = sim.energies().mechanical() - sim.external_work();
    let (mut drift, mut scale) = (0.0f64, 0.0f64);
    run(&mut sim, 0.2, |s, _, _| {
        let en = s.energies();
        drift = drift.max((en.mechanical() - s.external_work() - start).abs());
        scale = scale.max(en.kinetic + en.strain);
        ControlFlow::Continue(())
    })
    .unwrap();
    drift / scale
}

/// The system's energy balance holds as the step's accuracy does: the
/// work of the moving anchor is the step-mean force times its
/// displacement ((M24), second order), so the drift falls by about 4
/// when the step halves (P2 and Galerkin), and stays far below the
/// watchdog's tenth of the motion's energy.
#[test]
fn a_systems_energy_balance_converges_with_the_step() {
    for scheme in [stancf::TimeScheme::P2, stancf::TimeScheme::Galerkin] {
        let coarse = balance_drift(scheme, 2e-4);
        let fine = balance_drift(scheme, 1e-4);
        eprintln!("{scheme:?}: drift {coarse:.3e} at 0.2 ms, {fine:.3e} at 0.1 ms");
        assert!(coarse < 1e-2, "{scheme:?}: {coarse}");
        assert!(fine < coarse / 3.0, "{scheme:?}: {coarse} then {fine}");
    }
}

/// P2 far above its stable step (docs/method.md §4.5): the run stops at
/// the step whose energy grew without a source, as a single cable's does,
/// instead of running on to a blown-up state.
#[test]
fn an_unstable_step_trips_the_systems_energy_watchdog() {
    let mut sim = simulation(2e-2);
    sim.set_step_halvings(0).unwrap();
    let mut observed = 0;
    let e = run(&mut sim, 5.0, |_, _, _| {
        observed += 1;
        ControlFlow::Continue(())
    })
    .expect_err("an unstable run");
    assert_eq!(e.kind, stancf::error::FailureKind::EnergyGrowth, "{e}");
    assert!(e.to_string().contains("energy came from no source"), "{e}");
    assert_eq!(observed + 1, e.step, "the growing step is not observed");
}
