//! The design statistics of a system run (docs/interface.md, "Design
//! statistics"), gathered from the moments the run writes, at or after
//! `output.statistics_after` (t0):
//!
//! - each attached line end's tension T_k at the written moments t_k >= t0:
//!   its largest value and the first time it is reached, its smallest,
//!   its mean and its standard deviation
//!
//!   ```text
//!     mean = (1/n) sum_k T_k,    std = sqrt((1/n) sum_k (T_k - mean)^2)
//!   ```
//!
//!   (the population's, numpy's default ddof = 0), accumulated by
//!   Welford's update so that a long run loses no digits to cancellation;
//! - each line type with a breaking load: MBL / max T over the ends of its
//!   lines (the safety factor);
//! - each free or coupled point and body: its largest offset, the distance
//!   of its position (a body's reference point) from where it was at the
//!   run's first written moment (the static equilibrium, or the start).
//!
//! They are taken from the written samples (the values tensions.csv,
//! points.csv and bodies.csv hold, to the bit), whether or not those
//! files are written (`output.files`), so that a sweep's runs may leave
//! the tables out and keep their statistics.

use super::rows::SystemRow;
use crate::output::json_num;
use crate::scenario::{BodyType, PointType, SystemScenario};
use serde_json::{json, Value};

/// The running moments of one sampled quantity.
#[derive(Clone, Copy, Debug)]
struct Running {
    n: usize,
    mean: f64,
    /// Sum of squared deviations from the running mean (Welford).
    m2: f64,
    max: f64,
    time_of_max: f64,
    min: f64,
}

impl Running {
    fn first(t: f64, x: f64) -> Self {
        Running {
            n: 1,
            mean: x,
            m2: 0.0,
            max: x,
            time_of_max: t,
            min: x,
        }
    }

    /// Welford's update: mean_n = mean_(n-1) + (x - mean_(n-1)) / n,
    /// M2_n = M2_(n-1) + (x - mean_(n-1)) (x - mean_n).
    fn add(&mut self, t: f64, x: f64) {
        self.n += 1;
        let d = x - self.mean;
        self.mean += d / self.n as f64;
        self.m2 += d * (x - self.mean);
        if x > self.max {
            self.max = x;
            self.time_of_max = t;
        }
        self.min = self.min.min(x);
    }

    /// The population standard deviation sqrt(M2 / n).
    fn std(&self) -> f64 {
        (self.m2 / self.n as f64).sqrt()
    }
}

/// The largest offset of one point or body from its first written place.
#[derive(Clone, Copy, Debug)]
struct Offset {
    /// Its index in the scenario's points or bodies.
    index: usize,
    id: i64,
    start: Option<[f64; 3]>,
    largest: Option<f64>,
}

impl Offset {
    fn new(index: usize, id: i64) -> Self {
        Offset {
            index,
            id,
            start: None,
            largest: None,
        }
    }

    /// Takes the position `x` of a written moment (`counted`: in the
    /// statistics' window).
    fn add(&mut self, x: [f64; 3], counted: bool) {
        let start = *self.start.get_or_insert(x);
        if counted {
            let d = norm([x[0] - start[0], x[1] - start[1], x[2] - start[2]]);
            self.largest = Some(self.largest.map_or(d, |m| m.max(d)));
        }
    }
}

fn norm(v: [f64; 3]) -> f64 {
    (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt()
}

/// The statistics of a run, fed each written moment (see the module).
#[derive(Clone, Debug, Default)]
pub(super) struct Statistics {
    /// t0 (s).
    after: f64,
    /// The written moments counted.
    moments: usize,
    /// Per line, its ends A and B (None: loose, or no moment yet).
    ends: Vec<[Option<Running>; 2]>,
    points: Vec<Offset>,
    bodies: Vec<Offset>,
}

impl Statistics {
    /// Empty statistics of the scenario's lines, free and coupled points
    /// and bodies, from `output.statistics_after`.
    pub(super) fn new(sc: &SystemScenario) -> Self {
        let moved = |p: &PointType| matches!(p, PointType::Free | PointType::Coupled);
        Statistics {
            after: sc.statistics_after,
            moments: 0,
            ends: vec![[None; 2]; sc.lines.len()],
            points: (sc.points.iter().enumerate())
                .filter(|(_, p)| moved(&p.kind))
                .map(|(i, p)| Offset::new(i, p.id))
                .collect(),
            bodies: (sc.bodies.iter().enumerate())
                .filter(|(_, b)| matches!(b.kind, BodyType::Free | BodyType::Coupled))
                .map(|(i, b)| Offset::new(i, b.id))
                .collect(),
        }
    }

    /// Takes the moment `row`, written at the time `t`.
    pub(super) fn add(&mut self, t: f64, row: &SystemRow) {
        let counted = t >= self.after;
        for p in &mut self.points {
            if let Some((x, _, _)) = row.points.get(p.index) {
                p.add(*x, counted);
            }
        }
        for b in &mut self.bodies {
            if let Some(body) = row.bodies.get(b.index) {
                b.add(body.motion.position, counted);
            }
        }
        if !counted {
            return;
        }
        self.moments += 1;
        for (acc, ends) in self.ends.iter_mut().zip(&row.ends) {
            for (a, e) in acc.iter_mut().zip(ends) {
                let Some(e) = e else { continue };
                let tension = e.tension();
                match a {
                    Some(r) => r.add(t, tension),
                    None => *a = Some(Running::first(t, tension)),
                }
            }
        }
    }

    /// summary.json's `statistics` (docs/interface.md, "Design
    /// statistics"); its lists are empty when no moment was counted.
    pub(super) fn to_json(&self, sc: &SystemScenario) -> Value {
        let mut ends = Vec::new();
        for (line, acc) in sc.lines.iter().zip(&self.ends) {
            for (name, r) in ["A", "B"].iter().zip(acc) {
                let Some(r) = r else { continue };
                ends.push(json!({
                    "line": line.id,
                    "end": name,
                    "max": json_num(r.max),
                    "time_of_max": json_num(r.time_of_max),
                    "min": json_num(r.min),
                    "mean": json_num(r.mean),
                    "std": json_num(r.std()),
                }));
            }
        }
        let types: Vec<Value> = (sc.line_types.iter().enumerate())
            .filter_map(|(k, t)| {
                let mbl = t.mbl?;
                let largest = (sc.lines.iter().zip(&self.ends))
                    .filter(|(l, _)| l.line_type == k)
                    .flat_map(|(_, acc)| acc.iter().flatten().map(|r| r.max))
                    .reduce(f64::max)?;
                Some(json!({
                    "type": t.name,
                    "mbl": json_num(mbl),
                    "max_tension": json_num(largest),
                    "safety_factor": json_num(mbl / largest),
                }))
            })
            .collect();
        let offsets = |list: &[Offset]| -> Vec<Value> {
            list.iter()
                .filter_map(|o| {
                    let d = o.largest?;
                    Some(json!({"id": o.id, "max_offset": json_num(d)}))
                })
                .collect()
        };
        json!({
            "after": json_num(self.after),
            "moments": self.moments,
            "line_ends": ends,
            "line_types": types,
            "points": offsets(&self.points),
            "bodies": offsets(&self.bodies),
        })
    }
}

#[cfg(test)]
mod tests {
    use super::Running;

    /// Welford's moments equal the two-pass formulas on samples with a
    /// large mean and a small spread (where the one-pass sum of squares
    /// loses its digits): mean 1e6 + 0.5, population variance 1.25.
    #[test]
    fn welfords_moments_are_the_two_pass_ones() {
        let xs = [1e6 - 1.0, 1e6, 1e6 + 1.0, 1e6 + 2.0];
        let mut r = Running::first(0.0, xs[0]);
        for (k, x) in xs.iter().enumerate().skip(1) {
            r.add(k as f64, *x);
        }
        let mean = xs.iter().sum::<f64>() / 4.0;
        let var = xs.iter().map(|x| (x - mean) * (x - mean)).sum::<f64>() / 4.0;
        assert_eq!(mean, 1e6 + 0.5);
        assert!((r.mean - mean).abs() <= 1e-15 * mean);
        assert!((r.std() - var.sqrt()).abs() <= 1e-12);
        assert_eq!((r.max, r.time_of_max, r.min), (1e6 + 2.0, 3.0, 1e6 - 1.0));
    }
}
