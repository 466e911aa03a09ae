//! Pinned rods from decks (`Pinned`, `Body<n>Pinned` on a fixed body) and
//! TOML (`type = "pinned"`), docs/method.md §15.12: the lean in a
//! current, the physical pendulum, and what is refused.

use crate::common::*;
use std::f64::consts::PI;

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

/// `Body1Pinned` on a coupled body (docs/method.md §15.17), held at its
/// pose in a run: the rod is pinned at the body's point where the pose
/// puts its end A (the body at (1, 2, -20) turned 90 degrees in yaw) and
/// leans in the current as the same rod `Pinned` there does, its pose the
/// same to 1e-9 (m, degrees); and the body is pulled by the rod and the
/// line at its end A as the fixed pin's point is (points.csv there, the
/// line's and the rod's pull), to 1e-9 of it.
#[test]
fn a_rod_pinned_to_a_coupled_body_leans_as_on_a_fixed_pin() {
    let d = scratch("pinned-rod-coupled-body");
    std::fs::write(d.join("current_profile.txt"), PINNED_CURRENT).unwrap();
    let body = "1      Coupled   1.0    2    -20.0   0       0      90     0     0    0        0        0       0\n";
    let on_body = write_scenario(
        &d,
        "on-body.txt",
        &pinned_rod_deck("Body1Pinned", "-2    1     2     -2    1     6   ", body),
    );
    let global = write_scenario(
        &d,
        "global.txt",
        &pinned_rod_deck("Pinned     ", "0     0     -18   0     0     -14 ", ""),
    );
    let run = |deck: &std::path::PathBuf, name: &str| {
        let out = d.join(name);
        let o = run_quiet(deck, &out, &[]);
        assert_eq!(o.status.code(), Some(0), "{}", text(&o).1);
        out
    };
    let (a, b) = (run(&on_body, "on-body"), run(&global, "global"));
    let row = |out: &std::path::Path, body: f64, names: [&str; 3]| {
        let (header, rows) = read_csv(&out.join("bodies.csv"));
        let col = |c: &str| header.iter().position(|h| h == c).unwrap();
        let r = rows
            .iter()
            .find(|r| r[col("body")] == body)
            .expect("a body");
        names.map(|c| r[col(c)])
    };
    let pose = |out: &std::path::Path, body: f64| {
        let [x, y, z] = row(out, body, ["x", "y", "z"]);
        let [r, p, w] = row(out, body, ["roll", "pitch", "yaw"]);
        [x, y, z, r, p, w]
    };
    let (on, at) = (pose(&a, 2.0), pose(&b, 1.0));
    eprintln!("pinned to a coupled body: {on:?}; pinned globally: {at:?}");
    assert!(on[4] > 1.0, "it leans: {on:?}");
    for k in 0..6 {
        assert!((on[k] - at[k]).abs() < 1e-9, "{k}: {on:?} against {at:?}");
    }
    let pulled = row(&a, 1.0, ["fx", "fy", "fz"]);
    let (header, rows) = read_csv(&b.join("points.csv"));
    let col = |c: &str| header.iter().position(|h| h == c).unwrap();
    let pin = rows
        .iter()
        .find(|r| r[col("point")] == 3.0)
        .expect("the pin's point");
    let held = ["fx", "fy", "fz"].map(|c| pin[col(c)]);
    let size = held.iter().fold(0.0f64, |m, f| m.max(f.abs()));
    eprintln!("the coupled body pulled by {pulled:?}, the fixed pin's point by {held:?}");
    for k in 0..3 {
        assert!(
            (pulled[k] - held[k]).abs() < 1e-9 * size,
            "{pulled:?} {held:?}"
        );
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
/// line or the key, nothing written: a pinned rod of zero length.
#[test]
fn what_pinned_rods_do_not_build_is_refused_naming_the_line_or_key() {
    let d = scratch("pinned-rod-refusals");
    std::fs::write(d.join("current_profile.txt"), PINNED_CURRENT).unwrap();
    let cases = [(
        pinned_rod_deck("Pin", "0     0     -18   0     0     -14 ", "")
            .replace("-14   8       -", "-18   0       -"),
        "rod 1 is pinned with NumSegs 0, a rod of zero length",
    )];
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
}
