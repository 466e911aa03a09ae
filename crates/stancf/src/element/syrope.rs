//! Syrope's working curves (docs/method.md §2.12, (V7)-(V9)): the static
//! spring of a polyester rope whose tension-strain curve depends on the
//! largest mean tension Tmax it has carried, as MoorDyn v2 models it
//! (`ELASTIC_SYROPE`, after the Syrope model of Falkenberg et al.).
//!
//! The original working curve (OWC) is a table of total strain x and
//! tension y. The slow strain of a point of it is (V7)
//!
//! ```text
//!   z = x - (1 / beta) ln(1 + beta y / alpha)
//! ```
//!
//! (x less the dynamic spring's stretch under y, the dynamic stiffness
//! being alpha + beta y). Below Tmax the rope follows the working curve
//! WC(Tmax), 30 points from (eps_min, 0) to the OWC's point at Tmax
//! (eps_max, Tmax), shaped by the formula of the rope (V8):
//!
//! ```text
//!   xi = (x - eps_min) / (eps_max - eps_min),  eps_min = x0 + k1 (eps_max - x0)
//!   linear: y = Tmax xi  (k1 >= 1: the slope, eps_min = eps_max - Tmax / k1)
//!   quadratic: y = Tmax xi (k2 xi + 1 - k2);  exp: y = Tmax (1 - e^(k2 xi)) / (1 - e^k2)
//! ```
//!
//! The spring's tension at a slow strain z is the OWC's where z is at or
//! beyond the OWC's point at Tmax (the rope loaded past its history) and
//! the WC's below, both by linear interpolation held at the table's ends,
//! as MoorDyn interpolates. The same curve gives the total strain X(T) at
//! which the tension T is at rest (V9).

use crate::error::ModelError;

/// The working curve's formula (MoorDyn's `WCType`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum WorkingCurveForm {
    Linear,
    Quadratic,
    Exponential,
}

/// A rope's Syrope model: its OWC and working-curve formula, and the
/// dynamic stiffness alpha + beta T.
#[derive(Clone, Debug, PartialEq)]
pub struct Syrope {
    /// OWC: total strain x, tension y, slow strain z (V7).
    x: Vec<f64>,
    y: Vec<f64>,
    z: Vec<f64>,
    pub form: WorkingCurveForm,
    pub k1: f64,
    pub k2: f64,
    /// The dynamic stiffness alpha + beta T (N; MoorDyn's alphaMBL, vbeta).
    pub alpha: f64,
    pub beta: f64,
}

/// The points of a working curve (MoorDyn's nEApointsWC).
pub const WORKING_CURVE_POINTS: usize = 30;

/// The spring at a slow strain: its tension T, dT/dz, the total strain
/// X(T) of the same curve at rest and dX/dT.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SyropeSpring {
    pub tension: f64,
    pub d_tension: f64,
    pub strain_at_rest: f64,
    pub d_strain_at_rest: f64,
}

impl Syrope {
    /// The model of OWC `points` (strain, tension; strains rising) with
    /// the working-curve `form`, `k1`, `k2` and the dynamic stiffness
    /// alpha + beta T. Refused (naming `key`): fewer than 2 points,
    /// strains or tensions not rising, alpha or beta not positive, slow
    /// strains (V7) not rising (MoorDyn refuses it too).
    pub fn new(
        points: &[(f64, f64)],
        form: WorkingCurveForm,
        (k1, k2): (f64, f64),
        (alpha, beta): (f64, f64),
        key: &str,
    ) -> Result<Self, ModelError> {
        let bad = |m: String| Err(ModelError::invalid(key, m));
        if points.len() < 2 {
            return bad(format!(
                "the original working curve has {} points; it needs 2 or more",
                points.len()
            ));
        }
        if !(alpha > 0.0 && beta > 0.0 && alpha.is_finite() && beta.is_finite()) {
            return bad(format!(
                "the dynamic stiffness alpha + beta T needs alpha > 0 and beta > 0 (got {alpha:e}, {beta:e})"
            ));
        }
        if !(k1.is_finite() && k2.is_finite()) {
            return bad("the working curve's k1 and k2 must be finite numbers".into());
        }
        for w in points.windows(2) {
            if !(w[1].0 > w[0].0 && w[1].1 >= w[0].1) {
                return bad(format!(
                    "the original working curve's strains must rise and its tensions not fall: \
                     ({}, {}) is followed by ({}, {})",
                    w[0].0, w[0].1, w[1].0, w[1].1
                ));
            }
        }
        let x: Vec<f64> = points.iter().map(|p| p.0).collect();
        let y: Vec<f64> = points.iter().map(|p| p.1).collect();
        let z: Vec<f64> = points
            .iter()
            .map(|&(x, y)| slow_strain(x, y, alpha, beta))
            .collect();
        if let Some(k) = (1..z.len()).find(|&k| z[k] <= z[k - 1]) {
            return bad(format!(
                "the slow strains x - ln(1 + beta T / alpha) / beta of the original working curve \
                 do not rise at its point {} (strain {}, tension {}): its static stiffness there \
                 exceeds the dynamic alpha + beta T",
                k + 1,
                x[k],
                y[k]
            ));
        }
        Ok(Syrope {
            x,
            y,
            z,
            form,
            k1,
            k2,
            alpha,
            beta,
        })
    }

    /// The OWC's total strain at tension `t`.
    pub fn strain_at(&self, t: f64) -> f64 {
        interpolate(&self.y, &self.x, t).0
    }

    /// The OWC's tension range [first, last].
    pub fn tension_range(&self) -> (f64, f64) {
        (self.y[0], self.y[self.y.len() - 1])
    }

    /// Checks a largest mean tension against the OWC (MoorDyn refuses one
    /// outside its tensions).
    pub fn check_tmax(&self, tmax: f64, key: &str) -> Result<(), ModelError> {
        let (lo, hi) = self.tension_range();
        if tmax.is_finite() && tmax > lo && tmax <= hi {
            let wc = self.working_curve(tmax);
            if let Some(k) = (1..wc.2.len()).find(|&k| wc.2[k] <= wc.2[k - 1]) {
                return Err(ModelError::invalid(
                    key,
                    format!(
                        "the working curve of Tmax {tmax:e} N has slow strains that do not rise \
                         (at its point {}): its stiffness exceeds the dynamic alpha + beta T",
                        k + 1
                    ),
                ));
            }
            return Ok(());
        }
        Err(ModelError::invalid(
            key,
            format!("Tmax0 is {tmax:e} N; it must be above {lo:e} N and at most {hi:e} N, the original working curve's tensions"),
        ))
    }

    /// WC(Tmax) (V8): its total strains, tensions and slow strains.
    pub fn working_curve(&self, tmax: f64) -> (Vec<f64>, Vec<f64>, Vec<f64>) {
        let [x, y, z] = self.working_points(tmax);
        (x.to_vec(), y.to_vec(), z.to_vec())
    }

    /// WC(Tmax) on the stack (the spring evaluates it at every collocation
    /// node of every Newton iteration: no allocation there).
    fn working_points(&self, tmax: f64) -> [[f64; WORKING_CURVE_POINTS]; 3] {
        let eps_max = interpolate(&self.y, &self.x, tmax).0;
        let x0 = self.x[0];
        let eps_min = if self.form == WorkingCurveForm::Linear && self.k1 >= 1.0 {
            eps_max - tmax / self.k1
        } else {
            x0 + self.k1 * (eps_max - x0)
        };
        let n = WORKING_CURVE_POINTS;
        let mut out = [[0.0; WORKING_CURVE_POINTS]; 3];
        for i in 0..n {
            let xi = i as f64 / (n - 1) as f64;
            let xs = eps_min + (eps_max - eps_min) * xi;
            let ys = match self.form {
                WorkingCurveForm::Linear => tmax * xi,
                WorkingCurveForm::Quadratic => tmax * xi * (self.k2 * xi + 1.0 - self.k2),
                WorkingCurveForm::Exponential => {
                    tmax * (1.0 - (self.k2 * xi).exp()) / (1.0 - self.k2.exp())
                }
            };
            out[0][i] = xs;
            out[1][i] = ys;
            out[2][i] = slow_strain(xs, ys, self.alpha, self.beta);
        }
        out
    }

    /// The spring at slow strain `z` under the history `tmax` (the
    /// module's rule): the OWC at or beyond its point at Tmax, else
    /// WC(Tmax).
    pub fn spring(&self, z: f64, tmax: f64) -> SyropeSpring {
        let z_top = interpolate(&self.y, &self.z, tmax).0;
        let curve;
        let (xs, ys, zs) = if z >= z_top {
            (&self.x[..], &self.y[..], &self.z[..])
        } else {
            curve = self.working_points(tmax);
            (&curve[0][..], &curve[1][..], &curve[2][..])
        };
        let (tension, d_tension) = interpolate(zs, ys, z);
        let (strain_at_rest, d_strain_at_rest) = interpolate(ys, xs, tension);
        SyropeSpring {
            tension,
            d_tension,
            strain_at_rest,
            d_strain_at_rest,
        }
    }

    /// The tension at rest at the total strain `eps` under the history
    /// `tmax`: the WC's below eps_max, the OWC's beyond (the static law).
    pub fn tension_at_rest(&self, eps: f64, tmax: f64) -> f64 {
        let eps_max = interpolate(&self.y, &self.x, tmax).0;
        if eps >= eps_max {
            interpolate(&self.x, &self.y, eps).0
        } else {
            let (x, y, _) = self.working_curve(tmax);
            interpolate(&x, &y, eps).0
        }
    }

    /// The slow strain at rest under tension `t` with history `tmax` (on
    /// the OWC above Tmax, else on WC(Tmax)).
    pub fn slow_strain_at_rest(&self, t: f64, tmax: f64) -> f64 {
        if t >= tmax {
            interpolate(&self.y, &self.z, t).0
        } else {
            let (_, y, z) = self.working_curve(tmax);
            interpolate(&y, &z, t).0
        }
    }

    /// The static law's points: WC(Tmax) from (0, 0) (slack up to
    /// eps_min), then the OWC beyond Tmax.
    pub fn static_curve(&self, tmax: f64) -> Vec<(f64, f64)> {
        let (x, y, _) = self.working_curve(tmax);
        let mut out = vec![(0.0, 0.0)];
        out.extend(
            x.iter()
                .zip(&y)
                .map(|(&a, &b)| (a, b))
                .filter(|&(a, _)| a > 0.0),
        );
        out.extend(
            self.x
                .iter()
                .zip(&self.y)
                .map(|(&a, &b)| (a, b))
                .filter(|&(_, b)| b > tmax),
        );
        out
    }
}

/// z = x - ln(1 + beta y / alpha) / beta (V7).
fn slow_strain(x: f64, y: f64, alpha: f64, beta: f64) -> f64 {
    x - (1.0 + beta * y / alpha).ln() / beta
}

/// MoorDyn's linear interpolation of (xp, yp) at x, held at the ends
/// (`interp_factor`: the segment whose upper point is the first at or
/// above x), and its slope there (0 where held).
pub fn interpolate(xp: &[f64], yp: &[f64], x: f64) -> (f64, f64) {
    let n = xp.len();
    if x <= xp[0] {
        return (yp[0], 0.0);
    }
    if x >= xp[n - 1] {
        return (yp[n - 1], 0.0);
    }
    let i = (1..n).find(|&i| x <= xp[i]).unwrap_or(n - 1);
    let slope = (yp[i] - yp[i - 1]) / (xp[i] - xp[i - 1]);
    (yp[i - 1] + slope * (x - xp[i - 1]), slope)
}

#[cfg(test)]
#[path = "syrope_tests.rs"]
mod tests;
