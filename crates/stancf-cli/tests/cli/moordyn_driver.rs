//! MoorDyn driver files (OpenFAST's `md_driver.inp` and `*.dvr`): the
//! deck they name runs in their sea, for their TMax, from MoorDyn's start
//! (docs/interface.md, "MoorDyn driver files").

use crate::common::*;

/// A MoorDyn driver file (the layout of OpenFAST's r-test drivers) for
/// `deck`, run `t_max` s at coupling step `dt_c`, with InputsMode `mode`,
/// InputsFile `inputs` and the initial platform row `platform`.
fn driver(
    deck: &str,
    (t_max, dt_c): (f64, f64),
    (mode, inputs): (u8, &str),
    platform: &str,
) -> String {
    format!(
        "MoorDyn driver input file\nanother comment line\n\
         ---------------------- ENVIRONMENTAL CONDITIONS -------------------------------\n\
         9.80665            Gravity          - Gravity (m/s^2)\n\
         1025.0             rhoW             - Water density (kg/m^3)\n\
         75.0               WtrDpth          - Water depth (m)\n\
         ---------------------- MOORDYN ------------------------------------------------\n\
         \"{deck}\"          MDInputFile      - Primary MoorDyn input file name (quoted string)\n\
         \"driver\"          OutRootName      - The name which prefixes all generated files\n\
         {t_max}             TMax             - Total run time (s)\n\
         {dt_c}              dtC              - TimeInterval for the simulation (sec)\n\
         {mode}              InputsMode       - MoorDyn coupled object inputs (switch)\n\
         \"{inputs}\"        InputsFile       - Filename for the MoorDyn inputs file\n\
         0                   NumTurbines      - Number of wind turbines (-)\n\
         ---------------------- Initial Positions --------------------------------------\n\
         ref_X    ref_Y    surge_init   sway_init  heave_init  roll_init  pitch_init   yaw_init\n\
         (m)      (m)        (m)          (m)        (m)       (rad)       (rad)        (rad)\n\
         {platform}\n\
         END of driver input file\n"
    )
}

const AT_REST: &str = "0 0 0 0 0 0 0 0";

/// Writes `contents` as the driver file `name` in `d` and runs it into
/// `d/out`, which it returns (the run must succeed).
fn run_driver(d: &std::path::Path, name: &str, contents: &str) -> std::path::PathBuf {
    let dvr = write_scenario(d, name, contents);
    let out = d.join("out");
    let o = run_quiet(&dvr, &out, &[]);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o).1);
    out
}

/// Runs the r-test deck `fixture` (copied as `deck`) from a driver of
/// `t_max` s at `dt_c` with its objects held, and reads its channels.csv.
fn r_test_channels(
    name: &str,
    fixture: &str,
    deck: &str,
    (t_max, dt_c): (f64, f64),
) -> (Vec<String>, Vec<Vec<f64>>) {
    let d = scratch(name);
    copy_fixture(&d, fixture, deck);
    let out = run_driver(
        &d,
        "md_driver.inp",
        &driver(deck, (t_max, dt_c), (0, ""), AT_REST),
    );
    read_csv(&out.join("channels.csv"))
}

/// OpenFAST's r-test md_horizontal deck (fixture md-horizontal-moordyn.txt:
/// a free rod of 10 m, 2 m across and 3250 kg/m, level 5 m down, a dummy
/// line between two fixed points): its rod sinks level (TmaxIC 0: from
/// the deck's pose) under
/// its net weight F = (3250 - 1025 pi) g 10 m, its mass and added mass
/// M = (3250 + 1025 pi) 10 m, against its transverse drag
/// k v^2 = 1/2 rho Cd D L v^2: z(t) = z0 - (M / k) ln cosh(t sqrt(k F) / M),
/// to 1e-8 m over 20 s at the driver's step of 0.01 s (the Galerkin
/// step's error at this step is far below; the rest is the step's Newton
/// tolerance on a fall of 10 m). MoorDyn-F's r-test output,
/// driver.MD.out, is -5.0226186 m at 1 s and -9.9659360 at 16 s; the
/// closed form's -5.02261859 and -9.96593596.
#[test]
fn openfasts_md_horizontal_driver_sinks_its_rod_as_its_drag_closed_form() {
    let (header, rows) = r_test_channels(
        "driver-horizontal",
        "md-horizontal-moordyn.txt",
        "horizontal.dat",
        (20.0, 0.01),
    );
    let col = |n: &str| header.iter().position(|h| h == n).unwrap();
    // dtOut 0.1 s: a row every 10 steps, t = 0 to 20 s.
    assert_eq!(rows.len(), 201);
    let g = 9.80665;
    let (rho, a, l) = (1025.0, std::f64::consts::PI, 10.0);
    let f = (3250.0 - rho * a) * g * l;
    let m = (3250.0 + rho * a) * l;
    let k = 0.5 * rho * 0.6 * 2.0 * l;
    let mut worst: f64 = 0.0;
    for r in &rows {
        let t = r[col("t")];
        let z = -5.0 - m / k * (t * (k * f).sqrt() / m).cosh().ln();
        worst = worst.max((r[col("ROD1PZ")] - z).abs());
        assert_eq!(r[col("ROD1PX")], -5.0);
        assert!((r[col("ROD1RY")] - 90.0).abs() < 1e-9);
    }
    assert!(worst < 1e-8, "worst {worst:e} m");
}

/// A deck with TmaxIC 0 starts each line in its elastic catenary between
/// the deck's points (MoorDyn's start without initial conditions), not
/// straight: a chain of 120 m hung between two fixed points 100 m apart
/// stays within 2 mm of its start over 2 s (the catenary is the line's
/// equilibrium but for the 12 elements' discretization, of the order of
/// (h/L)^4 L); from the straight start it would fall metres. The t = 0
/// row gives the catenary's fairlead tension (C12) (MoorDyn's output has
/// zero there, docs/method.md §13.7): the tension the line holds, on
/// average over the 2 s, to 1e-4 (measured 2e-6); the 12 cubics'
/// strain, which cannot follow the catenary's between the nodes
/// (docs/method.md (M32b)), sets it swinging about it by up to 9 % at
/// first (EA 7e8 N), damped by its BA.
#[test]
fn a_tmaxic_0_deck_starts_its_lines_in_their_catenaries() {
    let d = scratch("driver-catenary");
    let deck = "hung chain
------------------------- LINE TYPES -------------------------------------------
LineType  Diam  MassDen  EA      BA/-zeta  EI   Cd   Ca   CdAx  CaAx
(-)       (m)   (kg/m)   (N)     (N-s/-)   (-)  (-)  (-)  (-)   (-)
chain     0.1   100.0    7.0e8   -0.5      0    1.2  1.0  0.4   0.5
----------------------- POINTS -------------------------------------------------
ID  Attachment  X      Y    Z      M  V  CdA  CA
(-) (-)         (m)    (m)  (m)    (kg) (m^3) (m^2) (-)
1   Fixed       -50    0    -20    0  0  0    0
2   Fixed       50     0    -20    0  0  0    0
-------------------------- LINES -----------------------------------------------
ID  LineType  AttachA  AttachB  UnstrLen  NumSegs  Outputs
(-) (-)       (-)      (-)      (m)       (-)      (-)
1   chain     1        2        120.0     12       -
-------------------------- OPTIONS ---------------------------------------------
0.01     dtM
200      WtrDpth
0        TmaxIC
------------------------------ OUTPUTS -----------------------------------------
L1N6PZ
FairTen1
--------------------------- need this line -------------------------------------
";
    write_scenario(&d, "chain.dat", deck);
    let out = run_driver(
        &d,
        "md_driver.inp",
        &driver("chain.dat", (2.0, 0.01), (0, ""), AT_REST),
    );
    let (header, rows) = read_csv(&out.join("channels.csv"));
    let z = header.iter().position(|h| h == "L1N6PZ").unwrap();
    let z0 = rows[0][z];
    // The inextensible catenary's sag, a (cosh(50 / a) - 1) with
    // 2 a sinh(50 / a) = 120 m: 29.2344 m; the chain's stretch under its
    // 42 kN (6e-5) adds about a centimetre.
    assert!(
        (z0 + 20.0 + 29.2344).abs() < 0.05,
        "the middle starts at {z0} m"
    );
    let drift = rows.iter().map(|r| (r[z] - z0).abs()).fold(0.0, f64::max);
    assert!(drift < 2e-3, "the middle moved {drift} m from its catenary");
    let ten = header.iter().position(|h| h == "FairTen1").unwrap();
    let t0 = rows[0][ten];
    let mean = rows.iter().map(|r| r[ten]).sum::<f64>() / rows.len() as f64;
    assert!(
        (mean - t0).abs() < 1e-4 * t0,
        "t = 0: {t0} N, on average {mean} N"
    );
}

/// OpenFAST's r-test md_case5: an 850 m chain from an anchor on the bed
/// 400 m off to a fairlead 200 m up, longer than the 600 m that can hang
/// and lie straight (C20), with TmaxIC 0. MoorDyn-F finds no catenary and
/// lays it straight between its ends; stancf starts it the same way, its
/// segments shortened and slack (a deck's lines carry no compression,
/// (M4a)): the fairlead holds nothing at t = 0, then the falling chain
/// pulls (MoorDyn-F's driver.MD.out: 2.0800e5 N at 0.1 s, 7.2697e5 N at
/// 2 s).
#[test]
fn r_test_md_case5_an_overlong_chain_starts_straight_and_slack_as_moordyn_lays_it() {
    let (header, rows) = r_test_channels(
        "driver-case5",
        "md-case5-moordyn.txt",
        "case5.dat",
        (2.0, 0.01),
    );
    let ten = header.iter().position(|h| h == "FAIRTEN1").unwrap();
    assert_eq!(rows[0][ten], 0.0);
    // Pulling, and less than the chain's wet weight, 4.97 MN.
    for r in &rows[1..] {
        assert!(r[ten] > 0.0 && r[ten] < 4.97e6, "{r:?}");
    }
}

/// OpenFAST's r-test md_case2 (TmaxIC 0): a 500 m chain from an anchor on
/// the bed to a free point 400 m off and 100 m up, exactly as long as its
/// "L" (XF + ZF, past L_max of (C20) by its stretch), and a rope stretched
/// 18 % from that point to a fixed one. MoorDyn finds no catenary for the
/// chain and lays it straight, though its end is free, so at first only
/// the rope pulls the point, up along its chord: MoorDyn-F's
/// driver.MD.out has the point 2.72 m higher at 0.1 s (Line1NBPZ
/// -97.279 m) and the rope at 5.4931e8 N. A chain hung from the point
/// would pull it down instead (6.4 m down at 0.1 s). The release of the
/// stretch is a wave front, which the lumped masses of MoorDyn's 24 and 10
/// segments and these elements carry differently: 0.15 m (5 % of the
/// rise) and 1 % of the tension allow for that; the step, 0.005 s, is
/// converged (0.001 s gives the same to 1 mm).
#[test]
fn r_test_md_case2_a_chain_to_a_free_point_as_long_as_its_l_starts_straight() {
    let (header, rows) = r_test_channels(
        "driver-case2",
        "md-case2-moordyn.txt",
        "case2.dat",
        (0.1, 0.005),
    );
    let column = |name: &str| header.iter().position(|h| h == name).unwrap();
    let last = rows.last().unwrap();
    assert!((last[column("t")] - 0.1).abs() < 1e-9);
    let z = last[column("Line1NBPZ")];
    assert!((z - -97.279).abs() < 0.15, "the free point at z = {z} m");
    let tension = last[column("FAIRTEN2")];
    assert!(
        (tension / 5.4931e8 - 1.0).abs() < 0.01,
        "the rope pulls {tension} N"
    );
}

/// MoorDyn's BodiesAndRods.dat's buoyant cable (its lines 4 to 6 over
/// free points 8 and 9, here 1 to 3 over 2 and 3, its body end fixed), started from its catenaries
/// (TmaxIC 0): each line's closed form meets the free points where the
/// deck puts them, so the lines start joined there, exactly (the closed
/// form's far end carries 1e-14 m of round-off, which the start leaves
/// out), and the run goes on.
#[test]
fn lines_started_from_their_catenaries_meet_at_their_free_points() {
    let d = scratch("driver-joined");
    let deck = "a buoyant cable over two free points
------------------------- LINE TYPES --------------------------------------------------
LineType  Diam    MassDenInAir    EA       BA/-zeta    EI    Can   Cat  Cdn   Cdt
(-)       (m)       (kg/m)        (N)      (Pa-s/-)  (n-m^2) (-)   (-)  (-)   (-)
cable     0.175      40       751e6         -0.8      0.0    1.0   0.0  1.2   0.008
buoyancy  0.26       40       751e6         -0.8      0.0    1.0   0.0  1.2   0.008
----------------------- POINTS ----------------------------------------------
Node      Type      X        Y         Z        M        V         CdA   CA
(-)       (-)      (m)      (m)       (m)      (kg)     (m^3)     (m^2)  (-)
1         Fixed   -200       0      -70         0        0         0     0
2         Free     -60       0      -30         0        0         0     0
3         Free     -20       0      -30         0        0         0     0
4         Fixed      0       0        0         0        0         0     0
-------------------------- LINES -------------------------------------------------
Line     LineType NodeA     NodeB  UnstrLen  NumSegs     Flags/Outputs
(-)      (-)       (-)       (-)   (m)         (-)          (-)
1        cable      1         2    200          12           -
2      buoyancy     2         3     50           6           -
3        cable      3         4     50           6           -
-------------------------- SOLVER OPTIONS---------------------------------------------------
0.0005   dtM          - time step to use in mooring integration
70       WtrDpth      - water depth
0.0      TmaxIC       - no initial conditions
------------------------------ OUTPUTS -----------------------------------------------------
--------------------------- need this line -------------------------------------------------
";
    write_scenario(&d, "cable.dat", deck);
    let out = run_driver(
        &d,
        "md_driver.inp",
        &driver("cable.dat", (0.2, 0.01), (0, ""), AT_REST),
    );
    let (header, rows) = read_csv(&out.join("points.csv"));
    let col = |n: &str| header.iter().position(|h| h == n).unwrap();
    let start = rows
        .iter()
        .find(|r| r[col("t")] == 0.0 && r[col("point")] == 2.0)
        .unwrap();
    assert_eq!(
        [start[col("x")], start[col("y")], start[col("z")]],
        [-60.0, 0.0, -30.0]
    );
}

/// InputsMode 1: the coupled point follows the driver's time series as
/// MoorDyn's driver prepares it, sampled at dtC and smoothed forward and
/// back (docs/interface.md (D1)): a point moved at 0.5 m/s along x for
/// 6 s is, 2.5 s from either end of the record, on the straight line to
/// 1e-9 m (the smoothing keeps a line; its transients at the ends decay
/// as 0.9^i, below 1e-11 of the 9 samples' lag there).
#[test]
fn a_drivers_time_series_moves_its_coupled_point() {
    let d = scratch("driver-series");
    let deck = rope_deck("FairTen1\nPoint2PX\n");
    write_scenario(&d, "rope.dat", &deck);
    let (header, rows) = read_csv(&{
        // Where the deck puts the coupled point.
        let out = d.join("statics");
        let o = run_quiet(&d.join("rope.dat"), &out, &[]);
        assert_eq!(o.status.code(), Some(0), "{}", text(&o).1);
        out.join("points.csv")
    });
    let id = header.iter().position(|h| h == "point").unwrap();
    let x = header.iter().position(|h| h == "x").unwrap();
    let coupled = rows.iter().find(|r| r[id] == 2.0).unwrap();
    let [x0, y0, z0] = [coupled[x], coupled[x + 1], coupled[x + 2]];
    let series: String = (0..=120)
        .map(|i| {
            let t = 0.05 * i as f64;
            format!("{t} {} {y0} {z0}\n", x0 + 0.5 * t)
        })
        .collect();
    write_scenario(
        &d,
        "motion.dat",
        &format!("# Time PointX PointY PointZ\n{series}"),
    );
    let out = run_driver(
        &d,
        "md_driver.inp",
        &driver("rope.dat", (6.0, 0.01), (1, "motion.dat"), AT_REST),
    );
    let (header, rows) = read_csv(&out.join("channels.csv"));
    let t = header.iter().position(|h| h == "t").unwrap();
    let px = header.iter().position(|h| h == "Point2PX").unwrap();
    let inside: Vec<_> = rows.iter().filter(|r| r[t] >= 2.5 && r[t] <= 3.5).collect();
    assert_eq!(inside.len(), 101);
    for r in inside {
        let want = x0 + 0.5 * r[t];
        assert!(
            (r[px] - want).abs() < 1e-9,
            "t {}: {} against {want}",
            r[t],
            r[px]
        );
    }
}

/// A driver that cannot run is refused naming its line: a deck that is
/// not there, InputsMode 1 without its file, an offset platform with a
/// coupled body or a CoupledPinned rod of the deck's own (moving them by
/// the offsets is not built).
#[test]
fn a_bad_driver_file_is_refused_naming_its_line() {
    for (name, dvr, needle) in [
        (
            "no-deck",
            driver("absent.dat", (1.0, 0.01), (0, ""), AT_REST),
            "line 8: MDInputFile",
        ),
        (
            "no-series",
            driver("h.dat", (1.0, 0.01), (1, ""), AT_REST),
            "line 13: InputsMode 1 needs InputsFile",
        ),
        (
            "offset",
            driver("b.dat", (1.0, 0.01), (0, ""), "0 0 5 0 0 0 0 0"),
            "line 18: initial platform offsets",
        ),
        (
            "offset-pinned-rod",
            driver("r.dat", (1.0, 0.01), (0, ""), "0 0 0 0 0 0 0 2"),
            "with a coupled body or rod of the deck",
        ),
    ] {
        let d = scratch(name);
        copy_fixture(&d, "md-horizontal-moordyn.txt", "h.dat");
        write_scenario(&d, "b.dat", &coupled_body_deck());
        write_scenario(&d, "r.dat", &pinned_rod_deck());
        let file = write_scenario(&d, "md_driver.inp", &dvr);
        refused_by_check_and_run(&file, &d.join("never"), &["md_driver.inp", needle], &[]);
    }
}

/// The catenary start of a TOML system: md_case5's overlong chain starts
/// straight and slack when its line type carries no compression
/// (`compression = false`, as a deck's lines), and is refused naming the
/// line when it carries compression (TOML's default), since it would
/// start pushing its ends apart (docs/method.md §13.7).
#[test]
fn an_overlong_line_that_carries_compression_is_refused_a_catenary_start() {
    let scenario = |compression: &str| {
        format!(
            "[water]\ndepth = 200.0\n[[line_types]]\nname = \"chain\"\ndiameter = 0.333\n\
             mass_per_length = 685.0\nea = 3.27e9\n{compression}\
             {}{}[[lines]]\nid = 1\ntype = \"chain\"\nlength = 850.0\nelements = 20\na = 1\nb = 2\n\
             [analysis]\ntype = \"dynamic\"\ninitial = \"catenary\"\nduration = 0.1\n\
             time_step = 0.01\n",
            toml_point(1, "fixed", [-400.0, 0.0, -200.0]),
            toml_point(2, "fixed", [0.0, 0.0, 0.0]),
        )
    };
    expect_input_error(
        "catenary-start-compression",
        &scenario(""),
        &[
            "line 1",
            "850 m",
            "initial = \"catenary\" for a line without compression",
        ],
    );
    let d = scratch("catenary-start-slack");
    let file = write_scenario(&d, "slack.toml", &scenario("compression = false\n"));
    let o = run_quiet(&file, &d.join("out"), &[]);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o).1);
}

/// A deck whose chain of 360 m runs from an anchor on the bed at
/// (-300, 0, -75) to `fairlead` (a row's attachment and body-axes
/// position, `Coupled 20 0 -10` or `Turbine1 20 0 -10`).
fn chain_deck(fairlead: &str) -> String {
    format!(
        "a chain to a platform's fairlead\n\
         ---------------------- LINE TYPES ----------------------------------\n\
         TypeName   Diam    Mass/m     EA     BA/-zeta    EI    Cd     Ca    CdAx    CaAx\n\
         (name)     (m)     (kg/m)     (N)    (N-s/-)     (-)   (-)    (-)   (-)     (-)\n\
         chain      0.1     20.0    5.0e8     -1.0        0     1.2    1.0   0.2     0.0\n\
         ---------------------- POINTS --------------------------------------\n\
         ID  Attachment  X       Y     Z      M   V    CdA  CA\n\
         (-)  (-)       (m)     (m)   (m)    (kg) (m^3) (m^2) (-)\n\
         1   Fixed     -300     0    -75     0    0    0    0\n\
         2   {fairlead}   0    0    0    0    0\n\
         ---------------------- LINES ---------------------------------------\n\
         ID  LineType  AttachA  AttachB  UnstrLen  NumSegs  Outputs\n\
         (-)   (-)      (-)      (-)      (m)       (-)      (-)\n\
         1    chain      1        2       360       10       -\n\
         ---------------------- OPTIONS -------------------------------------\n\
         0.01    dtM\n\
         ------------------------- need this line --------------------------\n"
    )
}

/// `chain_deck`'s chain to a point on a coupled body of its own.
fn coupled_body_deck() -> String {
    chain_deck("Body1 20 0 -10").replace(
        "---------------------- POINTS",
        "---------------------- BODIES ----------------------------------\n\
         ID Attachment X0 Y0 Z0 r0 p0 y0 Mass CG I Volume CdA Ca\n\
         (#) (-) (m) (m) (m) (deg) (deg) (deg) (kg) (m) (kg-m^2) (m^3) (m^2) (-)\n\
         1 Coupled 0 0 0 0 0 0 1000 0 0 0 0 0\n\
         ---------------------- POINTS",
    )
}

/// `chain_deck` with a CoupledPinned rod of 10 m hanging from (0, 20,
/// -5).
fn pinned_rod_deck() -> String {
    chain_deck("Coupled 20 0 -10").replace(
        "---------------------- POINTS",
        "---------------------- ROD TYPES -----------------------------------\n\
         TypeName Diam Mass/m Cd Ca CdEnd CaEnd\n\
         (name) (m) (kg/m) (-) (-) (-) (-)\n\
         can 1.0 1000 0.6 1.0 0.6 1.0\n\
         ---------------------- RODS ----------------------------------------\n\
         ID RodType Attachment Xa Ya Za Xb Yb Zb NumSegs RodOutputs\n\
         (#) (name) (#/key) (m) (m) (m) (m) (m) (m) (-) (-)\n\
         1 can CoupledPinned 0 20 -5 0 20 -15 2 -\n\
         ---------------------- POINTS",
    )
}

/// Point `id`'s position in points.csv at t = 0.
fn start_position(out: &std::path::Path, id: f64) -> [f64; 3] {
    let (header, rows) = read_csv(&out.join("points.csv"));
    let col = |n: &str| header.iter().position(|h| h == n).unwrap();
    let row = rows
        .iter()
        .find(|r| r[col("t")] == 0.0 && r[col("point")] == id)
        .expect("the point at t = 0");
    [row[col("x")], row[col("y")], row[col("z")]]
}

/// OpenFAST's driver places a coupled point by its platform's initial
/// offsets as MoorDyn-F's MD_Init does, x = t + R x_deck (D3), R the
/// platform's rotation R_z R_y R_x (D2): surge 10 m, heave -2 m and pitch
/// 0.1 rad (the row's 5.7295779513 deg) take the fairlead at (20, 0, -10)
/// to (10 + 20 c - 10 s, 0, -2 - 20 s - 10 c), c, s the cosine and sine of
/// 0.1, where the run starts (its static equilibrium with the fairlead
/// held there), to round-off.
#[test]
fn a_drivers_platform_offsets_place_its_coupled_points_as_moordyn_f() {
    let d = scratch("driver-offsets");
    write_scenario(&d, "chain.dat", &chain_deck("Coupled 20 0 -10"));
    let pitch = 0.1f64;
    let row = format!("0 0 10 0 -2 0 {} 0", pitch.to_degrees());
    let out = run_driver(
        &d,
        "md_driver.inp",
        &driver("chain.dat", (0.02, 0.01), (0, ""), &row),
    );
    let (s, c) = pitch.sin_cos();
    let want = [10.0 + 20.0 * c - 10.0 * s, 0.0, -2.0 - 20.0 * s - 10.0 * c];
    assert_near(start_position(&out, 2.0), want, 1e-12);
}

/// `got` within `tol` of `want` in each coordinate.
fn assert_near(got: [f64; 3], want: [f64; 3], tol: f64) {
    for k in 0..3 {
        assert!((got[k] - want[k]).abs() < tol, "{got:?} against {want:?}");
    }
}

/// With NumTurbines 1 (FAST.Farm's mode) the row's ref_X, ref_Y place
/// the turbine and its offsets move and turn its platform (D3): yaw
/// 30 deg turns its Turbine1 fairlead at (20, 0, -10) to (-20 + 10 +
/// 20 cos 30, 20 sin 30, -10) at the start; a deck's own coupled point is
/// turbine 1's in MoorDyn-F and takes its ref without offsets too
/// ((20, 0, -10) with ref (-20, 5) at (0, 5, -10)); both to round-off.
#[test]
fn a_fast_farm_drivers_rows_move_and_turn_the_turbines_platform() {
    let farm = |name: &str, fairlead: &str, row: &str| {
        let d = scratch(name);
        write_scenario(&d, "farm.dat", &chain_deck(fairlead));
        let text = driver("farm.dat", (0.02, 0.01), (0, ""), row).replace(
            "0                   NumTurbines",
            "1                   NumTurbines",
        );
        start_position(&run_driver(&d, "md_driver.inp", &text), 2.0)
    };
    let (s, c) = 30f64.to_radians().sin_cos();
    let turned = farm(
        "driver-farm-offsets",
        "Turbine1 20 0 -10",
        "-20 0 10 0 0 0 0 30",
    );
    assert_near(turned, [-10.0 + 20.0 * c, 20.0 * s, -10.0], 1e-12);
    let placed = farm("driver-farm-ref", "Coupled 20 0 -10", "-20 5 0 0 0 0 0 0");
    assert_near(placed, [0.0, 5.0, -10.0], 1e-12);
}

/// With InputsMode 1 the inputs' first row places the coupled points, so
/// a platform row's offsets move nothing; `check` says so, naming the
/// row.
#[test]
fn a_drivers_offsets_under_a_time_series_are_noted_as_moving_nothing() {
    let d = scratch("driver-offsets-series");
    write_scenario(&d, "chain.dat", &chain_deck("Coupled 20 0 -10"));
    write_scenario(&d, "motion.dat", "0 20 0 -10\n1 21 0 -10\n");
    let dvr = write_scenario(
        &d,
        "md_driver.inp",
        &driver(
            "chain.dat",
            (1.0, 0.01),
            (1, "motion.dat"),
            "0 0 5 0 0 0 0 0",
        ),
    );
    let o = stancf(&["check", dvr.to_str().unwrap()]);
    let (out, err) = text(&o);
    assert_eq!(o.status.code(), Some(0), "{err}");
    assert!(
        out.contains("line 18: initial platform offsets")
            && out.contains("the offsets do not move"),
        "{out}"
    );
}

/// A driver passes MoorDyn-F its TMax, over which a WaterKin file's
/// elevation record (`WaveKinMod 1`) is resampled: `chain_deck` with a
/// 20 s record of a 10 s wave, run 10 s at dtC 0.05 s, takes the record's
/// first 10 s (40 samples every 0.25 s: one period, one wave) and says so
/// (docs/method.md (W2i)).
#[test]
fn a_drivers_tmax_is_the_run_length_a_wave_record_is_resampled_over() {
    let d = scratch("driver-wave-record");
    let omega = 2.0 * std::f64::consts::PI / 10.0;
    let record: String = (0..=80)
        .map(|i| {
            let t = 0.25 * f64::from(i);
            format!("{t} {}\n", 0.5 * (omega * t).cos())
        })
        .collect();
    std::fs::write(d.join("eta.txt"), record).unwrap();
    std::fs::write(
        d.join("waterkin.dat"),
        "waves and currents\nnotes\n--- WAVES ---\n1 WaveKinMod\n\"eta.txt\" WaveKinFile\n\
         0.25 dtWave\n0 WaveDir\n0 - X\n0\n0 - Y\n0\n0 - Z\n0\n--- CURRENT ---\n0 CurrentMod\n",
    )
    .unwrap();
    let deck = chain_deck("Coupled 20 0 -10")
        .replace("0.01    dtM\n", "0.01    dtM\n\"waterkin.dat\"  WaterKin\n");
    std::fs::write(d.join("deck.dat"), deck).unwrap();
    let dvr = write_scenario(
        &d,
        "md_driver.inp",
        &driver("deck.dat", (10.0, 0.05), (0, ""), AT_REST),
    );
    let o = stancf(&["check", dvr.to_str().unwrap()]);
    let (so, se) = text(&o);
    assert_eq!(o.status.code(), Some(0), "{se}");
    assert!(
        so.contains("WaveKinMod 1, 1 wave component(s) heading 0 deg")
            && so.contains("over the run's 10 s")
            && so.contains("40 samples"),
        "{so}"
    );
    run_driver(
        &d,
        "md_driver.inp",
        &driver("deck.dat", (10.0, 0.05), (0, ""), AT_REST),
    );
}
