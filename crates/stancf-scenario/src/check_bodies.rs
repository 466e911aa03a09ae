//! What `stancf check` says of a system's rigid bodies (docs/method.md
//! §15) and of its degrees of freedom.

use crate::scenario::{PointType, SystemScenario};
use stancf::error::Sig;
use stancf::system::System;

/// A vector as `check` writes it, `[x, y, z]`.
fn v3(v: [f64; 3]) -> String {
    format!("[{}, {}, {}]", Sig(v[0]), Sig(v[1]), Sig(v[2]))
}

/// One line per body: its kind, its mass, inertia and water (a free
/// body's), its pose (reference point and MoorDyn's roll, pitch and yaw)
/// and its points.
pub fn body_words(sc: &SystemScenario) -> Vec<(String, String)> {
    sc.bodies
        .iter()
        .enumerate()
        .map(|(b, body)| {
            let points = sc
                .points
                .iter()
                .filter(|p| matches!(p.kind, PointType::Body { body: on, .. } if on == b))
                .map(|p| p.id.to_string())
                .collect::<Vec<_>>();
            let what = if body.is_free() {
                let water = if sc.water.is_some() {
                    format!(
                        ", volume {} m^3, CdA {} m^2, rotational CdA {}, Ca {}",
                        Sig(body.volume),
                        v3(body.drag_areas),
                        v3(body.rotational_drag_areas),
                        v3(body.ca)
                    )
                } else {
                    String::new()
                };
                format!(
                    "free (6 degrees of freedom), mass {} kg, centre of mass {} m, moments {} \
                     kg m^2{water}",
                    Sig(body.mass),
                    v3(body.centre_of_mass),
                    v3(body.moments)
                )
            } else {
                "fixed".to_string()
            };
            let points = match points.len() {
                0 => "no points".to_string(),
                1 => format!("point {}", points[0]),
                _ => format!("points {}", points.join(", ")),
            };
            (
                format!("body {}", body.id),
                format!(
                    "{what}; reference point at {} m, roll, pitch, yaw {} deg; {points}",
                    v3(body.position),
                    v3(body.angles)
                ),
            )
        })
        .collect()
}

/// The system's degrees of freedom: the lines' nodal coordinates, less 3
/// at every attached line end (its position is its point's), plus 3 per
/// free point and 6 per free body, less 2 per clamped end (its
/// direction).
pub fn dof_words(sc: &SystemScenario, system: &System) -> String {
    let coordinates: usize = system.lines().iter().map(|l| l.model.dofs()).sum();
    let ends: usize = sc
        .lines
        .iter()
        .map(|l| l.ends.iter().flatten().count())
        .sum();
    let free_points = sc
        .points
        .iter()
        .filter(|p| p.kind == PointType::Free)
        .count();
    let free_bodies = sc.bodies.iter().filter(|b| b.is_free()).count();
    let clamps: usize = sc
        .lines
        .iter()
        .map(|l| l.clamps.iter().flatten().count())
        .sum();
    let dofs = coordinates + 3 * free_points + 6 * free_bodies - 3 * ends - 2 * clamps;
    let mut parts = vec![format!("{coordinates} nodal coordinates of the lines")];
    parts.push(format!("less 3 at each of {ends} attached line ends"));
    if free_points > 0 {
        parts.push(format!("3 per free point ({free_points})"));
    }
    if free_bodies > 0 {
        parts.push(format!("6 per free body ({free_bodies})"));
    }
    if clamps > 0 {
        parts.push(format!("less 2 per clamped end ({clamps})"));
    }
    format!("{dofs} ({})", parts.join(", "))
}
