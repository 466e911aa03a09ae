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
use std::path::Path;

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
    let mut sections = Vec::new();
    for s in list.iter().copied() {
        let dir = out.join(s);
        std::fs::create_dir_all(&dir)
            .map_err(|e| Failure::Other(format!("{}: {e}", dir.display())))?;
        match s {
            "circle-bending" => circle::circle_bending(&dir)?,
            "pendulum" => pendulum::pendulum(&dir)?,
            "impact-axial" => impact::axial(&dir)?,
            "impact-transverse" => impact::transverse(&dir)?,
            "efficiency" => efficiency::efficiency(&dir)?,
            "grid-refinement" => efficiency::grid_refinement(&dir)?,
            _ => unreachable!("listed in STUDIES"),
        }
        let figures = study_figures::study_figures(s, &dir)?;
        println!(
            "{s}: tables{} in {}",
            if figures.is_empty() {
                ""
            } else {
                " and figures"
            },
            dir.display()
        );
        sections.push((s, figures));
    }
    if study == "all" {
        report::write_report(out, &sections)?;
        println!("report: {}", out.join("REPORT.md").display());
    }
    Ok(())
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
