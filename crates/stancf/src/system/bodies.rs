//! Rigid bodies in a system (docs/method.md §15.7): a floating platform,
//! a buoy, a clump weight with a size. Lines attach to points fixed on
//! a body (a point of kind [`PointKind::Body`], given in the body's axes
//! from its reference point).
//!
//! - A *fixed* body holds its points where its pose puts them: they
//!   become fixed points (anchors on a seabed template).
//! - A *coupled* body is moved by another code (a floating platform's
//!   solver, docs/method.md §13): its points become coupled points, each
//!   on the motion of the body point (`crate::coupling`).
//! - A *free* body has six unknowns per time slot: its centre of mass
//!   and its rotation vector over the step (§15.3-15.4), stepped with its
//!   lines by the Galerkin step. Its points' positions are functions of
//!   them (B11): a line end there moves with the body, and its rows
//!   load the body through the chain rule (§15.7).

use super::{End, Point, PointKind};
use crate::body::{BodyForces, BodyWater, FreeBody, RigidInertia, Rod};
use crate::error::ModelError;
use crate::scheme::TimeScheme;

/// What holds a body.
#[derive(Clone, Debug, PartialEq)]
pub enum BodyKind {
    /// Held at its pose: its points are fixed points.
    Fixed,
    /// Six unknowns: moved by its weight, its buoyancy, its water and its
    /// lines.
    Free,
    /// Moved by a coupling code: its points are coupled points (its mass,
    /// inertia and water are the coupling code's, as in MoorDyn).
    Coupled,
}

/// A rigid body of a system.
#[derive(Clone, Debug, PartialEq)]
pub struct Body {
    pub kind: BodyKind,
    /// The reference point at t = 0 (m): the origin of the body's axes,
    /// where its points are given from.
    pub position: [f64; 3],
    /// Body axes to global at t = 0.
    pub rotation: [[f64; 3]; 3],
    /// Mass, centre of mass (body axes, from the reference point) and
    /// inertia tensor at the centre of mass (body axes).
    pub inertia: RigidInertia,
    /// The body's velocity at its reference point and its angular
    /// velocity (global) at t = 0.
    pub velocity: [f64; 3],
    pub angular_velocity: [f64; 3],
    /// The water on the body: buoyancy of its volume at the centre of
    /// mass (MoorDyn's), added mass and drag (B9)-(B10); None in air.
    pub water: Option<BodyWater>,
    /// Constant forces (global, N) at body points (body axes, from the
    /// reference point): a point's weight, buoyancy and given force when
    /// the point is on the body (see [`super::System::with_bodies`]).
    pub loads: Vec<([f64; 3], [f64; 3])>,
    /// Rods fixed in the body (body axes, from the reference point): on a
    /// free body their mass joins its inertia, and in water they join its
    /// water, which gives them the buoyancy, added mass and drag of their
    /// parts under the surface (docs/method.md §15.10-§15.11;
    /// [`super::System::with_bodies`] folds them).
    pub rods: Vec<Rod>,
    /// The body's point pinned to a point, if it is: it turns freely
    /// about it (docs/method.md §15.12; MoorDyn's pinned rod), and at a
    /// free point or a free body's point moves with it (a joint, §15.14).
    pub pin: Option<Pin>,
    /// A constant moment on a free body (global, N m; B27), beside the
    /// constant forces of `loads` (a force on the body is a load at its
    /// reference point).
    pub moment: [f64; 3],
    /// A connector (MoorDyn's free rod of zero length that lines with
    /// bending stiffness are clamped to, docs/method.md §15.20): a free
    /// body of no mass, inertia, water or loads whose points are at its
    /// reference point; its rotation carries only the clamps of its lines
    /// (along its z axis), which it turns to balance their moments, and
    /// its spin about that axis, which no clamp sees, is held.
    pub connector: bool,
}

/// A body's point `local` (body axes, from the reference point) held at
/// point `point` of the system, the body turning freely about it: a
/// fixed point (an anchor, or a point of a fixed body; §15.12), or a free
/// point or a point of another free body, moving with it (a joint,
/// §15.14). Not a coupled point.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Pin {
    pub local: [f64; 3],
    pub point: usize,
}

impl Body {
    /// A body at rest, in air.
    pub fn new(
        kind: BodyKind,
        position: [f64; 3],
        rotation: [[f64; 3]; 3],
        inertia: RigidInertia,
    ) -> Self {
        Body {
            kind,
            position,
            rotation,
            inertia,
            velocity: [0.0; 3],
            angular_velocity: [0.0; 3],
            water: None,
            loads: Vec::new(),
            rods: Vec::new(),
            pin: None,
            moment: [0.0; 3],
            connector: false,
        }
    }

    /// A connector at `position` whose lines are clamped along the unit
    /// `axis` (its z axis; [`Body::connector`]).
    pub fn connector(position: [f64; 3], axis: [f64; 3]) -> Self {
        let nothing = RigidInertia {
            mass: 0.0,
            centre_of_mass: [0.0; 3],
            inertia_at_centre: [[0.0; 3]; 3],
        };
        let z = crate::vec3::normalized(axis);
        let k = (0..3)
            .min_by(|&a, &b| z[a].abs().total_cmp(&z[b].abs()))
            .expect("3 axes");
        let mut e = [0.0; 3];
        e[k] = 1.0;
        let x = crate::vec3::normalized(crate::vec3::sub(
            e,
            crate::vec3::scale(crate::vec3::dot(z, e), z),
        ));
        let y = crate::vec3::cross(z, x);
        // Columns x, y, z: body axes to global.
        let rotation = std::array::from_fn(|r| [x[r], y[r], z[r]]);
        let mut body = Body::new(BodyKind::Free, position, rotation, nothing);
        body.connector = true;
        body
    }

    /// A body that is one rod (MoorDyn's free, fixed or coupled rod): its
    /// reference point at the rod's end A, its axes the global ones at
    /// t = 0; `rod` is given from end A (its `end_a` is moved to 0).
    pub fn rod(kind: BodyKind, end_a: [f64; 3], mut rod: Rod) -> Self {
        rod.end_b = crate::vec3::sub(rod.end_b, rod.end_a);
        rod.end_a = [0.0; 3];
        let nothing = RigidInertia {
            mass: 0.0,
            centre_of_mass: [0.0; 3],
            inertia_at_centre: [[0.0; 3]; 3],
        };
        let identity = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
        let mut body = Body::new(kind, end_a, identity, nothing);
        body.rods.push(rod);
        body
    }

    /// The global position of the body point `local` (body axes, from
    /// the reference point) at t = 0 (B1).
    pub fn point(&self, local: [f64; 3]) -> [f64; 3] {
        crate::body::pose::point(self.position, &self.rotation, local)
    }

    /// The velocity of the body point `local` at t = 0.
    pub fn point_velocity(&self, local: [f64; 3]) -> [f64; 3] {
        let arm = crate::body::pose::rotate(&self.rotation, local);
        crate::vec3::add(
            self.velocity,
            crate::vec3::cross(self.angular_velocity, arm),
        )
    }

    /// The body's state for stepping with steps of `dt` under `gravity`:
    /// its weight and buoyancy at the centre of mass (B5).
    pub(super) fn free_body(&self, gravity: [f64; 3], dt: f64) -> Result<FreeBody, ModelError> {
        let (volume, density) = self
            .water
            .as_ref()
            .map_or((0.0, 0.0), |w| (w.volume, w.density));
        let mut forces = BodyForces::weight_and_buoyancy(&self.inertia, volume, density, gravity);
        forces.forces.extend(self.loads.iter().copied());
        let body = FreeBody::new(
            &self.inertia,
            &forces,
            self.position,
            &self.rotation,
            self.velocity,
            self.angular_velocity,
            dt,
        )?
        .with_scheme(TimeScheme::Galerkin)
        .with_moment(self.moment);
        match &self.water {
            Some(w) => body.with_water(w.clone()),
            None => Ok(body),
        }
    }

    fn check(&self, key: &str) -> Result<(), ModelError> {
        let finite = |v: &[f64]| v.iter().all(|x| x.is_finite());
        if !finite(&self.position)
            || !finite(&self.velocity)
            || !finite(&self.angular_velocity)
            || !finite(&self.moment)
        {
            return Err(ModelError::invalid(
                key,
                "position, velocities and moment must be finite",
            ));
        }
        let r = &self.rotation;
        let rrt = crate::vec3::mat3_mul(r, &crate::vec3::mat3_transpose(r));
        let det = crate::vec3::dot(r[0], crate::vec3::cross(r[1], r[2]));
        let off = (0..9)
            .map(|k| (rrt[k / 3][k % 3] - if k / 3 == k % 3 { 1.0 } else { 0.0 }).abs())
            .fold(0.0, f64::max);
        if !(off <= 1e-9 && det > 0.0) {
            return Err(ModelError::invalid(
                format!("{key}.rotation"),
                "is not a rotation (orthonormal, determinant +1)",
            ));
        }
        if self.connector {
            let bare = self.inertia.mass == 0.0
                && self.inertia.inertia_at_centre == [[0.0; 3]; 3]
                && self.water.is_none()
                && self.loads.is_empty()
                && self.rods.is_empty()
                && self.pin.is_none()
                && self.moment == [0.0; 3]
                && self.kind == BodyKind::Free;
            if !bare {
                return Err(ModelError::invalid(
                    key,
                    "a connector is a free body of no mass, inertia, water, loads, rods, pin or \
                     moment (its lines carry everything)",
                ));
            }
        } else if self.kind == BodyKind::Free {
            self.inertia.validate(key)?;
            if let Some(w) = &self.water {
                w.validate(&format!("{key}.water"))?;
            }
        } else if self.water.as_ref().is_some_and(|w| !w.external.is_zero()) {
            return Err(ModelError::invalid(
                format!("{key}.water.external"),
                "only a free body takes an external force and damping (a fixed or coupled \
                 body's motion is given)",
            ));
        }
        Ok(())
    }
}

/// Every body's points: (point index, body coordinates).
pub(super) type BodyPoints = Vec<Vec<(usize, [f64; 3])>>;

/// Validates the bodies and places the points on them: a point on a
/// fixed body becomes a fixed point where the body puts it, a point on a
/// coupled body a coupled point there (at rest until a coupling code
/// moves the body); a point on a free body gets its position at t = 0,
/// and its mass, weight, buoyancy and given force become the body's
/// ([`fold_point`]); a free body whose mass then lies on a line has its
/// inertia completed about it ((B2a), [`super::line_body`]). Returns every
/// body's points with their body coordinates, and which bodies' inertia
/// was completed. Keys: `bodies[i]`, `points[i]`.
pub(super) fn place_points(
    bodies: &mut [Body],
    points: &mut [Point],
    gravity: [f64; 3],
) -> Result<(BodyPoints, Vec<bool>), ModelError> {
    let mut on_body = vec![Vec::new(); bodies.len()];
    for (i, b) in bodies.iter_mut().enumerate() {
        fold_rods(b, gravity).map_err(|e| e.under(&format!("bodies[{i}]")))?;
    }
    for (i, p) in points.iter_mut().enumerate() {
        let PointKind::Body { body, local } = p.kind else {
            continue;
        };
        if let Some(b) = bodies.get_mut(body) {
            fold_point(b, p, local, gravity).map_err(|e| e.under(&format!("points[{i}]")))?;
        }
    }
    let mut on_a_line = vec![false; bodies.len()];
    for (i, b) in bodies.iter_mut().enumerate() {
        let key = format!("bodies[{i}]");
        if b.kind == BodyKind::Free {
            let locals: Vec<[f64; 3]> = points
                .iter()
                .filter_map(|p| match p.kind {
                    PointKind::Body { body, local } if body == i => Some(local),
                    _ => None,
                })
                .collect();
            on_a_line[i] = super::line_body::complete_inertia_on_a_line(b, &locals, &key)?;
        }
        b.check(&key)?;
    }
    for (i, p) in points.iter_mut().enumerate() {
        let PointKind::Body { body, local } = p.kind else {
            continue;
        };
        let key = format!("points[{i}]");
        let Some(b) = bodies.get(body) else {
            return Err(ModelError::invalid(
                key,
                format!("is on body {body}, which does not exist"),
            ));
        };
        if local.iter().any(|x| !x.is_finite()) {
            return Err(ModelError::invalid(
                format!("{key}.local"),
                "must be finite",
            ));
        }
        p.position = b.point(local);
        on_body[body].push((i, local));
        match b.kind {
            BodyKind::Fixed => p.kind = PointKind::Fixed,
            BodyKind::Coupled => {
                p.kind = PointKind::Coupled(crate::motion::CoupledMotion::Interval(
                    crate::motion::MotionInterval::at_rest(p.position),
                ))
            }
            BodyKind::Free => {}
        }
    }
    // Where each point moves at t = 0 (a free body's point with its body,
    // a coupled point on its motion).
    let velocities: Vec<[f64; 3]> = points
        .iter()
        .map(|p| match p.kind {
            PointKind::Body { body, local } => bodies[body].point_velocity(local),
            _ => p.state_at(0.0).1,
        })
        .collect();
    for i in 0..bodies.len() {
        super::body_pins::check_pin(i, &mut bodies[i], points, &velocities)
            .map_err(|e| e.under(&format!("bodies[{i}].pin")))?;
    }
    super::body_pins::check_joint_loops(bodies, points)?;
    Ok((on_body, on_a_line))
}

/// A point on a free body with a mass m, a force F or water (a volume V
/// in water of density rho): the point mass joins the body's inertia
/// ([`RigidInertia::with_point_mass`]), so its weight acts at the body's
/// new centre of mass with the body's, and F - rho V g acts at the point,
/// a constant force (MoorDyn's point on a body: its weight and its whole
/// buoyancy at the point, docs/moordyn-bodies-rods.md §2.3). Its
/// drag and added mass are not built and are refused; so is anything of
/// its own on a fixed or coupled body (whose loads are not stepped).
fn fold_point(
    body: &mut Body,
    p: &mut Point,
    local: [f64; 3],
    gravity: [f64; 3],
) -> Result<(), ModelError> {
    let own = p.mass != 0.0 || p.force != [0.0; 3] || p.water.is_some();
    if !own {
        return Ok(());
    }
    if body.kind != BodyKind::Free {
        return Err(ModelError::invalid(
            "",
            "a point on a fixed or coupled body carries no mass, force or water of its own",
        ));
    }
    if !p.mass.is_finite() || p.mass < 0.0 || p.force.iter().any(|f| !f.is_finite()) {
        return Err(ModelError::invalid(
            "",
            "the mass must be finite and not negative, the force finite",
        ));
    }
    let mut load = p.force;
    if let Some(w) = &p.water {
        w.check("water")?;
        if w.drag_area != 0.0 || w.ca != 0.0 {
            return Err(ModelError::invalid(
                "",
                "the drag and added mass of a point on a body are not built; give the body \
                 its drag area and added mass",
            ));
        }
        let b = w.buoyancy(&gravity);
        for k in 0..3 {
            load[k] += b[k];
        }
    }
    body.inertia = body.inertia.with_point_mass(p.mass, local);
    if load != [0.0; 3] {
        body.loads.push((load, local));
    }
    p.mass = 0.0;
    p.force = [0.0; 3];
    p.water = None;
    Ok(())
}

/// A body's rods (docs/method.md §15.10-§15.11): on a free or coupled body each
/// rod's mass joins its inertia ((B17), [`RigidInertia::with_part`]); in
/// water the rod joins the body's water, which gives it the buoyancy of
/// its part under the surface z = 0 (B20)-(B21), its added mass and its
/// drag (B18)-(B19) at every pose, so the water's `gravity` is set to the
/// system's g, which must then point along -z. A fixed body's rods hold
/// nothing that moves; a coupled body's fold as a free body's over its own
/// zeroed mass and water, their loads pushing the host (B36), and stay in
/// `rods` (a second fold rebuilds the same); a free body's are moved out of
/// `rods`, so a second fold finds none.
fn fold_rods(body: &mut Body, gravity: [f64; 3]) -> Result<(), ModelError> {
    for (k, rod) in body.rods.iter().enumerate() {
        rod.validate(&format!("rods[{k}]"))?;
    }
    match body.kind {
        BodyKind::Fixed => {
            body.rods.clear();
            return Ok(());
        }
        // A coupled body's own mass, inertia and water are the host's (as
        // MoorDyn zeroes them); its rods are carried by the host, their
        // inertia and water giving what they push it with
        // ([`super::held_push`], (B36)).
        BodyKind::Coupled => {
            body.inertia = RigidInertia {
                mass: 0.0,
                centre_of_mass: [0.0; 3],
                inertia_at_centre: [[0.0; 3]; 3],
            };
            if let Some(w) = &mut body.water {
                w.volume = 0.0;
                w.added_mass_coefficients = [0.0; 3];
                w.drag_areas = [0.0; 3];
                w.rotational_drag_areas = [0.0; 3];
            }
        }
        BodyKind::Free => {}
    }
    // A coupled body keeps its rods (its inertia and water are rebuilt
    // from them at every fold, so a second fold changes nothing); a free
    // body's are moved out, so a second fold finds none.
    let rods = match body.kind {
        BodyKind::Coupled => body.rods.clone(),
        _ => std::mem::take(&mut body.rods),
    };
    for rod in &rods {
        body.inertia = body.inertia.with_part(&rod.inertia());
    }
    let Some(water) = &mut body.water else {
        return Ok(());
    };
    if body.kind == BodyKind::Coupled {
        water.rods.clear();
    }
    if !rods.is_empty() {
        // Without gravity (a deck's g 0) the rods have no buoyancy, and
        // their drag and added mass act below z = 0 as with it.
        if !(gravity[0] == 0.0 && gravity[1] == 0.0 && gravity[2] <= 0.0) {
            return Err(ModelError::invalid(
                "rods",
                format!(
                    "rods in water need gravity along -z or none (the water's surface is z = \
                     0), not {gravity:?}"
                ),
            ));
        }
        water.gravity = gravity[2].abs();
    }
    water.rods.extend(rods);
    Ok(())
}

impl super::System {
    /// Starts every line attached to a body that moves at t = 0 (its
    /// `velocity`, `angular_velocity`) with the velocity field linear in
    /// its material coordinate s between its ends' velocities,
    /// v(s) = v_A + (v_B - v_A) s / L (the slope's rate (v_B - v_A) / L):
    /// its ends move with their points, as a step requires of the ends on
    /// a body (at rest at fixed, coupled and free points; a loose end as
    /// the other end). Lines whose ends are both at rest keep `states`.
    /// What a static equilibrium's line states (at rest) need before a
    /// run that starts its bodies moving.
    pub fn start_lines_with_bodies(&self, states: &mut [crate::State]) {
        use crate::model::{SLOT_R, SLOT_R_X};
        let end_velocity = |e: End| match e {
            End::Point(p) => match self.points()[p].kind {
                PointKind::Body { body, local } => Some(self.bodies()[body].point_velocity(local)),
                _ => Some([0.0; 3]),
            },
            End::Loose => None,
        };
        for (line, state) in self.lines().iter().zip(states.iter_mut()) {
            let (va, vb) = match line.ends.map(end_velocity) {
                [Some(a), Some(b)] => (a, b),
                [Some(a), None] => (a, a),
                [None, Some(b)] => (b, b),
                [None, None] => continue,
            };
            if va == [0.0; 3] && vb == [0.0; 3] {
                continue;
            }
            let model = &line.model;
            let length = model.cable.length;
            for node in 0..model.nodes() {
                let s = model.node_coordinate(node) / length;
                for c in 0..3 {
                    state.v[model.coordinate(node, SLOT_R, c)] = va[c] + (vb[c] - va[c]) * s;
                    state.v[model.coordinate(node, SLOT_R_X, c)] = (vb[c] - va[c]) / length;
                }
            }
        }
    }
}
