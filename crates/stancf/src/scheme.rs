//! The time scheme, in one place: what differs between the P2 step
//! (docs/method.md §4, eq. 22), the Galerkin step (§5, and §11.10 for a
//! system) and a static solve (§6.8) in the layout of the unknowns, the
//! step, the assembly and the end impulses. The integrator, the assembly,
//! a system's simulation and the checks ask the scheme here instead of
//! testing which one it is.

/// Position (e) or velocity (v) coordinates of a time node.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Kind {
    Position,
    Velocity,
}

/// (time node, kind) of each slot of a node's unknowns or rows.
pub type Slots = Vec<(usize, Kind)>;

/// What is solved for: the equations a step (or a static solve)
/// assembles. Outside this file the assembly asks the predicates below,
/// never which variant it is.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Scheme {
    /// A P2 step with `layers` element layers in time.
    P2 { layers: usize },
    /// A Galerkin step (all four variations of the slab action).
    Galerkin,
    /// A static solve.
    Static,
}

impl Scheme {
    /// Element layers per step: P2's `layers` (docs/method.md §4.3), the
    /// Galerkin step's one slab (§5.4), none in a static solve (§6.8:
    /// one time node, the time-invariant slab).
    pub fn layers(self) -> usize {
        match self {
            Scheme::P2 { layers } => layers,
            Scheme::Galerkin => 1,
            Scheme::Static => 0,
        }
    }

    /// The unknown slots and the row slots, (time node, kind) each
    /// (docs/method.md §4.3, §5.1, §6.8): P2 solves e_i, v_i at the layers'
    /// end nodes i = 1..L from the rows dA/de_0, both variations at the
    /// interior nodes and dA/de_L (eq. 22); the Galerkin step solves w_a,
    /// e_b, w_b from dA/de_a, dA/dw_a, dA/dw_b (M22); a static solve e
    /// from dU/de - f (M25).
    pub fn slots(self) -> (Slots, Slots) {
        match self {
            Scheme::P2 { layers } => {
                let u: Slots = (1..=layers)
                    .flat_map(|i| [(i, Kind::Position), (i, Kind::Velocity)])
                    .collect();
                let mut r = vec![(0, Kind::Position)];
                for i in 1..layers {
                    r.push((i, Kind::Position));
                    r.push((i, Kind::Velocity));
                }
                r.push((layers, Kind::Position));
                (u, r)
            }
            Scheme::Galerkin => (
                vec![
                    (0, Kind::Velocity),
                    (1, Kind::Position),
                    (1, Kind::Velocity),
                ],
                vec![
                    (0, Kind::Position),
                    (0, Kind::Velocity),
                    (1, Kind::Velocity),
                ],
            ),
            Scheme::Static => (vec![(0, Kind::Position)], vec![(0, Kind::Position)]),
        }
    }

    /// Whether this is a static solve, the time-invariant slab
    /// (docs/method.md §6.8): the elements' and points' rows are the
    /// equilibrium dU/de - f (M25), not the variations of the slab action
    /// (§4.2 for P2, §5.1 for Galerkin).
    pub fn is_static(self) -> bool {
        self == Scheme::Static
    }

    /// Whether a step starts from known values at its input time node
    /// (docs/method.md §4.3: P2's e_a, v_a; §5.1: Galerkin's e_a, its
    /// rate w_a an unknown where free); a static solve has no start (§6.8).
    pub fn has_known_start(self) -> bool {
        !self.is_static()
    }

    /// Whether the rows carry inertia, the momentum terms M v_a of the
    /// input row (docs/method.md §4.3, §5.1: p_a) and P2's -M v_L of the
    /// output row; a static solve has none (§6.8, T = 0).
    pub fn has_inertia(self) -> bool {
        !self.is_static()
    }

    /// Whether the nodal loads (point forces, end moments) enter as their
    /// work over each layer of the slab (docs/method.md §2.6-2.7, §4.2),
    /// rather than as minus the force in the static rows (§6.8, (M7)).
    pub fn loads_as_work(self) -> bool {
        !self.is_static()
    }

    /// The sign of a multiplier in the rows it frees (docs/method.md
    /// §6.3, §6.5): + in a step's rows, which are generalized impulses
    /// (§4.3, §5.1), - in the static rows dU/de - f (§6.8), so that a
    /// multiplier is the reaction on the cable either way.
    pub fn multiplier_sign(self) -> f64 {
        if self.is_static() {
            -1.0
        } else {
            1.0
        }
    }

    /// Whether the variation at the end position, dA/de_b (time node 1,
    /// [`Kind::Position`]), is no row but the end momentum p_b = dA/de_b,
    /// gathered as the step's end impulse after convergence
    /// (docs/method.md §5.1, (M22): the Galerkin step). P2's end position
    /// is an unknown whose row is dA/de_L - M v_L (§4.3).
    pub fn end_variation_is_momentum(self) -> bool {
        self == Scheme::Galerkin
    }

    /// Whether the output row holds the end momentum, dA/de_L - M v_L
    /// (docs/method.md §4.3, eq. 22: P2, which solves for v_L); the
    /// Galerkin step computes p_b = dA/de_b after convergence instead
    /// (§5.1), and a static solve has no inertia (§6.8).
    pub fn end_row_holds_momentum(self) -> bool {
        matches!(self, Scheme::P2 { .. })
    }
}

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

    /// Whether the step is stable only below a step length: P2 yes
    /// (docs/method.md §4.5-4.6, its stable step), the Galerkin step is
    /// unconditionally stable (§5.2).
    pub fn conditionally_stable(self) -> bool {
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
        assert!(TimeScheme::P2.conditionally_stable());
        assert!(!TimeScheme::Galerkin.conditionally_stable());
    }

    #[test]
    fn the_predicates_say_what_each_scheme_assembles() {
        let (p2, galerkin, statics) = (Scheme::P2 { layers: 2 }, Scheme::Galerkin, Scheme::Static);
        assert_eq!(
            [p2.layers(), galerkin.layers(), statics.layers()],
            [2, 1, 0]
        );
        for s in [p2, galerkin] {
            assert!(!s.is_static() && s.has_known_start() && s.has_inertia());
            assert!(s.loads_as_work());
            assert_eq!(s.multiplier_sign(), 1.0);
        }
        assert!(statics.is_static() && !statics.has_known_start() && !statics.has_inertia());
        assert!(!statics.loads_as_work());
        assert_eq!(statics.multiplier_sign(), -1.0);
        assert!(galerkin.end_variation_is_momentum());
        assert!(!p2.end_variation_is_momentum() && !statics.end_variation_is_momentum());
        assert!(p2.end_row_holds_momentum());
        assert!(!galerkin.end_row_holds_momentum() && !statics.end_row_holds_momentum());
        // P2's output row is dA/de_L, an unknown e_L; Galerkin's e_b is an
        // unknown without a row of its own (its variation is p_b).
        let (u, r) = p2.slots();
        assert_eq!(u.len(), 4);
        assert_eq!(r.last(), Some(&(2, Kind::Position)));
        let (u, r) = galerkin.slots();
        assert!(u.contains(&(1, Kind::Position)) && !r.contains(&(1, Kind::Position)));
        assert_eq!(
            statics.slots(),
            (vec![(0, Kind::Position)], vec![(0, Kind::Position)])
        );
    }
}
