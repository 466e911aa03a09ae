//! (b) Mutations of the shipped examples: the examples shortened to a
//! few steps, then lines deleted, duplicated, swapped or inserted, a
//! character flipped, a number scaled or negated, the text truncated or a
//! value replaced.

use crate::bound::bound_work;
use crate::common::repo_file;
use crate::grammar::{f64_literal, weird, wide_number};
use proptest::prelude::*;
use proptest::sample::select;
use std::path::PathBuf;

fn examples_dir() -> PathBuf {
    repo_file("examples")
}

/// The shipped examples, each shortened to a few steps (`duration` set to
/// 4 time steps), with their comments kept.
pub fn shortened_examples() -> Vec<(String, String)> {
    let mut names: Vec<PathBuf> = std::fs::read_dir(examples_dir())
        .expect("examples/")
        .flatten()
        .map(|e| e.path())
        .filter(|p| p.extension().is_some_and(|e| e == "toml"))
        .collect();
    names.sort();
    assert!(!names.is_empty(), "no examples/*.toml");
    names
        .into_iter()
        .map(|p| {
            let text = std::fs::read_to_string(&p).unwrap();
            let value = |key: &str| -> Option<f64> {
                text.lines()
                    .find(|l| l.trim_start().starts_with(key))
                    .and_then(|l| l.split('=').nth(1))
                    .and_then(|v| v.split('#').next())
                    .and_then(|v| v.trim().parse().ok())
            };
            let short = match value("time_step") {
                Some(dt) => text
                    .lines()
                    .map(|l| {
                        if l.trim_start().starts_with("duration") {
                            format!("duration = {:e}   # shortened to 4 steps", 4.0 * dt)
                        } else {
                            l.to_string()
                        }
                    })
                    .collect::<Vec<_>>()
                    .join("\n"),
                None => text,
            };
            (p.file_name().unwrap().to_string_lossy().into_owned(), short)
        })
        .collect()
}

/// The MoorDyn decks in `examples/` (`*.txt`), as shipped: a deck alone
/// runs statics only, so there is nothing to shorten.
pub fn shipped_decks() -> Vec<(String, String)> {
    let mut names: Vec<PathBuf> = std::fs::read_dir(examples_dir())
        .expect("examples/")
        .flatten()
        .map(|e| e.path())
        .filter(|p| p.extension().is_some_and(|e| e == "txt"))
        .collect();
    names.sort();
    assert!(!names.is_empty(), "no examples/*.txt decks");
    names
        .into_iter()
        .map(|p| {
            let text = std::fs::read_to_string(&p).unwrap();
            (p.file_name().unwrap().to_string_lossy().into_owned(), text)
        })
        .collect()
}

/// A position in a sequence of any length (taken modulo the length).
#[derive(Clone, Copy, Debug)]
pub struct Ix(pub usize);

impl Ix {
    fn index(self, len: usize) -> usize {
        self.0 % len
    }
}

impl Arbitrary for Ix {
    type Parameters = ();
    type Strategy = proptest::strategy::Map<std::ops::Range<usize>, fn(usize) -> Ix>;
    fn arbitrary_with(_: ()) -> Self::Strategy {
        (0..1usize << 20).prop_map(Ix)
    }
}

#[derive(Clone, Debug)]
pub enum Mutation {
    DeleteLine(Ix),
    DuplicateLine(Ix),
    SwapLines(Ix, Ix),
    FlipChar(Ix, char),
    ScaleNumber(Ix, i32),
    NegateNumber(Ix),
    Truncate(Ix),
    InsertLine(Ix, String),
    ReplaceValue(Ix, String),
}

const INSERTS: &[&str] = &[
    "bogus = 1",
    "[extra]",
    "[cable]",
    "[analysis]",
    "[[loads]]",
    "[[constraints]]",
    "[[initial_velocity]]",
    "type = \"gravity\"",
    "type = \"static\"",
    "type = \"clamped\"",
    "node = \"all\"",
    "node = 2.5",
    "node = -1",
    "node = 99",
    "elements = 1000001",
    "time_layers = 17",
    "time_layers = 2",
    "duration = 1e30",
    "time_step = 1e-300",
    "every = 0",
    "title = \"x,y\"",
    "velocity = [1e300, 0, 0]",
    "angular_velocity = [0, 0, 1e200]",
    "fix_curvature = true",
    "element = \"SAC-3\"",
    "time_scheme = \"galerkin\"",
    "solver = \"broyden\"",
    "solver = \"modified-newton\"",
    "constraint_method = \"elimination\"",
    "planar_reduction = false",
    "quadrature = [1, 1]",
    "quadrature = [2, 3, 1]",
    "max_iterations = 1",
    "tolerance = 1e-300",
    "tolerance = 1e300",
    "area = 1e300",
    "second_moment = 1e-300",
    "length = 1e300",
    "density = 1e-300",
    "youngs_modulus = 1e300",
    "[[constraints]]\ntype = \"clamped\"\nnode = \"B\"",
    "[[constraints]]\ntype = \"prescribed\"\nnode = \"B\"\namplitude = [0, 0.01, 0]\nfrequency = 1e300",
    "[[loads]]\ntype = \"end-moment\"\nnode = \"B\"\nmoment = [1e300, 0, 0]",
    "[[loads]]\ntype = \"point-force\"\nnode = \"B\"\nforce = [0, -1e300, 0]",
    "[[loads]]\ntype = \"air-drag\"\ndrag_coefficient = 1e300\nfluid_density = 1.2",
    "[[initial_velocity]]\nnode = \"all\"\nangular_velocity = [0, 0, 1]",
    "[[initial_velocity]]\nnode = \"B\"\nvelocity = [0, 1e200, 0]",
    "\u{0}",
    "\u{feff}title = \"bom\"",
    "a = \"unterminated",
    "[",
    "=",
    "'''",
];

const FLIPS: &[char] = &[
    '"', '\'', '[', ']', '{', '}', '=', '#', '\n', '.', ',', '-', '+', 'e', 'E', '0', '1', '9',
    ' ', '\t', '\\', '_', 'x', 'A', 'é', '\u{0}', '\u{7f}', '\u{2028}',
];

fn mutation() -> impl Strategy<Value = Mutation> {
    let value = prop_oneof![weird(), wide_number()];
    prop_oneof![
        1 => any::<Ix>().prop_map(Mutation::DeleteLine),
        1 => any::<Ix>().prop_map(Mutation::DuplicateLine),
        1 => (any::<Ix>(), any::<Ix>()).prop_map(|(a, b)| Mutation::SwapLines(a, b)),
        1 => (any::<Ix>(), select(FLIPS)).prop_map(|(i, c)| Mutation::FlipChar(i, c)),
        3 => (any::<Ix>(), select(&[-300, -20, -10, -5, -3, -2, -1, 1, 2, 3, 5, 10, 20, 300][..]))
            .prop_map(|(i, k)| Mutation::ScaleNumber(i, k)),
        1 => any::<Ix>().prop_map(Mutation::NegateNumber),
        1 => any::<Ix>().prop_map(Mutation::Truncate),
        2 => (any::<Ix>(), select(INSERTS)).prop_map(|(i, l)| Mutation::InsertLine(i, l.to_string())),
        2 => (any::<Ix>(), value).prop_map(|(i, v)| Mutation::ReplaceValue(i, v)),
    ]
}

/// The numbers of a text: byte ranges of tokens such as `4`, `-2.0`,
/// `1.25e-13` that follow a space, `[`, `,`, `=` or a line start.
pub fn number_spans(text: &str) -> Vec<(usize, usize)> {
    let b = text.as_bytes();
    let mut spans = Vec::new();
    let mut i = 0;
    while i < b.len() {
        let starts = (b[i].is_ascii_digit() || b[i] == b'-' || b[i] == b'+')
            && (i == 0 || matches!(b[i - 1], b' ' | b'[' | b',' | b'=' | b'\n' | b'\t'));
        if starts {
            let mut j = i + 1;
            while j < b.len() && (b[j].is_ascii_digit() || b"._eE+-".contains(&b[j])) {
                j += 1;
            }
            if text[i..j].replace('_', "").parse::<f64>().is_ok() {
                spans.push((i, j));
            }
            i = j;
        } else {
            i += 1;
        }
    }
    spans
}

pub fn apply(text: &str, m: &Mutation) -> String {
    let mut lines: Vec<String> = text.lines().map(String::from).collect();
    let join = |lines: Vec<String>| lines.join("\n") + "\n";
    match m {
        Mutation::DeleteLine(i) if !lines.is_empty() => {
            lines.remove(i.index(lines.len()));
            join(lines)
        }
        Mutation::DuplicateLine(i) if !lines.is_empty() => {
            let k = i.index(lines.len());
            let l = lines[k].clone();
            lines.insert(k, l);
            join(lines)
        }
        Mutation::SwapLines(a, b) if !lines.is_empty() => {
            let (a, b) = (a.index(lines.len()), b.index(lines.len()));
            lines.swap(a, b);
            join(lines)
        }
        Mutation::InsertLine(i, l) => {
            let k = i.index(lines.len() + 1);
            lines.insert(k, l.clone());
            join(lines)
        }
        Mutation::ReplaceValue(i, v) => {
            let with_value: Vec<usize> = (0..lines.len())
                .filter(|&k| lines[k].contains('=') && !lines[k].trim_start().starts_with('#'))
                .collect();
            if with_value.is_empty() {
                return text.to_string();
            }
            let k = with_value[i.index(with_value.len())];
            let key = lines[k].split('=').next().unwrap().to_string();
            lines[k] = format!("{key}= {v}");
            join(lines)
        }
        Mutation::FlipChar(i, c) => {
            let mut chars: Vec<char> = text.chars().collect();
            if chars.is_empty() {
                return c.to_string();
            }
            let k = i.index(chars.len());
            chars[k] = *c;
            chars.into_iter().collect()
        }
        Mutation::Truncate(i) => text
            .chars()
            .take(i.index(text.chars().count() + 1))
            .collect(),
        Mutation::ScaleNumber(i, k) => {
            let spans = number_spans(text);
            if spans.is_empty() {
                return text.to_string();
            }
            let (a, b) = spans[i.index(spans.len())];
            let tok = &text[a..b];
            let integer = !tok.contains(['.', 'e', 'E']);
            let new = if integer && *k > 0 {
                // Stays an integer: may overflow i64 (an error TOML must report).
                format!("{tok}{}", "0".repeat(*k as usize))
            } else {
                let v: f64 = tok.replace('_', "").parse().unwrap();
                f64_literal(v * 10f64.powi(*k))
            };
            format!("{}{new}{}", &text[..a], &text[b..])
        }
        Mutation::NegateNumber(i) => {
            let spans = number_spans(text);
            if spans.is_empty() {
                return text.to_string();
            }
            let (a, b) = spans[i.index(spans.len())];
            let tok = &text[a..b];
            let new = match tok.strip_prefix('-') {
                Some(rest) => rest.to_string(),
                None => format!("-{}", tok.trim_start_matches('+')),
            };
            format!("{}{new}{}", &text[..a], &text[b..])
        }
        _ => text.to_string(),
    }
}

pub fn mutated_example() -> BoxedStrategy<String> {
    let examples = shortened_examples();
    let mut texts: Vec<String> = examples.into_iter().map(|(_, t)| t).collect();
    texts.extend(shipped_decks().into_iter().map(|(_, t)| t));
    (select(texts), prop::collection::vec(mutation(), 1..=2))
        .prop_map(|(text, ms)| bound_work(ms.iter().fold(text, |t, m| apply(&t, m))))
        .boxed()
}
