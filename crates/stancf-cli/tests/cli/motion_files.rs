//! Coupled points moved by a table of positions (docs/interface.md,
//! "Systems", `[[motions]] file`): the run follows the table's spline,
//! and every bad table is refused with exit 2 naming the file and its
//! line, before anything is written.

use crate::common::*;

/// A 1 m rope between a fixed point 1 at the origin and a coupled point
/// 2 at [1, 0, 0] moved by `motion` (the body of its `[[motions]]`),
/// stepped for `duration` s in steps of 0.1 ms written every 10th.
fn fairlead(motion: &str, duration: f64) -> String {
    format!(
        "{}[[motions]]\npoint = 2\n{motion}\n[analysis]\ntype = \"dynamic\"\n\
         time_step = 1e-4\nduration = {duration}\n[output]\nevery = 10\n",
        one_rope("table", "", ("coupled", [1.0, 0.0, 0.0]), (1, 1.0, 4), "")
    )
}

/// The cubic the table samples: position and velocity of point 2.
fn cubic(t: f64) -> ([f64; 3], [f64; 3]) {
    (
        [1.0, 5.0 * t * t - 100.0 * t * t * t, 0.1 * t],
        [0.0, 10.0 * t - 300.0 * t * t, 0.1],
    )
}

/// `t,x,y,z` rows of the cubic at t = 0, 2.5 ms, ..., 12.5 ms, columns
/// in the order `header` names them.
fn cubic_table(header: &str) -> String {
    let mut s = format!("{header}\n");
    let names: Vec<&str> = header.split(',').collect();
    for i in 0..6 {
        let t = 2.5e-3 * i as f64;
        let (r, _) = cubic(t);
        let row: Vec<String> = names
            .iter()
            .map(|n| match *n {
                "t" => format!("{t:e}"),
                "x" => format!("{:e}", r[0]),
                "y" => format!("{:e}", r[1]),
                _ => format!("{:e}", r[2]),
            })
            .collect();
        s.push_str(&row.join(","));
        s.push('\n');
    }
    s
}

/// The not-a-knot spline through samples of a cubic is the cubic (M39),
/// so point 2 in points.csv moves along it to round-off, in position and
/// velocity, at every written time (between the table's rows too), and
/// `stancf check` names the table.
#[test]
fn a_point_moved_by_a_table_follows_it_in_points_csv() {
    let d = scratch("motion-file-runs");
    std::fs::write(d.join("fairlead.csv"), cubic_table("t,y,x,z")).unwrap();
    let sc = write_scenario(&d, "table.toml", &fairlead("file = \"fairlead.csv\"", 0.01));
    let o = stancf(&["check", sc.to_str().unwrap()]);
    let (so, se) = text(&o);
    assert_eq!(o.status.code(), Some(0), "{se}");
    assert!(
        so.contains("moving along the table fairlead.csv (6 rows, t = 0 to 0.0125 s)"),
        "{so}"
    );
    let out = d.join("out");
    let o = run_quiet(&sc, &out, &[]);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o).1);
    let (header, rows) = read_csv(&out.join("points.csv"));
    assert_eq!(header.join(","), "t,point,x,y,z,vx,vy,vz,fx,fy,fz");
    let moved: Vec<&Vec<f64>> = rows.iter().filter(|r| r[1] == 2.0).collect();
    assert_eq!(moved.len(), 11, "t = 0 and every 10th of 100 steps");
    for r in moved {
        let (p, v) = cubic(r[0]);
        for c in 0..3 {
            assert!(
                (r[2 + c] - p[c]).abs() <= 1e-14,
                "t = {}: {r:?} vs {p:?}",
                r[0]
            );
            assert!(
                (r[5 + c] - v[c]).abs() <= 1e-12,
                "t = {}: {r:?} vs {v:?}",
                r[0]
            );
        }
    }
}

fn refused(name: &str, motion: &str, table: &str, needles: &[&str]) {
    expect_input_error_beside(
        name,
        &fairlead(motion, 0.01),
        &[("fairlead.csv", table)],
        needles,
    );
}

const FILE: &str = "file = \"fairlead.csv\"";

#[test]
fn a_missing_motion_file_is_refused_naming_it() {
    refused(
        "motion-file-missing",
        "file = \"nowhere.csv\"",
        "",
        &["motions[0].file", "nowhere.csv", "cannot read"],
    );
}

#[test]
fn a_bad_motion_table_is_refused_naming_the_file_and_line() {
    let good = cubic_table("t,x,y,z");
    let mut lines: Vec<&str> = good.lines().collect();
    let cases: Vec<(&str, String, &str)> = vec![
        (
            "header",
            good.replacen("t,x,y,z", "t,x,y,w", 1),
            "line 1: the header",
        ),
        (
            "text",
            good.replacen("0e0,1e0", "0e0,one", 1),
            "line 2: \"one\" in column x",
        ),
        (
            "nan",
            good.replacen("0e0,1e0", "0e0,NaN", 1),
            "line 2: x = NaN",
        ),
        ("columns", format!("{good}1,2,3\n"), "line 8: 3 values"),
        (
            "order",
            format!("{good}1e-3,1,0,0\n"),
            "line 8: t = 0.001 does not follow",
        ),
        (
            "rows",
            format!("{}\n{}\n", lines[0], lines[1]),
            "has 1 row(s)",
        ),
        (
            "late",
            format!("{}\n{}\n", lines[0], lines[2..].join("\n")),
            "does not cover",
        ),
    ];
    lines.truncate(5);
    let short = format!("{}\n", lines.join("\n"));
    for (name, table, needle) in
        cases
            .into_iter()
            .chain([("short", short, "to t = 0.0075 s and does not cover the run")])
    {
        refused(
            &format!("motion-file-{name}"),
            FILE,
            &table,
            &["motions[0].file", "fairlead.csv", needle],
        );
    }
}

#[test]
fn a_table_away_from_its_point_is_refused_with_both_positions() {
    let table = cubic_table("t,x,y,z").replacen("0e0,1e0", "0e0,1.000001e0", 1);
    refused(
        "motion-file-start",
        FILE,
        &table,
        &[
            "fairlead.csv",
            "[1.000001, 0.0, 0.0]",
            "point 2's position [1.0, 0.0, 0.0]",
        ],
    );
}

#[test]
fn a_file_with_an_oscillations_key_is_refused_naming_the_key() {
    for key in [
        "amplitude = [0.1, 0.0, 0.0]",
        "period = 1.0",
        "phase = 0.0",
        "ramp = 1.0",
    ] {
        let name = key.split(' ').next().unwrap();
        refused(
            &format!("motion-file-and-{name}"),
            &format!("{FILE}\n{key}"),
            &cubic_table("t,x,y,z"),
            &[&format!("motions[0].{name}"), "either a file"],
        );
    }
}
