//! What `stancf run` prints for a system (docs/interface.md, "Systems"):
//! each line's end tensions in one number form (6 significant digits,
//! exponent form: `1.10601e6`, `9.08050e5`), named for what they are:
//! the tension at equilibrium of a static run, the largest of a dynamic
//! run; the same numbers as summary.json's `max_tension_a` and `_b`.

use crate::common::*;

/// The printed line of each line: `line <id>: <what> <a> N at end A, <b>
/// N at end B`, with a and b as summary.json gives them, printed `{:.5e}`.
fn expect_tension_lines(out: &std::path::Path, stdout: &str, what: &str) {
    let summary = read_json(&out.join("summary.json"));
    let lines = summary["lines"].as_array().expect("summary.json's lines");
    assert!(!lines.is_empty());
    for l in lines {
        let a = l["max_tension_a"].as_f64().unwrap();
        let b = l["max_tension_b"].as_f64().unwrap();
        let expected = format!(
            "line {}: {what} {a:.5e} N at end A, {b:.5e} N at end B",
            l["id"]
        );
        assert!(stdout.contains(&expected), "{expected:?} not in\n{stdout}");
    }
    // No tension in the other form, nor the other run's words.
    let other = if what == "largest tension" {
        "tension at equilibrium"
    } else {
        "largest tension"
    };
    assert!(!stdout.contains(other), "{stdout}");
}

#[test]
fn a_static_systems_summary_gives_the_tension_at_equilibrium_in_one_number_form() {
    let d = scratch("system-summary-static");
    let out = d.join("out");
    let o = run_to(&repo_file("examples/midwater-bridle-moordyn.txt"), &out);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o).1);
    let stdout = text(&o).0;
    expect_tension_lines(&out, &stdout, "tension at equilibrium");
    // A static run has no steps to time.
    let summary = read_json(&out.join("summary.json"));
    assert!(summary["stepping_wall_time_s"].is_null(), "{summary}");
    // The README's figures: 13889.8 N at the anchor end of line 1.
    assert!(
        stdout.contains("line 1: tension at equilibrium 1.38898e4 N at end A"),
        "{stdout}"
    );
}

#[test]
fn a_dynamic_systems_summary_gives_the_largest_tension_in_one_number_form() {
    let d = scratch("system-summary-dynamic");
    let text_of = one_rope("sag", "", ("fixed", [3.0, 0.0, 0.0]), (7, 4.0, 8), "")
        + "[analysis]\ntype = \"dynamic\"\ntime_step = 1e-4\nduration = 1e-3\n";
    let sc = write_scenario(&d, "sag.toml", &text_of);
    let out = d.join("out");
    let o = run_to(&sc, &out);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o).1);
    expect_tension_lines(&out, &text(&o).0, "largest tension");
    // The steps' own wall time, a part of the whole run's.
    let summary = read_json(&out.join("summary.json"));
    let stepping = summary["stepping_wall_time_s"].as_f64().expect("timed");
    let whole = summary["wall_time_s"].as_f64().unwrap();
    assert!(stepping > 0.0 && stepping <= whole, "{stepping} {whole}");
}
