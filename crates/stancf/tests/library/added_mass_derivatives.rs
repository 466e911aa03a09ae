//! The entrained water's kinetic energy (docs/method.md §12.5,
//! (W25)-(W31)) in the slab and in the assembled step, against central
//! finite differences: the slab gradient against the action, the slab
//! Hessian against the gradient (SAC-2 and SAC-3, anisotropic Can != Cat,
//! the element piercing the surface so that s' and s'' matter), and the
//! step's Jacobian in every scheme and constraint route.
//!
//! Tolerance: as in `element_derivatives.rs`, central differences with
//! h = 1e-5 on O(1) states agree with an exact derivative to ~1e-10
//! relative; 1e-6 catches any wrong term (an O(1) relative error). The
//! submerged fraction (W17) is a cubic inside its band, so the differences
//! see no kink unless a Gauss point lies within h of the band's edge.

use crate::common::step_checks::{check_elements_schemes_and_routes, clamped_start, ALL_SCHEMES};
use crate::common::water_lines::*;
use crate::common::*;
use stancf::element::{CableElement, SlabDerivatives, SlabLoads, TimeSlab};
use stancf::water::LineInWater;
use stancf::{Cable, Constraint, ElementType, Load, Material, Model, ModelOptions};

const H: f64 = 1e-5;
const TOL: f64 = 1e-6;

/// Slab loads of gravity and `water`.
fn wet(water: &LineInWater) -> SlabLoads<'_> {
    SlabLoads {
        gravity: [0.0, 0.0, -9.81],
        host_flow: None,
        drag: &[],
        seabed: None,
        water: Some(water),
        time: 0.0,
        in_plane: false,
    }
}

/// The added mass's part of the slab gradient (with minus without
/// coefficients, so that whatever else the water does cancels) against
/// central differences of its part of the action, and the whole slab
/// Hessian against central differences of the whole gradient.
fn check_slab_with_added_mass<const NS: usize, const ND: usize>(
    el: &CableElement<NS, ND>,
    slab: &TimeSlab,
    y: &[[f64; ND]; 4],
    d: f64,
    label: &str,
) {
    let water = LineInWater::new(still_water(50.0), added_mass_only(d, 1.0, 0.3));
    let dry = LineInWater::new(still_water(50.0), added_mass_only(d, 0.0, 0.0));
    let (loads, bare) = (wet(&water), wet(&dry));
    let added_action = |y: &[[f64; ND]; 4]| {
        let (mut a, mut b) = (SlabDerivatives::default(), SlabDerivatives::default());
        el.slab_derivatives(slab, y, &loads, false, &mut a);
        el.slab_derivatives(slab, y, &bare, false, &mut b);
        (a.action - b.action, a.grad)
    };
    let mut with = SlabDerivatives::<ND>::default();
    let mut without = SlabDerivatives::<ND>::default();
    el.slab_derivatives(slab, y, &loads, true, &mut with);
    el.slab_derivatives(slab, y, &bare, false, &mut without);
    let (t_a, _) = added_action(y);
    assert!(t_a.abs() > 1e-3, "{label}: the added mass is exercised");
    let mut grad_fd = vec![0.0; 4 * ND];
    let mut hess_fd = vec![vec![0.0; 4 * ND]; 4 * ND];
    for n in 0..4 {
        for b in 0..ND {
            let (mut yp, mut ym) = (*y, *y);
            yp[n][b] += H;
            ym[n][b] -= H;
            let ((ap, gp), (am, gm)) = (added_action(&yp), added_action(&ym));
            grad_fd[n * ND + b] = (ap - am) / (2.0 * H);
            for m in 0..4 {
                for a in 0..ND {
                    hess_fd[m * ND + a][n * ND + b] = (gp[m][a] - gm[m][a]) / (2.0 * H);
                }
            }
        }
    }
    let added_grad: Vec<f64> = (0..4 * ND)
        .map(|k| with.grad[k / ND][k % ND] - without.grad[k / ND][k % ND])
        .collect();
    let e = rel_diff(&added_grad, &grad_fd);
    assert!(e < TOL, "{label}: added-mass gradient rel. error {e:e}");
    let (mut hess, mut fd) = (Vec::new(), Vec::new());
    let mut block = [[0.0; ND]; ND];
    for m in 0..4 {
        for n in 0..4 {
            el.slab_hessian_block(slab, &with, m, n, &mut block);
            for a in 0..ND {
                for b in 0..ND {
                    hess.push(block[a][b]);
                    fd.push(hess_fd[m * ND + a][n * ND + b]);
                }
            }
        }
    }
    let e = rel_diff(&hess, &fd);
    assert!(e < TOL, "{label}: Hessian rel. error {e:e}");
    eprintln!("{label}: T_a part of the action {t_a:.4e}, Hessian rel. error {e:.1e}");
}

/// Random slab states about the straight element on the water line
/// (z = 0 +- 0.2 with d = 0.6: every Gauss point in the surface band,
/// where s, s' and s'' are all nonzero).
#[test]
fn slab_jacobian_with_added_mass_near_the_surface_matches_finite_differences() {
    let mut rng = Rng(0x000a_dded_0a55_0013);
    let s = slab(0.05, 3);
    for trial in 0..3 {
        let el2 = sac2(0.4, ALL_MEASURES[trial], &rules(3, 3));
        let y2 = random_slab_state::<4, 12>(&mut rng, 0.4, 0.2);
        check_slab_with_added_mass(&el2, &s, &y2, 0.6, &format!("SAC-2 #{trial}"));
        let el3 = sac3(0.4, ALL_MEASURES[3 - trial], &rules(5, 5));
        let y3 = random_slab_state::<6, 18>(&mut rng, 0.4, 0.2);
        check_slab_with_added_mass(&el3, &s, &y3, 0.6, &format!("SAC-3 #{trial}"));
    }
}

fn rope() -> Material {
    Material {
        youngs_modulus: 2.0e3,
        density: 900.0,
        area: 1.0e-3,
        second_moment: 2.0e-7,
        axial_damping: 0.0,
    }
}

/// A cable of 3 elements piercing the water line (z from 0.15 down to
/// -0.11, inside the surface band of d = 0.4), Can = 1, Cat = 0.3.
fn cable_through_the_surface(kind: ElementType, constraints: Vec<Constraint>) -> Model {
    let cable = Cable::straight(1.2, 3, kind)
        .with_origin([0.1, -0.2, 0.15])
        .with_direction([1.0, 0.5, -0.25]);
    let loads = vec![
        Load::Gravity {
            acceleration: [0.0, 0.0, -9.81],
        },
        in_still_water(30.0, 0.4, 1.0, 0.3),
    ];
    Model::new(cable, rope(), ModelOptions::default(), loads)
        .unwrap()
        .with_constraints(constraints)
        .unwrap()
}

/// Assembled steps with added mass (the momentum p = M v + dT_a/dv of the
/// P2 output row depends on e_L as well, (W30)): P2 with 1 and 2 layers,
/// the Galerkin step and statics, SAC-2 and SAC-3, free and clamped by
/// both routes; the Jacobian against central differences to 1e-7 (as the
/// seabed's step check: h = 1e-6 gives ~1e-9).
#[test]
fn step_jacobian_with_added_mass_matches_finite_differences() {
    let mut rng = Rng(0x000a_dded_0a55_0014);
    let model = |kind, constrained| cable_through_the_surface(kind, clamped_start(constrained));
    let label = "in water";
    let worst = check_elements_schemes_and_routes(&model, &ALL_SCHEMES, &mut rng, label, 1e-7);
    eprintln!("step Jacobians with added mass: worst rel. error {worst:.1e}");
}
