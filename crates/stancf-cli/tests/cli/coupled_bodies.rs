//! Coupled bodies from scenarios and decks (docs/interface.md, "Rigid
//! bodies" and "Coupling"; docs/method.md §13.6): a TOML `type =
//! "coupled"` body and a deck's Coupled, Vessel, Ves and Cpld bodies
//! open as coupled bodies, their 6 numbers first in the coupling arrays;
//! a run holds them at their pose and writes the lines' force and moment
//! on them; what a coupled body does not take is refused by name.

use crate::common::*;
use stancf_cli::coupling;
use std::path::Path;

/// MoorDyn's example/body.txt (OC3-Hywind): coupled body 1 at z = -70 m,
/// three 902.2 m chains from its points 4, 5, 6 to anchors 1, 2, 3.
const OC3_DECK: &str = "crates/stancf-cli/tests/fixtures/oc3-coupled-body-moordyn.txt";

/// 40 Galerkin steps of 5 ms from the static equilibrium (the Galerkin
/// form, as no stiffness destabilizes it: the chains' P2 step would be
/// 0.7 ms).
const DYNAMIC: &str = "type = \"dynamic\"\ninitial = \"static\"\ntime_step = 0.005\n\
                       duration = 0.2\ntime_scheme = \"galerkin\"";

fn oc3_deck() -> String {
    std::fs::read_to_string(repo_file(OC3_DECK)).unwrap()
}

/// Coupled body 7 at [0, 0, -10] m (its pose: `angles`, degrees, and
/// `body_keys`) in 50 m of water, held by three chains from its points
/// 1, 2, 3 (1 m out, 0.5 m below its reference point) to anchors 4, 5, 6;
/// coupled point 10 at [0, 20, -5] m on a chain to anchor 11; `analysis`
/// the [analysis] table.
fn coupled_body_toml(body_keys: &str, analysis: &str) -> String {
    let mut s = String::from(
        "title = \"coupled body\"\n[water]\ndepth = 50.0\ndensity = 1025.0\n\
         [[line_types]]\nname = \"chain\"\ndiameter = 0.02\nmass_per_length = 2.0\n\
         ea = 1.0e7\ncd = 1.2\nca = 1.0\n\
         [[bodies]]\nid = 7\ntype = \"coupled\"\nposition = [0.0, 0.0, -10.0]\n",
    );
    s.push_str(body_keys);
    s.push('\n');
    for k in 0..3 {
        let angle = 2.0 * std::f64::consts::PI * k as f64 / 3.0;
        let (c, sn) = (angle.cos(), angle.sin());
        s.push_str(&format!(
            "[[points]]\nid = {}\ntype = \"body\"\nbody = 7\nposition = [{c:?}, {sn:?}, -0.5]\n\
             [[points]]\nid = {}\ntype = \"fixed\"\nposition = [{:?}, {:?}, -50.0]\n\
             [[lines]]\nid = {}\ntype = \"chain\"\nlength = 60.0\nelements = 12\na = {}\nb = {}\n",
            k + 1,
            k + 4,
            50.0 * c,
            50.0 * sn,
            k + 1,
            k + 4,
            k + 1
        ));
    }
    s.push_str(
        "[[points]]\nid = 10\ntype = \"coupled\"\nposition = [0.0, 20.0, -5.0]\n\
         [[points]]\nid = 11\ntype = \"fixed\"\nposition = [0.0, 45.0, -50.0]\n\
         [[lines]]\nid = 4\ntype = \"chain\"\nlength = 55.0\nelements = 12\na = 11\nb = 10\n",
    );
    s.push_str(&format!("[analysis]\n{analysis}\n"));
    s
}

fn cross(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

fn three(row: &[f64], first: usize) -> [f64; 3] {
    [row[first], row[first + 1], row[first + 2]]
}

/// The largest difference of two vectors.
fn gap(a: &[f64], b: &[f64]) -> f64 {
    a.iter()
        .zip(b)
        .map(|(x, y)| (x - y).abs())
        .fold(0.0, f64::max)
}

/// The lines' force on a body and their moment about `reference` from
/// points.csv rows (t, point, x, y, z, vx, vy, vz, fx, fy, fz) of `points`.
fn sums(rows: &[&Vec<f64>], reference: [f64; 3]) -> ([f64; 3], [f64; 3]) {
    let mut f = [0.0; 3];
    let mut m = [0.0; 3];
    for r in rows {
        let (x, fp) = (three(r, 2), three(r, 8));
        let arm = [
            x[0] - reference[0],
            x[1] - reference[1],
            x[2] - reference[2],
        ];
        let mp = cross(arm, fp);
        for c in 0..3 {
            f[c] += fp[c];
            m[c] += mp[c];
        }
    }
    (f, m)
}

/// Each of MoorDyn's coupled words makes the deck's body a coupled body
/// (docs/moordyn-bodies-rods.md §1.1), and `stancf check` says so.
#[test]
fn moordyns_coupled_words_make_a_coupled_body_of_a_deck() {
    let d = scratch("coupled-body-words");
    for word in ["Coupled", "Vessel", "ves", "CPLD"] {
        let deck = oc3_deck().replace("1    Coupled ", &format!("1    {word} "));
        let path = write_scenario(&d, &format!("{word}.txt"), &deck);
        let o = stancf(&["check", path.to_str().unwrap()]);
        let (out, err) = text(&o);
        assert_eq!(o.status.code(), Some(0), "{word}: {err}");
        assert!(
            out.contains("body 1                      coupled (moved by a coupling code")
                && out.contains("on coupled body 1 at [5.2, 0, 0] m"),
            "{word}: {out}"
        );
    }
}

/// A run holds a coupled body at its pose, as a coupled point without a
/// motion: bodies.csv writes the deck's pose and the lines' force and
/// moment, the sums over its points in points.csv to round-off; the
/// coupling handle's static start gives the same forces.
#[test]
fn a_run_holds_a_coupled_body_at_its_pose_and_writes_its_lines_loads() {
    let d = scratch("coupled-body-run");
    let path = write_scenario(&d, "oc3.txt", &oc3_deck());
    let out = d.join("out");
    let o = run_quiet(&path, &out, &[]);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o).1);
    let (_, bodies) = read_csv(&out.join("bodies.csv"));
    let (_, points) = read_csv(&out.join("points.csv"));
    assert_eq!(bodies.len(), 1);
    let b = &bodies[0];
    assert_eq!(
        &b[2..14],
        &[0.0, 0.0, -70.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0]
    );
    let on_body: Vec<&Vec<f64>> = points.iter().filter(|r| r[1] >= 4.0).collect();
    assert_eq!(on_body.len(), 3);
    let (f, m) = sums(&on_body, [0.0, 0.0, -70.0]);
    // The pull is 1.6e6 N: round-off of three sums is a few 1e-10 N.
    let pull = f[2].abs();
    assert!(pull > 1e6, "{f:?}");
    assert!(gap(&f, &b[14..17]) <= 1e-12 * pull, "{f:?} {b:?}");
    assert!(gap(&m, &b[17..20]) <= 1e-12 * pull * 5.2, "{m:?} {b:?}");
    let summary = read_json(&out.join("summary.json"));
    assert_eq!(summary["bodies"][0]["type"], "coupled");
    // The coupling handle's static start: the same equilibrium, so the
    // same loads (to the static solve's tolerance, 1e-9 of the pull).
    let mut opened = coupling::from_text(&oc3_deck(), Path::new("oc3.txt")).unwrap();
    assert_eq!(opened.coupled_body_ids, vec![1]);
    let x0 = opened.handle.initial_positions();
    let start = opened.handle.initialize(&x0, None).unwrap();
    assert!(gap(&start, &b[14..20]) <= 1e-9 * pull, "{start:?} {b:?}");
}

/// The coupling arrays of a TOML system with coupled body 7 and coupled
/// point 10: the body's 6 numbers, then the point's 3; stepped with a
/// surge and a yaw, the body's force and moment are its points' sums and
/// the point's force is its own, to round-off.
#[test]
fn a_toml_coupled_body_comes_first_in_the_coupling_arrays() {
    let text = coupled_body_toml("", DYNAMIC);
    let mut opened = coupling::from_text(&text, Path::new("coupled.toml")).unwrap();
    assert_eq!(opened.coupled_body_ids, vec![7]);
    assert_eq!(opened.coupled_ids, vec![10]);
    let h = &mut opened.handle;
    assert_eq!(h.coupled_dof(), 9);
    let x0 = h.initial_positions();
    assert_eq!(x0, vec![0.0, 0.0, -10.0, 0.0, 0.0, 0.0, 0.0, 20.0, -5.0]);
    h.initialize(&x0, None).unwrap();
    let index = |id: i64| opened.point_ids.iter().position(|&p| p == id).unwrap();
    let h = &mut opened.handle;
    for k in 1..=3 {
        let t = 0.05 * k as f64;
        let mut x = x0.clone();
        x[0] = 0.1 * t; // surge (m)
        x[5] = 0.2 * t; // yaw (rad)
        x[7] = 20.0 + 0.1 * t;
        let f = h.step_to(t, &x, None).unwrap().last_step;
        let mut force = [0.0; 3];
        let mut moment = [0.0; 3];
        for id in 1..=3 {
            let p = h.point(index(id)).unwrap();
            let arm = [
                p.position[0] - x[0],
                p.position[1] - x[1],
                p.position[2] - x[2],
            ];
            let mp = cross(arm, p.force);
            for c in 0..3 {
                force[c] += p.force[c];
                moment[c] += mp[c];
            }
        }
        let scale = force.iter().map(|v| v.abs()).fold(0.0, f64::max);
        assert!(
            gap(&f[0..3], &force) <= 1e-12 * scale,
            "t = {t}: {f:?} {force:?}"
        );
        assert!(
            gap(&f[3..6], &moment) <= 1e-12 * scale,
            "t = {t}: {f:?} {moment:?}"
        );
        let point = h.point(index(10)).unwrap();
        assert_eq!(point.position, [0.0, x[7], -5.0]);
        assert_eq!(&f[6..9], &point.force);
    }
}

/// A dynamic run of the TOML system holds body 7 at its pose (turned by
/// its angles) through the run, its points where the pose puts them.
#[test]
fn a_dynamic_run_holds_a_toml_coupled_body_at_its_pose() {
    let scenario = coupled_body_toml("angles = [0.0, 0.0, 30.0]", DYNAMIC);
    let d = scratch("coupled-body-dynamic");
    let path = write_scenario(&d, "coupled.toml", &scenario);
    let out = d.join("out");
    let o = run_quiet(&path, &out, &[]);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o).1);
    let (_, bodies) = read_csv(&out.join("bodies.csv"));
    let (_, points) = read_csv(&out.join("points.csv"));
    assert!(bodies.len() > 10, "{} rows", bodies.len());
    // Point 1 at 1 m along the body's x axis, turned 30 degrees in yaw.
    let (c, s) = (30f64.to_radians().cos(), 30f64.to_radians().sin());
    for row in &bodies {
        assert_eq!(&row[2..5], &[0.0, 0.0, -10.0]);
        assert!(gap(&row[5..8], &[0.0, 0.0, 30.0]) <= 1e-12, "{row:?}");
        assert!(row[8..14].iter().all(|&v| v == 0.0), "{row:?}");
        let at: Vec<&Vec<f64>> = points
            .iter()
            .filter(|r| r[0] == row[0] && (1.0..=3.0).contains(&r[1]))
            .collect();
        let p1 = at.iter().find(|r| r[1] == 1.0).unwrap();
        assert!(gap(&p1[2..5], &[c, s, -10.5]) <= 1e-12, "{p1:?}");
        let (f, m) = sums(&at, [0.0, 0.0, -10.0]);
        let scale = f.iter().map(|v| v.abs()).fold(0.0, f64::max);
        assert!(gap(&f, &row[14..17]) <= 1e-12 * scale, "{f:?} {row:?}");
        assert!(gap(&m, &row[17..20]) <= 1e-12 * scale, "{m:?} {row:?}");
    }
}

/// A coupled body's mass, inertia, water and velocities are the host's:
/// each key of a free body is refused naming it; so is a clamp at its
/// point.
#[test]
fn what_a_coupled_body_does_not_take_is_refused_by_name() {
    for (key, value) in [
        ("mass", "100.0"),
        ("centre_of_mass", "[0.0, 0.0, -0.3]"),
        ("inertia", "[1.0, 1.0, 1.0]"),
        ("volume", "1.0"),
        ("cda", "[1.0, 1.0, 1.0]"),
        ("rotational_cda", "[1.0, 1.0, 1.0]"),
        ("ca", "[1.0, 1.0, 1.0]"),
        ("velocity", "[1.0, 0.0, 0.0]"),
        ("angular_velocity", "[0.0, 0.0, 0.1]"),
    ] {
        let text = coupled_body_toml(&format!("{key} = {value}"), "type = \"static\"");
        expect_input_error(
            &format!("coupled-body-{key}"),
            &text,
            &[
                &format!("bodies[0].{key}"),
                "a coupled body is moved by the coupling code",
            ],
        );
    }
    let clamped = coupled_body_toml("", "type = \"static\"").replace(
        "a = 4\nb = 1\n",
        "a = 4\nb = 1\nclamp_b = [0.0, 0.0, 1.0]\n",
    );
    expect_input_error(
        "coupled-body-clamp",
        &clamped,
        &[
            "point 1 on coupled body 7",
            "a clamp that turns with a body the host moves",
        ],
    );
}

/// A TOML system whose coupled bodies are written with their ids out of
/// order (9, then 4) puts them in the arrays by id, as MoorDyn does: body
/// 4's pose first in `initial_positions`.
#[test]
fn coupled_bodies_come_in_the_arrays_by_id() {
    let text = coupled_body_toml("", DYNAMIC);
    let two =
        format!("{text}\n[[bodies]]\nid = 4\ntype = \"coupled\"\nposition = [30.0, 0.0, -10.0]\n")
            .replace("[[bodies]]\nid = 7", "[[bodies]]\nid = 9");
    let two = two.replace("body = 7", "body = 9");
    let opened = coupling::from_text(&two, Path::new("coupled.toml")).unwrap();
    assert_eq!(opened.coupled_body_ids, vec![4, 9]);
    let x0 = opened.handle.initial_positions();
    assert_eq!(&x0[0..3], &[30.0, 0.0, -10.0]);
    assert_eq!(&x0[6..9], &[0.0, 0.0, -10.0]);
}
