//! The spatial quadrature of the strain energy: the default Gauss points
//! per element type (docs/method.md §3.3), the fewest that keep every
//! element's stiffness at full rank, and the warnings when fewer are asked
//! for (docs/method.md §3.4, (M15)).

use super::{ElementType, Model};
use crate::element::{Measures, SpaceRules};
use crate::error::ModelError;
use crate::quadrature::GaussRule;

/// Gauss points per element in space for the axial and the bending
/// energy (the paper uses one rule for both).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct SpacePoints {
    pub axial: usize,
    pub bending: usize,
}

/// How the strain energy is computed.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct ModelOptions {
    pub measures: Measures,
    /// Spatial quadrature; `None` takes the element's default
    /// ([`ElementType::default_space_points`]).
    pub space_points: Option<SpacePoints>,
}

impl ElementType {
    /// Gauss points in space (axial, bending) used when none are given:
    /// the paper's choices, 3 for SAC-2 ("3 x 3") and 5 for SAC-3
    /// ("5 x 3", Table 5); docs/method.md §3.3.
    pub fn default_space_points(self) -> SpacePoints {
        match self {
            ElementType::Sac2 => SpacePoints {
                axial: 3,
                bending: 3,
            },
            ElementType::Sac3 => SpacePoints {
                axial: 5,
                bending: 5,
            },
        }
    }

    /// The fewest Gauss points that leave no spurious zero-energy mode in
    /// any element (continuity can suppress such a mode in a mesh, so
    /// fewer points are not always singular).
    /// With NS shape functions the linearized axial strain u' is a
    /// polynomial of degree NS - 2 in each element and the curvature
    /// (r_xx) one of degree NS - 3; n points annihilate a nonzero
    /// polynomial of degree d only if n <= d, so the rank needs NS - 1
    /// axial and NS - 2 bending points (SAC-2: 3 and 2; SAC-3: 5 and 4;
    /// docs/method.md §3.4, (M15)).
    pub fn minimal_space_points(self) -> SpacePoints {
        let ns = 2 * self.vectors_per_node();
        SpacePoints {
            axial: ns - 1,
            bending: ns - 2,
        }
    }
}

/// The Gauss rules for `points`.
pub(super) fn space_rules(points: SpacePoints) -> Result<SpaceRules, ModelError> {
    Ok(SpaceRules {
        axial: GaussRule::new(points.axial)
            .map_err(|e| ModelError::invalid("analysis.quadrature", e.message))?,
        bending: GaussRule::new(points.bending)
            .map_err(|e| ModelError::invalid("analysis.quadrature", e.message))?,
    })
}

impl Model {
    /// The spatial quadrature in use.
    pub fn space_points(&self) -> SpacePoints {
        self.options
            .space_points
            .unwrap_or_else(|| self.cable.element_type.default_space_points())
    }

    /// Warnings about the model that do not make it invalid: a spatial
    /// quadrature too coarse to give every element's stiffness full rank
    /// (the mesh may then have spurious zero-energy modes that drift
    /// without bound; docs/method.md §3.4, (M15)).
    pub fn warnings(&self) -> Vec<String> {
        let p = self.space_points();
        let min = self.cable.element_type.minimal_space_points();
        let mut w = Vec::new();
        let name = self.cable.element_type.name();
        if p.axial < min.axial {
            w.push(format!(
                "{} Gauss points for the axial energy of {name} may leave spurious zero-energy modes \
                 ({} or more avoid them)",
                p.axial, min.axial
            ));
        }
        if p.bending < min.bending {
            w.push(format!(
                "{} Gauss points for the bending energy of {name} may leave spurious zero-energy modes \
                 ({} or more avoid them)",
                p.bending, min.bending
            ));
        }
        w
    }
}
