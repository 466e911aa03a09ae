//! The coordinate index function and what is built on it (docs/method.md
//! §1.1): vector slots, [`coordinate`], node ranges, the length scale of
//! each coordinate kind, and the selection of the out-of-plane coordinates
//! for the planar reduction (docs/method.md §6.7).

use super::{Load, Model, State};
use crate::numbering::{coordinate, node_range, SLOT_R};
use std::ops::Range;

impl Model {
    /// Index of the first coordinate of node j.
    pub fn node_offset(&self, node: usize) -> usize {
        self.coordinate(node, SLOT_R, 0)
    }

    /// Global index of component `component` of vector `slot` of node
    /// `node` (see [`coordinate`]).
    #[inline]
    pub fn coordinate(&self, node: usize, slot: usize, component: usize) -> usize {
        coordinate(self.dofs_per_node(), node, slot, component)
    }

    /// The coordinates of node j (see [`node_range`]).
    #[inline]
    pub fn node_range(&self, node: usize) -> Range<usize> {
        node_range(self.dofs_per_node(), node)
    }

    /// The out-of-plane coordinates (the z components of r, r_x, r_xx at
    /// every node) if the motion from `state` stays in the plane z = z0:
    /// every node at z0 with r_x, r_xx and all rates in the plane; gravity,
    /// point forces and the fluid velocity of drag in the plane; end
    /// moments about z; constraints that do not move out of it. Then, by
    /// the mirror symmetry about the plane, the z equations hold for
    /// z = z0 and zero slopes at every step, and their Jacobian does not
    /// couple them to the in-plane ones at such states (every coupling
    /// term carries an out-of-plane component), so eliminating them gives
    /// the same motion with a third fewer unknowns (docs/method.md §6.7).
    /// `None` otherwise.
    pub fn planar_coordinates(&self, state: &State) -> Option<Vec<usize>> {
        let dpn = self.dofs_per_node();
        let n = self.dofs();
        if state.e.len() != n || state.v.len() != n || !self.constraints.directions.is_empty() {
            // A direction hold is not split by coordinates (§6.10).
            return None;
        }
        let z0 = state.e[2];
        let mut out = Vec::with_capacity(n / 3);
        for g in (2..n).step_by(3) {
            let value = if g % dpn == 2 { z0 } else { 0.0 };
            if state.e[g] != value || state.v[g] != 0.0 {
                return None;
            }
            if let Some(m) = &self.constraints.motion[g] {
                if !m.is_still() || m.value(0.0) != value {
                    return None;
                }
            }
            out.push(g);
        }
        let in_plane = self.loads.iter().all(|l| match l {
            Load::Gravity { acceleration } => acceleration[2] == 0.0,
            Load::PointForce { force, .. } => force[2] == 0.0,
            Load::EndMoment { moment, .. } => moment[0] == 0.0 && moment[1] == 0.0,
            Load::AirDrag(d) => d.fluid_velocity[2] == 0.0,
            Load::Seabed(c) => matches!(
                c.seabed.surface,
                crate::water::BedSurface::Plane { normal, .. } if normal[2] == 0.0
            ),
            // Buoyancy acts along z, the plane's normal.
            Load::Water(_) => false,
        });
        in_plane.then_some(out)
    }

    /// Holds the out-of-plane coordinates at their values when the motion
    /// from `state` is planar (see [`Self::planar_coordinates`]); returns
    /// whether it did.
    pub fn reduce_to_plane(&mut self, state: &State) -> bool {
        match self.planar_coordinates(state) {
            Some(dofs) => {
                for g in dofs {
                    self.constraints.hold_inactive(g, state.e[g]);
                }
                self.constraints.in_plane = true;
                true
            }
            None => false,
        }
    }

    /// Length scale of each coordinate kind of node j: a change of r by
    /// 1 m, of r_x by 1/l or of r_xx by 1/l^2 moves the centre line by
    /// about 1 m inside an element of length l, with l the longer of the
    /// node's elements (the one it moves more; all are `L / n` on a
    /// uniform mesh).
    pub fn coordinate_length_scale(&self, node: usize, dof_in_node: usize) -> f64 {
        let before = node.checked_sub(1).map_or(0.0, |k| self.element_length(k));
        let after = if node < self.cable.elements {
            self.element_length(node)
        } else {
            0.0
        };
        let l = before.max(after);
        match dof_in_node / 3 {
            0 => 1.0,
            1 => l,
            _ => l * l,
        }
    }
}
