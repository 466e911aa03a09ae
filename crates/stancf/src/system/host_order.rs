//! Where a host that sets the waves is asked, in MoorDyn's order
//! (`Waves::kinematicsForAllNodes`; docs/method.md §12.1, (W2h)): every
//! line's nodes (line by line, node 0 to N), then every rod's N + 1
//! nodes (rod by rod, evenly from end A to end B), then every point,
//! then every body's reference point, MoorDyn's ground body at the
//! origin first.
//!
//! A system built from a MoorDyn deck holds its rods in bodies (a free
//! rod is a body of its own, a rod on a body joins that body's water), a
//! fixed rod as its end points, a rod of zero length as a point, and it
//! adds points at rods' ends; the scenario that builds it says which of
//! its parts each of the deck's rods, points and bodies is
//! ([`HostOrder`], [`super::System::with_host_order`]). Without that,
//! the order is the system's own: the rods of each body's water, body by
//! body, then all points, then all bodies.

use super::Topology;
use crate::error::ModelError;

/// Where one of MoorDyn's rods is in the system.
#[derive(Clone, Debug, PartialEq)]
pub enum HostRod {
    /// Rod `rod` of body `body`'s water (its nodes move with the body).
    InBody { body: usize, rod: usize },
    /// A rod held where it is: its ends A and B (global) and its segments.
    Fixed {
        ends: [[f64; 3]; 2],
        segments: usize,
    },
    /// A rod of zero length: MoorDyn's one node, at point `0`.
    AtPoint(usize),
    /// A rod of zero length on body `body` with no point there: its one
    /// node at `local` in the body's axes (from its reference point).
    OnBody { body: usize, local: [f64; 3] },
}

/// The rods, points and bodies a host is asked at, in MoorDyn's order
/// (module doc), by their indices in the system (`points`: MoorDyn's
/// points, not those a scenario adds at rods' ends, nor a line failure's
/// release).
#[derive(Clone, Debug, PartialEq)]
pub struct HostOrder {
    pub rods: Vec<HostRod>,
    pub points: Vec<usize>,
    pub bodies: Vec<usize>,
}

impl HostOrder {
    /// The system's own order (module doc).
    pub(super) fn of(topology: &Topology) -> HostOrder {
        let rods = topology
            .bodies
            .iter()
            .enumerate()
            .flat_map(|(b, body)| {
                let count = body.water.as_ref().map_or(0, |w| w.rods.len());
                (0..count).map(move |rod| HostRod::InBody { body: b, rod })
            })
            .collect();
        HostOrder {
            rods,
            points: (0..topology.points.len()).collect(),
            bodies: (0..topology.bodies.len()).collect(),
        }
    }

    /// Refuses a body, rod or point the system does not have, naming it.
    pub(super) fn check(&self, topology: &Topology) -> Result<(), ModelError> {
        let bodies = topology.bodies.len();
        for (k, rod) in self.rods.iter().enumerate() {
            let known = match *rod {
                HostRod::InBody { body, rod } => topology
                    .bodies
                    .get(body)
                    .and_then(|b| b.water.as_ref())
                    .is_some_and(|w| rod < w.rods.len()),
                HostRod::Fixed { ends, .. } => ends.iter().flatten().all(|c| c.is_finite()),
                HostRod::AtPoint(p) => p < topology.points.len(),
                HostRod::OnBody { body, local } => {
                    body < bodies && local.iter().all(|c| c.is_finite())
                }
            };
            if !known {
                return Err(ModelError::invalid(
                    format!("host_order.rods[{k}]"),
                    format!("{rod:?}: the system has no such rod, or its ends are not finite"),
                ));
            }
        }
        if let Some(p) = self.points.iter().find(|&&p| p >= topology.points.len()) {
            return Err(ModelError::invalid(
                "host_order.points",
                format!("point {p} named, the system has {}", topology.points.len()),
            ));
        }
        if let Some(b) = self.bodies.iter().find(|&&b| b >= bodies) {
            return Err(ModelError::invalid(
                "host_order.bodies",
                format!("body {b} named, the system has {bodies}"),
            ));
        }
        Ok(())
    }

    /// The number of nodes of rod k (MoorDyn's N + 1).
    pub(super) fn rod_nodes(&self, topology: &Topology, k: usize) -> usize {
        match self.rods[k] {
            HostRod::InBody { body, rod } => {
                let water = topology.bodies[body].water.as_ref();
                water.map_or(1, |w| w.rods[rod].segments + 1)
            }
            HostRod::Fixed { segments, .. } => segments + 1,
            HostRod::AtPoint(_) | HostRod::OnBody { .. } => 1,
        }
    }

    /// How many places a host is asked at besides the lines' nodes: the
    /// rods' nodes, the points, the ground and the bodies.
    pub(super) fn count(&self, topology: &Topology) -> usize {
        let rods: usize = (0..self.rods.len())
            .map(|k| self.rod_nodes(topology, k))
            .sum();
        rods + self.points.len() + 1 + self.bodies.len()
    }
}

/// The place of node j of a rod from A to B in `segments` segments:
/// A + j/N (B - A) (MoorDyn's nodes, evenly along the rod).
pub(super) fn rod_node(ends: &[[f64; 3]; 2], segments: usize, j: usize) -> [f64; 3] {
    if segments == 0 {
        return ends[0];
    }
    let s = j as f64 / segments as f64;
    std::array::from_fn(|i| ends[0][i] + s * (ends[1][i] - ends[0][i]))
}
