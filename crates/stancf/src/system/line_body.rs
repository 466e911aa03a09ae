//! A free body whose mass lies on one line through its centre (point
//! masses on a line, MoorDyn's orbitalBody deck), or at its centre alone
//! (a point mass, OpenFAST's md_BdyExtLdDmpg; docs/method.md §15.2,
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

/// The line through the centre of mass that J_G (B2) of a body with mass
/// lies on: Some(Some(n)) for mass on a line (J_G = a n n^T, a > 0),
/// Some(None) for mass at the centre alone (J_G = 0), None otherwise.
fn mass_line(j: &[[f64; 3]; 3]) -> Option<Option<[f64; 3]>> {
    let a = j[0][0] + j[1][1] + j[2][2];
    if a == 0.0 && j.iter().flatten().all(|v| *v == 0.0) {
        return Some(None);
    }
    if !(a > 0.0 && a.is_finite()) {
        return None;
    }
    // n along J_G's largest column; rank 1 if J_G = a n n^T.
    let k = (0..3)
        .max_by(|&p, &q| j[p][p].total_cmp(&j[q][q]))
        .expect("three columns");
    let n = crate::vec3::normalized([j[0][k], j[1][k], j[2][k]]);
    let off = (0..9)
        .map(|e| (j[e / 3][e % 3] - a * n[e / 3] * n[e % 3]).abs())
        .fold(0.0, f64::max);
    (off <= 1e-9 * a).then_some(Some(n))
}

/// Completes the inertia of free body `body` (key `key`) by (B2a) if its
/// mass lies on a line through its centre, or at its centre alone (a
/// point mass: no inertia about any line, completed to m times 1 m^2 on
/// every axis, which the motion does not depend on), `points` the body
/// coordinates of its points: whether it did. Refused by name where
/// something acts off the line (a moment about it that no inertia takes)
/// or the body starts turning about it.
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
    let Some(line) = mass_line(&j) else {
        return Ok(false);
    };
    let a = match line {
        Some(_) => j[0][0] + j[1][1] + j[2][2],
        None => inertia.mass,
    };
    let centre = inertia.centre_of_mass;
    let spread = match line {
        Some(_) => (a / inertia.mass).sqrt(),
        None => 0.0,
    };
    let on_line = |p: [f64; 3]| {
        let d: [f64; 3] = std::array::from_fn(|i| p[i] - centre[i]);
        let across = match line {
            Some(n) => {
                let along = dot(d, n);
                std::array::from_fn(|i| d[i] - along * n[i])
            }
            None => d,
        };
        norm(across) <= 1e-9 * spread.max(norm(p)).max(norm(centre))
    };
    let refuse = |what: String| {
        let lies = match line {
            Some(n) => format!(
                "its mass lies on a line through its centre of mass (direction {n:?} in body \
                 axes), so it has no inertia about that line"
            ),
            None => "its mass is at its centre of mass alone (no moments of inertia), so it has \
                     no inertia about any line through it"
                .to_string(),
        };
        Err(ModelError::invalid(
            key,
            format!("{lies}, and {what}, which would turn it (docs/method.md (B2a))"),
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
            && w.rotational_drag_areas == [0.0; 3];
        if !bare {
            return refuse("its water's drag or added mass acts on it".into());
        }
        // MoorDyn-F's external force and damping act at the reference
        // point (B42)-(B43).
        if !w.external.is_zero() && !on_line([0.0; 3]) {
            return refuse("its external loads act at its reference point, off the line".into());
        }
    }
    // The spin about the line (global axes: R n); about any axis for mass
    // at the centre alone.
    let omega = norm(body.angular_velocity);
    let spin = match line {
        Some(n) => dot(body.angular_velocity, sub(body.point(n), body.position)),
        None => omega,
    };
    if spin.abs() > 1e-12 * omega {
        return refuse(format!("it starts spinning about the line at {spin} rad/s"));
    }
    for (r, row) in body.inertia.inertia_at_centre.iter_mut().enumerate() {
        for (c, entry) in row.iter_mut().enumerate() {
            *entry += a * match line {
                Some(n) => n[r] * n[c],
                None => f64::from(u8::from(r == c)),
            };
        }
    }
    Ok(true)
}
