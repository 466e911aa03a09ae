//! The planar reduction: a motion that stays in a plane z = z0 is solved
//! without its out-of-plane coordinates (`Model::reduce_to_plane`), and
//! gives the same motion and reactions as the full 3-D solve.

use stancf::element::{SlabDerivatives, SlabLoads};
use stancf::loads::{AirDrag, DragModel};
use stancf::{
    Cable, Constraint, ConstraintKind, ConstraintMethod, ElementType, Load, Material, Measures,
    Model, ModelOptions, NewtonSettings, Simulation, State, StepSettings, TimeScheme,
};

const TOL: f64 = 1e-12;
const LENGTH: f64 = 0.5;

/// The paper's pinned pendulum (SAC-3) in the plane z = 0.3, with every
/// load that can stay in a plane: gravity, a point force, an end moment
/// about z and drag in a wind along the plane.
fn pendulum(loads_out_of_plane: bool) -> (Model, State) {
    let moment_z = if loads_out_of_plane {
        [1e-6, 0.0, 2e-5]
    } else {
        [0.0, 0.0, 2e-5]
    };
    let model = Model::new(
        Cable::straight(LENGTH, 4, ElementType::Sac3).with_origin([0.0, 0.0, 0.3]),
        Material::chen2023_gutta_percha(),
        ModelOptions::default(),
        vec![
            Load::Gravity {
                acceleration: [0.0, -9.81, 0.0],
            },
            Load::PointForce {
                node: 2,
                force: [1e-4, 2e-4, 0.0],
            },
            Load::EndMoment {
                node: 4,
                moment: moment_z,
            },
            Load::AirDrag(AirDrag {
                drag_coefficient: 1.5,
                fluid_density: 1.225,
                diameter: 3.7e-3,
                fluid_velocity: [0.5, 0.2, 0.0],
                model: DragModel::Full,
            }),
        ],
    )
    .unwrap()
    .with_constraints(vec![Constraint {
        node: 0,
        kind: ConstraintKind::Pinned,
    }])
    .unwrap();
    let state = model.initial_state();
    (model, state)
}

fn settings(scheme: TimeScheme, method: ConstraintMethod, planar: bool) -> StepSettings {
    StepSettings {
        time_step: 1e-4,
        time_scheme: scheme,
        constraint_method: method,
        planar_reduction: planar,
        newton: NewtonSettings {
            tolerance: TOL,
            max_iterations: 50,
            ..NewtonSettings::default()
        },
        ..StepSettings::default()
    }
}

const STEPS: usize = 200;

/// Same motion and reactions with and without the reduction, for both
/// schemes and both constraint methods; a third fewer unknowns for the
/// unconstrained coordinates.
#[test]
fn planar_reduction_gives_the_same_motion_and_reactions() {
    for scheme in [TimeScheme::P2, TimeScheme::Galerkin] {
        for method in [ConstraintMethod::Multiplier, ConstraintMethod::Elimination] {
            let (model, state) = pendulum(false);
            assert_eq!(
                model.planar_coordinates(&state).map(|d| d.len()),
                Some(model.dofs() / 3)
            );
            let mut full = Simulation::new(
                model.clone(),
                state.clone(),
                settings(scheme, method, false),
            )
            .unwrap();
            let mut planar = Simulation::new(model, state, settings(scheme, method, true)).unwrap();
            // Node 0 is pinned (3 coordinates held), 9 per node for SAC-3:
            // the reduction holds the z components of the other 6 of node
            // 0 and of the 9 of the 4 other nodes; with multipliers, the
            // pinned z coordinate's multipliers go too.
            let (nf, np) = (full.unknowns_per_step(), planar.unknowns_per_step());
            assert!(np < nf, "{scheme:?} {method:?}: {np} of {nf}");
            for _ in 0..STEPS {
                full.step().unwrap();
                planar.step().unwrap();
            }
            // Both are solved to TOL L per step in the scaled norm (r, r_x,
            // r_xx weighted by 1, l, l^2); the in-plane equations are the
            // same, so they differ by at most 2 STEPS TOL L in that norm.
            let bound = 2.0 * STEPS as f64 * TOL * LENGTH;
            let l = LENGTH / 4.0;
            let (ef, ep) = (&full.state().e, &planar.state().e);
            let diff = ef
                .iter()
                .zip(ep.iter())
                .enumerate()
                .fold(0.0f64, |m, (g, (a, b))| {
                    m.max((a - b).abs() * l.powi(((g % 9) / 3) as i32))
                });
            eprintln!(
                "{scheme:?} {method:?}: {np} of {nf} unknowns, scaled difference {diff:.1e} \
                 (bound {bound:.0e})"
            );
            assert!(diff < bound, "{scheme:?} {method:?}: {diff:e}");
            // The reduced solve keeps the plane exactly, the full one to
            // round-off (its Jacobian couples z to the plane by terms that
            // vanish analytically but not in floating point).
            for g in (2..ef.len()).step_by(3) {
                let z = if g % 9 == 2 { 0.3 } else { 0.0 };
                assert!(
                    (ef[g] - z).abs() < 1e-14,
                    "{scheme:?} {method:?}: full solve, coordinate {g}: {}",
                    ef[g]
                );
                assert_eq!(ep[g], z, "{scheme:?} {method:?}: reduced, coordinate {g}");
            }
            // The pin's reaction: the same in the plane, zero out of it.
            let (rf, rp) = (full.reactions()[0].1, planar.reactions()[0].1);
            let scale = rf[0].abs().max(rf[1].abs());
            for c in 0..2 {
                assert!(
                    (rf[c] - rp[c]).abs() < 1e-8 * scale,
                    "{scheme:?} {method:?}: {rf:?} {rp:?}"
                );
            }
            assert!(rp[2].abs() < 1e-12 * scale, "{rp:?}");
        }
    }
}

/// Anything out of the plane keeps the full 3-D solve.
#[test]
fn motion_out_of_the_plane_is_not_reduced() {
    let (model, state) = pendulum(true);
    assert!(model.planar_coordinates(&state).is_none(), "moment about x");
    let (model, mut state) = pendulum(false);
    model.set_node_velocity(&mut state, 4, [0.0, 0.0, 1e-3]);
    assert!(
        model.planar_coordinates(&state).is_none(),
        "velocity along z"
    );
    let (model, mut state) = pendulum(false);
    let n = model.dofs_per_node();
    state.e[4 * n + 5] = 1e-3; // r_x of node 4 tilted out of the plane
    assert!(
        model.planar_coordinates(&state).is_none(),
        "slope out of the plane"
    );
    let full = settings(TimeScheme::P2, ConstraintMethod::Multiplier, false);
    let auto = settings(TimeScheme::P2, ConstraintMethod::Multiplier, true);
    let (model, mut state) = pendulum(false);
    model.set_node_velocity(&mut state, 4, [0.0, 0.0, 1e-3]);
    let a = Simulation::new(model.clone(), state.clone(), full).unwrap();
    let b = Simulation::new(model, state, auto).unwrap();
    assert_eq!(a.unknowns_per_step(), b.unknowns_per_step());
}

/// Holds a slab state in the plane z = z0: r's z at z0, r_x's and r_xx's
/// z at 0, no z velocity.
fn into_plane<const NS: usize, const ND: usize>(y: &mut [[f64; ND]; 4], z0: f64) {
    for (m, values) in y.iter_mut().enumerate() {
        for (d, v) in values.iter_mut().enumerate() {
            if d % 3 == 2 {
                // Vector d / 3 of the element: r at a node where it is a
                // multiple of the vectors per node.
                let is_position = (d / 3) % (NS / 2) == 0;
                *v = if m % 2 == 0 && is_position { z0 } else { 0.0 };
            }
        }
    }
}

/// The kernel of a line held in a plane (docs/method.md §7.10) gives the
/// 3-D kernel's x and y entries of the gradient, of every Hessian block
/// and of the slab gradient, to the bit, and zero z rows and columns: the
/// accumulation over 2 components changes nothing the reduced step uses.
fn in_plane_kernel_matches<const NS: usize, const ND: usize>(
    make: impl Fn(Measures) -> stancf::element::CableElement<NS, ND>,
) {
    let mut rng = crate::common::Rng(0x0bad_cafe_1234_5678);
    let slab = crate::common::slab(0.01, 3);
    for measures in crate::common::ALL_MEASURES {
        let el = make(measures);
        for _ in 0..5 {
            let mut y = crate::common::random_slab_state::<NS, ND>(&mut rng, 0.25, 0.1);
            into_plane::<NS, ND>(&mut y, 0.3);
            let (mut g3, mut h3) = ([0.0; ND], [[0.0; ND]; ND]);
            let (mut g2, mut h2) = ([0.0; ND], [[0.0; ND]; ND]);
            let u3 = el.strain_energy_derivatives(&y[0], &mut g3, Some(&mut h3));
            let u2 = el.strain_energy_derivatives_in_plane(&y[0], &mut g2, Some(&mut h2));
            assert_eq!(u3.to_bits(), u2.to_bits());
            for a in 0..ND {
                if a % 3 == 2 {
                    assert_eq!(g2[a], 0.0);
                    assert!(h2[a].iter().all(|&v| v == 0.0));
                    continue;
                }
                assert_eq!(g2[a].to_bits(), g3[a].to_bits(), "gradient {a}");
                for b in (0..ND).filter(|b| b % 3 != 2) {
                    assert_eq!(h2[a][b].to_bits(), h3[a][b].to_bits(), "Hessian ({a}, {b})");
                }
            }
            let mut loads = SlabLoads::gravity([0.0, -9.81, 0.0]);
            let mut full = SlabDerivatives::default();
            el.slab_derivatives(&slab, &y, &loads, true, &mut full);
            loads.in_plane = true;
            let mut plane = SlabDerivatives::default();
            el.slab_derivatives(&slab, &y, &loads, true, &mut plane);
            let (mut b3, mut b2) = ([[0.0; ND]; ND], [[0.0; ND]; ND]);
            for m in 0..4 {
                for a in (0..ND).filter(|a| a % 3 != 2) {
                    assert_eq!(plane.grad[m][a].to_bits(), full.grad[m][a].to_bits());
                }
                for n in 0..4 {
                    el.slab_hessian_block(&slab, &full, m, n, &mut b3);
                    el.slab_hessian_block(&slab, &plane, m, n, &mut b2);
                    for a in 0..ND {
                        for b in 0..ND {
                            if a % 3 == 2 || b % 3 == 2 {
                                assert_eq!(b2[a][b], 0.0, "block ({m}, {n}), ({a}, {b})");
                            } else {
                                assert_eq!(b2[a][b].to_bits(), b3[a][b].to_bits());
                            }
                        }
                    }
                }
            }
        }
    }
}

#[test]
fn the_in_plane_kernel_is_the_3d_kernel_in_the_plane() {
    let rules = crate::common::rules(5, 3);
    in_plane_kernel_matches(|m| crate::common::sac2(0.25, m, &rules));
    in_plane_kernel_matches(|m| crate::common::sac3(0.25, m, &rules));
}
