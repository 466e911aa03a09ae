//! A seabed of varying depth (docs/method.md §12.2 (W40a)-(W46a)):
//! MoorDyn's 3-D seafloor file, given by a deck's `SeafloorFile` or by
//! `[water.seabed] file`. Issue 31's check: a seafloor file that is a plane
//! gives what the tilted flat bed gives.

use crate::common::*;
use std::path::Path;

/// MoorDyn's WD0050_Chain test deck without its water depth, its anchor
/// at x = 400 m on a bed that falls towards the fairlead: z = -50 + 0.025
/// (x - 400).
fn chain() -> String {
    let depth = "50                   WtrDpth              water depth (m)\n";
    assert!(WD0050_CHAIN.contains(depth));
    WD0050_CHAIN.replace(depth, "")
}

/// The bed's slope along x and its height at x = 0.
const SLOPE: f64 = 0.025;
const HEIGHT_AT_0: f64 = -60.0;

/// MoorDyn's seafloor format for the plane z = HEIGHT_AT_0 + SLOPE x on
/// x = -100, -50, ..., 600 and y = -20, 0, 20: every tick and height is
/// a multiple of 1/8, exact in the single precision MoorDyn reads.
fn plane_seafloor() -> String {
    let xs: Vec<f64> = (-2..=12).map(|k| 50.0 * k as f64).collect();
    let ys = [-20.0, 0.0, 20.0];
    let mut s = format!("{} {}\n", xs.len(), ys.len());
    for axis in [&xs[..], &ys[..]] {
        let ticks: Vec<String> = axis.iter().map(|v| v.to_string()).collect();
        s += &(ticks.join(" ") + "\n");
    }
    for x in &xs {
        for y in ys {
            s += &format!("{x} {y} {}\n", HEIGHT_AT_0 + SLOPE * x);
        }
    }
    s
}

/// The chain's run under `water` keys (the bed's): the end forces of
/// tensions.csv, rows t, line, end, fx, fy, fz, tension.
fn chain_on(dir: &Path, name: &str, water: &str, analysis: &str) -> Vec<Vec<f64>> {
    let sc = write_scenario(
        dir,
        &format!("{name}.toml"),
        &format!(
            "[system]\nmoordyn = \"deck.txt\"\n\n[water]\ndepth = {}\n{water}\n{analysis}",
            -HEIGHT_AT_0
        ),
    );
    let out = dir.join(format!("out-{name}"));
    let o = run_quiet(&sc, &out, &[]);
    assert_eq!(o.status.code(), Some(0), "{name}: {}", text(&o).1);
    read_tensions(&out.join("tensions.csv"))
}

/// The largest difference of two runs' end forces, over the largest
/// force.
fn force_difference(a: &[Vec<f64>], b: &[Vec<f64>]) -> f64 {
    assert_eq!(a.len(), b.len());
    let largest = a.iter().map(|r| r[6].abs()).fold(0.0, f64::max);
    a.iter()
        .zip(b)
        .flat_map(|(p, q)| (3..7).map(move |c| (p[c] - q[c]).abs()))
        .fold(0.0, f64::max)
        / largest
}

/// The chain resting on the plane bed given as a seafloor file and as
/// `slope`: the same equilibrium and the same 4 s of motion under a
/// fairlead surge. The grid reproduces the plane to round-off (its
/// bilinear is exact on a plane, its nodes exact in single precision)
/// and its normal from the slopes is the plane's to 1e-16, so the two
/// solve the same contact law. They integrate it differently: on a plane
/// the push is integrated exactly where the chain is in the bed, on a
/// grid at the axial rule (docs/method.md §12.2, (W47a)-(W47c)), so they
/// differ by the axial rule's error across the touchdown's kink, of first
/// order in the element length: on the OC4 chain at 40 elements 7e-5 of
/// H_F at rest, and in motion at 30 elements 0.4 % of the tension's range
/// (docs/method.md §12.2). Bounded at 1e-3 of the largest force at rest
/// and 2e-2 in motion (measured: 9.4e-5 and 6.7e-3); the earlier bound,
/// 1e-9, held when both took the axial rule (measured 3.5e-15 and
/// 1.7e-11).
#[test]
fn a_seafloor_file_that_is_a_plane_gives_the_tilted_beds_equilibrium_and_motion() {
    let dir = scratch("bathymetry_plane");
    write_scenario(&dir, "deck.txt", &chain());
    write_scenario(&dir, "bed.txt", &plane_seafloor());
    let file = "[water.seabed]\nfile = \"bed.txt\"\n";
    let slope = format!("[water.seabed]\nslope = [{SLOPE}, 0.0]\n");
    let statics = "[analysis]\ntype = \"static\"\n";
    let (a, b) = (
        chain_on(&dir, "file-static", file, statics),
        chain_on(&dir, "slope-static", &slope, statics),
    );
    let static_gap = force_difference(&a, &b);
    assert!(static_gap <= 1e-3, "static forces differ by {static_gap:e}");
    // The bed is felt: the anchor's force is not the fairlead's
    // horizontal pull alone (the resting chain's weight along the slope).
    assert!((a[0][3].abs() - a[1][3].abs()).abs() > 1e3, "{a:?}");
    // The Galerkin step: P2 (a system's default) grows this chain's
    // energy from rest at this step, bed or no bed (noted in issue 31's
    // note; the subject here is the bed).
    let dynamics = "[[motions]]\npoint = 2\namplitude = [2.0, 0.0, 0.0]\nperiod = 10.0\n\
                    ramp = 2.0\n[analysis]\ntype = \"dynamic\"\ntime_step = 0.1\n\
                    duration = 4.0\ninitial = \"static\"\ntime_scheme = \"galerkin\"\n";
    let (a, b) = (
        chain_on(&dir, "file-dynamic", file, dynamics),
        chain_on(&dir, "slope-dynamic", &slope, dynamics),
    );
    let dynamic_gap = force_difference(&a, &b);
    assert!(
        dynamic_gap <= 2e-2,
        "forces in motion differ by {dynamic_gap:e}"
    );
}

/// MoorDyn's own 3-D seafloor test deck (tests/Mooring/3D_seafloor/
/// hanging_lines.txt) names its bed relative to MoorDyn's tests folder;
/// kept in a copy of that layout, it is found above the deck's folder
/// (`check` says where), and its ten 10 m chains hang clear of the bed
/// from their fixed points with the tension w L at the top (w the wet
/// weight: 1.1 kg/m less the water of 13.332 mm, MoorDyn's default
/// density 1025 kg/m^3, its g 9.80665 m/s^2) to the solve's tolerance.
#[test]
fn moordyn_3d_seafloor_test_deck_finds_its_bed_and_hangs_its_lines() {
    let dir = scratch("bathymetry_moordyn_deck");
    let beds = dir.join("tests/Mooring/3D_seafloor");
    std::fs::create_dir_all(&beds).unwrap();
    // MoorDyn's make_3d_seafloor.py: 100 x ticks over [-50, 50], 5 y
    // ticks, z = -40 + 0.2 (x + 50) as its seafloor_profile_3d.txt holds.
    let xs: Vec<f64> = (0..100).map(|i| -50.0 + 100.0 * i as f64 / 99.0).collect();
    let ys = [-2.0, -1.0, 0.0, 1.0, 2.0];
    let mut bed = format!("100 5\n{}\n-2.0 -1.0 0.0 1.0 2.0\n", xs.map_join());
    for x in &xs {
        for y in ys {
            bed += &format!("{x} {y} {}\n", -40.0 + 0.2 * (x + 50.0));
        }
    }
    std::fs::write(beds.join("seafloor_profile_3d.txt"), bed).unwrap();
    let mut points = String::new();
    let mut lines = String::new();
    for k in 0..10 {
        let x = -50.0 + 10.0 * k as f64;
        points += &format!(
            "{} fixed {x} 0.0 -6.6 0 0 0 0\n{} free {x} 0.0 -16.6 0 0 0 0\n",
            2 * k + 1,
            2 * k + 2
        );
        lines += &format!("{} chain {} {} 10 10 p,t\n", k + 1, 2 * k + 1, 2 * k + 2);
    }
    let deck = format!(
        "--------------------- MoorDyn Input File ---------------------\n\
         MoorDyn's 3D_seafloor/hanging_lines.txt\n\
         ----------------------- LINE TYPES ---------------------------\n\
         TypeName Diam Mass/m EA BA/-zeta EI Cd Ca CdAx CaAx\n\
         (name) (m) (kg/m) (N) (N-s/-) (N-m^2) (-) (-) (-) (-)\n\
         chain 13.332E-3 1.1 7.51E6 -0.5 0 0.0 0.0 0.0 1.0\n\
         ----------------------- POINTS -------------------------------\n\
         Node Type X Y Z M V CdA CA\n(-) (-) (m) (m) (m) (kg) (m^3) (m^2) (-)\n{points}\
         -------------------------- LINES -----------------------------\n\
         Line LineType NodeA NodeB UnstrLen NumSegs Flags/Outputs\n\
         (-) (-) (-) (-) (m) (-) (-)\n{lines}\
         -------------------------- SOLVER OPTIONS---------------------\n\
         0.00050 dtM - time step\n3.0e6 kb - bottom stiffness\n3.0e5 cb - bottom damping\n\
         30 WtrDpth - water depth\n\
         Mooring/3D_seafloor/seafloor_profile_3d.txt SeafloorFile 3D seafloor file path\n\
         ------------------------- need this line ---------------------\n"
    );
    let deck_path = write_scenario(&beds, "hanging_lines.txt", &deck);
    let o = stancf(&["check", deck_path.to_str().unwrap()]);
    let (stdout, stderr) = text(&o);
    assert!(o.status.success(), "{stderr}");
    let tests_dir = std::fs::canonicalize(dir.join("tests")).unwrap();
    for needle in [
        "a bathymetry of 100 x 5 nodes, z from -40 to -20 m".to_string(),
        format!(
            "relative to {}, a folder above the deck's",
            tests_dir.display()
        ),
        "the nodes' mean depth, 30 m in place of the deck's WtrDpth 30 m".into(),
    ] {
        assert!(
            stdout.contains(&needle) || stderr.contains(&needle),
            "{needle}\n{stdout}\n{stderr}"
        );
    }
    let out = dir.join("out");
    let o = run_quiet(&deck_path, &out, &[]);
    assert!(o.status.success(), "{}", text(&o).1);
    let d: f64 = 13.332e-3;
    let w = (1.1 - 1025.0 * std::f64::consts::PI / 4.0 * d * d) * 9.80665;
    for row in read_tensions(&out.join("tensions.csv")) {
        if row[2] == 0.0 {
            assert!((row[6] - w * 10.0).abs() <= 1e-8 * w * 10.0, "{row:?}");
        }
    }
}

/// Join a tick axis as MoorDyn's generator writes it.
trait MapJoin {
    fn map_join(&self) -> String;
}

impl MapJoin for Vec<f64> {
    fn map_join(&self) -> String {
        self.iter()
            .map(|v| v.to_string())
            .collect::<Vec<_>>()
            .join(" ")
    }
}

/// What stancf refuses in a seafloor file, by line; a depth beside a
/// deck's seafloor file (MoorDyn's depth is the bed's mean); a slope
/// beside a seafloor file.
#[test]
fn a_seafloor_file_moordyn_would_misread_is_refused_by_line() {
    let deck = chain().replace(
        "0.5                  FrictionCoefficient",
        "bed.txt SeafloorFile\n0.5                  FrictionCoefficient",
    );
    expect_refusal_beside(
        "bathymetry_missing_node",
        "[system]\nmoordyn = \"deck.txt\"\n",
        &[
            ("deck.txt", &deck),
            ("bed.txt", "2 2\n0 10\n0 5\n0 0 -1\n0 5 -1\n10 0 -1\n"),
        ],
        &[
            "option SeafloorFile",
            "bed.txt",
            "no row gives the node (x, y) = (10, 5)",
        ],
    );
    expect_refusal_beside(
        "bathymetry_and_depth",
        "[system]\nmoordyn = \"deck.txt\"\n[water]\ndepth = 60\n",
        &[("deck.txt", &deck), ("bed.txt", &plane_seafloor())],
        &["water.depth", "gives it too (option SeafloorFile, line 21)"],
    );
    expect_refusal_beside(
        "bathymetry_and_slope",
        "[system]\nmoordyn = \"deck.txt\"\n[water]\ndepth = 60\n[water.seabed]\n\
         slope = [0.1, 0.0]\nfile = \"bed.txt\"\n",
        &[("deck.txt", &chain()), ("bed.txt", &plane_seafloor())],
        &["water.seabed.slope", "give a slope or a file, not both"],
    );
}
