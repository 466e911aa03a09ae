//! A system in a sea whose waves a host sets (MoorDyn's `WaveKin 1`;
//! docs/method.md §12.1, (W2f)-(W2g)): the points where the host is
//! asked for the water's velocity and local acceleration, in MoorDyn's
//! order, and the values it sets there, held until it sets them again.
//!
//! MoorDyn asks at every line's nodes (line by line, node 0 to N), then
//! every rod's nodes, every point (fixed, coupled and free alike) and
//! every body, its ground body first (`Waves::kinematicsForAllNodes`). A
//! host written for MoorDyn sizes its arrays by that count, so stancf
//! asks at the same places in the same order: its line nodes are the
//! deck's (N segments, N + 1 nodes), then the points, then MoorDyn's
//! ground body at the origin (whose value nothing uses, as in MoorDyn).
//! Rods and bodies in such a sea are refused: the host's flow at them is
//! not taken in this version.

use super::{Line, System, SystemSimulation, Topology};
use crate::error::ModelError;
use crate::model::{coordinate, Model, SLOT_R};
use crate::water::NodeFlow;

/// Whether the line of `model` takes a host's flow at its nodes (its sea's
/// waves are a host's, [`start_still`]).
pub(crate) fn takes_host_flow(model: &Model) -> bool {
    model.water.as_ref().is_some_and(|w| w.host.is_some())
}

/// Gives every line and point in a sea whose waves a host sets still
/// water to start from (the host has set nothing yet, as in MoorDyn).
pub(super) fn start_still(lines: &mut [Line], topology: &mut Topology) {
    let hosted = |sea: &crate::water::kinematics::Sea| sea.host_waves();
    for line in lines.iter_mut() {
        let nodes = line.model.nodes();
        if let Some(water) = line.model.water.as_mut().filter(|w| hosted(&w.water.sea)) {
            water.host = Some(NodeFlow::still(nodes));
        }
    }
    for p in &mut topology.points {
        if let Some(water) = p.water.as_mut().filter(|w| hosted(&w.water.sea)) {
            water.host = Some(([0.0; 3], [0.0; 3]));
        }
    }
}

/// Refuses to step `system` in a sea whose waves a host sets where the
/// host's flow would be left out: a line with vortex-induced vibration
/// (its lift's flow), or any body or rod (MoorDyn asks at their nodes
/// too). Its static solve, which sees no host's flow, is not refused.
pub(super) fn refuse_untaken(system: &System) -> Result<(), ModelError> {
    let hosted = |l: &Line| takes_host_flow(&l.model);
    if !system.lines().iter().any(hosted) {
        return Ok(());
    }
    if let Some(i) = system
        .lines()
        .iter()
        .position(|l| hosted(l) && l.model.viv().is_some())
    {
        return Err(ModelError::invalid(
            format!("lines[{i}]"),
            "vortex-induced vibration in a sea whose waves a host sets is not taken in this \
             version (the lift's flow would leave out the host's)",
        ));
    }
    if !system.bodies().is_empty() {
        return Err(ModelError::invalid(
            "bodies[0]",
            "bodies and rods in a sea whose waves a host sets are not taken in this version: \
             the host's flow is used at the lines' nodes and the points only",
        ));
    }
    Ok(())
}

impl SystemSimulation {
    /// Whether a host sets the waves ([`crate::water::kinematics::Sea::with_host_waves`]).
    pub fn takes_host_waves(&self) -> bool {
        self.lines.iter().any(|l| takes_host_flow(l.model()))
    }

    /// How many points [`Self::host_flow_points`] names: every line's
    /// nodes, the points the system started with, the ground; 0 if no
    /// host sets the waves.
    pub fn host_flow_count(&self) -> usize {
        if !self.takes_host_waves() {
            return 0;
        }
        let nodes: usize = self.lines.iter().map(|l| l.model().nodes()).sum();
        nodes + self.points_at_start() + 1
    }

    /// Where the host is asked for the water's kinematics, now, in
    /// MoorDyn's order (module doc): every line's nodes, every point, the
    /// ground at the origin. Empty if no host sets the waves.
    pub fn host_flow_points(&self) -> Vec<[f64; 3]> {
        if !self.takes_host_waves() {
            return Vec::new();
        }
        let mut out = Vec::with_capacity(self.host_flow_count());
        for l in &self.lines {
            let (m, e) = (l.model(), &l.state().e);
            let dpn = m.dofs_per_node();
            out.extend((0..m.nodes()).map(|k| {
                let o = coordinate(dpn, k, SLOT_R, 0);
                [e[o], e[o + 1], e[o + 2]]
            }));
        }
        out.extend((0..self.points_at_start()).map(|p| self.point_state(p).0));
        out.push([0.0; 3]);
        out
    }

    /// The points the system started with: a line failure's release
    /// appends a free point of its own (docs/method.md §11.16), which
    /// MoorDyn does not add to the points its host is asked at (its count
    /// is fixed at init), nor does stancf.
    fn points_at_start(&self) -> usize {
        self.topology.points.len() - self.releases().len()
    }

    /// Sets the water's velocity `velocity` and local acceleration
    /// `acceleration` at the points of [`Self::host_flow_points`] (one
    /// each, in its order), used from the next step on until they are set
    /// again (W2f)-(W2g). Refused: no host sets the waves, a count other
    /// than the points', or a value that is not finite.
    pub fn set_host_flow(
        &mut self,
        velocity: &[[f64; 3]],
        acceleration: &[[f64; 3]],
    ) -> Result<(), ModelError> {
        if !self.takes_host_waves() {
            return Err(ModelError::invalid(
                "water",
                "the sea's waves are not a host's (MoorDyn's WaveKin 1): there is no flow \
                 to set",
            ));
        }
        let count = self.host_flow_count();
        for (name, values) in [("velocity", velocity), ("acceleration", acceleration)] {
            if values.len() != count {
                return Err(ModelError::invalid(
                    name,
                    format!(
                        "{} points given, the host's waves are asked at {count}",
                        values.len()
                    ),
                ));
            }
            if let Some(i) = values.iter().position(|v| v.iter().any(|c| !c.is_finite())) {
                return Err(ModelError::invalid(
                    format!("{name}[{i}]"),
                    format!("must be finite, got {:?}", values[i]),
                ));
            }
        }
        let mut next = 0;
        for l in &mut self.lines {
            let nodes = l.model().nodes();
            let range = next..next + nodes;
            l.set_host_flow(NodeFlow {
                velocity: velocity[range.clone()].to_vec(),
                acceleration: acceleration[range].to_vec(),
            });
            next += nodes;
        }
        let at_start = self.points_at_start();
        for (p, point) in self.topology.points.iter_mut().take(at_start).enumerate() {
            if let Some(w) = point.water.as_mut().filter(|w| w.host.is_some()) {
                w.host = Some((velocity[next + p], acceleration[next + p]));
            }
        }
        Ok(())
    }
}
