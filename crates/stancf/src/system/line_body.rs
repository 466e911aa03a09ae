//! A free body whose mass lies on one line through its centre (point
//! masses on a line, MoorDyn's orbitalBody deck; docs/method.md §15.2,
//! (B2a)).
//!
//! Its second moment (B2) is J_G = a n n^T (n the line's direction in
//! body axes, a = int |xi|^2 dm), so I_G = a (1 - n n^T) has no moment
//! about n and the body's mass matrix is singular: its spin about the
//! line moves none of its mass. If nothing acts on the body off the line
//! (its points, loads and pin on the line, no water but a volume, whose
//! buoyancy acts at the centre of mass, no constant moment), the moment
//! about the centre of mass is r x F with r along n, so M . n = 0. With
//! the moment about the line completed to a,
//!
//! ```text
//!   I_G = a 1,   a omega_dot = M,   d(omega . n)/dt = (M . n)/a + omega . (omega x n) = 0   (B2a)
//! ```
//!
//! and a body that starts without spin about its line never has one: the
//! line turns as the mass on it does (a omega_perp_dot = M, the
//! dumbbell's dL/dt = M with L = a omega_perp), exactly.

use super::Body;
use crate::error::ModelError;
use crate::vec3::{dot, norm, sub};

/// Completes the inertia of free body `body` (key `key`) by (B2a) if its
/// mass lies on a line through its centre, `points` the body coordinates
/// of its points: whether it did. Refused by name where something acts
/// off the line (a moment about it that no inertia takes) or the body
/// starts spinning about it.
pub(super) fn complete_inertia_on_a_line(
    body: &mut Body,
    points: &[[f64; 3]],
    key: &str,
) -> Result<bool, ModelError> {
    let inertia = &body.inertia;
    // A rod has extent across its axis: a body of rods whose inertia is
    // singular is one of rods too thin, refused by (B2) as it was.
    let rods = body.water.as_ref().is_some_and(|w| !w.rods.is_empty()) || !body.rods.is_empty();
    if body.connector || rods || inertia.mass <= 0.0 || !inertia.mass.is_finite() {
        return Ok(false);
    }
    let j = inertia.second_moment_at_centre();
    let a = j[0][0] + j[1][1] + j[2][2];
    if !(a > 0.0 && a.is_finite()) {
        return Ok(false);
    }
    // n along J_G's largest column; rank 1 if J_G = a n n^T.
    let k = (0..3)
        .max_by(|&p, &q| j[p][p].total_cmp(&j[q][q]))
        .expect("three columns");
    let column = [j[0][k], j[1][k], j[2][k]];
    let n = crate::vec3::normalized(column);
    let off = (0..9)
        .map(|e| (j[e / 3][e % 3] - a * n[e / 3] * n[e % 3]).abs())
        .fold(0.0, f64::max);
    if off > 1e-9 * a {
        return Ok(false);
    }
    let centre = inertia.centre_of_mass;
    let spread = (a / inertia.mass).sqrt();
    let on_line = |p: [f64; 3]| {
        let d: [f64; 3] = std::array::from_fn(|i| p[i] - centre[i]);
        let along = dot(d, n);
        let across: [f64; 3] = std::array::from_fn(|i| d[i] - along * n[i]);
        norm(across) <= 1e-9 * spread.max(norm(d))
    };
    let refuse = |what: String| {
        Err(ModelError::invalid(
            key,
            format!(
                "its mass lies on a line through its centre of mass (direction {n:?} in body \
                 axes), so it has no inertia about that line, and {what}, which would turn it \
                 about the line (docs/method.md (B2a))"
            ),
        ))
    };
    for p in points {
        if !on_line(*p) {
            return refuse(format!("its point at {p:?} (body axes) is off the line"));
        }
    }
    for (_, at) in &body.loads {
        if !on_line(*at) {
            return refuse(format!("a force acts off the line, at {at:?} (body axes)"));
        }
    }
    if let Some(pin) = &body.pin {
        if !on_line(pin.local) {
            return refuse(format!(
                "its pin at {:?} (body axes) is off the line",
                pin.local
            ));
        }
    }
    if body.moment != [0.0; 3] {
        return refuse("a constant moment acts on it".into());
    }
    if let Some(w) = &body.water {
        let bare = w.added_mass_coefficients == [0.0; 3]
            && w.drag_areas == [0.0; 3]
            && w.rotational_drag_areas == [0.0; 3]
            && w.external.is_zero();
        if !bare {
            return refuse("its water's drag, added mass or external loads act on it".into());
        }
    }
    // The line's direction in global axes: R n.
    let axis = sub(body.point(n), body.position);
    let spin = dot(body.angular_velocity, axis);
    let omega = norm(body.angular_velocity);
    if spin.abs() > 1e-12 * omega {
        return refuse(format!("it starts spinning about the line at {spin} rad/s"));
    }
    for (r, row) in body.inertia.inertia_at_centre.iter_mut().enumerate() {
        for (c, entry) in row.iter_mut().enumerate() {
            *entry += a * n[r] * n[c];
        }
    }
    Ok(true)
}
