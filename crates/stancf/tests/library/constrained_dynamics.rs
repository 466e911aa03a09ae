//! Constrained dynamics: the paper's pinned pendulum (section 5, no drag),
//! a clamped cantilever and a prescribed support motion, with both
//! constraint routes (multipliers and elimination).

use stancf::observe::momentum;
use stancf::{
    run, Cable, Constraint, ConstraintKind, ConstraintMethod, ElementType, Load, Material, Model,
    ModelOptions, NewtonSettings, Simulation, StepSettings,
};
use std::ops::ControlFlow;

fn gutta_percha() -> Material {
    Material::chen2023_gutta_percha()
}

const G: [f64; 3] = [0.0, -9.81, 0.0];

fn pendulum(kind: ElementType, elements: usize, constraint: ConstraintKind) -> Model {
    Model::new(
        Cable::straight(0.5, elements, kind),
        gutta_percha(),
        ModelOptions::default(),
        vec![Load::Gravity { acceleration: G }],
    )
    .unwrap()
    .with_constraints(vec![Constraint {
        node: 0,
        kind: constraint,
    }])
    .unwrap()
}

fn settings(dt: f64, method: ConstraintMethod, tol: f64) -> StepSettings {
    StepSettings {
        time_step: dt,
        constraint_method: method,
        newton: NewtonSettings {
            tolerance: tol,
            max_iterations: 50,
            ..NewtonSettings::default()
        },
        ..StepSettings::default()
    }
}

/// What a run records: the energy band (relative to the energy scale),
/// the largest excursion of the constrained node from its prescribed
/// position, the worst defect of the discrete momentum balance, and the
/// final coordinates.
struct Record {
    band: f64,
    node_error: f64,
    momentum_defect: f64,
    final_e: Vec<f64>,
    work: f64,
}

fn simulate(model: Model, dt: f64, duration: f64, method: ConstraintMethod, tol: f64) -> Record {
    simulate_perturbed(model, dt, duration, method, tol, 0.0)
}

fn simulate_perturbed(
    model: Model,
    dt: f64,
    duration: f64,
    method: ConstraintMethod,
    tol: f64,
    perturbation: f64,
) -> Record {
    let mut s = model.initial_state();
    let last = s.e.len() - 5;
    s.e[last] += perturbation;
    let (mass, _, _) = momentum(&model, &s);
    let motion: Vec<_> = (0..3)
        .map(|c| model.constraints.motion[c].clone().unwrap())
        .collect();
    let mut sim = Simulation::new(model, s, settings(dt, method, tol)).unwrap();
    let e0 = sim.energies();
    let (mut p_prev, mut scale, mut worst) = (momentum(sim.model(), sim.state()).1, 0.0f64, 0.0f64);
    let (mut node_error, mut defect) = (0.0f64, 0.0f64);
    let mut t_prev = 0.0;
    run(&mut sim, duration, |sim, rep, en| {
        let work = sim.constraint_work();
        scale = scale.max(en.kinetic + en.strain + (en.gravity - e0.gravity).abs() + work.abs());
        worst = worst.max((en.mechanical() - e0.mechanical() - work).abs());
        let r = sim.model().node_position(&sim.state().e, 0);
        for c in 0..3 {
            node_error = node_error.max((r[c] - motion[c].value(rep.t)).abs());
        }
        // P_b - P_a = (m g + reaction) dt, exactly for P2 (rigid
        // translation invariance of the action; see Simulation::reactions).
        let p = momentum(sim.model(), sim.state()).1;
        let h = rep.t - t_prev;
        let f = sim.reactions()[0].1;
        for c in 0..3 {
            let d = (p[c] - p_prev[c]) - (mass * G[c] + f[c]) * h;
            defect = defect.max(d.abs() / (mass * 9.81 * h));
        }
        p_prev = p;
        t_prev = rep.t;
        ControlFlow::Continue(())
    })
    .unwrap();
    Record {
        band: worst / scale,
        node_error,
        momentum_defect: defect,
        final_e: sim.state().e.clone(),
        work: sim.constraint_work(),
    }
}

fn max_diff(a: &[f64], b: &[f64]) -> f64 {
    a.iter()
        .zip(b)
        .map(|(x, y)| (x - y).abs())
        .fold(0.0, f64::max)
}

/// The paper's pendulum (Table 9, 4 SAC-2, pinned at A, released
/// horizontal at rest), 0.8 s, no drag:
///
/// - the pin stays at the origin to 1e-12 m;
/// - the energy error is the scheme's: it falls with order ~4 from
///   dt = 2e-4 to 1e-4 and is below 1e-9 of the energy scale at 1e-4
///   (measured ~1e-10);
/// - the reaction at the pin balances gravity and the inertia of the
///   cable: the momentum change of every step equals (m g + R) dt to
///   1e-9 of the weight impulse (round-off of the momentum sum);
/// - multipliers and elimination give the same motion to 1e-10 m.
#[test]
fn chen2023_pendulum_pinned_without_drag() {
    let m = || pendulum(ElementType::Sac2, 4, ConstraintKind::Pinned);
    let coarse = simulate(m(), 2e-4, 0.8, ConstraintMethod::Multiplier, 1e-12);
    let fine = simulate(m(), 1e-4, 0.8, ConstraintMethod::Multiplier, 1e-12);
    let elim = simulate(m(), 1e-4, 0.8, ConstraintMethod::Elimination, 1e-12);
    let order = (coarse.band / fine.band).log2();
    eprintln!(
        "pendulum: energy band {:.3e} (dt 2e-4) {:.3e} (dt 1e-4), order {order:.2}; pin {:.1e} m; \
         momentum defect {:.1e}; routes differ by {:.1e} m",
        coarse.band,
        fine.band,
        fine.node_error,
        fine.momentum_defect,
        max_diff(&fine.final_e, &elim.final_e)
    );
    assert!(fine.node_error <= 1e-12 && elim.node_error <= 1e-12);
    assert!(fine.band < 1e-9, "band {}", fine.band);
    assert!(order > 3.5, "energy error order {order}");
    assert!(fine.momentum_defect < 1e-9 && elim.momentum_defect < 1e-9);
    assert!(max_diff(&fine.final_e, &elim.final_e) < 1e-10);
}

/// A SAC-3 cantilever clamped at A (r, r_x fixed), falling under gravity
/// from the horizontal: the clamp holds, the energy is conserved, and the
/// two routes agree to 1e-10 m.
#[test]
fn clamped_cantilever_both_routes_agree() {
    let m = || {
        pendulum(
            ElementType::Sac3,
            4,
            ConstraintKind::Clamped {
                fix_curvature: false,
            },
        )
    };
    let a = simulate(m(), 5e-5, 0.3, ConstraintMethod::Multiplier, 1e-12);
    let b = simulate(m(), 5e-5, 0.3, ConstraintMethod::Elimination, 1e-12);
    let diff = max_diff(&a.final_e, &b.final_e);
    eprintln!(
        "clamped SAC-3: band {:.3e}, routes differ by {diff:.1e} m",
        a.band
    );
    assert!(a.node_error <= 1e-12 && b.node_error <= 1e-12);
    // r_x of the clamp stays the reference tangent.
    assert!((a.final_e[3] - 1.0).abs() < 1e-12 && a.final_e[4].abs() < 1e-12);
    assert!(a.band < 1e-8);
    assert!(diff < 1e-10, "{diff}");
}

/// End A shaken: r(t) = r0 + u t + a sin(2 pi f t + phi). The node follows
/// the motion to round-off, the energy balance E - E0 = W (work of the
/// reaction) holds to the discretization error, and the two routes agree:
/// to 1e-10 m over 0.1 s. Later the shaken cable amplifies round-off (a
/// 1e-13 m change of the initial state grows to ~1e-7 m by 0.5 s), so over
/// 0.5 s the routes must differ by less than such a perturbation does.
#[test]
fn prescribed_support_motion() {
    let shake = ConstraintKind::Prescribed {
        velocity: [0.0, 0.05, 0.0],
        amplitude: [0.03, 0.0, 0.01],
        frequency: 2.0,
        phase: 0.3,
    };
    let m = || pendulum(ElementType::Sac2, 4, shake.clone());
    let tol = 1e-12;
    let short_a = simulate(m(), 1e-4, 0.1, ConstraintMethod::Multiplier, tol);
    let short_b = simulate(m(), 1e-4, 0.1, ConstraintMethod::Elimination, tol);
    let short = max_diff(&short_a.final_e, &short_b.final_e);
    let a = simulate(m(), 1e-4, 0.5, ConstraintMethod::Multiplier, tol);
    let b = simulate(m(), 1e-4, 0.5, ConstraintMethod::Elimination, tol);
    let c = simulate_perturbed(m(), 1e-4, 0.5, ConstraintMethod::Multiplier, tol, 1e-13);
    let routes = max_diff(&a.final_e, &b.final_e);
    let perturbed = max_diff(&a.final_e, &c.final_e);
    eprintln!(
        "prescribed: node error {:.1e} m, energy balance {:.3e} of the scale (work {:.4e} J), \
         momentum defect {:.1e}; routes differ by {short:.1e} m at 0.1 s, {routes:.1e} m at 0.5 s \
         (a 1e-13 m perturbation: {perturbed:.1e} m)",
        a.node_error, a.band, a.work, a.momentum_defect
    );
    assert!(a.node_error < 1e-12 && b.node_error < 1e-12);
    assert!(a.work.abs() > 1e-4, "the support did work");
    assert!(a.band < 1e-4, "energy balance {}", a.band);
    assert!(a.momentum_defect < 1e-9);
    assert!(short < 1e-10, "{short}");
    assert!(routes < perturbed, "{routes} vs {perturbed}");
}

/// A moment of 1.5 pi EI / L suddenly applied at the free end of a short
/// clamped PVC cantilever: the tip overshoots its static rotation of
/// 1.5 pi past 2 pi. The moment's potential -M theta needs theta followed
/// continuously through +-pi; the energy T + U - M theta stays conserved
/// (a wrap error would jump it by 2 pi M).
#[test]
fn end_moment_in_dynamics_conserves_energy_through_full_turns() {
    let pvc = Material::chen2023_pvc();
    let (length, n) = (0.2, 8);
    let m = 1.5 * std::f64::consts::PI * pvc.youngs_modulus * pvc.second_moment / length;
    let model = Model::new(
        Cable::straight(length, n, ElementType::Sac2),
        pvc,
        ModelOptions::default(),
        vec![Load::EndMoment {
            node: n,
            moment: [0.0, 0.0, m],
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
    let s = model.initial_state();
    let mut sim = Simulation::new(
        model,
        s,
        settings(2e-6, ConstraintMethod::Multiplier, 1e-12),
    )
    .unwrap();
    let e0 = sim.energies().mechanical();
    let (mut max_theta, mut scale, mut worst) = (0.0f64, 0.0f64, 0.0f64);
    run(&mut sim, 0.08, |_, _, en| {
        max_theta = max_theta.max(-en.load_potential / m);
        scale = scale.max(en.kinetic + en.strain);
        worst = worst.max((en.mechanical() - e0).abs());
        ControlFlow::Continue(())
    })
    .unwrap();
    eprintln!(
        "end moment: tip rotation up to {:.3} pi, energy band {:.3e} of {scale:.3e} J",
        max_theta / std::f64::consts::PI,
        worst / scale
    );
    assert!(
        max_theta > 2.0 * std::f64::consts::PI,
        "the tip turned {max_theta} rad only"
    );
    assert!(worst < 1e-6 * scale, "energy band {}", worst / scale);
}
