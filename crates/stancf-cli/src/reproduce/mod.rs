//! `stancf reproduce <study>`: the paper's studies, each writing its tables
//! as CSV and Markdown into its own folder.

mod circle;
mod efficiency;
mod impact;
mod pendulum;
mod report;
mod study_figures;

use crate::output::write_atomic;
use crate::Failure;
use rayon::prelude::*;
use std::path::Path;
use study_figures::StudyFigure;

/// The studies of docs/interface.md.
pub const STUDIES: [&str; 6] = [
    "circle-bending",
    "impact-axial",
    "impact-transverse",
    "efficiency",
    "grid-refinement",
    "pendulum",
];

pub fn reproduce(study: &str, out: &Path) -> Result<(), Failure> {
    let list: Vec<&str> = match study {
        "all" => STUDIES.to_vec(),
        s if STUDIES.contains(&s) => vec![s],
        s => {
            return Err(Failure::Input(format!(
                "unknown study \"{s}\" (available: {}, all)",
                STUDIES.join(", ")
            )))
        }
    };
    // The studies that time themselves (efficiency, grid refinement) run
    // alone, so their wall-clock ratios are not shared with other work;
    // the others side by side on the cores. Reported in the list's order.
    let timed = |s: &&str| matches!(*s, "efficiency" | "grid-refinement");
    let mut done: Vec<(&str, Vec<StudyFigure>)> = Vec::new();
    for s in list.iter().copied().filter(timed) {
        done.push((s, run_study(s, out)?));
    }
    let others: Vec<&str> = list.iter().copied().filter(|s| !timed(s)).collect();
    let parallel: Vec<(&str, Vec<StudyFigure>)> = others
        .par_iter()
        .map(|&s| run_study(s, out).map(|f| (s, f)))
        .collect::<Result<_, _>>()?;
    done.extend(parallel);
    let mut sections = Vec::new();
    for s in list.iter().copied() {
        let at = done
            .iter()
            .position(|(d, _)| *d == s)
            .expect("every study ran");
        let (_, figures) = done.swap_remove(at);
        println!(
            "{s}: tables{} in {}",
            if figures.is_empty() {
                ""
            } else {
                " and figures"
            },
            out.join(s).display()
        );
        sections.push((s, figures));
    }
    if study == "all" {
        report::write_report(out, &sections)?;
        println!("report: {}", out.join("REPORT.md").display());
    }
    Ok(())
}

/// Runs one study into `out/<study>`: its tables, then its figures (the
/// figures' file names are returned).
fn run_study(s: &str, out: &Path) -> Result<Vec<StudyFigure>, Failure> {
    let dir = out.join(s);
    std::fs::create_dir_all(&dir).map_err(|e| Failure::Other(format!("{}: {e}", dir.display())))?;
    match s {
        "circle-bending" => circle::circle_bending(&dir)?,
        "pendulum" => pendulum::pendulum(&dir)?,
        "impact-axial" => impact::axial(&dir)?,
        "impact-transverse" => impact::transverse(&dir)?,
        "efficiency" => efficiency::efficiency(&dir)?,
        "grid-refinement" => efficiency::grid_refinement(&dir)?,
        _ => unreachable!("listed in STUDIES"),
    }
    study_figures::study_figures(s, &dir)
}

/// Writes a study's files atomically.
fn write_files(dir: &Path, files: &[(&str, &str)]) -> Result<(), Failure> {
    for (name, text) in files {
        write_atomic(dir, name, text.as_bytes())
            .map_err(|e| Failure::Other(format!("{}: {e}", dir.join(name).display())))?;
    }
    Ok(())
}

/// Markdown number: fixed for moderate magnitudes, exponent otherwise.
fn md_num(x: f64) -> String {
    if x == 0.0 {
        "0".into()
    } else if x.abs() >= 0.01 && x.abs() < 1e4 {
        format!("{x:.4}")
    } else {
        format!("{x:.3e}")
    }
}
