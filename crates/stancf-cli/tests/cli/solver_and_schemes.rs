//! Solvers and time schemes chosen from a scenario, and how they fail: an
//! unstable step is warned about and a blow-up exits with code 3, a Newton
//! failure exits with code 3 keeping valid files, drag and Broyden, the
//! Galerkin scheme, and the planar reduction.

use crate::common::{
    expect_input_error, read_csv, repo_file, scratch, stancf, text, write_scenario,
};

/// A small valid scenario: the transverse impact, shortened.
const BASE: &str = crate::common::IMPACT;

/// A step above P2's stable limit is warned about by `check` and `run`; a
/// blow-up ends with exit code 3, a message naming the time, the step and
/// the energy, and valid result files up to the last good step.
#[test]
fn unstable_step_is_warned_and_a_blow_up_exits_with_code_3() {
    let d = scratch("blowup");
    let sc = write_scenario(
        &d,
        "unstable.toml",
        &BASE
            .replace("time_step = 5.0e-5", "time_step = 3.0e-4")
            .replace("duration = 2.0e-3", "duration = 0.05")
            .replace("every = 4", "every = 1"),
    );
    let o = stancf(&["check", sc.to_str().unwrap()]);
    let (so, _) = text(&o);
    assert_eq!(o.status.code(), Some(0));
    assert!(so.contains("warning: analysis.time_step"), "{so}");
    assert!(so.contains("exceeds the stable step"), "{so}");

    let out = d.join("res");
    let o = stancf(&["run", sc.to_str().unwrap(), "--out", out.to_str().unwrap()]);
    let (_, se) = text(&o);
    assert_eq!(o.status.code(), Some(3), "{se}");
    assert!(se.contains("warning: analysis.time_step"), "{se}");
    assert!(se.contains("energy grows without a source"), "{se}");
    assert!(
        se.contains("t = ") && se.contains("step ") && se.contains("residual"),
        "{se}"
    );
    assert!(se.contains(" J above the initial"), "{se}");
    let (_, hist) = read_csv(&out.join("history.csv"));
    let (_, nodes) = read_csv(&out.join("nodes.csv"));
    read_csv(&out.join("stress.csv"));
    let summary: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("summary.json")).unwrap()).unwrap();
    assert_eq!(summary["converged"], false);
    assert!(summary["error"].as_str().unwrap().contains("energy grows"));
    let steps = summary["steps"].as_u64().unwrap() as usize;
    assert!((1..166).contains(&steps), "stopped early: {steps}");
    // Rows for t = 0 and every converged, accepted step; nodes match.
    assert_eq!(hist.len(), steps + 1);
    assert_eq!(nodes.len(), (steps + 1) * 9);
    // The energies written are those of good steps: within the watchdog's
    // 10 % of the initial energy.
    let e0 = hist[0][4];
    for r in &hist {
        assert!((r[4] - e0).abs() < 0.1 * e0, "bad state written: {r:?}");
    }
}

/// Newton that cannot converge (one iteration allowed, tolerance below
/// what one iteration reaches) ends with exit code 3 and a message naming
/// the time, the step and the residual; the files hold the valid start.
#[test]
fn newton_failure_exits_with_code_3_and_keeps_valid_files() {
    let d = scratch("newton-fail");
    let sc = write_scenario(
        &d,
        "fail.toml",
        &BASE.replace(
            "quadrature = [3, 3]",
            // One chord iteration cannot confirm convergence: the increment
            // test needs a second.
            "quadrature = [3, 3]\nmax_iterations = 1\ntolerance = 1e-14\nsolver = \"modified-newton\"",
        ),
    );
    let out = d.join("res");
    let o = stancf(&["run", sc.to_str().unwrap(), "--out", out.to_str().unwrap()]);
    let (_, se) = text(&o);
    assert_eq!(o.status.code(), Some(3), "{se}");
    assert!(se.contains("Newton did not converge"), "{se}");
    assert!(
        se.contains("t = 0") && se.contains("step 1") && se.contains("scaled residual"),
        "{se}"
    );
    let (_, hist) = read_csv(&out.join("history.csv"));
    assert_eq!(hist.len(), 1);
    let summary: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("summary.json")).unwrap()).unwrap();
    assert_eq!(summary["converged"], false);
    assert_eq!(summary["steps"], 0);
}

/// Drag and Broyden from a scenario: the run says which solver it used,
/// writes the per-step diagnostics, and accounts for the drag's work.
#[test]
fn drag_and_broyden_from_a_scenario() {
    let d = scratch("drag-broyden");
    let sc = write_scenario(
        &d,
        "drag.toml",
        &BASE
            .replace(
                "[[loads]]\ntype = \"gravity\"",
                "[[loads]]\ntype = \"air-drag\"\ndrag_coefficient = 1.2\nfluid_density = 1.225\nmodel = \"normal\"\ntangential_coefficient = 0.1\nfluid_velocity = [0.0, 0.0, 2.0]\n[[loads]]\ntype = \"gravity\"",
            )
            .replace("quadrature = [3, 3]", "quadrature = [3, 3]\nsolver = \"broyden\""),
    );
    let out = d.join("res");
    let o = stancf(&["run", sc.to_str().unwrap(), "--out", out.to_str().unwrap()]);
    let (so, se) = text(&o);
    assert_eq!(o.status.code(), Some(0), "{so}{se}");
    assert!(so.contains("Broyden iterations per step"), "{so}");
    let s: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("summary.json")).unwrap()).unwrap();
    assert_eq!(s["solver"]["method"], "broyden");
    assert!(s["solver"]["factorizations"].as_u64().unwrap() < 40);
    assert!(s["solver"]["part_a_s"].as_f64().unwrap() > 0.0);
    assert!(s["energy"]["drag_work"].as_f64().unwrap() != 0.0);
    // The convergence-rate column is empty where the estimate is undefined
    // (no NaN is ever written); every other field is a finite number.
    let solver = std::fs::read_to_string(out.join("solver.csv")).unwrap();
    let mut lines = solver.lines();
    assert!(lines
        .next()
        .unwrap()
        .starts_with("t,step,iterations,factorizations,"));
    let rows: Vec<&str> = lines.collect();
    assert_eq!(rows.len(), 40);
    for r in rows {
        for (k, f) in r.split(',').enumerate() {
            if k != 6 || !f.is_empty() {
                assert!(f.parse::<f64>().unwrap().is_finite(), "{r}");
            }
        }
    }
    let conv = std::fs::read_to_string(out.join("convergence.csv")).unwrap();
    assert!(conv.lines().count() > 40);
    let (h, _) = read_csv(&out.join("history.csv"));
    assert_eq!(h.last().unwrap(), "drag_work");
}

/// `time_scheme = "galerkin"`: `check` reports no stability limit but the
/// mesh's w_max dt; a run at ten times P2's limit neither warns nor blows
/// up; more than one time layer is an input error that says why.
#[test]
fn galerkin_from_a_scenario() {
    let d = scratch("galerkin");
    let text_g = BASE
        .replace(
            "quadrature = [3, 3]",
            "quadrature = [3, 3]\ntime_scheme = \"galerkin\"",
        )
        .replace("time_step = 5.0e-5", "time_step = 1.0e-3")
        .replace("duration = 2.0e-3", "duration = 0.05")
        .replace("every = 4", "every = 1");
    let sc = write_scenario(&d, "g.toml", &text_g);
    let o = stancf(&["check", sc.to_str().unwrap()]);
    let (so, _) = text(&o);
    assert_eq!(o.status.code(), Some(0));
    assert!(
        so.contains("Galerkin (unconditionally stable); w_max dt = 29.98"),
        "{so}"
    );
    assert!(so.contains("warnings                    none"), "{so}");
    let out = d.join("res");
    let o = stancf(&["run", sc.to_str().unwrap(), "--out", out.to_str().unwrap()]);
    let (_, se) = text(&o);
    assert_eq!(o.status.code(), Some(0), "{se}");
    assert!(!se.contains("warning"), "{se}");
    let s: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("summary.json")).unwrap()).unwrap();
    assert_eq!(s["time_scheme"], "galerkin");
    assert!(s["stable_time_step"].is_null(), "{s}");
    let w_dt = s["w_max_dt"].as_f64().unwrap();
    assert!((w_dt - 29.98).abs() < 0.01, "{w_dt}");
    // Newton builds one tangent per iteration.
    let tangents = s["solver"]["tangents_per_step"].as_f64().unwrap();
    let iterations = s["iterations"]["mean_per_step"].as_f64().unwrap();
    assert!(
        tangents >= 1.0 && tangents <= iterations,
        "{tangents} {iterations}"
    );
    // Linear momentum exact: the weight impulse m g t.
    let m = 1380.0 * 3.0e-6 * 4.0;
    let py = s["linear_momentum"][1].as_f64().unwrap();
    assert!((py + m * 9.81 * 0.05).abs() < 1e-14, "{py}");
    // Modified Newton from the scenario: the same motion with the factors
    // kept across steps (fewer tangents than steps).
    let sc_m = write_scenario(
        &d,
        "gm.toml",
        &text_g.replace("time_scheme", "solver = \"modified-newton\"\ntime_scheme"),
    );
    let out_m = d.join("res-m");
    let o = stancf(&[
        "run",
        sc_m.to_str().unwrap(),
        "--out",
        out_m.to_str().unwrap(),
    ]);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o).1);
    let sm: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(out_m.join("summary.json")).unwrap())
            .unwrap();
    assert_eq!(sm["solver"]["method"], "modified-newton");
    assert!(
        sm["solver"]["tangents_per_step"].as_f64().unwrap() < 1.0,
        "{sm}"
    );
    // Both converge to 1e-10 of the length (4 m): the ends agree to that
    // order, amplified at most by the few steps.
    for k in 0..3 {
        let (a, b) = (
            s["tip"][k].as_f64().unwrap(),
            sm["tip"][k].as_f64().unwrap(),
        );
        assert!((a - b).abs() < 1e-8, "{a} {b}");
    }
    expect_input_error(
        "galerkin-layers",
        &text_g.replace(
            "time_scheme = \"galerkin\"",
            "time_scheme = \"galerkin\"\ntime_layers = 2",
        ),
        &["analysis.time_layers", "one layer per step"],
    );
}

/// `planar_reduction`: on by default, the planar impact is solved without
/// its z coordinates (two thirds of the unknowns) and moves as the full
/// solve does; `false` keeps the full 3-D solve; a wrong type is an input
/// error naming the key.
#[test]
fn planar_reduction_from_a_scenario() {
    let d = scratch("planar");
    let summary = |name: &str, scenario: &str| -> serde_json::Value {
        let sc = write_scenario(&d, &format!("{name}.toml"), scenario);
        let out = d.join(name);
        let o = stancf(&["run", sc.to_str().unwrap(), "--out", out.to_str().unwrap()]);
        assert_eq!(o.status.code(), Some(0), "{}", text(&o).1);
        serde_json::from_str(&std::fs::read_to_string(out.join("summary.json")).unwrap()).unwrap()
    };
    let reduced = summary("reduced", BASE);
    let full = summary(
        "full",
        &BASE.replace("[analysis]", "[analysis]\nplanar_reduction = false"),
    );
    assert_eq!(reduced["planar"], true);
    assert_eq!(full["planar"], false);
    let (nr, nf) = (
        reduced["unknowns_per_step"].as_u64().unwrap(),
        full["unknowns_per_step"].as_u64().unwrap(),
    );
    assert_eq!(3 * nr, 2 * nf, "{nr} of {nf}");
    // Both converge to 1e-10 of the 4 m length per step (40 steps).
    for k in 0..3 {
        let (a, b) = (
            reduced["tip"][k].as_f64().unwrap(),
            full["tip"][k].as_f64().unwrap(),
        );
        assert!((a - b).abs() < 2.0 * 40.0 * 4e-10, "{a} {b}");
    }
    // Out of the plane: gravity with a z component keeps the full solve.
    let tilted = summary(
        "tilted",
        &BASE.replace(
            "acceleration = [0.0, -9.81, 0.0]",
            "acceleration = [0.0, -9.81, 0.1]",
        ),
    );
    assert_eq!(tilted["planar"], false);
    expect_input_error(
        "planar-type",
        &BASE.replace("[analysis]", "[analysis]\nplanar_reduction = \"yes\""),
        &["planar_reduction"],
    );
}

/// The numbers after each of `keys` in `text`, in order.
fn numbers_after(text: &str, keys: &[&str]) -> Vec<f64> {
    let mut rest = text;
    keys.iter()
        .map(|k| {
            let at = rest.find(k).unwrap_or_else(|| panic!("no {k:?} in {text}")) + k.len();
            rest = &rest[at..];
            rest.split_whitespace().next().unwrap().parse().unwrap()
        })
        .collect()
}

/// Item 20 of issue 28: the watchdog's message of a damped run above its
/// stable step gives the energies of the step that made the energy grow:
/// the mechanical energy plus what drag took out is the total, and the
/// total less the initial energy is the growth (it used to take the work
/// of the step before, and read as a lower energy "above" the initial).
#[test]
fn the_energy_watchdog_of_a_dragged_pendulum_reports_one_consistent_balance() {
    let d = scratch("drag-watchdog");
    let scenario = std::fs::read_to_string(repo_file("examples/pendulum-drag.toml"))
        .unwrap()
        .replace("drag_coefficient = 1.5", "drag_coefficient = 1e6")
        .replace("time_step = 1.0e-4", "time_step = 5.0e-3");
    let sc = write_scenario(&d, "dragged.toml", &scenario);
    let o = stancf(&[
        "run",
        sc.to_str().unwrap(),
        "--out",
        d.join("out").to_str().unwrap(),
    ]);
    let (_, err) = text(&o);
    assert_eq!(o.status.code(), Some(3), "{err}");
    let v = numbers_after(
        &err,
        &[
            "the mechanical energy",
            "plus the",
            "took out is",
            "J,",
            "above the initial",
        ],
    );
    let (mechanical, taken, total, growth, initial) = (v[0], v[1], v[2], v[3], v[4]);
    assert!(taken > 0.0, "{err}");
    // Printed to 7 and 4 significant digits.
    assert!(
        (mechanical + taken - total).abs() <= 1e-6 * total.abs().max(taken),
        "{err}"
    );
    assert!((total - initial - growth).abs() <= 1e-3 * growth, "{err}");
    assert!(growth > 0.0 && total > initial, "{err}");
}
