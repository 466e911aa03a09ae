//! MoorDyn-F's water kinematics file (the deck's `WaterKin` option;
//! docs/interface.md, "MoorDyn decks"), read as MoorDyn-F reads it
//! (`SetupWaterKin`): two header lines, the waves' header, `WaveKinMod`,
//! `WaveKinFile`, `dtWave`, `WaveDir`, the wave grid's x, y and z (a type
//! line and an entries line each), the current's header and `CurrentMod`;
//! with `CurrentMod` 1, two header lines and rows `z ux uy` up to the
//! first line that is not three numbers (at most 100 rows), in either
//! order of z. stancf takes `WaveKinMod` 0 (no waves) with `CurrentMod` 0
//! or 1 (a steady current profile, as `[water.current] profile`); a wave
//! grid (`WaveKinMod` 1 or 2) and a current from SeaState (`CurrentMod`
//! 2) are refused naming the file's line.

use super::water::{Current, CurrentField};
use super::ScenarioError;
use crate::moordyn::{Deck, SupportedOption};
use stancf::water::current::{CurrentProfile, CurrentRow};
use std::path::Path;

/// MoorDyn-F's most rows of a current profile.
const MAX_ROWS: usize = 100;

/// The deck's `WaterKin` file's steady current (None for `CurrentMod`
/// 0), with a note of where the file was found; None without the option.
/// Refused naming the option's line and the file's: a file not found, a
/// wave grid, SeaState's current, a profile MoorDyn-F refuses.
pub(super) fn deck_waterkin(
    deck: &Deck,
    file: &str,
    path: &Path,
) -> Result<Option<(Option<Current>, String)>, ScenarioError> {
    let Some((named, name, line)) = deck.option_text(SupportedOption::WaterKinFile) else {
        return Ok(None);
    };
    let refuse = |e: String| ScenarioError(format!("{file}: line {line}: option {name}: {e}"));
    for other in [SupportedOption::Currents, SupportedOption::WaveKin] {
        if let Some((_, other_line)) = deck.option_at(other) {
            return Err(refuse(format!(
                "MoorDyn-F's water kinematics file and MoorDyn-C's {} (line {other_line}) both \
                 describe the sea: give one of them",
                other.name()
            )));
        }
    }
    let found = super::deck_files::locate(named, path).map_err(refuse)?;
    let read = |e: String| refuse(format!("{}: {e}", found.path.display()));
    let text = crate::input_file::read_text(&found.path).map_err(read)?;
    let rows = read_waterkin(&text).map_err(read)?;
    let note = format!(
        "OPTIONS: {name} {named} (line {line}): found at {} ({}): no waves, {}",
        found.path.display(),
        found.place,
        match &rows {
            None => "no current".to_string(),
            Some(r) => format!("a steady current profile of {} rows", r.len()),
        }
    );
    let current = rows.map(|rows| Current {
        field: CurrentField::Profile(rows),
        ramp: 0.0,
        source: format!("{} (the deck's {name})", found.path.display()),
    });
    Ok(Some((current, note)))
}

/// The current profile of a WaterKin file's text (None for `CurrentMod`
/// 0), z increasing. Errors name the line.
fn read_waterkin(text: &str) -> Result<Option<Vec<CurrentRow>>, String> {
    let lines: Vec<&str> = text.lines().collect();
    let at = |i: usize| -> Result<&str, String> {
        lines.get(i).copied().ok_or_else(|| {
            format!(
                "the file ends at line {}, before line {}",
                lines.len(),
                i + 1
            )
        })
    };
    let mode = |i: usize, what: &str| -> Result<i64, String> {
        let word = at(i)?.split_whitespace().next().unwrap_or("");
        word.parse::<i64>()
            .map_err(|_| format!("line {}: {what} is \"{word}\", not a whole number", i + 1))
    };
    // Lines 1-2 header, 3 the waves' header, 4 WaveKinMod.
    match mode(3, "WaveKinMod")? {
        0 => {}
        m @ (1 | 2) => {
            return Err(format!(
                "line 4: WaveKinMod {m}: MoorDyn-F's wave grid is not supported; give the waves \
                 as [water.waves] or [water.jonswap] in a scenario that takes the deck, and \
                 WaveKinMod 0 here"
            ))
        }
        m => {
            return Err(format!(
                "line 4: WaveKinMod is {m}; MoorDyn-F's are 0, 1 and 2"
            ))
        }
    }
    // WaveKinFile, dtWave, WaveDir (lines 5-7), the grid's x, y, z (8-13),
    // the current's header (14), CurrentMod (15).
    match mode(14, "CurrentMod")? {
        0 => Ok(None),
        1 => profile(&lines).map(Some),
        2 => Err(
            "line 15: CurrentMod 2: a current from OpenFAST's SeaState module is not \
                  read; give it as [water.current] in a scenario that takes the deck"
                .into(),
        ),
        m => Err(format!(
            "line 15: CurrentMod is {m}; MoorDyn-F's are 0, 1 and 2"
        )),
    }
}

/// `CurrentMod` 1's rows after its two header lines (line 18 on): the
/// first of the next three lines that reads as three numbers starts the
/// table, which ends at the first that does not (MoorDyn-F's reading).
fn profile(lines: &[&str]) -> Result<Vec<CurrentRow>, String> {
    let row = |l: &str| -> Option<CurrentRow> {
        let v: Vec<f64> = l
            .split(|c: char| c.is_whitespace() || c == ',')
            .filter(|w| !w.is_empty())
            .take(3)
            .map(str::parse::<f64>)
            .collect::<Result<_, _>>()
            .ok()?;
        (v.len() == 3 && v.iter().all(|x| x.is_finite())).then(|| CurrentRow {
            z: v[0],
            velocity: [v[1], v[2], 0.0],
        })
    };
    let first = (17..20)
        .find(|&i| lines.get(i).is_some_and(|l| row(l).is_some()))
        .ok_or("lines 18-20: no row \"z ux uy\" of the current profile (MoorDyn-F looks there)")?;
    let mut rows: Vec<CurrentRow> = lines[first..]
        .iter()
        .map_while(|l| row(l))
        .take(MAX_ROWS)
        .collect();
    if rows.first().map(|r| r.z) > rows.last().map(|r| r.z) {
        rows.reverse();
    }
    CurrentProfile::new(&rows)
        .map_err(|e| format!("the current profile from line {}: {}", first + 1, e.message))?;
    Ok(rows)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn file(current: &str) -> String {
        format!(
            "MoorDyn Waves and Currents input file\nnotes\n--- WAVES ---\n0 WaveKinMod\n\"\" \
             WaveKinFile\n0.5 dtWave\n0 WaveDir\n2 - X\n-24, 150, 100 - X grid\n2 - Y\n\
             -100, 100, 5 - Y grid\n2 - Z\n-600, 0, 60 - Z grid\n--- CURRENT ---\n{current}"
        )
    }

    #[test]
    fn a_steady_profile_is_read_to_its_last_row_in_increasing_z() {
        let text = file("1 CurrentMod\nz-depth x y\n(m) (m/s) (m/s)\n0.0 0.3 0.1\n-5 0.2 0\n-11.0 0.1 0\n--- need this line ---\n");
        let rows = read_waterkin(&text).unwrap().unwrap();
        let z: Vec<f64> = rows.iter().map(|r| r.z).collect();
        assert_eq!(z, [-11.0, -5.0, 0.0]);
        assert_eq!(rows[2].velocity, [0.3, 0.1, 0.0]);
        assert_eq!(read_waterkin(&file("0 CurrentMod\n")).unwrap(), None);
    }

    #[test]
    fn a_wave_grid_and_seastates_current_are_refused_by_line() {
        let waves = file("0 CurrentMod\n").replacen("0 WaveKinMod", "1 WaveKinMod", 1);
        let e = read_waterkin(&waves).unwrap_err();
        assert!(e.contains("line 4: WaveKinMod 1"), "{e}");
        let e = read_waterkin(&file("2 CurrentMod\n")).unwrap_err();
        assert!(e.contains("line 15: CurrentMod 2"), "{e}");
        let e = read_waterkin(&file("1 CurrentMod\nz x y\n(m) (m/s) (m/s)\n")).unwrap_err();
        assert!(e.contains("no row"), "{e}");
    }
}
