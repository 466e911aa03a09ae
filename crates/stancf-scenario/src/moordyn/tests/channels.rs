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
        ("Rod1PX", "there is no rod 1 (0 rods)"),
        ("Body1PX", "there is no body 1 (0 bodies)"),
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
