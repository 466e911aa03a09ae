//! The `ROD TYPES` and `RODS` sections (MoorDyn-C's `readRodProps` and
//! `readRod`, docs/moordyn-bodies-rods.md §1.2-§1.3) and the line ends
//! at rod ends (`R<n>A`, `Rod<n>B`, §1.5), column for column.
//!
//! - ROD TYPES: `TypeName Diam Mass/m Cd Ca CdEnd CaEnd` (further
//!   columns ignored, as MoorDyn ignores them); names matched exactly.
//! - RODS: `ID RodType Attachment Xa Ya Za Xb Yb Zb NumSegs RodOutputs`.
//!   The attachment is read as MoorDyn's `decomposeString` splits it
//!   (letters, digits, letters): `Fixed`, `Fix`, `Anchor` hold the rod
//!   (global ends); `Free`, `Point`, `Con` free it; `Body<n>` fixes it in
//!   body n (ends in the body's axes from its reference point);
//!   `Pinned`, `Pin` (digits after it ignored: `Pinned1`) pin its end A
//!   where it is (global ends), `Body<n>Pinned`, `Body<n>Pin` at body
//!   n's point (body axes), the rod turning freely about it (§1.3);
//!   `CoupledPinned`, `VesselPinned`, `VesPin`, `CpldPin` pin its end A
//!   to a point the host moves (global ends); `Coupled`, `Vessel`, `Ves`,
//!   `Cpld` make it a coupled rod, moved by the host in six degrees of
//!   freedom (global ends at the pose the host gives as zero). Any other
//!   word is refused by name.

use super::ends::{decompose, LineAttachment};
use super::layout::{Row, Section};
use super::sections::{columns, count, non_negative, number, sequential};
use super::{DeckError, DeckLine};

/// A row of `ROD TYPES`.
#[derive(Debug, Clone, PartialEq)]
pub struct RodType {
    /// 1-based line number in the file.
    pub line: usize,
    /// `TypeName`, matched case-sensitively by the rods.
    pub name: String,
    /// `Diam` (m), > 0.
    pub diameter: f64,
    /// `Mass/m` (kg/m).
    pub mass_per_length: f64,
    /// `Cd`: drag across the rod (on d per length).
    pub cd: f64,
    /// `Ca`: added mass across the rod (on the volume).
    pub ca: f64,
    /// `CdEnd`: drag of each end cap (on pi d^2 / 4).
    pub cd_end: f64,
    /// `CaEnd`: added mass of each end cap (on pi d^3 / 12).
    pub ca_end: f64,
}

/// What holds a rod of a deck.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum RodAttachment {
    /// `Fixed`, `Fix` or `Anchor`: held where its ends are (global).
    Fixed,
    /// `Free`, `Point` or `Con`: six degrees of freedom (three for a rod
    /// of zero length, `NumSegs` = 0).
    Free,
    /// `Body<n>`: fixed in body n (its id, from 1), its ends in the
    /// body's axes from its reference point.
    Body(usize),
    /// `Pinned` or `Pin`: end A held where it is (global ends), the rod
    /// turning freely about it (three degrees of freedom).
    Pinned,
    /// `Body<n>Pinned` or `Body<n>Pin`: end A held at body n's point
    /// (its ends in the body's axes from its reference point), the rod
    /// turning freely about it.
    BodyPinned(usize),
    /// `CoupledPinned`, `VesselPinned`, `VesPin` or `CpldPin`: end A
    /// moved by the host (three coupled numbers), the rod turning freely
    /// about it.
    CoupledPinned,
    /// `Coupled`, `Vessel`, `Ves` or `Cpld`: moved by the host in six
    /// degrees of freedom (six coupled numbers: end A and MoorDyn's
    /// angles, which turn the rod from where its ends put it).
    Coupled,
}

/// A row of `RODS`.
#[derive(Debug, Clone, PartialEq)]
pub struct DeckRod {
    /// 1-based line number in the file.
    pub line: usize,
    /// `ID`, 1, 2, 3... in order.
    pub id: usize,
    /// Index of its type in [`super::Deck::rod_types`].
    pub type_index: usize,
    pub attachment: RodAttachment,
    /// `Xa Ya Za` (m).
    pub end_a: [f64; 3],
    /// `Xb Yb Zb` (m).
    pub end_b: [f64; 3],
    /// `NumSegs`: 0 (a rod of zero length, a point) or more.
    pub segments: usize,
    /// `RodOutputs` as written.
    pub outputs: String,
}

impl DeckRod {
    /// Whether MoorDyn would write a `_Rod<n>.out` file for this rod: one
    /// of the letters `pvUDctsd` is present (as `MoorDyn2.cpp` tests).
    pub fn wants_rod_file(&self) -> bool {
        self.outputs.chars().any(|c| "pvUDctsd".contains(c))
    }
}

const ROD_TYPE_COLUMNS: &str = "TypeName Diam Mass/m Cd Ca CdEnd CaEnd";
const ROD_COLUMNS: &str = "ID RodType Attachment Xa Ya Za Xb Yb Zb NumSegs RodOutputs";

/// `ROD TYPES` rows.
pub(crate) fn rod_types(s: &Section) -> Result<Vec<RodType>, DeckError> {
    let mut out: Vec<RodType> = Vec::new();
    for row in &s.rows {
        columns(row, 7, "ROD TYPES", ROD_TYPE_COLUMNS)?;
        let name = row.words[0];
        if let Some(first) = out.iter().find(|t| t.name == name) {
            return Err(DeckError::at(
                row.line,
                format!(
                    "rod type \"{name}\" is defined twice (first at line {})",
                    first.line
                ),
            ));
        }
        let what = |col: &str| format!("{col} of rod type \"{name}\"");
        out.push(RodType {
            line: row.line,
            name: name.to_string(),
            diameter: non_negative(row, 1, &what("Diam"), true)?,
            mass_per_length: non_negative(row, 2, &what("Mass/m"), false)?,
            cd: non_negative(row, 3, &what("Cd"), false)?,
            ca: non_negative(row, 4, &what("Ca"), false)?,
            cd_end: non_negative(row, 5, &what("CdEnd"), false)?,
            ca_end: non_negative(row, 6, &what("CaEnd"), false)?,
        });
    }
    Ok(out)
}

/// `RODS` rows, their types looked up in `types`.
pub(crate) fn rods(s: &Section, types: &[RodType]) -> Result<Vec<DeckRod>, DeckError> {
    let mut out = Vec::new();
    for row in &s.rows {
        columns(row, 11, "RODS", ROD_COLUMNS)?;
        let id = count(row, 0, "the rod ID")?;
        sequential(row, id, out.len() + 1, "rod")?;
        let attachment = attachment(row, id)?;
        let name = row.words[1];
        let Some(type_index) = types.iter().position(|t| t.name == name) else {
            let known: Vec<&str> = types.iter().map(|t| t.name.as_str()).collect();
            let known = if known.is_empty() {
                "none (the deck has no ROD TYPES rows)".to_string()
            } else {
                known.join(", ")
            };
            return Err(DeckError::at(
                row.line,
                format!(
                    "rod {id} uses rod type \"{name}\", which ROD TYPES does not define; \
                     known: {known}"
                ),
            ));
        };
        let what = |col: &str| format!("{col} of rod {id}");
        let coordinate = |col: usize, name: &str| number(row, col, &what(name));
        let segments = match row.words[9].parse::<usize>() {
            Ok(n) => n,
            Err(_) => {
                return Err(DeckError::at(
                    row.line,
                    format!(
                        "NumSegs of rod {id} is \"{}\"; it must be a whole number, 0 or more",
                        row.words[9]
                    ),
                ))
            }
        };
        out.push(DeckRod {
            line: row.line,
            id,
            type_index,
            attachment,
            end_a: [
                coordinate(3, "Xa")?,
                coordinate(4, "Ya")?,
                coordinate(5, "Za")?,
            ],
            end_b: [
                coordinate(6, "Xb")?,
                coordinate(7, "Yb")?,
                coordinate(8, "Zb")?,
            ],
            segments,
            outputs: row.words[10].to_string(),
        });
    }
    Ok(out)
}

/// The attachment of rod `id` (column 3), or its refusal by name.
fn attachment(row: &Row, id: usize) -> Result<RodAttachment, DeckError> {
    let w = row.words[2];
    let (let1, num1, let2) = decompose(w);
    let refuse =
        |why: &str| DeckError::at(row.line, format!("rod {id} is attached to \"{w}\": {why}"));
    match let1.as_str() {
        "ANCHOR" | "FIXED" | "FIX" => Ok(RodAttachment::Fixed),
        "POINT" | "CON" | "FREE" => Ok(RodAttachment::Free),
        // MoorDyn-C reads `Pinned1` as `Pinned` (the digits ignored).
        "PINNED" | "PIN" => Ok(RodAttachment::Pinned),
        "VESSELPINNED" | "VESPIN" | "CPLDPIN" | "COUPLEDPINNED" => Ok(RodAttachment::CoupledPinned),
        "VESSEL" | "VES" | "COUPLED" | "CPLD" => Ok(RodAttachment::Coupled),
        "BODY" => {
            let pinned = match let2.as_str() {
                "" => false,
                "PINNED" | "PIN" => true,
                _ => {
                    return Err(refuse(
                        "a rod on a body is written Body<n> (fixed in body n) or Body<n>Pinned",
                    ))
                }
            };
            match num1.parse::<usize>() {
                Ok(n) if n >= 1 && pinned => Ok(RodAttachment::BodyPinned(n)),
                Ok(n) if n >= 1 => Ok(RodAttachment::Body(n)),
                _ => Err(refuse(
                    "a rod on a body names the body's number, e.g. Body1",
                )),
            }
        }
        _ => Err(refuse(
            "unknown attachment; known: Fixed (Anchor, Fix), Free (Point, Con), Pinned (Pin), \
             Coupled (Vessel, Ves, Cpld), CoupledPinned (VesselPinned, VesPin, CpldPin), \
             Body<n> (fixed in body n), Body<n>Pinned",
        )),
    }
}

/// Checks what stands on the rods: the body of a `Body<n>` or
/// `Body<n>Pinned` rod exists,
/// and every rod a line end names exists.
pub(crate) fn check_rods(
    rods: &[DeckRod],
    bodies: usize,
    lines: &[DeckLine],
) -> Result<(), DeckError> {
    for r in rods {
        if let RodAttachment::Body(n) | RodAttachment::BodyPinned(n) = r.attachment {
            if n > bodies {
                return Err(DeckError::at(
                    r.line,
                    format!(
                        "rod {} is on body {n}, which BODIES does not define ({bodies} bodies)",
                        r.id
                    ),
                ));
            }
        }
    }
    for l in lines {
        for (end, a) in ["A", "B"].into_iter().zip([l.end_a, l.end_b]) {
            if let LineAttachment::Rod(n, _) = a {
                if n > rods.len() {
                    return Err(DeckError::at(
                        l.line,
                        format!(
                            "end {end} of line {} is attached to rod {n}, which RODS does not \
                             define ({} rods)",
                            l.id,
                            rods.len()
                        ),
                    ));
                }
            }
        }
    }
    Ok(())
}
