//! MoorDyn-F's `EXTERNAL LOADS` section (its docs, "External Loads
//! (MoorDyn-F only)"; docs/method.md §15.21): `ID Object Fext Blin Bquad
//! CSys`, a constant force and linear and quadratic damping on a point or
//! a body.
//!
//! - `Object` is `Body<n>` or `Point<n>` (any case); each of `Fext`,
//!   `Blin`, `Bquad` is three bar-separated values (`x|y|z`).
//! - On a body they act at its reference point, along the global axes
//!   when `CSys` is `G` and along the body's when it is `L` (MoorDyn-F
//!   takes no other word for a body); on a point, along the global axes
//!   whatever `CSys` says (MoorDyn-F warns when it is not `-`; stancf
//!   notes it).
//! - Several rows on one object add up.
//! - Refused by row: a rod (MoorDyn-F damps it along and across its axis
//!   from end A; stancf does not build that), an object the deck does not
//!   have, and one whose motion is given (a fixed or coupled point or
//!   body, whose external loads MoorDyn-F adds to the force it reports).

use super::bodies::{bars, BodyAttachment, DeckBody};
use super::layout::{Row, Section};
use super::sections::{columns, count};
use super::{Attachment, DeckError, DeckPoint};

/// What an external load acts on.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum LoadedObject {
    /// `Body<n>`, n from 1.
    Body(usize),
    /// `Point<n>`, n from 1.
    Point(usize),
}

/// The axes an external load on a body is given in.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum LoadAxes {
    /// `G`: global.
    Global,
    /// `L`: the body's own, turning with it.
    Body,
}

/// A row of `EXTERNAL LOADS`.
#[derive(Debug, Clone, PartialEq)]
pub struct DeckExternalLoad {
    /// 1-based line number in the file.
    pub line: usize,
    pub id: usize,
    pub object: LoadedObject,
    /// `Fext` (N).
    pub force: [f64; 3],
    /// `Blin` (N s/m).
    pub linear: [f64; 3],
    /// `Bquad` (N s^2/m^2).
    pub quadratic: [f64; 3],
    /// `CSys` (a point's are always global).
    pub axes: LoadAxes,
    /// `CSys` as written.
    pub axes_word: String,
}

const COLUMNS: &str = "ID Object Fext Blin Bquad CSys";

/// The rows of `EXTERNAL LOADS`, checked against the deck's points and
/// bodies.
pub(crate) fn external_loads(
    s: &Section,
    points: &[DeckPoint],
    bodies: &[DeckBody],
) -> Result<Vec<DeckExternalLoad>, DeckError> {
    let mut out = Vec::new();
    for row in &s.rows {
        columns(row, 6, "EXTERNAL LOADS", COLUMNS)?;
        let id = count(row, 0, "the external load ID")?;
        let object = object(row, points, bodies)?;
        let three = |col: usize, name: &str, non_negative: bool| -> Result<[f64; 3], DeckError> {
            let what = format!("{name} of external load {id}");
            match bars(row, col, &what, non_negative)?.as_slice() {
                [x, y, z] => Ok([*x, *y, *z]),
                v => Err(DeckError::at(
                    row.line,
                    format!(
                        "{what} has {} bar-separated values (\"{}\"); a point's or a body's \
                         takes three (x|y|z)",
                        v.len(),
                        row.words[col]
                    ),
                )),
            }
        };
        let force = three(2, "Fext", false)?;
        let linear = three(3, "Blin", true)?;
        let quadratic = three(4, "Bquad", true)?;
        let word = row.words[5];
        let axes = match (object, word.to_ascii_uppercase().as_str()) {
            (LoadedObject::Body(_), "G") => LoadAxes::Global,
            (LoadedObject::Body(_), "L") => LoadAxes::Body,
            (LoadedObject::Body(n), _) => {
                return Err(DeckError::at(
                    row.line,
                    format!(
                        "CSys of external load {id} is \"{word}\"; on body {n} it is G (global \
                         axes) or L (the body's), as MoorDyn-F reads it"
                    ),
                ))
            }
            (LoadedObject::Point(_), _) => LoadAxes::Global,
        };
        out.push(DeckExternalLoad {
            line: row.line,
            id,
            object,
            force,
            linear,
            quadratic,
            axes,
            axes_word: word.to_string(),
        });
    }
    Ok(out)
}

/// `Object`: a free point or a free body of the deck.
fn object(row: &Row, points: &[DeckPoint], bodies: &[DeckBody]) -> Result<LoadedObject, DeckError> {
    let word = row.words[1];
    let lower = word.to_ascii_lowercase();
    let split = lower
        .find(|c: char| c.is_ascii_digit())
        .unwrap_or(lower.len());
    let (kind, number) = lower.split_at(split);
    let n: usize = number.parse().unwrap_or(0);
    let refuse = |why: String| Err(DeckError::at(row.line, why));
    match kind {
        "body" => match bodies.get(n.wrapping_sub(1)) {
            None => refuse(format!(
                "Object \"{word}\": the deck has no body {n} (its bodies are 1 to {})",
                bodies.len()
            )),
            Some(b)
                if matches!(
                    b.attachment,
                    BodyAttachment::Free | BodyAttachment::CoupledPinned
                ) =>
            {
                Ok(LoadedObject::Body(n))
            }
            Some(b) => refuse(format!(
                "Object \"{word}\": body {n} is {}; external loads act on a free body only \
                 (a fixed or coupled body's motion is given, and MoorDyn-F adds them to the \
                 force it reports, which stancf does not)",
                b.attachment_word
            )),
        },
        "point" => match points.get(n.wrapping_sub(1)) {
            None => refuse(format!(
                "Object \"{word}\": the deck has no point {n} (its points are 1 to {})",
                points.len()
            )),
            Some(p) if p.attachment == Attachment::Free => Ok(LoadedObject::Point(n)),
            Some(_) => refuse(format!(
                "Object \"{word}\": point {n} is not free; external loads act on a free point \
                 only (a fixed or coupled point's motion is given; a point on a body: load \
                 the body)"
            )),
        },
        "rod" => refuse(format!(
            "Object \"{word}\": external loads on a rod are not supported (MoorDyn-F applies \
             the force at end A and damps the rod across and along its axis)"
        )),
        _ => refuse(format!(
            "Object \"{word}\" is not Body<n> or Point<n> (nor MoorDyn-F's Rod<n>)"
        )),
    }
}

/// Sum of the external loads on body `n` (id from 1): (the global force,
/// the body-axes force, the global damping, the body-axes damping).
pub fn on_body(
    loads: &[DeckExternalLoad],
    n: usize,
) -> (
    [f64; 3],
    [f64; 3],
    stancf::damping::AxisDamping,
    stancf::damping::AxisDamping,
) {
    let mut global_force = [0.0; 3];
    let mut body_force = [0.0; 3];
    let mut global = stancf::damping::AxisDamping::default();
    let mut body = stancf::damping::AxisDamping::default();
    for l in loads.iter().filter(|l| l.object == LoadedObject::Body(n)) {
        let (force, damping) = match l.axes {
            LoadAxes::Global => (&mut global_force, &mut global),
            LoadAxes::Body => (&mut body_force, &mut body),
        };
        add_load(l, force, damping);
    }
    (global_force, body_force, global, body)
}

/// Sum of the external loads on point `n` (id from 1): (the force, the
/// damping), global.
pub fn on_point(loads: &[DeckExternalLoad], n: usize) -> ([f64; 3], stancf::damping::AxisDamping) {
    let mut force = [0.0; 3];
    let mut damping = stancf::damping::AxisDamping::default();
    for l in loads.iter().filter(|l| l.object == LoadedObject::Point(n)) {
        add_load(l, &mut force, &mut damping);
    }
    (force, damping)
}

fn add_load(
    l: &DeckExternalLoad,
    force: &mut [f64; 3],
    damping: &mut stancf::damping::AxisDamping,
) {
    for k in 0..3 {
        force[k] += l.force[k];
        damping.linear[k] += l.linear[k];
        damping.quadratic[k] += l.quadratic[k];
    }
}
