use super::*;

const OC4: &str = include_str!("../../../../examples/oc4-deepcwind-moordyn.txt");

/// A small deck in the shape of MoorDyn's own test inputs
/// (`tests/Mooring/lines.txt`, `WD0200_Chain.txt`): `POINT PROPERTIES`,
/// `Vessel` points, comment text after the options, `fileIC` and
/// `disableOutTime`, no OUTPUTS, the `need this line` end marker.
const MOORDYN_TEST_STYLE: &str = "\
--------------------- MoorDyn Input File ------------------------------------
Single chain line for a finite difference check
----------------------- LINE TYPES ------------------------------------------
TypeName   Diam    Mass/m     EA         BA/-zeta    EI         Cd     Ca     CdAx    CaAx
(name)     (m)     (kg/m)     (N)        (N-s/-)     (N-m^2)    (-)    (-)    (-)     (-)
chain      0.25    390        1.6e9      -1.0        0          1.4    1.0    0.6     0.0
---------------------- POINT PROPERTIES --------------------------------
ID    Type      X       Y       Z       Mass   Volume  CdA    Ca
(#)   (-)       (m)     (m)     (m)     (kg)   (m\u{2c6}3)   (m^2)  (-)
1     Fixed     700    0.0      -200.0  0      0       0      0
2     Vessel    0.0     0.0     0.0     0      0       0      0
---------------------- LINES ----------------------------------------
ID   LineType   AttachA  AttachB  UnstrLen  NumSegs  LineOutputs
(#)   (name)     (#)      (#)       (m)       (-)     (-)
1     chain      1        2         760       76      -
---------------------- OPTIONS -----------------------------------------
2                    writeLog             Write a log file
0.001                dtM                  time step
1.0e5                kBot                 bottom stiffness (Pa/m)
1.0e4                cBot                 bottom damping (Pa-s/m)
1025.0               WtrDnsty             water density (kg/m^3)
200                  WtrDpth              water depth (m)
1.0                  dtIC                 time interval for analyzing convergence during IC gen (s)
100.0                TmaxIC               max time for ic gen (s)
1.0e-4               threshIC             threshold for IC convergence (-)
WD0200_Chain.txt.ic  fileIC               Load a quasistatic solution before the IC solver (-)
0.5                  FrictionCoefficient  general bottom friction coefficient, as a start (-)
1       disableOutTime
------------------------- need this line --------------------------------------
";

/// A minimal deck; `{types}`, `{points}`, `{lines}`, `{options}` and
/// `{outputs}` are replaced by the tests.
const BASE: &str = "\
--- MoorDyn input ---
a test deck
--- LINE TYPES ---
TypeName Diam Mass/m EA BA/-zeta EI Cd Ca CdAx CaAx
(name) (m) (kg/m) (N) (N-s/-) (N-m^2) (-) (-) (-) (-)
chain 0.1 20 1e8 -0.8 0 1.2 1 0.4 0.5
--- POINTS ---
ID Attachment X Y Z Mass Volume CdA Ca
(#) (-) (m) (m) (m) (kg) (m^3) (m^2) (-)
1 Fixed -100 0 -50 0 0 0 0
2 Coupled 0 0 -5 0 0 0 0
--- LINES ---
ID LineType AttachA AttachB UnstrLen NumSegs Outputs
(#) (name) (#) (#) (m) (-) (-)
1 chain 1 2 110 10 -
--- OPTIONS ---
0.001 dtM
--- OUTPUTS ---
FairTen1
--- END ---
";

fn with(find: &str, replace: &str) -> String {
    assert!(BASE.contains(find), "{find}");
    BASE.replacen(find, replace, 1)
}

fn error(text: &str) -> DeckError {
    parse(text).expect_err("the deck should be refused")
}

/// The 1-based number of the line of `text` that contains `needle`.
fn line_of(text: &str, needle: &str) -> usize {
    text.lines().position(|l| l.contains(needle)).expect(needle) + 1
}

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
        (chain.cd, chain.ca, chain.cd_ax, chain.ca_ax),
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
        assert_eq!((line.end_a, line.end_b), (k + 1, k + 4));
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
    let scenario = include_str!("../../../../examples/pendulum.toml");
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
fn ic_generator_options_are_accepted() {
    let deck = parse(OC4).unwrap();
    for name in ["dtIC", "TmaxIC", "CdScaleIC", "threshIC"] {
        let o = deck.options.iter().find(|o| o.name == name).unwrap();
        assert_eq!(o.kind, OptionKind::Ignored, "{name}");
    }
    let old = "5.0 ICDfac\n0.001 ICthresh\n0 ICTmax\n1 writeLog\n0 WaveKin\n0 Currents\n0.001 dtM";
    let deck = parse(&with("0.001 dtM", old)).unwrap();
    assert_eq!(deck.options.len(), 7);
    assert_eq!(deck.option(SupportedOption::TimeStep), Some(0.001));
}

#[test]
fn an_unknown_option_is_refused_naming_its_line() {
    let text = with("0.001 dtM", "0.001 dtM\n3 WtrDepth water depth");
    let e = error(&text);
    assert_eq!(e.line, Some(line_of(&text, "WtrDepth")));
    assert_eq!(
        e.to_string(),
        format!(
            "line {}: unknown option \"WtrDepth\"",
            line_of(&text, "WtrDepth")
        )
    );
}

#[test]
fn options_that_change_the_physics_are_refused_by_name() {
    for (row, words) in [
        ("1 WaveKin", "wave files are not read"),
        ("0.5 CFL", "Courant"),
        ("RK4 tScheme", "time integrators"),
        ("bathy.txt SeafloorFile", "bathymetry"),
        ("0.3 mu_kT", "FrictionCoefficient"),
    ] {
        let text = with("0.001 dtM", &format!("0.001 dtM\n{row}"));
        let e = error(&text);
        assert_eq!(e.line, Some(line_of(&text, row)), "{row}");
        assert!(e.message.contains(words), "{row}: {e}");
    }
}

#[test]
fn an_option_given_twice_under_two_names_is_refused() {
    let text = with("0.001 dtM", "1025 rho\n0.001 dtM\n1000 WtrDnsty");
    let e = error(&text);
    assert_eq!(e.line, Some(line_of(&text, "WtrDnsty")));
    assert!(e.message.contains("first as rho"), "{e}");
}

#[test]
fn a_supported_option_must_be_a_finite_number() {
    let e = error(&with("0.001 dtM", "fast dtM"));
    assert!(e.message.contains("not a finite number"), "{e}");
    let e = error(&with("0.001 dtM", "-1 dtM"));
    assert!(e.message.contains("must be positive"), "{e}");
}

#[test]
fn a_misspelt_line_type_is_refused_naming_the_line() {
    let text = BASE
        .replace(
            "1 chain 1 2 110 10 -",
            "1 chain 1 2 110 10 -\n2 chain 2 1 110 10 -\n3 chian 1 2 110 10 -",
        )
        .replace("2 chain 2 1", "2 chain 1 2");
    let e = error(&text);
    let n = line_of(&text, "chian");
    assert_eq!(
        e.to_string(),
        format!(
            "line {n}: line 3 uses line type \"chian\", which LINE TYPES does not define; known: chain"
        )
    );
}

#[test]
fn a_rod_is_refused_naming_its_line() {
    let rods = "--- RODS ---\nID RodType Attachment Xa Ya Za Xb Yb Zb NumSegs RodOutputs\n\
                (#) (name) (word) (m) (m) (m) (m) (m) (m) (-) (-)\n\
                1 Can Fixed 0 0 -10 0 0 -5 4 -\n--- POINTS ---";
    let text = with("--- POINTS ---", rods);
    let e = error(&text);
    assert_eq!(e.line, Some(line_of(&text, "1 Can Fixed")));
    assert!(e.message.starts_with("rods are not supported"), "{e}");
    // An empty rod section is fine, with or without its column rows.
    parse(&with(
        "--- POINTS ---",
        "--- ROD TYPES ---\n--- RODS ---\nID RodType\n(#) (-)\n--- POINTS ---",
    ))
    .unwrap();
    // A line attached to a rod end.
    let text = with("1 chain 1 2 110 10 -", "1 chain R1A 2 110 10 -");
    let e = error(&text);
    assert_eq!(e.line, Some(line_of(&text, "R1A")));
    assert!(e.message.contains("rods are not supported"), "{e}");
}

#[test]
fn a_body_is_refused_naming_its_line() {
    let bodies = "--- BODIES ---\nID Attachment X0 Y0 Z0 r0 p0 y0 Mass CG I Volume CdA Ca\n\
                  (#) (word) (m) (m) (m) (deg) (deg) (deg) (kg) (m) (kg-m^2) (m^3) (m^2) (-)\n\
                  1 coupled 0 0 0 0 0 0 0 0 0 0 0 0\n--- POINTS ---";
    let text = with("--- POINTS ---", bodies);
    let e = error(&text);
    assert_eq!(e.line, Some(line_of(&text, "1 coupled")));
    assert!(e.message.starts_with("bodies are not supported"), "{e}");
    let text = with("2 Coupled 0 0 -5", "2 Body1 0 0 -5");
    let e = error(&text);
    assert_eq!(e.line, Some(line_of(&text, "Body1")));
    assert!(e.message.contains("bodies are not supported"), "{e}");
}

#[test]
fn point_attachment_synonyms_read_and_others_are_refused_by_name() {
    for (word, kind) in [
        ("Anchor", Attachment::Fixed),
        ("fix", Attachment::Fixed),
        ("Vessel", Attachment::Coupled),
        ("FAIRLEAD", Attachment::Coupled),
        ("Cpld", Attachment::Coupled),
        ("Free", Attachment::Free),
        ("Connect", Attachment::Free),
    ] {
        let deck = parse(&with("2 Coupled", &format!("2 {word}"))).unwrap();
        assert_eq!(deck.points[1].attachment, kind, "{word}");
    }
    for (word, words) in [
        ("Turbine2", "turbines"),
        ("Vessel2", "turbines"),
        ("CpldPin", "pinned"),
        ("Floating", "unknown attachment \"Floating\""),
    ] {
        let e = error(&with("2 Coupled", &format!("2 {word}")));
        assert!(e.message.contains(words), "{word}: {e}");
    }
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
fn a_negative_ba_is_kept_as_a_damping_ratio() {
    let deck = parse(BASE).unwrap();
    assert_eq!(deck.line_types[0].ba, -0.8);
    assert_eq!(deck.line_types[0].damping_ratio(), Some(0.8));
    let deck = parse(&with("-0.8", "2.5e5")).unwrap();
    assert_eq!(deck.line_types[0].ba, 2.5e5);
    assert_eq!(deck.line_types[0].damping_ratio(), None);
}

#[test]
fn a_non_constant_ea_is_refused_naming_the_form() {
    for (ea, words) in [
        ("ea_curve.dat", "nonlinear curve"),
        ("1e8|2e8", "viscoelastic"),
        ("SYROPE:owc.dat|0.1|0.2", "Syrope"),
    ] {
        let text = with("1e8 -0.8", &format!("{ea} -0.8"));
        let e = error(&text);
        assert_eq!(e.line, Some(line_of(&text, ea)), "{ea}");
        assert!(e.message.starts_with("EA of line type \"chain\""), "{e}");
        assert!(e.message.contains(words), "{ea}: {e}");
    }
}

#[test]
fn viv_columns_are_accepted_only_with_a_zero_lift_coefficient() {
    parse(&with("0.4 0.5", "0.4 0.5 0")).unwrap();
    parse(&with("0.4 0.5", "0.4 0.5 0.0 0.08 0.18")).unwrap();
    let e = error(&with("0.4 0.5", "0.4 0.5 0.8"));
    assert!(e.message.contains("vortex-induced"), "{e}");
    let e = error(&with("0.4 0.5", "0.4 0.5 0 0.08"));
    assert!(e.message.contains("this one has 12"), "{e}");
}

#[test]
fn numbers_must_be_finite_numbers() {
    let e = error(&with("chain 0.1 20", "chain 0.1 2O"));
    assert_eq!(
        e.message,
        "Mass/m of line type \"chain\" is \"2O\", which is not a number"
    );
    let e = error(&with("-100 0 -50", "-100 0 NaN"));
    assert_eq!(
        e.message,
        "Z of point 1 is \"NaN\", which is not a finite number"
    );
    let e = error(&with("-100 0 -50", "-100 0 inf"));
    assert!(e.message.contains("not a finite number"), "{e}");
}

#[test]
fn wrong_column_counts_and_bad_lines_are_refused_naming_the_line() {
    let text = with("1 chain 1 2 110 10 -", "1 chain 1 2 110 10");
    let e = error(&text);
    assert_eq!(e.line, Some(line_of(&text, "1 chain 1 2 110 10")));
    assert!(e.message.contains("LINES rows have 7 columns"), "{e}");
    let e = error(&with(
        "1 Fixed -100 0 -50 0 0 0 0",
        "1 Fixed -100 0 -50 0 0",
    ));
    assert!(e.message.contains("POINTS rows have 9 columns"), "{e}");
    let e = error(&with("110 10 -", "110 0 -"));
    assert!(e.message.contains("NumSegs of line 1"), "{e}");
    let e = error(&with("110 10 -", "0 10 -"));
    assert!(e.message.contains("UnstrLen of line 1 is 0"), "{e}");
    let e = error(&with("1 chain 1 2", "1 chain 1 7"));
    assert!(
        e.message.contains("point 7, which POINTS does not define"),
        "{e}"
    );
    let e = error(&with("1 chain 1 2", "1 chain 2 2"));
    assert!(e.message.contains("both ends of line 1"), "{e}");
}

#[test]
fn duplicate_ids_and_type_names_are_refused() {
    let text = with("2 Coupled", "1 Coupled");
    let e = error(&text);
    assert_eq!(e.line, Some(line_of(&text, "1 Coupled")));
    assert!(e.message.contains("point 1 is defined twice"), "{e}");
    let text = with(
        "chain 0.1 20 1e8 -0.8 0 1.2 1 0.4 0.5",
        "chain 0.1 20 1e8 -0.8 0 1.2 1 0.4 0.5\nchain 0.2 20 1e8 -0.8 0 1.2 1 0.4 0.5",
    );
    let e = error(&text);
    assert!(e.message.contains("defined twice (first at line 6)"), "{e}");
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
fn unknown_and_repeated_section_headers_are_refused_naming_the_line() {
    let text = with("--- LINES ---", "--- LINE LSIT ---");
    let e = error(&text);
    assert_eq!(e.line, Some(line_of(&text, "LINE LSIT")));
    assert!(e.message.starts_with("unknown section header"), "{e}");
    let text = format!("{BASE}--- OPTIONS ---\n1 dtM\n");
    let e = error(&text);
    assert_eq!(e.line, Some(text.lines().count() - 1));
    assert!(e.message.contains("a second OPTIONS section"), "{e}");
    let text = with("1 chain 1 2 110 10 -", "1 chain 1 2 110 10 -\n--- FAILURE ---\nID Point Lines FailTime FailTen\n() () (,) (s) (N)\n1 2 1 10 0");
    let e = error(&text);
    assert!(
        e.message.starts_with("line failures are not supported"),
        "{e}"
    );
}

#[test]
fn a_table_without_its_units_row_is_refused() {
    let text = with("(#) (name) (#) (#) (m) (-) (-)\n", "");
    let e = error(&text);
    assert_eq!(e.line, Some(line_of(&text, "1 chain 1 2")));
    assert!(
        e.message.contains("expected the row of units of LINES"),
        "{e}"
    );
}

#[test]
fn a_deck_without_lines_is_refused() {
    let e = error(&with("1 chain 1 2 110 10 -\n", ""));
    assert_eq!(e.line, None);
    assert!(e.message.contains("no lines"), "{e}");
}

#[test]
fn channels_of_lines_and_points_parse_as_moordyn_reads_them() {
    let outputs = "FairTen1 AnchTen1\nL1N5T\nLine1N10PX\nl1nbfz\nL1NAVY\nL1PZ\nL1TenA\nL1TB\n\
                   Point2FX\nP1PZ\nCon2Ay\npoint2ten\nEND";
    let deck = parse(&with("FairTen1", outputs)).unwrap();
    use Axis::*;
    let got: Vec<Channel> = deck.outputs.iter().map(|o| o.channel).collect();
    let node = |node, quantity| Channel::LineNode {
        line: 1,
        node,
        quantity,
    };
    let point = |point, quantity| Channel::Point { point, quantity };
    assert_eq!(
        got,
        [
            Channel::FairleadTension { line: 1 },
            Channel::AnchorTension { line: 1 },
            node(5, LineQuantity::Tension),
            node(10, LineQuantity::Position(X)),
            node(10, LineQuantity::Force(Z)),
            node(0, LineQuantity::Velocity(Y)),
            node(0, LineQuantity::Position(Z)),
            Channel::LineEndTension {
                line: 1,
                end: LineEnd::A
            },
            Channel::LineEndTension {
                line: 1,
                end: LineEnd::B
            },
            point(2, PointQuantity::Force(X)),
            point(1, PointQuantity::Position(Z)),
            point(2, PointQuantity::Acceleration(Y)),
            point(2, PointQuantity::Tension),
        ]
    );
    assert_eq!(deck.outputs[1].line, deck.outputs[0].line);
}

#[test]
fn unknown_or_impossible_channels_are_refused_naming_the_line() {
    for (name, words) in [
        ("FairTen2", "there is no line 2"),
        ("L1N11T", "nodes 0 to 10"),
        ("P3PX", "there is no point 3"),
        ("L1N5AX", "no \"AX\" at line nodes"),
        ("P1RX", "no \"RX\" at points"),
        ("L1N5", "no quantity"),
        ("L1N5QQ", "unknown quantity \"QQ\""),
        ("Rod1PX", "rods are not supported"),
        ("Body1PX", "bodies are not supported"),
        ("Tension1", "unknown channel"),
        ("FairTen", "no object number"),
        ("L1N5TA", "take no node"),
    ] {
        let text = with("FairTen1", &format!("FairTen1\n{name}"));
        let e = error(&text);
        let n = text.lines().position(|l| l == name).unwrap() + 1;
        assert_eq!(e.line, Some(n), "{name}");
        assert!(
            e.message.starts_with(&format!("output channel \"{name}\"")),
            "{e}"
        );
        assert!(e.message.contains(words), "{name}: {e}");
    }
    let text = with("FairTen1", "FairTen1\nEND\nAnchTen1");
    let e = error(&text);
    assert!(e.message.contains("follows END"), "{e}");
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

/// Found by the random decks of the property tests (issue 28): a chain
/// from an anchor on the seabed to a 2000 kg clump and on to a fairlead,
/// whose static path cannot pass load factor 0.99986. Its increments were
/// cut below the precision of the load factor, where one no longer moves
/// it and so "converged"; that reset the cuts, the next increment doubled,
/// failed and was cut back to it, for ever (`stancf run` never ended).
/// Such an increment is a failure now (statics/newton.rs).
const STALLING_DECK: &str = "\
--- LINE TYPES ---
TypeName Diam Mass/m EA BA/-zeta EI Cd Ca CdAx CaAx
(name) (m) (kg/m) (N) (N-s/-) (N-m^2) (-) (-) (-) (-)
chain 0.1 20.0 1.0e8 0 0 0 0 0 0
--- POINTS ---
ID Attachment X Y Z Mass Volume CdA Ca
(#) (-) (m) (m) (m) (kg) (m^3) (m^2) (-)
1 Fixed -25.0 0.0 -50.0 0 0 0 0
2 Coupled 0.0 0.0 -5.0 0 0 0 0
3 Free -12.5 0.0 -32.5 2000 0 0 0
--- LINES ---
ID LineType AttachA AttachB UnstrLen NumSegs Outputs
(#) (name) (#) (#) (m) (-) (-)
1 chain 1 3 27.958 1 -
2 chain 3 2 39.27 2 -
--- OPTIONS ---
50.0 WtrDpth
";

#[test]
fn a_static_path_that_stalls_fails_once_its_cuts_reach_the_load_factors_precision() {
    let path = Path::new("stalling.txt");
    let sc = match crate::scenario::parse_input(STALLING_DECK, "stalling.txt", path) {
        Ok(crate::scenario::Input::System(sc)) => sc,
        other => panic!("the deck reads as a system: {other:?}"),
    };
    let mut statics = crate::check_system::prepare(path, &sc)
        .expect("the deck's system builds")
        .statics
        .expect("a deck alone is a static analysis");
    // Far more increments than the path takes to stall; before the fix
    // the solve went on past any number of them.
    let mut increments = 0;
    let result = statics.solve(|_, _| {
        increments += 1;
        if increments > 10_000 {
            std::ops::ControlFlow::Break(())
        } else {
            std::ops::ControlFlow::Continue(())
        }
    });
    let e = result.expect_err("the path stalls at load factor 0.99986");
    let m = e.to_string();
    assert!(increments <= 10_000, "{increments} increments: {m}");
    // Ends there: its increments below the load factor's precision fail
    // and are cut until the halvings run out, or the path, creeping,
    // takes the most increments it may.
    assert!(m.contains("load factor 0.9998"), "{m}");
    assert!(m.contains("halvings") || m.contains("stalled"), "{m}");
}
