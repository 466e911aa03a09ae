//! The straight reference cable and its element type (docs/method.md
//! §1.1-§1.3): SAC-2 (cubic Hermite, nodal r, r_x) or SAC-3 (quintic
//! Hermite, nodal r, r_x, r_xx), and its mesh grading (§1.6).

use super::Grading;
use crate::numbering::ElementType;

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
