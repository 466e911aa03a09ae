//! A MoorDyn deck's water (docs/interface.md, "Water"): the options
//! WtrDpth, WtrDnsty, kBot, cBot, FrictionCoefficient (axial and
//! transverse alike) and `Currents` 1 (the steady profile of
//! `current_profile.txt` beside the deck, MoorDyn-C's format), 2 and 5
//! (its dynamic profile and 4-D grid, `super::moordyn_current_grids`),
//! merged with the `[water]` keys of a scenario that takes the deck: a
//! key both give is refused naming both.
//!
//! What the deck asks for that stancf does not map is refused by name:
//! `Currents` 3 and 4 (node modes MoorDyn does not implement either).
//! The deck's waves (`WaveKin`): `super::moordyn_waves`.

use super::context::Ctx;
use super::water::{Current, CurrentField, Water, WaterKeys};
use super::ScenarioError;
use crate::moordyn::{Deck, SupportedOption};
use stancf::water::current::{CurrentProfile, CurrentRow};
use std::path::Path;

/// The file MoorDyn-C reads a steady current profile from (`Currents 1`),
/// in the deck's folder.
pub const CURRENT_PROFILE_FILE: &str = "current_profile.txt";

/// The lines of MoorDyn-C's `current_profile.txt` before its rows (a
/// title, a description, the column names), skipped as MoorDyn skips them.
const CURRENT_PROFILE_HEADER_LINES: usize = 3;

/// The water keys the deck at `path` (named `file` in messages) gives,
/// and notes on its current where it varies in time and on its seafloor
/// file.
pub(super) fn deck_water_keys(
    deck: &Deck,
    file: &str,
    path: &Path,
) -> Result<(WaterKeys, Vec<String>), ScenarioError> {
    let friction = deck.option(SupportedOption::FrictionCoefficient);
    for separate in [
        SupportedOption::AxialFriction,
        SupportedOption::TransverseFriction,
    ] {
        if let (Some(one), Some(other)) = (
            deck.option_at(SupportedOption::FrictionCoefficient),
            deck.option_at(separate),
        ) {
            return Err(ScenarioError(format!(
                "{file}: line {}: option {} and {} (line {}) both give the seabed's friction \
                 (MoorDyn-C's one coefficient, MoorDyn-F's separate ones): give one of them",
                other.1, other.0, one.0, one.1
            )));
        }
    }
    let (current, note) = match super::moordyn_waterkin::deck_waterkin(deck, file, path)? {
        Some((current, note)) => (current, Some(note)),
        None => deck_current(deck, file, path)?,
    };
    let (bathymetry, bed_note) = super::moordyn_seafloor::deck_seafloor(deck, file, path)?;
    // MoorDyn's water depth with a seafloor file is the bed's mean depth,
    // whatever WtrDpth says (MoorDyn2.cpp, after the options).
    let depth = match &bathymetry {
        Some(bed) => Some(-bed.grid.mean_height()),
        None => deck.option(SupportedOption::WaterDepth),
    };
    let keys = WaterKeys {
        depth,
        density: deck.option(SupportedOption::WaterDensity),
        stiffness: deck.option(SupportedOption::BottomStiffness),
        damping: deck.option(SupportedOption::BottomDamping),
        friction_axial: deck.option(SupportedOption::AxialFriction).or(friction),
        friction_transverse: deck
            .option(SupportedOption::TransverseFriction)
            .or(friction),
        current,
        bathymetry,
        host_waves: deck.host_sets_waves().then_some(true),
        ..WaterKeys::default()
    };
    Ok((keys, note.into_iter().chain(bed_note).collect()))
}

/// `Currents`: 0 (or missing) none; 1 the steady profile of
/// [`CURRENT_PROFILE_FILE`] beside the deck; 2 and 5 the dynamic profile
/// and the 4-D grid (`super::moordyn_current_grids`), with a note; 3 and
/// 4 (MoorDyn's unimplemented node modes) and others refused.
fn deck_current(
    deck: &Deck,
    file: &str,
    path: &Path,
) -> Result<(Option<Current>, Option<String>), ScenarioError> {
    use super::moordyn_current_grids as grids;
    let Some(mode) = deck.option(SupportedOption::Currents) else {
        return Ok((None, None));
    };
    let (name, line) = deck
        .option_at(SupportedOption::Currents)
        .expect("the option is set");
    let source = match mode {
        0.0 => return Ok((None, None)),
        1.0 => CURRENT_PROFILE_FILE,
        2.0 => grids::DYNAMIC_PROFILE_FILE,
        5.0 => grids::GRID_4D_FILE,
        _ => {
            return Err(ScenarioError(format!(
                "{file}: line {line}: option {name} is {mode}: MoorDyn-C's current modes are 0, \
                 1 (steady profile), 2 (dynamic profile) and 5 (4-D grid); its 3 and 4 are not \
                 implemented by MoorDyn either"
            )))
        }
    };
    let dir = path.parent().unwrap_or(Path::new(""));
    let at = dir.join(source);
    let read = |e: String| {
        ScenarioError(format!(
            "{file}: line {line}: option {name} {mode} reads {}: {e}",
            at.display()
        ))
    };
    let described = format!("{} (the deck's {name} {mode})", at.display());
    if mode == 1.0 {
        let rows = read_current_profile(&at).map_err(read)?;
        let current = Current {
            field: CurrentField::Profile(rows),
            ramp: 0.0,
            source: described,
        };
        return Ok((Some(current), None));
    }
    let text = crate::input_file::read_text(&at).map_err(read)?;
    let grid = if mode == 2.0 {
        grids::read_dynamic_profile(&text)
    } else {
        grids::read_grid_4d(&text)
    }
    .map_err(read)?;
    let note = grids::grid_note(mode as u8, name, line, &at, &grid);
    let current = Current {
        field: CurrentField::Grid(Box::new(grid)),
        ramp: 0.0,
        source: described,
    };
    Ok((Some(current), Some(note)))
}

/// MoorDyn-C's steady current profile: 3 lines skipped, then rows
/// `z ux [uy [uz]]` (m, m/s; z up, the still surface z = 0; uy and uz 0
/// when left out and further columns ignored, as MoorDyn reads them),
/// blank lines skipped, z strictly increasing or decreasing. Errors name
/// the line.
pub fn read_current_profile(path: &Path) -> Result<Vec<CurrentRow>, String> {
    let text = crate::input_file::read_text(path)?;
    let mut rows = Vec::new();
    let mut lines = Vec::new();
    let shape = "\"z ux [uy [uz]]\"";
    for (at, mut v) in table_rows(&text, CURRENT_PROFILE_HEADER_LINES, 2..=usize::MAX, shape)? {
        v.resize(v.len().max(4), 0.0);
        rows.push(CurrentRow {
            z: v[0],
            velocity: [v[1], v[2], v[3]],
        });
        lines.push(at);
    }
    if rows.is_empty() {
        return Err(format!(
            "no rows after the {CURRENT_PROFILE_HEADER_LINES} header lines"
        ));
    }
    CurrentProfile::new(&rows).map_err(|e| {
        let row: Option<usize> = e
            .key
            .trim_start_matches("rows[")
            .split(']')
            .next()
            .and_then(|i| i.parse().ok());
        match row {
            Some(i) => format!("line {}: {}", lines[i], e.message),
            None => e.message,
        }
    })?;
    Ok(rows)
}

/// The rows of a whitespace-separated table of MoorDyn's (a current
/// profile, wave components): `skip` header lines left out, blank lines
/// skipped, each row of `count` finite numbers (`usize::MAX` as its end:
/// any more; `row` says what one is in the error), with its 1-based line
/// number. Errors name the line.
pub(super) fn table_rows(
    text: &str,
    skip: usize,
    count: std::ops::RangeInclusive<usize>,
    row: &str,
) -> Result<Vec<(usize, Vec<f64>)>, String> {
    let mut rows = Vec::new();
    for (n, l) in crate::echo::text_lines(text).enumerate().skip(skip) {
        let words: Vec<&str> = l.split_whitespace().collect();
        if words.is_empty() {
            continue;
        }
        let at = n + 1;
        if !count.contains(&words.len()) {
            let (lo, hi) = (count.start(), count.end());
            let numbers = if lo == hi {
                format!("{lo}")
            } else if *hi == usize::MAX {
                format!("at least {lo}")
            } else {
                format!("{lo} or {hi}")
            };
            return Err(format!(
                "line {at}: a row is {row}, {numbers} numbers, got {} words",
                words.len()
            ));
        }
        let values = words
            .iter()
            .map(|w| super::messages::finite_word(w, at))
            .collect::<Result<Vec<f64>, String>>()?;
        rows.push((at, values));
    }
    Ok(rows)
}

/// The deck option a `[water]` key of [`WaterKeys::given`] collides with.
fn deck_option_of(key: &str, deck: &Deck) -> SupportedOption {
    let separate = |which: SupportedOption| {
        if deck.option(which).is_some() {
            which
        } else {
            SupportedOption::FrictionCoefficient
        }
    };
    let bed = deck.option_text(SupportedOption::SeafloorFile).is_some();
    match key {
        "water.depth" if bed => SupportedOption::SeafloorFile,
        "water.seabed.file" => SupportedOption::SeafloorFile,
        "water.depth" => SupportedOption::WaterDepth,
        "water.density" => SupportedOption::WaterDensity,
        "water.seabed.stiffness" => SupportedOption::BottomStiffness,
        "water.seabed.damping" => SupportedOption::BottomDamping,
        "water.current" => SupportedOption::Currents,
        "water.host_waves" if deck.sea_from_seastate().is_some() => SupportedOption::WaterKinFile,
        "water.host_waves" => SupportedOption::WaveKin,
        "water.seabed.friction_axial" => separate(SupportedOption::AxialFriction),
        _ => separate(SupportedOption::TransverseFriction),
    }
}

/// The deck's water with the scenario's `[water]` keys `added` (checked
/// under `ctx`, the scenario) : a key both give is refused naming the
/// key and the deck's option and line. Without a depth from either,
/// MoorDyn's rule ([`moordyn_depth`]), noted (the note returned).
pub(super) fn deck_water(
    deck_keys: WaterKeys,
    file: &str,
    deck: &Deck,
    added: Option<(&Ctx, WaterKeys)>,
    host: &super::HostEnvironment,
) -> Result<(Water, Option<String>), ScenarioError> {
    let scenario = added.as_ref().map(|(ctx, _)| *ctx);
    let mut keys = match added {
        None => deck_keys,
        Some((ctx, added)) => {
            for ((key, in_deck), (_, in_scenario)) in deck_keys.given().iter().zip(added.given()) {
                if *in_deck && in_scenario {
                    let (name, line) = deck
                        .option_at(deck_option_of(key, deck))
                        .expect("the deck sets it");
                    return Err(ctx.err(
                        key,
                        format!(
                            "the deck {file} gives it too (option {name}, line {line}): give \
                             it in one place"
                        ),
                    ));
                }
            }
            deck_keys.or(added)
        }
    }
    .or(host.water_keys());
    if let (Some(_), Some((_, name, line))) =
        (keys.slope, deck.option_text(SupportedOption::SeafloorFile))
    {
        let ctx = scenario.expect("a deck gives no slope: the scenario's");
        return Err(ctx.err(
            "water.seabed.slope",
            format!(
                "the deck {file} gives the bed's shape (option {name}, line {line}): give a \
                 slope or a seafloor file, not both"
            ),
        ));
    }
    let mut note = None;
    if keys.depth.is_none() {
        if let Some(depth) = moordyn_depth(deck) {
            keys.depth = Some(depth);
            note = Some(format!(
                "OPTIONS: no WtrDpth: MoorDyn's rule, the depth of the deepest point, {} m (its \
                 anchors on the bed); give WtrDpth, water.depth in a scenario that takes the \
                 deck, or the host's depth (--water-depth, or from a coupling code), for another",
                stancf::error::Sig(depth)
            ));
        }
    }
    let water = keys.water().ok_or_else(|| {
        ScenarioError(format!(
            "{file}: OPTIONS: WtrDpth is missing and no point is under the surface to take \
             MoorDyn's depth from (the deepest point's): give WtrDpth, water.depth in a \
             scenario that takes the deck, or the host's depth (--water-depth)"
        ))
    })?;
    Ok((water, note))
}

/// MoorDyn's water depth when a deck gives none (`MoorDyn::ReadInFile`:
/// WtrDpth starts at 0 and each point below -WtrDpth lowers it to that
/// point): the depth of the deepest point of POINTS, if one is under the
/// surface.
fn moordyn_depth(deck: &Deck) -> Option<f64> {
    let deepest = deck
        .points
        .iter()
        .map(|p| -p.position[2])
        .fold(0.0f64, f64::max);
    (deepest > 0.0).then_some(deepest)
}
