//! The command line as docs/interface.md specifies it: `run` and `check`,
//! result files, exit codes, and one test per class of bad input.

mod common;
use common::{read_csv, repo_file, scratch, stancf, text, write_scenario, BIN};
use std::path::Path;
use std::process::Command;

/// A small valid scenario: the transverse impact, shortened.
const BASE: &str = common::IMPACT;

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

/// Runs `stancf run` on a scenario and checks the exit code 2, that the
/// message names the file and `needles`, and that no output is written.
fn expect_input_error(name: &str, scenario: &str, needles: &[&str]) {
    let d = scratch(name);
    let sc = write_scenario(&d, "bad.toml", scenario);
    let out = d.join("never");
    for cmd in ["run", "check"] {
        let mut args = vec![cmd, sc.to_str().unwrap()];
        if cmd == "run" {
            args.extend(["--out", out.to_str().unwrap()]);
        }
        let o = stancf(&args);
        let (_, se) = text(&o);
        assert_eq!(o.status.code(), Some(2), "{name} ({cmd}): {se}");
        assert!(se.contains("bad.toml"), "{name}: file not named: {se}");
        for n in needles {
            assert!(se.contains(n), "{name}: {n:?} not in: {se}");
        }
    }
    assert!(!out.exists(), "{name}: an output folder was created");
}

#[test]
fn bad_input_malformed_toml() {
    expect_input_error(
        "malformed",
        &BASE.replace("length = 4.0", "length = = 4.0"),
        &["line 4"],
    );
}

#[test]
fn bad_input_unknown_key_at_any_level() {
    expect_input_error("unknown-top", &format!("colour = 1\n{BASE}"), &["colour"]);
    expect_input_error(
        "unknown-cable",
        &BASE.replace("length = 4.0", "lenght = 4.0"),
        &["lenght"],
    );
    expect_input_error(
        "unknown-analysis",
        &BASE.replace("type = \"dynamic\"", "type = \"dynamic\"\ntimestep = 1"),
        &["timestep"],
    );
    expect_input_error(
        "unknown-load",
        &BASE.replace("type = \"gravity\"", "type = \"gravity\"\nstrength = 2"),
        &["loads[0]", "strength"],
    );
    expect_input_error(
        "unknown-iv",
        &BASE.replace("node = \"A\"", "node = \"A\"\nspeed = 1"),
        &["speed"],
    );
    expect_input_error(
        "unknown-output",
        &BASE.replace("every = 4", "evry = 4"),
        &["evry"],
    );
}

#[test]
fn bad_input_missing_required_key() {
    expect_input_error(
        "missing-length",
        &BASE.replace("length = 4.0\n", ""),
        &["cable.length", "missing"],
    );
    expect_input_error(
        "missing-density",
        &BASE.replace("density = 1380.0\n", ""),
        &["material.density", "missing"],
    );
    expect_input_error(
        "missing-step",
        &BASE.replace("time_step = 5.0e-5\n", ""),
        &["analysis.time_step", "missing"],
    );
    expect_input_error(
        "missing-force",
        &BASE.replace("acceleration = [0.0, -9.81, 0.0]\n", ""),
        &["loads[0].acceleration", "missing"],
    );
}

#[test]
fn bad_input_zero_or_negative_quantities() {
    for (from, to, key) in [
        ("length = 4.0", "length = 0.0", "cable.length"),
        ("length = 4.0", "length = -4.0", "cable.length"),
        ("elements = 8", "elements = 0", "cable.elements"),
        ("elements = 8", "elements = -3", "cable.elements"),
        (
            "youngs_modulus = 3.4e9",
            "youngs_modulus = -1.0",
            "material.youngs_modulus",
        ),
        ("density = 1380.0", "density = 0", "material.density"),
        ("area = 3.0e-6", "area = -3.0e-6", "material.area"),
        (
            "second_moment = 1.25e-13",
            "second_moment = 0.0",
            "material.second_moment",
        ),
        (
            "time_step = 5.0e-5",
            "time_step = 0.0",
            "analysis.time_step",
        ),
        (
            "time_step = 5.0e-5",
            "time_step = -1e-5",
            "analysis.time_step",
        ),
        (
            "duration = 2.0e-3",
            "duration = -2.0e-3",
            "analysis.duration",
        ),
    ] {
        expect_input_error(
            &format!("nonpositive-{key}-{to}"),
            &BASE.replace(from, to),
            &[key],
        );
    }
}

#[test]
fn bad_input_step_longer_than_duration() {
    expect_input_error(
        "step-longer",
        &BASE.replace("time_step = 5.0e-5", "time_step = 5.0e-3"),
        &["analysis.time_step", "longer than the duration"],
    );
}

#[test]
fn bad_input_non_finite_number() {
    expect_input_error(
        "nan",
        &BASE.replace("length = 4.0", "length = nan"),
        &["cable.length", "finite"],
    );
    expect_input_error(
        "inf",
        &BASE.replace("origin = [-2.0, 0.0, 0.0]", "origin = [-2.0, inf, 0.0]"),
        &["cable.origin", "finite"],
    );
    expect_input_error(
        "inf-velocity",
        &BASE.replace("velocity = [0.0, 10.0, 0.0]", "velocity = [0.0, -inf, 0.0]"),
        &["initial_velocity[0].velocity", "finite"],
    );
}

#[test]
fn bad_input_unknown_choices() {
    expect_input_error(
        "element",
        &BASE.replace("element = \"SAC-2\"", "element = \"SAC-4\""),
        &["cable.element", "SAC-4"],
    );
    expect_input_error(
        "strain",
        &BASE.replace(
            "quadrature = [3, 3]",
            "quadrature = [3, 3]\naxial_strain = \"log\"",
        ),
        &["analysis.axial_strain", "log"],
    );
    expect_input_error(
        "curvature",
        &BASE.replace(
            "quadrature = [3, 3]",
            "quadrature = [3, 3]\ncurvature = \"approx\"",
        ),
        &["analysis.curvature", "approx"],
    );
    expect_input_error(
        "load-type",
        &BASE.replace("type = \"gravity\"", "type = \"magnet\""),
        &["loads[0].type", "magnet"],
    );
}

#[test]
fn bad_input_node_index_out_of_range() {
    expect_input_error(
        "node-range",
        &BASE.replace("node = 8", "node = 9"),
        &["initial_velocity[1].node", "out of range"],
    );
    expect_input_error(
        "node-name",
        &BASE.replace("node = \"A\"", "node = \"C\""),
        &["initial_velocity[0].node", "\"C\""],
    );
    expect_input_error(
        "force-node",
        &BASE.replace(
            "[[initial_velocity]]\nnode = \"A\"",
            "[[loads]]\ntype = \"point-force\"\nnode = 12\nforce = [1.0, 0.0, 0.0]\n[[initial_velocity]]\nnode = \"A\"",
        ),
        &["loads[1].node", "out of range"],
    );
}

#[test]
fn bad_input_zero_direction_vector() {
    expect_input_error(
        "zero-dir",
        &BASE.replace("direction = [1.0, 0.0, 0.0]", "direction = [0.0, 0.0, 0.0]"),
        &["cable.direction", "zero vector"],
    );
}

#[test]
fn bad_input_vector_without_three_components() {
    expect_input_error(
        "two-comp",
        &BASE.replace("origin = [-2.0, 0.0, 0.0]", "origin = [-2.0, 0.0]"),
        &["cable.origin", "3 components"],
    );
    expect_input_error(
        "four-comp",
        &BASE.replace(
            "velocity = [0.0, 10.0, 0.0]",
            "velocity = [0.0, 10.0, 0.0, 1.0]",
        ),
        &["initial_velocity[0].velocity", "3 components"],
    );
}

#[test]
fn bad_input_quadrature_points() {
    expect_input_error(
        "zero-points",
        &BASE.replace("quadrature = [3, 3]", "quadrature = [0, 3]"),
        &["analysis.quadrature", "between 1 and 10"],
    );
    expect_input_error(
        "eleven-points",
        &BASE.replace("quadrature = [3, 3]", "quadrature = [3, 11]"),
        &["analysis.quadrature", "between 1 and 10"],
    );
    expect_input_error(
        "one-number",
        &BASE.replace("quadrature = [3, 3]", "quadrature = [3]"),
        &["analysis.quadrature"],
    );
}

#[test]
fn bad_input_zero_time_layers() {
    expect_input_error(
        "layers",
        &BASE.replace(
            "quadrature = [3, 3]",
            "quadrature = [3, 3]\ntime_layers = 0",
        ),
        &["analysis.time_layers", "between 1 and 16"],
    );
}

#[test]
fn unreadable_file_is_an_input_error() {
    let o = stancf(&["run", "/nonexistent/scenario.toml"]);
    let (_, se) = text(&o);
    assert_eq!(o.status.code(), Some(2));
    assert!(se.contains("/nonexistent/scenario.toml"), "{se}");
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

#[test]
fn bad_input_constraints() {
    let pin = |extra: &str| {
        BASE.replace(
            "[[loads]]\ntype = \"gravity\"",
            &format!("{extra}\n[[loads]]\ntype = \"gravity\""),
        )
        .replace(
            "[[initial_velocity]]\nnode = \"A\"\nvelocity = [0.0, 10.0, 0.0]\n",
            "",
        )
    };
    expect_input_error(
        "constraint-node",
        &pin("[[constraints]]\ntype = \"pinned\"\nnode = 11"),
        &["constraints[0].node", "out of range"],
    );
    expect_input_error(
        "constraint-type",
        &pin("[[constraints]]\ntype = \"welded\"\nnode = \"A\""),
        &["constraints[0].type", "welded"],
    );
    expect_input_error(
        "constraint-conflict",
        &pin("[[constraints]]\ntype = \"clamped\"\nnode = \"A\"\n[[constraints]]\ntype = \"pinned\"\nnode = 0"),
        &["constraints[1]", "conflicts with constraints[0]", "node 0"],
    );
    expect_input_error(
        "constraint-unknown-key",
        &pin("[[constraints]]\ntype = \"pinned\"\nnode = \"A\"\nstiffness = 3"),
        &["constraints[0]", "stiffness"],
    );
    expect_input_error(
        "fix-curvature-sac2",
        &pin("[[constraints]]\ntype = \"clamped\"\nnode = \"A\"\nfix_curvature = true"),
        &["constraints[0].fix_curvature", "SAC-3"],
    );
    // An initial velocity on a pinned node contradicts the pin.
    expect_input_error(
        "velocity-vs-pin",
        &pin("[[constraints]]\ntype = \"pinned\"\nnode = \"B\""),
        &["initial_velocity[0].velocity", "pinned"],
    );
}

#[test]
fn bad_input_static_without_constraints_against_rigid_motions() {
    let statik = BASE
        .replace("type = \"dynamic\"", "type = \"static\"")
        .replace(
            "[[initial_velocity]]\nnode = \"A\"\nvelocity = [0.0, 10.0, 0.0]\n[[initial_velocity]]\nnode = 8\nvelocity = [0.0, -10.0, 0.0]\n",
            "",
        );
    expect_input_error("static-free", &statik, &["constraints", "rigid motions"]);
    let one_pin = statik.replace(
        "[[loads]]\ntype = \"gravity\"",
        "[[constraints]]\ntype = \"pinned\"\nnode = 4\n[[loads]]\ntype = \"gravity\"",
    );
    expect_input_error(
        "static-one-pin",
        &one_pin,
        &["constraints", "rigid motions"],
    );
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

/// `stancf reproduce circle-bending`: its tables exist, and the SAC-3
/// 10-element full circle closes within 1e-3 mm.
#[test]
fn reproduce_circle_bending() {
    let d = scratch("reproduce");
    let o = stancf(&["reproduce", "circle-bending", "--out", d.to_str().unwrap()]);
    assert_eq!(o.status.code(), Some(0), "{:?}", text(&o));
    let dir = d.join("circle-bending");
    let md = std::fs::read_to_string(dir.join("table3.md")).unwrap();
    assert!(md.contains("Table 3") && md.contains("65.31"));
    let csv = std::fs::read_to_string(dir.join("table3.csv")).unwrap();
    let mut found = false;
    for line in csv.lines().skip(1) {
        let f: Vec<&str> = line.split(',').collect();
        // element, ..., fix_curvature, curvature, elements, lambda, tip_x_mm
        if f[1] == "SAC-3" && f[4] == "false" && f[5] == "paper" && f[6] == "10" && f[7] == "2" {
            let err: f64 = f[8].parse().unwrap();
            assert!(err.abs() < 1e-3, "{err}");
            found = true;
        }
    }
    assert!(found);
    let conv = std::fs::read_to_string(dir.join("convergence.csv")).unwrap();
    assert_eq!(conv.lines().count(), 1 + 2 * 2 * 4);
    let o = stancf(&["reproduce", "no-such-study"]);
    assert_eq!(o.status.code(), Some(2));
}

/// `stancf reproduce pendulum`: 16 SAC-3 elements with engineering strain
/// (the reference's measure) stay within 0.05 mm of the Exudyn reference
/// tip at the six report times, with and without drag; the study reports
/// the same for 4 SAC-2 elements.
#[test]
fn reproduce_pendulum_matches_the_exudyn_reference() {
    let d = scratch("reproduce-pendulum");
    let o = stancf(&["reproduce", "pendulum", "--out", d.to_str().unwrap()]);
    assert_eq!(o.status.code(), Some(0), "{:?}", text(&o));
    let dir = d.join("pendulum");
    let csv = std::fs::read_to_string(dir.join("tip_at_image_times.csv")).unwrap();
    let mut checked = 0;
    for line in csv.lines().skip(1) {
        let f: Vec<&str> = line.split(',').collect();
        // element,elements,axial_strain,drag_coefficient,t,x,y,ex,ey,distance
        let t: f64 = f[4].parse().unwrap();
        if f[0] == "SAC-3" && f[1] == "16" && f[2] == "engineering" && t > 0.1 {
            let dist: f64 = f[9].parse().unwrap();
            assert!(dist < 0.05, "{line}");
            checked += 1;
        }
    }
    assert_eq!(checked, 12, "six times, with and without drag");
    let md = std::fs::read_to_string(dir.join("pendulum.md")).unwrap();
    assert!(md.contains("not public") && md.contains("4 SAC-2 (the paper's mesh)"));
    for f in ["shapes_068.csv", "tip_trajectory.csv"] {
        assert!(std::fs::metadata(dir.join(f)).unwrap().len() > 1000);
    }
}

/// `stancf reproduce grid-refinement` (Table 6): refining in time at the
/// fine mesh gives an order between 3.5 and 4.5 on the energy error, for
/// Newton and Broyden, and the orders are printed beside the paper's.
#[test]
fn reproduce_grid_refinement_orders() {
    let d = scratch("reproduce-grid");
    let o = stancf(&["reproduce", "grid-refinement", "--out", d.to_str().unwrap()]);
    assert_eq!(o.status.code(), Some(0), "{:?}", text(&o));
    let dir = d.join("grid-refinement");
    let csv = std::fs::read_to_string(dir.join("table6.csv")).unwrap();
    let mut orders = Vec::new();
    for line in csv.lines().skip(1) {
        let f: Vec<&str> = line.split(',').collect();
        if f[0].starts_with("time") && !f[6].is_empty() {
            orders.push(f[6].parse::<f64>().unwrap());
        }
    }
    assert_eq!(orders.len(), 6, "three refinements, two solvers");
    for o in &orders {
        assert!((3.5..=4.5).contains(o), "{orders:?}");
    }
    let md = std::fs::read_to_string(dir.join("table6.md")).unwrap();
    assert!(md.contains("paper's Table 6") && md.contains("3.91"));
}

/// The efficiency, impact-axial and impact-transverse studies run and
/// write their tables (their numbers are checked by the library tests;
/// timings are ratios and not asserted).
#[test]
fn reproduce_efficiency_and_impact_studies() {
    let d = scratch("reproduce-eff");
    for (study, files) in [
        ("efficiency", vec!["efficiency.csv", "efficiency.md"]),
        (
            "impact-axial",
            vec!["impact-axial.md", "stress_map_sac2.csv", "energy_sac3.csv"],
        ),
        (
            "impact-transverse",
            vec![
                "impact-transverse.md",
                "energy_sac2.csv",
                "midpoint_sac3.csv",
            ],
        ),
    ] {
        let o = stancf(&["reproduce", study, "--out", d.to_str().unwrap()]);
        assert_eq!(o.status.code(), Some(0), "{study}: {:?}", text(&o));
        for f in files {
            let p = d.join(study).join(f);
            assert!(std::fs::metadata(&p).unwrap().len() > 200, "{p:?}");
        }
    }
    let csv = std::fs::read_to_string(d.join("efficiency/efficiency.csv")).unwrap();
    assert_eq!(csv.lines().count(), 10, "nine cases");
    let md = std::fs::read_to_string(d.join("impact-axial/impact-axial.md")).unwrap();
    assert!(md.contains("23.5 MPa"));
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

#[test]
fn bad_input_drag() {
    let drag = |extra: &str| {
        BASE.replace(
            "[[loads]]\ntype = \"gravity\"",
            &format!("[[loads]]\ntype = \"air-drag\"\n{extra}\n[[loads]]\ntype = \"gravity\""),
        )
    };
    expect_input_error(
        "drag-model",
        &drag("drag_coefficient = 1.0\nfluid_density = 1.2\nmodel = \"turbulent\""),
        &["loads[0].model", "turbulent"],
    );
    expect_input_error(
        "drag-negative",
        &drag("drag_coefficient = -1.0\nfluid_density = 1.2"),
        &["loads[0].drag_coefficient", ">= 0"],
    );
    expect_input_error(
        "drag-missing",
        &drag("fluid_density = 1.2"),
        &["loads[0].drag_coefficient", "missing"],
    );
    expect_input_error(
        "drag-tangential-full",
        &drag("drag_coefficient = 1.0\nfluid_density = 1.2\ntangential_coefficient = 0.1"),
        &["loads[0].tangential_coefficient", "normal"],
    );
    expect_input_error(
        "solver",
        &BASE.replace(
            "quadrature = [3, 3]",
            "quadrature = [3, 3]\nsolver = \"secant\"",
        ),
        &["analysis.solver", "secant"],
    );
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

/// A PNG file: signature, IHDR size, and a size a real figure has.
fn check_png(path: &Path) {
    let b = std::fs::read(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    assert_eq!(&b[..8], b"\x89PNG\r\n\x1a\n", "{}", path.display());
    assert_eq!(&b[12..16], b"IHDR", "{}", path.display());
    let w = u32::from_be_bytes(b[16..20].try_into().unwrap());
    let h = u32::from_be_bytes(b[20..24].try_into().unwrap());
    assert!(
        (600..=2000).contains(&w) && (400..=1500).contains(&h),
        "{w} x {h}"
    );
    assert!(
        b.len() > 10_000 && b.len() < 5_000_000,
        "{}: {} bytes",
        path.display(),
        b.len()
    );
}

/// An SVG file that a browser would draw, with its title in it.
fn check_svg(path: &Path, title: &str) {
    let s = std::fs::read_to_string(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    assert!(s.starts_with("<svg"), "{}", path.display());
    assert!(s.trim_end().ends_with("</svg>"), "{}", path.display());
    assert!(s.contains(title), "{}: no title {title:?}", path.display());
    assert!(
        s.len() > 2_000 && s.len() < 10_000_000,
        "{}: {} bytes",
        path.display(),
        s.len()
    );
}

/// `run --plot` draws the run's figures next to its results, `plot DIR`
/// redraws them from the files; a folder without results is an input
/// error.
#[test]
fn run_plot_and_plot_dir_write_valid_figures() {
    let d = scratch("plots");
    let sc = write_scenario(
        &d,
        "p.toml",
        &BASE.replace("title = \"test\"", "title = \"plot test\""),
    );
    let out = d.join("res");
    let o = stancf(&[
        "run",
        sc.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
        "--plot",
    ]);
    let (so, se) = text(&o);
    assert_eq!(o.status.code(), Some(0), "{se}");
    assert!(
        so.contains("figures: shapes, energy, stress_map, convergence"),
        "{so}"
    );
    let figures = [
        ("shapes", "plot test: shapes"),
        ("energy", "plot test: energies"),
        ("stress_map", "plot test: axial stress"),
        ("convergence", "plot test: residuals"),
    ];
    for (name, title) in figures {
        check_png(&out.join(format!("{name}.png")));
        check_svg(&out.join(format!("{name}.svg")), title);
    }
    // Redrawn from the files alone.
    for (name, _) in figures {
        std::fs::remove_file(out.join(format!("{name}.png"))).unwrap();
    }
    let o = stancf(&["plot", out.to_str().unwrap()]);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o).1);
    for (name, _) in figures {
        check_png(&out.join(format!("{name}.png")));
    }
    let o = stancf(&["plot", d.to_str().unwrap()]);
    let (_, se) = text(&o);
    assert_eq!(o.status.code(), Some(2), "{se}");
    assert!(se.contains("no summary.json"), "{se}");
}

/// The values of a `<DataArray ... Name="name" ...>` of a VTK XML file.
fn vtk_array(xml: &str, name: &str) -> Vec<f64> {
    let tag = format!("Name=\"{name}\"");
    let start = xml.find(&tag).unwrap_or_else(|| panic!("no array {name}"));
    let open = start + xml[start..].find('>').unwrap() + 1;
    let close = open + xml[open..].find("</DataArray>").unwrap();
    xml[open..close]
        .split_whitespace()
        .map(|v| v.parse::<f64>().unwrap())
        .collect()
}

/// `run --vtk`: one PolyData file per written step and the collection with
/// the times; read back, the polyline passes through the nodes of
/// nodes.csv and its arrays have the right sizes and values.
#[test]
fn vtk_files_read_back() {
    let d = scratch("vtk");
    let sc = write_scenario(&d, "v.toml", BASE);
    let out = d.join("res");
    let o = stancf(&[
        "run",
        sc.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
        "--vtk",
    ]);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o).1);
    let (_, hist) = read_csv(&out.join("history.csv"));
    let (_, nodes) = read_csv(&out.join("nodes.csv"));
    let (_, stress) = read_csv(&out.join("stress.csv"));
    let pvd = std::fs::read_to_string(out.join("cable.pvd")).unwrap();
    assert!(pvd.contains("type=\"Collection\""));
    let entries: Vec<(f64, String)> = pvd
        .lines()
        .filter(|l| l.starts_with("<DataSet"))
        .map(|l| {
            let attr = |a: &str| {
                let k = l.find(&format!("{a}=\"")).unwrap() + a.len() + 2;
                l[k..k + l[k..].find('"').unwrap()].to_string()
            };
            (attr("timestep").parse().unwrap(), attr("file"))
        })
        .collect();
    assert_eq!(entries.len(), hist.len(), "one file per written step");
    let per_element = 16;
    let n_points = 8 * (per_element - 1) + 1;
    for (k, (t, file)) in entries.iter().enumerate() {
        assert_eq!(*t, hist[k][0], "time of {file}");
        let xml = std::fs::read_to_string(out.join(file)).unwrap();
        assert!(
            xml.contains(&format!("NumberOfPoints=\"{n_points}\"")),
            "{file}"
        );
        let pos = vtk_array(&xml, "position");
        assert_eq!(pos.len(), 3 * n_points);
        // Through every node of nodes.csv at this time.
        let at_t: Vec<&Vec<f64>> = nodes.iter().filter(|r| r[0] == *t).collect();
        assert_eq!(at_t.len(), 9);
        for (j, node) in at_t.iter().enumerate() {
            let p = j * (per_element - 1);
            for c in 0..3 {
                assert!(
                    (pos[3 * p + c] - node[2 + c]).abs() < 1e-12,
                    "{file}: node {j}: {} vs {}",
                    pos[3 * p + c],
                    node[2 + c]
                );
            }
        }
        assert_eq!(vtk_array(&xml, "velocity").len(), 3 * n_points);
        let s = vtk_array(&xml, "s");
        assert_eq!(s.len(), n_points);
        assert_eq!(s[0], 0.0);
        assert!((s[n_points - 1] - 4.0).abs() < 1e-12);
        let sigma = vtk_array(&xml, "axial_stress");
        assert_eq!(sigma.len(), n_points);
        assert_eq!(vtk_array(&xml, "curvature").len(), n_points);
        // The free end's stress is the one stress.csv has there.
        let end = stress.iter().find(|r| r[0] == *t && r[1] == 0.0).unwrap();
        assert!(
            (sigma[0] - end[2]).abs() <= 1e-9 * end[2].abs().max(1.0),
            "{file}"
        );
        let conn = vtk_array(&xml, "connectivity");
        assert_eq!(conn, (0..n_points).map(|i| i as f64).collect::<Vec<_>>());
        assert_eq!(vtk_array(&xml, "offsets"), vec![n_points as f64]);
    }
    // The initial velocities of the struck ends.
    let xml = std::fs::read_to_string(out.join(&entries[0].1)).unwrap();
    let v = vtk_array(&xml, "velocity");
    assert_eq!(v[1], 10.0);
    assert_eq!(v[3 * (n_points - 1) + 1], -10.0);
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

/// `stancf reproduce all`: REPORT.md with a section per study headed by the
/// paper's table and figure numbers, every figure embedded by a relative
/// link to a valid PNG (with its SVG twin), the paper's values and the
/// differences beside ours, and a verdict per study.
#[test]
fn reproduce_all_writes_the_report() {
    let d = scratch("report");
    let o = stancf(&["reproduce", "all", "--out", d.to_str().unwrap()]);
    let (so, se) = text(&o);
    assert_eq!(o.status.code(), Some(0), "{se}");
    assert!(so.contains("report: "), "{so}");
    let report = std::fs::read_to_string(d.join("REPORT.md")).unwrap();
    for heading in [
        "## Table 3 and Fig. 3: circle bending",
        "## Fig. 4: double-ended axial impact",
        "## Fig. 5: double-ended transverse impact",
        "## Tables 5, 7, 8 and Figs. 6, 7: efficiency",
        "## Table 6: grid refinement",
        "## Figs. 8, 10 and Table 10: free pendulum with air drag",
        "### Table 8 as measured",
        "### Table 10 times",
    ] {
        assert!(report.contains(heading), "no {heading:?}");
    }
    assert_eq!(
        report.matches("**What agrees and what does not.**").count(),
        6
    );
    assert!(
        report.contains("(paper 65.3100, difference +0.0317)"),
        "Table 3 difference"
    );
    let links: Vec<&str> = report
        .lines()
        .filter_map(|l| l.strip_prefix("!["))
        .map(|l| {
            let start = l.find("](").unwrap() + 2;
            &l[start..l.len() - 1]
        })
        .collect();
    for f in [
        "circle-bending/fig3_shapes.png",
        "impact-axial/fig4_stress_sac2.png",
        "impact-axial/fig4_stress_sac3.png",
        "impact-transverse/fig5a_midpoint.png",
        "impact-transverse/fig5b_energy.png",
        "efficiency/fig6_efficiency.png",
        "efficiency/fig7_residuals.png",
        "pendulum/fig8_shapes.png",
        "pendulum/fig10_shapes.png",
        "pendulum/fig10_tip_path_drag.png",
        "pendulum/fig10_tip_path_nodrag.png",
    ] {
        assert!(links.contains(&f), "{f} not embedded: {links:?}");
    }
    for link in &links {
        check_png(&d.join(link));
        let svg = d.join(link).with_extension("svg");
        assert!(svg.exists(), "{}", svg.display());
    }
    // The pendulum's tip path is drawn against the reference it ships.
    let svg = std::fs::read_to_string(d.join("pendulum/fig10_tip_path_drag.svg")).unwrap();
    assert!(svg.contains("Exudyn 1.13 reference"));
}
