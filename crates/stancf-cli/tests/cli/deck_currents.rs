//! A MoorDyn deck's currents that vary in time (docs/interface.md,
//! "Water"): `Currents 2` (`current_profile_dynamic.txt`) and `Currents 5`
//! (`current_profile_4d.txt`) become a current on a grid in space and
//! time (docs/method.md §12.1 (W9a)); their readers are checked against
//! MoorDyn's documented examples in the scenario crate's
//! `moordyn_current_grids` tests.

use crate::common::*;
use std::path::Path;

/// A taut line from an anchor at (-80, 0, -50) to a fixed point at
/// (0, 0, -5) in a current, `Currents {mode}`.
fn deck(mode: u8) -> String {
    format!(
        "MoorDyn v2 deck: a line in a current
------------------------------ LINE TYPES --------------------------------------
TypeName  Diam    Mass/m   EA        BA/-zeta  EI       Cd    Ca    CdAx  CaAx
(name)    (m)     (kg/m)   (N)       (N-s/-)   (N-m^2)  (-)   (-)   (-)   (-)
rope      0.08    8.0      5.0E7     -0.8      0        1.2   1.0   0.01  0.5
-------------------------------- POINTS ----------------------------------------
ID  Attachment  X        Y        Z        Mass    Volume  CdA    Ca
(#) (-)         (m)      (m)      (m)      (kg)    (m^3)   (m^2)  (-)
1   Fixed       -80.0    0.0      -50.0    0       0       0      0
2   Fixed       0.0      0.0      -5.0     0       0       0      0
-------------------------------- LINES -----------------------------------------
ID  LineType  AttachA  AttachB  UnstrLen  NumSegs  Outputs
(#) (name)    (#)      (#)      (m)       (-)      (-)
1   rope      1        2        92.0      12       -
------------------------------- OPTIONS ----------------------------------------
9.81      g
50        WtrDpth
{mode}         Currents
------------------------- need this line ---------------------------------------
"
    )
}

/// The steady profile: ux 0.3, 0.6, 0.9 m/s and uy 0, 0.2, 0 m/s at
/// z = -50, -20, 0 m.
const STEADY: &str = "h\nh\nz ux uy uz\n-50 0.3 0 0\n-20 0.6 0.2 0\n0 0.9 0 0\n";

/// The same profile in `current_profile_dynamic.txt` at t = 0 s and, at
/// t = `later` s, `scale` times it.
fn dynamic_profile(later: f64, scale: f64) -> String {
    let row = |t: f64, s: f64| format!("{t} {} {} {} 0 {} 0\n", 0.3 * s, 0.6 * s, 0.9 * s, 0.2 * s);
    format!(
        "h\nh\nh\nh\n-50 -20 0\n\n{}{}",
        row(0.0, 1.0),
        row(later, scale)
    )
}

/// The same steady profile on a 4-D grid of 2 x 2 x 3 x 2 nodes.
fn grid_4d() -> String {
    let mut s = "2 2 3 2\n-100 50\n-10 10\n-50 -20 0\n0 100\n".to_string();
    for x in [-100, 50] {
        for y in [-10, 10] {
            for (z, u) in [(-50, [0.3, 0.0]), (-20, [0.6, 0.2]), (0, [0.9, 0.0])] {
                for t in [0, 100] {
                    s += &format!("{x} {y} {z} {t} {} {} 0\n", u[0], u[1]);
                }
            }
        }
    }
    s
}

/// Runs the deck in `dir` (with its current file) statically, or 20
/// steps of 0.05 s from its equilibrium; the tensions.
fn tensions(dir: &Path, dynamic: bool) -> Vec<Vec<f64>> {
    let analysis = if dynamic {
        "type = \"dynamic\"\ntime_scheme = \"galerkin\"\ntime_step = 0.05\nduration = 1.0\n"
    } else {
        "type = \"static\"\n"
    };
    let sc = write_scenario(
        dir,
        "run.toml",
        &format!("[system]\nmoordyn = \"deck.txt\"\n[analysis]\n{analysis}"),
    );
    let out = dir.join(format!("out-{dynamic}"));
    let o = run_quiet(&sc, &out, &[]);
    assert_eq!(o.status.code(), Some(0), "{dir:?}: {}", text(&o).1);
    read_tensions(&out.join("tensions.csv"))
}

fn largest_difference(a: &[Vec<f64>], b: &[Vec<f64>]) -> f64 {
    assert_eq!(a.len(), b.len());
    a.iter()
        .zip(b)
        .map(|(x, y)| (x[6] - y[6]).abs())
        .fold(0.0, f64::max)
}

/// Two runs of equations that agree to round-off stop their Newton
/// iterations within the solver's tolerance of each other: 1e-10 of the
/// line's length in the unknowns (docs/interface.md, `tolerance`), which
/// an element's axial stiffness EA / l turns into a tension.
const NEWTON_TENSION: f64 = 1e-10 * 92.0 * 5.0e7 / (92.0 / 12.0);

/// A steady profile given as MoorDyn's dynamic profile (two equal times)
/// or its 4-D grid (uniform in x, y and t) is the same current as
/// `Currents 1` (the interpolations are all linear in z and differ in
/// their arithmetic only): the static and dynamic tensions agree within
/// the Newton iterations' tolerance ([`NEWTON_TENSION`], 0.06 N of 1e4),
/// and `check` says what each is.
#[test]
fn a_steady_current_given_as_moordyns_time_grids_is_the_steady_profile() {
    let mut runs = Vec::new();
    for (mode, file, contents) in [
        (1, "current_profile.txt", STEADY.to_string()),
        (
            2,
            "current_profile_dynamic.txt",
            dynamic_profile(100.0, 1.0),
        ),
        (5, "current_profile_4d.txt", grid_4d()),
    ] {
        let d = scratch(&format!("deck-current-{mode}"));
        std::fs::write(d.join("deck.txt"), deck(mode)).unwrap();
        std::fs::write(d.join(file), contents).unwrap();
        if mode != 1 {
            let (so, se) = text(&stancf(&["check", d.join("deck.txt").to_str().unwrap()]));
            for words in [
                format!("line 18: Currents {mode}: the current of"),
                "multilinear in space and time".to_string(),
                "a static run sees the current at t = 0".to_string(),
            ] {
                assert!(so.contains(&words), "{words}: {so}{se}");
            }
        }
        runs.push((tensions(&d, false), tensions(&d, true)));
    }
    let size = runs[0].0[0][6];
    assert!(size > 1e3, "{size}");
    for (mode, run) in [2, 5].iter().zip(&runs[1..]) {
        for (dynamic, (a, b)) in [(false, (&run.0, &runs[0].0)), (true, (&run.1, &runs[0].1))] {
            let worst = largest_difference(a, b);
            assert!(
                worst < NEWTON_TENSION,
                "Currents {mode}, dynamic {dynamic}: {worst} N from Currents 1's"
            );
        }
    }
}

/// A dynamic profile that doubles over 2 s: the static equilibrium is the
/// one of its first time (Currents 1's, within the Newton tolerance), and
/// in the run the growing current pulls the line harder than the steady
/// one does.
#[test]
fn a_current_that_grows_in_time_is_its_first_profile_in_statics_and_then_grows() {
    let d = scratch("deck-current-growing");
    std::fs::write(d.join("deck.txt"), deck(2)).unwrap();
    std::fs::write(
        d.join("current_profile_dynamic.txt"),
        dynamic_profile(2.0, 2.0),
    )
    .unwrap();
    let s = scratch("deck-current-steady");
    std::fs::write(s.join("deck.txt"), deck(1)).unwrap();
    std::fs::write(s.join("current_profile.txt"), STEADY).unwrap();
    let (growing, steady) = (tensions(&d, false), tensions(&s, false));
    assert!(largest_difference(&growing, &steady) < NEWTON_TENSION);
    let (growing, steady) = (tensions(&d, true), tensions(&s, true));
    let last = growing.len() - 1;
    let (g, s) = (growing[last][6], steady[last][6]);
    assert!(
        g > s * 1.001,
        "at 1 s: {g} N against the steady current's {s} N"
    );
}

/// MoorDyn-F's water kinematics file with `WaveKinMod` `wave_mode` and
/// `CurrentMod` 1 with the rows `current_rows`.
fn waterkin(wave_mode: u8, current_rows: &str) -> String {
    format!(
        "MoorDyn Waves and Currents input file\nnotes\n--- WAVES ---\n{wave_mode} WaveKinMod\n\
         \"\" WaveKinFile\n0.5 dtWave\n0 WaveDir\n2 - X type\n-24, 150, 100 - X\n2 - Y type\n\
         -100, 100, 5 - Y\n2 - Z type\n-600, 0, 60 - Z\n--- CURRENT ---\n1 CurrentMod\n\
         z-depth x-current y-current\n(m) (m/s) (m/s)\n{current_rows}--- need this line ---\n"
    )
}

/// MoorDyn-F's water kinematics file (the `WaterKin` option, as OpenFAST's
/// md_VIV gives its current) with no waves and `CurrentMod` 1: its rows
/// `z ux uy` (here from the surface down, which MoorDyn-F turns round)
/// are the steady profile of `Currents 1`, and the static and dynamic
/// tensions are the same to the bit.
#[test]
fn a_moordyn_f_waterkin_files_current_profile_is_the_same_current_as_currents_1() {
    let steady = scratch("deck-current-1-again");
    std::fs::write(steady.join("deck.txt"), deck(1)).unwrap();
    std::fs::write(steady.join("current_profile.txt"), STEADY).unwrap();
    let d = scratch("deck-waterkin");
    let with_file = deck(0).replace("0         Currents", "\"WaterKin.dat\" WaterKin");
    std::fs::write(d.join("deck.txt"), with_file).unwrap();
    std::fs::write(
        d.join("WaterKin.dat"),
        waterkin(0, "0 0.9 0\n-20 0.6 0.2\n-50 0.3 0\n"),
    )
    .unwrap();
    let (so, se) = text(&stancf(&["check", d.join("deck.txt").to_str().unwrap()]));
    assert!(
        so.contains("no waves, a steady current profile of 3 rows"),
        "{so}{se}"
    );
    for dynamic in [false, true] {
        assert_eq!(
            tensions(&d, dynamic),
            tensions(&steady, dynamic),
            "dynamic {dynamic}"
        );
    }
    // The hybrid method's waves (OpenFAST's SeaState's) are refused
    // naming the file's line; a record without its file, naming the field.
    std::fs::write(d.join("WaterKin.dat"), waterkin(2, "0 0.9 0\n")).unwrap();
    refused_by_check_and_run(
        &d.join("deck.txt"),
        &d.join("never"),
        &[
            "WaterKin.dat",
            "line 4: WaveKinMod 2",
            "SeaState",
            "[[water.waves]]",
        ],
        &[],
    );
    std::fs::write(d.join("WaterKin.dat"), waterkin(1, "0 0.9 0\n")).unwrap();
    refused_by_check_and_run(
        &d.join("deck.txt"),
        &d.join("never"),
        &["WaterKin.dat", "line 5: WaveKinMod 1 needs a WaveKinFile"],
        &[],
    );
}

/// The `U` and `D` flags of MoorDyn's line file at the static equilibrium
/// in `Currents 1`'s steady profile: each node's water velocity is the
/// profile's, linear in z between its rows, at the node's written height
/// (to the 8 digits written), and the line's hydrodynamic forces (the
/// current's drag at rest, as MoorDyn's `D` without buoyancy) are what its
/// two points hold horizontally: the sum of D along x and y equals the
/// sum of the points' forces, to the Newton tolerance's tension
/// ([`NEWTON_TENSION`]); the strain rates `d` of a line at rest are 0.
#[test]
fn moordyns_u_and_d_line_outputs_are_the_current_and_the_drag_its_points_hold() {
    let d = scratch("deck-current-line-out");
    let deck = deck(1).replace("12       -", "12       pUDd");
    std::fs::write(d.join("deck.txt"), deck).unwrap();
    std::fs::write(d.join("current_profile.txt"), STEADY).unwrap();
    let out = d.join("out");
    let o = run_quiet(&d.join("deck.txt"), &out, &[]);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o).1);
    let file = std::fs::read_to_string(out.join("deck_Line1.out")).unwrap();
    let rows: Vec<Vec<&str>> = file
        .lines()
        .map(|l| l.split_whitespace().collect())
        .collect();
    let (header, values) = (&rows[0], &rows[2]);
    let value = |name: &str| -> f64 {
        let c = header.iter().position(|h| *h == name).unwrap();
        values[c].parse().unwrap()
    };
    let profile = |z: f64| -> [f64; 2] {
        let (z0, u0, z1, u1) = if z <= -20.0 {
            (-50.0, [0.3, 0.0], -20.0, [0.6, 0.2])
        } else {
            (-20.0, [0.6, 0.2], 0.0, [0.9, 0.0])
        };
        let f = (z - z0) / (z1 - z0);
        [u0[0] + f * (u1[0] - u0[0]), u0[1] + f * (u1[1] - u0[1])]
    };
    let mut drag = [0.0; 2];
    for i in 0..13 {
        let want = profile(value(&format!("Node{i}pz")));
        for (c, q) in ["Ux", "Uy"].iter().enumerate() {
            let have = value(&format!("Node{i}{q}"));
            assert!(
                (have - want[c]).abs() <= 5e-8,
                "node {i} {q}: {have} against {}",
                want[c]
            );
        }
        assert_eq!(value(&format!("Node{i}Uz")), 0.0);
        drag[0] += value(&format!("Node{i}Dx"));
        drag[1] += value(&format!("Node{i}Dy"));
    }
    for j in 1..=12 {
        assert_eq!(value(&format!("Seg{j}dSt")), 0.0);
    }
    let (_, points) = read_csv(&out.join("points.csv"));
    for (c, axis) in ["x", "y"].iter().enumerate() {
        let held = points[0][8 + c] + points[1][8 + c];
        assert!(drag[c].abs() > 100.0, "{axis}: {} N of drag", drag[c]);
        assert!(
            (drag[c] - held).abs() <= 2.0 * NEWTON_TENSION + 1e-7 * held.abs(),
            "{axis}: drag {} N, the points hold {held} N",
            drag[c]
        );
    }
}
