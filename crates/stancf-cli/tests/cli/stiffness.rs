//! stiffness.csv and summary.json's `stiffness` (docs/interface.md,
//! "Systems"; docs/method.md §15.9): the free bodies' mooring stiffness
//! at a system's static equilibrium, checked against what the statics of
//! elastic lines require of it, not against an earlier output.
//!
//! The tolerances: the static solve converges to 1e-10 of the lines'
//! scale, and the matrix is the exact condensed tangent at that state, so
//! what symmetry or the balance of moments makes equal is equal to about
//! 1e-10 of the matrix's size (measured 1e-12 and 1e-13); the tests allow
//! 1e-8 of its largest entry.

use crate::common::*;
use std::path::{Path, PathBuf};

const HEADER: &str = "body,row,dx,dy,dz,rx,ry,rz";
const ROWS: [&str; 6] = ["fx", "fy", "fz", "mx", "my", "mz"];

/// A 6 x 6 matrix, rows fx..mz, columns dx..rz.
type Matrix = [[f64; 6]; 6];

/// The static equilibrium of the moored buoy (common::moored_buoy, the
/// system of examples/moored-buoy.toml: three lines at 120 degrees, of
/// 60, 62 and 64 m), its lines made `lengths` when given.
fn buoy_statics(name: &str, lengths: Option<f64>) -> PathBuf {
    let mut sc = moored_buoy("", "type = \"static\"");
    if let Some(l) = lengths {
        for from in ["length = 60.0", "length = 62.0", "length = 64.0"] {
            sc = sc.replace(from, &format!("length = {l:?}"));
        }
    }
    run_in(name, &sc)
}

/// Runs `scenario` quietly in a scratch folder; the run must succeed.
fn run_in(name: &str, scenario: &str) -> PathBuf {
    let d = scratch(name);
    let sc = write_scenario(&d, &format!("{name}.toml"), scenario);
    let out = d.join("out");
    let o = run_quiet(&sc, &out, &[]);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o).1);
    out
}

/// stiffness.csv: its header checked, each body's matrix (its 6 rows in
/// the order fx..mz, checked), in the file's order.
fn read_stiffness(out: &Path) -> Vec<(i64, Matrix)> {
    let text = std::fs::read_to_string(out.join("stiffness.csv")).unwrap();
    let mut lines = text.lines();
    assert_eq!(lines.next(), Some(HEADER));
    let rows: Vec<Vec<&str>> = lines.map(|l| l.split(',').collect()).collect();
    assert_eq!(rows.len() % 6, 0, "whole blocks of 6 rows: {rows:?}");
    rows.chunks(6)
        .map(|block| {
            let id: i64 = block[0][0].parse().unwrap();
            let mut k: Matrix = [[0.0; 6]; 6];
            for (i, row) in block.iter().enumerate() {
                assert_eq!(row.len(), 8, "{row:?}");
                assert_eq!((row[0].parse::<i64>().unwrap(), row[1]), (id, ROWS[i]));
                for j in 0..6 {
                    k[i][j] = row[2 + j].parse().unwrap();
                    assert!(k[i][j].is_finite(), "{row:?}");
                }
            }
            (id, k)
        })
        .collect()
}

/// summary.json's matrix of body `index` in `bodies`.
fn summary_matrix(out: &Path, index: usize) -> Matrix {
    let s = read_json(&out.join("summary.json"));
    let rows = s["bodies"][index]["stiffness"].as_array().unwrap();
    std::array::from_fn(|i| std::array::from_fn(|j| rows[i][j].as_f64().unwrap()))
}

fn largest(k: &Matrix) -> f64 {
    k.iter().flatten().fold(0.0, |m, v| m.max(v.abs()))
}

/// The moored buoy as shipped, at its equilibrium: one block of 6 rows
/// for its one free body (id 1), the same numbers as summary.json's, and
/// the structure (B16) gives the matrix of conservative lines (elastic,
/// under gravity and buoyancy, on a frictionless bed at a static
/// equilibrium): the translational block symmetric, the force-rotation
/// block the transpose of the moment-displacement one, and the
/// rotational block's antisymmetric part the moment of the pull turning
/// with the body, K_rot - K_rot^T = [M x] with M the lines' moment about
/// the reference point (bodies.csv's mx, my, mz; derived from
/// -(sum a f^T - (a . f) I) in docs/method.md (B16)). M is some 290 N m
/// here (the uneven lines tilt the buoy), so this sees the pull's term.
/// Lines in tension resist a translation of the body (a positive
/// translational diagonal).
#[test]
fn the_shipped_buoys_matrix_has_the_structure_of_conservative_lines_and_is_in_the_summary() {
    let out = buoy_statics("stiffness-buoy", None);
    let blocks = read_stiffness(&out);
    assert_eq!(blocks.len(), 1);
    let (id, k) = blocks[0];
    assert_eq!(id, 1);
    assert_eq!(
        k,
        summary_matrix(&out, 0),
        "summary.json's matrix is the file's"
    );
    let tol = 1e-8 * largest(&k);
    for i in 0..3 {
        for j in 0..3 {
            assert!((k[i][j] - k[j][i]).abs() < tol, "K_tt symmetric: {k:?}");
            assert!(
                (k[i][3 + j] - k[3 + j][i]).abs() < tol,
                "K_tr = K_rt^T: {k:?}"
            );
        }
    }
    let (_, bodies) = read_csv(&out.join("bodies.csv"));
    let m = [bodies[0][17], bodies[0][18], bodies[0][19]];
    assert!(m[0].hypot(m[1]) > 100.0, "the buoy is tilted: {m:?}");
    let hat_m = [[0.0, -m[2], m[1]], [m[2], 0.0, -m[0]], [-m[1], m[0], 0.0]];
    for i in 0..3 {
        for j in 0..3 {
            let skew = k[3 + i][3 + j] - k[3 + j][3 + i];
            assert!((skew - hat_m[i][j]).abs() < tol, "{i},{j}: {skew} vs {m:?}");
        }
    }
    for i in 0..3 {
        assert!(
            k[i][i] > 0.0,
            "lines in tension resist a translation: {k:?}"
        );
    }
}

/// Three equal lines at 120 degrees to points at 120 degrees on the
/// buoy's underside, its centre of mass on its axis: the equilibrium is
/// symmetric about the vertical (a 120-degree turn and the mirror in
/// the x-z plane), so K_xx = K_yy, K_xy = 0, K_rx,rx = K_ry,ry, the
/// surge-pitch coupling K_x,ry = -K_y,rx and K_x,rx = 0; the lines,
/// pulled down by the buoy's lift, stiffen it against heave (K_zz > 0),
/// and nothing couples yaw to the rest.
#[test]
fn a_buoy_on_three_equal_lines_at_120_degrees_is_as_stiff_in_surge_as_in_sway() {
    let out = buoy_statics("stiffness-symmetric", Some(60.0));
    let [(_, k)] = read_stiffness(&out)[..] else {
        panic!("one body")
    };
    let tol = 1e-8 * largest(&k);
    let close = |a: f64, b: f64, what: &str| assert!((a - b).abs() < tol, "{what}: {a} {b}");
    close(k[0][0], k[1][1], "K_xx = K_yy");
    close(k[0][1], 0.0, "K_xy");
    close(k[1][0], 0.0, "K_yx");
    close(k[3][3], k[4][4], "K_rx,rx = K_ry,ry");
    close(k[0][4], -k[1][3], "K_x,ry = -K_y,rx");
    close(k[0][3], 0.0, "K_x,rx");
    close(k[1][4], 0.0, "K_y,ry");
    for j in [0, 1, 3, 4] {
        close(k[5][j], 0.0, "yaw from the rest");
        close(k[j][5], 0.0, "the rest from yaw");
    }
    assert!(k[2][2] > 0.0 && k[0][0] > 0.0 && k[5][5] > 0.0, "{k:?}");
}

/// A dynamic run from the equilibrium writes the matrix of the
/// equilibrium it starts from: the static run's, to the bit (the same
/// static solve), whatever the motion does after.
#[test]
fn a_dynamic_run_from_the_equilibrium_writes_the_equilibriums_matrix() {
    let statics = buoy_statics("stiffness-static", None);
    let analysis = "type = \"dynamic\"\ninitial = \"static\"\ntime_step = 0.05\nduration = 0.1";
    let dynamic = run_in("stiffness-dynamic", &moored_buoy("", analysis));
    assert_eq!(read_stiffness(&dynamic), read_stiffness(&statics));
}

/// No stiffness.csv (and no `stiffness` in summary.json) without a free
/// body or without a static equilibrium; naming it in `output.files`
/// there is an input error that says why.
#[test]
fn no_stiffness_csv_without_a_free_body_or_an_equilibrium() {
    let rope = one_rope("rope", "", ("fixed", [1.0, 0.0, 0.0]), (1, 1.2, 4), "")
        + "[analysis]\ntype = \"static\"\n";
    let out = run_in("stiffness-rope", &rope);
    assert!(!out.join("stiffness.csv").exists(), "{:?}", names(&out));
    // Steps of 0.01 s resolve the bed's contact (its period 2 pi sqrt(m / (k d))
    // is 0.036 s) as the lines, released from their reference, whip down.
    let reference =
        "type = \"dynamic\"\ninitial = \"reference\"\ntime_step = 0.01\nduration = 0.02";
    let moving = run_in("stiffness-reference", &moored_buoy("", reference));
    assert!(!moving.join("stiffness.csv").exists());
    assert!(read_json(&moving.join("summary.json"))["bodies"][0]
        .get("stiffness")
        .is_none());
    let chosen = "[output]\nfiles = [\"stiffness.csv\"]\n";
    expect_input_error(
        "stiffness-csv-without-bodies",
        &(rope + chosen),
        &[
            "output.files",
            "\"stiffness.csv\" would stay empty",
            "no free body",
        ],
    );
    expect_input_error(
        "stiffness-csv-without-equilibrium",
        &(moored_buoy("", reference) + chosen),
        &[
            "output.files",
            "\"stiffness.csv\" would stay empty",
            "analysis.initial",
        ],
    );
}

/// `output.files` without stiffness.csv leaves it out (the matrix stays
/// in summary.json); with it alone, it is the same bytes as a run that
/// writes everything.
#[test]
fn stiffness_csv_is_chosen_by_output_files_like_the_other_tables() {
    let everything = buoy_statics("stiffness-all", None);
    let static_buoy = moored_buoy("", "type = \"static\"");
    let alone = run_in(
        "stiffness-alone",
        &(static_buoy.clone() + "[output]\nfiles = [\"stiffness.csv\"]\n"),
    );
    assert_eq!(
        names(&alone),
        ["scenario.toml", "stiffness.csv", "summary.json"]
    );
    let read = |d: &Path| std::fs::read(d.join("stiffness.csv")).unwrap();
    assert_eq!(read(&everything), read(&alone));
    let without = run_in(
        "stiffness-left-out",
        &(static_buoy + "[output]\nfiles = [\"bodies.csv\"]\n"),
    );
    assert_eq!(
        names(&without),
        ["bodies.csv", "scenario.toml", "summary.json"]
    );
    assert_eq!(summary_matrix(&without, 0), summary_matrix(&everything, 0));
}
