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
//! drag; f_end: the catenary's end force (C12)). A free body is balanced
//! the same way in force and in moment about its centre of mass, its
//! points where its pose puts them (its centre r_G and a rotation vector
//! phi from its rotation as given, R = exp([phi]) R_0, global axes):
//!
//! ```text
//!   G_b = [ F_b + sum_P f_end,P ;  sum_j (x_j - r_G) x F_j + sum_P (x_P - r_G) x f_end,P ] = 0
//! ```
//!
//! (F_b its weight and buoyancy at the centre, F_j its constant loads at
//! their points x_j). Started from the points
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

use super::network::{imbalance, joint_root, Network};
use super::seed::catenary_states_at;
use super::{End, System};
use crate::band::BandLu;
use crate::body::pose::Pose;
use crate::model::State;

/// Newton iterations on (M32a) at most. Where a line in the network
/// turns from slack to taut between the iterates (a short stiff line
/// whose closed form's force jumps from its weight's pull to EA times the
/// stretch), the Newton step overshoots and is cut to a part of itself
/// every iteration, and |G| falls linearly for tens of iterations before
/// Newton's quadratic convergence takes over: MoorDyn's local_euler
/// complex_system, its stiffeners of 3.12 m and EA 3.6e8 N between a
/// body and two connectors, falls from 1.9e5 to 2.8e4 N over iterations
/// 3 to 59 at an eighth of the step and converges at 68.
const MAX_ITERATIONS: usize = 300;
/// ... while it makes progress: given up when |G|_inf has not fallen
/// below [`STALL_FALL`] of its value [`STALL_WINDOW`] iterations before
/// (complex_system's slow phase falls by 25 to 45 % over 30).
const STALL_WINDOW: usize = 30;
/// The fraction of |G|_inf that [`STALL_WINDOW`] iterations must get
/// below to go on.
const STALL_FALL: f64 = 0.9;
/// ... and within a work budget: the evaluations of G (2 n for each
/// Jacobian, one for each trial of a step) of this many iterations that
/// each try [`STEP_TRIALS`] steps. Cheap iterations (a Jacobian and a
/// few cuts: complex_system's 68 take 2.7e3 of its 4.0e3) go on; a
/// network whose steps keep failing through the Levenberg shifts (up to
/// 7 shifts of 30 cuts an iteration) stops within the work of 60 plain
/// iterations, as before.
const BUDGET_ITERATIONS: usize = 60;
/// The trials of one step in the budget: [`descend`]'s halvings.
const STEP_TRIALS: usize = 30;
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
/// coupled points where they are at t = 0, the free points and the free
/// bodies' points at the equilibrium (M32a) of the catenary network, or
/// where the scenario puts them when (M32a) has none that Newton reaches
/// from there (a free point its lines hardly pull slid first, (M32e)).
pub fn balanced_points(system: &System) -> Vec<[f64; 3]> {
    balanced(system).0
}

/// A free body's pose (reference point, rotation) at the catenary
/// network's equilibrium (M32a), or as given where it has none; one per
/// body (fixed and coupled bodies as given).
pub fn balanced_bodies(system: &System) -> Vec<Pose> {
    balanced(system).1
}

/// The points' positions and the bodies' poses of [`balanced_points`] and
/// [`balanced_bodies`].
fn balanced(system: &System) -> (Vec<[f64; 3]>, Vec<Pose>) {
    let mut positions: Vec<[f64; 3]> = system.points().iter().map(|p| p.state_at(0.0).0).collect();
    let mut poses: Vec<_> = system
        .bodies()
        .iter()
        .map(|b| (b.position, b.rotation))
        .collect();
    // A pinned body keeps its given pose (its pin holds it there), unless
    // it hangs at a joint from one of the network's bodies: then it rides
    // with that body, turned with it as given (§15.14).
    // A connector (§15.20) carries only its lines' ends at one point: it
    // balances there as a free point, its rotation as given.
    let connector = |b: usize| system.bodies()[b].connector;
    let bodies: Vec<usize> = system
        .free_bodies()
        .filter(|&b| system.bodies()[b].pin.is_none() && !connector(b))
        .collect();
    let riders = bodies
        .iter()
        .map(|&b| {
            system
                .free_bodies()
                .filter(|&c| c != b && joint_root(system, c) == b)
                .collect()
        })
        .collect();
    // Where an assembly turns freely about the vertical (§15.14), a spring
    // holds its heading as given (its force zero at the solution).
    let yaw_springs = bodies
        .iter()
        .map(|&b| {
            super::body_holds::yaw_hold(system, b).map(|_| {
                let mass: f64 = std::iter::once(b)
                    .chain(
                        system
                            .free_bodies()
                            .filter(|&c| c != b && joint_root(system, c) == b),
                    )
                    .map(|m| system.bodies()[m].inertia.mass)
                    .sum();
                (mass * crate::vec3::norm(system.gravity())).max(1.0)
            })
        })
        .collect();
    let net = Network {
        free: (0..positions.len())
            .filter(|&p| {
                let pt = &system.points()[p];
                pt.is_free() || pt.body().is_some_and(connector)
            })
            .collect(),
        bodies,
        riders,
        yaw_springs,
        ea_cap: f64::INFINITY,
    };
    if net.free.is_empty() && net.bodies.is_empty() {
        return (positions, poses);
    }
    super::network::slide_slack_points(system, &net, &mut positions);
    let start = net.start(system, &positions);
    let solved = solve_network(system, &net, &positions, start.clone())
        .or_else(|| stiffening(system, net.clone(), &positions, start));
    if let Some(x) = solved {
        net.place(system, &x, &mut positions);
        for k in 0..net.bodies.len() {
            for (b, pose) in net.members(system, &x, k) {
                poses[b] = pose;
            }
        }
        for &p in &net.free {
            if let Some(b) = system.points()[p].body() {
                poses[b].0 = positions[p];
            }
        }
    }
    (positions, poses)
}

/// The lines' stiffness continuation of (M32a), where Newton on the
/// network itself does not converge: stiff lines (EA many thousands of
/// times their tension) that must swing to their equilibrium (a weight
/// pushed aside on taut ropes, a pendulum released from aside) make the
/// Newton step move along the ropes' tangent and stretch them, and the
/// halved steps creep. The network is solved with every line's EA capped
/// at [`SOFT_EA`] times the forces at play, where a swing stretches the
/// lines by a few per cent only, and then with the cap raised
/// [`STIFFENING`] times at each stage, each from the last one's solution,
/// until no line is capped (docs/method.md §11.6). None if a stage fails.
fn stiffening(
    system: &System,
    mut net: Network,
    start: &[[f64; 3]],
    mut x: Vec<f64>,
) -> Option<Vec<f64>> {
    let mut positions = start.to_vec();
    let scale = imbalance(system, &net, &mut positions, &x)?.1;
    let stiffest = system
        .lines()
        .iter()
        .map(|l| l.model.material.section().ea)
        .fold(0.0f64, f64::max);
    let mut cap = SOFT_EA * scale;
    loop {
        net.ea_cap = if cap >= stiffest { f64::INFINITY } else { cap };
        x = solve_network(system, &net, start, x)?;
        if net.ea_cap == f64::INFINITY {
            return Some(x);
        }
        cap *= STIFFENING;
    }
}

/// The softened network's EA over its forces (a few per cent of stretch
/// under them).
const SOFT_EA: f64 = 30.0;
/// The factor the cap rises by at each stage of [`stiffening`].
const STIFFENING: f64 = 30.0;

/// Newton on (M32a) from `x`; the unknowns of `net`, or None if it does
/// not converge.
fn solve_network(
    system: &System,
    net: &Network,
    start: &[[f64; 3]],
    mut x: Vec<f64>,
) -> Option<Vec<f64>> {
    let n = net.size();
    let mut positions = start.to_vec();
    let length = length_scale(system, net);
    let (mut g, force_scale) = imbalance(system, net, &mut positions, &x)?;
    let inf = |v: &[f64]| v.iter().fold(0.0f64, |m, c| m.max(c.abs()));
    let mut lu = BandLu::new(n, n - 1, n - 1);
    let mut history = Vec::with_capacity(MAX_ITERATIONS);
    let budget = BUDGET_ITERATIONS * (2 * n + STEP_TRIALS);
    let mut evaluations = 0;
    for k in 0..MAX_ITERATIONS {
        if inf(&g) <= TOLERANCE * force_scale {
            return Some(x);
        }
        history.push(inf(&g));
        let stalled = k >= STALL_WINDOW && history[k] > STALL_FALL * history[k - STALL_WINDOW];
        if stalled || evaluations > budget {
            break;
        }
        evaluations += 2 * n;
        // dG/dx by central differences of the closed forms.
        let h = 1e-6 * length;
        let mut jac = vec![0.0; n * n];
        for j in 0..n {
            let mut xp = x.clone();
            xp[j] += h;
            let (gp, _) = imbalance(system, net, &mut positions, &xp)?;
            xp[j] -= 2.0 * h;
            let (gm, _) = imbalance(system, net, &mut positions, &xp)?;
            for i in 0..n {
                jac[i * n + j] = (gp[i] - gm[i]) / (2.0 * h);
            }
        }
        // The Newton step, cut to at most a quarter of the lines' length
        // and half a radian of turn and halved until |G| falls. Where no
        // cut of it lowers |G| (a network without stiffness in some
        // direction: a body hanging on lines that do not yet pull, no
        // pendulum, no sway, and a step without bound there), the
        // diagonal is shifted (Levenberg), 1e-10 ... 1e2 of its size with
        // its sign (G is a force: a stable network's dG/dx is negative).
        let size = (0..n).fold(0.0f64, |m, i| m.max(jac[i * n + i].abs()));
        let sign = if (0..n).map(|i| jac[i * n + i]).sum::<f64>() > 0.0 {
            1.0
        } else {
            -1.0
        };
        let mut shift = 0.0;
        let (trial, gt) = loop {
            let step = shifted_step(&mut lu, &jac, sign * shift, &g).and_then(|dx| {
                let at = (&x[..], &g[..], length);
                descend(system, net, &mut positions, at, &dx, &mut evaluations)
            });
            if let Some(found) = step {
                break found;
            }
            if size == 0.0 || shift > 1e2 * size {
                return None;
            }
            shift = if shift == 0.0 {
                1e-10 * size
            } else {
                100.0 * shift
            };
        };
        x = trial;
        g = gt;
    }
    (inf(&g) <= ACCEPTED * force_scale).then_some(x)
}

/// The step dx of (J + shift I) dx = g, or None if singular or not
/// finite.
fn shifted_step(lu: &mut BandLu, jac: &[f64], shift: f64, g: &[f64]) -> Option<Vec<f64>> {
    let n = g.len();
    let a = lu.matrix_mut();
    a.clear();
    for i in 0..n {
        for j in 0..n {
            a.add(i, j, jac[i * n + j] + if i == j { shift } else { 0.0 });
        }
    }
    lu.factorize().ok()?;
    let mut dx = g.to_vec();
    lu.solve(&mut dx);
    dx.iter().all(|d| d.is_finite()).then_some(dx)
}

/// x - alpha dx with alpha the largest of 1, 1/2, ... (30 halvings, at
/// most a quarter of `length` and half a radian of turn) that lowers
/// |G|_inf below |g|_inf, from `(x, g, length)`; the trial and its G, or
/// None. Each evaluation of G is counted in `evaluations`.
fn descend(
    system: &System,
    net: &Network,
    positions: &mut [[f64; 3]],
    (x, g, length): (&[f64], &[f64], f64),
    dx: &[f64],
    evaluations: &mut usize,
) -> Option<(Vec<f64>, Vec<f64>)> {
    let inf = |v: &[f64]| v.iter().fold(0.0f64, |m, c| m.max(c.abs()));
    let full = inf(dx);
    let mut alpha = if full > 0.25 * length {
        0.25 * length / full
    } else {
        1.0
    };
    let turn = (0..net.bodies.len())
        .flat_map(|k| (3..6).map(move |c| 3 * net.free.len() + 6 * k + c))
        .fold(0.0f64, |m, i| m.max(dx[i].abs()));
    if alpha * turn > 0.5 {
        alpha = 0.5 / turn;
    }
    // A body with rods moves at most a quarter of its shortest rod a step:
    // their buoyancy changes over their length (a waterplane's stiffness
    // appears where one meets the surface), which the tangent of a
    // longer step does not see.
    for (k, &b) in net.bodies.iter().enumerate() {
        let rods = std::iter::once(b)
            .chain(net.riders[k].iter().copied())
            .filter_map(|m| system.bodies()[m].water.as_ref())
            .flat_map(|w| w.rods.iter().map(|r| r.length()));
        let reach = 0.25 * rods.fold(f64::INFINITY, f64::min);
        let o = 3 * net.free.len() + 6 * k;
        let moved = (0..3).fold(0.0f64, |m, c| m.max(dx[o + c].abs()));
        if reach.is_finite() && reach > 0.0 && alpha * moved > reach {
            alpha = reach / moved;
        }
    }
    for _ in 0..STEP_TRIALS {
        let trial: Vec<f64> = x.iter().zip(dx).map(|(xi, d)| xi - alpha * d).collect();
        *evaluations += 1;
        if let Some((gt, _)) = imbalance(system, net, positions, &trial) {
            if inf(&gt) < inf(g) {
                return Some((trial, gt));
            }
        }
        alpha *= 0.5;
    }
    None
}

/// The mean length of the lines attached to the free points and bodies:
/// the scale of the finite differences and of the largest step.
fn length_scale(system: &System, net: &Network) -> f64 {
    let lengths: Vec<f64> = system
        .lines()
        .iter()
        .filter(|l| {
            l.ends.iter().any(|e| {
                matches!(e, End::Point(p)
                    if net.free.contains(p)
                        || system.points()[*p].body().is_some_and(|b| net.bodies.contains(&b)))
            })
        })
        .map(|l| l.model.cable.length)
        .collect();
    if lengths.is_empty() {
        1.0
    } else {
        lengths.iter().sum::<f64>() / lengths.len() as f64
    }
}
