//! Line ends clamped in a direction (docs/method.md §6.10): r_x held
//! parallel to a unit d by n_1 . r_x = n_2 . r_x = 0 with multipliers.
//! A cantilever clamped at 30 degrees bends as Euler-Bernoulli says and
//! swings at its first frequency in the Galerkin step, the held r_x stays
//! on d to round-off through a dynamic run with either step, the end keeps
//! its axial strain, and the route that cannot take the hold refuses it.

use std::ops::ControlFlow;

use stancf::system::{catenary_states, End, Line, Point, System, SystemSimulation, SystemStatics};
use stancf::{
    Cable, Constraint, ConstraintKind, ConstraintMethod, ElementType, Load, Material, Model,
    ModelOptions, Simulation, StaticSettings, StaticSolver, StepSettings, TimeScheme,
};

const DEG30: f64 = std::f64::consts::FRAC_PI_6;

/// 30 degrees above the horizontal x axis, and the normal in the x-y plane.
fn d30() -> ([f64; 3], [f64; 3]) {
    (
        [DEG30.cos(), DEG30.sin(), 0.0],
        [-DEG30.sin(), DEG30.cos(), 0.0],
    )
}

/// The paper's PVC cable (EI = 4.25e-4 N m^2, EA = 1.02e4 N).
fn pvc() -> Material {
    Material::chen2023_pvc()
}

/// A 1 m cantilever of 10 SAC-2 along d, pinned at node 0 with r_x held
/// parallel to d, under `loads`.
fn cantilever(loads: Vec<Load>) -> Model {
    let (d, _) = d30();
    Model::new(
        Cable::straight(1.0, 10, ElementType::Sac2).with_direction(d),
        pvc(),
        ModelOptions::default(),
        loads,
    )
    .unwrap()
    .with_constraints(vec![
        Constraint {
            node: 0,
            kind: ConstraintKind::Pinned,
        },
        Constraint {
            node: 0,
            kind: ConstraintKind::Parallel { direction: d },
        },
    ])
    .unwrap()
}

fn solve(model: Model, method: ConstraintMethod) -> StaticSolver {
    let mut s = StaticSolver::new(
        model,
        StaticSettings {
            tolerance: 1e-13,
            constraint_method: method,
            ..StaticSettings::default()
        },
    )
    .unwrap();
    s.solve(|_, _| ControlFlow::Continue(())).unwrap();
    s
}

/// Tip deflection along the normal over P L^3 / (3 EI), minus 1, for a
/// tip load P = alpha EI / L^2 along the normal (alpha: the tip rotation
/// of linear theory times 2).
fn cantilever_error(alpha: f64) -> f64 {
    let m = pvc();
    let ei = m.youngs_modulus * m.second_moment;
    let (_, n) = d30();
    let p = alpha * ei;
    let s = solve(
        cantilever(vec![Load::PointForce {
            node: 10,
            force: n.map(|c| p * c),
        }]),
        ConstraintMethod::Multiplier,
    );
    let tip = s.model().node_position(&s.state().e, 10);
    let deflection = tip[0] * n[0] + tip[1] * n[1] + tip[2] * n[2];
    // The clamp balances the load's moment about the root, tip x P n
    // (P L z in linear theory; the tip's actual position is the lever).
    let (node, m) = s.clamp_moments()[0];
    assert_eq!(node, 0);
    let load_moment = p * (tip[0] * n[1] - tip[1] * n[0]);
    assert!(
        (m[2] + load_moment).abs() <= 1e-9 * load_moment && m[0] == 0.0 && m[1] == 0.0,
        "clamp moment {m:?}, load moment {load_moment:e} about z"
    );
    // The root's tangent stays on d.
    let o = 3;
    let e = &s.state().e;
    let off = (e[o] * n[0] + e[o + 1] * n[1]).abs() + e[o + 2].abs();
    assert!(off <= 1e-14, "root tangent off d by {off:e}");
    deflection / (p / (3.0 * ei)) - 1.0
}

/// Euler-Bernoulli theory is the small-deflection limit: SAC-2 elements
/// are exact for its cubic deflection, so what is left is the geometric
/// nonlinearity of the large-rotation solution, which falls with the load
/// (the elastica's tip deflection is P L^3 / 3EI (1 - c alpha^2 + ...),
/// alpha = P L^2 / EI, so the relative error is even in the load and
/// falls as alpha^2). With alpha = 1e-2, 1e-3, 1e-4 the error must fall
/// by at least a factor 50 per decade of load (measured 100: quadratic)
/// and be below 1e-8 at the smallest load (measured 1.2e-9, 0.12
/// alpha^2). The clamp's moment (M42) balances the load's moment about
/// the root, to the static tolerance.
#[test]
fn a_cantilever_clamped_at_30_degrees_matches_euler_bernoulli() {
    let errors: Vec<f64> = [1e-2, 1e-3, 1e-4]
        .iter()
        .map(|&a| cantilever_error(a))
        .collect();
    for (a, e) in [1e-2, 1e-3, 1e-4].iter().zip(&errors) {
        println!("alpha {a:e}: relative error {e:.3e}");
    }
    for w in errors.windows(2) {
        let ratio = w[0].abs() / w[1].abs().max(f64::MIN_POSITIVE);
        println!("  error ratio per decade of load: {ratio:.1}");
        assert!(ratio >= 50.0, "{errors:?}");
    }
    assert!(errors[2].abs() < 1e-8, "{errors:?}");
}

/// The elimination route fixes coordinates and cannot hold their
/// combination; it refuses the hold by name.
#[test]
fn a_direction_hold_is_refused_by_elimination() {
    let e = StaticSolver::new(
        cantilever(vec![]),
        StaticSettings {
            constraint_method: ConstraintMethod::Elimination,
            ..StaticSettings::default()
        },
    )
    .err()
    .expect("refused");
    assert_eq!(e.key, "analysis.constraint_method", "{e}");
    assert!(e.message.contains("clamped in a direction"), "{e}");
}

/// beta_1 L of a cantilever's first mode (cos(bL) cosh(bL) = -1).
const BETA1_L: f64 = 1.875_104_068_711_961;

/// The first mode of an Euler-Bernoulli cantilever of length 1 and its
/// slope at x: W(x) = cosh bx - cos bx - s (sinh bx - sin bx).
fn first_mode(x: f64) -> (f64, f64) {
    let b = BETA1_L;
    let s = (b.cosh() + b.cos()) / (b.sinh() + b.sin());
    let bx = b * x;
    let w = bx.cosh() - bx.cos() - s * (bx.sinh() - bx.sin());
    let slope = b * (bx.sinh() + bx.sin() - s * (bx.cosh() - bx.cos()));
    (w, slope)
}

/// The tip's deflection along the normal over a free vibration of
/// [`cantilever`] (no load) started at rest in its first mode with the tip
/// `amplitude` off the axis, stepped by `scheme` at `steps_per_period`
/// steps of Euler-Bernoulli's first period over `periods`: (t, deflection)
/// at every step.
fn vibration(scheme: TimeScheme, steps_per_period: f64, periods: f64) -> (f64, Vec<(f64, f64)>) {
    let m = pvc();
    let (ei, mass) = (m.youngs_modulus * m.second_moment, m.density * m.area);
    let omega = BETA1_L * BETA1_L * (ei / mass).sqrt();
    let period = 2.0 * std::f64::consts::PI / omega;
    let model = cantilever(vec![]);
    let (d, n) = d30();
    let mut start = model.initial_state();
    let amplitude = 1e-3;
    let tip = first_mode(1.0).0;
    for k in 0..=10 {
        let x = k as f64 / 10.0;
        let (w, slope) = first_mode(x);
        for c in 0..3 {
            start.e[6 * k + c] = x * d[c] + amplitude * w / tip * n[c];
            start.e[6 * k + 3 + c] = d[c] + amplitude * slope / tip * n[c];
        }
    }
    let dt = period / steps_per_period;
    let settings = StepSettings {
        time_step: dt,
        time_scheme: scheme,
        ..StepSettings::default()
    };
    let mut sim = Simulation::new(model, start, settings).unwrap();
    let deflection = |e: &[f64]| (0..3).map(|c| e[60 + c] * n[c]).sum::<f64>();
    let mut path = vec![(0.0, deflection(&sim.state().e))];
    for _ in 0..(steps_per_period * periods).round() as usize {
        sim.step().unwrap();
        let (t, e) = (sim.state().t, &sim.state().e);
        assert!(off_direction(e, d) <= 1e-12, "r_x left d at t = {t}");
        path.push((t, deflection(e)));
    }
    (period, path)
}

/// The times where the deflection crosses zero, by linear interpolation
/// between steps.
fn zero_crossings(path: &[(f64, f64)]) -> Vec<f64> {
    path.windows(2)
        .filter(|w| w[0].1 * w[1].1 < 0.0)
        .map(|w| w[0].0 - w[0].1 * (w[1].0 - w[0].0) / (w[1].1 - w[0].1))
        .collect()
}

/// The Galerkin step holds a clamp (its end rates solve M v = p with the
/// hold's rate rows, (M43)): a cantilever clamped at 30 degrees, released
/// from its first mode, swings at Euler-Bernoulli's first frequency
/// omega_1 = (beta_1 L)^2 sqrt(EI / (rho A L^4)), with its root's tangent
/// on d at every step (1e-12) and without numerical damping. The
/// period, twice the time between the first two zero crossings, is
/// within 2e-5 of 2 pi / omega_1: the ten SAC-2 elements' error on the
/// first mode is O((h/L)^4) (below 1e-6), the step's phase error at 200
/// steps a period (omega dt)^6 / 1e3, below 1e-10, the linear
/// interpolation of a crossing (omega dt)^2 dt / 6, below 1e-6 of the
/// period, and the tip's 1 mm amplitude shifts the frequency by the
/// geometric nonlinearity, O(A^2 / L^2) = 1e-6. (P2 is not stable at
/// this step: the cable's axial modes.)
#[test]
fn a_cantilever_clamped_by_the_galerkin_step_swings_at_its_first_frequency() {
    {
        let scheme = TimeScheme::Galerkin;
        let (period, path) = vibration(scheme, 200.0, 1.05);
        let crossings = zero_crossings(&path);
        assert!(crossings.len() >= 2, "{crossings:?}");
        let measured = 2.0 * (crossings[1] - crossings[0]);
        let error = measured / period - 1.0;
        // The amplitude after a period: no numerical damping.
        let last = path.iter().rev().find(|(t, _)| *t <= period).unwrap();
        let peak = path.iter().map(|p| p.1.abs()).fold(0.0, f64::max);
        println!(
            "{scheme:?}: period {measured:.9} s against {period:.9} s ({error:.2e}); \
             largest deflection {peak:.6e} m, at t = {:.4} s {:.6e} m",
            last.0, last.1
        );
        assert!(error.abs() < 2e-5, "{scheme:?}: {error:e}");
        assert!((peak / 1e-3 - 1.0).abs() < 1e-4, "{scheme:?}: {peak:e}");
    }
}

/// A soft rope: 2 mm^2 at 10 MPa (EA 20 N), 2 g/m, EI 2e-3 N m^2.
fn rope() -> Material {
    Material {
        youngs_modulus: 1e7,
        density: 1000.0,
        area: 2e-6,
        second_moment: 2e-10,
        axial_damping: 0.0,
    }
}

/// A rope hanging from a fixed point at the origin, clamped there in
/// `d`; 1 m of [`rope`] in 8 SAC-2 under gravity along -z.
fn hanging(d: [f64; 3]) -> System {
    let model = Model::new(
        Cable::straight(1.0, 8, ElementType::Sac2).with_direction([0.3, 0.0, -1.0]),
        rope(),
        ModelOptions::default(),
        vec![Load::Gravity {
            acceleration: [0.0, 0.0, -9.81],
        }],
    )
    .unwrap();
    let line = Line {
        model,
        ends: [End::Point(0), End::Loose],
    }
    .clamped(0, d)
    .unwrap();
    System::new(
        line_vec(line),
        vec![Point::fixed([0.0; 3])],
        [0.0, 0.0, -9.81],
    )
    .unwrap()
}

fn line_vec(line: Line) -> Vec<Line> {
    vec![line]
}

/// |d x r_x| / |r_x| at node 0 (the sine of the angle off d).
fn off_direction(e: &[f64], d: [f64; 3]) -> f64 {
    let r = [e[3], e[4], e[5]];
    let c = [
        d[1] * r[2] - d[2] * r[1],
        d[2] * r[0] - d[0] * r[2],
        d[0] * r[1] - d[1] * r[0],
    ];
    let norm = |v: [f64; 3]| (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt();
    norm(c) / norm(r)
}

/// A rope clamped 30 degrees off the vertical swings from its start (its
/// end tangent turned onto d, the rest straight along another line): at
/// every step of 0.25 ms the clamped r_x is parallel to d to round-off
/// (the hold's rows are linear and solved to the Newton tolerance), and
/// the clamp's moment is the reaction normal to d; with both steps.
#[test]
fn a_clamped_end_stays_parallel_to_its_direction_through_a_dynamic_run() {
    let d = [DEG30.sin(), 0.0, -DEG30.cos()];
    for scheme in [TimeScheme::P2, TimeScheme::Galerkin] {
        let system = hanging(d);
        let line = &system.lines()[0];
        let start = vec![line.model.initial_state()];
        assert!(off_direction(&start[0].e, d) < 1e-15);
        let settings = StepSettings {
            time_step: 2.5e-4,
            time_scheme: scheme,
            ..StepSettings::default()
        };
        let mut sim = SystemSimulation::new(system, start, settings).unwrap();
        let mut worst = 0.0f64;
        let mut moment_seen = 0.0f64;
        let mut moment = [0.0; 3];
        for _ in 0..800 {
            sim.step().unwrap();
            let e = &sim.lines()[0].state().e;
            worst = worst.max(off_direction(e, d));
            let (node, m) = sim.lines()[0].clamp_moments()[0];
            assert_eq!(node, 0);
            // The moment is normal to the clamped tangent.
            let along = m[0] * d[0] + m[1] * d[1] + m[2] * d[2];
            let size = (m.iter().map(|c| c * c).sum::<f64>()).sqrt();
            assert!(along.abs() <= 1e-9 * size.max(1e-300), "{m:?}");
            moment_seen = moment_seen.max(size);
            moment = m;
        }
        println!(
            "{scheme:?}: largest |n . r_x| / |r_x|: {worst:.2e}; largest clamp moment \
             {moment_seen:.3e} N m, at 0.2 s {moment:?}"
        );
        assert!(worst <= 1e-12, "{worst:e}");
        assert!(moment_seen > 0.0);
    }
}

/// The clamp's moment of [`hanging`] 30 degrees off the vertical,
/// averaged over the last 10 ms of 0.2 s, stepped by `scheme` at `dt`.
fn late_clamp_moment(scheme: TimeScheme, dt: f64) -> f64 {
    let d = [DEG30.sin(), 0.0, -DEG30.cos()];
    let system = hanging(d);
    let start = vec![system.lines()[0].model.initial_state()];
    let settings = StepSettings {
        time_step: dt,
        time_scheme: scheme,
        ..StepSettings::default()
    };
    let mut sim = SystemSimulation::new(system, start, settings).unwrap();
    let (steps, window) = ((0.2 / dt).round() as usize, (0.01 / dt).round() as usize);
    let mut mean = 0.0;
    for i in 0..steps {
        sim.step().unwrap();
        if i >= steps - window {
            // The moment is about y: the rope swings in the x-z plane.
            mean += sim.lines()[0].clamp_moments()[0].1[1] / window as f64;
        }
    }
    mean
}

/// The two steps converge to the same clamp moment (the Galerkin step's
/// with the hold's impulse at t_b, (M43)): the late mean moment of the
/// swinging rope at 62.5 us differs between P2 and the Galerkin step by
/// less than the sum of their own error estimates, each run's change
/// from the run at twice the step.
#[test]
fn both_steps_converge_to_the_same_clamp_moment() {
    let (coarse, fine) = (1.25e-4, 6.25e-5);
    let p2 = [coarse, fine].map(|dt| late_clamp_moment(TimeScheme::P2, dt));
    let galerkin = [coarse, fine].map(|dt| late_clamp_moment(TimeScheme::Galerkin, dt));
    let estimates = (p2[0] - p2[1]).abs() + (galerkin[0] - galerkin[1]).abs();
    let apart = (p2[1] - galerkin[1]).abs();
    println!(
        "late clamp moment: P2 {p2:?}, Galerkin {galerkin:?} N m; apart {apart:.2e}, \
         error estimates {estimates:.2e}"
    );
    assert!(apart <= estimates, "{apart:e} > {estimates:e}");
}

/// The hold fixes the tangent's direction, not its length: a rope
/// hanging straight down from a clamp along -z stretches at its top by
/// the tension there, the weight of the rope, over EA (engineering
/// strain: |r_x| - 1 = T / EA, here 8.0e-6), to the static tolerance and
/// the elements' error (the strain is linear along the rope, which SAC-2
/// represents exactly).
#[test]
fn a_clamped_end_keeps_its_axial_strain() {
    let d = [0.0, 0.0, -1.0];
    let model = Model::new(
        Cable::straight(2.0, 16, ElementType::Sac2).with_direction(d),
        pvc(),
        ModelOptions {
            measures: stancf::Measures {
                axial_strain: stancf::AxialStrain::Engineering,
                ..stancf::Measures::default()
            },
            ..ModelOptions::default()
        },
        vec![Load::Gravity {
            acceleration: [0.0, 0.0, -9.81],
        }],
    )
    .unwrap();
    let line = Line {
        model,
        ends: [End::Point(0), End::Loose],
    }
    .clamped(0, [0.0, 0.0, -7.0])
    .unwrap();
    let system = System::new(
        line_vec(line),
        vec![Point::fixed([0.0; 3])],
        [0.0, 0.0, -9.81],
    )
    .unwrap();
    let seeds = catenary_states(&system);
    let mut s = SystemStatics::new(
        system,
        seeds,
        StaticSettings {
            tolerance: 1e-13,
            ..StaticSettings::default()
        },
    )
    .unwrap();
    s.solve(|_, _| ControlFlow::Continue(())).unwrap();
    let m = pvc();
    let ea = m.youngs_modulus * m.area;
    let weight = m.density * m.area * 2.0 * 9.81;
    let e = &s.line_state(0).e;
    let stretch = (e[3] * e[3] + e[4] * e[4] + e[5] * e[5]).sqrt();
    let strain = stretch - 1.0;
    println!("top strain {strain:.6e}, T / EA = {:.6e}", weight / ea);
    assert!(e[3].abs() < 1e-15 && e[4].abs() < 1e-15, "r_x on d");
    assert!((strain / (weight / ea) - 1.0).abs() < 1e-6, "{strain:e}");
}

/// A clamp where nothing holds a rotation is refused by name.
#[test]
fn a_clamp_at_a_free_point_or_a_loose_end_is_refused() {
    let model = || {
        Model::new(
            Cable::straight(1.0, 4, ElementType::Sac2),
            pvc(),
            ModelOptions::default(),
            vec![],
        )
        .unwrap()
    };
    let at_free = Line {
        model: model(),
        ends: [End::Point(0), End::Point(1)],
    }
    .clamped(1, [1.0, 0.0, 0.0])
    .unwrap();
    let points = vec![Point::fixed([0.0; 3]), Point::free([1.0, 0.0, 0.0], 1.0)];
    let e = System::new(vec![at_free], points, [0.0; 3]).unwrap_err();
    assert_eq!(e.key, "lines[0]");
    assert!(e.message.contains("end B is clamped"), "{e}");
    let loose = Line {
        model: model(),
        ends: [End::Point(0), End::Loose],
    }
    .clamped(1, [1.0, 0.0, 0.0])
    .unwrap();
    let e = System::new(vec![loose], vec![Point::fixed([0.0; 3])], [0.0; 3]).unwrap_err();
    assert!(e.message.contains("end B is clamped"), "{e}");
    let zero = Line {
        model: model(),
        ends: [End::Point(0), End::Loose],
    }
    .clamped(0, [0.0; 3])
    .unwrap_err();
    assert!(zero.key.ends_with(".direction"), "{zero}");
}
