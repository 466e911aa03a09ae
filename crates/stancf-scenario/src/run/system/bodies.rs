//! The bodies of a system's written moment (docs/interface.md,
//! "Rigid bodies"): each body's pose, velocities and the loads on it, for
//! `bodies.csv` and a deck's `Body<n>` channels.
//!
//! - The lines' force on a body and their moment about its reference
//!   point, global: f = sum f_P, m = sum (x_P - x_ref) x f_P over its
//!   points P (f_P the net force of the lines at P, as in points.csv),
//!   plus the moments of the lines clamped to it (docs/method.md §15.19;
//!   over a step, their mean).
//! - MoorDyn's net force (`getFnet` of a free body, its `Body<n>FX..MZ`,
//!   docs/moordyn-bodies-rods.md §2.3): the lines', the body's weight and
//!   buoyancy (m - rho V) g at its centre of mass, its points' buoyancy
//!   and given forces, its rods' buoyancy (B20)-(B21), and the water's
//!   drag on it and its rods (B10), (B19), (B23); not its inertia, nor
//!   its added mass's. A fixed body's is its lines' (MoorDyn-C writes 0
//!   there, never computing it, §7.12 of the note).

use crate::output::Num;
use stancf::body::flow::FlowTime;
use stancf::body::jet::{Jet, JetVec};
use stancf::body::pose::{moordyn_angles, rotate, rotate_back};
use stancf::body::terms::{Context, NV};
use stancf::body::BodyWater;
use stancf::system::{Body, BodyKind, Topology};
use stancf::vec3::{add, cross, scale, sub};
use std::io::Write;

/// A body's pose and velocities at a written moment.
#[derive(Clone, Copy, Debug)]
pub(super) struct BodyMotion {
    /// The reference point (m), global.
    pub position: [f64; 3],
    /// Body axes to global.
    pub rotation: [[f64; 3]; 3],
    /// The reference point's velocity (m/s).
    pub velocity: [f64; 3],
    /// The angular velocity (rad/s), global.
    pub angular_velocity: [f64; 3],
}

/// One body at a written moment (see the module documentation).
#[derive(Clone, Copy, Debug)]
pub(super) struct BodyRow {
    pub motion: BodyMotion,
    /// MoorDyn's roll, pitch and yaw (degrees).
    pub angles: [f64; 3],
    /// The lines' force and their moment about the reference point.
    pub force: [f64; 3],
    pub moment: [f64; 3],
    /// MoorDyn's net force and moment about the reference point.
    pub net_force: [f64; 3],
    pub net_moment: [f64; 3],
}

impl BodyRow {
    /// Every value, for the check that none is non-finite.
    fn values(&self) -> impl Iterator<Item = f64> + '_ {
        let m = &self.motion;
        [
            m.position,
            self.angles,
            m.velocity,
            m.angular_velocity,
            self.force,
            self.moment,
            self.net_force,
            self.net_moment,
        ]
        .into_iter()
        .flatten()
        .chain(m.rotation.into_iter().flatten())
    }
}

/// The motion of a body held at its pose.
pub(super) fn at_rest(body: &Body) -> BodyMotion {
    BodyMotion {
        position: body.position,
        rotation: body.rotation,
        velocity: [0.0; 3],
        angular_velocity: [0.0; 3],
    }
}

/// The motion of a free body stepped by the core: its reference point's
/// velocity v_G + w x (r_ref - r_G).
pub(super) fn stepped(body: &stancf::body::FreeBody) -> BodyMotion {
    let position = body.position();
    let w = body.angular_velocity();
    BodyMotion {
        position,
        rotation: body.rotation(),
        velocity: add(
            body.centre_velocity(),
            cross(w, sub(position, body.centre())),
        ),
        angular_velocity: w,
    }
}

/// Each body's row: `motion(b)` its pose and velocities, `points` every
/// point's (position, velocity, net force of its lines), `clamps(b)` the
/// moment of the lines clamped to it (docs/method.md §15.19).
pub(super) fn body_rows(
    topology: &Topology,
    motion: impl Fn(usize) -> BodyMotion,
    points: &[([f64; 3], [f64; 3], [f64; 3])],
    clamps: impl Fn(usize) -> [f64; 3],
    time: FlowTime,
) -> Vec<BodyRow> {
    (0..topology.bodies().len())
        .map(|b| {
            let m = motion(b);
            let mut force = [0.0; 3];
            let mut moment = clamps(b);
            for &(p, _) in topology.body_points(b) {
                let (x, _, f) = points[p];
                force = add(force, f);
                moment = add(moment, cross(sub(x, m.position), f));
            }
            let body = &topology.bodies()[b];
            let (own_force, own_moment) = match body.kind {
                BodyKind::Free => own_loads(body, &m, topology.gravity(), time),
                // A coupled body held at its pose: its rods' push (B36);
                // without rods, nothing of its own (its mass is the host's).
                BodyKind::Coupled if !body.rods.is_empty() => stancf::system::held_push(
                    body,
                    topology.gravity(),
                    &stancf::system::HeldMotion::at_rest(m.position, m.rotation),
                    time,
                ),
                BodyKind::Coupled | BodyKind::Fixed => ([0.0; 3], [0.0; 3]),
            };
            BodyRow {
                motion: m,
                angles: moordyn_angles(&m.rotation),
                force,
                moment,
                net_force: add(force, own_force),
                net_moment: add(moment, own_moment),
            }
        })
        .collect()
}

/// A free body's own loads about its reference point: its weight and
/// buoyancy (m - rho V) g at its centre of mass, the constant forces at
/// its points (a point's buoyancy and given force, folded into the body),
/// and in water [`water_loads`].
fn own_loads(
    body: &Body,
    m: &BodyMotion,
    gravity: [f64; 3],
    time: FlowTime,
) -> ([f64; 3], [f64; 3]) {
    let water = body.water.as_ref();
    let (density, volume) = water.map_or((0.0, 0.0), |w| (w.density, w.volume));
    let weight = scale(body.inertia.mass - density * volume, gravity);
    let arm = rotate(&m.rotation, body.inertia.centre_of_mass);
    let mut force = weight;
    let mut moment = cross(arm, weight);
    for (f, xi) in &body.loads {
        force = add(force, *f);
        moment = add(moment, cross(rotate(&m.rotation, *xi), *f));
    }
    if let Some(w) = water {
        let (f, about_centre) = water_loads(body, m, w, time);
        force = add(force, f);
        moment = add(moment, add(about_centre, cross(arm, f)));
    }
    (force, moment)
}

/// The water's loads on a free body at its motion `m`, as the core's step
/// takes them (stancf::body::terms): the buoyancy of its rods' parts
/// under the surface (B20)-(B21), and the drag of (B10) (-1/2 rho
/// diag(CdA) u |u| at the reference point, u = R^T (v_ref - U), and the
/// moment -1/2 rho diag(CdA_r) Omega |Omega|) with its rods' (B19) and
/// the momentum the water keeps as their wet part changes (B23). The
/// force and its moment about the centre of mass, global.
fn water_loads(body: &Body, m: &BodyMotion, w: &BodyWater, time: FlowTime) -> ([f64; 3], [f64; 3]) {
    let c = body.inertia.centre_of_mass;
    let ctx = Context {
        mass: body.inertia.mass,
        inertia_at_centre: &body.inertia.inertia_at_centre,
        centre_of_mass: c,
        rotation_a: &m.rotation,
        loads: &[],
        water: Some(w),
        time,
    };
    let arm = rotate(&m.rotation, c);
    let centre = add(m.position, arm);
    let (mut force, mut moment) = ctx.buoyancy_at(centre);
    // The twelve variables at theta = 0 (R = R_a, Omega = theta_dot), the
    // pose's as variables: the rates of the rods' wet parts (B23) are
    // their derivatives along the motion.
    let v_g = add(m.velocity, cross(m.angular_velocity, arm));
    let omega = rotate_back(&m.rotation, m.angular_velocity);
    let mut v: [JetVec<NV>; 4] = [[Jet::constant(0.0); 3]; 4];
    for i in 0..3 {
        v[0][i] = Jet::constant(v_g[i]);
        v[1][i] = Jet::variable(0.0, 3 + i);
        v[2][i] = Jet::constant(omega[i]);
        v[3][i] = Jet::variable(centre[i], 9 + i);
    }
    if let Some((on_centre, on_theta)) = ctx.drag(&v) {
        force = add(force, on_centre.map(|f| f.v));
        moment = add(moment, rotate(&m.rotation, on_theta.map(|f| f.v)));
    }
    (force, moment)
}

/// The header of bodies.csv.
pub(super) const HEADER: &str = "t,body,x,y,z,roll,pitch,yaw,vx,vy,vz,wx,wy,wz,fx,fy,fz,mx,my,mz";

/// Refuses a body row with a value that is not finite (none may reach a
/// file): the body's id, for the message.
pub(super) fn check_finite(rows: &[BodyRow], ids: &[i64]) -> Result<(), String> {
    match rows.iter().position(|r| !r.values().all(f64::is_finite)) {
        Some(b) => Err(format!("state of body {}", ids[b])),
        None => Ok(()),
    }
}

/// The rows of bodies.csv at the written time `t` (each body once, by
/// its id).
pub(super) fn write_rows(
    w: &mut impl Write,
    t: f64,
    ids: &[i64],
    rows: &[BodyRow],
) -> std::io::Result<()> {
    for (id, r) in ids.iter().zip(rows) {
        let m = &r.motion;
        write!(w, "{},{id}", Num(t))?;
        for v in [
            m.position,
            r.angles,
            m.velocity,
            m.angular_velocity,
            r.force,
            r.moment,
        ] {
            write!(w, ",{},{},{}", Num(v[0]), Num(v[1]), Num(v[2]))?;
        }
        writeln!(w)?;
    }
    Ok(())
}

/// summary.json's `bodies`: each body's id, type, and its reference point
/// and MoorDyn angles (degrees) at the end of the run (`sim`) or of the
/// static solve (`statics`), else where the scenario puts it.
pub(super) fn bodies_json(
    sc: &crate::scenario::SystemScenario,
    sim: Option<&stancf::system::SystemSimulation>,
    statics: Option<&stancf::system::SystemStatics>,
) -> Vec<serde_json::Value> {
    sc.bodies
        .iter()
        .enumerate()
        .map(|(b, body)| {
            let (position, rotation) = match (sim, statics) {
                (Some(s), _) => match s.free_body(b) {
                    Some(free) => (free.position(), free.rotation()),
                    None => (body.position, body.rotation()),
                },
                (None, Some(st)) => st.body_pose(b).unwrap_or((body.position, body.rotation())),
                _ => (body.position, body.rotation()),
            };
            serde_json::json!({
                "id": body.id,
                "type": body.type_word(),
                "position_final": super::vec3(position),
                "angles_final": super::vec3(moordyn_angles(&rotation)),
            })
        })
        .collect()
}

/// summary.json's `rods`: each rod's id, what holds it ("free",
/// "pinned", "body", "fixed", or "point" for a deck's free rod of zero
/// length), the body it is (a free or pinned rod) or is fixed in, by its
/// index in `bodies` and its id in bodies.csv, and the ids of the points
/// at its ends A and B (null where no line attaches; a pinned rod's end
/// A always has its pin's point).
pub(super) fn rods_json(sc: &crate::scenario::SystemScenario) -> Vec<serde_json::Value> {
    sc.rods
        .iter()
        .map(|r| {
            let point = |p: Option<usize>| p.map(|p| sc.points[p].id);
            serde_json::json!({
                "id": r.id,
                "type": r.holder_word(),
                "rod_type": r.type_name,
                "body": r.body(),
                "body_id": r.body().map(|b| sc.bodies[b].id),
                "points": [point(r.points[0]), point(r.points[1])],
            })
        })
        .collect()
}
