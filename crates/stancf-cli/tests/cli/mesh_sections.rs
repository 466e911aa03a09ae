//! Meshes in sections (docs/interface.md, `grading = { sections = [...] }`
//! and `[[mesh]]`; docs/method.md §1.6, (M38a)): a line divided into
//! consecutive sections of equal elements runs with those nodes, a
//! MoorDyn deck's lines take their mesh from the scenario, and bad
//! sections or meshes are refused naming the key.

use crate::common::*;
use stancf::{Grading, MeshSection};

/// A rope 10 m long hanging between points 8 m apart, with `line_keys`
/// (its mesh) and `analysis` as the `[analysis]` body; `elements` is
/// written only if given.
fn hanging(elements: Option<usize>, line_keys: &str, analysis: &str) -> String {
    let rope = one_rope(
        "rope in sections",
        "",
        ("fixed", [8.0, 0.0, 0.0]),
        (7, 10.0, elements.unwrap_or(0)),
        line_keys,
    );
    let rope = match elements {
        Some(_) => rope,
        None => rope.replace("elements = 0\n", ""),
    };
    format!("{rope}[analysis]\n{analysis}\n")
}

/// 3 m in 6 elements, then 7 m in 4.
const SECTIONS: &str =
    "grading = { sections = [{ length = 3.0, elements = 6 }, { length = 7.0, elements = 4 }] }";

fn sections() -> Grading {
    Grading::Sections(vec![
        MeshSection {
            length: 3.0,
            elements: 6,
        },
        MeshSection {
            length: 7.0,
            elements: 4,
        },
    ])
}

/// A line in sections, its element count left to the sections, runs in
/// statics with exit 0: stress.csv's elements start at the sections'
/// nodes (0.5 m apart over the first 3 m, 1.75 m after), summary.json
/// records the sections and their sum, and `check` names the shortest
/// and longest elements.
#[test]
fn a_line_in_sections_runs_with_its_sections_nodes() {
    let d = scratch("sections-system");
    let sc = write_scenario(
        &d,
        "static.toml",
        &hanging(None, SECTIONS, "type = \"static\""),
    );
    let out = d.join("static");
    let o = run_to(&sc, &out);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o).1);
    let x = sections().node_coordinates(10.0, 10);
    assert_eq!(x[6], 3.0);
    let (_, rows) = read_csv(&out.join("lines/7/stress.csv"));
    assert_eq!(element_starts(&rows, rows[0][0]), x[..10].to_vec());
    let summary = read_json(&out.join("summary.json"));
    let line = &summary["lines"][0];
    assert_eq!(line["elements"], 10);
    assert_eq!(line["grading"]["sections"][0]["length"].as_f64(), Some(3.0));
    assert_eq!(line["grading"]["sections"][1]["elements"], 4);
    let (so, se) = text(&stancf(&["check", sc.to_str().unwrap()]));
    assert!(
        so.contains("0.5 m to 1.75 m long, in 2 sections"),
        "{so}\n{se}"
    );
}

/// The elements of `[cable]` may be left to its sections too; given, they
/// must be their sum.
#[test]
fn a_cable_in_sections_takes_its_element_count_from_them() {
    let d = scratch("sections-cable");
    let scenario = IMPACT.replace(
        "elements = 8\n",
        "grading = { sections = [{ length = 1.0, elements = 4 }, { length = 3.0, elements = 4 }] }\n",
    );
    assert_ne!(scenario, IMPACT, "the impact's [cable] has 8 elements");
    let sc = write_scenario(&d, "impact.toml", &scenario);
    let out = d.join("out");
    let o = run_to(&sc, &out);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o).1);
    let summary = read_json(&out.join("summary.json"));
    assert_eq!(summary["elements"], 8, "{summary}");
    let bad = scenario.replace("grading = ", "elements = 9\ngrading = ");
    expect_input_error(
        "sections-cable-count",
        &bad,
        &["cable.elements", "is 9", "8 elements"],
    );
}

/// A section too short for double precision is refused naming it (the
/// section of the shortest elements), not only the cable's length and
/// element count. A section of 1e-18 m at end A has elements of 1e-18 m,
/// and the coordinates' rounding (1.3e-15 m at up to 6 m from 0) is 1332
/// of them; at end B its element is rounded away to 0 m, below the
/// 1e-150 m the solver may divide by.
#[test]
fn a_section_too_short_for_double_precision_is_refused_naming_it() {
    let tiny = "{ length = 1e-18, elements = 1 }";
    let rest = "{ length = 4.0, elements = 7 }";
    for (sections, key, needle) in [
        (
            format!("{tiny}, {rest}"),
            "sections[0].length",
            "of the shortest element's length",
        ),
        (
            format!("{rest}, {tiny}"),
            "sections[1].length",
            "= 0 m is below 1e-150",
        ),
    ] {
        let scenario = IMPACT.replace(
            "elements = 8\n",
            &format!("grading = {{ sections = [{sections}] }}\n"),
        );
        assert_ne!(scenario, IMPACT, "the impact's [cable] has 8 elements");
        expect_input_error(
            &format!("sections-tiny-{key}"),
            &scenario,
            &[&format!("cable.grading.{key}"), needle],
        );
    }
}

/// The chain deck as shipped: `examples/oc4-deepcwind-moordyn.txt`
/// (three lines of 835.35 m in 20 segments, BA = -1, a damping ratio).
fn oc4_deck_as_shipped() -> String {
    std::fs::read_to_string(repo_file("examples/oc4-deepcwind-moordyn.txt")).unwrap()
}

/// The chain deck every deck test reads: [`oc4_deck_as_shipped`] with BA
/// in N s (1.224e7, what the damping ratio 1 gives at 20 segments), so
/// that its lines may take meshes that are not uniform.
fn oc4_deck() -> String {
    let shipped = oc4_deck_as_shipped();
    let deck = shipped.replace("7.536E8   -1.0 ", "7.536E8   1.224E7 ");
    assert_ne!(deck, shipped, "the chain's BA column moved");
    deck
}

/// A static scenario of the OC4 deck with `meshes` ([[mesh]] entries).
fn oc4_scenario(meshes: &str) -> String {
    format!(
        "title = \"meshed deck\"\n[system]\nmoordyn = \"deck.txt\"\n{meshes}\n\
         [analysis]\ntype = \"static\"\n"
    )
}

/// `[[mesh]]` gives deck line 1 sections refined where it touches down
/// (100 m in 1 element, 280 m in 4, the rest in 2), line 2 a uniform 6
/// elements and line 3 a grading of the deck's 20 segments: the statics
/// run and summary.json records each line's mesh.
#[test]
fn a_deck_line_takes_its_mesh_from_the_scenario() {
    let meshes = r#"
[[mesh]]
lines = [1]
grading = { sections = [{ length = 100.0, elements = 1 }, { length = 280.0, elements = 4 }, { length = 455.35, elements = 2 }] }
[[mesh]]
lines = [2]
elements = 6
[[mesh]]
lines = [3]
grading = { toward = "A", ratio = 2.0 }
"#;
    let d = scratch("sections-deck");
    let summary = read_json(&oc4_statics(&d, "meshed", meshes).join("summary.json"));
    let lines = &summary["lines"];
    assert_eq!(lines[0]["elements"], 7);
    assert_eq!(
        lines[0]["grading"]["sections"][2]["length"].as_f64(),
        Some(455.35)
    );
    assert_eq!(lines[1]["elements"], 6);
    assert!(lines[1]["grading"].is_null(), "{}", lines[1]);
    assert_eq!(lines[2]["elements"], 20);
    assert_eq!(lines[2]["grading"]["toward"], "A");
}

/// The statics of the OC4 deck with `meshes`, written to `dir/name`.
fn oc4_statics(dir: &std::path::Path, name: &str, meshes: &str) -> std::path::PathBuf {
    std::fs::write(dir.join("deck.txt"), oc4_deck()).unwrap();
    let sc = write_scenario(dir, &format!("{name}.toml"), &oc4_scenario(meshes));
    let out = dir.join(name);
    let o = run_to(&sc, &out);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o).1);
    out
}

/// The tension at fairlead 1 (point 4) of a statics run.
fn fairlead_tension(out: &std::path::Path) -> f64 {
    let (header, rows) = read_csv(&out.join("points.csv"));
    let col = |name: &str| header.iter().position(|h| h == name).unwrap();
    let r = rows.iter().find(|r| r[col("point")] == 4.0).unwrap();
    (r[col("fx")].powi(2) + r[col("fy")].powi(2) + r[col("fz")].powi(2)).sqrt()
}

/// Elements where the line touches down buy what elements everywhere
/// buy: the OC4 chain's static fairlead tension in 7 elements, 4 of them
/// over the 280 m where it touches down, is as close to the converged
/// tension (160 uniform elements; 80 differ from it by 3e-5) as the
/// deck's 20 uniform segments are. Measured: 2.3e-4 and 2.1e-4 off; 10
/// uniform elements are 1.8e-3 off. Bound: 5e-4, and the 10 uniform
/// elements must miss it (the claim is about the sections, not any mesh).
#[test]
fn elements_at_the_touchdown_buy_the_accuracy_of_a_finer_uniform_mesh() {
    let d = scratch("sections-touchdown");
    let uniform = |n: usize| format!("[[mesh]]\nlines = [1, 2, 3]\nelements = {n}\n");
    let converged = fairlead_tension(&oc4_statics(&d, "fine", &uniform(160)));
    let sections = "[[mesh]]\nlines = [1, 2, 3]\ngrading = { sections = [\
        { length = 100.0, elements = 1 }, { length = 280.0, elements = 4 }, \
        { length = 455.35, elements = 2 }] }\n";
    let error = |name: &str, meshes: &str| {
        (fairlead_tension(&oc4_statics(&d, name, meshes)) / converged - 1.0).abs()
    };
    let (sectioned, deck, coarse) = (
        error("sections", sections),
        error("deck", ""),
        error("coarse", &uniform(10)),
    );
    eprintln!("fairlead tension off by {sectioned:.2e} (7 in sections), {deck:.2e} (20 uniform), {coarse:.2e} (10 uniform)");
    assert!(sectioned < 5e-4 && deck < 5e-4, "{sectioned:e}, {deck:e}");
    assert!(coarse > 5e-4, "{coarse:e}");
}

/// A deck's channels of a remeshed line's ends follow the ends: with line
/// 1 in 8 elements instead of 20 segments, `L1NBPZ` (node 20 of the deck)
/// is the fairlead's z (-14 m, where the deck puts it) and `L1N0PZ` the
/// anchor's (-200 m), and the shipped deck's damping ratio takes the
/// uniform 8 elements.
#[test]
fn a_remeshed_deck_lines_end_channels_follow_its_ends() {
    let d = scratch("sections-deck-channels");
    let deck = oc4_deck_as_shipped().replace("AnchTen3\n", "AnchTen3\nL1NBPZ\nL1N0PZ\n");
    std::fs::write(d.join("deck.txt"), deck).unwrap();
    let sc = write_scenario(
        &d,
        "s.toml",
        &oc4_scenario("[[mesh]]\nlines = [1]\nelements = 8"),
    );
    let out = d.join("out");
    let o = run_to(&sc, &out);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o).1);
    let (header, rows) = read_csv(&out.join("channels.csv"));
    let col = |name: &str| header.iter().position(|h| h == name).unwrap();
    let last = rows.last().unwrap();
    assert_eq!(last[col("L1NBPZ")], -14.0);
    assert_eq!(last[col("L1N0PZ")], -200.0);
}

/// A line type's damping ratio (ba < 0) is defined on elements of one
/// length: a `[[lines]]` entry graded or in sections with such a type is
/// refused naming its grading.
#[test]
fn a_damping_ratio_on_a_mesh_that_is_not_uniform_is_refused() {
    let rope = hanging(None, SECTIONS, "type = \"static\"");
    let with_ratio = rope.replacen("[[line_types]]\n", "[[line_types]]\nba = -0.5\n", 1);
    assert_ne!(with_ratio, rope);
    expect_input_error(
        "sections-damping-ratio",
        &with_ratio,
        &["lines[0].grading", "damping ratio"],
    );
}

/// Sections that do not add up to the line, element counts that are not
/// their sum, a grading both geometric and in sections, a section
/// without its elements: exit 2 naming the key, nothing written.
#[test]
fn bad_sections_are_refused_naming_the_key() {
    let s = |a: &str, b: &str| format!("grading = {{ sections = [{a}, {b}] }}");
    let cases = [
        (
            None,
            s(
                "{ length = 3.0, elements = 6 }",
                "{ length = 6.0, elements = 4 }",
            ),
            vec!["lines[0].grading.sections", "add up to 9", "10 long"],
        ),
        (
            Some(12),
            SECTIONS.to_string(),
            vec!["lines[0].elements", "is 12", "10 elements"],
        ),
        (
            None,
            SECTIONS.replace("{ sections", "{ toward = \"A\", sections"),
            vec!["lines[0].grading.toward", "not both"],
        ),
        (
            None,
            s("{ length = 3.0, elements = 6 }", "{ length = 7.0 }"),
            vec!["lines[0].grading.sections[1].elements", "missing"],
        ),
        (
            None,
            s(
                "{ length = 0.0, elements = 6 }",
                "{ length = 10.0, elements = 4 }",
            ),
            vec!["lines[0].grading.sections[0].length"],
        ),
        (
            None,
            s(
                "{ length = 3.0, elements = 0 }",
                "{ length = 7.0, elements = 4 }",
            ),
            vec!["lines[0].grading.sections[0].elements", "between 1 and"],
        ),
        (None, String::new(), vec!["lines[0].elements", "missing"]),
    ];
    for (i, (elements, keys, needles)) in cases.iter().enumerate() {
        let scenario = hanging(*elements, keys, "type = \"static\"");
        expect_input_error(&format!("sections-bad-{i}"), &scenario, needles);
    }
}

/// `[[mesh]]` naming a line the deck does not have, a line twice, no
/// line, or neither elements nor grading; sections that do not add up to
/// the deck line's length; and `[[mesh]]` in a system without a deck:
/// exit 2 naming the key, nothing written.
#[test]
fn bad_deck_meshes_are_refused_naming_the_key() {
    let deck = oc4_deck();
    let cases = [
        (
            "[[mesh]]\nlines = [4]\nelements = 8",
            vec!["mesh[0].lines", "no line 4", "1, 2, 3"],
        ),
        (
            "[[mesh]]\nlines = [1, 2]\nelements = 8\n[[mesh]]\nlines = [2]\nelements = 9",
            vec!["mesh[1].lines", "line 2 is meshed twice"],
        ),
        (
            "[[mesh]]\nlines = []\nelements = 8",
            vec!["mesh[0].lines", "names no line"],
        ),
        ("[[mesh]]\nelements = 8", vec!["mesh[0].lines", "missing"]),
        (
            "[[mesh]]\nlines = [1]",
            vec!["mesh[0]", "neither elements nor grading"],
        ),
        (
            "[[mesh]]\nlines = [3]\ngrading = { sections = [{ length = 800.0, elements = 8 }] }",
            vec!["mesh[0].grading.sections", "add up to 800", "835.35 long"],
        ),
        (
            "[[mesh]]\nlines = [3]\nelements = 0",
            vec!["mesh[0].elements", "between 1 and"],
        ),
    ];
    for (i, (meshes, needles)) in cases.iter().enumerate() {
        expect_input_error_beside(
            &format!("sections-deck-bad-{i}"),
            &oc4_scenario(meshes),
            &[("deck.txt", &deck)],
            needles,
        );
    }
    let sections =
        "[[mesh]]\nlines = [2]\ngrading = { sections = [{ length = 400.0, elements = 4 }, \
                    { length = 435.35, elements = 4 }] }";
    expect_input_error_beside(
        "sections-deck-damping-ratio",
        &oc4_scenario(sections),
        &[("deck.txt", &oc4_deck_as_shipped())],
        &["mesh[0].grading", "damping ratio", "BA = -1"],
    );
    let channels = oc4_deck().replace("AnchTen3\n", "AnchTen3\nL1N7PZ\n");
    expect_input_error_beside(
        "sections-deck-interior-channel",
        &oc4_scenario("[[mesh]]\nlines = [1]\nelements = 8"),
        &[("deck.txt", &channels)],
        &["mesh[0].lines", "L1N7PZ", "node 7"],
    );
    let system = format!(
        "{}[[mesh]]\nlines = [7]\nelements = 4\n",
        hanging(Some(10), "", "type = \"static\"")
    );
    expect_input_error(
        "sections-mesh-without-deck",
        &system,
        &["mesh", "MoorDyn deck"],
    );
}
