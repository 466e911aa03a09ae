//! What rods do not build, refused naming the deck's line or the TOML
//! key (docs/interface.md, "Rods").

use crate::common::*;

/// `deck` with the one output channel `name`, refused with `words` at
/// its line (a case of the test below).
fn rod_channel(deck: &str, name: &'static str, words: &str) -> (String, &'static str, String) {
    let with = deck.replace(
        "water depth (m)\n",
        &format!("water depth (m)\n--- OUTPUTS ---\nFairTen1\n{name}\n"),
    );
    (with, name, words.to_string())
}

/// What is not built is refused naming the deck's line: a line with
/// bending stiffness at a coupled rod, a rod in
/// water that reaches the surface, a zero-length free rod without lines,
/// a rod output channel of a node the rod does not have (one MoorDyn
/// has none for, RZ, is noted: `rod_channels.rs`), a rod type's value
/// out of the
/// solver's range.
#[test]
fn what_rods_do_not_build_is_refused_naming_the_deck_line() {
    let d = scratch("rod-refusals");
    let base = body_rod_deck("-", "0");
    let line_of =
        |text: &str, needle: &str| text.lines().position(|l| l.contains(needle)).unwrap() + 1;
    let cases: Vec<(String, &str, String)> =
        vec![
        (
            body_rod_deck("-", "1e3").replace("1    can       Body1", "1    can       Coupled"),
            "1     rope       1        R1A",
            "AttachB of line 1 is end A of rod 1, and its line type has bending stiffness EI = \
             1000 N m^2, so MoorDyn clamps it to the rod's axis: a clamp that turns with a rod \
             the host moves (a coupled rod, or a rod fixed in a coupled body) is not built yet"
                .into(),
        ),
        (
            base.replace(
                "2     rope       2        R2A       18        6",
                "2     rope       2        R1B       40        6",
            )
            .replace(
                "3     rope       r2b      Rod1B     20        6       -\n",
                "",
            ),
            "2    conn      Free",
            "rod 2 is free with NumSegs 0".into(),
        ),
        rod_channel(&base, "R1N9PX", "the rod has nodes 0 to 4 (4 segments)"),
        (
            base.replace("can           0.5      100 ", "can           0.5      1e160 "),
            "can           0.5      1e160",
            "Mass/m: the value given = 1e160 is beyond 1e150".into(),
        ),
    ];
    for (k, (deck, at, words)) in cases.iter().enumerate() {
        let file = write_scenario(&d, &format!("bad{k}.txt"), deck);
        let n = line_of(deck, at);
        let errs =
            refused_by_check_and_run(&file, &d.join(format!("never{k}")), &[words.as_str()], &[]);
        assert!(
            errs[0].contains(&format!("bad{k}.txt: line {n}: ")),
            "{k}: {}",
            errs[0]
        );
    }
}

/// A TOML rod's keys are checked as the reader checks every key: unknown
/// keys, a rod type not defined, a body rod's body, a point at a rod end
/// given a position, an end or a mass, a rod above the water, segments
/// below 1, a rod of zero length, one too thin to have a body's inertia
/// (the core's refusal named by the rod), a value out of range.
#[test]
fn toml_rod_keys_are_checked_naming_the_key() {
    let base = rising_rod("type = \"dynamic\"\ntime_step = 0.01\nduration = 1.0");
    for (name, scenario, needles) in [
        (
            "rod-unknown-key",
            base.replace("segments = 4\n", "segments = 4\nlength = 2.0\n"),
            vec!["unknown field `length`"],
        ),
        (
            "rod-type-unknown-key",
            base.replace("ca = 1.0\n[[rods]]", "ca = 1.0\ncdax = 1.0\n[[rods]]"),
            vec!["unknown field `cdax`"],
        ),
        (
            "rod-type-undefined",
            base.replace("rod_type = \"can\"", "rod_type = \"cann\""),
            vec![
                "rods[0].rod_type",
                "rod type \"cann\" is not defined (known: can)",
            ],
        ),
        (
            "rod-body-undefined",
            base.replace(
                "type = \"free\"\nrod_type",
                "type = \"body\"\nbody = 3\nrod_type",
            ),
            vec![
                "rods[0].body",
                "body 3 is not defined (there are no [[bodies]])",
            ],
        ),
        (
            "rod-point-position",
            base.replace("end = \"A\"\n", "end = \"A\"\nposition = [0.0, 0.0, 0.0]\n"),
            vec!["points[0].position", "leave the position out"],
        ),
        (
            "rod-point-end",
            base.replace("end = \"A\"\n", "end = \"C\"\n"),
            vec!["points[0].end", "unknown value \"C\""],
        ),
        (
            "rod-point-mass",
            base.replace("end = \"A\"\n", "end = \"A\"\nmass = 1.0\n"),
            vec!["points[0].mass", "a point at a rod's end carries no mass"],
        ),
        (
            "rod-no-segments",
            base.replace("segments = 4", "segments = 0"),
            vec!["rods[0].segments", "must be between 1 and 10000, got 0"],
        ),
        (
            "rod-too-thin",
            base.replace("diameter = 0.5", "diameter = 1e-200"),
            vec!["rods[0]: moments of inertia"],
        ),
        (
            "rod-too-heavy",
            base.replace("mass_per_length = 100.0", "mass_per_length = 1e160"),
            vec!["rod_types[0].mass_per_length", "beyond 1e150"],
        ),
        (
            "rod-zero-length",
            base.replace("end_b = [1.0, 0.0, -10.0]", "end_b = [-1.0, 0.0, -10.0]"),
            vec!["rods[0]", "a rod of zero length has no axis"],
        ),
    ] {
        expect_input_error(name, &scenario, &needles);
    }
}
