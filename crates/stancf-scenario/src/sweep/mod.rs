//! `stancf sweep`: one scenario run over a grid of values of its keys.
//!
//! `--set key=v1,v2,...` names a key by its dotted path in the scenario
//! (`analysis.time_step`, `loads.1.drag_coefficient`: array entries by their
//! 0-based index) and the values it takes; several `--set` make the grid
//! their Cartesian product. Every point is the scenario with those values
//! put in, validated by the same code as a scenario file (a bad key or
//! value stops the sweep before anything runs, exit 2), then run in its own
//! folder `DIR/run_<k>/` (with its `scenario.toml`), `--jobs` at a time.
//! `DIR/sweep.csv` gathers the varied values and the summary figures of
//! every run, also of runs that failed (their error in the last column),
//! as RFC 4180 CSV (a cell with a comma, quote or line break is quoted).
//!
//! A key may be given once (nor may one key lie inside another:
//! `loads.0` and `loads.0.acceleration`), and a grid has at most
//! [`MAX_POINTS`] points, counted from the lengths of the lists before
//! any point is built. The points are then built and validated one at a
//! time, nothing of them kept, so validation needs memory for the table
//! only (a few bytes per point) and takes about 0.1 ms per point.

mod extremes;
mod figures;
mod grid;

pub use extremes::{extremes_csv, gumbel_fit, seed_axis, Gumbel, RunRow};
pub use figures::{columns, figures, FIGURES, SYSTEM_FIGURES};

use crate::output::{write_atomic, Num, ResultFolder};
use crate::Failure;
use grid::Grid;

pub use grid::{base_document, SCENARIO_AXIS};
use std::path::PathBuf;

/// One swept key and its values.
#[derive(Clone, Debug, PartialEq)]
pub struct Axis {
    pub key: String,
    pub values: Vec<toml::Value>,
}

/// Splits at commas that are not inside brackets or TOML strings (`"..."`
/// with backslash escapes; `'...'` literal, when it starts a value, so
/// that a bare word may hold an apostrophe).
fn split_top_level(s: &str) -> Vec<&str> {
    let (mut depth, mut start) = (0i32, 0);
    let mut quote: Option<char> = None;
    let mut escaped = false;
    // The last character outside strings that is not white space.
    let mut prev: Option<char> = None;
    let mut out = Vec::new();
    for (i, c) in s.char_indices() {
        if let Some(q) = quote {
            if escaped {
                escaped = false;
            } else if c == '\\' && q == '"' {
                escaped = true;
            } else if c == q {
                quote = None;
            }
            continue;
        }
        let starts_value = matches!(prev, None | Some(',' | '[' | '{' | '='));
        if !c.is_whitespace() {
            prev = Some(c);
        }
        match c {
            '"' => quote = Some(c),
            '\'' if starts_value => quote = Some(c),
            '[' | '{' => depth += 1,
            ']' | '}' => depth -= 1,
            ',' if depth == 0 => {
                out.push(&s[start..i]);
                start = i + 1;
                prev = None;
            }
            _ => {}
        }
    }
    out.push(&s[start..]);
    out
}

/// A value as TOML (number, boolean, array, quoted string), or a bare word
/// as a string (`newton`).
pub fn parse_value(s: &str) -> toml::Value {
    let s = s.trim();
    match format!("v = {s}").parse::<toml::Table>() {
        Ok(mut t) => t
            .remove("v")
            .unwrap_or_else(|| toml::Value::String(s.into())),
        Err(_) => toml::Value::String(s.into()),
    }
}

/// `key=v1,v2,...`.
pub fn parse_set(arg: &str) -> Result<Axis, String> {
    let (key, values) = arg
        .split_once('=')
        .ok_or_else(|| format!("--set {arg}: expected key=value[,value...]"))?;
    let key = key.trim();
    if key.is_empty() || key.split('.').any(|s| s.is_empty()) {
        return Err(format!("--set {arg}: {key:?} is not a dotted key"));
    }
    let values: Vec<toml::Value> = split_top_level(values)
        .into_iter()
        .filter(|v| !v.trim().is_empty())
        .map(parse_value)
        .collect();
    if values.is_empty() {
        return Err(format!("--set {arg}: no values"));
    }
    Ok(Axis {
        key: key.to_string(),
        values,
    })
}

/// The most points a sweep may have. Every point is a run with its own
/// folder of result files (megabytes for the examples) and a row of
/// sweep.csv: ten thousand are hours of computing on a workstation and
/// gigabytes of results, while validating them takes about a second. A
/// larger study is several sweeps (a grid per `--out` folder). The Python
/// package's sweep has the same bound (`stancf._stancf.SWEEP_LIMIT`).
pub const MAX_POINTS: usize = 10_000;

/// The number of points of a grid with lists of these lengths (their
/// product), or why it is refused: more than [`MAX_POINTS`]. Computed
/// before any point is built.
pub fn grid_size(lengths: &[usize]) -> Result<usize, String> {
    let product = lengths.iter().try_fold(1usize, |n, &l| n.checked_mul(l));
    let dims = lengths
        .iter()
        .map(|l| l.to_string())
        .collect::<Vec<_>>()
        .join(" x ");
    match product {
        Some(n) if n <= MAX_POINTS => Ok(n),
        Some(n) => Err(format!(
            "sweep: the grid has {n} points ({dims}), more than the limit of \
             {MAX_POINTS} points per sweep; split it into several sweeps"
        )),
        None => Err(format!(
            "sweep: the grid has more than {} points ({dims}), more than the \
             limit of {MAX_POINTS} points per sweep; split it into several sweeps",
            usize::MAX
        )),
    }
}

/// Refuses a key given twice and a key inside another (`loads.0` and
/// `loads.0.acceleration`): either way a run would be labelled with a
/// value it did not use. (A key has one spelling: list entries are
/// written `0`, `1`, ..., see [`apply`].)
pub fn check_keys(keys: &[&str]) -> Result<(), String> {
    for (i, a) in keys.iter().enumerate() {
        for b in &keys[i + 1..] {
            if a == b {
                return Err(format!(
                    "sweep: the key {a} is given twice; give each key once, with \
                     all its values in one list"
                ));
            }
            let (outer, inner) = if a.len() < b.len() { (a, b) } else { (b, a) };
            if inner.starts_with(outer) && inner[outer.len()..].starts_with('.') {
                return Err(format!(
                    "sweep: the keys {outer} and {inner} overlap ({inner} is part of \
                     {outer}), so a run would not have the value of {outer} its row \
                     shows; vary one of them"
                ));
            }
        }
    }
    Ok(())
}

/// Puts `value` at the dotted `key` of a scenario document: tables by
/// name (created if missing), arrays by 0-based index (which must exist,
/// written without sign or leading zeros, so a key has one spelling).
pub fn apply(doc: &mut toml::Table, key: &str, value: toml::Value) -> Result<(), String> {
    let parts: Vec<&str> = key.split('.').collect();
    let mut here = doc;
    let mut path = String::new();
    for (i, part) in parts.iter().enumerate() {
        let last = i + 1 == parts.len();
        if !path.is_empty() {
            path.push('.');
        }
        path.push_str(part);
        if last {
            here.insert((*part).to_string(), value);
            return Ok(());
        }
        let next = here
            .entry((*part).to_string())
            .or_insert_with(|| toml::Value::Table(toml::Table::new()));
        // An array step: the next part is its index.
        let next = match next {
            toml::Value::Array(items) => {
                let idx_part = parts[i + 1];
                let idx: usize = idx_part
                    .parse()
                    .ok()
                    .filter(|i: &usize| i.to_string() == idx_part)
                    .ok_or_else(|| {
                        format!("{path} is a list: {idx_part:?} is not an index (0, 1, 2, ...)")
                    })?;
                let n = items.len();
                let item = items
                    .get_mut(idx)
                    .ok_or_else(|| format!("{path} has {n} entries: no index {idx}"))?;
                if i + 2 == parts.len() {
                    *item = value;
                    return Ok(());
                }
                return match item {
                    toml::Value::Table(t) => apply(t, &parts[i + 2..].join("."), value),
                    _ => Err(format!("{path}.{idx} is not a table")),
                };
            }
            toml::Value::Table(t) => t,
            _ => return Err(format!("{path} is a value, not a table")),
        };
        here = next;
    }
    Ok(())
}

/// Point `k` of the grid (`k` < [`grid_size`]): one value per axis, the
/// first axis slowest, as the Cartesian product lists them.
pub fn point(axes: &[Axis], mut k: usize) -> Vec<&toml::Value> {
    let mut values = Vec::with_capacity(axes.len());
    for a in axes.iter().rev() {
        let n = a.values.len();
        values.push(&a.values[k % n]);
        k /= n;
    }
    values.reverse();
    values
}

/// A value as text (strings bare, the rest as TOML: `[0, -10, 0]`).
fn cell(v: &toml::Value) -> String {
    match v {
        toml::Value::String(s) => s.clone(),
        toml::Value::Float(x) => Num(*x).to_string(),
        other => other.to_string(),
    }
}

/// A CSV field (RFC 4180): quoted, with quotes doubled, when it holds a
/// comma, a quote or a line break; as it is otherwise.
pub fn csv_field(s: &str) -> std::borrow::Cow<'_, str> {
    if s.contains([',', '"', '\n', '\r']) {
        format!("\"{}\"", s.replace('"', "\"\"")).into()
    } else {
        s.into()
    }
}

/// `stancf sweep`: every point of the grid of `sets` over the scenario
/// files `paths` (one more axis, `scenario`, when there are several)
/// validated first, then run `jobs` at a time into `run_<k>` of one
/// result folder with its sweep.csv (docs/interface.md, "stancf sweep").
pub fn sweep(
    paths: &[PathBuf],
    sets: &[String],
    jobs: Option<usize>,
    out: Option<PathBuf>,
) -> Result<(), Failure> {
    let grid = Grid::read(paths, sets)?;
    let target = out.unwrap_or_else(|| {
        let stem = paths[0]
            .file_stem()
            .map(|s| s.to_string_lossy().into_owned())
            .unwrap_or_default();
        PathBuf::from("out").join(format!("{}-sweep", crate::run::safe_folder_name(&stem)))
    });
    // The sweep's folder is one transaction, its runs' folders inside it.
    let folder = ResultFolder::open(&target)?;
    let dir = folder.staging().to_path_buf();
    let jobs = jobs
        .unwrap_or_else(|| {
            std::thread::available_parallelism()
                .map(|n| n.get())
                .unwrap_or(1)
        })
        .clamp(1, grid.points);
    let outcomes = grid.run_all(&dir, &target, jobs);
    let table = grid.table(&dir, outcomes);
    let cannot = |e: std::io::Error| {
        Failure::Other(format!("{}: cannot write results: {e}", target.display()))
    };
    write_atomic(&dir, "sweep.csv", table.csv.as_bytes()).map_err(cannot)?;
    if let Some(extremes) = &table.extremes {
        write_atomic(&dir, "extremes.csv", extremes.as_bytes()).map_err(cannot)?;
    }
    folder.commit().map_err(cannot)?;
    let shown = target.join("sweep.csv");
    if table.interrupted {
        return Err(Failure::Interrupted(format!(
            "sweep: interrupted; the runs that finished, and those cut short up to their last \
             step, are in {} (status column)",
            shown.display()
        )));
    }
    println!(
        "sweep: {} runs ({} at a time), {} failed; table in {}",
        grid.points,
        jobs,
        table.failed.len(),
        shown.display()
    );
    if table.failed.is_empty() {
        return Ok(());
    }
    Err(Failure::Solver(format!(
        "sweep: runs {} failed (see the error column of {})",
        table
            .failed
            .iter()
            .map(|k| k.to_string())
            .collect::<Vec<_>>()
            .join(", "),
        shown.display()
    )))
}

#[cfg(test)]
mod tests;
