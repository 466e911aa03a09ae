//! The figures of a sweep's row, read from its run's summary.json
//! (docs/interface.md, "stancf sweep"): a single cable's [`FIGURES`]; a
//! system's [`SYSTEM_FIGURES`] and its design statistics, one column per
//! line end, line type, point and body (`tension_max_line1_A`,
//! `safety_factor_chain`, `offset_max_point4`, ...).

use serde_json::Value;

/// The summary figures of a single cable's row, in order, with their paths
/// in summary.json (list entries by index).
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

/// The summary figures of a system's row before its statistics.
pub const SYSTEM_FIGURES: [(&str, &[&str]); 4] = [
    ("steps", &["steps"]),
    ("time", &["t_final"]),
    ("wall_time_s", &["wall_time_s"]),
    ("iterations", &["iterations"]),
];

/// The statistics of a line end in a row, with their names in
/// summary.json's `statistics.line_ends` entries.
const END_STATISTICS: [(&str, &str); 5] = [
    ("tension_max", "max"),
    ("tension_max_time", "time_of_max"),
    ("tension_min", "min"),
    ("tension_mean", "mean"),
    ("tension_std", "std"),
];

/// The prefixes of the columns that are a run's largest value (a seed's
/// maximum, which extremes.csv reduces over the seeds).
pub const MAXIMA: [&str; 2] = ["tension_max_line", "offset_max_"];

/// The number at `path` of `summary` (None: absent or not a number).
fn at(summary: &Value, path: &[&str]) -> Option<f64> {
    let mut v = summary;
    for p in path {
        v = match p.parse::<usize>() {
            Ok(i) => v.get(i)?,
            Err(_) => v.get(*p)?,
        };
    }
    v.as_f64()
}

/// Whether summary.json is a system's.
fn is_system(summary: &Value) -> bool {
    summary.get("system").and_then(Value::as_bool) == Some(true)
}

/// The figures of one run's row: (column, value) in the table's order; a
/// figure the summary lacks is None (an empty cell). A system's design
/// statistics add a column per line end, line type with a breaking load,
/// and free or coupled point and body (docs/interface.md, "Design
/// statistics").
pub fn figures(summary: &Value) -> Vec<(String, Option<f64>)> {
    if !is_system(summary) {
        return (FIGURES.iter())
            .map(|(name, path)| (name.to_string(), at(summary, path)))
            .collect();
    }
    let mut out: Vec<(String, Option<f64>)> = (SYSTEM_FIGURES.iter())
        .map(|(name, path)| (name.to_string(), at(summary, path)))
        .collect();
    let Some(stats) = summary.get("statistics") else {
        return out;
    };
    let list = |name: &str| {
        stats
            .get(name)
            .and_then(Value::as_array)
            .cloned()
            .unwrap_or_default()
    };
    let id = |v: &Value, key: &str| match v.get(key) {
        Some(Value::String(s)) => s.clone(),
        Some(other) => other.to_string(),
        None => String::new(),
    };
    for e in list("line_ends") {
        let end = format!("line{}_{}", id(&e, "line"), id(&e, "end"));
        for (column, key) in END_STATISTICS {
            out.push((format!("{column}_{end}"), at(&e, &[key])));
        }
    }
    for t in list("line_types") {
        out.push((
            format!("safety_factor_{}", id(&t, "type")),
            at(&t, &["safety_factor"]),
        ));
    }
    for (kind, list) in [("point", list("points")), ("body", list("bodies"))] {
        for p in list {
            out.push((
                format!("offset_max_{kind}{}", id(&p, "id")),
                at(&p, &["max_offset"]),
            ));
        }
    }
    out
}

/// The columns of a table of rows with these figures: the names in the
/// order they first appear (a run that failed early lacks some; runs of
/// different scenario files may have different lines).
pub fn columns<'a>(rows: impl IntoIterator<Item = &'a [(String, Option<f64>)]>) -> Vec<String> {
    let mut names: Vec<String> = Vec::new();
    for row in rows {
        for (name, _) in row {
            if !names.contains(name) {
                names.push(name.clone());
            }
        }
    }
    names
}

/// The value of column `name` in a row's figures.
pub fn value(row: &[(String, Option<f64>)], name: &str) -> Option<f64> {
    row.iter().find(|(n, _)| n == name).and_then(|(_, v)| *v)
}
