//! Line ends clamped in a direction from the command line
//! (docs/interface.md, "Systems": `[[lines]] clamp_a`, `clamp_b`): a
//! clamped end leaves its point along the clamp, and every misplaced or
//! malformed clamp is refused with exit 2 naming its key.

use crate::common::*;

/// A 4 m rope with some bending stiffness between fixed points at the
/// origin and at [3, 0, -1], end A clamped by `clamp` (a TOML line, or
/// empty); `point2` is the type of point 2 and `analysis` the
/// `[analysis]` body.
fn riser(clamp: &str, point2: &str, analysis: &str) -> String {
    format!(
        "{}[analysis]\n{analysis}\n",
        one_rope(
            "riser",
            "ei = 0.05",
            (point2, [3.0, 0.0, -1.0]),
            (1, 4.0, 16),
            clamp
        )
    )
}

/// The static equilibrium of a rope clamped at A along (1, 0, -1): the
/// tangent of node 0 in nodes.csv is along the clamp to round-off,
/// while the same rope pinned there leaves at another angle, and `stancf
/// check` shows the clamp.
#[test]
fn a_clamped_end_leaves_its_point_along_the_clamp() {
    let d = scratch("clamp-runs");
    let sc = write_scenario(
        &d,
        "riser.toml",
        &riser("clamp_a = [1.0, 0.0, -1.0]", "fixed", "type = \"static\""),
    );
    let o = stancf(&["check", sc.to_str().unwrap()]);
    let (so, se) = text(&o);
    assert_eq!(o.status.code(), Some(0), "{se}");
    assert!(
        so.contains("ends point 1 (clamped along [0.707107, 0, -0.707107])"),
        "{so}"
    );
    let tangent = |scenario: &str, name: &str| {
        let sc = write_scenario(&d, name, scenario);
        let out = d.join(format!("out-{name}"));
        let o = run_quiet(&sc, &out, &[]);
        assert_eq!(o.status.code(), Some(0), "{}", text(&o).1);
        let (header, rows) = read_csv(&out.join("lines/1/nodes.csv"));
        assert_eq!(header.join(","), "t,node,x,y,z,dx_ds,dy_ds,dz_ds");
        let last_t = rows.last().unwrap()[0];
        let r = rows.iter().find(|r| r[0] == last_t && r[1] == 0.0).unwrap();
        [r[5], r[6], r[7]]
    };
    let t = tangent(
        &riser("clamp_a = [1.0, 0.0, -1.0]", "fixed", "type = \"static\""),
        "c.toml",
    );
    assert!(
        (t[0] + t[2]).abs() <= 1e-12 * t[0].abs() && t[1].abs() <= 1e-14,
        "{t:?}"
    );
    let pinned = tangent(&riser("", "fixed", "type = \"static\""), "p.toml");
    assert!((pinned[0] + pinned[2]).abs() > 1e-2, "{pinned:?}");
}

/// A dynamic run from the equilibrium with a clamped end at a coupled
/// point runs (exit 0) with either step, the clamp held at every written
/// step.
#[test]
fn a_clamped_end_at_a_moving_point_runs() {
    let d = scratch("clamp-dynamic");
    for scheme in ["p2", "galerkin"] {
        let analysis = format!(
            "type = \"dynamic\"\ninitial = \"static\"\ntime_step = 1e-4\nduration = 2e-3\n\
             time_scheme = \"{scheme}\""
        );
        let clamp_and_motion = "clamp_b = [1.0, 0.0, 1.0]\n[[motions]]\npoint = 2\n\
                                amplitude = [0.0, 0.1, 0.0]\nperiod = 0.5";
        let scenario = riser(clamp_and_motion, "coupled", &analysis);
        let sc = write_scenario(&d, &format!("moving-{scheme}.toml"), &scenario);
        let out = d.join(format!("out-{scheme}"));
        let o = run_quiet(&sc, &out, &[]);
        assert_eq!(o.status.code(), Some(0), "{}\n{scenario}", text(&o).1);
        let (_, rows) = read_csv(&out.join("lines/1/nodes.csv"));
        let ends: Vec<&Vec<f64>> = rows.iter().filter(|r| r[1] == 16.0).collect();
        assert!(ends.len() >= 2);
        for r in ends {
            assert!(
                (r[5] - r[7]).abs() <= 1e-12 * r[5].abs() && r[6].abs() <= 1e-13,
                "{scheme}: {r:?}"
            );
        }
    }
}

#[test]
fn a_zero_or_malformed_clamp_is_refused_naming_its_key() {
    let st = "type = \"static\"";
    expect_input_error(
        "clamp-zero",
        &riser("clamp_a = [0.0, 0.0, 0.0]", "fixed", st),
        &["lines[0].clamp_a", "zero vector"],
    );
    expect_input_error(
        "clamp-two",
        &riser("clamp_b = [1.0, 0.0]", "fixed", st),
        &["lines[0].clamp_b", "3 components"],
    );
}

#[test]
fn a_clamp_at_a_free_point_or_a_loose_end_is_refused_naming_its_key() {
    let st = "type = \"static\"";
    let free = riser("clamp_b = [1.0, 0.0, 0.0]", "free", st).replace(
        "position = [3.0, 0.0, -1.0]",
        "position = [3.0, 0.0, -1.0]\nmass = 1.0",
    );
    expect_input_error("clamp-free", &free, &["lines[0].clamp_b", "free point 2"]);
    let loose = riser("clamp_b = [1.0, 0.0, 0.0]", "fixed", st).replace("b = 2\n", "");
    let loose = loose.replace(
        "[[points]]\nid = 2\ntype = \"fixed\"\nposition = [3.0, 0.0, -1.0]\n",
        "",
    );
    expect_input_error(
        "clamp-loose",
        &loose,
        &["lines[0].clamp_b", "end B is loose"],
    );
}

#[test]
fn a_clamp_with_elimination_is_refused_naming_its_key() {
    expect_input_error(
        "clamp-elimination",
        &riser(
            "clamp_a = [1.0, 0.0, -1.0]",
            "fixed",
            "type = \"static\"\nconstraint_method = \"elimination\"",
        ),
        &["lines[0].clamp_a", "multiplier"],
    );
}

/// A deck whose lines have bending stiffness (EI 1e3 N m^2) at the ends
/// of a rod fixed in a free body (clamped along the rod's axis, turning
/// with the body, docs/method.md §15.19) and at a free rod of zero length
/// (a connector, §15.20): `check` names the connector, the static solve
/// converges, and a dynamic run from that equilibrium stays there, every
/// body (the free body and the connector) still to 1e-7 m and 1e-7 rad
/// over 0.5 s (the static tolerance 1e-10 of the 36 m lines' length is
/// 4e-9 m; nothing else moves them). The lines' moment on the free body,
/// its clamps' included, is zero at the balance and over the steps, to
/// 1e-9 of their force times the rod's half length (the tolerance's).
#[test]
fn lines_with_bending_stiffness_at_a_bodys_rod_and_a_connector_balance_and_stay() {
    let d = scratch("bent-rod-lines");
    let deck = write_scenario(&d, "bent.txt", &body_rod_deck("-", "1e3"));
    let o = stancf(&["check", deck.to_str().unwrap()]);
    let (so, se) = text(&o);
    assert_eq!(o.status.code(), Some(0), "{se}");
    assert!(
        so.contains("body 2                      connector of rod 2"),
        "{so}"
    );
    assert!(so.contains("less 1 per connector's spin (1)"), "{so}");
    let out = d.join("out");
    let o = run_quiet(&deck, &out, &[]);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o).1);
    let (header, rows) = read_csv(&out.join("bodies.csv"));
    let col = |name: &str| header.iter().position(|h| h == name).unwrap();
    let at_rest: Vec<&Vec<f64>> = rows.iter().collect();
    // The body the lines are clamped to has its mooring stiffness (the
    // clamps' moments in it, docs/method.md §15.9); the connector none.
    let s = read_json(&out.join("summary.json"));
    let stiffness = &s["bodies"][0]["stiffness"];
    assert_eq!(stiffness.as_array().map(Vec::len), Some(6), "{s}");
    assert_eq!(s["bodies"][1]["stiffness"], serde_json::Value::Null);
    let note = s["bodies"][1]["stiffness_note"].as_str().unwrap();
    assert!(note.contains("a connector"), "{note}");
    let csv = std::fs::read_to_string(out.join("stiffness.csv")).unwrap();
    let ids: Vec<&str> = csv
        .lines()
        .skip(1)
        .map(|l| &l[..l.find(',').unwrap()])
        .collect();
    assert_eq!(ids, ["1"; 6], "the body's six rows, none for the connector");
    let dynamic = write_scenario(
        &d,
        "dynamic.toml",
        "[system]\nmoordyn = \"bent.txt\"\n[analysis]\ntype = \"dynamic\"\n\
         time_step = 0.01\nduration = 0.5\n",
    );
    let o = run_quiet(&dynamic, &d.join("dyn"), &[]);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o).1);
    let (_, moving) = read_csv(&d.join("dyn").join("bodies.csv"));
    let (mut worst, mut moment) = (0.0f64, 0.0f64);
    for m in &moving {
        let rest = at_rest
            .iter()
            .find(|r| r[col("body")] == m[col("body")])
            .expect("the body at rest");
        for c in ["x", "y", "z", "roll", "pitch", "yaw"] {
            worst = worst.max((m[col(c)] - rest[col(c)]).abs());
        }
        // The lines' moment on the body (the clamps' with the points'),
        // against the lines' force times the rod's half length: zero at
        // the balance (the body's own loads act at its reference point),
        // and each step's mean the balance's.
        if m[col("body")] != 1.0 {
            continue;
        }
        let scale = 2.0
            * (0..3)
                .map(|k| rest[col(["fx", "fy", "fz"][k])].powi(2))
                .sum::<f64>()
                .sqrt();
        for c in ["mx", "my", "mz"] {
            assert!(
                rest[col(c)].abs() < 1e-9 * scale,
                "{c} {} of {scale}",
                rest[col(c)]
            );
            moment = moment.max((m[col(c)] - rest[col(c)]).abs() / scale);
        }
    }
    eprintln!(
        "largest move from the equilibrium over 0.5 s: {worst:.1e}; largest change of the \
         lines' moment {moment:.1e} of the equilibrium's"
    );
    assert!(worst < 1e-7, "{worst:e}");
    assert!(moment < 1e-9, "{moment:e}");
}

/// A TOML cantilever holding a body: a 2 m line (EI 10 N m^2, 10
/// elements) clamped along x at a fixed point and at a free body's point
/// (`clamp_b` at a point on a body: the clamp turns with the body,
/// docs/method.md §15.19), the body loaded by P = 2.5e-3 N down and a
/// moment M = P 0.5 m about y, no gravity. In linear theory the end
/// deflects by P L^3/3EI + M L^2/2EI and turns by P L^2/2EI + M L/EI;
/// at alpha = P L^2/EI = 1e-3 both hold to 1e-5 (the elastica's alpha^2,
/// the stretch P/EA 2.5e-10), and bodies.csv's lines' moment on the body
/// (its clamp's) balances M to the static tolerance.
#[test]
fn a_toml_cantilever_holding_a_body_bends_and_turns_it() {
    let (length, ei) = (2.0f64, 10.0f64);
    let load = 1e-3 * ei / (length * length);
    let moment = 0.5 * load;
    let text = format!(
        "title = \"cantilever holding a body\"\n[system]\ngravity = [0.0, 0.0, 0.0]\n\
         [[line_types]]\nname = \"beam\"\ndiameter = 0.01\nmass_per_length = 0.1\nea = 1.0e7\n\
         ei = {ei:?}\n{}{}\
         [[bodies]]\nid = 1\ntype = \"free\"\nposition = [{length:?}, 0.0, 0.0]\nmass = 1.0\n\
         inertia = [0.1, 0.1, 0.1]\nforce = [0.0, 0.0, {:?}]\nmoment = [0.0, {moment:?}, 0.0]\n\
         [[lines]]\nid = 1\ntype = \"beam\"\nlength = {length:?}\nelements = 10\na = 1\nb = 2\n\
         clamp_a = [1.0, 0.0, 0.0]\nclamp_b = [1.0, 0.0, 0.0]\n\
         [analysis]\ntype = \"static\"\ntolerance = 1e-12\n",
        toml_point(1, "fixed", [0.0; 3]),
        "[[points]]\nid = 2\ntype = \"body\"\nbody = 1\nposition = [0.0, 0.0, 0.0]\n",
        -load,
    );
    let d = scratch("toml-body-cantilever");
    let file = write_scenario(&d, "cantilever.toml", &text);
    let out = d.join("out");
    let o = run_quiet(&file, &out, &[]);
    assert_eq!(o.status.code(), Some(0), "{}", text_of(&o));
    let (header, rows) = read_csv(&out.join("bodies.csv"));
    let col = |name: &str| header.iter().position(|h| h == name).unwrap();
    let r = rows.last().unwrap();
    let delta = load * length.powi(3) / (3.0 * ei) + moment * length.powi(2) / (2.0 * ei);
    let turn = load * length.powi(2) / (2.0 * ei) + moment * length / ei;
    let (z, pitch) = (-r[col("z")], r[col("pitch")].to_radians());
    eprintln!(
        "deflection {z:.9e} (linear {delta:.9e}), turn {pitch:.9e} (linear {turn:.9e}), my {}",
        r[col("my")]
    );
    assert!((z - delta).abs() < 1e-5 * delta, "{z:e}");
    assert!((pitch - turn).abs() < 1e-5 * turn, "{pitch:e}");
    // The lines' moment (the clamp's; the point is at the reference
    // point) balances the body's own load's moment.
    assert!(
        (r[col("my")] + moment).abs() < 1e-6 * moment,
        "{}",
        r[col("my")]
    );
}

/// MoorDyn's local_euler complex_system (its test deck, a fixture): a
/// small free body (29.5 kg, 0.014 m^3) tethered to the bed by 7 m of
/// nylon, between two connectors on stiffeners of 3.12 m (EA 3.6e8 N,
/// EI 3.8e4 N m^2) that the deck places 3.5 m apart, one on 147 m of
/// cable to an anchor, the other on a riser with a buoyant section over
/// two more connectors to a coupled point. The catenary network has to
/// take the stiffeners' 4.3e7 N of stretch away before the path (M32)
/// starts (docs/method.md §11.6); it did not within 60 iterations, and
/// the path from the deck's positions stalled at load factor 0.32. At
/// the equilibrium the lines carry the body's wet weight,
/// (m - rho V) g with MoorDyn's g, and nothing else on it or on the
/// massless connectors: to 1e-8 of the largest tension (6e4 N; the static
/// tolerance is 1e-10 of the rows).
#[test]
fn moordyns_complex_system_balances_its_body_and_connectors_from_stretched_stiffeners() {
    let d = scratch("complex-system");
    let deck = copy_fixture(&d, "complex-system-moordyn.txt", "complex_system.txt");
    let out = d.join("out");
    let o = run_quiet(&deck, &out, &[]);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o).1);
    let (header, rows) = read_csv(&out.join("bodies.csv"));
    let col = |name: &str| header.iter().position(|h| h == name).unwrap();
    let tensions = read_tensions(&out.join("tensions.csv"));
    let largest = tensions.iter().fold(0.0f64, |m, r| m.max(r[6]));
    assert!(largest > 5e4, "{largest}");
    let wet_weight = (29.5 - 1025.0 * 0.014) * 9.80665;
    assert_eq!(rows.len(), 5, "the body and four connectors");
    for r in &rows {
        let lift = if r[col("body")] == 1.0 {
            wet_weight
        } else {
            0.0
        };
        for (c, want) in [("fx", 0.0), ("fy", 0.0), ("fz", lift)] {
            assert!(
                (r[col(c)] - want).abs() < 1e-8 * largest,
                "body {}: {c} {} against {want}",
                r[col("body")],
                r[col(c)]
            );
        }
    }
}
