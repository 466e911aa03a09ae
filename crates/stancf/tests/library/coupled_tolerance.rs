//! A coupling code's intervals crossed in steps chosen by a tolerance on
//! the end forces (docs/method.md §11.17, (M23c); §13.3): the host
//! couples at its own rate and the handle takes the internal steps the
//! tolerance needs.

use crate::common::rope_systems::{three_to_a_point, SWING};
use stancf::coupling::{CoupledForces, CoupledSystem};
use stancf::{NewtonSettings, StaticSettings, StepSettings, TimeScheme};

/// Where the host puts the swinging anchor of [`three_to_a_point`] at t,
/// and how fast it moves it: [`SWING`]'s amplitude and period, from rest
/// (x = x0 + a (1 - cos w t)), so that the lines' static start and the
/// host's first velocity agree.
fn host_anchor(t: f64) -> (Vec<f64>, Vec<f64>) {
    let w = 2.0 * std::f64::consts::PI / SWING.period;
    let a = SWING.amplitude[0];
    let x = vec![-1.0 + a * (1.0 - (w * t).cos()), -1.7, 0.5];
    let v = vec![a * w * (w * t).sin(), 0.0, 0.0];
    (x, v)
}

/// The rope system's handle (4 elements a line, Galerkin, Newton to
/// 1e-12) of step length `dt`, with `tolerance` if given, initialized at
/// the anchor's place at 0.
fn handle(dt: f64, tolerance: Option<f64>) -> CoupledSystem {
    let system = three_to_a_point(4);
    let settings = StepSettings {
        time_step: dt,
        time_scheme: TimeScheme::Galerkin,
        newton: NewtonSettings {
            tolerance: 1e-12,
            ..NewtonSettings::default()
        },
        ..StepSettings::default()
    };
    let h = CoupledSystem::new(system.clone(), system, StaticSettings::default(), settings)
        .expect("handle");
    let mut h = match tolerance {
        Some(tol) => h.with_force_tolerance(tol).expect("tolerance"),
        None => h,
    };
    let (x, xd) = host_anchor(0.0);
    h.initialize(&x, Some(&xd)).expect("initialize");
    h
}

/// The host's calls every `every` up to `duration`: each call's forces.
fn coupled_run(h: &mut CoupledSystem, every: f64, duration: f64) -> Vec<CoupledForces> {
    let calls = (duration / every).round() as usize;
    (1..=calls)
        .map(|k| {
            let t = k as f64 * every;
            let (x, xd) = host_anchor(t);
            h.step_to(t, &x, Some(&xd)).expect("coupled step")
        })
        .collect()
}

/// The largest difference of the interval means of `run` from
/// `reference`'s, over the largest force of the reference.
fn largest_difference(run: &[CoupledForces], reference: &[CoupledForces]) -> f64 {
    let scale = reference
        .iter()
        .flat_map(|f| f.interval_mean.iter())
        .fold(0.0f64, |m, v| m.max(v.abs()));
    run.iter()
        .zip(reference)
        .flat_map(|(a, b)| a.interval_mean.iter().zip(&b.interval_mean))
        .fold(0.0f64, |m, (a, b)| m.max((a - b).abs() / scale))
}

/// A host couples the rope system every 5 ms for 0.1 s, the handle's
/// step length 5 ms; against 0.125 ms equal steps (their own error below
/// 1e-7 of the forces, as in step_control.rs):
/// - every call ends at the host's time and each interval's kept steps
///   (taken as halves, so an even count) are at least one;
/// - the forces at 1e-3 and 1e-5: each kept step's local error is within
///   the tolerance, the Galerkin step is A-stable and the ropes damp, so
///   the mean force over an interval, which the steps' means make up, is
///   off by at most the kept steps times the tolerance (the forces'
///   largest as the scale: the control's per-end scale is that or the
///   line's weight, at most this);
/// - 100 times tighter lands at least 10 times closer (the global error
///   goes at most as tol^(3/4), 31.6 times) and takes more steps;
/// - equal steps of the step length are further off than the loose
///   tolerance, which is why the tolerance shortens them.
#[test]
fn a_coupled_system_whose_steps_a_tolerance_chooses_follows_the_finely_stepped_one() {
    let (every, duration) = (5e-3, 0.1);
    let reference = coupled_run(&mut handle(1.25e-4, None), every, duration);
    let coarse = coupled_run(&mut handle(every, None), every, duration);
    let mut errors = Vec::new();
    for tol in [1e-3, 1e-5] {
        let mut h = handle(every, Some(tol));
        assert_eq!(h.force_tolerance(), Some(tol));
        let run = coupled_run(&mut h, every, duration);
        assert!((h.time() - duration).abs() < 1e-15, "{}", h.time());
        assert!(run.iter().all(|f| f.steps >= 2 && f.steps % 2 == 0));
        let kept: usize = run.iter().map(|f| f.steps / 2).sum();
        let error = largest_difference(&run, &reference);
        eprintln!("tol {tol:e}: {kept} kept steps, interval means off by {error:.3e}");
        assert!(
            error <= kept as f64 * tol,
            "tol {tol}: {error} over {kept} steps"
        );
        errors.push((error, kept));
    }
    let coarse_error = largest_difference(&coarse, &reference);
    eprintln!("equal 5 ms steps: off by {coarse_error:.3e}");
    assert!(errors[1].0 <= 0.1 * errors[0].0, "{errors:?}");
    assert!(errors[1].1 > errors[0].1, "{errors:?}");
    assert!(coarse_error > errors[0].0, "{coarse_error} {errors:?}");
}

/// A predictor-corrector host repeats an interval from a saved state: the
/// tolerance's next step is part of the state, so the repeated interval
/// and the one after it are the same bits as a run that never went back.
#[test]
fn a_repeated_interval_of_a_tolerance_handle_steps_on_to_the_same_bits() {
    let every = 5e-3;
    let mut straight = handle(every, Some(1e-4));
    let once = coupled_run(&mut straight, every, 4.0 * every);
    let mut repeated = handle(every, Some(1e-4));
    coupled_run(&mut repeated, every, 2.0 * every);
    let saved = repeated.save();
    let (x, xd) = host_anchor(3.0 * every);
    let wrong: Vec<f64> = x.iter().map(|c| c + 1e-3).collect();
    repeated
        .step_to(3.0 * every, &wrong, Some(&xd))
        .expect("a guess");
    repeated.restore(&saved).expect("restore");
    let mut again = Vec::new();
    for k in 3..=4 {
        let t = k as f64 * every;
        let (x, xd) = host_anchor(t);
        again.push(repeated.step_to(t, &x, Some(&xd)).expect("step"));
    }
    assert_eq!(&once[2..], &again[..]);
}

/// A tolerance that needs more internal steps than one call may take
/// fails the call at the time it reached (a converged step), naming the
/// bound; the next call continues from there.
#[test]
fn a_tolerance_needing_more_steps_than_a_call_may_take_stops_at_its_last_kept_step() {
    let every = 5e-3;
    let mut h = handle(every, Some(1e-5));
    let run = coupled_run(&mut h, every, 2.0 * every);
    assert!(run[1].steps > 4, "{}", run[1].steps);
    h.set_max_interval_steps(4).unwrap();
    let (x, xd) = host_anchor(3.0 * every);
    let e = h
        .step_to(3.0 * every, &x, Some(&xd))
        .unwrap_err()
        .to_string();
    assert!(e.contains("max_interval_steps"), "{e}");
    let reached = h.time();
    assert!(reached > 2.0 * every && reached < 3.0 * every, "{reached}");
    h.set_max_interval_steps(1000).unwrap();
    h.step_to(3.0 * every, &x, Some(&xd))
        .expect("the rest of the interval");
    assert!((h.time() - 3.0 * every).abs() < 1e-15);
}
