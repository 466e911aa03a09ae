//! A system whose geometry has no equilibrium is named before it is
//! solved (issue 28, item 9): a point below the seabed by how much, a line
//! too short to span its points by the strain it would need. These used
//! to end as "Newton did not converge at load factor 0" (exit 3) with
//! `check` saying nothing; now `check` and `run` refuse them (exit 2).

use crate::common::*;

/// The bridle deck of the examples with `old` replaced by `new`.
fn bridle_with(old: &str, new: &str) -> String {
    let deck = std::fs::read_to_string(repo_file("examples/midwater-bridle-moordyn.txt")).unwrap();
    assert!(deck.contains(old), "{old}");
    deck.replace(old, new)
}

#[test]
fn a_water_depth_above_a_fixed_points_depth_names_the_point_and_how_far_below_the_bed() {
    let d = scratch("below-bed");
    let deck = write_scenario(
        &d,
        "deck.txt",
        &bridle_with("150       WtrDpth", "50        WtrDpth"),
    );
    refused_by_check_and_run(
        &deck,
        &d.join("out"),
        &[
            "deck.txt: line 12: Z, line 23: WtrDpth",
            "point 1 at z = -60 m is 10 m below the seabed (z = -50 m there)",
        ],
        &["Newton"],
    );
    std::fs::remove_dir_all(&d).unwrap();
}

#[test]
fn every_point_below_the_bed_of_a_scenario_is_refused_naming_the_first() {
    let d = scratch("all-below");
    let sc = format!(
        "{}[water]\ndepth = 10.0\n[analysis]\ntype = \"static\"\n",
        one_rope("sunk", "", ("fixed", [4.0, 0.0, -20.0]), (1, 5.0, 4), "")
    )
    .replace("position = [0.0, 0.0, 0.0]", "position = [0.0, 0.0, -20.0]");
    let sc = write_scenario(&d, "sunk.toml", &sc);
    refused_by_check_and_run(
        &sc,
        &d.join("out"),
        &[
            "sunk.toml: points[0].position, water.depth",
            "point 1 at z = -20 m is 10 m below the seabed",
        ],
        &["Newton"],
    );
    std::fs::remove_dir_all(&d).unwrap();
}

#[test]
fn lines_too_short_to_span_their_points_are_named_with_the_strain_they_would_need() {
    let d = scratch("too-short");
    // Through the free clump: 4 m and 5 m of wire between anchors 72.8 m
    // apart.
    let deck = bridle_with("46.0      20", "4.0      20").replace("68.0      24", "5.0      24");
    let deck = write_scenario(&d, "deck.txt", &deck);
    refused_by_check_and_run(
        &deck,
        &d.join("out"),
        &[
            "line 19: UnstrLen",
            "points 1 and 2 are 72.8011 m apart",
            "the lines between them (through free points) are 9 m long at most",
            "709 %",
        ],
        &["Newton"],
    );
    // One line between two fixed points 10 m apart, 5 m long, is in
    // equilibrium stretched 100 %: noted, and solved statically, pulling
    // with EA eps = 2e4 N (its 3.9 N of weight tilt the end forces by
    // 1e-4 rad, 5e-9 of the tension).
    let sc = format!(
        "{}[analysis]\ntype = \"static\"\n",
        one_rope("short", "", ("fixed", [10.0, 0.0, 0.0]), (1, 5.0, 4), "")
    );
    let sc = write_scenario(&d, "short.toml", &sc);
    let o = stancf(&["check", sc.to_str().unwrap()]);
    let (so, se) = text(&o);
    assert_eq!(o.status.code(), Some(0), "{se}");
    assert!(
        so.contains("lines[0].length: line 1 is 5 m long") && so.contains("stretched by 100 %"),
        "{so}{se}"
    );
    let out = d.join("out");
    let o = run_quiet(&sc, &out, &[]);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o).1);
    for row in read_tensions(&out.join("tensions.csv")) {
        assert!((row[6] - 2e4).abs() < 1e-6 * 2e4, "{row:?}");
    }
    // 15 % short of the span is within what a rope may stretch: it runs.
    let taut = format!(
        "{}[analysis]\ntype = \"static\"\n",
        one_rope("taut", "", ("fixed", [5.75, 0.0, 0.0]), (1, 5.0, 4), "")
    );
    let taut = write_scenario(&d, "taut.toml", &taut);
    let o = stancf(&["check", taut.to_str().unwrap()]);
    assert!(o.status.success(), "{:?}", text(&o));
    std::fs::remove_dir_all(&d).unwrap();
}
