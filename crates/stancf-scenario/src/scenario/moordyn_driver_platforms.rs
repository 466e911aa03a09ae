//! A MoorDyn driver's initial platform offsets with its coupled objects
//! held (InputsMode 0; docs/interface.md "MoorDyn driver files",
//! docs/method.md §13.7): each platform row's surge, sway, heave (m) and
//! roll, pitch, yaw (the driver's degrees, taken to radians) place the
//! platform's coupled objects as MoorDyn-F's `MD_Init` (OpenFAST v4 on)
//! places them, with R the platform's rotation (D2):
//!
//! ```text
//!   x = t + R x_deck + ref                                           (D3)
//! ```
//!
//! (t the offsets, ref the turbine's reference position in FAST.Farm
//! mode, 0 in OpenFAST's). OpenFAST mode: the deck's coupled points, by
//! the one platform row. FAST.Farm mode (NumTurbines > 0): each turbine's
//! platform body (a coupled body at its reference position) moves to
//! ref + t and turns by R, with its `Turbine<n>` points on it; a deck's
//! own coupled points are on turbine 1, as MoorDyn-F counts them, and
//! take its row and its ref (with offsets or without). A coupled body or
//! rod of the deck's own (turbine 1's) with nonzero offsets on row 1 is
//! refused: moving it, its rods and its points by (D3) is not built.

use super::rod_parts::RodHolder;
use super::system_parts::{PointType, SystemScenario};
use super::ScenarioError;
use crate::moordyn::driver::DriverFile;
use crate::moordyn::{Attachment, Deck};
use stancf::body::pose::{moordyn_angles, openfast_platform_rotation, point, rotate};
use stancf::vec3::add;

/// The offsets t and rotation R of platform row `row` (D2), or None when
/// they are all zero.
fn offsets(row: &[f64; 8]) -> Option<([f64; 3], [[f64; 3]; 3])> {
    if row[2..].iter().all(|&v| v == 0.0) {
        return None;
    }
    let angles = [row[5], row[6], row[7]].map(f64::to_radians);
    Some(([row[2], row[3], row[4]], openfast_platform_rotation(angles)))
}

/// Places the coupled objects of `sc` (built from `deck`) by the driver's
/// platform rows (D3). Refused naming the driver's row: offsets with a
/// coupled body or rod of the deck's own.
pub(super) fn place(
    d: &DriverFile,
    deck: &Deck,
    sc: &mut SystemScenario,
    file: &str,
) -> Result<(), ScenarioError> {
    let turbine_bodies = turbine_bodies(deck, sc);
    for (k, row) in d.platforms.iter().enumerate() {
        let placed = offsets(row);
        // The deck's own coupled points are turbine 1's: its ref always
        // (FAST.Farm mode), its offsets if any.
        if k == 0 {
            let reference = if d.turbines > 0 {
                [row[0], row[1], 0.0]
            } else {
                [0.0; 3]
            };
            if placed.is_some() {
                refuse_coupled_bodies(d, row, sc, &turbine_bodies, file)?;
            }
            let (t, r) = placed.unwrap_or(([0.0; 3], openfast_platform_rotation([0.0; 3])));
            for p in sc
                .points
                .iter_mut()
                .filter(|p| p.kind == PointType::Coupled)
            {
                p.position = add(add(t, rotate(&r, p.position)), reference);
            }
        }
        let Some((t, r)) = placed else {
            continue;
        };
        sc.notes.push(format!(
            "{file}: line {}: initial platform offsets {:?} (surge, sway, heave in m; roll, \
             pitch, yaw in degrees) place {} as MoorDyn-F's MD_Init does, turned by the \
             platform's rotation R_z R_y R_x (docs/method.md (D2)-(D3))",
            d.lines[10] + k,
            &row[2..],
            if d.turbines > 0 {
                format!("turbine {}'s platform", k + 1)
            } else {
                "the coupled points".to_string()
            }
        ));
        if let Some(Some(b)) = turbine_bodies.get(k) {
            let body = &mut sc.bodies[*b];
            body.position = add(body.position, t);
            body.angles = moordyn_angles(&r);
            let position = body.position;
            for p in sc.points.iter_mut() {
                if let PointType::Body { body, local } = p.kind {
                    if body == *b {
                        p.position = point(position, &r, local);
                    }
                }
            }
        }
    }
    Ok(())
}

/// Refuses, naming the driver's first platform row, a coupled body of the
/// deck's own (not a turbine's platform) or a rod pinned to a coupled
/// point: moving them by (D3) is not built.
fn refuse_coupled_bodies(
    d: &DriverFile,
    row: &[f64; 8],
    sc: &SystemScenario,
    turbine_bodies: &[Option<usize>],
    file: &str,
) -> Result<(), ScenarioError> {
    let body = sc.bodies.iter().enumerate().find(|(b, body)| {
        (body.is_coupled() || body.host_pin.is_some()) && !turbine_bodies.contains(&Some(*b))
    });
    let pinned_rod = sc
        .rods
        .iter()
        .find(|r| matches!(r.holder, RodHolder::Pinned { coupled: true, .. }));
    let what = match (body, pinned_rod) {
        (_, Some(rod)) => format!("rod {}", rod.id),
        (Some((_, body)), None) => format!("body {} of the system", body.id),
        (None, None) => return Ok(()),
    };
    Err(ScenarioError(format!(
        "{file}: line {}: initial platform offsets {:?} (surge, sway, heave, roll, pitch, yaw) \
         with a coupled body or rod of the deck ({what}): moving it, its rods and its points \
         by the offsets is not built; give zeros and place it in the deck",
        d.lines[10],
        &row[2..],
    )))
}

/// The index in `sc.bodies` of turbine n's platform body (n = 1, 2, ...
/// at index n - 1; None for a turbine no point is on), found through the
/// deck's `Turbine<n>` points.
fn turbine_bodies(deck: &Deck, sc: &SystemScenario) -> Vec<Option<usize>> {
    let mut bodies = Vec::new();
    for p in &deck.points {
        let Attachment::Turbine(n) = p.attachment else {
            continue;
        };
        let on = sc.points.iter().find(|q| q.id == p.id as i64);
        if let Some(PointType::Body { body, .. }) = on.map(|q| q.kind) {
            if bodies.len() < n {
                bodies.resize(n, None);
            }
            bodies[n - 1] = Some(body);
        }
    }
    bodies
}

/// With InputsMode 1 the inputs' positions place the coupled points from
/// their first row, so a platform row's offsets move nothing: noted.
pub(super) fn superseded_note(d: &DriverFile, sc: &mut SystemScenario, file: &str) {
    for (k, row) in d.platforms.iter().enumerate() {
        if offsets(row).is_some() {
            sc.notes.push(format!(
                "{file}: line {}: initial platform offsets {:?}: with InputsMode 1 the coupled \
                 points start at the inputs' first positions, which the offsets do not move",
                d.lines[10] + k,
                &row[2..]
            ));
        }
    }
}
