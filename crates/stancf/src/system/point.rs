//! A point of a system (docs/method.md §11.1): what holds it, its mass,
//! load, water and damping.

use crate::motion::CoupledMotion;

/// What holds a point.
#[derive(Clone, Debug, PartialEq)]
pub enum PointKind {
    /// Held at its position (an anchor).
    Fixed,
    /// Three translational unknowns (a shackle, a clump weight, a buoy).
    Free,
    /// Moved along a given motion (a fairlead): an oscillation about its
    /// position (M30) or a table (M39).
    Coupled(CoupledMotion),
    /// Fixed on body `body` at `local` (body axes, from its reference
    /// point; docs/method.md §15.7). On a fixed body it becomes a fixed
    /// point; on a free body it moves with the body (B11).
    Body { body: usize, local: [f64; 3] },
}

/// A point of a system.
#[derive(Clone, Debug, PartialEq)]
pub struct Point {
    pub kind: PointKind,
    /// Position at t = 0 (m).
    pub position: [f64; 3],
    /// Mass (kg) of a free point (its weight m g acts on it).
    pub mass: f64,
    /// A constant force on a free point (N), e.g. a buoy's net lift.
    pub force: [f64; 3],
    /// The water on a free point: buoyancy, drag, the fluid's inertia and
    /// the added mass (docs/method.md §12.6); None in air.
    pub water: Option<crate::water::PointInWater>,
    /// Damping of a free point along the global axes (MoorDyn-F's
    /// EXTERNAL LOADS, docs/method.md §15.21, (B42)).
    pub damping: crate::damping::AxisDamping,
}

impl Point {
    pub fn fixed(position: [f64; 3]) -> Self {
        Point {
            kind: PointKind::Fixed,
            position,
            mass: 0.0,
            force: [0.0; 3],
            water: None,
            damping: Default::default(),
        }
    }

    pub fn free(position: [f64; 3], mass: f64) -> Self {
        Point {
            kind: PointKind::Free,
            position,
            mass,
            force: [0.0; 3],
            water: None,
            damping: Default::default(),
        }
    }

    /// A coupled point at `position` (its position at t = 0) moving
    /// along `motion` (an [`crate::constraints::Oscillation`], a
    /// [`crate::motion::MotionTable`] or a [`CoupledMotion`]).
    pub fn coupled(position: [f64; 3], motion: impl Into<CoupledMotion>) -> Self {
        Point {
            kind: PointKind::Coupled(motion.into()),
            position,
            mass: 0.0,
            force: [0.0; 3],
            water: None,
            damping: Default::default(),
        }
    }

    /// A point on body `body` at `local` (body axes, from the body's
    /// reference point); its position is set from the body's by
    /// [`System::with_bodies`].
    pub fn on_body(body: usize, local: [f64; 3]) -> Self {
        Point {
            kind: PointKind::Body { body, local },
            position: [0.0; 3],
            mass: 0.0,
            force: [0.0; 3],
            water: None,
            damping: Default::default(),
        }
    }

    pub fn is_free(&self) -> bool {
        self.kind == PointKind::Free
    }

    /// The free body this point is on, if any.
    pub fn body(&self) -> Option<usize> {
        match self.kind {
            PointKind::Body { body, .. } => Some(body),
            _ => None,
        }
    }

    /// Whether the point's position is an unknown of the step: a free
    /// point, or a point on a free body (whose position follows the
    /// body's unknowns, §15.7).
    pub fn is_unknown(&self) -> bool {
        self.is_free() || self.body().is_some()
    }

    /// Position and velocity of a fixed or coupled point at time t (a
    /// free point's are unknowns: this gives its initial position, at
    /// rest).
    pub fn state_at(&self, t: f64) -> ([f64; 3], [f64; 3]) {
        match &self.kind {
            PointKind::Coupled(motion) => motion.state_at(&self.position, t),
            _ => (self.position, [0.0; 3]),
        }
    }
}
