//! Where the free points start a static solve (docs/method.md §11.6,
//! (M32a)): the equilibrium of the *catenary network*, each line replaced
//! by its seed shape (the elastic catenary through its end points, or
//! the closed form resting on the bed) and each free point p balanced
//! between its load and the end forces of its lines,
//!
//! ```text
//!   G_p(P) = F_p + F_w,p(P_p) + sum_(lines at p) f_end(P) = 0     (M32a)
//! ```
//!
//! (F_p: weight, buoyancy and constant force; F_w,p: the steady current's
//! drag; f_end: the catenary's end force (C12)). Started from the points
//! where the scenario puts them, the homotopy (M32) would have to carry
//! a free point from there to its equilibrium; when its lines start
//! slack and the point falls until they pull, the path can turn back
//! (a fold in the load factor, where the path stalls) or pass near one
//! and end on another branch, e.g. a rope folded in compression. From
//! the network's equilibrium the path is short: the catenaries differ
//! from the discrete lines' equilibrium only by the discretization.
//!
//! (M32a) is solved by Newton on the free points' coordinates, its
//! Jacobian by central differences of the closed forms, steps cut back
//! until |G| falls. If it does not converge (a point held by slack
//! weightless lines only, no catenary through its ends), the points
//! stay where the scenario puts them.

use super::seed::{catenary_states_at, end_positions_at, seed_shape};
use super::{End, System};
use crate::band::BandLu;
use crate::model::State;

/// Newton iterations on (M32a).
const MAX_ITERATIONS: usize = 60;
/// Converged: |G|_inf below this fraction of the forces at play.
const TOLERANCE: f64 = 1e-10;
/// Accepted after the last iteration: |G|_inf below this fraction (the
/// static solve takes the rest of the way).
const ACCEPTED: f64 = 1e-6;

/// The seed of a system's static solve (§11.6): [`super::catenary_states`] with
/// the free points where these catenaries hold them in equilibrium
/// ([`balanced_points`], (M32a)).
pub fn static_seed_states(system: &System) -> Vec<State> {
    catenary_states_at(system, &balanced_points(system))
}

/// Every point's position at the start of a static solve: the fixed and
/// coupled points where they are at t = 0, the free points at the
/// equilibrium (M32a) of the catenary network, or where the scenario puts
/// them when (M32a) has none that Newton reaches from there.
pub fn balanced_points(system: &System) -> Vec<[f64; 3]> {
    let mut positions: Vec<[f64; 3]> = system.points().iter().map(|p| p.state_at(0.0).0).collect();
    let free: Vec<usize> = (0..positions.len())
        .filter(|&p| system.points()[p].is_free())
        .collect();
    if free.is_empty() {
        return positions;
    }
    if let Some(x) = solve_network(system, &free, &positions) {
        for (k, &p) in free.iter().enumerate() {
            positions[p] = [x[3 * k], x[3 * k + 1], x[3 * k + 2]];
        }
    }
    positions
}

/// Newton on (M32a) from `start`; the free points' coordinates (3 per
/// point of `free`), or None if it does not converge.
fn solve_network(system: &System, free: &[usize], start: &[[f64; 3]]) -> Option<Vec<f64>> {
    let n = 3 * free.len();
    let mut positions = start.to_vec();
    let mut x: Vec<f64> = free.iter().flat_map(|&p| start[p]).collect();
    let length = length_scale(system, free);
    let (mut g, force_scale) = imbalance(system, free, &mut positions, &x)?;
    let inf = |v: &[f64]| v.iter().fold(0.0f64, |m, c| m.max(c.abs()));
    let mut lu = BandLu::new(n, n - 1, n - 1);
    for _ in 0..MAX_ITERATIONS {
        if inf(&g) <= TOLERANCE * force_scale {
            return Some(x);
        }
        // dG/dx by central differences of the closed forms.
        let h = 1e-6 * length;
        let a = lu.matrix_mut();
        a.clear();
        for j in 0..n {
            let mut xp = x.clone();
            xp[j] += h;
            let (gp, _) = imbalance(system, free, &mut positions, &xp)?;
            xp[j] -= 2.0 * h;
            let (gm, _) = imbalance(system, free, &mut positions, &xp)?;
            for i in 0..n {
                a.add(i, j, (gp[i] - gm[i]) / (2.0 * h));
            }
        }
        lu.factorize().ok()?;
        let mut dx = g.clone();
        lu.solve(&mut dx);
        // A step of at most a quarter of the lines' length, halved until
        // the imbalance falls.
        let full = inf(&dx);
        let mut alpha = if full > 0.25 * length {
            0.25 * length / full
        } else {
            1.0
        };
        let mut accepted = None;
        for _ in 0..30 {
            let trial: Vec<f64> = x.iter().zip(&dx).map(|(xi, d)| xi - alpha * d).collect();
            if let Some((gt, _)) = imbalance(system, free, &mut positions, &trial) {
                if inf(&gt) < inf(&g) {
                    accepted = Some((trial, gt));
                    break;
                }
            }
            alpha *= 0.5;
        }
        let (trial, gt) = accepted?;
        x = trial;
        g = gt;
    }
    (inf(&g) <= ACCEPTED * force_scale).then_some(x)
}

/// G(x) of (M32a) with the free points at `x` (written into `positions`),
/// and the scale of the forces at play (the largest load or end force);
/// None if a line has a non-finite force.
fn imbalance(
    system: &System,
    free: &[usize],
    positions: &mut [[f64; 3]],
    x: &[f64],
) -> Option<(Vec<f64>, f64)> {
    for (k, &p) in free.iter().enumerate() {
        positions[p] = [x[3 * k], x[3 * k + 1], x[3 * k + 2]];
    }
    let mut g = vec![0.0; x.len()];
    let mut scale = 0.0f64;
    let slot = |p: usize| free.iter().position(|&q| q == p);
    for (k, &p) in free.iter().enumerate() {
        let mut f = system.point_load(p);
        if let Some(water) = &system.points()[p].water {
            let drag = water.static_force(&positions[p]).force;
            for c in 0..3 {
                f[c] += drag[c];
            }
        }
        for c in 0..3 {
            g[3 * k + c] += f[c];
            scale = scale.max(f[c].abs());
        }
    }
    for (li, line) in system.lines().iter().enumerate() {
        let ends: Vec<(usize, usize)> = line
            .ends
            .iter()
            .enumerate()
            .filter_map(|(end, e)| match e {
                End::Point(p) => slot(*p).map(|k| (end, k)),
                End::Loose => None,
            })
            .collect();
        if ends.is_empty() {
            continue;
        }
        let (a, b) = end_positions_at(system, li, positions);
        let shape = seed_shape(system, li, a, b);
        for (end, k) in ends {
            let f = shape.end_force(end);
            for c in 0..3 {
                if !f[c].is_finite() {
                    return None;
                }
                g[3 * k + c] += f[c];
                scale = scale.max(f[c].abs());
            }
        }
    }
    Some((g, scale.max(f64::MIN_POSITIVE)))
}

/// The mean length of the lines attached to the free points: the scale
/// of the finite differences and of the largest step.
fn length_scale(system: &System, free: &[usize]) -> f64 {
    let lengths: Vec<f64> = system
        .lines()
        .iter()
        .filter(|l| {
            l.ends
                .iter()
                .any(|e| matches!(e, End::Point(p) if free.contains(p)))
        })
        .map(|l| l.model.cable.length)
        .collect();
    if lengths.is_empty() {
        1.0
    } else {
        lengths.iter().sum::<f64>() / lengths.len() as f64
    }
}
