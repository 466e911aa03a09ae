//! A system in a sea whose waves a host sets (MoorDyn's `WaveKin 1`;
//! docs/method.md §12.1, (W2f)-(W2h)): the points where the host is
//! asked for the water's velocity and local acceleration, in MoorDyn's
//! order, and the values it sets there, held until it sets them again.
//!
//! MoorDyn asks at every line's nodes (line by line, node 0 to N), then
//! every rod's nodes, every point (fixed, coupled and free alike) and
//! every body, its ground body first (`Waves::kinematicsForAllNodes`). A
//! host written for MoorDyn sizes its arrays by that count, so stancf
//! asks at the same places in the same order: its line nodes are the
//! deck's (N segments, N + 1 nodes), then the rods' nodes, the points and
//! the bodies as [`HostOrder`] names them, with MoorDyn's ground body at
//! the origin (whose value nothing uses, as in MoorDyn). A body takes
//! the value at its reference point for its own drag and fluid inertia,
//! and each of its rods its nodes' values along it (W2h).

use super::host_order::{rod_node, HostOrder, HostRod};
use super::{BodyKind, Line, System, SystemSimulation, Topology};
use crate::body::BodyHostFlow;
use crate::error::ModelError;
use crate::model::{coordinate, Model, SLOT_R};
use crate::water::NodeFlow;

/// Whether the line of `model` takes a host's flow at its nodes (its sea's
/// waves are a host's, [`start_still`]).
pub(crate) fn takes_host_flow(model: &Model) -> bool {
    model.water.as_ref().is_some_and(|w| w.host.is_some())
}

/// Whether a host sets the waves: a line of `models`, or a point or body
/// of `topology`, takes its flow (the one test of it, for a system, a
/// simulation and a coupling handle).
pub(crate) fn takes_host_waves<'a>(
    mut models: impl Iterator<Item = &'a Model>,
    topology: &Topology,
) -> bool {
    models.any(takes_host_flow) || topology.takes_host_flow()
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
    for body in &mut topology.bodies {
        if let Some(water) = body.water.as_mut() {
            // Only in a host's sea (a host flow given elsewhere is dropped).
            let in_hosted_sea = water.sea.as_ref().is_some_and(|s| hosted(s));
            water.host = in_hosted_sea.then(|| BodyHostFlow::still(&water.rods));
        }
    }
}

impl System {
    /// The system with MoorDyn's order of the rods, points and bodies a
    /// host that sets the waves is asked at ([`HostOrder`]; a scenario
    /// built from a deck gives the deck's). Refused: a body, rod or point
    /// the system does not have.
    pub fn with_host_order(mut self, order: HostOrder) -> Result<Self, ModelError> {
        order.check(&self.topology)?;
        self.topology.host_order = Some(order);
        Ok(self)
    }
}

impl Topology {
    /// Whether a point or a body takes a host's flow (in a sea whose waves
    /// a host sets).
    fn takes_host_flow(&self) -> bool {
        let point = |p: &super::Point| p.water.as_ref().is_some_and(|w| w.host.is_some());
        let body = |b: &super::Body| b.water.as_ref().is_some_and(|w| w.host.is_some());
        self.points.iter().any(point) || self.bodies.iter().any(body)
    }

    /// The order a host is asked in ([`HostOrder`]): the one given, or the
    /// system's own.
    pub fn host_order(&self) -> HostOrder {
        self.host_order
            .clone()
            .unwrap_or_else(|| HostOrder::of(self))
    }
}

/// Refuses to step `system` in a sea whose waves a host sets where the
/// host's flow would be left out: a line with vortex-induced vibration
/// (its lift's flow), or a body in water without the sea (whose flow the
/// host's joins). Its static solve, which sees no host's flow, is not
/// refused.
pub(super) fn refuse_untaken(system: &System) -> Result<(), ModelError> {
    let hosted = |l: &Line| takes_host_flow(&l.model);
    if !takes_host_waves(system.lines().iter().map(|l| &l.model), system) {
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
    if let Some(b) = system.bodies().iter().position(|b| {
        b.kind != BodyKind::Fixed
            && b.water
                .as_ref()
                .is_some_and(|w| w.density > 0.0 && w.host.is_none())
    }) {
        return Err(ModelError::invalid(
            format!("bodies[{b}].water"),
            "the body is in water but not in the sea whose waves a host sets: the host's \
             flow would not reach it (give the body the sea)",
        ));
    }
    Ok(())
}

impl SystemSimulation {
    /// Whether a host sets the waves ([`crate::water::kinematics::Sea::with_host_waves`]):
    /// a line, point or body takes the host's flow.
    pub fn takes_host_waves(&self) -> bool {
        takes_host_waves(self.lines.iter().map(|l| l.model()), &self.topology)
    }

    /// How many points [`Self::host_flow_points`] names: every line's
    /// nodes, then the rods' nodes, the points, the ground and the bodies
    /// of the system's [`HostOrder`]; 0 if no host sets the waves.
    pub fn host_flow_count(&self) -> usize {
        if !self.takes_host_waves() {
            return 0;
        }
        let nodes: usize = self.lines.iter().map(|l| l.model().nodes()).sum();
        nodes + self.host_order_now().count(&self.topology)
    }

    /// [`Topology::host_order`], its points no more than the system
    /// started with: a line failure's release appends a free point of its
    /// own (docs/method.md §11.16), which MoorDyn does not add to the
    /// points its host is asked at (its count is fixed at init), nor does
    /// stancf.
    fn host_order_now(&self) -> HostOrder {
        let mut order = self.topology.host_order();
        let at_start = self.topology.points.len() - self.releases().len();
        order.points.retain(|&p| p < at_start);
        order
    }

    /// Where the host is asked for the water's kinematics, now, in
    /// MoorDyn's order (module doc), a coupled body where the system
    /// holds it (its pose at the start; see
    /// [`Self::host_flow_points_with`]). Empty if no host sets the waves.
    pub fn host_flow_points(&self) -> Vec<[f64; 3]> {
        self.host_flow_points_with(|_| None)
    }

    /// [`Self::host_flow_points`] with a coupled body b's pose (its
    /// reference point and rotation) from `coupled(b)`, where a host
    /// moves it.
    pub fn host_flow_points_with(
        &self,
        coupled: impl Fn(usize) -> Option<([f64; 3], [[f64; 3]; 3])>,
    ) -> Vec<[f64; 3]> {
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
        let order = self.host_order_now();
        let body_point = |b: usize, local: [f64; 3]| -> [f64; 3] {
            if let Some(free) = self.free_body(b) {
                return free.point(local);
            }
            let body = &self.topology.bodies[b];
            match coupled(b).filter(|_| body.kind == BodyKind::Coupled) {
                Some((position, rotation)) => crate::body::pose::point(position, &rotation, local),
                None => body.point(local),
            }
        };
        for (k, rod) in order.rods.iter().enumerate() {
            let nodes = order.rod_nodes(&self.topology, k);
            let ends = match *rod {
                HostRod::InBody { body, rod } => {
                    let water = self.topology.bodies[body].water.as_ref();
                    let r = &water.expect("checked: a rod in the body's water").rods[rod];
                    [body_point(body, r.end_a), body_point(body, r.end_b)]
                }
                HostRod::Fixed { ends, .. } => ends,
                HostRod::AtPoint(p) => [self.point_state(p).0; 2],
                HostRod::OnBody { body, local } => [body_point(body, local); 2],
            };
            out.extend((0..nodes).map(|j| rod_node(&ends, nodes - 1, j)));
        }
        out.extend(order.points.iter().map(|&p| self.point_state(p).0));
        out.push([0.0; 3]);
        out.extend(order.bodies.iter().map(|&b| body_point(b, [0.0; 3])));
        out
    }

    /// Sets the water's velocity `velocity` and local acceleration
    /// `acceleration` at the points of [`Self::host_flow_points`] (one
    /// each, in its order), used from the next step on until they are set
    /// again (W2f)-(W2h). Refused: no host sets the waves, a count other
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
        let mut take = |n: usize| {
            let range = next..next + n;
            next += n;
            NodeFlow {
                velocity: velocity[range.clone()].to_vec(),
                acceleration: acceleration[range].to_vec(),
            }
        };
        for l in &mut self.lines {
            let nodes = l.model().nodes();
            l.set_host_flow(take(nodes));
        }
        let order = self.host_order_now();
        let mut bodies: Vec<Option<BodyHostFlow>> = self
            .topology
            .bodies
            .iter()
            .map(|b| {
                let water = b.water.as_ref().filter(|w| w.host.is_some());
                water.map(|w| BodyHostFlow::still(&w.rods))
            })
            .collect();
        for (k, rod) in order.rods.iter().enumerate() {
            let at_nodes = take(order.rod_nodes(&self.topology, k));
            if let HostRod::InBody { body, rod } = *rod {
                if let Some(host) = bodies[body].as_mut() {
                    host.rods[rod] = at_nodes;
                }
            }
        }
        let points = take(order.points.len());
        for (j, &p) in order.points.iter().enumerate() {
            let point = &mut self.topology.points[p];
            if let Some(w) = point.water.as_mut().filter(|w| w.host.is_some()) {
                w.host = Some((points.velocity[j], points.acceleration[j]));
            }
        }
        let _ground = take(1);
        let references = take(order.bodies.len());
        for (j, &b) in order.bodies.iter().enumerate() {
            if let Some(host) = bodies[b].as_mut() {
                host.reference = (references.velocity[j], references.acceleration[j]);
            }
        }
        for (b, host) in bodies.into_iter().enumerate() {
            let Some(host) = host else { continue };
            if let Some(step) = self.bodies.iter_mut().find(|s| s.index == b) {
                step.body.set_host_flow(host.clone())?;
            }
            if let Some(w) = self.topology.bodies[b].water.as_mut() {
                w.host = Some(host);
            }
        }
        Ok(())
    }
}
