//! MoorDyn-F's `FAILURE` section (its docs, "Failure (MoorDyn-F only)";
//! docs/method.md §11.16): `FailureID Point Line(s) FailTime FailTen`,
//! line ends let go of a point or a rod end at a time or a tension,
//! whichever comes first.
//!
//! - `Point` is a point's number (`<n>`, `P<n>`, `Point<n>`, `C<n>`,
//!   `Con<n>`) or a rod's end (`R<n>A`, `Rod<n>B`), any case;
//! - `Line(s)` is one line number or several joined by commas (`1,2,3`),
//!   each attached there (MoorDyn-F refuses the row otherwise);
//! - `FailTime` (s) and `FailTen` (N): 0 means "not by this"; both 0 is a
//!   failure that never happens (MoorDyn-F warns and ignores it; stancf
//!   notes it).
//!
//! MoorDyn-F numbers the rows 1, 2, 3... and so must the deck.

use super::ends::{decompose, LineAttachment, RodEnd};
use super::layout::Section;
use super::sections::{count, non_negative, sequential};
use super::{DeckError, DeckLine};

/// A row of `FAILURE`.
#[derive(Debug, Clone, PartialEq)]
pub struct DeckFailure {
    /// 1-based line number in the file.
    pub line: usize,
    pub id: usize,
    /// The point or rod end let go of.
    pub node: LineAttachment,
    /// The lines released there, by their numbers (from 1).
    pub lines: Vec<usize>,
    /// `FailTime` (s; 0: none).
    pub time: f64,
    /// `FailTen` (N; 0: none).
    pub tension: f64,
}

const COLUMNS: &str = "FailureID Point Line(s) FailTime FailTen";

/// The rows of `FAILURE`, checked against the deck's `points`
/// (their count), `rods` (their count) and `lines`.
pub(crate) fn failures(
    s: &Section,
    (points, rods): (usize, usize),
    lines: &[DeckLine],
) -> Result<Vec<DeckFailure>, DeckError> {
    let mut out = Vec::with_capacity(s.rows.len());
    for row in &s.rows {
        if row.words.len() != 5 {
            return Err(DeckError::at(
                row.line,
                format!(
                    "FAILURE rows have 5 columns ({COLUMNS}; several lines joined by commas, \
                     without spaces); this one has {}",
                    row.words.len()
                ),
            ));
        }
        let id = count(row, 0, "the failure ID")?;
        sequential(row, id, out.len() + 1, "failure")?;
        let node = node(row.words[1], (points, rods))
            .map_err(|m| DeckError::at(row.line, format!("failure {id}: {m}")))?;
        let mut released = Vec::new();
        for word in row.words[2].split(',') {
            let n = match word.trim().parse::<usize>() {
                Ok(n) if (1..=lines.len()).contains(&n) => n,
                _ => {
                    return Err(DeckError::at(
                        row.line,
                        format!(
                            "failure {id}: line \"{word}\" is not one of the deck's {} lines",
                            lines.len()
                        ),
                    ))
                }
            };
            let line = &lines[n - 1];
            if line.end_a != node && line.end_b != node {
                return Err(DeckError::at(
                    row.line,
                    format!("failure {id}: line {n} is not attached to {}", row.words[1]),
                ));
            }
            if released.contains(&n) {
                return Err(DeckError::at(
                    row.line,
                    format!("failure {id}: line {n} is given twice"),
                ));
            }
            released.push(n);
        }
        let time = non_negative(row, 3, &format!("FailTime of failure {id}"), false)?;
        let tension = non_negative(row, 4, &format!("FailTen of failure {id}"), false)?;
        out.push(DeckFailure {
            line: row.line,
            id,
            node,
            lines: released,
            time,
            tension,
        });
    }
    Ok(out)
}

/// The point or rod end a failure names, checked against the deck's
/// `points` and `rods` counts; the message says what is wrong.
fn node(word: &str, (points, rods): (usize, usize)) -> Result<LineAttachment, String> {
    let (letters, digits, rest) = decompose(word);
    let n = digits
        .parse::<usize>()
        .map_err(|_| format!("\"{word}\" names no point or rod end (no number)"))?;
    match letters.as_str() {
        "R" | "ROD" => {
            let end = match rest.as_str() {
                "A" => RodEnd::A,
                "B" => RodEnd::B,
                _ => return Err(format!("\"{word}\": a rod's end is A or B (R<n>A, R<n>B)")),
            };
            if n == 0 || n > rods {
                return Err(format!("\"{word}\": the deck has {rods} rods"));
            }
            Ok(LineAttachment::Rod(n, end))
        }
        "" | "P" | "POINT" | "C" | "CON" if rest.is_empty() => {
            if n == 0 || n > points {
                return Err(format!("\"{word}\": the deck has {points} points"));
            }
            Ok(LineAttachment::Point(n))
        }
        _ => Err(format!(
            "\"{word}\" is neither a point (<n>, P<n>, Point<n>) nor a rod end (R<n>A, R<n>B)"
        )),
    }
}
