//! The assembled P2 system of a step (eq. 22, with time layers) against
//! finite differences of its residual, and its rows against their
//! definition.

mod common;

use common::*;
use stancf::assembly::{AssemblyScratch, Kind, SlabLayout, StepProblem, StepStart};
use stancf::band::BandMatrix;
use stancf::element::TimeSlab;
use stancf::quadrature::GaussRule;
use stancf::{Cable, ElementType, Load, Material, Model, ModelOptions};

fn model(kind: ElementType, elements: usize, loads: Vec<Load>) -> Model {
    let material = Material {
        youngs_modulus: 2.0e3,
        density: 900.0,
        area: 1.0e-3,
        second_moment: 2.0e-7,
    };
    let cable = Cable::straight(1.2, elements, kind)
        .with_origin([0.1, -0.2, 0.3])
        .with_direction([1.0, 0.5, -0.25]);
    Model::new(cable, material, ModelOptions::default(), loads).unwrap()
}

/// dR/dx of the assembled step against central differences of R, for
/// 1, 2 and 3 layers, SAC-2 and SAC-3, with gravity and a point force.
#[test]
fn step_jacobian_matches_finite_differences() {
    let mut rng = Rng(0x7777_1234_abcd_0099);
    for kind in [ElementType::Sac2, ElementType::Sac3] {
        for layers in 1..=3 {
            let m = model(
                kind,
                3,
                vec![
                    Load::Gravity {
                        acceleration: [0.0, -9.81, 0.0],
                    },
                    Load::PointForce {
                        node: 2,
                        force: [0.3, 0.1, -0.2],
                    },
                ],
            );
            let layout = SlabLayout::new(&m, layers);
            let slab = TimeSlab::new(0.02 / layers as f64, &GaussRule::new(3).unwrap());
            let s0 = m.initial_state();
            let mut start = StepStart {
                e: s0.e.iter().map(|v| v + 0.05 * rng.next()).collect(),
                v: s0.v.iter().map(|_| 0.5 * rng.next()).collect(),
                mass_v: vec![0.0; m.dofs()],
            };
            m.mass_times(&start.v.clone(), &mut start.mass_v);
            let n = layout.size();
            // A guess near the start.
            let mut x = vec![0.0; n];
            for node in 0..layout.nodes {
                for i in 1..=layers {
                    let ue = layout.unknown(i, Kind::Position, node).unwrap();
                    let uv = layout.unknown(i, Kind::Velocity, node).unwrap();
                    for c in 0..layout.dpn {
                        let g = node * layout.dpn + c;
                        x[ue + c] = start.e[g] + 0.03 * rng.next();
                        x[uv + c] = start.v[g] + 0.3 * rng.next();
                    }
                }
            }
            let (kl, ku) = layout.bandwidths();
            let mut jac = BandMatrix::new(n, kl, ku);
            let mut r = vec![0.0; n];
            let mut scratch = AssemblyScratch::new(&m);
            StepProblem {
                model: &m,
                layout: &layout,
                slab: &slab,
                start: &start,
            }
            .assemble(&x, &mut r, Some(&mut jac), &mut scratch);
            let mut r_only = vec![0.0; n];
            StepProblem {
                model: &m,
                layout: &layout,
                slab: &slab,
                start: &start,
            }
            .assemble(&x, &mut r_only, None, &mut scratch);
            assert_eq!(r, r_only, "residual must not depend on whether J is built");
            let h = 1e-6;
            let mut analytic = Vec::with_capacity(n * n);
            let mut fd = Vec::with_capacity(n * n);
            let mut rp = vec![0.0; n];
            let mut rm = vec![0.0; n];
            for c in 0..n {
                let mut xp = x.clone();
                let mut xm = x.clone();
                xp[c] += h;
                xm[c] -= h;
                StepProblem {
                    model: &m,
                    layout: &layout,
                    slab: &slab,
                    start: &start,
                }
                .assemble(&xp, &mut rp, None, &mut scratch);
                StepProblem {
                    model: &m,
                    layout: &layout,
                    slab: &slab,
                    start: &start,
                }
                .assemble(&xm, &mut rm, None, &mut scratch);
                for row in 0..n {
                    fd.push((rp[row] - rm[row]) / (2.0 * h));
                    analytic.push(jac.get(row, c));
                }
            }
            let e = rel_diff(&analytic, &fd);
            assert!(
                e < 1e-6,
                "{kind:?}, {layers} layers: Jacobian rel. error {e:e}"
            );
        }
    }
}

/// For a free particle-like motion (rigid translation at constant velocity)
/// the exact solution satisfies every P2 row: the residual at the exact
/// end state is zero to round-off (method notes, "Sanity check").
#[test]
fn rigid_translation_satisfies_the_p2_rows() {
    for kind in [ElementType::Sac2, ElementType::Sac3] {
        for layers in 1..=3 {
            let m = model(kind, 4, vec![]);
            let layout = SlabLayout::new(&m, layers);
            let dt = 0.01;
            let h = dt / layers as f64;
            let slab = TimeSlab::new(h, &GaussRule::new(3).unwrap());
            let mut s = m.initial_state();
            for node in 0..m.nodes() {
                m.set_node_velocity(&mut s, node, [0.3, -1.1, 0.7]);
            }
            let mut start = StepStart {
                e: s.e.clone(),
                v: s.v.clone(),
                mass_v: vec![0.0; m.dofs()],
            };
            m.mass_times(&s.v, &mut start.mass_v);
            let mut x = vec![0.0; layout.size()];
            for node in 0..layout.nodes {
                for i in 1..=layers {
                    let ue = layout.unknown(i, Kind::Position, node).unwrap();
                    let uv = layout.unknown(i, Kind::Velocity, node).unwrap();
                    for c in 0..layout.dpn {
                        let g = node * layout.dpn + c;
                        x[ue + c] = s.e[g] + i as f64 * h * s.v[g];
                        x[uv + c] = s.v[g];
                    }
                }
            }
            let mut r = vec![0.0; layout.size()];
            let mut scratch = AssemblyScratch::new(&m);
            StepProblem {
                model: &m,
                layout: &layout,
                slab: &slab,
                start: &start,
            }
            .assemble(&x, &mut r, None, &mut scratch);
            let scale: f64 = start.mass_v.iter().fold(0.0, |a, b| a.max(b.abs()));
            let worst = r.iter().fold(0.0f64, |a, b| a.max(b.abs()));
            assert!(
                worst < 1e-13 * scale,
                "{kind:?} {layers}: residual {worst:e}"
            );
        }
    }
}
