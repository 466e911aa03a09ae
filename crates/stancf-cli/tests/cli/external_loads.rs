//! MoorDyn-F's EXTERNAL LOADS (docs/method.md §15.21, (B42)-(B43)): a
//! constant force and linear and quadratic damping on free bodies and
//! points, from a deck and from TOML, against the closed forms of a
//! pushed, damped mass.

use crate::common::*;

/// Two neutrally buoyant bodies (1025 kg, 1 m^3, no drag) and a
/// neutrally buoyant point (1025 kg, 1 m^3) on a nearly massless spring
/// line (EA/L = 1025 N/m, 1e-3 kg/m, as dense as the water), each pushed
/// by 1025 N: body 1 along x with the quadratic damping 1025 N s^2/m^2
/// (global axes), body 2, yawed 90 degrees, along its own x (global y)
/// with the linear damping 1025 N s/m in its axes, the point along x
/// with the linear damping 410 N s/m.
const DECK: &str = "Two bodies and a point pushed and damped
--- LINE TYPES ---
TypeName Diam MassDenInAir EA BA/-zeta EI Can Cat Cdn Cdt
(-) (m) (kg/m) (N) (Pa-s/-) (n-m^2) (-) (-) (-) (-)
spring 1.1145335e-3 1.0e-3 10250.0 0.0 0.0 0.0 0.0 0.0 0.0
--- BODIES ---
ID Attachment X0 Y0 Z0 r0 p0 y0 Mass CG* I* Volume CdA* Ca
(#) (-) (m) (m) (m) (deg) (deg) (deg) (kg) (m) (kg-m^2) (m^3) (m^2) (-)
1 free 0 0 -10 0 0 0 1025 0 100 1 0 0
2 free 0 20 -10 0 0 90 1025 0 100 1 0 0
--- POINTS ---
ID Attachment X Y Z M V CdA CA
(-) (-) (m) (m) (m) (kg) (m^3) (m^2) (-)
1 Free 0.0 40 -10 1025 1 0 0
2 Fixed -10.0 40 -10 0 0 0 0
--- LINES ---
ID LineType AttachA AttachB UnstrLen NumSegs LineOutputs
(-) (-) (-) (-) (m) (-) (-)
1 spring 2 1 10.0 4 -
--- EXTERNAL LOADS ---
ID Object Fext Blin Bquad CSys
(#) (name) (N) (Ns/m) (Ns^2/m^2) (-)
1 Body1 1025|0|0 0|0|0 1025|0|0 G
2 Body2 1025|0|0 1025|0|0 0|0|0 L
3 Point1 1025|0|0 410|0|0 0|0|0 -
--- OPTIONS ---
0.01 dtM
100 WtrDpth
1025 WtrDnsty
--- need this line ---
";

/// A CSV file's header and rows.
type Table = (Vec<String>, Vec<Vec<f64>>);

/// A dynamic run of 3 s in steps of 0.05 s of `deck` from the deck's
/// positions; bodies.csv's and points.csv's (header, rows).
fn run_deck(name: &str, deck: &str) -> (Table, Table) {
    let d = scratch(name);
    std::fs::write(d.join("deck.txt"), deck).unwrap();
    let path = write_scenario(
        &d,
        "run.toml",
        "title = \"external loads\"\n[system]\nmoordyn = \"deck.txt\"\n\
         [analysis]\ntype = \"dynamic\"\ninitial = \"reference\"\ntime_step = 0.05\nduration = 3.0\n",
    );
    let checked = stancf(&["check", path.to_str().unwrap()]);
    assert_eq!(checked.status.code(), Some(0), "{}", text(&checked).1);
    let notes = text(&checked).0 + &text(&checked).1;
    assert!(
        notes.contains("external load 2 (MoorDyn-F's EXTERNAL LOADS) on body 2, at its reference point along the body's axes"),
        "{notes}"
    );
    let out = d.join("out");
    let o = run_quiet(&path, &out, &[]);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o).1);
    (
        read_csv(&out.join("bodies.csv")),
        read_csv(&out.join("points.csv")),
    )
}

/// The value of `column` in the row of object `id` at time `t`.
fn at(table: &Table, id_column: &str, id: f64, t: f64, column: &str) -> f64 {
    let col = |n: &str| table.0.iter().position(|c| c == n).unwrap();
    let row = table
        .1
        .iter()
        .find(|r| r[col(id_column)] == id && (r[col("t")] - t).abs() < 1e-9)
        .unwrap();
    row[col(column)]
}

/// Closed forms, pushed by F = 1025 N from rest (m = 1025 kg):
/// - quadratic damping b2 = 1025: v = v_t tanh(t / tau), x = v_t tau ln
///   cosh(t / tau), v_t = sqrt(F / b2) = 1 m/s, tau = m / sqrt(F b2) = 1 s;
/// - linear damping b1 = 1025: v = v_t (1 - exp(-t / tau)), v_t = F / b1,
///   tau = m / b1 = 1 s (body 2's own x axis is the global y);
/// - the point on its spring (k = 1025 N/m, omega = 1 rad/s, zeta = 0.2):
///   x = F/k (1 - exp(-zeta t) (cos w_d t + zeta / sqrt(1 - zeta^2) sin
///   w_d t)), w_d = sqrt(1 - zeta^2).
///
/// The bodies to 1e-9 (the Galerkin step's error at dt = tau / 20 is
/// below 1e-12, measured 1.2e-13); the point to 2e-5 m and m/s, what its
/// spring's own mass (0.01 kg, a third of it moving with the point: 3e-6
/// of its mass, a phase of 5e-6 rad after 3 s) leaves.
#[test]
fn moordyn_f_external_loads_push_and_damp_bodies_and_points_as_their_closed_forms() {
    let (bodies, points) = run_deck("external-loads-deck", DECK);
    let t = 3.0f64;
    let body = |id: f64, c: &str| at(&bodies, "body", id, t, c);
    let checks = [
        ("body 1 vx", body(1.0, "vx"), t.tanh(), 1e-9),
        ("body 1 x", body(1.0, "x"), t.cosh().ln(), 1e-9),
        ("body 2 vy", body(2.0, "vy"), 1.0 - (-t).exp(), 1e-9),
        (
            "body 2 y",
            body(2.0, "y"),
            20.0 + t - (1.0 - (-t).exp()),
            1e-9,
        ),
        ("body 2 vx", body(2.0, "vx"), 0.0, 1e-9),
    ];
    let (zeta, wd) = (0.2f64, (1.0f64 - 0.04).sqrt());
    let decay = (-zeta * t).exp();
    let x = 1.0 - decay * ((wd * t).cos() + zeta / wd * (wd * t).sin());
    let v = decay / wd * (wd * t).sin();
    let point = |c: &str| at(&points, "point", 1.0, t, c);
    let point_checks = [
        ("point 1 x", point("x"), x, 2e-5),
        ("point 1 vx", point("vx"), v, 2e-5),
    ];
    for (what, got, want, tol) in checks.into_iter().chain(point_checks) {
        eprintln!("{what}: {got} against {want}");
        assert!((got - want).abs() < tol, "{what}: {got} against {want}");
    }
}

/// The same loads from TOML: a body in air (no [water]) with
/// `force`, `damping_quadratic`, and a second one turned 90 degrees with
/// `body_force` and `body_damping_linear`, both 1025 kg under g: their
/// horizontal motion is the closed forms' above (g = 9.81 pulls down
/// alone, no buoyancy in air).
#[test]
fn toml_bodies_take_a_body_force_and_damping_in_air() {
    let d = scratch("external-loads-toml");
    let body = |id: usize, y: f64, keys: &str| {
        format!(
            "[[bodies]]\nid = {id}\ntype = \"free\"\nposition = [0.0, {y}, -10.0]\n\
             angles = [0.0, 0.0, {}]\nmass = 1025.0\ninertia = [100.0, 100.0, 100.0]\n{keys}\n",
            if id == 2 { 90.0 } else { 0.0 }
        )
    };
    let sc = format!(
        "title = \"damped bodies in air\"\n{}{}\
         [analysis]\ntype = \"dynamic\"\ninitial = \"reference\"\ntime_step = 0.05\nduration = 3.0\n",
        body(1, 0.0, "force = [1025.0, 0.0, 0.0]\ndamping_quadratic = [1025.0, 0.0, 0.0]"),
        body(2, 20.0, "body_force = [1025.0, 0.0, 0.0]\nbody_damping_linear = [1025.0, 0.0, 0.0]"),
    );
    let path = write_scenario(&d, "air.toml", &sc);
    let out = d.join("out");
    let o = run_quiet(&path, &out, &[]);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o).1);
    let bodies = read_csv(&out.join("bodies.csv"));
    let t = 3.0f64;
    let b = |id: f64, c: &str| at(&bodies, "body", id, t, c);
    for (what, got, want) in [
        ("body 1 vx", b(1.0, "vx"), t.tanh()),
        ("body 2 vy", b(2.0, "vy"), 1.0 - (-t).exp()),
        ("body 1 vz", b(1.0, "vz"), -9.81 * t),
    ] {
        assert!((got - want).abs() < 1e-9, "{what}: {got} against {want}");
    }
}

/// What MoorDyn-F's EXTERNAL LOADS can say that stancf does not build,
/// or that is wrong, is refused naming the row: a rod, a fixed point, a
/// coupled body, a body's CSys other than G or L, two values where three
/// are read, a negative damping, an object the deck does not have.
#[test]
fn external_loads_stancf_does_not_build_are_refused_naming_the_row() {
    let d = scratch("external-loads-refused");
    let row = |r: &str| DECK.replace("3 Point1 1025|0|0 410|0|0 0|0|0 -", r);
    let coupled = DECK
        .replace("2 free 0 20 -10 0 0 90", "2 coupled 0 20 -10 0 0 90")
        .replace(
            "2 Body2 1025|0|0 1025|0|0 0|0|0 L",
            "2 Body2 1|0|0 0|0|0 0|0|0 G",
        );
    let cases = [
        (
            "rod",
            row("3 Rod1 1|0|0 0|0 0|0 -"),
            "line 25",
            "external loads on a rod are not supported",
        ),
        (
            "fixed-point",
            row("3 Point2 1|0|0 0|0|0 0|0|0 -"),
            "line 25",
            "point 2 is not free",
        ),
        (
            "coupled-body",
            coupled,
            "line 24",
            "body 2 is coupled; external loads act on a free body only",
        ),
        (
            "csys",
            row("3 Body1 1|0|0 0|0|0 0|0|0 X"),
            "line 25",
            "on body 1 it is G (global axes) or L",
        ),
        (
            "two-values",
            row("3 Point1 1|0 0|0|0 0|0|0 -"),
            "line 25",
            "has 2 bar-separated values",
        ),
        (
            "negative",
            row("3 Point1 1|0|0 -4|0|0 0|0|0 -"),
            "line 25",
            "its values must be zero or positive",
        ),
        (
            "missing",
            row("3 Body7 1|0|0 0|0|0 0|0|0 G"),
            "line 25",
            "the deck has no body 7",
        ),
    ];
    for (name, deck, line, needle) in cases {
        let path = d.join(format!("{name}.txt"));
        std::fs::write(&path, deck).unwrap();
        refused_by_check_and_run(
            &path,
            &d.join(format!("never-{name}")),
            &[line, needle],
            &[],
        );
    }
}

/// A static solve holds a body-fixed force (B43): a 1000 kg body hung
/// level by three equal ropes from the corners of a triangle about its
/// centre, pushed by 3000 N along its own x, swings aside without turning
/// (the three ropes stay parallel and equally taut, so their moment about
/// the centre is zero and the pose R = I is an equilibrium), and so rests
/// where the same force given in global axes puts it (to the solve's
/// tolerance, bound 1e-8 m); without the force it hangs below its ropes.
#[test]
fn a_static_solve_holds_a_body_fixed_force_as_the_same_global_force() {
    let d = scratch("external-loads-static");
    let scenario = |keys: &str| weight_on_three_ropes(0.05, 1.0e6, keys);
    let rest = |name: &str, keys: &str| -> [f64; 6] {
        let path = write_scenario(&d, &format!("{name}.toml"), &scenario(keys));
        let out = d.join(format!("out-{name}"));
        let o = run_quiet(&path, &out, &[]);
        assert_eq!(o.status.code(), Some(0), "{}", text(&o).1);
        let table = read_csv(&out.join("bodies.csv"));
        ["x", "y", "z", "roll", "pitch", "yaw"].map(|c| at(&table, "body", 1.0, 1.0, c))
    };
    let fixed_in_body = rest("body-force", "body_force = [3000.0, 0.0, 0.0]");
    let global = rest("global-force", "force = [3000.0, 0.0, 0.0]");
    let plumb = rest("no-force", "");
    eprintln!("body-fixed {fixed_in_body:?}, global {global:?}, none {plumb:?}");
    for k in 0..6 {
        assert!(
            (fixed_in_body[k] - global[k]).abs() < 1e-8,
            "{fixed_in_body:?} {global:?}"
        );
    }
    assert!(
        fixed_in_body[0] > 1.0 && plumb[0].abs() < 1e-9,
        "{fixed_in_body:?} {plumb:?}"
    );
}
