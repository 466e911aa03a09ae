//! What the figures read from a result folder: the run's facts from
//! `summary.json` ([`RunInfo`]), the nodes of `nodes.csv` by time, the
//! centre line drawn through them and the plane a cable moves in. The
//! figures of single cables (`figures.rs`), of systems
//! (`figures_system.rs`) and of energies (`figures_energy.rs`) draw from
//! these.

use crate::results::{by_time, Table};
use std::io;
use std::path::Path;

/// What `summary.json` says that the figures need.
#[derive(Clone, Debug)]
pub struct RunInfo {
    pub title: String,
    pub dynamic: bool,
    /// Reference (unstretched) length of every element, from the
    /// length, the element count and the grading (docs/method.md §1.6).
    pub element_lengths: Option<Vec<f64>>,
}

/// The element lengths a `summary.json` object (a cable's, or a system's
/// line's) describes: its `length`, `elements` and `grading` (absent:
/// uniform), by the library's [`stancf::Grading::element_lengths`]. None
/// without a length or an element count, or with a grading it cannot read.
pub fn element_lengths_of(s: &serde_json::Value) -> Option<Vec<f64>> {
    let (Some(length), Some(n)) = (s["length"].as_f64(), s["elements"].as_u64()) else {
        return None;
    };
    if n == 0 {
        return None;
    }
    let grading = grading_of(&s["grading"])?;
    Some(grading.element_lengths(length, n as usize))
}

/// The grading summary.json writes (`{"toward", "ratio"}` or
/// `{"sections": [{"length", "elements"}, ...]}`, absent for a uniform
/// mesh); None if it cannot be read.
pub fn grading_of(g: &serde_json::Value) -> Option<stancf::Grading> {
    if g.is_null() {
        return Some(stancf::Grading::Uniform);
    }
    if let Some(sections) = g["sections"].as_array() {
        let mut out = Vec::with_capacity(sections.len());
        for s in sections {
            out.push(stancf::MeshSection {
                length: s["length"].as_f64()?,
                elements: s["elements"].as_u64()? as usize,
            });
        }
        return Some(stancf::Grading::Sections(out));
    }
    let toward = match g["toward"].as_str()? {
        "A" => stancf::GradedEnd::A,
        "B" => stancf::GradedEnd::B,
        "both" => stancf::GradedEnd::Both,
        _ => return None,
    };
    let ratio = g["ratio"].as_f64()?;
    Some(stancf::Grading::Geometric { toward, ratio })
}

impl RunInfo {
    pub fn read(dir: &Path) -> io::Result<RunInfo> {
        let path = dir.join("summary.json");
        let text = crate::input_file::read_result_text(&path)?;
        let s: serde_json::Value = serde_json::from_str(&text).map_err(|e| {
            io::Error::new(
                io::ErrorKind::InvalidData,
                format!("{}: {e}", path.display()),
            )
        })?;
        Ok(RunInfo {
            title: s["title"].as_str().unwrap_or("stancf run").to_string(),
            dynamic: s["analysis"].as_str() != Some("static"),
            element_lengths: element_lengths_of(&s),
        })
    }
}

/// The two coordinate axes (0 = x, 1 = y, 2 = z) along which the cable
/// moves most, in ascending order: the plane of the shape plots.
pub fn plane_of_motion(points: impl Iterator<Item = [f64; 3]>) -> (usize, usize) {
    let mut lo = [f64::MAX; 3];
    let mut hi = [f64::MIN; 3];
    for p in points {
        for c in 0..3 {
            lo[c] = lo[c].min(p[c]);
            hi[c] = hi[c].max(p[c]);
        }
    }
    let extent: Vec<f64> = (0..3).map(|c| (hi[c] - lo[c]).max(0.0)).collect();
    // Drop the axis with the smallest extent (z on ties: planar problems).
    let drop = (0..3)
        .rev()
        .min_by(|&a, &b| extent[a].partial_cmp(&extent[b]).expect("finite"))
        .unwrap_or(2);
    let mut axes = (0..3).filter(|&c| c != drop);
    (axes.next().unwrap_or(0), axes.next().unwrap_or(1))
}

/// A node as written: position and (if the file has it) slope r_x.
#[derive(Clone, Copy, Debug)]
pub struct NodeRow {
    pub r: [f64; 3],
    pub slope: Option<[f64; 3]>,
}

/// The nodes of every written step of `nodes.csv`: (t, nodes).
pub fn read_nodes(dir: &Path) -> io::Result<Vec<(f64, Vec<NodeRow>)>> {
    let table = Table::read(&dir.join("nodes.csv"))?;
    let f = "nodes.csv";
    let c = [
        table.need("x", f)?,
        table.need("y", f)?,
        table.need("z", f)?,
    ];
    let d = [table.col("dx_ds"), table.col("dy_ds"), table.col("dz_ds")];
    Ok(by_time(&table)
        .into_iter()
        .map(|(t, rows)| {
            let nodes = rows
                .iter()
                .map(|row| NodeRow {
                    r: [row[c[0]], row[c[1]], row[c[2]]],
                    slope: match d {
                        [Some(a), Some(b), Some(e)] => Some([row[a], row[b], row[e]]),
                        _ => None,
                    },
                })
                .collect();
            (t, nodes)
        })
        .collect())
}

/// The centre line through the nodes: the cubic Hermite interpolation of
/// positions and slopes over each element k of length `element_lengths[k]`
/// (eq. 4; exact for SAC-2, the cubic part of SAC-3), `per_element` points
/// per element; straight segments without slopes or lengths.
pub fn centre_line(
    nodes: &[NodeRow],
    element_lengths: Option<&[f64]>,
    per_element: usize,
) -> Vec<[f64; 3]> {
    let mut out = Vec::new();
    for (k, pair) in nodes.windows(2).enumerate() {
        let (a, b) = (&pair[0], &pair[1]);
        let l = element_lengths.and_then(|ls| ls.get(k).copied());
        let (Some(da), Some(db), Some(l)) = (a.slope, b.slope, l) else {
            if k == 0 {
                out.push(a.r);
            }
            out.push(b.r);
            continue;
        };
        let first = if k == 0 { 0 } else { 1 };
        for i in first..=per_element {
            let x = i as f64 / per_element as f64;
            let (x2, x3) = (x * x, x * x * x);
            let h = [
                2.0 * x3 - 3.0 * x2 + 1.0,
                l * (x3 - 2.0 * x2 + x),
                -2.0 * x3 + 3.0 * x2,
                l * (x3 - x2),
            ];
            out.push(std::array::from_fn(|c| {
                h[0] * a.r[c] + h[1] * da[c] + h[2] * b.r[c] + h[3] * db[c]
            }));
        }
    }
    out
}

pub(crate) const AXES: [&str; 3] = ["x", "y", "z"];
