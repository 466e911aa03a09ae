//! The energy watchdog and the step warnings through the binary: a cable
//! at rest runs to the end (issue 11, item 2), and a Galerkin step beyond
//! the w_max dt at which its results are shown to be meaningful is warned
//! about by `check` and `run`, and named again when the run fails (item
//! 12).

use crate::common::{read_json, run_quiet, scratch, stancf, text, write_scenario};

/// A 1 m PVC cable of two SAC-2 elements at rest, with `extra` TOML
/// (constraints, loads, [analysis] keys); 10 000 steps of 5e-5 s
/// (w_max dt = 1.5, within P2's limit of 3.16).
fn at_rest(extra_top: &str, extra_analysis: &str, element: &str, direction: &str) -> String {
    format!(
        r#"title = "at rest"
[cable]
length = 1.0
elements = 2
element = "{element}"
direction = {direction}
[material]
youngs_modulus = 3.4e9
density = 1380.0
area = 3.0e-6
second_moment = 1.25e-13
{extra_top}
[analysis]
type = "dynamic"
time_step = 5.0e-5
duration = 0.5
{extra_analysis}
[output]
every = 1000
"#
    )
}

/// The cases of the issue (each stopped at step 3 with "energy grows
/// without a source"): free, pinned, clamped, 3-D, Galerkin, zero gravity,
/// a zero end moment. Each runs its 10 000 steps and exits 0, with the
/// cable where it started.
#[test]
fn a_cable_at_rest_runs_for_ever() {
    let d = scratch("at-rest");
    let x = "[1.0, 0.0, 0.0]";
    let pinned = "[[constraints]]\ntype = \"pinned\"\nnode = \"A\"";
    let clamped = "[[constraints]]\ntype = \"clamped\"\nnode = \"A\"";
    let cases = [
        ("free", at_rest("", "", "SAC-2", x)),
        ("pinned", at_rest(pinned, "", "SAC-2", x)),
        ("clamped", at_rest(clamped, "", "SAC-2", x)),
        // SAC-3 at this step would be beyond P2's limit (w_max dt 3.2).
        (
            "3-D",
            at_rest("", "", "SAC-2", "[0.6, 0.48, 0.64]"),
        ),
        ("galerkin", at_rest(pinned, "time_scheme = \"galerkin\"", "SAC-2", x)),
        (
            "zero gravity",
            at_rest(
                "[[loads]]\ntype = \"gravity\"\nacceleration = [0.0, 0.0, 0.0]",
                "",
                "SAC-2",
                x,
            ),
        ),
        (
            "zero moment",
            at_rest(
                &format!(
                    "{clamped}\n[[loads]]\ntype = \"end-moment\"\nnode = \"B\"\nmoment = [0.0, 0.0, 0.0]"
                ),
                "",
                "SAC-2",
                x,
            ),
        ),
    ];
    for (k, (name, scenario)) in cases.iter().enumerate() {
        let sc = write_scenario(&d, &format!("rest{k}.toml"), scenario);
        let out = d.join(format!("res{k}"));
        let o = run_quiet(&sc, &out, &[]);
        let (_, se) = text(&o);
        assert_eq!(o.status.code(), Some(0), "{name}: {se}");
        let s = read_json(&out.join("summary.json"));
        assert_eq!(s["steps"], 10_000, "{name}");
        assert_eq!(s["converged"], true, "{name}");
        assert_eq!(s["planar"], *name != "3-D", "{name}");
        // Where it started: end B at (1, 0, 0) m along the direction, to
        // 10^4 steps of round-off (see the library test).
        let dir: Vec<f64> = if *name == "3-D" {
            vec![0.6, 0.48, 0.64]
        } else {
            vec![1.0, 0.0, 0.0]
        };
        for c in 0..3 {
            let tip = s["tip"][c].as_f64().unwrap();
            assert!((tip - dir[c]).abs() < 1e-9, "{name}: tip {}", s["tip"]);
        }
    }
}

/// The paper's transverse impact (examples/impact-transverse.toml) with
/// the Galerkin step, shortened to 0.05 s, at step `dt`.
fn galerkin_impact(dt: &str) -> String {
    let text = std::fs::read_to_string(crate::common::repo_file("examples/impact-transverse.toml"))
        .unwrap();
    let text = text
        .replace(
            "time_step = 5.0e-5",
            &format!("time_step = {dt}\ntime_scheme = \"galerkin\""),
        )
        .replace("duration = 1.8", "duration = 0.05")
        .replace("every = 20", "every = 1");
    assert!(text.contains("galerkin") && text.contains("duration = 0.05"));
    text
}

/// The issue's case: the transverse impact at 100 times P2's stable step,
/// 1.054778e-2 s, w_max dt = 316.2. `check` warns, saying w_max dt, the
/// limit 10 sqrt(10) = 31.62 (stability::GALERKIN_ACCURATE_W_DT) and the
/// step that satisfies it, 31.62 / 2.998049e4 rad/s = 1.0547e-3 s rounded
/// down to 1.054e-3 s; at that step `check` has no warning. `run` prints
/// the warning first and, when the run fails (the energy jumps by 85 % in
/// the first step, exit 3), names it again in the failure message. At
/// 1e-3 s (w_max dt = 29.98) nothing is said.
#[test]
fn a_galerkin_step_beyond_its_meaningful_range_is_warned_and_named_on_failure() {
    let d = scratch("galerkin-range");
    let far = write_scenario(&d, "far.toml", &galerkin_impact("1.054778e-2"));
    let o = stancf(&["check", far.to_str().unwrap()]);
    let (so, se) = text(&o);
    assert_eq!(o.status.code(), Some(0), "{se}");
    let warning = so
        .lines()
        .find(|l| l.starts_with("warning: analysis.time_step"))
        .unwrap_or_else(|| panic!("no warning: {so}"));
    for part in [
        "Galerkin step at w_max dt = 316.2",
        "beyond 31.62",
        "meaningful",
        "use a step of at most 1.0540e-3 s",
    ] {
        assert!(warning.contains(part), "{part:?} not in {warning}");
    }
    assert!(
        so.contains("results shown meaningful up to w_max dt = 31.62"),
        "{so}"
    );

    let suggested = write_scenario(&d, "suggested.toml", &galerkin_impact("1.054e-3"));
    let o = stancf(&["check", suggested.to_str().unwrap()]);
    let (so, _) = text(&o);
    assert!(so.contains("w_max dt = 31.5"), "{so}");
    assert!(so.contains("warnings                    none"), "{so}");
    let within = write_scenario(&d, "within.toml", &galerkin_impact("1.0e-3"));
    let (so, _) = text(&stancf(&["check", within.to_str().unwrap()]));
    assert!(so.contains("warnings                    none"), "{so}");

    let out = d.join("res");
    let o = run_quiet(&far, &out, &[]);
    let (_, se) = text(&o);
    assert_eq!(o.status.code(), Some(3), "{se}");
    let mut lines = se.lines().filter(|l| !l.trim().is_empty());
    let first = lines.next().unwrap();
    assert!(first.starts_with("warning: analysis.time_step"), "{se}");
    assert!(first.contains("w_max dt = 316.2"), "{se}");
    let error = se
        .lines()
        .find(|l| l.starts_with("error:"))
        .expect("an error line");
    assert!(error.contains("energy grows without a source"), "{error}");
    assert!(
        error.contains("the Galerkin step's w_max dt = 316.2 is beyond 31.62")
            && error.contains("use a step of at most 1.0540e-3 s"),
        "{error}"
    );
}

/// A P2 run that blows up above P2's limit is told to reduce the step, not
/// about the Galerkin step's range.
#[test]
fn a_p2_failure_does_not_speak_of_the_galerkin_range() {
    let d = scratch("p2-failure");
    let text_p2 = galerkin_impact("3.0e-4").replace("time_scheme = \"galerkin\"", "");
    let sc = write_scenario(&d, "p2.toml", &text_p2);
    let out = d.join("res");
    let o = run_quiet(&sc, &out, &[]);
    let (_, se) = text(&o);
    assert_eq!(o.status.code(), Some(3), "{se}");
    assert!(
        se.contains("exceeds the stable step estimate of P2"),
        "{se}"
    );
    assert!(se.contains("reduce the time step"), "{se}");
    assert!(!se.contains("Galerkin"), "{se}");
}
