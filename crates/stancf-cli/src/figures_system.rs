//! The figures of a system's results (`stancf plot`, `run --plot`): every
//! line's shape at a few written times in one frame, the energies, the
//! tension at every line end over time, and the curvature along every
//! line (its envelope over the run and its first written state).

use crate::figures::{
    centre_line, element_lengths_of, energy_figure, plane_of_motion, read_nodes, RunInfo, AXES,
};
use crate::plot::{sequential, Lines, Series, PALETTE};
use crate::results::{spread, Table};
use std::io;
use std::path::Path;

/// One line's id, element lengths and written shapes.
struct LineShapes {
    id: i64,
    element_lengths: Option<Vec<f64>>,
    steps: Vec<(f64, Vec<crate::figures::NodeRow>)>,
}

fn bad(path: &Path, what: &str) -> io::Error {
    io::Error::new(
        io::ErrorKind::InvalidData,
        format!("{}: {what}", path.display()),
    )
}

/// Whether `dir` holds a system's results (summary.json's `system`).
pub(crate) fn is_system(dir: &Path) -> io::Result<bool> {
    let path = dir.join("summary.json");
    let text = crate::input_file::read_result_text(&path)?;
    let s: serde_json::Value =
        serde_json::from_str(&text).map_err(|e| bad(&path, &e.to_string()))?;
    Ok(s["system"].as_bool() == Some(true))
}

/// The tables the figures of a system are drawn from that `dir` lacks (a
/// run whose `[output] files` left them out), named as in the folder.
fn missing_tables(dir: &Path) -> io::Result<Vec<String>> {
    let path = dir.join("summary.json");
    let text = crate::input_file::read_result_text(&path)?;
    let s: serde_json::Value =
        serde_json::from_str(&text).map_err(|e| bad(&path, &e.to_string()))?;
    let mut needed = vec!["tensions.csv".to_string(), "history.csv".to_string()];
    for l in s["lines"].as_array().into_iter().flatten() {
        for table in ["nodes.csv", "node_loads.csv"] {
            needed.push(format!("lines/{}/{table}", l["id"]));
        }
    }
    Ok(needed
        .into_iter()
        .filter(|n| !dir.join(n).exists())
        .collect())
}

/// The lines listed in summary.json with their written shapes.
fn read_lines(dir: &Path) -> io::Result<Vec<LineShapes>> {
    let path = dir.join("summary.json");
    let text = crate::input_file::read_result_text(&path)?;
    let s: serde_json::Value =
        serde_json::from_str(&text).map_err(|e| bad(&path, &e.to_string()))?;
    let lines = s["lines"]
        .as_array()
        .ok_or_else(|| bad(&path, "no lines"))?;
    lines
        .iter()
        .map(|l| {
            let id = l["id"]
                .as_i64()
                .ok_or_else(|| bad(&path, "a line without an id"))?;
            let element_lengths = element_lengths_of(l);
            let steps = read_nodes(&dir.join("lines").join(id.to_string()))?;
            Ok(LineShapes {
                id,
                element_lengths,
                steps,
            })
        })
        .collect()
}

/// Every line at `count` written times spread over the run, in the plane
/// the system moves in most (colour: time; all lines of a time share it).
fn shapes_figure(lines: &[LineShapes], info: &RunInfo, count: usize) -> Lines {
    let all = lines
        .iter()
        .flat_map(|l| l.steps.iter().flat_map(|(_, n)| n.iter().map(|r| r.r)));
    let (a, b) = plane_of_motion(all);
    let mut fig = Lines::new(
        format!("{}: shapes", info.title),
        format!("{} (m)", AXES[a]),
        format!("{} (m)", AXES[b]),
    );
    fig.equal_axes = true;
    let steps = lines.first().map_or(0, |l| l.steps.len());
    let picks = spread(steps, count);
    for (k, &i) in picks.iter().enumerate() {
        for l in lines {
            let Some((t, nodes)) = l.steps.get(i) else {
                continue;
            };
            let curve = centre_line(nodes, l.element_lengths.as_deref(), 12);
            fig.series.push(Series::line(
                format!("line {}, t = {}", l.id, crate::plot::tick(*t)),
                curve.iter().map(|p| (p[a], p[b])).collect(),
                sequential(k, picks.len()),
            ));
        }
    }
    fig
}

/// The tension at every line end against time, from tensions.csv.
fn tensions_figure(dir: &Path, info: &RunInfo) -> io::Result<Lines> {
    let path = dir.join("tensions.csv");
    let text = crate::input_file::read_result_text(&path)?;
    let mut series: Vec<(String, Vec<(f64, f64)>)> = Vec::new();
    for (n, row) in text.lines().enumerate().skip(1) {
        let f: Vec<&str> = row.split(',').collect();
        let (Some(t), Some(line), Some(end), Some(tension)) =
            (f.first(), f.get(1), f.get(2), f.get(6))
        else {
            return Err(bad(&path, &format!("line {}: too few columns", n + 1)));
        };
        let num = |s: &str| -> io::Result<f64> {
            s.parse()
                .map_err(|_| bad(&path, &format!("line {}: {s:?} is not a number", n + 1)))
        };
        let label = format!("line {line} end {end}");
        let point = (num(t)?, num(tension)?);
        match series.iter_mut().find(|(l, _)| *l == label) {
            Some((_, points)) => points.push(point),
            None => series.push((label, vec![point])),
        }
    }
    let mut fig = Lines::new(
        format!("{}: end tensions", info.title),
        if info.dynamic { "t (s)" } else { "load" },
        "tension (N)",
    );
    for (k, (label, points)) in series.into_iter().enumerate() {
        let mut s = Series::line(label, points, PALETTE[k % PALETTE.len()]);
        if info.dynamic {
            s = s.with_markers();
        }
        fig.series.push(s);
    }
    Ok(fig)
}

/// The curvature along every line from `lines/<id>/node_loads.csv`:
/// its largest value at each node over the written times (the envelope
/// users hold against a minimum bend radius, 1 / kappa) and its value at
/// the first written time, against the material coordinate.
fn curvature_figure(dir: &Path, lines: &[LineShapes], info: &RunInfo) -> io::Result<Lines> {
    let mut fig = Lines::new(
        format!("{}: curvature along the lines", info.title),
        "s (m)",
        "curvature (1/m)",
    );
    for (k, l) in lines.iter().enumerate() {
        let file = format!("lines/{}/node_loads.csv", l.id);
        let table = Table::read(&dir.join(&file))?;
        let (cn, cs, ck) = (
            table.need("node", &file)?,
            table.need("s", &file)?,
            table.need("curvature", &file)?,
        );
        let mut envelope: Vec<(f64, f64)> = Vec::new();
        let mut first: Vec<(f64, f64)> = Vec::new();
        for row in &table.rows {
            let node = row[cn] as usize;
            if node >= envelope.len() {
                envelope.push((row[cs], row[ck]));
                first.push((row[cs], row[ck]));
            } else {
                envelope[node].1 = envelope[node].1.max(row[ck]);
            }
        }
        let colour = PALETTE[k % PALETTE.len()];
        fig.series
            .push(Series::line(format!("line {}, largest", l.id), envelope, colour).with_markers());
        if info.dynamic {
            fig.series
                .push(Series::line(format!("line {}, first", l.id), first, colour));
        }
    }
    Ok(fig)
}

/// The figures of a system's results in `dir`; their names.
pub fn plot_system(dir: &Path, info: &RunInfo) -> io::Result<Vec<String>> {
    let missing = missing_tables(dir)?;
    if !missing.is_empty() {
        return Err(bad(
            dir,
            &format!(
                "the figures are drawn from tables this run did not write (output.files): {}",
                missing.join(", ")
            ),
        ));
    }
    let lines = read_lines(dir)?;
    let shapes = shapes_figure(&lines, info, 4);
    crate::plot::save(&shapes, dir, "shapes")?;
    let history = Table::read(&dir.join("history.csv"))?;
    let energy = energy_figure(&history, info)?;
    crate::plot::save(&energy, dir, "energy")?;
    let tensions = tensions_figure(dir, info)?;
    crate::plot::save(&tensions, dir, "tensions")?;
    let curvature = curvature_figure(dir, &lines, info)?;
    crate::plot::save(&curvature, dir, "curvature")?;
    Ok(vec![
        "shapes".into(),
        "energy".into(),
        "tensions".into(),
        "curvature".into(),
    ])
}
