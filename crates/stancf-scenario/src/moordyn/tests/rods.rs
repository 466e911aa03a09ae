//! The ROD TYPES and RODS sections column for column
//! (docs/moordyn-bodies-rods.md §1.2-§1.3) and the line ends at rod ends
//! (§1.5): what is read, and what is refused naming its line.

use super::*;

const ROD_TYPES: &str = "--- ROD TYPES ---\nTypeName Diam Mass/m Cd Ca CdEnd CaEnd\n\
                         (name) (m) (kg/m) (-) (-) (-) (-)\n\
                         Can 0.5 100 1.2 1.0 0.6 0.5\n";

/// BASE with a body, the rod types ROD_TYPES and a RODS section whose
/// one row is `row`, before its POINTS.
fn with_rod(row: &str) -> String {
    let rods = format!(
        "--- BODIES ---\nID Attachment X0 Y0 Z0 r0 p0 y0 Mass CG I Volume CdA Ca\n\
         (#) (word) (m) (m) (m) (deg) (deg) (deg) (kg) (m) (kg-m^2) (m^3) (m^2) (-)\n\
         1 Free 0 0 -3 0 0 0 500 0 100 0 0 0\n{ROD_TYPES}\
         --- RODS ---\nID RodType Attachment Xa Ya Za Xb Yb Zb NumSegs RodOutputs\n\
         (#) (name) (word) (m) (m) (m) (m) (m) (m) (-) (-)\n{row}\n--- POINTS ---"
    );
    with("--- POINTS ---", &rods)
}

/// The one rod of a deck with the RODS row `row`.
fn rod(row: &str) -> DeckRod {
    let deck = parse(&with_rod(row)).unwrap_or_else(|e| panic!("{row}: {e}"));
    assert_eq!(deck.rods.len(), 1);
    deck.rods[0].clone()
}

#[test]
fn a_rod_type_and_a_rod_are_read_column_for_column() {
    let deck = parse(&with_rod("1 Can Free 1 2 -10 3 2 -10 4 pv")).unwrap();
    let t = &deck.rod_types[0];
    assert_eq!(t.name, "Can");
    assert_eq!(
        [
            t.diameter,
            t.mass_per_length,
            t.cd,
            t.ca,
            t.cd_end,
            t.ca_end
        ],
        [0.5, 100.0, 1.2, 1.0, 0.6, 0.5]
    );
    let r = &deck.rods[0];
    assert_eq!((r.id, r.attachment), (1, RodAttachment::Free));
    assert_eq!(deck.rod_type_of(r).name, "Can");
    assert_eq!(r.end_a, [1.0, 2.0, -10.0]);
    assert_eq!(r.end_b, [3.0, 2.0, -10.0]);
    assert_eq!(r.segments, 4);
    assert_eq!(r.outputs, "pv");
    assert!(r.wants_rod_file());
    // `f` alone creates no file in MoorDyn (§1.3).
    assert!(!rod("1 Can Free 1 2 -10 3 2 -10 4 f").wants_rod_file());
    assert!(!rod("1 Can Free 1 2 -10 3 2 -10 4 -").wants_rod_file());
}

#[test]
fn each_attachment_word_is_read_as_moordyn_reads_it() {
    for (word, kind) in [
        ("Fixed", RodAttachment::Fixed),
        ("fix", RodAttachment::Fixed),
        ("ANCHOR", RodAttachment::Fixed),
        ("Free", RodAttachment::Free),
        ("point", RodAttachment::Free),
        ("Con", RodAttachment::Free),
        ("Body1", RodAttachment::Body(1)),
        ("body1", RodAttachment::Body(1)),
        ("Pinned", RodAttachment::Pinned),
        ("Pinned1", RodAttachment::Pinned),
        ("pin", RodAttachment::Pinned),
        ("Body1Pinned", RodAttachment::BodyPinned(1)),
        ("body1pin", RodAttachment::BodyPinned(1)),
        ("CoupledPinned", RodAttachment::CoupledPinned),
        ("VesPin", RodAttachment::CoupledPinned),
        ("cpldpin", RodAttachment::CoupledPinned),
        ("VesselPinned", RodAttachment::CoupledPinned),
        ("Coupled", RodAttachment::Coupled),
        ("Vessel", RodAttachment::Coupled),
        ("cpld", RodAttachment::Coupled),
    ] {
        assert_eq!(
            rod(&format!("1 Can {word} 0 0 -5 1 0 -5 2 -")).attachment,
            kind,
            "{word}"
        );
    }
    // NumSegs 0: a rod of zero length.
    assert_eq!(rod("1 Can Free 0 0 -5 0 0 -5 0 -").segments, 0);
}

#[test]
fn unknown_rod_attachments_are_refused_by_name_with_their_line() {
    for (word, words) in [
        ("Turbine1", "unknown attachment"),
        ("Body", "names the body's number"),
        ("Body1Foo", "written Body<n>"),
        (
            "Body2Pinned",
            "on body 2, which BODIES does not define (1 bodies)",
        ),
        (
            "Body2",
            "on body 2, which BODIES does not define (1 bodies)",
        ),
    ] {
        let text = with_rod(&format!("1 Can {word} 0 0 -5 1 0 -5 2 -"));
        let e = error(&text);
        assert_eq!(e.line, Some(line_of(&text, "1 Can ")), "{word}: {e}");
        assert!(e.message.contains(words), "{word}: {e}");
    }
}

#[test]
fn malformed_rod_rows_and_types_are_refused_naming_the_line() {
    for (row, words) in [
        ("1 Can Free 0 0 -5 1 0 -5 2", "RODS rows have 11 columns"),
        ("2 Can Free 0 0 -5 1 0 -5 2 -", "expected 1, found 2"),
        (
            "1 Cann Free 0 0 -5 1 0 -5 2 -",
            "rod type \"Cann\", which ROD TYPES does not define; known: Can",
        ),
        ("1 Can Free 0 0 x 1 0 -5 2 -", "Za of rod 1 is \"x\""),
        (
            "1 Can Free 0 0 -5 1 0 -5 -1 -",
            "NumSegs of rod 1 is \"-1\"",
        ),
    ] {
        let text = with_rod(row);
        let e = error(&text);
        assert_eq!(e.line, Some(line_of(&text, row)), "{row}: {e}");
        assert!(e.message.contains(words), "{row}: {e}");
    }
    for (type_row, words) in [
        ("Can 0.5 100 1.2 1.0 0.6", "ROD TYPES rows have 7 columns"),
        ("Can 0 100 1.2 1.0 0.6 0.5", "Diam of rod type \"Can\" is 0"),
        ("Can 0.5 100 -1 1.0 0.6 0.5", "Cd of rod type \"Can\" is -1"),
    ] {
        let text = with_rod("1 Can Free 0 0 -5 1 0 -5 2 -")
            .replace("Can 0.5 100 1.2 1.0 0.6 0.5", type_row);
        let e = error(&text);
        assert_eq!(e.line, Some(line_of(&text, type_row)), "{type_row}: {e}");
        assert!(e.message.contains(words), "{type_row}: {e}");
    }
    // A second type of the same name.
    let text = with_rod("1 Can Free 0 0 -5 1 0 -5 2 -").replace(
        "Can 0.5 100 1.2 1.0 0.6 0.5",
        "Can 0.5 100 1.2 1.0 0.6 0.5\nCan 0.4 90 1 1 0 0",
    );
    let e = error(&text);
    assert_eq!(e.line, Some(line_of(&text, "Can 0.4")));
    assert!(e.message.contains("defined twice"), "{e}");
    // Types are looked up when both sections are read: RODS may come first.
    let text = with_rod("1 Can Free 0 0 -5 1 0 -5 2 -");
    let types_last = text
        .replacen(ROD_TYPES, "", 1)
        .replace("--- OPTIONS ---", &format!("{ROD_TYPES}--- OPTIONS ---"));
    assert_eq!(parse(&types_last).unwrap().rods[0].type_index, 0);
}

#[test]
fn line_ends_at_rod_ends_are_read_in_any_case_and_checked() {
    let rod_row = "1 Can Free 0 0 -5 1 0 -5 2 -";
    for (a, b, want) in [
        (
            "R1A",
            "2",
            [LineAttachment::Rod(1, RodEnd::A), LineAttachment::Point(2)],
        ),
        (
            "1",
            "rod1b",
            [LineAttachment::Point(1), LineAttachment::Rod(1, RodEnd::B)],
        ),
        (
            "Rod1A",
            "r1B",
            [
                LineAttachment::Rod(1, RodEnd::A),
                LineAttachment::Rod(1, RodEnd::B),
            ],
        ),
    ] {
        let text = with_rod(rod_row).replace("1 chain 1 2 110", &format!("1 chain {a} {b} 110"));
        let deck = parse(&text).unwrap_or_else(|e| panic!("{a} {b}: {e}"));
        assert_eq!([deck.lines[0].end_a, deck.lines[0].end_b], want, "{a} {b}");
    }
    for (a, words) in [
        ("R1", "naming end A or B"),
        ("R1C", "naming end A or B"),
        ("R0A", "names the rod's number"),
        ("RA", "expected a point ID such as 4 or P4, or a rod end"),
        (
            "R2A",
            "attached to rod 2, which RODS does not define (1 rods)",
        ),
    ] {
        let text = with_rod(rod_row).replace("1 chain 1 2 110", &format!("1 chain {a} 2 110"));
        let e = error(&text);
        assert_eq!(e.line, Some(line_of(&text, "1 chain ")), "{a}: {e}");
        assert!(e.message.contains(words), "{a}: {e}");
    }
    // Both ends at the same rod end.
    let text = with_rod(rod_row).replace("1 chain 1 2 110", "1 chain R1A r1a 110");
    assert!(error(&text)
        .message
        .contains("both ends of line 1 are attached to end A of rod 1"));
}

#[test]
fn empty_rod_sections_are_fine() {
    let deck = parse(&with(
        "--- POINTS ---",
        "--- ROD TYPES ---\n--- RODS ---\nID RodType\n(#) (-)\n--- POINTS ---",
    ))
    .unwrap();
    assert!(deck.rods.is_empty() && deck.rod_types.is_empty());
}

/// `R<n><q>` and `Rod<n><q>` (any case) as `MoorDyn2.cpp` reads them,
/// the rod as a whole (`Rod::GetRodOutput` with no node).
#[test]
fn rod_channels_parse_as_moordyn_reads_them() {
    let outputs = "Rod1PX R1PZ rod1ry R1RVX Rod1VZ R1AY R1RAX Rod1TenA R1TB rod1sub R1FZ \
                   Rod1MY";
    let text = with_rod("1 Can Free 0 0 -5 1 0 -5 2 -").replace("FairTen1", outputs);
    let deck = parse(&text).unwrap();
    use Axis::*;
    use RodQuantity as Q;
    let got: Vec<Channel> = deck.outputs.iter().map(|o| o.channel).collect();
    let want = [
        Q::Position(X),
        Q::Position(Z),
        Q::Rotation(Y),
        Q::AngularVelocity(X),
        Q::Velocity(Z),
        Q::Acceleration(Y),
        Q::AngularAcceleration(X),
        Q::EndTension(LineEnd::A),
        Q::EndTension(LineEnd::B),
        Q::Submerged,
        Q::Force(Z),
        Q::Moment(Y),
    ]
    .map(|quantity| Channel::Rod { rod: 1, quantity });
    assert_eq!(got, want);
}

/// A node the rod does not have, a rod RODS does not define: refused
/// naming the line (MoorDyn refuses them); what MoorDyn has no value for
/// is kept with why, its column empty (MoorDyn warns and skips it).
#[test]
fn rod_channels_of_missing_rods_or_nodes_are_refused_and_unknown_ones_kept_with_why() {
    for (name, refused, words) in [
        (
            "Rod1RZ",
            false,
            "MoorDyn has no \"RZ\" of a rod (no rotation about its axis",
        ),
        ("R1RVZ", false, "no \"RVZ\" of a rod"),
        ("R1RAZ", false, "no \"RAZ\" of a rod"),
        ("Rod1N3PX", true, "the rod has nodes 0 to 2 (2 segments)"),
        ("R1NCPX", false, "after N comes a node number, A or B"),
        ("Rod1T", false, "MoorDyn writes 0 for \"T\" of a rod"),
        ("Rod1Ten", false, "MoorDyn writes 0 for \"TEN\" of a rod"),
        ("Rod1QQ", false, "MoorDyn outputs no \"QQ\" of a rod"),
        ("Rod1", false, "no quantity"),
        ("Rod2PX", true, "there is no rod 2 (1 rods)"),
        ("R0PX", true, "there is no rod 0 (1 rods)"),
    ] {
        let text = with_rod("1 Can Free 0 0 -5 1 0 -5 2 -")
            .replace("FairTen1", &format!("FairTen1\n{name}"));
        let verdict = super::channel_verdict(&text, name);
        assert_eq!(verdict.is_err(), refused, "{name}: {verdict:?}");
        let message = verdict.unwrap_or_else(|e| e);
        assert!(message.contains(words), "{name}: {message}");
    }
}

/// A rod's node channels: `N<k>`, `NA` (node 0) and `NB` (the last, its
/// NumSegs), their positions and velocities; any other quantity of a node
/// is read as one stancf does not compute.
#[test]
fn rod_node_channels_name_their_node_and_quantity() {
    let text = with_rod("1 Can Free 0 0 -5 1 0 -5 2 -")
        .replace("FairTen1", "FairTen1\nRod1N1PX\nR1NAVZ\nR1NBPY\nR1NBFX");
    let deck = crate::moordyn::parse(&text).expect("the deck");
    let rods: Vec<_> = deck
        .outputs
        .iter()
        .filter_map(|o| match o.channel {
            Channel::Rod { quantity, .. } => Some(quantity),
            _ => None,
        })
        .collect();
    assert_eq!(
        rods,
        [
            RodQuantity::NodePosition(1, Axis::X),
            RodQuantity::NodeVelocity(0, Axis::Z),
            RodQuantity::NodePosition(2, Axis::Y),
            RodQuantity::NodeOther(2),
        ]
    );
}
