//! Rigid bodies of a system (docs/interface.md, "Rigid bodies";
//! docs/method.md §15): `[[bodies]]` of a TOML system or a MoorDyn deck's
//! BODIES, fixed (its points are fixed points where its pose puts them),
//! coupled (moved by a coupling code, docs/method.md §13.6; held at its
//! pose in a run of its own) or free (six degrees of freedom, moved by its
//! weight, its buoyancy, its water and its lines). What the water they are in may be is
//! `body_water.rs`.

use super::context::Ctx;
use super::raw::RawBody;
use super::water::Water;
use super::ScenarioError;
use stancf::body::pose;

/// What holds a body.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum BodyType {
    /// Held at its pose.
    Fixed,
    /// Moved by a coupling code (its 6 numbers in the coupling arrays);
    /// held at its pose in a run of its own. Its mass, inertia and water
    /// are the host's.
    Coupled,
    /// Six degrees of freedom.
    Free,
}

/// A rigid body of a system. A fixed or coupled body's inertia, water
/// and velocities are zero (its pose is given).
#[derive(Clone, Debug, PartialEq)]
pub struct SystemBody {
    /// The body's id (a deck's BODIES ID; `id` of `[[bodies]]`).
    pub id: i64,
    pub kind: BodyType,
    /// The reference point at t = 0 (m), global.
    pub position: [f64; 3],
    /// MoorDyn's roll, pitch and yaw (degrees): R = R_x R_y R_z.
    pub angles: [f64; 3],
    /// Mass (kg).
    pub mass: f64,
    /// The centre of mass, body axes from the reference point (m).
    pub centre_of_mass: [f64; 3],
    /// Principal moments of inertia about the centre of mass along the
    /// body axes (kg m^2).
    pub moments: [f64; 3],
    /// Displaced volume (m^3): buoyancy at the centre of mass and the
    /// added mass's volume, in water.
    pub volume: f64,
    /// Translational drag areas CdA (m^2), body axes.
    pub drag_areas: [f64; 3],
    /// Rotational drag areas (multiplying Omega |Omega|, MoorDyn's).
    pub rotational_drag_areas: [f64; 3],
    /// Added-mass coefficients along the body axes, on the volume.
    pub ca: [f64; 3],
    /// The reference point's velocity and the angular velocity (global)
    /// at t = 0.
    pub velocity: [f64; 3],
    pub angular_velocity: [f64; 3],
    /// A constant force at the reference point and a constant moment
    /// (global, N and N m; docs/method.md §15.13).
    pub force: [f64; 3],
    pub moment: [f64; 3],
    /// A constant force at the reference point fixed in the body's axes
    /// (N), and the reference point's damping along the global and the
    /// body's axes (MoorDyn-F's EXTERNAL LOADS, docs/method.md §15.21).
    pub body_force: [f64; 3],
    pub damping: stancf::damping::AxisDamping,
    pub body_damping: stancf::damping::AxisDamping,
    /// A free body pinned at its reference point to a coupled point (its
    /// index among the points) that a host moves: MoorDyn's
    /// CoupledPinned body (docs/method.md §15.17).
    pub host_pin: Option<usize>,
    /// A connector's axis (global, at t = 0): the body is MoorDyn's free
    /// rod of zero length that its lines with bending stiffness are
    /// clamped to along this axis (docs/method.md §15.20).
    pub connector_axis: Option<[f64; 3]>,
}

impl SystemBody {
    /// A fixed body `id` at `position` turned by MoorDyn's `angles`
    /// (degrees): its inertia, water and velocities zero.
    pub fn fixed(id: i64, position: [f64; 3], angles: [f64; 3]) -> Self {
        SystemBody {
            id,
            kind: BodyType::Fixed,
            position,
            angles,
            mass: 0.0,
            centre_of_mass: [0.0; 3],
            moments: [0.0; 3],
            volume: 0.0,
            drag_areas: [0.0; 3],
            rotational_drag_areas: [0.0; 3],
            ca: [0.0; 3],
            velocity: [0.0; 3],
            angular_velocity: [0.0; 3],
            force: [0.0; 3],
            moment: [0.0; 3],
            body_force: [0.0; 3],
            damping: Default::default(),
            body_damping: Default::default(),
            host_pin: None,
            connector_axis: None,
        }
    }

    /// Body axes to global at t = 0.
    pub fn rotation(&self) -> [[f64; 3]; 3] {
        pose::rotation_from_moordyn_angles(self.angles)
    }

    /// The global position at t = 0 of the body point `local` (body axes,
    /// from the reference point).
    pub fn point(&self, local: [f64; 3]) -> [f64; 3] {
        pose::point(self.position, &self.rotation(), local)
    }

    pub fn is_free(&self) -> bool {
        self.kind == BodyType::Free
    }

    pub fn is_coupled(&self) -> bool {
        self.kind == BodyType::Coupled
    }

    /// "free", "fixed" or "coupled", as `type` of `[[bodies]]` says it.
    pub fn type_word(&self) -> &'static str {
        match self.kind {
            BodyType::Free => "free",
            BodyType::Fixed => "fixed",
            BodyType::Coupled => "coupled",
        }
    }

    /// Whether any of the body's water values (volume, drag areas, added
    /// mass) is not zero.
    pub fn has_water_values(&self) -> bool {
        self.volume != 0.0 || self.has_drag() || self.ca != [0.0; 3]
    }

    /// Whether the body has a drag area, translational or rotational.
    pub fn has_drag(&self) -> bool {
        self.drag_areas != [0.0; 3] || self.rotational_drag_areas != [0.0; 3]
    }

    /// Whether the body starts moving.
    pub fn moves_at_start(&self) -> bool {
        self.velocity != [0.0; 3] || self.angular_velocity != [0.0; 3]
    }
}

/// Whether principal moments `m` are those of a body with extent in
/// every direction: J_k = (m_a + m_b - m_k) / 2 positive, as the core's
/// [`stancf::body::RigidInertia::validate`] requires (the same leading
/// minors of the diagonal J_G against the trace).
pub fn moments_of_a_body(m: [f64; 3]) -> bool {
    let trace = m[0] + m[1] + m[2];
    if !trace.is_finite() || trace <= 0.0 {
        return false;
    }
    let j = [0, 1, 2].map(|k| 0.5 * trace - m[k]);
    let minors = [j[0], j[0] * j[1], j[0] * j[1] * j[2]];
    (0..3).all(|k| minors[k] > 1e-12 * trace.powi(k as i32 + 1))
}

/// The keys of `[[bodies]]` that only a free body takes.
const FREE_KEYS: [&str; 16] = [
    "mass",
    "centre_of_mass",
    "inertia",
    "volume",
    "cda",
    "rotational_cda",
    "ca",
    "velocity",
    "angular_velocity",
    "force",
    "moment",
    "body_force",
    "damping_linear",
    "damping_quadratic",
    "body_damping_linear",
    "body_damping_quadratic",
];

/// `[[bodies]]`: `id` (required, unique), `type` ("free", "fixed" or
/// "coupled", required), `position` (required), `angles` (degrees, default 0); a
/// free body's `mass` (> 0) and `inertia` (the three moments, each less
/// than the sum of the other two), required, `centre_of_mass`,
/// `volume`, `cda`, `rotational_cda`, `ca` (>= 0), `velocity`,
/// `angular_velocity`, and a constant `force` (at the reference point)
/// and `moment` (global, N and N m) (default 0). A fixed body is held at its pose, a
/// coupled body moved by a coupling code (the host carries its mass,
/// inertia and water): the keys of a free body are refused there, naming
/// the key.
pub(super) fn bodies(ctx: &Ctx, raw: &[RawBody]) -> Result<Vec<SystemBody>, ScenarioError> {
    let mut out: Vec<SystemBody> = Vec::with_capacity(raw.len());
    for (i, r) in raw.iter().enumerate() {
        let key = |k: &str| format!("bodies[{i}].{k}");
        let id = ctx.required(&key("id"), r.id)?;
        if out.iter().any(|b| b.id == id) {
            return Err(ctx.err(&key("id"), format!("body {id} is defined twice")));
        }
        let kind = match ctx.choice(
            &key("type"),
            Some(ctx.required(&key("type"), r.kind.as_deref())?),
            "",
            &["free", "fixed", "coupled"],
        )? {
            "free" => BodyType::Free,
            "coupled" => BodyType::Coupled,
            _ => BodyType::Fixed,
        };
        let position = ctx.vector(
            &key("position"),
            &ctx.required(&key("position"), r.position.clone())?,
        )?;
        let angles = ctx.vector_or(&key("angles"), r.angles.as_deref(), [0.0; 3])?;
        let fixed = SystemBody {
            kind,
            ..SystemBody::fixed(id, position, angles)
        };
        if kind != BodyType::Free {
            if let Some(k) = FREE_KEYS.iter().zip(r.free_keys()).find(|(_, g)| *g) {
                let why = if kind == BodyType::Coupled {
                    "a coupled body is moved by the coupling code, which carries its mass, \
                     inertia and water (MoorDyn's coupled body: the lines' force and moment \
                     only are returned); give them to the host, or make the body free, \
                     type = \"free\""
                } else {
                    "a fixed body is held at its pose: its mass, inertia, water and \
                     velocities do nothing (give them to a free body, type = \"free\")"
                };
                return Err(ctx.err(&key(k.0), why));
            }
            out.push(fixed);
            continue;
        }
        out.push(free_body(ctx, i, r, fixed)?);
    }
    Ok(out)
}

/// The free body of `[[bodies]]` entry i (`body`: its id, type and pose).
fn free_body(
    ctx: &Ctx,
    i: usize,
    r: &RawBody,
    body: SystemBody,
) -> Result<SystemBody, ScenarioError> {
    let key = |k: &str| format!("bodies[{i}].{k}");
    let mass = ctx.required_positive(&key("mass"), r.mass)?;
    let moments = non_negative_vector(
        ctx,
        &key("inertia"),
        &ctx.required(&key("inertia"), r.inertia.clone())?,
    )?;
    // Zero moments: a point mass, which the library takes where everything
    // acts at its centre (docs/method.md (B2a)).
    if !(moments_of_a_body(moments) || moments == [0.0; 3]) {
        return Err(ctx.err(
            &key("inertia"),
            format!(
                "the moments {moments:?} kg m^2 about the centre of mass are not those of a body \
                 with extent in all three directions: each must be less than the sum of the \
                 other two (or all 0, a point mass)"
            ),
        ));
    }
    let optional = |k: &str, v: &Option<Vec<f64>>| optional_non_negative(ctx, &key(k), v);
    Ok(SystemBody {
        mass,
        centre_of_mass: ctx.vector_or(
            &key("centre_of_mass"),
            r.centre_of_mass.as_deref(),
            [0.0; 3],
        )?,
        moments,
        volume: match r.volume {
            Some(v) => ctx.non_negative(&key("volume"), v)?,
            None => 0.0,
        },
        drag_areas: optional("cda", &r.cda)?,
        rotational_drag_areas: optional("rotational_cda", &r.rotational_cda)?,
        ca: optional("ca", &r.ca)?,
        velocity: ctx.vector_or(&key("velocity"), r.velocity.as_deref(), [0.0; 3])?,
        angular_velocity: ctx.vector_or(
            &key("angular_velocity"),
            r.angular_velocity.as_deref(),
            [0.0; 3],
        )?,
        force: ctx.vector_or(&key("force"), r.force.as_deref(), [0.0; 3])?,
        moment: ctx.vector_or(&key("moment"), r.moment.as_deref(), [0.0; 3])?,
        body_force: ctx.vector_or(&key("body_force"), r.body_force.as_deref(), [0.0; 3])?,
        damping: stancf::damping::AxisDamping {
            linear: optional("damping_linear", &r.damping_linear)?,
            quadratic: optional("damping_quadratic", &r.damping_quadratic)?,
        },
        body_damping: stancf::damping::AxisDamping {
            linear: optional("body_damping_linear", &r.body_damping_linear)?,
            quadratic: optional("body_damping_quadratic", &r.body_damping_quadratic)?,
        },
        ..body
    })
}

/// An optional vector of 3 finite numbers, each >= 0 (zero if not given).
pub(super) fn optional_non_negative(
    ctx: &Ctx,
    key: &str,
    v: &Option<Vec<f64>>,
) -> Result<[f64; 3], ScenarioError> {
    match v {
        Some(v) => non_negative_vector(ctx, key, v),
        None => Ok([0.0; 3]),
    }
}

/// A vector of 3 finite numbers, each >= 0.
fn non_negative_vector(ctx: &Ctx, key: &str, v: &[f64]) -> Result<[f64; 3], ScenarioError> {
    let v = ctx.vector(key, v)?;
    if let Some(c) = v.iter().position(|&c| c < 0.0) {
        return Err(ctx.err(key, format!("component {c} is {}; it must be >= 0", v[c])));
    }
    Ok(v)
}

/// The water's current where it is the same at every depth (zero
/// without one); None where it varies with depth (or in time).
pub fn uniform_current(w: &Water) -> Option<[f64; 3]> {
    let Some(c) = &w.current else {
        return Some([0.0; 3]);
    };
    let rows = c.profile()?;
    let first = rows[0].velocity;
    rows.iter().all(|r| r.velocity == first).then_some(first)
}
