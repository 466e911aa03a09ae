//! What a line end of a deck is attached to: a point, or an end of a rod
//! (`R<n>A`, `R<n>B`, `Rod<n>A`, `Rod<n>B`, any case;
//! docs/moordyn-bodies-rods.md §1.5), and MoorDyn's `decomposeString`
//! that splits such words.

use super::layout::Row;
use super::DeckError;

/// An end of a rod.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum RodEnd {
    A,
    B,
}

impl RodEnd {
    pub fn letter(self) -> char {
        match self {
            RodEnd::A => 'A',
            RodEnd::B => 'B',
        }
    }
}

/// What a line end is attached to.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum LineAttachment {
    /// A point, by its id (from 1).
    Point(usize),
    /// An end of a rod, by the rod's id (from 1).
    Rod(usize, RodEnd),
}

/// MoorDyn's `decomposeString`, upper-cased: leading letters, the digits
/// after them, and the rest.
pub(crate) fn decompose(word: &str) -> (String, String, String) {
    let upper = word.to_ascii_uppercase();
    let letters = upper
        .find(|c: char| !c.is_ascii_alphabetic())
        .unwrap_or(upper.len());
    let (let1, rest) = upper.split_at(letters);
    let digits = rest
        .find(|c: char| !c.is_ascii_digit())
        .unwrap_or(rest.len());
    let (num1, rest) = rest.split_at(digits);
    (let1.to_string(), num1.to_string(), rest.to_string())
}

/// A line end written `R<n>A`, `R<n>B`, `Rod<n>A` or `Rod<n>B` (any
/// case): None if the word is not a rod end; an error if it names a rod
/// without its end or with another letter.
pub(crate) fn rod_end(
    row: &Row,
    line_id: usize,
    col: usize,
    which: &str,
) -> Result<Option<LineAttachment>, DeckError> {
    let w = row.words[col];
    let (let1, num1, let2) = decompose(w);
    if !matches!(let1.as_str(), "R" | "ROD") {
        return Ok(None);
    }
    let end = match let2.as_str() {
        "A" => RodEnd::A,
        "B" => RodEnd::B,
        _ => {
            return Err(DeckError::at(
                row.line,
                format!(
                    "Attach{which} of line {line_id} is \"{w}\"; a rod end is written R<n>A or \
                     R<n>B (Rod<n>A, Rod<n>B), naming end A or B"
                ),
            ))
        }
    };
    match num1.parse::<usize>() {
        Ok(n) if n >= 1 => Ok(Some(LineAttachment::Rod(n, end))),
        _ => Err(DeckError::at(
            row.line,
            format!(
                "Attach{which} of line {line_id} is \"{w}\"; a rod end names the rod's number, \
                 e.g. R1A"
            ),
        )),
    }
}
