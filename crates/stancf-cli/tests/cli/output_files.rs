//! `[output] files`: a system run writes the result tables it is asked
//! for, byte for byte as a run that writes them all, and nothing else
//! beside summary.json and scenario.toml (docs/interface.md, "Systems").

use crate::common::*;

/// A rope hanging from the origin to a fixed point 2 m along x, released
/// from straight for 20 steps of 0.25 ms (below the stable P2 step of its
/// 0.42 m elements, 0.28 ms: at 1 ms the system's energy watchdog stops
/// it at the 7th step, its energy up by 37 %), with `output` as the body
/// of its `[output]` section.
fn rope(output: &str) -> String {
    format!(
        "{}[analysis]\ntype = \"dynamic\"\ntime_step = 2.5e-4\nduration = 5e-3\n[output]\n{output}\n",
        one_rope("rope", "", ("fixed", [2.0, 0.0, 0.0]), (1, 2.5, 6), "")
    )
}

#[test]
fn a_system_run_writes_only_the_files_chosen_and_those_as_a_full_run_does() {
    let d = scratch("output-files-chosen");
    let all = d.join("all");
    let o = run_quiet(
        &write_scenario(&d, "all.toml", &rope("every = 2")),
        &all,
        &[],
    );
    assert_eq!(o.status.code(), Some(0), "{}", text(&o).1);
    let chosen = d.join("chosen");
    let files = "every = 2\nfiles = [\"points.csv\", \"tensions.csv\"]";
    let o = run_quiet(
        &write_scenario(&d, "chosen.toml", &rope(files)),
        &chosen,
        &[],
    );
    assert_eq!(o.status.code(), Some(0), "{}", text(&o).1);
    assert_eq!(
        names(&chosen),
        [
            "points.csv",
            "scenario.toml",
            "summary.json",
            "tensions.csv"
        ]
    );
    for f in ["points.csv", "tensions.csv"] {
        let (a, b) = (std::fs::read(all.join(f)), std::fs::read(chosen.join(f)));
        assert_eq!(a.unwrap(), b.unwrap(), "{f} differs from the full run's");
    }
    // The line's own tables alone: lines/1 holds just them.
    let lines = d.join("lines");
    let files = "files = [\"nodes.csv\", \"node_loads.csv\"]";
    let o = run_quiet(&write_scenario(&d, "lines.toml", &rope(files)), &lines, &[]);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o).1);
    assert_eq!(
        names(&lines.join("lines/1")),
        ["node_loads.csv", "nodes.csv"]
    );
    assert!(!lines.join("points.csv").exists());
}

#[test]
fn an_unknown_or_repeated_output_file_is_refused_naming_the_key() {
    expect_input_error(
        "output-files-unknown",
        &rope("files = [\"points.csv\", \"forces.csv\"]"),
        &["output.files", "\"forces.csv\"", "node_loads.csv"],
    );
    expect_input_error(
        "output-files-twice",
        &rope("files = [\"points.csv\", \"points.csv\"]"),
        &["output.files", "named twice"],
    );
}

/// channels.csv holds a MoorDyn deck's OUTPUTS channels: naming it where
/// nothing fills it (a system without a deck, a deck without channels)
/// is refused naming the key and why.
#[test]
fn channels_csv_where_no_deck_gives_channels_is_refused() {
    expect_input_error(
        "output-files-channels-no-deck",
        &rope("files = [\"points.csv\", \"channels.csv\"]"),
        &[
            "output.files",
            "\"channels.csv\" would stay empty",
            "no deck",
        ],
    );
    let deck_scenario = "title = \"rope deck\"\n[system]\nmoordyn = \"deck.txt\"\n\
        [analysis]\ntype = \"static\"\n[output]\nfiles = [\"channels.csv\"]\n";
    expect_input_error_beside(
        "output-files-channels-no-outputs",
        deck_scenario,
        &[("deck.txt", &rope_deck(""))],
        &["output.files", "the deck lists no OUTPUTS channels"],
    );
    let d = scratch("output-files-channels-deck");
    std::fs::write(d.join("deck.txt"), rope_deck("FairTen1\n")).unwrap();
    let sc = write_scenario(&d, "deck.toml", deck_scenario);
    let o = run_quiet(&sc, &d.join("out"), &[]);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o).1);
    assert_eq!(
        names(&d.join("out")),
        ["channels.csv", "scenario.toml", "summary.json"]
    );
}

#[test]
fn a_single_cable_refuses_output_files() {
    let mut sc = pendulum("pendulum", 1e-3, 1e-2, 1);
    sc.push_str("files = [\"nodes.csv\"]\n");
    expect_input_error("output-files-cable", &sc, &["output.files", "single cable"]);
}

#[test]
fn plot_refuses_a_run_that_leaves_out_what_it_draws_from() {
    let d = scratch("output-files-plot");
    let sc = write_scenario(&d, "bad.toml", &rope("files = [\"points.csv\"]"));
    let out = d.join("never");
    let o = run_quiet(&sc, &out, &["--plot"]);
    let (_, se) = text(&o);
    assert_eq!(o.status.code(), Some(2), "{se}");
    for needle in ["bad.toml", "output.files", "--plot", "tensions.csv"] {
        assert!(se.contains(needle), "{needle:?} not in: {se}");
    }
    assert!(!out.exists(), "an output folder was created");
}

#[test]
fn plot_names_the_tables_a_run_left_out_and_draws_nothing() {
    let d = scratch("output-files-plot-later");
    let out = d.join("out");
    let files = "files = [\"points.csv\", \"tensions.csv\"]";
    let o = run_quiet(&write_scenario(&d, "some.toml", &rope(files)), &out, &[]);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o).1);
    let o = stancf(&["plot", out.to_str().unwrap()]);
    let (_, se) = text(&o);
    assert_eq!(o.status.code(), Some(2), "{se}");
    for needle in ["output.files", "history.csv", "lines/1/nodes.csv"] {
        assert!(se.contains(needle), "{needle:?} not in: {se}");
    }
    assert!(
        !names(&out)
            .iter()
            .any(|n| n.ends_with(".png") || n.ends_with(".svg")),
        "a figure was drawn: {:?}",
        names(&out)
    );
}

/// `[output] end_forces = "at_time"`: every row of tensions.csv and
/// points.csv holds the estimate at t of (M23a) (docs/method.md §6.5),
/// 1.5 R_k - 0.5 R_(k-1) of the step means R a run with the default
/// writes (its first step: the mean itself), to round-off; the positions
/// are the same bits.
#[test]
fn end_forces_at_time_are_the_line_through_the_last_two_step_means() {
    let d = scratch("output-end-forces");
    let run = |name: &str, output: &str| {
        let out = d.join(name);
        let sc = write_scenario(&d, &format!("{name}.toml"), &rope(output));
        let o = run_quiet(&sc, &out, &[]);
        assert_eq!(o.status.code(), Some(0), "{}", text(&o).1);
        out
    };
    let mean = run("mean", "");
    let at_time = run("at_time", "end_forces = \"at_time\"");
    let kind = |dir: &std::path::Path| read_json(&dir.join("summary.json"))["end_forces"].clone();
    assert_eq!(
        (kind(&mean), kind(&at_time)),
        ("step_mean".into(), "at_time".into())
    );
    let (_, m) = read_csv_with_blanks(&mean.join("points.csv"));
    let (_, a) = read_csv_with_blanks(&at_time.join("points.csv"));
    assert_eq!(m.len(), a.len());
    // Rows: t, point, x, y, z, vx, vy, vz, fx, fy, fz; two points a time.
    let point_rows = |rows: &[Vec<f64>], p: f64| -> Vec<Vec<f64>> {
        rows.iter()
            .filter(|r| r[1] == p && r[0] > 0.0)
            .cloned()
            .collect()
    };
    for p in [1.0, 2.0] {
        let (m, a) = (point_rows(&m, p), point_rows(&a, p));
        assert_eq!(m.len(), 20);
        for k in 0..m.len() {
            assert_eq!(
                m[k][..8],
                a[k][..8],
                "point {p}, step {k}: the state differs"
            );
            for c in 8..11 {
                let want = if k == 0 {
                    m[0][c]
                } else {
                    1.5 * m[k][c] - 0.5 * m[k - 1][c]
                };
                let scale = m[k][c].abs().max(m[k.max(1) - 1][c].abs());
                assert!(
                    (a[k][c] - want).abs() <= 8.0 * f64::EPSILON * scale,
                    "point {p}, step {k}, column {c}: {} against {want}",
                    a[k][c]
                );
            }
        }
    }
    let tm = read_tensions(&mean.join("tensions.csv"));
    let ta = read_tensions(&at_time.join("tensions.csv"));
    let last = tm.len() - 1;
    assert!(tm.len() == ta.len() && ta[last][6] != tm[last][6]);
    assert!(
        (ta[last][6] - (ta[last][3].powi(2) + ta[last][4].powi(2) + ta[last][5].powi(2)).sqrt())
            .abs()
            <= 1e-12 * ta[last][6]
    );
}

/// `end_forces` takes "step_mean" or "at_time" and belongs to systems:
/// another value, or the key in a single cable's scenario, exit 2
/// naming it.
#[test]
fn end_forces_other_than_the_two_or_of_a_single_cable_are_refused() {
    expect_input_error(
        "output-end-forces-value",
        &rope("end_forces = \"instant\""),
        &["output.end_forces", "\"instant\""],
    );
    let cable = IMPACT.replace("[output]", "[output]\nend_forces = \"at_time\"");
    assert_ne!(cable, IMPACT);
    expect_input_error(
        "output-end-forces-cable",
        &cable,
        &["output.end_forces", "single cable"],
    );
}
