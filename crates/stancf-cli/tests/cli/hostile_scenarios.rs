//! Hostile scenarios (issue 11, items 6, 7 and 13): extreme finite inputs,
//! runs too long or too large to be meant, and the messages a user sees
//! for malformed input. Every refusal is exit 2 naming the file and the
//! key, with nothing written.

use crate::common::{names, pendulum, run_to, scratch, stancf, text, write_scenario};
use std::path::Path;

/// A free 4 m PVC cable whose end A is struck sideways (8 SAC-2, 4 steps).
const BASE: &str = r#"title = "hostile"
[cable]
length = 4.0
elements = 8
element = "SAC-2"
origin = [-2.0, 0.0, 0.0]
direction = [1.0, 0.0, 0.0]
[material]
youngs_modulus = 3.4e9
density = 1380.0
area = 3.0e-6
second_moment = 1.25e-13
[[initial_velocity]]
node = "A"
velocity = [0.0, 10.0, 0.0]
[analysis]
type = "dynamic"
time_step = 5.0e-5
duration = 2.0e-4
[output]
every = 1
"#;

/// BASE with the line starting with `key =` replaced by `key = value`.
fn with(key: &str, value: &str) -> String {
    with_in(BASE, key, value)
}

fn with_in(base: &str, key: &str, value: &str) -> String {
    let mut found = false;
    let s: Vec<String> = base
        .lines()
        .map(|l| {
            if !found && l.starts_with(&format!("{key} =")) {
                found = true;
                format!("{key} = {value}")
            } else {
                l.to_string()
            }
        })
        .collect();
    assert!(found, "no key {key}");
    s.join("\n") + "\n"
}

/// BASE with more tables at the end.
fn plus(extra: &str) -> String {
    format!("{BASE}{extra}")
}

/// The keys an input error names: what stands between "error: <file>: "
/// and the next ": ".
fn named_keys<'a>(stderr: &'a str, file: &str) -> &'a str {
    let rest = stderr
        .split_once(&format!("{file}: "))
        .unwrap_or_else(|| panic!("file {file} not named: {stderr}"))
        .1;
    rest.split_once(": ").map_or(rest, |(k, _)| k)
}

/// `check` and `run` both refuse `scenario` with exit 2, naming the file
/// and `key` among the keys of the message; `run` creates no output folder.
fn refused(name: &str, scenario: &str, key: &str) -> String {
    let dir = scratch(&format!("hostile-{name}"));
    let file = write_scenario(&dir, "bad.toml", scenario);
    let out = dir.join("out");
    let mut stderr = String::new();
    for cmd in ["check", "run"] {
        let mut args = vec![cmd, file.to_str().unwrap()];
        if cmd == "run" {
            args.extend(["--out", out.to_str().unwrap()]);
        }
        let o = stancf(&args);
        let (so, se) = text(&o);
        assert_eq!(o.status.code(), Some(2), "{name} ({cmd}): {se}{so}");
        let keys = named_keys(&se, "bad.toml");
        assert!(
            keys.contains(key),
            "{name} ({cmd}): {key} not in the keys {keys:?}: {se}"
        );
        for bad in ["NaN", "inf s", "18446744073709551615"] {
            assert!(!so.contains(bad), "{name} ({cmd}) printed {bad}: {so}");
        }
        stderr = se;
    }
    assert!(!out.exists(), "{name}: run created its output folder");
    stderr
}

/// `check` and `run` both accept `scenario`: exit 0, no NaN or inf printed.
fn accepted(name: &str, scenario: &str) {
    let dir = scratch(&format!("hostile-ok-{name}"));
    let file = write_scenario(&dir, "ok.toml", scenario);
    let o = stancf(&["check", file.to_str().unwrap()]);
    let (so, se) = text(&o);
    assert_eq!(o.status.code(), Some(0), "{name} (check): {se}");
    for bad in ["NaN", " inf"] {
        assert!(!so.contains(bad), "{name}: check printed {bad}: {so}");
    }
    let out = dir.join("out");
    let o = stancf(&[
        "run",
        file.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
        "-q",
    ]);
    let (_, se) = text(&o);
    assert_eq!(o.status.code(), Some(0), "{name} (run): {se}");
    assert!(out.join("summary.json").exists(), "{name}: no summary");
}

// ---------------------------------------------------------------------
// Item 6: extreme finite inputs

#[test]
fn extreme_section_and_mesh_values_are_refused_naming_the_key() {
    for (value, key) in [
        ("1e300", "material.area"),
        ("1e-300", "material.area"),
        ("1e300", "material.second_moment"),
        ("1e300", "material.youngs_modulus"),
        ("1e150", "material.youngs_modulus"),
        ("1e300", "material.density"),
        ("1e-300", "material.density"),
        ("1e300", "cable.length"),
        ("1e-300", "cable.length"),
        ("1e-60", "cable.length"),
    ] {
        let short = key.rsplit('.').next().unwrap();
        refused(&format!("{short}-{value}"), &with(short, value), key);
    }
}

#[test]
fn an_area_of_1e300_is_refused_naming_the_key_and_the_overflowing_figure() {
    let se = refused("area-message", &with("area", "1e300"), "material.area");
    assert!(se.contains("E A = inf N overflows"), "{se}");
    assert!(se.contains("material.area = 1e300"), "{se}");
}

#[test]
fn a_tiny_element_of_sac3_is_refused_for_its_slope_inertia() {
    let s = with_in(&with("element", "\"SAC-3\""), "length", "1e-40");
    let se = refused("sac3-tiny", &s, "cable.length");
    assert!(se.contains("rho A l^5"), "{se}");
}

#[test]
fn extreme_velocities_are_refused_naming_the_key() {
    refused(
        "velocity",
        &with("velocity", "[0.0, 1e200, 0.0]"),
        "initial_velocity[0].velocity",
    );
    refused(
        "velocity-energy",
        &with("velocity", "[0.0, 1e150, 0.0]"),
        "initial_velocity[0].velocity",
    );
    let spin = BASE.replace(
        "node = \"A\"\nvelocity = [0.0, 10.0, 0.0]",
        "node = \"all\"\nangular_velocity = [0.0, 0.0, 1e300]",
    );
    refused("omega", &spin, "initial_velocity[0].angular_velocity");
    let far = BASE.replace(
        "node = \"A\"\nvelocity = [0.0, 10.0, 0.0]",
        "node = \"all\"\nangular_velocity = [0.0, 0.0, 1.0]\ncenter = [1e300, 0.0, 0.0]",
    );
    refused("center", &far, "initial_velocity[0].center");
    refused(
        "origin",
        &with("origin", "[1e300, 0.0, 0.0]"),
        "cable.origin",
    );
}

#[test]
fn a_cable_so_far_from_the_origin_that_newton_cannot_converge_is_refused() {
    // 1000 km away, a 0.5 m element's coordinates are rounded to 2.2e-10 m,
    // 4.4e-10 of its length: above the default tolerance 1e-10.
    let far = with("origin", "[1e6, 0.0, 0.0]");
    let se = refused("origin-far", &far, "cable.origin");
    assert!(se.contains("analysis.tolerance"), "{se}");
    // With a tolerance above the rounding it runs.
    accepted(
        "origin-far-loose",
        &far.replace("[analysis]", "[analysis]\ntolerance = 1e-8"),
    );
    accepted("origin-near", &with("origin", "[1e4, 0.0, 0.0]"));
}

#[test]
fn extreme_loads_are_refused_naming_the_key() {
    for (name, extra, key) in [
        (
            "gravity",
            "[[loads]]\ntype = \"gravity\"\nacceleration = [0.0, -1e300, 0.0]\n",
            "loads[0].acceleration",
        ),
        (
            "gravity-fall",
            "[[loads]]\ntype = \"gravity\"\nacceleration = [0.0, -1e150, 0.0]\n",
            "loads[0].acceleration",
        ),
        (
            "force",
            "[[loads]]\ntype = \"point-force\"\nnode = \"B\"\nforce = [0.0, 1e300, 0.0]\n",
            "loads[0].force",
        ),
        (
            "moment",
            "[[loads]]\ntype = \"end-moment\"\nnode = \"B\"\nmoment = [0.0, 0.0, 1e300]\n",
            "loads[0].moment",
        ),
        (
            "drag",
            "[[loads]]\ntype = \"air-drag\"\ndrag_coefficient = 1e300\nfluid_density = 1.2\n",
            "loads[0].drag_coefficient",
        ),
        (
            "wind",
            "[[loads]]\ntype = \"air-drag\"\ndrag_coefficient = 1.0\nfluid_density = 1.2\nfluid_velocity = [0.0, 1e200, 0.0]\n",
            "loads[0].fluid_velocity",
        ),
        (
            "amplitude",
            "[[constraints]]\ntype = \"prescribed\"\nnode = \"B\"\namplitude = [0.0, 1e300, 0.0]\nfrequency = 10.0\n",
            "constraints[0].amplitude",
        ),
        (
            "frequency",
            "[[constraints]]\ntype = \"prescribed\"\nnode = \"B\"\namplitude = [0.0, 0.01, 0.0]\nfrequency = 1e300\n",
            "constraints[0].frequency",
        ),
    ] {
        refused(name, &plus(extra), key);
    }
}

#[test]
fn a_static_analysis_with_an_extreme_force_is_refused_naming_the_key() {
    let s = BASE
        .replace(
            "[[initial_velocity]]\nnode = \"A\"\nvelocity = [0.0, 10.0, 0.0]\n",
            "[[constraints]]\ntype = \"clamped\"\nnode = \"A\"\n\
             [[loads]]\ntype = \"point-force\"\nnode = \"B\"\nforce = [0.0, -1e300, 0.0]\n",
        )
        .replace(
            "type = \"dynamic\"\ntime_step = 5.0e-5\nduration = 2.0e-4",
            "type = \"static\"\nload_steps = 2",
        );
    refused("static-force", &s, "loads[0].force");
}

#[test]
fn a_step_so_long_that_the_courant_number_overflows_is_refused() {
    let s = with_in(&with("time_step", "1e300"), "duration", "4e300");
    refused("dt-huge", &s, "analysis.time_step");
}

#[test]
fn extremes_that_harm_nothing_are_accepted_and_run() {
    accepted("tiny-second-moment", &with("second_moment", "1e-300"));
    accepted("tiny-modulus", &with("youngs_modulus", "1e-300"));
    accepted("huge-direction", &with("direction", "[1e300, 1e300, 0.0]"));
    accepted("tiny-direction", &with("direction", "[1e-300, 0.0, 0.0]"));
}

// ---------------------------------------------------------------------
// Item 7: bounds on work

#[test]
fn a_duration_of_1e30_is_refused_as_an_uncountable_number_of_steps() {
    let se = refused(
        "duration-1e30",
        &with("duration", "1e30"),
        "analysis.duration",
    );
    assert!(se.contains("analysis.time_step"), "{se}");
    assert!(se.contains("2e34 steps"), "{se}");
}

#[test]
fn check_prints_the_true_step_count_and_warns_above_1e8_steps() {
    let dir = scratch("hostile-steps-warn");
    let file = write_scenario(&dir, "long.toml", &with("duration", "1e4"));
    let o = stancf(&["check", file.to_str().unwrap()]);
    let (so, se) = text(&o);
    assert_eq!(o.status.code(), Some(0), "{se}");
    let steps = so
        .lines()
        .find(|l| l.starts_with("steps "))
        .unwrap_or_else(|| panic!("no steps line: {so}"));
    assert!(steps.trim_end().ends_with(" 200000000"), "{steps}");
    let warning = so
        .lines()
        .find(|l| l.starts_with("warning:") && l.contains("--allow-large"))
        .unwrap_or_else(|| panic!("no bound warning: {so}"));
    for needle in [
        "analysis.duration",
        "analysis.time_step",
        "2e8 steps",
        "1e8",
    ] {
        assert!(warning.contains(needle), "{needle} not in {warning}");
    }
    assert!(!so.contains("warnings                    none"), "{so}");
}

#[test]
fn run_refuses_more_than_1e8_steps_naming_the_keys_and_the_flag() {
    let dir = scratch("hostile-steps-run");
    let file = write_scenario(&dir, "long.toml", &with("duration", "1e4"));
    let out = dir.join("out");
    let o = run_to(&file, &out);
    let (_, se) = text(&o);
    assert_eq!(o.status.code(), Some(2), "{se}");
    let keys = named_keys(&se, "long.toml");
    assert!(keys.contains("analysis.duration"), "{se}");
    assert!(keys.contains("analysis.time_step"), "{se}");
    assert!(se.contains("--allow-large"), "{se}");
    assert!(!out.exists(), "an output folder was created");
}

/// 1000 elements written at every one of 1e5 steps: about 50 GB.
fn huge_output() -> String {
    with_in(
        &with_in(&with("elements", "1000"), "duration", "5.0"),
        "every",
        "1",
    )
}

#[test]
fn check_warns_when_the_results_would_exceed_4_gb() {
    let dir = scratch("hostile-size-warn");
    let file = write_scenario(&dir, "big.toml", &huge_output());
    let o = stancf(&["check", file.to_str().unwrap()]);
    let (so, se) = text(&o);
    assert_eq!(o.status.code(), Some(0), "{se}");
    let estimate = so
        .lines()
        .find(|l| l.starts_with("result files"))
        .unwrap_or_else(|| panic!("no estimate: {so}"));
    assert!(estimate.contains(" GB"), "{estimate}");
    let warning = so
        .lines()
        .find(|l| l.starts_with("warning:") && l.contains("--allow-large"))
        .unwrap_or_else(|| panic!("no size warning: {so}"));
    assert!(warning.contains("output.every"), "{warning}");
    assert!(warning.contains("4 GB"), "{warning}");
}

#[test]
fn run_refuses_results_beyond_4_gb_naming_output_every() {
    let dir = scratch("hostile-size-run");
    let file = write_scenario(&dir, "big.toml", &huge_output());
    let out = dir.join("out");
    let o = run_to(&file, &out);
    let (_, se) = text(&o);
    assert_eq!(o.status.code(), Some(2), "{se}");
    let keys = named_keys(&se, "big.toml");
    assert!(keys.contains("output.every"), "{se}");
    assert!(se.contains("--allow-large"), "{se}");
    assert!(!out.exists(), "an output folder was created");
}

#[test]
fn an_ordinary_run_is_within_the_bounds() {
    let dir = scratch("hostile-small");
    let file = write_scenario(&dir, "small.toml", BASE);
    let o = stancf(&["check", file.to_str().unwrap()]);
    let (so, _) = text(&o);
    assert!(so.contains("warnings                    none"), "{so}");
    assert!(!so.contains("--allow-large"), "{so}");
}

// ---------------------------------------------------------------------
// Item 13: messages

/// `check` refuses `scenario` naming `key` and saying every one of
/// `needles`, and none of `never`.
fn message(name: &str, scenario: &str, key: &str, needles: &[&str], never: &[&str]) {
    let dir = scratch(&format!("hostile-msg-{name}"));
    let file = write_scenario(&dir, "bad.toml", scenario);
    let o = stancf(&["check", file.to_str().unwrap()]);
    let (_, se) = text(&o);
    assert_eq!(o.status.code(), Some(2), "{name}: {se}");
    assert!(
        se.contains(&format!("bad.toml: {key}: ")),
        "{name}: {key} not named: {se}"
    );
    for n in needles {
        assert!(se.contains(n), "{name}: {n:?} not in {se}");
    }
    for n in never {
        assert!(!se.contains(n), "{name}: {n:?} in {se}");
    }
}

#[test]
fn a_fractional_node_is_refused_saying_what_a_node_may_be() {
    let what = ["\"A\"", "\"B\"", "integer node index 0..=8", "2.5"];
    let never = ["untagged", "RawNode", "variant"];
    message(
        "iv-node",
        &BASE.replace("node = \"A\"", "node = 2.5"),
        "initial_velocity[0].node",
        &[&what[..], &["\"all\""]].concat(),
        &never,
    );
    message(
        "constraint-node",
        &plus("[[constraints]]\ntype = \"pinned\"\nnode = 2.5\n"),
        "constraints[0].node",
        &what,
        &never,
    );
    message(
        "force-node",
        &plus("[[loads]]\ntype = \"point-force\"\nnode = 2.5\nforce = [0.0, 1.0, 0.0]\n"),
        "loads[0].node",
        &what,
        &never,
    );
    message(
        "moment-node-list",
        &plus("[[loads]]\ntype = \"end-moment\"\nnode = [8]\nmoment = [0.0, 0.0, 1.0]\n"),
        "loads[0].node",
        &["\"A\"", "a list"],
        &never,
    );
}

#[test]
fn a_wrongly_typed_load_or_constraint_value_names_its_key_in_plain_words() {
    let never = ["sequence", "f64", "i64"];
    message(
        "gravity-scalar",
        &plus("[[loads]]\ntype = \"gravity\"\nacceleration = 9.81\n"),
        "loads[0].acceleration",
        &["vector of 3 numbers", "9.81"],
        &never,
    );
    message(
        "force-text",
        &plus("[[loads]]\ntype = \"point-force\"\nnode = \"B\"\nforce = [0.0, \"1\", 0.0]\n"),
        "loads[0].force",
        &["component 1", "number", "\"1\""],
        &never,
    );
    message(
        "drag-text",
        &plus("[[loads]]\ntype = \"air-drag\"\ndrag_coefficient = \"high\"\nfluid_density = 1.2\n"),
        "loads[0].drag_coefficient",
        &["a number", "\"high\""],
        &never,
    );
    message(
        "clamp-flag",
        &plus("[[constraints]]\ntype = \"clamped\"\nnode = \"A\"\nfix_curvature = 1\n"),
        "constraints[0].fix_curvature",
        &["true or false"],
        &never,
    );
}

#[test]
fn a_wrongly_typed_top_level_value_is_described_in_plain_words_with_its_line() {
    let dir = scratch("hostile-msg-types");
    for (name, s, needles) in [
        (
            "elements",
            with("elements", "8.5"),
            vec!["line 4", "expected an integer"],
        ),
        (
            "length",
            with("length", "\"4\""),
            vec!["line 3", "expected a number"],
        ),
        (
            "origin",
            with("origin", "3"),
            vec!["line 6", "expected a list"],
        ),
    ] {
        let file = write_scenario(&dir, &format!("{name}.toml"), &s);
        let o = stancf(&["check", file.to_str().unwrap()]);
        let (_, se) = text(&o);
        assert_eq!(o.status.code(), Some(2), "{name}: {se}");
        for n in needles {
            assert!(se.contains(n), "{name}: {n:?} not in {se}");
        }
        for n in ["i64", "f64", "sequence"] {
            assert!(!se.contains(n), "{name}: {n:?} in {se}");
        }
    }
}

/// Runs `check` on `contents` and returns its standard error, which must
/// be an input error of at most `max` bytes.
fn short_error(name: &str, contents: &str, max: usize) -> String {
    let dir = scratch(&format!("hostile-long-{name}"));
    let file = write_scenario(&dir, "long.toml", contents);
    let o = stancf(&["check", file.to_str().unwrap()]);
    let (_, se) = text(&o);
    assert_eq!(
        o.status.code(),
        Some(2),
        "{name}: {}",
        &se[..se.len().min(500)]
    );
    assert!(se.len() <= max, "{name}: {} bytes of stderr", se.len());
    se
}

#[test]
fn a_5_mb_bad_line_is_echoed_in_at_most_200_characters() {
    let line = format!("title = \"{}\n", "x".repeat(5_000_000));
    let se = short_error("line", &format!("{line}{BASE}"), 1500);
    assert!(se.contains("long.toml: TOML parse error at line 1"), "{se}");
    assert!(se.contains('…'), "no ellipsis where cut: {se}");
    let echoed = se
        .lines()
        .find(|l| l.starts_with("1 | "))
        .expect("the line");
    assert!(echoed.chars().count() <= 4 + 200 + 2, "{echoed}");
}

#[test]
fn the_error_column_stays_in_the_window_of_a_long_line() {
    // The error (a second `=`) 1 MB into the line: the window shows it
    // with the caret under it.
    let line = format!("title = \"{}\" = 1\n", "y".repeat(1_000_000));
    let se = short_error("column", &format!("{line}{BASE}"), 1500);
    let lines: Vec<&str> = se.lines().collect();
    let at = lines
        .iter()
        .position(|l| l.starts_with("1 | "))
        .expect("the line");
    let caret = lines[at + 1].find('^').expect("a caret");
    let shown: Vec<char> = lines[at].chars().collect();
    let under: String = shown[caret..].iter().take(1).collect();
    assert_eq!(under, "=", "caret not under the error: {se}");
}

#[test]
fn long_unknown_keys_and_values_are_cut_in_messages() {
    let key = "k".repeat(3_000_000);
    let se = short_error(
        "key",
        &BASE.replace("[material]", &format!("[material]\n{key} = 1")),
        1500,
    );
    assert!(se.contains("unknown field"), "{se}");
    let value = "v".repeat(3_000_000);
    let se = short_error("value", &with("element", &format!("\"{value}\"")), 1000);
    assert!(se.contains("cable.element") && se.contains('…'), "{se}");
    let se = short_error(
        "load-type",
        &plus(&format!("[[loads]]\ntype = \"{value}\"\n")),
        1000,
    );
    assert!(se.contains("loads[0].type") && se.contains('…'), "{se}");
}

/// A cantilever (clamped at A) under an end moment that would roll it up
/// in one load step with one Newton iteration: the static solve fails.
fn failing_static() -> String {
    BASE.replace(
        "[[initial_velocity]]\nnode = \"A\"\nvelocity = [0.0, 10.0, 0.0]\n",
        "[[constraints]]\ntype = \"clamped\"\nnode = \"A\"\n\
         [[loads]]\ntype = \"end-moment\"\nnode = \"B\"\nmoment = [0.0, 0.0, 1e-1]\n",
    )
    .replace(
        "type = \"dynamic\"\ntime_step = 5.0e-5\nduration = 2.0e-4",
        "type = \"static\"\nload_steps = 1\nmax_iterations = 1",
    )
}

#[test]
fn a_static_failure_names_the_load_factor_not_a_time() {
    let dir = scratch("hostile-static-fail");
    let file = write_scenario(&dir, "static.toml", &failing_static());
    let out = dir.join("out");
    let o = run_to(&file, &out);
    let (_, se) = text(&o);
    assert_eq!(o.status.code(), Some(3), "{se}");
    assert!(se.contains("at load factor 0 (increment 1,"), "{se}");
    assert!(!se.contains("t = "), "{se}");
}

#[test]
fn a_solver_failure_prints_its_time_with_at_most_six_significant_digits() {
    // Three times P2's stable step: the energy grows within a few steps,
    // at a time k dt whose binary sum has a long decimal tail.
    let s = with_in(&with("time_step", "3.1e-4"), "duration", "0.05");
    let dir = scratch("hostile-time-digits");
    let file = write_scenario(&dir, "fast.toml", &s);
    let out = dir.join("out");
    let o = stancf(&[
        "run",
        file.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
        "-q",
    ]);
    let (_, se) = text(&o);
    assert_eq!(o.status.code(), Some(3), "{se}");
    let t = se
        .split_once(" at t = ")
        .unwrap_or_else(|| panic!("no time: {se}"))
        .1
        .split_once(" s")
        .unwrap()
        .0;
    let digits = t
        .split('e')
        .next()
        .unwrap()
        .chars()
        .filter(|c| c.is_ascii_digit())
        .collect::<String>()
        .trim_start_matches('0')
        .len();
    assert!(digits <= 6, "t = {t} has {digits} significant digits: {se}");
    let value: f64 = t.parse().unwrap_or_else(|_| panic!("t = {t}"));
    assert!(value > 0.0, "{se}");
}

#[test]
fn plot_names_the_figure_whose_path_is_a_folder() {
    let dir = scratch("hostile-plot-folder");
    let file = write_scenario(&dir, "pendulum.toml", &pendulum("plot", 1e-3, 4e-3, 1));
    let out = dir.join("out");
    let o = stancf(&[
        "run",
        file.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
        "-q",
    ]);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o).1);
    std::fs::create_dir(out.join("energy.png")).unwrap();
    let o = stancf(&["plot", out.to_str().unwrap()]);
    let (_, se) = text(&o);
    assert_eq!(o.status.code(), Some(2), "{se}");
    let path = out.join("energy.png");
    assert!(
        se.contains(&path.display().to_string()),
        "file not named: {se}"
    );
    assert!(se.contains("is a folder"), "{se}");
    assert!(
        !names(&out).iter().any(|n| n.ends_with(".partial")),
        "a .partial left: {:?}",
        names(&out)
    );
    assert!(
        Path::new(&out.join("energy.png")).is_dir(),
        "the user's folder was touched"
    );
}

/// Issue 11, item 13: when `output.every` does not divide the step count,
/// the last step is written anyway, with its own Newton figures (it used
/// to show 0 iterations and no increment).
#[test]
fn the_last_step_written_out_of_turn_keeps_its_own_solver_figures() {
    let d = scratch("every-last-row");
    // 105 steps written every 10th: the last row is step 105.
    let sc = write_scenario(&d, "p.toml", &pendulum("p", 1e-4, 1.05e-2, 10));
    let out = d.join("out");
    let o = stancf(&[
        "run",
        "--quiet",
        sc.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{:?}", text(&o));
    let (h_head, history) = crate::common::read_csv(&out.join("history.csv"));
    let (s_head, solver) = crate::common::read_csv_with_blanks(&out.join("solver.csv"));
    let col = |head: &[String], name: &str| head.iter().position(|h| h == name).unwrap();
    let last = history.last().unwrap();
    let last_step = solver.last().unwrap();
    assert_eq!(history.len(), 1 + 10 + 1);
    assert!((last[0] - 1.05e-2).abs() < 1e-15);
    for name in ["iterations", "residual", "increment"] {
        assert_eq!(
            last[col(&h_head, name)],
            last_step[col(&s_head, name)],
            "{name} of the last row"
        );
    }
    assert!(last[col(&h_head, "iterations")] >= 1.0);
    std::fs::remove_dir_all(&d).unwrap();
}
