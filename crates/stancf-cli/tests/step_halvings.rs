//! `[analysis] step_halvings` (docs/method.md §11.13, docs/interface.md):
//! a system's step that Newton fails is taken again in halves, from a
//! scenario; refused by name for a single cable and above its bound.

mod common;

use common::{
    expect_input_error, pendulum, read_json, repo_file, run_quiet, scratch, write_scenario,
};

/// examples/bridle.toml with Galerkin steps of 10 ms for 1.5 s: at about
/// 1.09 s, as its ropes go slack, Newton does not finish a step.
fn bridle(halvings: Option<u32>) -> String {
    let text = std::fs::read_to_string(repo_file("examples/bridle.toml")).unwrap();
    let extra = halvings.map_or(String::new(), |h| format!("step_halvings = {h}\n"));
    text.replace(
        "time_step = 0.00015",
        &format!("time_step = 0.01\ntime_scheme = \"galerkin\"\n{extra}"),
    )
    .replace("every = 100", "every = 1")
}

#[test]
fn a_bridle_that_stops_at_a_slack_rope_runs_on_with_step_halvings() {
    let dir = scratch("step-halvings");
    let plain = write_scenario(&dir, "plain.toml", &bridle(None));
    let o = run_quiet(&plain, &dir.join("plain"), &[]);
    assert_eq!(
        o.status.code(),
        Some(3),
        "{}",
        String::from_utf8_lossy(&o.stderr)
    );
    let failed = read_json(&dir.join("plain/summary.json"));
    let t_failed = failed["t_final"].as_f64().unwrap();
    assert!(t_failed > 0.5 && t_failed < 1.5, "{t_failed}");

    let halved = write_scenario(&dir, "halved.toml", &bridle(Some(5)));
    let o = run_quiet(&halved, &dir.join("halved"), &[]);
    assert_eq!(
        o.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&o.stderr)
    );
    let done = read_json(&dir.join("halved/summary.json"));
    assert!(
        (done["t_final"].as_f64().unwrap() - 1.5).abs() < 1e-9,
        "{done}"
    );
    // Up to the failure the files are the run's without halvings.
    let a = std::fs::read_to_string(dir.join("plain/points.csv")).unwrap();
    let b = std::fs::read_to_string(dir.join("halved/points.csv")).unwrap();
    let lines = a.lines().count();
    assert!(b.lines().take(lines).eq(a.lines()));
}

#[test]
fn step_halvings_are_refused_for_a_single_cable_and_above_ten() {
    let cable =
        pendulum("halvings", 1e-4, 1e-3, 1).replace("[analysis]", "[analysis]\nstep_halvings = 2");
    expect_input_error(
        "single-cable-halvings",
        &cable,
        &["analysis.step_halvings", "single cable"],
    );
    expect_input_error(
        "eleven-halvings",
        &bridle(Some(11)),
        &["analysis.step_halvings"],
    );
}
