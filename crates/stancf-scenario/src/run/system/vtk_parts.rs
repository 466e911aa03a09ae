//! A system's rigid parts in ParaView (`stancf run --vtk`,
//! `vtk/bodies_<k>.vtp`, docs/interface.md): at each written moment its
//! rods from end A to end B, and each body's axes from its reference
//! point and spokes to its points, as [`crate::vtk::Segment`]s.

use super::rods::RodFrame;
use super::rows::SystemRow;
use crate::scenario::{PointType, SystemScenario};
use crate::vtk::Segment;
use stancf::body::pose::rotate;
use stancf::vec3::{add, norm, sub};

/// Which body each point is on, and each body's id and size (its
/// farthest point or rod end from its reference point, or 1 m): the
/// length of its axes.
pub(super) struct BodyParts {
    point_body: Vec<Option<usize>>,
    ids: Vec<i64>,
    sizes: Vec<f64>,
}

impl BodyParts {
    /// The parts of `sc`, or None where it has neither bodies nor rods.
    pub(super) fn of(sc: &SystemScenario) -> Option<BodyParts> {
        if sc.bodies.is_empty() && sc.rods.is_empty() {
            return None;
        }
        let point_body: Vec<Option<usize>> = sc
            .points
            .iter()
            .map(|p| match p.kind {
                PointType::Body { body, .. } => Some(body),
                _ => None,
            })
            .collect();
        let sizes = (0..sc.bodies.len())
            .map(|b| {
                let at = sc.bodies[b].position;
                let points = sc
                    .points
                    .iter()
                    .zip(&point_body)
                    .filter(|(_, on)| **on == Some(b))
                    .map(|(p, _)| norm(sub(p.position, at)));
                let rods = sc
                    .rods
                    .iter()
                    .filter(|r| r.body() == Some(b))
                    .flat_map(|r| r.ends.map(|e| norm(sub(e, at))));
                let size = points.chain(rods).fold(0.0f64, f64::max);
                if size > 0.0 {
                    size
                } else {
                    1.0
                }
            })
            .collect();
        Some(BodyParts {
            point_body,
            ids: sc.bodies.iter().map(|b| b.id).collect(),
            sizes,
        })
    }

    /// The segments at `row`: every rod, then each body's three axes (half
    /// its size long) and its spokes.
    pub(super) fn segments(&self, rods: &[RodFrame], row: &SystemRow) -> Vec<Segment> {
        let mut out: Vec<Segment> = rods.iter().filter_map(|r| r.segment(row)).collect();
        for (b, body) in row.bodies.iter().enumerate() {
            let m = &body.motion;
            let piece = |to: [f64; 3], axis: i64| Segment {
                a: m.position,
                b: to,
                body: self.ids[b],
                rod: 0,
                axis,
                radius: 0.0,
            };
            for k in 0..3 {
                let mut e = [0.0; 3];
                e[k] = 0.5 * self.sizes[b];
                out.push(piece(add(m.position, rotate(&m.rotation, e)), k as i64 + 1));
            }
            for (p, on) in self.point_body.iter().enumerate() {
                if *on == Some(b) {
                    out.push(piece(row.points[p].0, 0));
                }
            }
        }
        out
    }
}
