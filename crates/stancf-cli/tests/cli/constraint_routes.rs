//! How a system's constraints are enforced (docs/interface.md
//! `constraint_method`, docs/method.md §6.3-6.4): eliminated unless the
//! scenario asks for multipliers or a line end is clamped, with the
//! same motion either way.

use crate::common::*;

/// A bridle (a clump weight of 2 kg on a 4 m rope from a fixed point
/// and a 5 m rope from a coupled point swinging 0.3 m along x every
/// 0.5 s; the ropes with some bending stiffness and damping), Galerkin
/// steps of 2 ms for 0.1 s from the equilibrium; `extra` (TOML lines)
/// added to `[analysis]`, `line_keys` to line 2.
fn swung_clump(extra: &str, line_keys: &str) -> String {
    let rest = format!(
        "[[motions]]\npoint = 2\namplitude = [0.3, 0.0, 0.0]\nperiod = 0.5\n[analysis]\n\
         type = \"dynamic\"\ninitial = \"static\"\ntime_step = 2e-3\nduration = 0.1\n\
         time_scheme = \"galerkin\"\n{extra}\n[output]\nfiles = [\"points.csv\"]"
    );
    bridle_system(2.0, ("coupled", "ei = 0.05\nba = 20.0", line_keys), &rest)
}

/// The words of `stancf check` on the scenario's constraints.
fn route_in_check(d: &std::path::Path, name: &str, scenario: &str) -> String {
    let sc = write_scenario(d, name, scenario);
    let o = stancf(&["check", sc.to_str().unwrap()]);
    let (so, se) = text(&o);
    assert_eq!(o.status.code(), Some(0), "{se}");
    so.lines()
        .find(|l| l.trim_start().starts_with("constraints"))
        .unwrap_or_else(|| panic!("no constraints line: {so}"))
        .to_string()
}

/// The forces on the three points at every written step.
fn point_forces(d: &std::path::Path, name: &str, scenario: &str) -> Vec<Vec<f64>> {
    let sc = write_scenario(d, name, scenario);
    let out = d.join(format!("out-{name}"));
    let o = run_quiet(&sc, &out, &[]);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o).1);
    let (_, rows) = read_csv(&out.join("points.csv"));
    rows.iter().map(|r| r[8..11].to_vec()).collect()
}

/// A system's fixed coordinates are eliminated from its steps unless
/// `analysis.constraint_method` asks for multipliers or a line end is
/// clamped in a direction (which only multipliers hold): `check` says
/// which. The two routes solve the same equations, so the forces on the
/// fixed, the free and the coupled point agree at every step to Newton's
/// tolerance: 1e-10 of a rope's length moves an end force by at most
/// (EA / l) 1e-10 L = (2e4 N / 0.5 m) 1e-10 5 m = 2e-5 N, of a weight
/// of 19.6 N, so 1e-6 of it bounds the difference.
#[test]
fn a_systems_constraints_are_eliminated_with_the_multiplier_routes_motion() {
    let d = scratch("constraint-routes");
    let default = route_in_check(&d, "default.toml", &swung_clump("", ""));
    assert!(default.contains("eliminated"), "{default}");
    let asked = swung_clump("constraint_method = \"multiplier\"", "");
    let multipliers = route_in_check(&d, "asked.toml", &asked);
    assert!(
        multipliers.contains("Lagrange multipliers (analysis.constraint_method"),
        "{multipliers}"
    );
    let clamped = route_in_check(
        &d,
        "clamped.toml",
        &swung_clump("", "clamp_a = [1.0, 0.0, 1.0]"),
    );
    assert!(clamped.contains("a line end is clamped"), "{clamped}");

    let eliminated = point_forces(&d, "default.toml", &swung_clump("", ""));
    let with_multipliers = point_forces(&d, "asked.toml", &asked);
    assert_eq!(eliminated.len(), with_multipliers.len());
    assert_eq!(eliminated.len(), 3 * 51, "t = 0 and 50 steps of 3 points");
    let weight = 2.0 * 9.81;
    let worst = eliminated
        .iter()
        .zip(&with_multipliers)
        .flat_map(|(a, b)| a.iter().zip(b).map(|(x, y)| (x - y).abs()))
        .fold(0.0, f64::max);
    let moved = eliminated
        .iter()
        .zip(&eliminated[3..])
        .flat_map(|(a, b)| a.iter().zip(b).map(|(x, y)| (x - y).abs()))
        .fold(0.0, f64::max);
    eprintln!(
        "largest difference of a point force {worst:e} N; largest change over a step {moved:e} N"
    );
    assert!(
        moved > 1e-2 * weight,
        "the swing must load the points: {moved:e}"
    );
    assert!(worst <= 1e-6 * weight, "{worst:e} N");
}
