//! The `BODIES` section (MoorDyn-C's `readBody`, docs/moordyn-bodies-rods.md
//! §1.1) and the `Body<n>` points on them: `ID Attachment X0 Y0 Z0 r0 p0 y0
//! Mass CG I Volume CdA Ca`, column for column.
//!
//! - `CG` is one value (z, the centre at (0, 0, z)) or `x|y|z`; `I` one
//!   value (the three moments) or `Ix|Iy|Iz`; `Ca` one value or three;
//!   `CdA` one value (all six drag areas), two (`translational|rotational`),
//!   three (x, y, z, each both translational and rotational) or six
//!   (translational x, y, z, then rotational x, y, z), as MoorDyn's
//!   documentation defines them. MoorDyn-C 2.7.1 drops the x value of a
//!   three- or six-value CdA (its loop starts at the second, §1.1 of the
//!   note); stancf takes them as documented.
//! - The attachment, matched on its first run of letters as MoorDyn's
//!   `decomposeString` does: `Fixed`, `Fix`, `Anchor` hold the body;
//!   `Coupled`, `Vessel`, `Ves`, `Cpld` make a coupled body, moved by a
//!   coupling code (docs/method.md §13.6); the pinned words
//!   (`CoupledPinned`, `VesselPinned`, `VesPin`, `CpldPin`) are free bodies
//!   pinned at their reference point to a point the host moves
//!   (docs/method.md §15.17); every other word is a free body, as
//!   MoorDyn-C takes it.

use super::layout::{Row, Section};
use super::sections::{columns, count, non_negative, number, sequential};
use super::{Attachment, DeckError, DeckPoint};

/// What holds a body of a deck.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum BodyAttachment {
    /// `Fixed`, `Fix` or `Anchor`: held at its pose.
    Fixed,
    /// `Coupled`, `Vessel`, `Ves` or `Cpld`: moved by a coupling code (its
    /// mass, inertia and water are the host's, as MoorDyn zeroes them).
    Coupled,
    /// `CoupledPinned`, `VesselPinned`, `VesPin` or `CpldPin`: its
    /// reference point moved by a coupling code, free to turn about it
    /// (its mass, inertia and water its own).
    CoupledPinned,
    /// Any other word MoorDyn-C reads as free (`Free`, `Body`, ...).
    Free,
}

/// A row of `BODIES`.
#[derive(Debug, Clone, PartialEq)]
pub struct DeckBody {
    /// 1-based line number in the file.
    pub line: usize,
    /// `ID`, 1, 2, 3... in order.
    pub id: usize,
    pub attachment: BodyAttachment,
    /// The attachment word as written.
    pub attachment_word: String,
    /// `X0 Y0 Z0` (m): the reference point, global.
    pub position: [f64; 3],
    /// `r0 p0 y0` (degrees): MoorDyn's roll, pitch and yaw (intrinsic
    /// x-y'-z'').
    pub angles: [f64; 3],
    /// `Mass` (kg).
    pub mass: f64,
    /// `CG` (m): the centre of mass in body axes from the reference point.
    pub centre_of_mass: [f64; 3],
    /// `I` (kg m^2): the moments about the centre of mass, body axes.
    pub moments: [f64; 3],
    /// `Volume` (m^3).
    pub volume: f64,
    /// `CdA` (m^2): translational drag areas, body axes.
    pub drag_areas: [f64; 3],
    /// `CdA` (rotational): the areas that multiply Omega |Omega|.
    pub rotational_drag_areas: [f64; 3],
    /// `Ca`: added-mass coefficients along the body axes, on the volume.
    pub ca: [f64; 3],
}

/// The number of columns MoorDyn reads in a BODIES row.
const BODY_COLUMNS: &str = "ID Attachment X0 Y0 Z0 r0 p0 y0 Mass CG I Volume CdA Ca";

/// `BODIES` rows.
pub(crate) fn bodies(s: &Section) -> Result<Vec<DeckBody>, DeckError> {
    let mut out = Vec::new();
    for row in &s.rows {
        columns(row, 14, "BODIES", BODY_COLUMNS)?;
        let id = count(row, 0, "the body ID")?;
        sequential(row, id, out.len() + 1, "body")?;
        let what = |col: &str| format!("{col} of body {id}");
        let attachment = attachment(row)?;
        let position = [
            number(row, 2, &what("X0"))?,
            number(row, 3, &what("Y0"))?,
            number(row, 4, &what("Z0"))?,
        ];
        let angles = [
            number(row, 5, &what("r0"))?,
            number(row, 6, &what("p0"))?,
            number(row, 7, &what("y0"))?,
        ];
        let cg = bars(row, 9, &what("CG"), false)?;
        let centre_of_mass = match cg.as_slice() {
            [z] => [0.0, 0.0, *z],
            [x, y, z] => [*x, *y, *z],
            _ => return Err(counts(row, 9, &what("CG"), cg.len(), "1 (z) or 3 (x|y|z)")),
        };
        let i = bars(row, 10, &what("I"), true)?;
        let moments = match i.as_slice() {
            [m] => [*m; 3],
            [x, y, z] => [*x, *y, *z],
            _ => return Err(counts(row, 10, &what("I"), i.len(), "1 or 3 (Ix|Iy|Iz)")),
        };
        let (drag_areas, rotational_drag_areas) = drag_areas(row, &what("CdA"))?;
        let ca = bars(row, 13, &what("Ca"), true)?;
        let ca = match ca.as_slice() {
            [c] => [*c; 3],
            [x, y, z] => [*x, *y, *z],
            _ => return Err(counts(row, 13, &what("Ca"), ca.len(), "1 or 3 (x|y|z)")),
        };
        out.push(DeckBody {
            line: row.line,
            id,
            attachment,
            attachment_word: row.words[1].to_string(),
            position,
            angles,
            mass: non_negative(row, 8, &what("Mass"), false)?,
            centre_of_mass,
            moments,
            volume: non_negative(row, 11, &what("Volume"), false)?,
            drag_areas,
            rotational_drag_areas,
            ca,
        });
    }
    Ok(out)
}

/// The attachment of a body: fixed, coupled, coupled pinned or free (any
/// other word, as MoorDyn-C reads it); `Turbine<n>`, a body on a farm's
/// turbine in MoorDyn-F, refused rather than read as free.
fn attachment(row: &Row) -> Result<BodyAttachment, DeckError> {
    let w = row.words[1];
    let upper = w.to_ascii_uppercase();
    let letters: String = upper
        .chars()
        .take_while(|c| c.is_ascii_alphabetic())
        .collect();
    Ok(match letters.as_str() {
        "ANCHOR" | "FIXED" | "FIX" => BodyAttachment::Fixed,
        "VESSEL" | "VES" | "COUPLED" | "CPLD" => BodyAttachment::Coupled,
        "VESSELPINNED" | "VESPIN" | "CPLDPIN" | "COUPLEDPINNED" => BodyAttachment::CoupledPinned,
        "TURBINE" if upper.len() > letters.len() => {
            return Err(DeckError::at(
                row.line,
                format!(
                    "body {} is attached to \"{w}\", a farm's turbine (FAST.Farm): a body on a \
                     turbine is not supported (points on turbines are); MoorDyn-C would read \
                     it as a free body",
                    row.words[0]
                ),
            ))
        }
        _ => BodyAttachment::Free,
    })
}

/// The bar-separated values of column `col` (`a|b|c`), each a finite
/// number (`non_negative`: also >= 0).
pub(crate) fn bars(
    row: &Row,
    col: usize,
    what: &str,
    non_negative: bool,
) -> Result<Vec<f64>, DeckError> {
    let w = row.words[col];
    let mut out = Vec::new();
    for (k, piece) in w.split('|').enumerate() {
        let v = match piece.parse::<f64>() {
            Ok(v) if v.is_finite() => v,
            _ => {
                let which = if w.contains('|') {
                    format!(" (value {} of \"{w}\")", k + 1)
                } else {
                    String::new()
                };
                return Err(DeckError::at(
                    row.line,
                    format!("{what} is \"{piece}\"{which}, which is not a finite number"),
                ));
            }
        };
        if non_negative && v < 0.0 {
            return Err(DeckError::at(
                row.line,
                format!("{what} is \"{w}\"; its values must be zero or positive"),
            ));
        }
        out.push(v);
    }
    Ok(out)
}

/// The error of column `col` holding `n` values where MoorDyn reads
/// `allowed`.
fn counts(row: &Row, col: usize, what: &str, n: usize, allowed: &str) -> DeckError {
    DeckError::at(
        row.line,
        format!(
            "{what} has {n} bar-separated values (\"{}\"); MoorDyn reads {allowed}",
            row.words[col]
        ),
    )
}

/// `CdA`: 1 value (all six areas), 2 (`translational|rotational`), 3
/// (x, y, z for both) or 6 (translational x, y, z, rotational x, y, z), as
/// MoorDyn's documentation defines them (MoorDyn-C 2.7.1 drops the first
/// of 3 or 6 values; stancf does not).
fn drag_areas(row: &Row, what: &str) -> Result<([f64; 3], [f64; 3]), DeckError> {
    let v = bars(row, 12, what, true)?;
    Ok(match v.as_slice() {
        [c] => ([*c; 3], [*c; 3]),
        [t, r] => ([*t; 3], [*r; 3]),
        [x, y, z] => ([*x, *y, *z], [*x, *y, *z]),
        [x, y, z, rx, ry, rz] => ([*x, *y, *z], [*rx, *ry, *rz]),
        _ => {
            return Err(counts(
                row,
                12,
                what,
                v.len(),
                "1, 2 (translational|rotational), 3 (x|y|z) or 6 (x|y|z|rx|ry|rz)",
            ))
        }
    })
}

/// Checks the points on a farm's turbines (`Turbine<n>`,
/// [`Attachment::Turbine`]): like a point on a coupled body, none carries
/// a mass, volume, drag or added mass of its own (the platform's are the
/// turbine model's).
pub(crate) fn check_turbine_points(points: &[DeckPoint]) -> Result<(), DeckError> {
    for p in points {
        let Attachment::Turbine(n) = p.attachment else {
            continue;
        };
        if [p.mass, p.volume, p.cda, p.ca].iter().any(|v| *v != 0.0) {
            return Err(DeckError::at(
                p.line,
                format!(
                    "point {} is on turbine {n} with Mass {}, Volume {}, CdA {} and Ca {}: a \
                     point on a turbine's platform carries no mass, volume or drag of its own \
                     (the platform's are the turbine model's)",
                    p.id, p.mass, p.volume, p.cda, p.ca
                ),
            ));
        }
    }
    Ok(())
}

/// Checks the points on bodies (`Body<n>`, [`Attachment::Body`]): body n
/// exists, and the point carries no drag or added mass of its own (nor a
/// mass or volume on a fixed or coupled body).
pub(crate) fn check_body_points(
    points: &[DeckPoint],
    bodies: &[DeckBody],
) -> Result<(), DeckError> {
    for p in points {
        let Attachment::Body(n) = p.attachment else {
            continue;
        };
        if n == 0 || n > bodies.len() {
            return Err(DeckError::at(
                p.line,
                format!(
                    "point {} is on body {n}, which BODIES does not define ({} bodies)",
                    p.id,
                    bodies.len()
                ),
            ));
        }
        // Its mass and volume join a free body (docs/method.md §15.8);
        // its drag and added mass are not built.
        let free = bodies[n - 1].attachment == BodyAttachment::Free;
        let own = if free {
            [p.cda, p.ca]
        } else {
            [p.mass + p.volume.abs(), p.cda.abs() + p.ca.abs()]
        };
        if own.iter().any(|&v| v != 0.0) {
            return Err(DeckError::at(
                p.line,
                format!(
                    "point {} is on body {n} with Mass {}, Volume {}, CdA {} and Ca {}: {}",
                    p.id,
                    p.mass,
                    p.volume,
                    p.cda,
                    p.ca,
                    if free {
                        "the drag and added mass of a point on a body are not built (give them \
                         to the body, or set CdA and Ca to 0)"
                    } else {
                        "a point on a fixed or coupled body carries no mass, volume or drag of \
                         its own (a coupled body's are the coupling code's)"
                    }
                ),
            ));
        }
    }
    Ok(())
}
