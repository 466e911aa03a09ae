//! The rods of a system's written moment, for a deck's `Rod<n>` channels
//! (MoorDyn's `Rod::GetRodOutput`, docs/moordyn-bodies-rods.md §4.1;
//! docs/interface.md, "A deck's rods"): each rod's end A (its reference
//! point), its velocity, its axis, its angular velocity, the force of
//! the lines at its ends, its submerged fraction and, for a free rod,
//! its net force, all from its holder's row.
//!
//! - A rod on a body (free, or fixed in a body) is where its body's pose
//!   puts it: end A at x_ref + R xi_A, moving at v_ref + w x (R xi_A),
//!   its axis R (xi_B - xi_A) / L.
//! - A fixed rod stays at its ends: no velocity, no net force.
//! - A rod of zero length is a point: its position and velocity are the
//!   point's (its free point's, or its holder's at its end A).

use super::bodies::BodyRow;
use super::rows::SystemRow;
use crate::moordyn::{Axis, LineEnd, RodQuantity};
use crate::scenario::{RodHolder, SystemRod, SystemScenario};
use stancf::body::pose::{point, rotate, rotate_back};
use stancf::body::Rod;
use stancf::vec3::{add, cross, norm, sub};

/// A rod as its channels need it: what holds it, its ends in its
/// holder's frame (a body's axes from its reference point; global for a
/// fixed rod), the rod (None for one of zero length) and the points at
/// its ends.
pub(super) struct RodFrame {
    /// Its id, and the id of the body it is or is fixed in (0: none).
    pub id: i64,
    pub body_id: i64,
    holder: RodHolder,
    /// End A in the holder's frame.
    end_a: [f64; 3],
    rod: Option<Rod>,
    points: [Option<usize>; 2],
}

/// The frames of the scenario's rods. A rod of zero length on a body
/// has its end A in the body's axes, from where the body's pose at t = 0
/// puts it.
pub(super) fn frames(sc: &SystemScenario) -> Vec<RodFrame> {
    sc.rods.iter().map(|r| frame(sc, r)).collect()
}

fn frame(sc: &SystemScenario, r: &SystemRod) -> RodFrame {
    let end_a = match (&r.rod, r.holder) {
        (Some(rod), _) => rod.end_a,
        (
            None,
            RodHolder::Body { body }
            | RodHolder::Free { body }
            | RodHolder::Pinned { body, .. }
            | RodHolder::Coupled { body },
        ) => {
            let b = &sc.bodies[body];
            rotate_back(&b.rotation(), sub(r.ends[0], b.position))
        }
        (None, _) => r.ends[0],
    };
    RodFrame {
        id: r.id,
        body_id: r.body().map_or(0, |b| sc.bodies[b].id),
        holder: r.holder,
        end_a,
        rod: r.rod.clone(),
        points: r.points,
    }
}

/// A rod at a written moment.
struct RodState {
    /// End A and its velocity (global).
    end_a: [f64; 3],
    velocity: [f64; 3],
    /// The unit axis from A to B (global); None for a rod of zero length.
    axis: Option<[f64; 3]>,
    /// The angular velocity (rad/s), global.
    angular_velocity: [f64; 3],
}

impl RodFrame {
    /// The rod's state at `row`.
    fn state(&self, row: &SystemRow) -> RodState {
        let still = |end_a| RodState {
            end_a,
            velocity: [0.0; 3],
            axis: self.rod.as_ref().map(Rod::axis),
            angular_velocity: [0.0; 3],
        };
        match self.holder {
            RodHolder::Fixed => still(self.end_a),
            RodHolder::Point { point, .. } => {
                let (x, v, _) = row.points[point];
                RodState {
                    velocity: v,
                    ..still(x)
                }
            }
            RodHolder::Free { body }
            | RodHolder::Pinned { body, .. }
            | RodHolder::Body { body }
            | RodHolder::Coupled { body } => {
                let m = &row.bodies[body].motion;
                let arm = rotate(&m.rotation, self.end_a);
                RodState {
                    end_a: point(m.position, &m.rotation, self.end_a),
                    velocity: add(m.velocity, cross(m.angular_velocity, arm)),
                    axis: self.rod.as_ref().map(|r| rotate(&m.rotation, r.axis())),
                    angular_velocity: m.angular_velocity,
                }
            }
        }
    }

    /// The rod as a ParaView segment at `row` (None for a rod of zero
    /// length), its radius d/2.
    pub(super) fn segment(&self, row: &SystemRow) -> Option<crate::vtk::Segment> {
        let rod = self.rod.as_ref()?;
        let s = self.state(row);
        let axis = s.axis?;
        Some(crate::vtk::Segment {
            a: s.end_a,
            b: add(s.end_a, stancf::vec3::scale(rod.length(), axis)),
            body: self.body_id,
            rod: self.id,
            axis: 0,
            radius: 0.5 * rod.diameter,
        })
    }

    /// Node `node` of the rod's segments at state `s`: x_k = x_A + (k / N)
    /// L q on the rigid rod and its velocity v_A + w x (x_k - x_A) (a rod
    /// of zero length: its one node, end A).
    fn node(&self, s: &RodState, node: usize) -> ([f64; 3], [f64; 3]) {
        let reach = match (&self.rod, s.axis) {
            (Some(rod), Some(q)) if rod.segments > 0 => {
                let along = rod.length() * node as f64 / rod.segments as f64;
                q.map(|c| along * c)
            }
            _ => [0.0; 3],
        };
        (
            add(s.end_a, reach),
            add(s.velocity, cross(s.angular_velocity, reach)),
        )
    }

    /// Every node of the rod's segments at `row`, A to B (one for a rod
    /// of zero length): position and velocity, MoorDyn's `r` and `rd`.
    pub(super) fn nodes(&self, row: &SystemRow) -> Vec<([f64; 3], [f64; 3])> {
        let s = self.state(row);
        let segments = self.rod.as_ref().map_or(0, |r| r.segments);
        (0..=segments).map(|k| self.node(&s, k)).collect()
    }

    /// The net force of the lines attached at end `k` (0 where none is).
    fn end_tension(&self, row: &SystemRow, k: usize) -> f64 {
        self.points[k].map_or(0.0, |p| norm(row.points[p].2))
    }

    /// The net force and its moment about end A `at`: a free rod's are
    /// its body's (MoorDyn's `getFnet`, [`super::bodies`]), moved from
    /// the body's reference point; a fixed rod's none (MoorDyn never
    /// computes a fixed rod's forces). A rod on a body is refused on
    /// reading (NaN here).
    fn net(&self, bodies: &[BodyRow], at: [f64; 3]) -> ([f64; 3], [f64; 3]) {
        match self.holder {
            RodHolder::Free { body }
            | RodHolder::Pinned { body, .. }
            | RodHolder::Coupled { body } => {
                let b = &bodies[body];
                let arm = sub(b.motion.position, at);
                (b.net_force, add(b.net_moment, cross(arm, b.net_force)))
            }
            RodHolder::Fixed => ([0.0; 3], [0.0; 3]),
            RodHolder::Body { .. } | RodHolder::Point { .. } => ([f64::NAN; 3], [f64::NAN; 3]),
        }
    }
}

/// MoorDyn's "roll" and "pitch" of a rod (radians): -phi sin(beta) and
/// phi cos(beta), phi = atan2(sqrt(q_x^2 + q_y^2), q_z) the axis's angle
/// from the vertical and beta = atan2(q_y, q_x) its heading (0 within
/// 1e-6 of the vertical), as `Rod::doRHS` with `orientationAngles`.
pub(super) fn roll_and_pitch(q: [f64; 3]) -> [f64; 2] {
    let across = q[0].hypot(q[1]);
    let phi = across.atan2(q[2]);
    let beta = if across < 1e-6 { 0.0 } else { q[1].atan2(q[0]) };
    [-phi * beta.sin(), phi * beta.cos()]
}

/// The value of quantity `q` of the rod `frame` at `row` (MoorDyn's
/// units: degrees and degrees per second). What is refused on reading
/// (accelerations; a zero-length rod's all but its position and
/// velocity; a body rod's forces) is NaN here.
pub(super) fn rod_value(frame: &RodFrame, q: RodQuantity, row: &SystemRow) -> f64 {
    let k = |a: Axis| match a {
        Axis::X => 0,
        Axis::Y => 1,
        Axis::Z => 2,
    };
    let s = frame.state(row);
    match q {
        RodQuantity::Position(a) => s.end_a[k(a)],
        RodQuantity::Velocity(a) => s.velocity[k(a)],
        RodQuantity::Rotation(a) => s
            .axis
            .map_or(f64::NAN, |q| roll_and_pitch(q)[k(a)].to_degrees()),
        RodQuantity::AngularVelocity(a) => match s.axis {
            Some(_) => s.angular_velocity[k(a)].to_degrees(),
            None => f64::NAN,
        },
        RodQuantity::EndTension(end) => {
            frame.end_tension(row, if end == LineEnd::A { 0 } else { 1 })
        }
        RodQuantity::Submerged => match (&frame.rod, s.axis) {
            (Some(rod), Some(axis)) => rod.submerged_volume(s.end_a[2], axis[2]) / rod.volume(),
            _ => f64::NAN,
        },
        RodQuantity::Force(a) => frame.net(&row.bodies, s.end_a).0[k(a)],
        RodQuantity::Moment(a) => frame.net(&row.bodies, s.end_a).1[k(a)],
        RodQuantity::NodePosition(node, a) => frame.node(&s, node).0[k(a)],
        RodQuantity::NodeVelocity(node, a) => frame.node(&s, node).1[k(a)],
        RodQuantity::Acceleration(_)
        | RodQuantity::AngularAcceleration(_)
        | RodQuantity::NodeOther(_) => f64::NAN,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use stancf::vec3::normalized as unit;

    /// A rod's node moves with the rigid rod: node k of N at (k/N) L
    /// along its axis from end A, at v_A + w x (x_k - x_A), against the
    /// central difference of the node's position under the same rigid
    /// motion (end A moving at v_A, the axis turning at w), to 1e-9 m/s.
    #[test]
    fn a_rods_node_moves_with_the_rigid_rod() {
        let rod = Rod {
            end_a: [0.0; 3],
            end_b: [4.0, 0.0, 3.0],
            diameter: 0.2,
            mass_per_length: 10.0,
            drag_coefficient: 0.0,
            added_mass_coefficient: 0.0,
            end_drag_coefficient: 0.0,
            end_added_mass_coefficient: 0.0,
            segments: 4,
        };
        let frame = RodFrame {
            id: 1,
            body_id: 0,
            holder: RodHolder::Fixed,
            end_a: [0.0; 3],
            rod: Some(rod.clone()),
            points: [None; 2],
        };
        let (v_a, w) = ([0.3, -0.2, 0.1], [0.4, 0.7, -0.5]);
        let at = |t: f64| {
            let turn = stancf::body::rotation::exp_map(w.map(|c| c * t));
            RodState {
                end_a: v_a.map(|c| c * t),
                velocity: v_a,
                axis: Some(stancf::body::pose::rotate(&turn, rod.axis())),
                angular_velocity: w,
            }
        };
        let h = 1e-5;
        for k in 0..=4 {
            let (_, v) = frame.node(&at(0.0), k);
            let (p, m) = (frame.node(&at(h), k).0, frame.node(&at(-h), k).0);
            for c in 0..3 {
                let fd = (p[c] - m[c]) / (2.0 * h);
                assert!((fd - v[c]).abs() < 1e-9, "node {k}: {v:?} against {fd}");
            }
        }
        let b = frame.node(&at(0.0), 4).0;
        assert!((0..3).all(|c| (b[c] - rod.end_b[c]).abs() < 1e-12), "{b:?}");
    }

    /// MoorDyn's angles of a rod: 0 standing with end A below end B
    /// (MoorDyn's docs: "a rod with zero rotation"), pitch 90 degrees
    /// lying along +x, roll -90 along +y, pitch 180 hanging (end A above
    /// B), and 45 degrees tilted toward +x.
    #[test]
    fn a_rods_roll_and_pitch_are_moordyns() {
        let deg = |q: [f64; 3]| roll_and_pitch(unit(q)).map(f64::to_degrees);
        let close = |a: [f64; 2], b: [f64; 2]| (0..2).all(|i| (a[i] - b[i]).abs() < 1e-12);
        for (q, want) in [
            ([0.0, 0.0, 1.0], [0.0, 0.0]),
            ([1.0, 0.0, 0.0], [0.0, 90.0]),
            ([0.0, 1.0, 0.0], [-90.0, 0.0]),
            ([-1.0, 0.0, 0.0], [0.0, -90.0]),
            ([0.0, 0.0, -1.0], [0.0, 180.0]),
            ([1.0, 0.0, 1.0], [0.0, 45.0]),
        ] {
            let got = deg(q);
            assert!(close(got, want), "{q:?}: {got:?} against {want:?}");
        }
    }
}
