//! `reproduce circle-bending`: the paper's Table 3 (section 4.1).

use super::{md_num, write_files};
use crate::output::Num;
use crate::Failure;
use stancf::{
    Cable, Constraint, ConstraintKind, Curvature, ElementType, Load, Material, Measures, Model,
    ModelOptions, SpacePoints, StaticSettings, StaticSolver,
};
use std::fmt::Write as _;
use std::ops::ControlFlow;
use std::path::Path;

/// One circle-bending configuration.
#[derive(Clone, Copy)]
struct Bending {
    element: ElementType,
    elements: usize,
    points: SpacePoints,
    fix_curvature: bool,
    curvature: Curvature,
    lambda: f64,
}

/// The static solver of the 1 m PVC cantilever clamped at A under the
/// moment lambda pi E I / L at B (20 increments per unit of lambda).
fn bending_solver(c: &Bending) -> Result<StaticSolver, Failure> {
    let m = Material::chen2023_pvc();
    let moment = c.lambda * std::f64::consts::PI * m.youngs_modulus * m.second_moment / 1.0;
    let model = Model::new(
        Cable::straight(1.0, c.elements, c.element),
        m,
        ModelOptions {
            measures: Measures {
                curvature: c.curvature,
                ..Measures::default()
            },
            space_points: Some(c.points),
        },
        vec![Load::EndMoment {
            node: c.elements,
            moment: [0.0, 0.0, moment],
        }],
    )
    .and_then(|m| {
        m.with_constraints(vec![Constraint {
            node: 0,
            kind: ConstraintKind::Clamped {
                fix_curvature: c.fix_curvature,
            },
        }])
    })
    .map_err(|e| Failure::Other(format!("circle-bending: {e}")))?;
    let settings = StaticSettings {
        load_steps: (20.0 * c.lambda).round() as usize,
        tolerance: 1e-12,
        ..StaticSettings::default()
    };
    StaticSolver::new(model, settings).map_err(|e| Failure::Other(format!("circle-bending: {e}")))
}

/// The tip of the cantilever of [`bending_solver`], and the Newton
/// iterations it took.
fn bend(c: &Bending) -> Result<([f64; 3], usize), Failure> {
    let mut solver = bending_solver(c)?;
    let mut iterations = 0;
    solver
        .solve(|_, inc| {
            iterations += inc.iterations;
            ControlFlow::Continue(())
        })
        .map_err(|e| Failure::Solver(format!("circle-bending: {e}")))?;
    Ok((
        solver.model().node_position(&solver.state().e, c.elements),
        iterations,
    ))
}

/// The load path of the full circle (10 SAC-2, 5 axial / 3 bending
/// points, 40 increments): the centre line every 5 increments, for Fig. 3,
/// as CSV rows `lambda,s,x,y` (lambda of the applied moment).
fn load_path_shapes() -> Result<String, Failure> {
    let c = Bending {
        element: ElementType::Sac2,
        elements: 10,
        points: SpacePoints {
            axial: 5,
            bending: 3,
        },
        fix_curvature: false,
        curvature: Curvature::Paper,
        lambda: 2.0,
    };
    let mut solver = bending_solver(&c)?;
    let mut csv = String::from("lambda,s,x,y\n");
    let write = |csv: &mut String, lambda: f64, solver: &StaticSolver| {
        for p in stancf::observe::cable_points(solver.model(), solver.state(), 12) {
            writeln!(
                csv,
                "{},{},{},{}",
                Num(lambda),
                Num(p.s),
                Num(p.r[0]),
                Num(p.r[1])
            )
            .ok();
        }
    };
    write(&mut csv, 0.0, &solver);
    solver
        .solve(|solver, inc| {
            if inc.step % 5 == 0 {
                write(&mut csv, c.lambda * inc.load_factor, solver);
            }
            ControlFlow::Continue(())
        })
        .map_err(|e| Failure::Solver(format!("circle-bending: {e}")))?;
    Ok(csv)
}

/// A row of Table 3: which element and quadrature, and the paper's values
/// for (5 el. semicircle, 5 el. circle, 10 el. semicircle, 10 el. circle).
struct Table3Row {
    label: &'static str,
    element: ElementType,
    points: SpacePoints,
    fix_curvature: bool,
    paper: [Option<f64>; 4],
}

fn table3_rows() -> Vec<Table3Row> {
    let pts = |axial, bending| SpacePoints { axial, bending };
    let sac2 = [Some(65.31), Some(-197.3), Some(0.400), Some(18.30)];
    vec![
        Table3Row {
            label: "SAC-2, 5 axial / 3 bending points",
            element: ElementType::Sac2,
            points: pts(5, 3),
            fix_curvature: false,
            paper: sac2,
        },
        Table3Row {
            label: "SAC-2, 3 points for both",
            element: ElementType::Sac2,
            points: pts(3, 3),
            fix_curvature: false,
            paper: sac2,
        },
        Table3Row {
            label: "SAC-2, 5 points for both",
            element: ElementType::Sac2,
            points: pts(5, 5),
            fix_curvature: false,
            paper: sac2,
        },
        Table3Row {
            label: "SAC-3 without r_xx constraint (5 points)",
            element: ElementType::Sac3,
            points: pts(5, 5),
            fix_curvature: false,
            paper: [Some(0.172), Some(1.380e-3), Some(-4.622e-4), Some(2.636e-6)],
        },
        Table3Row {
            label: "SAC-3 with r_xx constraint (5 points)",
            element: ElementType::Sac3,
            points: pts(5, 5),
            fix_curvature: true,
            paper: [None, None, Some(21.17), Some(0.063)],
        },
    ]
}

fn curvature_name(c: Curvature) -> &'static str {
    match c {
        Curvature::Paper => "paper",
        Curvature::Exact => "exact",
    }
}

/// Table 3 analogue and the convergence of the tip error (docs/interface.md,
/// `reproduce circle-bending`).
pub fn circle_bending(dir: &Path) -> Result<(), Failure> {
    let mut csv = String::from(
        "row,element,axial_points,bending_points,fix_curvature,curvature,elements,lambda,tip_x_mm,tip_y_mm,paper_mm,iterations\n",
    );
    let mut md = String::new();
    writeln!(
        md,
        "# Circle bending (Chen et al. 2023, section 4.1, Table 3)\n"
    )
    .ok();
    writeln!(
        md,
        "A 1 m PVC cantilever (Table 2) clamped at end A, bent by the moment \
         M = lambda pi E I / L at end B: lambda = 1 bends it into a semicircle (tip at \
         (0, 2L/pi)), lambda = 2 into a full circle (tip back at the clamp). The table gives \
         the horizontal error of the tip, x_tip - 0, in mm. Signs: x_tip is negative when \
         the tip stops before the clamp; the paper prints some values unsigned (18.30 for \
         the 10-element circle, whose tip stops before the clamp), so each cell gives our \
         signed x_tip and, in brackets, the paper's value and the difference in magnitude, \
         |ours| - |paper| (mm). Static analysis, Green strain, {} to {} load steps, tolerance 1e-12.\n",
        20, 40
    )
    .ok();
    let rows = table3_rows();
    // Largest relative difference from the paper's column, per SAC-2 row
    // (curvature "paper"; magnitudes, since the paper's 18.30 is unsigned).
    let mut sac2_match: Vec<(&str, f64)> = Vec::new();
    for curvature in [Curvature::Paper, Curvature::Exact] {
        writeln!(
            md,
            "## Table 3, curvature \"{}\" ({})\n",
            curvature_name(curvature),
            match curvature {
                Curvature::Paper => "|r_x x r_xx| / |r_x|^2, eq. (9) as printed",
                Curvature::Exact => "|r_x x r_xx| / |r_x|^3",
            }
        )
        .ok();
        writeln!(
            md,
            "| element and quadrature | 5 el., semicircle | 5 el., circle | 10 el., semicircle | 10 el., circle |"
        )
        .ok();
        writeln!(md, "|---|---|---|---|---|").ok();
        for (ri, row) in rows.iter().enumerate() {
            let mut cells = Vec::new();
            let mut worst = 0.0f64;
            for (k, (elements, lambda)) in [(5, 1.0), (5, 2.0), (10, 1.0), (10, 2.0)]
                .into_iter()
                .enumerate()
            {
                let c = Bending {
                    element: row.element,
                    elements,
                    points: row.points,
                    fix_curvature: row.fix_curvature,
                    curvature,
                    lambda,
                };
                let (tip, its) = bend(&c)?;
                let paper = row.paper[k];
                if let Some(p) = paper {
                    worst = worst.max(((tip[0] * 1e3).abs() / p.abs() - 1.0).abs());
                }
                writeln!(
                    csv,
                    "{ri},{},{},{},{},{},{elements},{lambda},{},{},{},{its}",
                    row.element.name(),
                    row.points.axial,
                    row.points.bending,
                    row.fix_curvature,
                    curvature_name(curvature),
                    Num(tip[0] * 1e3),
                    Num(tip[1] * 1e3),
                    paper.map(|p| Num(p).to_string()).unwrap_or_default()
                )
                .ok();
                let p = match paper {
                    Some(p) if curvature == Curvature::Paper => format!(
                        " (paper {}, difference in magnitude {:+.4})",
                        md_num(p),
                        (tip[0] * 1e3).abs() - p.abs()
                    ),
                    Some(_) => String::new(),
                    None if curvature == Curvature::Paper => " (no data)".into(),
                    None => String::new(),
                };
                cells.push(format!("{}{}", md_num(tip[0] * 1e3), p));
            }
            writeln!(md, "| {} | {} |", row.label, cells.join(" | ")).ok();
            if curvature == Curvature::Paper && row.element == ElementType::Sac2 {
                sac2_match.push((row.label, worst));
            }
        }
        writeln!(md).ok();
    }
    let mut ranked = sac2_match.clone();
    ranked.sort_by(|a, b| a.1.total_cmp(&b.1));
    writeln!(md, "Notes:\n").ok();
    writeln!(
        md,
        "- Which quadrature reproduces the paper's SAC-2 column (largest relative difference \
         of the four magnitudes from the paper's): {}. The paper says \"3 x 3\" for SAC-2; its \
         numbers are not those of 3 points for both terms, but those of 5 points for the axial \
         term (with 3 or 5 for bending). Exudyn's ANCFCable2D defaults (5 axial / 3 bending \
         points) give 65.34, -197.3, 0.4006, -18.33 mm.",
        ranked
            .iter()
            .map(|(l, w)| format!("{l}: {:.2} %", 100.0 * w))
            .collect::<Vec<_>>()
            .join("; ")
    )
    .ok();
    writeln!(
        md,
        "- The paper's 10-element circle value, 18.30, is positive; the tip lies before the \
         clamp (negative x), as Exudyn's -18.33 mm: the paper most likely printed the \
         magnitude.\n\
         - SAC-3 uses 5 points (3 leave each quintic element with zero-energy modes). The \
         paper's SAC-3 numbers are not monotone in the mesh or the load (its full circle is \
         more accurate than its semicircle); ours fall with refinement, see below.\n\
         - Fixing r_xx at the clamp imposes zero curvature there, which the bent cantilever \
         does not have: that error is the paper's \"with r_xx constraint\" row.\n"
    )
    .ok();

    // Convergence of the error with the mesh.
    let mut conv_csv = String::from("element,elements,lambda,tip_x_mm,order\n");
    writeln!(
        md,
        "## Convergence of the tip error with the mesh (curvature \"paper\")\n"
    )
    .ok();
    writeln!(
        md,
        "| element | lambda | 5 el. | 10 el. | 20 el. | 40 el. | orders |"
    )
    .ok();
    writeln!(md, "|---|---|---|---|---|---|---|").ok();
    for (element, points) in [
        (
            ElementType::Sac2,
            SpacePoints {
                axial: 5,
                bending: 3,
            },
        ),
        (
            ElementType::Sac3,
            SpacePoints {
                axial: 5,
                bending: 5,
            },
        ),
    ] {
        for lambda in [1.0, 2.0] {
            let mut errs = Vec::new();
            for elements in [5, 10, 20, 40] {
                let c = Bending {
                    element,
                    elements,
                    points,
                    fix_curvature: false,
                    curvature: Curvature::Paper,
                    lambda,
                };
                errs.push(bend(&c)?.0[0]);
            }
            let orders: Vec<f64> = errs
                .windows(2)
                .map(|w| (w[0] / w[1]).abs().log2())
                .collect();
            for (k, elements) in [5, 10, 20, 40].into_iter().enumerate() {
                let order = if k > 0 {
                    Num(orders[k - 1]).to_string()
                } else {
                    String::new()
                };
                writeln!(
                    conv_csv,
                    "{},{elements},{lambda},{},{order}",
                    element.name(),
                    Num(errs[k] * 1e3)
                )
                .ok();
            }
            writeln!(
                md,
                "| {} | {lambda} | {} | {} |",
                element.name(),
                errs.iter()
                    .map(|e| md_num(e * 1e3))
                    .collect::<Vec<_>>()
                    .join(" | "),
                orders
                    .iter()
                    .map(|o| format!("{o:.2}"))
                    .collect::<Vec<_>>()
                    .join(", ")
            )
            .ok();
        }
    }
    writeln!(
        md,
        "\nThe order is log2 of the ratio of successive errors. Errors near 1e-9 mm are at \
         the level of the solver tolerance and round-off; their ratios mean nothing."
    )
    .ok();
    let shapes = load_path_shapes()?;
    write_files(
        dir,
        &[
            ("table3.csv", &csv),
            ("convergence.csv", &conv_csv),
            ("shapes.csv", &shapes),
            ("table3.md", &md),
        ],
    )?;
    Ok(())
}
