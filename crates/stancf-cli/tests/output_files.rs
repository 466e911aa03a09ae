//! `[output] files`: a system run writes the result tables it is asked
//! for, byte for byte as a run that writes them all, and nothing else
//! beside summary.json and scenario.toml (docs/interface.md, "Systems").

mod common;

use common::*;

/// A rope hanging from the origin to a fixed point 2 m along x, released
/// from straight for 20 steps of 1 ms, with `output` as the body of its
/// `[output]` section.
fn rope(output: &str) -> String {
    format!(
        "{}[analysis]\ntype = \"dynamic\"\ntime_step = 1e-3\nduration = 2e-2\n[output]\n{output}\n",
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
