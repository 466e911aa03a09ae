//! What a [`CoupledSystem`] reads out at its current time: a point's
//! position, velocity and force, and a line's nodes, tensions and
//! curvatures (docs/interface.md, "Coupling").

use super::{CoupledSystem, PointReading};
use crate::model::{coordinate, SLOT_R};
use crate::observe::{cable_points, node_bending};

impl CoupledSystem {
    /// Point p (in the system's order) at the current time: its position
    /// and velocity (a coupled point's on its interval's motion, a free
    /// point's from the solve) and the net force of its lines on it (the
    /// mean over the last step, as the coupling arrays'). None before
    /// [`Self::initialize`] or for a point that does not exist.
    pub fn point(&self, p: usize) -> Option<PointReading> {
        let sim = self.simulation()?;
        if p >= self.system.points().len() {
            return None;
        }
        let (position, velocity) = sim.point_state(p);
        Some(PointReading {
            position,
            velocity,
            force: sim.point_force(p),
        })
    }

    /// Positions of line i's nodes (m).
    pub fn line_nodes(&self, line: usize) -> Option<Vec<[f64; 3]>> {
        self.line_node_coordinates(line, false)
    }

    /// Velocities of line i's nodes (m/s).
    pub fn line_velocities(&self, line: usize) -> Option<Vec<[f64; 3]>> {
        self.line_node_coordinates(line, true)
    }

    /// The axial force at line i's nodes (N; EA eps, or a nonlinear or
    /// viscoelastic line's law's, docs/method.md §2.2a, §2.11; the mean of the two
    /// elements' values at a shared node, docs/method.md §1.2).
    pub fn line_tensions(&self, line: usize) -> Option<Vec<f64>> {
        let l = self.simulation()?.lines().get(line)?;
        let area = l.model().material.area;
        Some(
            cable_points(l.model(), l.state(), 2)
                .iter()
                .map(|p| p.axial_stress * area)
                .collect(),
        )
    }

    /// The curvature at line i's nodes (1/m).
    pub fn line_curvatures(&self, line: usize) -> Option<Vec<f64>> {
        let l = self.simulation()?.lines().get(line)?;
        Some(
            node_bending(l.model(), l.state())
                .iter()
                .map(|b| b.curvature)
                .collect(),
        )
    }

    fn line_node_coordinates(&self, line: usize, rates: bool) -> Option<Vec<[f64; 3]>> {
        let l = self.simulation()?.lines().get(line)?;
        let s = l.state();
        let values = if rates { &s.v } else { &s.e };
        let dpn = l.model().dofs_per_node();
        Some(
            (0..l.model().nodes())
                .map(|j| {
                    let o = coordinate(dpn, j, SLOT_R, 0);
                    [values[o], values[o + 1], values[o + 2]]
                })
                .collect(),
        )
    }
}
