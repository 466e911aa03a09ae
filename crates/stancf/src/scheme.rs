//! The time scheme, in one place: what differs between the P2 step
//! (docs/method.md §4, eq. 22) and the Galerkin step (§5, and §11.10 for a
//! system) in the layout of the unknowns, the step and the end impulses.
//! The integrator, a system's simulation and the checks ask the scheme
//! here instead of testing which one it is.

use crate::assembly::Scheme;

/// Which equations a step solves (docs/method.md §4.2-4.3 for P2, §5 for
/// the Galerkin step).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum TimeScheme {
    /// Hamilton's law with the P2 formula, eq. (22): conditionally stable,
    /// fourth order.
    #[default]
    P2,
    /// The Galerkin variational integrator on the cubic slab: with 3 Gauss
    /// points in time the 3-stage Gauss-Legendre method, unconditionally
    /// stable, sixth order, symplectic; one layer per step.
    Galerkin,
}

impl TimeScheme {
    /// The layout a step of `layers` element layers in time assembles
    /// (docs/method.md §4.3, §5.1): P2 solves the layers' end nodes, the
    /// Galerkin step all four variations of one slab.
    pub fn layout(self, layers: usize) -> Scheme {
        match self {
            TimeScheme::P2 => Scheme::P2 { layers },
            TimeScheme::Galerkin => Scheme::Galerkin,
        }
    }

    /// The time slots of unknowns per step (docs/method.md §4.3, §5.1):
    /// e and v at each of the `layers` end nodes (P2), or e_b, v_b and the
    /// start's rates (Galerkin, one layer).
    pub fn slots(self, layers: usize) -> usize {
        match self {
            TimeScheme::P2 => 2 * layers,
            TimeScheme::Galerkin => 3,
        }
    }

    /// Whether the step carries the momentum p = M v from step to step
    /// (docs/method.md §5.1): the Galerkin step's start equation is
    /// p_a = -dA/de_a, which needs the constrained mass's factors to turn
    /// the end momentum into v_b, and whose end impulses hold
    /// p_b - dA/de_b. The P2 step solves for v directly.
    pub fn carries_momentum(self) -> bool {
        self == TimeScheme::Galerkin
    }

    /// Whether a step may have more than one element layer in time: P2
    /// yes (docs/method.md §4.3), the Galerkin step is one slab (§5.4).
    pub fn layers_allowed(self) -> bool {
        self == TimeScheme::P2
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn p2_solves_its_layers_and_galerkin_one_slab_with_momentum() {
        assert_eq!(TimeScheme::P2.layout(3), Scheme::P2 { layers: 3 });
        assert_eq!(TimeScheme::P2.slots(3), 6);
        assert!(!TimeScheme::P2.carries_momentum());
        assert_eq!(TimeScheme::Galerkin.layout(1), Scheme::Galerkin);
        assert_eq!(TimeScheme::Galerkin.slots(1), 3);
        assert!(TimeScheme::Galerkin.carries_momentum());
        assert!(!TimeScheme::Galerkin.layers_allowed());
    }
}
