//! What a system is besides its lines' models (docs/method.md §11.1): its
//! points, what each line end attaches to, and gravity on the points'
//! masses. A [`super::System`] is its topology and its lines' models; a
//! running [`super::SystemSimulation`] keeps the topology alone, its
//! line simulations own the models (each model exists once).

use super::{end_node, End, Point, PointKind};
use crate::error::ModelError;
use crate::model::Model;
use crate::motion::CoupledMotion;

/// A system's points, line ends and gravity (no line models).
#[derive(Clone, Debug)]
pub struct Topology {
    /// What line i's ends A and B attach to.
    pub(super) ends: Vec<[End; 2]>,
    pub(super) points: Vec<Point>,
    /// Rigid bodies (docs/method.md §15.7).
    pub(super) bodies: Vec<super::Body>,
    /// Every body's points (indices) and their body coordinates.
    pub(super) body_points: Vec<Vec<(usize, [f64; 3])>>,
    /// Line ends clamped in a direction at free bodies' points
    /// (docs/method.md §15.19).
    pub(super) clamps: Vec<super::body_clamps::BodyClamp>,
    /// Acceleration of gravity on the points' masses (m/s^2).
    pub(super) gravity: [f64; 3],
    /// MoorDyn's order of the rods, points and bodies a host that sets the
    /// waves is asked at (None: the system's own, [`super::HostOrder`]).
    pub(super) host_order: Option<super::HostOrder>,
    /// The seabed under each free point, where a line attached there has
    /// one (docs/method.md (W42p)).
    pub(super) point_beds: Vec<Option<super::point_bed::PointBed>>,
}

/// A line end attached to a point: the end (0 = A, 1 = B), the point and
/// the end's node in the line ([`end_node`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct AttachedEnd {
    pub end: usize,
    pub point: usize,
    pub node: usize,
}

/// The attached ends of a line whose ends are `ends` and whose model is
/// `model`: the one mapping of a line end to its point and node.
pub fn attached_ends<'a>(
    ends: &'a [End; 2],
    model: &'a Model,
) -> impl Iterator<Item = AttachedEnd> + 'a {
    ends.iter()
        .enumerate()
        .filter_map(move |(end, e)| match *e {
            End::Point(point) => Some(AttachedEnd {
                end,
                point,
                node: end_node(model, end),
            }),
            End::Loose => None,
        })
}

impl Topology {
    /// What each line's ends A and B attach to (one entry per line).
    pub fn line_ends(&self) -> &[[End; 2]] {
        &self.ends
    }

    /// The attached ends of line `line`, whose model is `model`
    /// ([`attached_ends`]).
    pub fn attached_ends<'a>(
        &'a self,
        line: usize,
        model: &'a Model,
    ) -> impl Iterator<Item = AttachedEnd> + 'a {
        attached_ends(&self.ends[line], model)
    }

    /// Whether a line end is clamped at free body b's point (§15.19).
    pub fn holds_clamps(&self, b: usize) -> bool {
        self.clamps.iter().any(|c| c.body == b)
    }

    /// The line ends clamped at free bodies' points (§15.19).
    pub(super) fn body_clamps(&self) -> &[super::body_clamps::BodyClamp] {
        &self.clamps
    }

    pub fn points(&self) -> &[Point] {
        &self.points
    }

    pub fn bodies(&self) -> &[super::Body] {
        &self.bodies
    }

    /// Body b's points (indices) and their coordinates in its axes from
    /// its reference point.
    pub fn body_points(&self, b: usize) -> &[(usize, [f64; 3])] {
        &self.body_points[b]
    }

    /// The free bodies' indices, in order.
    pub fn free_bodies(&self) -> impl Iterator<Item = usize> + '_ {
        (0..self.bodies.len()).filter(|&b| self.bodies[b].kind == super::BodyKind::Free)
    }

    /// The point free body b is pinned to when that point moves with
    /// the solution, a free point or a point on another free body: a
    /// joint (docs/method.md §15.14). None for a pin to a fixed point or
    /// no pin.
    pub fn joint_point(&self, b: usize) -> Option<usize> {
        let pin = self.bodies[b].pin?;
        self.points[pin.point].is_unknown().then_some(pin.point)
    }

    /// The free body free body b hangs from through its joint, if the
    /// joint's point is on one.
    pub fn joint_parent(&self, b: usize) -> Option<usize> {
        self.points[self.joint_point(b)?].body()
    }

    /// The free bodies, each before the body it hangs from through a
    /// joint (deepest first, then in order): a child's rows go to its
    /// joint's point before the parent carries that point's rows to its
    /// own (§15.14). The joints form no loop ([`super::System::with_bodies`]
    /// refuses one).
    pub fn free_bodies_children_first(&self) -> Vec<usize> {
        let depth = |mut b: usize| {
            let mut d = 0;
            while let Some(parent) = self.joint_parent(b) {
                b = parent;
                d += 1;
                if d > self.bodies.len() {
                    break;
                }
            }
            d
        };
        let mut order: Vec<usize> = self.free_bodies().collect();
        order.sort_by_key(|&b| std::cmp::Reverse(depth(b)));
        order
    }

    /// The border unknowns' owners a line block at point p reaches: the
    /// free body p is on and, up its joints, each joint's point and the
    /// body it is on (the rows of a body's points go to the body, a
    /// child's centre rows to its joint's point, §15.14).
    pub fn joint_chain(&self, p: usize) -> (Vec<usize>, Vec<usize>) {
        let (mut points, mut bodies) = (Vec::new(), Vec::new());
        let mut at = self.points[p].body();
        while let Some(b) = at {
            if bodies.contains(&b) {
                break;
            }
            bodies.push(b);
            at = self.joint_point(b).and_then(|jp| {
                points.push(jp);
                self.points[jp].body()
            });
        }
        (points, bodies)
    }

    pub fn gravity(&self) -> [f64; 3] {
        self.gravity
    }

    /// The constant load on free point p: its weight, its constant force
    /// and, in water, its buoyancy (W33).
    pub fn point_load(&self, p: usize) -> [f64; 3] {
        let pt = &self.points[p];
        let buoyancy = pt
            .water
            .as_ref()
            .map_or([0.0; 3], |w| w.buoyancy(&self.gravity));
        std::array::from_fn(|i| pt.mass * self.gravity[i] + pt.force[i] + buoyancy[i])
    }

    /// The seabed's push on free point p (docs/method.md (W42p)); None
    /// where no line attached there has a seabed, or p is not free.
    pub fn point_bed(&self, p: usize) -> Option<&super::point_bed::PointBed> {
        self.point_beds.get(p)?.as_ref()
    }

    /// The inertia of free point p: its mass and, in water, its added mass
    /// (W35).
    pub fn point_inertia(&self, p: usize) -> f64 {
        let pt = &self.points[p];
        pt.mass + pt.water.as_ref().map_or(0.0, |w| w.added_mass())
    }

    /// Refuses to move point p unless it is a coupled point.
    pub(super) fn check_coupled(&self, p: usize) -> Result<(), ModelError> {
        let key = format!("points[{p}]");
        match self.points.get(p).map(|pt| &pt.kind) {
            Some(PointKind::Coupled(_)) => Ok(()),
            Some(_) => Err(ModelError::invalid(key, "is not a coupled point")),
            None => Err(ModelError::invalid(key, "does not exist")),
        }
    }

    /// Moves coupled point p along `motion` (checked by
    /// [`Self::check_coupled`]; the attachment constraints of its lines
    /// are the models' owners' to move).
    pub(super) fn set_point_motion(&mut self, p: usize, motion: CoupledMotion) {
        self.points[p].kind = PointKind::Coupled(motion);
    }

    /// The lines attached to point p: (line, end 0 = A or 1 = B).
    pub fn attachments(&self, p: usize) -> impl Iterator<Item = (usize, usize)> + '_ {
        self.ends.iter().enumerate().flat_map(move |(li, ends)| {
            ends.iter()
                .enumerate()
                .filter(move |(_, e)| **e == End::Point(p))
                .map(move |(end, _)| (li, end))
        })
    }

    /// Checks that every line is held: connected, through lines and free
    /// points, to a fixed or coupled point. A static equilibrium of a
    /// group of lines that nothing holds is not unique (it can translate).
    pub fn check_held(&self) -> Result<(), ModelError> {
        let n_points = self.points.len();
        // Union-find over points (0..n_points), lines (n_points..) and
        // bodies (after the lines): a body joins its points.
        let n_nodes = n_points + self.ends.len();
        let mut parent: Vec<usize> = (0..n_nodes + self.bodies.len()).collect();
        fn root(parent: &mut [usize], mut i: usize) -> usize {
            while parent[i] != i {
                parent[i] = parent[parent[i]];
                i = parent[i];
            }
            i
        }
        for (li, ends) in self.ends.iter().enumerate() {
            for end in ends {
                if let End::Point(p) = *end {
                    let (a, b) = (root(&mut parent, p), root(&mut parent, n_points + li));
                    parent[a] = b;
                }
            }
        }
        for (p, point) in self.points.iter().enumerate() {
            if let Some(b) = point.body() {
                let (a, r) = (root(&mut parent, p), root(&mut parent, n_nodes + b));
                parent[a] = r;
            }
        }
        // A pinned body joins its pin's point.
        for (b, body) in self.bodies.iter().enumerate() {
            if let Some(pin) = body.pin {
                let (a, r) = (root(&mut parent, pin.point), root(&mut parent, n_nodes + b));
                parent[a] = r;
            }
        }
        let mut held = vec![false; parent.len()];
        for (p, point) in self.points.iter().enumerate() {
            if !point.is_unknown() {
                let r = root(&mut parent, p);
                held[r] = true;
            }
        }
        for li in 0..self.ends.len() {
            if !held[root(&mut parent, n_points + li)] {
                return Err(ModelError::invalid(
                    format!("lines[{li}]"),
                    "nothing holds this line: it is not connected, through lines, free \
                     points and free bodies, to a fixed or coupled point, so its equilibrium \
                     is not unique",
                ));
            }
        }
        Ok(())
    }

    /// Whether some point's position is an unknown, a free point or a
    /// point on a free body (the lines are then solved together).
    pub fn has_free_points(&self) -> bool {
        self.points.iter().any(Point::is_unknown)
    }

    /// Whether the system has a free body.
    pub fn has_free_bodies(&self) -> bool {
        self.free_bodies().next().is_some()
    }
}
