//! The `bodies` figure of a system with rigid bodies (docs/interface.md,
//! "Figures"): from bodies.csv, each body's motion, its reference point's
//! displacement from where it is first written (x, y, z; a mooring's
//! offsets are small against the body's depth) and its roll, pitch and
//! yaw (MoorDyn's angles, degrees), over time in a dynamic run (a point
//! per body in a static one).

use crate::figure_data::RunInfo;
use crate::plot::{Lines, Panels, Series, PALETTE};
use crate::results::Table;
use std::io;
use std::path::Path;

/// bodies.csv's columns of a body's pose, with their axis labels.
const TRANSLATIONS: [&str; 3] = ["x", "y", "z"];
const ROTATIONS: [&str; 3] = ["roll", "pitch", "yaw"];

/// The figure from `dir`/bodies.csv, or None where the run wrote none (no
/// bodies, or left out by `output.files`): two panels, the positions (m)
/// and the angles (degrees) of every body over t, a hue per quantity, a
/// line style per body.
pub fn bodies_figure(dir: &Path, info: &RunInfo) -> io::Result<Option<Panels>> {
    let path = dir.join("bodies.csv");
    if !path.exists() {
        return Ok(None);
    }
    let table = Table::read(&path)?;
    let f = "bodies.csv";
    let (t, body) = (table.need("t", f)?, table.need("body", f)?);
    let mut ids: Vec<f64> = table.rows.iter().map(|r| r[body]).collect();
    ids.dedup();
    ids.sort_by(f64::total_cmp);
    ids.dedup();
    let x_label = if info.dynamic { "t (s)" } else { "load factor" };
    let mut panels = Vec::new();
    for (names, unit, label, offset) in [
        (TRANSLATIONS, "m", "displacement", true),
        (ROTATIONS, "deg", "angle", false),
    ] {
        let title = if offset {
            format!(
                "{}: bodies' displacements from their first written pose",
                info.title
            )
        } else {
            format!("{}: bodies' angles", info.title)
        };
        let mut panel = Lines::new(title, x_label, format!("{label} ({unit})"));
        for (k, name) in names.iter().enumerate() {
            let c = table.need(name, f)?;
            for (j, id) in ids.iter().enumerate() {
                let rows: Vec<&Vec<f64>> = table.rows.iter().filter(|r| r[body] == *id).collect();
                let first = if offset { rows[0][c] } else { 0.0 };
                let points = rows.iter().map(|r| (r[t], r[c] - first)).collect();
                let label = if offset {
                    format!("body {id} {name} - {name}0")
                } else {
                    format!("body {id} {name}")
                };
                let mut s = Series::line(label, points, PALETTE[k]);
                s.dashed = j % 2 == 1;
                s.markers = !info.dynamic;
                panel.series.push(s);
            }
        }
        panels.push(panel);
    }
    Ok(Some(Panels { panels }))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Two bodies over three times: a panel of displacements (from the
    /// first row of each) and one of angles, each with a series per body
    /// and quantity; no bodies.csv, no figure.
    #[test]
    fn each_bodys_pose_is_a_series_of_its_own() {
        let d = std::env::temp_dir().join(format!("stancf-figbodies-{}", std::process::id()));
        std::fs::create_dir_all(&d).unwrap();
        let info = RunInfo {
            title: "buoy".into(),
            dynamic: true,
            element_lengths: None,
        };
        assert!(bodies_figure(&d, &info).unwrap().is_none());
        let mut csv = String::from("t,body,x,y,z,roll,pitch,yaw\n");
        for k in 0..3 {
            for id in [1, 2] {
                let v = k as f64 + 10.0 * id as f64;
                csv.push_str(&format!("{k},{id},{v},0,-{v},1,2,{v}\n"));
            }
        }
        std::fs::write(d.join("bodies.csv"), csv).unwrap();
        let fig = bodies_figure(&d, &info).unwrap().unwrap();
        assert_eq!(fig.panels.len(), 2);
        assert_eq!(fig.panels[0].series.len(), 6);
        let x2 = &fig.panels[0].series[1];
        assert_eq!(x2.label, "body 2 x - x0");
        assert_eq!(x2.points, [(0.0, 0.0), (1.0, 1.0), (2.0, 2.0)]);
        assert!(x2.dashed);
        assert_eq!(fig.panels[1].series[5].label, "body 2 yaw");
        std::fs::remove_dir_all(&d).ok();
    }
}
