//! What holds a free body in a system's static solve (docs/method.md
//! §15.8, §15.10-§15.12) where nothing gives it a stiffness: a body no
//! line holds is refused unless a pin holds it or it floats on its rods;
//! a spin about a line through everything that loads it, and a floating
//! body's surge, sway and yaw, are held by springs whose forces vanish at
//! the solution.

use super::System;

/// Whether a line holds free body b (one of its points has a line).
fn on_lines(system: &System, b: usize) -> bool {
    system
        .points()
        .iter()
        .enumerate()
        .any(|(p, pt)| pt.body() == Some(b) && system.attachments(p).next().is_some())
}

/// Whether free body b floats on its rods alone: no line and no pin hold
/// it, it has rods in water (their buoyancy a potential of the pose, with
/// a waterplane's stiffness where they cross the surface, §15.11), there
/// is gravity (without it nothing floats: no weight, no buoyancy) and no
/// current drags it (which would push it away for ever).
fn floats(system: &System, b: usize) -> bool {
    let body = &system.bodies()[b];
    if system.gravity() == [0.0; 3] {
        return false;
    }
    let Some(w) = &body.water else { return false };
    let dragged = w.current != [0.0; 3]
        && (w.drag_areas != [0.0; 3]
            || w.rods
                .iter()
                .any(|r| r.drag_coefficient != 0.0 || r.end_drag_coefficient != 0.0));
    body.pin.is_none() && !on_lines(system, b) && !w.rods.is_empty() && !dragged
}

/// Refuses a free body that no line or pin holds, that does not float on
/// its rods ([`floats`]) and that something acts on ([`rest_hold`]): its
/// weight and buoyancy have nothing to
/// balance them, so it has no static equilibrium (it sinks or rises for
/// ever, and drifts sideways on nothing); a dynamic run from its given
/// pose is its motion. Key `bodies[b]`.
pub(super) fn check_held(system: &System) -> Result<(), crate::error::ModelError> {
    for b in system.free_bodies() {
        let held = system.bodies()[b].pin.is_some() || on_lines(system, b) || floats(system, b);
        if !held && rest_hold(system, b).is_some() {
            continue;
        }
        if held && floats(system, b) {
            check_afloat(system, b)?;
        }
        if !held {
            return Err(crate::error::ModelError::invalid(
                format!("bodies[{b}]"),
                "is free and no line holds it: it has no static equilibrium (nothing balances \
                 its weight and buoyancy); start a dynamic run from its given pose instead",
            ));
        }
    }
    Ok(())
}

/// Where free body b stays in a static solve because nothing holds it
/// and nothing acts on it ([`unloaded`]; no line, pin or buoyancy): every
/// pose is an equilibrium, none isolated, and its rows are zero with a
/// zero Jacobian. The solve holds it where it is given with springs on
/// all six unknowns, k (r_G - r_G0) and k theta (k = 1 N/m and 1 N m, any
/// positive stiffness: their forces are zero at the solution, the given
/// pose; docs/method.md §15.8). Its centre of mass at t = 0, if so.
pub(super) fn rest_hold(system: &System, b: usize) -> Option<[f64; 3]> {
    let body = &system.bodies()[b];
    let held = body.pin.is_some() || on_lines(system, b) || floats(system, b);
    (!held && !body.connector && unloaded(system, b))
        .then(|| body.point(body.inertia.centre_of_mass))
}

/// Whether nothing acts on free body b at rest: no gravity, no constant
/// force or moment, no current, waves or external loads of its water.
fn unloaded(system: &System, b: usize) -> bool {
    let body = &system.bodies()[b];
    let still = body
        .water
        .as_ref()
        .is_none_or(|w| w.current == [0.0; 3] && w.sea.is_none() && w.external.is_zero());
    system.gravity() == [0.0; 3]
        && body.loads.iter().all(|(f, _)| *f == [0.0; 3])
        && body.moment == [0.0; 3]
        && still
}

/// Refuses a body floating on its rods alone that their whole buoyancy
/// (with its own volume's) cannot carry: it sinks, and has no static
/// equilibrium (a body has no seabed contact). Key `bodies[b]`.
fn check_afloat(system: &System, b: usize) -> Result<(), crate::error::ModelError> {
    let body = &system.bodies()[b];
    let Some(w) = &body.water else { return Ok(()) };
    let g = crate::vec3::norm(system.gravity());
    let volume = w.volume + w.rods.iter().map(|r| r.volume()).sum::<f64>();
    let (lift, weight) = (w.density * volume * g, body.inertia.mass * g);
    if lift < weight {
        return Err(crate::error::ModelError::invalid(
            format!("bodies[{b}]"),
            format!(
                "floats on no line and sinks: its buoyancy under water, {lift:.6e} N, is less \
                 than its weight, {weight:.6e} N, so it has no static equilibrium (a body has no \
                 seabed contact); start a dynamic run from its given pose instead"
            ),
        ));
    }
    Ok(())
}

/// The height of free body b's reference point at which, floating on its
/// rods alone ([`floats`]) at its given attitude, its buoyancy (its
/// volume's and its rods' parts under z = 0, (B20)) carries its weight:
/// the catenary network's start for it (a rod deep under water has no
/// stiffness in heave, and the network's Newton no direction to rise
/// in). The buoyancy falls as the body rises, so bisection between the
/// height where its rods are all under water and where they are all out
/// finds it. None if b does not float, or floats at any height.
pub(super) fn floating_height(system: &System, b: usize) -> Option<f64> {
    if !floats(system, b) {
        return None;
    }
    let body = &system.bodies()[b];
    let w = body.water.as_ref()?;
    let r = &body.rotation;
    let up = |x: [f64; 3]| crate::body::pose::rotate(r, x)[2];
    let weight = body.inertia.mass;
    let displaced = |z: f64| -> f64 {
        let rods: f64 = w
            .rods
            .iter()
            .map(|rod| rod.submerged_volume(z + up(rod.end_a), up(rod.axis())))
            .sum();
        w.density * (w.volume + rods)
    };
    let reach = w
        .rods
        .iter()
        .flat_map(|rod| [up(rod.end_a), up(rod.end_b)].map(|h| h.abs() + rod.diameter))
        .fold(0.0f64, f64::max);
    let (mut low, mut high) = (-2.0 * reach, 2.0 * reach);
    if displaced(low) < weight || displaced(high) > weight {
        return None;
    }
    for _ in 0..200 {
        let middle = 0.5 * (low + high);
        if displaced(middle) >= weight {
            low = middle;
        } else {
            high = middle;
        }
    }
    Some(0.5 * (low + high))
}

/// The holds of a body that floats on its rods alone ([`floats`]): still
/// water's buoyancy and gravity are vertical and the same at any
/// horizontal position and heading, so its surge, sway and yaw have no
/// stiffness and its static rows are singular there. The solve holds them
/// with springs k_t (x_G - x_0, y_G - y_0) on the centre's horizontal rows
/// and k_r a (a . theta) on the rotation's, a = R_0^T e_z the vertical in
/// its axes: every such force and moment is zero at any pose, so the
/// springs' are zero at the solution, which is the one without them (the
/// body where it is given, over its heave, roll and pitch equilibrium;
/// docs/method.md §15.11).
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) struct FloatHold {
    pub at: [f64; 2],
    pub vertical: [f64; 3],
    pub translation: f64,
    pub rotation: f64,
}

/// [`FloatHold`] of free body b if it floats on its rods alone: its
/// centre's horizontal position at t = 0, and springs of its weight over
/// (and times) its longest rod's length.
pub(super) fn float_hold(system: &System, b: usize) -> Option<FloatHold> {
    if !floats(system, b) {
        return None;
    }
    let body = &system.bodies()[b];
    let centre = body.point(body.inertia.centre_of_mass);
    let length = body
        .water
        .as_ref()?
        .rods
        .iter()
        .map(|r| r.length())
        .fold(0.0f64, f64::max)
        .max(f64::MIN_POSITIVE);
    let weight = (body.inertia.mass * crate::vec3::norm(system.gravity())).max(f64::MIN_POSITIVE);
    let r = &body.rotation;
    Some(FloatHold {
        at: [centre[0], centre[1]],
        vertical: [r[2][0], r[2][1], r[2][2]],
        translation: weight / length,
        rotation: weight * length,
    })
}

/// The body points of body b (body axes, from the reference point).
pub(super) fn points_local(system: &System, b: usize) -> Vec<[f64; 3]> {
    system
        .points()
        .iter()
        .filter_map(|p| match p.kind {
            super::PointKind::Body { body, local } if body == b => Some(local),
            _ => None,
        })
        .collect()
}

/// The line (a unit vector in body axes) on which the body's centre of
/// mass, its loads' points, its points and its rods under water all lie,
/// if they do (to 1e-9 of their span) and no lumped drag of the body's
/// acts in a current: then nothing turns the body about that line, its
/// static rows are singular there (a free rod held at its ends spins
/// freely), and the solve holds the spin, theta . a = 0, with a spring
/// k a (a . theta) in its rotation rows. Every moment about the line
/// being zero at any pose, the spring's moment is zero at the solution:
/// the equilibrium is the one without it (docs/method.md §15.10).
pub(super) fn spin_axis(body: &super::Body, points: &[[f64; 3]]) -> Option<[f64; 3]> {
    use crate::vec3::{cross, norm, scale, sub};
    if let Some(w) = &body.water {
        if w.current != [0.0; 3] && w.drag_areas != [0.0; 3] {
            return None;
        }
    }
    let mut all = vec![body.inertia.centre_of_mass];
    all.extend(body.pin.map(|pin| pin.local));
    all.extend(body.loads.iter().map(|(_, at)| *at));
    all.extend_from_slice(points);
    if let Some(w) = &body.water {
        all.extend(w.rods.iter().flat_map(|r| [r.end_a, r.end_b]));
    }
    let (mut from, mut to, mut span) = (all[0], all[0], 0.0);
    for p in &all {
        for q in &all {
            let d = norm(sub(*p, *q));
            if d > span {
                (from, to, span) = (*p, *q, d);
            }
        }
    }
    if span == 0.0 {
        return None;
    }
    let axis = scale(1.0 / span, sub(to, from));
    let on_line = all
        .iter()
        .all(|p| norm(cross(sub(*p, from), axis)) <= 1e-9 * span);
    on_line.then_some(axis)
}

/// The vertical (body axes at t = 0) about which free body b and the
/// bodies hanging from it through joints (its assembly, §15.14) turn
/// freely, if they do: b is pinned to nothing, does not float on its rods
/// alone ([`FloatHold`] holds that yaw), and every line end on the
/// assembly is on one vertical line at t = 0 (to 1e-9 of the assembly's
/// size), with no current dragging it, no horizontal constant force and
/// no constant moment on it. Gravity and still water's buoyancy are the
/// same at any heading, so a turn of the whole assembly about that line
/// moves no line and changes no potential: its static rows are singular
/// there (MoorDyn's decks hold bodies by several lines at one point), and
/// the solve holds the turn with a spring k a (a . theta) on b's
/// rotation rows, a = R_0^T e_z. The equilibria form a family over the
/// heading, a . theta goes through zero along it, and there the spring's
/// moment is zero: the equilibrium is one without it (docs/method.md
/// §15.14).
pub(super) fn yaw_hold(system: &System, b: usize) -> Option<[f64; 3]> {
    use crate::vec3::{norm, sub};
    let root = &system.bodies()[b];
    let g = system.gravity();
    if root.pin.is_some() || floats(system, b) || g[0] != 0.0 || g[1] != 0.0 {
        return None;
    }
    let assembly: Vec<usize> = system
        .free_bodies()
        .filter(|&c| {
            let mut at = Some(c);
            while let Some(k) = at {
                if k == b {
                    return true;
                }
                at = system.joint_parent(k);
            }
            false
        })
        .collect();
    let mut ends = Vec::new();
    let mut size = 0.0f64;
    for &k in &assembly {
        let body = &system.bodies()[k];
        let dragged = body.water.as_ref().is_some_and(|w| {
            w.current != [0.0; 3]
                && (w.drag_areas != [0.0; 3]
                    || w.rods
                        .iter()
                        .any(|r| r.drag_coefficient != 0.0 || r.end_drag_coefficient != 0.0))
        });
        let level = body.loads.iter().all(|(f, _)| f[0] == 0.0 && f[1] == 0.0);
        if dragged || !level || body.moment != [0.0; 3] {
            return None;
        }
        for (p, pt) in system.points().iter().enumerate() {
            if pt.body() == Some(k) {
                size = size.max(norm(sub(pt.position, root.position)));
                if system.attachments(p).next().is_some() {
                    ends.push(pt.position);
                }
            }
        }
    }
    let first = *ends.first()?;
    let off = |p: &[f64; 3]| (p[0] - first[0]).hypot(p[1] - first[1]);
    let scale = size.max(1.0);
    ends.iter().all(|p| off(p) <= 1e-9 * scale).then(|| {
        let r = &root.rotation;
        [r[2][0], r[2][1], r[2][2]]
    })
}
