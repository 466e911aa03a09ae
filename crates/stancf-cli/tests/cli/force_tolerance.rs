//! `[analysis] force_tolerance` (docs/interface.md, docs/method.md
//! §11.17): a system's steps chosen by a tolerance on its end forces,
//! from a scenario; refused by name where it cannot be.

use crate::common::{
    expect_input_error, pendulum, read_json, repo_file, run_quiet, scratch, write_scenario,
};

/// examples/jumper-tolerance.toml: the jumper's steps at most 2 s,
/// written at the multiples of 2 s, the forces at t, and the kept steps
/// reported; a tenth of the tolerance takes more and shorter steps.
#[test]
fn the_jumper_example_runs_in_steps_chosen_by_its_force_tolerance() {
    let dir = scratch("force-tolerance");
    let text = std::fs::read_to_string(repo_file("examples/jumper-tolerance.toml")).unwrap();
    let text = text.replace("duration = 107.0", "duration = 30.0");
    let mut runs = Vec::new();
    for tol in ["1e-2", "1e-3"] {
        let scenario = write_scenario(
            &dir,
            &format!("jumper-{tol}.toml"),
            &text.replace(
                "force_tolerance = 1e-3",
                &format!("force_tolerance = {tol}"),
            ),
        );
        let out = dir.join(tol);
        let o = run_quiet(&scenario, &out, &[]);
        assert_eq!(
            o.status.code(),
            Some(0),
            "{}",
            String::from_utf8_lossy(&o.stderr)
        );
        let summary = read_json(&out.join("summary.json"));
        assert_eq!(summary["end_forces"], "at_time", "{summary}");
        let control = &summary["step_control"];
        let steps = control["steps"].as_u64().unwrap();
        let longest = control["longest_step"].as_f64().unwrap();
        assert_eq!(summary["steps"].as_u64(), Some(steps), "{summary}");
        assert!(longest <= 2.0 && steps >= 15, "{control}");
        // Written at t = 0 and the multiples of 2 s.
        let tensions = std::fs::read_to_string(out.join("tensions.csv")).unwrap();
        let mut times: Vec<f64> = tensions
            .lines()
            .skip(1)
            .map(|l| l.split(',').next().unwrap().parse().unwrap())
            .collect();
        // One row per line end and written time, each time once.
        assert_eq!(times.len(), 2 * 16, "{times:?}");
        times.dedup();
        let want: Vec<f64> = (0..=15).map(|k| 2.0 * k as f64).collect();
        assert_eq!(times.len(), want.len(), "{times:?}");
        for (t, w) in times.iter().zip(&want) {
            assert!((t - w).abs() < 1e-9, "{times:?}");
        }
        runs.push((steps, control["shortest_step"].as_f64().unwrap()));
    }
    assert!(runs[1].0 > runs[0].0, "{runs:?}");
}

#[test]
fn a_force_tolerance_is_refused_where_it_cannot_choose_steps() {
    let jumper = std::fs::read_to_string(repo_file("examples/jumper-tolerance.toml")).unwrap();
    expect_input_error(
        "tolerance-p2",
        &jumper.replace(
            "force_tolerance = 1e-3",
            "force_tolerance = 1e-3\ntime_scheme = \"p2\"",
        ),
        &["analysis.time_scheme", "force_tolerance", "Galerkin"],
    );
    expect_input_error(
        "tolerance-range",
        &jumper.replace("force_tolerance = 1e-3", "force_tolerance = 0.7"),
        &["analysis.force_tolerance", "below 0.5"],
    );
    expect_input_error(
        "tolerance-static",
        &jumper
            .replace("type = \"dynamic\"", "type = \"static\"")
            .replace("time_step = 2.0\n", "")
            .replace("duration = 107.0\n", ""),
        &["analysis.force_tolerance", "static"],
    );
    let cable = pendulum("pendulum", 1e-3, 0.01, 1)
        .replace("[analysis]", "[analysis]\nforce_tolerance = 1e-3");
    expect_input_error(
        "tolerance-cable",
        &cable,
        &["analysis.force_tolerance", "single cable"],
    );
}
