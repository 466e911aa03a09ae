//! Graded meshes from the command line (docs/interface.md, the `grading`
//! key of `[cable]` and `[[lines]]`; docs/method.md §1.6): runs write the
//! graded arc lengths, `check` reports the shortest and longest elements,
//! and bad gradings are refused naming the key.

use crate::common::*;
use stancf::{GradedEnd, Grading};

/// A rope hanging between two fixed points 8 m apart, 10 m long, in 12
/// elements graded by `grading` (a TOML inline table, or "" for none),
/// with `analysis` as the `[analysis]` body.
fn hanging(grading: &str, analysis: &str) -> String {
    let grading = if grading.is_empty() {
        String::new()
    } else {
        format!("grading = {grading}")
    };
    format!(
        "{}[analysis]\n{analysis}\n",
        one_rope(
            "graded rope",
            "",
            ("fixed", [8.0, 0.0, 0.0]),
            (7, 10.0, 12),
            &grading
        )
    )
}

/// The node coordinates the library gives the line of [`hanging`].
fn nodes_toward_b() -> Vec<f64> {
    Grading::Geometric {
        toward: GradedEnd::B,
        ratio: 4.0,
    }
    .node_coordinates(10.0, 12)
}

/// A graded line of a system runs (statics, and dynamics from the
/// straight start) with exit 0; its stress.csv's s column runs through
/// the graded node coordinates (shorter elements toward B, 17 digits
/// written), its straight start in nodes.csv puts node j at x_j along
/// the chord, and summary.json records the grading.
#[test]
fn a_graded_system_line_runs_and_writes_its_graded_arc_lengths() {
    let d = scratch("grading-system");
    let x = nodes_toward_b();
    let g = r#"{ toward = "B", ratio = 4.0 }"#;
    let sc = write_scenario(&d, "static.toml", &hanging(g, "type = \"static\""));
    let out = d.join("static");
    let o = run_to(&sc, &out);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o).1);
    let (header, rows) = read_csv(&out.join("lines/7/stress.csv"));
    assert_eq!(header.join(","), "t,s,axial_stress,curvature,element");
    let starts = element_starts(&rows, rows[0][0]);
    assert_eq!(starts.len(), 12);
    for k in 0..12 {
        assert_eq!(starts[k], x[k], "element {k}");
    }
    assert_eq!(rows.last().unwrap()[1], 10.0, "s ends at the length");
    assert!(x[12] - x[11] < (x[1] - x[0]) / 3.9, "finer toward B: {x:?}");
    let summary = read_json(&out.join("summary.json"));
    let line = &summary["lines"][0];
    assert_eq!(line["grading"]["toward"], "B");
    assert_eq!(line["grading"]["ratio"].as_f64(), Some(4.0));

    let analysis = "type = \"dynamic\"\ntime_step = 2e-4\nduration = 2e-3";
    let sc = write_scenario(&d, "dynamic.toml", &hanging(g, analysis));
    let out = d.join("dynamic");
    let o = run_to(&sc, &out);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o).1);
    let (_, nodes) = read_csv(&out.join("lines/7/nodes.csv"));
    // t = 0: straight from (0, 0, 0) to (8, 0, 0), node j at 0.8 x_j.
    for r in nodes.iter().filter(|r| r[0] == 0.0) {
        let j = r[1] as usize;
        assert!((r[2] - 0.8 * x[j]).abs() <= 1e-15 * 8.0, "node {j}: {r:?}");
    }
    let (_, rows) = read_csv(&out.join("lines/7/stress.csv"));
    let last = rows.last().unwrap()[0];
    assert!(last > 1.9e-3, "the last written step: {last}");
    assert_eq!(element_starts(&rows, last), x[..12].to_vec());
}

/// `stancf check` of a system names each line's shortest and longest
/// element; a uniform line its one element length.
#[test]
fn check_reports_the_shortest_and_longest_element_of_each_line() {
    let d = scratch("grading-check");
    let g = r#"{ toward = "both", ratio = 3.0 }"#;
    let analysis = "type = \"dynamic\"\ntime_step = 1e-4\nduration = 1e-3";
    let sc = write_scenario(&d, "graded.toml", &hanging(g, analysis));
    let o = stancf(&["check", sc.to_str().unwrap()]);
    let (so, se) = text(&o);
    assert_eq!(o.status.code(), Some(0), "{se}");
    let l = Grading::Geometric {
        toward: GradedEnd::Both,
        ratio: 3.0,
    }
    .element_lengths(10.0, 12);
    let want = format!(
        "{} m to {} m long, graded toward both with ratio 3",
        stancf::error::Sig(l[0].min(l[11])),
        stancf::error::Sig(l[5])
    );
    assert!(so.contains(&want), "{want:?} not in:\n{so}");
    assert!(so.contains("stable step (P2)"), "{so}");
    let sc = write_scenario(&d, "uniform.toml", &hanging("", analysis));
    let (so, _) = text(&stancf(&["check", sc.to_str().unwrap()]));
    let want = format!("({} m long)", stancf::error::Sig(10.0 / 12.0));
    assert!(so.contains(&want), "{want:?} not in:\n{so}");
}

/// A single `[cable]` takes the same key: the paper's transverse impact
/// graded toward both ends runs, stress.csv's s runs through the graded
/// nodes, and `check` reports the shortest element, which sets the
/// Courant number c dt / l_min.
#[test]
fn a_graded_cable_scenario_runs_with_its_graded_arc_lengths() {
    let d = scratch("grading-cable");
    let scenario = IMPACT.replace(
        "element = \"SAC-2\"",
        "element = \"SAC-2\"\ngrading = { toward = \"both\", ratio = 2.0 }",
    );
    let sc = write_scenario(&d, "impact.toml", &scenario);
    let out = d.join("out");
    let o = run_to(&sc, &out);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o).1);
    let g = Grading::Geometric {
        toward: GradedEnd::Both,
        ratio: 2.0,
    };
    let x = g.node_coordinates(4.0, 8);
    let (_, rows) = read_csv(&out.join("stress.csv"));
    assert_eq!(element_starts(&rows, 0.0), x[..8].to_vec());
    let summary = read_json(&out.join("summary.json"));
    assert_eq!(summary["grading"]["toward"], "both");
    let shortest = g.element_lengths(4.0, 8)[0];
    let c = (3.4e9f64 / 1380.0).sqrt();
    let courant = summary["courant_number"].as_f64().unwrap();
    assert!(
        (courant / (c * 5e-5 / shortest) - 1.0).abs() < 1e-12,
        "{courant}"
    );
    let (so, se) = text(&stancf(&["check", sc.to_str().unwrap()]));
    assert!(so.contains("graded toward both with ratio 2"), "{so}\n{se}");
}

/// A ratio below 1 or not finite, an unknown end, a missing key, an
/// unknown key, or too few elements for the grading: exit 2 naming the
/// key, for `[cable]` and for `[[lines]]`.
#[test]
fn bad_gradings_are_refused_naming_the_key() {
    let cases = [
        (r#"{ toward = "B", ratio = 0.5 }"#, "grading.ratio", ">= 1"),
        (
            r#"{ toward = "B", ratio = nan }"#,
            "grading.ratio",
            "finite",
        ),
        (
            r#"{ toward = "B", ratio = inf }"#,
            "grading.ratio",
            "finite",
        ),
        (
            r#"{ toward = "C", ratio = 2.0 }"#,
            "grading.toward",
            "\"C\"",
        ),
        (r#"{ ratio = 2.0 }"#, "grading.toward", "missing"),
        (r#"{ toward = "A" }"#, "grading.ratio", "missing"),
        (
            r#"{ toward = "A", ratio = 2.0, bias = 1 }"#,
            "bias",
            "unknown",
        ),
    ];
    for (i, (g, key, what)) in cases.iter().enumerate() {
        let system = hanging(g, "type = \"static\"");
        expect_input_error(&format!("grading-line-{i}"), &system, &[key, what]);
        if !key.starts_with("bias") {
            expect_input_error(
                &format!("grading-line-key-{i}"),
                &system,
                &[&format!("lines[0].{key}")],
            );
        }
        let cable = IMPACT.replace(
            "element = \"SAC-2\"",
            &format!("element = \"SAC-2\"\ngrading = {g}"),
        );
        expect_input_error(&format!("grading-cable-{i}"), &cable, &[key, what]);
        if !key.starts_with("bias") {
            expect_input_error(
                &format!("grading-cable-key-{i}"),
                &cable,
                &[&format!("cable.{key}")],
            );
        }
    }
    let two = hanging(r#"{ toward = "both", ratio = 2.0 }"#, "type = \"static\"")
        .replace("elements = 12", "elements = 2");
    expect_input_error(
        "grading-too-few",
        &two,
        &["lines[0].grading", "at least 3 elements"],
    );
}

/// The shipped example of a graded line is what its comment says: 20
/// elements four times shorter at the fairlead, and a step below the
/// stable step `check` reports (which its shortest elements set).
#[test]
fn the_graded_fairlead_example_steps_below_its_stable_step() {
    let ex = repo_file("examples/fairlead-graded.toml");
    let o = stancf(&["check", ex.to_str().unwrap()]);
    let (so, se) = text(&o);
    assert_eq!(o.status.code(), Some(0), "{se}");
    assert!(so.contains("graded toward B with ratio 4"), "{so}");
    let stable: f64 = so
        .lines()
        .find_map(|l| l.strip_prefix("stable step (P2)"))
        .and_then(|l| l.split_whitespace().next())
        .and_then(|v| v.parse().ok())
        .unwrap_or_else(|| panic!("no stable step in:\n{so}"));
    let text = std::fs::read_to_string(&ex).unwrap();
    let dt: f64 = text
        .lines()
        .find_map(|l| l.strip_prefix("time_step = "))
        .and_then(|v| v.split_whitespace().next())
        .and_then(|v| v.parse().ok())
        .expect("time_step");
    assert!(dt < stable, "time_step {dt} s, stable step {stable} s");
}
