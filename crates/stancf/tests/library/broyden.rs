//! Broyden rank one (eq. 27) against Newton on the paper's problems: the
//! same converged motion, with far fewer factorizations.

use stancf::loads::{AirDrag, DragModel};
use stancf::{
    run, Cable, Constraint, ConstraintKind, ElementType, Load, Material, Model, ModelOptions,
    NewtonSettings, Simulation, SolverMethod, StepSettings,
};
use std::ops::ControlFlow;

fn solve(
    model: Model,
    dt: f64,
    duration: f64,
    method: SolverMethod,
) -> (Vec<f64>, usize, usize, usize) {
    let s = model.initial_state();
    solve_from(model, s, dt, duration, method)
}

/// Final coordinates, factorizations, iterations and steps of a run.
fn solve_from(
    model: Model,
    s: stancf::State,
    dt: f64,
    duration: f64,
    method: SolverMethod,
) -> (Vec<f64>, usize, usize, usize) {
    let settings = StepSettings {
        time_step: dt,
        newton: NewtonSettings {
            tolerance: 1e-12,
            max_iterations: 50,
            method,
        },
        ..StepSettings::default()
    };
    let mut sim = Simulation::new(model, s, settings).unwrap();
    let (mut factorizations, mut iterations) = (0, 0);
    run(&mut sim, duration, |_, rep, _| {
        factorizations += rep.newton.factorizations;
        iterations += rep.newton.iterations;
        ControlFlow::Continue(())
    })
    .unwrap();
    (
        sim.state().e.clone(),
        factorizations,
        iterations,
        sim.steps(),
    )
}

fn compare(label: &str, model: impl Fn() -> Model, dt: f64, duration: f64) {
    let (en, fn_, itn, steps) = solve(model(), dt, duration, SolverMethod::Newton);
    for method in [SolverMethod::Broyden, SolverMethod::ModifiedNewton] {
        let (eb, fb, itb, _) = solve(model(), dt, duration, method);
        let diff = en
            .iter()
            .zip(&eb)
            .map(|(a, b)| (a - b).abs())
            .fold(0.0, f64::max);
        eprintln!(
            "{label}: {steps} steps; Newton {fn_} factorizations, {itn} iterations; {method:?} \
             {fb} factorizations, {itb} iterations; coordinates differ by {diff:.2e}"
        );
        assert!(diff < 1e-8, "{label}: {diff}");
        assert!(fb < steps, "{label}: {fb} factorizations for {steps} steps");
    }
}

#[test]
fn broyden_agrees_with_newton_on_the_pendulum_with_drag() {
    let model = || {
        let m = Material::chen2023_gutta_percha();
        Model::new(
            Cable::straight(0.5, 4, ElementType::Sac2),
            m,
            ModelOptions::default(),
            vec![
                Load::Gravity {
                    acceleration: [0.0, -9.81, 0.0],
                },
                Load::AirDrag(AirDrag {
                    drag_coefficient: 1.5,
                    fluid_density: 1.225,
                    diameter: (4.0 * m.area / std::f64::consts::PI).sqrt(),
                    fluid_velocity: [0.0; 3],
                    model: DragModel::Full,
                }),
            ],
        )
        .unwrap()
        .with_constraints(vec![Constraint {
            node: 0,
            kind: ConstraintKind::Pinned,
        }])
        .unwrap()
    };
    compare("pendulum with drag", model, 1e-4, 0.8);
}

#[test]
fn broyden_agrees_with_newton_on_the_axial_impact() {
    for kind in [ElementType::Sac2, ElementType::Sac3] {
        let impact = |method| {
            let m = Model::new(
                Cable::straight(4.0, 8, kind).with_origin([-2.0, 0.0, 0.0]),
                Material::chen2023_pvc(),
                ModelOptions::default(),
                vec![],
            )
            .unwrap();
            let mut s = m.initial_state();
            m.set_node_velocity(&mut s, 0, [10.0, 0.0, 0.0]);
            m.set_node_velocity(&mut s, 8, [-10.0, 0.0, 0.0]);
            solve_from(m, s, 1e-5, 4e-3, method)
        };
        let (en, fn_, _, steps) = impact(SolverMethod::Newton);
        let (eb, fb, _, _) = impact(SolverMethod::Broyden);
        let diff = en
            .iter()
            .zip(&eb)
            .map(|(a, b)| (a - b).abs())
            .fold(0.0, f64::max);
        eprintln!(
            "axial impact {kind:?}: {steps} steps; Newton {fn_} factorizations; Broyden {fb}; \
             differ by {diff:.2e}"
        );
        assert!(diff < 1e-8);
        assert!(fb < steps);
    }
}
