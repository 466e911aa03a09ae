//! MoorDyn decks of rods and bodies alone, without a line (MoorDyn's
//! rod_tests/AddedMass.txt, RodPinnedFloating.txt): the system is its
//! bodies (docs/method.md §15.10).

use crate::common::*;

/// A deck of rods (their ROD TYPES row: 0.5 m across, 100 kg/m, Ca 1)
/// with `rods` as its RODS rows and no line, in 16 m of water.
fn rods_alone(rods: &str) -> String {
    format!(
        "--------------------- MoorDyn Input File ---------------------------------------
Rods alone, no line
---------------------- ROD TYPES -----------------------------------------------
TypeName  Diam   Mass/m    Cd     Ca    CdEnd      CaEnd
(name)    (m)    (kg/m)    (-)    (-)   (-)        (-)
floatRod  0.5    100.0     0.0    1.0   0.0        1.0
---------------------- RODS ----------------------------------------------------
ID     RodType   Attachment  Xa    Ya    Za    Xb    Yb    Zb   NumSegs   RodOutputs
(#)    (name)    (#/key)     (m)   (m)   (m)   (m)   (m)   (m)  (-)       (-)
{rods}---------------------- OPTIONS -------------------------------------------------
0.0005    dtM          - time step
16.0      WtrDpth      - water depth
0         TmaxIC       - max time for ic gen (s)
------------------------- need this line ---------------------------------------
"
    )
}

/// MoorDyn's AddedMass.txt: a buoyant rod 10 m down, lying along y, and
/// nothing else. `check` describes it (no line, one free body, six
/// degrees of freedom); `run` floats it on the surface, its sections'
/// wet fraction its density's ratio to the water's, w / (rho A) = 0.4969:
/// its axis at z = -a x with Phi(x) = 1/2 + (x sqrt(1 - x^2) + asin x) /
/// pi equal to that fraction (B22), 1.23 mm up, to 1e-9 m (the static
/// tolerance of the rod's scale).
#[test]
fn a_deck_of_a_rod_alone_floats_it_at_its_draft() {
    let d = scratch("rod-alone");
    let deck = write_scenario(
        &d,
        "rod.txt",
        &rods_alone("1      floatRod  free        0     -1    -10   0   1.0   -10    4       -\n"),
    );
    let o = stancf(&["check", deck.to_str().unwrap()]);
    let so = text(&o).0;
    assert_eq!(o.status.code(), Some(0), "{}", text(&o).1);
    assert!(
        so.contains("degrees of freedom          6 (0 nodal coordinates of the lines")
            && so.contains("6 per free body (1))"),
        "{so}"
    );
    let out = d.join("out");
    let o = run_quiet(&deck, &out, &[]);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o).1);
    let (header, rows) = read_csv(&out.join("bodies.csv"));
    let z = rows[0][header.iter().position(|h| h == "z").unwrap()];
    let fraction = 100.0 / (1025.0 * std::f64::consts::PI * 0.0625);
    let phi = |x: f64| 0.5 + (x * (1.0 - x * x).sqrt() + x.asin()) / std::f64::consts::PI;
    let (mut low, mut high) = (-1.0f64, 1.0f64);
    for _ in 0..200 {
        let mid = 0.5 * (low + high);
        if phi(mid) < fraction {
            low = mid;
        } else {
            high = mid;
        }
    }
    let want = -0.25 * 0.5 * (low + high);
    eprintln!("the rod alone floats at z = {z:.12} m, Archimedes {want:.12} m");
    assert!((z - want).abs() < 1e-9, "{z} against {want}");
}

/// MoorDyn's RodPinnedFloating.txt's rods (0.25 m across, 10 kg/m), here
/// in water of 1025 kg/m^3 (the deck's is 1000): buoyant, 10 kg/m against
/// the 50.3 kg/m of water they displace, pinned at one end 5 m down,
/// lying along x and along y: their equilibrium stands them upright above
/// their pins, the rod along x pitched by -90 degrees (its end B up) and
/// the one along y rolled by 90, their centres straight above the pin,
/// to the static tolerance.
#[test]
fn a_deck_of_pinned_rods_alone_stands_them_upright() {
    let d = scratch("pinned-rods-alone");
    let deck = rods_alone(
        "1      floatRod  Pinned      0     0     -5    1     0     -5     1       -\n\
         2      floatRod  Pinned      0     0     -5    0     1     -5     1       -\n",
    )
    .replace("0.5    100.0", "0.25   10.0");
    let file = write_scenario(&d, "pinned.txt", &deck);
    let out = d.join("out");
    let o = run_quiet(&file, &out, &[]);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o).1);
    let (header, rows) = read_csv(&out.join("bodies.csv"));
    let col = |name: &str| header.iter().position(|h| h == name).unwrap();
    let (x_rod, y_rod) = (&rows[0], &rows[1]);
    eprintln!(
        "pinned rods: pitch {} and roll {} degrees",
        x_rod[col("pitch")],
        y_rod[col("roll")]
    );
    assert!((x_rod[col("pitch")] + 90.0).abs() < 1e-6, "{x_rod:?}");
    assert!((y_rod[col("roll")] - 90.0).abs() < 1e-6, "{y_rod:?}");
    for r in [x_rod, y_rod] {
        assert_eq!([r[col("x")], r[col("y")], r[col("z")]], [0.0, 0.0, -5.0]);
    }
}

/// The AddedMass rod stepped from a scenario that takes its deck
/// (`system.moordyn`, a dynamic run from the deck's pose): released at
/// rest 10 m down it rises at a = (rho V - m) g / (m + rho V Ca) (MoorDyn:
/// "~2.3 seconds to get to z = -1"), a parabola the Galerkin step holds
/// exactly: its rise in 1 s to 1e-9 m.
#[test]
fn a_rod_alone_rises_from_a_scenario_that_takes_its_deck() {
    let d = scratch("rod-alone-rises");
    let sc = rising_rod(&d, "type = \"dynamic\"\ntime_step = 0.01\nduration = 1.0\n");
    let out = d.join("out");
    let o = run_quiet(&sc, &out, &[]);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o).1);
    let (t, rise, want, _) = rise_and_closed_form(&out);
    eprintln!("the rod alone rises {rise:.9} m in {t} s, closed form {want:.9} m");
    assert_eq!(t, 1.0);
    assert!((rise - want).abs() < 1e-9, "{rise} against {want}");
}

/// The AddedMass rod's deck and a scenario taking it, released from the
/// deck's pose (`initial = "reference"`) with `analysis` in its
/// `[analysis]`.
fn rising_rod(d: &std::path::Path, analysis: &str) -> std::path::PathBuf {
    write_scenario(
        d,
        "rod.txt",
        &rods_alone("1      floatRod  free        0     -1    -10   0   1.0   -10    4       -\n"),
    );
    write_scenario(
        d,
        "rises.toml",
        &format!(
            "[system]\nmoordyn = \"rod.txt\"\n[analysis]\ninitial = \"reference\"\n{analysis}"
        ),
    )
}

/// The rising rod's last time, its rise since the start and the closed
/// form's, 1/2 a t^2 with a = (rho V - m) g / (m + rho V Ca), from
/// bodies.csv in `out`; and the rows written.
fn rise_and_closed_form(out: &std::path::Path) -> (f64, f64, f64, usize) {
    let (header, rows) = read_csv(&out.join("bodies.csv"));
    let col = |n: &str| header.iter().position(|h| h == n).unwrap();
    let last = rows.last().unwrap();
    let (volume, mass) = (std::f64::consts::PI * 0.0625 * 2.0, 200.0);
    let accel = (1025.0 * volume - mass) * 9.80665 / (mass + 1025.0 * volume);
    let t = last[col("t")];
    let rise = last[col("z")] - rows[0][col("z")];
    (t, rise, 0.5 * accel * t * t, rows.len())
}

/// A dynamic scenario (its `type` left to its default) that takes a deck
/// and gives no `time_step` steps at the deck's (its dtM, 0.5 ms here:
/// what a coupled run of the deck takes), saying so in `check`; the rod
/// rises as the closed form says.
#[test]
fn a_scenario_taking_a_deck_steps_at_the_decks_step_by_default() {
    let d = scratch("deck-step-default");
    let sc = rising_rod(&d, "duration = 0.05\n");
    let o = stancf(&["check", sc.to_str().unwrap()]);
    let (so, se) = text(&o);
    assert_eq!(o.status.code(), Some(0), "{se}");
    assert!(
        so.contains("note: analysis.time_step: the deck's step, 0.0005 s")
            && so.contains("in steps of 0.0005 s"),
        "{so}\n{se}"
    );
    let out = d.join("out");
    let o = run_quiet(&sc, &out, &[]);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o).1);
    let (_, rise, want, rows) = rise_and_closed_form(&out);
    assert_eq!(rows, 101, "one row per step and the start");
    assert!((rise - want).abs() < 1e-12, "{rise} against {want}");
}

/// A deck's rod that sinks (OpenFAST's md_vertical: heavier than the
/// water it displaces, no line) has no static equilibrium. With MoorDyn's
/// initial conditions asked for (TmaxIC above 0), `check` and `run` of
/// the deck alone (a static run) refuse it naming its row and the rod,
/// not the library's body, and say how to run it dynamically. With
/// TmaxIC 0, as md_vertical has it, MoorDyn's `Init` generates none and
/// leaves the rod where the deck puts it: the deck alone passes `check`
/// and its run writes that start at t = 0, saying why there is no
/// equilibrium (docs/method.md §13.7). Run dynamically, it sinks as a
/// body of its mass and added mass (to 1e-6 m).
#[test]
fn a_decks_sinking_rod_is_refused_naming_its_row() {
    let heavy = rods_alone("1 floatRod Free 0 0 -10 0 1 -10 2 -\n")
        .replace("floatRod  0.5    100.0 ", "floatRod  0.5    300.0 ");
    let row = heavy
        .lines()
        .position(|l| l.starts_with("1 floatRod"))
        .unwrap()
        + 1;
    let named = format!("bad.txt: line {row}: rod 1: floats on no line and sinks");
    let d = scratch("rod-sinks");
    let with_ic = heavy.replace("0         TmaxIC", "60        TmaxIC");
    let deck = write_scenario(&d, "bad.txt", &with_ic);
    let route =
        "take it in a scenario, [system] moordyn = \"bad.txt\" with [analysis] type = \"dynamic\"";
    refused_by_check_and_run(&deck, &d.join("never"), &[&named, route], &[]);
    // Without initial conditions: MoorDyn's start.
    write_scenario(&d, "bad.txt", &heavy);
    let o = stancf(&["check", deck.to_str().unwrap()]);
    let (so, se) = text(&o);
    assert_eq!(o.status.code(), Some(0), "{se}");
    assert!(
        so.contains("MoorDyn's start") && so.contains("rod 1: floats on no line and sinks"),
        "{so}"
    );
    let start = d.join("start");
    let o = run_quiet(&deck, &start, &[]);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o).1);
    let summary = read_json(&start.join("summary.json"));
    let why = summary["no_static_equilibrium"].as_str().unwrap();
    assert!(
        why.starts_with(&format!("line {row}: rod 1: floats on no line")),
        "{why}"
    );
    let (header, rows) = read_csv(&start.join("bodies.csv"));
    let col = |n: &str| header.iter().position(|h| h == n).unwrap();
    assert_eq!(rows.len(), 1);
    assert_eq!((rows[0][col("t")], rows[0][col("z")]), (0.0, -10.0));
    // A deck without dtM (and no line to take MoorDyn's step from) writes
    // the same start: the start is never stepped.
    let no_step = heavy.replace("0.0005    dtM          - time step\n", "");
    assert_ne!(no_step, heavy);
    write_scenario(&d, "bad.txt", &no_step);
    let o = run_quiet(&deck, &d.join("start-no-step"), &[]);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o).1);
    // Taken so, it sinks.
    let sc = write_scenario(
        &d,
        "sink.toml",
        "[system]\nmoordyn = \"bad.txt\"\n[analysis]\ntype = \"dynamic\"\ninitial = \"reference\"\n\
         time_step = 0.05\nduration = 1.0\n",
    );
    let out = d.join("out");
    let o = run_quiet(&sc, &out, &[]);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o).1);
    let (header, rows) = read_csv(&out.join("bodies.csv"));
    let z = header.iter().position(|h| h == "z").unwrap();
    // Level, it sinks at a = (m - rho A) g / (m + Ca rho A) (no drag:
    // Cd 0), which the Galerkin step integrates exactly.
    let (m, rho_a) = (300.0, 1025.0 * std::f64::consts::PI * 0.25 * 0.25);
    let a = (m - rho_a) * 9.80665 / (m + rho_a);
    let t = header.iter().position(|h| h == "t").unwrap();
    for r in &rows {
        let want = -10.0 - 0.5 * a * r[t] * r[t];
        assert!(
            (r[z] - want).abs() < 1e-6,
            "t {}: z {} against {want}",
            r[t],
            r[z]
        );
    }
}

/// MoorDyn's body_tests/orbitalBody.txt: body 1 has no mass of its own
/// and two 20 kg point masses on a line (its moment about the line is
/// completed, docs/method.md (B2a)), body 2 a rod; no gravity, and the
/// bodies above the water. Nothing holds or loads the bodies: every pose
/// is an equilibrium, and the static solve holds each where the deck
/// puts it (§15.8), its mooring stiffness zero (nothing is attached);
/// `check` describes the deck, `run` (a deck alone, static) and a
/// dynamic run from the deck's pose leave the bodies where they are.
#[test]
fn moordyns_orbital_body_deck_is_read_and_runs_from_its_pose() {
    let d = scratch("orbital");
    let deck = write_scenario(
        &d,
        "orbitalBody.txt",
        "--------------------- MoorDyn Input File -------------------------------------------------------
Testing body kinematics when body origin != COM
---------------------- ROD TYPES ------------------------------------
TypeName      Diam     Mass/m    Cd     Ca      CdEnd    CaEnd
(name)        (m)      (kg/m)    (-)    (-)     (-)      (-)
buoy          1        1.0e1     0.0    0.0     0.0      0.0
---------------------------- BODIES -----------------------------------------------------
ID      Attachment  X0     Y0      Z0      r0        p0     y0      Mass  CG*        I*        Volume   CdA*   Ca
(#)     (-)         (m)    (m)     (m)     (deg)     (deg)  (deg)   (kg)  (m)        (kg-m^2)  (m^3)    (m^2)  (-)
1       free        0      10      20      0.0       0      0       0     0|-10|0    0         0        0      0
2       free        0      10      20      0.0       0      0       0     0|-10|0    0         0        0      0
----------------------- POINTS ----------------------------------------------
Node      Type       X         Y          Z        M        V          CdA    CA
(-)       (-)        (m)       (m)        (m)      (kg)     (m^3)      (m^2)  (-)
1         Body1      0.0       -10        -2       20.0     0          0      0
2         Body1      0.0       -10        2        20.0     0          0      0
---------------------- RODS ----------------------------------------
ID     RodType   Attachment  Xa    Ya    Za    Xb    Yb     Zb    NumSegs   RodOutputs
(#)    (name)    (#/key)     (m)   (m)   (m)   (m)   (m)    (m)   (-)       (-)
1      buoy      Body2       0     -10   -2    0     -10.0  2     10        -
-------------------------- SOLVER OPTIONS---------------------------------------------------
0.0      g            - No gravity
1e-3     dtM          - time step to use in mooring integration
70       WtrDpth      - water depth
0.0      TmaxIC       - threshold for IC convergence
--------------------------- need this line -------------------------------------------------
",
    );
    let o = stancf(&["check", deck.to_str().unwrap()]);
    let so = text(&o).0;
    assert_eq!(o.status.code(), Some(0), "{}", text(&o).1);
    assert!(
        so.contains("6 per free body (2))")
            && so.contains("point 2                     on free body 1"),
        "{so}"
    );
    let statics = d.join("statics");
    let o = run_quiet(&deck, &statics, &[]);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o).1);
    let (header, rows) = read_csv(&statics.join("bodies.csv"));
    let col = |name: &str| header.iter().position(|h| h == name).unwrap();
    for row in &rows {
        for (name, want) in [("x", 0.0), ("y", 10.0), ("z", 20.0), ("pitch", 0.0)] {
            assert!(
                (row[col(name)] - want).abs() <= 1e-12,
                "{name}: {}",
                row[col(name)]
            );
        }
    }
    // Nothing is attached to the bodies: their mooring stiffness is zero.
    let stiffness = std::fs::read_to_string(statics.join("stiffness.csv")).unwrap();
    let rows: Vec<&str> = stiffness.lines().skip(1).collect();
    assert_eq!(rows.len(), 12, "{stiffness}");
    for row in rows {
        let values = row.split(',').skip(2).map(|v| v.parse::<f64>().unwrap());
        assert!(values.into_iter().all(|v| v == 0.0), "{row}");
    }
    let scenario = write_scenario(
        &d,
        "orbit.toml",
        "[system]\nmoordyn = \"orbitalBody.txt\"\n[analysis]\ntype = \"dynamic\"\n\
         initial = \"reference\"\nduration = 0.01\n",
    );
    let out = d.join("out");
    let o = run_quiet(&scenario, &out, &[]);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o).1);
    let (header, rows) = read_csv(&out.join("bodies.csv"));
    let col = |name: &str| header.iter().position(|h| h == name).unwrap();
    let last = &rows[rows.len() - 1];
    assert!(
        (last[col("t")] - 0.01).abs() <= 1e-12,
        "t = {}",
        last[col("t")]
    );
    for (name, want) in [("x", 0.0), ("y", 10.0), ("z", 20.0), ("pitch", 0.0)] {
        assert!(
            (last[col(name)] - want).abs() <= 1e-12,
            "{name}: {}",
            last[col(name)]
        );
    }
}
