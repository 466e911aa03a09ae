//! Lines without compression (docs/method.md §2.2, (M4a)): a rope's end
//! pushed towards its other end transmits nothing, where a line that
//! carries compression pushes back with EA eps.

use stancf::{
    run, Cable, Constraint, ConstraintKind, ElementType, Material, Model, ModelOptions,
    NewtonSettings, Simulation, StepSettings, TimeScheme,
};
use std::ops::ControlFlow;

/// A straight 2 m rope (no gravity) pinned at node 0, its end B pushed
/// towards A at 0.1 m/s for 0.2 s: returns the largest force the pin
/// exerts on it, and the largest strain energy.
fn pushed_rope(compression: bool, scheme: TimeScheme) -> (f64, f64) {
    let material = Material {
        youngs_modulus: 1e6,
        density: 1000.0,
        area: 1e-3,
        second_moment: 1e-11,
        axial_damping: 0.0,
    };
    let cable = Cable::straight(2.0, 4, ElementType::Sac2).with_direction([0.6, 0.8, 0.0]);
    let model = Model::new(cable, material, ModelOptions::default(), vec![]).unwrap();
    let model = if compression {
        model
    } else {
        model.without_compression()
    };
    let constraints = vec![
        Constraint {
            node: 0,
            kind: ConstraintKind::Pinned,
        },
        Constraint {
            node: 4,
            kind: ConstraintKind::Prescribed {
                velocity: [-0.06, -0.08, 0.0],
                amplitude: [0.0; 3],
                frequency: 0.0,
                phase: 0.0,
            },
        },
    ];
    let model = model.with_constraints(constraints).unwrap();
    let s = model.initial_state();
    let settings = StepSettings {
        time_step: 1e-3,
        time_scheme: scheme,
        newton: NewtonSettings {
            tolerance: 1e-12,
            max_iterations: 50,
            ..NewtonSettings::default()
        },
        ..StepSettings::default()
    };
    let mut sim = Simulation::new(model, s, settings).unwrap();
    let (mut force, mut strain) = (0.0f64, 0.0f64);
    run(&mut sim, 0.2, |sim, _, en| {
        for (node, f) in sim.reactions() {
            if *node == 0 {
                force = force.max(f.iter().map(|c| c * c).sum::<f64>().sqrt());
            }
        }
        strain = strain.max(en.strain);
        ControlFlow::Continue(())
    })
    .unwrap();
    (force, strain)
}

/// Shortened from the start, the rope without compression has no axial
/// strain energy (what is left, below 1e-20 J, is its EI's share of a
/// round-off curvature) and its pin feels nothing (round-off of forces
/// of order EA = 1e3 N); with compression the pin is pushed by EA eps, eps = 0.02 / 2 =
/// 1e-2 at the end: 10 N and more (the wave from the pushed end).
#[test]
fn a_rope_pushed_together_pushes_back_with_nothing() {
    for scheme in [TimeScheme::P2, TimeScheme::Galerkin] {
        let (slack_force, slack_strain) = pushed_rope(false, scheme);
        let (stiff_force, stiff_strain) = pushed_rope(true, scheme);
        eprintln!(
            "{scheme:?}: pin force {slack_force:.1e} N without compression, {stiff_force:.3} N \
             with; strain energy {slack_strain:.1e} J, {stiff_strain:.3e} J"
        );
        assert!(slack_strain < 1e-20, "{scheme:?}: {slack_strain}");
        assert!(slack_force < 1e-9, "{scheme:?}: {slack_force}");
        assert!(stiff_force > 5.0, "{scheme:?}: {stiff_force}");
    }
}

/// The P2 step's stability of a rope without compression is judged on
/// its axial modes whether it starts slack or taut (docs/method.md §4.5,
/// `stancf::system::taut_states`): a slack rope straight between its ends
/// is compressed and has no axial stiffness there, and judged so its
/// "stable" step was that of its bending alone (here 45 times the
/// axial modes' limit) while it pulls taut within a step. Slack and just
/// taut, the limits agree to the geometric stiffness of a strain of
/// 1e-9 against EA's (1e-6 is far above it).
#[test]
fn a_slack_ropes_stable_p2_step_is_its_taut_axial_modes() {
    use crate::common::rope_systems::{line_model, G};
    use stancf::quadrature::GaussRule;
    use stancf::system::{stable_step, straight_states, End, Line, Point, System};
    let system_of = |chord: f64| {
        let (a, b) = ([0.0; 3], [chord, 0.0, -0.5]);
        let model = line_model([0.0; 3], [1.0, 0.0, -0.5], 10).without_compression();
        let line = Line {
            model,
            ends: [End::Point(0), End::Point(1)],
        };
        System::new(vec![line], vec![Point::fixed(a), Point::fixed(b)], G).unwrap()
    };
    let limit = |system: &System| stable_step(system, TimeScheme::P2, 3, 1).unwrap();
    let length = (1.0f64 + 0.25).sqrt();
    let slack = system_of(((0.8 * length).powi(2) - 0.25).sqrt());
    let (slack_limit, taut_limit) = (limit(&slack), limit(&system_of(1.0)));
    assert!(
        (slack_limit - taut_limit).abs() <= 1e-6 * taut_limit,
        "slack {slack_limit} s, taut {taut_limit} s"
    );
    let compressed = &straight_states(&slack)[0];
    let rule = GaussRule::new(3).unwrap();
    let bending_only =
        stancf::stability::stable_step(&slack.lines()[0].model, &compressed.e, &rule, 1).unwrap();
    assert!(
        bending_only > 10.0 * taut_limit,
        "{bending_only} s against {taut_limit} s"
    );
}
