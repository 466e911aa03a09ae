//! The words of the messages: pieces of the user's input echoed at most
//! [`MAX_ECHO`] characters long, TOML values described in words, and
//! TOML syntax and type errors shown with their line and a caret.

use super::ScenarioError;

pub use crate::echo::{clip, MAX_ECHO};

/// A word of a whitespace table at line `at` as a finite number, or the
/// message naming the line and the word.
pub(super) fn finite_word(word: &str, at: usize) -> Result<f64, String> {
    word.parse::<f64>()
        .ok()
        .filter(|v| v.is_finite())
        .ok_or_else(|| format!("line {at}: \"{}\" is not a finite number", clip(word, 60)))
}

/// A number as MoorDyn's `stof` reads it: a finite float.
pub(super) fn stof_word(word: &str, at: usize) -> Result<f64, String> {
    let v = finite_word(word, at)? as f32;
    if v.is_finite() {
        Ok(f64::from(v))
    } else {
        Err(format!(
            "line {at}: {word} is beyond single precision, in which MoorDyn reads the file"
        ))
    }
}

/// A TOML value in a message: its type and (clipped) value.
pub(super) fn describe_value(v: &toml::Value) -> String {
    match v {
        toml::Value::String(s) => format!("the string \"{}\"", clip(s, 60)),
        toml::Value::Integer(i) => format!("the integer {i}"),
        toml::Value::Float(x) => format!("the number {x}"),
        toml::Value::Boolean(b) => format!("{b}"),
        toml::Value::Datetime(d) => format!("the date {d}"),
        toml::Value::Array(a) => format!(
            "a list of {} item{}",
            a.len(),
            if a.len() == 1 { "" } else { "s" }
        ),
        toml::Value::Table(_) => "a table".into(),
    }
}

/// serde's words for the types of a scenario file, in the file's words;
/// pieces of input quoted in the message (between ` or ") clipped.
pub(super) fn plain_words(message: &str) -> String {
    let mut m = message.trim_end().to_string();
    for (from, to) in [
        ("expected i64", "expected an integer"),
        ("expected u64", "expected an integer"),
        ("expected usize", "expected an integer"),
        ("expected f64", "expected a number"),
        ("expected a sequence", "expected a list [..]"),
        ("floating point `", "number `"),
        (
            "number too large to fit in target type",
            "number too large (at most 9223372036854775807)",
        ),
    ] {
        m = m.replace(from, to);
    }
    // Clip each quoted piece: a 5 MB key or string must not be echoed.
    let mut out = String::with_capacity(m.len().min(4 * MAX_ECHO));
    let mut rest = m.as_str();
    while let Some(open) = rest.find(['`', '"']) {
        let q = rest.as_bytes()[open] as char;
        out.push_str(&rest[..=open]);
        rest = &rest[open + 1..];
        match rest.find(q) {
            Some(close) => {
                out.push_str(&clip(&rest[..close], 60));
                out.push(q);
                rest = &rest[close + 1..];
            }
            None => {
                out.push_str(&clip(rest, 60));
                rest = "";
            }
        }
    }
    out.push_str(rest);
    clip(&out, 4 * MAX_ECHO)
}

/// A TOML syntax or type error: the line and column, the offending line
/// (a window of at most [`MAX_ECHO`] characters around the error) with a
/// caret under it, and serde's message in plain words.
pub(super) fn toml_error(file: &str, text: &str, e: &toml::de::Error) -> ScenarioError {
    let message = plain_words(e.message());
    let Some(span) = e.span() else {
        return ScenarioError(format!("{file}: {message}"));
    };
    let floor = |mut i: usize| {
        i = i.min(text.len());
        while !text.is_char_boundary(i) {
            i -= 1;
        }
        i
    };
    let start = floor(span.start);
    let end = floor(span.end.max(span.start));
    let line_start = text[..start].rfind('\n').map_or(0, |i| i + 1);
    let line_end = text[start..].find('\n').map_or(text.len(), |i| start + i);
    let line_no = text[..start].matches('\n').count() + 1;
    let line = text[line_start..line_end].trim_end_matches('\r');
    let column = text[line_start..start].chars().count();
    let width = text[start..end.min(line_start + line.len()).max(start)]
        .chars()
        .count()
        .max(1);
    // The window of the line shown: MAX_ECHO characters, the error
    // starting at most a third of the way in.
    let chars = line.chars().count();
    let from = if chars <= MAX_ECHO {
        0
    } else {
        column.saturating_sub(MAX_ECHO / 3).min(chars - MAX_ECHO)
    };
    let shown: String = line.chars().skip(from).take(MAX_ECHO).collect();
    let (lead, tail) = (
        if from > 0 { "…" } else { "" },
        if from + MAX_ECHO < chars { "…" } else { "" },
    );
    let caret_at = column - from + lead.chars().count();
    let caret_width = width.min(MAX_ECHO + 1 - (column - from).min(MAX_ECHO));
    let gutter = " ".repeat(line_no.to_string().len());
    ScenarioError(format!(
        "{file}: TOML parse error at line {line_no}, column {}\n{gutter} |\n{line_no} | {lead}{shown}{tail}\n{gutter} | {}{}\n{message}",
        column + 1,
        " ".repeat(caret_at),
        "^".repeat(caret_width),
    ))
}
