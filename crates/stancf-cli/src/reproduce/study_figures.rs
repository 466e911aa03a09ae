//! The figures of the paper's studies, drawn from the CSV files each study
//! writes, with their captions for `REPORT.md` (report.rs).

use crate::figure_data::RunInfo;
use crate::figures::stress_figure;
use crate::plot::{save, sequential, Lines, Series, PALETTE};
use crate::results::{Table, TextTable};
use crate::Failure;
use std::io;
use std::path::Path;

/// A figure of a study: file stem (in the study's folder) and caption.
pub struct StudyFigure {
    pub file: String,
    pub caption: String,
}

fn fig(file: &str, caption: &str) -> StudyFigure {
    StudyFigure {
        file: file.into(),
        caption: caption.into(),
    }
}

fn other(dir: &Path) -> impl Fn(io::Error) -> Failure + '_ {
    move |e| Failure::Other(format!("{}: {e}", dir.display()))
}

/// Draws the figures of `study` from the files in `dir`.
pub fn study_figures(study: &str, dir: &Path) -> Result<Vec<StudyFigure>, Failure> {
    let r = match study {
        "circle-bending" => circle(dir),
        "impact-axial" => impact_axial(dir),
        "impact-transverse" => impact_transverse(dir),
        "efficiency" => efficiency(dir),
        "grid-refinement" => Ok(Vec::new()),
        "pendulum" => pendulum(dir),
        _ => Ok(Vec::new()),
    };
    r.map_err(other(dir))
}

/// Rows of a CSV grouped by the value of one column, in file order.
fn group_by(table: &Table, col: usize) -> Vec<(f64, Vec<&Vec<f64>>)> {
    let mut out: Vec<(f64, Vec<&Vec<f64>>)> = Vec::new();
    for row in &table.rows {
        match out.last_mut() {
            Some((k, rows)) if *k == row[col] => rows.push(row),
            _ => out.push((row[col], vec![row])),
        }
    }
    out
}

/// Fig. 3: the load path to the full circle, with the analytic circles
/// (radius L / (lambda pi) under M = lambda pi E I / L).
fn circle(dir: &Path) -> io::Result<Vec<StudyFigure>> {
    let t = Table::read(&dir.join("shapes.csv"))?;
    let f = "shapes.csv";
    let (cl, cx, cy) = (t.need("lambda", f)?, t.need("x", f)?, t.need("y", f)?);
    let groups = group_by(&t, cl);
    let mut lines = Lines::new(
        "Fig. 3: circle bending, 10 SAC-2 (5/3 points), load path to the full circle",
        "x (m)",
        "y (m)",
    );
    lines.equal_axes = true;
    for (k, (lambda, rows)) in groups.iter().enumerate() {
        lines.series.push(Series::line(
            format!(
                "lambda = {}",
                crate::plot::tick((lambda * 1e9).round() / 1e9)
            ),
            rows.iter().map(|r| (r[cx], r[cy])).collect(),
            sequential(k, groups.len()),
        ));
    }
    for (k, (lambda, _)) in groups.iter().enumerate().filter(|(_, g)| g.0 > 0.0) {
        let radius = 1.0 / (lambda * std::f64::consts::PI);
        let pts = (0..=200)
            .map(|i| {
                let s = i as f64 / 200.0;
                (
                    radius * (s / radius).sin(),
                    radius * (1.0 - (s / radius).cos()),
                )
            })
            .collect();
        let mut s = Series::line(
            if k + 1 == groups.len() {
                "analytic (radius L / (lambda pi))"
            } else {
                ""
            },
            pts,
            PALETTE[6],
        )
        .dashed();
        s.width = 1;
        lines.series.push(s);
    }
    save(&lines, dir, "fig3_shapes")?;
    Ok(vec![fig(
        "fig3_shapes",
        "Fig. 3: the cantilever under M = lambda pi E I / L every 5 of 40 load increments \
         (solid) and the analytic circles (dashed). The centre lines are drawn through \
         12 points per element.",
    )])
}

/// Fig. 4: the space-time maps of axial stress.
fn impact_axial(dir: &Path) -> io::Result<Vec<StudyFigure>> {
    let mut out = Vec::new();
    for (el, name) in [("sac2", "SAC-2"), ("sac3", "SAC-3")] {
        let t = Table::read(&dir.join(format!("stress_map_{el}.csv")))?;
        let info = RunInfo {
            title: format!("Fig. 4: axial impact, {name}, 8 elements"),
            dynamic: true,
            element_lengths: None,
        };
        let mut map = stress_figure(&t, &info, 400)?;
        map.clip_quantile = None;
        let file = format!("fig4_stress_{el}");
        save(&map, dir, &file)?;
        out.push(fig(
            &file,
            &format!(
                "Fig. 4 ({name}): axial stress over the material coordinate and time; the two \
                 compression waves from the struck ends meet at the middle at 1.27 ms and \
                 return as tension after reflecting at the free ends."
            ),
        ));
    }
    Ok(out)
}

/// Fig. 5: the midpoint's path and the energies.
fn impact_transverse(dir: &Path) -> io::Result<Vec<StudyFigure>> {
    let mut path = Lines::new(
        "Fig. 5a: transverse impact, path of the midpoint (8 elements)",
        "t (s)",
        "distance of the midpoint from the origin (m)",
    );
    path.log_y = true;
    for (k, (el, name)) in [("sac2", "SAC-2"), ("sac3", "SAC-3")].iter().enumerate() {
        let t = Table::read(&dir.join(format!("midpoint_{el}.csv")))?;
        let f = "midpoint csv";
        let (ct, cx, cy) = (t.need("t", f)?, t.need("x", f)?, t.need("y", f)?);
        path.series.push(Series::line(
            *name,
            t.rows
                .iter()
                .map(|r| (r[ct], (r[cx] * r[cx] + r[cy] * r[cy]).sqrt().max(1e-18)))
                .collect(),
            PALETTE[k],
        ));
    }
    save(&path, dir, "fig5a_midpoint")?;
    let t = Table::read(&dir.join("energy_sac2.csv"))?;
    let mut en = Lines::new(
        "Fig. 5b: transverse impact, energies (SAC-2, 8 elements, dt = 2.5e-5 s)",
        "t (s)",
        "energy (J)",
    );
    for (k, (col, label)) in [
        ("kinetic", "kinetic"),
        ("strain", "strain"),
        ("total", "total"),
    ]
    .iter()
    .enumerate()
    {
        let c = t.need(col, "energy_sac2.csv")?;
        let mut s = Series::line(
            *label,
            t.rows.iter().map(|r| (r[0], r[c])).collect(),
            if *col == "total" {
                PALETTE[6]
            } else {
                PALETTE[k]
            },
        );
        if *col == "total" {
            s = s.dashed();
        }
        en.series.push(s);
    }
    save(&en, dir, "fig5b_energy")?;
    Ok(vec![
        fig(
            "fig5a_midpoint",
            "Fig. 5a: distance of the midpoint from the origin (log scale). The centrally \
             symmetric motion keeps it at the round-off level until the physical instability \
             of that symmetric motion has amplified the round-off (SAC-3 resolves the \
             whipping ends and breaks symmetry sooner).",
        ),
        fig(
            "fig5b_energy",
            "Fig. 5b: kinetic, strain and total energy; the total stays within the band of \
             the table above.",
        ),
    ])
}

/// Fig. 7: residual against evaluation (Fig. 6 is drawn by the study).
fn efficiency(dir: &Path) -> io::Result<Vec<StudyFigure>> {
    let t = TextTable::read(&dir.join("fig7_residuals.csv"))?;
    let f = "fig7_residuals.csv";
    let (cc, cs, ce, cr, cm, cl) = (
        t.need("case", f)?,
        t.need("step", f)?,
        t.need("evaluation", f)?,
        t.need("residual", f)?,
        t.need("solver", f)?,
        t.need("element", f)?,
    );
    let mut lines = Lines::new(
        "Fig. 7: residual against evaluation, steps 1 to 5 of the nine cases",
        "evaluation within the step",
        "scaled residual",
    );
    lines.log_y = true;
    lines.integer_x = true;
    // (case, step) -> points, in file order.
    type StepLine = ((String, String), String, Vec<(f64, f64)>);
    let mut series: Vec<StepLine> = Vec::new();
    for r in &t.rows {
        let key = (r[cc].clone(), r[cs].clone());
        let point = (TextTable::num(r, ce), TextTable::num(r, cr).max(1e-18));
        match series.last_mut() {
            Some((k, _, pts)) if *k == key => pts.push(point),
            _ => series.push((
                key,
                format!("case {}, {} {}", r[cc], r[cl], r[cm]),
                vec![point],
            )),
        }
    }
    let cases: Vec<String> = {
        let mut c: Vec<String> = series.iter().map(|s| s.0 .0.clone()).collect();
        c.dedup();
        c
    };
    for ((case, step), label, pts) in series {
        let k = cases.iter().position(|c| *c == case).unwrap_or(0);
        let broyden = label.ends_with("BR1");
        let mut s = Series::line(
            if step == "1" { label } else { String::new() },
            pts,
            sequential(k, cases.len()),
        )
        .with_markers();
        s.dashed = broyden;
        lines.series.push(s);
    }
    save(&lines, dir, "fig7_residuals")?;
    Ok(vec![
        fig(
            "fig6_efficiency",
            "Fig. 6: Part A (element evaluation and assembly), Part B (linear algebra), \
             total time and iterations of the nine cases of Table 5, as ratios to case 1 \
             (medians of 7 runs on this machine).",
        ),
        fig(
            "fig7_residuals",
            "Fig. 7: the scaled residual of every evaluation of the first five steps of each \
             case of Table 5 (one line per step). Newton brings the predictor's residual to \
             round-off in one update; Broyden, on a Jacobian kept from an earlier step, may \
             need one more.",
        ),
    ])
}

/// A CSV file of the pendulum study: rows labelled by their model
/// (element, elements, axial_strain, drag_coefficient), with x and y (and
/// possibly t) columns.
struct PendulumFile {
    table: TextTable,
    model: [usize; 4],
    t: Option<usize>,
    x: usize,
    y: usize,
}

impl PendulumFile {
    fn read(dir: &Path, file: &str) -> io::Result<Self> {
        let table = TextTable::read(&dir.join(file))?;
        let model = [
            table.need("element", file)?,
            table.need("elements", file)?,
            table.need("axial_strain", file)?,
            table.need("drag_coefficient", file)?,
        ];
        let t = table.header.iter().position(|h| h == "t");
        let (x, y) = (table.need("x", file)?, table.need("y", file)?);
        Ok(PendulumFile {
            table,
            model,
            t,
            x,
            y,
        })
    }

    /// (x, y) of the rows of one model (`[element, elements, strain, C]`
    /// as written), at time `t` if given.
    fn points(&self, model: [&str; 4], t: Option<f64>) -> Vec<(f64, f64)> {
        self.table
            .rows
            .iter()
            .filter(|r| (0..4).all(|k| r[self.model[k]] == model[k]))
            .filter(|r| match (t, self.t) {
                (Some(t), Some(c)) => (TextTable::num(r, c) - t).abs() < 1e-9,
                _ => true,
            })
            .map(|r| (TextTable::num(r, self.x), TextTable::num(r, self.y)))
            .collect()
    }

    /// The distinct times of the file, ascending.
    fn times(&self) -> Vec<f64> {
        let Some(c) = self.t else {
            return Vec::new();
        };
        let mut t: Vec<f64> = self
            .table
            .rows
            .iter()
            .map(|r| TextTable::num(r, c))
            .collect();
        t.sort_by(|a, b| a.total_cmp(b));
        t.dedup();
        t
    }
}

/// Figs. 8-10: the tip's path against the Exudyn reference, and the
/// shapes at t = 0.68 s.
fn pendulum(dir: &Path) -> io::Result<Vec<StudyFigure>> {
    let paths = PendulumFile::read(dir, "tip_trajectory.csv")?;
    let pick =
        |element: &str, n: &str, strain: &str, c: &str| paths.points([element, n, strain, c], None);
    let reference = |name: &str| -> io::Result<Vec<(f64, f64)>> {
        let r = Table::read(&dir.join(name))?;
        Ok(r.rows.iter().map(|row| (row[1], row[2])).collect())
    };
    let mut out = Vec::new();
    for (drag, c, file) in [
        (true, "1.5", "fig10_tip_path_drag"),
        (false, "0", "fig10_tip_path_nodrag"),
    ] {
        let mut lines = Lines::new(
            format!(
                "Fig. 10 analogue: path of the pendulum's tip, {}",
                if drag { "air drag C = 1.5" } else { "no drag" }
            ),
            "x (m)",
            "y (m)",
        );
        lines.equal_axes = true;
        let exu = reference(if drag {
            "exudyn_drag_tip.csv"
        } else {
            "exudyn_nodrag_tip.csv"
        })?;
        let mut e = Series::line(
            "Exudyn 1.13 reference (64 el., engineering strain)",
            exu,
            PALETTE[6],
        );
        e.width = 4;
        lines.series.push(e);
        lines.series.push(
            Series::line(
                "stancf 16 SAC-3, engineering strain",
                pick("SAC-3", "16", "engineering", c),
                PALETTE[1],
            )
            .dashed(),
        );
        lines.series.push(Series::line(
            "stancf 4 SAC-2, Green strain (the paper's model)",
            pick("SAC-2", "4", "Green", c),
            PALETTE[0],
        ));
        save(&lines, dir, file)?;
        out.push(fig(
            file,
            &format!(
                "Fig. 10 analogue ({}): the tip's path over 0.8 s against the Exudyn reference, \
                 in place of the paper's experiment (its images are not public; Fig. 9 is the \
                 test rig). At this scale the three coincide: the \
                 16-element SAC-3 path is within 0.005 mm of the Exudyn reference at the report \
                 times, the paper's 4-element SAC-2 mesh millimetres away (the tables above).",
                if drag { "with drag" } else { "without drag" }
            ),
        ));
    }
    // Fig. 10 analogue: the shapes at the six report times, with drag.
    let sh = PendulumFile::read(dir, "shapes_at_report_times.csv")?;
    let reference = Table::read(&dir.join("exudyn_drag_shapes.csv"))?;
    let mut lines = Lines::new(
        "Fig. 10 analogue: the pendulum at the six report times, air drag C = 1.5",
        "x (m)",
        "y (m)",
    );
    lines.equal_axes = true;
    // Our report times (the reference also has t = 0 and 0.8 s).
    let times = sh.times();
    for (k, &t) in times.iter().enumerate() {
        let first = k == 0;
        let mut e = Series::line(
            if first {
                "Exudyn 1.13 reference (64 el.)"
            } else {
                ""
            },
            reference
                .rows
                .iter()
                .filter(|r| (r[0] - t).abs() < 1e-9)
                .map(|r| (r[3], r[4]))
                .collect(),
            PALETTE[6],
        );
        e.width = 4;
        lines.series.push(e);
        for (element, n, strain, label, color, dashed) in [
            (
                "SAC-3",
                "16",
                "engineering",
                "stancf 16 SAC-3, engineering strain",
                PALETTE[1],
                true,
            ),
            (
                "SAC-2",
                "4",
                "Green",
                "stancf 4 SAC-2, Green (the paper's model)",
                PALETTE[0],
                false,
            ),
        ] {
            let pts = sh.points([element, n, strain, "1.5"], Some(t));
            let mut s = Series::line(if first { label } else { "" }, pts, color);
            s.dashed = dashed;
            lines.series.push(s);
        }
    }
    save(&lines, dir, "fig10_shapes")?;
    out.push(fig(
        "fig10_shapes",
        "Fig. 10 analogue: the cable at the report times 0.19, 0.30, 0.42, 0.53, 0.67 and \
         0.79 s (the paper's images 2 to 7) against the Exudyn reference, in place of the \
         paper's photographs (not public).",
    ));
    let shapes = PendulumFile::read(dir, "shapes_068.csv")?;
    let mut lines = Lines::new(
        "Fig. 8: the pendulum at t = 0.68 s for drag coefficients 0 to 2 (4 SAC-2, Green)",
        "x (m)",
        "y (m)",
    );
    lines.equal_axes = true;
    let cs = ["0", "0.5", "1", "1.5", "2"];
    for (k, c) in cs.iter().enumerate() {
        let pts = shapes.points(["SAC-2", "4", "Green", c], None);
        lines.series.push(Series::line(
            format!("C = {c}"),
            pts,
            sequential(k, cs.len()),
        ));
    }
    save(&lines, dir, "fig8_shapes")?;
    out.insert(
        0,
        fig(
            "fig8_shapes",
            "Fig. 8: shapes at t = 0.68 s with the drag coefficient from \
         0 to 2 (the paper's model: 4 SAC-2, Green strain); the table above gives the tip \
         and the lowest point of each.",
        ),
    );
    Ok(out)
}
