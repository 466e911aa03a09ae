//! MoorDyn's Syrope line types (docs/method.md §2.12): the EA column
//! `SYROPE:<file>|alphaMBL|vbeta` with `BA|BA_D`, and the `SYROPE IC`
//! section's largest and mean tensions per line (`Line(s) Tmax0 Tmean0`,
//! lines as a comma-separated list), read as MoorDyn's `readLineProps`
//! and `load` read them. The settings file (OWC path, WCType, k1, k2) and
//! the curve are the scenario's to read: it knows where the deck is.

use super::layout::{Row, Section};
use super::DeckError;

/// A Syrope line type's columns.
#[derive(Clone, Debug, PartialEq)]
pub struct SyropeColumns {
    /// The settings file named after `SYROPE:`.
    pub file: String,
    /// The dynamic stiffness alpha + beta T (N, -).
    pub alpha: f64,
    pub beta: f64,
    /// BA (N s, or minus a damping ratio) and BA_D (N s).
    pub ba: f64,
    pub ba_dynamic: f64,
}

/// A `SYROPE IC` row: the lines it sets (1-based ids) and their Tmax0
/// and Tmean0 (N).
#[derive(Clone, Debug, PartialEq)]
pub struct SyropeIc {
    pub line: usize,
    pub lines: Vec<usize>,
    pub tmax0: f64,
    pub tmean0: f64,
}

/// The Syrope columns of LINE TYPES row `row` (type `name`), None when EA
/// is not a `SYROPE:` form.
pub(crate) fn syrope_columns(row: &Row, name: &str) -> Result<Option<SyropeColumns>, DeckError> {
    let ea_word = row.words[3];
    if !ea_word.to_ascii_uppercase().starts_with("SYROPE:") {
        return Ok(None);
    }
    let err = |msg: String| DeckError::at(row.line, format!("line type \"{name}\": {msg}"));
    let ea: Vec<&str> = ea_word.split('|').collect();
    if ea.len() != 3 {
        return Err(err(format!(
            "EA is \"{ea_word}\": a Syrope EA has 3 bar-separated values, \
             SYROPE:<file>|alphaMBL|vbeta (MoorDyn refuses other counts)"
        )));
    }
    let value = |w: &str, what: &str| -> Result<f64, DeckError> {
        match w.parse::<f64>() {
            Ok(v) if v.is_finite() => Ok(v),
            _ => Err(err(format!("{what} is \"{w}\", not a number"))),
        }
    };
    let ba: Vec<&str> = row.words[4].split('|').collect();
    if ba.len() > 2 {
        return Err(err(format!("BA is \"{}\": at most BA|BA_D", row.words[4])));
    }
    let ba_dynamic = match ba.get(1) {
        Some(w) => super::visco_columns::dynamic_damping(value(w, "BA_D")?).map_err(err)?,
        None => 0.0,
    };
    Ok(Some(SyropeColumns {
        file: ea[0][7..].to_string(),
        alpha: value(ea[1], "alphaMBL")?,
        beta: value(ea[2], "vbeta")?,
        ba: value(ba[0], "BA")?,
        ba_dynamic,
    }))
}

/// The `SYROPE IC` rows: `Line(s) Tmax0 Tmean0`, the lines a comma-
/// separated list of ids (checked against the deck's lines later).
pub(crate) fn syrope_ic(s: &Section) -> Result<Vec<SyropeIc>, DeckError> {
    let mut out = Vec::new();
    for row in &s.rows {
        if row.words.len() < 3 {
            return Err(DeckError::at(
                row.line,
                format!(
                    "SYROPE IC rows have 3 columns (Line(s) Tmax0 Tmean0); this one has {}",
                    row.words.len()
                ),
            ));
        }
        let number = |k: usize, what: &str| -> Result<f64, DeckError> {
            match row.words[k].parse::<f64>() {
                Ok(v) if v.is_finite() => Ok(v),
                _ => Err(DeckError::at(
                    row.line,
                    format!("SYROPE IC: {what} is \"{}\", not a number", row.words[k]),
                )),
            }
        };
        let lines = row.words[0]
            .split(',')
            .map(|w| match w.parse::<usize>() {
                Ok(id) if id > 0 => Ok(id),
                _ => Err(DeckError::at(
                    row.line,
                    format!("SYROPE IC: \"{w}\" is not a line id (1, 2, ...)"),
                )),
            })
            .collect::<Result<Vec<_>, _>>()?;
        out.push(SyropeIc {
            line: row.line,
            lines,
            tmax0: number(1, "Tmax0")?,
            tmean0: number(2, "Tmean0")?,
        });
    }
    Ok(out)
}
