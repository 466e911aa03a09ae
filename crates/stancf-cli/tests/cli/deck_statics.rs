//! A MoorDyn deck's static equilibrium as users check it (issue 35): the
//! forces on its points in MoorDyn's output channels, and a line with no
//! unique equilibrium refused saying which and why.

use crate::common::*;

/// Two chains in 50 m of water: from an anchor on the bed to a free
/// clump weight (500 kg, 0.02 m^3) and on to a coupled fairlead, with
/// the channels of every point's net force.
const CLUMP_DECK: &str = "--------------------- MoorDyn v2 input file ---------------------
Two chains and a clump weight
------------------------------ LINE TYPES ------------------------------
TypeName  Diam    Mass/m   EA        BA/-zeta  EI       Cd    Ca    CdAx  CaAx
(name)    (m)     (kg/m)   (N)       (N-s/-)   (N-m^2)  (-)   (-)   (-)   (-)
chain     0.05    12.0     2.0E7     -0.8      0        1.2   1.0   0.01  0.5
-------------------------------- POINTS --------------------------------
ID  Attachment  X        Y        Z        Mass    Volume  CdA    Ca
(#) (-)         (m)      (m)      (m)      (kg)    (m^3)   (m^2)  (-)
1   Fixed       -80.0    0.0      -50.0    0       0       0      0
2   Free        -20.0    0.0      -35.0    500     0.02    0      0
3   Coupled     20.0     0.0      -5.0     0       0       0      0
-------------------------------- LINES ---------------------------------
ID  LineType  AttachA  AttachB  UnstrLen  NumSegs  Outputs
(#) (name)    (#)      (#)      (m)       (-)      (-)
1   chain     1        2        62.0      15       -
2   chain     2        3        48.0      10       -
------------------------------- OPTIONS --------------------------------
0.001     dtM
9.81      g
50        WtrDpth
1025      WtrDnsty
------------------------------- OUTPUTS --------------------------------
Con1fx Con1fz Point2FX P2FY p2fz Con3FX Con3fz Con3T
------------------------- need this line -------------------------------
";

/// The columns of channels.csv and the rows of points.csv (t, point, x,
/// y, z, vx, vy, vz, fx, fy, fz) of a static run of `deck`.
fn run_channels(name: &str, deck: &str) -> (Vec<(String, f64)>, Vec<Vec<f64>>) {
    let dir = scratch(name);
    let path = write_scenario(&dir, "clump.txt", deck);
    let out = dir.join("out");
    let o = run_quiet(&path, &out, &[]);
    assert!(o.status.success(), "{}", text(&o).1);
    let (header, rows) = read_csv(&out.join("channels.csv"));
    assert_eq!(rows.len(), 1);
    let channels = header.into_iter().zip(rows[0].iter().copied()).collect();
    (channels, read_csv(&out.join("points.csv")).1)
}

/// MoorDyn's point channels `Con<n>FX`, `Point<n>FX`, `P<n>FX` (any
/// case) and `Con<n>T` are the net force on the point, `Fnet`: at a
/// fixed or coupled point without mass or volume the force of its lines
/// (points.csv's), at a free point in equilibrium zero (its lines'
/// force, weight and buoyancy balance, to the solve's tolerance 1e-10 of
/// the scaled rows: 1e-6 of its weight here).
#[test]
fn moordyn_point_force_channels_are_the_net_forces_on_the_points() {
    let (channels, points) = run_channels("point_force_channels", CLUMP_DECK);
    let value = |name: &str| {
        channels
            .iter()
            .find(|(n, _)| n == name)
            .unwrap_or_else(|| panic!("no channel {name}"))
            .1
    };
    let point = |id: f64| points.iter().find(|r| r[1] == id).unwrap();
    let (anchor, fairlead) = (point(1.0), point(3.0));
    assert_eq!(value("Con1fx"), anchor[8]);
    assert_eq!(value("Con1fz"), anchor[10]);
    assert_eq!(value("Con3FX"), fairlead[8]);
    assert_eq!(value("Con3fz"), fairlead[10]);
    let t3 = (fairlead[8].powi(2) + fairlead[9].powi(2) + fairlead[10].powi(2)).sqrt();
    assert!((value("Con3T") - t3).abs() <= 1e-12 * t3);
    let weight = 500.0 * 9.81;
    for c in ["Point2FX", "P2FY", "p2fz"] {
        assert!(value(c).abs() < 1e-6 * weight, "{c} = {} N", value(c));
    }
    // The clump's lines hold its wet weight.
    let clump = point(2.0);
    let wet = weight - 1025.0 * 0.02 * 9.81;
    assert!(
        (clump[10] - wet).abs() < 1e-6 * weight,
        "{} vs {wet}",
        clump[10]
    );
}

/// MoorDyn's r-test md_case5 (OpenFAST): 850 m of chain from an anchor
/// on the bed at 400 m to a fairlead at the surface, in 200 m of water.
/// Hanging from the fairlead and lying straight to the anchor it needs at
/// most L_max = XF + V0/W = 600 m (C20); the other 250 m would lie slack
/// on the bed in no determined shape. As the r-test has it, TmaxIC 0,
/// MoorDyn's `Init` lays it straight and slack between its ends: the deck
/// alone passes `check` and its run writes that start, the fairlead
/// holding nothing, with the reason (docs/method.md §13.7). Where the
/// deck asks for MoorDyn's initial conditions (TmaxIC 60), MoorDyn relaxes
/// from that start and settles nowhere either (MoorPy's case5.dat: its
/// Init ends with a remaining error, the fairlead at 0 N): the same start
/// is written, and `check` says what MoorDyn does (before 2026-11-30 it
/// was refused, a deck MoorDyn accepts). Its driver runs it on from there
/// (`moordyn_driver::r_test_md_case5_...`).
#[test]
fn a_line_longer_than_its_path_can_hold_has_no_unique_equilibrium() {
    let dir = scratch("overlong_line");
    let given = std::fs::read_to_string(repo_file(
        "crates/stancf-cli/tests/fixtures/md-case5-moordyn.txt",
    ))
    .unwrap();
    let with_ic = given.replace("0.0      TmaxIC", "60.0     TmaxIC");
    assert_ne!(with_ic, given);
    for (deck, moordyn) in [
        (&given, "the deck's TmaxIC is 0: no initial conditions"),
        (
            &with_ic,
            "MoorDyn relaxes from it for its initial conditions (TmaxIC 60 s)",
        ),
    ] {
        let path = write_scenario(&dir, "md_case5.dat", deck);
        let (stdout, stderr) = text(&stancf(&["check", path.to_str().unwrap()]));
        assert!(
            stdout.contains(moordyn) && stdout.contains("no static equilibrium"),
            "{stdout}\n{stderr}"
        );
        let start = dir.join("start");
        let o = run_quiet(&path, &start, &[]);
        assert!(o.status.success(), "{}", text(&o).1);
        let why = read_json(&start.join("summary.json"))["no_static_equilibrium"]
            .as_str()
            .unwrap()
            .to_string();
        assert!(
            why.starts_with("line 1: its 850 m") && why.contains("599.96") && why.contains("(C20)"),
            "{why}"
        );
        for row in read_tensions(&start.join("tensions.csv")) {
            assert_eq!((row[0], row[6]), (0.0, 0.0));
        }
    }
    // 590 m fit: the same deck runs.
    let dir = scratch("overlong_line_shortened");
    let path = write_scenario(&dir, "md.dat", &given.replace("850.00", "590.00"));
    let o = run_quiet(&path, &dir.join("out"), &[]);
    assert!(o.status.success(), "{}", text(&o).1);
}

/// A deck's `tScheme` (MoorDyn's integrator) is accepted and noted, and
/// without a `dtM` the step is MoorDyn's from its Courant number: CFL 2 pi
/// (L/N) sqrt(w/EA) = 0.4 x 2 pi x 0.25 m x sqrt(0.08 / 2e4) = 1.2566 ms
/// for the rope's segment, which `check` gives as the coupled run's step;
/// `check` and the run's warnings say both, and summary.json keeps them
/// as `notes`.
#[test]
fn a_decks_time_scheme_is_noted_and_its_step_taken_from_its_courant_number() {
    let d = scratch("deck-scheme-cfl");
    let deck = rope_deck("").replace("1.0e-4 dtM\n", "RK4 tScheme\n0.4 CFL\n");
    let file = write_scenario(&d, "rope.txt", &deck);
    let dt = 0.4 * 2.0 * std::f64::consts::PI * 0.25 * (0.08f64 / 2.0e4).sqrt();
    let (stdout, stderr) = text(&stancf(&["check", file.to_str().unwrap()]));
    let scheme = "tScheme RK4: MoorDyn's integrator is not used";
    let step = format!(
        "MoorDyn's step from CFL 0.4 is {} s",
        stancf::error::Sig(dt)
    );
    assert!(
        stdout.contains(scheme) && stdout.contains(&step),
        "{stdout}\n{stderr}"
    );
    let coupled = format!(
        "{} s, the step of a coupled run of this deck (P2, stable below",
        stancf::error::Sig(dt)
    );
    assert!(stdout.contains(&coupled), "{stdout}");
    let out = d.join("out");
    let o = run_quiet(&file, &out, &[]);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o).1);
    let notes = read_json(&out.join("summary.json"))["notes"].clone();
    let notes: Vec<String> = serde_json::from_value(notes).unwrap();
    assert!(notes.iter().any(|n| n.contains(scheme)), "{notes:?}");
    assert!(notes.iter().any(|n| n.contains(&step)), "{notes:?}");
}

/// A deck without `WtrDpth` takes MoorDyn's depth, that of its deepest
/// point (MoorDyn starts at 0 and lowers the depth to each point below
/// it; OpenFAST's glue-code decks leave it to the host): the rope's
/// points 1 m down give 1 m, noted; with no point under the surface
/// there is no depth to take, and the deck is refused saying so.
#[test]
fn a_deck_without_wtrdpth_takes_moordyns_depth_of_its_deepest_point() {
    let d = scratch("deck-depth");
    let deck = rope_deck("").replace("50 WtrDpth\n", "");
    let file = write_scenario(&d, "rope.txt", &deck);
    let (stdout, stderr) = text(&stancf(&["check", file.to_str().unwrap()]));
    assert!(stdout.contains("depth 1 m,"), "{stdout}\n{stderr}");
    assert!(
        stdout.contains("no WtrDpth: MoorDyn's rule, the depth of the deepest point, 1 m"),
        "{stdout}"
    );
    let above = deck.replace(" -1.0 0 0 0 0\n", " 1.0 0 0 0 0\n");
    assert_eq!(above.matches(" 1.0 0 0 0 0\n").count(), 2, "{above}");
    let file = write_scenario(&d, "above.txt", &above);
    let o = stancf(&["check", file.to_str().unwrap()]);
    assert_eq!(o.status.code(), Some(2));
    assert!(
        text(&o).1.contains("no point is under the surface"),
        "{}",
        text(&o).1
    );
}

/// MoorPy's decks name the water depth `depth` (its examples' sample.txt,
/// its tests' case8.dat): taken as WtrDpth, with a note that MoorDyn 2.7
/// does not read the name.
#[test]
fn a_moorpy_decks_depth_option_is_its_water_depth() {
    let d = scratch("deck-depth-moorpy");
    let deck = rope_deck("").replace("50 WtrDpth\n", "50 depth\n");
    let file = write_scenario(&d, "rope.txt", &deck);
    let o = stancf(&["check", file.to_str().unwrap()]);
    let (stdout, stderr) = text(&o);
    assert_eq!(o.status.code(), Some(0), "{stderr}");
    assert!(stdout.contains("depth 50 m,"), "{stdout}");
    assert!(
        stdout.contains("option depth: MoorPy's name for WtrDpth"),
        "{stdout}"
    );
}

/// A rope (2 kg/m, 20 mm: 1.678 kg/m wet) hanging 10 m in 5 segments from
/// a fixed point with a 50 kg clump at its foot: MoorDyn's node tension
/// channels `L1N<k>T` are its tension there, the weight below, T_k =
/// (50 + 1.678 s_k) g with s_k = 2k m from the foot (exact at the nodes: the
/// strain, linear in s, is within the elements' cubic), the top node's
/// the end's force; to 1e-8 of the weight (the static tolerance).
#[test]
fn moordyn_node_tension_channels_are_the_weight_hanging_below() {
    let deck = "--- MoorDyn v2 ---\nA clump on a rope\n--- LINE TYPES ---\n\
        TypeName Diam Mass/m EA BA/-zeta EI Cd Ca CdAx CaAx\n\
        (name) (m) (kg/m) (N) (N-s/-) (N-m^2) (-) (-) (-) (-)\n\
        rope 0.02 2.0 1.0e6 0 0 0 0 0 0\n--- POINTS ---\n\
        ID Attachment X Y Z Mass Volume CdA Ca\n(#) (-) (m) (m) (m) (kg) (m^3) (m^2) (-)\n\
        1 Fixed 0 0 -5 0 0 0 0\n2 Free 0 0 -15 50 0 0 0\n--- LINES ---\n\
        ID LineType AttachA AttachB UnstrLen NumSegs Outputs\n(#) (name) (#) (#) (m) (-) (-)\n\
        1 rope 2 1 10 5 -\n--- OPTIONS ---\n1.0e-3 dtM\n9.81 g\n50 WtrDpth\n\
        --- OUTPUTS ---\nL1N1T\nL1N3T\nL1N5T\nEND\n--- need this line ---\n";
    let (channels, _) = run_channels("node_tensions", deck);
    let wet = 2.0 - 1025.0 * std::f64::consts::PI * 0.01 * 0.01;
    for (k, (name, value)) in channels.iter().skip(1).enumerate() {
        let node = [1.0, 3.0, 5.0][k];
        let want = (50.0 + wet * 2.0 * node) * 9.81;
        eprintln!("{name}: {value} N against {want} N");
        assert!((value - want).abs() < 1e-8 * want, "{name}: {value} {want}");
    }
}

/// MoorDyn's old 12-column point rows (`X Y Z Mass Volume FX FY FZ CdA
/// Ca`) give a free point a constant force (Point.cpp's `pointF`): at the
/// static equilibrium the two ropes hold it against that force and its
/// weight, their pull on it (points.csv) (-30, 0, 5 + 0.5 g) N to the
/// static solve's tolerance; a force on a point the deck holds is refused
/// naming its row.
#[test]
fn an_old_point_rows_constant_force_acts_on_its_free_point() {
    let deck = |second: &str| {
        format!(
            "--- MoorDyn input file ---\nTwo ropes and a weight pushed sideways\n\
             --- LINE TYPES ---\n\
             TypeName Diam Mass/m EA BA/-zeta EI Cd Ca CdAx CaAx\n\
             (name) (m) (kg/m) (N) (N-s/-) (N-m^2) (-) (-) (-) (-)\n\
             rope 0.01 0.08 2.0e4 0 0 0 0 0 0\n\
             --- POINTS ---\n\
             ID Attachment X Y Z Mass Volume FX FY FZ CdA Ca\n\
             (#) (-) (m) (m) (m) (kg) (m^3) (N) (N) (N) (m^2) (-)\n\
             1 Fixed -1.0 0.0 -1.0 0 0 0 0 0 0 0\n\
             {second}\n\
             3 Fixed 1.0 0.0 -1.0 0 0 0 0 0 0 0\n\
             --- LINES ---\n\
             ID LineType AttachA AttachB UnstrLen NumSegs Outputs\n\
             (#) (name) (#) (#) (m) (-) (-)\n\
             1 rope 1 2 1.05 8 -\n\
             2 rope 2 3 1.05 8 -\n\
             --- OPTIONS ---\n\
             9.81 g\n50 WtrDpth\n--- need this line ---\n"
        )
    };
    let d = scratch("point-force");
    std::fs::write(
        d.join("deck.txt"),
        deck("2 Free 0.0 0.0 -1.0 0.5 0 30.0 0 -5.0 0 0"),
    )
    .unwrap();
    let out = d.join("out");
    let o = run_quiet(&d.join("deck.txt"), &out, &[]);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o).1);
    let (h, rows) = read_csv(&out.join("points.csv"));
    let col = |n: &str| h.iter().position(|c| c == n).unwrap();
    let p = rows.iter().find(|r| r[col("point")] == 2.0).unwrap();
    let want = [-30.0, 0.0, 5.0 + 0.5 * 9.81];
    for (i, name) in ["fx", "fy", "fz"].iter().enumerate() {
        assert!(
            (p[col(name)] - want[i]).abs() < 1e-6,
            "{name}: {} against {}",
            p[col(name)],
            want[i]
        );
    }
    std::fs::write(
        d.join("held.txt"),
        deck("2 Fixed 0.0 0.0 -1.0 0 0 30.0 0 0 0 0"),
    )
    .unwrap();
    refused_by_check_and_run(
        &d.join("held.txt"),
        &d.join("never"),
        &[
            "line 11",
            "point 2 has a constant force (FX FY FZ) but is not free",
        ],
        &[],
    );
}

/// OpenFAST's r-test deck md_bodyDrag: a 10 kg body (no volume) set 5 m
/// over its anchor on a spring line of 4.5 m (EA 500 N, 1.95 kg/m wet).
/// The line cannot hold it up, so it falls past its anchor and hangs
/// below it on the taut line, stretched by its weight and the line's:
///
///   z = z_anchor - L - (P L + w L^2 / 2) / EA = -10.770207 m
///
/// (MoorDyn 2.7's initial conditions: -10.7702). The catenary network
/// passes the vertical line through its slack, folded state (docs/
/// method.md §11.6, (M32d)); before it, the static solve ended with the
/// body on top of the line held up as a strut in compression (174 N,
/// warned of). The same for a free point of the same weight. The claim:
/// the closed form to 1e-8 m (the straight line's quadratic stretch is
/// in the cubic elements' span, so what remains is the solve's
/// tolerance), and no compression warned of.
#[test]
fn a_weight_set_over_its_anchor_falls_past_it_and_hangs_below() {
    let deck = |object: &str, point: &str| {
        format!(
            "A weight set over its anchor\n\
             --- LINE TYPES ---\n\
             TypeName Diam MassDenInAir EA BA/-zeta EI Can Cat Cdn Cdt\n\
             (-) (m) (kg/m) (N) (Pa-s/-) (n-m^2) (-) (-) (-) (-)\n\
             spring 0.1 10.0 500.0 -0.4 0.0 0.0 0.0 0.0 0.00\n\
             {object}\
             --- POINTS ---\n\
             ID Attachment X Y Z M V CdA CA\n\
             (-) (-) (m) (m) (m) (kg) (m^3) (m^2) (-)\n\
             {point}\n\
             2 Fixed 0.0 0 -5 0 0 0 0\n\
             --- LINES ---\n\
             ID LineType AttachA AttachB UnstrLen NumSegs LineOutputs\n\
             (-) (-) (-) (-) (m) (-) (-)\n\
             1 spring 1 2 4.5 1 -\n\
             --- SOLVER OPTIONS ---\n\
             9.81 g\n0.002 dtM\n15 WtrDpth\n--- need this line ---\n"
        )
    };
    let body = "--- BODIES ---\n\
                ID Attachment X0 Y0 Z0 r0 p0 y0 Mass CG* I* Volume CdA* Ca\n\
                (#) (-) (m) (m) (m) (deg) (deg) (deg) (kg) (m) (kg-m^2) (m^3) (m^2) (-)\n\
                1 free 0 0 0 0 -90 0 1e1 0 5 0 0.1 0\n";
    let (g, rho, length, ea) = (9.81, 1025.0, 4.5, 500.0);
    let w = (10.0 - rho * std::f64::consts::PI / 4.0 * 0.1f64.powi(2)) * g;
    let p = 10.0 * g;
    let z = -5.0 - length - (p * length + 0.5 * w * length * length) / ea;
    let d = scratch("weight-over-anchor");
    for (name, deck_text, table, column) in [
        (
            "body",
            deck(body, "1 Body1 0.0 0 0 0 0 0 0"),
            "bodies.csv",
            "z",
        ),
        (
            "point",
            deck("", "1 Free 0.0 0 0 10 0 0 0"),
            "points.csv",
            "z",
        ),
    ] {
        let path = write_scenario(&d, &format!("{name}.txt"), &deck_text);
        let out = d.join(format!("out-{name}"));
        let o = run_quiet(&path, &out, &[]);
        assert_eq!(o.status.code(), Some(0), "{}", text(&o).1);
        assert!(!text(&o).1.contains("shortens"), "{}", text(&o).1);
        let (h, rows) = read_csv(&out.join(table));
        let col = h.iter().position(|c| c == column).unwrap();
        let got = rows[0][col];
        eprintln!("{name}: z = {got} m against {z} m");
        assert!((got - z).abs() < 1e-8, "{name}: z = {got} against {z}");
    }
}

/// The catenary network's stiffness continuation (docs/method.md §11.6):
/// a 1000 kg body hung level by three equal ropes of 30 m (EA 1e8 N, as
/// dense as the water, so they hang straight) from the corners of a
/// triangle about its centre, pushed aside by 3000 N. Its equilibrium is
/// the pendulum's: the ropes parallel at tan(theta) = F / W, each
/// stretched by |F + W| / (3 EA), the body at
/// x = L (1 + eps) sin(theta), z = -L (1 + eps) cos(theta); the closed
/// form to 1e-8 m (the ropes' stretch and the straight line are what the
/// elements hold). Before, the network's Newton steps along the stiff
/// ropes' tangent crept (|G| stalled at 2.8e3 N), the path started from
/// the ropes hanging plumb and failed at load factor 0 (exit 3).
#[test]
fn a_weight_pushed_aside_on_stiff_ropes_rests_at_its_pendulum_angle() {
    let (mass, push, length, ea, g) = (1000.0f64, 3000.0f64, 30.0f64, 1.0e8f64, 9.81f64);
    let diameter = (4.0 * 2.0 / (1025.0 * std::f64::consts::PI)).sqrt();
    let sc = weight_on_three_ropes(diameter, ea, &format!("force = [{push:?}, 0.0, 0.0]"));
    let d = scratch("stiff-ropes-pushed");
    let path = write_scenario(&d, "pushed.toml", &sc);
    let out = d.join("out");
    let o = run_quiet(&path, &out, &[]);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o).1);
    let (h, rows) = read_csv(&out.join("bodies.csv"));
    let col = |n: &str| h.iter().position(|c| c == n).unwrap();
    let weight = mass * g;
    let theta = (push / weight).atan();
    let eps = push.hypot(weight) / (3.0 * ea);
    let want = [
        length * (1.0 + eps) * theta.sin(),
        -length * (1.0 + eps) * theta.cos(),
    ];
    let got = [rows[0][col("x")], rows[0][col("z")]];
    eprintln!("body at {got:?} m against {want:?} m");
    for k in 0..2 {
        assert!((got[k] - want[k]).abs() < 1e-8, "{got:?} against {want:?}");
    }
}

/// A 10 kg weight set on a frictionless bed of slope 0.2 (z = -30 + 0.2 x)
/// at x = 10 m, on a neutrally buoyant rope of 32 m (EA 1e6 N) from a
/// fixed point at (0, 0, -5) m, 29.7 m away: the rope is slack, and the
/// weight slides down the slope until the rope is straight (its only
/// frictionless equilibrium: a weightless rope bends only where a force
/// acts, and the plane bed cannot bend it along itself). The catenary
/// network slides it there first (docs/method.md (M32e)); before, the
/// load path stalled at load factor 0 and the pseudo-transient
/// continuation ended on a rope folded in compression 29.1 m long. The
/// equilibrium: the weight 25 m down the slope, the rope 32 m long to its
/// stretch T L / EA (1 mm; the bed's penalty lets the weight 5 cm into
/// it), and the anchor pulling with T such that the rope's pull up the
/// slope carries the weight's share down it, m g sin(theta) = 19.24 N,
/// to 1e-6.
#[test]
fn a_weight_on_a_slope_slides_until_its_slack_rope_is_straight() {
    let d = scratch("slope-slide");
    let wet = 1025.0 * std::f64::consts::PI / 4.0 * 0.02 * 0.02;
    let sc = format!(
        "title = \"a weight on a slope\"\n\
         [[line_types]]\nname = \"rope\"\ndiameter = 0.02\nmass_per_length = {wet:?}\nea = 1.0e6\n\
         {}{}[[lines]]\nid = 1\ntype = \"rope\"\nlength = 32.0\nelements = 16\na = 1\nb = 2\n\
         [water]\ndepth = 30.0\ndensity = 1025.0\n[water.seabed]\nslope = [0.2, 0.0]\n\
         [analysis]\ntype = \"static\"\n",
        toml_point(1, "fixed", [0.0, 0.0, -5.0]),
        toml_point(2, "free", [10.0, 0.0, -28.0]) + "mass = 10.0\n",
    );
    let (p, ends) = solved_weight_and_ends(&d, "slope.toml", &sc);
    let a = [0.0, 0.0, -5.0];
    let chord = ((p[0] - a[0]).powi(2) + (p[1] - a[1]).powi(2) + (p[2] - a[2]).powi(2)).sqrt();
    let tension = ends[0][6];
    assert!(p[0] < -15.0, "the weight is at {p:?}");
    assert!(
        (chord - 32.0 * (1.0 + tension / 1e6)).abs() < 2e-3,
        "chord {chord} m"
    );
    // The whole rope's balance along the frictionless slope: the anchor's
    // pull (the force of end A on its point, down the slope) carries the
    // weight's share down it.
    let norm = (1.0f64 + 0.04).sqrt();
    let downhill = [-1.0 / norm, 0.0, -0.2 / norm];
    let pull: f64 = (0..3).map(|c| ends[0][3 + c] * downhill[c]).sum();
    let share = 10.0 * 9.81 * 0.2 / norm;
    assert!(
        (pull - share).abs() < 1e-6 * share,
        "{pull} N down the slope against {share} N"
    );
}

/// MoorDyn's seafloor.txt as a scenario: a 10 kg bob at the end of a
/// neutrally buoyant rope of 32 m (d 0.1 m, EA 1e9 N) from a fixed point
/// at the surface, set on a frictionless bed of slope 0.2 (z = -30 +
/// 0.2 x) at x = 10 m. The rope is slack there; the bob slides down the
/// slope until it is straight, reaching the bed at a steep angle, so its
/// own Gauss points stay clear of the bed and the bob rests on its own
/// push (docs/method.md (W42p), k_p = kBot d l / 2 = 2.4e5 N/m). Before
/// it, nothing held the bob up and the static solve ended in exit 3.
/// The bob's balance against the closed form: along the slope the rope's
/// pull carries the weight's share, (F_B + W) . t = 0; across it the
/// bed pushes N = -(F_B + W) . n, and the bob is in by N / k_p + delta /
/// 2 ((W41), delta = 1e-4 m): both to 1e-6 of the weight (the rope's
/// stretch, T / EA = 5e-8, and the bed's give, 0.4 mm, move the
/// directions by less than 1e-5; these are balances at the solve's
/// point, not the directions').
#[test]
fn a_pendulums_bob_rests_on_a_slope_on_its_own_push() {
    let d = scratch("bob-on-slope");
    let (mass, g, k, diameter, elements, length) = (10.0, 9.81, 3e6, 0.1, 20.0, 32.0);
    let neutral = 1000.0 * std::f64::consts::PI / 4.0 * diameter * diameter;
    let sc = format!(
        "title = \"a bob on a slope\"\n\
         [[line_types]]\nname = \"rope\"\ndiameter = {diameter:?}\nmass_per_length = {neutral:?}\n\
         ea = 1.0e9\n\
         {}{}[[lines]]\nid = 1\ntype = \"rope\"\nlength = {length:?}\nelements = {elements}\n\
         a = 1\nb = 2\n\
         [water]\ndepth = 30.0\ndensity = 1000.0\n[water.seabed]\nstiffness = {k:?}\n\
         slope = [0.2, 0.0]\n[analysis]\ntype = \"static\"\n",
        toml_point(1, "fixed", [0.0, -1.0, 0.0]),
        toml_point(2, "free", [10.0, -1.0, -28.0]) + &format!("mass = {mass:?}\n"),
    );
    let (bob, ends) = solved_weight_and_ends(&d, "bob.toml", &sc);
    let pull = [ends[1][3], ends[1][4], ends[1][5]];
    let weight = mass * g;
    let norm = (1.0f64 + 0.04).sqrt();
    let (t, n) = (
        [1.0 / norm, 0.0, 0.2 / norm],
        [-0.2 / norm, 0.0, 1.0 / norm],
    );
    let net = [pull[0], pull[1], pull[2] - weight];
    let along: f64 = (0..3).map(|c| net[c] * t[c]).sum();
    let push: f64 = -(0..3).map(|c| net[c] * n[c]).sum::<f64>();
    let depth_in = n[2] * (-30.0 + 0.2 * bob[0] - bob[2]);
    let stiffness = k * diameter * 0.5 * length / elements;
    let want = push / stiffness + 0.5e-3 * diameter;
    eprintln!(
        "bob at {bob:?}: along the slope {along:.3e} N, push {push:.6} N, in by {depth_in:.9e} m \
         against {want:.9e} m"
    );
    assert!(bob[0] < 0.0, "the bob slid down the slope: {bob:?}");
    assert!(along.abs() < 1e-6 * weight, "{along} N along the slope");
    assert!(
        (depth_in - want).abs() * stiffness < 1e-6 * weight,
        "in by {depth_in} m against {want} m"
    );
}

/// Runs the static scenario `sc` (written to `file` in `d`), which must
/// reach its equilibrium by the load path (exit 0, no pseudo-transient
/// continuation): the position of its second point (the weight) and the
/// rows of tensions.csv.
fn solved_weight_and_ends(d: &std::path::Path, file: &str, sc: &str) -> ([f64; 3], Vec<Vec<f64>>) {
    let path = write_scenario(d, file, sc);
    let out = d.join("out");
    let o = run_quiet(&path, &out, &[]);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o).1);
    assert!(!text(&o).1.contains("pseudo-transient"), "{}", text(&o).1);
    let (h, rows) = read_csv(&out.join("points.csv"));
    let col = |n: &str| h.iter().position(|c| c == n).unwrap();
    let weight = [rows[1][col("x")], rows[1][col("y")], rows[1][col("z")]];
    (weight, read_tensions(&out.join("tensions.csv")))
}

/// A 500 kg clump weight (no volume) between two chains lying on a flat,
/// frictionless bed at 100 m, the second chain rising to a point 20 m
/// under the surface: the clump comes to rest on the bed on its own push
/// (docs/method.md (W42p)), k_p = kBot d (l_1 + l_2) / 2 over the chains'
/// end elements (7.75 and 8.5 m). Its balance is exact whatever the
/// chains' Gauss points carry near it: the push is minus its weight and
/// its lines' pull, so it is in the bed by (m g + F_z) / k_p + delta / 2
/// (delta = 1e-3 d), and nothing holds it along the bed, F_x = 0; both
/// to 1e-6 of its weight (the static solve's residual). Measured: 2.186
/// mm in. Before (W42p) the same clump sank 17.3 mm, carried through the
/// chains' Gauss points beside it (their ends lifting it by its whole
/// weight, 4905 N; 228fc80).
#[test]
fn a_clump_weight_rests_on_the_bed_between_two_chains() {
    let d = scratch("clump-on-bed");
    let (mass, g, diameter, k) = (500.0, 9.81, 0.1, 3e6);
    let chain = "[[line_types]]\nname = \"chain\"\ndiameter = 0.1\nmass_per_length = 100.0\n\
                 ea = 5.0e8\n";
    let line = |id: u32, length: f64, a: u32, b: u32| {
        format!(
            "[[lines]]\nid = {id}\ntype = \"chain\"\nlength = {length:?}\nelements = 20\n\
             a = {a}\nb = {b}\n"
        )
    };
    let sc = format!(
        "title = \"a clump on the bed\"\n{chain}{}{}{}{}{}\
         [water]\ndepth = 100.0\ndensity = 1025.0\n[analysis]\ntype = \"static\"\n",
        toml_point(1, "fixed", [-120.0, 0.0, -100.0]),
        toml_point(2, "fixed", [100.0, 0.0, -20.0]),
        toml_point(3, "free", [0.0, 0.0, -100.0]) + &format!("mass = {mass:?}\n"),
        line(1, 155.0, 1, 3),
        line(2, 170.0, 3, 2),
    );
    let path = write_scenario(&d, "clump.toml", &sc);
    let out = d.join("out");
    let o = run_quiet(&path, &out, &[]);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o).1);
    let (h, rows) = read_csv(&out.join("points.csv"));
    let col = |n: &str| h.iter().position(|c| c == n).unwrap();
    let clump = &rows[2];
    let weight = mass * g;
    let (pull_x, pull_z) = (clump[col("fx")], clump[col("fz")]);
    let stiffness = k * diameter * 0.5 * (155.0 + 170.0) / 20.0;
    let want = (weight - pull_z) / stiffness + 0.5e-3 * diameter;
    let sunk = -100.0 - clump[col("z")];
    eprintln!("clump in by {sunk:.9e} m against {want:.9e} m, pull along the bed {pull_x:e} N");
    assert!(pull_x.abs() < 1e-6 * weight, "{pull_x} N along the bed");
    assert!(
        (sunk - want).abs() * stiffness < 1e-6 * weight,
        "in by {sunk} m against {want} m"
    );
}
