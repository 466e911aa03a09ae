//! `[[motions]]` of coupled points (docs/interface.md, "Systems"): an
//! oscillation (M30), or `file = "fairlead.csv"`, a coupled point's
//! absolute positions in time (docs/method.md §11.11). The file is CSV with the header `t,x,y,z` (exactly these four
//! columns, in any order; the column names of `points.csv`, so a point's
//! rows of one run can drive another once its other columns are
//! dropped), one row per time, times strictly increasing, at least 2
//! rows. Blank lines are skipped. Every problem names the file and its
//! line.

use super::analysis::Analysis;
use super::context::Ctx;
use super::raw::RawMotion;
use super::system_parts::{PointType, SystemPoint};
use super::ScenarioError;
use stancf::constraints::{MotionTable, Oscillation};
use stancf::motion::CoupledMotion;
use stancf::system::{extent, table_start_mismatch, TABLE_START_TOLERANCE};
use std::path::Path;

/// `[[motions]]`: `point` (a coupled point's id, one motion each), and
/// either `amplitude` (m, required), `period` (s, > 0, required), `phase`
/// (degrees, default 0), `ramp` (s, >= 0, default 0):
/// r(t) = r0 + f(t) amplitude sin(2 pi t / period + phase) (M30); or
/// `file` (relative to the scenario at `path`), a table of absolute
/// positions (M39) that covers the run, [0, duration], and starts at the
/// point's position (within 1e-9 of the system's size: `lengths` of the
/// lines and the points' positions).
pub(super) fn motions(
    ctx: &Ctx,
    raw: &[RawMotion],
    points: &mut [SystemPoint],
    lengths: &[f64],
    path: &Path,
    analysis: &Analysis,
) -> Result<(), ScenarioError> {
    let size = extent(lengths.iter().copied(), points.iter().map(|p| p.position));
    let mut moved = vec![false; points.len()];
    for (i, r) in raw.iter().enumerate() {
        let key = |k: &str| format!("motions[{i}].{k}");
        let id = ctx.required(&key("point"), r.point)?;
        let Some(p) = points.iter().position(|p| p.id == id) else {
            return Err(ctx.err(&key("point"), format!("point {id} is not defined")));
        };
        if points[p].kind != PointType::Coupled {
            return Err(ctx.err(&key("point"), format!("point {id} is not a coupled point")));
        }
        if moved[p] {
            return Err(ctx.err(&key("point"), format!("point {id} already has a motion")));
        }
        moved[p] = true;
        if let Some(file) = &r.file {
            let table = table_motion(ctx, i, r, file, path)?;
            check_table(ctx, &key("file"), file, &table, &points[p], size, analysis)?;
            points[p].motion = table.into();
            points[p].motion_file = Some(file.clone());
            continue;
        }
        let amplitude = ctx.vector(
            &key("amplitude"),
            &ctx.required(&key("amplitude"), r.amplitude.clone())?,
        )?;
        let oscillation = Oscillation {
            amplitude,
            period: ctx.required_positive(&key("period"), r.period)?,
            phase: ctx
                .finite(&key("phase"), r.phase.unwrap_or(0.0))?
                .to_radians(),
            ramp: ctx.non_negative(&key("ramp"), r.ramp.unwrap_or(0.0))?,
        };
        check_oscillation_scales(ctx, &key(""), &oscillation)?;
        points[p].motion = CoupledMotion::Oscillation(oscillation);
    }
    Ok(())
}

/// An oscillation's amplitude, period, ramp and peak speed |a| 2 pi / T
/// within the range the solver computes in
/// ([`crate::scale_range::MAX_SCALE`]); `key` is `motions[i].`.
fn check_oscillation_scales(ctx: &Ctx, key: &str, o: &Oscillation) -> Result<(), ScenarioError> {
    use crate::scale_range::MAX_SCALE;
    let amplitude = o.amplitude.iter().map(|a| a.abs()).fold(0.0, f64::max);
    let speed = amplitude * 2.0 * std::f64::consts::PI / o.period;
    for (k, what, v, divisor) in [
        ("amplitude", "the amplitude", amplitude, false),
        ("period", "the period", o.period, true),
        ("ramp", "the ramp", o.ramp, false),
        (
            "amplitude, period",
            "the peak speed |a| 2 pi / T",
            speed,
            false,
        ),
    ] {
        let out = !v.is_finite() || v > MAX_SCALE || (divisor && v < 1.0 / MAX_SCALE);
        if out {
            let keys: Vec<String> = k.split(", ").map(|k| format!("{key}{k}")).collect();
            return Err(ctx.err(
                &keys.join(", "),
                format!(
                    "{what} is {v:e}, out of the range the solver computes in (1e-150 to \
                     1e150 in SI units): check the value and its unit"
                ),
            ));
        }
    }
    Ok(())
}

/// A motion table's positions, time gaps and speeds between rows within
/// the range the solver computes in ([`crate::scale_range::MAX_SCALE`]).
fn table_scales(
    ctx: &Ctx,
    key: &str,
    file: &str,
    table: &MotionTable,
) -> Result<(), ScenarioError> {
    use crate::scale_range::MAX_SCALE;
    let (times, positions) = (table.times(), table.positions());
    let far = positions
        .iter()
        .flat_map(|p| p.iter())
        .fold(0.0f64, |m, c| m.max(c.abs()));
    let mut worst = ("the largest coordinate", far, far > MAX_SCALE);
    for k in 1..times.len() {
        let gap = times[k] - times[k - 1];
        let d = (0..3)
            .map(|c| (positions[k][c] - positions[k - 1][c]).powi(2))
            .sum::<f64>()
            .sqrt();
        let speed = d / gap;
        if gap < 1.0 / MAX_SCALE {
            worst = ("a time step between rows", gap, true);
            break;
        }
        if !speed.is_finite() || speed > MAX_SCALE {
            worst = ("a speed between rows", speed, true);
            break;
        }
    }
    let (what, v, out) = worst;
    if out {
        return Err(ctx.err(
            key,
            format!(
                "{file}: {what} is {v:e}, out of the range the solver computes in (1e-150 to \
                 1e150 in SI units): check the table's values and their units"
            ),
        ));
    }
    Ok(())
}

/// The table of `motions[i].file`, which excludes the oscillation's keys.
fn table_motion(
    ctx: &Ctx,
    i: usize,
    r: &RawMotion,
    file: &str,
    path: &Path,
) -> Result<MotionTable, ScenarioError> {
    for (present, name) in [
        (r.amplitude.is_some(), "amplitude"),
        (r.period.is_some(), "period"),
        (r.phase.is_some(), "phase"),
        (r.ramp.is_some(), "ramp"),
    ] {
        if present {
            return Err(ctx.err(
                &format!("motions[{i}].{name}"),
                format!(
                    "a motion is either a file (\"{}\") or an oscillation (amplitude, period, \
                     phase, ramp), not both",
                    super::clip(file, 60)
                ),
            ));
        }
    }
    let full = path.parent().unwrap_or(Path::new("")).join(file);
    read_motion_file(&full, &full.display().to_string())
        .map_err(|e| ctx.err(&format!("motions[{i}].file"), e))
}

/// A table must cover the run, [0, duration] (0 for statics), and start
/// at its point's position.
fn check_table(
    ctx: &Ctx,
    key: &str,
    file: &str,
    table: &MotionTable,
    point: &SystemPoint,
    size: f64,
    analysis: &Analysis,
) -> Result<(), ScenarioError> {
    table_scales(ctx, key, file, table)?;
    let (first, last) = table.span();
    let end = match analysis.kind {
        super::AnalysisKind::Dynamic => analysis.duration,
        super::AnalysisKind::Static => 0.0,
    };
    if first > 0.0 || last < end {
        return Err(ctx.err(
            key,
            format!(
                "{file}: the table runs from t = {first} to t = {last} s and does not cover \
                 the run, from t = 0 to t = {end} s"
            ),
        ));
    }
    if let Some(d) = table_start_mismatch(&point.position, table, size) {
        return Err(ctx.err(
            key,
            format!(
                "{file}: the table's position at t = 0, {:?}, is {d:e} m from point {}'s \
                 position {:?} (allowed: {TABLE_START_TOLERANCE:e} of the system's size, \
                 {size} m)",
                table.state(0.0).0,
                point.id,
                point.position
            ),
        ));
    }
    Ok(())
}

/// Why a motion file was refused: `<file> line <n>: <what>`, or
/// `<file>: <what>` for the whole file.
pub(super) type MotionFileError = String;

/// Reads and checks the table of `path` (as the scenario wrote it:
/// `shown`).
pub(super) fn read_motion_file(path: &Path, shown: &str) -> Result<MotionTable, MotionFileError> {
    let text = crate::input_file::read_text(path).map_err(|e| format!("{shown}: {e}"))?;
    parse_motion_table(&text, shown)
}

/// The table in `text` (see the module's doc).
pub(super) fn parse_motion_table(text: &str, shown: &str) -> Result<MotionTable, MotionFileError> {
    let mut lines = crate::echo::text_lines(text)
        .enumerate()
        .map(|(i, l)| (i + 1, l.trim()))
        .filter(|(_, l)| !l.is_empty());
    let Some((header_line, header)) = lines.next() else {
        return Err(format!(
            "{shown}: the motion file is empty (it needs the header t,x,y,z and rows)"
        ));
    };
    let columns = header_columns(header).map_err(|e| format!("{shown} line {header_line}: {e}"))?;
    let mut times = Vec::new();
    let mut positions = Vec::new();
    for (n, line) in lines {
        let at = |msg: String| format!("{shown} line {n}: {msg}");
        let fields: Vec<&str> = line.split(',').map(str::trim).collect();
        if fields.len() != 4 {
            return Err(at(format!(
                "{} values, the header has 4 (t, x, y, z)",
                fields.len()
            )));
        }
        let mut row = [0.0; 4];
        for (k, field) in fields.iter().enumerate() {
            let value: f64 = field.parse().map_err(|_| {
                at(format!(
                    "\"{}\" in column {} is not a number",
                    super::clip(field, 40),
                    NAMES[columns[k]]
                ))
            })?;
            if !value.is_finite() {
                return Err(at(format!(
                    "{} = {value} is not a finite number",
                    NAMES[columns[k]]
                )));
            }
            row[columns[k]] = value;
        }
        if let Some(&last) = times.last() {
            if row[0] <= last {
                return Err(at(format!(
                    "t = {} does not follow t = {last}: times must increase strictly",
                    row[0]
                )));
            }
        }
        times.push(row[0]);
        positions.push([row[1], row[2], row[3]]);
    }
    if times.len() < 2 {
        return Err(format!(
            "{shown}: the motion file has {} row(s); the interpolation needs at least 2",
            times.len()
        ));
    }
    MotionTable::new(times, positions).map_err(|e| format!("{shown}: {}", e.message))
}

const NAMES: [&str; 4] = ["t", "x", "y", "z"];

/// Which of t, x, y, z each column holds.
fn header_columns(header: &str) -> Result<[usize; 4], String> {
    let names: Vec<&str> = header.split(',').map(str::trim).collect();
    let mut out = [0usize; 4];
    let mut seen = [false; 4];
    // The line is quoted only when it looks like a table's header (a few
    // short names between commas): a file that is no motion table at all
    // (a password file, a binary) is not echoed.
    let plausible = names.len() > 1
        && names.iter().all(|n| {
            n.len() <= 12
                && n.chars()
                    .all(|c| c.is_ascii_alphanumeric() || "_ ()[]/".contains(c))
        });
    let bad = || {
        if plausible {
            format!(
                "the header must name the columns t, x, y and z (in any order), got \"{}\"",
                super::clip(header, 60)
            )
        } else {
            "the first line is not a header of column names: a motion file is a CSV table \
             with the header t,x,y,z and rows of 4 numbers"
                .to_string()
        }
    };
    if names.len() != 4 {
        return Err(bad());
    }
    for (k, name) in names.iter().enumerate() {
        let Some(c) = NAMES.iter().position(|n| n == name) else {
            return Err(bad());
        };
        if seen[c] {
            return Err(bad());
        }
        seen[c] = true;
        out[k] = c;
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn columns_may_come_in_any_order_and_blank_lines_are_skipped() {
        let t = parse_motion_table("z, t,x,y\n\n3,0,1,2\n6,1,4,5\n", "m.csv").unwrap();
        assert_eq!(t.times(), &[0.0, 1.0]);
        assert_eq!(t.positions(), &[[1.0, 2.0, 3.0], [4.0, 5.0, 6.0]]);
    }

    #[test]
    fn each_bad_table_names_its_line() {
        for (text, want) in [
            ("", "m.csv: the motion file is empty"),
            ("t,x,y\n0,0,0\n", "m.csv line 1: the header"),
            (
                "root:x:0:0:root:/root:/bin/bash\n",
                "m.csv line 1: the first line is not a header of column names",
            ),
            ("t,x,y,x\n", "m.csv line 1: the header"),
            (
                "t,x,y,z\n0,0,0,0\n1,0,a,0\n",
                "m.csv line 3: \"a\" in column y",
            ),
            ("t,x,y,z\n0,0,0,0\n1,0,inf,0\n", "m.csv line 3: y = inf"),
            ("t,x,y,z\n0,0,0,0\n1,0,0\n", "m.csv line 3: 3 values"),
            (
                "t,x,y,z\n0,0,0,0\n0,1,0,0\n",
                "m.csv line 3: t = 0 does not follow",
            ),
            ("t,x,y,z\n0,0,0,0\n", "m.csv: the motion file has 1 row(s)"),
        ] {
            let e = parse_motion_table(text, "m.csv").unwrap_err();
            assert!(e.starts_with(want), "{text:?}: {e}");
        }
    }
}
