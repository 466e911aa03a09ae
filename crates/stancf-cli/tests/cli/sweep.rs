//! `stancf sweep` as docs/interface.md specifies it: the grid, sweep.csv
//! (RFC 4180, read back here with a CSV reader), failures kept row by row,
//! and the refusals (exit 2, naming the key or the size, nothing written).

use crate::common::{column as col, sweep_table as table};
use crate::common::{
    names, pendulum, read_rfc4180 as read_csv, run_to, scratch, stancf, text, BIN,
};
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};

/// A small valid scenario: the transverse impact, shortened.
const BASE: &str = crate::common::IMPACT;

fn write_scenario(dir: &Path, contents: &str) -> PathBuf {
    let p = dir.join("s.toml");
    std::fs::write(&p, contents).unwrap();
    p
}

const FIGURES: [&str; 10] = [
    "steps",
    "time",
    "wall_time_s",
    "iterations_per_step",
    "factorizations",
    "energy_max_rel_drift",
    "stress_peak_pa",
    "tip_x",
    "tip_y",
    "tip_z",
];

#[test]
fn the_reader_of_these_tests_reads_rfc_4180() {
    let rows = read_csv("a,b\r\n\"x, \"\"y\"\"\",\"two\nlines\"\n,\n");
    assert_eq!(
        rows,
        [vec!["a", "b"], vec!["x, \"y\"", "two\nlines"], vec!["", ""]]
    );
}

/// The grid of two `--set` runs in parallel, one folder per run; sweep.csv
/// has one row per point with the varied values and the summary figures,
/// equal to separate runs of the same scenarios; a run that fails is
/// reported, the others are kept; a bad key stops the sweep before
/// anything runs.
#[test]
fn sweep_runs_the_grid_and_reports_failures() {
    let d = scratch("grid");
    let sc = write_scenario(&d, BASE);
    let out = d.join("res");
    let o = stancf(&[
        "sweep",
        sc.to_str().unwrap(),
        "--set",
        "analysis.time_step=5e-5,2.5e-5",
        "--set",
        "initial_velocity.1.velocity=[0,-10,0],[0,-5,0],[0,0,0]",
        "--jobs",
        "2",
        "--out",
        out.to_str().unwrap(),
    ]);
    let (so, se) = text(&o);
    assert_eq!(o.status.code(), Some(0), "{se}");
    assert!(so.contains("6 runs (2 at a time), 0 failed"), "{so}");
    let (header, rows) = table(&out);
    let mut expected = vec![
        "run",
        "analysis.time_step",
        "initial_velocity.1.velocity",
        "status",
    ];
    expected.extend(FIGURES);
    expected.push("error");
    assert_eq!(header, expected);
    assert_eq!(rows.len(), 6);
    for (k, row) in rows.iter().enumerate() {
        assert_eq!(row[col(&header, "run")], k.to_string());
        assert_eq!(row[col(&header, "status")], "ok");
        assert_eq!(row[col(&header, "error")], "");
        // The same scenario run alone gives the same tip, to the bit.
        let alone = d.join(format!("alone{k}"));
        let run_sc = out.join(format!("run_{k:04}")).join("scenario.toml");
        let o = run_to(&run_sc, &alone);
        assert_eq!(o.status.code(), Some(0));
        let s: serde_json::Value =
            serde_json::from_str(&std::fs::read_to_string(alone.join("summary.json")).unwrap())
                .unwrap();
        let tip_y: f64 = row[col(&header, "tip_y")].parse().unwrap();
        assert_eq!(tip_y, s["tip"][1].as_f64().unwrap(), "run {k}");
    }
    assert_eq!(rows[0][1], "5e-5");
    // An array value is its TOML text, whole, in one quoted cell.
    assert_eq!(rows[5][2], "[0, 0, 0]");
    // A step far beyond P2's limit fails that run only.
    let o = stancf(&[
        "sweep",
        sc.to_str().unwrap(),
        "--set",
        "analysis.time_step=5e-5,1e-3",
        "--set",
        "analysis.duration=0.05",
        "--out",
        d.join("res2").to_str().unwrap(),
    ]);
    let (so, se) = text(&o);
    assert_eq!(o.status.code(), Some(3), "{so} {se}");
    assert!(se.contains("runs 1 failed"), "{se}");
    let (header, rows) = table(&d.join("res2"));
    assert_eq!(rows[0][col(&header, "status")], "ok");
    assert_eq!(rows[1][col(&header, "status")], "failed");
    let error = &rows[1][col(&header, "error")];
    // It names the run's folder where it is after the sweep, not where it
    // was written.
    let run_1 = d.join("res2").join("run_0001");
    assert!(error.contains(run_1.to_str().unwrap()), "{error}");
    assert!(!error.contains(".stancf-"), "{error}");
    // A misspelt key: exit 2 naming it, nothing run.
    let o = stancf(&[
        "sweep",
        sc.to_str().unwrap(),
        "--set",
        "analysis.time_stepp=1e-5",
        "--out",
        d.join("res3").to_str().unwrap(),
    ]);
    let (_, se) = text(&o);
    assert_eq!(o.status.code(), Some(2), "{se}");
    assert!(se.contains("time_stepp"), "{se}");
    assert!(!d.join("res3").exists());
}

/// The same key twice would run with the last value and label runs with
/// values they did not use: refused before anything runs, naming the key.
/// So are a key inside another and a second spelling of a list index.
#[test]
fn the_same_sweep_key_given_twice_is_refused_naming_it() {
    let d = scratch("twice");
    let sc = write_scenario(&d, BASE);
    let out = d.join("res");
    let refused = |sets: &[&str], needle: &str| {
        let mut args = vec!["sweep", sc.to_str().unwrap()];
        for s in sets {
            args.extend(["--set", s]);
        }
        args.extend(["--out", out.to_str().unwrap()]);
        let o = stancf(&args);
        let (so, se) = text(&o);
        assert_eq!(o.status.code(), Some(2), "{sets:?}: {so} {se}");
        assert!(se.contains(needle), "{sets:?}: {se}");
        assert!(!out.exists(), "{sets:?} wrote {}", out.display());
    };
    refused(
        &["analysis.time_step=5e-5", "analysis.time_step=2.5e-5"],
        "sweep: the key analysis.time_step is given twice",
    );
    refused(
        &[" analysis.time_step =5e-5", "analysis.time_step=2.5e-5"],
        "sweep: the key analysis.time_step is given twice",
    );
    refused(
        &[
            "initial_velocity.1=[]",
            "initial_velocity.1.velocity=[0,-5,0]",
        ],
        "the keys initial_velocity.1 and initial_velocity.1.velocity overlap",
    );
    // `01` or `+1` for list entry 1 would be a second spelling of one key.
    for alias in [
        "initial_velocity.01.velocity",
        "initial_velocity.+1.velocity",
    ] {
        let set = format!("{alias}=[0,-5,0]");
        refused(
            &["initial_velocity.1.velocity=[0,-10,0]", &set],
            "is not an index (0, 1, 2, ...)",
        );
    }
}

/// String values with a comma, a quote or a line break, and error
/// messages with commas, come back whole from a CSV reader.
#[test]
fn sweep_csv_cells_round_trip_through_a_csv_reader() {
    let d = scratch("quoting");
    let sc = write_scenario(&d, BASE);
    let out = d.join("res");
    let o = stancf(&[
        "sweep",
        sc.to_str().unwrap(),
        "--set",
        r#"title="a, b","say \"hi\", then go","two\nlines",plain"#,
        "--set",
        "analysis.time_step=5e-5,1e-3",
        "--set",
        "analysis.duration=0.05",
        "--jobs",
        "2",
        "--out",
        out.to_str().unwrap(),
    ]);
    let (so, se) = text(&o);
    assert_eq!(o.status.code(), Some(3), "{so} {se}");
    let (header, rows) = table(&out);
    assert_eq!(rows.len(), 8);
    let titles: Vec<&str> = rows
        .iter()
        .map(|r| r[col(&header, "title")].as_str())
        .collect();
    assert_eq!(
        titles,
        [
            "a, b",
            "a, b",
            "say \"hi\", then go",
            "say \"hi\", then go",
            "two\nlines",
            "two\nlines",
            "plain",
            "plain"
        ]
    );
    for (k, r) in rows.iter().enumerate() {
        assert_eq!(r[col(&header, "run")], k.to_string());
        // Each run had the title its row shows.
        let s: serde_json::Value = serde_json::from_str(
            &std::fs::read_to_string(out.join(format!("run_{k:04}/summary.json"))).unwrap(),
        )
        .unwrap();
        assert_eq!(s["title"].as_str(), Some(titles[k]), "run {k}");
        // Every odd run has the step far beyond the limit: failed, with
        // its whole message (commas and all) in one cell.
        let status = &r[col(&header, "status")];
        let error = &r[col(&header, "error")];
        if k % 2 == 1 {
            assert_eq!(status, "failed");
            assert!(
                error.contains("the energy grows without a source"),
                "{error}"
            );
            assert!(error.contains(", "), "a message with a comma: {error}");
            assert!(error.ends_with(&format!("run_{k:04}")), "{error}");
        } else {
            assert_eq!(status, "ok", "{error}");
            assert_eq!(error, "");
            for f in FIGURES {
                let x: f64 = r[col(&header, f)].parse().unwrap();
                assert!(x.is_finite(), "{f}");
            }
        }
    }
}

/// The size is the product of the list lengths, checked before any point
/// is built or validated: a misspelt key in a grid too big is reported as
/// the size, at once, and nothing is written.
#[test]
fn a_grid_above_ten_thousand_points_is_refused_before_it_is_built() {
    let d = scratch("too-big");
    let sc = write_scenario(&d, BASE);
    let out = d.join("res");
    let list = |n: usize| {
        (1..=n)
            .map(|k| format!("{}e-6", k))
            .collect::<Vec<_>>()
            .join(",")
    };
    let a = format!("analysis.time_step={}", list(101));
    let b = format!("analysis.duration_misspelt={}", list(100));
    let o = stancf(&[
        "sweep",
        sc.to_str().unwrap(),
        "--set",
        &a,
        "--set",
        &b,
        "--out",
        out.to_str().unwrap(),
    ]);
    let (so, se) = text(&o);
    assert_eq!(o.status.code(), Some(2), "{so} {se}");
    assert!(
        se.contains("the grid has 10100 points (101 x 100), more than the limit of 10000"),
        "{se}"
    );
    assert!(!out.exists());
    // 10^6 x 10^6 x ... does not wrap around to a small number.
    let o = stancf(&[
        "sweep",
        sc.to_str().unwrap(),
        "--set",
        "analysis.time_step=1e-5,2e-5",
        "--set",
        &format!("analysis.duration={}", list(10_000)),
        "--out",
        out.to_str().unwrap(),
    ]);
    let (_, se) = text(&o);
    assert_eq!(o.status.code(), Some(2), "{se}");
    assert!(se.contains("20000 points (2 x 10000)"), "{se}");
    assert!(!out.exists());
}

/// A grid of exactly the limit is accepted, and all of it is validated
/// before anything runs: a bad value in the last block of points stops it
/// with exit 2, naming the point, with nothing written.
#[test]
fn a_grid_at_the_limit_is_validated_point_by_point_before_anything_runs() {
    let d = scratch("at-limit");
    let sc = write_scenario(&d, BASE);
    let out = d.join("res");
    let mut durations: Vec<String> = (1..100).map(|k| format!("{k}e-3")).collect();
    durations.push("-1".into());
    let steps: Vec<String> = (1..=100).map(|k| format!("{k}e-6")).collect();
    let o = stancf(&[
        "sweep",
        sc.to_str().unwrap(),
        "--set",
        &format!("analysis.duration={}", durations.join(",")),
        "--set",
        &format!("analysis.time_step={}", steps.join(",")),
        "--out",
        out.to_str().unwrap(),
    ]);
    let (so, se) = text(&o);
    assert_eq!(o.status.code(), Some(2), "{so} {se}");
    assert!(
        se.contains("with analysis.duration=-1, analysis.time_step=1e-6"),
        "{se}"
    );
    assert!(se.contains("analysis.duration: must be > 0"), "{se}");
    assert!(!out.exists());
}

#[test]
fn a_new_sweep_replaces_an_earlier_larger_one_whole() {
    let d = scratch("replace");
    let sc = d.join("p.toml");
    std::fs::write(&sc, pendulum("p", 1e-4, 2e-3, 1)).unwrap();
    let out = d.join("sw");
    let run = |values: &str| {
        stancf(&[
            "sweep",
            sc.to_str().unwrap(),
            "--set",
            &format!("analysis.time_step={values}"),
            "--out",
            out.to_str().unwrap(),
        ])
    };
    let o = run("1e-4,2e-4,5e-4");
    assert!(o.status.success(), "{:?}", text(&o));
    assert_eq!(
        names(&out),
        ["run_0000", "run_0001", "run_0002", "sweep.csv"]
    );
    let o = run("1e-4");
    assert!(o.status.success(), "{:?}", text(&o));
    // No run folder of the earlier sweep is left beside the new table.
    assert_eq!(names(&out), ["run_0000", "sweep.csv"]);
    assert_eq!(names(&out.join("run_0000")).len(), 8);
    assert_eq!(names(&d), ["p.toml", "sw"]);
    std::fs::remove_dir_all(&d).unwrap();
}

#[test]
fn ctrl_c_stops_a_sweep_and_keeps_every_row_with_its_status() {
    let d = scratch("sigint");
    let sc = d.join("long.toml");
    // Each run would take minutes: the interrupt finds them running.
    std::fs::write(&sc, pendulum("long", 1e-4, 1e3, 100)).unwrap();
    let out = d.join("sw");
    let child = Command::new(BIN)
        .args(["sweep", sc.to_str().unwrap(), "--jobs", "1", "--out"])
        .arg(&out)
        .args(["--set", "analysis.time_step=1e-4,2e-4,3e-4"])
        .stdout(Stdio::null())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    // Wait until run 0 is stepping (its staging folder has a history).
    let start = std::time::Instant::now();
    let stepping = || {
        let Some(staging) = std::fs::read_dir(&d)
            .unwrap()
            .flatten()
            .find(|e| e.file_name().to_string_lossy().starts_with(".sw.stancf-"))
        else {
            return false;
        };
        std::fs::read_dir(staging.path()).is_ok_and(|entries| {
            entries.flatten().any(|e| {
                std::fs::metadata(e.path().join("history.csv.partial"))
                    .is_ok_and(|m| m.len() > 1000)
            })
        })
    };
    while !stepping() {
        assert!(start.elapsed().as_secs() < 60, "run 0 never started");
        std::thread::sleep(std::time::Duration::from_millis(10));
    }
    // SAFETY: kill(2) on our own child.
    assert_eq!(unsafe { libc::kill(child.id() as i32, libc::SIGINT) }, 0);
    let o = child.wait_with_output().unwrap();
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(130), "{err}");
    let (header, rows) = table(&out);
    let status = col(&header, "status");
    let statuses: Vec<&str> = rows.iter().map(|r| r[status].as_str()).collect();
    assert_eq!(statuses, ["interrupted", "not run", "not run"]);
    // The interrupted run's results are there, valid up to its last step.
    let summary: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("run_0000/summary.json")).unwrap())
            .unwrap();
    assert_eq!(summary["interrupted"], true);
    assert_eq!(names(&out), ["run_0000", "sweep.csv"]);
    std::fs::remove_dir_all(&d).unwrap();
}
