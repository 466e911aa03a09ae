//! The table sections: `LINE TYPES`, `POINTS`, `LINES` (`BODIES` is
//! `bodies.rs`, `ROD TYPES` and `RODS` `rods.rs`), and the refusal of the sections stancf cannot represent.

use super::ends::{rod_end, LineAttachment};
use super::layout::{Row, Section, SectionKind};
use super::{Attachment, DeckError, DeckLine, DeckPoint, LineType};

/// A finite number, or an error naming the column and the row's object.
pub(crate) fn number(row: &Row, col: usize, what: &str) -> Result<f64, DeckError> {
    let w = row.words[col];
    match w.parse::<f64>() {
        Ok(v) if v.is_finite() => Ok(v),
        Ok(_) => Err(DeckError::at(
            row.line,
            format!("{what} is \"{w}\", which is not a finite number"),
        )),
        Err(_) => Err(DeckError::at(
            row.line,
            format!("{what} is \"{w}\", which is not a number"),
        )),
    }
}

/// A number that must be ≥ 0 (`strict`: > 0).
pub(crate) fn non_negative(
    row: &Row,
    col: usize,
    what: &str,
    strict: bool,
) -> Result<f64, DeckError> {
    let v = number(row, col, what)?;
    if v < 0.0 || (strict && v == 0.0) {
        let bound = if strict {
            "positive"
        } else {
            "zero or positive"
        };
        return Err(DeckError::at(
            row.line,
            format!("{what} is {v}; it must be {bound}"),
        ));
    }
    Ok(v)
}

/// A whole number ≥ 1.
pub(crate) fn count(row: &Row, col: usize, what: &str) -> Result<usize, DeckError> {
    let w = row.words[col];
    match w.parse::<usize>() {
        Ok(n) if n >= 1 => Ok(n),
        _ => Err(DeckError::at(
            row.line,
            format!("{what} is \"{w}\"; it must be a whole number, 1 or more"),
        )),
    }
}

/// `NumSegs`: 1 to the most elements a line may have
/// ([`stancf::model::MAX_ELEMENTS`]).
fn segments(row: &Row, what: &str) -> Result<usize, DeckError> {
    let max = stancf::model::MAX_ELEMENTS;
    let n = row.words[5];
    match n.parse::<u128>() {
        Ok(k) if k > max as u128 => Err(DeckError::at(
            row.line,
            format!("{what} is {n}, above the {max} segments a line may have"),
        )),
        _ => count(row, 5, what),
    }
}

/// At least `min` words, or an error naming the columns expected.
pub(crate) fn columns(row: &Row, min: usize, section: &str, names: &str) -> Result<(), DeckError> {
    if row.words.len() < min {
        return Err(DeckError::at(
            row.line,
            format!(
                "{section} rows have {min} columns ({names}); this one has {}",
                row.words.len()
            ),
        ));
    }
    Ok(())
}

/// The ids of a table must be 1, 2, 3... in order, as MoorDyn requires.
pub(crate) fn sequential(
    row: &Row,
    id: usize,
    expected: usize,
    what: &str,
) -> Result<(), DeckError> {
    if id != expected {
        let detail = if id < expected {
            format!("{what} {id} is defined twice or out of order")
        } else {
            format!("{what} {expected} is missing")
        };
        return Err(DeckError::at(
            row.line,
            format!("{what} ids must be 1, 2, 3... in order: expected {expected}, found {id} ({detail})"),
        ));
    }
    Ok(())
}

const LINE_TYPE_COLUMNS: &str = "TypeName Diam Mass/m EA BA/-zeta EI Cd Ca CdAx CaAx";

/// `LINE TYPES` rows.
pub(crate) fn line_types(s: &Section) -> Result<Vec<LineType>, DeckError> {
    let mut out: Vec<LineType> = Vec::new();
    for row in &s.rows {
        let t = line_type(row)?;
        if let Some(first) = out.iter().find(|o| o.name == t.name) {
            return Err(DeckError::at(
                row.line,
                format!(
                    "line type \"{}\" is defined twice (first at line {})",
                    t.name, first.line
                ),
            ));
        }
        out.push(t);
    }
    Ok(out)
}

fn line_type(row: &Row) -> Result<LineType, DeckError> {
    if row.words.len() == 9 {
        return Err(DeckError::at(
            row.line,
            format!(
                "LINE TYPES rows have 10 columns ({LINE_TYPE_COLUMNS}); this one has 9, as the \
                 LINE DICTIONARY of a MoorDyn v1 deck (Name Diam MassDenInAir EA BA/-zeta Can \
                 Cat Cdn Cdt: no EI, the coefficients in another order), which stancf does not \
                 read in this version: it reads MoorDyn v2 decks"
            ),
        ));
    }
    columns(row, 10, "LINE TYPES", LINE_TYPE_COLUMNS)?;
    let name = row.words[0];
    let viv = match row.words.len() {
        10 => None,
        11 | 13 => viv_columns(row, name)?,
        n => {
            return Err(DeckError::at(
                row.line,
                format!(
                    "LINE TYPES rows have 10 columns ({LINE_TYPE_COLUMNS}), 11 (+ Cl) or 13 \
                     (+ Cl dF cF); this one has {n} (MoorDyn refuses other counts; start a \
                     comment with #)"
                ),
            ))
        }
    };
    let what = |col: &str| format!("{col} of line type \"{name}\"");
    // EA as a file name: MoorDyn's nonlinear curve (read by the scenario,
    // which knows where the deck is).
    let ea_word = row.words[3];
    let ea_curve_file = (ea_word.parse::<f64>().is_err()
        && !ea_word.contains('|')
        && !ea_word.to_ascii_uppercase().starts_with("SYROPE:"))
    .then(|| ea_word.to_string());
    let visco = super::visco_columns::viscoelastic(row, name)?;
    let syrope = super::syrope_columns::syrope_columns(row, name)?;
    if ea_curve_file.is_none() && visco.is_none() && syrope.is_none() {
        constant(row, 3, name, "EA")?;
    }
    if visco.is_none() && syrope.is_none() {
        constant(row, 4, name, "BA/-zeta")?;
    }
    let (ea_dynamic, ba_dynamic) = match (&visco, &syrope) {
        (Some(v), _) => (Some(v.dynamic.clone()), v.ba_dynamic),
        (None, Some(s)) => (None, s.ba_dynamic),
        (None, None) => (None, 0.0),
    };
    constant(row, 5, name, "EI")?;
    Ok(LineType {
        line: row.line,
        name: name.to_string(),
        diameter: non_negative(row, 1, &what("Diam"), true)?,
        mass_per_length: non_negative(row, 2, &what("Mass/m"), true)?,
        ea: match (&ea_curve_file, &visco) {
            (Some(_), _) => 0.0,
            (None, Some(v)) => v.ea,
            (None, None) if syrope.is_some() => 0.0,
            (None, None) => non_negative(row, 3, &what("EA"), true)?,
        },
        ea_curve_file,
        ea_dynamic,
        ba_dynamic,
        ba: match (&visco, &syrope) {
            (Some(v), _) => v.ba,
            (None, Some(s)) => s.ba,
            (None, None) => number(row, 4, &what("BA/-zeta"))?,
        },
        syrope,
        ei: non_negative(row, 5, &what("EI"), false)?,
        cd_normal: non_negative(row, 6, &what("Cd"), false)?,
        ca_normal: non_negative(row, 7, &what("Ca"), false)?,
        cd_axial: non_negative(row, 8, &what("CdAx"), false)?,
        ca_axial: non_negative(row, 9, &what("CaAx"), false)?,
        viv,
    })
}

/// The optional VIV columns `Cl` or `Cl dF cF` (docs/method.md §12.7):
/// None where `Cl` = 0 (MoorDyn's VIV off); dF and cF default to
/// MoorDyn's 0.08 and 0.18.
fn viv_columns(row: &Row, name: &str) -> Result<Option<super::VivColumns>, DeckError> {
    let what = |col: &str| format!("{col} of line type \"{name}\"");
    let cl = non_negative(row, 10, &what("Cl"), false)?;
    if cl == 0.0 {
        return Ok(None);
    }
    let (range, centre) = if row.words.len() == 13 {
        (
            non_negative(row, 11, &what("dF"), false)?,
            non_negative(row, 12, &what("cF"), false)?,
        )
    } else {
        (super::VivColumns::RANGE, super::VivColumns::CENTRE)
    };
    if centre <= 0.0 || range >= centre {
        return Err(DeckError::at(
            row.line,
            format!(
                "line type \"{name}\": the VIV synchronisation range is cF = {centre} +- dF = \
                 {range}; it needs cF > 0 and dF < cF (the shedding frequency stays positive)"
            ),
        ));
    }
    Ok(Some(super::VivColumns { cl, range, centre }))
}

/// BA and EI must be plain numbers, and EA a number or a curve file's
/// name: MoorDyn also takes the name of a file holding a nonlinear curve
/// for BA and EI, `a|b` or `a|b|c` viscoelastic forms and `SYROPE:...`
/// for EA (`readLineProps`, `read_curve`).
fn constant(row: &Row, col: usize, name: &str, column: &str) -> Result<(), DeckError> {
    let w = row.words[col];
    if w.parse::<f64>().is_ok() {
        return Ok(());
    }
    let kind = if w.to_ascii_uppercase().starts_with("SYROPE:") {
        "the Syrope polyester model"
    } else if w.contains('|') {
        "a viscoelastic (bar-separated) value"
    } else {
        "not a number (MoorDyn would read a nonlinear curve from a file of that name; stancf \
         reads one for EA only)"
    };
    Err(DeckError::at(
        row.line,
        format!(
            "{column} of line type \"{name}\" is \"{w}\", {kind}; only a constant \
             {column} is supported"
        ),
    ))
}

const POINT_COLUMNS: &str = "ID Attachment X Y Z Mass Volume CdA Ca";

/// `POINTS` rows.
pub(crate) fn points(s: &Section) -> Result<Vec<DeckPoint>, DeckError> {
    let mut out = Vec::new();
    for row in &s.rows {
        columns(row, 9, "POINTS", POINT_COLUMNS)?;
        let id = count(row, 0, "the point ID")?;
        sequential(row, id, out.len() + 1, "point")?;
        let attachment = attachment(row, id)?;
        let what = |col: &str| format!("{col} of point {id}");
        // 12 words or more: MoorDyn reads `X Y Z Mass Volume FX FY FZ CdA Ca`,
        // the force a constant one on the point (Point.cpp, `pointF`).
        let mut force = [0.0; 3];
        let (cda, ca) = if row.words.len() >= 12 {
            for (c, (col, name)) in [(7, "FX"), (8, "FY"), (9, "FZ")].into_iter().enumerate() {
                force[c] = number(row, col, &what(name))?;
            }
            if force != [0.0; 3] && attachment != Attachment::Free {
                return Err(DeckError::at(
                    row.line,
                    format!(
                        "point {id} has a constant force (FX FY FZ) but is not free: stancf \
                         takes a force on a free point only (on a point the deck holds it \
                         would only change the reported force)"
                    ),
                ));
            }
            (10, 11)
        } else {
            (7, 8)
        };
        out.push(DeckPoint {
            line: row.line,
            id,
            attachment,
            position: [
                number(row, 2, &what("X"))?,
                number(row, 3, &what("Y"))?,
                number(row, 4, &what("Z"))?,
            ],
            mass: non_negative(row, 5, &what("Mass"), false)?,
            volume: non_negative(row, 6, &what("Volume"), false)?,
            cda: non_negative(row, cda, &what("CdA"), false)?,
            ca: non_negative(row, ca, &what("Ca"), false)?,
            force,
        });
    }
    Ok(out)
}

/// The words of `MoorDyn2.cpp` for point types, compared upper-cased.
fn attachment(row: &Row, id: usize) -> Result<Attachment, DeckError> {
    let w = row.words[1];
    let upper = w.to_ascii_uppercase();
    let letters = upper.trim_end_matches(|c: char| c.is_ascii_digit());
    let numbered = letters.len() < upper.len();
    let kind = match letters {
        "ANCHOR" | "FIXED" | "FIX" if !numbered => Attachment::Fixed,
        "POINT" | "CONNECT" | "CON" | "FREE" if !numbered => Attachment::Free,
        "FAIRLEAD" | "VESSEL" | "VES" | "COUPLED" | "CPLD" if !numbered => Attachment::Coupled,
        _ if upper.starts_with("BODY") => return body_attachment(row, id, w),
        "TURBINE" if numbered => match upper[letters.len()..].parse::<usize>() {
            Ok(n) if n >= 1 => Attachment::Turbine(n),
            _ => {
                return Err(refused(
                    row,
                    id,
                    w,
                    "turbines are numbered from 1 (Turbine1)",
                ))
            }
        },
        "FAIRLEAD" | "VESSEL" | "VES" | "COUPLED" | "CPLD" => {
            return Err(refused(
                row,
                id,
                w,
                "a numbered coupled point is not MoorDyn's; a point on one of a farm's \
                 turbines (FAST.Farm) is Turbine<n>",
            ))
        }
        _ if letters.contains("PIN") => {
            return Err(refused(row, id, w, "pinned attachments are not supported"))
        }
        _ => {
            return Err(DeckError::at(
                row.line,
                format!(
                    "point {id} has the unknown attachment \"{w}\"; known: Fixed (Anchor, Fix), \
                     Free (Point, Connect, Con), Coupled (Vessel, Ves, Fairlead, Cpld), \
                     Body<n> (on body n), Turbine<n> (on a farm's turbine n)"
                ),
            ))
        }
    };
    Ok(kind)
}

/// `Body<n>` (any case, as MoorDyn's `decomposeString` reads it): a
/// point on body n. Words after the number (`Body1Pinned`), which
/// MoorDyn ignores for a point, are refused.
fn body_attachment(row: &Row, id: usize, w: &str) -> Result<Attachment, DeckError> {
    let rest = &w[4..];
    let digits = rest
        .find(|c: char| !c.is_ascii_digit())
        .unwrap_or(rest.len());
    if digits == 0 {
        return Err(refused(
            row,
            id,
            w,
            "a point on a body names the body's number, e.g. Body1",
        ));
    }
    if digits < rest.len() {
        return Err(refused(
            row,
            id,
            w,
            &format!(
                "a point on a body is fixed to it; MoorDyn reads this as Body{} and ignores \"{}\": \
                 write Body{}",
                &rest[..digits],
                &rest[digits..],
                &rest[..digits]
            ),
        ));
    }
    match rest.parse::<usize>() {
        Ok(n) => Ok(Attachment::Body(n)),
        Err(_) => Err(refused(row, id, w, "the body number is too large")),
    }
}

fn refused(row: &Row, id: usize, word: &str, why: &str) -> DeckError {
    DeckError::at(
        row.line,
        format!("point {id} is attached to \"{word}\": {why}"),
    )
}

/// A `LINES` row before its type and points are looked up.
pub(crate) struct RawLine<'a> {
    line: usize,
    id: usize,
    line_type: &'a str,
    ends: [LineAttachment; 2],
    unstretched_length: f64,
    segments: usize,
    outputs: &'a str,
}

const LINE_COLUMNS: &str = "ID LineType AttachA AttachB UnstrLen NumSegs Outputs";

/// `LINES` rows.
pub(crate) fn lines<'a>(s: &Section<'a>) -> Result<Vec<RawLine<'a>>, DeckError> {
    let mut out = Vec::new();
    for row in &s.rows {
        columns(row, 7, "LINES", LINE_COLUMNS)?;
        let id = count(row, 0, "the line ID")?;
        sequential(row, id, out.len() + 1, "line")?;
        let what = |col: &str| format!("{col} of line {id}");
        let unstretched_length = number(row, 4, &what("UnstrLen"))?;
        if unstretched_length <= 0.0 {
            return Err(DeckError::at(
                row.line,
                format!("UnstrLen of line {id} is {unstretched_length}; it must be positive"),
            ));
        }
        out.push(RawLine {
            line: row.line,
            id,
            line_type: row.words[1],
            ends: [end(row, id, 2, "A")?, end(row, id, 3, "B")?],
            unstretched_length,
            segments: segments(row, &what("NumSegs"))?,
            outputs: row.words[6],
        });
    }
    Ok(out)
}

/// An attachment of a line end: a point id, written `4`, `P4`, `Point4`,
/// `C4` or `Con4`, or a rod end, `R1A`, `Rod1B` (`MoorDyn2.cpp`).
fn end(row: &Row, id: usize, col: usize, which: &str) -> Result<LineAttachment, DeckError> {
    if let Some(rod) = rod_end(row, id, col, which)? {
        return Ok(rod);
    }
    let w = row.words[col];
    let upper = w.to_ascii_uppercase();
    let digits_at = upper
        .find(|c: char| c.is_ascii_digit())
        .unwrap_or(upper.len());
    let (letters, rest) = upper.split_at(digits_at);
    let digits_end = rest
        .find(|c: char| !c.is_ascii_digit())
        .unwrap_or(rest.len());
    let (digits, tail) = rest.split_at(digits_end);
    let point = matches!(letters, "" | "C" | "CON" | "P" | "POINT") && tail.is_empty();
    match digits.parse::<usize>() {
        Ok(n) if point && n >= 1 => Ok(LineAttachment::Point(n)),
        _ => Err(DeckError::at(
            row.line,
            format!(
                "Attach{which} of line {id} is \"{w}\"; expected a point ID such as 4 or P4, or a rod \
                 end such as R1A (columns: {LINE_COLUMNS})"
            ),
        )),
    }
}

/// Lines with their types and points looked up.
pub(crate) fn link_lines(
    raw: Vec<RawLine>,
    types: &[LineType],
    points: &[super::DeckPoint],
) -> Result<Vec<DeckLine>, DeckError> {
    let mut out = Vec::new();
    for l in raw {
        let Some(type_index) = types.iter().position(|t| t.name == l.line_type) else {
            let known: Vec<&str> = types.iter().map(|t| t.name.as_str()).collect();
            let known = if known.is_empty() {
                "none".to_string()
            } else {
                known.join(", ")
            };
            return Err(DeckError::at(
                l.line,
                format!(
                    "line {} uses line type \"{}\", which LINE TYPES does not define; known: {known}",
                    l.id, l.line_type
                ),
            ));
        };
        for (end, a) in ["A", "B"].into_iter().zip(l.ends) {
            let LineAttachment::Point(p) = a else {
                continue;
            };
            if p > points.len() {
                return Err(DeckError::at(
                    l.line,
                    format!(
                        "end {end} of line {} is attached to point {p}, which POINTS does not \
                         define ({} points)",
                        l.id,
                        points.len()
                    ),
                ));
            }
        }
        if l.ends[0] == l.ends[1] {
            return Err(DeckError::at(
                l.line,
                format!(
                    "both ends of line {} are attached to {}",
                    l.id,
                    match l.ends[0] {
                        LineAttachment::Point(p) => format!("point {p}"),
                        LineAttachment::Rod(r, e) => format!("end {} of rod {r}", e.letter()),
                    }
                ),
            ));
        }
        out.push(DeckLine {
            line: l.line,
            id: l.id,
            line_type: l.line_type.to_string(),
            type_index,
            end_a: l.ends[0],
            end_b: l.ends[1],
            unstretched_length: l.unstretched_length,
            segments: l.segments,
            outputs: l.outputs.to_string(),
        });
    }
    Ok(out)
}

/// Sections stancf cannot represent are accepted only empty; the first
/// data row is refused.
pub(crate) fn refuse_rows(s: &Section, kind: SectionKind) -> Result<(), DeckError> {
    let Some(row) = s.rows.first() else {
        return Ok(());
    };
    let why = match kind {
        SectionKind::Control => "line length control is not supported",
        SectionKind::SyropeIc => "the Syrope polyester model is not supported",
        _ => "this section is not supported",
    };
    Err(DeckError::at(
        row.line,
        format!("{} (section {} at line {})", why, kind.title(), s.header),
    ))
}
