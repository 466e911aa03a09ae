//! `[output] interval`: a system's result tables written at the multiples
//! of an interval the steps need not land on, from the Galerkin step's
//! own cubics (docs/method.md §6.5a, (M23d)); history.csv keeps the
//! steps (docs/interface.md, "Systems").

use crate::common::*;
use std::path::Path;

/// The OC4 DeepCwind deck (examples/oc4-deepcwind-moordyn.txt) with its
/// fairlead point 4 moved 8 m at 100 s after a one-period ramp, 30 s at
/// steps of `dt`, Galerkin, the fairleads' forces at t, with `output` as
/// the body of its `[output]` section.
fn oc4(dir: &Path, name: &str, dt: f64, output: &str) -> std::path::PathBuf {
    copy_fixture_from_examples(dir, "oc4-deepcwind-moordyn.txt");
    write_scenario(
        dir,
        name,
        &format!(
            "[system]\nmoordyn = \"oc4-deepcwind-moordyn.txt\"\n[[motions]]\npoint = 4\n\
             amplitude = [8.0, 0.0, 0.0]\nperiod = 100.0\nramp = 100.0\n[analysis]\n\
             type = \"dynamic\"\ninitial = \"static\"\ntime_step = {dt}\nduration = 30.0\n\
             time_scheme = \"galerkin\"\n[output]\nend_forces = \"at_time\"\n{output}\n"
        ),
    )
}

fn copy_fixture_from_examples(dir: &Path, name: &str) {
    std::fs::copy(repo_file(&format!("examples/{name}")), dir.join(name)).unwrap();
}

/// points.csv's rows of point `p`: (t, x, y, z, fx, fy, fz).
fn point_rows(out: &Path, p: f64) -> Vec<[f64; 7]> {
    let (_, rows) = read_csv(&out.join("points.csv"));
    rows.iter()
        .filter(|r| r[1] == p)
        .map(|r| [r[0], r[2], r[3], r[4], r[8], r[9], r[10]])
        .collect()
}

/// At steps of 1 s written every 0.1 s: a row at every 0.1 s (301), the
/// same as the run written at its steps where a step ends (to 1e-9 of
/// the force: the same cubic's end, evaluated at s = 1), and between the
/// steps within 1e-4 of the fairlead tension's range of a run at steps
/// of 0.1 s written at each (the Galerkin step's fourth-order error at
/// 1 s against the motion's 100 s period is about (2 pi / 100)^4 =
/// 1.6e-5 of it; a straight line between the steps' ends would be
/// (2 pi / 100)^2 / 8 = 5e-4 of the range off where the force curves
/// most). Measured: 0.87 N of a range of 59 881 N (1.4e-5).
/// history.csv keeps the 30 steps and the start.
#[test]
fn a_system_written_between_its_steps_follows_its_finely_stepped_run() {
    let d = scratch("output-interval");
    let runs = [
        ("between", 1.0, "interval = 0.1"),
        ("steps", 1.0, "every = 1"),
        ("fine", 0.1, "every = 1"),
    ];
    for (name, dt, output) in runs {
        let sc = oc4(&d, &format!("{name}.toml"), dt, output);
        let o = run_quiet(&sc, &d.join(name), &[]);
        assert_eq!(o.status.code(), Some(0), "{name}: {}", text(&o).1);
    }
    let between = point_rows(&d.join("between"), 4.0);
    let steps = point_rows(&d.join("steps"), 4.0);
    let fine = point_rows(&d.join("fine"), 4.0);
    assert_eq!(between.len(), 301);
    assert_eq!(fine.len(), 301);
    for (k, row) in between.iter().enumerate() {
        assert!((row[0] - 0.1 * k as f64).abs() < 1e-12, "{k}: {}", row[0]);
    }
    let tension = |r: &[f64; 7]| (r[4] * r[4] + r[5] * r[5] + r[6] * r[6]).sqrt();
    for s in &steps {
        let b = between.iter().find(|b| b[0] == s[0]).expect("a step's end");
        assert!(
            (tension(b) - tension(s)).abs() <= 1e-9 * tension(s),
            "{}: {} {}",
            s[0],
            tension(b),
            tension(s)
        );
    }
    let t_fine: Vec<f64> = fine.iter().map(tension).collect();
    let range = t_fine.iter().cloned().fold(f64::MIN, f64::max)
        - t_fine.iter().cloned().fold(f64::MAX, f64::min);
    let worst = between
        .iter()
        .zip(&t_fine)
        .map(|(b, f)| (tension(b) - f).abs())
        .fold(0.0, f64::max);
    eprintln!("worst {worst} N of a range of {range} N");
    assert!(worst <= 1e-4 * range, "{worst} of {range}");
    let (_, history) = read_csv(&d.join("between").join("history.csv"));
    assert_eq!(history.len(), 31);
}

/// Refused naming the key (exit 2, nothing written): beside
/// `output.every`, with the step means, not positive, writing more
/// moments than a run writes without `--allow-large`, with P2, in a
/// static analysis, with line failures, in a single cable's scenario.
#[test]
fn an_output_interval_the_run_cannot_write_is_refused_by_name() {
    let d = scratch("output-interval-refused");
    let cases = [
        ("every = 2\ninterval = 0.1", "output.every"),
        ("interval = 0.1\nend_forces = \"step_mean\"", "step_mean"),
        ("interval = -0.1", "output.interval"),
        ("interval = 1e-9", "--allow-large"),
    ];
    for (k, (output, says)) in cases.into_iter().enumerate() {
        let sc = oc4(&d, &format!("case{k}.toml"), 1.0, output)
            .to_str()
            .unwrap()
            .to_string();
        let text = std::fs::read_to_string(&sc)
            .unwrap()
            .replace("end_forces = \"at_time\"\n", "");
        std::fs::write(&sc, text).unwrap();
        refused_by_check_and_run(
            Path::new(&sc),
            &d.join("never"),
            &["output.interval", says],
            &[],
        );
    }
    let p2 = oc4(&d, "p2.toml", 1.0, "interval = 0.1");
    let text = std::fs::read_to_string(&p2)
        .unwrap()
        .replace("time_scheme = \"galerkin\"", "time_scheme = \"p2\"");
    std::fs::write(&p2, text).unwrap();
    refused_by_check_and_run(&p2, &d.join("never"), &["output.interval", "galerkin"], &[]);
    let statics = write_scenario(
        &d,
        "static.toml",
        "[system]\nmoordyn = \"oc4-deepcwind-moordyn.txt\"\n[analysis]\ntype = \"static\"\n\
         [output]\ninterval = 0.1\n",
    );
    refused_by_check_and_run(
        &statics,
        &d.join("never"),
        &["output.interval", "static"],
        &[],
    );
    let deck = std::fs::read_to_string(d.join("oc4-deepcwind-moordyn.txt")).unwrap();
    let failing = deck.replacen(
        "------------------------------- OPTIONS",
        "--- FAILURE ---\nID Point Lines FailTime FailTen\n() () (,) (s) (N)\n1 4 1 15 0\n\
         ------------------------------- OPTIONS",
        1,
    );
    std::fs::write(d.join("failing.txt"), failing).unwrap();
    let failures = oc4(&d, "failures.toml", 1.0, "interval = 0.1");
    let text = std::fs::read_to_string(&failures)
        .unwrap()
        .replace("oc4-deepcwind-moordyn.txt", "failing.txt");
    std::fs::write(&failures, text).unwrap();
    refused_by_check_and_run(
        &failures,
        &d.join("never"),
        &["output.interval", "failures"],
        &[],
    );
    let cable = std::fs::read_to_string(repo_file("examples/impact-axial.toml")).unwrap();
    let cable = write_scenario(
        &d,
        "cable.toml",
        &cable.replacen("[output]\n", "[output]\ninterval = 0.1\n", 1),
    );
    refused_by_check_and_run(
        &cable,
        &d.join("never"),
        &["output.interval", "single"],
        &[],
    );
}

/// With steps chosen by a force tolerance (docs/method.md §11.17) the
/// interval's moments fall inside the steps the tolerance took (a run
/// step crossed in several): a row at every 0.1 s, and the fairlead
/// tension within the tolerance's 1e-3 of the tension of the run at
/// steps of 0.1 s written at each (the tolerance bounds each end force's
/// estimated error relative to its size, (M23c)).
#[test]
fn a_system_whose_steps_a_tolerance_chooses_is_written_between_them() {
    let d = scratch("output-interval-tolerance");
    let between = oc4(&d, "between.toml", 2.0, "interval = 0.1");
    let controlled = std::fs::read_to_string(&between)
        .unwrap()
        .replace("time_scheme", "force_tolerance = 1e-3\ntime_scheme");
    std::fs::write(&between, controlled).unwrap();
    let fine = oc4(&d, "fine.toml", 0.1, "every = 1");
    for (sc, out) in [(&between, "between"), (&fine, "fine")] {
        let o = run_quiet(sc, &d.join(out), &[]);
        assert_eq!(o.status.code(), Some(0), "{out}: {}", text(&o).1);
    }
    let between = point_rows(&d.join("between"), 4.0);
    let fine = point_rows(&d.join("fine"), 4.0);
    assert_eq!(between.len(), 301);
    let tension = |r: &[f64; 7]| (r[4] * r[4] + r[5] * r[5] + r[6] * r[6]).sqrt();
    let worst = between
        .iter()
        .zip(&fine)
        .map(|(b, f)| {
            assert!((b[0] - f[0]).abs() < 1e-12);
            (tension(b) - tension(f)).abs() / tension(f)
        })
        .fold(0.0, f64::max);
    eprintln!("worst relative difference {worst}");
    assert!(worst <= 1e-3, "{worst}");
}
