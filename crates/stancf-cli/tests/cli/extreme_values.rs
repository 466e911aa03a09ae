//! Values out of the range the solver computes in are refused as the user
//! wrote them (issue 28, items 8 and 16): a deck's value by its line and
//! column, a system scenario's by its key, never by a key of stancf's own
//! making (`lines[0].material.youngs_modulus`), never accepted to fail
//! later. Each refusal is exit 2 from both `check` and `run`, with
//! nothing written.

use crate::common::*;
use std::path::Path;

/// The bridle deck of the examples.
fn bridle() -> String {
    std::fs::read_to_string(repo_file("examples/midwater-bridle-moordyn.txt")).unwrap()
}

/// The 1-based number of the deck line that starts with `start`.
fn line_starting(text: &str, start: &str) -> usize {
    text.lines()
        .position(|l| l.starts_with(start))
        .unwrap_or_else(|| panic!("no line starts with {start:?}"))
        + 1
}

/// Keys of stancf's own making, which a refusal must not name.
const INTERNAL_KEYS: [&str; 5] = ["material.", "loads[", "cable.", "water.gravity", "seed"];

/// `check` and `run` of `file` both exit 2 naming `file` and each of
/// `needles`, with no key of stancf's own making; `run` writes nothing.
fn refused_as_written(dir: &Path, file: &Path, needles: &[String]) {
    let mut needles: Vec<&str> = needles.iter().map(String::as_str).collect();
    let name = file.file_name().unwrap().to_str().unwrap();
    needles.push(name);
    refused_by_check_and_run(file, &dir.join("out"), &needles, &INTERNAL_KEYS);
}

#[test]
fn extreme_deck_values_are_refused_by_their_line_and_column() {
    let deck = bridle();
    let d = scratch("extreme-deck");
    let type_row = "wire      0.05    12.0     2.0E8 ";
    let line_row = "1   wire      1        3        46.0      20 ";
    let point_row = "3   Free        30.0     0.0      -95.0    2000 ";
    let cases: Vec<(&str, String, String, &str)> = vec![
        // (what, old text, new text, column named)
        (
            "Diam 1e300",
            type_row.into(),
            type_row.replace("0.05 ", "1e300 "),
            "Diam",
        ),
        (
            "Diam 1e-300",
            type_row.into(),
            type_row.replace("0.05 ", "1e-300 "),
            "Diam",
        ),
        (
            "Mass/m 1e300",
            type_row.into(),
            type_row.replace("12.0 ", "1e300 "),
            "Mass/m",
        ),
        (
            "EA 1e-300",
            type_row.into(),
            type_row.replace("2.0E8 ", "1e-300 "),
            "EA",
        ),
        (
            "UnstrLen 1e300",
            line_row.into(),
            line_row.replace("46.0 ", "1e300 "),
            "UnstrLen",
        ),
        (
            "UnstrLen 1e-300",
            line_row.into(),
            line_row.replace("46.0 ", "1e-300 "),
            "UnstrLen",
        ),
        (
            "Mass 1e300",
            point_row.into(),
            point_row.replace("2000 ", "1e300 "),
            "Mass",
        ),
        ("g 1e300", "9.81      g".into(), "1e300     g".into(), "g"),
        (
            "WtrDnsty 1e300",
            "1025      WtrDnsty".into(),
            "1e300     WtrDnsty".into(),
            "WtrDnsty",
        ),
        ("g 1e-200", "9.81      g".into(), "1e-200    g".into(), "g"),
        (
            "dtM 1e-300",
            "0.0005    dtM".into(),
            "1e-300    dtM".into(),
            "dtM",
        ),
        (
            "kBot 0",
            "150       WtrDpth".into(),
            "150       WtrDpth\n0 kBot".into(),
            "kBot",
        ),
    ];
    for (what, old, new, column) in cases {
        assert!(deck.contains(&old), "{what}");
        let bad = deck.replacen(&old, &new, 1);
        let row = new.lines().last().unwrap();
        let line = line_starting(&bad, row);
        let file = write_scenario(&d, "bad.txt", &bad);
        refused_as_written(&d, &file, &[format!("line {line}: {column}")]);
    }
    std::fs::remove_dir_all(&d).unwrap();
}

/// A rope hanging in water 30 m deep, with `water` (TOML lines) added to
/// its `[water]` and a dynamic analysis.
fn rope_in_water(water: &str) -> String {
    format!(
        "{}[water]\ndepth = 30.0\n{water}\n[analysis]\ntype = \"dynamic\"\ntime_step = 1e-3\n\
         duration = 0.01\n",
        one_rope("w", "", ("fixed", [4.0, 0.0, 0.0]), (1, 5.0, 4), "")
    )
}

#[test]
fn extreme_system_values_are_refused_by_their_keys() {
    let d = scratch("extreme-toml");
    let cases = [
        ("density = 1e300", "water.density"),
        ("[water.jonswap]\nhs = 2.0\ntp = 1e300", "water.jonswap.tp"),
        (
            "[[water.waves]]\namplitude = 1.0\nperiod = 1e100",
            "water.waves[0].period",
        ),
        (
            "[water.seabed]\nstiffness = 1e-300",
            "water.seabed.stiffness",
        ),
        (
            "[water.seabed]\nslip_velocity = 1e-300",
            "water.seabed.slip_velocity",
        ),
        (
            "[water.seabed]\nslip_velocity = 1e-12",
            "water.seabed.slip_velocity",
        ),
        ("[water.seabed]\nslope = [1e300, 0.0]", "water.seabed.slope"),
        ("[water.jonswap]\nhs = 1e150\ntp = 10.0", "water.jonswap.hs"),
    ];
    for (water, key) in cases {
        let file = write_scenario(&d, "bad.toml", &rope_in_water(water));
        refused_as_written(&d, &file, &[format!("bad.toml: {key}")]);
    }
    let heavy = one_rope("heavy", "", ("fixed", [4.0, 0.0, 0.0]), (1, 5.0, 4), "")
        .replace("mass_per_length = 0.08", "mass_per_length = 1e200")
        + "[analysis]\ntype = \"static\"\n";
    let file = write_scenario(&d, "bad.toml", &heavy);
    refused_as_written(&d, &file, &["line_types[0].mass_per_length".into()]);
    // A motion of a period of 5e-324 s, a line of 1e-60 m with a bending
    // stiffness (its bending frequency 1e124 rad/s).
    let moved = format!(
        "{}[[motions]]\npoint = 2\namplitude = [0.1, 0.0, 0.0]\nperiod = 5e-324\n\
         [analysis]\ntype = \"dynamic\"\ntime_step = 1e-3\nduration = 0.01\n",
        one_rope("m", "", ("coupled", [4.0, 0.0, 0.0]), (1, 5.0, 4), "")
    );
    let file = write_scenario(&d, "bad.toml", &moved);
    refused_as_written(&d, &file, &["bad.toml: motions[0].period".into()]);
    let tiny = one_rope(
        "t",
        "ei = 2e4",
        ("fixed", [1e-60, 0.0, 0.0]),
        (1, 1e-60, 4),
        "",
    ) + "[analysis]\ntype = \"static\"\n";
    let file = write_scenario(&d, "bad.toml", &tiny);
    refused_as_written(
        &d,
        &file,
        &["lines[0].length".into(), "bending frequency".into()],
    );
    std::fs::remove_dir_all(&d).unwrap();
}

#[test]
fn a_slow_but_plausible_slip_velocity_still_runs() {
    let d = scratch("slip-ok");
    let file = write_scenario(
        &d,
        "ok.toml",
        &rope_in_water("[water.seabed]\nslip_velocity = 1e-6"),
    );
    let o = run_quiet(&file, &d.join("out"), &[]);
    assert!(o.status.success(), "{:?}", text(&o));
    std::fs::remove_dir_all(&d).unwrap();
}

/// Item 17 of issue 28: a wave no sea has (a 100 m wave of 5 s in 20 m of
/// water: steeper than 1/7 and higher than the depth lets it be) runs, and
/// `check` and `run` say so, once each.
#[test]
fn a_wave_beyond_breaking_is_warned_of_once_by_check_and_run() {
    let d = scratch("breaking-wave");
    let sc = format!(
        "{}[water]\ndepth = 20.0\n[[water.waves]]\namplitude = 50.0\nperiod = 5.0\n\
         [analysis]\ntype = \"dynamic\"\ntime_step = 1e-3\nduration = 2e-3\n",
        one_rope("w", "", ("fixed", [4.0, 0.0, -5.0]), (1, 5.0, 4), "")
    )
    .replace("position = [0.0, 0.0, 0.0]", "position = [0.0, 0.0, -5.0]");
    let file = write_scenario(&d, "wave.toml", &sc);
    for cmd in ["check", "run"] {
        let mut args = vec![cmd, file.to_str().unwrap()];
        let out = d.join("out");
        if cmd == "run" {
            args.extend(["--out", out.to_str().unwrap()]);
        }
        let o = stancf(&args);
        let (so, se) = text(&o);
        let all = format!("{so}{se}");
        // It runs (or the solver gives up on such a sea: exit 3); it is
        // not refused.
        assert!(matches!(o.status.code(), Some(0) | Some(3)), "{cmd}: {all}");
        assert_eq!(
            all.matches("steeper than a wave can be").count(),
            1,
            "{cmd}: {all}"
        );
        assert_eq!(all.matches("H/h = 5.00 > 0.78").count(), 1, "{cmd}: {all}");
    }
    // A 2 m wave of 8 s there is neither.
    let calm = sc
        .replace("amplitude = 50.0", "amplitude = 1.0")
        .replace("period = 5.0", "period = 8.0");
    let file = write_scenario(&d, "calm.toml", &calm);
    let o = stancf(&["check", file.to_str().unwrap()]);
    let (so, se) = text(&o);
    assert!(
        o.status.success() && !so.contains("break") && !se.contains("break"),
        "{so}{se}"
    );
    std::fs::remove_dir_all(&d).unwrap();
}
