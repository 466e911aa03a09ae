//! `REPORT.md` (`stancf reproduce all`): every study's tables beside the
//! paper's, its figures with their captions (drawn by study_figures.rs),
//! and what agrees and what does not.

use super::study_figures::StudyFigure;
use crate::Failure;
use std::path::Path;

/// The study folders and the paper's numbers they answer, in report order.
pub const SECTIONS: [(&str, &str, &str); 6] = [
    (
        "circle-bending",
        "table3.md",
        "Table 3 and Fig. 3: circle bending",
    ),
    (
        "impact-axial",
        "impact-axial.md",
        "Fig. 4: double-ended axial impact",
    ),
    (
        "impact-transverse",
        "impact-transverse.md",
        "Fig. 5: double-ended transverse impact",
    ),
    (
        "efficiency",
        "efficiency.md",
        "Tables 5, 7, 8 and Figs. 6, 7: efficiency",
    ),
    ("grid-refinement", "table6.md", "Table 6: grid refinement"),
    (
        "pendulum",
        "pendulum.md",
        "Figs. 8, 10 and Table 10: free pendulum with air drag",
    ),
];

/// What agrees with the paper and what does not, per study (the numbers
/// are in the tables above each paragraph).
fn verdict(study: &str) -> &'static str {
    match study {
        "circle-bending" => {
            "**What agrees and what does not.** The paper's SAC-2 column is reproduced to \
             0.02 % with 5 Gauss points for both terms (0.17 % with Exudyn's 5 axial / 3 \
             bending), not with the 3 x 3 the paper states (1.69 mm instead of 65.31 mm for 5 \
             elements): the paper's numbers are those of 5 points. Its 18.30 mm for the \
             10-element circle is a magnitude (the tip stops before the clamp). SAC-3 converges \
             to the analytic circle (Fig. 3) and closes it to 8e-7 L with 10 elements; the \
             paper's SAC-3 values are not monotone in the mesh. Fixing r_xx at the clamp \
             imposes a zero curvature the bent cantilever does not have: 21.05 mm here, 21.17 \
             in the paper."
        }
        "impact-axial" => {
            "**What agrees and what does not.** The two waves run at the bar speed (1581 and \
             1571 m/s for SAC-2 and SAC-3 against sqrt(E/rho) = 1570 m/s), meet in the middle \
             and reflect at the free ends as in the paper's Fig. 4. The peak stress where they \
             meet is 24.1 MPa (SAC-2) and 22.6 MPa (SAC-3) against the paper's 23.5 MPa; the \
             continuum value for this initial condition is rho c v0 = 21.66 MPa, which 64 \
             elements reach within 0.11 %: the paper's 8-element value is a coarse-mesh \
             number, as ours are."
        }
        "impact-transverse" => {
            "**What agrees and what does not.** The energy stays in a bounded band with no \
             drift, and the linear momentum stays zero, as in the paper's Fig. 5b. The paper's \
             Fig. 5a shows the midpoint at the origin throughout; ours stays there to \
             round-off only while the motion is centrally symmetric: that symmetric motion is \
             physically unstable, and round-off grows at a rate that does not depend on the \
             step until the midpoint leaves (Fig. 5a, log scale)."
        }
        "efficiency" => {
            "**What agrees and what does not.** The paper's qualitative findings hold: fewer \
             elements and steps cost proportionally less, higher order (SAC-3) costs more per \
             step, and Broyden saves most of Part B (it keeps the factorized Jacobian: 2 \
             factorizations for 400 steps). Time ratios depend on the machine (medians of 7 \
             runs). Table 7's convergence-rate estimate is undefined for us: one Newton update \
             takes the predictor's residual to round-off, so no step has the three residuals \
             above the tolerance that the estimate needs (Fig. 7)."
        }
        "grid-refinement" => {
            "**What agrees and what does not.** The energy error is fourth order in time \
             (4.10, 4.02, 4.01; the paper: 3.91 and 4.26). Refining in space alone raises the \
             error here (order -4) where the paper reports 0.33: a finer mesh raises the \
             highest frequency w_max and with it w_max dt, which drives P2's error. The \
             paper's grids cannot be matched exactly: it does not say over which interval its \
             time elements are counted."
        }
        "pendulum" => {
            "**What agrees and what does not.** With 16 SAC-3 elements the tip follows the \
             Exudyn reference to 0.005 mm, the reference's own accuracy, with and without drag \
             (Fig. 10 analogue). The paper's mesh of 4 SAC-2 elements is up to 5.6 mm from that \
             converged path, more than the RMSE the paper reports against its experiment \
             (0.38 to 1.52 mm); the experiment's images are not public, so that comparison \
             cannot be repeated."
        }
        _ => "",
    }
}

/// A study's Markdown as a section of the report: its title dropped (the
/// section has one), headings one level down, relative links into its
/// folder.
fn embed(md: &str, study: &str) -> String {
    let mut out = String::new();
    for line in md.lines() {
        if line.starts_with("# ") {
            continue;
        }
        let line = if line.starts_with('#') {
            format!("#{line}")
        } else if let Some(rest) = line.strip_prefix("![") {
            match rest.split_once("](") {
                Some((alt, target)) if !target.starts_with("http") && !target.starts_with('/') => {
                    format!("![{alt}]({study}/{target}")
                }
                _ => line.to_string(),
            }
        } else {
            line.to_string()
        };
        out.push_str(&line);
        out.push('\n');
    }
    out
}

/// `DIR/REPORT.md`: every study with its tables, figures and verdict.
pub fn write_report(out: &Path, sections: &[(&str, Vec<StudyFigure>)]) -> Result<(), Failure> {
    use std::fmt::Write as _;
    let mut md = String::new();
    writeln!(
        md,
        "# stancf and the studies of Chen, Li, Lu and Lan (Machines 2023, 11, 433)\n\n\
         Written by `stancf reproduce all --out {}` (stancf {}). Every table puts our \
         numbers beside the paper's; every figure is a PNG with an SVG twin next to it, drawn \
         from the CSV files in the study's folder. Times are of this machine and are given \
         as ratios where they are compared.\n",
        out.display(),
        env!("CARGO_PKG_VERSION")
    )
    .ok();
    writeln!(md, "## Contents\n").ok();
    for (study, _) in sections {
        if let Some((_, _, title)) = SECTIONS.iter().find(|s| s.0 == *study) {
            writeln!(md, "- [{title}](#{})", anchor(title)).ok();
        }
    }
    md.push('\n');
    for (study, figures) in sections {
        let Some((_, file, title)) = SECTIONS.iter().find(|s| s.0 == *study) else {
            continue;
        };
        writeln!(md, "## {title}\n").ok();
        let path = out.join(study).join(file);
        let body = std::fs::read_to_string(&path)
            .map_err(|e| Failure::Other(format!("{}: {e}", path.display())))?;
        let mut body = embed(&body, study);
        let mut rest = Vec::new();
        for f in figures {
            let png = format!("{study}/{}.png", f.file);
            match caption_in_place(&body, &png, &f.caption) {
                Some(captioned) => body = captioned,
                None => rest.push((png, f)),
            }
        }
        md.push_str(&body);
        md.push('\n');
        for (png, f) in rest {
            writeln!(md, "![{}]({png})\n\n*{}*\n", f.file, f.caption).ok();
        }
        writeln!(md, "{}\n", verdict(study)).ok();
    }
    crate::output::write_atomic(out, "REPORT.md", md.as_bytes())
        .map_err(|e| Failure::Other(format!("{}: {e}", out.join("REPORT.md").display())))
}

/// A study's Markdown that already shows the figure `png` (the efficiency
/// study places Fig. 6 among its tables) with the caption in italics
/// below the image; None if the Markdown does not show it.
fn caption_in_place(body: &str, png: &str, caption: &str) -> Option<String> {
    let target = format!("]({png})");
    let mut found = false;
    let mut out = String::new();
    for line in body.lines() {
        out.push_str(line);
        out.push('\n');
        if !found && line.starts_with("![") && line.ends_with(&target) {
            found = true;
            out.push_str(&format!("\n*{caption}*\n"));
        }
    }
    found.then_some(out)
}

/// GitHub's anchor of a heading.
fn anchor(title: &str) -> String {
    title
        .to_lowercase()
        .chars()
        .filter_map(|c| match c {
            'a'..='z' | '0'..='9' | '-' | '_' => Some(c),
            ' ' => Some('-'),
            _ => None,
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn embedded_markdown_is_demoted_relinked_and_its_figures_captioned() {
        let md = "# Title\n\nText.\n\n## Table 8\n\n![Fig. 6](fig6.png)\n![x](http://a/b.png)\n";
        let e = embed(md, "efficiency");
        assert_eq!(
            e,
            "\nText.\n\n### Table 8\n\n![Fig. 6](efficiency/fig6.png)\n![x](http://a/b.png)\n"
        );
        let captioned = caption_in_place(&e, "efficiency/fig6.png", "Fig. 6: times.").unwrap();
        assert!(
            captioned.contains("![Fig. 6](efficiency/fig6.png)\n\n*Fig. 6: times.*\n"),
            "{captioned}"
        );
        assert_eq!(caption_in_place(&e, "efficiency/fig9.png", "no"), None);
        assert_eq!(
            anchor("Table 3 and Fig. 3: circle bending"),
            "table-3-and-fig-3-circle-bending"
        );
    }
}
