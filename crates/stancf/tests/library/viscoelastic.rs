//! A viscoelastic line's slab rows and their exact Jacobian
//! (docs/method.md §2.11, (V5)-(V6)): against central differences of
//! the rows, and at rest against the elastic line of the static EA.

use crate::common::*;
use stancf::element::{
    CableElement, DynamicStiffness, Measures, SlabDerivatives, SlabLoads, TimeSlab, Viscoelastic,
};
use stancf::shape::{cubic_hermite, quintic_hermite};
use stancf::{AxialStrain, Curvature};

fn laws() -> [Viscoelastic; 2] {
    [
        Viscoelastic {
            dynamic: DynamicStiffness::Constant(7.0),
            static_damping: 0.4,
            dynamic_damping: 0.05,
        },
        Viscoelastic {
            dynamic: DynamicStiffness::MeanLoad {
                alpha: 4.0,
                beta: 3.0,
            },
            static_damping: 0.2,
            dynamic_damping: 0.0,
        },
    ]
}

fn visco_section(law: &Viscoelastic, tension_only: bool) -> stancf::element::Section {
    stancf::element::Section {
        visco: Some(law.clone()),
        tension_only,
        ..section()
    }
}

/// The slab rows' Jacobian against central differences of the rows, from
/// a fixed internal state `history`.
fn check_jacobian<const NS: usize, const ND: usize>(
    el: &CableElement<NS, ND>,
    slab: &TimeSlab,
    y: &[[f64; ND]; 4],
    history: &[f64],
    label: &str,
) {
    let loads = SlabLoads::gravity([0.3, -9.81, 0.1]);
    let e = slab_jacobian_error(el, slab, y, &loads, history);
    assert!(e < 1e-6, "{label}: Jacobian rel. error {e:e}");
}

#[test]
fn a_viscoelastic_slabs_jacobian_is_the_finite_differences_of_its_rows() {
    let mut rng = Rng(0x9e3779b97f4a7c15);
    for law in laws() {
        for (strain, tension_only) in [
            (AxialStrain::Green, false),
            (AxialStrain::Engineering, true),
        ] {
            let m = Measures {
                axial_strain: strain,
                curvature: Curvature::Exact,
            };
            let r = rules(4, 3);
            let sec = visco_section(&law, tension_only);
            let el2 = CableElement::new(cubic_hermite, 0.45, sec.clone(), m, &r);
            let el3 = CableElement::new(quintic_hermite, 0.45, sec, m, &r);
            for points in [2, 3] {
                let s = slab(0.08, points);
                let history = [0.02, -0.01, 0.05, 0.03];
                let y2 = random_slab_state::<4, 12>(&mut rng, 0.45, 0.2);
                let label = format!("{law:?} {strain:?} SAC-2 {points} points");
                check_jacobian(&el2, &s, &y2, &history, &label);
                let y3 = random_slab_state::<6, 18>(&mut rng, 0.45, 0.2);
                check_jacobian(&el3, &s, &y3, &history, &label.replace("SAC-2", "SAC-3"));
            }
        }
    }
}

#[test]
fn a_viscoelastic_line_at_rest_has_the_rows_of_the_elastic_line_of_its_static_ea() {
    let mut rng = Rng(0x2545f4914f6cdd1d);
    let m = Measures {
        axial_strain: AxialStrain::Engineering,
        curvature: Curvature::Exact,
    };
    let r = rules(4, 3);
    for law in laws() {
        let visco = CableElement::new(cubic_hermite, 0.45, visco_section(&law, false), m, &r);
        let elastic = CableElement::new(cubic_hermite, 0.45, section(), m, &r);
        // Held still: e_b = e_a, no velocity; the internal state at rest.
        let mut y = random_slab_state::<4, 12>(&mut rng, 0.45, 0.05);
        y[2] = y[0];
        y[1] = [0.0; 12];
        y[3] = [0.0; 12];
        let history = visco.rest_internal_state(&y[0]);
        let loads = SlabLoads::gravity([0.0, -9.81, 0.0]);
        let s = slab(0.1, 3);
        let (mut dv, mut de) = (
            SlabDerivatives::<12>::default(),
            SlabDerivatives::<12>::default(),
        );
        visco.slab_derivatives_from(&s, &y, &loads, &history, false, &mut dv);
        elastic.slab_derivatives(&s, &y, &loads, false, &mut de);
        let (gv, ge): (Vec<f64>, Vec<f64>) = (
            dv.grad.iter().flatten().copied().collect(),
            de.grad.iter().flatten().copied().collect(),
        );
        let e = rel_diff(&gv, &ge);
        assert!(e < 1e-12, "{law:?}: rows differ by {e:e}");
        // And the internal state stays where it was.
        for (end, start) in dv.visco.end.iter().zip(&history) {
            assert!(
                (end - start).abs() <= 1e-13 * start.abs().max(1e-3),
                "{end} vs {start}"
            );
        }
    }
}

/// The line of the dynamic checks: 1 m in 4 SAC-2 elements (engineering
/// strain), EA = 1e6 N static, so light (0.01 kg/m) that its axial modes
/// (5 kHz) are far above the drive: its strain is uniform, and the
/// tension is the law's under that strain's history alone. End A pinned,
/// end B at x = 1 + `prestrain` driven along x by `amplitude` sin(w t).
fn driven_line(
    law: Option<Viscoelastic>,
    prestrain: f64,
    amplitude: f64,
    period: f64,
) -> (stancf::Model, stancf::State) {
    use stancf::motion::{CoupledMotion, Oscillation};
    use stancf::{Cable, Constraint, ConstraintKind, ElementType, Material};
    let material = Material {
        youngs_modulus: 1e9,
        density: 10.0,
        area: 1e-3,
        second_moment: 1e-15,
        axial_damping: 0.0,
    };
    let options = engineering_options();
    let b = [1.0 + prestrain, 0.0, 0.0];
    let cable = Cable::straight(1.0, 4, ElementType::Sac2);
    let mut model = stancf::Model::new(cable, material, options, vec![]).unwrap();
    if let Some(law) = law {
        model = model.with_viscoelastic(law).unwrap();
    }
    let model = model
        .with_constraints(vec![
            Constraint {
                node: 0,
                kind: ConstraintKind::Pinned,
            },
            Constraint {
                node: 4,
                kind: ConstraintKind::Attached {
                    position: b,
                    motion: CoupledMotion::Oscillation(Oscillation {
                        amplitude: [amplitude, 0.0, 0.0],
                        period,
                        phase: 0.0,
                        ramp: 0.0,
                    }),
                },
            },
        ])
        .unwrap();
    // Uniformly stretched, stretching at the drive's rate a w x.
    let w = 2.0 * std::f64::consts::PI / period;
    let mut s = model.initial_state();
    for j in 0..model.nodes() {
        let x = model.node_coordinate(j);
        s.e[model.coordinate(j, 0, 0)] = (1.0 + prestrain) * x;
        s.e[model.coordinate(j, 1, 0)] = 1.0 + prestrain;
        s.v[model.coordinate(j, 0, 0)] = amplitude * w * x;
        s.v[model.coordinate(j, 1, 0)] = amplitude * w;
    }
    model.apply_constraints(&mut s);
    (model, s)
}

/// N(t) of the law (V1)-(V2) with a constant k2 under eps = e0 + a sin(w t)
/// from rest at e0: eps1 = eps1_rest + a Im(H e^{iwt}) + C e^{-k t / c},
/// H = (k2 + i w c2) / (k + i w c), C = -a Im(H), k = k1 + k2,
/// c = c1 + c2; N = k1 eps1 + c1 eps1_dot.
fn standard_solid_tension(law: &Viscoelastic, ea: f64, e0: f64, a: f64, w: f64, t: f64) -> f64 {
    let s = law.springs(ea, 0.0);
    let (c1, c2) = (law.static_damping, law.dynamic_damping);
    let (k, c) = (s.k1 + s.k2, c1 + c2);
    let (nr, ni, dr, di) = (s.k2, w * c2, k, w * c);
    let d = dr * dr + di * di;
    let (hr, hi) = ((nr * dr + ni * di) / d, (ni * dr - nr * di) / d);
    let lambda = k / c;
    let rest = e0 * s.k2 / k;
    let eps1 = rest + a * (hr * (w * t).sin() + hi * (w * t).cos()) - a * hi * (-lambda * t).exp();
    let rate =
        a * w * (hr * (w * t).cos() - hi * (w * t).sin()) + a * hi * lambda * (-lambda * t).exp();
    s.k1 * eps1 + c1 * rate
}

/// No dashpot beside the dynamic spring (MoorDyn's BA_D = 0, the common
/// case): N = k2 (eps - eps1) needs no strain rate, so the checks do not
/// see the noise of the Galerkin step's end rates M^-1 p_b of this very
/// light line's r_x (1e-4 of the stretch rate, bounded).
const DRIVEN_LAW: Viscoelastic = Viscoelastic {
    dynamic: DynamicStiffness::Constant(3e6),
    static_damping: 2e5,
    dynamic_damping: 0.0,
};

/// 2 s of the driven line (Galerkin step dt): the largest |N - N_exact|
/// at nodes 0, 2, 4, the largest |E - E_0 - W| (W the work of the moving
/// end and of the dashpots) and the dissipated energy.
fn driven_run(dt: f64) -> (f64, f64, f64) {
    let (e0, a, period) = (0.01, 0.005, 0.5);
    let w = 2.0 * std::f64::consts::PI / period;
    let (model, s) = driven_line(Some(DRIVEN_LAW), e0, a, period);
    let settings = step_settings(dt, stancf::TimeScheme::Galerkin, 1e-9);
    let mut sim = stancf::Simulation::new(model, s, settings).unwrap();
    let e_start = sim.energies().mechanical();
    let (mut worst, mut balance) = (0.0f64, 0.0f64);
    for _ in 0..(2.0 / dt).round() as usize {
        sim.step().unwrap();
        let exact = standard_solid_tension(&DRIVEN_LAW, 1e6, e0, a, w, sim.state().t);
        for node in [0, 2, 4] {
            let n = stancf::observe::node_axial_force(sim.model(), sim.state(), node);
            worst = worst.max((n - exact).abs());
        }
        let gap = sim.energies().mechanical() - e_start - sim.external_work();
        balance = balance.max(gap.abs());
    }
    (worst, balance, -sim.damping_work())
}

#[test]
fn a_driven_viscoelastic_line_carries_the_standard_solids_tension() {
    let (worst, _, _) = driven_run(0.0025);
    // The line's inertia makes its tension differ from end to end by up
    // to m L a w^2 = 0.008 N (the law's N is of the uniform strain); the
    // time discretization (order 4 to 6 at w dt = 0.03) adds far less.
    let inertia = 0.01 * 1.0 * 0.005 * (4.0 * std::f64::consts::PI).powi(2);
    assert!(worst < 2.0 * inertia, "N off by {worst:e} N");
}

#[test]
fn a_driven_viscoelastic_lines_energy_balance_closes_at_second_order() {
    // E - E_0 - W: the springs' stored energy against the work of the
    // moving end (its mean force over a step times its displacement,
    // (M24), second order) and of the dashpots (collocated).
    let (_, coarse, dissipated) = driven_run(0.005);
    let (_, fine, _) = driven_run(0.0025);
    assert!(dissipated > 0.0);
    let order = (coarse / fine).log2();
    assert!(
        (order - 2.0).abs() < 0.15,
        "balance {coarse:e} -> {fine:e} J, order {order}"
    );
    assert!(
        fine < 1e-3 * dissipated,
        "balance {fine:e} J of {dissipated:e} J dissipated"
    );
}

/// Assembled steps of a viscoelastic cable under gravity: P2 and the
/// Galerkin step, SAC-2 and SAC-3, free and with a clamped end and a
/// moving node by both constraint routes: the step Jacobian (every
/// unknown of the slab) against central differences.
#[test]
fn a_viscoelastic_lines_step_jacobian_is_the_finite_differences_of_its_rows() {
    use crate::common::step_checks::check_schemes_and_routes;
    use stancf::assembly::Scheme;
    use stancf::{Cable, ElementType, Load, Material};
    let mut rng = Rng(0x5eed_0bad_cafe_0017);
    for kind in [ElementType::Sac2, ElementType::Sac3] {
        for law in laws() {
            let model = |constrained: bool| {
                let material = Material {
                    youngs_modulus: 2.0e3,
                    density: 1.0e3,
                    area: 1e-3,
                    second_moment: 1e-4,
                    axial_damping: 0.0,
                };
                let options = engineering_options();
                let gravity = vec![Load::Gravity {
                    acceleration: [0.0, -9.81, 0.0],
                }];
                let cons = clamped_and_driven(constrained);
                stancf::Model::new(Cable::straight(0.9, 3, kind), material, options, gravity)
                    .unwrap()
                    .with_viscoelastic(law.clone())
                    .unwrap()
                    .with_constraints(cons)
                    .unwrap()
            };
            let schemes = [Scheme::P2 { layers: 1 }, Scheme::Galerkin];
            check_schemes_and_routes(
                &model,
                &schemes,
                &mut rng,
                &format!("{kind:?} {law:?}"),
                1e-7,
            );
        }
    }
}

/// P2's stable step is judged on what a fast motion meets: the dynamic
/// spring k2 (the static spring's dashpot holds), so the highest
/// frequency of an axially vibrating line is sqrt(k2 / EA) times the
/// elastic line's.
#[test]
fn a_viscoelastic_lines_highest_frequency_is_that_of_its_dynamic_stiffness() {
    let (visco, s) = driven_line(Some(DRIVEN_LAW), 0.01, 0.0, 1.0);
    let (elastic, _) = driven_line(None, 0.01, 0.0, 1.0);
    let ratio = stancf::stability::highest_frequency(&visco, &s.e)
        / stancf::stability::highest_frequency(&elastic, &s.e);
    assert!((ratio - 3f64.sqrt()).abs() < 1e-4, "ratio {ratio}");
}

/// The ABS rule the mean-load form models (MoorDyn's `EA|alphaMBL|vbeta`):
/// a rope's dynamic stiffness at a mean tension T is alpha + beta T. A
/// rope held at T (strain e0, T = EA e0) and shaken by a small fast
/// stretch (amplitude 1e-5, w c1 / (k1 + k2) = 100: the static spring's
/// dashpot holds) answers with the stiffness k2 = alpha + beta T through
/// the standard solid's modulus |(k1 + i w c1) k2 / (k1 + k2 + i w c1)|
/// (5e-5 below k2 here); measured by the discrete Fourier transform of
/// its fairlead's force over whole periods, to 1e-3 (the rope's inertia
/// adds 2e-5).
#[test]
fn a_mean_load_rope_shaken_fast_has_the_dynamic_stiffness_alpha_plus_beta_times_its_tension() {
    let (alpha, beta) = (2e6, 30.0);
    let law = Viscoelastic {
        dynamic: DynamicStiffness::MeanLoad { alpha, beta },
        static_damping: 1e6,
        dynamic_damping: 0.0,
    };
    let a = 1e-5;
    for e0 in [0.01, 0.05] {
        let tension = 1e6 * e0;
        let k2 = alpha + beta * tension;
        let k1 = k2 * 1e6 / (k2 - 1e6);
        let w = 100.0 * (k1 + k2) / 1e6;
        let period = 2.0 * std::f64::consts::PI / w;
        let (model, s) = driven_line(Some(law.clone()), e0, a, period);
        let per_period = 32;
        let dt = period / per_period as f64;
        let settings = step_settings(dt, stancf::TimeScheme::Galerkin, 1e-11);
        let mut sim = stancf::Simulation::new(model, s, settings).unwrap();
        let (mut re, mut im) = (0.0, 0.0);
        let (skip, periods) = (4 * per_period, 8 * per_period);
        for k in 0..skip + periods {
            sim.step().unwrap();
            if k >= skip {
                let t = sim.state().t;
                let n = stancf::observe::node_axial_force(sim.model(), sim.state(), 4);
                re += n * (w * t).cos();
                im += n * (w * t).sin();
            }
        }
        let amplitude = 2.0 * (re * re + im * im).sqrt() / periods as f64;
        let c1 = 1e6;
        let (nr, ni) = (k1 * k2, w * c1 * k2);
        let (dr, di) = (k1 + k2, w * c1);
        let modulus = ((nr * nr + ni * ni) / (dr * dr + di * di)).sqrt();
        let measured = amplitude / a;
        assert!(
            (measured / modulus - 1.0).abs() < 1e-3,
            "mean tension {tension} N: stiffness {measured:e} N against {modulus:e} N (k2 {k2:e})"
        );
    }
}

/// Syrope's rope (docs/method.md §2.12): MoorDyn's test curve (a part of
/// it), the exponential working curve (k1 0.2, k2 1.5), alpha 1.53e8 N,
/// beta 23.12, its largest mean tension so far 1.302e6 N; dashpots of
/// 1e6 and 1e4 N s (a time of 6 ms, so that a motion over 100 s is
/// quasi-static).
fn syrope_rope() -> Viscoelastic {
    let owc = [
        (2.06897e-3, 1.71768e5),
        (6.20690e-3, 4.78788e5),
        (1.24138e-2, 8.66556e5),
        (2.06897e-2, 1.32880e6),
        (3.10345e-2, 1.89540e6),
        (4.13793e-2, 2.56220e6),
        (6.00000e-2, 4.38601e6),
    ];
    let form = stancf::element::WorkingCurveForm::Exponential;
    let curves =
        stancf::element::Syrope::new(&owc, form, (0.2, 1.5), (1.53e8, 23.12), "rope").unwrap();
    Viscoelastic {
        dynamic: DynamicStiffness::Syrope {
            curves: std::sync::Arc::new(curves),
            tmax0: 1.302e6,
        },
        static_damping: 1e6,
        dynamic_damping: 1e4,
    }
}

/// Loaded slowly past its largest mean tension and back, a Syrope rope
/// follows its working curve, then the original curve past Tmax0, then,
/// unloading, the working curve of the new largest tension: back at its
/// first strain it pulls less than it did (by more than 1e5 N) (the rope has been
/// stretched for good). At every step its tension is the quasi-static
/// law's, T(eps, Tmax so far), to what its dashpots carry at that rate,
/// (c1 + c2) |eps_dot| (4e-4 of the tension at most here), and 3e-5 of
/// the tension: the rope's history is its spring's tension, which trails
/// the quasi-static law's at the turn by the dashpots' share of the steps
/// before it (measured 16 N, 9e-6 of the tension, at dt 0.25 and 0.125 s
/// alike; the test's Tmax is the quasi-static law's).
#[test]
fn a_syrope_rope_loaded_past_its_history_unloads_along_a_new_working_curve() {
    use stancf::motion::{CoupledMotion, MotionTable};
    use stancf::{Cable, Constraint, ConstraintKind, ElementType, Material};
    let law = syrope_rope();
    let DynamicStiffness::Syrope { curves, tmax0 } = &law.dynamic else {
        unreachable!()
    };
    let (e0, e1) = (0.0130, 0.0300);
    let table = MotionTable::new(
        vec![0.0, 50.0, 100.0],
        vec![
            [1.0 + e0, 0.0, 0.0],
            [1.0 + e1, 0.0, 0.0],
            [1.0 + e0, 0.0, 0.0],
        ],
    )
    .unwrap();
    let material = Material {
        youngs_modulus: 1e8 / 0.0324,
        density: 40.0 / 0.0324,
        area: 0.0324,
        second_moment: 1e-12,
        axial_damping: 0.0,
    };
    let options = engineering_options();
    let cable = Cable::straight(1.0, 2, ElementType::Sac2);
    let model = stancf::Model::new(cable, material, options, vec![])
        .unwrap()
        .with_viscoelastic(law.clone())
        .unwrap()
        .with_constraints(vec![
            Constraint {
                node: 0,
                kind: ConstraintKind::Pinned,
            },
            Constraint {
                node: 2,
                kind: ConstraintKind::Attached {
                    position: [1.0 + e0, 0.0, 0.0],
                    motion: CoupledMotion::Table(std::sync::Arc::new(table.clone())),
                },
            },
        ])
        .unwrap();
    // Uniformly stretched and stretching at the table's first rate (no
    // wave from the start).
    let rate0 = table.state(0.0).1[0];
    let mut s = model.initial_state();
    for j in 0..model.nodes() {
        let x = model.node_coordinate(j);
        s.e[model.coordinate(j, 0, 0)] = (1.0 + e0) * x;
        s.e[model.coordinate(j, 1, 0)] = 1.0 + e0;
        s.v[model.coordinate(j, 0, 0)] = rate0 * x;
        s.v[model.coordinate(j, 1, 0)] = rate0;
    }
    model.apply_constraints(&mut s);
    let first = curves.tension_at_rest(e0, *tmax0);
    let dt = 0.25;
    let mut sim = stancf::Simulation::new(
        model,
        s,
        step_settings(dt, stancf::TimeScheme::Galerkin, 1e-8),
    )
    .unwrap();
    let mut tmax = *tmax0;
    let (mut worst, mut allowed) = (0.0f64, 0.0f64);
    let mut last = 0.0;
    for _ in 0..(100.0 / dt).round() as usize {
        sim.step().unwrap();
        let t = sim.state().t;
        let (x, v) = table.state(t);
        let (eps, eps_dot) = (x[0] - 1.0, v[0]);
        let quasi_static = curves.tension_at_rest(eps, tmax);
        tmax = tmax.max(quasi_static);
        let n = stancf::observe::node_axial_force(sim.model(), sim.state(), 2);
        worst = worst.max((n - quasi_static).abs() - 1.01e6 * eps_dot.abs());
        allowed = allowed.max(3e-5 * quasi_static);
        last = n;
    }
    assert!(
        worst < allowed,
        "off the quasi-static law by {worst:e} N beyond the dashpot's share"
    );
    assert!(tmax > 1.8e6, "loaded past Tmax0 to {tmax:e} N");
    let unloaded = curves.tension_at_rest(e0, tmax);
    assert!((last - unloaded).abs() < 3e-5 * unloaded + 1.01e6 * table.state(100.0).1[0].abs());
    assert!(
        first - unloaded > 1e5,
        "the rope stretched for good: {first:e} N then {unloaded:e} N"
    );
}
