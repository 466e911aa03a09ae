//! Axial (Kelvin-Voigt) damping, N = EA eps + BA eps_dot (docs/method.md
//! §2.10, (M34)-(M36)): its exact Jacobian against finite differences
//! (element slab and assembled steps of both schemes), its work against
//! the energy lost, the decay of a rod's first axial mode against the
//! Kelvin-Voigt closed form, MoorDyn's damping-ratio conversion, and
//! statics untouched by it.

use crate::common::step_checks::check_schemes_and_routes;
use crate::common::*;
use stancf::assembly::Scheme;
use stancf::element::axial_strain as axial_strain_of;
use stancf::element::{CableElement, Section, SlabDerivatives, SlabLoads, TimeSlab};
use stancf::quadrature::GaussRule;
use stancf::shape::{cubic_hermite, quintic_hermite};
use stancf::{
    run, AxialStrain, Cable, Constraint, ConstraintKind, ElementType, Load, Material, Measures,
    Model, ModelOptions, Simulation, StaticSettings, StaticSolver, StepSettings, TimeScheme,
};
use std::ops::ControlFlow;

/// Central differences with this step agree with an exact derivative to
/// ~1e-9 relative here (truncation h^2 f''' ~ 1e-12, round-off eps / h ~
/// 1e-10 of the entries); 1e-7 leaves room for the smallest entries.
const FD_TOL: f64 = 1e-7;
const H: f64 = 1e-6;

fn damped_section(ba: f64) -> Section {
    Section { ba, ..section() }
}

/// dA/dy with and without damping: the damping part of the gradient,
/// `sum_g w_g dt T_m sum_s w_s l N_x,k s`, against one computed without
/// the kernel's strain derivatives: eps_dot by central differences of eps
/// along the slab's motion in time, d eps / d r_x by central differences
/// of eps.
fn check_damping_force<const NS: usize, const ND: usize>(
    el: &CableElement<NS, ND>,
    undamped: &CableElement<NS, ND>,
    shape: fn(f64, f64) -> stancf::shape::SpatialShape<NS>,
    time_rule: &GaussRule,
    y: &[[f64; ND]; 4],
    axial_points: usize,
    label: &str,
) {
    let slab = &TimeSlab::new(0.05, time_rule);
    let loads = SlabLoads::gravity([0.0, -9.81, 0.0]);
    let (mut with, mut without) = (SlabDerivatives::default(), SlabDerivatives::default());
    el.slab_derivatives(slab, y, &loads, false, &mut with);
    undamped.slab_derivatives(slab, y, &loads, false, &mut without);
    let measure = el.measures.axial_strain;
    let ba = el.section.ba;
    let rule = GaussRule::new(axial_points).unwrap();
    let mut expect = [[0.0; ND]; 4];
    let mut work = 0.0;
    for (tp, (tau, _)) in slab.points.iter().zip(time_rule.iter()) {
        for (xi, w) in rule.iter() {
            let sh = shape(xi, el.length);
            // r_x along the slab's motion, at tau + d: sum_m T_m(t) y_m.
            let rx_at = |dt: f64| {
                let ts = stancf::shape::time_hermite(tau + dt / slab.dt, slab.dt);
                let mut rx = [0.0; 3];
                for m in 0..4 {
                    for k in 0..NS {
                        for i in 0..3 {
                            rx[i] += ts.t[m] * sh.n_x[k] * y[m][3 * k + i];
                        }
                    }
                }
                rx
            };
            let rx = rx_at(0.0);
            let ht = 1e-5 * slab.dt;
            let eps_dot = (axial_strain_of(measure, &rx_at(ht))
                - axial_strain_of(measure, &rx_at(-ht)))
                / (2.0 * ht);
            let mut deps = [0.0; 3];
            for i in 0..3 {
                let (mut p, mut m) = (rx, rx);
                p[i] += H;
                m[i] -= H;
                deps[i] = (axial_strain_of(measure, &p) - axial_strain_of(measure, &m)) / (2.0 * H);
            }
            work -= tp.w_dt * w * el.length * ba * eps_dot * eps_dot;
            for m in 0..4 {
                for k in 0..NS {
                    for i in 0..3 {
                        expect[m][3 * k + i] -= tp.w_dt
                            * tp.shape.t[m]
                            * w
                            * el.length
                            * sh.n_x[k]
                            * ba
                            * eps_dot
                            * deps[i];
                    }
                }
            }
        }
    }
    let got: Vec<f64> = (0..4)
        .flat_map(|m| (0..ND).map(move |d| (m, d)))
        .map(|(m, d)| with.grad[m][d] - without.grad[m][d])
        .collect();
    let exp: Vec<f64> = expect.iter().flatten().copied().collect();
    let e = rel_diff(&got, &exp);
    eprintln!("{label}: damping force rel. error {e:.1e}");
    assert!(e < 1e-7, "{label}: damping force rel. error {e:e}");
    assert!(
        (with.damping_work - work).abs() < 1e-7 * work.abs(),
        "{label}: damping work {} against {work}",
        with.damping_work
    );
    assert!(with.damping_work < 0.0 && without.damping_work == 0.0);
}

/// The Hessian blocks of the damped slab (every pair of e_a, v_a, e_b,
/// v_b) against central differences of its gradient.
fn check_slab_jacobian<const NS: usize, const ND: usize>(
    el: &CableElement<NS, ND>,
    slab: &TimeSlab,
    y: &[[f64; ND]; 4],
    label: &str,
) -> f64 {
    let loads = SlabLoads::gravity([0.2, -9.81, 0.0]);
    let mut d = SlabDerivatives::<ND>::default();
    el.slab_derivatives(slab, y, &loads, true, &mut d);
    let (mut dp, mut dm) = (SlabDerivatives::default(), SlabDerivatives::default());
    let (mut exact, mut fd) = (Vec::new(), Vec::new());
    let mut block = [[0.0; ND]; ND];
    for n in 0..4 {
        for b in 0..ND {
            let (mut yp, mut ym) = (*y, *y);
            yp[n][b] += H;
            ym[n][b] -= H;
            el.slab_derivatives(slab, &yp, &loads, false, &mut dp);
            el.slab_derivatives(slab, &ym, &loads, false, &mut dm);
            for m in 0..4 {
                el.slab_hessian_block(slab, &d, m, n, &mut block);
                for a in 0..ND {
                    exact.push(block[a][b]);
                    fd.push((dp.grad[m][a] - dm.grad[m][a]) / (2.0 * H));
                }
            }
        }
    }
    let e = rel_diff(&exact, &fd);
    eprintln!("{label}: slab Jacobian rel. error {e:.1e}");
    assert!(e < FD_TOL, "{label}: slab Jacobian rel. error {e:e}");
    e
}

/// The damped slab of SAC-2 and SAC-3, Green and engineering strain:
/// the damping force against an independent evaluation (M34), and the
/// exact Jacobian (every block, positions and velocities at both time
/// nodes) against central differences to 1e-7.
#[test]
fn slab_jacobian_with_axial_damping_matches_finite_differences() {
    let mut rng = Rng(0x0ba0_0ba1_0ba2_0ba3);
    for axial_strain in [AxialStrain::Green, AxialStrain::Engineering] {
        let m = Measures {
            axial_strain,
            ..Measures::default()
        };
        let time_rule = GaussRule::new(3).unwrap();
        let s = TimeSlab::new(0.05, &time_rule);
        let (r3, r5) = (rules(3, 3), rules(5, 5));
        let el2 = CableElement::new(cubic_hermite, 0.4, damped_section(0.7), m, &r3);
        let plain2 = CableElement::new(cubic_hermite, 0.4, section(), m, &r3);
        let el3 = CableElement::new(quintic_hermite, 0.4, damped_section(0.7), m, &r5);
        let plain3 = CableElement::new(quintic_hermite, 0.4, section(), m, &r5);
        let y2 = random_slab_state::<4, 12>(&mut rng, 0.4, 0.2);
        let y3 = random_slab_state::<6, 18>(&mut rng, 0.4, 0.2);
        let label2 = format!("SAC-2 {axial_strain:?}");
        let label3 = format!("SAC-3 {axial_strain:?}");
        check_damping_force(&el2, &plain2, cubic_hermite, &time_rule, &y2, 3, &label2);
        check_damping_force(&el3, &plain3, quintic_hermite, &time_rule, &y3, 5, &label3);
        check_slab_jacobian(&el2, &s, &y2, &label2);
        check_slab_jacobian(&el3, &s, &y3, &label3);
    }
}

/// A damped cable (BA comparable to EA dt-scaled forces), bent and moving.
fn damped_model(kind: ElementType, strain: AxialStrain, constraints: Vec<Constraint>) -> Model {
    let material = Material {
        youngs_modulus: 2.0e3,
        density: 900.0,
        area: 1.0e-3,
        second_moment: 2.0e-7,
        axial_damping: 0.3,
    };
    let cable = Cable::straight(1.2, 3, kind)
        .with_origin([0.1, -0.2, 0.3])
        .with_direction([1.0, 0.5, -0.25]);
    let options = ModelOptions {
        measures: Measures {
            axial_strain: strain,
            ..Measures::default()
        },
        ..ModelOptions::default()
    };
    let gravity = vec![Load::Gravity {
        acceleration: [0.0, -9.81, 0.0],
    }];
    Model::new(cable, material, options, gravity)
        .unwrap()
        .with_constraints(constraints)
        .unwrap()
}

/// Assembled steps of a damped cable: P2 with 1 and 2 layers and the
/// Galerkin step, SAC-2 and SAC-3, both strains, free and with a clamped
/// end and a moving node by both constraint routes: the step Jacobian
/// (every unknown of the slab) against central differences to 1e-7.
#[test]
fn step_jacobian_with_axial_damping_matches_finite_differences() {
    let mut rng = Rng(0x5eed_0bad_cafe_0001);
    let mut worst = 0.0f64;
    for kind in [ElementType::Sac2, ElementType::Sac3] {
        for strain in [AxialStrain::Green, AxialStrain::Engineering] {
            let model = |constrained: bool| {
                let cons = clamped_and_driven(constrained);
                damped_model(kind, strain, cons)
            };
            let schemes = [
                Scheme::P2 { layers: 1 },
                Scheme::P2 { layers: 2 },
                Scheme::Galerkin,
            ];
            let label = format!("{kind:?} {strain:?}");
            let e = check_schemes_and_routes(&model, &schemes, &mut rng, &label, FD_TOL);
            worst = worst.max(e);
        }
    }
    eprintln!("damped step Jacobians: worst rel. error {worst:.1e}");
}

/// The static equilibrium of a damped cable is the undamped one to the
/// bit: rates are zero in statics and the damping does not enter it.
#[test]
fn statics_ignore_the_axial_damping() {
    let solve = |ba: f64| {
        let material = Material::chen2023_gutta_percha().with_axial_damping(ba);
        let model = Model::new(
            Cable::straight(0.5, 6, ElementType::Sac2),
            material,
            ModelOptions::default(),
            vec![Load::Gravity {
                acceleration: [0.0, -9.81, 0.0],
            }],
        )
        .unwrap()
        .with_constraints(vec![Constraint {
            node: 0,
            kind: ConstraintKind::Clamped {
                fix_curvature: false,
            },
        }])
        .unwrap();
        let mut solver = StaticSolver::new(model, StaticSettings::default()).unwrap();
        solver.solve(|_, _| ControlFlow::Continue(())).unwrap();
        solver.state().e.clone()
    };
    assert_eq!(solve(0.0), solve(0.05));
}

/// MoorDyn's conversion of a damping ratio (its negative BA/-zeta entry):
/// BA = zeta l sqrt(EA w) (MoorDyn's Line.cpp: c = zeta l sqrt(E rho),
/// BA = c A), by hand for a chain-like section.
#[test]
fn a_damping_ratio_becomes_moordyns_coefficient() {
    let (ea, w, d) = (753.6e6, 113.35, 0.0766);
    let area = std::f64::consts::PI * d * d / 4.0;
    let material = Material {
        youngs_modulus: ea / area,
        density: w / area,
        area,
        second_moment: 1e-12,
        axial_damping: 0.0,
    };
    let (zeta, l) = (0.8, 835.35 / 20.0);
    // By hand: c = zeta (L / N) sqrt(E rho) (Pa s), BA = c A (N s).
    let e_mod = ea / area;
    let rho = w / area;
    let by_hand = zeta * l * (e_mod * rho).sqrt() * area;
    let got = material.axial_damping_for_ratio(zeta, l);
    assert!(
        (got - by_hand).abs() <= 1e-12 * by_hand,
        "{got} against {by_hand}"
    );
    // ... which is the damping ratio zeta of the mode at omega = 2 c / l
    // (M35): zeta(omega) = BA omega / (2 EA).
    let omega = 2.0 / l * (ea / w).sqrt();
    assert!((got * omega / (2.0 * ea) - zeta).abs() < 1e-12);
}

fn settings(dt: f64, scheme: TimeScheme) -> StepSettings {
    step_settings(dt, scheme, 1e-12)
}

/// The paper's gutta-percha pendulum (0.5 m, 4 SAC-2, pinned at end A,
/// released horizontal) with an axial stretching velocity v0 x / L on top,
/// damped by BA (engineering strain): the largest |E - E_0 - W_d| over
/// `duration`, the dissipated -W_d and the largest kinetic energy.
fn damped_pendulum(dt: f64, scheme: TimeScheme, duration: f64) -> (f64, f64, f64) {
    let material = Material::chen2023_gutta_percha().with_axial_damping(0.05);
    let options = ModelOptions {
        measures: Measures {
            axial_strain: AxialStrain::Engineering,
            ..Measures::default()
        },
        ..ModelOptions::default()
    };
    let model = Model::new(
        Cable::straight(0.5, 4, ElementType::Sac2),
        material,
        options,
        vec![Load::Gravity {
            acceleration: [0.0, -9.81, 0.0],
        }],
    )
    .unwrap()
    .with_constraints(vec![Constraint {
        node: 0,
        kind: ConstraintKind::Pinned,
    }])
    .unwrap();
    let mut s = model.initial_state();
    let v0 = 2.0;
    for j in 1..model.nodes() {
        let x = model.node_coordinate(j);
        s.v[model.coordinate(j, 0, 0)] = v0 * x / 0.5;
        s.v[model.coordinate(j, 1, 0)] = v0 / 0.5;
    }
    let mut sim = Simulation::new(model, s, settings(dt, scheme)).unwrap();
    let e0 = sim.energies().mechanical();
    let (mut worst, mut scale) = (0.0f64, 0.0f64);
    run(&mut sim, duration, |sim, _, en| {
        worst = worst.max((en.mechanical() - e0 - sim.damping_work()).abs());
        scale = scale.max(en.kinetic);
        ControlFlow::Continue(())
    })
    .unwrap();
    assert_eq!(sim.drag_work(), 0.0);
    (worst, -sim.damping_work(), scale)
}

/// A damped pendulum, also stretching and shrinking axially: the energy
/// it loses is the work its damping does, E - E_0 = W_d (M35), to the
/// scheme's accuracy; both sides are the same slab quadrature of the
/// discrete motion, so the balance error is the scheme's energy error.
/// P2 is fourth order: the error falls by 6.1, 8.8, 12.6 for successive
/// halvings of dt from 4e-4 s (on its way to 16), so a halving from 1e-4
/// to 5e-5 s must gain more than 8 (order above 3). The Galerkin step is
/// sixth order and its balance sits at round-off here (~1e-13 J at both
/// steps). The two schemes dissipate the same energy (to 1e-6 at 1e-4 s),
/// a third of the largest kinetic energy in 0.3 s.
#[test]
fn a_damped_pendulum_loses_what_its_damping_dissipates() {
    let (p2_coarse, dissipated, scale) = damped_pendulum(1e-4, TimeScheme::P2, 0.3);
    let (p2_fine, _, _) = damped_pendulum(5e-5, TimeScheme::P2, 0.3);
    let (g_coarse, g_dissipated, _) = damped_pendulum(2e-4, TimeScheme::Galerkin, 0.3);
    let (g_fine, _, _) = damped_pendulum(1e-4, TimeScheme::Galerkin, 0.3);
    eprintln!(
        "dissipated {dissipated:.6e} J ({:.2} of the largest kinetic energy); balance error: \
         P2 {p2_coarse:.2e} J at dt = 1e-4, {p2_fine:.2e} J at 5e-5 (ratio {:.1}); Galerkin \
         {g_coarse:.2e} J at 2e-4, {g_fine:.2e} J at 1e-4",
        dissipated / scale,
        p2_coarse / p2_fine
    );
    assert!(dissipated > 0.2 * scale, "the damping dissipates");
    assert!((dissipated - g_dissipated).abs() < 1e-5 * dissipated);
    assert!(p2_coarse < 1e-5 * dissipated, "{p2_coarse:e}");
    assert!(
        p2_coarse / p2_fine > 8.0,
        "order: ratio {}",
        p2_coarse / p2_fine
    );
    for g in [g_coarse, g_fine] {
        assert!(g < 1e-10 * dissipated, "Galerkin balance {g:e}");
    }
}

/// The taut rod of the decay test: length 1 m, EA = 1e3 N, m = 0.1 kg/m
/// (c = 100 m/s), end A pinned at the origin, end B held at (1 + eps0) L,
/// eps0 = 1e-3 (engineering strain: the axial motion is then exactly
/// linear, rho A u_tt = EA u_ss + BA u_sst).
const ROD: (f64, f64, f64) = (1.0, 1.0e3, 0.1);
const PRESTRAIN: f64 = 1e-3;

/// Maxima of the midpoint's axial displacement from its rest position,
/// each found on the cubic Hermite of the step it falls in (eq. 6, the
/// scheme's own interpolant, accurate to O(dt^4)), over `periods` periods
/// of the first mode, started with the axial velocity v0 sin(pi s / L).
fn rod_peaks(ba: f64, elements: usize, steps_per_period: usize, scheme: TimeScheme) -> Vec<f64> {
    let (l, ea, m) = ROD;
    let area = 1e-4;
    let material = Material {
        youngs_modulus: ea / area,
        density: m / area,
        area,
        second_moment: 1e-10,
        axial_damping: ba,
    };
    let options = ModelOptions {
        measures: Measures {
            axial_strain: AxialStrain::Engineering,
            ..Measures::default()
        },
        ..ModelOptions::default()
    };
    let b = [(1.0 + PRESTRAIN) * l, 0.0, 0.0];
    let model = Model::new(
        Cable::straight(l, elements, ElementType::Sac2),
        material,
        options,
        vec![],
    )
    .unwrap()
    .with_constraints(vec![
        Constraint {
            node: 0,
            kind: ConstraintKind::Pinned,
        },
        Constraint {
            node: elements,
            kind: ConstraintKind::Attached {
                position: b,
                motion: stancf::motion::CoupledMotion::NONE,
            },
        },
    ])
    .unwrap();
    let omega = std::f64::consts::PI / l * (ea / m).sqrt();
    let v0 = 0.01;
    let mut s = model.initial_state();
    for j in 0..model.nodes() {
        let x = model.node_coordinate(j);
        let k = std::f64::consts::PI / l;
        s.e[model.coordinate(j, 0, 0)] = (1.0 + PRESTRAIN) * x;
        s.e[model.coordinate(j, 1, 0)] = 1.0 + PRESTRAIN;
        s.v[model.coordinate(j, 0, 0)] = v0 * (k * x).sin();
        s.v[model.coordinate(j, 1, 0)] = v0 * k * (k * x).cos();
    }
    model.apply_constraints(&mut s);
    let period = 2.0 * std::f64::consts::PI / omega;
    let dt = period / steps_per_period as f64;
    let mid = model.coordinate(elements / 2, 0, 0);
    let rest = (1.0 + PRESTRAIN) * l / 2.0;
    let mut sim = Simulation::new(model, s, settings(dt, scheme)).unwrap();
    let mut peaks = Vec::new();
    let (mut ea_, mut va) = (sim.state().e[mid] - rest, sim.state().v[mid]);
    run(&mut sim, 6.0 * period, |sim, _, _| {
        let (eb, vb) = (sim.state().e[mid] - rest, sim.state().v[mid]);
        if va > 0.0 && vb <= 0.0 {
            peaks.push(hermite_maximum(ea_, va, eb, vb, dt));
        }
        (ea_, va) = (eb, vb);
        ControlFlow::Continue(())
    })
    .unwrap();
    peaks
}

/// The largest value of the cubic Hermite with end values a, b and end
/// slopes va > 0 >= vb over a step dt: at the root in [0, 1] of its
/// derivative, a quadratic in s = (t - t_a) / dt.
fn hermite_maximum(a: f64, va: f64, b: f64, vb: f64, dt: f64) -> f64 {
    let (p, q) = (va * dt, vb * dt);
    let c2 = 6.0 * a + 3.0 * p - 6.0 * b + 3.0 * q;
    let c1 = -6.0 * a - 4.0 * p + 6.0 * b - 2.0 * q;
    let c0 = p;
    let s = if c2.abs() < 1e-300 {
        -c0 / c1
    } else {
        let disc = (c1 * c1 - 4.0 * c2 * c0).max(0.0).sqrt();
        let roots = [(-c1 + disc) / (2.0 * c2), (-c1 - disc) / (2.0 * c2)];
        *roots
            .iter()
            .filter(|r| (-1e-12..=1.0 + 1e-12).contains(*r))
            .fold(&f64::NAN, |best, r| if best.is_nan() { r } else { best })
    };
    let (s2, s3) = (s * s, s * s * s);
    (2.0 * s3 - 3.0 * s2 + 1.0) * a
        + (s3 - 2.0 * s2 + s) * p
        + (-2.0 * s3 + 3.0 * s2) * b
        + (s3 - s2) * q
}

/// The damping ratio from successive maxima: their ratio is exactly
/// exp(zeta omega T_d) for a damped mode, so the logarithmic decrement
/// delta = ln(u_1 / u_n) / (n - 1) gives zeta = delta / sqrt(4 pi^2 +
/// delta^2).
fn damping_ratio_of(peaks: &[f64]) -> f64 {
    let n = peaks.len();
    assert!(n >= 5, "{n} maxima");
    let delta = (peaks[0] / peaks[n - 1]).ln() / (n - 1) as f64;
    delta / (4.0 * std::f64::consts::PI.powi(2) + delta * delta).sqrt()
}

/// A Kelvin-Voigt rod held taut at both ends, vibrating axially in its
/// first mode: the mode decays with the damping ratio
/// zeta_1 = BA omega_1 / (2 EA), omega_1 = pi / L sqrt(EA / m) (here
/// zeta_1 = 0.05), measured by the logarithmic decrement of the
/// midpoint's maxima over six periods, by P2 and by the Galerkin step.
///
/// Why the discrete rod should get it: for this linear motion the damping
/// matrix is BA / EA times the axial stiffness matrix (the same integral
/// of N_x N_x), so every discrete mode has zeta_n = BA omega_n^h / (2 EA)
/// exactly, and the error is that of omega_1^h (O((h / L)^6) for cubic
/// Hermite elements with the consistent mass: ~5e-8 at 8 elements) and
/// of the time scheme (P2 fourth order, the Galerkin step sixth:
/// O((omega dt)^4)). The bound below is (omega dt)^4 / 10, 2.5e-5 at 50
/// steps per period and 9.7e-8 at 200; measured 4.8e-7 (P2) and 3.8e-7
/// (Galerkin) at 8 elements and 50 steps per period, 3e-9 and 2e-12 at
/// 16 elements and 200.
#[test]
fn a_kelvin_voigt_rod_decays_with_zeta_ba_omega_over_2_ea() {
    let (l, ea, m) = ROD;
    let omega = std::f64::consts::PI / l * (ea / m).sqrt();
    let zeta = 0.05;
    let ba = 2.0 * ea * zeta / omega;
    for scheme in [TimeScheme::P2, TimeScheme::Galerkin] {
        let mut errors = Vec::new();
        for (elements, steps_per_period) in [(8, 50), (16, 200)] {
            let measured = damping_ratio_of(&rod_peaks(ba, elements, steps_per_period, scheme));
            let error = (measured / zeta - 1.0).abs();
            let bound = (2.0 * std::f64::consts::PI / steps_per_period as f64).powi(4) / 10.0;
            eprintln!(
                "{scheme:?}, {elements} elements, {steps_per_period} steps per period: zeta \
                 {measured:.10} (rel. error {error:.1e}, bound {bound:.1e})"
            );
            assert!(error < bound, "{scheme:?}: rel. error {error:e}");
            errors.push(error);
        }
        assert!(
            errors[1] < 0.1 * errors[0],
            "{scheme:?} converges: {errors:?}"
        );
    }
    // Without damping the maxima do not decay (the measurement's floor).
    let undamped = damping_ratio_of(&rod_peaks(0.0, 8, 50, TimeScheme::P2));
    assert!(undamped.abs() < 1e-7, "undamped: zeta {undamped:e}");
}
