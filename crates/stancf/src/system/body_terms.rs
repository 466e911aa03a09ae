//! A free body's share of a system's Galerkin step (docs/method.md
//! §15.7, (B11)-(B13)).
//!
//! The body's unknowns per slot are its centre's three and its rotation
//! vector's three, in the border after the points'. A point P on the body
//! keeps its border unknowns y_P (its slot values, shared by the line
//! ends attached there), but its rows change:
//!
//! - the lines' rows at P, R_P (their share of the action's variation
//!   in P's slot values), are carried to the body's rows by the chain
//!   rule through (B11), y_P = phi(q):
//!
//!   ```text
//!     row q_s += (d y_P / d q_s)^T R_P                                 (B12)
//!   ```
//!
//!   with the Galerkin row slots (0,e), (0,w), (1,w) of §5.1: the start's
//!   variations move e_a and the slope w_a, the slopes' variations move
//!   the slopes. The map's derivatives depend on the unknowns (u_a,
//!   theta_b), so the Jacobian gains R_P . d2 y_P / dq dq';
//! - P's rows become its constraint, y_P - phi(q) = 0, at P's unknown
//!   slots (0,w), (1,e), (1,w):
//!
//!   ```text
//!     w_P,a = w_a + R_a (u_a x xi'),   e_P,b = r_b + R_a exp([theta_b]) xi',
//!     w_P,b = w_b + R_a exp([theta_b]) (J_r(theta_b) u_b x xi')         (B13)
//!   ```
//!
//! This is Hamilton's law for the lines and the body together in the
//! body's coordinates (the line ends' slot values are the body point's):
//! the system's Newton iterates on it with the bordered Jacobian, the
//! points' rows now linear in y_P. The body's own rows are
//! [`crate::body::FreeBody`]'s (B6).

use super::layout::SystemLayout;
use crate::body::attach::{offsets, project};
use crate::body::jet::JetVec;
use crate::body::FreeBody;
use crate::bordered::BorderedMatrix;
use crate::linear::AddEntries;

/// A point on a body: its index and its place from the body's centre of
/// mass, xi' = xi - c (body axes).
#[derive(Clone, Copy, Debug)]
pub(super) struct BodyPoint {
    pub point: usize,
    pub arm: [f64; 3],
}

/// A free body of a system step: its state and its points.
#[derive(Clone, Debug)]
pub(super) struct StepBody {
    pub index: usize,
    pub body: FreeBody,
    pub points: Vec<BodyPoint>,
    /// Where the body is pinned, if it is (§15.12).
    pub pin: Option<StepPin>,
}

/// A body's pin in a step (§15.12, `system/pins.rs`): the pinned point
/// from the centre of mass (body axes) and what holds it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) struct StepPin {
    pub arm: [f64; 3],
    pub hold: PinHold,
    /// The slot values (0,w), (1,e), (1,w) of a given hold over the step:
    /// [0, P, 0] at a fixed point, the point's velocity at the start and
    /// position and velocity at the end on a host's motion (B34).
    pub held: [[f64; 3]; 3],
    /// The body's linear momentum at the step's start, and the pin's mean
    /// force on the body over the last step (B35).
    pub momentum_a: [f64; 3],
    pub force: [f64; 3],
    /// How far a host's motion moved the pinned point over the step, and
    /// the work the pin did on the body so far: its mean force times that,
    /// step by step (second order, as a coupled point's (M24)); zero at a
    /// fixed point or a joint.
    pub moved: [f64; 3],
    pub work: f64,
}

/// What holds a pinned point: a fixed point (global); a point whose
/// slot values are unknowns of the step, a free point or another free
/// body's point (a joint, §15.14); or a coupled point, moved by a host or
/// a motion (§15.17).
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) enum PinHold {
    Fixed([f64; 3]),
    Point(usize),
    Moving(usize),
}

/// Global index of the FreeBody's Galerkin unknown (or row) i: its blocks
/// [w_a, r_b - r_a, w_b | u_a, theta_b, u_b] (rows [(0,e), (0,w), (1,w)]
/// of the centre, then of the rotation) in the system's slots.
fn global(layout: &SystemLayout, b: usize, i: usize) -> usize {
    let (slot, k) = if i < 9 {
        (i / 3, i % 3)
    } else {
        ((i - 9) / 3, 3 + (i - 9) % 3)
    };
    layout.body_unknown(b, slot, k).expect("a free body")
}

/// The body point's offsets at the step's start (theta = 0, slope u_a)
/// and end (theta_b, u_b), (B11) on jets.
pub(super) struct PointMaps {
    pub start: (JetVec<6>, JetVec<6>),
    pub end: (JetVec<6>, JetVec<6>),
}

impl StepBody {
    /// The body's Galerkin unknowns (FreeBody order) from the system's x.
    pub fn unknowns(&self, layout: &SystemLayout, x: &[f64]) -> [f64; 18] {
        std::array::from_fn(|i| x[global(layout, self.index, i)])
    }

    /// Writes the body's unknowns into the system's x.
    pub fn set_unknowns(&self, layout: &SystemLayout, xb: &[f64; 18], x: &mut [f64]) {
        for (i, v) in xb.iter().enumerate() {
            x[global(layout, self.index, i)] = *v;
        }
    }

    /// (B11) for point `arm` at the body's unknowns xb.
    pub fn maps(&self, arm: [f64; 3], xb: &[f64; 18]) -> PointMaps {
        let part = |a: usize| [xb[a], xb[a + 1], xb[a + 2]];
        let ra = self.body.rotation();
        PointMaps {
            start: offsets(&ra, arm, [0.0; 3], part(9)),
            end: offsets(&ra, arm, part(12), part(15)),
        }
    }

    /// The slot values (B13) of a point at the body's unknowns: its
    /// unknown slots (0,w), (1,e), (1,w).
    pub fn point_slots(&self, maps: &PointMaps, xb: &[f64; 18]) -> [[f64; 3]; 3] {
        let r_a = self.body.centre();
        let (_, va) = &maps.start;
        let (pb, vb) = &maps.end;
        [
            std::array::from_fn(|c| xb[c] + va[c].v),
            std::array::from_fn(|c| r_a[c] + xb[3 + c] + pb[c].v),
            std::array::from_fn(|c| xb[6 + c] + vb[c].v),
        ]
    }

    /// Adds the body's own rows (B6), carries its points' rows to it (B12)
    /// and sets the points' rows to their constraints (B13). Call after
    /// every line and point has added its rows.
    pub fn add(
        &self,
        layout: &SystemLayout,
        x: &[f64],
        residual: &mut [f64],
        mut jacobian: Option<&mut BorderedMatrix>,
    ) {
        let b = self.index;
        let xb = self.unknowns(layout, x);
        let (mut rows, mut jac) = ([0.0; 18], [0.0; 18 * 18]);
        self.body.galerkin_rows_into(&xb, &mut rows, &mut jac);
        for i in 0..18 {
            residual[global(layout, b, i)] += rows[i];
        }
        if let Some(m) = jacobian.as_deref_mut() {
            for i in 0..18 {
                for j in 0..18 {
                    let v = jac[i * 18 + j];
                    if v != 0.0 {
                        m.add(global(layout, b, i), global(layout, b, j), v);
                    }
                }
            }
        }
        let q = |slot: usize, k: usize| layout.body_unknown(b, slot, k).expect("free body");
        for bp in &self.points {
            let y =
                |slot: usize, c: usize| layout.point_unknown(bp.point, slot, c).expect("border");
            let maps = self.maps(bp.arm, &xb);
            let (pa, va) = &maps.start;
            let (pb, vb) = &maps.end;
            // The lines' rows at P, R_P, at its row slots (0,e), (0,w), (1,w).
            let raw: [[f64; 3]; 3] =
                std::array::from_fn(|s| std::array::from_fn(|c| residual[y(s, c)]));
            let start = project(raw[0], pa) + project(raw[1], va);
            let end = project(raw[2], vb);
            for c in 0..3 {
                for s in 0..3 {
                    residual[q(s, c)] += raw[s][c];
                }
                residual[q(0, 3 + c)] += start.g[c];
                residual[q(1, 3 + c)] += start.g[3 + c];
                residual[q(2, 3 + c)] += end.g[3 + c];
            }
            if let Some(m) = jacobian.as_deref_mut() {
                for s in 0..3 {
                    for c in 0..3 {
                        m.add_border_row(q(s, c), y(s, c), 1.0);
                    }
                }
                for j in 0..3 {
                    for c in 0..3 {
                        m.add_border_row(q(0, 3 + j), y(0, c), pa[c].g[j]);
                        m.add_border_row(q(0, 3 + j), y(1, c), va[c].g[j]);
                        m.add_border_row(q(1, 3 + j), y(1, c), va[c].g[3 + j]);
                        m.add_border_row(q(2, 3 + j), y(2, c), vb[c].g[3 + j]);
                    }
                }
                for s in 0..3 {
                    for c in 0..3 {
                        m.clear_border_row(y(s, c));
                    }
                }
                // The map's change along the unknowns u_a (start) and
                // theta_b, u_b (end): R_P . d2 y_P.
                for j in 0..3 {
                    for i in 0..3 {
                        m.add(q(0, 3 + j), q(0, 3 + i), start.h[j][3 + i]);
                        m.add(q(1, 3 + j), q(0, 3 + i), start.h[3 + j][3 + i]);
                        m.add(q(2, 3 + j), q(1, 3 + i), end.h[3 + j][i]);
                        m.add(q(2, 3 + j), q(2, 3 + i), end.h[3 + j][3 + i]);
                    }
                }
            }
            // P's rows: its constraints (B13) at its unknown slots.
            let target = self.point_slots(&maps, &xb);
            for s in 0..3 {
                for c in 0..3 {
                    residual[y(s, c)] = x[y(s, c)] - target[s][c];
                }
            }
            if let Some(m) = jacobian.as_deref_mut() {
                for c in 0..3 {
                    for s in 0..3 {
                        m.add(y(s, c), y(s, c), 1.0);
                        m.add(y(s, c), q(s, c), -1.0);
                    }
                    for j in 0..3 {
                        m.add(y(0, c), q(0, 3 + j), -va[c].g[3 + j]);
                        m.add(y(1, c), q(1, 3 + j), -pb[c].g[j]);
                        m.add(y(2, c), q(1, 3 + j), -vb[c].g[j]);
                        m.add(y(2, c), q(2, 3 + j), -vb[c].g[3 + j]);
                    }
                }
            }
        }
    }

    /// The generalized momentum of the body and its lines at the step's
    /// end, in (v_G, Omega) at the end's pose, less the points' share
    /// (which the lines' end momenta bring, §15.7 (B14)): the body's
    /// [dA/dr_b; J_r(theta_b)^-T (dA/dtheta_b + sum_P (d w_P,b /
    /// dtheta_b)^T R_P(1,w))] with R_P the lines' (1,w) rows at P,
    /// `end_rows(point)`, and `clamps`, the share of the lines clamped to
    /// it (B39, §15.19). With it, a pinned body's centre row at the
    /// end's slot (1,w), which a joint carries to its point's (B29; zero
    /// for a body not pinned).
    pub fn end_momentum(
        &self,
        xb: &[f64; 18],
        end_rows: impl Fn(usize) -> [f64; 3],
        clamps: [f64; 3],
    ) -> Option<([f64; 6], [f64; 3])> {
        let (p, mut dtheta) = self.body.galerkin_end_gradient(xb);
        dtheta = crate::vec3::add(dtheta, clamps);
        for bp in &self.points {
            let maps = self.maps(bp.arm, xb);
            let end = project(end_rows(bp.point), &maps.end.1);
            for j in 0..3 {
                dtheta[j] += end.g[j];
            }
        }
        let mut centre_row = [0.0; 3];
        if self.pin.is_some() {
            let (mut rows, mut jac) = ([0.0; 18], [0.0; 18 * 18]);
            self.body.galerkin_rows_into(xb, &mut rows, &mut jac);
            centre_row = self.centre_end_row([rows[6], rows[7], rows[8]], &end_rows);
            let share = self.pin_end_share(xb, centre_row);
            for j in 0..3 {
                dtheta[j] += share[j];
            }
        }
        let theta_b = [xb[12], xb[13], xb[14]];
        let jr = crate::body::rotation::right_jacobian(theta_b);
        let pi = crate::body::free::solve_transposed(&jr, dtheta)?;
        Some(([p[0], p[1], p[2], pi[0], pi[1], pi[2]], centre_row))
    }
}
