//! How a node's coordinates are numbered (docs/method.md §1.1): the
//! element type (Table 1) fixes the vectors per node, the vector slots
//! name them, and [`coordinate`] is the index function. Below the model
//! and its constraints, which both number coordinates so.

use std::ops::Range;

/// The two space-time elements of the paper (Table 1).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ElementType {
    /// Cubic Hermite in space (eq. 4): nodal r, r_x.
    Sac2,
    /// Quintic Hermite in space (eq. 5): nodal r, r_x, r_xx.
    Sac3,
}

impl ElementType {
    /// Vector coordinates per node (2 or 3).
    pub fn vectors_per_node(self) -> usize {
        match self {
            ElementType::Sac2 => 2,
            ElementType::Sac3 => 3,
        }
    }

    /// Scalar coordinates per node (6 or 9).
    pub fn dofs_per_node(self) -> usize {
        3 * self.vectors_per_node()
    }

    pub fn name(self) -> &'static str {
        match self {
            ElementType::Sac2 => "SAC-2",
            ElementType::Sac3 => "SAC-3",
        }
    }
}

/// Vector slot of the position r in a node's coordinates.
pub const SLOT_R: usize = 0;
/// Vector slot of the gradient r_x.
pub const SLOT_R_X: usize = 1;
/// Vector slot of the second gradient r_xx (SAC-3 only).
pub const SLOT_R_XX: usize = 2;

/// Global index of component `component` (x, y, z = 0, 1, 2) of vector
/// `slot` ([`SLOT_R`], [`SLOT_R_X`], [`SLOT_R_XX`]) of node `node`, with
/// `dpn` scalar coordinates per node: `node dpn + 3 slot + component`
/// (docs/method.md §1.1). The one place the numbering is written; every
/// index of a coordinate is computed here. An element's coordinates are
/// contiguous from its first node's, so a slot past the node's own
/// vectors counts on into the next node: element k's vector a (its own
/// order, 0..NS) is `coordinate(dpn, k, a, i)`, and `coordinate(dpn, k,
/// SLOT_R, 0)` is the start of element k's slice.
#[inline]
pub const fn coordinate(dpn: usize, node: usize, slot: usize, component: usize) -> usize {
    node * dpn + 3 * slot + component
}

/// The coordinates of node `node`: `[r, r_x(, r_xx)]`.
#[inline]
pub const fn node_range(dpn: usize, node: usize) -> Range<usize> {
    coordinate(dpn, node, SLOT_R, 0)..coordinate(dpn, node + 1, SLOT_R, 0)
}
