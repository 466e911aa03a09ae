//! A MoorDyn deck's line types as a scenario's (docs/interface.md,
//! "MoorDyn v2 decks"): their axial laws read from the files the deck
//! names (EA curve files, docs/method.md §2.2a; Syrope's settings, curve
//! and SYROPE IC, §2.12) and checked (the viscoelastic forms, §2.11), and
//! each LINE TYPES row as a [`LineType`].

use super::system_parts::LineType;
use super::ScenarioError;
use crate::moordyn::Deck;
use std::path::Path;
use std::sync::Arc;

/// The deck with its line types' EA set where a file gives the law (a
/// curve's secant at its last point, MoorDyn's EA for its damping ratio
/// and CFL; Syrope's original curve's), each type's curve, each line's
/// Syrope Tmax0, and the notes of what was read where.
pub(super) struct DeckLaws {
    pub deck: Deck,
    pub curves: Vec<Option<Arc<stancf::element::AxialCurve>>>,
    pub tmax0: Vec<Option<f64>>,
    pub notes: Vec<String>,
}

/// Reads and checks the line types' laws of `deck` (file `file` at
/// `path`).
pub(super) fn deck_line_laws(
    deck: &Deck,
    file: &str,
    path: &Path,
) -> Result<DeckLaws, ScenarioError> {
    let (curves, curve_notes) = super::ea_curves::deck_curves(deck, file, path)?;
    let (syrope_laws, syrope_notes) = super::syrope_files::deck_syrope(deck, file, path)?;
    let mut deck = deck.clone();
    for ((t, c), s) in deck.line_types.iter_mut().zip(&curves).zip(&syrope_laws) {
        {
            if let Some(c) = c {
                t.ea = c.secant_stiffness();
            }
            if let Some(ea) = s.as_ref().and_then(super::syrope_files::syrope_ea) {
                t.ea = ea;
                t.ea_dynamic = s.clone();
            }
        }
    }
    let (tmax0, tmax0_notes) = super::syrope_files::deck_tmax0(&deck, &syrope_laws, file)?;
    for (t, c) in deck.line_types.iter().zip(&curves) {
        check_deck_law(t, c.is_some(), file)?;
    }
    let mut notes = curve_notes;
    notes.extend(syrope_notes);
    notes.extend(tmax0_notes);
    Ok(DeckLaws {
        deck,
        curves,
        tmax0,
        notes,
    })
}

/// A viscoelastic LINE TYPES row's law, checked (docs/method.md §2.11):
/// an error naming the row.
fn check_deck_law(
    t: &crate::moordyn::LineType,
    has_curve: bool,
    file: &str,
) -> Result<(), ScenarioError> {
    let at = |m: String| {
        ScenarioError(format!(
            "{file}: line {}: line type \"{}\": {m}",
            t.line, t.name
        ))
    };
    if t.ea_dynamic.is_none() {
        return Ok(());
    }
    if has_curve {
        return Err(at(
            "a viscoelastic EA needs a constant static EA, not a curve file".into(),
        ));
    }
    super::visco_types::check_law(&deck_line_type(t, None, 0.0)).map_err(|(_, m)| at(m))
}

/// The deck's LINE TYPES rows as line types, with their EA curves
/// `curves` (one per row).
pub(super) fn deck_line_types(
    deck: &crate::moordyn::Deck,
    curves: Vec<Option<std::sync::Arc<stancf::element::AxialCurve>>>,
) -> Vec<LineType> {
    let dtm = deck.time_step().unwrap_or(0.0);
    deck.line_types
        .iter()
        .zip(curves)
        .map(|(t, c)| deck_line_type(t, c, dtm))
        .collect()
}

/// A LINE TYPES row as a line type; `dtm` is the deck's MoorDyn step,
/// over 500 of which MoorDyn takes a VIV line's running mean squares
/// (docs/method.md §12.7).
pub(super) fn deck_line_type(
    t: &crate::moordyn::LineType,
    ea_curve: Option<std::sync::Arc<stancf::element::AxialCurve>>,
    dtm: f64,
) -> LineType {
    LineType {
        name: t.name.clone(),
        diameter: t.diameter,
        mass_per_length: t.mass_per_length,
        ea: t.ea,
        ea_curve,
        ea_dynamic: t.ea_dynamic.clone(),
        ba_dynamic: t.ba_dynamic,
        ei: t.ei,
        ba: t.ba,
        cd_normal: t.cd_normal,
        ca_normal: t.ca_normal,
        cd_axial: t.cd_axial,
        ca_axial: t.ca_axial,
        // MoorDyn's segments carry no compression (Line.cpp: T = 0
        // when l_str <= l); the static solve keeps it (docs/method.md
        // §2.2, (M4a)).
        compression: false,
        viv: t.viv.map(|v| stancf::element::Viv {
            lift: v.cl,
            centre: v.centre,
            range: v.range,
            averaging_time: crate::moordyn::VivColumns::MEAN_SQUARE_STEPS * dtm,
        }),
        // A MoorDyn deck has no breaking load (the scenario's system.mbl).
        mbl: None,
    }
}
