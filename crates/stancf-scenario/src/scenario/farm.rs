//! A FAST.Farm deck's turbines (docs/interface.md, "MoorDyn decks"): a
//! farm-level MoorDyn deck holds the shared moorings of several floating
//! turbines, its points on turbine n written `Turbine<n>` with X, Y, Z
//! from the turbine's reference position, which the FAST.Farm input
//! gives (its WT_X, WT_Y, WT_Z rows). Each turbine's platform is a
//! coupled body of stancf's at that position, unturned, its points the
//! body's points: the host (or a scenario's motions) moves the platform,
//! and the coupling API takes each turbine's six degrees of freedom, as
//! FAST.Farm gives MoorDyn each turbine's platform motion.
//!
//! The positions come from the scenario that takes the deck (`[farm]
//! turbines = [[x, y, z], ...]`, or `[farm] fast_farm = "<file>.fstf"`),
//! else from a FAST.Farm input beside the deck that names the deck as its
//! `SharedMoorFile`; a deck alone without one is refused, naming the
//! first turbine point.

use super::bodies::{BodyType, SystemBody};
use super::context::Ctx;
use super::raw::RawFarm;
use super::ScenarioError;
use crate::moordyn::{Attachment, Deck};
use stancf::error::Sig;
use std::path::Path;

/// The turbines' reference positions (m, global) and where they came
/// from.
#[derive(Clone, Debug, PartialEq)]
pub struct Farm {
    pub positions: Vec<[f64; 3]>,
    pub source: String,
}

/// `[farm]`: the positions given, or read from the FAST.Farm input it
/// names (relative to the scenario's folder `dir`); one of them.
pub(super) fn scenario_farm(ctx: &Ctx, raw: RawFarm, dir: &Path) -> Result<Farm, ScenarioError> {
    match (raw.turbines, raw.fast_farm) {
        (Some(rows), None) => {
            let positions = rows
                .iter()
                .enumerate()
                .map(|(i, v)| ctx.vector(&format!("farm.turbines[{i}]"), v))
                .collect::<Result<Vec<_>, _>>()?;
            Ok(Farm {
                positions,
                source: "farm.turbines".into(),
            })
        }
        (None, Some(name)) => {
            let path = dir.join(&name);
            let read = |e: String| ctx.err("farm.fast_farm", format!("{}: {e}", path.display()));
            let text = crate::input_file::read_text(&path).map_err(read)?;
            let (_, positions) = read_fast_farm(&text).map_err(read)?;
            Ok(Farm {
                positions,
                source: format!("{} (farm.fast_farm)", path.display()),
            })
        }
        _ => Err(ctx.err(
            "farm",
            "give the turbines' positions (turbines = [[x, y, z], ...]) or the FAST.Farm input \
             that lists them (fast_farm = \"<file>.fstf\"), one of them",
        )),
    }
}

/// What a FAST.Farm input (`.fstf`) says of its moorings and turbines:
/// the quoted `SharedMoorFile` (None where absent) and each turbine's
/// WT_X, WT_Y, WT_Z, the `NumTurbines` rows after its two header lines.
/// Errors name the line.
pub fn read_fast_farm(text: &str) -> Result<(Option<String>, Vec<[f64; 3]>), String> {
    let lines: Vec<&str> = crate::echo::text_lines(text).collect();
    let named = |key: &str| {
        lines.iter().position(|l| {
            l.split_whitespace()
                .nth(1)
                .is_some_and(|w| w.eq_ignore_ascii_case(key))
        })
    };
    let mooring = named("SharedMoorFile").map(|k| {
        let w = lines[k].split_whitespace().next().unwrap_or("");
        w.trim_matches('"').to_string()
    });
    let at = named("NumTurbines").ok_or("no NumTurbines line")?;
    let first = lines[at].split_whitespace().next().unwrap_or("");
    let count: usize = first.parse().ok().filter(|n| *n >= 1).ok_or_else(|| {
        format!(
            "line {}: NumTurbines is \"{first}\", not a count >= 1",
            at + 1
        )
    })?;
    let mut positions = Vec::with_capacity(count);
    for k in 0..count {
        // The column names and their units come first.
        let row = at + 3 + k;
        let words: Vec<&str> = lines
            .get(row)
            .map(|l| l.split_whitespace().collect())
            .unwrap_or_default();
        let number = |i: usize| -> Result<f64, String> {
            words
                .get(i)
                .and_then(|w| w.parse::<f64>().ok())
                .filter(|v| v.is_finite())
                .ok_or_else(|| {
                    format!(
                        "line {}: turbine {}'s row starts WT_X WT_Y WT_Z, three numbers",
                        row + 1,
                        k + 1
                    )
                })
        };
        positions.push([number(0)?, number(1)?, number(2)?]);
    }
    Ok((mooring, positions))
}

/// The highest turbine a point of the deck is on (0 for none).
fn turbines_used(deck: &Deck) -> usize {
    deck.points
        .iter()
        .filter_map(|p| match p.attachment {
            Attachment::Turbine(n) => Some(n),
            _ => None,
        })
        .max()
        .unwrap_or(0)
}

/// The deck's farm: None without turbine points (a `[farm]` beside such a
/// deck is noted unused); else `given` (the scenario's `[farm]`) or the
/// FAST.Farm input beside the deck at `path` that names it. Refused
/// naming the first turbine point's line: no positions, or fewer
/// turbines than the points name.
pub(super) fn deck_farm(
    deck: &Deck,
    file: &str,
    path: &Path,
    given: Option<Farm>,
) -> Result<(Option<Farm>, Option<String>), ScenarioError> {
    let used = turbines_used(deck);
    if used == 0 {
        let note = given.map(|f| {
            format!(
                "the turbines of {} are unused: the deck has no Turbine<n> points",
                f.source
            )
        });
        return Ok((None, note));
    }
    let first = deck
        .points
        .iter()
        .find(|p| matches!(p.attachment, Attachment::Turbine(_)))
        .expect("a turbine point");
    let farm = match given {
        Some(f) => f,
        None => beside(path)?.ok_or_else(|| {
            ScenarioError(format!(
                "{file}: line {}: point {} is on turbine {}: a farm-level deck's turbines are \
                 where its FAST.Farm input puts them; give a scenario that takes the deck \
                 ([system] moordyn = ...) with [farm] turbines = [[x, y, z], ...] or fast_farm \
                 = \"<file>.fstf\", or keep the FAST.Farm input that names this deck as its \
                 SharedMoorFile beside it",
                first.line,
                first.id,
                match first.attachment {
                    Attachment::Turbine(n) => n,
                    _ => unreachable!(),
                }
            ))
        })?,
    };
    if farm.positions.len() < used {
        return Err(ScenarioError(format!(
            "{file}: a point is on turbine {used}, and {} gives {} turbines",
            farm.source,
            farm.positions.len()
        )));
    }
    let note = format!(
        "POINTS: the Turbine<n> points are on {} turbines' platforms at {} (from {}), each a \
         coupled body, unturned at t = 0: ids {} to {} in bodies.csv, after the deck's bodies, \
         6 coupled degrees of freedom each in the coupling's order",
        farm.positions.len(),
        farm.positions
            .iter()
            .map(|p| format!("({}, {}, {})", Sig(p[0]), Sig(p[1]), Sig(p[2])))
            .collect::<Vec<_>>()
            .join(", "),
        farm.source,
        deck.bodies.len() + 1,
        deck.bodies.len() + farm.positions.len()
    );
    Ok((Some(farm), Some(note)))
}

/// The FAST.Farm input in the deck's folder whose `SharedMoorFile` is
/// the deck (by file name), if one is.
fn beside(path: &Path) -> Result<Option<Farm>, ScenarioError> {
    let dir = path
        .parent()
        .filter(|d| !d.as_os_str().is_empty())
        .unwrap_or(Path::new("."));
    let Some(name) = path.file_name() else {
        return Ok(None);
    };
    let Ok(entries) = std::fs::read_dir(dir) else {
        return Ok(None);
    };
    let mut inputs: Vec<_> = entries
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| {
            p.extension()
                .is_some_and(|x| x.eq_ignore_ascii_case("fstf"))
        })
        .collect();
    inputs.sort();
    for input in inputs {
        let Ok(text) = crate::input_file::read_text(&input) else {
            continue;
        };
        let Ok((Some(mooring), positions)) = read_fast_farm(&text) else {
            continue;
        };
        if Path::new(&mooring).file_name() == Some(name) {
            return Ok(Some(Farm {
                positions,
                source: format!("{}, the FAST.Farm input beside the deck", input.display()),
            }));
        }
    }
    Ok(None)
}

/// Appends turbine n's platform as a coupled body at its position for
/// n = 1..: returns the index of turbine 1's body.
pub(super) fn turbine_bodies(farm: &Farm, bodies: &mut Vec<SystemBody>) -> usize {
    let first = bodies.len();
    for p in &farm.positions {
        let id = super::rod_parts::next_body_id(bodies);
        bodies.push(SystemBody {
            kind: BodyType::Coupled,
            ..SystemBody::fixed(id, *p, [0.0; 3])
        });
    }
    first
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_fast_farm_input_gives_its_mooring_file_and_turbines() {
        let text = "------- FAST.Farm for OpenFAST INPUT FILE ---\ntitle\n\
                    \"SharedMooring2.dat\" SharedMoorFile  - name\n\
                    2                 NumTurbines        - Number of wind turbines (-)\n\
                    WT_X     WT_Y  WT_Z     WT_FASTInFile\n(m) (m) (m) (string)\n\
                    0.000 0     0.000    \"T1.fst\"  -180\n\
                    1600.000 0     -1.5    \"T2.fst\" 1420\n--- WAKE DYNAMICS ---\n";
        let (mooring, turbines) = read_fast_farm(text).unwrap();
        assert_eq!(mooring.as_deref(), Some("SharedMooring2.dat"));
        assert_eq!(turbines, vec![[0.0, 0.0, 0.0], [1600.0, 0.0, -1.5]]);
        let short = text.replace("1600.000 0     -1.5", "1600.000");
        let e = read_fast_farm(&short).unwrap_err();
        assert!(
            e.contains("line 8: turbine 2's row starts WT_X WT_Y WT_Z"),
            "{e}"
        );
    }
}
