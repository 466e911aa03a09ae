//! Rigid bodies in systems (docs/interface.md, "Rigid bodies"): a TOML
//! buoy and a MoorDyn deck's BODIES run through statics and motion,
//! bodies.csv and the deck's body channels hold what the body feels, and
//! what is not built is refused naming the key or the deck's line.

use crate::common::*;
use std::path::Path;

const G: f64 = 9.81;
/// The buoy's net lift, (rho V - m) g (common::moored_buoy).
const LIFT: f64 = (1025.0 * 2.0 - 500.0) * G;

const BODIES_HEADER: [&str; 20] = [
    "t", "body", "x", "y", "z", "roll", "pitch", "yaw", "vx", "vy", "vz", "wx", "wy", "wz", "fx",
    "fy", "fz", "mx", "my", "mz",
];

fn cross(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

fn norm(v: [f64; 3]) -> f64 {
    v.iter().map(|x| x * x).sum::<f64>().sqrt()
}

fn three(row: &[f64], first: usize) -> [f64; 3] {
    [row[first], row[first + 1], row[first + 2]]
}

/// Runs `scenario` (written as `name`.toml in a scratch folder) quietly
/// and returns its output folder; the run must succeed.
fn run_ok(name: &str, scenario: &str) -> std::path::PathBuf {
    let d = scratch(name);
    let sc = write_scenario(&d, &format!("{name}.toml"), scenario);
    let out = d.join("out");
    let o = run_quiet(&sc, &out, &[]);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o).1);
    out
}

/// The buoy's balance at a row of bodies.csv: the lines' force and
/// their moment about the reference point against its net lift at its
/// centre of mass, c = (0, 0, -0.3) in its axes, as fractions of the
/// lift (and of the lift times 1 m).
fn imbalance(row: &[f64]) -> (f64, f64) {
    let force = three(row, 14);
    let moment = three(row, 17);
    let r = rotation_of_angles(three(row, 5));
    let arm: [f64; 3] = std::array::from_fn(|i| -0.3 * r[i][2]);
    let lift = [0.0, 0.0, LIFT];
    let m_lift = cross(arm, lift);
    let f: [f64; 3] = std::array::from_fn(|i| force[i] + lift[i]);
    let m: [f64; 3] = std::array::from_fn(|i| moment[i] + m_lift[i]);
    (norm(f) / LIFT, norm(m) / LIFT)
}

/// The buoy's equilibrium, then 1 s of Galerkin steps from it at rest.
/// bodies.csv's first row (the equilibrium) balances the buoy's net lift
/// at its centre of mass with the lines' force and moment to 1e-6 (the
/// static solve converges to 1e-10 of the lines' scale; measured 1e-13
/// and 1e-10), its lines' force is the sum of points.csv's at its
/// three points, the uneven lines tilt it, and the run keeps it there to
/// 1e-9 m: at rest at its equilibrium the step holds it to round-off
/// (the core's run of this buoy: 4e-14 m in 2 s), where a run from the
/// scenario's pose instead of the equilibrium's would be refused or
/// move it by metres.
#[test]
fn a_buoy_held_by_three_lines_balances_its_net_lift_at_equilibrium_and_stays_there() {
    let analysis = "type = \"dynamic\"\ninitial = \"static\"\ntime_step = 0.05\nduration = 1.0";
    let out = run_ok("buoy-balance", &moored_buoy("", analysis));
    let (header, rows) = read_csv(&out.join("bodies.csv"));
    assert_eq!(header, BODIES_HEADER);
    assert_eq!(rows.len(), 21, "one row per written time");
    let first = &rows[0];
    assert_eq!((first[0], first[1]), (0.0, 1.0));
    let (force, moment) = imbalance(first);
    eprintln!("imbalance at equilibrium: force {force:.1e}, moment {moment:.1e} of the lift");
    assert!(force < 1e-6 && moment < 1e-6, "{force:e} {moment:e}");
    let tilt = first[5].abs() + first[6].abs();
    assert!(
        tilt > 0.1 && tilt < 30.0,
        "roll and pitch {:?}",
        three(first, 5)
    );
    let (_, points) = read_csv(&out.join("points.csv"));
    let mut sum = [0.0; 3];
    for p in points.iter().filter(|p| p[0] == 0.0 && p[1] <= 3.0) {
        for c in 0..3 {
            sum[c] += p[8 + c];
        }
    }
    let lines = three(first, 14);
    assert!(norm(std::array::from_fn(|c| sum[c] - lines[c])) <= 1e-12 * LIFT);
    let start = three(first, 2);
    let moved = rows
        .iter()
        .map(|r| norm(std::array::from_fn(|c| r[2 + c] - start[c])))
        .fold(0.0, f64::max);
    eprintln!("the buoy moved at most {moved:.1e} m in 1 s");
    assert!(moved < 1e-9, "{moved:e}");
    let summary = read_json(&out.join("summary.json"));
    let last = rows.last().unwrap();
    let position = &summary["bodies"][0]["position_final"];
    for c in 0..3 {
        assert_eq!(position[c].as_f64(), Some(last[2 + c]));
    }
    assert_eq!(summary["bodies"][0]["type"], "free");
    assert_eq!(summary["points"][0]["type"], "body");
}

/// A static analysis writes the equilibrium once, at t = 1, with the
/// dynamic run's first row's pose (the same static solve).
#[test]
fn a_static_analysis_writes_the_bodys_equilibrium_at_t_1() {
    let out = run_ok("buoy-static", &moored_buoy("", "type = \"static\""));
    let (_, rows) = read_csv(&out.join("bodies.csv"));
    assert_eq!(rows.len(), 1);
    assert_eq!(rows[0][0], 1.0);
    let (force, moment) = imbalance(&rows[0]);
    assert!(force < 1e-6 && moment < 1e-6, "{force:e} {moment:e}");
    for v in &rows[0][8..14] {
        assert_eq!(*v, 0.0, "at rest");
    }
}

/// A constant force at the buoy's reference point and a constant moment
/// (`force`, `moment`, docs/method.md §15.13, (B27)): at the equilibrium
/// the lines' force and moment about the reference point balance them
/// with the net lift at the centre of mass, to 1e-6 of the lift (the
/// static tolerance); the force pulls it 2.5 m sideways, the moment turns
/// it. On a fixed body the keys are refused naming them.
#[test]
fn a_constant_force_and_moment_on_the_buoy_are_held_by_its_lines() {
    let (fx, mz) = (3000.0, 2000.0);
    let keys = format!("force = [{fx:?}, 0.0, 0.0]\nmoment = [0.0, 0.0, {mz:?}]");
    let out = run_ok("buoy-force", &moored_buoy(&keys, "type = \"static\""));
    let (_, rows) = read_csv(&out.join("bodies.csv"));
    let row = &rows[0];
    let (force, moment) = (three(row, 14), three(row, 17));
    let r = rotation_of_angles(three(row, 5));
    let arm: [f64; 3] = std::array::from_fn(|i| -0.3 * r[i][2]);
    let lift = [0.0, 0.0, LIFT];
    let m_lift = cross(arm, lift);
    let f: [f64; 3] = std::array::from_fn(|i| force[i] + lift[i] + [fx, 0.0, 0.0][i]);
    let m: [f64; 3] = std::array::from_fn(|i| moment[i] + m_lift[i] + [0.0, 0.0, mz][i]);
    eprintln!(
        "buoy under a force and a moment: x {:.3} m, yaw {:.3} deg; imbalance {:.1e}, {:.1e}",
        row[2],
        row[7],
        norm(f) / LIFT,
        norm(m) / LIFT
    );
    assert!(
        norm(f) < 1e-6 * LIFT && norm(m) < 1e-6 * LIFT,
        "{f:?} {m:?}"
    );
    assert!(row[2] > 0.1 && row[7].abs() > 0.1, "it moves and turns");
    let fixed = moored_buoy("", "type = \"static\"").replace("type = \"free\"", "type = \"fixed\"");
    let fixed = fixed.replace(
        "mass = 500.0\ncentre_of_mass = [0.0, 0.0, -0.3]\ninertia = [300.0, 300.0, 200.0]\nvolume = 2.0\n",
        "moment = [0.0, 0.0, 1.0]\n",
    );
    expect_input_error(
        "fixed-body-moment",
        &fixed,
        &["bodies[0].moment", "a fixed body"],
    );
}

/// In a uniform current of 0.5 m/s along x the buoy's lines hold its
/// drag 1/2 rho CdA |U| U (CdA 1 m^2 on every axis: 128.1 N whatever its
/// tilt) with its lift, to 1e-6 of the lift, as at rest (the static
/// solve holds the body's drag in the steady current, docs/method.md
/// §15.8): the current reaches the body.
#[test]
fn a_buoy_in_a_uniform_current_is_held_against_its_drag_and_lift() {
    let scenario = moored_buoy("cda = [1.0, 1.0, 1.0]", "type = \"static\"").replace(
        "density = 1025.0\n",
        "density = 1025.0\n[water.current]\nvelocity = [0.5, 0.0, 0.0]\n",
    );
    let out = run_ok("buoy-current", &scenario);
    let (_, rows) = read_csv(&out.join("bodies.csv"));
    let drag = 0.5 * 1025.0 * 1.0 * 0.5 * 0.5;
    let f = three(&rows[0], 14);
    let err = norm([f[0] + drag, f[1], f[2] + LIFT]);
    eprintln!("the lines' force {f:?} against the drag {drag} N and the lift: {err:.1e} N");
    assert!(err < 1e-6 * LIFT, "{err:e}");
}

/// A buoy pushed at its equilibrium (0.5 m/s in x, 0.2 rad/s about z)
/// starts with its push: bodies.csv's first row holds it, points.csv's
/// its points' velocities v + w x (x_P - x_ref) (to 1e-12 m/s, their
/// round-off). Without drag on the buoy, its energy less the water's
/// work on the lines is kept to the step's error, which falls at the
/// fourth order of bodies in systems (docs/method.md §15.7): at dt 0.05
/// and 0.025 s the largest drift over 1 s is 8.0e-4 and 3.0e-5 of the
/// push's kinetic energy (ratio 27); asserted: below 1e-4 at 0.025 s and
/// a ratio above 8 (order above 3).
#[test]
fn a_pushed_buoy_starts_with_its_push_and_keeps_its_energy_to_fourth_order() {
    let push = "velocity = [0.5, 0.0, 0.0]\nangular_velocity = [0.0, 0.0, 0.2]";
    let drift = |dt: f64| -> (f64, f64, std::path::PathBuf) {
        let analysis =
            format!("type = \"dynamic\"\ninitial = \"static\"\ntime_step = {dt}\nduration = 1.0");
        let out = run_ok(&format!("buoy-push-{dt}"), &moored_buoy(push, &analysis));
        let (header, history) = read_csv(&out.join("history.csv"));
        let col = |n: &str| header.iter().position(|h| h == n).unwrap();
        let (total, water) = (col("total"), col("water_work"));
        let e0 = history[0][total];
        let drift = history
            .iter()
            .map(|r| (r[total] - r[water] - e0).abs())
            .fold(0.0, f64::max);
        (drift, history[0][col("kinetic")], out)
    };
    let (coarse, k0, out) = drift(0.05);
    let (fine, _, _) = drift(0.025);
    // At least the buoy's own, m v^2 / 2 + I_z w^2 / 2 = 62.5 + 4 J (its
    // lines move too).
    assert!(k0 > 66.5 && k0 < 100.0, "the push's kinetic energy: {k0}");
    eprintln!(
        "energy drift {:.1e} and {:.1e} of the push's {k0:.1} J (ratio {:.1})",
        coarse / k0,
        fine / k0,
        coarse / fine
    );
    assert!(
        fine < 1e-4 * k0 && coarse > 8.0 * fine,
        "{coarse:e} {fine:e}"
    );
    let (_, rows) = read_csv(&out.join("bodies.csv"));
    let first = &rows[0];
    // The rates at the reference point come back from the centre's
    // velocity and the rotation: to their round-off.
    let given = [0.5, 0.0, 0.0, 0.0, 0.0, 0.2];
    for (k, want) in given.iter().enumerate() {
        assert!((first[8 + k] - want).abs() < 1e-15, "{:?}", &first[8..14]);
    }
    let (_, points) = read_csv(&out.join("points.csv"));
    let x_ref = three(first, 2);
    for p in points.iter().filter(|p| p[0] == 0.0 && p[1] <= 3.0) {
        let arm: [f64; 3] = std::array::from_fn(|c| p[2 + c] - x_ref[c]);
        let turn = cross([0.0, 0.0, 0.2], arm);
        let want: [f64; 3] = std::array::from_fn(|c| [0.5, 0.0, 0.0][c] + turn[c]);
        let err = norm(std::array::from_fn(|c| p[5 + c] - want[c]));
        assert!(err < 1e-12, "point {}: {err:e}", p[1]);
    }
}

/// The deck with a free body passes `stancf check` (the body, its mass,
/// its pose and the degrees of freedom printed) and runs: at its
/// equilibrium the line holds the body's weight m g (g = 9.80665, the
/// deck's default) to 1e-9 of it (static tolerance 1e-10 of the
/// line's scale), MoorDyn's net force on it (channel Body1FZ) is zero
/// to the same, and 0.5 s of motion from the equilibrium keeps it there
/// to 1e-9 m.
#[test]
fn a_deck_with_a_free_body_passes_check_and_runs_statics_and_motion() {
    let d = scratch("body-deck");
    let outputs = "Body1PZ\nBody1RX\nBody1VZ\nBody1FZ\nBody1MX\nAnchTen1\n";
    let deck = write_scenario(&d, "deck.dat", &body_deck("", "", outputs));
    let o = stancf(&["check", deck.to_str().unwrap()]);
    let (report, err) = text(&o);
    assert_eq!(o.status.code(), Some(0), "{err}");
    for needle in [
        "body 1",
        "free (6 degrees of freedom), mass 21244 kg",
        "moments [10000, 10000, 15000] kg m^2",
        "reference point at [0, 0, -50] m, roll, pitch, yaw [0, 0, 0] deg; point 1",
        "on free body 1 at [0, 0, 0] m in its axes",
        "degrees of freedom          66 (66 nodal coordinates",
    ] {
        assert!(report.contains(needle), "no {needle:?} in\n{report}");
    }
    let out = d.join("static");
    let o = run_quiet(&deck, &out, &[]);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o).1);
    let weight = 21244.0 * 9.80665;
    let (_, rows) = read_csv(&out.join("bodies.csv"));
    assert_eq!(rows.len(), 1);
    let fz = rows[0][16];
    assert!((fz - weight).abs() < 1e-9 * weight, "{fz} against {weight}");
    let (header, channels) = read_csv(&out.join("channels.csv"));
    assert_eq!(
        header,
        ["t", "Body1PZ", "Body1RX", "Body1VZ", "Body1FZ", "Body1MX", "AnchTen1"]
    );
    assert_eq!(channels[0][1], rows[0][4], "Body1PZ is bodies.csv's z");
    assert!(
        channels[0][4].abs() < 1e-9 * weight,
        "net force {}",
        channels[0][4]
    );
    let scenario = write_scenario(
        &d,
        "dynamic.toml",
        "[system]\nmoordyn = \"deck.dat\"\n[analysis]\ntype = \"dynamic\"\ntime_step = 0.01\n\
         duration = 0.5\n",
    );
    let out = d.join("dynamic");
    let o = run_quiet(&scenario, &out, &[]);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o).1);
    let (_, channels) = read_csv(&out.join("channels.csv"));
    assert_eq!(channels.len(), 51);
    let z0 = channels[0][1];
    let moved = channels
        .iter()
        .map(|r| (r[1] - z0).abs())
        .fold(0.0, f64::max);
    assert!(moved < 1e-9, "{moved:e}");
}

/// A point on a deck's free body with a mass and a volume of its own (10
/// kg, 4 litres) adds its weight and its buoyancy to the body's (as
/// MoorDyn's point on a body does: docs/method.md §15.8): at the static
/// equilibrium the line holds (21244 + 10 - 1025 x 0.004) g, to the
/// static tolerance (1e-9 of it), and the body's net force (Body1FZ,
/// the point's buoyancy in it) is zero to the same.
#[test]
fn a_heavy_point_on_a_deck_body_adds_its_weight_and_buoyancy_to_the_body() {
    let d = scratch("body-heavy-point");
    let deck = write_scenario(
        &d,
        "deck.dat",
        &body_deck(
            "",
            " 1        Body1     0        0         0        10        0.004        0        0",
            "Body1FZ\n",
        ),
    );
    let out = d.join("static");
    let o = run_quiet(&deck, &out, &[]);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o).1);
    let weight = (21244.0 + 10.0 - 1025.0 * 0.004) * 9.80665;
    let (_, rows) = read_csv(&out.join("bodies.csv"));
    let fz = rows[0][16];
    eprintln!("the line holds {fz} N, the body and its point weigh {weight} N in water");
    assert!((fz - weight).abs() < 1e-9 * weight, "{fz} against {weight}");
    let (_, channels) = read_csv(&out.join("channels.csv"));
    let net = channels[0][1];
    assert!(net.abs() < 1e-9 * weight, "net force {net}");
}

/// md_BdyExtLdDmpg's body: a point mass (moments of inertia 0).
const POINT_MASS_BODY: &str =
    " 1     free       0      0    -50     0      0      0    2.1244e4    0    0    0     0        0";

/// The deck's refusals name its line: a point on a body with a drag area
/// of its own, a point mass (a body without moments of inertia, which
/// MoorDyn takes) whose line pulls off its centre, turning it with no
/// inertia to resist (docs/method.md (B2a)).
#[test]
fn a_dragging_body_point_or_a_point_mass_pulled_off_its_centre_in_a_deck_is_refused_by_line() {
    let dragging_point = body_deck(
        "",
        " 1        Body1     0        0         0        0        0        1.5        0",
        "",
    );
    let pulled_off_centre = body_deck(
        POINT_MASS_BODY,
        " 1        Body1     1        0         0        0        0        0        0",
        "",
    );
    for (name, deck, needle, words) in [
        (
            "dragging-point",
            dragging_point,
            "Body1     0        0         0        0        0        1.5",
            "the drag and added mass of a point on a body are not built",
        ),
        (
            "pulled-off-centre",
            pulled_off_centre,
            "1     free",
            "no inertia about any line through it, and its point at [1.0, 0.0, 0.0]",
        ),
    ] {
        let line = deck.lines().position(|l| l.contains(needle)).unwrap() + 1;
        let at = format!("line {line}:");
        expect_refusal_beside(name, &deck, &[], &["bad.toml", &at, words]);
    }
}

/// OpenFAST's r-test md_BdyExtLdDmpg: a point mass (a body of 21 244 kg
/// without moments of inertia, its line at its centre, docs/method.md
/// (B2a)) hanging by a nylon line, pushed by MoorDyn-F's external force
/// (104.17, 50, -10) kN and damped along the global axes. At its static
/// equilibrium the line holds the force and the weight, -(F + m g), to
/// 1e-9 (the static tolerance), and the body does not turn; a dynamic
/// run from there stays to 1e-9 m over 2 s (the damping acts on no
/// velocity).
#[test]
fn r_test_md_bdy_ext_ld_dmpg_a_pushed_point_mass_hangs_where_its_forces_balance() {
    let d = scratch("point-mass");
    let deck = body_deck(POINT_MASS_BODY, "", "").replace(
        "-------------------------- SOLVER OPTIONS",
        "---------------------- EXTERNAL LOADS --------------------------------
ID    Object            Fext                Blin               Bquad            CSys
(#)   (name)            (N)                (Ns/m)            (Ns^2/m^2)         (-)
 1     Body1  1.0417e5|0.5e5|-1.0e4   1.0e3|0.7e3|0.6e2  3.0e3|2.1e3|1.0e4       G
-------------------------- SOLVER OPTIONS",
    );
    let deck = write_scenario(&d, "md_BdyExtLdDmpg.dat", &deck);
    let at = point_mass_held_at_rest(&deck, &d.join("statics"), 9.80665);
    let scenario = write_scenario(
        &d,
        "dynamic.toml",
        "[system]\nmoordyn = \"md_BdyExtLdDmpg.dat\"\n[analysis]\ntype = \"dynamic\"\n\
         time_step = 0.05\nduration = 2.0\n",
    );
    let out = d.join("dynamic");
    let o = run_quiet(&scenario, &out, &[]);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o).1);
    let (header, rows) = read_csv(&out.join("bodies.csv"));
    let last = &rows[rows.len() - 1];
    for (c, name) in ["x", "y", "z"].iter().enumerate() {
        let x = last[header.iter().position(|h| h == name).unwrap()];
        assert!((x - at[c]).abs() <= 1e-9, "{name}: {x} against {}", at[c]);
    }
}

/// The r-test's point mass as a TOML body (`inertia = [0, 0, 0]`, its
/// force a constant `force`, gravity 9.81): the line holds -(F + m g) to
/// 1e-9 of the weight, and the body does not turn.
#[test]
fn a_toml_point_mass_body_hangs_where_its_force_and_weight_balance() {
    let d = scratch("toml-point-mass");
    let scenario = write_scenario(
        &d,
        "point_mass.toml",
        "[water]\ndepth = 100.0\ndensity = 1025.0\n[[line_types]]\nname = \"nylon\"\n\
         diameter = 0.124\nmass_per_length = 35.0\nea = 5.0e6\n[[bodies]]\nid = 1\n\
         type = \"free\"\nposition = [0.0, 0.0, -50.0]\nmass = 21244.0\n\
         inertia = [0.0, 0.0, 0.0]\nforce = [104170.0, 50000.0, -10000.0]\n[[points]]\nid = 1\n\
         type = \"body\"\nbody = 1\nposition = [0.0, 0.0, 0.0]\n[[points]]\nid = 2\n\
         type = \"fixed\"\nposition = [0.0, 0.0, 0.0]\n[[lines]]\nid = 1\ntype = \"nylon\"\n\
         length = 48.0\nelements = 10\na = 2\nb = 1\n[analysis]\ntype = \"static\"\n",
    );
    point_mass_held_at_rest(&scenario, &d.join("out"), 9.81);
}

/// Runs `scenario` (a static run of md_BdyExtLdDmpg's point mass of
/// 21 244 kg pushed by (104.17, 50, -10) kN under gravity `g`) into
/// `out`: the lines hold -(F + m g) to 1e-9 of the weight (the static
/// tolerance) and the body does not turn. Its position.
fn point_mass_held_at_rest(scenario: &std::path::Path, out: &std::path::Path, g: f64) -> [f64; 3] {
    let o = run_quiet(scenario, out, &[]);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o).1);
    let (header, rows) = read_csv(&out.join("bodies.csv"));
    let col = |name: &str| header.iter().position(|h| h == name).unwrap();
    let weight = 21244.0 * g;
    let held = [-104170.0, -50000.0, 10000.0 + weight];
    for (c, name) in ["fx", "fy", "fz"].iter().enumerate() {
        let f = rows[0][col(name)];
        assert!(
            (f - held[c]).abs() <= 1e-9 * weight,
            "{name}: {f} against {}",
            held[c]
        );
    }
    for name in ["roll", "pitch", "yaw", "mx", "my", "mz"] {
        assert_eq!(rows[0][col(name)], 0.0, "{name}");
    }
    ["x", "y", "z"].map(|n| rows[0][col(n)])
}

/// A free body is stepped by the Galerkin scheme: an explicit "p2" is
/// refused naming the key (and so are time layers, which it does not
/// take).
#[test]
fn the_p2_scheme_with_a_free_body_is_refused_naming_the_key() {
    let dynamic = "type = \"dynamic\"\ntime_step = 0.05\nduration = 1.0\n";
    expect_input_error(
        "body-p2",
        &moored_buoy("", &format!("{dynamic}time_scheme = \"p2\"")),
        &["analysis.time_scheme", "Galerkin"],
    );
    expect_input_error(
        "body-layers",
        &moored_buoy("", &format!("{dynamic}time_layers = 2")),
        &["analysis.time_layers", "Galerkin"],
    );
}

/// `[[bodies]]` values that are wrong are refused naming the key: a
/// negative mass, an unknown type, moments no body has, a fixed body
/// with a mass, a point on a body that does not exist, its volume in
/// air; and bodies.csv chosen for a system without bodies.
#[test]
fn bad_body_values_are_refused_naming_the_key() {
    let statics = "type = \"static\"";
    let buoy = moored_buoy("", statics);
    let cases: Vec<(&str, String, Vec<&str>)> = vec![
        (
            "negative-mass",
            buoy.replace("mass = 500.0", "mass = -500.0"),
            vec!["bodies[0].mass", "must be > 0"],
        ),
        (
            "unknown-type",
            buoy.replace("type = \"free\"", "type = \"floating\""),
            vec!["bodies[0].type", "\"floating\""],
        ),
        (
            "flat-inertia",
            buoy.replace("[300.0, 300.0, 200.0]", "[100.0, 100.0, 200.0]"),
            vec!["bodies[0].inertia", "less than the sum of the other two"],
        ),
        (
            "fixed-with-mass",
            buoy.replace("type = \"free\"", "type = \"fixed\""),
            vec!["bodies[0].mass", "a fixed body is held at its pose"],
        ),
        (
            "missing-body",
            buoy.replacen("body = 1", "body = 7", 1),
            vec!["points[0].body", "body 7 is not defined"],
        ),
        (
            "volume-in-air",
            buoy.replace("[water]\ndepth = 50.0\ndensity = 1025.0\n", "")
                .replace("cd = 1.2\nca = 1.0\n", ""),
            vec!["bodies[0].volume", "acts in water"],
        ),
        (
            "bodies-csv-without-bodies",
            one_rope("rope", "", ("fixed", [1.0, 0.0, 0.0]), (1, 1.2, 4), "")
                + "[analysis]\ntype = \"static\"\n[output]\nfiles = [\"bodies.csv\"]\n",
            vec!["output.files", "\"bodies.csv\" would stay empty"],
        ),
    ];
    for (name, scenario, needles) in cases {
        assert_ne!(scenario, buoy, "{name}: the change did not apply");
        expect_input_error(name, &scenario, &needles);
    }
}

/// `[output] files = ["bodies.csv"]` writes bodies.csv alone (with
/// summary.json and scenario.toml), the same bytes as a run that writes
/// everything.
#[test]
fn bodies_csv_may_be_chosen_alone_and_is_written_the_same() {
    let everything = run_ok("buoy-all", &moored_buoy("", "type = \"static\""));
    let alone = run_ok(
        "buoy-alone",
        &(moored_buoy("", "type = \"static\"") + "[output]\nfiles = [\"bodies.csv\"]\n"),
    );
    assert_eq!(
        names(&alone),
        ["bodies.csv", "scenario.toml", "summary.json"]
    );
    let read = |d: &Path| std::fs::read(d.join("bodies.csv")).unwrap();
    assert_eq!(read(&everything), read(&alone));
}

/// The deck's body hung from a coupled fairlead instead of a fixed point
/// (the coupling API, docs/interface.md "Coupling"): `initialize` at the
/// fairlead's place solves the same equilibrium as `stancf run` (the
/// lines' force on the fairlead is points.csv's on the fixed point, to
/// 1e-9 of the body's weight: both static solves converge to 1e-10 of
/// the line's scale), and steps with the fairlead at rest keep it (the
/// simulation starts from the equilibrium system, the body where the
/// static solve left it: a start from the deck's pose would put the body
/// 5 cm from its line's end), the force within 1e-6 of the weight over
/// 0.2 s.
#[test]
fn a_coupled_run_of_a_deck_with_a_free_body_starts_from_its_equilibrium() {
    let d = scratch("body-coupled");
    let fixed = write_scenario(&d, "fixed.dat", &body_deck("", "", ""));
    let out = d.join("out");
    let o = run_quiet(&fixed, &out, &[]);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o).1);
    let (_, points) = read_csv(&out.join("points.csv"));
    let at_anchor = three(&points[1], 8);
    let coupled_deck = body_deck("", "", "").replace(" 2        Fixed ", " 2        Coupled ");
    let coupled = write_scenario(&d, "coupled.dat", &coupled_deck);
    let mut c = stancf_cli::coupling::open(&coupled).expect("a coupled system");
    assert_eq!(c.coupled_ids, [2]);
    let weight = 21244.0 * 9.80665;
    let f0 = c
        .handle
        .initialize(&[0.0; 3], None)
        .expect("the equilibrium");
    let err = norm(std::array::from_fn(|k| f0[k] - at_anchor[k]));
    assert!(err < 1e-9 * weight, "{f0:?} against {at_anchor:?}");
    let mut worst = 0.0f64;
    for k in 1..=20 {
        let f = c
            .handle
            .step_to(0.01 * k as f64, &[0.0; 3], None)
            .expect("a step");
        let d = norm(std::array::from_fn(|i| f.last_step[i] - f0[i]));
        worst = worst.max(d);
    }
    eprintln!(
        "the fairlead's force moved by {:.1e} of the weight",
        worst / weight
    );
    assert!(worst < 1e-6 * weight, "{worst:e}");
}

/// MoorDyn's body-drag test (tests/Mooring/body_tests/bodyDrag.txt, its
/// tests/bodies.cpp "Body drag": "drag coefficients don't go negative in
/// certain orientations"): a 10 kg body pitched -90 degrees with CdA 0.1
/// falls on its damped spring line for 5 s from the deck's positions.
/// MoorDyn asks only that it runs; stancf's claim is the physics behind
/// it: the drag never puts energy in (the water's work never rises from
/// one written step to the next, beyond round-off: the drag's power at
/// every time point is -1/2 rho CdA |u|^3 <= 0, summed with positive
/// weights), and the energy less the work of the drag and the line's
/// damping is kept to the step's error (measured 2.8e-6 J while they take
/// 2.5 kJ; asserted 1e-6 of what they take).
#[test]
fn moordyns_body_drag_deck_loses_energy_only_to_its_drag_and_damping() {
    let d = scratch("body-drag");
    let deck = std::fs::read_to_string(repo_file(
        "crates/stancf-cli/tests/fixtures/body-drag-moordyn.txt",
    ))
    .unwrap();
    write_scenario(&d, "bodyDrag.txt", &deck);
    let run = write_scenario(
        &d,
        "run.toml",
        "[system]\nmoordyn = \"bodyDrag.txt\"\n[analysis]\ntype = \"dynamic\"\n\
         initial = \"reference\"\ntime_step = 0.002\nduration = 5.0\n",
    );
    let out = d.join("out");
    let o = run_quiet(&run, &out, &[]);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o).1);
    let (header, rows) = read_csv(&out.join("history.csv"));
    let col = |name: &str| header.iter().position(|h| h == name).unwrap();
    let (total, damping, water) = (col("total"), col("damping_work"), col("water_work"));
    let e0 = rows[0][total];
    let last = rows.last().unwrap();
    let taken = last[damping].abs() + last[water].abs();
    assert!(
        last[water] < -1000.0,
        "the drag takes energy: {}",
        last[water]
    );
    let mut balance = 0.0f64;
    for pair in rows.windows(2) {
        let rise = pair[1][water] - pair[0][water];
        assert!(
            rise <= 1e-12 * taken,
            "the drag put {rise:e} J in at t = {}",
            pair[1][0]
        );
        balance = balance.max((pair[1][total] - pair[1][damping] - pair[1][water] - e0).abs());
    }
    eprintln!("energy balance {balance:.1e} J while drag and damping take {taken:.1} J");
    assert!(balance <= 1e-6 * taken, "{balance:e} of {taken}");
}
