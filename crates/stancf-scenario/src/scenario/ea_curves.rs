//! Nonlinear axial laws of line types (docs/method.md §2.2a, (M4b);
//! docs/interface.md, "Line types"): a MoorDyn deck's EA given as the
//! name of a curve file, read as MoorDyn reads it (`read_curve`: three
//! header lines, then rows of strain and tension), found beside the deck
//! first (MoorDyn opens it from the deck's folder) and then where
//! [`super::deck_files::locate`] looks; a TOML line type's `ea_curve`, its
//! [strain, tension] pairs inline.

use super::context::Ctx;
use super::raw::RawLineType;
use super::ScenarioError;
use crate::moordyn::Deck;
use stancf::element::AxialCurve;
use std::path::Path;
use std::sync::Arc;

/// `ea_curve` of a `[[line_types]]` entry: pairs [strain, tension],
/// checked as (M4b) takes them; `ea` beside it is refused.
pub(super) fn toml_curve(
    ctx: &Ctx,
    key: &str,
    r: &RawLineType,
) -> Result<Option<Arc<AxialCurve>>, ScenarioError> {
    let Some(rows) = &r.ea_curve else {
        return Ok(None);
    };
    if r.ea.is_some() {
        return Err(ctx.err(
            key,
            "gives the axial law; leave `ea` out (the curve's secant at its last point takes its \
             place where an EA is needed: a damping ratio, the seed)",
        ));
    }
    let mut points = Vec::with_capacity(rows.len());
    for (k, row) in rows.iter().enumerate() {
        match row.as_slice() {
            [strain, tension] => points.push((*strain, *tension)),
            _ => {
                return Err(ctx.err(
                    key,
                    format!(
                        "row {} has {} numbers; each is [strain, tension]",
                        k + 1,
                        row.len()
                    ),
                ))
            }
        }
    }
    AxialCurve::new(&points, key)
        .map(|c| Some(Arc::new(c)))
        .map_err(|e| ctx.err(key, e.to_string()))
}

/// Each deck line type's curve, None where its EA is a number.
pub(super) type DeckCurves = Vec<Option<Arc<AxialCurve>>>;

/// Every deck line type's curve (None where EA is a number), and the
/// notes saying which file was found where.
pub(super) fn deck_curves(
    deck: &Deck,
    file: &str,
    path: &Path,
) -> Result<(DeckCurves, Vec<String>), ScenarioError> {
    let mut curves = Vec::with_capacity(deck.line_types.len());
    let mut notes = Vec::new();
    for t in &deck.line_types {
        let Some(named) = &t.ea_curve_file else {
            curves.push(None);
            continue;
        };
        let refuse = |why: String| {
            ScenarioError(format!(
                "{file}: line {}: EA of line type \"{}\" names the curve file {named}: {why}",
                t.line, t.name
            ))
        };
        let beside = path.parent().map(|d| d.join(named)).filter(|p| p.is_file());
        let (found, place) = match beside {
            Some(p) => (p, "beside the deck, as MoorDyn opens it".to_string()),
            None => {
                let f = super::deck_files::locate(named, path).map_err(refuse)?;
                (f.path, f.place)
            }
        };
        let points = read_curve(&found).map_err(refuse)?;
        let curve = AxialCurve::new(&points, "the curve").map_err(|e| refuse(e.to_string()))?;
        notes.push(format!(
            "line {}: line type \"{}\": EA from the curve file {named}, found at {} ({place}): {} \
             points to strain {} at {} N; beyond it its last segment goes on (MoorDyn holds the \
             last tension) (docs/method.md §2.2a)",
            t.line,
            t.name,
            found.display(),
            points.len(),
            points[points.len() - 1].0,
            points[points.len() - 1].1
        ));
        curves.push(Some(Arc::new(curve)));
    }
    Ok((curves, notes))
}

/// MoorDyn's curve file: three header lines, then a strain and a tension
/// on each line (more words are ignored, as MoorDyn ignores them; blank
/// lines are skipped).
pub(super) fn read_curve(path: &Path) -> Result<Vec<(f64, f64)>, String> {
    let text =
        crate::input_file::read_text(path).map_err(|e| format!("{}: {e}", path.display()))?;
    let mut points = Vec::new();
    for (k, line) in text.lines().enumerate().skip(3) {
        let words: Vec<&str> = line.split_whitespace().collect();
        if words.is_empty() {
            continue;
        }
        let number = |w: &str| w.parse::<f64>().ok().filter(|v| v.is_finite());
        match (
            words.first().and_then(|w| number(w)),
            words.get(1).and_then(|w| number(w)),
        ) {
            (Some(x), Some(y)) => points.push((x, y)),
            _ => {
                return Err(format!(
                    "{} line {}: \"{}\" is not a strain and a tension",
                    path.display(),
                    k + 1,
                    line.trim()
                ))
            }
        }
    }
    Ok(points)
}
