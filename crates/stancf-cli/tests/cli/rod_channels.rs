//! MoorDyn's `Rod<n>` output channels (docs/interface.md, "Rods"): a
//! rod's pose, its lines' pull and its submerged fraction against closed
//! forms, and a rod on a body moving with it.

use crate::common::*;
use std::f64::consts::PI;

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
Rod1N1PX Rod1NBPX Rod1NBPZ Rod1NAVZ
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
/// water's drag) and its moment about end A zero; no velocity; its nodes
/// (`N1`, `NA`, `NB`) where its 4 segments put them. Measured:
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
        // Its nodes on the rigid rod (4 segments of 2.5 m from end A).
        near("Rod1N1PX", -2.5, 1e-9);
        near("Rod1NBPX", 5.0, 1e-9);
        near("Rod1NBPZ", z, 1e-9);
        near("Rod1NAVZ", 0.0, 1e-9);
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

/// Output channels stancf does not compute (a body rod's own force, a
/// zero-length rod's roll, a rod's acceleration) and names MoorDyn does
/// not know as channels (MoorDyn-F's old `N4Px`, a rod's `RZ`: MoorDyn
/// warns and skips them) are noted, naming their line, and their columns
/// in channels.csv are left empty (the result readers' NaN, never a
/// number that is not one), the others written: the run goes on.
#[test]
fn channels_stancf_does_not_compute_are_noted_and_left_empty() {
    let d = scratch("channels-left-empty");
    let deck = body_rod_deck("-", "0").replace(
        "water depth (m)\n",
        "water depth (m)\n--- OUTPUTS ---\nFairTen1\nRod1FX\nRod2RY\nRod1AX\nN4Px\nRod1RZ\nRod1PZ\n",
    );
    let file = write_scenario(&d, "deck.txt", &deck);
    let (stdout, _) = text(&stancf(&["check", file.to_str().unwrap()]));
    for name in ["Rod1FX", "Rod2RY", "Rod1AX"] {
        let note = format!("output channel {name}: ");
        assert!(stdout.contains(&note), "{name}: {stdout}");
    }
    for name in ["N4Px", "Rod1RZ"] {
        let note = format!("output channel {name}: not a channel MoorDyn knows");
        assert!(stdout.contains(&note), "{name}: {stdout}");
    }
    assert!(
        stdout.contains("its column in channels.csv is left empty"),
        "{stdout}"
    );
    let out = d.join("out");
    let o = run_quiet(&file, &out, &[]);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o).1);
    let text = std::fs::read_to_string(out.join("channels.csv")).unwrap();
    let mut lines = text.lines();
    assert_eq!(
        lines.next(),
        Some("t,FairTen1,Rod1FX,Rod2RY,Rod1AX,N4Px,Rod1RZ,Rod1PZ")
    );
    let mut rows = 0;
    for line in lines {
        let f: Vec<&str> = line.split(',').collect();
        assert_eq!(f.len(), 8, "{line}");
        assert!((2..=6).all(|k| f[k].is_empty()), "{line}");
        for k in [0, 1, 7] {
            assert!(f[k].parse::<f64>().unwrap().is_finite(), "{line}");
        }
        rows += 1;
    }
    assert!(rows > 0);
}
