//! OUTPUTS: the channels of lines and points as MoorDyn reads them, and
//! those refused by line.

use super::*;

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

/// A channel of a line, point, rod or body the deck does not define is
/// refused naming its line (MoorDyn refuses it); a name MoorDyn does not
/// know (an object letter or a quantity it has not) is kept, its column
/// left empty, with why (MoorDyn warns and skips it).
#[test]
fn channels_of_missing_objects_are_refused_and_unknown_names_kept_with_why() {
    for (name, refused, words) in [
        ("FairTen2", true, "there is no line 2"),
        ("L1N11T", true, "nodes 0 to 10"),
        ("P3PX", true, "there is no point 3"),
        ("Rod1PX", true, "there is no rod 1 (0 rods)"),
        ("Body1PX", true, "there is no body 1 (0 bodies)"),
        ("x,y", true, "letters and digits"),
        ("Fair_Ten1", true, "letters and digits"),
        ("L1N5AX", false, "no \"AX\" at line nodes"),
        ("P1RX", false, "no \"RX\" at points"),
        ("L1N5", false, "no quantity"),
        ("L1N5QQ", false, "unknown quantity \"QQ\""),
        ("Tension1", false, "unknown channel"),
        ("N4Px", false, "unknown channel"),
        ("FairTen", false, "no object number"),
        ("L1N5TA", false, "take no node"),
    ] {
        let text = with("FairTen1", &format!("FairTen1\n{name}"));
        let verdict = channel_verdict(&text, name);
        assert_eq!(verdict.is_err(), refused, "{name}: {verdict:?}");
        let message = verdict.unwrap_or_else(|e| e);
        assert!(message.contains(words), "{name}: {message}");
    }
    let text = with("FairTen1", "FairTen1\nEND\nAnchTen1");
    let e = error(&text);
    assert!(e.message.contains("follows END"), "{e}");
}
