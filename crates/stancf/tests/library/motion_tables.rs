//! Tabulated motions of coupled points (docs/method.md §11.11): the
//! not-a-knot spline (M39)-(M40) is exact for cubics and fourth-order
//! accurate for a smooth motion, and a line driven by a table sampled
//! from an oscillation follows the line driven by the oscillation itself
//! to the interpolation error, at the same order.

use stancf::constraints::{MotionTable, Oscillation};
use stancf::motion::CoupledMotion;
use stancf::system::{End, Line, Point, System, SystemSimulation};
use stancf::{Cable, ConstraintMethod, ElementType, Load, Material, Model, ModelOptions};
use stancf::{ModelError, StepSettings};

const G: [f64; 3] = [0.0, -9.81, 0.0];

/// The fairlead's swing: 1 cm across and 3 mm along a hanging line at
/// 2 Hz, small enough for the line to respond linearly, and no ramp (the
/// ramp's third derivative jumps at t = ramp, which would cost the spline
/// an order there).
const SWING: Oscillation = Oscillation {
    amplitude: [0.01, 0.003, 0.0],
    period: 0.5,
    phase: 0.0,
    ramp: 0.0,
};

/// The oscillation about `r0` sampled every `spacing` from t0 to t1.
fn sampled(r0: [f64; 3], spacing: f64, t0: f64, t1: f64) -> MotionTable {
    let n = ((t1 - t0) / spacing).round() as usize;
    let times: Vec<f64> = (0..=n).map(|i| t0 + i as f64 * spacing).collect();
    let motion = CoupledMotion::from(SWING);
    let positions = times.iter().map(|&t| motion.state_at(&r0, t).0).collect();
    MotionTable::new(times, positions).expect("table")
}

/// Largest |table - oscillation| in position and velocity over [0, t1]
/// (501 samples, off the knots).
fn interpolation_error(table: &MotionTable, t1: f64) -> (f64, f64) {
    let motion = CoupledMotion::from(SWING);
    let mut worst = (0.0f64, 0.0f64);
    for k in 0..=500 {
        let t = k as f64 / 500.0 * 0.9973 * t1;
        let (r, v) = table.state(t);
        let (r_exact, v_exact) = motion.state_at(&[0.0; 3], t);
        for c in 0..3 {
            worst.0 = worst.0.max((r[c] - r_exact[c]).abs());
            worst.1 = worst.1.max((v[c] - v_exact[c]).abs());
        }
    }
    worst
}

fn order(coarse: f64, fine: f64) -> f64 {
    (coarse / fine).log2()
}

#[test]
fn a_tabulated_oscillation_converges_at_fourth_order_in_the_spacing() {
    // The spline's error is h^4 / 384 max|r''''| in position and
    // O(h^3) in velocity (de Boor, A Practical Guide to Splines, ch. V);
    // the spacings resolve the 0.5 s period with 10 to 80 samples.
    let spacings = [0.05, 0.025, 0.0125, 0.00625];
    let errors: Vec<(f64, f64)> = spacings
        .iter()
        .map(|&h| interpolation_error(&sampled([0.0; 3], h, -0.2, 1.2), 1.0))
        .collect();
    let w = 2.0 * std::f64::consts::PI / SWING.period;
    let bound = |h: f64| 5.0 / 384.0 * h.powi(4) * 0.01 * w.powi(4);
    for (i, (&h, e)) in spacings.iter().zip(&errors).enumerate() {
        println!("spacing {h}: position {:.3e}, velocity {:.3e}", e.0, e.1);
        assert!(
            e.0 <= bound(h),
            "spacing {h}: {:e} above {:e}",
            e.0,
            bound(h)
        );
        if i > 0 {
            let (p, v) = (order(errors[i - 1].0, e.0), order(errors[i - 1].1, e.1));
            println!("  orders: position {p:.2}, velocity {v:.2}");
            assert!((3.8..4.2).contains(&p), "position order {p}");
            assert!((2.8..4.2).contains(&v), "velocity order {v}");
        }
    }
}

/// 2 mm^2 at 10 MPa: EA 20 N, stretched 1e-3 by its own weight.
fn rope() -> Material {
    Material {
        youngs_modulus: 1e7,
        density: 1000.0,
        area: 2e-6,
        second_moment: 2e-12,
        axial_damping: 0.0,
    }
}

/// A 1 m rope of 8 SAC-2 hanging from a coupled point at the origin
/// that moves along `motion`, stepped to t = 0.5 s (P2, dt 0.25 ms): the
/// positions of its nodes.
fn driven_line(motion: CoupledMotion, method: ConstraintMethod) -> Vec<[f64; 3]> {
    let cable = Cable::straight(1.0, 8, ElementType::Sac2).with_direction([0.0, -1.0, 0.0]);
    let model = Model::new(
        cable,
        rope(),
        ModelOptions::default(),
        vec![Load::Gravity { acceleration: G }],
    )
    .expect("model");
    let state = model.initial_state();
    let system = System::new(
        vec![Line {
            model,
            ends: [End::Point(0), End::Loose],
        }],
        vec![Point::coupled([0.0; 3], motion)],
        G,
    )
    .expect("system");
    let settings = StepSettings {
        time_step: 2.5e-4,
        constraint_method: method,
        ..StepSettings::default()
    };
    let mut sim = SystemSimulation::new(system, vec![state], settings).expect("simulation");
    for _ in 0..2000 {
        sim.step().expect("step");
    }
    let line = &sim.lines()[0];
    (0..line.model().nodes())
        .map(|j| line.model().node_position(&line.state().e, j))
        .collect()
}

fn largest_difference(a: &[[f64; 3]], b: &[[f64; 3]]) -> f64 {
    a.iter()
        .zip(b)
        .flat_map(|(p, q)| (0..3).map(move |c| (p[c] - q[c]).abs()))
        .fold(0.0, f64::max)
}

/// Least-squares slope of log(error) against log(spacing).
fn fitted_order(spacings: &[f64], errors: &[f64]) -> f64 {
    let n = spacings.len() as f64;
    let x: Vec<f64> = spacings.iter().map(|h| h.ln()).collect();
    let y: Vec<f64> = errors.iter().map(|e| e.ln()).collect();
    let (mx, my) = (x.iter().sum::<f64>() / n, y.iter().sum::<f64>() / n);
    let sxy: f64 = x.iter().zip(&y).map(|(a, b)| (a - mx) * (b - my)).sum();
    let sxx: f64 = x.iter().map(|a| (a - mx) * (a - mx)).sum();
    sxy / sxx
}

/// The end's error is the spline's, O(h^4) in position and O(h^3) in
/// velocity (oscillating at the table's spacing, so its effect on the
/// line's nodes integrates to O(h^4)); the line passes it on with the
/// amplification of its response to an end motion near its low modes
/// (the drive is 2 Hz, the hanging line's first modes 0.6 to 2 Hz):
/// measured 2 to 9, bounded by 20 here.
#[test]
fn a_line_driven_by_a_sampled_oscillation_follows_the_oscillation_to_the_interpolation_error() {
    for method in [ConstraintMethod::Multiplier, ConstraintMethod::Elimination] {
        let exact = driven_line(SWING.into(), method);
        let spacings = [0.02, 0.01, 0.005, 0.0025];
        let mut diffs = Vec::new();
        for h in spacings {
            let table = sampled([0.0; 3], h, 0.0, 0.6);
            let (interp, _) = interpolation_error(&table, 0.5);
            let diff = largest_difference(&driven_line(table.into(), method), &exact);
            println!("{method:?} spacing {h}: line {diff:.3e}, interpolation {interp:.3e}");
            assert!(diff <= 20.0 * interp, "{diff:e} against {interp:e}");
            diffs.push(diff);
        }
        let o = fitted_order(&spacings, &diffs);
        println!("{method:?}: order {o:.2}");
        assert!((3.5..4.5).contains(&o), "order {o}");
    }
}

#[test]
fn a_table_must_start_at_its_point() {
    let table = sampled([0.0; 3], 0.05, 0.1, 1.0);
    let model = Model::new(
        Cable::straight(1.0, 4, ElementType::Sac2),
        rope(),
        ModelOptions::default(),
        vec![],
    )
    .expect("model");
    let lines = vec![Line {
        model,
        ends: [End::Point(0), End::Loose],
    }];
    let at = |p: [f64; 3]| System::new(lines.clone(), vec![Point::coupled(p, table.clone())], G);
    let r0 = table.state(0.0).0;
    let e: ModelError = at([r0[0], r0[1] + 1e-6, r0[2]]).expect_err("1e-6 m off, 1 m long");
    assert_eq!(e.key, "points[0].motion", "{e}");
    assert!(e.message.contains("from the point's position"), "{e}");
    at([r0[0], r0[1] + 1e-10, r0[2]]).expect("within 1e-9 of the size");
}
