//! Air drag (eq. 17) against analytic motions, and its energy accounting.

use stancf::loads::{AirDrag, DragModel};
use stancf::{
    run, Cable, Constraint, ConstraintKind, ElementType, Load, Material, Model, ModelOptions,
    NewtonSettings, Simulation, StepSettings,
};
use std::ops::ControlFlow;

const G: f64 = 9.81;

fn drag(c: f64, model: DragModel) -> AirDrag {
    AirDrag {
        drag_coefficient: c,
        fluid_density: 1.225,
        diameter: 3.7e-3,
        fluid_velocity: [0.0; 3],
        model,
    }
}

fn settings(dt: f64) -> StepSettings {
    StepSettings {
        time_step: dt,
        newton: NewtonSettings {
            tolerance: 1e-12,
            max_iterations: 50,
            ..NewtonSettings::default()
        },
        ..StepSettings::default()
    }
}

/// A straight horizontal cable falling under gravity with the paper's
/// ("full") drag: every point moves alike, so m v' = m g - 1/2 C rho d v^2
/// per unit length, v(t) = v_t tanh(g t / v_t) with the terminal velocity
/// v_t = sqrt(2 rho A g / (C rho_air d)). Checked along the way to 1e-6
/// relative (P2 is fourth order; dt = 1e-3 against a time constant of
/// 0.6 s) and at 3 s within 0.5 % of v_t.
#[test]
fn horizontal_cable_reaches_the_terminal_velocity() {
    let material = Material::chen2023_gutta_percha();
    let d = drag(1.5, DragModel::Full);
    for kind in [ElementType::Sac2, ElementType::Sac3] {
        let model = Model::new(
            Cable::straight(0.5, 2, kind),
            material,
            ModelOptions::default(),
            vec![
                Load::Gravity {
                    acceleration: [0.0, -G, 0.0],
                },
                Load::AirDrag(d),
            ],
        )
        .unwrap();
        let rho_a = material.density * material.area;
        let vt = (2.0 * rho_a * G / (d.drag_coefficient * d.fluid_density * d.diameter)).sqrt();
        let s = model.initial_state();
        let mut sim = Simulation::new(model, s, settings(1e-3)).unwrap();
        let mut worst = 0.0f64;
        run(&mut sim, 3.0, |sim, rep, _| {
            let v = -sim.state().v[1];
            let exact = vt * (G * rep.t / vt).tanh();
            worst = worst.max((v - exact).abs() / vt);
            ControlFlow::Continue(())
        })
        .unwrap();
        let v = -sim.state().v[1];
        eprintln!(
            "{kind:?}: v(3 s) = {v:.6} m/s, terminal {vt:.6} m/s; worst deviation from \
             v_t tanh(g t / v_t): {worst:.2e} of v_t; drag work {:.6e} J",
            sim.drag_work()
        );
        assert!((v / vt - 1.0).abs() < 5e-3);
        assert!(worst < 1e-6, "{worst}");
        // Every node falls alike: the cable stays straight and horizontal.
        let dpn = kind.dofs_per_node();
        for j in 0..3 {
            assert!((sim.state().e[j * dpn + 1] - sim.state().e[1]).abs() < 1e-9);
        }
    }
}

/// A vertical cable falling along its own axis: the cross-flow ("normal")
/// drag sees no normal velocity, so it falls freely, y = y0 - g t^2 / 2
/// (to 1e-9 m after 1 s; P2 reproduces the quadratic motion).
#[test]
fn vertical_cable_falls_freely_under_cross_flow_drag() {
    let model = Model::new(
        Cable::straight(0.5, 4, ElementType::Sac2).with_direction([0.0, -1.0, 0.0]),
        Material::chen2023_gutta_percha(),
        ModelOptions::default(),
        vec![
            Load::Gravity {
                acceleration: [0.0, -G, 0.0],
            },
            Load::AirDrag(drag(
                1.5,
                DragModel::Normal {
                    tangential_coefficient: 0.0,
                },
            )),
        ],
    )
    .unwrap();
    let s = model.initial_state();
    let y0: Vec<f64> = (0..5).map(|j| model.node_position(&s.e, j)[1]).collect();
    let mut sim = Simulation::new(model, s, settings(1e-3)).unwrap();
    let mut worst = 0.0f64;
    run(&mut sim, 1.0, |sim, rep, _| {
        for (j, y) in y0.iter().enumerate() {
            let r = sim.model().node_position(&sim.state().e, j);
            let exact = y - 0.5 * G * rep.t * rep.t;
            worst = worst
                .max((r[1] - exact).abs())
                .max(r[0].abs())
                .max(r[2].abs());
        }
        ControlFlow::Continue(())
    })
    .unwrap();
    eprintln!("vertical fall: worst deviation from free fall {worst:.2e} m");
    assert!(worst < 1e-9, "{worst}");
    assert!(sim.drag_work().abs() < 1e-15);
}

/// The paper's pendulum with drag (C = 1.5, 4 SAC-2): the mechanical
/// energy never rises from one step to the next beyond what the solver
/// tolerance allows (tolerance 1e-12 of L in position, times the largest
/// force, the weight: ~1e-13 J), and the energy balance E - E0 = W_drag
/// holds to the scheme's accuracy.
#[test]
fn pendulum_energy_decreases_with_drag() {
    let material = Material::chen2023_gutta_percha();
    let model = Model::new(
        Cable::straight(0.5, 4, ElementType::Sac2),
        material,
        ModelOptions::default(),
        vec![
            Load::Gravity {
                acceleration: [0.0, -G, 0.0],
            },
            Load::AirDrag(drag(1.5, DragModel::Full)),
        ],
    )
    .unwrap()
    .with_constraints(vec![Constraint {
        node: 0,
        kind: ConstraintKind::Pinned,
    }])
    .unwrap();
    let weight = material.density * material.area * 0.5 * G;
    let allowance = 1e-12 * 0.5 * weight;
    let s = model.initial_state();
    let mut sim = Simulation::new(model, s, settings(1e-4)).unwrap();
    let mut previous = sim.energies().mechanical();
    let e0 = previous;
    let (mut worst_rise, mut worst_balance, mut scale) = (f64::MIN, 0.0f64, 0.0f64);
    run(&mut sim, 0.8, |sim, _, en| {
        let e = en.mechanical();
        worst_rise = worst_rise.max(e - previous);
        previous = e;
        scale = scale.max(en.kinetic);
        worst_balance = worst_balance.max((e - e0 - sim.drag_work()).abs());
        ControlFlow::Continue(())
    })
    .unwrap();
    eprintln!(
        "pendulum with drag: largest rise of energy in a step {worst_rise:.2e} J (allowance \
         {allowance:.1e} J), energy balance {:.2e} of the kinetic scale, dissipated {:.4e} J",
        worst_balance / scale,
        -sim.drag_work()
    );
    assert!(worst_rise <= allowance, "{worst_rise}");
    assert!(worst_balance < 1e-8 * scale);
    assert!(sim.drag_work() < -1e-4 * scale, "drag dissipated energy");
}
