//! What a rod of a system is (docs/interface.md, "Rods"): what holds it,
//! its type's numbers, its ends and the points at them; a free rod's
//! body. Read from a deck in `rods.rs`, from TOML in `rod_toml.rs`.

use super::bodies::{BodyType, SystemBody};
use stancf::body::Rod;

/// A rod type's numbers (MoorDyn's ROD TYPES row; `[[rod_types]]`).
#[derive(Clone, Debug, PartialEq)]
pub struct RodTypeValues {
    pub name: String,
    pub diameter: f64,
    pub mass_per_length: f64,
    pub cd: f64,
    pub ca: f64,
    pub cd_end: f64,
    pub ca_end: f64,
}

impl RodTypeValues {
    pub fn of_deck(t: &crate::moordyn::RodType) -> Self {
        RodTypeValues {
            name: t.name.clone(),
            diameter: t.diameter,
            mass_per_length: t.mass_per_length,
            cd: t.cd,
            ca: t.ca,
            cd_end: t.cd_end,
            ca_end: t.ca_end,
        }
    }
}

/// What holds a rod of a system.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum RodHolder {
    /// Held where it is (its ends global).
    Fixed,
    /// Free: body `body` (its index in [`SystemScenario::bodies`]) is the
    /// rod.
    Free { body: usize },
    /// Fixed in body `body` (its index).
    Body { body: usize },
    /// Pinned at its end A: body `body` (its index) is the rod, as a free
    /// rod's, its end A held at the point at that end (the rod's
    /// `points[0]`, always there), turning freely about it: a fixed point,
    /// or with `host` the point of a free body (its index) at its
    /// coordinates (from its reference point, its axes), a joint.
    /// With `coupled` (and no host) the point is a coupled one, moved by
    /// the host (MoorDyn's CoupledPinned rod; TOML "coupled_pinned").
    Pinned {
        body: usize,
        host: Option<(usize, [f64; 3])>,
        coupled: bool,
    },
    /// A deck's free rod of zero length: free point `point` (its index),
    /// or with `connector` the point of that body (its index), the
    /// connector its lines with bending stiffness are clamped to
    /// (docs/method.md §15.20).
    Point {
        point: usize,
        connector: Option<usize>,
    },
    /// Moved by the host in six degrees of freedom (MoorDyn's coupled
    /// rod): coupled body `body` (its index) is the rod, its reference
    /// point at end A, its axes the global ones at the pose zero.
    Coupled { body: usize },
}

/// A rod of a system.
#[derive(Clone, Debug, PartialEq)]
pub struct SystemRod {
    /// Its id (a deck's RODS ID; `id` of `[[rods]]`).
    pub id: i64,
    pub holder: RodHolder,
    /// The name of its type, and its index (a deck's ROD TYPES row,
    /// `[[rod_types]]` entry).
    pub type_name: String,
    pub type_index: usize,
    /// The rod with its type's numbers; its ends in its body's axes from
    /// the body's reference point (a free rod's from end A, global axes),
    /// global for a fixed rod. None for a rod of zero length (a point).
    pub rod: Option<Rod>,
    /// Its ends A and B at t = 0, global (m).
    pub ends: [[f64; 3]; 2],
    /// Its ends in its holder's frame (as `rod`'s: body axes from the
    /// body's reference point on a body, from end A for a free or pinned
    /// rod, global for a fixed one), also for a rod of zero length.
    pub local: [[f64; 3]; 2],
    /// The points (indices) at its ends A and B where lines attach.
    pub points: [Option<usize>; 2],
}

impl SystemRod {
    /// The body the rod is a part of (a free or pinned rod's own body, or
    /// the body it is fixed in).
    pub fn body(&self) -> Option<usize> {
        match self.holder {
            RodHolder::Free { body }
            | RodHolder::Pinned { body, .. }
            | RodHolder::Body { body }
            | RodHolder::Coupled { body } => Some(body),
            RodHolder::Point { connector, .. } => connector,
            RodHolder::Fixed => None,
        }
    }

    /// The body that is the rod (a free or pinned rod's, a connector), if
    /// it is one.
    pub fn own_body(&self) -> Option<usize> {
        match self.holder {
            RodHolder::Free { body }
            | RodHolder::Pinned { body, .. }
            | RodHolder::Coupled { body } => Some(body),
            RodHolder::Point { connector, .. } => connector,
            _ => None,
        }
    }

    /// The point (index) a pinned rod's end A is held at.
    pub fn pin_point(&self) -> Option<usize> {
        match self.holder {
            RodHolder::Pinned { .. } => self.points[0],
            _ => None,
        }
    }

    /// What holds it, as `check` and summary.json name it.
    pub fn holder_word(&self) -> &'static str {
        match self.holder {
            RodHolder::Fixed => "fixed",
            RodHolder::Free { .. } => "free",
            RodHolder::Coupled { .. } => "coupled",
            RodHolder::Pinned { coupled: true, .. } => "coupled pinned",
            RodHolder::Pinned { .. } => "pinned",
            RodHolder::Body { .. } => "body",
            RodHolder::Point { .. } => "point",
        }
    }

    /// Where it lies against the surface z = 0 at t = 0: "submerged",
    /// "crossing the surface" or "above the surface".
    pub fn waterline(&self) -> &'static str {
        let [a, b] = self.ends.map(|e| e[2]);
        if a < 0.0 && b < 0.0 {
            "submerged"
        } else if a > 0.0 && b > 0.0 {
            "above the surface"
        } else {
            "crossing the surface"
        }
    }

    /// Whether its water (in a scenario with water) acts on something
    /// that moves: a free or pinned rod, a rod on a free body, or one the
    /// host moves (a coupled rod, a rod on a coupled body: its water
    /// pushes the host, docs/method.md §15.18).
    pub fn moves(&self, bodies: &[SystemBody]) -> bool {
        self.body()
            .is_some_and(|b| bodies[b].is_free() || bodies[b].is_coupled())
    }
}

/// The rod of type `t` between `end_a` and `end_b` (in its holder's
/// frame) with `segments` segments.
pub(super) fn rod_of(t: &RodTypeValues, end_a: [f64; 3], end_b: [f64; 3], segments: usize) -> Rod {
    Rod {
        end_a,
        end_b,
        diameter: t.diameter,
        mass_per_length: t.mass_per_length,
        drag_coefficient: t.cd,
        added_mass_coefficient: t.ca,
        end_drag_coefficient: t.cd_end,
        end_added_mass_coefficient: t.ca_end,
        segments,
    }
}

/// The body of a free rod from `end_a` (global), id `id`: a free body of
/// no mass of its own at end A, global axes (the rod brings its mass).
pub(super) fn free_rod_body(id: i64, end_a: [f64; 3]) -> SystemBody {
    SystemBody {
        kind: BodyType::Free,
        ..SystemBody::fixed(id, end_a, [0.0; 3])
    }
}

/// The id a new body of a free rod takes: one more than the largest id
/// of `bodies` (1 if there are none).
pub(super) fn next_body_id(bodies: &[SystemBody]) -> i64 {
    bodies
        .iter()
        .map(|b| b.id)
        .max()
        .unwrap_or(0)
        .saturating_add(1)
}
