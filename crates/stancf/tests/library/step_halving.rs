//! A step that Newton fails is taken again in halves (docs/method.md
//! §11.13): until the first failure the run is the one without halvings,
//! to the bit; the failed step becomes the two half steps a simulation at
//! half the step would take from there, to the bit, its mean forces on
//! the points the means of the halves'; and the run goes on at its own
//! step length.

use crate::common::rope_systems::three_to_a_point;
use stancf::system::{straight_states, SystemSimulation, MAX_STEP_HALVINGS};
use stancf::{NewtonSettings, StepSettings, TimeScheme};

/// Three 20-element ropes to a free point, one anchor swinging, Galerkin
/// steps of 5 ms with Newton allowed 4 iterations: step 31 needs more
/// (its halves do not). A tight iteration budget stands for any step
/// Newton cannot finish (a touchdown's kink, a slack line).
fn rope_star(halvings: u32) -> SystemSimulation {
    let system = three_to_a_point(20);
    let start = straight_states(&system);
    let settings = StepSettings {
        time_step: 5e-3,
        time_scheme: TimeScheme::Galerkin,
        newton: NewtonSettings {
            max_iterations: 4,
            ..NewtonSettings::default()
        },
        ..StepSettings::default()
    };
    let mut sim = SystemSimulation::new(system, start, settings).unwrap();
    sim.set_step_halvings(halvings).unwrap();
    sim
}

/// The lines' mean forces over the last step on every point.
fn point_forces(sim: &SystemSimulation) -> Vec<[f64; 3]> {
    (0..sim.topology().points().len())
        .map(|p| sim.point_force(p))
        .collect()
}

/// Every line's coordinates and rates, and every point's state.
fn snapshot(sim: &SystemSimulation) -> Vec<f64> {
    let mut out = Vec::new();
    for l in sim.lines() {
        out.extend_from_slice(&l.state().e);
        out.extend_from_slice(&l.state().v);
    }
    for p in 0..sim.topology().points().len() {
        let (x, v) = sim.point_state(p);
        out.extend_from_slice(&x);
        out.extend_from_slice(&v);
    }
    out
}

#[test]
fn a_step_newton_fails_is_taken_in_halves_and_the_run_goes_on() {
    let mut plain = rope_star(0);
    let mut halving = rope_star(3);
    let mut failed_at = None;
    for k in 1..=200 {
        let before = plain.clone();
        let ok = halving.step().is_ok();
        assert!(ok, "step {k} failed even in eighths");
        if failed_at.is_some() {
            continue;
        }
        match plain.step() {
            Ok(_) => assert_eq!(snapshot(&plain), snapshot(&halving), "step {k}"),
            Err(e) => {
                failed_at = Some(k);
                assert!(e.to_string().contains("did not converge"), "{e}");
                // The failed step is the two half steps from the last
                // converged state.
                let mut halves = before;
                halves.set_time_step(2.5e-3);
                halves.step().unwrap();
                let first = point_forces(&halves);
                halves.step().unwrap();
                assert_eq!(snapshot(&halves), snapshot(&halving), "step {k}");
                assert_eq!(halving.time_step(), 5e-3);
                // Its mean forces on the points (what a coupling
                // interval's impulse takes) are the means of the halves'.
                let second = point_forces(&halves);
                for (p, f) in point_forces(&halving).iter().enumerate() {
                    for c in 0..3 {
                        let mean = 0.5 * (first[p][c] + second[p][c]);
                        let size = first[p]
                            .iter()
                            .chain(&second[p])
                            .fold(0.0f64, |m, x| m.max(x.abs()));
                        assert!(
                            (f[c] - mean).abs() <= 1e-12 * size,
                            "point {p}: {f:?} against the halves' mean at {c}: {mean}"
                        );
                    }
                }
            }
        }
    }
    assert_eq!(failed_at, Some(31));
    assert!((halving.time() - 1.0).abs() < 1e-12, "{}", halving.time());
}

#[test]
fn more_halvings_than_the_bound_are_refused() {
    let mut sim = rope_star(0);
    assert!(sim.set_step_halvings(MAX_STEP_HALVINGS).is_ok());
    let e = sim.set_step_halvings(MAX_STEP_HALVINGS + 1).unwrap_err();
    assert!(e.to_string().contains("step_halvings"), "{e}");
}
