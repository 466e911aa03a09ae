//! Rods in systems (docs/interface.md, "Rods"): a TOML free rod rising
//! in still water as a body of its mass and added mass, MoorDyn decks'
//! free, body and zero-length rods with lines at their ends held at the
//! balance of their weights, what `check` and summary.json say of them,
//! and what is not built refused naming the key or the deck's line.

use crate::common::*;
use std::f64::consts::PI;

/// A horizontal free rod (MoorDyn's `rod_tests/AddedMass.txt`: 2 m
/// long, 0.5 m across, 100 kg/m, Ca 1, every other coefficient 0) at
/// z = -10 m in still water, with a light thread (1 m, 1 mm, 0.01 kg/m,
/// no drag or added mass) hanging from each end; `analysis` the
/// `[analysis]` body.
fn rising_rod(analysis: &str) -> String {
    format!(
        "title = \"rising rod\"\n[water]\ndepth = 50.0\ndensity = 1025.0\n\
         [[line_types]]\nname = \"thread\"\ndiameter = 0.001\nmass_per_length = 0.01\nea = 1.0e3\n\
         [[rod_types]]\nname = \"can\"\ndiameter = 0.5\nmass_per_length = 100.0\nca = 1.0\n\
         [[rods]]\nid = 7\ntype = \"free\"\nrod_type = \"can\"\nend_a = [-1.0, 0.0, -10.0]\n\
         end_b = [1.0, 0.0, -10.0]\nsegments = 4\n\
         [[points]]\nid = 1\ntype = \"rod\"\nrod = 7\nend = \"A\"\n\
         [[points]]\nid = 2\ntype = \"rod\"\nrod = 7\nend = \"B\"\n\
         [[lines]]\nid = 1\ntype = \"thread\"\nlength = 1.0\nelements = 2\na = 1\n\
         [[lines]]\nid = 2\ntype = \"thread\"\nlength = 1.0\nelements = 2\na = 2\n\
         [analysis]\n{analysis}\n"
    )
}

/// The rising rod: MoorDyn's analytic z(t) = z0 + a t^2 / 2 with
/// a = (rho V - m) g / (m + Ca rho V), here with the threads, which only
/// translate with it (their mass m_l and volume V_l, no added mass):
/// a = (rho V - m + rho V_l - m_l) g / (m + Ca rho V + m_l). Across its
/// axis the rod's added mass is Ca rho V and its caps carry none; the
/// Galerkin step integrates a constant acceleration exactly. What is
/// left is the threads' axial ringing (they start unstretched): their
/// force varies by a part of their 0.18 N wet weight against the rod's
/// 1987 N lift, and averages out; measured 2.7e-9 m of the 1.65 m rise.
/// The claim is 1e-6 m: leaving the threads out of a moves z(1) by
/// 2e-4 m, and a wrong added mass (Ca on the caps, or none) by far more.
/// The rod does not turn, and summary.json names its body.
#[test]
fn a_free_rod_rises_in_still_water_as_a_body_of_its_mass_and_added_mass() {
    let d = scratch("rising-rod");
    let sc = write_scenario(
        &d,
        "rod.toml",
        &rising_rod("type = \"dynamic\"\ntime_step = 0.01\nduration = 1.0"),
    );
    let out = d.join("out");
    let o = run_quiet(&sc, &out, &[]);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o).1);
    let (rho, g) = (1025.0, 9.81);
    let (m, v) = (200.0, PI * 0.25 * 0.25 * 2.0);
    let (m_l, v_l) = (2.0 * 0.01, 2.0 * PI * 0.0005 * 0.0005);
    let a = (rho * v - m + rho * v_l - m_l) * g / (m + rho * v + m_l);
    let (header, rows) = read_csv(&out.join("bodies.csv"));
    let col = |name: &str| header.iter().position(|h| h == name).unwrap();
    assert_eq!(rows.len(), 101);
    for r in &rows {
        let t = r[col("t")];
        let want = -10.0 + 0.5 * a * t * t;
        assert!(
            (r[col("z")] - want).abs() < 1e-6,
            "t = {t}: z {} against {want}",
            r[col("z")]
        );
        assert!(
            (r[col("vz")] - a * t).abs() < 1e-5,
            "t = {t}: vz {}",
            r[col("vz")]
        );
        for c in ["x", "y", "roll", "pitch", "yaw"] {
            let want = if c == "x" { -1.0 } else { 0.0 };
            assert!(
                (r[col(c)] - want).abs() < 1e-9,
                "t = {t}: {c} {}",
                r[col(c)]
            );
        }
    }
    let s = read_json(&out.join("summary.json"));
    let rods = s["rods"].as_array().unwrap();
    assert_eq!(rods.len(), 1);
    assert_eq!(rods[0]["id"], 7);
    assert_eq!(rods[0]["type"], "free");
    assert_eq!(rods[0]["body"], 0);
    assert_eq!(rods[0]["body_id"], 1);
    assert_eq!(rods[0]["points"], serde_json::json!([1, 2]));
    assert_eq!(s["bodies"][0]["id"], 1);
    // check lists the rod: its holder, length, mass and water.
    let o = stancf(&["check", sc.to_str().unwrap()]);
    let (so, se) = text(&o);
    assert_eq!(o.status.code(), Some(0), "{se}");
    let rod_line = so.lines().find(|l| l.starts_with("rod 7")).expect("rod 7");
    for w in [
        "free, body 1",
        "length 2 m",
        "mass 200 kg",
        "submerged",
        "point 1 at A",
    ] {
        assert!(rod_line.contains(w), "{w}: {rod_line}");
    }
    assert!(
        so.lines()
            .any(|l| l.starts_with("rods") && l.ends_with(" 1")),
        "{so}"
    );
}

/// MoorDyn's `tests/Mooring/RodHanging.txt` (examples/): a free rod of
/// 20 m, 77.7 kg/m and 0.25 m at z = -75 m hung by two ropes from the
/// surface at x = -450 and 450 m. At the static equilibrium the ropes
/// hold its wet weight, (w L - rho pi d^2/4 L) g with MoorDyn's g and
/// rho, at its middle, 10 m from its reference point end A: force and
/// moment to the static tolerance (1e-6 of the weight here), and it does
/// not turn (MoorDyn's test: it "should not rotate at all").
#[test]
fn moordyns_hanging_rod_hangs_level_at_the_balance_of_its_wet_weight() {
    let d = scratch("rod-hanging");
    let deck = repo_file("examples/rod-hanging-moordyn.txt");
    let out = d.join("out");
    let o = run_quiet(&deck, &out, &[]);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o).1);
    let (header, rows) = read_csv(&out.join("bodies.csv"));
    let col = |name: &str| header.iter().position(|h| h == name).unwrap();
    let r = rows.last().unwrap();
    let (l, dia, w) = (20.0, 0.25, 77.7066);
    let wet = (w * l - 1025.0 * PI * dia * dia / 4.0 * l) * 9.80665;
    assert!(
        (r[col("fz")] - wet).abs() < 1e-6 * wet,
        "fz {} against {wet}",
        r[col("fz")]
    );
    assert!(r[col("fx")].abs() < 1e-6 * wet, "fx {}", r[col("fx")]);
    assert!(
        (r[col("my")] + 10.0 * wet).abs() < 1e-5 * wet,
        "my {}",
        r[col("my")]
    );
    for c in ["roll", "pitch", "yaw"] {
        assert!(r[col(c)].abs() < 1e-6, "{c} {}", r[col(c)]);
    }
    let s = read_json(&out.join("summary.json"));
    assert_eq!(s["rods"][0]["type"], "free");
    // The points at R1A and R1B come after the deck's two.
    assert_eq!(s["rods"][0]["points"], serde_json::json!([3, 4]));
}

/// A free body carrying a rod (`Body1`, 4 m, 100 kg/m, 0.5 m) hung from
/// the surface by lines at the rod's ends, one line running through a
/// free rod of zero length (`NumSegs` 0, a point); `rod_outputs` the
/// zero-length rod's RodOutputs, `ei` the ropes' EI.
fn body_rod_deck(rod_outputs: &str, ei: &str) -> String {
    format!(
        "--------------------- MoorDyn Input File ---------------------------------------
A free body carrying a rod, hung by lines at the rod's ends
----------------------- LINE TYPES ------------------------------------------
TypeName Diam  Mass/m   EA         BA/-zeta EI      Cd  Ca  CdAx CaAx
(name)   (m)   (kg/m)   (N)        (N-s/-)  (N-m^2) (-) (-) (-)  (-)
rope     0.05  10.0     1.0E8      -0.5     {ei}    1.2 1.0 0.1  0.0
---------------------- ROD TYPES -----------------------------------------------
TypeName      Diam     Mass/m    Cd     Ca      CdEnd    CaEnd
(name)        (m)      (kg/m)    (-)    (-)     (-)      (-)
can           0.5      100       1.2    1.0     0.6      0.5
conn          0.1      5         1.0    1.0     1.0      1.0
---------------------------- BODIES -----------------------------------------------------
ID   Attachment  X0     Y0    Z0     r0      p0     y0     Mass  CG*   I*      Volume   CdA*    Ca
(#)     (-)      (m)    (m)   (m)   (deg)   (deg)  (deg)   (kg)  (m)  (kg-m^2)  (m^3)   (m^2)   (-)
1      Free      0.0    0    -20.0   0       0      0      1000   0    1000     0        0       0
---------------------- RODS ----------------------------------------------------
ID   RodType   Attachment  Xa    Ya    Za    Xb    Yb    Zb   NumSegs RodOutputs
(#)  (name)     (#/key)    (m)   (m)   (m)   (m)   (m)   (m)  (-)     (-)
1    can       Body1       -2    0     0     2     0     0    4       -
2    conn      Free        15    0     -10   15    0     -10  0       {rod_outputs}
---------------------- POINTS --------------------------------------------------
ID    Type      X       Y       Z       Mass   Volume  CdA    Ca
(#)   (-)       (m)     (m)     (m)     (kg)   (m^3)   (m^2)  (-)
1     Fixed     -30     0       0       0      0       0      0
2     Fixed      30     0       0       0      0       0      0
---------------------- LINES ---------------------------------------------------
ID   LineType   AttachA  AttachB  UnstrLen  NumSegs  LineOutputs
(#)   (name)     (#)      (#)       (m)       (-)     (-)
1     rope       1        R1A       36        12      -
2     rope       2        R2A       18        6       -
3     rope       r2b      Rod1B     20        6       -
---------------------- OPTIONS -------------------------------------------------
0.002         dtM                  time step (s)
100           WtrDpth              water depth (m)
------------------------- need this line --------------------------------------
"
    )
}

/// The body and its rod settle where the lines hold their weight less
/// the rod's buoyancy, (1000 + 400 - 1025 pi 0.25^2 4) g, both acting at
/// the body's reference point (its centre of mass and the rod's middle):
/// the lines' force to the static tolerance, and no moment about it.
/// The zero-length rod is a free point joining lines 2 and 3; check lists
/// both rods and notes the per-rod file that is not written.
#[test]
fn a_deck_with_a_rod_on_a_body_and_lines_at_its_ends_runs_to_the_balance() {
    let d = scratch("body-rod");
    let deck = write_scenario(&d, "body-rod.txt", &body_rod_deck("p", "0"));
    let out = d.join("out");
    let o = run_quiet(&deck, &out, &[]);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o).1);
    let (header, rows) = read_csv(&out.join("bodies.csv"));
    let col = |name: &str| header.iter().position(|h| h == name).unwrap();
    let r = rows.last().unwrap();
    let wet = (1000.0 + 400.0 - 1025.0 * PI * 0.0625 * 4.0) * 9.80665;
    assert!(
        (r[col("fz")] - wet).abs() < 1e-6 * wet,
        "fz {} against {wet}",
        r[col("fz")]
    );
    for c in ["fx", "mx", "my", "mz"] {
        assert!(r[col(c)].abs() < 1e-6 * wet, "{c} {}", r[col(c)]);
    }
    let s = read_json(&out.join("summary.json"));
    let rods = s["rods"].as_array().unwrap();
    assert_eq!(
        (&rods[0]["type"], &rods[0]["body"]),
        (&"body".into(), &0.into())
    );
    assert_eq!(rods[0]["points"], serde_json::json!([4, 5]));
    assert_eq!(rods[1]["type"], "point");
    assert_eq!(rods[1]["body"], serde_json::Value::Null);
    assert_eq!(rods[1]["points"], serde_json::json!([3, 3]));
    let o = stancf(&["check", deck.to_str().unwrap()]);
    let (so, se) = text(&o);
    assert_eq!(o.status.code(), Some(0), "{se}");
    let line = |start: &str| {
        so.lines()
            .find(|l| l.starts_with(start))
            .unwrap_or_else(|| panic!("{start}: {so}"))
            .to_string()
    };
    assert!(
        line("rod 1").contains("fixed in free body 1; type can, length 4 m"),
        "{so}"
    );
    assert!(line("rod 1").contains("mass 400 kg; submerged"), "{so}");
    assert!(
        line("rod 2").contains("free of zero length (NumSegs 0): point 3"),
        "{so}"
    );
    assert!(line("body 1").contains("rods 1 fixed in it"), "{so}");
    assert!(
        so.contains(
            "rod 2 asks for a file of its own (RodOutputs \"p\"), which stancf does not write"
        ),
        "{so}"
    );
    // A dynamic run from that equilibrium stays there: the core steps
    // the zero-length rod, a free point of no mass between two lines
    // (nothing moves: velocities are round-off, 1e-13 m/s measured).
    let dynamic = write_scenario(
        &d,
        "dynamic.toml",
        "[system]\nmoordyn = \"body-rod.txt\"\n[analysis]\ntype = \"dynamic\"\n\
         time_step = 0.01\nduration = 0.5\n",
    );
    let o = run_quiet(&dynamic, &d.join("dyn"), &[]);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o).1);
    let (_, moving) = read_csv(&d.join("dyn").join("bodies.csv"));
    for m in &moving {
        for c in ["x", "z", "pitch"] {
            assert!(
                (m[col(c)] - r[col(c)]).abs() < 1e-9,
                "t = {}: {c} {}",
                m[0],
                m[col(c)]
            );
        }
        for c in ["vx", "vz", "wy"] {
            assert!(m[col(c)].abs() < 1e-9, "t = {}: {c} {}", m[0], m[col(c)]);
        }
    }
    // RodOutputs without a file letter: no note.
    let quiet = write_scenario(&d, "quiet.txt", &body_rod_deck("-", "0"));
    let (so, _) = text(&stancf(&["check", quiet.to_str().unwrap()]));
    assert!(!so.contains("file of its own"), "{so}");
}

/// `deck` with the one output channel `name`, refused with `words` at
/// its line (a case of the test below).
fn rod_channel(deck: &str, name: &'static str, words: &str) -> (String, &'static str, String) {
    let with = deck.replace(
        "water depth (m)\n",
        &format!("water depth (m)\n--- OUTPUTS ---\nFairTen1\n{name}\n"),
    );
    (with, name, words.to_string())
}

/// What is not built is refused naming the deck's line: a line with
/// bending stiffness at a rod end, a pinned or coupled rod, a rod in
/// water that reaches the surface, a zero-length free rod without lines,
/// a rod output channel stancf has no value for (a body rod's forces, a
/// zero-length rod's all but its position and velocity, accelerations)
/// or MoorDyn has none for (RZ, nodes), a rod type's value out of the
/// solver's range; a deck of rods alone (no lines) is refused saying why.
#[test]
fn what_rods_do_not_build_is_refused_naming_the_deck_line() {
    let d = scratch("rod-refusals");
    let base = body_rod_deck("-", "0");
    let line_of =
        |text: &str, needle: &str| text.lines().position(|l| l.contains(needle)).unwrap() + 1;
    let cases: Vec<(String, &str, String)> =
        vec![
        (
            body_rod_deck("-", "1e3"),
            "1     rope       1        R1A",
            "AttachB of line 1 is end A of rod 1, and its line type has bending stiffness EI = \
             1000 N m^2: a line with bending stiffness at the end of a rod that moves (MoorDyn \
             clamps it to the rod's axis) is not built yet (at a fixed rod it is clamped)"
                .into(),
        ),
        (
            base.replace("1    can       Body1 ", "1    can       Body1Pinned "),
            "Body1Pinned",
            "rod 1 is pinned to body 1, which is free: a rod pinned to a free or coupled body \
             is not built yet"
                .into(),
        ),
        (
            base.replace("1    can       Body1 ", "1    can       Coupled "),
            "1    can       Coupled",
            "coupled rods are not built yet".into(),
        ),
        (
            base.replace(
                "2     rope       2        R2A       18        6",
                "2     rope       2        R1B       40        6",
            )
            .replace(
                "3     rope       r2b      Rod1B     20        6       -\n",
                "",
            ),
            "2    conn      Free",
            "rod 2 is free with NumSegs 0".into(),
        ),
        rod_channel(&base, "Rod1FX", "rod 1 is fixed in body 1: its share of the body's loads \
            is not separated in this version (the body's net force and moment are Body1FX ... \
            Body1MZ)"),
        rod_channel(&base, "Rod2RY", "rod 2 has NumSegs 0, a rod of zero length that stancf \
            builds as a point: it has a position and a velocity (PX PY PZ VX VY VZ)"),
        rod_channel(&base, "Rod1AX", "stancf does not compute this value in this version"),
        rod_channel(&base, "Rod1RZ", "MoorDyn has no \"RZ\" of a rod (no rotation about its axis"),
        rod_channel(&base, "R1N2PX", "node-level rod channels are not written"),
        (
            base.replace("can           0.5      100 ", "can           0.5      1e160 "),
            "can           0.5      1e160",
            "Mass/m: the value given = 1e160 is beyond 1e150".into(),
        ),
    ];
    for (k, (deck, at, words)) in cases.iter().enumerate() {
        let file = write_scenario(&d, &format!("bad{k}.txt"), deck);
        let n = line_of(deck, at);
        let errs =
            refused_by_check_and_run(&file, &d.join(format!("never{k}")), &[words.as_str()], &[]);
        assert!(
            errs[0].contains(&format!("bad{k}.txt: line {n}: ")),
            "{k}: {}",
            errs[0]
        );
    }
    // MoorDyn's rod_tests/AddedMass.txt has rods and no lines.
    let no_lines = base
        .split("---------------------- LINES")
        .next()
        .unwrap()
        .to_string()
        + "---------------------- OPTIONS -----\n100 WtrDpth\n--- END ---\n";
    let file = write_scenario(&d, "nolines.txt", &no_lines);
    refused_by_check_and_run(
        &file,
        &d.join("never-nl"),
        &[
            "the deck defines no lines",
            "a deck of rods or bodies alone is not built",
        ],
        &[],
    );
}

/// A TOML rod's keys are checked as the reader checks every key: unknown
/// keys, a rod type not defined, a body rod's body, a point at a rod end
/// given a position, an end or a mass, a rod above the water, segments
/// below 1, a rod of zero length, one too thin to have a body's inertia
/// (the core's refusal named by the rod), a value out of range.
#[test]
fn toml_rod_keys_are_checked_naming_the_key() {
    let base = rising_rod("type = \"dynamic\"\ntime_step = 0.01\nduration = 1.0");
    for (name, scenario, needles) in [
        (
            "rod-unknown-key",
            base.replace("segments = 4\n", "segments = 4\nlength = 2.0\n"),
            vec!["unknown field `length`"],
        ),
        (
            "rod-type-unknown-key",
            base.replace("ca = 1.0\n[[rods]]", "ca = 1.0\ncdax = 1.0\n[[rods]]"),
            vec!["unknown field `cdax`"],
        ),
        (
            "rod-type-undefined",
            base.replace("rod_type = \"can\"", "rod_type = \"cann\""),
            vec![
                "rods[0].rod_type",
                "rod type \"cann\" is not defined (known: can)",
            ],
        ),
        (
            "rod-body-undefined",
            base.replace(
                "type = \"free\"\nrod_type",
                "type = \"body\"\nbody = 3\nrod_type",
            ),
            vec![
                "rods[0].body",
                "body 3 is not defined (there are no [[bodies]])",
            ],
        ),
        (
            "rod-point-position",
            base.replace("end = \"A\"\n", "end = \"A\"\nposition = [0.0, 0.0, 0.0]\n"),
            vec!["points[0].position", "leave the position out"],
        ),
        (
            "rod-point-end",
            base.replace("end = \"A\"\n", "end = \"C\"\n"),
            vec!["points[0].end", "unknown value \"C\""],
        ),
        (
            "rod-point-mass",
            base.replace("end = \"A\"\n", "end = \"A\"\nmass = 1.0\n"),
            vec!["points[0].mass", "a point at a rod's end carries no mass"],
        ),
        (
            "rod-no-segments",
            base.replace("segments = 4", "segments = 0"),
            vec!["rods[0].segments", "must be between 1 and 10000, got 0"],
        ),
        (
            "rod-too-thin",
            base.replace("diameter = 0.5", "diameter = 1e-200"),
            vec!["rods[0]: moments of inertia"],
        ),
        (
            "rod-too-heavy",
            base.replace("mass_per_length = 100.0", "mass_per_length = 1e160"),
            vec!["rod_types[0].mass_per_length", "beyond 1e150"],
        ),
        (
            "rod-zero-length",
            base.replace("end_b = [1.0, 0.0, -10.0]", "end_b = [-1.0, 0.0, -10.0]"),
            vec!["rods[0]", "a rod of zero length has no axis"],
        ),
    ] {
        expect_input_error(name, &scenario, &needles);
    }
}

/// The rising rod reaches the surface at t* = sqrt(2 x 10 / a) = 2.46 s
/// at v* = a t* = 7.9 m/s and breaks through it (docs/method.md §15.11):
/// - the water keeps the momentum of the added mass the rod leaves behind
///   (B23), so it leaves no faster than its buoyancy less its weight
///   could push its bare mass over its crossing (under d / v* = 0.063 s):
///   v* + (rho V - m) g / m d / v* = 9.8 m/s (the Lagrangian of the added
///   mass alone would hand it the added mass's energy: 17.6 m/s);
/// - out of the water (its axis and its caps' spheres a radius up) it
///   flies as a stone: dv/dt = -g, but for the 1 m threads' wet weight
///   (0.18 N on 200 kg: 1e-4 g), checked to 1e-3 g;
/// - it falls back, slams into the water and floats, the run ending
///   normally with its balance in the water's work.
#[test]
fn a_free_rod_breaks_through_the_surface_and_falls_back() {
    let d = scratch("rod-surface");
    let sc = write_scenario(
        &d,
        "rod.toml",
        &rising_rod("type = \"dynamic\"\ntime_step = 0.01\nduration = 5.0"),
    );
    let out = d.join("out");
    let o = run_quiet(&sc, &out, &[]);
    let (_, se) = text(&o);
    assert_eq!(o.status.code(), Some(0), "{se}");
    let (header, rows) = read_csv(&out.join("bodies.csv"));
    let col = |name: &str| header.iter().position(|h| h == name).unwrap();
    let (g, radius, rho) = (9.81, 0.25, 1025.0);
    let (volume, mass) = (PI * radius * radius * 2.0, 200.0);
    let rise = (rho * volume - mass) * g / (mass + rho * volume);
    let arrival = rise * (2.0 * 10.0 / rise).sqrt();
    let bound = arrival + (rho * volume - mass) * g / mass * (2.0 * radius / arrival);
    let fastest = rows.iter().map(|r| r[col("vz")]).fold(f64::MIN, f64::max);
    eprintln!("arrives at {arrival:.3} m/s, leaves at most at {fastest:.3} m/s (bound {bound:.3})");
    assert!(fastest < bound, "{fastest} against {bound}");
    let flying: Vec<&Vec<f64>> = rows.iter().filter(|r| r[col("z")] > 2.0 * radius).collect();
    assert!(flying.len() > 50, "{} rows in the air", flying.len());
    let (first, last) = (flying[0], flying[flying.len() - 1]);
    let deceleration = (last[col("vz")] - first[col("vz")]) / (last[0] - first[0]);
    assert!(
        (deceleration + g).abs() < 1e-3 * g,
        "dv/dt in the air {deceleration}"
    );
    let landed = rows.last().unwrap();
    assert!(
        landed[col("z")] < radius,
        "back in the water: z {}",
        landed[col("z")]
    );
    let s = read_json(&out.join("summary.json"));
    assert!(s["error"].is_null(), "{}", s["error"]);
}

/// A rod fixed in a TOML body (`type = "body"`) joins the body: hung by
/// lines at the rod's ends, body and rod settle where the lines hold
/// (1000 + 400 - 1025 pi 0.25^2 4) g (TOML's g = 9.81), to the static
/// tolerance.
#[test]
fn a_toml_rod_on_a_body_adds_its_weight_and_buoyancy_to_the_body() {
    let scenario = "title = \"body rod\"\n[water]\ndepth = 100.0\ndensity = 1025.0\n\
        [[line_types]]\nname = \"rope\"\ndiameter = 0.05\nmass_per_length = 10.0\nea = 1.0e8\n\
        [[rod_types]]\nname = \"can\"\ndiameter = 0.5\nmass_per_length = 100.0\ncd = 1.2\nca = 1.0\n\
        [[bodies]]\nid = 4\ntype = \"free\"\nposition = [0.0, 0.0, -20.0]\nmass = 1000.0\n\
        inertia = [1000.0, 1000.0, 1000.0]\n\
        [[rods]]\nid = 1\ntype = \"body\"\nbody = 4\nrod_type = \"can\"\n\
        end_a = [-2.0, 0.0, 0.0]\nend_b = [2.0, 0.0, 0.0]\n\
        [[points]]\nid = 1\ntype = \"fixed\"\nposition = [-30.0, 0.0, 0.0]\n\
        [[points]]\nid = 2\ntype = \"fixed\"\nposition = [30.0, 0.0, 0.0]\n\
        [[points]]\nid = 3\ntype = \"rod\"\nrod = 1\nend = \"A\"\n\
        [[points]]\nid = 4\ntype = \"rod\"\nrod = 1\nend = \"B\"\n\
        [[lines]]\nid = 1\ntype = \"rope\"\nlength = 36.0\nelements = 12\na = 1\nb = 3\n\
        [[lines]]\nid = 2\ntype = \"rope\"\nlength = 36.0\nelements = 12\na = 2\nb = 4\n\
        [analysis]\ntype = \"static\"\n";
    let d = scratch("toml-body-rod");
    let sc = write_scenario(&d, "rod.toml", scenario);
    let out = d.join("out");
    let o = run_quiet(&sc, &out, &[]);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o).1);
    let (header, rows) = read_csv(&out.join("bodies.csv"));
    let col = |name: &str| header.iter().position(|h| h == name).unwrap();
    let r = rows.last().unwrap();
    let wet = (1000.0 + 400.0 - 1025.0 * PI * 0.0625 * 4.0) * 9.81;
    assert!(
        (r[col("fz")] - wet).abs() < 1e-6 * wet,
        "fz {} against {wet}",
        r[col("fz")]
    );
    let s = read_json(&out.join("summary.json"));
    assert_eq!(s["rods"][0]["type"], "body");
    assert_eq!(s["rods"][0]["body_id"], 4);
}

/// A deck's free body with Mass 0 and I 0 that carries a rod (MoorDyn's
/// floats made of rods, OpenFAST's md_float): the rod's mass and inertia
/// make the body, and at the balance the lines hold the rod's wet weight
/// alone, (400 - 1025 pi 0.25^2 4) g, to the static tolerance (the body
/// is buoyant: here it starts 40 m down and its anchors are 60 m down,
/// so that they hold it under water). Without a rod such a body is
/// refused, naming its line.
#[test]
fn a_deck_body_of_no_mass_of_its_own_takes_its_rods_mass() {
    let d = scratch("massless-body-rod");
    let text = body_rod_deck("-", "0")
        .replace(
            "1      Free      0.0    0    -20.0   0       0      0      1000   0    1000",
            "1      Free      0.0    0    -40.0   0       0      0      0      0    0   ",
        )
        .replace(
            "2    conn      Free        15    0     -10   15    0     -10  0",
            "2    conn      Free        15    0     -50   15    0     -50  0",
        )
        .replace(
            "1     Fixed     -30     0       0 ",
            "1     Fixed     -30     0     -60 ",
        )
        .replace(
            "2     Fixed      30     0       0 ",
            "2     Fixed      30     0     -60 ",
        );
    let deck = write_scenario(&d, "body-rod.txt", &text);
    let out = d.join("out");
    let o = run_quiet(&deck, &out, &[]);
    assert_eq!(o.status.code(), Some(0), "{}", text_of(&o));
    let (header, rows) = read_csv(&out.join("bodies.csv"));
    let col = |name: &str| header.iter().position(|h| h == name).unwrap();
    let wet = (400.0 - 1025.0 * PI * 0.0625 * 4.0) * 9.80665;
    let fz = rows.last().unwrap()[col("fz")];
    assert!((fz - wet).abs() < 1e-6 * wet.abs(), "fz {fz} against {wet}");
    let bare = text.replace(
        "1    can       Body1       -2    0     0     2     0     0    4       -",
        "1    can       Fixed       -2    0     0     2     0     0    4       -",
    );
    let deck = write_scenario(&d, "bare.txt", &bare);
    let o = stancf(&["check", deck.to_str().unwrap()]);
    assert_eq!(o.status.code(), Some(2));
    assert!(text_of(&o).contains("line 15: Mass"), "{}", text_of(&o));
}

fn text_of(o: &std::process::Output) -> String {
    let (so, se) = text(o);
    format!("{so}{se}")
}

/// MoorDyn's cantilevered beam (tests/Mooring/BeamCantilevered.txt, its
/// tests/beam.cpp): a 10 m line of EI 1e7 N m^2 and 100 kg/m leaves a
/// fixed rod's end B along the rod's axis (a clamp) and hangs free at
/// its other end, in air (z = 10 m). At its static equilibrium every
/// node sags as the closed form of a cantilever under its weight p,
/// z - 10 = -p x^2 (6 L^2 - 4 x L + x^2) / (24 EI) (0.123 m at the
/// tip), to 5e-4 of the tip's sag: the beam's slope (0.016) makes the
/// linear theory's error (w')^2 ~ 3e-4, the 19 cubic elements' far less.
/// The deck's `cfl` (issue 31) is replaced by a `dtM`; nothing else.
#[test]
fn moordyns_cantilevered_beam_sags_as_the_closed_form() {
    let deck = "--------------------- MoorDyn Input File ------------------------------------
MoorDyn input file of the mooring system for FD validation cases
----------------------- LINE TYPES ------------------------------------------
TypeName   Diam    Mass/m     EA         BA/-zeta    EI         Cd     Ca     CdAx    CaAx
(name)     (m)     (kg/m)     (N)        (N-s/-)     (N-m^2)    (-)    (-)    (-)     (-)
beam      0.05     100.0      1.5e9      -1.0        1e7        0.0    0.0    0.1     0.0
---------------------- ROD TYPES ------------------------------------
TypeName      Diam     Mass/m    Cd     Ca      CdEnd    CaEnd
(name)        (m)      (kg/m)    (-)    (-)     (-)      (-)
cantilever    0.25     100.0     0.0    0.0     0.0      0.0
---------------------- RODS ----------------------------------------
ID   RodType   Attachment  Xa    Ya    Za    Xb    Yb    Zb   NumSegs  RodOutputs
(#)  (name)     (#/key)    (m)   (m)   (m)   (m)   (m)   (m)  (-)       (-)
1    cantilever Fixed      -10.0 0     10.0  0.0   0     10.0 1         -
---------------------- POINT PROPERTIES --------------------------------
ID    Type      X       Y       Z       Mass   Volume  CdA    Ca
(#)   (-)       (m)     (m)     (m)     (kg)   (m^3)   (m^2)  (-)
1     Free      10      0.0     9.9     0      0       0      0
---------------------- LINES ----------------------------------------
ID   LineType   AttachA  AttachB  UnstrLen  NumSegs  LineOutputs
(#)   (name)     (#)      (#)       (m)       (-)     (-)
1     beam       R1B      1         10        19      -
---------------------- OPTIONS -----------------------------------------
2             writeLog             Write a log file
0.001         dtM                  time step (the deck's cfl 0.1, issue 31)
10            WtrDpth              water depth (m)
1.0           dtIC                 time interval for analyzing convergence during IC gen (s)
40.0          TmaxIC               max time for ic gen (s)
1e-5          threshIC             threshold for IC convergence (-)
1       disableOutTime
------------------------- need this line --------------------------------------
";
    let d = scratch("cantilever");
    let path = write_scenario(&d, "BeamCantilevered.txt", deck);
    let out = d.join("out");
    let o = run_quiet(&path, &out, &[]);
    assert_eq!(o.status.code(), Some(0), "{}", text_of(&o));
    let s = read_json(&out.join("summary.json"));
    let g = s["gravity"]
        .as_array()
        .map_or(9.80665, |v| -v[2].as_f64().unwrap());
    let (header, rows) = read_csv(&out.join("lines/1/nodes.csv"));
    let col = |name: &str| header.iter().position(|h| h == name).unwrap();
    let last_t = rows.last().unwrap()[0];
    let (l, ei, p) = (10.0, 1e7, 100.0 * g);
    let sag = |x: f64| -p * x * x * (6.0 * l * l - 4.0 * x * l + x * x) / (24.0 * ei);
    let tip = sag(l).abs();
    let mut worst = 0.0f64;
    for r in rows.iter().filter(|r| r[0] == last_t) {
        let (x, z) = (r[col("x")], r[col("z")]);
        worst = worst.max((z - 10.0 - sag(x)).abs());
    }
    eprintln!("cantilever: largest difference {worst:.2e} m of a tip sag of {tip:.4} m");
    assert!(worst < 5e-4 * tip, "{worst:e} of {tip}");
}

/// A deck of one free rod (10 m, 0.5 m across, 400 kg/m: it sinks) hung
/// level at z = -20 m, end A at x = -5 m, by two ropes of 20 m (0.05 m,
/// 10 kg/m, EA 1e8 N) from fixed points at the surface straight above
/// its ends; OUTPUTS the rod's channels.
const LEVEL_ROD: &str =
    "--------------------- MoorDyn Input File ---------------------------------------
A free rod hung level under water by a vertical rope at each end
----------------------- LINE TYPES ------------------------------------------
TypeName Diam  Mass/m   EA         BA/-zeta EI      Cd  Ca  CdAx CaAx
(name)   (m)   (kg/m)   (N)        (N-s/-)  (N-m^2) (-) (-) (-)  (-)
rope     0.05  10.0     1.0E8      -0.5     0       1.2 1.0 0.1  0.0
---------------------- ROD TYPES -----------------------------------------------
TypeName      Diam     Mass/m    Cd     Ca      CdEnd    CaEnd
(name)        (m)      (kg/m)    (-)    (-)     (-)      (-)
can           0.5      400       1.2    1.0     0.6      0.5
---------------------- RODS ----------------------------------------------------
ID   RodType   Attachment  Xa    Ya    Za    Xb    Yb    Zb   NumSegs RodOutputs
(#)  (name)     (#/key)    (m)   (m)   (m)   (m)   (m)   (m)  (-)     (-)
1    can       Free        -5    0     -20   5     0     -20  4       -
---------------------- POINTS --------------------------------------------------
ID    Type      X       Y       Z       Mass   Volume  CdA    Ca
(#)   (-)       (m)     (m)     (m)     (kg)   (m^3)   (m^2)  (-)
1     Fixed     -5      0       0       0      0       0      0
2     Fixed      5      0       0       0      0       0      0
---------------------- LINES ---------------------------------------------------
ID   LineType   AttachA  AttachB  UnstrLen  NumSegs  LineOutputs
(#)   (name)     (#)      (#)       (m)       (-)     (-)
1     rope       1        R1A       20        10      -
2     rope       2        R1B       20        10      -
---------------------- OPTIONS -------------------------------------------------
0.002         dtM                  time step (s)
100           WtrDpth              water depth (m)
---------------------- OUTPUTS -------------------------------------------------
Rod1PX Rod1PZ Rod1RX Rod1RY Rod1TENA Rod1SUB Rod1FZ
Rod1PY Rod1VZ Rod1RVY Rod1TENB Rod1FX Rod1MY
------------------------- need this line --------------------------------------
";

/// Runs `deck` (written as `name` in `d`) statically and, from that
/// balance, dynamically for 1 s in steps of 0.01 s (a scenario that
/// takes the deck); the rows of both channels.csv files, static first.
fn channels_static_and_dynamic(
    d: &std::path::Path,
    name: &str,
    deck: &str,
) -> (Vec<String>, Vec<Vec<f64>>) {
    let path = write_scenario(d, name, deck);
    let o = run_quiet(&path, &d.join("static"), &[]);
    assert_eq!(o.status.code(), Some(0), "{}", text_of(&o));
    let dynamic = write_scenario(
        d,
        "dynamic.toml",
        &format!(
            "[system]\nmoordyn = \"{name}\"\n[analysis]\ntype = \"dynamic\"\n\
             time_step = 0.01\nduration = 1.0\n"
        ),
    );
    let o = run_quiet(&dynamic, &d.join("dynamic"), &[]);
    assert_eq!(o.status.code(), Some(0), "{}", text_of(&o));
    let (header, mut rows) = read_csv(&d.join("static").join("channels.csv"));
    let (again, moving) = read_csv(&d.join("dynamic").join("channels.csv"));
    assert_eq!(header, again);
    assert_eq!((rows.len(), moving.len()), (1, 101));
    rows.extend(moving);
    (header, rows)
}

/// The level rod's channels (MoorDyn's `Rod::GetRodOutput`) against the
/// closed form, at its static balance and in a dynamic run from it
/// (where nothing moves): end A at x = -5 m, y = 0, and z = -20 m less
/// the rope's stretch under its end tension T = W/2 and its own wet
/// weight w, (T L + w L^2 / 2) / EA (2.1 mm); MoorDyn's angles of a rod
/// lying along +x, roll 0 and pitch 90 degrees (its zero is a rod
/// standing with end A below B); TENA and TENB the rope's pull at each
/// end, W/2 by symmetry (W the rod's wet weight, (400 - rho pi 0.25^2)
/// 10 g); SUB 1; the net force (its lines', its weight and buoyancy, the
/// water's drag) and its moment about end A zero; no velocity. Measured:
/// 1e-14 m, 5e-11 W and 4e-10 W m (the dynamic steps' Newton
/// tolerance); claimed 1e-9 m, 1e-8 W and 1e-8 W m: leaving the rod's
/// buoyancy out of its net force would move FZ by 1.01 W and MY by
/// 5.1 W m.
#[test]
fn a_rods_channels_are_its_pose_and_its_lines_pull() {
    let d = scratch("rod-channels-level");
    let (header, rows) = channels_static_and_dynamic(&d, "level.txt", LEVEL_ROD);
    let col = |name: &str| header.iter().position(|h| h == name).unwrap();
    let (g, rho) = (9.80665, 1025.0);
    let w_rod = (400.0 - rho * PI * 0.0625) * 10.0 * g;
    let w_rope = (10.0 - rho * PI * 0.025 * 0.025) * g;
    let pull = w_rod / 2.0;
    let z = -20.0 - (pull * 20.0 + w_rope * 20.0 * 20.0 / 2.0) / 1e8;
    for r in &rows {
        let t = r[0];
        let near = |name: &str, want: f64, tol: f64| {
            let got = r[col(name)];
            assert!(
                (got - want).abs() <= tol,
                "t = {t}: {name} {got} against {want}"
            );
        };
        near("Rod1PX", -5.0, 1e-9);
        near("Rod1PY", 0.0, 1e-9);
        near("Rod1PZ", z, 1e-9);
        near("Rod1RX", 0.0, 1e-9);
        near("Rod1RY", 90.0, 1e-9);
        near("Rod1TENA", pull, 1e-8 * w_rod);
        near("Rod1TENB", pull, 1e-8 * w_rod);
        near("Rod1SUB", 1.0, 0.0);
        near("Rod1FX", 0.0, 1e-8 * w_rod);
        near("Rod1FZ", 0.0, 1e-8 * w_rod);
        near("Rod1MY", 0.0, 1e-8 * w_rod);
        near("Rod1VZ", 0.0, 1e-9);
        near("Rod1RVY", 0.0, 1e-6);
    }
}

/// A free spar (10 m, 1 m across, 100 kg/m) standing in the surface, end
/// A 8 m down, held by a rope (42 m, as above) from its foot to a point
/// 50 m down; OUTPUTS its channels.
const SPAR: &str =
    "--------------------- MoorDyn Input File ---------------------------------------
A free rod standing in the surface, held down by a line from its foot
----------------------- LINE TYPES ------------------------------------------
TypeName Diam  Mass/m   EA         BA/-zeta EI      Cd  Ca  CdAx CaAx
(name)   (m)   (kg/m)   (N)        (N-s/-)  (N-m^2) (-) (-) (-)  (-)
rope     0.05  10.0     1.0E8      -0.5     0       1.2 1.0 0.1  0.0
---------------------- ROD TYPES -----------------------------------------------
TypeName      Diam     Mass/m    Cd     Ca      CdEnd    CaEnd
(name)        (m)      (kg/m)    (-)    (-)     (-)      (-)
spar          1.0      100       1.2    1.0     0.6      0.5
---------------------- RODS ----------------------------------------------------
ID   RodType   Attachment  Xa    Ya    Za    Xb    Yb    Zb   NumSegs RodOutputs
(#)  (name)     (#/key)    (m)   (m)   (m)   (m)   (m)   (m)  (-)     (-)
1    spar      Free        0     0     -8    0     0     2    10      -
---------------------- POINTS --------------------------------------------------
ID    Type      X       Y       Z       Mass   Volume  CdA    Ca
(#)   (-)       (m)     (m)     (m)     (kg)   (m^3)   (m^2)  (-)
1     Fixed     0       0       -50     0      0       0      0
---------------------- LINES ---------------------------------------------------
ID   LineType   AttachA  AttachB  UnstrLen  NumSegs  LineOutputs
(#)   (name)     (#)      (#)       (m)       (-)     (-)
1     rope       1        R1A       42        14      -
---------------------- OPTIONS -------------------------------------------------
0.002         dtM                  time step (s)
60            WtrDpth              water depth (m)
---------------------- OUTPUTS -------------------------------------------------
Rod1PZ Rod1RX Rod1RY Rod1TENA Rod1TENB Rod1SUB Rod1FZ Rod1MX
------------------------- need this line --------------------------------------
";

/// The spar floats at the balance rho g A h = m g + T of its draft h and
/// the rope's pull T (TENA): SUB is h / L, the exact submerged fraction,
/// and end A is h down. The draft is closed too from the rope's stretch:
/// h = 8 m less (T 42 - w 42^2 / 2) / EA, with T = rho g A h - m g
/// (h = 7.978 m). RX and RY are 0 (standing, A below B), no line pulls
/// at B, no net force. Measured: 3e-12 (SUB), 9e-15 m (h), 3e-12 of the
/// buoyancy (FZ), in the static and the dynamic run; claimed 1e-9, 1e-9
/// m and 1e-8: MoorDyn's mean of its nodes' fractions (its VOF) would
/// differ by the cut node's share.
#[test]
fn a_spars_submerged_fraction_is_its_draft_over_its_length() {
    let d = scratch("rod-channels-spar");
    let (header, rows) = channels_static_and_dynamic(&d, "spar.txt", SPAR);
    let col = |name: &str| header.iter().position(|h| h == name).unwrap();
    let (g, rho, length) = (9.80665, 1025.0, 10.0);
    let weight = 100.0 * length * g;
    let lift = rho * g * PI * 0.25;
    let w_rope = (10.0 - rho * PI * 0.025 * 0.025) * g;
    let (l, ea) = (42.0, 1e8);
    let draft = (8.0 + w_rope * l * l / (2.0 * ea) + weight * l / ea) / (1.0 + lift * l / ea);
    for r in &rows {
        let t = r[0];
        let near = |name: &str, want: f64, tol: f64| {
            let got = r[col(name)];
            assert!(
                (got - want).abs() <= tol,
                "t = {t}: {name} {got} against {want}"
            );
        };
        let pull = r[col("Rod1TENA")];
        near("Rod1SUB", (weight + pull) / (lift * length), 1e-9);
        near("Rod1SUB", draft / length, 1e-9);
        near("Rod1PZ", -draft, 1e-9);
        near("Rod1TENA", lift * draft - weight, 1e-8 * lift * draft);
        near("Rod1TENB", 0.0, 0.0);
        near("Rod1RX", 0.0, 1e-9);
        near("Rod1RY", 0.0, 1e-9);
        near("Rod1FZ", 0.0, 1e-8 * lift * draft);
        near("Rod1MX", 0.0, 1e-8 * lift * draft);
    }
}

/// The body rod deck above with a fixed rod 3 (0.1 m across) tilted up
/// from (0, 0, -1.5) to (1, 1, 0.5) through the surface, no line at it,
/// and OUTPUTS `outputs`.
fn three_rods_deck(outputs: &str) -> String {
    body_rod_deck("-", "0")
        .replace(
            "2    conn      Free        15    0     -10   15    0     -10  0       -\n",
            "2    conn      Free        15    0     -10   15    0     -10  0       -\n\
             3    conn      Fixed       0     0     -1.5  1     1     0.5  2       -\n",
        )
        .replace(
            "water depth (m)\n",
            &format!("water depth (m)\n--- OUTPUTS ---\n{outputs}\n"),
        )
}

/// A rod fixed in a body is where the body puts it: in a dynamic run
/// from the deck's pose (the body falls, swings and turns on its lines),
/// at every written moment end A is the body's point (-2, 0, 0), its
/// velocity v + w x (R xi_A), its angles MoorDyn's of R e_x, RVX and RVY
/// the body's w (deg/s), TENA and TENB the net pull of the lines at its
/// ends (tensions.csv), SUB 1; the zero-length rod 2 is its point. The
/// fixed rod 3 stays: end A, roll -phi sin(beta) and pitch phi cos(beta)
/// (phi = atan(sqrt(2) / 2), beta = 45 deg), no pull, and 3/4 of it under
/// water (the surface cuts its axis 1.5 of its 2 m rise up; its caps,
/// 0.03 m high, are clear of it). Round-off only: claimed 1e-9.
#[test]
fn a_rod_on_a_body_moves_with_it_and_a_fixed_rod_stays() {
    let d = scratch("rod-channels-body");
    let outputs = "Rod1PX Rod1PY Rod1PZ Rod1VX Rod1VZ Rod1RX Rod1RY Rod1RVX Rod1RVY Rod1TENA \
                   Rod1TENB Rod1SUB Rod2PX Rod2PZ Rod2VZ Rod3PX Rod3PZ Rod3RX Rod3RY Rod3SUB \
                   Rod3TENA Rod3FZ Rod3MX";
    write_scenario(&d, "rods.txt", &three_rods_deck(outputs));
    let dynamic = write_scenario(
        &d,
        "dynamic.toml",
        "[system]\nmoordyn = \"rods.txt\"\n[analysis]\ntype = \"dynamic\"\n\
         initial = \"reference\"\ntime_step = 0.01\nduration = 1.0\n",
    );
    let out = d.join("out");
    let o = run_quiet(&dynamic, &out, &[]);
    assert_eq!(o.status.code(), Some(0), "{}", text_of(&o));
    let (header, rows) = read_csv(&out.join("channels.csv"));
    let (bh, bodies) = read_csv(&out.join("bodies.csv"));
    let (ph, points) = read_csv(&out.join("points.csv"));
    let tensions = read_tensions(&out.join("tensions.csv"));
    let col = |h: &[String], name: &str| h.iter().position(|c| c == name).unwrap();
    assert_eq!((rows.len(), bodies.len()), (101, 101));
    let phi = (2.0f64.sqrt() / 2.0).atan();
    let beta = PI / 4.0;
    let mut turned = 0.0f64;
    for (r, b) in rows.iter().zip(&bodies) {
        let t = r[0];
        let near = |name: &str, want: f64| {
            let got = r[col(&header, name)];
            assert!(
                (got - want).abs() <= 1e-9 * (1.0 + want.abs()),
                "t = {t}: {name} {got} against {want}"
            );
        };
        let bv = |name: &str| b[col(&bh, name)];
        let rotation =
            stancf::body::pose::rotation_from_moordyn_angles([bv("roll"), bv("pitch"), bv("yaw")]);
        let w = [bv("wx"), bv("wy"), bv("wz")];
        turned = turned.max(bv("pitch").abs());
        let arm = stancf::body::pose::rotate(&rotation, [-2.0, 0.0, 0.0]);
        let velocity =
            stancf::vec3::add([bv("vx"), bv("vy"), bv("vz")], stancf::vec3::cross(w, arm));
        for (k, a) in ["X", "Y", "Z"].iter().enumerate() {
            near(
                &format!("Rod1P{a}"),
                [bv("x"), bv("y"), bv("z")][k] + arm[k],
            );
        }
        near("Rod1VX", velocity[0]);
        near("Rod1VZ", velocity[2]);
        let q = stancf::body::pose::rotate(&rotation, [1.0, 0.0, 0.0]);
        let (p, h) = (q[0].hypot(q[1]).atan2(q[2]), q[1].atan2(q[0]));
        near("Rod1RX", (-p * h.sin()).to_degrees());
        near("Rod1RY", (p * h.cos()).to_degrees());
        near("Rod1RVX", w[0].to_degrees());
        near("Rod1RVY", w[1].to_degrees());
        let pull = |line: f64| {
            tensions
                .iter()
                .find(|x| x[0] == t && x[1] == line && x[2] == 1.0)
                .map_or(0.0, |x| x[6])
        };
        near("Rod1TENA", pull(1.0));
        near("Rod1TENB", pull(3.0));
        near("Rod1SUB", 1.0);
        let point = points
            .iter()
            .find(|x| x[0] == t && x[1] == 3.0)
            .expect("point 3");
        near("Rod2PX", point[col(&ph, "x")]);
        near("Rod2PZ", point[col(&ph, "z")]);
        near("Rod2VZ", point[col(&ph, "vz")]);
        near("Rod3PX", 0.0);
        near("Rod3PZ", -1.5);
        near("Rod3RX", (-phi * beta.sin()).to_degrees());
        near("Rod3RY", (phi * beta.cos()).to_degrees());
        near("Rod3SUB", 0.75);
        near("Rod3TENA", 0.0);
        near("Rod3FZ", 0.0);
        near("Rod3MX", 0.0);
    }
    // The body turned: the checks above saw R at work.
    assert!(turned > 0.1, "the body's pitch reached only {turned} deg");
}

/// A buoyant rod (4 m, 0.3 m across, 20 kg/m, Cd 1.2, no end drag)
/// pinned at its foot 18 m down, standing up, in a uniform steady
/// current of 0.5 m/s along x (`current_profile.txt`, the same at every
/// depth); `attachment` its RODS attachment, `bodies` the BODIES rows. A
/// light line joins a fixed point to the pin (`R1A`: its pull goes to
/// the pin, not the rod) and one hangs from the rod's top (`R1B`) to a
/// fixed point downstream (the static solve of a pinned body that holds
/// no line does not converge yet: see the report of issue 30).
fn pinned_rod_deck(attachment: &str, ends: &str, bodies: &str) -> String {
    format!(
        "--------------------- MoorDyn Input File ---------------------------------------
A buoyant rod pinned at its foot, leaning in a uniform current
----------------------- LINE TYPES ------------------------------------------
TypeName Diam  Mass/m   EA         BA/-zeta EI      Cd  Ca  CdAx CaAx
(name)   (m)   (kg/m)   (N)        (N-s/-)  (N-m^2) (-) (-) (-)  (-)
thread   0.02  1.0      1.0E6      -0.5     0       1.2 1.0 0.1  0.0
---------------------- ROD TYPES -----------------------------------------------
TypeName      Diam     Mass/m    Cd     Ca      CdEnd    CaEnd
(name)        (m)      (kg/m)    (-)    (-)     (-)      (-)
float         0.3      20        1.2    1.0     0.0      0.0
---------------------------- BODIES -----------------------------------------------------
ID   Attachment  X0     Y0    Z0     r0      p0     y0     Mass  CG*   I*      Volume   CdA*    Ca
(#)     (-)      (m)    (m)   (m)   (deg)   (deg)  (deg)   (kg)  (m)  (kg-m^2)  (m^3)   (m^2)   (-)
{bodies}---------------------- RODS ----------------------------------------------------
ID   RodType   Attachment  Xa    Ya    Za    Xb    Yb    Zb   NumSegs RodOutputs
(#)  (name)     (#/key)    (m)   (m)   (m)   (m)   (m)   (m)  (-)     (-)
1    float     {attachment} {ends}  8       -
---------------------- POINTS --------------------------------------------------
ID    Type      X       Y       Z       Mass   Volume  CdA    Ca
(#)   (-)       (m)     (m)     (m)     (kg)   (m^3)   (m^2)  (-)
1     Fixed     -10     0       -18     0      0       0      0
2     Fixed     6       0       -14     0      0       0      0
---------------------- LINES ---------------------------------------------------
ID   LineType   AttachA  AttachB  UnstrLen  NumSegs  LineOutputs
(#)   (name)     (#)      (#)       (m)       (-)     (-)
1     thread     1        R1A       10.5      10      -
2     thread     R1B      2         6.5       10      -
---------------------- OPTIONS -------------------------------------------------
0.002         dtM                  time step (s)
30            WtrDpth              water depth (m)
1             Currents             steady current profile
------------------------- need this line --------------------------------------
"
    )
}

/// The uniform current of [`pinned_rod_deck`], 0.5 m/s along x.
const PINNED_CURRENT: &str = "current\nz ux uy uz\n(m) (m/s) (m/s) (m/s)\n-30 0.5 0 0\n0 0.5 0 0\n";

/// The lean a of a rod pinned at its foot, its lift `lift` = (rho V - m)
/// g at its middle and the drag across it 1/2 rho Cd d L U^2 cos^2(a)
/// (`drag` its value upright; uniform along it, so at its middle too),
/// with `moment` the other loads' moment about the pin (about y, N m):
/// (L/2) (drag cos^2(a) - lift sin(a)) + moment = 0, by Newton from 0.
fn pinned_lean(lift: f64, drag: f64, l: f64, moment: f64) -> f64 {
    let f = |a: f64| 0.5 * l * (drag * a.cos().powi(2) - lift * a.sin()) + moment;
    let df = |a: f64| -0.5 * l * (2.0 * drag * a.cos() * a.sin() + lift * a.cos());
    let mut a = 0.0f64;
    for _ in 0..60 {
        a -= f(a) / df(a);
    }
    assert!(f(a).abs() < 1e-9, "Newton: {}", f(a));
    a
}

/// The deck's `Pinned1` rod (OpenFAST's md_no_line writes it so; the
/// digits are ignored) leans downstream until the moments about its pin
/// balance: its lift (rho V - m) g = 2058 N and the drag across it at its
/// middle, and the lines' moment at its top (bodies.csv's my about the
/// reference point, end A): the lean from pitch (MoorDyn's angles, the
/// rod turning about y) to 1e-8 rad (measured 1.3e-12, the static
/// tolerance 1e-10 on 2058 N's moments; without the lines' moment the
/// lean is off by 2.3e-2 rad, without the drag by 8.9e-2), roll and yaw 0,
/// the foot at the pin to 1e-9 m (measured 4e-15). The line at R1A ends
/// at the pin's fixed point (point 3, after the deck's two), the one at
/// R1B at the rod's point (4); check and summary.json say it is pinned,
/// and its body has no 6 x 6 stiffness, saying why, without a warning.
#[test]
fn a_deck_rod_pinned_at_its_foot_leans_in_a_current_to_the_balance_of_moments() {
    let d = scratch("pinned-rod-lean-deck");
    std::fs::write(d.join("current_profile.txt"), PINNED_CURRENT).unwrap();
    let deck = write_scenario(
        &d,
        "pinned.txt",
        &pinned_rod_deck("Pinned1    ", "0     0     -18   0     0     -14 ", ""),
    );
    let out = d.join("out");
    let o = run_quiet(&deck, &out, &[]);
    let (_, err) = text(&o);
    assert_eq!(o.status.code(), Some(0), "{err}");
    assert!(!err.contains("no mooring stiffness"), "{err}");
    let (header, rows) = read_csv(&out.join("bodies.csv"));
    let col = |name: &str| header.iter().position(|h| h == name).unwrap();
    let r = rows.last().unwrap();
    let (rho, g, l, dia, u) = (1025.0, 9.80665, 4.0, 0.3, 0.5);
    let lift = (rho * PI * dia * dia / 4.0 * l - 20.0 * l) * g;
    let drag = 0.5 * rho * 1.2 * dia * l * u * u;
    let want = pinned_lean(lift, drag, l, r[col("my")]);
    let lean = r[col("pitch")].to_radians();
    eprintln!(
        "pinned deck rod: lean {lean:.12} rad against {want:.12} ({:.1e}); lines' moment {} N m",
        lean - want,
        r[col("my")]
    );
    assert!((lean - want).abs() < 1e-8, "{lean} against {want}");
    assert!(r[col("roll")].abs() < 1e-9 && r[col("yaw")].abs() < 1e-9);
    let foot = [r[col("x")], r[col("y")], r[col("z")] + 18.0];
    assert!(foot.iter().all(|c| c.abs() < 1e-9), "the foot at {foot:?}");
    let s = read_json(&out.join("summary.json"));
    assert_eq!(s["rods"][0]["type"], "pinned");
    assert_eq!(s["rods"][0]["points"], serde_json::json!([3, 4]));
    assert_eq!(s["bodies"][0]["stiffness"], serde_json::Value::Null);
    let note = s["bodies"][0]["stiffness_note"].as_str().unwrap();
    assert!(note.contains("turns about its pin"), "{note}");
    let o = stancf(&["check", deck.to_str().unwrap()]);
    let (so, se) = text(&o);
    assert_eq!(o.status.code(), Some(0), "{se}");
    let rod_line = so.lines().find(|l| l.starts_with("rod 1")).expect("rod 1");
    for w in [
        "pinned at end A to point 3 (fixed; the rod turns freely about it), body 1",
        "point 3 at A, point 4 at B",
    ] {
        assert!(rod_line.contains(w), "{w}: {rod_line}");
    }
    assert!(
        so.lines()
            .any(|l| l.starts_with("point 3") && l.contains("fixed at [0, 0, -18] m")),
        "{so}"
    );
    assert!(so.contains("less 3 per pinned body (1)"), "{so}");
}

/// `Body1Pinned` on a fixed body: the rod's ends are the body's points
/// where its pose puts them (here the body at (1, 2, -20) turned 90
/// degrees in yaw: the body point (-2, 1, 2) is at (0, 0, -18) and
/// (-2, 1, 6) at (0, 0, -14)), and its end A is held at a fixed point
/// there: it leans in the current as the same rod `Pinned` at those
/// global ends does, its pose (bodies.csv) the same to 1e-9 (m, degrees;
/// the two differ by the rounding of the body's pose, 2e-16 m).
#[test]
fn a_rod_pinned_to_a_fixed_body_is_pinned_where_the_body_puts_its_end_a() {
    let d = scratch("pinned-rod-fixed-body");
    std::fs::write(d.join("current_profile.txt"), PINNED_CURRENT).unwrap();
    let body = "1      Fixed     1.0    2    -20.0   0       0      90     0     0    0        0        0       0\n";
    let on_body = write_scenario(
        &d,
        "on-body.txt",
        &pinned_rod_deck("Body1Pinned", "-2    1     2     -2    1     6   ", body),
    );
    let global = write_scenario(
        &d,
        "global.txt",
        &pinned_rod_deck("Pinned     ", "0     0     -18   0     0     -14 ", body),
    );
    let rod_line = |deck: &std::path::PathBuf| {
        let o = stancf(&["check", deck.to_str().unwrap()]);
        let (so, se) = text(&o);
        assert_eq!(o.status.code(), Some(0), "{se}");
        so.lines()
            .find(|l| l.starts_with("rod 1"))
            .expect("rod 1")
            .to_string()
    };
    let a = rod_line(&on_body);
    assert!(
        a.contains("pinned at end A to point 3 (fixed; the rod turns freely about it), body 2"),
        "{a}"
    );
    let pose = |deck: &std::path::PathBuf, name: &str| {
        let out = d.join(name);
        let o = run_quiet(deck, &out, &[]);
        assert_eq!(o.status.code(), Some(0), "{}", text(&o).1);
        let (header, rows) = read_csv(&out.join("bodies.csv"));
        let col = |c: &str| header.iter().position(|h| h == c).unwrap();
        let r = rows.iter().find(|r| r[col("body")] == 2.0).expect("body 2");
        ["x", "y", "z", "roll", "pitch", "yaw"].map(|c| r[col(c)])
    };
    let (a, b) = (pose(&on_body, "on-body"), pose(&global, "global"));
    eprintln!("pinned to a fixed body: {a:?}; pinned globally: {b:?}");
    assert!(a[4] > 1.0, "it leans: {a:?}");
    for k in 0..6 {
        assert!((a[k] - b[k]).abs() < 1e-9, "{k}: {a:?} against {b:?}");
    }
}

/// The TOML scenario of a buoyant rod (as [`pinned_rod_deck`]'s, type
/// "pinned") pinned at its foot in a uniform current of 0.5 m/s with
/// g = 9.81, a thread without drag (3 m, 0.02 m, 1 kg/m) hanging from
/// its top (a loose end: it hangs straight down, pulling the top down by
/// its wet weight w = (1 - rho pi d^2/4) g 3 m = 19.95 N), and no point
/// at end A (the pin's fixed point is made there, id 2).
const PINNED_LEAN: &str = "title = \"pinned rod in a current\"
[water]
depth = 30.0
density = 1025.0
[water.current]
velocity = [0.5, 0.0, 0.0]
[[line_types]]
name = \"thread\"
diameter = 0.02
mass_per_length = 1.0
ea = 1.0e6
[[rod_types]]
name = \"float\"
diameter = 0.3
mass_per_length = 20.0
cd = 1.2
ca = 1.0
[[rods]]
id = 1
type = \"pinned\"
rod_type = \"float\"
end_a = [0.0, 0.0, -18.0]
end_b = [0.0, 0.0, -14.0]
segments = 8
[[points]]
id = 1
type = \"rod\"
rod = 1
end = \"B\"
[[lines]]
id = 1
type = \"thread\"
length = 3.0
elements = 4
a = 1
[analysis]
type = \"static\"
";

/// The TOML pinned rod leans to the closed form (rho V - m) g sin(a) -
/// 2 w sin(a) = 1/2 rho Cd d L U^2 cos^2(a) (the thread's pull w at the
/// top, twice the middle's arm): to 1e-8 rad (measured 0 to the digits
/// written; leaving the thread out moves it by 1.7e-3 rad), the foot at
/// the pin to 1e-9 m, the pin's point made (id 2, fixed, at end A) with
/// summary.json's rod's points [2, 1].
#[test]
fn a_toml_rod_pinned_at_its_foot_leans_in_a_current_as_the_closed_form() {
    let d = scratch("pinned-rod-lean-toml");
    let sc = write_scenario(&d, "lean.toml", PINNED_LEAN);
    let out = d.join("out");
    let o = run_quiet(&sc, &out, &[]);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o).1);
    let (header, rows) = read_csv(&out.join("bodies.csv"));
    let col = |name: &str| header.iter().position(|h| h == name).unwrap();
    let r = rows.last().unwrap();
    let (rho, g, l, dia, u) = (1025.0, 9.81, 4.0, 0.3, 0.5);
    let thread = (1.0 - rho * PI * 0.01 * 0.01) * g * 3.0;
    let lift = (rho * PI * dia * dia / 4.0 * l - 20.0 * l) * g - 2.0 * thread;
    let want = pinned_lean(lift, 0.5 * rho * 1.2 * dia * l * u * u, l, 0.0);
    let lean = r[col("pitch")].to_radians();
    eprintln!(
        "pinned TOML rod: lean {lean:.12} rad against {want:.12} ({:.1e})",
        lean - want
    );
    assert!((lean - want).abs() < 1e-8, "{lean} against {want}");
    let foot = [r[col("x")], r[col("y")], r[col("z")] + 18.0];
    assert!(foot.iter().all(|c| c.abs() < 1e-9), "the foot at {foot:?}");
    let s = read_json(&out.join("summary.json"));
    assert_eq!(s["rods"][0]["type"], "pinned");
    assert_eq!(s["rods"][0]["points"], serde_json::json!([2, 1]));
    let (ph, points) = read_csv(&out.join("points.csv"));
    let pc = |name: &str| ph.iter().position(|h| h == name).unwrap();
    let pin = points
        .iter()
        .find(|p| p[pc("point")] == 2.0)
        .expect("point 2");
    assert_eq!(
        [pin[pc("x")], pin[pc("y")], pin[pc("z")]],
        [0.0, 0.0, -18.0]
    );
}

/// A rod (4 m, 0.3 m across, 20 kg/m) pinned at its top in air (no
/// [water]) released from rest 0.01 rad from hanging straight down
/// swings with the physical pendulum's period T = 2 pi sqrt(I_A / (m g
/// L/2)) (1 + theta0^2/16), I_A = m (L^2/3 + d^2/16): the period from
/// the zero crossings of its angle in bodies.csv (theta0 less the pitch
/// its body turns by, linearly between rows written every step of
/// 0.01 s, T/328) over three periods, to 1e-4 of it (measured 7e-9); the
/// pinned end stays at the pin to 1e-9 m (measured 7e-16). The pin's
/// point (a `[[points]]` of type "rod" at end A) holds a line to a fixed
/// point, which does not touch the rod; the rod's body holds no line.
#[test]
fn a_rod_pinned_at_its_top_swings_as_a_physical_pendulum() {
    let (l, dia, theta0, g) = (4.0f64, 0.3, 0.01f64, 9.81);
    let d = scratch("pinned-rod-pendulum");
    let sc = write_scenario(
        &d,
        "swing.toml",
        &format!(
            "title = \"pinned pendulum rod\"\n\
             [[line_types]]\nname = \"thread\"\ndiameter = 0.01\nmass_per_length = 0.1\nea = 1.0e4\n\
             [[rod_types]]\nname = \"bar\"\ndiameter = {dia:?}\nmass_per_length = 20.0\n\
             [[rods]]\nid = 1\ntype = \"pinned\"\nrod_type = \"bar\"\nend_a = [0.0, 0.0, 0.0]\n\
             end_b = [{:?}, 0.0, {:?}]\nsegments = 4\n\
             [[points]]\nid = 1\ntype = \"rod\"\nrod = 1\nend = \"A\"\n\
             [[points]]\nid = 2\ntype = \"fixed\"\nposition = [1.0, 0.0, 0.0]\n\
             [[lines]]\nid = 1\ntype = \"thread\"\nlength = 1.0\nelements = 2\na = 1\nb = 2\n\
             [analysis]\ntype = \"dynamic\"\ntime_step = 0.01\nduration = 11.0\n",
            l * theta0.sin(),
            -l * theta0.cos()
        ),
    );
    let out = d.join("out");
    let o = run_quiet(&sc, &out, &[]);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o).1);
    let (header, rows) = read_csv(&out.join("bodies.csv"));
    let col = |name: &str| header.iter().position(|h| h == name).unwrap();
    assert_eq!(rows.len(), 1101);
    let angle: Vec<(f64, f64)> = rows
        .iter()
        .map(|r| (r[col("t")], theta0 - r[col("pitch")].to_radians()))
        .collect();
    let crossings: Vec<f64> = angle
        .windows(2)
        .filter(|w| w[0].1 * w[1].1 < 0.0)
        .map(|w| w[0].0 + (w[1].0 - w[0].0) * w[0].1 / (w[0].1 - w[1].1))
        .collect();
    assert!(crossings.len() >= 7, "{crossings:?}");
    let period = (crossings[6] - crossings[0]) / 3.0;
    let m = 20.0 * l;
    let inertia = m * (l * l / 3.0 + dia * dia / 16.0);
    let want = 2.0 * PI * (inertia / (m * g * l / 2.0)).sqrt() * (1.0 + theta0.powi(2) / 16.0);
    let drift = rows
        .iter()
        .map(|r| r[col("x")].hypot(r[col("y")]).hypot(r[col("z")]))
        .fold(0.0f64, f64::max);
    eprintln!(
        "pinned pendulum rod: period {period:.9} s against {want:.9} s ({:.1e}); the pin moved \
         {drift:.1e} m",
        (period - want) / want
    );
    assert!(
        (period - want).abs() < 1e-4 * want,
        "{period} against {want}"
    );
    assert!(drift < 1e-9, "{drift:e}");
}

/// What pinned rods do not build is refused with exit 2 naming the deck's
/// line or the key, nothing written: a rod pinned to a coupled body
/// (`Body1Pinned`; a free body's is in
/// [`what_rods_do_not_build_is_refused_naming_the_deck_line`]), a rod
/// pinned to a host (`CoupledPinned`), a pinned rod of zero length, a
/// TOML pinned rod naming a body.
#[test]
fn what_pinned_rods_do_not_build_is_refused_naming_the_line_or_key() {
    let d = scratch("pinned-rod-refusals");
    std::fs::write(d.join("current_profile.txt"), PINNED_CURRENT).unwrap();
    let coupled = "1      Coupled   0.0    0    -20.0   0       0      0      0     0    0        0        0       0\n";
    let cases = [
        (
            pinned_rod_deck("Body1Pinned", "0     0     2     0     0     6   ", coupled),
            "rod 1 is pinned to body 1, which is coupled: a rod pinned to a free or coupled \
             body is not built yet",
        ),
        (
            pinned_rod_deck("CoupledPinned", "0     0     -18   0     0     -14 ", ""),
            "rod 1 is attached to \"CoupledPinned\": coupled rods are not built yet",
        ),
        (
            pinned_rod_deck("Pin", "0     0     -18   0     0     -14 ", "")
                .replace("-14   8       -", "-18   0       -"),
            "rod 1 is pinned with NumSegs 0, a rod of zero length",
        ),
    ];
    for (k, (deck, words)) in cases.iter().enumerate() {
        let file = write_scenario(&d, &format!("bad{k}.txt"), deck);
        let n = deck
            .lines()
            .position(|l| l.starts_with("1    float"))
            .unwrap()
            + 1;
        let errs = refused_by_check_and_run(&file, &d.join(format!("never{k}")), &[words], &[]);
        assert!(
            errs[0].contains(&format!("bad{k}.txt: line {n}: ")),
            "{k}: {}",
            errs[0]
        );
    }
    expect_input_error(
        "pinned-rod-body-key",
        &PINNED_LEAN.replace("type = \"pinned\"\n", "type = \"pinned\"\nbody = 1\n"),
        &[
            "rods[0].body",
            "a rod pinned to a body is not built in a TOML scenario",
        ],
    );
}

/// OpenFAST's md_float (its regression deck, a buoy of two rods on a free
/// body of no mass of its own, pitched 45 degrees, on no line): the deck's
/// static analysis floats it upright where its buoyancy carries it
/// (docs/method.md §15.11): the ballast rod (4 m across, 1 m, 21.5 t)
/// under water, the can (2 m across, 500 kg) in to the depth h with
/// rho (V_ballast + pi h) = 22 t: h = 2.8318 m, Rod1Sub = h / 5, the body's
/// reference point (1 m above the can's foot) at 1 - h, to the static
/// tolerance (1e-8); upright (Body1RY 0). MoorDyn starts its pitch decay
/// from the 45 degrees; this is where it decays to.
#[test]
fn openfasts_md_float_buoy_floats_upright_at_its_draft() {
    let d = scratch("md-float");
    let deck = d.join("moordyn.dat");
    std::fs::copy(
        repo_file("crates/stancf-cli/tests/fixtures/md-float-moordyn.txt"),
        &deck,
    )
    .unwrap();
    let out = d.join("out");
    let o = run_quiet(&deck, &out, &[]);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o).1);
    let (header, rows) = read_csv(&out.join("channels.csv"));
    let col = |name: &str| header.iter().position(|h| h == name).unwrap();
    let r = rows.last().unwrap();
    let rho = 1025.0;
    let ballast = PI * 4.0 * 1.0;
    let h = (22_000.0 / rho - ballast) / PI;
    eprintln!(
        "md_float: Rod1Sub {} (closed form {}), Body1PZ {} (closed form {}), Body1RY {}",
        r[col("Rod1Sub")],
        h / 5.0,
        r[col("Body1PZ")],
        1.0 - h,
        r[col("Body1RY")]
    );
    assert!(
        (r[col("Rod1Sub")] - h / 5.0).abs() < 1e-8,
        "{}",
        r[col("Rod1Sub")]
    );
    assert!(
        (r[col("Body1PZ")] - (1.0 - h)).abs() < 1e-8,
        "{}",
        r[col("Body1PZ")]
    );
    assert!(r[col("Body1RY")].abs() < 1e-6, "{}", r[col("Body1RY")]);
}

/// A deck's rod of zero length fixed in a body (`Body1`, NumSegs 0, at
/// body coordinates [1, 0, 0]) puts the points of the lines at its ends
/// where it is on the body, [1, 0, 0] in the body's axes and
/// [1, 0, -20] m at t = 0 (they were put at the body's reference point).
#[test]
fn a_zero_length_rod_on_a_body_holds_its_lines_where_it_is() {
    let d = scratch("zero-length-body-rod");
    let deck_text = body_rod_deck("-", "0")
        .replace(
            "2    conn      Free        15    0     -10   15    0     -10  0",
            "2    conn      Body1       1     0     0     1     0     0    0",
        )
        .replace(
            "2     rope       2        R2A       18        6",
            "2     rope       2        R2A       40        6",
        );
    let deck = write_scenario(&d, "zero-length.txt", &deck_text);
    let o = stancf(&["check", deck.to_str().unwrap()]);
    let (so, se) = text(&o);
    assert_eq!(o.status.code(), Some(0), "{se}");
    let line = so
        .lines()
        .find(|l| l.starts_with("point 4 "))
        .unwrap_or_default();
    assert!(
        line.ends_with("on free body 1 at [1, 0, 0] m in its axes, at [1, 0, -20] m"),
        "{so}"
    );
}
