//! A free body pinned at one of its points to a fixed point (docs/method.md
//! §15.12, (B24)-(B26)): MoorDyn's `Pinned` rod, turning freely about its
//! end A, and a rod pinned to a fixed body. The body keeps its six
//! unknowns per slot; its centre follows its rotation,
//!
//! ```text
//!   r_G = P - R xi',   v_G = R (xi' x Omega)                                (B24)
//! ```
//!
//! (xi' the pinned point from the centre of mass, body axes; P the pin),
//! so Hamilton's law is taken over the rotation's variations alone, the
//! centre's following: the centre's rows (their variations at the slots
//! (0,e), (0,w), (1,w), with the lines' rows its points carried there)
//! are carried to the rotation's by the chain rule through (B24), as a
//! point's are to its body's (B12) but from the centre to the rotation,
//!
//! ```text
//!   row theta_a += -(d p_a / d theta_a)^T R_r,a - (d v_a / d theta_a)^T R_w,a
//!   row u_a     += -(d v_a / d u_a)^T R_w,a,   row u_b += -(d v_b / d u_b)^T R_w,b    (B25)
//! ```
//!
//! (p, v the offsets (B11) of xi' at the start and the end), and the
//! centre's rows become (B24) at its unknown slots: w_a + v_a = 0,
//! r_a + (r_b - r_a) + p_b = P, w_b + v_b = 0. The end's angular momentum
//! about the pin, Pi_pin = Pi + [xi' x]^T R^T p, is the variation of the
//! action at theta_b with the centre following (the centre's rows at
//! the end join it), and the end rates solve the mass matrix with the
//! centre's rate rows carried to the rotation's by G_c = R [xi' x] and
//! replaced by v_G - G_c Omega = 0 (B26). The pin does no work.

use super::body_terms::StepBody;
use super::layout::SystemLayout;
use crate::body::attach::project;
use crate::bordered::BorderedMatrix;
use crate::linear::AddEntries;

impl StepBody {
    /// (B25) and (B24) over the body's rows: call after
    /// [`StepBody::add`].
    pub fn add_pin(
        &self,
        layout: &SystemLayout,
        x: &[f64],
        residual: &mut [f64],
        mut jacobian: Option<&mut BorderedMatrix>,
    ) {
        let Some(pin) = self.pin else { return };
        let b = self.index;
        let q = |slot: usize, k: usize| layout.body_unknown(b, slot, k).expect("free body");
        let xb = self.unknowns(layout, x);
        let maps = self.maps(pin.arm, &xb);
        let (pa, va) = &maps.start;
        let (pb, vb) = &maps.end;
        let raw: [[f64; 3]; 3] =
            std::array::from_fn(|s| std::array::from_fn(|c| residual[q(s, c)]));
        let start = project(raw[0], pa) + project(raw[1], va);
        let end = project(raw[2], vb);
        for j in 0..3 {
            residual[q(0, 3 + j)] -= start.g[j];
            residual[q(1, 3 + j)] -= start.g[3 + j];
            residual[q(2, 3 + j)] -= end.g[3 + j];
        }
        if let Some(m) = jacobian.as_deref_mut() {
            for j in 0..3 {
                for c in 0..3 {
                    m.add_border_row(q(0, 3 + j), q(0, c), -pa[c].g[j]);
                    m.add_border_row(q(0, 3 + j), q(1, c), -va[c].g[j]);
                    m.add_border_row(q(1, 3 + j), q(1, c), -va[c].g[3 + j]);
                    m.add_border_row(q(2, 3 + j), q(2, c), -vb[c].g[3 + j]);
                }
            }
            for j in 0..3 {
                for i in 0..3 {
                    m.add(q(0, 3 + j), q(0, 3 + i), -start.h[j][3 + i]);
                    m.add(q(1, 3 + j), q(0, 3 + i), -start.h[3 + j][3 + i]);
                    m.add(q(2, 3 + j), q(1, 3 + i), -end.h[3 + j][i]);
                    m.add(q(2, 3 + j), q(2, 3 + i), -end.h[3 + j][3 + i]);
                }
            }
            for s in 0..3 {
                for c in 0..3 {
                    m.clear_border_row(q(s, c));
                }
            }
        }
        // (B24) at the centre's unknown slots (0,w), (1,e), (1,w).
        let r_a = self.body.centre();
        for c in 0..3 {
            residual[q(0, c)] = xb[c] + va[c].v;
            residual[q(1, c)] = r_a[c] + xb[3 + c] + pb[c].v - pin.at[c];
            residual[q(2, c)] = xb[6 + c] + vb[c].v;
        }
        if let Some(m) = jacobian {
            for c in 0..3 {
                for s in 0..3 {
                    m.add(q(s, c), q(s, c), 1.0);
                }
                for j in 0..3 {
                    m.add(q(0, c), q(0, 3 + j), va[c].g[3 + j]);
                    m.add(q(1, c), q(1, 3 + j), pb[c].g[j]);
                    m.add(q(2, c), q(1, 3 + j), vb[c].g[j]);
                    m.add(q(2, c), q(2, 3 + j), vb[c].g[3 + j]);
                }
            }
        }
    }

    /// The centre's rows at the end's slot (1,w) join the end's angular
    /// momentum through (B24): -(d v_b / d theta_b)^T R_w,b, with R_w,b
    /// the body's own row there and its points' (1,w) rows `end_rows`.
    pub(super) fn pin_end_share(
        &self,
        xb: &[f64; 18],
        own_w_b: [f64; 3],
        end_rows: &impl Fn(usize) -> [f64; 3],
    ) -> [f64; 3] {
        let Some(pin) = self.pin else {
            return [0.0; 3];
        };
        let mut row = own_w_b;
        for bp in &self.points {
            let r = end_rows(bp.point);
            for c in 0..3 {
                row[c] += r[c];
            }
        }
        let maps = self.maps(pin.arm, xb);
        let share = project(row, &maps.end.1);
        [-share.g[0], -share.g[1], -share.g[2]]
    }

    /// G_c = R [xi' x] of (B26): v_G = G_c Omega at the end's pose.
    pub(super) fn pin_rate_map(&self) -> Option<[[f64; 3]; 3]> {
        let pin = self.pin?;
        let rotation = self.body.rotation();
        let a = pin.arm;
        let hat = [[0.0, -a[2], a[1]], [a[2], 0.0, -a[0]], [-a[1], a[0], 0.0]];
        Some(crate::vec3::mat3_mul(&rotation, &hat))
    }
}

/// (B26) in the end rates' matrix: body `q`'s (global rate unknowns)
/// centre rows carried to its rotation's by G_c^T and replaced by
/// v_G - G_c Omega = 0.
pub(super) fn pin_mass(m: &mut BorderedMatrix, q: [usize; 6], g: &[[f64; 3]; 3]) {
    for j in 0..3 {
        for c in 0..3 {
            if g[c][j] != 0.0 {
                m.add_border_row(q[3 + j], q[c], g[c][j]);
            }
        }
    }
    for c in 0..3 {
        m.clear_border_row(q[c]);
        m.add(q[c], q[c], 1.0);
        for j in 0..3 {
            if g[c][j] != 0.0 {
                m.add(q[c], q[3 + j], -g[c][j]);
            }
        }
    }
}

/// (B26)'s right side: the centre's momentum rows carried to the
/// rotation's by G_c^T, the centre's set to 0 (v_G - G_c Omega = 0).
pub(super) fn pin_momentum(rates: &mut [f64], q: [usize; 6], g: &[[f64; 3]; 3]) {
    for c in 0..3 {
        let raw = rates[q[c]];
        for j in 0..3 {
            rates[q[3 + j]] += g[c][j] * raw;
        }
        rates[q[c]] = 0.0;
    }
}
