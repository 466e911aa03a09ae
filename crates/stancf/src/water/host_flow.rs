//! The water's kinematics a host sets at the nodes (docs/method.md §12.1,
//! (W2f)-(W2g)): MoorDyn's `WaveKin 1`, where the coupling code computes
//! the waves (its own wave model, a CFD field, a measured record) at the
//! points MoorDyn names and hands over the water's velocity and local
//! acceleration there (MoorDyn's `ExternalWaveKinSet`).
//!
//! The values at a line's nodes are held from the call that sets them to
//! the next one, as MoorDyn holds them over its internal steps, and are
//! interpolated linearly in the element's axial coordinate between its
//! two end nodes to the points of the axial rule:
//!
//! ```text
//!   u(xi) = (1 - xi) u_k + xi u_k+1,   a(xi) = (1 - xi) a_k + xi a_k+1     (W2f)
//! ```
//!
//! added to the sea's own flow there (its current; a sea whose waves the
//! host sets has no waves of its own), as MoorDyn adds its current to the
//! external waves:
//!
//! ```text
//!   u_f = u_sea(r, t) + u(xi),   a_f = a_sea(r, t) + a(xi)                 (W2g)
//! ```
//!
//! The host's values belong to the material points of the line (its
//! nodes), not to places in space: they do not depend on r, so they add
//! nothing to the flow's gradients G_u, G_a of (W21)-(W22), and the
//! step's Jacobian stays exact. The free surface stays at z = 0 and the
//! waves' dynamic pressure zero, as in MoorDyn, which takes neither from
//! the host.

/// The water's velocity and local acceleration a host has set at each
/// node of a line (zero until it sets them, as in MoorDyn).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct NodeFlow {
    /// u_k (m/s) at node k.
    pub velocity: Vec<[f64; 3]>,
    /// a_k (m/s^2) at node k.
    pub acceleration: Vec<[f64; 3]>,
}

impl NodeFlow {
    /// Still water at `nodes` nodes.
    pub fn still(nodes: usize) -> NodeFlow {
        NodeFlow {
            velocity: vec![[0.0; 3]; nodes],
            acceleration: vec![[0.0; 3]; nodes],
        }
    }

    /// The flow at element k's two end nodes, k and k + 1.
    pub fn element(&self, k: usize) -> ElementFlow {
        ElementFlow {
            velocity: [self.velocity[k], self.velocity[k + 1]],
            acceleration: [self.acceleration[k], self.acceleration[k + 1]],
        }
    }
}

/// The host's flow at an element's two end nodes.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct ElementFlow {
    pub velocity: [[f64; 3]; 2],
    pub acceleration: [[f64; 3]; 2],
}

/// The host's flow at a point of an element: velocity and local
/// acceleration.
pub type FlowAt = ([f64; 3], [f64; 3]);

impl ElementFlow {
    /// (W2f): the flow at `xi` (0 at the element's first node, 1 at its
    /// second).
    pub fn at(&self, xi: f64) -> FlowAt {
        let lerp = |v: &[[f64; 3]; 2]| std::array::from_fn(|i| (1.0 - xi) * v[0][i] + xi * v[1][i]);
        (lerp(&self.velocity), lerp(&self.acceleration))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_flow_between_two_nodes_is_theirs_at_the_ends_and_linear_between() {
        let flow = NodeFlow {
            velocity: vec![[1.0, 2.0, 3.0], [3.0, -2.0, 0.0]],
            acceleration: vec![[0.0, 0.5, 0.0], [1.0, 0.5, -1.0]],
        };
        let e = flow.element(0);
        assert_eq!(e.at(0.0), ([1.0, 2.0, 3.0], [0.0, 0.5, 0.0]));
        assert_eq!(e.at(1.0), ([3.0, -2.0, 0.0], [1.0, 0.5, -1.0]));
        assert_eq!(e.at(0.25), ([1.5, 1.0, 2.25], [0.25, 0.5, -0.25]));
    }
}
