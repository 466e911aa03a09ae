//! Line ends clamped in a direction at a free body (docs/method.md
//! §15.19, (B37)-(B40)): a riser leaving a buoyancy can, a line with
//! bending stiffness at the end of a rod that moves (MoorDyn's
//! cantilevered end, the line leaving the rod along its axis).
//!
//! The clamp of §6.10 holds the end's r_x parallel to a direction d by
//! n_k . r_x = 0; here the frame (d, n_1, n_2) is fixed in the body,
//! n_k(t) = R(t) n_k' with R(t) = R_a exp([theta(t)]) over a step (B3),
//! so the hold is C_k(t) = n_k(t) . r_x(t) = 0 and its equations involve
//! the body's unknowns. The line keeps the hold's multipliers and rows in
//! its band (the body's unknowns are in its block's border, as for a line
//! end at a body point); this file assembles them:
//!
//! - the equations at the unknown slots (0,w), (1,e), (1,w) are the
//!   hold's rate at t_a, value at t_b and rate at t_b,
//!
//!   ```text
//!     C_k'(a) = n_k(a) . w_a + n_k'(a) . r_x(a),    C_k(b) = n_k(b) . e_b,
//!     C_k'(b) = n_k(b) . w_b + n_k'(b) . e_b                            (B37)
//!   ```
//!
//!   (n_k' the frame's rate, R (J_r theta_dot x n_k'), the offsets of
//!   (B11) without the centre: [`crate::body::attach::offsets`]);
//! - the reactions of the row slots (0,e), (0,w), (1,w) are lambda times
//!   the gradients of G = (C_k(a), C_k'(a), C_k'(b)) in that slot's
//!   variations, of the line's r_x and of the body's rotation alike
//!   (the body's start variation moves its frame's value and rate, as it
//!   moves a point's (B12)):
//!
//!   ```text
//!     row s of r_x      += sign lambda_s dG_s / d(r_x's slot-s variable)
//!     row s of theta    += sign lambda_s dG_s / d(theta's slot-s variable) (B38)
//!   ```
//!
//!   which for a frame fixed in space are the multipliers of §6.10. The
//!   reactions are the gradient of one function of the line's and the
//!   body's coordinates, so they do no work in a motion that keeps the
//!   hold, and a rigid turn of everything leaves G unchanged: the clamp
//!   moves neither the energy nor the angular momentum of the system;
//! - the end momenta take G's dependence on the end values (B7): the
//!   line's p_b on r_x gains sign lambda_(1,w) n_k'(b), the body's
//!   dA/dtheta_b gains sign lambda_(1,w) d C_k'(b) / d theta_b (B39);
//! - the mass solve at the step's end (B14) takes the hold's rate,
//!   n_k(b) . v_rx + c_k . Omega = 0 with c_k = n_k' x R_b^T r_x(b), and
//!   its impulse mu_k on r_x (n_k) and on the body (c_k): eliminated as in
//!   (M43), mu_k = n_k . (p - M v)_rx, the body's Omega rows gain
//!   - sum_k c_k n_k . (M v - p)_rx (B40).
//!
//! In statics the body's rotation is R_0 exp([theta]) and the hold is
//! n_k(theta) . r_x = 0 with its multiplier in r_x's and theta's rows.

use super::layout::SystemLayout;
use crate::assembly::SlabLayout;
use crate::body::attach::{offsets, project};
use crate::body::jet::JetVec;
use crate::constraints::DirectionHold;
use crate::linear::AddEntries;
use crate::model::{coordinate, SLOT_R_X};
use crate::vec3::{dot, scale};

/// A line end clamped at a free body's point: line `line`'s hold `hold`
/// (index in its model's direction holds) at node `node`, whose frame is
/// `local` in body `body`'s axes.
#[derive(Clone, Debug, PartialEq)]
pub struct BodyClamp {
    pub line: usize,
    pub hold: usize,
    pub node: usize,
    pub body: usize,
    pub local: DirectionHold,
}

/// A connector's spin (its rotation about its z axis, which no clamp
/// sees, §15.20) held: the z rotation rows `rows` (one per slot) replaced
/// by x_row = 0 (the spin's value or rate from the pose it is measured
/// from).
pub(super) fn hold_spin(
    rows: &[usize],
    x: &[f64],
    residual: &mut [f64],
    mut jacobian: Option<&mut crate::bordered::BorderedMatrix>,
) {
    for &r in rows {
        residual[r] = x[r];
        if let Some(m) = jacobian.as_deref_mut() {
            m.clear_border_row(r);
            m.add(r, r, 1.0);
        }
    }
}

/// Where a clamp's quantities are in a step's (or a static solve's)
/// global numbering: the line's r_x unknowns and rows per slot, the
/// hold's multipliers and rows per slot, the body's rotation unknowns
/// (and rows) per slot.
struct ClampIndices {
    r_x: [[usize; 3]; 3],
    rows: [[usize; 3]; 3],
    multipliers: [[usize; 2]; 3],
    hold_rows: [[usize; 2]; 3],
    turn: [[usize; 3]; 3],
}

impl ClampIndices {
    /// The indices at the step's slots (a static solve's one slot first,
    /// the others unused).
    fn of(clamp: &BodyClamp, layout: &SystemLayout, dpn: usize) -> Self {
        let numbering: &SlabLayout = &layout.lines[clamp.line];
        let map = &layout.maps[clamp.line];
        let g0 = coordinate(dpn, clamp.node, SLOT_R_X, 0);
        let slots = numbering.unknown_slots.len();
        // Entry (s, c) of a slot's three (usize::MAX: no such slot or entry).
        let table = |f: &dyn Fn(usize, usize) -> Option<usize>| -> [[usize; 3]; 3] {
            std::array::from_fn(|s| {
                std::array::from_fn(|c| {
                    (s < slots).then(|| f(s, c)).flatten().unwrap_or(usize::MAX)
                })
            })
        };
        let global = |u: Option<usize>| u.map(|u| map.global[u]);
        let hold =
            |f: &dyn Fn(usize) -> Option<usize>, k: usize| (k < 2).then(|| global(f(k))).flatten();
        let two = |t: [[usize; 3]; 3]| t.map(|r| [r[0], r[1]]);
        ClampIndices {
            r_x: table(&|s, c| global(numbering.unknown_at(s, g0 + c))),
            rows: table(&|s, c| global(numbering.row_at(s, g0 + c))),
            multipliers: two(table(&|s, k| {
                hold(&|k| numbering.hold_multiplier(clamp.hold, s, k), k)
            })),
            hold_rows: two(table(&|s, k| {
                hold(&|k| numbering.hold_row(clamp.hold, s, k), k)
            })),
            turn: table(&|s, j| layout.body_unknown(clamp.body, s, 3 + j)),
        }
    }
}

/// Adds (i, j, v) to the Jacobian if there is one.
fn put<J: AddEntries>(jacobian: &mut Option<&mut J>, i: usize, j: usize, v: f64) {
    if let Some(m) = jacobian.as_deref_mut() {
        if v != 0.0 {
            m.add(i, j, v);
        }
    }
}

fn values(x: &[f64], at: &[usize; 3]) -> [f64; 3] {
    at.map(|i| x[i])
}

/// The frame's normal k at the step's start and end on jets over (theta,
/// theta_dot) of that end ((B11) without the centre): (n(a), n'(a)) at
/// theta = 0, slope u_a; (n(b), n'(b)) at theta_b, u_b.
pub(super) struct FrameJets {
    pub start: (JetVec<6>, JetVec<6>),
    pub end: (JetVec<6>, JetVec<6>),
}

/// [`FrameJets`] of body-axes normal `normal` of a body at R_a with
/// Galerkin unknowns `xb` (FreeBody order: u_a at 9, theta_b at 12, u_b
/// at 15).
pub(super) fn frame_jets(
    rotation_a: &[[f64; 3]; 3],
    normal: [f64; 3],
    xb: &[f64; 18],
) -> FrameJets {
    let part = |a: usize| [xb[a], xb[a + 1], xb[a + 2]];
    FrameJets {
        start: offsets(rotation_a, normal, [0.0; 3], part(9)),
        end: offsets(rotation_a, normal, part(12), part(15)),
    }
}

/// The line's r_x values a clamp's step terms read: r_x(a) (given), w_a,
/// e_b, w_b (unknowns).
pub(super) struct ClampValues {
    pub r_a: [f64; 3],
    pub w_a: [f64; 3],
    pub e_b: [f64; 3],
    pub w_b: [f64; 3],
}

/// Adds clamp `clamp`'s Galerkin terms (B37)-(B38) at the system's
/// unknowns x: the hold's rows and its reactions on the line's r_x rows
/// and the body's rotation rows, with their derivatives. `r_a` is the
/// line's r_x at the step's start, `rotation_a` and `xb` the body's
/// rotation there and its Galerkin unknowns.
#[allow(clippy::too_many_arguments)]
pub(super) fn add_step_clamp<J: AddEntries>(
    clamp: &BodyClamp,
    layout: &SystemLayout,
    dpn: usize,
    r_a: [f64; 3],
    rotation_a: &[[f64; 3]; 3],
    xb: &[f64; 18],
    x: &[f64],
    residual: &mut [f64],
    mut jacobian: Option<&mut J>,
) {
    let at = ClampIndices::of(clamp, layout, dpn);
    let step = StepClamp {
        sign: layout.lines[clamp.line].scheme.multiplier_sign(),
        v: ClampValues {
            r_a,
            w_a: values(x, &at.r_x[0]),
            e_b: values(x, &at.r_x[1]),
            w_b: values(x, &at.r_x[2]),
        },
        at,
    };
    for k in 0..2 {
        let jets = frame_jets(rotation_a, clamp.local.normals[k], xb);
        let m: [usize; 3] = std::array::from_fn(|s| step.at.multipliers[s][k]);
        let lambda = m.map(|i| x[i]);
        step.hold_rows(k, &jets, residual, &mut jacobian);
        step.line_reactions(&jets, (m, lambda), residual, &mut jacobian);
        step.body_reactions(&jets, (m, lambda), residual, &mut jacobian);
    }
}

/// A clamp's Galerkin terms at the step's unknowns (see
/// [`add_step_clamp`]).
struct StepClamp {
    at: ClampIndices,
    sign: f64,
    v: ClampValues,
}

/// A jet's value.
fn value(n: &JetVec<6>) -> [f64; 3] {
    [n[0].v, n[1].v, n[2].v]
}

/// A clamp's multipliers of normal k in the row slots (0,e), (0,w),
/// (1,w): their indices and values.
type Multipliers = ([usize; 3], [f64; 3]);

impl StepClamp {
    /// (B37): normal k's hold rate at a, value at b, rate at b.
    fn hold_rows<J: AddEntries>(
        &self,
        k: usize,
        jets: &FrameJets,
        residual: &mut [f64],
        jacobian: &mut Option<&mut J>,
    ) {
        let (at, v) = (&self.at, &self.v);
        let (q, r_x, h) = (&at.turn, &at.r_x, &at.hold_rows);
        let ((na, nad), (nb, nbd)) = (&jets.start, &jets.end);
        let (na_v, nb_v, nbd_v) = (value(na), value(nb), value(nbd));
        let rate_a = project(v.r_a, nad);
        residual[h[0][k]] += dot(na_v, v.w_a) + rate_a.v;
        let value_b = project(v.e_b, nb);
        residual[h[1][k]] += value_b.v;
        let (slope_b, rate_b) = (project(v.w_b, nb), project(v.e_b, nbd));
        residual[h[2][k]] += slope_b.v + rate_b.v;
        for c in 0..3 {
            put(jacobian, h[0][k], r_x[0][c], na_v[c]);
            put(jacobian, h[1][k], r_x[1][c], nb_v[c]);
            put(jacobian, h[2][k], r_x[2][c], nb_v[c]);
            put(jacobian, h[2][k], r_x[1][c], nbd_v[c]);
        }
        for i in 0..3 {
            put(jacobian, h[0][k], q[0][i], rate_a.g[3 + i]);
            put(jacobian, h[1][k], q[1][i], value_b.g[i]);
            put(jacobian, h[2][k], q[1][i], slope_b.g[i] + rate_b.g[i]);
            put(jacobian, h[2][k], q[2][i], rate_b.g[3 + i]);
        }
    }

    /// (B38) in r_x's rows (0,e), (0,w), (1,w).
    fn line_reactions<J: AddEntries>(
        &self,
        jets: &FrameJets,
        (m, lambda): Multipliers,
        residual: &mut [f64],
        jacobian: &mut Option<&mut J>,
    ) {
        let (q, rows, sign) = (&self.at.turn, &self.at.rows, self.sign);
        let ((na, nad), (nb, _)) = (&jets.start, &jets.end);
        let (na_v, nad_v, nb_v) = (value(na), value(nad), value(nb));
        for c in 0..3 {
            residual[rows[0][c]] += sign * (lambda[0] * na_v[c] + lambda[1] * nad_v[c]);
            residual[rows[1][c]] += sign * lambda[1] * na_v[c];
            residual[rows[2][c]] += sign * lambda[2] * nb_v[c];
            put(jacobian, rows[0][c], m[0], sign * na_v[c]);
            put(jacobian, rows[0][c], m[1], sign * nad_v[c]);
            put(jacobian, rows[1][c], m[1], sign * na_v[c]);
            put(jacobian, rows[2][c], m[2], sign * nb_v[c]);
            for i in 0..3 {
                let d_start = sign * lambda[1] * nad[c].g[3 + i];
                put(jacobian, rows[0][c], q[0][i], d_start);
                put(jacobian, rows[2][c], q[1][i], sign * lambda[2] * nb[c].g[i]);
            }
        }
    }

    /// (B38) in the body's rotation rows: (0,e) varies theta_a (the
    /// frame's value and rate at a), (0,w) varies u_a, (1,w) varies u_b.
    fn body_reactions<J: AddEntries>(
        &self,
        jets: &FrameJets,
        (m, lambda): Multipliers,
        residual: &mut [f64],
        jacobian: &mut Option<&mut J>,
    ) {
        let (q, r_x, sign, v) = (&self.at.turn, &self.at.r_x, self.sign, &self.v);
        let ((na, nad), (_, nbd)) = (&jets.start, &jets.end);
        let (start_value, start_slope) = (project(v.r_a, na), project(v.w_a, na));
        let (rate_a, rate_b) = (project(v.r_a, nad), project(v.e_b, nbd));
        for j in 0..3 {
            let slope_j = start_slope.g[j] + rate_a.g[j];
            residual[q[0][j]] += sign * (lambda[0] * start_value.g[j] + lambda[1] * slope_j);
            residual[q[1][j]] += sign * lambda[1] * rate_a.g[3 + j];
            residual[q[2][j]] += sign * lambda[2] * rate_b.g[3 + j];
            put(jacobian, q[0][j], m[0], sign * start_value.g[j]);
            put(jacobian, q[0][j], m[1], sign * slope_j);
            put(jacobian, q[1][j], m[1], sign * rate_a.g[3 + j]);
            put(jacobian, q[2][j], m[2], sign * rate_b.g[3 + j]);
            for c in 0..3 {
                put(jacobian, q[0][j], r_x[0][c], sign * lambda[1] * na[c].g[j]);
                put(
                    jacobian,
                    q[2][j],
                    r_x[1][c],
                    sign * lambda[2] * nbd[c].g[3 + j],
                );
            }
            for i in 0..3 {
                let d_start = lambda[0] * start_value.h[j][3 + i]
                    + lambda[1] * (start_slope.h[j][3 + i] + rate_a.h[j][3 + i]);
                put(jacobian, q[0][j], q[0][i], sign * d_start);
                let d_rate_a = sign * lambda[1] * rate_a.h[3 + j][3 + i];
                put(jacobian, q[1][j], q[0][i], d_rate_a);
                put(
                    jacobian,
                    q[2][j],
                    q[1][i],
                    sign * lambda[2] * rate_b.h[3 + j][i],
                );
                let d_rate_b = sign * lambda[2] * rate_b.h[3 + j][3 + i];
                put(jacobian, q[2][j], q[2][i], d_rate_b);
            }
        }
    }
}

/// What a converged step leaves of a clamp at its end: the reaction of
/// its r_x's row (0,e) (B38) without the multipliers' sign, as a fixed
/// hold's is summed (`Simulation::clamp_moments`), sum_k lambda_(0,e),k
/// n_k(a) + lambda_(0,w),k n_k'(a); and its shares of the end momenta
/// (B39): on the line's r_x, sign sum_k lambda_(1,w),k n_k'(b) (global),
/// on the body's theta_b, sign sum_k lambda_(1,w),k d C_k'(b) / d theta_b.
#[derive(Clone, Copy, Debug, Default)]
pub(super) struct ClampStepEnd {
    pub reaction: [f64; 3],
    pub on_line: [f64; 3],
    pub on_body: [f64; 3],
}

/// [`ClampStepEnd`] of clamp `clamp` at converged unknowns x;
/// `rotation_a`, `xb` as [`add_step_clamp`]'s.
pub(super) fn step_end(
    clamp: &BodyClamp,
    layout: &SystemLayout,
    dpn: usize,
    rotation_a: &[[f64; 3]; 3],
    xb: &[f64; 18],
    x: &[f64],
) -> ClampStepEnd {
    let at = ClampIndices::of(clamp, layout, dpn);
    let sign = layout.lines[clamp.line].scheme.multiplier_sign();
    let (e_b, w_b) = (values(x, &at.r_x[1]), values(x, &at.r_x[2]));
    let mut end = ClampStepEnd::default();
    for k in 0..2 {
        let lambda = at.multipliers.map(|m| x[m[k]]);
        let jets = frame_jets(rotation_a, clamp.local.normals[k], xb);
        let ((na, nad), (nb, nbd)) = (&jets.start, &jets.end);
        let (slope, rate) = (project(w_b, nb), project(e_b, nbd));
        for c in 0..3 {
            end.reaction[c] += lambda[0] * na[c].v + lambda[1] * nad[c].v;
            end.on_line[c] += sign * lambda[2] * nbd[c].v;
            end.on_body[c] += sign * lambda[2] * (slope.g[c] + rate.g[c]);
        }
    }
    end
}

/// Adds clamp `clamp`'s static terms at x: the hold n_k(theta) . r_x = 0
/// with n_k(theta) = R_0 exp([theta]) n_k', its multiplier in r_x's rows
/// and in theta's (sign lambda n_k and sign lambda (dn_k/dtheta)^T r_x),
/// with their derivatives. `rotation` is R_0.
pub(super) fn add_static_clamp<J: AddEntries>(
    clamp: &BodyClamp,
    layout: &SystemLayout,
    dpn: usize,
    rotation: &[[f64; 3]; 3],
    x: &[f64],
    residual: &mut [f64],
    mut jacobian: Option<&mut J>,
) {
    let at = ClampIndices::of(clamp, layout, dpn);
    let sign = layout.lines[clamp.line].scheme.multiplier_sign();
    let (q, rows, r_x) = (&at.turn[0], &at.rows[0], &at.r_x[0]);
    let r = values(x, r_x);
    let theta = [x[q[0]], x[q[1]], x[q[2]]];
    for k in 0..2 {
        let (n, _) = offsets(rotation, clamp.local.normals[k], theta, [0.0; 3]);
        let n_v = [n[0].v, n[1].v, n[2].v];
        let hold = project(r, &n);
        let (row, m) = (at.hold_rows[0][k], at.multipliers[0][k]);
        let lambda = x[m];
        residual[row] += hold.v;
        for c in 0..3 {
            put(&mut jacobian, row, r_x[c], n_v[c]);
            residual[rows[c]] += sign * lambda * n_v[c];
            put(&mut jacobian, rows[c], m, sign * n_v[c]);
        }
        for j in 0..3 {
            put(&mut jacobian, row, q[j], hold.g[j]);
            residual[q[j]] += sign * lambda * hold.g[j];
            put(&mut jacobian, q[j], m, sign * hold.g[j]);
            for c in 0..3 {
                put(&mut jacobian, rows[c], q[j], sign * lambda * n[c].g[j]);
                put(&mut jacobian, q[j], r_x[c], sign * lambda * n[c].g[j]);
            }
            for i in 0..3 {
                put(&mut jacobian, q[j], q[i], sign * lambda * hold.h[j][i]);
            }
        }
    }
}

/// The moment (global) clamp `clamp` puts on its body at a static
/// equilibrium x: minus its moment on the line, r_x x Q (M42), Q = sum_k
/// lambda_k n_k(theta) (a static multiplier is the force itself).
/// `rotation` is R_0 (as [`add_static_clamp`]'s).
pub(super) fn static_moment(
    clamp: &BodyClamp,
    layout: &SystemLayout,
    dpn: usize,
    rotation: &[[f64; 3]; 3],
    x: &[f64],
) -> [f64; 3] {
    let at = ClampIndices::of(clamp, layout, dpn);
    let theta = at.turn[0].map(|i| x[i]);
    let mut q = [0.0; 3];
    for k in 0..2 {
        let (n, _) = offsets(rotation, clamp.local.normals[k], theta, [0.0; 3]);
        for c in 0..3 {
            q[c] += x[at.multipliers[0][k]] * n[c].v;
        }
    }
    let r_x = values(x, &at.r_x[0]);
    scale(-1.0, DirectionHold::moment(r_x, q))
}
