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
//! every run, also of runs that failed (their error in the last column).

use crate::commands::{run, RunOptions};
use crate::output::{write_atomic, Num};
use crate::scenario;
use crate::Failure;
use std::fmt::Write as _;
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::Mutex;

/// One swept key and its values.
#[derive(Clone, Debug, PartialEq)]
pub struct Axis {
    pub key: String,
    pub values: Vec<toml::Value>,
}

/// Splits at commas that are not inside brackets or quotes.
fn split_top_level(s: &str) -> Vec<&str> {
    let (mut depth, mut quoted, mut start) = (0i32, false, 0);
    let mut out = Vec::new();
    for (i, c) in s.char_indices() {
        match c {
            '"' => quoted = !quoted,
            '[' | '{' if !quoted => depth += 1,
            ']' | '}' if !quoted => depth -= 1,
            ',' if !quoted && depth == 0 => {
                out.push(&s[start..i]);
                start = i + 1;
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

/// Puts `value` at the dotted `key` of a scenario document: tables by
/// name (created if missing), arrays by 0-based index (which must exist).
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
                    .map_err(|_| format!("{path} is a list: {idx_part:?} is not an index"))?;
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

/// The grid: every combination of the axes' values, first axis slowest.
pub fn grid(axes: &[Axis]) -> Vec<Vec<toml::Value>> {
    let mut points: Vec<Vec<toml::Value>> = vec![Vec::new()];
    for a in axes {
        points = points
            .into_iter()
            .flat_map(|p| {
                a.values.iter().map(move |v| {
                    let mut q = p.clone();
                    q.push(v.clone());
                    q
                })
            })
            .collect();
    }
    points
}

/// A value for a CSV cell (strings bare, arrays in brackets, no commas).
fn cell(v: &toml::Value) -> String {
    match v {
        toml::Value::String(s) => s.clone(),
        toml::Value::Float(x) => Num(*x).to_string(),
        other => other.to_string().replace(',', ";"),
    }
}

/// The summary figures of sweep.csv (and of the Python package's sweep),
/// in order, with their paths in summary.json (list entries by index).
pub const FIGURES: [(&str, &[&str]); 10] = [
    ("steps", &["steps"]),
    ("time", &["time"]),
    ("wall_time_s", &["wall_time_s"]),
    ("iterations_per_step", &["iterations", "mean_per_step"]),
    ("factorizations", &["iterations", "factorizations"]),
    ("energy_max_rel_drift", &["energy", "max_rel_drift"]),
    ("stress_peak_pa", &["stress_peak", "axial_stress"]),
    ("tip_x", &["tip", "0"]),
    ("tip_y", &["tip", "1"]),
    ("tip_z", &["tip", "2"]),
];

fn figure(summary: &serde_json::Value, path: &[&str]) -> String {
    let mut v = summary;
    for p in path {
        v = match p.parse::<usize>() {
            Ok(i) => &v[i],
            Err(_) => &v[*p],
        };
    }
    match v {
        serde_json::Value::Number(n) => n.as_f64().map(|x| Num(x).to_string()).unwrap_or_default(),
        _ => String::new(),
    }
}

/// `stancf sweep`.
pub fn sweep(
    path: &Path,
    sets: &[String],
    jobs: Option<usize>,
    out: Option<PathBuf>,
) -> Result<(), Failure> {
    let file = path.display().to_string();
    let text = std::fs::read_to_string(path)
        .map_err(|e| Failure::Input(format!("{file}: cannot read the file: {e}")))?;
    scenario::parse(&text, &file, path).map_err(|e| Failure::Input(e.0))?;
    let base: toml::Table = text
        .parse()
        .map_err(|e: toml::de::Error| Failure::Input(format!("{file}: {e}")))?;
    if sets.is_empty() {
        return Err(Failure::Input(
            "sweep: give at least one --set key=v1,v2,...".into(),
        ));
    }
    let axes: Vec<Axis> = sets
        .iter()
        .map(|s| parse_set(s))
        .collect::<Result<_, _>>()
        .map_err(Failure::Input)?;
    // Every point is built and validated before anything runs.
    let points = grid(&axes);
    let mut scenarios = Vec::with_capacity(points.len());
    for (k, point) in points.iter().enumerate() {
        let mut doc = base.clone();
        let label: Vec<String> = axes
            .iter()
            .zip(point)
            .map(|(a, v)| format!("{}={}", a.key, cell(v)))
            .collect();
        for (a, v) in axes.iter().zip(point) {
            apply(&mut doc, &a.key, v.clone())
                .map_err(|e| Failure::Input(format!("{file}: --set {}: {e}", a.key)))?;
        }
        let text =
            toml::to_string(&doc).map_err(|e| Failure::Other(format!("{file}: run {k}: {e}")))?;
        let name = format!("{file} with {}", label.join(", "));
        scenario::parse(&text, &name, path).map_err(|e| Failure::Input(e.0))?;
        scenarios.push(text);
    }
    let dir = out.unwrap_or_else(|| {
        let stem = path
            .file_stem()
            .map(|s| s.to_string_lossy().into_owned())
            .unwrap_or_default();
        PathBuf::from("out").join(format!("{stem}-sweep"))
    });
    std::fs::create_dir_all(&dir).map_err(|e| Failure::Other(format!("{}: {e}", dir.display())))?;
    let run_dirs: Vec<PathBuf> = (0..points.len())
        .map(|k| dir.join(format!("run_{k:04}")))
        .collect();
    for (d, text) in run_dirs.iter().zip(&scenarios) {
        std::fs::create_dir_all(d).map_err(|e| Failure::Other(format!("{}: {e}", d.display())))?;
        write_atomic(d, "scenario.toml", text.as_bytes())
            .map_err(|e| Failure::Other(format!("{}: {e}", d.display())))?;
    }
    let jobs = jobs
        .unwrap_or_else(|| {
            std::thread::available_parallelism()
                .map(|n| n.get())
                .unwrap_or(1)
        })
        .clamp(1, points.len());
    // Runs, `jobs` at a time; each records how it ended.
    let next = AtomicUsize::new(0);
    let outcomes: Mutex<Vec<Option<String>>> = Mutex::new(vec![None; points.len()]);
    std::thread::scope(|s| {
        for _ in 0..jobs {
            s.spawn(|| loop {
                let k = next.fetch_add(1, Ordering::SeqCst);
                if k >= points.len() {
                    break;
                }
                let d = &run_dirs[k];
                let result = run(
                    &d.join("scenario.toml"),
                    RunOptions {
                        out: Some(d.clone()),
                        quiet: true,
                        ..RunOptions::default()
                    },
                );
                let error = match result {
                    Ok(()) => String::new(),
                    Err(e) => e.to_string(),
                };
                outcomes.lock().expect("no run panics holding it")[k] = Some(error);
            });
        }
    });
    let outcomes = outcomes.into_inner().expect("all runs joined");
    // sweep.csv
    let mut csv = String::from("run");
    for a in &axes {
        write!(csv, ",{}", a.key).ok();
    }
    csv.push_str(",status");
    for (name, _) in FIGURES {
        write!(csv, ",{name}").ok();
    }
    csv.push_str(",error\n");
    let mut failed = Vec::new();
    for (k, point) in points.iter().enumerate() {
        let error = outcomes[k].clone().unwrap_or_else(|| "did not run".into());
        write!(csv, "{k}").ok();
        for v in point {
            write!(csv, ",{}", cell(v)).ok();
        }
        let summary: Option<serde_json::Value> =
            std::fs::read_to_string(run_dirs[k].join("summary.json"))
                .ok()
                .and_then(|t| serde_json::from_str(&t).ok());
        write!(csv, ",{}", if error.is_empty() { "ok" } else { "failed" }).ok();
        for (_, p) in FIGURES {
            write!(
                csv,
                ",{}",
                summary.as_ref().map(|s| figure(s, p)).unwrap_or_default()
            )
            .ok();
        }
        writeln!(csv, ",{}", error.replace([',', '\n'], " ")).ok();
        if !error.is_empty() {
            failed.push(k);
        }
    }
    write_atomic(&dir, "sweep.csv", csv.as_bytes())
        .map_err(|e| Failure::Other(format!("{}: {e}", dir.display())))?;
    println!(
        "sweep: {} runs ({} at a time), {} failed; table in {}",
        points.len(),
        jobs,
        failed.len(),
        dir.join("sweep.csv").display()
    );
    if failed.is_empty() {
        Ok(())
    } else {
        Err(Failure::Solver(format!(
            "sweep: runs {} failed (see the error column of {})",
            failed
                .iter()
                .map(|k| k.to_string())
                .collect::<Vec<_>>()
                .join(", "),
            dir.join("sweep.csv").display()
        )))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sets_parse_with_arrays_and_words() {
        let a = parse_set("analysis.time_step=1e-4,5e-5").unwrap();
        assert_eq!(a.key, "analysis.time_step");
        assert_eq!(
            a.values,
            vec![toml::Value::Float(1e-4), toml::Value::Float(5e-5)]
        );
        let a = parse_set("loads.0.acceleration=[0,-9.81,0],[0,-1.62,0]").unwrap();
        assert_eq!(a.values.len(), 2);
        assert!(matches!(&a.values[0], toml::Value::Array(v) if v.len() == 3));
        let a = parse_set("analysis.solver=newton,broyden").unwrap();
        assert_eq!(a.values[1], toml::Value::String("broyden".into()));
        assert!(parse_set("analysis.time_step").is_err());
        assert!(parse_set("a..b=1").is_err());
    }

    #[test]
    fn apply_reaches_tables_and_list_entries() {
        let mut doc: toml::Table =
            "[analysis]\ntime_step = 1.0\n[[loads]]\ntype = \"gravity\"\n[[loads]]\ntype = \"air-drag\"\ndrag_coefficient = 1.0\n"
                .parse()
                .unwrap();
        apply(&mut doc, "analysis.time_step", toml::Value::Float(0.5)).unwrap();
        apply(&mut doc, "analysis.tolerance", toml::Value::Float(1e-9)).unwrap();
        apply(
            &mut doc,
            "loads.1.drag_coefficient",
            toml::Value::Float(1.5),
        )
        .unwrap();
        assert_eq!(doc["analysis"]["time_step"].as_float(), Some(0.5));
        assert_eq!(doc["analysis"]["tolerance"].as_float(), Some(1e-9));
        assert_eq!(doc["loads"][1]["drag_coefficient"].as_float(), Some(1.5));
        assert!(apply(
            &mut doc,
            "loads.2.drag_coefficient",
            toml::Value::Float(1.0)
        )
        .unwrap_err()
        .contains("no index 2"));
        assert!(apply(&mut doc, "analysis.time_step.x", toml::Value::Float(1.0)).is_err());
    }

    #[test]
    fn grid_is_the_cartesian_product() {
        let axes = [parse_set("a=1,2").unwrap(), parse_set("b=3,4,5").unwrap()];
        let g = grid(&axes);
        assert_eq!(g.len(), 6);
        assert_eq!(g[0], vec![toml::Value::Integer(1), toml::Value::Integer(3)]);
        assert_eq!(g[5], vec![toml::Value::Integer(2), toml::Value::Integer(5)]);
    }
}
