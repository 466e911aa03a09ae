//! `integrator::step_unknowns` (what `stancf check` reports of a large
//! mesh without building the simulation) counts what `Simulation::new`
//! builds and refuses what it refuses.

use stancf::integrator::step_unknowns;
use stancf::{
    Cable, Constraint, ConstraintKind, ConstraintMethod, ElementType, Load, Material, Model,
    ModelOptions, Simulation, StepSettings, TimeScheme,
};

fn model(
    kind: ElementType,
    direction: [f64; 3],
    loads: Vec<Load>,
    constraints: Vec<Constraint>,
) -> Model {
    Model::new(
        Cable::straight(2.0, 5, kind).with_direction(direction),
        Material::chen2023_pvc(),
        ModelOptions::default(),
        loads,
    )
    .unwrap()
    .with_constraints(constraints)
    .unwrap()
}

#[test]
fn step_unknowns_counts_what_a_simulation_builds() {
    let clamped = ConstraintKind::Clamped {
        fix_curvature: false,
    };
    let driven = ConstraintKind::Prescribed {
        velocity: [0.0, 0.1, 0.0],
        amplitude: [0.01, 0.0, 0.0],
        frequency: 3.0,
        phase: 0.0,
    };
    let held = [
        vec![],
        vec![Constraint {
            node: 0,
            kind: ConstraintKind::Pinned,
        }],
        vec![
            Constraint {
                node: 0,
                kind: clamped,
            },
            Constraint {
                node: 5,
                kind: driven,
            },
        ],
    ];
    let gravity = Load::Gravity {
        acceleration: [0.0, -9.81, 0.0],
    };
    let out_of_plane = Load::PointForce {
        node: 5,
        force: [0.0, 0.0, 0.1],
    };
    let mut planar_seen = [false; 2];
    for kind in [ElementType::Sac2, ElementType::Sac3] {
        for (direction, loads) in [
            ([1.0, 0.0, 0.0], vec![gravity.clone()]),
            ([1.0, 0.0, 0.0], vec![gravity.clone(), out_of_plane.clone()]),
            ([0.6, 0.0, 0.8], vec![]),
        ] {
            for constraints in &held {
                for (scheme, layers) in [
                    (TimeScheme::P2, 1),
                    (TimeScheme::P2, 3),
                    (TimeScheme::Galerkin, 1),
                ] {
                    for method in [ConstraintMethod::Multiplier, ConstraintMethod::Elimination] {
                        for planar_reduction in [true, false] {
                            let m = model(kind, direction, loads.clone(), constraints.clone());
                            let mut s = m.initial_state();
                            m.set_node_velocity(&mut s, 3, [0.0, 1.0, 0.0]);
                            let settings = StepSettings {
                                time_scheme: scheme,
                                time_layers: layers,
                                constraint_method: method,
                                planar_reduction,
                                ..StepSettings::default()
                            };
                            let counted = step_unknowns(&m, &s, &settings).unwrap();
                            let sim = Simulation::new(m, s, settings).unwrap();
                            let built = (sim.unknowns_per_step(), sim.is_planar());
                            assert_eq!(
                                counted,
                                built,
                                "{kind:?} {direction:?} {} loads, {} constraints, {scheme:?} x \
                                 {layers}, {method:?}, reduction {planar_reduction}",
                                loads.len(),
                                constraints.len()
                            );
                            planar_seen[usize::from(built.1)] = true;
                        }
                    }
                }
            }
        }
    }
    assert_eq!(planar_seen, [true, true], "both planar and 3-D cases");
}

/// The settings and states `Simulation::new` refuses are refused with the
/// same key.
#[test]
fn step_unknowns_refuses_what_a_simulation_refuses() {
    let m = model(ElementType::Sac2, [1.0, 0.0, 0.0], vec![], vec![]);
    let s = m.initial_state();
    let mut short = s.clone();
    short.e.pop();
    let mut not_finite = s.clone();
    not_finite.v[4] = f64::NAN;
    let torsion = model(
        ElementType::Sac2,
        [1.0, 0.0, 0.0],
        vec![Load::EndMoment {
            node: 5,
            moment: [1.0, 0.0, 0.0],
        }],
        vec![],
    );
    let torsion_state = torsion.initial_state();
    let base = StepSettings::default();
    let cases: Vec<(&Model, &stancf::State, StepSettings)> = vec![
        (
            &m,
            &s,
            StepSettings {
                time_step: 0.0,
                ..base.clone()
            },
        ),
        (
            &m,
            &s,
            StepSettings {
                time_layers: 0,
                ..base.clone()
            },
        ),
        (
            &m,
            &s,
            StepSettings {
                time_points: 11,
                ..base.clone()
            },
        ),
        (
            &m,
            &s,
            StepSettings {
                time_scheme: TimeScheme::Galerkin,
                time_layers: 2,
                ..base.clone()
            },
        ),
        (&m, &short, base.clone()),
        (&m, &not_finite, base.clone()),
        (&torsion, &torsion_state, base.clone()),
    ];
    for (model, state, settings) in cases {
        let counted = step_unknowns(model, state, &settings).unwrap_err();
        let built = Simulation::new(model.clone(), state.clone(), settings)
            .err()
            .expect("refused");
        assert_eq!(counted, built);
    }
}
