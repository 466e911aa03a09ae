//! Notes on a MoorDyn deck's OPTIONS that `check` prints and `run` warns
//! of: what is used differently from MoorDyn, or read under another
//! name.

use crate::moordyn::{Deck, SupportedOption};
use stancf::error::Sig;

/// Notes on the deck's options: one given again (the last holds); a
/// `tScheme` is MoorDyn's integrator, which stancf does not use (it steps
/// with its own scheme); without a `dtM`, the step MoorDyn derives from
/// its Courant number ([`Deck::time_step`]); MoorPy's names for the
/// water depth.
pub(super) fn option_notes(deck: &Deck) -> Vec<String> {
    let mut notes = Vec::new();
    for o in &deck.options {
        if let Some((name, line)) = &o.replaces {
            notes.push(format!(
                "line {}: option {} is given again (first as {name} at line {line}): this \
                 value holds, as MoorDyn reads its options in order",
                o.line, o.name
            ));
        }
        let lower = o.name.to_ascii_lowercase();
        if lower == "depth" || lower == "wtrdepth" {
            notes.push(format!(
                "line {}: option {}: MoorPy's name for WtrDpth, taken as the water depth \
                 (MoorDyn 2.7 does not read it: it warns and takes the deepest point's depth)",
                o.line, o.name
            ));
        }
        if o.name.eq_ignore_ascii_case("tscheme") {
            let scheme = match &o.value {
                crate::moordyn::OptionValue::Text(t) => t.clone(),
                crate::moordyn::OptionValue::Number(v) => v.to_string(),
            };
            notes.push(format!(
                "line {}: tScheme {scheme}: MoorDyn's integrator is not used; stancf steps \
                 with its own scheme (a system's Galerkin step, docs/method.md §5), at the \
                 deck's step in a coupled or dynamic run",
                o.line
            ));
        }
    }
    if deck.option(SupportedOption::TimeStep).is_none() {
        if let Some(dt) = deck.time_step() {
            let cfl = deck.option(SupportedOption::Courant);
            notes.push(format!(
                "OPTIONS: no dtM: MoorDyn's step from {} is {} s (the Courant number times \
                 the shortest line segment's natural period 2 pi sqrt(m/k)), the step of a \
                 coupled run; stancf's Galerkin step is stable at any step, not bound by a \
                 Courant number",
                match cfl {
                    Some(c) => format!("CFL {}", Sig(c)),
                    None => "its default CFL 0.5".to_string(),
                },
                Sig(dt)
            ));
        }
    }
    notes
}
