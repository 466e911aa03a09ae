//! Systems in water (docs/interface.md, "Water"): `[water]` and a
//! MoorDyn deck's water options describe the same sea, a deck's current
//! file is read and acts, lines may pierce the surface, and every bad
//! value is refused naming its key.

use crate::common::*;
use std::f64::consts::PI;
use std::path::Path;

/// A chain from an anchor on the bed (z = -50 m) to a fairlead at
/// z = -5 m, partly resting on the bed, in a sheared current with
/// friction: the deck, with `options` added to its OPTIONS.
fn chain_deck(options: &str) -> String {
    format!(
        "--------------------- MoorDyn v2 input file ------------------------------------
A chain from an anchor on the bed to a fairlead, in a sheared current
------------------------------ LINE TYPES --------------------------------------
TypeName  Diam    Mass/m   EA        BA/-zeta  EI       Cd    Ca    CdAx  CaAx
(name)    (m)     (kg/m)   (N)       (N-s/-)   (N-m^2)  (-)   (-)   (-)   (-)
chain     0.05    12.0     2.0E6     -0.8      0        1.2   1.0   0.01  0.5
-------------------------------- POINTS ----------------------------------------
ID  Attachment  X        Y        Z        Mass    Volume  CdA    Ca
(#) (-)         (m)      (m)      (m)      (kg)    (m^3)   (m^2)  (-)
1   Fixed       -80.0    0.0      -50.0    0       0       0      0
2   Coupled     0.0      0.0      -5.0     0       0       0      0
-------------------------------- LINES -----------------------------------------
ID  LineType  AttachA  AttachB  UnstrLen  NumSegs  Outputs
(#) (name)    (#)      (#)      (m)       (-)      (-)
1   chain     1        2        100.0     20       -
------------------------------- OPTIONS ----------------------------------------
9.81      g
50        WtrDpth
1025      WtrDnsty
3.0e6     kBot
3.0e5     cBot
0.5       FrictionCoefficient
1         Currents
{options}------------------------- need this line ---------------------------------------
"
    )
}

/// MoorDyn-C's steady current profile file (3 header lines, then
/// `z ux uy uz`) of the chain's sea.
const CHAIN_CURRENT: &str = "--------------------- MoorDyn steady currents File ---------------
Tabulated file with the water currents components
z (m), ux (m/s), uy (m/s), uz (m/s)
-50.0 0.2 0.0 0.0
-20.0 0.4 0.1 0.0
0.0 0.6 0.0 0.0
";

/// The chain's `[[motions]]` and `[analysis]`: a static analysis, or a
/// dynamic one of 10 steps of 3 ms (the stable P2 step) from it.
fn chain_run(dynamic: bool) -> String {
    let analysis = if dynamic {
        "type = \"dynamic\"\ninitial = \"static\"\ntime_step = 0.003\nduration = 0.03\n"
    } else {
        "type = \"static\"\n"
    };
    format!(
        "[[motions]]\npoint = 2\namplitude = [0.5, 0.0, 0.0]\nperiod = 4.0\n\
         [analysis]\n{analysis}"
    )
}

/// The waves the scenarios add to the chain's sea (a deck cannot give
/// them).
const CHAIN_WAVES: &str = "wave_ramp = 0.01\n[[water.waves]]\namplitude = 1.0\nperiod = 8.0\n\
                           heading = 30.0\n";

/// The chain's system written in TOML: the deck's line type, points,
/// line and water options, the current file's rows, and the waves.
fn chain_toml(dynamic: bool) -> String {
    format!(
        "title = \"twin\"\n[system]\ngravity = [0.0, 0.0, -9.81]\n\
         [water]\ndepth = 50.0\ndensity = 1025.0\n{CHAIN_WAVES}\
         [water.seabed]\nstiffness = 3.0e6\ndamping = 3.0e5\nfriction_axial = 0.5\n\
         friction_transverse = 0.5\n\
         [water.current]\nprofile = [[-50.0, 0.2, 0.0, 0.0], [-20.0, 0.4, 0.1, 0.0], \
         [0.0, 0.6, 0.0, 0.0]]\n\
         [[line_types]]\nname = \"chain\"\ndiameter = 0.05\nmass_per_length = 12.0\nea = 2.0e6\n\
         ba = -0.8\ncd = 1.2\nca = 1.0\ncdax = 0.01\ncaax = 0.5\n\
         {}{}[[lines]]\nid = 1\ntype = \"chain\"\nlength = 100.0\nelements = 20\na = 1\nb = 2\n{}",
        toml_point(1, "fixed", [-80.0, 0.0, -50.0]),
        toml_point(2, "coupled", [0.0, 0.0, -5.0]),
        chain_run(dynamic)
    )
}

/// A scenario taking the chain's deck (`system.moordyn`), adding the
/// waves in `[water]`.
fn chain_deck_scenario(dynamic: bool) -> String {
    format!(
        "title = \"twin\"\n[system]\nmoordyn = \"deck.txt\"\n[water]\n{CHAIN_WAVES}{}",
        chain_run(dynamic)
    )
}

/// Writes the deck and its current file into `dir`.
fn write_chain_deck(dir: &Path, options: &str) {
    std::fs::write(dir.join("deck.txt"), chain_deck(options)).unwrap();
    std::fs::write(dir.join("current_profile.txt"), CHAIN_CURRENT).unwrap();
}

/// The deck (with its current file) and its TOML twin describe the same
/// inputs to the same code, so every results file agrees to the bit:
/// the static equilibrium on the bed in the current, and 10 steps in the
/// current and the waves from it.
#[test]
fn a_deck_with_water_options_and_its_toml_twin_write_identical_results() {
    for dynamic in [false, true] {
        let d = scratch(&format!("water-twin-{dynamic}"));
        write_chain_deck(&d, "");
        let deck = write_scenario(&d, "deck.toml", &chain_deck_scenario(dynamic));
        let toml = write_scenario(&d, "twin.toml", &chain_toml(dynamic));
        let (out_deck, out_toml) = (d.join("out-deck"), d.join("out-toml"));
        for (sc, out) in [(&deck, &out_deck), (&toml, &out_toml)] {
            let o = run_quiet(sc, out, &[]);
            assert_eq!(o.status.code(), Some(0), "{}", text(&o).1);
        }
        for f in [
            "lines/1/nodes.csv",
            "lines/1/stress.csv",
            "points.csv",
            "tensions.csv",
            "history.csv",
        ] {
            let a = std::fs::read(out_deck.join(f)).unwrap();
            let b = std::fs::read(out_toml.join(f)).unwrap();
            assert!(a == b, "dynamic {dynamic}: {f} differs");
        }
        let (_, rows) = read_csv(&out_toml.join("lines/1/nodes.csv"));
        let steps = if dynamic { 11 } else { 1 };
        assert_eq!(rows.len(), 21 * steps, "dynamic {dynamic}");
        let resting = rows[..21].iter().filter(|r| r[4] < -49.9).count();
        assert!(resting >= 3, "the chain rests on the bed: {resting} nodes");
    }
}

/// `stancf check` shows the water: depth, density, the seabed, the
/// current's rows and where they come from, the waves.
#[test]
fn check_shows_the_water_its_seabed_current_and_waves() {
    let d = scratch("water-check");
    write_chain_deck(&d, "");
    let deck = write_scenario(&d, "deck.toml", &chain_deck_scenario(true));
    let o = stancf(&["check", deck.to_str().unwrap()]);
    let (so, se) = text(&o);
    assert_eq!(o.status.code(), Some(0), "{se}");
    for needle in [
        "depth 50 m, density 1025 kg/m^3",
        "kBot 3e6 Pa/m",
        "friction 0.5 axial and 0.5 transverse",
        "3 rows, z = -50 m: 0.2 m/s to z = 0 m: 0.6 m/s",
        "current_profile.txt (the deck's Currents 1)",
        "1 regular Airy wave(s)",
        "ramped over 0.01 s",
    ] {
        assert!(so.contains(needle), "{needle:?} not in:\n{so}");
    }
}

/// A taut, neutrally buoyant line across the deck's current (the
/// current file's rows interpolated to 0.5 m/s along y at its depth)
/// carries MoorDyn's normal drag f = rho_w Cd d U^2 / 2 per unstretched
/// length (W19): its ends hold f L0 cos^3(theta) summed over the line,
/// theta its angle to the chord, so between f L0 (1 - 3/2 theta0^2) and
/// f L0 (theta0 the end's, 4e-3 here). The static tolerance adds 1e-8.
#[test]
fn a_decks_current_file_drags_a_taut_line_by_morisons_normal_drag() {
    let d = scratch("water-drag");
    let area = PI * 0.05 * 0.05 / 4.0;
    let mass = 1025.0 * area;
    let (ea, tension, span) = (1.0e7, 1.0e5, 100.0);
    let length = span / (1.0 + tension / ea);
    let deck = chain_deck("")
        .replace("12.0     2.0E6     -0.8 ", &format!("{mass:?} 1.0E7 0.0 "))
        .replace("0.01  0.5", "0.0   0.0")
        .replace("-80.0    0.0      -50.0", "0.0      0.0      -20.0")
        .replace("0.0      0.0      -5.0 ", "100.0    0.0      -20.0")
        .replace("2   Coupled", "2   Fixed  ")
        .replace("100.0     20", &format!("{length:?} 20"));
    std::fs::write(d.join("deck.txt"), deck).unwrap();
    let current = "header\nheader\nheader\n0.0 0.0 0.7 0.0\n-50.0 0.0 0.2 0.0\n";
    std::fs::write(d.join("current_profile.txt"), current).unwrap();
    let out = d.join("out");
    let o = run_quiet(&d.join("deck.txt"), &out, &[]);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o).1);
    let ends = read_tensions(&out.join("tensions.csv"));
    assert_eq!(ends.len(), 2);
    let drag: f64 = ends.iter().map(|r| r[4]).sum();
    let u = 0.2 + 0.5 * 30.0 / 50.0;
    let expected = 0.5 * 1025.0 * 1.2 * 0.05 * u * u * length;
    let theta0 = (ends[0][4] / ends[0][3]).abs().atan();
    assert!(theta0 < 5e-3, "theta0 {theta0}");
    let low = expected * (1.0 - 1.5 * theta0 * theta0) - 1e-8 * expected;
    let high = expected * (1.0 + 1e-8);
    assert!(
        (low..=high).contains(&drag),
        "end forces along the current {drag} N, f L0 = {expected} N (theta0 {theta0})"
    );
}

/// A rope from z = -20 m to z = +5 m, through the still surface, runs;
/// its ends carry its weight less the buoyancy of its submerged length
/// (W17-W18): the line pulls its points down by m g L0 - rho_w A g L0_sub,
/// L0_sub the unstretched length below z = 0 read from its nodes. The
/// surface's smoothstep is odd about z = 0 and leaves nothing; the axial
/// Gauss rule of the element the surface cuts integrates a step 1 cm wide
/// and errs by less than the spacing of its points (the separation
/// theorem of Gauss rules), under the element's length h: the bound is
/// rho_w A g h (measured 0.11 h).
#[test]
fn a_line_through_the_water_surface_runs_and_carries_its_wet_and_dry_weight() {
    let d = scratch("water-surface");
    let scenario = format!(
        "{}[water]\ndepth = 30.0\n[analysis]\ntype = \"static\"\n",
        one_rope(
            "surface",
            "cd = 1.2\nca = 1.0",
            ("fixed", [10.0, 0.0, 5.0]),
            (1, 27.0, 20),
            ""
        )
    )
    .replace("position = [0.0, 0.0, 0.0]", "position = [0.0, 0.0, -20.0]");
    let path = write_scenario(&d, "surface.toml", &scenario);
    let out = d.join("out");
    let o = run_quiet(&path, &out, &[]);
    assert_eq!(o.status.code(), Some(0), "{}\n{scenario}", text(&o).1);
    let (_, nodes) = read_csv(&out.join("lines/1/nodes.csv"));
    let crossing = nodes.windows(2).position(|w| w[1][4] > 0.0).unwrap();
    let (z0, z1) = (nodes[crossing][4], nodes[crossing + 1][4]);
    let h = 27.0 / 20.0;
    let submerged = h * (crossing as f64 + z0 / (z0 - z1));
    let (g, area) = (9.81, PI * 0.01 * 0.01 / 4.0);
    let buoyancy = 1025.0 * area * g * submerged;
    let expected = -0.08 * g * 27.0 + buoyancy;
    let ends = read_tensions(&out.join("tensions.csv"));
    let fz: f64 = ends.iter().map(|r| r[5]).sum();
    assert!(
        (fz - expected).abs() <= 1025.0 * area * g * h,
        "ends' vertical force {fz} N, weight less buoyancy {expected} N ({submerged} m below)"
    );
}

/// The lazy-wave example (three lines of two line types joined at free
/// points) holds its wave: at the static equilibrium the buoyant section
/// arches above the sag bend of the upper cable (a hog bend higher than
/// the sag bend), the lower cable touches down and rests on the bed
/// (the bed pushes its last nodes), and two seconds under the wave run;
/// `stancf plot` draws the curvature along the lines.
#[test]
fn the_lazy_wave_example_holds_its_wave_and_plots_its_curvature() {
    let d = scratch("water-lazy-wave");
    let example = std::fs::read_to_string(repo_file("examples/lazy-wave.toml")).unwrap();
    let short = example.replace("duration = 40.0", "duration = 2.0");
    assert_ne!(short, example, "the example's duration moved");
    let sc = write_scenario(&d, "lazy-wave.toml", &short);
    let out = d.join("out");
    let o = run_quiet(&sc, &out, &[]);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o).1);
    let heights = |line: usize| -> Vec<f64> {
        let nodes = std::fs::read_to_string(out.join(format!("lines/{line}/nodes.csv"))).unwrap();
        nodes
            .lines()
            .skip(1)
            .map(|l| l.split(',').collect::<Vec<_>>())
            .filter(|f| f[0] == "0")
            .map(|f| f[4].parse().unwrap())
            .collect()
    };
    let sag = heights(1).into_iter().fold(f64::INFINITY, f64::min);
    let hog = heights(2).into_iter().fold(f64::NEG_INFINITY, f64::max);
    assert!(hog > sag + 2.0, "hog bend {hog} m, sag bend {sag} m");
    let loads = std::fs::read_to_string(out.join("lines/3/node_loads.csv")).unwrap();
    let resting = loads
        .lines()
        .skip(1)
        .map(|l| l.split(',').collect::<Vec<_>>())
        .filter(|f| f[0] == "0" && f[7].parse::<f64>().unwrap() > 0.0)
        .count();
    assert!(resting >= 5, "{resting} nodes of line 3 on the bed");
    let o = stancf(&["plot", out.to_str().unwrap()]);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o).1);
    assert!(out.join("curvature.svg").exists());
}

/// A dynamic run in water writes the water's and the seabed's work so far
/// in history.csv (`water_work`, `seabed_work`, the library's
/// `SystemSimulation::water_work` and `seabed_work`): zero at the start,
/// and not after the lazy-wave example's first two seconds, where the
/// water and the bed both work.
#[test]
fn history_carries_the_water_and_seabed_work() {
    let d = scratch("water-history-work");
    let example = std::fs::read_to_string(repo_file("examples/lazy-wave.toml")).unwrap();
    let sc = write_scenario(
        &d,
        "lazy.toml",
        &example.replace("duration = 40.0", "duration = 2.0"),
    );
    let out = d.join("out");
    let o = run_quiet(&sc, &out, &[]);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o).1);
    let (header, rows) = read_csv(&out.join("history.csv"));
    let (water, bed) = (
        header
            .iter()
            .position(|h| h == "water_work")
            .expect("water_work"),
        header
            .iter()
            .position(|h| h == "seabed_work")
            .expect("seabed_work"),
    );
    let last = rows.last().unwrap();
    assert!(last[water] != 0.0 && last[bed] != 0.0, "{last:?}");
    assert!(
        rows[0][water] == 0.0 && rows[0][bed] == 0.0,
        "{:?}",
        rows[0]
    );
}

/// `--water-depth` is the host's depth of a deck without WtrDpth (a glue
/// code's deck): `check` and `run` take it where the deck says nothing,
/// and say so; the deck's own WtrDpth wins, with a note.
#[test]
fn the_command_lines_water_depth_is_a_decks_without_wtrdpth() {
    let d = scratch("water-depth-flag");
    let oc4 = std::fs::read_to_string(repo_file("examples/oc4-deepcwind-moordyn.txt")).unwrap();
    let without: String = oc4
        .lines()
        .filter(|l| l.split_whitespace().nth(1) != Some("WtrDpth"))
        .map(|l| format!("{l}\n"))
        .collect();
    std::fs::write(d.join("glue.txt"), without).unwrap();
    let deck = d.join("glue.txt");
    let deck = deck.to_str().unwrap();
    let (so, se) = text_of_check(&["check", deck, "--water-depth", "210"]);
    assert!(so.contains("depth 210 m"), "{so}{se}");
    assert!(
        so.contains("no WtrDpth: the host's water depth, 210 m"),
        "{so}"
    );
    let (so, _) = text_of_check(&["check", deck]);
    assert!(
        so.contains("depth 200 m") && so.contains("MoorDyn's rule"),
        "{so}"
    );
    let own = repo_file("examples/oc4-deepcwind-moordyn.txt");
    let (so, _) = text_of_check(&["check", own.to_str().unwrap(), "--water-depth", "210"]);
    assert!(so.contains("depth 200 m"), "{so}");
    assert!(so.contains("the deck's WtrDpth 200 m is used; the host's water depth, 210 m, is not"));
    for (flag, out) in [(Some("210"), "out-210"), (None, "out-rule")] {
        let mut args = vec!["run", "--quiet", deck, "--out"];
        let out = d.join(out);
        args.push(out.to_str().unwrap());
        if let Some(h) = flag {
            args.extend(["--water-depth", h]);
        }
        let o = stancf(&args);
        assert_eq!(o.status.code(), Some(0), "{}", text(&o).1);
    }
    let fairlead = |out: &str| read_tensions(&d.join(out).join("tensions.csv"))[1][6];
    let (deeper, rule) = (fairlead("out-210"), fairlead("out-rule"));
    assert!(
        (deeper - rule).abs() > 1e-3 * rule,
        "{deeper} against {rule}"
    );
    let o = stancf(&["check", deck, "--water-depth=-3"]);
    assert_eq!(o.status.code(), Some(2));
    assert!(
        text(&o).1.contains("the host's water depth is -3 m"),
        "{}",
        text(&o).1
    );
}

/// `stancf <args>`'s standard output and error, the exit code 0.
fn text_of_check(args: &[&str]) -> (String, String) {
    let o = stancf(args);
    assert_eq!(o.status.code(), Some(0), "{args:?}: {}", text(&o).1);
    text(&o)
}

/// MoorDyn-F's `mu_kT` and `mu_kA` are the seabed's transverse and axial
/// friction coefficients (`check` shows them); beside MoorDyn-C's one
/// `FrictionCoefficient` they are refused naming both lines.
#[test]
fn moordyn_fs_friction_coefficients_are_the_seabeds_transverse_and_axial() {
    let d = scratch("water-mu-k");
    let deck = chain_deck("0.3 mu_kT\n0.6 mu_kA\n").replace("0.5       FrictionCoefficient\n", "");
    std::fs::write(d.join("deck.txt"), &deck).unwrap();
    std::fs::write(d.join("current_profile.txt"), CHAIN_CURRENT).unwrap();
    let (so, se) = text_of_check(&["check", d.join("deck.txt").to_str().unwrap()]);
    assert!(
        so.contains("friction 0.6 axial and 0.3 transverse"),
        "{so}{se}"
    );
    std::fs::write(d.join("both.txt"), chain_deck("0.3 mu_kT\n")).unwrap();
    let o = stancf(&["check", d.join("both.txt").to_str().unwrap()]);
    assert_eq!(o.status.code(), Some(2));
    let e = text(&o).1;
    assert!(
        e.contains("option mu_kT and FrictionCoefficient") && e.contains("give one of them"),
        "{e}"
    );
}
