//! The coupling API (docs/method.md §13, docs/interface.md "Coupling"):
//! a system stepped by another code that moves its coupled points is the
//! run with the same motion prescribed, to round-off when the code calls
//! once per step and to the interpolation error of (C1)-(C2) otherwise;
//! save and restore repeat an interval to the bit.

mod common;

use common::{read_csv, repo_file, scratch, write_scenario};
use stancf::constraints::Oscillation;
use stancf::coupling::CoupledSystem;
use stancf::motion::CoupledMotion;
use stancf_cli::coupling;
use stancf_cli::run::{run_text, RunOptions};
use std::path::Path;

/// The fairlead (point 2) of examples/bridle.toml swings along all three
/// axes (so no plane holds the motion) for `duration` seconds.
const DT: f64 = 2e-4;
const START: [f64; 3] = [6.0, 0.0, 1.0];
const SWING: Oscillation = Oscillation {
    amplitude: [0.2, 0.1, 0.05],
    period: 1.0,
    phase: 0.0,
    ramp: 0.5,
};

fn bridle(scheme: &str, duration: f64) -> String {
    let text = std::fs::read_to_string(repo_file("examples/bridle.toml")).unwrap();
    let head = text.split("[[motions]]").next().unwrap();
    format!(
        "{head}[[motions]]\npoint = 2\namplitude = {:?}\nperiod = {}\nramp = {}\n\n\
         [analysis]\ntype = \"dynamic\"\ninitial = \"static\"\ntime_step = {DT}\n\
         duration = {duration}\ntime_scheme = \"{scheme}\"\nplanar_reduction = false\n\n\
         [output]\nevery = 1\n",
        SWING.amplitude, SWING.period, SWING.ramp
    )
}

/// The fairlead's position and velocity at t.
fn swing(t: f64) -> ([f64; 3], [f64; 3]) {
    CoupledMotion::Oscillation(SWING).state_at(&START, t)
}

/// `stancf run` of the scenario: the fairlead's force rows (t, f).
fn run_forces(name: &str, scenario: &str) -> Vec<(f64, [f64; 3])> {
    let dir = scratch(name);
    let path = write_scenario(&dir, "bridle.toml", scenario);
    let out = dir.join("out");
    let opts = RunOptions {
        out: Some(out.clone()),
        quiet: true,
        ..RunOptions::default()
    };
    run_text(scenario, &path, opts).unwrap();
    let (h, rows) = read_csv(&out.join("points.csv"));
    let col = |n: &str| h.iter().position(|c| c == n).unwrap();
    rows.iter()
        .filter(|r| r[col("point")] == 2.0)
        .map(|r| (r[col("t")], [r[col("fx")], r[col("fy")], r[col("fz")]]))
        .collect()
}

fn handle(scenario: &str) -> CoupledSystem {
    let opened = coupling::from_text(scenario, Path::new("bridle.toml")).unwrap();
    assert_eq!(opened.coupled_ids, vec![2]);
    opened.handle
}

fn distance(a: &[f64], b: &[f64]) -> f64 {
    a.iter()
        .zip(b)
        .map(|(x, y)| (x - y).powi(2))
        .sum::<f64>()
        .sqrt()
}

fn largest(rows: &[(f64, [f64; 3])]) -> f64 {
    rows.iter()
        .map(|(_, f)| distance(f, &[0.0; 3]))
        .fold(0.0, f64::max)
}

#[test]
fn a_coupling_code_calling_once_per_step_reproduces_the_prescribed_run() {
    for scheme in ["p2", "galerkin"] {
        let steps = 400;
        let scenario = bridle(scheme, steps as f64 * DT);
        let run = run_forces(&format!("coupling_once_{scheme}"), &scenario);
        assert_eq!(run.len(), steps + 1);
        let mut h = handle(&scenario);
        let f0 = h.initialize(&START, Some(&[0.0; 3])).unwrap();
        // Round-off: the static solve and every step see the same numbers;
        // only t_k = k dt against the run's accumulated t differ, in the
        // last bits of the motion's argument.
        let tol = 1e-10 * largest(&run);
        assert!(
            distance(&f0, &run[0].1) <= tol,
            "{scheme}: static {f0:?} vs {:?}",
            run[0].1
        );
        let mut worst: f64 = 0.0;
        for (t, f_run) in run.iter().skip(1) {
            // The run's own time, accumulated step by step.
            let tk = h.time() + DT;
            assert!((t - tk).abs() < 1e-12);
            let (r, v) = swing(tk);
            let f = h.step_to(tk, &r, Some(&v)).unwrap();
            assert_eq!(f.steps, 1);
            worst = worst.max(distance(&f.last_step, f_run));
            assert_eq!(f.last_step, f.interval_mean, "one step: the same mean");
        }
        println!(
            "{scheme}: worst force difference {worst:e} N of {} N",
            largest(&run)
        );
        assert!(worst <= tol, "{scheme}: {worst:e} N above {tol:e} N");
    }
}

/// The largest distance between the fairlead's motion and its piecewise
/// cubic (C2) through the motion's values and rates every `interval`
/// seconds, over [0, end] (sampled 40 times per interval).
fn interpolation_error(interval: f64, end: f64) -> f64 {
    let n = (end / interval).round() as usize;
    let mut worst: f64 = 0.0;
    for k in 0..n {
        let (t0, t1) = (k as f64 * interval, (k + 1) as f64 * interval);
        let ((r0, v0), (r1, v1)) = (swing(t0), swing(t1));
        let piece = stancf::motion::MotionInterval {
            t0,
            duration: interval,
            start: r0,
            end: r1,
            rates: Some((v0, v1)),
        };
        for j in 1..40 {
            let t = t0 + interval * j as f64 / 40.0;
            worst = worst.max(distance(&piece.state(t).0, &swing(t).0));
        }
    }
    worst
}

#[test]
fn longer_coupling_intervals_differ_from_the_run_by_the_interpolation_error() {
    let end = 1.0;
    let scenario = bridle("galerkin", end);
    let run = run_forces("coupling_intervals", &scenario);
    // The fairlead's static stiffness |dF/dx| along the motion, by central
    // differences of the equilibrium (the force error of a position error
    // at rates well below the lines' first natural frequency).
    let mut h = handle(&scenario);
    let d = 1e-4;
    let dir = [0.2 / 0.229, 0.1 / 0.229, 0.05 / 0.229];
    let at = |s: f64| -> [f64; 3] { std::array::from_fn(|c| START[c] + s * dir[c]) };
    let fp = h.initialize(&at(d), None).unwrap();
    let fm = h.initialize(&at(-d), None).unwrap();
    let stiffness = distance(&fp, &fm) / (2.0 * d);
    let mut errors = Vec::new();
    for steps_per_interval in [2.5, 10.0] {
        let interval = steps_per_interval * DT;
        // Compare impulses over spans that hold whole intervals and whole
        // run steps: 5 steps (two intervals of 2.5) or 10 steps (one).
        let span_steps = if steps_per_interval == 2.5 { 5 } else { 10 };
        let per_span = span_steps as f64 / steps_per_interval;
        h.initialize(&START, Some(&[0.0; 3])).unwrap();
        let mut worst: f64 = 0.0;
        let mut k = 0;
        let n = (end / interval).round() as usize;
        let mut impulse = [0.0; 3];
        for i in 1..=n {
            let t = i as f64 * interval;
            let (r, v) = swing(t);
            let f = h.step_to(t, &r, Some(&v)).unwrap();
            assert_eq!(f.steps, steps_per_interval.ceil() as usize);
            for c in 0..3 {
                impulse[c] += f.interval_mean[c] * interval;
            }
            if i % per_span as usize == 0 {
                let run_impulse: [f64; 3] = std::array::from_fn(|c| {
                    (k + 1..=k + span_steps)
                        .map(|j| run[j].1[c] * DT)
                        .sum::<f64>()
                });
                let span = span_steps as f64 * DT;
                worst = worst.max(distance(&impulse, &run_impulse) / span);
                k += span_steps;
                impulse = [0.0; 3];
            }
        }
        let e = interpolation_error(interval, end);
        let bound = 2.0 * stiffness * e;
        println!(
            "{steps_per_interval} steps per interval: mean force off by {worst:e} N; \
             interpolation error {e:e} m x stiffness {stiffness:e} N/m = {:e} N",
            stiffness * e
        );
        assert!(worst <= bound, "{worst:e} N above {bound:e} N");
        errors.push(worst);
    }
    // (C2) is fourth order: 4 times the interval, 4^4 = 256 times the
    // error (at least a hundredfold, the time discretization of the
    // shorter steps aside).
    assert!(
        errors[1] / errors[0] > 100.0,
        "ratio {}",
        errors[1] / errors[0]
    );
}

#[test]
fn save_step_restore_step_is_identical_to_the_bit() {
    let scenario = bridle("galerkin", 1.0);
    let mut h = handle(&scenario);
    h.initialize(&START, Some(&[0.0; 3])).unwrap();
    let mut t = 0.0;
    let mut advance = |h: &mut CoupledSystem, t: &mut f64| {
        *t += 3.7 * DT;
        let (r, v) = swing(*t + 0.6);
        h.step_to(*t, &r, Some(&v)).unwrap()
    };
    for _ in 0..20 {
        advance(&mut h, &mut t);
    }
    let saved = h.save();
    let t_saved = t;
    let first: Vec<_> = (0..10).map(|_| advance(&mut h, &mut t)).collect();
    let nodes_first = h.line_nodes(1).unwrap();
    h.restore(&saved);
    t = t_saved;
    let second: Vec<_> = (0..10).map(|_| advance(&mut h, &mut t)).collect();
    assert_eq!(first, second);
    assert_eq!(nodes_first, h.line_nodes(1).unwrap());
}

#[test]
fn bad_calls_are_refused_and_the_handle_goes_on() {
    let scenario = bridle("galerkin", 1.0);
    let mut h = handle(&scenario);
    let e = h.step_to(DT, &START, None).unwrap_err().to_string();
    assert!(e.contains("initialize"), "{e}");
    let e = h.initialize(&[0.0; 4], None).unwrap_err().to_string();
    assert!(e.contains("expected 3 values"), "{e}");
    let e = h
        .initialize(&[6.0, f64::NAN, 1.0], None)
        .unwrap_err()
        .to_string();
    assert!(e.contains("x[1]"), "{e}");
    h.initialize(&START, None).unwrap();
    let e = h.step_to(0.0, &START, None).unwrap_err().to_string();
    assert!(e.contains("must come after"), "{e}");
    let f = h.step_to(DT, &START, None).unwrap();
    assert!(f.last_step.iter().all(|x| x.is_finite()));
    let single = std::fs::read_to_string(repo_file("examples/pendulum.toml")).unwrap();
    let e = coupling::from_text(&single, Path::new("pendulum.toml"))
        .err()
        .unwrap()
        .to_string();
    assert!(e.contains("single cable"), "{e}");
}
