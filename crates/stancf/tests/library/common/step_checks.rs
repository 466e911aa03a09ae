//! Finite-difference checks of an assembled step (or static solve),
//! shared by the tests of the step's rows (`step_assembly.rs`,
//! `axial_damping.rs`).
#![allow(dead_code)]

use super::{rel_diff, Rng};
use stancf::assembly::{AssemblyScratch, Kind, Scheme, SlabLayout, StepProblem, StepStart};
use stancf::band::BandMatrix;
use stancf::element::TimeSlab;
use stancf::quadrature::GaussRule;
use stancf::ConstraintMethod;
use stancf::Model;

/// dR/dx against central differences of R at a random iterate near
/// `start`: asserts a relative error (2-norm over all entries) below `tol`
/// and returns it.
pub fn check_jacobian(
    m: &Model,
    layout: &SlabLayout,
    slab: &TimeSlab,
    start: &StepStart,
    rng: &mut Rng,
    label: &str,
    tol: f64,
) -> f64 {
    let n = layout.size();
    let mut x = vec![0.0; n];
    for (slot, &(i, kind)) in layout.unknown_slots.iter().enumerate() {
        for g in 0..m.dofs() {
            if let Some(u) = layout.unknown_at(slot, g) {
                x[u] = match kind {
                    Kind::Position => start.e[g] + 0.03 * rng.next() * (i as f64 + 0.5),
                    Kind::Velocity => start.v[g] + 0.3 * rng.next(),
                };
            }
        }
        for g in 0..m.dofs() {
            if let Some(r) = layout.constraint_row_at(slot, g) {
                let _ = r;
            }
        }
    }
    for s in 0..layout.row_slots.len() {
        for g in 0..m.dofs() {
            if let Some(u) = layout.multiplier_at(s, g) {
                x[u] = rng.next();
            }
        }
        for h in 0..m.constraints.directions.len() {
            for k in 0..2 {
                if let Some(u) = layout.hold_multiplier(h, s, k) {
                    x[u] = rng.next();
                }
            }
        }
    }
    let p = StepProblem {
        model: m,
        layout,
        slab,
        start,
    };
    let (kl, ku) = layout.bandwidths();
    let mut jac = BandMatrix::new(n, kl, ku);
    let mut r = vec![0.0; n];
    let mut scratch = AssemblyScratch::new(m, layout);
    p.assemble(&x, &mut r, Some(&mut jac), &mut scratch);
    let mut r_only = vec![0.0; n];
    p.residual(&x, &mut r_only, &mut scratch);
    assert_eq!(
        r, r_only,
        "{label}: residual must not depend on whether J is built"
    );
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
        p.residual(&xp, &mut rp, &mut scratch);
        p.residual(&xm, &mut rm, &mut scratch);
        for row in 0..n {
            fd.push((rp[row] - rm[row]) / (2.0 * h));
            analytic.push(jac.get(row, c));
        }
    }
    let e = rel_diff(&analytic, &fd);
    assert!(e < tol, "{label}: Jacobian rel. error {e:e}");
    e
}

/// A step start near the reference state with random e and v.
pub fn random_start(m: &Model, layout: &SlabLayout, h: f64, rng: &mut Rng) -> StepStart {
    let s0 = m.initial_state();
    let e: Vec<f64> = s0.e.iter().map(|v| v + 0.05 * rng.next()).collect();
    let v: Vec<f64> = s0.v.iter().map(|_| 0.5 * rng.next()).collect();
    let mut start = StepStart::new(m, layout.time_nodes());
    start.set(m, 0.37, &e, &v, h);
    start
}

/// The schemes every load's step check covers: P2 with 1 and 2 layers,
/// the Galerkin step and statics.
pub const ALL_SCHEMES: [Scheme; 4] = [
    Scheme::P2 { layers: 1 },
    Scheme::P2 { layers: 2 },
    Scheme::Galerkin,
    Scheme::Static,
];

/// The constraints of a constrained route: node 0 clamped (r and r_x).
pub fn clamped_start(constrained: bool) -> Vec<stancf::Constraint> {
    if !constrained {
        return vec![];
    }
    vec![stancf::Constraint {
        node: 0,
        kind: stancf::ConstraintKind::Clamped {
            fix_curvature: false,
        },
    }]
}

/// The constraint routes every step check covers: free, and constrained
/// by multipliers and by elimination.
pub const ROUTES: [(bool, ConstraintMethod); 3] = [
    (false, ConstraintMethod::Multiplier),
    (true, ConstraintMethod::Multiplier),
    (true, ConstraintMethod::Elimination),
];

/// [`check_jacobian`] for each scheme of `schemes` and each of
/// [`ROUTES`], on `model(constrained)` at a random start (slabs of 0.02 s
/// split into the scheme's layers); returns the worst relative error.
pub fn check_schemes_and_routes(
    model: &dyn Fn(bool) -> Model,
    schemes: &[Scheme],
    rng: &mut Rng,
    label: &str,
    tol: f64,
) -> f64 {
    let mut worst = 0.0f64;
    for &scheme in schemes {
        for (constrained, method) in ROUTES {
            let m = model(constrained);
            let layout = SlabLayout::new(&m, scheme, method);
            let layers = match scheme {
                Scheme::P2 { layers } => layers,
                _ => 1,
            };
            let h = 0.02 / layers as f64;
            let slab = TimeSlab::new(h, &GaussRule::new(3).unwrap());
            let start = random_start(&m, &layout, h, rng);
            let label = format!("{label} {scheme:?} {constrained} {method:?}");
            worst = worst.max(check_jacobian(&m, &layout, &slab, &start, rng, &label, tol));
        }
    }
    worst
}

/// [`check_schemes_and_routes`] for SAC-2 and SAC-3, the model of each
/// `model(element_type, constrained)`; returns the worst relative error.
pub fn check_elements_schemes_and_routes(
    model: &dyn Fn(stancf::ElementType, bool) -> Model,
    schemes: &[Scheme],
    rng: &mut Rng,
    label: &str,
    tol: f64,
) -> f64 {
    let mut worst = 0.0f64;
    for kind in [stancf::ElementType::Sac2, stancf::ElementType::Sac3] {
        let of_kind = |constrained: bool| model(kind, constrained);
        let label = format!("{label} {kind:?}");
        worst = worst.max(check_schemes_and_routes(
            &of_kind, schemes, rng, &label, tol,
        ));
    }
    worst
}
