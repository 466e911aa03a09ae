//! The figures of one run, drawn from its result files: cable shapes over
//! time (the paper's Figs. 3, 5a, 8, 10), energies against time (Fig. 5b),
//! the space-time map of axial stress (Fig. 4) and the residual against the
//! iteration (Fig. 7).

use crate::figure_data::{centre_line, plane_of_motion, read_nodes, NodeRow, RunInfo, AXES};
pub use crate::figures_energy::energy_figure;
use crate::figures_energy::range_of;
use crate::plot::{sequential, ColorMap, Lines, Series};
use crate::results::{by_time, spread, Table};
use crate::Failure;
use std::io;
use std::path::Path;

/// When the cable moves by less than 1 % of its size (an axial impact
/// moves it by micrometres along its own axis), the axis d (0, 1, 2) along
/// which its nodes move most from the first written state and the power of
/// ten that brings that displacement to between 5 % and 50 % of its size.
pub fn magnification(steps: &[(f64, Vec<NodeRow>)]) -> Option<(usize, f64)> {
    let first = &steps.first()?.1;
    let size = (0..3)
        .map(|c| range_of(&first.iter().map(|n| n.r[c]).collect::<Vec<_>>()))
        .fold(0.0, f64::max);
    let mut largest = [0.0f64; 3];
    for (_, nodes) in steps {
        for (n, r0) in nodes.iter().zip(first) {
            for c in 0..3 {
                largest[c] = largest[c].max((n.r[c] - r0.r[c]).abs());
            }
        }
    }
    let d = (0..3).max_by(|&i, &j| largest[i].total_cmp(&largest[j]))?;
    let u = largest[d];
    if !(u > 0.0 && size > 0.0 && u < 0.01 * size) {
        return None;
    }
    Some((d, 10f64.powf((0.5 * size / u).log10().floor())))
}

/// Shapes at up to `count` written times, in the plane of motion; a cable
/// that moves by less than 1 % of its size ([`magnification`]) gets its
/// displacement along the axis it moves most, magnified by a power of ten
/// that the axis label and the title state, against its position at the
/// first written time.
pub fn shapes_figure(
    steps: &[(f64, Vec<NodeRow>)],
    info: &RunInfo,
    count: usize,
    time_label: &str,
) -> Lines {
    let picks = spread(steps.len(), count);
    let label = |t: f64| format!("{time_label} = {}", crate::plot::tick(t));
    if let Some((d, k)) = magnification(steps) {
        let first = &steps[0].1;
        let (a, _) = plane_of_motion(first.iter().map(|n| n.r));
        let factor = crate::plot::tick(k);
        let mut fig = Lines::new(
            format!(
                "{}: shapes, displacement along {} magnified {factor} times",
                info.title, AXES[d]
            ),
            format!("{} at t = {} (m)", AXES[a], crate::plot::tick(steps[0].0)),
            format!("{} displacement x {factor} (m)", AXES[d]),
        );
        for (j, &i) in picks.iter().enumerate() {
            let (t, nodes) = &steps[i];
            let pts = nodes
                .iter()
                .zip(first)
                .map(|(n, r0)| (r0.r[a], k * (n.r[d] - r0.r[d])))
                .collect();
            fig.series
                .push(Series::line(label(*t), pts, sequential(j, picks.len())));
        }
        return fig;
    }
    let (a, b) = plane_of_motion(steps.iter().flat_map(|(_, n)| n.iter().map(|r| r.r)));
    let mut fig = Lines::new(
        format!("{}: shapes", info.title),
        format!("{} (m)", AXES[a]),
        format!("{} (m)", AXES[b]),
    );
    fig.equal_axes = true;
    for (k, &i) in picks.iter().enumerate() {
        let (t, nodes) = &steps[i];
        let line = centre_line(nodes, info.element_lengths.as_deref(), 12);
        fig.series.push(Series::line(
            label(*t),
            line.iter().map(|p| (p[a], p[b])).collect(),
            sequential(k, picks.len()),
        ));
    }
    fig
}

/// The space-time map of axial stress from `stress.csv` (columns: written
/// times, at most `max_columns` of them; rows: the sampled points, where
/// the two samples of an interior node are averaged).
pub fn stress_figure(stress: &Table, info: &RunInfo, max_columns: usize) -> io::Result<ColorMap> {
    let f = "stress.csv";
    let (cs, cv) = (stress.need("s", f)?, stress.need("axial_stress", f)?);
    let steps = by_time(stress);
    let picks = spread(steps.len(), max_columns);
    // Material points: the distinct s of the first step.
    let mut s_values: Vec<f64> = steps
        .first()
        .map(|(_, rows)| rows.iter().map(|r| r[cs]).collect())
        .unwrap_or_default();
    s_values.sort_by(|a, b| a.partial_cmp(b).expect("finite"));
    s_values.dedup();
    let y_edges = edges(&s_values);
    let times: Vec<f64> = picks.iter().map(|&i| steps[i].0).collect();
    let x_edges = edges(&times);
    let values = picks
        .iter()
        .map(|&i| {
            let mut sum = vec![0.0; s_values.len()];
            let mut n = vec![0usize; s_values.len()];
            for r in &steps[i].1 {
                if let Ok(j) = s_values.binary_search_by(|v| v.partial_cmp(&r[cs]).expect("finite"))
                {
                    sum[j] += r[cv];
                    n[j] += 1;
                }
            }
            sum.iter()
                .zip(n.iter())
                .map(|(s, &k)| if k > 0 { s / k as f64 * 1e-6 } else { f64::NAN })
                .collect()
        })
        .collect();
    Ok(ColorMap {
        title: format!("{}: axial stress", info.title),
        x_label: if info.dynamic { "t (s)" } else { "load factor" }.into(),
        y_label: "material coordinate s (m)".into(),
        value_label: "axial stress E eps (MPa)".into(),
        x_edges,
        y_edges,
        values,
        diverging: true,
        clip_quantile: Some(0.99),
    })
}

/// Cell edges around sorted centres: midpoints, and half a gap beyond
/// the ends.
pub fn edges(centres: &[f64]) -> Vec<f64> {
    match centres.len() {
        0 => vec![0.0, 1.0],
        1 => vec![centres[0] - 0.5, centres[0] + 0.5],
        n => {
            let mut e = Vec::with_capacity(n + 1);
            e.push(centres[0] - 0.5 * (centres[1] - centres[0]));
            for w in centres.windows(2) {
                e.push(0.5 * (w[0] + w[1]));
            }
            e.push(centres[n - 1] + 0.5 * (centres[n - 1] - centres[n - 2]));
            e
        }
    }
}

/// The scaled residual of every evaluation of up to `count` steps spread
/// over the run, from `convergence.csv`.
pub fn convergence_figure(conv: &Table, info: &RunInfo, count: usize) -> io::Result<Lines> {
    let f = "convergence.csv";
    let (cstep, ceval, cres) = (
        conv.need("step", f)?,
        conv.need("evaluation", f)?,
        conv.need("residual", f)?,
    );
    // (step, t, (evaluation, residual) of each evaluation)
    type StepResiduals = (f64, f64, Vec<(f64, f64)>);
    let mut steps: Vec<StepResiduals> = Vec::new();
    for row in &conv.rows {
        match steps.last_mut() {
            Some((step, _, pts)) if *step == row[cstep] => pts.push((row[ceval], row[cres])),
            _ => steps.push((row[cstep], row[0], vec![(row[ceval], row[cres])])),
        }
    }
    let mut fig = Lines::new(
        format!("{}: residuals", info.title),
        "evaluation",
        "scaled residual",
    );
    fig.log_y = true;
    fig.integer_x = true;
    let picks = spread(steps.len(), count);
    for (k, &i) in picks.iter().enumerate() {
        let (step, t, pts) = &steps[i];
        // Exact zeros cannot be drawn on a log axis: shown at 1e-18.
        let pts = pts.iter().map(|&(x, y)| (x, y.max(1e-18))).collect();
        fig.series.push(
            Series::line(
                format!("step {} (t = {})", *step as usize, crate::plot::tick(*t)),
                pts,
                sequential(k, picks.len()),
            )
            .with_markers(),
        );
    }
    Ok(fig)
}

/// Writes the figures of the run whose results are in `dir` next to them;
/// returns their names (without extension).
pub fn plot_results(dir: &Path) -> io::Result<Vec<String>> {
    let info = RunInfo::read(dir)?;
    if crate::figures_system::is_system(dir)? {
        return crate::figures_system::plot_system(dir, &info);
    }
    let mut written = Vec::new();
    let mut put = |fig: &dyn Fn(&Path, &str) -> io::Result<()>, name: &str| -> io::Result<()> {
        fig(dir, name)?;
        written.push(name.to_string());
        Ok(())
    };
    let steps = read_nodes(dir)?;
    let time_label = if info.dynamic { "t" } else { "load" };
    let shapes = shapes_figure(&steps, &info, 9, time_label);
    put(&|d, n| crate::plot::save(&shapes, d, n), "shapes")?;
    let history = Table::read(&dir.join("history.csv"))?;
    let energy = energy_figure(&history, &info, false)?;
    put(&|d, n| crate::plot::save(&energy, d, n), "energy")?;
    let stress = Table::read(&dir.join("stress.csv"))?;
    let map = stress_figure(&stress, &info, 400)?;
    put(&|d, n| crate::plot::save(&map, d, n), "stress_map")?;
    if dir.join("convergence.csv").exists() {
        let conv = Table::read(&dir.join("convergence.csv"))?;
        let fig = convergence_figure(&conv, &info, 8)?;
        put(&|d, n| crate::plot::save(&fig, d, n), "convergence")?;
    }
    Ok(written)
}

/// `stancf plot DIR`: the figures of the results already in DIR.
pub fn plot(dir: &Path) -> Result<(), Failure> {
    if !dir.join("summary.json").exists() {
        return Err(Failure::Input(format!(
            "{}: no summary.json here: not a folder of stancf results",
            dir.display()
        )));
    }
    let names = plot_results(dir).map_err(|e| Failure::Input(e.to_string()))?;
    println!(
        "figures: {} (PNG and SVG) in {}",
        names.join(", "),
        dir.display()
    );
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::figure_data::element_lengths_of;

    #[test]
    fn hermite_centre_line_passes_through_the_nodes_and_bends_with_the_slopes() {
        // A quarter circle of radius 1 in one element: r(0) = (1, 0),
        // r(l) = (0, 1), unit tangents, l = pi / 2.
        let l = std::f64::consts::FRAC_PI_2;
        let nodes = [
            NodeRow {
                r: [1.0, 0.0, 0.0],
                slope: Some([0.0, 1.0, 0.0]),
            },
            NodeRow {
                r: [0.0, 1.0, 0.0],
                slope: Some([-1.0, 0.0, 0.0]),
            },
        ];
        let line = centre_line(&nodes, Some(&[l]), 8);
        assert_eq!(line.len(), 9);
        assert_eq!(line[0], [1.0, 0.0, 0.0]);
        assert_eq!(line[8], [0.0, 1.0, 0.0]);
        // A cubic Hermite with arc-length tangents (|r_x| = 1, as SAC-2
        // nodes carry them) stays inside the circle, 1.52 % short of the
        // radius at mid-element (computed from the basis: 0.98479).
        for p in &line[1..8] {
            let r = (p[0] * p[0] + p[1] * p[1]).sqrt();
            assert!(r < 1.0 && r > 0.9847, "{r}");
        }
    }

    /// A graded mesh's summary gives each element its own length, the
    /// library's (docs/method.md §1.6), so the Hermite curve of a straight
    /// graded line through its nodes stays on the line and moves forward;
    /// a grading that cannot be read gives no lengths (straight segments).
    #[test]
    fn a_graded_summary_gives_each_element_its_own_length() {
        let s = serde_json::json!({
            "length": 10.0, "elements": 5, "grading": {"toward": "B", "ratio": 4.0}
        });
        let g = stancf::Grading::Geometric {
            toward: stancf::GradedEnd::B,
            ratio: 4.0,
        };
        let lengths = element_lengths_of(&s).expect("lengths");
        assert_eq!(lengths, g.element_lengths(10.0, 5));
        let nodes: Vec<NodeRow> = g
            .node_coordinates(10.0, 5)
            .iter()
            .map(|&x| NodeRow {
                r: [x, 0.0, 0.0],
                slope: Some([1.0, 0.0, 0.0]),
            })
            .collect();
        let line = centre_line(&nodes, Some(&lengths), 8);
        for w in line.windows(2) {
            assert!(w[1][0] > w[0][0] && w[1][1] == 0.0, "{w:?}");
        }
        let bad = serde_json::json!({
            "length": 10.0, "elements": 5, "grading": {"toward": "C", "ratio": 4.0}
        });
        assert_eq!(element_lengths_of(&bad), None);
    }

    /// The figures show the numbers of the files, not a recomputation.
    #[test]
    fn figures_take_their_data_from_the_result_files() {
        let dir = std::env::temp_dir().join(format!("stancf-fig-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let w = |name: &str, text: &str| std::fs::write(dir.join(name), text).unwrap();
        w(
            "summary.json",
            r#"{"title": "synthetic", "analysis": "dynamic", "length": 2.0, "elements": 2}"#,
        );
        w(
            "nodes.csv",
            "t,node,x,y,z,dx_ds,dy_ds,dz_ds\n\
             0,0,0,0,0,1,0,0\n0,1,1,0,0,1,0,0\n0,2,2,0,0,1,0,0\n\
             0.5,0,0,0,0,1,0,0\n0.5,1,0.9,-0.3,0,1,0,0\n0.5,2,1.7,-0.9,0,0.6,-0.8,0\n",
        );
        w(
            "history.csv",
            "t,kinetic,strain,gravity,total,iterations\n0,1.5,0,0,1.5,0\n0.5,1.25,0.25,0,1.5,2\n",
        );
        w(
            "stress.csv",
            "t,s,axial_stress,curvature,element\n0,0,1e6,0,0\n0,1,3e6,0,0\n0,1,5e6,0,1\n0,2,-2e6,0,1\n\
             0.5,0,0,0,0\n0.5,1,1e6,0,0\n0.5,1,1e6,0,1\n0.5,2,7e6,0,1\n",
        );
        let info = RunInfo::read(&dir).unwrap();
        assert_eq!(info.element_lengths, Some(vec![1.0, 1.0]));
        let steps = read_nodes(&dir).unwrap();
        let shapes = shapes_figure(&steps, &info, 9, "t");
        assert_eq!(shapes.series.len(), 2);
        let last = &shapes.series[1].points;
        // Through the nodes of the file: s = 0, l, 2 l.
        assert_eq!(last[0], (0.0, 0.0));
        assert_eq!(last[12], (0.9, -0.3));
        assert_eq!(*last.last().unwrap(), (1.7, -0.9));
        let history = Table::read(&dir.join("history.csv")).unwrap();
        let energy = energy_figure(&history, &info, false).unwrap();
        let labels =
            |p: &Lines| -> Vec<String> { p.series.iter().map(|s| s.label.clone()).collect() };
        assert_eq!(energy.panels.len(), 2);
        assert_eq!(
            labels(&energy.panels[0]),
            ["kinetic", "strain"],
            "zero gravity left out"
        );
        assert_eq!(
            energy.panels[0].series[0].points,
            vec![(0.0, 1.5), (0.5, 1.25)]
        );
        assert_eq!(
            energy.panels[0].series[1].points,
            vec![(0.0, 0.0), (0.5, 0.25)]
        );
        // The balance E - E(0) - W: no work columns, so E - E(0).
        assert_eq!(labels(&energy.panels[1]), ["W = 0: no work written"]);
        assert_eq!(
            energy.panels[1].series[0].points,
            vec![(0.0, 0.0), (0.5, 0.0)]
        );
        let stress = Table::read(&dir.join("stress.csv")).unwrap();
        let map = stress_figure(&stress, &info, 400).unwrap();
        // MPa; the two samples of the interior node averaged.
        assert_eq!(map.values, vec![vec![1.0, 4.0, -2.0], vec![0.0, 1.0, 7.0]]);
        assert_eq!(map.y_edges, vec![-0.5, 0.5, 1.5, 2.5]);
        assert_eq!(map.x_edges, vec![-0.25, 0.25, 0.75]);
        let written = plot_results(&dir).unwrap();
        assert_eq!(written, ["shapes", "energy", "stress_map"]);
        std::fs::remove_dir_all(&dir).unwrap();
    }

    /// A cable that moves by less than 1 % of its size (an axial impact)
    /// is drawn as its displacement along the axis it moves most,
    /// magnified by a power of ten the axis label states.
    #[test]
    fn a_small_displacement_is_magnified_and_the_factor_named() {
        let at = |u: f64| -> Vec<NodeRow> {
            (0..3)
                .map(|i| NodeRow {
                    r: [i as f64 + u * (i as f64 - 1.0), 0.0, 0.0],
                    slope: Some([1.0, 0.0, 0.0]),
                })
                .collect()
        };
        let steps = vec![(0.0, at(0.0)), (1.0, at(3e-4))];
        assert_eq!(magnification(&steps), Some((0, 1000.0)));
        let info = RunInfo {
            title: "axial".into(),
            dynamic: true,
            element_lengths: Some(vec![1.0, 1.0]),
        };
        let fig = shapes_figure(&steps, &info, 9, "t");
        assert_eq!(fig.y_label, "x displacement x 1000 (m)");
        assert!(fig.title.contains("magnified 1000 times"), "{}", fig.title);
        let last = &fig.series[1].points;
        for (p, want) in last.iter().zip([(0.0, -0.3), (1.0, 0.0), (2.0, 0.3)]) {
            assert!(
                (p.0 - want.0).abs() < 1e-12 && (p.1 - want.1).abs() < 1e-9,
                "{p:?}"
            );
        }
        // Moving by its own size: drawn as it is.
        let steps = vec![(0.0, at(0.0)), (1.0, at(0.5))];
        assert_eq!(magnification(&steps), None);
        assert!(shapes_figure(&steps, &info, 9, "t").equal_axes);
    }

    #[test]
    fn plane_of_motion_drops_the_still_axis() {
        let pts = [[0.0, 0.0, 0.3], [1.0, -2.0, 0.3], [0.5, 1.0, 0.3]];
        assert_eq!(plane_of_motion(pts.into_iter()), (0, 1));
        let pts = [[0.0, 0.0, 0.0], [0.0, 1.0, 2.0]];
        assert_eq!(plane_of_motion(pts.into_iter()), (1, 2));
    }
}
