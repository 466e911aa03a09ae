//! Design load cases: `stancf sweep` of systems and MoorDyn decks, the
//! design statistics of a system run (summary.json's `statistics`) and
//! extremes.csv over the seeds of each sea state (docs/interface.md,
//! "Design statistics" and "stancf sweep").

use crate::common::{
    column, csv_table, read_json, read_rfc4180, read_tensions, refused_by_check_and_run, repo_file,
    run_quiet, scratch, stancf, sweep_table, text, write_scenario,
};
use std::path::Path;

/// Two chains in 50 m of water under a JONSWAP sea, one fairlead moved
/// sideways: 20 s in steps of 0.25 s, the statistics from 5 s on.
const SEA: &str = include_str!("../fixtures/two-lines-in-a-sea.toml");

/// SEA with its significant wave height and seed set.
fn sea(hs: &str, seed: &str) -> String {
    SEA.replace("hs = 2.0", &format!("hs = {hs}"))
        .replace("seed = 0", &format!("seed = {seed}"))
}

fn sweep(scenario: &Path, sets: &[&str], out: &Path) {
    let mut args = vec!["sweep", scenario.to_str().unwrap()];
    for s in sets {
        args.extend(["--set", s]);
    }
    args.extend(["--jobs", "2", "--out", out.to_str().unwrap()]);
    let o = stancf(&args);
    assert!(o.status.success(), "{:?}", text(&o));
}

/// The statistics' figures of one line end in summary.json.
fn end_statistics(summary: &serde_json::Value, line: i64, end: &str) -> serde_json::Value {
    summary["statistics"]["line_ends"]
        .as_array()
        .unwrap()
        .iter()
        .find(|e| e["line"] == line && e["end"] == end)
        .unwrap_or_else(|| panic!("no statistics of line {line} end {end}"))
        .clone()
}

/// The statistics are those of the written time series: over the rows of
/// tensions.csv at t >= 5 s, the largest tension and its first time, the
/// smallest, the mean and the population standard deviation by the
/// two-pass formulas (Welford's one-pass update differs from them by
/// round-off, a few units of 1e-16 of the mean: 1e-12 allows 1e4 of
/// them); the coupled fairlead's largest distance from its place at t = 0
/// in points.csv; the chain's safety factor MBL / the largest end tension.
#[test]
fn a_system_runs_statistics_are_those_of_its_written_time_series() {
    let d = scratch("sweep-systems-statistics");
    let sc = write_scenario(&d, "sea.toml", SEA);
    let out = d.join("out");
    let o = run_quiet(&sc, &out, &[]);
    assert!(o.status.success(), "{:?}", text(&o));
    let summary = read_json(&out.join("summary.json"));
    let stats = &summary["statistics"];
    assert_eq!(stats["after"], 5.0);
    let rows = read_tensions(&out.join("tensions.csv"));
    let mut largest = 0.0f64;
    for line in [1, 2] {
        for (end, code) in [("A", 0.0), ("B", 1.0)] {
            let samples: Vec<(f64, f64)> = rows
                .iter()
                .filter(|r| r[1] == line as f64 && r[2] == code && r[0] >= 5.0)
                .map(|r| (r[0], r[6]))
                .collect();
            // 5 s to 20 s in steps of 0.25 s.
            assert_eq!(samples.len(), 61);
            assert_eq!(stats["moments"], 61);
            let n = samples.len() as f64;
            let mean = samples.iter().map(|s| s.1).sum::<f64>() / n;
            let var = samples.iter().map(|s| (s.1 - mean).powi(2)).sum::<f64>() / n;
            let max = samples.iter().map(|s| s.1).fold(f64::MIN, f64::max);
            let t_max = samples.iter().find(|s| s.1 == max).unwrap().0;
            let min = samples.iter().map(|s| s.1).fold(f64::MAX, f64::min);
            let e = end_statistics(&summary, line, end);
            assert_eq!(e["max"].as_f64(), Some(max));
            assert_eq!(e["time_of_max"].as_f64(), Some(t_max));
            assert_eq!(e["min"].as_f64(), Some(min));
            let m = e["mean"].as_f64().unwrap();
            assert!((m - mean).abs() <= 1e-12 * mean, "{m} against {mean}");
            let s = e["std"].as_f64().unwrap();
            assert!(
                (s - var.sqrt()).abs() <= 1e-12 * mean,
                "{s} against {}",
                var.sqrt()
            );
            // The line whose fairlead moves 2 m swings its tension by a
            // quarter of its mean (measured: std 3.4 kN on 13 kN at end
            // A); the other line only by the sea (19 N).
            if line == 1 {
                assert!(s > 0.1 * mean, "{s}");
            } else {
                assert!(s > 0.0 && s < 0.01 * mean, "{s}");
            }
            largest = largest.max(max);
        }
    }
    let t = &stats["line_types"][0];
    assert_eq!(t["type"], "chain");
    assert_eq!(t["max_tension"].as_f64(), Some(largest));
    assert_eq!(t["safety_factor"].as_f64(), Some(2.0e6 / largest));
    let (header, points) = crate::common::read_csv(&out.join("points.csv"));
    let (px, py, pz) = (
        column(&header, "x"),
        column(&header, "y"),
        column(&header, "z"),
    );
    let of_point = |id: f64| points.iter().filter(move |r| r[1] == id);
    let start = of_point(3.0).next().unwrap().clone();
    let offset = of_point(3.0)
        .filter(|r| r[0] >= 5.0)
        .map(|r| {
            let d = [r[px] - start[px], r[py] - start[py], r[pz] - start[pz]];
            (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).sqrt()
        })
        .fold(0.0, f64::max);
    let listed = stats["points"].as_array().unwrap();
    let ids: Vec<i64> = listed.iter().map(|p| p["id"].as_i64().unwrap()).collect();
    assert_eq!(ids, [3, 4], "the coupled points, not the fixed ones");
    assert_eq!(listed[0]["max_offset"].as_f64(), Some(offset));
    // The ramped motion of amplitude 2 m reaches it within the window.
    assert!((offset - 2.0).abs() < 0.05, "{offset}");
    assert_eq!(listed[1]["max_offset"].as_f64(), Some(0.0));
}

/// A sweep of a system over two sea states and three seeds: each row of
/// sweep.csv holds the numbers of the same run done alone with `stancf
/// run` (to the bit), and extremes.csv gives each sea state's mean of
/// the three maxima (the same sum, to the bit) and a Gumbel most probable
/// maximum within the maxima's range.
#[test]
fn a_sweep_of_a_system_gives_the_numbers_of_its_runs_done_one_at_a_time() {
    let d = scratch("sweep-systems-grid");
    let sc = write_scenario(&d, "sea.toml", SEA);
    let out = d.join("sw");
    sweep(
        &sc,
        &["water.jonswap.hs=1.0,2.5", "water.jonswap.seed=0,1,2"],
        &out,
    );
    let (header, rows) = sweep_table(&out);
    assert_eq!(rows.len(), 6);
    let columns: Vec<String> = header
        .iter()
        .filter(|h| h.contains("_line") || h.starts_with("safety") || h.starts_with("offset"))
        .cloned()
        .collect();
    // 4 ends x 5 figures, 1 safety factor, 2 offsets.
    assert_eq!(columns.len(), 23, "{header:?}");
    for row in &rows {
        let cell = |name: &str| row[column(&header, name)].clone();
        assert_eq!(cell("status"), "ok");
        let alone = d.join(format!("alone_{}", cell("run")));
        let scenario = write_scenario(
            &d,
            &format!("alone_{}.toml", cell("run")),
            &sea(&cell("water.jonswap.hs"), &cell("water.jonswap.seed")),
        );
        let o = run_quiet(&scenario, &alone, &[]);
        assert!(o.status.success(), "{:?}", text(&o));
        let summary = read_json(&alone.join("summary.json"));
        for line in [1, 2] {
            for end in ["A", "B"] {
                let e = end_statistics(&summary, line, end);
                for (figure, key) in [
                    ("tension_max", "max"),
                    ("tension_max_time", "time_of_max"),
                    ("tension_min", "min"),
                    ("tension_mean", "mean"),
                    ("tension_std", "std"),
                ] {
                    let swept: f64 = cell(&format!("{figure}_line{line}_{end}")).parse().unwrap();
                    assert_eq!(Some(swept), e[key].as_f64(), "{figure} line {line} {end}");
                }
            }
        }
        let sf: f64 = cell("safety_factor_chain").parse().unwrap();
        let alone_sf = summary["statistics"]["line_types"][0]["safety_factor"].as_f64();
        assert_eq!(Some(sf), alone_sf);
    }
    // extremes.csv: one row per significant wave height.
    let (eh, extremes) = csv_table(&out.join("extremes.csv"));
    assert_eq!(eh[..3], ["water.jonswap.hs", "seeds", "failed"]);
    assert_eq!(extremes.len(), 2);
    for (k, state) in extremes.iter().enumerate() {
        assert_eq!((state[1].as_str(), state[2].as_str()), ("3", "0"));
        for line in [1, 2] {
            for end in ["A", "B"] {
                let name = format!("tension_max_line{line}_{end}");
                let maxima: Vec<f64> = rows[3 * k..3 * k + 3]
                    .iter()
                    .map(|r| r[column(&header, &name)].parse().unwrap())
                    .collect();
                let mean: f64 = state[column(&eh, &format!("{name}_mean"))].parse().unwrap();
                assert_eq!(mean, maxima.iter().sum::<f64>() / 3.0);
                let mpm: f64 = state[column(&eh, &format!("{name}_mpm"))].parse().unwrap();
                let lo = maxima.iter().copied().fold(f64::MAX, f64::min);
                let hi = maxima.iter().copied().fold(f64::MIN, f64::max);
                let scale: f64 = state[column(&eh, &format!("{name}_gumbel_scale"))]
                    .parse()
                    .unwrap();
                assert!(mpm > lo - (hi - lo) && mpm < hi, "{mpm} of {maxima:?}");
                assert!(scale > 0.0 && scale < hi - lo, "{scale} of {maxima:?}");
            }
        }
    }
}

/// A bare MoorDyn deck is swept as the scenario that takes it: keys reach
/// what a scenario adds to a deck (its sea, analysis, statistics and the
/// breaking load of a deck's line type).
#[test]
fn a_moordyn_deck_is_swept_through_the_scenario_that_takes_it() {
    let d = scratch("sweep-systems-deck");
    let deck = d.join("oc4.txt");
    std::fs::copy(repo_file("examples/oc4-deepcwind-moordyn.txt"), &deck).unwrap();
    let out = d.join("sw");
    sweep(
        &deck,
        &[
            "analysis.duration=2.0",
            "analysis.time_step=0.5",
            "analysis.time_scheme=galerkin",
            "water.jonswap.hs=2.0",
            "water.jonswap.tp=10.0",
            "water.jonswap.seed=0,1",
            "system.mbl.chain=7.0e6",
        ],
        &out,
    );
    let (header, rows) = sweep_table(&out);
    assert_eq!(rows.len(), 2);
    for row in &rows {
        assert_eq!(row[column(&header, "status")], "ok");
        assert_eq!(row[column(&header, "time")], "2");
        let sf: f64 = row[column(&header, "safety_factor_chain")].parse().unwrap();
        let t: f64 = row[column(&header, "tension_max_line1_B")].parse().unwrap();
        assert!(sf <= 7.0e6 / t && t > 1.0e6, "{sf} {t}");
    }
    // The run's scenario is the one that takes the deck.
    let taken = std::fs::read_to_string(out.join("run_0000/scenario.toml")).unwrap();
    assert!(taken.contains("moordyn = \"oc4.txt\""), "{taken}");
    assert!(out.join("extremes.csv").exists());
}

/// Bad design-statistics keys are input errors naming the key, exit 2.
#[test]
fn bad_statistics_keys_are_refused_naming_them() {
    let d = scratch("sweep-systems-refusals");
    let negative = SEA.replace("statistics_after = 5.0", "statistics_after = -1.0");
    let sc = write_scenario(&d, "negative.toml", &negative);
    refused_by_check_and_run(&sc, &d.join("never"), &["output.statistics_after"], &[]);
    let no_deck = SEA.replace(
        "gravity = [0.0, 0.0, -9.81]",
        "gravity = [0.0, 0.0, -9.81]\nmbl = { chain = 1.0e6 }",
    );
    let sc = write_scenario(&d, "no-deck.toml", &no_deck);
    refused_by_check_and_run(&sc, &d.join("never"), &["system.mbl", "mbl"], &[]);
    let zero = SEA.replace("mbl = 2.0e6", "mbl = 0.0");
    let sc = write_scenario(&d, "zero.toml", &zero);
    refused_by_check_and_run(&sc, &d.join("never"), &["line_types[0].mbl"], &[]);
    std::fs::copy(
        repo_file("examples/oc4-deepcwind-moordyn.txt"),
        d.join("oc4.txt"),
    )
    .unwrap();
    let wrapper = "[system]\nmoordyn = \"oc4.txt\"\nmbl = { wire = 1.0e6 }\n";
    let sc = write_scenario(&d, "wire.toml", wrapper);
    refused_by_check_and_run(&sc, &d.join("never"), &["system.mbl.wire", "chain"], &[]);
    let cable = crate::common::IMPACT.replace("[output]", "[output]\nstatistics_after = 1.0");
    let sc = write_scenario(&d, "cable.toml", &cable);
    refused_by_check_and_run(&sc, &d.join("never"), &["output.statistics_after"], &[]);
    // The reader of these tests reads the quoted cells a sweep writes.
    assert_eq!(read_rfc4180("a\n\"b,c\"\n"), [vec!["a"], vec!["b,c"]]);
}

/// Scenario files as one more axis: the intact system and a damaged one
/// (its second line gone) swept over two seeds. sweep.csv's `scenario`
/// column names each run's file, the damaged runs leave the lost line's
/// cells empty, and extremes.csv reduces each file's seeds apart.
#[test]
fn intact_and_damaged_variants_are_one_more_axis() {
    let d = scratch("sweep-systems-variants");
    let intact = write_scenario(&d, "intact.toml", SEA);
    // Line 2 gone, with its anchor and fairlead.
    let mut lost = SEA.to_string();
    for block in [
        "[[points]]\nid = 2\ntype = \"fixed\"\nposition = [120.0, 0.0, -50.0]\n",
        "[[points]]\nid = 4\ntype = \"coupled\"\nposition = [5.0, 0.0, -5.0]\n",
        "[[lines]]\nid = 2\ntype = \"chain\"\nlength = 130.0\nelements = 8\na = 2\nb = 4\n",
    ] {
        assert!(lost.contains(block), "{block}");
        lost = lost.replace(block, "");
    }
    let damaged = write_scenario(&d, "damaged.toml", &lost);
    let out = d.join("sw");
    let o = stancf(&[
        "sweep",
        intact.to_str().unwrap(),
        damaged.to_str().unwrap(),
        "--set",
        "water.jonswap.seed=0,1",
        "--jobs",
        "2",
        "--out",
        out.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{:?}", text(&o));
    let (header, rows) = sweep_table(&out);
    assert_eq!(
        header[..4],
        ["run", "scenario", "water.jonswap.seed", "status"]
    );
    let files: Vec<&str> = rows.iter().map(|r| r[1].as_str()).collect();
    let (i, dm) = (intact.to_str().unwrap(), damaged.to_str().unwrap());
    assert_eq!(files, [i, i, dm, dm]);
    let lost = column(&header, "tension_max_line2_A");
    assert!(rows[..2].iter().all(|r| !r[lost].is_empty()));
    assert!(rows[2..].iter().all(|r| r[lost].is_empty()));
    let kept = column(&header, "tension_max_line1_B");
    assert!(rows.iter().all(|r| r[kept].parse::<f64>().unwrap() > 0.0));
    let (eh, extremes) = csv_table(&out.join("extremes.csv"));
    assert_eq!(eh[..3], ["scenario", "seeds", "failed"]);
    assert_eq!(extremes.len(), 2);
    assert_eq!((extremes[0][0].as_str(), extremes[1][0].as_str()), (i, dm));
    let lost_mean = column(&eh, "tension_max_line2_A_mean");
    assert!(!extremes[0][lost_mean].is_empty() && extremes[1][lost_mean].is_empty());
}

/// `[deck]` sets a deck's values as its own columns would: a sweep of
/// line 1's UnstrLen and the chain's Cd gives, row by row, the static
/// tensions of copies of the deck with those columns edited (to the
/// bit), and a shorter line pulls harder at its fairlead.
#[test]
fn deck_values_are_swept_as_edited_copies_of_the_deck() {
    let d = scratch("sweep-systems-deck-values");
    let deck_text =
        std::fs::read_to_string(repo_file("examples/oc4-deepcwind-moordyn.txt")).unwrap();
    let deck = d.join("oc4.txt");
    std::fs::write(&deck, &deck_text).unwrap();
    let out = d.join("sw");
    sweep(
        &deck,
        &[
            "deck.lines.1.length=830.0,840.0",
            "deck.line_types.chain.cd=1.5",
        ],
        &out,
    );
    let (header, rows) = sweep_table(&out);
    let fairlead = column(&header, "tension_max_line1_B");
    let mut tensions = Vec::new();
    for (row, length) in rows.iter().zip(["830.0", "840.0"]) {
        let edited = deck_text
            .replace(
                "1   chain     1        4        835.35",
                &format!("1   chain     1        4        {length}"),
            )
            .replace(
                "chain     0.0766  113.35   7.536E8   -1.0      0        2.0",
                "chain     0.0766  113.35   7.536E8   -1.0      0        1.5",
            );
        assert_ne!(edited, deck_text);
        let copy = d.join(format!("oc4-{length}.txt"));
        std::fs::write(&copy, edited).unwrap();
        let alone = d.join(format!("alone-{length}"));
        let o = run_quiet(&copy, &alone, &[]);
        assert!(o.status.success(), "{:?}", text(&o));
        let summary = read_json(&alone.join("summary.json"));
        let swept: f64 = row[fairlead].parse().unwrap();
        assert_eq!(
            Some(swept),
            end_statistics(&summary, 1, "B")["max"].as_f64()
        );
        tensions.push(swept);
    }
    assert!(tensions[0] > tensions[1], "{tensions:?}");
    // Refused naming the key: an id the deck lacks, a column it has not,
    // a value its column refuses, and [deck] without a deck.
    for (values, needle) in [
        ("[deck.lines.4]\nlength = 10.0\n", "deck.lines.4"),
        ("[deck.lines.1]\nsag = 1.0\n", "deck.lines.1.sag"),
        (
            "[deck.line_types.chain]\ncd = -1.0\n",
            "deck.line_types.chain.cd",
        ),
        ("[deck.line_types.wire]\ncd = 1.0\n", "deck.line_types.wire"),
        (
            "[deck.points.1]\nposition = [1.0, 2.0]\n",
            "deck.points.1.position",
        ),
    ] {
        let sc = write_scenario(
            &d,
            "bad.toml",
            &format!("[system]\nmoordyn = \"oc4.txt\"\n{values}"),
        );
        refused_by_check_and_run(&sc, &d.join("never"), &[needle], &[]);
    }
    let sc = write_scenario(
        &d,
        "no-deck.toml",
        &format!("{SEA}\n[deck.lines.1]\nlength = 1.0\n"),
    );
    refused_by_check_and_run(&sc, &d.join("never"), &["deck", "system.moordyn"], &[]);
}
