//! What `stancf check` says of a system's rigid bodies (docs/method.md
//! §15) and of its degrees of freedom.

use crate::scenario::{PointType, RodHolder, SystemScenario};
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
            let rods: Vec<String> = sc
                .rods
                .iter()
                .filter(|r| matches!(r.holder, RodHolder::Body { body } if body == b))
                .map(|r| r.id.to_string())
                .collect();
            let rods = match rods.len() {
                0 => String::new(),
                _ => format!("; rods {} fixed in it", rods.join(", ")),
            };
            let own_rod = sc.rods.iter().find(|r| r.own_body() == Some(b));
            let what = if let Some(r) = own_rod {
                let host = |p: usize| match sc.points[p].kind {
                    PointType::Coupled => " (a coupled point the host moves)",
                    _ => "",
                };
                match (r.holder, r.pin_point()) {
                    (RodHolder::Point { .. }, _) => format!(
                        "connector of rod {} (zero length: no mass or inertia; 5 degrees of \
                         freedom, its point's 3 and its axis's 2, turning to balance the moments \
                         of the lines clamped to it, docs/method.md §15.20)",
                        r.id
                    ),
                    (RodHolder::Coupled { .. }, _) => format!(
                        "coupled rod {} (moved by the host in 6 degrees of freedom, its reference \
                         point at end A; its weight, water and inertia push the host)",
                        r.id
                    ),
                    (_, Some(p)) => format!(
                        "pinned rod {} (3 degrees of freedom, turning about its end A held at \
                         point {}{}; its mass and water are the rod's)",
                        r.id,
                        sc.points[p].id,
                        host(p)
                    ),
                    (_, None) => format!(
                        "free rod {} (6 degrees of freedom; its mass and water are the rod's)",
                        r.id
                    ),
                }
            } else if body.is_free() {
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
                let held = match body.host_pin {
                    Some(p) => format!(
                        "pinned to the host (3 degrees of freedom, turning about its reference \
                         point on point {}, which a coupling code moves; held at its pose in a \
                         run)",
                        sc.points[p].id
                    ),
                    None => "free (6 degrees of freedom)".to_string(),
                };
                format!(
                    "{held}, mass {} kg, centre of mass {} m, moments {} kg m^2{water}",
                    Sig(body.mass),
                    v3(body.centre_of_mass),
                    v3(body.moments)
                )
            } else if body.is_coupled() {
                "coupled (moved by a coupling code; held at its pose in a run)".to_string()
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
                    "{what}; reference point at {} m, roll, pitch, yaw {} deg; {points}{rods}",
                    v3(body.position),
                    v3(body.angles)
                ),
            )
        })
        .collect()
}

/// The system's degrees of freedom: the lines' nodal coordinates, less 3
/// at every attached line end (its position is its point's), plus 3 per
/// free point and 6 per free body, less 3 per pinned body (its pinned
/// point's position) and 2 per clamped end (its direction).
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
    let pins = sc.rods.iter().filter_map(|r| r.pin_point()).count()
        + sc.bodies.iter().filter(|b| b.host_pin.is_some()).count();
    let clamps: usize = sc
        .lines
        .iter()
        .map(|l| l.clamps.iter().flatten().count())
        .sum();
    // A connector's spin about its axis is held.
    let connectors = sc
        .bodies
        .iter()
        .filter(|b| b.connector_axis.is_some())
        .count();
    let dofs = coordinates + 3 * free_points + 6 * free_bodies
        - 3 * ends
        - 3 * pins
        - 2 * clamps
        - connectors;
    let mut parts = vec![format!("{coordinates} nodal coordinates of the lines")];
    parts.push(format!("less 3 at each of {ends} attached line ends"));
    if free_points > 0 {
        parts.push(format!("3 per free point ({free_points})"));
    }
    if free_bodies > 0 {
        parts.push(format!("6 per free body ({free_bodies})"));
    }
    if pins > 0 {
        parts.push(format!("less 3 per pinned body ({pins})"));
    }
    if clamps > 0 {
        parts.push(format!("less 2 per clamped end ({clamps})"));
    }
    if connectors > 0 {
        parts.push(format!("less 1 per connector's spin ({connectors})"));
    }
    format!("{dofs} ({})", parts.join(", "))
}

/// The rods: how many, then one line per rod: what holds it, its type,
/// length and mass, whether it lies under the water (its water acts on
/// what moves), its ends and the points at them.
pub fn rod_words(sc: &SystemScenario) -> Vec<(String, String)> {
    if sc.rods.is_empty() {
        return Vec::new();
    }
    let mut out = vec![("rods".to_string(), sc.rods.len().to_string())];
    for r in &sc.rods {
        let holder = match r.holder {
            RodHolder::Fixed => "fixed (held where it is)".to_string(),
            RodHolder::Free { body } => format!("free, body {}", sc.bodies[body].id),
            RodHolder::Coupled { body } => format!(
                "coupled, body {} (moved by the host in six degrees of freedom; its weight, \
                 water and inertia push the host)",
                sc.bodies[body].id
            ),
            RodHolder::Pinned {
                body,
                host,
                coupled,
            } => format!(
                "pinned at end A to point {} ({}; the rod turns freely about it), body {}",
                r.pin_point().map_or(0, |p| sc.points[p].id),
                match host {
                    Some((h, _)) if sc.bodies[h].is_coupled() => {
                        format!("on coupled body {}, moved by the host", sc.bodies[h].id)
                    }
                    Some((h, _)) => format!("on free body {}, a joint", sc.bodies[h].id),
                    None if coupled => "coupled, moved by the host".to_string(),
                    None => "fixed".to_string(),
                },
                sc.bodies[body].id
            ),
            RodHolder::Body { body } => format!(
                "fixed in {} body {}",
                sc.bodies[body].type_word(),
                sc.bodies[body].id
            ),
            RodHolder::Point {
                point,
                connector: None,
            } => format!(
                "free of zero length (NumSegs 0): point {}, of no mass, carrying its lines",
                sc.points[point].id
            ),
            RodHolder::Point {
                point,
                connector: Some(body),
            } => format!(
                "free of zero length (NumSegs 0): point {}, of no mass, carrying its lines, and \
                 connector {} (a body of no mass), which its lines with bending stiffness are \
                 clamped to and which turns to balance their moments",
                sc.points[point].id, sc.bodies[body].id
            ),
        };
        let size = match &r.rod {
            Some(rod) => format!(
                ", length {} m, diameter {} m, mass {} kg",
                Sig(rod.length()),
                Sig(rod.diameter),
                Sig(rod.mass_per_length * rod.length())
            ),
            None => String::new(),
        };
        let water = match (&sc.water, &r.rod) {
            (None, _) => "in air",
            (Some(_), None) => "in water (no volume)",
            (Some(_), Some(_)) if !r.moves(&sc.bodies) => "its water unused (it does not move)",
            (Some(_), Some(_)) => r.waterline(),
        };
        let points: Vec<String> = ["A", "B"]
            .iter()
            .zip(r.points)
            .filter_map(|(e, p)| p.map(|p| format!("point {} at {e}", sc.points[p].id)))
            .collect();
        let points = match points.len() {
            0 => "no line attached".to_string(),
            _ => points.join(", "),
        };
        out.push((
            format!("rod {}", r.id),
            format!(
                "{holder}; type {}{size}; {water}; ends {} and {} m; {points}",
                crate::echo::clip(&r.type_name, 60),
                v3(r.ends[0]),
                v3(r.ends[1])
            ),
        ));
    }
    out
}
