//! The assembled systems (a P2 step with time layers, eq. 22, and a static
//! solve) against finite differences of their residuals, with every kind
//! of load and constraint, by both constraint routes.

use crate::common::step_checks::{check_jacobian, random_start};
use crate::common::*;
use stancf::assembly::{AssemblyScratch, Kind, Scheme, SlabLayout, StepProblem, StepStart};
use stancf::element::TimeSlab;
use stancf::quadrature::GaussRule;
use stancf::{
    Cable, Constraint, ConstraintKind, ConstraintMethod, ElementType, Load, Material, Model,
    ModelOptions,
};

fn model(
    kind: ElementType,
    elements: usize,
    loads: Vec<Load>,
    constraints: Vec<Constraint>,
) -> Model {
    let material = Material {
        youngs_modulus: 2.0e3,
        density: 900.0,
        area: 1.0e-3,
        second_moment: 2.0e-7,
        axial_damping: 0.0,
    };
    let cable = Cable::straight(1.2, elements, kind)
        .with_origin([0.1, -0.2, 0.3])
        .with_direction([1.0, 0.5, -0.25]);
    Model::new(cable, material, ModelOptions::default(), loads)
        .unwrap()
        .with_constraints(constraints)
        .unwrap()
}

fn all_loads() -> Vec<Load> {
    vec![
        Load::Gravity {
            acceleration: [0.0, -9.81, 0.0],
        },
        Load::PointForce {
            node: 2,
            force: [0.3, 0.1, -0.2],
        },
        Load::EndMoment {
            node: 3,
            moment: [0.01, 0.02, 0.05],
        },
        Load::AirDrag(stancf::loads::AirDrag {
            drag_coefficient: 1.3,
            fluid_density: 1.2,
            diameter: 0.02,
            fluid_velocity: [0.5, 0.2, -0.3],
            model: stancf::loads::DragModel::Normal {
                tangential_coefficient: 0.1,
            },
        }),
        Load::AirDrag(stancf::loads::AirDrag {
            drag_coefficient: 0.8,
            fluid_density: 1.2,
            diameter: 0.02,
            fluid_velocity: [0.0; 3],
            model: stancf::loads::DragModel::Full,
        }),
    ]
}

fn some_constraints(kind: ElementType) -> Vec<Constraint> {
    vec![
        Constraint {
            node: 0,
            kind: ConstraintKind::Clamped {
                fix_curvature: kind == ElementType::Sac3,
            },
        },
        Constraint {
            node: 2,
            kind: ConstraintKind::Prescribed {
                velocity: [0.1, 0.0, -0.2],
                amplitude: [0.0, 0.02, 0.01],
                frequency: 3.0,
                phase: 0.4,
            },
        },
    ]
}

/// P2 steps with 1 to 3 layers, SAC-2 and SAC-3, gravity, a point force,
/// an end moment and air drag (full and cross-flow, in wind), free and
/// constrained (clamp, prescribed motion) by
/// both routes.
#[test]
fn step_jacobian_matches_finite_differences() {
    let mut rng = Rng(0x7777_1234_abcd_0099);
    for kind in [ElementType::Sac2, ElementType::Sac3] {
        for layers in 1..=3 {
            for (constrained, method) in [
                (false, ConstraintMethod::Multiplier),
                (true, ConstraintMethod::Multiplier),
                (true, ConstraintMethod::Elimination),
            ] {
                let cons = if constrained {
                    some_constraints(kind)
                } else {
                    vec![]
                };
                let m = model(kind, 3, all_loads(), cons);
                let layout = SlabLayout::new(&m, Scheme::P2 { layers }, method);
                let h = 0.02 / layers as f64;
                let slab = TimeSlab::new(h, &GaussRule::new(3).unwrap());
                let start = random_start(&m, &layout, h, &mut rng);
                let label =
                    format!("{kind:?} {layers} layers, constrained {constrained} {method:?}");
                check_jacobian(&m, &layout, &slab, &start, &mut rng, &label, 1e-6);
            }
        }
    }
}

/// The static system dU/de - f = 0 with load factor, moment, wind load
/// (drag on a cable at rest) and constraints by both routes.
#[test]
fn static_jacobian_matches_finite_differences() {
    let mut rng = Rng(0x1111_2222_3333_4444);
    for kind in [ElementType::Sac2, ElementType::Sac3] {
        for method in [ConstraintMethod::Multiplier, ConstraintMethod::Elimination] {
            let m = model(kind, 3, all_loads(), some_constraints(kind));
            let layout = SlabLayout::new(&m, Scheme::Static, method);
            let slab = TimeSlab::new(1.0, &GaussRule::new(1).unwrap());
            let mut start = random_start(&m, &layout, 0.0, &mut rng);
            start.load_factor = 0.7;
            check_jacobian(
                &m,
                &layout,
                &slab,
                &start,
                &mut rng,
                &format!("static {kind:?} {method:?}"),
                1e-6,
            );
        }
    }
}

/// A line end clamped in a direction (r pinned, r_x held parallel to an
/// oblique d by multipliers, docs/method.md §6.10) beside the other
/// constraints: P2 with 1 to 3 layers and statics, SAC-2 and SAC-3.
#[test]
fn a_direction_hold_jacobian_matches_finite_differences() {
    let mut rng = Rng(0x5eed_00f0_c1a3_9e11);
    for kind in [ElementType::Sac2, ElementType::Sac3] {
        let mut cons = some_constraints(kind);
        cons.push(Constraint {
            node: 3,
            kind: ConstraintKind::Pinned,
        });
        cons.push(Constraint {
            node: 3,
            kind: ConstraintKind::Parallel {
                direction: [0.8, -0.3, 0.5],
            },
        });
        let m = model(kind, 3, all_loads(), cons);
        for scheme in [
            Scheme::P2 { layers: 1 },
            Scheme::P2 { layers: 2 },
            Scheme::P2 { layers: 3 },
            Scheme::Galerkin,
            Scheme::Static,
        ] {
            let layout = SlabLayout::new(&m, scheme, ConstraintMethod::Multiplier);
            // A static solve's slab is the unit time-invariant one.
            let (h, slab_dt, points, label) = match scheme {
                Scheme::P2 { layers } => {
                    let h = 0.02 / layers as f64;
                    (h, h, 3, format!("{kind:?} {layers} layers"))
                }
                Scheme::Galerkin => (0.02, 0.02, 3, format!("{kind:?} Galerkin")),
                _ => (0.0, 1.0, 1, format!("{kind:?} static")),
            };
            let slab = TimeSlab::new(slab_dt, &GaussRule::new(points).unwrap());
            let start = random_start(&m, &layout, h, &mut rng);
            check_jacobian(&m, &layout, &slab, &start, &mut rng, &label, 1e-6);
        }
    }
}

/// For a free particle-like motion (rigid translation at constant velocity)
/// the exact solution satisfies every P2 row: the residual at the exact
/// end state is zero to round-off (docs/method.md §4.2, its checks).
#[test]
fn rigid_translation_satisfies_the_p2_rows() {
    for kind in [ElementType::Sac2, ElementType::Sac3] {
        for layers in 1..=3 {
            let m = model(kind, 4, vec![], vec![]);
            let layout = SlabLayout::new(&m, Scheme::P2 { layers }, ConstraintMethod::Multiplier);
            let dt = 0.01;
            let h = dt / layers as f64;
            let slab = TimeSlab::new(h, &GaussRule::new(3).unwrap());
            let mut s = m.initial_state();
            for node in 0..m.nodes() {
                m.set_node_velocity(&mut s, node, [0.3, -1.1, 0.7]);
            }
            let mut start = StepStart::new(&m, layout.time_nodes());
            start.set(&m, 0.0, &s.e, &s.v, h);
            let mut x = vec![0.0; layout.size()];
            for (slot, &(i, kind)) in layout.unknown_slots.iter().enumerate() {
                for g in 0..m.dofs() {
                    let u = layout.unknown_at(slot, g).unwrap();
                    x[u] = match kind {
                        Kind::Position => s.e[g] + i as f64 * h * s.v[g],
                        Kind::Velocity => s.v[g],
                    };
                }
            }
            let mut r = vec![0.0; layout.size()];
            let mut scratch = AssemblyScratch::new(&m, &layout);
            let p = StepProblem {
                model: &m,
                layout: &layout,
                slab: &slab,
                start: &start,
            };
            p.residual(&x, &mut r, &mut scratch);
            let scale: f64 = start.mass_v.iter().fold(0.0, |a, b| a.max(b.abs()));
            let worst = r.iter().fold(0.0f64, |a, b| a.max(b.abs()));
            assert!(
                worst < 1e-13 * scale,
                "{kind:?} {layers}: residual {worst:e}"
            );
        }
    }
}

/// The layouts are square, banded as declared, and the two routes differ
/// by exactly the multipliers and constraint equations.
#[test]
fn layouts_count_unknowns_and_rows() {
    for kind in [ElementType::Sac2, ElementType::Sac3] {
        let m = model(kind, 4, vec![], some_constraints(kind));
        let fixed = (0..m.dofs())
            .filter(|&g| m.constraints.is_constrained(g))
            .count();
        for layers in 1..=2 {
            let mult = SlabLayout::new(&m, Scheme::P2 { layers }, ConstraintMethod::Multiplier);
            let elim = SlabLayout::new(&m, Scheme::P2 { layers }, ConstraintMethod::Elimination);
            let free = m.dofs() * 2 * layers;
            assert_eq!(mult.size(), free + 2 * layers * fixed);
            assert_eq!(elim.size(), free - 2 * layers * fixed);
        }
    }
}
