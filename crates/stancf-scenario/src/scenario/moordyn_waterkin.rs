//! MoorDyn-F's water kinematics file (the deck's `WaterKin` option;
//! docs/interface.md, "MoorDyn decks"), read as MoorDyn-F reads it
//! (`SetupWaterKin`): two header lines, the waves' header, `WaveKinMod`,
//! `WaveKinFile`, `dtWave`, `WaveDir`, the wave grid's x, y and z (a type
//! line and an entries line each), the current's header and `CurrentMod`;
//! with `CurrentMod` 1, two header lines and rows `z ux uy` up to the
//! first line that is not three numbers (blank lines skipped, as Fortran's
//! list-directed read skips them; at most 100 rows, noted beyond), in
//! either order of z. A relative path is taken from the deck's folder, as
//! MoorDyn-F opens it. stancf takes `WaveKinMod` 0 (no waves) or 1 (an
//! elevation record, `super::moordyn_waterkin_waves`) with `CurrentMod` 0
//! or 1 (a steady current profile, as `[water.current] profile`); the
//! hybrid method's waves (`WaveKinMod` 2) and a current from SeaState
//! (`CurrentMod` 2), OpenFAST's SeaState module's, are refused naming the
//! file's line.

use super::water::{Current, CurrentField};
use super::ScenarioError;
use crate::moordyn::{Deck, SupportedOption};
use stancf::water::current::{CurrentProfile, CurrentRow};
use std::path::Path;

/// MoorDyn-F's most rows of a current profile.
const MAX_ROWS: usize = 100;

/// The deck's `WaterKin` file's steady current (None for `CurrentMod`
/// 0), with a note of where the file was found; None without the option.
/// `SEASTATE` is a host's sea (no current of the deck's, a note).
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
        let set = deck.option(other).is_some_and(|v| v != 0.0);
        if let (true, Some((_, other_line))) = (set, deck.option_at(other)) {
            return Err(refuse(format!(
                "MoorDyn-F's water kinematics file and MoorDyn-C's {} (line {other_line}) both \
                 describe the sea: give one of them",
                other.name()
            )));
        }
    }
    if deck.sea_from_seastate().is_some() {
        let note = format!(
            "OPTIONS: {name} SEASTATE (line {line}): the water's kinematics (waves and current) \
             are the host's SeaState's, taken from the host at MoorDyn's points as WaveKin 1's \
             (stancf_wave_kin_set in C, Simulation.set_wave_kinematics in Python; docs/method.md \
             (W2f)-(W2h)); without a host the deck's statics are in still water"
        );
        return Ok(Some((None, note)));
    }
    let at = path.parent().unwrap_or(Path::new("")).join(named);
    let read = |e: String| refuse(format!("{}: {e}", at.display()));
    let text = crate::input_file::read_text(&at).map_err(read)?;
    let (profile, waves) = read_waterkin(&text).map_err(read)?;
    let note = format!(
        "OPTIONS: {name} {named} (line {line}): {} (from the deck's folder, as MoorDyn-F opens \
         it): {}, {}",
        at.display(),
        if waves {
            "waves from its elevation record (WaveKinMod 1, noted apart)"
        } else {
            "no waves"
        },
        match &profile {
            None => "no current".to_string(),
            Some((r, false)) => format!("a steady current profile of {} rows", r.len()),
            Some((r, true)) => format!(
                "a steady current profile of its first {} rows (MoorDyn-F reads no more; the \
                 rest are left out as it leaves them)",
                r.len()
            ),
        }
    );
    let current = profile.map(|(rows, _)| Current {
        field: CurrentField::Profile(rows),
        ramp: 0.0,
        source: format!("{} (the deck's {name})", at.display()),
    });
    Ok(Some((current, note)))
}

/// A WaterKin file's steady current profile and whether it gives waves.
type WaterKin = (Option<(Vec<CurrentRow>, bool)>, bool);

/// The current profile of a WaterKin file's text (None for `CurrentMod`
/// 0), z increasing, and whether rows beyond MoorDyn-F's 100 were left
/// out; and whether it gives waves (`WaveKinMod` 1, read by
/// `super::moordyn_waterkin_waves`). Errors name the line.
fn read_waterkin(text: &str) -> Result<WaterKin, String> {
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
    // Lines 1-2 header, 3 the waves' header, 4 WaveKinMod: its waves are
    // read by super::moordyn_waterkin_waves (here only checked).
    let waves = super::moordyn_waterkin_waves::read_wave_settings(&lines)?.is_some();
    // WaveKinFile, dtWave, WaveDir (lines 5-7), the grid's x, y, z (8-13),
    // the current's header (14), CurrentMod (15).
    match mode(14, "CurrentMod")? {
        0 => Ok((None, waves)),
        1 => profile(&lines).map(|p| (Some(p), waves)),
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
/// first of the next three lines (blank ones skipped) that reads as three
/// numbers starts the table, which ends at the first that does not
/// (MoorDyn-F's reading); whether rows beyond 100 were left out.
fn profile(lines: &[&str]) -> Result<(Vec<CurrentRow>, bool), String> {
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
    let filled: Vec<(usize, &str)> = lines
        .iter()
        .enumerate()
        .skip(17)
        .filter(|(_, l)| !l.trim().is_empty())
        .map(|(i, l)| (i, *l))
        .collect();
    let first = (0..3)
        .find(|&k| filled.get(k).is_some_and(|(_, l)| row(l).is_some()))
        .ok_or(
            "lines 18 on: none of the first three lines is a row \"z ux uy\" of the current \
                profile (MoorDyn-F looks there)",
        )?;
    let table: Vec<CurrentRow> = filled[first..].iter().map_while(|(_, l)| row(l)).collect();
    let beyond = table.len() > MAX_ROWS;
    let mut rows: Vec<CurrentRow> = table.into_iter().take(MAX_ROWS).collect();
    let first = filled[first].0;
    if rows.first().map(|r| r.z) > rows.last().map(|r| r.z) {
        rows.reverse();
    }
    CurrentProfile::new(&rows)
        .map_err(|e| format!("the current profile from line {}: {}", first + 1, e.message))?;
    Ok((rows, beyond))
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
        let (rows, beyond) = read_waterkin(&text).unwrap().0.unwrap();
        assert!(!beyond);
        let z: Vec<f64> = rows.iter().map(|r| r.z).collect();
        assert_eq!(z, [-11.0, -5.0, 0.0]);
        assert_eq!(rows[2].velocity, [0.3, 0.1, 0.0]);
        assert_eq!(
            read_waterkin(&file("0 CurrentMod\n")).unwrap(),
            (None, false)
        );
        // Blank lines are skipped, before the table and in it.
        let gaps = file("1 CurrentMod\nz x y\n(m) (m/s) (m/s)\n\n\n-11 0.1 0\n\n0 0.3 0\n");
        let (rows, _) = read_waterkin(&gaps).unwrap().0.unwrap();
        assert_eq!(rows.len(), 2);
        // MoorDyn-F reads 100 rows at most.
        let many: String = (0..120)
            .map(|k| format!("{} 0.2 0\n", -f64::from(k)))
            .collect();
        let text = file(&format!("1 CurrentMod\nz x y\n(m) (m/s) (m/s)\n{many}"));
        let (rows, beyond) = read_waterkin(&text).unwrap().0.unwrap();
        assert_eq!((rows.len(), beyond), (100, true));
    }

    #[test]
    fn seastates_waves_and_current_are_refused_by_line() {
        let waves = file("0 CurrentMod\n").replacen("0 WaveKinMod", "2 WaveKinMod", 1);
        let e = read_waterkin(&waves).unwrap_err();
        assert!(e.contains("line 4: WaveKinMod 2: the hybrid method"), "{e}");
        let e = read_waterkin(&file("2 CurrentMod\n")).unwrap_err();
        assert!(e.contains("line 15: CurrentMod 2"), "{e}");
        let e = read_waterkin(&file("1 CurrentMod\nz x y\n(m) (m/s) (m/s)\n")).unwrap_err();
        assert!(e.contains("none of the first three lines"), "{e}");
    }
}
