//! Rods in systems (docs/interface.md, "Rods"): a TOML free rod rising
//! in still water as a body of its mass and added mass, and through the
//! surface, MoorDyn decks' free, body and zero-length rods with lines at
//! their ends held at the balance of their weights, OpenFAST's md_float
//! floating at its draft, and what `check` and summary.json say of them.
//! Refusals: `rod_refusals.rs`; channels: `rod_channels.rs`; pins:
//! `pinned_rods.rs`.

use crate::common::*;
use std::f64::consts::PI;

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
            "rod 2's RodOutputs \"p\": its file of MoorDyn's holds the node positions and \
             velocities (p, v) it asks for"
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
    let deck = copy_fixture(&d, "md-float-moordyn.txt", "moordyn.dat");
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

/// examples/moored-spar.toml (a hull 2 m across and 20 m long in a free
/// body, 29 t of ballast, on three chains; pushed): its static
/// equilibrium floats it upright at its draft, its hull displacing the
/// body's mass (the ballast and the hull's 20 t) and the chains' pull,
/// rho pi s = m + |F_z| / g with s the keel's depth (the surface cuts the
/// hull's side), to 1e-8 of it (the static tolerance); then it rocks: its
/// pitch changes sign at least 8 times in 40 s (a period near 8 s) and
/// its swing decays (the water's drag).
#[test]
fn the_moored_spar_example_floats_at_its_draft_and_rocks() {
    let d = scratch("moored-spar");
    let out = d.join("out");
    let o = run_quiet(&repo_file("examples/moored-spar.toml"), &out, &[]);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o).1);
    let (header, rows) = read_csv(&out.join("bodies.csv"));
    let col = |name: &str| header.iter().position(|h| h == name).unwrap();
    let first = &rows[0];
    let draft = 16.0 - first[col("z")];
    let displaced = 1025.0 * PI * draft;
    let mass = 29_000.0 + 20_000.0 + first[col("fz")].abs() / 9.81;
    let pitch: Vec<f64> = rows.iter().map(|r| r[col("pitch")]).collect();
    let crossings = pitch.windows(2).filter(|w| w[0] * w[1] < 0.0).count();
    let half = pitch.len() / 2;
    let swing = |p: &[f64]| p.iter().fold(0.0f64, |m, v| m.max(v.abs()));
    eprintln!(
        "moored spar: draft {draft:.4} m, displaced {displaced:.3} kg against {mass:.3} kg; \
         pitch crosses zero {crossings} times, swings {:.3} then {:.3} degrees",
        swing(&pitch[..half]),
        swing(&pitch[half..])
    );
    assert!(first[col("pitch")].abs() < 1e-9, "{}", first[col("pitch")]);
    assert!((displaced - mass).abs() < 1e-8 * mass, "{displaced} {mass}");
    assert!(crossings >= 8, "{crossings}");
    assert!(swing(&pitch[half..]) < swing(&pitch[..half]));
}
