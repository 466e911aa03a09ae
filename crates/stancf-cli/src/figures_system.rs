//! The figures of a system's results (`stancf plot`, `run --plot`): every
//! line's shape at a few written times in one frame, the energies, the
//! tension at every line end over time, and the curvature along every
//! line (its envelope over the run and its first written state).

use crate::figure_data::{
    centre_line, element_lengths_of, plane_of_motion, read_nodes, NodeRow, RunInfo, AXES,
};
use crate::figures_energy::energy_figure;
use crate::plot::{Bars, Lines, Series, PALETTE};
use crate::results::{spread, Table};
use plotters::style::RGBColor;
use std::io;
use std::path::Path;

/// One line's id, element lengths and written shapes.
struct LineShapes {
    id: i64,
    element_lengths: Option<Vec<f64>>,
    steps: Vec<(f64, Vec<NodeRow>)>,
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

/// `colour` blended toward white by `f` in [0, 1] (0: the colour).
pub(crate) fn lighten(colour: RGBColor, f: f64) -> RGBColor {
    let m = |c: u8| (c as f64 + (255.0 - c as f64) * f.clamp(0.0, 1.0)).round() as u8;
    RGBColor(m(colour.0), m(colour.1), m(colour.2))
}

/// The written times a figure shows, as a sentence part: "t = 0, 13.35,
/// 40 s" (dynamic) or "load factor 1" (static).
fn times_text(times: &[f64], dynamic: bool) -> String {
    let list: Vec<String> = times.iter().map(|t| crate::plot::tick(*t)).collect();
    if dynamic {
        format!("t = {} s", list.join(", "))
    } else {
        format!("load factor {}", list.join(", "))
    }
}

/// Every line at `count` written times spread over the run, in the plane
/// the system moves in most: each line its own colour (the legend names
/// the lines by id), its earlier shapes lighter, the latest in full colour;
/// the title lists the times.
fn shapes_figure(lines: &[LineShapes], info: &RunInfo, count: usize) -> Lines {
    let all = lines
        .iter()
        .flat_map(|l| l.steps.iter().flat_map(|(_, n)| n.iter().map(|r| r.r)));
    let (a, b) = plane_of_motion(all);
    let steps = lines.first().map_or(0, |l| l.steps.len());
    let picks = spread(steps, count);
    let times: Vec<f64> = picks
        .iter()
        .filter_map(|&i| lines.first().and_then(|l| l.steps.get(i)).map(|s| s.0))
        .collect();
    let title = if picks.len() > 1 {
        format!(
            "{}: shapes at {} (lighter: earlier)",
            info.title,
            times_text(&times, info.dynamic)
        )
    } else {
        format!(
            "{}: shapes at {}",
            info.title,
            times_text(&times, info.dynamic)
        )
    };
    let mut fig = Lines::new(
        title,
        format!("{} (m)", AXES[a]),
        format!("{} (m)", AXES[b]),
    );
    fig.equal_axes = true;
    for (k, &i) in picks.iter().enumerate() {
        let age = if picks.len() > 1 {
            0.7 * (picks.len() - 1 - k) as f64 / (picks.len() - 1) as f64
        } else {
            0.0
        };
        for (j, l) in lines.iter().enumerate() {
            let Some((_, nodes)) = l.steps.get(i) else {
                continue;
            };
            let curve = centre_line(nodes, l.element_lengths.as_deref(), 12);
            // One legend entry per line, on its latest shape.
            let label = if k + 1 == picks.len() {
                format!("line {}", l.id)
            } else {
                String::new()
            };
            fig.series.push(Series::line(
                label,
                curve.iter().map(|p| (p[a], p[b])).collect(),
                lighten(PALETTE[j % PALETTE.len()], age),
            ));
        }
    }
    fig
}

/// A named series of (x, y) points.
type Named = (String, Vec<(f64, f64)>);

/// The tension of every line end at every written time, from
/// tensions.csv: (label, points) in the order of the file.
fn read_tensions(dir: &Path) -> io::Result<Vec<Named>> {
    let path = dir.join("tensions.csv");
    let text = crate::input_file::read_result_text(&path)?;
    let mut series: Vec<Named> = Vec::new();
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
    Ok(series)
}

/// Whether two series of the same times lie within 0.5 % of the figure's
/// tension range of each other at every time (ends joined at a free point
/// carry the same tension): drawn alike, one would hide the other.
fn coincide(a: &[(f64, f64)], b: &[(f64, f64)], range: f64) -> bool {
    a.len() == b.len()
        && a.iter()
            .zip(b)
            .all(|(p, q)| p.0 == q.0 && (p.1 - q.1).abs() <= 5e-3 * range)
}

/// The figure of the end tensions: curves against time, or bars when the
/// run wrote one state (a static system).
pub enum TensionFigure {
    Curves(Lines),
    Bars(Bars),
}

/// The tension at every line end against time, from tensions.csv. Every
/// series stays visible: one that coincides with an earlier one (the two
/// ends joined at a free point) is drawn dashed over it and its label says
/// so; markers only where they do not merge into a band. A run with one
/// written state (a static system) gets bars, one per line end.
fn tensions_figure(dir: &Path, info: &RunInfo) -> io::Result<TensionFigure> {
    let series = read_tensions(dir)?;
    if series.iter().all(|(_, p)| p.len() == 1) {
        let at = series.first().map_or(0.0, |s| s.1[0].0);
        return Ok(TensionFigure::Bars(Bars {
            title: format!(
                "{}: end tensions at {}",
                info.title,
                times_text(&[at], info.dynamic)
            ),
            y_label: "tension (N)".into(),
            categories: series.iter().map(|(l, _)| l.clone()).collect(),
            series: vec![(
                "tension".into(),
                series.iter().map(|(_, p)| p[0].1).collect(),
            )],
        }));
    }
    let (lo, hi) = series
        .iter()
        .flat_map(|(_, p)| p.iter().map(|q| q.1))
        .fold((f64::MAX, f64::MIN), |(a, b), v| (a.min(v), b.max(v)));
    let range = (hi - lo).max(f64::MIN_POSITIVE);
    let mut fig = Lines::new(
        format!("{}: end tensions", info.title),
        if info.dynamic { "t (s)" } else { "load factor" },
        "tension (N)",
    );
    for (k, (label, points)) in series.iter().enumerate() {
        let twin = series[..k]
            .iter()
            .find(|(_, p)| coincide(p, points, range))
            .map(|(l, _)| l.clone());
        let few = points.len() <= 60;
        let mut s = Series::line(label.clone(), points.clone(), PALETTE[k % PALETTE.len()]);
        if let Some(twin) = twin {
            s.label = format!("{label} (dashed: same as {twin})");
            s = s.dashed();
        } else {
            s.width = 3;
            if few && info.dynamic {
                s = s.with_markers();
            }
        }
        fig.series.push(s);
    }
    Ok(TensionFigure::Curves(fig))
}

/// The curvature along every line from `lines/<id>/node_loads.csv`,
/// against the material coordinate: its largest value at each node over
/// the written times (markers; the envelope users hold against a minimum
/// bend radius, 1 / kappa) and, in a dynamic run, its value at the first
/// written time (the start, a thin line), both named so in the legend.
fn curvature_figure(dir: &Path, lines: &[LineShapes], info: &RunInfo) -> io::Result<Lines> {
    let mut fig = Lines::new(
        format!("{}: curvature along the lines", info.title),
        "s (m)",
        "curvature (1/m)",
    );
    let mut span = (f64::MAX, f64::MIN);
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
            span = (span.0.min(row[0]), span.1.max(row[0]));
            let node = row[cn] as usize;
            if node >= envelope.len() {
                envelope.push((row[cs], row[ck]));
                first.push((row[cs], row[ck]));
            } else {
                envelope[node].1 = envelope[node].1.max(row[ck]);
            }
        }
        let colour = PALETTE[k % PALETTE.len()];
        if info.dynamic {
            fig.series.push(
                Series::line(
                    format!("line {}, largest over the run", l.id),
                    envelope,
                    colour,
                )
                .with_markers(),
            );
            let start = crate::plot::tick(span.0);
            fig.series.push(Series::line(
                format!("line {}, at the start (t = {start} s)", l.id),
                first,
                colour,
            ));
        } else {
            fig.series
                .push(Series::line(format!("line {}", l.id), envelope, colour).with_markers());
        }
    }
    if info.dynamic && span.0 <= span.1 {
        fig.title = format!(
            "{}: curvature, largest over t = {} to {} s (markers) and at the start (lines)",
            info.title,
            crate::plot::tick(span.0),
            crate::plot::tick(span.1)
        );
    } else if span.0 <= span.1 {
        fig.title = format!(
            "{}: curvature along the lines at {}",
            info.title,
            times_text(&[span.1], false)
        );
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
    let energy = energy_figure(&history, info, true)?;
    crate::plot::save(&energy, dir, "energy")?;
    match tensions_figure(dir, info)? {
        TensionFigure::Curves(fig) => crate::plot::save(&fig, dir, "tensions")?,
        TensionFigure::Bars(fig) => crate::plot::save(&fig, dir, "tensions")?,
    }
    let curvature = curvature_figure(dir, &lines, info)?;
    crate::plot::save(&curvature, dir, "curvature")?;
    let mut drawn = vec![
        "shapes".into(),
        "energy".into(),
        "tensions".into(),
        "curvature".into(),
    ];
    if let Some(bodies) = crate::figures_bodies::bodies_figure(dir, info)? {
        crate::plot::save(&bodies, dir, "bodies")?;
        drawn.push("bodies".into());
    }
    Ok(drawn)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn info(dynamic: bool) -> RunInfo {
        RunInfo {
            title: "sys".into(),
            dynamic,
            element_lengths: None,
        }
    }

    fn scratch(name: &str) -> std::path::PathBuf {
        let d = std::env::temp_dir().join(format!("stancf-figsys-{name}-{}", std::process::id()));
        std::fs::create_dir_all(&d).unwrap();
        d
    }

    /// Three lines at four times: each line its own hue (the same at every
    /// time, lighter when earlier), one legend entry per line naming it by
    /// id, and the times in the title.
    #[test]
    fn each_line_gets_its_own_colour_and_a_legend_entry_by_id() {
        let line = |id: i64, x0: f64| LineShapes {
            id,
            element_lengths: None,
            steps: (0..4)
                .map(|k| {
                    let z = -(k as f64);
                    let nodes = (0..3)
                        .map(|i| NodeRow {
                            r: [x0 + i as f64, 0.0, z - i as f64],
                            slope: None,
                        })
                        .collect();
                    (10.0 * k as f64, nodes)
                })
                .collect(),
        };
        let lines = [line(1, 0.0), line(2, 2.0), line(3, 4.0)];
        let fig = shapes_figure(&lines, &info(true), 4);
        assert_eq!(fig.series.len(), 12);
        let labels: Vec<&str> = fig
            .series
            .iter()
            .map(|s| s.label.as_str())
            .filter(|l| !l.is_empty())
            .collect();
        assert_eq!(labels, ["line 1", "line 2", "line 3"]);
        assert!(fig.title.contains("t = 0, 10, 20, 30 s"), "{}", fig.title);
        // The latest shapes in the palette's first three colours, all
        // different; every earlier shape lighter than the line's latest.
        let latest: Vec<RGBColor> = fig.series[9..].iter().map(|s| s.color).collect();
        assert_eq!(latest, [PALETTE[0], PALETTE[1], PALETTE[2]]);
        for (k, s) in fig.series[..9].iter().enumerate() {
            let own = PALETTE[k % 3];
            assert_ne!(s.color, own);
            assert!(s.color.0 >= own.0 && s.color.1 >= own.1 && s.color.2 >= own.2);
        }
    }

    /// Every series of tensions.csv is in the legend; the end of a line
    /// that carries the tension of an earlier one (two ends joined at a
    /// free point) is dashed over it and says so; one written state gives
    /// bars, one per line end.
    #[test]
    fn every_tension_series_is_named_and_coinciding_ones_are_dashed() {
        let d = scratch("tensions");
        let mut csv = String::from("t,line,end,fx,fy,fz,tension\n");
        for k in 0..5 {
            let t = k as f64 * 0.1;
            let f = [100.0 + k as f64, 50.0, 50.0 + 1e-4, 80.0 - k as f64];
            for (i, (line, end)) in [(1, "A"), (1, "B"), (2, "A"), (2, "B")].iter().enumerate() {
                csv.push_str(&format!("{t},{line},{end},0,0,0,{}\n", f[i]));
            }
        }
        std::fs::write(d.join("tensions.csv"), csv).unwrap();
        let TensionFigure::Curves(fig) = tensions_figure(&d, &info(true)).unwrap() else {
            panic!("curves expected")
        };
        let labels: Vec<&str> = fig.series.iter().map(|s| s.label.as_str()).collect();
        assert_eq!(
            labels,
            [
                "line 1 end A",
                "line 1 end B",
                "line 2 end A (dashed: same as line 1 end B)",
                "line 2 end B"
            ]
        );
        let dashed: Vec<bool> = fig.series.iter().map(|s| s.dashed).collect();
        assert_eq!(dashed, [false, false, true, false]);
        let mut colours: Vec<RGBColor> = fig.series.iter().map(|s| s.color).collect();
        colours.dedup();
        assert_eq!(colours.len(), 4);
        std::fs::write(
            d.join("tensions.csv"),
            "t,line,end,fx,fy,fz,tension\n1,1,A,0,0,0,5\n1,1,B,0,0,0,6\n",
        )
        .unwrap();
        let TensionFigure::Bars(bars) = tensions_figure(&d, &info(false)).unwrap() else {
            panic!("bars expected")
        };
        assert_eq!(bars.categories, ["line 1 end A", "line 1 end B"]);
        assert_eq!(bars.series[0].1, [5.0, 6.0]);
        assert!(bars.title.ends_with("at load factor 1"), "{}", bars.title);
        std::fs::remove_dir_all(&d).unwrap();
    }

    /// The curvature figure names its two curves per line by what they
    /// are: the largest value over the run and the value at the start,
    /// with its time.
    #[test]
    fn the_curvature_legend_says_what_each_curve_is() {
        let d = scratch("curvature");
        std::fs::create_dir_all(d.join("lines/7")).unwrap();
        std::fs::write(
            d.join("lines/7/node_loads.csv"),
            "t,node,s,curvature\n0.5,0,0,0.1\n0.5,1,1,0.2\n1.5,0,0,0.3\n1.5,1,1,0.1\n",
        )
        .unwrap();
        let lines = [LineShapes {
            id: 7,
            element_lengths: None,
            steps: Vec::new(),
        }];
        let fig = curvature_figure(&d, &lines, &info(true)).unwrap();
        let labels: Vec<&str> = fig.series.iter().map(|s| s.label.as_str()).collect();
        assert_eq!(
            labels,
            [
                "line 7, largest over the run",
                "line 7, at the start (t = 0.5 s)"
            ]
        );
        assert_eq!(fig.series[0].points, [(0.0, 0.3), (1.0, 0.2)]);
        assert_eq!(fig.series[1].points, [(0.0, 0.1), (1.0, 0.2)]);
        assert!(
            fig.title.contains("largest over t = 0.5 to 1.5 s"),
            "{}",
            fig.title
        );
        std::fs::remove_dir_all(&d).unwrap();
    }
}
