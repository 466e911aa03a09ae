//! The straight reference cable and its element type (docs/method.md
//! §1.1-§1.3): SAC-2 (cubic Hermite, nodal r, r_x) or SAC-3 (quintic
//! Hermite, nodal r, r_x, r_xx), and its mesh grading (§1.6).

use super::Grading;

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

/// A straight cable in its stress-free reference state.
#[derive(Clone, Debug, PartialEq)]
pub struct Cable {
    pub length: f64,
    pub elements: usize,
    pub element_type: ElementType,
    /// Position of end A (x = 0).
    pub origin: [f64; 3],
    /// Unit tangent of the reference shape (normalized on construction).
    pub direction: [f64; 3],
    /// How the elements divide the length (uniform unless given;
    /// docs/method.md §1.6).
    pub grading: Grading,
}

impl Cable {
    /// A cable along +x from the origin.
    pub fn straight(length: f64, elements: usize, element_type: ElementType) -> Self {
        Cable {
            length,
            elements,
            element_type,
            origin: [0.0; 3],
            direction: [1.0, 0.0, 0.0],
            grading: Grading::Uniform,
        }
    }

    pub fn with_origin(mut self, origin: [f64; 3]) -> Self {
        self.origin = origin;
        self
    }

    pub fn with_direction(mut self, direction: [f64; 3]) -> Self {
        self.direction = direction;
        self
    }

    /// The cable with its elements graded by `grading` (docs/method.md
    /// §1.6).
    pub fn with_grading(mut self, grading: Grading) -> Self {
        self.grading = grading;
        self
    }
}
