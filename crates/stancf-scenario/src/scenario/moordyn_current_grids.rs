//! A MoorDyn deck's currents that vary in time (docs/interface.md,
//! "Water"; docs/method.md §12.1 (W9a)-(W9b)): `Currents 2`, the dynamic
//! depth profile of `current_profile_dynamic.txt`, and `Currents 5`, the
//! 4-D grid of `current_profile_4d.txt`, both read as MoorDyn's docs
//! (waterkinematics.rst) describe them and given to the sea as a
//! [`CurrentGrid`]: multilinear in space and time, holding the nearest
//! value beyond the grid ("a point outside of the defined grid (either in
//! z value or in time) will use the nearest value").
//!
//! Where MoorDyn's code differs from its docs or from the field the file
//! gives (Waves/WaveGrid.cpp): it resamples the times every smallest
//! interval and, past the last time, repeats the record from its start
//! (its grid index wraps); it sets the current's acceleration to zero
//! where the fluid's inertia here sees dU/dt of the interpolated field;
//! and its 4-D reader starts at the file's seventh line, leaving the node
//! of the sixth (the first data row, by its docs and its own line count)
//! at zero current. The notes of `check` say so.

use stancf::error::Sig;
use stancf::water::current_grid::CurrentGrid;
use std::path::Path;

/// The file of `Currents 2`.
pub const DYNAMIC_PROFILE_FILE: &str = "current_profile_dynamic.txt";
/// The file of `Currents 5`.
pub const GRID_4D_FILE: &str = "current_profile_4d.txt";

/// The words of each line (1-based number), blank lines kept as empty.
fn lines_of(text: &str) -> Vec<(usize, Vec<&str>)> {
    crate::echo::text_lines(text)
        .enumerate()
        .map(|(n, l)| (n + 1, l.split_whitespace().collect()))
        .collect()
}

use super::messages::finite_word as number;

/// An axis's values by rising order: rising as given, or falling and
/// then reversed (with `reversed` true). Refused naming the line.
fn monotone(values: Vec<f64>, at: usize, what: &str) -> Result<(Vec<f64>, bool), String> {
    let rising = values.windows(2).all(|p| p[1] > p[0]);
    let falling = values.windows(2).all(|p| p[1] < p[0]);
    match (rising, falling) {
        (true, _) => Ok((values, false)),
        (_, true) => Ok((values.into_iter().rev().collect(), true)),
        _ => Err(format!(
            "line {at}: the {what} must rise or fall strictly: {}",
            values
                .iter()
                .map(|v| Sig(*v).to_string())
                .collect::<Vec<_>>()
                .join(" ")
        )),
    }
}

/// `current_profile_dynamic.txt` (`Currents 2`): 4 lines ignored; line 5
/// the depths z_1 .. z_n (m), read as MoorDyn reads them, in single
/// precision (`stof`); line 6 ignored; then a row per time, `t` and the
/// n values of ux, optionally followed by n of uy and n of uz (0 when
/// left out), times strictly rising. Blank rows are skipped. A grid of
/// one x and y (0), the depths and the times.
pub fn read_dynamic_profile(text: &str) -> Result<CurrentGrid, String> {
    let lines = lines_of(text);
    let Some((at_depths, depth_words)) = lines.get(4).cloned() else {
        return Err(format!(
            "{} line(s); the depths are on line 5 and the rows from line 7",
            lines.len()
        ));
    };
    let depths = depth_words
        .iter()
        .map(|w| super::messages::stof_word(w, at_depths))
        .collect::<Result<Vec<f64>, String>>()?;
    if depths.is_empty() {
        return Err(format!(
            "line {at_depths}: no depths (z, m) on the depths line"
        ));
    }
    let (z, reversed) = monotone(depths, at_depths, "depths")?;
    let n = z.len();
    let mut times = Vec::new();
    let mut columns: Vec<Vec<[f64; 3]>> = Vec::new();
    for (at, words) in lines.iter().skip(6).filter(|(_, w)| !w.is_empty()) {
        let components = (words.len() - 1) / n;
        if words.len() < 1 + n || words.len() != 1 + components * n || components > 3 {
            return Err(format!(
                "line {at}: a row is t and the {n} depths' ux, optionally then their uy and uz: \
                 {}, {} or {} numbers, got {}",
                1 + n,
                1 + 2 * n,
                1 + 3 * n,
                words.len()
            ));
        }
        let v = words
            .iter()
            .map(|w| number(w, *at))
            .collect::<Result<Vec<f64>, String>>()?;
        if let Some(&last) = times.last() {
            if v[0] <= last {
                return Err(format!(
                    "line {at}: the time {} s does not rise above the row before ({last} s)",
                    v[0]
                ));
            }
        }
        times.push(v[0]);
        let mut profile: Vec<[f64; 3]> = (0..n)
            .map(|k| {
                std::array::from_fn(|c| {
                    if c < components {
                        v[1 + c * n + k]
                    } else {
                        0.0
                    }
                })
            })
            .collect();
        if reversed {
            profile.reverse();
        }
        columns.push(profile);
    }
    if times.is_empty() {
        return Err("no rows of times from line 7".to_string());
    }
    // Node (k, l) of depth k and time l at k n_t + l.
    let velocity = (0..n)
        .flat_map(|k| columns.iter().map(move |c| c[k]))
        .collect();
    CurrentGrid::new([vec![0.0], vec![0.0], z, times], velocity).map_err(|e| e.message)
}

/// `current_profile_4d.txt` (`Currents 5`): line 1 the counts n_x n_y n_z
/// n_t; lines 2-5 the x, y, z (m) and t (s) values, each strictly rising;
/// then a row `x y z t ux uy uz` for every node, its coordinates the
/// axes' values (matched as numbers), in any order. Refused naming the
/// line: a count or a value that is not one, an axis of other than its
/// count of values, a row off the axes or repeated, and a node without
/// a row.
pub fn read_grid_4d(text: &str) -> Result<CurrentGrid, String> {
    let lines: Vec<(usize, Vec<&str>)> = lines_of(text);
    if lines.len() < 6 {
        return Err(format!(
            "{} line(s); the counts are on line 1, the axes on lines 2-5, the rows from line 6",
            lines.len()
        ));
    }
    let (at, counts) = &lines[0];
    let counts: Vec<usize> = counts
        .iter()
        .map(|w| w.parse::<usize>().ok().filter(|&c| c > 0))
        .collect::<Option<Vec<usize>>>()
        .filter(|c| c.len() >= 4)
        .ok_or_else(|| {
            format!("line {at}: the first line is the counts of x, y, z and t values, 4 positive whole numbers")
        })?;
    let names = ["x", "y", "z", "t"];
    let mut axes: [Vec<f64>; 4] = Default::default();
    for a in 0..4 {
        let (at, words) = &lines[1 + a];
        if words.len() != counts[a] {
            return Err(format!(
                "line {at}: {} {} values are counted on line 1, {} given",
                counts[a],
                names[a],
                words.len()
            ));
        }
        let values = words
            .iter()
            .map(|w| number(w, *at))
            .collect::<Result<Vec<f64>, String>>()?;
        if let Some(p) = values.windows(2).find(|p| p[1] <= p[0]) {
            return Err(format!(
                "line {at}: the {} values must rise strictly: {} after {}",
                names[a], p[1], p[0]
            ));
        }
        axes[a] = values;
    }
    // The rows by node index, kept in a map: a count of nodes far beyond
    // the file's rows allocates nothing the size of the grid.
    let nodes = counts[..4]
        .iter()
        .try_fold(1usize, |n, c| n.checked_mul(*c))
        .ok_or_else(|| "line 1: the counts' product, the grid's nodes, overflows".to_string())?;
    let mut given: std::collections::HashMap<usize, ([f64; 3], usize)> =
        std::collections::HashMap::new();
    for (at, words) in lines.iter().skip(5).filter(|(_, w)| !w.is_empty()) {
        if words.len() != 7 {
            return Err(format!(
                "line {at}: a row is \"x y z t ux uy uz\", 7 numbers, got {}",
                words.len()
            ));
        }
        let v = words
            .iter()
            .map(|w| number(w, *at))
            .collect::<Result<Vec<f64>, String>>()?;
        let mut node = 0;
        for a in 0..4 {
            let Some(i) = axes[a].iter().position(|&c| c == v[a]) else {
                return Err(format!(
                    "line {at}: {} = {} is not one of the {} values of line {}",
                    names[a],
                    v[a],
                    names[a],
                    a + 2
                ));
            };
            node = node * counts[a] + i;
        }
        if let Some((_, first)) = given.get(&node) {
            return Err(format!(
                "line {at}: the node ({}, {}, {}, {}) was given at line {first} already",
                v[0], v[1], v[2], v[3]
            ));
        }
        given.insert(node, ([v[4], v[5], v[6]], *at));
    }
    if given.len() < nodes {
        // The first node without a row: among the first len + 1.
        let first = (0..nodes)
            .find(|k| !given.contains_key(k))
            .expect("one is missing");
        let mut rest = first;
        let mut coordinates = [0.0; 4];
        for a in (0..4).rev() {
            coordinates[a] = axes[a][rest % counts[a]];
            rest /= counts[a];
        }
        return Err(format!(
            "{} of the grid's {nodes} nodes have no row, the first ({}, {}, {}, {})",
            nodes - given.len(),
            coordinates[0],
            coordinates[1],
            coordinates[2],
            coordinates[3]
        ));
    }
    let velocity = (0..nodes).map(|k| given[&k].0).collect();
    CurrentGrid::new(axes, velocity).map_err(|e| e.message)
}

/// The note of `check` for a deck's current grid of `mode` (2 or 5) read
/// from `path` at the option's `line`.
pub fn grid_note(mode: u8, name: &str, line: usize, path: &Path, grid: &CurrentGrid) -> String {
    let times = &grid.axes()[3];
    let skipped = if mode == 5 {
        "; MoorDyn's reader starts at the file's line 7 and leaves the node of line 6 (its first \
         row) at zero current, stancf reads it"
    } else {
        ""
    };
    format!(
        "line {line}: {name} {mode}: the current of {} on its grid, multilinear in space and \
         time (docs/method.md §12.1 (W9a)); before {} s and after {} s it holds the nearest \
         time's, as MoorDyn's docs say (its grid repeats the record from the start); its \
         acceleration dU/dt loads the lines through the water's inertia, which MoorDyn sets to \
         zero{skipped}; a static run sees the current at t = 0",
        path.display(),
        Sig(times[0]),
        Sig(times[times.len() - 1]),
    )
}

#[cfg(test)]
#[path = "moordyn_current_grids_tests.rs"]
mod tests;
