//! `run` and `check` on valid scenarios as docs/interface.md specifies
//! them: the contract result files and their contents (summary, history,
//! nodes, stress, reactions), the default output folder, `check`'s derived
//! figures, `--version` and `--help`, initial rigid rotation, the pendulum
//! and static examples, and a quiet run with no progress bar in a pipe.

use crate::common::{read_csv, repo_file, scratch, stancf, text, write_scenario, BIN};
use std::process::Command;

/// A small valid scenario: the transverse impact, shortened.
const BASE: &str = crate::common::IMPACT;

#[test]
fn run_writes_the_contract_files() {
    let d = scratch("run");
    let sc = write_scenario(&d, "impact.toml", BASE);
    let out = d.join("results");
    let o = stancf(&["run", sc.to_str().unwrap(), "--out", out.to_str().unwrap()]);
    let (so, se) = text(&o);
    assert_eq!(o.status.code(), Some(0), "{so}\n{se}");
    assert!(so.contains("40 steps"), "{so}");

    let (h, hist) = read_csv(&out.join("history.csv"));
    assert_eq!(
        h[..7],
        [
            "t",
            "kinetic",
            "strain",
            "gravity",
            "total",
            "iterations",
            "residual"
        ]
    );
    assert_eq!(hist[0][0], 0.0, "first row at t = 0");
    // Every 4th of 40 steps plus t = 0.
    assert_eq!(hist.len(), 11);
    assert!((hist.last().unwrap()[0] - 2e-3).abs() < 1e-15);
    for r in &hist {
        assert!((r[1] + r[2] + r[3] - r[4]).abs() <= 1e-12 * r[4].abs().max(1e-300));
    }
    let (h, nodes) = read_csv(&out.join("nodes.csv"));
    // The contract's columns, then the slope r_x (interface.md extension).
    assert_eq!(h, ["t", "node", "x", "y", "z", "dx_ds", "dy_ds", "dz_ds"]);
    assert_eq!(nodes.len(), 11 * 9);
    assert_eq!(nodes[0][1..], [0.0, -2.0, 0.0, 0.0, 1.0, 0.0, 0.0]);
    let (h, stress) = read_csv(&out.join("stress.csv"));
    assert_eq!(h[..4], ["t", "s", "axial_stress", "curvature"]);
    // At least 5 points per element, both ends included.
    let first: Vec<&Vec<f64>> = stress.iter().filter(|r| r[0] == 0.0).collect();
    assert!(first.len() >= 5 * 8);
    assert_eq!(first.first().unwrap()[1], 0.0);
    assert_eq!(first.last().unwrap()[1], 4.0);

    let summary: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("summary.json")).unwrap()).unwrap();
    for key in [
        "title",
        "analysis",
        "element",
        "elements",
        "dofs",
        "steps",
        "time",
        "converged",
        "wall_time_s",
        "iterations",
        "energy",
        "tip",
        "nodes_final",
    ] {
        assert!(summary.get(key).is_some(), "summary.json lacks {key}");
    }
    assert_eq!(summary["converged"], true);
    assert_eq!(summary["steps"], 40);
    assert_eq!(summary["dofs"], 54);
    assert_eq!(summary["element"], "SAC-2");
    assert_eq!(summary["nodes_final"].as_array().unwrap().len(), 9);
    for k in ["total", "mean_per_step", "max_per_step"] {
        assert!(summary["iterations"][k].is_number());
    }
    for k in ["initial", "final", "max_abs_drift", "max_rel_drift"] {
        assert!(summary["energy"][k].is_number());
    }
    // The final nodes of summary.json are the last rows of nodes.csv.
    let tip = summary["tip"].as_array().unwrap();
    let last = nodes.last().unwrap();
    for i in 0..3 {
        assert_eq!(tip[i].as_f64().unwrap(), last[2 + i]);
    }
    // Nothing half-written is left behind.
    for e in std::fs::read_dir(&out).unwrap() {
        let name = e.unwrap().file_name().into_string().unwrap();
        assert!(!name.ends_with(".partial"), "{name}");
    }
}

#[test]
fn default_output_folder_is_out_slash_stem() {
    let d = scratch("default-out");
    write_scenario(&d, "short.toml", BASE);
    let o = Command::new(BIN)
        .args(["run", "short.toml"])
        .current_dir(&d)
        .output()
        .unwrap();
    assert_eq!(o.status.code(), Some(0), "{:?}", text(&o));
    assert!(d.join("out/short/summary.json").exists());
}

#[test]
fn check_prints_the_derived_figures() {
    let o = stancf(&[
        "check",
        repo_file("examples/impact-transverse.toml")
            .to_str()
            .unwrap(),
    ]);
    let (so, se) = text(&o);
    assert_eq!(o.status.code(), Some(0), "{se}");
    for needle in [
        "DOFs                        54",
        // 54 coordinates, 2 unknowns each per P2 step, z eliminated (planar).
        "unknowns per step           72 (1 time layer; planar motion: z coordinates eliminated)",
        "wave speed sqrt(E/rho)      1569.6",
        "Courant number c dt/dx      0.1569",
        "stable step (P2)            1.0547",
        "steps                       36000",
        "warnings                    none",
    ] {
        assert!(so.contains(needle), "missing {needle:?} in\n{so}");
    }
}

#[test]
fn version_and_help() {
    let o = stancf(&["--version"]);
    assert_eq!(o.status.code(), Some(0));
    assert!(text(&o).0.contains(env!("CARGO_PKG_VERSION")));
    let o = stancf(&["--help"]);
    let (so, _) = text(&o);
    assert_eq!(o.status.code(), Some(0));
    assert!(so.contains("run") && so.contains("check"));
}

/// `node = "all"` with `angular_velocity` and `center`: the rigid rotation
/// reaches the initial state; a cable spinning about its centre has
/// T = 1/2 (rho A L) (L^2 / 12) w^2 exactly (the velocity field is linear).
#[test]
fn initial_rigid_rotation_from_the_scenario() {
    let d = scratch("spin");
    let sc = write_scenario(
        &d,
        "spin.toml",
        &BASE
            .replace(
                "[[initial_velocity]]\nnode = \"A\"\nvelocity = [0.0, 10.0, 0.0]\n[[initial_velocity]]\nnode = 8\nvelocity = [0.0, -10.0, 0.0]",
                "[[initial_velocity]]\nnode = \"all\"\nangular_velocity = [0.0, 0.0, 2.0]\ncenter = [0.0, 0.0, 0.0]",
            )
            .replace("[[loads]]\ntype = \"gravity\"\nacceleration = [0.0, -9.81, 0.0]\n", ""),
    );
    let out = d.join("res");
    let o = stancf(&["run", sc.to_str().unwrap(), "--out", out.to_str().unwrap()]);
    assert_eq!(o.status.code(), Some(0), "{:?}", text(&o));
    let (_, hist) = read_csv(&out.join("history.csv"));
    let m = 1380.0 * 3.0e-6 * 4.0;
    let exact = 0.5 * m * 16.0 / 12.0 * 4.0;
    assert!(
        (hist[0][1] / exact - 1.0).abs() < 1e-13,
        "{} vs {exact}",
        hist[0][1]
    );
    // The spinning cable turned: end B moved along +y.
    let summary: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("summary.json")).unwrap()).unwrap();
    assert!(summary["tip"][1].as_f64().unwrap() > 0.0);
}

/// The pendulum example: reactions.csv holds the pin force at every
/// written step after t = 0, and the pin holds.
#[test]
fn pendulum_example_writes_reactions() {
    let d = scratch("pendulum");
    let out = d.join("res");
    let ex = repo_file("examples/pendulum.toml");
    let o = stancf(&["run", ex.to_str().unwrap(), "--out", out.to_str().unwrap()]);
    assert_eq!(o.status.code(), Some(0), "{:?}", text(&o));
    let (h, reactions) = read_csv(&out.join("reactions.csv"));
    assert_eq!(h, ["t", "node", "fx", "fy", "fz"]);
    let (_, hist) = read_csv(&out.join("history.csv"));
    assert_eq!(reactions.len(), hist.len() - 1);
    assert!(reactions.iter().all(|r| r[1] == 0.0));
    let (_, nodes) = read_csv(&out.join("nodes.csv"));
    for r in nodes.iter().filter(|r| r[1] == 0.0) {
        assert!(r[2].abs() + r[3].abs() + r[4].abs() < 1e-12);
    }
    // Energy conserved to the scheme's accuracy (measured ~1e-10).
    let s: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("summary.json")).unwrap()).unwrap();
    assert!(s["energy"]["max_rel_drift"].as_f64().unwrap() < 1e-8);
}

/// The static example: summary.json of a static analysis (steps = load
/// steps, time = load factor 1, energy = strain energy), and the full
/// circle closing to the paper's SAC-2 accuracy.
#[test]
fn circle_bending_example_is_a_static_run() {
    let d = scratch("circle");
    let out = d.join("res");
    let ex = repo_file("examples/circle-bending.toml");
    let o = stancf(&["run", ex.to_str().unwrap(), "--out", out.to_str().unwrap()]);
    assert_eq!(o.status.code(), Some(0), "{:?}", text(&o));
    let s: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("summary.json")).unwrap()).unwrap();
    assert_eq!(s["analysis"], "static");
    assert_eq!(s["time"], 1.0);
    assert_eq!(s["steps"], 20);
    // Analytic strain energy of the circle: M^2 L / (2 EI) = 2 pi^2 EI / L.
    // Ten SAC-2 elements close the circle to 18 mm of 1 m; the energy is
    // 3.3 % low (measured), of the same order as that geometric error.
    let ei = 3.4e9 * 1.25e-13;
    let u = s["energy"]["final"].as_f64().unwrap();
    assert!(
        (u / (2.0 * std::f64::consts::PI.powi(2) * ei) - 1.0).abs() < 0.05,
        "{u}"
    );
    let tip_x = s["tip"][0].as_f64().unwrap();
    assert!((tip_x * 1e3 + 18.2972).abs() < 1e-3, "{tip_x}");
    let (_, hist) = read_csv(&out.join("history.csv"));
    assert_eq!(hist.len(), 21);
    assert_eq!(hist.last().unwrap()[0], 1.0);
    read_csv(&out.join("reactions.csv"));
}

/// The progress bar never reaches a pipe (standard error is not a
/// terminal here, and the run lasts more than the bar's one-second delay),
/// and `--quiet` leaves standard output empty.
#[test]
fn no_progress_bar_in_a_pipe_and_quiet_is_quiet() {
    let d = scratch("progress");
    let long = BASE.replace("duration = 2.0e-3", "duration = 3.0");
    let sc = write_scenario(&d, "long.toml", &long);
    let out = d.join("res");
    let started = std::time::Instant::now();
    let o = stancf(&["run", sc.to_str().unwrap(), "--out", out.to_str().unwrap()]);
    let (so, se) = text(&o);
    assert_eq!(o.status.code(), Some(0), "{se}");
    assert!(
        started.elapsed().as_secs_f64() > 1.0,
        "the run must outlast the delay"
    );
    assert!(!se.contains('\r') && !se.contains("it/step"), "{se:?}");
    assert!(so.contains("steps to t = 3 s"), "{so}");
    let sc = write_scenario(&d, "short.toml", BASE);
    let o = stancf(&[
        "run",
        sc.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
        "--quiet",
    ]);
    let (so, se) = text(&o);
    assert_eq!(o.status.code(), Some(0), "{se}");
    assert!(so.is_empty(), "{so}");
    assert!(out.join("summary.json").exists());
}
