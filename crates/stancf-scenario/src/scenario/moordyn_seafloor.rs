//! MoorDyn's 3-D seafloor file (`SeafloorFile`; docs/interface.md,
//! "Water"; docs/method.md §12.2 (W40a)-(W40c)), read as MoorDyn's
//! `Seafloor::setup` reads it:
//!
//! ```text
//!   nx ny                  the number of x and y ticks
//!   x_1 ... x_nx           the x ticks (m)
//!   y_1 ... y_ny           the y ticks (m)
//!   x y z                  one row per node: the bed's height z (m, up,
//!   ...                    the still surface z = 0) at (x, y)
//! ```
//!
//! Every number is read as MoorDyn's `stof` reads it, a float widened to
//! a double, so the ticks and heights are MoorDyn's to the bit. Where
//! MoorDyn accepts what is almost surely a mistake, the file is refused
//! by line instead of read silently: a row off the ticks (MoorDyn puts it
//! on the tick below), a node given twice (MoorDyn keeps the last) and a
//! node not given (MoorDyn puts the bed at the surface there, z = 0).
//! Blank lines are skipped; ticks must rise strictly (MoorDyn's
//! interpolation assumes it).

use super::messages::stof_word as float_word;
use super::ScenarioError;
use crate::moordyn::{Deck, SupportedOption};
use stancf::error::Sig;
use stancf::water::Bathymetry;
use std::path::Path;
use std::sync::Arc;

/// A bed of varying height read from a MoorDyn seafloor file, and where
/// it came from (for `stancf check`).
#[derive(Clone, Debug, PartialEq)]
pub struct SeabedFile {
    pub grid: Arc<Bathymetry>,
    /// The file and how it was found.
    pub source: String,
}

/// A count of ticks: a whole number >= 1 (MoorDyn's `stoi`).
fn count_word(word: &str, at: usize, what: &str) -> Result<usize, String> {
    word.parse::<usize>()
        .ok()
        .filter(|n| *n >= 1)
        .ok_or_else(|| {
            format!("line {at}: the number of {what} ticks is \"{word}\", not a whole number >= 1")
        })
}

/// The bed of a MoorDyn seafloor file's text. Errors name the line.
pub fn read_seafloor(text: &str) -> Result<Bathymetry, String> {
    let mut lines = crate::echo::text_lines(text)
        .enumerate()
        .map(|(n, l)| (n + 1, l.split_whitespace().collect::<Vec<_>>()))
        .filter(|(_, words)| !words.is_empty());
    let mut next = |what: &str| {
        lines.next().ok_or_else(|| {
            format!(
                "the file ends before {what} (it holds \"nx ny\", the x ticks, the y ticks, \
                 then a row \"x y z\" per node)"
            )
        })
    };
    let (at, sizes) = next("its first line, \"nx ny\"")?;
    if sizes.len() < 2 {
        return Err(format!(
            "line {at}: the first line is \"nx ny\", the numbers of ticks"
        ));
    }
    let nx = count_word(sizes[0], at, "x")?;
    let ny = count_word(sizes[1], at, "y")?;
    let mut axes = Vec::new();
    for (name, n) in [("x", nx), ("y", ny)] {
        let (at, words) = next(&format!("the {name} ticks"))?;
        if words.len() != n {
            return Err(format!(
                "line {at}: {} {name} ticks where the first line says {n}",
                words.len()
            ));
        }
        let ticks = words
            .iter()
            .map(|w| float_word(w, at))
            .collect::<Result<Vec<_>, _>>()?;
        if let Some(i) = (1..n).find(|&i| ticks[i] <= ticks[i - 1]) {
            return Err(format!(
                "line {at}: the {name} ticks must rise: {} after {}",
                words[i],
                words[i - 1]
            ));
        }
        axes.push((at, ticks));
    }
    let (x_line, xs) = axes.remove(0);
    let (y_line, ys) = axes.remove(0);
    // The line of the row that gave each node, 0 for none yet.
    let mut given = vec![0usize; nx * ny];
    let mut heights = vec![0.0; nx * ny];
    for (at, words) in lines {
        if words.len() != 3 {
            return Err(format!(
                "line {at}: a node's row is \"x y z\", 3 numbers; this one has {}",
                words.len()
            ));
        }
        let [x, y, z] = [0, 1, 2].map(|k| float_word(words[k], at));
        let (x, y, z) = (x?, y?, z?);
        let tick = |ticks: &[f64], v: f64, name: &str, line: usize| {
            ticks.iter().position(|t| *t == v).ok_or_else(|| {
                format!(
                    "line {at}: {name} = {} is not one of the {name} ticks of line {line} \
                     (MoorDyn would put the row on the tick below it)",
                    Sig(v)
                )
            })
        };
        let node = tick(&xs, x, "x", x_line)? * ny + tick(&ys, y, "y", y_line)?;
        if given[node] != 0 {
            return Err(format!(
                "line {at}: the node (x, y) = ({}, {}) is given twice, first at line {} \
                 (MoorDyn would keep this one)",
                Sig(x),
                Sig(y),
                given[node]
            ));
        }
        given[node] = at;
        heights[node] = z;
    }
    if let Some(node) = given.iter().position(|l| *l == 0) {
        let missing = given.iter().filter(|l| **l == 0).count();
        return Err(format!(
            "no row gives the node (x, y) = ({}, {}){}: every node of the {nx} x {ny} grid \
             needs its height (MoorDyn would put the bed at the surface, z = 0, there)",
            Sig(xs[node / ny]),
            Sig(ys[node % ny]),
            if missing > 1 {
                format!(" and {} more", missing - 1)
            } else {
                String::new()
            }
        ));
    }
    Bathymetry::new([xs, ys], heights).map_err(|e| e.to_string())
}

/// The deck's `SeafloorFile`: the bed in the file it names, found by
/// [`super::deck_files::locate`], with a note of where it was found, what
/// it holds and the water depth MoorDyn takes from it; None without the
/// option. Refused naming the option's line: a file not found or not
/// read, a bed whose mean height is not below the surface.
pub(super) fn deck_seafloor(
    deck: &Deck,
    file: &str,
    path: &Path,
) -> Result<(Option<SeabedFile>, Option<String>), ScenarioError> {
    let Some((named, name, line)) = deck.option_text(SupportedOption::SeafloorFile) else {
        return Ok((None, None));
    };
    let refuse = |e: String| ScenarioError(format!("{file}: line {line}: option {name}: {e}"));
    let found = super::deck_files::locate(named, path).map_err(refuse)?;
    let read = |e: String| refuse(format!("{}: {e}", found.path.display()));
    let text = crate::input_file::read_text(&found.path).map_err(read)?;
    let grid = read_seafloor(&text).map_err(read)?;
    let mean = grid.mean_height();
    if mean >= 0.0 {
        return Err(read(format!(
            "the bed's mean height is {} m, not below the surface (z = 0): MoorDyn takes the \
             water's depth from it",
            Sig(mean)
        )));
    }
    let (lo, hi) = grid.height_range();
    let [xs, ys] = grid.axes();
    let depth_given = deck
        .option(SupportedOption::WaterDepth)
        .map(|d| format!(" in place of the deck's WtrDpth {} m", Sig(d)))
        .unwrap_or_default();
    let note = format!(
        "OPTIONS: {name} {named} (line {line}): found at {} ({}): a bed of {} x {} nodes over x \
         [{}, {}] m, y [{}, {}] m, z from {} to {} m, bilinear between them and held at its edges \
         beyond; the contact pushes along the bed's local normal (MoorDyn's pushes up: \
         docs/method.md §12.2). The water's depth (for the waves) is the nodes' mean depth, {} \
         m{depth_given}, as MoorDyn sets it",
        found.path.display(),
        found.place,
        xs.len(),
        ys.len(),
        Sig(xs[0]),
        Sig(xs[xs.len() - 1]),
        Sig(ys[0]),
        Sig(ys[ys.len() - 1]),
        Sig(lo),
        Sig(hi),
        Sig(-mean)
    );
    let bed = SeabedFile {
        grid: Arc::new(grid),
        source: format!(
            "{} (the deck's {name}, {})",
            found.path.display(),
            found.place
        ),
    };
    Ok((Some(bed), Some(note)))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_grid_reads_as_moordyn_reads_it() {
        let text = "3 2\n-10 0.15 20\n-1 1\n\n\
                    -10 -1 -40\n-10 1 -40.5\n0.15 -1 -39\n0.15 1 -39.25\n20 -1 -38\n20 1 -38.1\n";
        let bed = read_seafloor(text).unwrap();
        // stof: 0.15 and -38.1 as floats, widened.
        assert_eq!(bed.axes()[0], vec![-10.0, f64::from(0.15f32), 20.0]);
        assert_eq!(bed.heights()[5], f64::from(-38.1f32));
        assert_eq!(bed.heights()[1], -40.5);
        assert_eq!(bed.height(20.0, 1.0).height, f64::from(-38.1f32));
    }

    #[test]
    fn a_file_moordyn_would_misread_is_refused_by_line() {
        let head = "2 2\n0 10\n0 5\n";
        for (rows, words) in [
            (
                "0 0 -1\n0 5 -1\n10 0 -1\n10 3 -1\n",
                "line 7: y = 3 is not one of the y ticks",
            ),
            (
                "0 0 -1\n0 5 -1\n10 0 -1\n0 0 -2\n10 5 -1\n",
                "line 7: the node (x, y) = (0, 0) is given twice, first at line 4",
            ),
            (
                "0 0 -1\n0 5 -1\n10 0 -1\n",
                "no row gives the node (x, y) = (10, 5)",
            ),
            (
                "0 0 -1 4\n",
                "line 4: a node's row is \"x y z\", 3 numbers; this one has 4",
            ),
            ("0 0 1e60\n", "beyond single precision"),
        ] {
            let e = read_seafloor(&format!("{head}{rows}")).unwrap_err();
            assert!(e.contains(words), "{e}");
        }
        let e = read_seafloor("2 2\n10 0\n0 5\n").unwrap_err();
        assert!(
            e.contains("line 2: the x ticks must rise: 0 after 10"),
            "{e}"
        );
        let e = read_seafloor("2 2\n0 10 20\n").unwrap_err();
        assert!(
            e.contains("line 2: 3 x ticks where the first line says 2"),
            "{e}"
        );
        let e = read_seafloor("2 0\n").unwrap_err();
        assert!(e.contains("line 1: the number of y ticks is \"0\""), "{e}");
    }
}
