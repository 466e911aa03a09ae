//! Lines without compression (docs/method.md §2.2, (M4a)): a line
//! type's `compression = false` and a MoorDyn deck's lines shed the
//! force of a shortened line, as MoorDyn's segments do; the static solve
//! keeps the compressive stiffness and says where its equilibrium is
//! shortened.

use crate::common::*;

/// A rope of 1 m in 4 elements without gravity (type keys
/// `compression`, "" or "compression = false") from the origin to point
/// 2 (`kind` at x = `x`), with `rest` (motions, analysis) appended.
fn weightless_rope(title: &str, compression: &str, (kind, x): (&str, f64), rest: &str) -> String {
    let mut sc = one_rope(title, compression, (kind, [x, 0.0, 0.0]), (1, 1.0, 4), "");
    sc.push_str("[system]\ngravity = [0.0, 0.0, 0.0]\n");
    sc.push_str(rest);
    sc
}

/// `compression = false` in a line type (docs/method.md §2.2, (M4a)): a
/// rope whose coupled end is pushed towards its fixed one transmits no
/// elastic force to the anchor, where the same rope carrying compression
/// pushes it with EA eps (140 N here). What reaches the anchor of the
/// slack rope is inertia: the pushed end's element (0.02 kg) accelerates
/// at up to 2.5 m/s^2, 0.05 N, and its consistent mass couples a part
/// of that to the next nodes (measured 1.5e-3 N); the claim is below
/// 1e-2 N, 1e-4 of the stiff rope's push.
#[test]
fn a_rope_type_without_compression_pushes_nothing_to_its_anchor() {
    let d = scratch("systems-compression");
    let largest_anchor_force = |compression: &str| -> f64 {
        let sc = weightless_rope(
            "pushed rope",
            compression,
            ("coupled", 1.0),
            "[[motions]]\npoint = 2\namplitude = [-0.01, 0.0, 0.0]\nperiod = 0.4\n\
             [analysis]\ntype = \"dynamic\"\ntime_step = 1.0e-4\nduration = 0.05\n",
        );
        let path = write_scenario(&d, "pushed.toml", &sc);
        let out = d.join(format!("out-{}", compression.len()));
        let o = run_quiet(&path, &out, &[]);
        assert_eq!(o.status.code(), Some(0), "{}", text(&o).1);
        read_tensions(&out.join("tensions.csv"))
            .iter()
            .filter(|row| row[2] == 0.0)
            .map(|row| row[6])
            .fold(0.0, f64::max)
    };
    let slack = largest_anchor_force("compression = false");
    let stiff = largest_anchor_force("");
    eprintln!("anchor force: {slack:e} N without compression, {stiff} N with");
    assert!(slack < 1e-2, "{slack}");
    assert!(stiff > 1.0, "{stiff}");
}

/// A MoorDyn deck's lines carry no compression, as MoorDyn's segments
/// (Line.cpp: T = 0 where l_str <= l; docs/method.md §2.2, (M4a)). A
/// neutrally buoyant rope (0.08 kg/m displacing 0.0805 kg/m) held its
/// length apart 1 m under the surface hangs at a static pull of 0.27 N
/// (its static solve keeps the compressive stiffness: without it a rope
/// at zero tension has none); its fairlead then pushed 1 cm towards the
/// anchor slackens it: the anchor force stays at most 0.31 N (the
/// static pull and the slack rope's inertia), where a rope carrying
/// compression pushes it with up to EA eps = 200 N (measured 56 N before
/// deck lines shed compression). The claim: below 1 N.
#[test]
fn a_moordyn_decks_line_pushed_together_pushes_nothing_to_its_anchor() {
    let d = scratch("systems-deck-compression");
    std::fs::write(d.join("deck.txt"), rope_deck("")).unwrap();
    let path = write_scenario(
        &d,
        "pushed.toml",
        "title = \"pushed rope deck\"\n[system]\nmoordyn = \"deck.txt\"\n\
         [[motions]]\npoint = 2\namplitude = [-0.01, 0.0, 0.0]\nperiod = 0.4\n\
         [analysis]\ntype = \"dynamic\"\ntime_step = 1.0e-4\nduration = 0.05\n",
    );
    let out = d.join("out");
    let checked = stancf(&["check", path.to_str().unwrap()]);
    assert_eq!(checked.status.code(), Some(0), "{}", text(&checked).1);
    assert!(text(&checked)
        .0
        .contains("no compression (docs/method.md §2.2)"));
    let o = run_quiet(&path, &out, &[]);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o).1);
    let anchor: Vec<f64> = read_tensions(&out.join("tensions.csv"))
        .iter()
        .filter(|row| row[2] == 0.0)
        .map(|row| row[6])
        .collect();
    let largest = anchor.iter().copied().fold(0.0, f64::max);
    eprintln!(
        "static pull {} N, largest anchor force {largest} N",
        anchor[0]
    );
    assert!(anchor[0] > 0.1 && anchor[0] < 0.5, "{}", anchor[0]);
    assert!(largest < 1.0, "{largest}");
}

/// A line without compression is solved at rest with its compressive
/// stiffness kept (docs/method.md §2.2, (M4a)); where its equilibrium is
/// shortened the run says so, naming the line and the compression the
/// motion will shed: a weightless rope of 1 m held straight 0.99 m apart
/// is shortened by 0.01, EA eps = 200 N. The same rope carrying
/// compression is not reported.
#[test]
fn a_line_without_compression_shortened_at_rest_is_reported() {
    let d = scratch("systems-static-compression");
    let stderr_of = |compression: &str| -> String {
        let sc = weightless_rope(
            "shortened rope",
            compression,
            ("fixed", 0.99),
            "[analysis]\ntype = \"static\"\n",
        );
        let path = write_scenario(&d, "shortened.toml", &sc);
        let out = d.join(format!("out-{}", compression.len()));
        let o = run_to(&path, &out);
        assert_eq!(o.status.code(), Some(0), "{}", text(&o).1);
        text(&o).1
    };
    let slack = stderr_of("compression = false");
    assert!(
        slack.contains("warning: lines[0] (id 1)")
            && slack.contains("shortens it by up to 0.01")
            && slack.contains("200 N"),
        "{slack}"
    );
    let stiff = stderr_of("");
    assert!(!stiff.contains("shortens"), "{stiff}");
}
