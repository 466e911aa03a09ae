//! The coupling API (docs/method.md §13, docs/interface.md "Coupling"):
//! a system stepped by another code that moves its coupled points is the
//! run with the same motion prescribed, to round-off when the code calls
//! once per step and to the interpolation error of (K1)-(K2) otherwise;
//! save and restore repeat an interval to the bit.

use crate::common::{one_rope, read_csv, repo_file, scratch, write_scenario};
use stancf::constraints::Oscillation;
use stancf::coupling::CoupledSystem;
use stancf::motion::CoupledMotion;
use stancf_cli::coupling;
use stancf_cli::run::{run_text, RunOptions};
use std::path::Path;

/// The fairlead (point 2) swings along all three axes (so no plane holds
/// the motion) about its position START.
const DT: f64 = 2e-4;
const START: [f64; 3] = [6.0, 0.0, 1.0];
const SWING: Oscillation = Oscillation {
    amplitude: [0.2, 0.1, 0.05],
    period: 1.0,
    phase: 0.0,
    ramp: 0.5,
};

/// examples/bridle.toml (two ropes from an anchor and the fairlead at
/// START to a clump weight at a free point) with the fairlead swinging
/// for `duration` seconds.
fn bridle(scheme: &str, duration: f64) -> String {
    let text = std::fs::read_to_string(repo_file("examples/bridle.toml")).unwrap();
    swinging(
        text.split("[[motions]]").next().unwrap(),
        scheme,
        duration,
        DT,
    )
}

/// One 6 m rope hanging from an anchor at the origin to the fairlead at
/// START, swinging for `duration` seconds in steps of `dt`.
fn hanging_rope(scheme: &str, duration: f64, dt: f64) -> String {
    let head = one_rope(
        "hanging rope",
        "ei = 0.0",
        ("coupled", START),
        (1, 7.0, 28),
        "",
    );
    let head = format!("{head}[system]\ngravity = [0.0, 0.0, -9.81]\n");
    swinging(&head, scheme, duration, dt)
}

/// A system `head` with point 2 swinging along SWING (a TOML scenario).
fn swinging(head: &str, scheme: &str, duration: f64, dt: f64) -> String {
    format!(
        "{head}[[motions]]\npoint = 2\namplitude = {:?}\nperiod = {}\nramp = {}\n\n\
         [analysis]\ntype = \"dynamic\"\ninitial = \"static\"\ntime_step = {dt}\n\
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
    let path = write_scenario(&dir, "swinging.toml", scenario);
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
    let opened = coupling::from_text(scenario, Path::new("swinging.toml")).unwrap();
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

/// The largest errors in position and in acceleration of the piecewise
/// cubic (K2) through the fairlead's positions and velocities every
/// `interval` seconds, against the motion itself, over [0, end] (sampled
/// 40 times per interval; the acceleration by central differences of the
/// displacement from START over 1 % of the interval: exact for the cubic,
/// 1e-7 m/s^2 off for the swing).
fn interpolation_errors(interval: f64, end: f64) -> (f64, f64) {
    let n = (end / interval).round() as usize;
    let (mut position, mut acceleration): (f64, f64) = (0.0, 0.0);
    let accel = |f: &dyn Fn(f64) -> [f64; 3], t: f64| -> [f64; 3] {
        let e = 1e-2 * interval;
        let (a, b, c) = (f(t - e), f(t), f(t + e));
        std::array::from_fn(|k| (a[k] - 2.0 * b[k] + c[k]) / (e * e))
    };
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
        let from_start = |r: [f64; 3]| -> [f64; 3] { std::array::from_fn(|c| r[c] - START[c]) };
        let cubic = |t: f64| from_start(piece.state(t).0);
        let exact = |t: f64| from_start(swing(t).0);
        for j in 1..40 {
            let t = t0 + interval * j as f64 / 40.0;
            position = position.max(distance(&cubic(t), &exact(t)));
            acceleration = acceleration.max(distance(&accel(&cubic, t), &accel(&exact, t)));
        }
    }
    (position, acceleration)
}

#[test]
fn longer_coupling_intervals_differ_from_the_run_by_the_interpolation_error() {
    // A Galerkin step of 2 ms: the coupling intervals of 2.5 and 10 steps
    // (5 and 20 ms) are long enough for (K2) to differ visibly from the
    // motion at 1 Hz.
    let (dt, end) = (2e-3, 1.0);
    let mass = 0.08 * 7.0;
    let mut errors = Vec::new();
    for steps_per_interval in [2.5f64, 10.0] {
        let interval = steps_per_interval * dt;
        // The handle splits an interval into ceil(2.5) = 3 steps of
        // interval / 3: the run compared takes the same steps, so that the
        // motion is all that differs.
        let steps = steps_per_interval.ceil() as usize;
        let h_step = interval / steps as f64;
        let scenario = hanging_rope("galerkin", end, h_step);
        let run = run_forces(&format!("coupling_intervals_{steps}"), &scenario);
        let mut h = handle(&scenario);
        // The fairlead's static stiffness |dF/dx| along the motion, by
        // central differences of the equilibrium.
        let d = 1e-4;
        let dir = SWING
            .amplitude
            .map(|a| a / distance(&SWING.amplitude, &[0.0; 3]));
        let at = |s: f64| -> [f64; 3] { std::array::from_fn(|c| START[c] + s * dir[c]) };
        let fp = h.initialize(&at(d), None).unwrap();
        let fm = h.initialize(&at(-d), None).unwrap();
        let stiffness = distance(&fp, &fm) / (2.0 * d);
        h.initialize(&START, Some(&[0.0; 3])).unwrap();
        let mut worst: f64 = 0.0;
        let n = (end / interval).round() as usize;
        for i in 1..=n {
            let t = h.time() + interval;
            let (r, v) = swing(t);
            let f = h.step_to(t, &r, Some(&v)).unwrap();
            assert_eq!(f.steps, steps);
            let row = &run[i * steps];
            assert!((row.0 - h.time()).abs() < 1e-9, "{} vs {}", row.0, h.time());
            worst = worst.max(distance(&f.last_step, &row.1));
        }
        // The lines answer a position error with their stiffness and an
        // acceleration error with at most their whole mass (the rope's
        // pendulum frequency, 0.2 Hz, is far below the 1 Hz swing: its
        // response is stiffness and inertia, without resonance).
        let (e_r, e_a) = interpolation_errors(interval, end);
        let bound = stiffness * e_r + mass * e_a;
        println!(
            "{steps_per_interval} steps per interval: force off by {worst:e} N; \
             K e_r + m e_a = {stiffness:.3e} N/m x {e_r:.3e} m + {mass} kg x {e_a:.3e} m/s^2 \
             = {bound:e} N"
        );
        assert!(worst <= bound, "{worst:e} N above {bound:e} N");
        errors.push((worst, e_a));
    }
    // The force error falls at least as fast as the acceleration error of
    // (K2), second order in the interval (measured: 94 against 14).
    let (force_ratio, accel_ratio) = (errors[1].0 / errors[0].0, errors[1].1 / errors[0].1);
    println!(
        "4 x the interval: force error x {force_ratio:.1}, acceleration error x {accel_ratio:.1}"
    );
    assert!(accel_ratio > 10.0 && force_ratio >= accel_ratio);
}

#[test]
fn save_step_restore_step_is_identical_to_the_bit() {
    let scenario = bridle("galerkin", 1.0);
    let mut h = handle(&scenario);
    // Started where the swing has the fairlead, as a host does.
    let (r0, v0) = swing(0.6);
    h.initialize(&r0, Some(&v0)).unwrap();
    let mut t = 0.0;
    let advance = |h: &mut CoupledSystem, t: &mut f64| {
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
    h.restore(&saved).unwrap();
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

/// A coupling code may start its platform anywhere: the bridle's static
/// equilibrium with the fairlead at x = 5.5 ... 6.1 m is the closed-form
/// catenary network's (M32a) (the two elastic catenaries balancing the
/// clump weight at the free point; stancf::system::balanced_points),
/// whichever side of the scenario's 6.0 m it starts. (Before the free
/// point was seeded at (M32a), 1 mm either side of 6.0 m gave a rope
/// folded in compression, 2.6 N off, or a stalled solve.) The force on
/// the fairlead is the catenary's (C12) to 1e-6 of its size, the
/// agreement docs/method.md §11.6 measures for one line with the rope's
/// EI = 1e-7 w L^3 (§11.7) (1.5e-6 for a line as heavy as its tension,
/// w L / T = 3; these ropes have w L / T = 0.1: measured 3.5e-11 to
/// 8e-11); the folded rope was 7e-2 off.
#[test]
fn the_bridles_equilibrium_is_the_catenary_networks_wherever_the_fairlead_starts() {
    use stancf::catenary::{Catenary, CatenaryLine, LineEnd};
    let rope = CatenaryLine {
        length: 5.0,
        weight: 0.08 * 9.81,
        ea: 2.0e4,
    };
    for x in [5.5, 5.99, 6.0, 6.001, 6.1] {
        let fairlead = [x, 0.0, 1.0];
        let mut h = handle(&bridle("galerkin", 0.01));
        let force = h.initialize(&fairlead, None).expect("static equilibrium");
        let mut system = h.system().clone();
        system
            .set_point_motion(
                1,
                CoupledMotion::Interval(stancf::motion::MotionInterval::at_rest(fairlead)),
            )
            .unwrap();
        let shackle = stancf::system::balanced_points(&system)[2];
        let catenary = Catenary::between(rope, fairlead, shackle, [0.0, 0.0, -1.0]).unwrap();
        let exact = catenary.end_force(LineEnd::A);
        let error = distance(&force, &exact);
        eprintln!("x = {x}: force {force:?}, catenary {exact:?}, error {error:e}");
        assert!(error <= 1e-6 * distance(&exact, &[0.0; 3]), "x = {x}");
    }
}
