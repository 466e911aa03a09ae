//! The BODIES section column for column (docs/moordyn-bodies-rods.md
//! §1.1), the points on bodies and the body channels: what is read, and
//! what is refused naming its line.

use super::*;

/// BASE with a BODIES section whose one row is `row` before its POINTS.
fn with_body(row: &str) -> String {
    let bodies = format!(
        "--- BODIES ---\nID Attachment X0 Y0 Z0 r0 p0 y0 Mass CG I Volume CdA Ca\n\
         (#) (word) (m) (m) (m) (deg) (deg) (deg) (kg) (m) (kg-m^2) (m^3) (m^2) (-)\n\
         {row}\n--- POINTS ---"
    );
    with("--- POINTS ---", &bodies)
}

/// The one body of a deck with the BODIES row `row`.
fn body(row: &str) -> DeckBody {
    let deck = parse(&with_body(row)).unwrap_or_else(|e| panic!("{row}: {e}"));
    assert_eq!(deck.bodies.len(), 1);
    deck.bodies[0].clone()
}

#[test]
fn a_body_row_is_read_column_for_column() {
    let b = body("1 Free 1 2 -3 10 -20 30 500 0.5|0|-0.3 100|200|250 2 1 0.8");
    assert_eq!(b.id, 1);
    assert_eq!(b.attachment, BodyAttachment::Free);
    assert_eq!(b.position, [1.0, 2.0, -3.0]);
    assert_eq!(b.angles, [10.0, -20.0, 30.0]);
    assert_eq!(b.mass, 500.0);
    assert_eq!(b.centre_of_mass, [0.5, 0.0, -0.3]);
    assert_eq!(b.moments, [100.0, 200.0, 250.0]);
    assert_eq!(b.volume, 2.0);
    assert_eq!(b.drag_areas, [1.0; 3]);
    assert_eq!(b.rotational_drag_areas, [1.0; 3]);
    assert_eq!(b.ca, [0.8; 3]);
}

#[test]
fn one_cg_value_is_z_and_one_moment_is_all_three() {
    let b = body("1 Free 0 0 -3 0 0 0 500 -0.4 120 0 0 0");
    assert_eq!(b.centre_of_mass, [0.0, 0.0, -0.4]);
    assert_eq!(b.moments, [120.0; 3]);
    let b = body("1 Free 0 0 -3 0 0 0 500 1|2|3 1|2|2.5 0 0 0");
    assert_eq!(b.centre_of_mass, [1.0, 2.0, 3.0]);
    assert_eq!(b.moments, [1.0, 2.0, 2.5]);
}

/// CdA with 1, 2, 3 and 6 values as MoorDyn's documentation defines
/// them; with 3 and 6 values the x value is kept (MoorDyn-C 2.7.1 drops
/// it, docs/moordyn-bodies-rods.md §7.1).
#[test]
fn cda_takes_one_two_three_or_six_values_as_moordyn_documents_them() {
    let cda = |w: &str| {
        let b = body(&format!("1 Free 0 0 -3 0 0 0 500 0 100 0 {w} 0"));
        (b.drag_areas, b.rotational_drag_areas)
    };
    assert_eq!(cda("2"), ([2.0; 3], [2.0; 3]));
    assert_eq!(cda("2|0.5"), ([2.0; 3], [0.5; 3]));
    assert_eq!(cda("1|2|3"), ([1.0, 2.0, 3.0], [1.0, 2.0, 3.0]));
    assert_eq!(cda("1|2|3|4|5|6"), ([1.0, 2.0, 3.0], [4.0, 5.0, 6.0]));
}

#[test]
fn ca_takes_one_or_three_values() {
    let ca = |w: &str| body(&format!("1 Free 0 0 -3 0 0 0 500 0 100 1 0 {w}")).ca;
    assert_eq!(ca("0.7"), [0.7; 3]);
    assert_eq!(ca("1|0.5|0.25"), [1.0, 0.5, 0.25]);
}

#[test]
fn fixed_words_hold_a_body_coupled_words_couple_it_pinned_words_pin_it_and_every_other_frees_it() {
    for (word, kind) in [
        ("Fixed", BodyAttachment::Fixed),
        ("anchor", BodyAttachment::Fixed),
        ("FIX2", BodyAttachment::Fixed),
        // MoorDyn's four coupled words (docs/moordyn-bodies-rods.md §1.1),
        // any case, matched on their first run of letters.
        ("Coupled", BodyAttachment::Coupled),
        ("vessel", BodyAttachment::Coupled),
        ("VES", BodyAttachment::Coupled),
        ("Cpld", BodyAttachment::Coupled),
        ("cpld2", BodyAttachment::Coupled),
        ("Free", BodyAttachment::Free),
        ("Body", BodyAttachment::Free),
        ("Turbines", BodyAttachment::Free),
        ("CoupledPinned", BodyAttachment::CoupledPinned),
        ("vesselpinned", BodyAttachment::CoupledPinned),
        ("VesPin", BodyAttachment::CoupledPinned),
        ("CpldPin2", BodyAttachment::CoupledPinned),
    ] {
        let b = body(&format!("1 {word} 0 0 -3 0 0 0 500 0 100 0 0 0"));
        assert_eq!(b.attachment, kind, "{word}");
        assert_eq!(b.attachment_word, word);
    }
}

#[test]
fn malformed_body_columns_are_refused_naming_the_line_and_column() {
    for (row, words) in [
        ("1 Free 0 0 -3 0 0 0 500 0 100 0 0", "14 columns"),
        ("2 Free 0 0 -3 0 0 0 500 0 100 0 0 0", "expected 1, found 2"),
        ("1 Free 0 0 -3 0 0 0 -5 0 100 0 0 0", "Mass of body 1 is -5"),
        (
            "1 Free 0 0 -3 0 0 0 500 1|2 100 0 0 0",
            "CG of body 1 has 2 bar-separated",
        ),
        (
            "1 Free 0 0 -3 0 0 0 500 0 1|2 0 0 0",
            "I of body 1 has 2 bar-separated",
        ),
        ("1 Free 0 0 -3 0 0 0 500 0 -1 0 0 0", "zero or positive"),
        (
            "1 Free 0 0 -3 0 0 0 500 0 100 0 1|2|3|4 0",
            "CdA of body 1 has 4",
        ),
        (
            "1 Free 0 0 -3 0 0 0 500 0 100 0 0 1|2",
            "Ca of body 1 has 2",
        ),
        (
            "1 Free 0 0 -3 0 0 0 500 0 100 0 0 x",
            "Ca of body 1 is \"x\"",
        ),
        ("1 Free 0 0 nan 0 0 0 500 0 100 0 0 0", "Z0 of body 1"),
        (
            "1 Turbine2 0 0 -3 0 0 0 500 0 100 0 0 0",
            "a body on a turbine is not supported",
        ),
    ] {
        let text = with_body(row);
        let e = error(&text);
        assert_eq!(e.line, Some(line_of(&text, row)), "{row}: {e}");
        assert!(e.message.contains(words), "{row}: {e}");
    }
}

#[test]
fn a_point_on_a_body_is_read_in_the_bodys_axes_and_checked() {
    let body_row = "1 Free 0 0 -3 0 0 0 500 0 100 0 0 0";
    let text = with_body(body_row).replace("2 Coupled 0 0 -5", "2 body1 0.5 0 -1");
    let deck = parse(&text).unwrap();
    assert_eq!(deck.points[1].attachment, Attachment::Body(1));
    assert_eq!(deck.points[1].position, [0.5, 0.0, -1.0]);
    for (word, words) in [
        (
            "Body2",
            "on body 2, which BODIES does not define (1 bodies)",
        ),
        ("Body", "names the body's number"),
        ("Body1Pinned", "ignores \"Pinned\""),
    ] {
        let text = with_body(body_row).replace("2 Coupled 0 0 -5", &format!("2 {word} 0 0 -1"));
        let e = error(&text);
        assert_eq!(e.line, Some(line_of(&text, word)), "{word}");
        assert!(e.message.contains(words), "{word}: {e}");
    }
    // A body point without any BODIES section.
    let text = with("2 Coupled 0 0 -5", "2 Body1 0 0 -5");
    let e = error(&text);
    assert_eq!(e.line, Some(line_of(&text, "Body1")));
    assert!(
        e.message
            .contains("which BODIES does not define (0 bodies)"),
        "{e}"
    );
    // Its own drag or added mass are refused; its mass and volume are
    // read (they become the free body's).
    for row in ["2 Body1 0 0 -1 0 0 1.5 0", "2 Body1 0 0 -1 0 0 0 1"] {
        let text = with_body(body_row).replace("2 Coupled 0 0 -5 0 0 0 0", row);
        let e = error(&text);
        assert_eq!(e.line, Some(line_of(&text, row)), "{row}");
        assert!(
            e.message
                .contains("the drag and added mass of a point on a body are not built"),
            "{e}"
        );
    }
    let text = with_body(body_row).replace("2 Coupled 0 0 -5 0 0 0 0", "2 Body1 0 0 -1 5 0.2 0 0");
    let deck = parse(&text).unwrap();
    assert_eq!((deck.points[1].mass, deck.points[1].volume), (5.0, 0.2));
    // On a fixed or coupled body even its mass is refused.
    for holder in ["Fixed", "Coupled"] {
        let row = "2 Body1 0 0 -1 5 0 0 0";
        let held = with_body(&format!("1 {holder} 0 0 -3 0 0 0 0 0 0 0 0 0"))
            .replace("2 Coupled 0 0 -5 0 0 0 0", row);
        let e = error(&held);
        assert_eq!(e.line, Some(line_of(&held, row)), "{holder}");
        assert!(
            e.message.contains(
                "a point on a fixed or coupled body carries no mass, volume or drag of its own"
            ),
            "{holder}: {e}"
        );
    }
}

#[test]
fn body_channels_are_read_and_a_missing_bodys_refused_naming_the_line() {
    let text = with_body("1 Free 0 0 -3 0 0 0 500 0 100 0 0 0").replace(
        "FairTen1",
        "FairTen1\nBody1PX\nB1RY\nbody1RVZ\nBody1FZ\nB1MX\nBody1TEN",
    );
    let deck = parse(&text).unwrap();
    let q: Vec<Channel> = deck.outputs[1..].iter().map(|o| o.channel).collect();
    let b = |quantity| Channel::Body { body: 1, quantity };
    assert_eq!(
        q,
        [
            b(BodyQuantity::Position(Axis::X)),
            b(BodyQuantity::Rotation(Axis::Y)),
            b(BodyQuantity::AngularVelocity(Axis::Z)),
            b(BodyQuantity::Force(Axis::Z)),
            b(BodyQuantity::Moment(Axis::X)),
            b(BodyQuantity::Tension),
        ]
    );
    for (name, refused, words) in [
        ("Body2PX", true, "there is no body 2 (1 bodies)"),
        ("Body1SUB", false, "no \"SUB\" of a body"),
        ("Body1", false, "no quantity"),
    ] {
        let text = with_body("1 Free 0 0 -3 0 0 0 500 0 100 0 0 0")
            .replace("FairTen1", &format!("FairTen1\n{name}"));
        let verdict = super::channel_verdict(&text, name);
        assert_eq!(verdict.is_err(), refused, "{name}: {verdict:?}");
        let message = verdict.unwrap_or_else(|e| e);
        assert!(message.contains(words), "{name}: {message}");
    }
}
