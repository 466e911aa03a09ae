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
//!
//! A joint (§15.14) pins the body to a point whose slot values y_P are
//! unknowns, a free point or another free body's point: r_G = y_P - R xi'
//! (B28), so the centre's rows also join P's as they are (B29), before
//! P's own rows are carried on to its body (children are added before
//! their parents), its end row joins P's end row, and the end rates hold
//! v_G - v_P - G_c Omega = 0 (B30).
//!
//! At rest (`StaticBody::add_pin`) the pin is (B24) at t = 0, its force
//! the centre's rows it replaces (B35); on a host's motion the step's
//! held slot values are the point's (B34, §15.17).

use super::body_statics::StaticBody;
use super::body_terms::{PinHold, StepBody};
use super::layout::SystemLayout;
use crate::body::attach::{offsets, project};
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
        // A joint: r_G = y_P - R xi' (B28), so the joint's point's rows
        // take the centre's as they are.
        let joint = |s: usize, c: usize| match pin.hold {
            PinHold::Point(p) => layout.point_unknown(p, s, c),
            PinHold::Fixed(_) | PinHold::Moving(_) => None,
        };
        for s in 0..3 {
            for c in 0..3 {
                if let Some(y) = joint(s, c) {
                    residual[y] += raw[s][c];
                }
            }
        }
        if let Some(m) = jacobian.as_deref_mut() {
            for s in 0..3 {
                for c in 0..3 {
                    if let Some(y) = joint(s, c) {
                        m.add_border_row(y, q(s, c), 1.0);
                    }
                }
            }
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
        // (B24) at the centre's unknown slots (0,w), (1,e), (1,w): the
        // pinned point's slot values are the hold's (B28).
        let held: [[f64; 3]; 3] = match pin.hold {
            PinHold::Fixed(_) | PinHold::Moving(_) => pin.held,
            PinHold::Point(_) => {
                std::array::from_fn(|s| std::array::from_fn(|c| x[joint(s, c).expect("joint")]))
            }
        };
        let pinned = self.point_slots(&maps, &xb);
        for s in 0..3 {
            for c in 0..3 {
                residual[q(s, c)] = pinned[s][c] - held[s][c];
            }
        }
        if let Some(m) = jacobian {
            for c in 0..3 {
                for s in 0..3 {
                    m.add(q(s, c), q(s, c), 1.0);
                    if let Some(y) = joint(s, c) {
                        m.add(q(s, c), y, -1.0);
                    }
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
    /// the centre's row there ([`Self::centre_end_row`]).
    pub(super) fn pin_end_share(&self, xb: &[f64; 18], row: [f64; 3]) -> [f64; 3] {
        let Some(pin) = self.pin else {
            return [0.0; 3];
        };
        let maps = self.maps(pin.arm, xb);
        let share = project(row, &maps.end.1);
        [-share.g[0], -share.g[1], -share.g[2]]
    }

    /// The centre's row at the end's slot (1,w), R_w,b: the body's own
    /// `own_w_b` and its points' (1,w) rows `end_rows`, which (B25)
    /// carries to the rotation and a joint (B29) to its point's.
    pub(super) fn centre_end_row(
        &self,
        own_w_b: [f64; 3],
        end_rows: &impl Fn(usize) -> [f64; 3],
    ) -> [f64; 3] {
        let mut row = own_w_b;
        for bp in &self.points {
            let r = end_rows(bp.point);
            for c in 0..3 {
                row[c] += r[c];
            }
        }
        row
    }

    /// The pin's rate map in the end rates' matrix (one slot): G_c =
    /// R [xi' x] of (B26), v_G = v_P + G_c Omega at the end's pose, and
    /// the rate unknowns of the joint's point P (B30), if the pin is a
    /// joint (v_P = 0 at a fixed point).
    pub(super) fn pin_rate_map(&self, layout: &SystemLayout) -> Option<PinRates> {
        let pin = self.pin?;
        let rotation = self.body.rotation();
        let a = pin.arm;
        let hat = [[0.0, -a[2], a[1]], [a[2], 0.0, -a[0]], [-a[1], a[0], 0.0]];
        let joint = match pin.hold {
            PinHold::Point(p) => Some(std::array::from_fn(|c| {
                layout.point_unknown(p, 0, c).expect("a joint's point")
            })),
            PinHold::Fixed(_) | PinHold::Moving(_) => None,
        };
        Some(PinRates {
            g: crate::vec3::mat3_mul(&rotation, &hat),
            joint,
            velocity: pin.held[2],
        })
    }
}

/// A pin in the end rates' matrix ([`StepBody::pin_rate_map`]): G_c, the
/// joint's point's rate unknowns, and a given hold's end velocity v_P
/// (zero at a fixed point; (B34) on a host's motion).
pub(super) struct PinRates {
    pub g: [[f64; 3]; 3],
    pub joint: Option<[usize; 3]>,
    pub velocity: [f64; 3],
}

/// (B26), (B30) in the end rates' matrix: body `q`'s (global rate
/// unknowns) centre rows carried to its rotation's by G_c^T and to a
/// joint's point's as they are, and replaced by v_G - v_P - G_c Omega = 0.
pub(super) fn pin_mass(m: &mut BorderedMatrix, q: [usize; 6], pin: &PinRates) {
    let g = &pin.g;
    for c in 0..3 {
        for j in 0..3 {
            if g[c][j] != 0.0 {
                m.add_border_row(q[3 + j], q[c], g[c][j]);
            }
        }
        if let Some(y) = pin.joint {
            m.add_border_row(y[c], q[c], 1.0);
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
        if let Some(y) = pin.joint {
            m.add(q[c], y[c], -1.0);
        }
    }
}

/// (B26), (B30)'s right side: the centre's momentum rows carried to the
/// rotation's by G_c^T and to a joint's point's, the centre's set to a
/// given hold's v_P (v_G - v_P - G_c Omega = 0; v_P = 0 at a fixed point
/// and at a joint, whose v_P is the point's unknown).
pub(super) fn pin_momentum(rates: &mut [f64], q: [usize; 6], pin: &PinRates) {
    for c in 0..3 {
        let raw = rates[q[c]];
        for j in 0..3 {
            rates[q[3 + j]] += pin.g[c][j] * raw;
        }
        if let Some(y) = pin.joint {
            rates[y[c]] += raw;
        }
        rates[q[c]] = pin.velocity[c];
    }
}

/// The pin at rest (§15.12): the static solve's (B24), its force (B35)
/// the centre's rows it replaces.
impl StaticBody {
    /// A pin (B24) at rest: the centre's rows carried to the rotation's
    /// through r_G = P - R_0 exp([theta]) xi' (their derivatives too) and,
    /// at a joint, to its point's as they are (B28), and replaced by
    /// r_G + R_0 exp([theta]) xi' - P = 0.
    pub(super) fn add_pin(
        &self,
        layout: &SystemLayout,
        x: &[f64],
        q: &[f64; 6],
        residual: &mut [f64],
        jacobian: Option<&mut BorderedMatrix>,
    ) -> Option<[f64; 3]> {
        let (arm, hold) = self.pin?;
        let g = |k: usize| self.global(layout, k);
        let joint = |c: usize| match hold {
            PinHold::Point(p) => layout.point_unknown(p, 0, c),
            PinHold::Fixed(_) | PinHold::Moving(_) => None,
        };
        let (p, _) = offsets(&self.rotation, arm, [q[3], q[4], q[5]], [0.0; 3]);
        let raw: [f64; 3] = std::array::from_fn(|c| residual[g(c)]);
        let moment = project(raw, &p);
        for j in 0..3 {
            residual[g(3 + j)] -= moment.g[j];
        }
        for c in 0..3 {
            let at = match hold {
                PinHold::Fixed(at) => at[c],
                PinHold::Point(_) => x[joint(c).expect("a joint's point")],
                PinHold::Moving(_) => unreachable!("the static pin is fixed"),
            };
            if let Some(y) = joint(c) {
                residual[y] += raw[c];
            }
            residual[g(c)] = q[c] + p[c].v - at;
        }
        if let Some(m) = jacobian {
            for c in 0..3 {
                if let Some(y) = joint(c) {
                    m.add_border_row(y, g(c), 1.0);
                }
            }
            for j in 0..3 {
                for c in 0..3 {
                    m.add_border_row(g(3 + j), g(c), -p[c].g[j]);
                }
                for i in 0..3 {
                    m.add(g(3 + j), g(3 + i), -moment.h[j][i]);
                }
            }
            for c in 0..3 {
                m.clear_border_row(g(c));
                m.add(g(c), g(c), 1.0);
                for j in 0..3 {
                    m.add(g(c), g(3 + j), p[c].g[j]);
                }
                if let Some(y) = joint(c) {
                    m.add(g(c), y, -1.0);
                }
            }
        }
        Some(raw)
    }
}

#[cfg(test)]
mod tests {
    use crate::body::{BodyWater, RigidInertia};
    use crate::system::{Body, BodyKind, Pin, Point, System};

    /// The static rows' Jacobian of a buoy holding a rod at a joint (a
    /// point of the buoy no line holds), the rod crossing the surface in a
    /// current, the buoy on two lines: the derivative of its rows (the
    /// rod's centre rows carried to the joint's point and on to the buoy,
    /// the joint's constraint against the point's unknowns), by central
    /// differences.
    #[test]
    fn the_static_jacobian_with_a_joint_is_the_derivative_of_its_rows() {
        let g = [0.0, 0.0, -9.81];
        let water = BodyWater {
            density: 1025.0,
            current: [0.4, -0.2, 0.0],
            ..BodyWater::default()
        };
        let identity = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
        let mut buoy = Body::new(
            BodyKind::Free,
            [0.0, 0.0, -1.0],
            identity,
            RigidInertia::principal(4000.0, [0.0, 0.0, -0.5], [500.0, 600.0, 700.0]),
        );
        buoy.water = Some(BodyWater {
            volume: 5.0,
            ..water.clone()
        });
        let joint_local = [0.5, 0.2, 0.3];
        let mut rod = crate::body::rod::sample();
        rod.end_b = [0.9, 0.4, 1.8];
        let a = buoy.point(joint_local);
        rod.end_a = a;
        rod.end_b = crate::vec3::add(a, rod.end_b);
        let mut hung = Body::rod(BodyKind::Free, a, rod);
        hung.water = Some(water);
        hung.pin = Some(Pin {
            local: [0.0; 3],
            point: 4,
        });
        let (lines, mut points) =
            crate::system::body_statics::tests::two_lines_to(&buoy, |k, local| {
                [0.5 * k as f64, 8.0 * local[1], -8.0]
            });
        points.push(Point::on_body(0, joint_local));
        let system = System::with_bodies(lines, points, vec![buoy, hung], g).unwrap();
        let (worst, size) = crate::system::body_statics::tests::static_jacobian_error(system);
        eprintln!("static Jacobian with a joint against differences: {worst:.1e} of {size:.1e}");
        assert!(worst < 1e-6 * size, "{worst:e} of {size:e}");
    }
}
