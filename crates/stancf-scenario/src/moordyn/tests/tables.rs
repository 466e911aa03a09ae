//! The tables (LINE TYPES, POINTS, LINES) and the layout of sections:
//! their rows, columns, numbers and names, and what is refused by line.

use super::*;

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
fn point_attachment_synonyms_read_and_others_are_refused_by_name() {
    for (word, kind) in [
        ("Anchor", Attachment::Fixed),
        ("fix", Attachment::Fixed),
        ("Vessel", Attachment::Coupled),
        ("FAIRLEAD", Attachment::Coupled),
        ("Cpld", Attachment::Coupled),
        ("Free", Attachment::Free),
        ("Connect", Attachment::Free),
        ("Turbine2", Attachment::Turbine(2)),
        ("TURBINE12", Attachment::Turbine(12)),
    ] {
        let deck = parse(&with("2 Coupled", &format!("2 {word}"))).unwrap();
        assert_eq!(deck.points[1].attachment, kind, "{word}");
    }
    for (word, words) in [
        ("Turbine0", "turbines are numbered from 1"),
        ("Vessel2", "turbines"),
        ("CpldPin", "pinned"),
        ("Floating", "unknown attachment \"Floating\""),
    ] {
        let e = error(&with("2 Coupled", &format!("2 {word}")));
        assert!(e.message.contains(words), "{word}: {e}");
    }
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
    // A file name is MoorDyn's nonlinear curve, which the scenario reads
    // (docs/method.md §2.2a); a curve for BA is refused.
    let curve = parse(&with("1e8 -0.8", "ea_curve.dat -0.8")).unwrap();
    assert_eq!(
        curve.line_types[0].ea_curve_file.as_deref(),
        Some("ea_curve.dat")
    );
    let e = error(&with("1e8 -0.8", "1e8 ba_curve.dat"));
    assert!(e.message.contains("BA/-zeta of line type \"chain\""), "{e}");
    assert!(e.message.contains("nonlinear curve"), "{e}");
    // The viscoelastic forms are read (docs/method.md §2.11); Syrope's is
    // refused.
    let visco = parse(&with("1e8 -0.8", "1e8|2e8 -0.8|1e3")).unwrap();
    assert_eq!(
        visco.line_types[0].ea_dynamic,
        Some(stancf::element::DynamicStiffness::Constant(2e8))
    );
    assert_eq!(
        (visco.line_types[0].ba, visco.line_types[0].ba_dynamic),
        (-0.8, 1e3)
    );
    let mean = parse(&with("1e8 -0.8", "1e8|2e8|0.4 5e6")).unwrap();
    assert_eq!(
        mean.line_types[0].ea_dynamic,
        Some(stancf::element::DynamicStiffness::MeanLoad {
            alpha: 2e8,
            beta: 0.4
        })
    );
    let e = error(&with("1e8 -0.8", "1e8 5e6|1e3"));
    assert!(
        e.message.contains("more bar-separated values than EA"),
        "{e}"
    );
    // Syrope's form: the settings file, alpha, beta; BA|BA_D beside it.
    let syrope = parse(&with("1e8 -0.8", "SYROPE:owc.dat|0.1|0.2 5e6|1e3")).unwrap();
    let s = syrope.line_types[0].syrope.as_ref().unwrap();
    assert_eq!(
        (s.file.as_str(), s.alpha, s.beta, s.ba, s.ba_dynamic),
        ("owc.dat", 0.1, 0.2, 5e6, 1e3)
    );
    let e = error(&with("1e8 -0.8", "SYROPE:owc.dat|0.1 -0.8"));
    assert!(e.message.contains("3 bar-separated values"), "{e}");
}

#[test]
fn viv_columns_give_the_lift_with_moordyns_defaults_and_zero_turns_it_off() {
    use crate::moordyn::VivColumns;
    assert_eq!(
        parse(&with("0.4 0.5", "0.4 0.5 0")).unwrap().line_types[0].viv,
        None
    );
    assert_eq!(
        parse(&with("0.4 0.5", "0.4 0.5 0.0 0.08 0.18"))
            .unwrap()
            .line_types[0]
            .viv,
        None
    );
    let one = parse(&with("0.4 0.5", "0.4 0.5 0.8")).unwrap();
    assert_eq!(
        one.line_types[0].viv,
        Some(VivColumns {
            cl: 0.8,
            range: 0.08,
            centre: 0.18
        })
    );
    let three = parse(&with("0.4 0.5", "0.4 0.5 0.7 0.05 0.2")).unwrap();
    assert_eq!(
        three.line_types[0].viv,
        Some(VivColumns {
            cl: 0.7,
            range: 0.05,
            centre: 0.2
        })
    );
    let e = error(&with("0.4 0.5", "0.4 0.5 0.7 0.3 0.2"));
    assert!(e.message.contains("dF < cF"), "{e}");
    let e = error(&with("0.4 0.5", "0.4 0.5 -0.7"));
    assert!(e.message.contains("Cl of line type"), "{e}");
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
fn unknown_and_repeated_section_headers_are_refused_naming_the_line() {
    let text = with("--- LINES ---", "--- LINE LSIT ---");
    let e = error(&text);
    assert_eq!(e.line, Some(line_of(&text, "LINE LSIT")));
    assert!(e.message.starts_with("unknown section header"), "{e}");
    let text = format!("{BASE}--- OPTIONS ---\n1 dtM\n");
    let e = error(&text);
    assert_eq!(e.line, Some(text.lines().count() - 1));
    assert!(e.message.contains("a second OPTIONS section"), "{e}");
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
