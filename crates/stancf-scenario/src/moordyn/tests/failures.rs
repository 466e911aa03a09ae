//! MoorDyn-F's FAILURE section: its rows read as MoorDyn-F reads them,
//! and what it refuses refused by line.

use super::*;
use crate::moordyn::failures::DeckFailure;

/// BASE with a FAILURE section of `rows` after its lines.
fn with_failures(rows: &str) -> String {
    with(
        "1 chain 1 2 110 10 -",
        &format!(
            "1 chain 1 2 110 10 -\n--- FAILURE ---\nID Point Lines FailTime FailTen\n\
             () () (,) (s) (N)\n{rows}"
        ),
    )
}

#[test]
fn failure_rows_read_their_point_lines_time_and_tension() {
    let text = with_failures("1 2 1 10 0\n2 p1 1 0 3e5");
    let deck = parse(&text).expect("deck");
    assert_eq!(
        deck.failures,
        vec![
            DeckFailure {
                line: line_of(&text, "1 2 1 10 0"),
                id: 1,
                node: LineAttachment::Point(2),
                lines: vec![1],
                time: 10.0,
                tension: 0.0,
            },
            DeckFailure {
                line: line_of(&text, "2 p1 1 0 3e5"),
                id: 2,
                node: LineAttachment::Point(1),
                lines: vec![1],
                time: 0.0,
                tension: 3e5,
            },
        ]
    );
}

#[test]
fn failure_rows_moordyn_f_refuses_are_refused_by_line() {
    for (row, says) in [
        ("1 2 1 10", "5 columns"),
        ("1 2 1, 10 0", "line \"\" is not one of"),
        ("2 2 1 10 0", "failure 1 is missing"),
        ("1 3 1 10 0", "the deck has 2 points"),
        ("1 R1A 1 10 0", "the deck has 0 rods"),
        ("1 Body1 1 10 0", "neither a point"),
        ("1 2 2 10 0", "not one of the deck's 1 lines"),
        ("1 2 1,1 10 0", "given twice"),
        ("1 2 1 -1 0", "FailTime of failure 1"),
    ] {
        let text = with_failures(row);
        let e = error(&text);
        assert_eq!(e.line, Some(line_of(&text, row)), "{row}: {e}");
        assert!(e.message.contains(says), "{row}: {e}");
    }
}
