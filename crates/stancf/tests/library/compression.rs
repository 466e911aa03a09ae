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
