//! Steps chosen by a tolerance on the end forces (docs/method.md §11.17,
//! (M23c)): step doubling on the Galerkin step's end forces at t.

use crate::common::rope_systems::three_to_a_point_stepped;
use stancf::system::{run_to_tolerance, ControlledSteps, StepControl, SystemSimulation};
use stancf::TimeScheme;
use std::ops::ControlFlow;

/// The rope system's end forces at t of every line end.
fn end_forces(sim: &SystemSimulation) -> Vec<[f64; 3]> {
    (0..3)
        .flat_map(|i| sim.end_forces_at_time(i).map(|e| e.force))
        .collect()
}

/// The forces at t of every line end at the multiples of `every` up to
/// `duration`, from fixed Galerkin steps of `dt`.
fn fixed_run(dt: f64, every: f64, duration: f64) -> Vec<(f64, Vec<[f64; 3]>)> {
    let mut sim = three_to_a_point_stepped(dt, TimeScheme::Galerkin);
    let per = (every / dt).round() as usize;
    let mut out = Vec::new();
    stancf::system::run(&mut sim, duration, |sim, _, at| {
        if at.step % per == 0 {
            out.push((sim.time(), end_forces(sim)));
        }
        ControlFlow::Continue(())
    })
    .expect("reference run");
    out
}

/// The largest relative error of the end forces of a run at `tol` (steps
/// of at most `big`) over `duration`, against `reference` at the same
/// written times, and how it stepped.
fn controlled_error(
    tol: f64,
    big: f64,
    duration: f64,
    reference: &[(f64, Vec<[f64; 3]>)],
) -> (f64, ControlledSteps) {
    let mut sim = three_to_a_point_stepped(big, TimeScheme::Galerkin);
    let control = StepControl::new(&sim, tol).unwrap();
    let mut written = Vec::new();
    let (done, steps) = run_to_tolerance(&mut sim, duration, control, |sim, _, _| {
        written.push((sim.time(), end_forces(sim)));
        ControlFlow::Continue(())
    })
    .expect("controlled run");
    assert!(done);
    assert_eq!(written.len(), reference.len());
    assert_eq!(sim.time_step(), big, "the step length is the run's again");
    // Each end's error over the larger of its force and its line's
    // weight, as the control judges it (M23c).
    let weights: Vec<f64> = sim
        .lines()
        .iter()
        .flat_map(|l| {
            let m = l.model();
            [m.material.density * m.material.area * m.cable.length * 9.81; 2]
        })
        .collect();
    let mut worst = 0.0f64;
    for ((t, got), (tr, want)) in written.iter().zip(reference) {
        assert!((t - tr).abs() < 1e-12, "written at {t}, not at {tr}");
        for ((g, w), weight) in got.iter().zip(want).zip(&weights) {
            let d = stancf::vec3::norm(stancf::vec3::sub(*g, *w));
            worst = worst.max(d / stancf::vec3::norm(*w).max(*weight));
        }
    }
    eprintln!("tol {tol:e}: largest relative error {worst:.3e}, {steps:?}");
    (worst, steps)
}

/// The rope system (three ropes to a 0.2 kg point, one anchor swinging)
/// with steps of at most 5 ms chosen at tolerances 1e-2 to 1e-5, against
/// fixed steps of 0.125 ms (their own error below 1e-7 of the forces),
/// at the 20 multiples of 5 ms to 0.1 s, each end's error over the larger
/// of its force and its line's weight as the control judges it:
/// - it writes at exactly those times and hands the step length back;
/// - each kept step's local error is within the tolerance (its halves
///   are kept, about a fifteenth of the difference where the step
///   resolves the motion), the Galerkin step is A-stable and the ropes
///   damp, so the global error is within the sum of the local ones, the
///   kept steps times the tolerance (measured: 1.2e-3, 1.1e-4, 1.1e-5,
///   1.0e-6, a tenth of the tolerance, at 49, 100, 195, 393 steps);
/// - local errors proportional to the tolerance over steps proportional
///   to its fourth root make a global error at most proportional to
///   tol^(3/4): 100 times tighter is at least 31.6 times closer; 10 times
///   is asserted (measured 112 and 103);
/// - and a tighter tolerance takes more, shorter steps.
#[test]
fn a_tighter_force_tolerance_takes_shorter_steps_and_lands_closer() {
    let (big, duration) = (5e-3, 0.1);
    let reference = fixed_run(1.25e-4, big, duration);
    let runs: Vec<(f64, f64, ControlledSteps)> = [1e-2, 1e-3, 1e-4, 1e-5]
        .into_iter()
        .map(|tol| {
            let (e, s) = controlled_error(tol, big, duration, &reference);
            (tol, e, s)
        })
        .collect();
    for &(tol, error, steps) in &runs {
        assert!(steps.longest <= big, "{steps:?}");
        assert!(error <= steps.accepted as f64 * tol, "tol {tol}: {error}");
    }
    for (loose, tight) in runs.iter().zip(&runs[2..]) {
        assert!(tight.1 <= 0.1 * loose.1, "{loose:?} {tight:?}");
        assert!(tight.2.accepted > loose.2.accepted, "{loose:?} {tight:?}");
        assert!(tight.2.longest < loose.2.longest, "{loose:?} {tight:?}");
    }
}

/// The control needs the Galerkin step and a positive, finite tolerance.
#[test]
fn a_force_tolerance_is_refused_with_p2_or_out_of_range() {
    let p2 = three_to_a_point_stepped(1e-3, TimeScheme::P2);
    let e = StepControl::new(&p2, 1e-3).unwrap_err().to_string();
    assert!(e.contains("Galerkin"), "{e}");
    let galerkin = three_to_a_point_stepped(1e-3, TimeScheme::Galerkin);
    for bad in [0.0, -1e-3, f64::NAN, f64::INFINITY] {
        let e = StepControl::new(&galerkin, bad).unwrap_err().to_string();
        assert!(e.contains("tolerance"), "{e}");
    }
}
