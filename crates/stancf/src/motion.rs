//! Motions of coupled points (docs/method.md §11.1, §11.11): a periodic
//! oscillation about the point's position (M30), or absolute positions
//! tabulated in time and interpolated by a not-a-knot cubic spline (M39).
//!
//! A step prescribes the position r and the velocity r_dot of every line
//! end at a coupled point at the time nodes of its slab (§6.1), so a
//! motion is evaluated for both at any t; the P2 predictor (§4.8) and
//! the energy balance (M24) see its acceleration through consecutive
//! steps, which the spline keeps continuous (K2).
//!
//! [`CoupledMotion`] is the one type a coupled point carries. A coupling
//! code that drives the point sets its motion over each coupling interval
//! from the positions (and velocities) it gives ([`MotionInterval`],
//! (K1)-(K2), docs/method.md §13.2): every consumer evaluates a motion
//! through [`CoupledMotion::state_at`] and [`CoordinateMotion`].

mod coordinate;
mod interval;

pub use coordinate::{ramp_factor, CoordinateMotion, HarmonicMotion, Oscillation};
pub use interval::{IntervalMotion, MotionInterval};

use crate::error::ModelError;
use std::sync::Arc;

/// How a coupled point moves. Cheap to clone (a table is shared).
#[derive(Clone, Debug, PartialEq)]
pub enum CoupledMotion {
    /// `r(t) = r0 + f(t) a sin(2 pi t / T + phi)` about the point's
    /// position r0 (M30).
    Oscillation(Oscillation),
    /// Absolute positions interpolated from a table (M39); its position
    /// at t = 0 is the point's.
    Table(Arc<MotionTable>),
    /// Set by a coupling code for the current coupling interval, (K1) or
    /// (K2); absolute positions.
    Interval(MotionInterval),
}

impl CoupledMotion {
    /// No motion: the point stays where it is.
    pub const NONE: CoupledMotion = CoupledMotion::Oscillation(Oscillation::NONE);

    /// Position and velocity at t of a point whose position at t = 0 is
    /// `position`.
    pub fn state_at(&self, position: &[f64; 3], t: f64) -> ([f64; 3], [f64; 3]) {
        match self {
            CoupledMotion::Oscillation(o) => {
                let m = |c: usize| o.coordinate_motion(position, c);
                (
                    std::array::from_fn(|c| m(c).value(t)),
                    std::array::from_fn(|c| m(c).rate_at(t)),
                )
            }
            CoupledMotion::Table(table) => table.state(t),
            CoupledMotion::Interval(i) => i.state(t),
        }
    }

    /// The motion of component k of a point at `position` moving so.
    pub fn coordinate_motion(&self, position: &[f64; 3], k: usize) -> CoordinateMotion {
        match self {
            CoupledMotion::Oscillation(o) => o.coordinate_motion(position, k),
            CoupledMotion::Table(table) => CoordinateMotion::Table {
                table: Arc::clone(table),
                component: k,
            },
            CoupledMotion::Interval(i) => CoordinateMotion::Interval(i.coordinate(k)),
        }
    }

    /// Whether the point actually moves.
    pub fn moves(&self) -> bool {
        match self {
            CoupledMotion::Oscillation(o) => {
                o.period > 0.0 && o.amplitude.iter().any(|&a| a != 0.0)
            }
            CoupledMotion::Table(table) => (0..3).any(|c| !table.is_constant(c)),
            CoupledMotion::Interval(i) => (0..3).any(|c| !i.coordinate(c).is_still()),
        }
    }

    /// The table, if the motion is tabulated.
    pub fn table(&self) -> Option<&MotionTable> {
        match self {
            CoupledMotion::Table(t) => Some(t),
            CoupledMotion::Oscillation(_) | CoupledMotion::Interval(_) => None,
        }
    }
}

impl From<Oscillation> for CoupledMotion {
    fn from(o: Oscillation) -> Self {
        CoupledMotion::Oscillation(o)
    }
}

impl From<MotionTable> for CoupledMotion {
    fn from(t: MotionTable) -> Self {
        CoupledMotion::Table(Arc::new(t))
    }
}

/// Positions r_i at strictly increasing times t_i, interpolated by the
/// not-a-knot cubic spline of each component (M39): C2, exact for cubic
/// polynomials, and fourth-order accurate in the spacing on the whole
/// table (a natural spline's zero end curvature would cost second order
/// near the ends). Two rows interpolate linearly, three by the parabola
/// through them. Outside [t_0, t_n-1] the end intervals' cubics continue.
#[derive(Clone, Debug, PartialEq)]
pub struct MotionTable {
    times: Vec<f64>,
    positions: Vec<[f64; 3]>,
    /// The spline's second derivative at each time, per component.
    curvature: Vec<[f64; 3]>,
}

impl MotionTable {
    /// The table of `positions` at `times` (same length, at least 2,
    /// finite, times strictly increasing). Key in errors: `motion`.
    pub fn new(times: Vec<f64>, positions: Vec<[f64; 3]>) -> Result<Self, ModelError> {
        let err = |m: String| Err(ModelError::invalid("motion", m));
        if times.len() != positions.len() {
            return err(format!(
                "{} times but {} positions",
                times.len(),
                positions.len()
            ));
        }
        if times.len() < 2 {
            return err(format!(
                "a table needs at least 2 rows, got {}",
                times.len()
            ));
        }
        for (i, (t, r)) in times.iter().zip(&positions).enumerate() {
            if !t.is_finite() || r.iter().any(|x| !x.is_finite()) {
                return err(format!("row {i} is not finite: t = {t}, r = {r:?}"));
            }
            if i > 0 && *t <= times[i - 1] {
                return err(format!(
                    "times must increase strictly: row {i} has t = {t} after {}",
                    times[i - 1]
                ));
            }
        }
        let curvature = not_a_knot_curvatures(&times, &positions);
        Ok(MotionTable {
            times,
            positions,
            curvature,
        })
    }

    pub fn times(&self) -> &[f64] {
        &self.times
    }

    pub fn positions(&self) -> &[[f64; 3]] {
        &self.positions
    }

    /// Rows.
    pub fn len(&self) -> usize {
        self.times.len()
    }

    /// Never true (a table has at least 2 rows).
    pub fn is_empty(&self) -> bool {
        self.times.is_empty()
    }

    /// The first and last time.
    pub fn span(&self) -> (f64, f64) {
        (self.times[0], self.times[self.times.len() - 1])
    }

    /// Whether component c has the same value in every row.
    pub fn is_constant(&self, c: usize) -> bool {
        self.positions.iter().all(|r| r[c] == self.positions[0][c])
    }

    /// Position and velocity at t (M39).
    pub fn state(&self, t: f64) -> ([f64; 3], [f64; 3]) {
        let i = self.interval(t);
        let mut r = [0.0; 3];
        let mut v = [0.0; 3];
        for c in 0..3 {
            (r[c], v[c], _) = self.evaluate(i, c, t);
        }
        (r, v)
    }

    /// Component c's value, rate and second rate at t (M39).
    pub fn component(&self, c: usize, t: f64) -> (f64, f64, f64) {
        self.evaluate(self.interval(t), c, t)
    }

    /// The interval [t_i, t_i+1] whose cubic holds at t (the first or
    /// last outside the table).
    fn interval(&self, t: f64) -> usize {
        let after = self.times.partition_point(|&ti| ti <= t);
        after.clamp(1, self.times.len() - 1) - 1
    }

    /// (M39) on interval i: with h = t_i+1 - t_i, a = (t_i+1 - t) / h,
    /// b = 1 - a, S = a y_i + b y_i+1 + h^2/6 ((a^3 - a) M_i + (b^3 - b) M_i+1).
    fn evaluate(&self, i: usize, c: usize, t: f64) -> (f64, f64, f64) {
        let h = self.times[i + 1] - self.times[i];
        let a = (self.times[i + 1] - t) / h;
        let b = (t - self.times[i]) / h;
        let (y0, y1) = (self.positions[i][c], self.positions[i + 1][c]);
        let (m0, m1) = (self.curvature[i][c], self.curvature[i + 1][c]);
        let value = a * y0 + b * y1 + h * h / 6.0 * ((a * a * a - a) * m0 + (b * b * b - b) * m1);
        let rate = (y1 - y0) / h + h / 6.0 * ((1.0 - 3.0 * a * a) * m0 + (3.0 * b * b - 1.0) * m1);
        (value, rate, a * m0 + b * m1)
    }
}

/// The second derivatives M_i of the not-a-knot spline through (t_i, y_i)
/// (M40): S' continuous at the interior knots,
/// `h_i-1 M_i-1 + 2 (h_i-1 + h_i) M_i + h_i M_i+1 = 6 (d_i - d_i-1)`,
/// d_i = (y_i+1 - y_i) / h_i, and S''' continuous at t_1 and t_n-2, which
/// gives M_0 and M_n-1 from their neighbours; substituted into the first
/// and last rows, a diagonally dominant tridiagonal system for
/// M_1..M_n-2 (Thomas algorithm). n = 3: the parabola (M constant);
/// n = 2: a line (M = 0).
fn not_a_knot_curvatures(t: &[f64], y: &[[f64; 3]]) -> Vec<[f64; 3]> {
    let n = t.len();
    let h: Vec<f64> = t.windows(2).map(|w| w[1] - w[0]).collect();
    let slope = |i: usize, c: usize| (y[i + 1][c] - y[i][c]) / h[i];
    let mut out = vec![[0.0; 3]; n];
    if n == 3 {
        for c in 0..3 {
            let m = 2.0 * (slope(1, c) - slope(0, c)) / (h[0] + h[1]);
            out.iter_mut().for_each(|r| r[c] = m);
        }
    }
    if n < 4 {
        return out;
    }
    // Rows i = 1..=n-2 (index i - 1): lower, diagonal, upper.
    let m = n - 2;
    let mut lower: Vec<f64> = (1..=m).map(|i| h[i - 1]).collect();
    let mut diag: Vec<f64> = (1..=m).map(|i| 2.0 * (h[i - 1] + h[i])).collect();
    let mut upper: Vec<f64> = (1..=m).map(|i| h[i]).collect();
    // M_0 = ((h0 + h1) M_1 - h0 M_2) / h1 into row 1.
    diag[0] += h[0] * (h[0] + h[1]) / h[1];
    upper[0] -= h[0] * h[0] / h[1];
    // M_n-1 = ((h_n-3 + h_n-2) M_n-2 - h_n-2 M_n-3) / h_n-3 into row n-2.
    let (hp, hl) = (h[n - 3], h[n - 2]);
    diag[m - 1] += hl * (hp + hl) / hp;
    lower[m - 1] -= hl * hl / hp;
    // Forward elimination (shared by the three components).
    for k in 1..m {
        let f = lower[k] / diag[k - 1];
        diag[k] -= f * upper[k - 1];
        lower[k] = f;
    }
    for c in 0..3 {
        let mut rhs: Vec<f64> = (1..=m)
            .map(|i| 6.0 * (slope(i, c) - slope(i - 1, c)))
            .collect();
        for k in 1..m {
            rhs[k] -= lower[k] * rhs[k - 1];
        }
        rhs[m - 1] /= diag[m - 1];
        for k in (0..m - 1).rev() {
            rhs[k] = (rhs[k] - upper[k] * rhs[k + 1]) / diag[k];
        }
        for (k, v) in rhs.iter().enumerate() {
            out[k + 1][c] = *v;
        }
        out[0][c] = ((h[0] + h[1]) * out[1][c] - h[0] * out[2][c]) / h[1];
        out[n - 1][c] = ((hp + hl) * out[n - 2][c] - hl * out[n - 3][c]) / hp;
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    fn sampled(n: usize, f: impl Fn(f64) -> [f64; 3]) -> MotionTable {
        let times: Vec<f64> = (0..n)
            .map(|i| i as f64 / (n - 1) as f64 + 0.01 * ((i * 7) % 3) as f64 / n as f64)
            .collect();
        let positions = times.iter().map(|&t| f(t)).collect();
        MotionTable::new(times, positions).unwrap()
    }

    #[test]
    fn the_spline_reproduces_a_cubic_on_an_uneven_table_and_beyond() {
        let f = |t: f64| [1.0 + 2.0 * t - t * t + 0.5 * t * t * t, -t * t * t, 3.0];
        let df = |t: f64| [2.0 - 2.0 * t + 1.5 * t * t, -3.0 * t * t, 0.0];
        let table = sampled(9, f);
        for k in 0..=50 {
            let t = -0.1 + 1.2 * k as f64 / 50.0;
            let (r, v) = table.state(t);
            for c in 0..3 {
                assert!((r[c] - f(t)[c]).abs() < 1e-13, "r at {t}");
                assert!((v[c] - df(t)[c]).abs() < 1e-12, "v at {t}");
            }
        }
    }

    #[test]
    fn short_tables_are_a_line_and_a_parabola() {
        let line = MotionTable::new(vec![0.0, 2.0], vec![[0.0; 3], [2.0, 4.0, 0.0]]).unwrap();
        assert_eq!(line.state(0.5), ([0.5, 1.0, 0.0], [1.0, 2.0, 0.0]));
        let p = |t: f64| 3.0 * t * t - t;
        let times = vec![0.0, 0.3, 1.0];
        let parabola = MotionTable::new(
            times.clone(),
            times.iter().map(|&t| [p(t), 0.0, 0.0]).collect(),
        )
        .unwrap();
        let (value, rate, second) = parabola.component(0, 0.7);
        assert!((value - p(0.7)).abs() < 1e-14);
        assert!((rate - (6.0 * 0.7 - 1.0)).abs() < 1e-13);
        assert!((second - 6.0).abs() < 1e-12);
    }

    #[test]
    fn a_bad_table_is_refused_by_row() {
        let bad = |t: Vec<f64>| MotionTable::new(t.clone(), vec![[0.0; 3]; t.len()]);
        assert!(bad(vec![0.0]).unwrap_err().message.contains("at least 2"));
        let e = bad(vec![0.0, 1.0, 1.0]).unwrap_err();
        assert!(e.message.contains("row 2"), "{e}");
        let e = bad(vec![0.0, f64::NAN]).unwrap_err();
        assert!(e.message.contains("row 1"), "{e}");
    }
}
