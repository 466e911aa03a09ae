//! Systems of lines joined at points (docs/method.md §9): a system of
//! one line is the single cable; a coupled point carries its line end
//! along its motion.

use stancf::constraints::Oscillation;
use stancf::system::{End, Line, Point, System, SystemSimulation};
use stancf::{
    Cable, Constraint, ConstraintKind, ConstraintMethod, ElementType, Load, Material, Model,
    ModelOptions, Simulation, StepSettings,
};

const G: [f64; 3] = [0.0, -9.81, 0.0];

/// A light rope: 2 mm^2 at 1 MPa (1 % strain under its own weight over a
/// metre, wave speed 32 m/s), bending stiffness 1e-6 of
/// its axial one over a metre squared.
fn rope() -> Material {
    Material {
        youngs_modulus: 1e6,
        density: 1000.0,
        area: 2e-6,
        second_moment: 2e-12,
    }
}

fn line_model(length: f64, elements: usize, origin: [f64; 3]) -> Model {
    let cable = Cable::straight(length, elements, ElementType::Sac2)
        .with_origin(origin)
        .with_direction([1.0, 0.0, 0.0]);
    Model::new(
        cable,
        rope(),
        ModelOptions::default(),
        vec![Load::Gravity { acceleration: G }],
    )
    .expect("model")
}

fn settings(method: ConstraintMethod) -> StepSettings {
    StepSettings {
        time_step: 1e-3,
        constraint_method: method,
        ..StepSettings::default()
    }
}

#[test]
fn a_one_line_system_steps_like_the_single_cable() {
    for method in [ConstraintMethod::Multiplier, ConstraintMethod::Elimination] {
        let single = line_model(1.0, 8, [0.0; 3])
            .with_constraints(vec![Constraint {
                node: 0,
                kind: ConstraintKind::Pinned,
            }])
            .expect("pinned");
        let mut sim =
            Simulation::new(single.clone(), single.initial_state(), settings(method)).expect("sim");
        let model = line_model(1.0, 8, [0.0; 3]);
        let state = model.initial_state();
        let system = System::new(
            vec![Line {
                model,
                ends: [End::Point(0), End::Loose],
            }],
            vec![Point::fixed([0.0; 3])],
            G,
        )
        .expect("system");
        let mut sys = SystemSimulation::new(system, vec![state], settings(method)).expect("sys");
        for _ in 0..200 {
            sim.step().expect("step");
            sys.step().expect("system step");
        }
        let a = &sim.state().e;
        let b = &sys.lines()[0].state().e;
        let diff = a
            .iter()
            .zip(b)
            .map(|(x, y)| (x - y).abs())
            .fold(0.0, f64::max);
        assert!(diff <= 1e-12, "{method:?}: largest difference {diff:e} m");
        // The anchor holds the line's weight plus its inertia: the end
        // force is minus the reaction on the cable.
        let f = sys.end_forces(0)[0].force;
        let r = sim.reactions()[0].1;
        for c in 0..3 {
            assert!(
                (f[c] + r[c]).abs() <= 1e-9 * r[c].abs().max(1.0),
                "{f:?} vs {r:?}"
            );
        }
    }
}

#[test]
fn a_coupled_point_moves_its_line_end() {
    let model = line_model(1.0, 8, [0.0; 3]);
    let state = model.initial_state();
    let o = Oscillation {
        amplitude: [0.0, 0.1, 0.0],
        period: 0.5,
        phase: 0.0,
        ramp: 0.25,
    };
    let system = System::new(
        vec![Line {
            model,
            ends: [End::Point(0), End::Loose],
        }],
        vec![Point::coupled([0.0; 3], o)],
        G,
    )
    .expect("system");
    let mut sys =
        SystemSimulation::new(system, vec![state], settings(ConstraintMethod::Elimination))
            .expect("sys");
    for _ in 0..400 {
        sys.step().expect("step");
        let t = sys.time();
        let line = &sys.lines()[0];
        let r = line.model().node_position(&line.state().e, 0);
        let (f, _) = stancf::constraints::ramp_factor(t, 0.25);
        let want = 0.1 * f * (2.0 * std::f64::consts::PI * t / 0.5).sin();
        assert!((r[1] - want).abs() <= 1e-12, "t = {t}: {} vs {want}", r[1]);
        assert_eq!(sys.point_state(0).0[1], r[1]);
    }
}
