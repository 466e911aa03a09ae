//! A MoorDyn deck's Syrope line types (docs/method.md §2.12): the
//! settings file named by `SYROPE:<file>` (lines of a value and its name:
//! `OWC`, `WCType`, `k1`, `k2`, as MoorDyn's
//! `read_syrope_working_curves` reads them) and the original working
//! curve it names (MoorDyn's curve file: three header lines, then strain
//! and tension), both relative to the deck's folder as MoorDyn opens
//! them, then where [`super::deck_files::locate`] looks; and each line's
//! Tmax0 from the `SYROPE IC` section.

use super::ScenarioError;
use crate::moordyn::Deck;
use stancf::element::{DynamicStiffness, Syrope, WorkingCurveForm};
use std::path::{Path, PathBuf};
use std::sync::Arc;

/// Each deck line type's Syrope law (None for the others), with notes
/// saying which files were found where.
pub(super) fn deck_syrope(
    deck: &Deck,
    file: &str,
    path: &Path,
) -> Result<(Vec<Option<DynamicStiffness>>, Vec<String>), ScenarioError> {
    let mut laws = Vec::with_capacity(deck.line_types.len());
    let mut notes = Vec::new();
    for t in &deck.line_types {
        let Some(s) = &t.syrope else {
            laws.push(None);
            continue;
        };
        let refuse = |why: String| {
            ScenarioError(format!(
                "{file}: line {}: EA of line type \"{}\" is Syrope's ({}): {why}",
                t.line, t.name, s.file
            ))
        };
        let settings_path = find(&s.file, path).map_err(refuse)?;
        let text = crate::input_file::read_text(&settings_path)
            .map_err(|e| refuse(format!("{}: {e}", settings_path.display())))?;
        let settings = read_settings(&text)
            .map_err(|e| refuse(format!("{}: {e}", settings_path.display())))?;
        let owc_path = find(&settings.owc, path).map_err(refuse)?;
        let points = super::ea_curves::read_curve(&owc_path).map_err(refuse)?;
        let curves = Syrope::new(
            &points,
            settings.form,
            (settings.k1, settings.k2),
            (s.alpha, s.beta),
            "the Syrope law",
        )
        .map_err(|e| refuse(e.message))?;
        notes.push(format!(
            "line {}: line type \"{}\": Syrope's working curves (docs/method.md §2.12) from {} \
             and the original curve {} ({} points, MoorDyn's three header lines skipped)",
            t.line,
            t.name,
            settings_path.display(),
            owc_path.display(),
            points.len()
        ));
        laws.push(Some(DynamicStiffness::Syrope {
            curves: Arc::new(curves),
            tmax0: f64::NAN,
        }));
    }
    Ok((laws, notes))
}

/// Each deck line's Tmax0 from SYROPE IC (None for lines of other
/// types); a Syrope line without one, a row naming a missing line or a
/// line of another type, and a Tmax0 outside the original curve are
/// refused naming the row. Tmean0 is noted: stancf starts a line at rest
/// at its equilibrium on the working curve of Tmax0.
pub(super) fn deck_tmax0(
    deck: &Deck,
    laws: &[Option<DynamicStiffness>],
    file: &str,
) -> Result<(Vec<Option<f64>>, Vec<String>), ScenarioError> {
    let mut out = vec![None; deck.lines.len()];
    let mut notes = Vec::new();
    for ic in &deck.syrope_ic {
        for &id in &ic.lines {
            let at = |m: String| ScenarioError(format!("{file}: line {}: SYROPE IC: {m}", ic.line));
            let Some(l) = deck.lines.get(id - 1) else {
                return Err(at(format!(
                    "there is no line {id} (the deck has {})",
                    deck.lines.len()
                )));
            };
            let Some(DynamicStiffness::Syrope { curves, .. }) = &laws[l.type_index] else {
                return Err(at(format!("line {id} is not of a Syrope line type")));
            };
            curves
                .check_tmax(ic.tmax0, "Tmax0")
                .map_err(|e| at(format!("line {id}: {}", e.message)))?;
            out[id - 1] = Some(ic.tmax0);
        }
        notes.push(format!(
            "line {}: SYROPE IC: Tmean0 {} N is not used: stancf starts the line at rest at its \
             equilibrium on the working curve of Tmax0 {} N (docs/method.md §2.12)",
            ic.line, ic.tmean0, ic.tmax0
        ));
    }
    for (i, l) in deck.lines.iter().enumerate() {
        if laws[l.type_index].is_some() && out[i].is_none() {
            return Err(ScenarioError(format!(
                "{file}: line {}: line {} is of the Syrope line type \"{}\": give its Tmax0 in a \
                 SYROPE IC section (MoorDyn needs it too)",
                l.line,
                i + 1,
                deck.line_types[l.type_index].name
            )));
        }
    }
    Ok((out, notes))
}

/// A file a deck names: beside the deck first, as MoorDyn opens it, then
/// where [`super::deck_files::locate`] looks.
fn find(named: &str, deck_path: &Path) -> Result<PathBuf, String> {
    if let Some(p) = deck_path
        .parent()
        .map(|d| d.join(named))
        .filter(|p| p.is_file())
    {
        return Ok(p);
    }
    super::deck_files::locate(named, deck_path).map(|f| f.path)
}

/// The settings of a Syrope line type.
struct Settings {
    owc: String,
    form: WorkingCurveForm,
    k1: f64,
    k2: f64,
}

/// Lines of `value name`: OWC, WCType (linear, quadratic, exp), k1, k2
/// (names case-blind, other lines skipped as MoorDyn warns and skips).
fn read_settings(text: &str) -> Result<Settings, String> {
    let (mut owc, mut form, mut k1, mut k2) = (None, None, None, None);
    for (k, line) in text.lines().enumerate() {
        let words: Vec<&str> = line.split_whitespace().collect();
        if words.len() < 2 {
            continue;
        }
        let number = |w: &str| {
            w.parse::<f64>()
                .ok()
                .filter(|v| v.is_finite())
                .ok_or_else(|| format!("line {}: \"{w}\" is not a number", k + 1))
        };
        match words[1].to_ascii_lowercase().as_str() {
            "owc" => owc = Some(words[0].to_string()),
            "wctype" => {
                form = Some(match words[0].to_ascii_lowercase().as_str() {
                    "linear" => WorkingCurveForm::Linear,
                    "quadratic" => WorkingCurveForm::Quadratic,
                    "exp" => WorkingCurveForm::Exponential,
                    other => {
                        return Err(format!(
                            "line {}: WCType \"{other}\" is not LINEAR, QUADRATIC or EXP",
                            k + 1
                        ))
                    }
                })
            }
            "k1" => k1 = Some(number(words[0])?),
            "k2" => k2 = Some(number(words[0])?),
            _ => {}
        }
    }
    match (owc, form, k1, k2) {
        (Some(owc), Some(form), Some(k1), Some(k2)) => Ok(Settings { owc, form, k1, k2 }),
        _ => {
            Err("the settings need OWC, WCType, k1 and k2 (one per line: value, then name)".into())
        }
    }
}

/// A Syrope line type's EA where one is needed (a damping ratio, the
/// seed): the original curve's secant at its last point.
pub(super) fn syrope_ea(law: &DynamicStiffness) -> Option<f64> {
    match law {
        DynamicStiffness::Syrope { curves, .. } => {
            let (_, hi) = curves.tension_range();
            Some(hi / curves.strain_at(hi))
        }
        _ => None,
    }
}
