//! Nonlinear axial laws from a tension-strain table (docs/method.md
//! §2.2a, (M4b); issue 32): a MoorDyn deck's EA given as a curve file
//! and a TOML line type's `ea_curve`, against the closed-form stretch of
//! a hanging line, with the energy balance of its motion, and the
//! refusals.

use crate::common::*;

/// The rope's table: strain, tension (N).
const TABLE: [(f64, f64); 4] = [(0.0, 0.0), (0.01, 1.0e5), (0.03, 5.0e5), (0.06, 1.4e6)];
const CURVE_FILE: &str = "Polyester rope: tension against strain\nStrain Tension\n(-) (N)\n\
                          0.0 0.0\n0.01 1.0e5\n0.03 5.0e5\n0.06 1.4e6\n";
const DIAMETER: f64 = 0.111464;
const G: f64 = 9.81;
const RHO: f64 = 1025.0;
const LENGTH: f64 = 100.0;

/// A weight of `mass` kg (no volume) on 100 m of the rope (`mass_per_length`
/// kg/m) below a fixed point at the surface, in `segments` elements; the
/// rope's EA is `ea` (the curve file's name, or a number).
fn deck(mass_per_length: f64, mass: f64, segments: usize, ea: &str) -> String {
    format!(
        "A weight on a polyester rope\n--- LINE TYPES ---\n\
         TypeName Diam Mass/m EA BA/-zeta EI Cd Ca CdAx CaAx\n\
         (name) (m) (kg/m) (N) (N-s/-) (N-m^2) (-) (-) (-) (-)\n\
         poly {DIAMETER} {mass_per_length} {ea} 0 0 0 0 0 0\n\
         --- POINTS ---\nID Attachment X Y Z Mass Volume CdA Ca\n\
         (#) (-) (m) (m) (m) (kg) (m^3) (m^2) (-)\n\
         1 Fixed 0 0 0 0 0 0 0\n2 Free 0 0 -100 {mass} 0 0 0\n\
         --- LINES ---\nID LineType AttachA AttachB UnstrLen NumSegs Outputs\n\
         (#) (name) (#) (#) (m) (-) (-)\n1 poly 1 2 {LENGTH} {segments} -\n\
         --- OPTIONS ---\n{G} g\n300 WtrDpth\n{RHO} WtrDnsty\n--- need this line ---\n"
    )
}

/// The strain at tension T: the table's inverse, linear between its
/// points (and along its last segment beyond them).
fn strain_at(t: f64) -> f64 {
    let k = (1..TABLE.len() - 1)
        .take_while(|&k| TABLE[k].1 <= t)
        .count();
    let (a, b) = (TABLE[k], TABLE[k + 1]);
    a.0 + (t - a.1) * (b.0 - a.0) / (b.1 - a.1)
}

/// The weight's depth in closed form: the line hangs straight, its
/// tension T = P + w s at s from the weight, so its stretched length is
/// L + int_0^L eps(T(s)) ds = L + (1/w) int_P^(P + w L) eps(T) dT, exact
/// by the trapezoid rule over the table's points (eps(T) is linear
/// between them).
fn closed_form_depth(mass_per_length: f64, mass: f64) -> f64 {
    let w = (mass_per_length - RHO * std::f64::consts::PI * DIAMETER * DIAMETER / 4.0) * G;
    let (bottom, top) = (mass * G, mass * G + w * LENGTH);
    let mut knots = vec![bottom.min(top)];
    knots.extend(
        TABLE
            .iter()
            .map(|p| p.1)
            .filter(|&t| t > bottom.min(top) && t < bottom.max(top)),
    );
    knots.push(bottom.max(top));
    let integral: f64 = knots
        .windows(2)
        .map(|k| 0.5 * (strain_at(k[0]) + strain_at(k[1])) * (k[1] - k[0]))
        .sum();
    -(LENGTH + integral / w.abs())
}

/// The free point's z of a static run of `deck_text` (the curve file
/// beside it).
fn static_depth(name: &str, deck_text: &str) -> f64 {
    let d = scratch(name);
    std::fs::write(d.join("poly_ea.txt"), CURVE_FILE).unwrap();
    let path = write_scenario(&d, "deck.txt", deck_text);
    let out = d.join("out");
    let o = run_quiet(&path, &out, &[]);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o).1);
    let (h, rows) = read_csv(&out.join("points.csv"));
    let col = |n: &str| h.iter().position(|c| c == n).unwrap();
    rows.iter().find(|r| r[col("point")] == 2.0).unwrap()[col("z")]
}

/// A weight on a rope whose EA is MoorDyn's curve file hangs at the
/// closed-form stretch of the table: where the line's tension stays in
/// one segment of it (a rope nearly as dense as the water, 3e5 N; the
/// same rope three times as heavy) its strain is linear along the line,
/// which the cubic elements hold, so the depth is the closed form's to
/// the solve's tolerance (bound 1e-8 m); where the tension crosses the
/// table's kink at 5e5 N (4.9e5 to 5.1e5 N along the line) the strain
/// has a kink inside an element, and the error falls with the elements
/// (10 to 40: at least 16 times, second order; measured 2.3e-6 to
/// 1.9e-8 m).
#[test]
fn a_weight_on_a_rope_of_a_tension_strain_curve_hangs_at_its_closed_form_stretch() {
    let mass = 3.0e5 / G;
    for (name, w) in [("light", 10.0), ("heavy", 30.0)] {
        let got = static_depth(
            &format!("ea-curve-{name}"),
            &deck(w, mass, 10, "poly_ea.txt"),
        );
        let want = closed_form_depth(w, mass);
        eprintln!("{name}: z = {got} m against {want} m");
        assert!((got - want).abs() < 1e-8, "{name}: {got} against {want}");
    }
    let kink = 4.9e5 / G;
    let want = closed_form_depth(30.0, kink);
    let errors: Vec<f64> = [10, 40]
        .iter()
        .map(|&n| {
            let got = static_depth(
                &format!("ea-curve-kink-{n}"),
                &deck(30.0, kink, n, "poly_ea.txt"),
            );
            eprintln!("kink, {n} elements: z = {got} m against {want} m");
            (got - want).abs()
        })
        .collect();
    assert!(
        errors[1] < errors[0] / 16.0 && errors[1] < 1e-6,
        "{errors:?}"
    );
}

/// `ea_curve` of a TOML line type is the deck's curve file: the same
/// rope and weight in a scenario give the deck's depth to round-off.
#[test]
fn a_toml_ea_curve_is_a_decks_curve_file() {
    let mass = 3.0e5 / G;
    let from_deck = static_depth("ea-curve-deck", &deck(30.0, mass, 10, "poly_ea.txt"));
    let d = scratch("ea-curve-toml");
    let pairs: Vec<String> = TABLE
        .iter()
        .map(|(e, t)| format!("[{e:?}, {t:?}]"))
        .collect();
    let sc = format!(
        "title = \"rope\"\n[water]\ndepth = 300.0\ndensity = {RHO}\n\
         [[line_types]]\nname = \"poly\"\ndiameter = {DIAMETER}\nmass_per_length = 30.0\n\
         ea_curve = [{}]\ncompression = false\n\
         [[points]]\nid = 1\ntype = \"fixed\"\nposition = [0.0, 0.0, 0.0]\n\
         [[points]]\nid = 2\ntype = \"free\"\nposition = [0.0, 0.0, -100.0]\nmass = {mass:?}\n\
         [[lines]]\nid = 1\ntype = \"poly\"\nlength = {LENGTH}\nelements = 10\na = 1\nb = 2\n\
         [analysis]\ntype = \"static\"\n",
        pairs.join(", ")
    );
    let path = write_scenario(&d, "rope.toml", &sc);
    let out = d.join("out");
    let o = run_quiet(&path, &out, &[]);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o).1);
    let (h, rows) = read_csv(&out.join("points.csv"));
    let col = |n: &str| h.iter().position(|c| c == n).unwrap();
    let got = rows.iter().find(|r| r[col("point")] == 2.0).unwrap()[col("z")];
    assert!((got - from_deck).abs() < 1e-9, "{got} against {from_deck}");
}

/// The rope released straight and unstretched with its weight swings
/// through the table's kinks (and its slack one); the energy balance of
/// the Galerkin step (the mechanical energy less the water's work,
/// history.csv) then holds to the step's error, which falls as the step
/// does: from dt = 0.01 to 0.005 s by at least 4 (second order; the
/// kinks take the step below its order 6 on smooth laws; measured 49.4
/// and 3.3 J of 1.2e6 J of strain energy, 15 times).
#[test]
fn a_rope_of_a_tension_strain_curve_keeps_its_energy_balance_as_the_step_falls() {
    let d = scratch("ea-curve-energy");
    std::fs::write(d.join("poly_ea.txt"), CURVE_FILE).unwrap();
    std::fs::write(d.join("deck.txt"), deck(30.0, 3.0e5 / G, 10, "poly_ea.txt")).unwrap();
    let drift = |dt: f64| -> f64 {
        let path = write_scenario(
            &d,
            &format!("run-{dt}.toml"),
            &format!(
                "title = \"bounce\"\n[system]\nmoordyn = \"deck.txt\"\n[analysis]\n\
                 type = \"dynamic\"\ninitial = \"reference\"\ntime_scheme = \"galerkin\"\n\
                 time_step = {dt}\nduration = 6.0\n"
            ),
        );
        let out = d.join(format!("out-{dt}"));
        let o = run_quiet(&path, &out, &[]);
        assert_eq!(o.status.code(), Some(0), "{}", text(&o).1);
        let (h, rows) = read_csv(&out.join("history.csv"));
        let col = |n: &str| h.iter().position(|c| c == n).unwrap();
        let balance = |r: &Vec<f64>| r[col("total")] - r[col("water_work")];
        let start = balance(&rows[0]);
        rows.iter()
            .map(|r| (balance(r) - start).abs())
            .fold(0.0, f64::max)
    };
    let (coarse, fine) = (drift(0.01), drift(0.005));
    eprintln!("energy balance drift: {coarse} J at dt 0.01 s, {fine} J at 0.005 s");
    assert!(fine < coarse / 4.0 && fine < 50.0, "{coarse} {fine}");
}

/// Refused, naming the deck's line and the file or the key: a curve file
/// that is not there, one whose tension falls, a row that is not two
/// numbers; in TOML, `ea` beside `ea_curve` and a curve not starting at
/// (0, 0).
#[test]
fn a_tension_strain_curve_that_cannot_be_used_is_refused_naming_it() {
    let d = scratch("ea-curve-refused");
    let cases = [
        ("missing", None, "no file poly_ea.txt"),
        (
            "falls",
            Some(CURVE_FILE.replace("0.06 1.4e6", "0.06 4.0e5")),
            "point 4: the tension 400000 N falls below",
        ),
        (
            "words",
            Some(CURVE_FILE.replace("0.03 5.0e5", "0.03 five")),
            "line 6: \"0.03 five\" is not a strain and a tension",
        ),
    ];
    for (name, curve, needle) in cases {
        let dir = d.join(name);
        std::fs::create_dir_all(&dir).unwrap();
        if let Some(c) = curve {
            std::fs::write(dir.join("poly_ea.txt"), c).unwrap();
        }
        let path = dir.join("deck.txt");
        std::fs::write(&path, deck(30.0, 1000.0, 10, "poly_ea.txt")).unwrap();
        refused_by_check_and_run(
            &path,
            &dir.join("never"),
            &["line 5", "EA of line type \"poly\"", needle],
            &[],
        );
    }
    let toml = |curve: &str| {
        format!(
            "title = \"rope\"\n[[line_types]]\nname = \"poly\"\ndiameter = 0.1\nmass_per_length = 30.0\n\
             {curve}\n[[points]]\nid = 1\ntype = \"fixed\"\nposition = [0.0, 0.0, 0.0]\n\
             [[points]]\nid = 2\ntype = \"fixed\"\nposition = [0.0, 0.0, -100.0]\n\
             [[lines]]\nid = 1\ntype = \"poly\"\nlength = 100.0\nelements = 4\na = 1\nb = 2\n\
             [analysis]\ntype = \"static\"\n"
        )
    };
    for (name, keys, needle) in [
        (
            "both",
            "ea = 1.0e6\nea_curve = [[0.0, 0.0], [0.01, 1.0e5]]",
            "leave `ea` out",
        ),
        (
            "offset",
            "ea_curve = [[0.01, 0.0], [0.02, 1.0e5]]",
            "must start at zero strain",
        ),
    ] {
        let path = write_scenario(&d, &format!("{name}.toml"), &toml(keys));
        refused_by_check_and_run(
            &path,
            &d.join(format!("never-{name}")),
            &["line_types[0].ea_curve", needle],
            &[],
        );
    }
}

/// The P2 step's stability is judged where the table is stiffest
/// (docs/method.md §2.2a, §4.6): the rope's stable step is that of the
/// same rope with the constant EA of its steepest segment, 3e7 N (to 1 %:
/// the stretched state's geometric stiffness T / |r_x| is the only
/// difference; measured equal to 6 digits), and not that of its first,
/// 1e7 N, sqrt(3) times longer.
#[test]
fn a_rope_of_a_tension_strain_curve_has_the_stable_step_of_its_stiffest_segment() {
    let d = scratch("ea-curve-stable-step");
    std::fs::write(d.join("poly_ea.txt"), CURVE_FILE).unwrap();
    let step = |name: &str, ea: &str| -> f64 {
        std::fs::write(d.join(format!("{name}.txt")), deck(30.0, 3.0e5 / G, 10, ea)).unwrap();
        let path = write_scenario(
            &d,
            &format!("{name}.toml"),
            &format!(
                "title = \"p2\"\n[system]\nmoordyn = \"{name}.txt\"\n[analysis]\ntype = \"dynamic\"\n\
                 initial = \"reference\"\ntime_step = 0.001\nduration = 0.01\n"
            ),
        );
        let o = stancf(&["check", path.to_str().unwrap()]);
        assert_eq!(o.status.code(), Some(0), "{}", text(&o).1);
        let out = text(&o).0;
        let line = out
            .lines()
            .find(|l| l.starts_with("stable step (P2)"))
            .expect(&out);
        line.split_whitespace().nth(3).unwrap().parse().unwrap()
    };
    let (curve, steepest, first) = (
        step("curve", "poly_ea.txt"),
        step("steep", "3.0e7"),
        step("first", "1.0e7"),
    );
    eprintln!("stable steps: curve {curve} s, EA 3e7 {steepest} s, EA 1e7 {first} s");
    assert!((curve / steepest - 1.0).abs() < 0.01, "{curve} {steepest}");
    assert!(first > 1.5 * curve, "{first} {curve}");
}
