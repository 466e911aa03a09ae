//! A MoorDyn driver file's InputsMode 1: the coupled objects' motions
//! from a time series (docs/interface.md, "MoorDyn driver files"), as
//! OpenFAST's `MoorDyn_Driver` prepares them. Its file is a table: a time
//! column, then the coupled degrees of freedom in MoorDyn's order (the
//! coupled bodies' 6, the coupled rods' 6, the coupled points' 3: their
//! absolute positions); lines starting with `!`, `#` or `%` and blank
//! lines are passed over (NWTC's `ProcessComFile`), values past the
//! columns the deck needs are ignored (its `ParseAry`).
//!
//! The driver samples the table linearly at the coupling times
//! t_i = i dtC, then smooths each column with a zero-phase exponential
//! filter, forward and back:
//!
//! ```text
//!   y_i = 0.1 x_i + 0.9 y_{i-1}   (y_0 = x_0),
//!   r_i = 0.1 y_i + 0.9 r_{i+1}   (r_n = y_n)                        (D1)
//! ```
//!
//! stancf takes the same samples r_i as each coupled point's motion table
//! (the not-a-knot spline through them, docs/method.md §11.11), so both
//! codes are moved the same way. MoorDyn's driver passes r_i as the input
//! at t_{i+1}, one coupling step late; stancf moves the point through r_i
//! at t_i, the time the file gives. The run starts from the static
//! equilibrium with the coupled points at r_0.

use super::system_parts::{PointType, SystemScenario};
use super::ScenarioError;
use crate::moordyn::driver::DriverFile;
use stancf::motion::MotionTable;
use std::path::Path;

/// The driver's time series as read (the raw rows: time and values).
pub(super) struct DriverMotions {
    /// The file as the messages name it.
    shown: String,
    /// As written in the driver file (the points' motion file).
    written: String,
    /// Per row: its 1-based line, then time and values.
    rows: Vec<(usize, Vec<f64>)>,
}

impl DriverMotions {
    /// The last time of the record: the driver ends its run there when
    /// it comes before TMax.
    pub(super) fn last_time(&self) -> f64 {
        self.rows.last().map_or(0.0, |r| r.1[0])
    }
}

/// Reads the InputsFile of driver `d` (relative to the driver's folder
/// `dir`). Refused naming the file and its line: an empty or missing
/// file, a value that is not a finite number, fewer than 2 rows, a time
/// not after the one before, a first time after 0.
pub(super) fn read_inputs(
    d: &DriverFile,
    file: &str,
    dir: &Path,
) -> Result<DriverMotions, ScenarioError> {
    let line_err = |m: String| ScenarioError(format!("{file}: line {}: {m}", d.lines[8]));
    if d.inputs_file.trim().is_empty() {
        return Err(line_err(
            "InputsMode 1 needs InputsFile, the coupled objects' time series".into(),
        ));
    }
    let path = dir.join(&d.inputs_file);
    let shown = path.display().to_string();
    let text = crate::input_file::read_text(&path)
        .map_err(|e| line_err(format!("InputsFile {:?}: {e} ({shown})", d.inputs_file)))?;
    let at = |line: usize, m: String| ScenarioError(format!("{shown}: line {line}: {m}"));
    let mut rows: Vec<(usize, Vec<f64>)> = Vec::new();
    for (k, row) in text.lines().enumerate() {
        let t = row.trim_start();
        if t.is_empty() || t.starts_with(['!', '#', '%']) {
            continue;
        }
        let values: Vec<f64> = t
            .split(|c: char| c.is_whitespace() || c == ',')
            .filter(|w| !w.is_empty())
            .map(|w| w.parse::<f64>().ok().filter(|x| x.is_finite()))
            .collect::<Option<_>>()
            .ok_or_else(|| at(k + 1, format!("{:?} is not a row of numbers", t.trim_end())))?;
        if let Some((_, last)) = rows.last() {
            if values[0] <= last[0] {
                return Err(at(
                    k + 1,
                    format!(
                        "time {} is not after the row before's, {}",
                        values[0], last[0]
                    ),
                ));
            }
        }
        rows.push((k + 1, values));
    }
    match rows.first() {
        None | Some(_) if rows.len() < 2 => Err(at(
            rows.first().map_or(1, |r| r.0),
            "a time series needs at least 2 rows".into(),
        )),
        Some((line, r)) if r[0] > 0.0 => Err(at(
            *line,
            format!(
                "the record starts at t = {}, after the run's start, 0",
                r[0]
            ),
        )),
        _ => Ok(DriverMotions {
            shown,
            written: d.inputs_file.clone(),
            rows,
        }),
    }
}

/// Gives each coupled point of `sc` its motion from `m` over the run
/// (t from 0 to `sc.analysis.duration` every dtC), its position the
/// motion's at t = 0. Refused: a deck with coupled bodies or rods (their
/// driven motion in a run is not built), a row with fewer values than the
/// deck's coupled degrees of freedom need.
pub(super) fn apply(
    m: &DriverMotions,
    sc: &mut SystemScenario,
    file: &str,
    d: &DriverFile,
) -> Result<(), ScenarioError> {
    if let Some(b) = sc.bodies.iter().find(|b| b.is_coupled()) {
        return Err(ScenarioError(format!(
            "{file}: line {}: InputsMode 1 with a coupled body or rod (body {} of the deck): \
             a driver's time series for a body is not built; run it through the coupling API \
             (stancf_step, Simulation.step), which takes a body's 6 degrees of freedom",
            d.lines[7], b.id
        )));
    }
    let mut coupled: Vec<usize> = (0..sc.points.len())
        .filter(|&p| sc.points[p].kind == PointType::Coupled)
        .collect();
    coupled.sort_by_key(|&p| sc.points[p].id);
    let columns = 3 * coupled.len();
    if let Some((line, r)) = m.rows.iter().find(|(_, r)| r.len() < columns + 1) {
        return Err(ScenarioError(format!(
            "{}: line {line}: {} values where the deck's {} coupled points need {} (time, then \
             x y z of each in the order of their ids)",
            m.shown,
            r.len(),
            coupled.len(),
            columns + 1
        )));
    }
    let dt = d.dt_c;
    let samples = (sc.analysis.duration / dt).round() as usize + 1;
    let times: Vec<f64> = (0..samples).map(|i| i as f64 * dt).collect();
    let series: Vec<Vec<f64>> = (0..columns)
        .map(|c| smoothed(&sampled(&m.rows, c + 1, &times)))
        .collect();
    for (k, &p) in coupled.iter().enumerate() {
        let positions: Vec<[f64; 3]> = (0..samples)
            .map(|i| [series[3 * k][i], series[3 * k + 1][i], series[3 * k + 2][i]])
            .collect();
        let table = MotionTable::new(times.clone(), positions.clone())
            .map_err(|e| ScenarioError(format!("{}: {}", m.shown, e.message)))?;
        sc.points[p].position = positions[0];
        sc.points[p].motion = table.into();
        sc.points[p].motion_file = Some(m.written.clone());
    }
    Ok(())
}

/// Column `c` of the rows sampled linearly at `times` (held at the
/// record's ends), as the driver interpolates its input.
fn sampled(rows: &[(usize, Vec<f64>)], c: usize, times: &[f64]) -> Vec<f64> {
    times
        .iter()
        .map(|&t| {
            let k = rows.partition_point(|(_, r)| r[0] <= t);
            match k {
                0 => rows[0].1[c],
                k if k == rows.len() => rows[k - 1].1[c],
                k => {
                    let (a, b) = (&rows[k - 1].1, &rows[k].1);
                    let f = (t - a[0]) / (b[0] - a[0]);
                    a[c] + f * (b[c] - a[c])
                }
            }
        })
        .collect()
}

/// The driver's zero-phase smoothing (D1) of a sampled column.
fn smoothed(x: &[f64]) -> Vec<f64> {
    let mut y = x.to_vec();
    for i in 1..y.len() {
        y[i] = 0.1 * x[i] + 0.9 * y[i - 1];
    }
    let mut r = y.clone();
    for i in (0..r.len().saturating_sub(1)).rev() {
        r[i] = 0.1 * y[i] + 0.9 * r[i + 1];
    }
    r
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_drivers_smoothing_keeps_a_constant_and_a_line_inside() {
        let constant = smoothed(&[2.5; 50]);
        assert!(constant.iter().all(|&v| (v - 2.5).abs() < 1e-15));
        // A ramp of slope 1 per sample is kept away from its ends (zero
        // phase: the forward pass lags 9 samples, the backward pass leads
        // 9); what is left of the ends' transients decays as 0.9^i, at
        // most 9 (0.9^i + 0.9^(n-1-i)).
        let ramp: Vec<f64> = (0..400).map(|i| i as f64).collect();
        let r = smoothed(&ramp);
        let bound = 9.0 * (0.9f64.powi(200) + 0.9f64.powi(199));
        assert!(
            (r[200] - 200.0).abs() <= bound,
            "{} against {bound:e}",
            r[200]
        );
        // Near the start the lag is not yet made up.
        assert!((r[0] - 0.0).abs() > 1.0, "{}", r[0]);
    }

    #[test]
    fn the_driver_samples_its_record_linearly() {
        let rows = vec![
            (1, vec![0.0, 1.0]),
            (2, vec![1.0, 3.0]),
            (3, vec![3.0, 7.0]),
        ];
        let s = sampled(&rows, 1, &[0.0, 0.5, 1.0, 2.0, 3.0, 4.0]);
        assert_eq!(s, vec![1.0, 2.0, 3.0, 5.0, 7.0, 7.0]);
    }
}
