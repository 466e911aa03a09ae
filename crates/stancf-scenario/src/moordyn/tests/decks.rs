//! Whole decks: the shipped OC4 example, decks in the shape of MoorDyn's and
//! OpenFAST's test inputs, older section names, comments and blank lines.

use super::*;

#[test]
fn the_oc4_example_deck_reads_three_lines_and_six_points() {
    let deck = parse(OC4).unwrap();
    assert!(deck.title.starts_with("OC4 DeepCwind"));
    assert_eq!(deck.line_types.len(), 1);
    let chain = &deck.line_types[0];
    assert_eq!(chain.name, "chain");
    assert_eq!(
        (chain.diameter, chain.mass_per_length, chain.ea, chain.ei),
        (0.0766, 113.35, 753.6e6, 0.0)
    );
    assert_eq!(
        (
            chain.cd_normal,
            chain.ca_normal,
            chain.cd_axial,
            chain.ca_axial
        ),
        (2.0, 0.8, 0.4, 0.25)
    );
    assert_eq!(chain.damping_ratio(), Some(1.0));
    assert_eq!(deck.points.len(), 6);
    assert_eq!(deck.lines.len(), 3);
    for (k, angle) in [180.0_f64, 60.0, -60.0].into_iter().enumerate() {
        let (s, c) = angle.to_radians().sin_cos();
        let anchor = &deck.points[k];
        let fairlead = &deck.points[k + 3];
        assert_eq!(anchor.attachment, Attachment::Fixed);
        assert_eq!(fairlead.attachment, Attachment::Coupled);
        for (p, r, z) in [(anchor, 837.6, -200.0), (fairlead, 40.868, -14.0)] {
            assert!((p.position[0] - r * c).abs() < 1e-3, "{p:?}");
            assert!((p.position[1] - r * s).abs() < 1e-3, "{p:?}");
            assert_eq!(p.position[2], z);
        }
        let line = &deck.lines[k];
        assert_eq!(
            (line.end_a, line.end_b),
            (LineAttachment::Point(k + 1), LineAttachment::Point(k + 4))
        );
        assert_eq!((line.unstretched_length, line.segments), (835.35, 20));
        assert_eq!(deck.line_type_of(line).name, "chain");
        assert!(!line.wants_line_file());
    }
    use SupportedOption as S;
    assert_eq!(deck.option(S::TimeStep), Some(0.001));
    assert_eq!(deck.option(S::Gravity), Some(9.81));
    assert_eq!(deck.option(S::WaterDepth), Some(200.0));
    assert_eq!(deck.option(S::WaterDensity), Some(1025.0));
    assert_eq!(deck.option(S::BottomStiffness), Some(3.0e6));
    assert_eq!(deck.option(S::BottomDamping), Some(3.0e5));
    assert_eq!(deck.option(S::FrictionCoefficient), None);
    let channels: Vec<Channel> = deck.outputs.iter().map(|o| o.channel).collect();
    assert_eq!(
        channels,
        [
            Channel::FairleadTension { line: 1 },
            Channel::FairleadTension { line: 2 },
            Channel::FairleadTension { line: 3 },
            Channel::AnchorTension { line: 1 },
            Channel::AnchorTension { line: 2 },
            Channel::AnchorTension { line: 3 },
        ]
    );
    assert_eq!(deck.outputs[0].line, line_of(OC4, "FairTen1"));
    assert_eq!(deck.outputs[0].name, "FairTen1");
}

#[test]
fn the_oc4_example_is_recognized_as_moordyn_and_a_toml_scenario_is_not() {
    assert!(looks_like_moordyn(OC4));
    assert!(looks_like_moordyn(MOORDYN_TEST_STYLE));
    let toml = "# --- a scenario ---\n[cable]\nlength = 10.0\n# lines and points\n";
    assert!(!looks_like_moordyn(toml));
    let scenario = include_str!("../../../../../examples/pendulum.toml");
    assert!(!looks_like_moordyn(scenario));
}

#[test]
fn a_deck_in_the_shape_of_moordyns_test_inputs_reads() {
    let deck = parse(MOORDYN_TEST_STYLE).unwrap();
    assert_eq!(
        deck.title,
        "Single chain line for a finite difference check"
    );
    assert_eq!(deck.points[1].attachment, Attachment::Coupled);
    assert_eq!(deck.lines[0].segments, 76);
    assert_eq!(deck.option(SupportedOption::FrictionCoefficient), Some(0.5));
    assert!(deck.outputs.is_empty());
    let file_ic = deck.options.iter().find(|o| o.name == "fileIC").unwrap();
    assert_eq!(file_ic.kind, OptionKind::Ignored);
    assert_eq!(
        file_ic.value,
        OptionValue::Text("WD0200_Chain.txt.ic".into())
    );
    assert_eq!(file_ic.line, line_of(MOORDYN_TEST_STYLE, "fileIC"));
}

#[test]
fn older_section_names_read_the_same() {
    let old = BASE
        .replace("--- LINE TYPES ---", "----- Line Dictionary -----")
        .replace("--- POINTS ---", "----- CONNECTION PROPERTIES -----")
        .replace("--- LINES ---", "----- LINE PROPERTIES -----")
        .replace("--- OPTIONS ---", "----- SOLVER OPTIONS -----")
        .replace("--- OUTPUTS ---", "----- OUTPUT -----");
    assert_eq!(parse(&old).unwrap(), parse(BASE).unwrap());
    let node = BASE.replace("--- POINTS ---", "--- node properties ---");
    assert_eq!(parse(&node).unwrap(), parse(BASE).unwrap());
}

#[test]
fn comments_and_blank_lines_are_skipped() {
    let text = with(
        "1 Fixed -100 0 -50 0 0 0 0",
        "\n1 Fixed -100 0 -50 0 0 0 0 # the anchor\n# a note\n",
    )
    .replace("0.001 dtM", "0.001 dtM#the step");
    // MoorDyn drops the whole word holding the #: this row is "dtM"'s
    // value without a name.
    let e = error(&text);
    assert!(e.message.contains("has only \"0.001\""), "{e}");
    let text = text.replace("0.001 dtM#the step", "0.001 dtM # the step");
    let deck = parse(&text).unwrap();
    assert_eq!(deck.points[0].line, line_of(&text, "the anchor"));
}

#[test]
fn a_deck_in_the_shape_of_openfast_moordyn_tests_reads_with_older_channel_names() {
    // As in OpenFAST's r-test `md_5MW_OC4Semi/moordyn.dat`: an `Echo`
    // row in the title, `SOLVER OPTIONS`, `- comment` after the options,
    // `Con<n>` point channels and `END` before the end marker.
    let text = "\
--------------------- MoorDyn Input File ---------------------
One line of a semi
FALSE    Echo      - not read
----------------------- LINE TYPES ---------------------------
Name   Diam    MassDen  EA      BA/-zeta  EI  Cd   Ca   CdAx  CaAx
(-)    (m)     (kg/m)   (N)     (N-s/-)   (-) (-)  (-)  (-)   (-)
main   0.0766  113.35   7.536E8 -1.0      0   2.0  0.8  0.4   0.25
---------------------- POINTS --------------------------------
ID  Attachment  X       Y    Z      M  V  CdA  CA
(-) (-)         (m)     (m)  (m)    (kg) (m^3) (m^2) (-)
1   Fixed       -837.6  0.0  -200.0 0  0  0    0
2   Vessel      -40.868 0.0  -14.0  0  0  0    0
---------------------- LINES ---------------------------------
ID  LineType  AttachA  AttachB  UnstrLen  NumSegs  Outputs
(-) (-)       (-)      (-)      (m)       (-)      (-)
1   main      1        2        835.35    20       pt
---------------------- SOLVER OPTIONS ------------------------
0.001    dtM       - time step (s)
3.0e6    kbot      - bottom stiffness (Pa/m)
3.0e5    cbot      - bottom damping (Pa-s/m)
------------------------ OUTPUTS -----------------------------
FairTen1
L1N10T
Con2Fx
Con2Pz
END
------------------------- need this line ---------------------
";
    let deck = parse(text).unwrap();
    assert_eq!(
        deck.title,
        "One line of a semi\nFALSE    Echo      - not read"
    );
    assert!(deck.lines[0].wants_line_file());
    assert_eq!(deck.option(SupportedOption::BottomStiffness), Some(3.0e6));
    assert_eq!(deck.outputs.len(), 4);
    assert_eq!(
        deck.outputs[2].channel,
        Channel::Point {
            point: 2,
            quantity: PointQuantity::Force(Axis::X)
        }
    );
}

#[test]
fn errors_display_their_line() {
    let e = DeckError::at(7, "bad");
    assert_eq!(e.to_string(), "line 7: bad");
    assert_eq!(DeckError::whole("bad").to_string(), "bad");
    let missing = std::path::Path::new("/nonexistent/deck.txt");
    let e = load(missing).unwrap_err();
    assert!(
        e.message.starts_with("/nonexistent/deck.txt: cannot read"),
        "{e}"
    );
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../../examples/oc4-deepcwind-moordyn.txt");
    assert_eq!(load(&path).unwrap(), parse(OC4).unwrap());
}

/// A dashed line before the first section, with text after it, is part
/// of the title: MoorDyn looks for its sections by name and reads past
/// it (issue 35). The same after a section is an unknown section.
#[test]
fn a_dashed_title_before_the_first_section_is_read_past() {
    let text = BASE.replacen(
        "a test deck\n",
        "a test deck\n------------- the mooring of a test ------------\nsome words about it\n",
        1,
    );
    let deck = parse(&text).unwrap();
    assert!(deck.title.contains("some words about it"), "{}", deck.title);
    let base = parse(BASE).unwrap();
    assert_eq!(deck.lines.len(), base.lines.len());
    assert_eq!(
        deck.lines[0].unstretched_length,
        base.lines[0].unstretched_length
    );
    assert_eq!(deck.lines[0].line, base.lines[0].line + 2);
    let after = BASE.replacen(
        "--- OPTIONS ---",
        "--- a note ---\nsome words\n--- OPTIONS ---",
        1,
    );
    assert!(error(&after).message.contains("unknown section header"));
}

/// A MoorDyn v1 deck's line dictionary (9 columns, no EI) is refused
/// saying so, not only counting its columns (issue 35).
#[test]
fn a_v1_line_dictionary_is_refused_as_a_v1_deck() {
    let row = BASE
        .lines()
        .skip_while(|l| !l.contains("LINE TYPES"))
        .nth(3)
        .unwrap()
        .to_string();
    let words: Vec<&str> = row.split_whitespace().collect();
    assert_eq!(words.len(), 10, "{row}");
    let v1_row = [&words[..5], &words[6..]].concat().join(" ");
    let e = error(&BASE.replacen(&row, &v1_row, 1));
    assert!(e.message.contains("MoorDyn v1"), "{e}");
    assert!(e.message.contains("has 9"), "{e}");
}
