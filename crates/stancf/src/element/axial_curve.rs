//! A nonlinear axial law given as a table of strain and tension
//! (MoorDyn's line type EA given as a curve file; docs/method.md §2.2a,
//! (M4b)): the tension T(eps) linear between the table's points, the
//! axial energy its integral,
//!
//! ```text
//!   T(eps) = T_k + s_k (eps - eps_k),   s_k = (T_k+1 - T_k) / (eps_k+1 - eps_k),   eps_k <= eps <= eps_k+1
//!   U(eps) = U_k + T_k (eps - eps_k) + 1/2 s_k (eps - eps_k)^2,   U_k = int_0^eps_k T     (M4b)
//! ```
//!
//! per unit length, with engineering strain eps = |r_x| - 1. The table
//! starts at (0, 0); beyond its last point the last segment goes on (where
//! MoorDyn holds the last tension, which leaves a line stretched beyond
//! its table without stiffness); below zero strain the first segment goes
//! on (a line that carries compression: the static solve's first path,
//! §2.2), or the law is (M4a)'s zero. The energy is C1 (T continuous)
//! and its second derivative the segment's slope, as (M4a)'s step at
//! zero: Newton crosses the table's kinks as it crosses the slack one.

use crate::error::ModelError;

/// The table of a nonlinear axial law (M4b).
#[derive(Clone, Debug, PartialEq)]
pub struct AxialCurve {
    strain: Vec<f64>,
    tension: Vec<f64>,
    /// U_k of (M4b) at each point.
    energy: Vec<f64>,
}

impl AxialCurve {
    /// The law through `points` (strain, tension N). Refused, naming
    /// `key`: fewer than two points, a first point other than (0, 0), a
    /// strain not above the one before, a tension below the one before (a
    /// falling tension would give the line a negative stiffness), a value
    /// not finite.
    pub fn new(points: &[(f64, f64)], key: &str) -> Result<Self, ModelError> {
        let bad = |why: String| Err(ModelError::invalid(key, why));
        if points.len() < 2 {
            return bad(format!(
                "has {} points; a curve needs at least two",
                points.len()
            ));
        }
        if let Some((k, p)) = points
            .iter()
            .enumerate()
            .find(|(_, p)| !(p.0.is_finite() && p.1.is_finite()))
        {
            return bad(format!("point {} ({}, {}) is not finite", k + 1, p.0, p.1));
        }
        if points[0] != (0.0, 0.0) {
            return bad(format!(
                "starts at ({}, {}); it must start at zero strain and zero tension",
                points[0].0, points[0].1
            ));
        }
        for k in 1..points.len() {
            let (a, b) = (points[k - 1], points[k]);
            if b.0 <= a.0 {
                return bad(format!(
                    "point {}: the strain {} is not above the one before, {}",
                    k + 1,
                    b.0,
                    a.0
                ));
            }
            if b.1 < a.1 {
                return bad(format!(
                    "point {}: the tension {} N falls below the one before, {} N (a line whose \
                     tension falls as it stretches has no stable state there)",
                    k + 1,
                    b.1,
                    a.1
                ));
            }
        }
        let strain: Vec<f64> = points.iter().map(|p| p.0).collect();
        let tension: Vec<f64> = points.iter().map(|p| p.1).collect();
        let mut energy = vec![0.0; points.len()];
        for k in 1..points.len() {
            energy[k] =
                energy[k - 1] + 0.5 * (tension[k - 1] + tension[k]) * (strain[k] - strain[k - 1]);
        }
        Ok(AxialCurve {
            strain,
            tension,
            energy,
        })
    }

    /// The table's points (strain, tension).
    pub fn points(&self) -> impl Iterator<Item = (f64, f64)> + '_ {
        self.strain
            .iter()
            .copied()
            .zip(self.tension.iter().copied())
    }

    /// The secant stiffness at the table's last point, T_n / eps_n (N):
    /// the EA MoorDyn turns a damping ratio into BA with, and what a seed
    /// takes for the line's EA.
    pub fn secant_stiffness(&self) -> f64 {
        let n = self.strain.len() - 1;
        self.tension[n] / self.strain[n]
    }

    /// The largest slope of the table (N): the stiffest the line gets.
    pub fn largest_slope(&self) -> f64 {
        (1..self.strain.len())
            .map(|k| self.slope(k - 1))
            .fold(0.0, f64::max)
    }

    /// The strain in the middle of the stiffest segment (the first of
    /// equal ones): where the line's axial modes are fastest.
    pub fn stiffest_strain(&self) -> f64 {
        let k = (0..self.strain.len() - 1).fold(0, |best, k| {
            if self.slope(k) > self.slope(best) {
                k
            } else {
                best
            }
        });
        0.5 * (self.strain[k] + self.strain[k + 1])
    }

    /// s_k, the slope of segment k.
    fn slope(&self, k: usize) -> f64 {
        (self.tension[k + 1] - self.tension[k]) / (self.strain[k + 1] - self.strain[k])
    }

    /// The segment holding eps (the first below zero, the last beyond
    /// the table).
    fn segment(&self, eps: f64) -> usize {
        let last = self.strain.len() - 2;
        self.strain[1..=last].partition_point(|&x| x <= eps)
    }

    /// (M4b) at eps: the energy per length U, the tension T = dU/deps and
    /// the slope dT/deps.
    pub fn at(&self, eps: f64) -> (f64, f64, f64) {
        let k = self.segment(eps);
        let (s, d) = (self.slope(k), eps - self.strain[k]);
        let t = self.tension[k] + s * d;
        (self.energy[k] + self.tension[k] * d + 0.5 * s * d * d, t, s)
    }
}

/// (M4b)'s energy density at r_x (engineering strain eps = |r_x| - 1,
/// n = r_x / |r_x|), its gradient and (if asked) its Hessian in r_x:
///
/// ```text
///   dU/dr_x = T n,   d2U/dr_x2 = s n n^T + T (I - n n^T) / |r_x|
/// ```
///
/// (zero where a line without compression, `tension_only`, is
/// shortened: (M4a)).
#[inline]
pub(super) fn curve_energy_terms(
    curve: &AxialCurve,
    rx: &[f64; 3],
    with_hessian: bool,
    tension_only: bool,
) -> (f64, [f64; 3], [[f64; 3]; 3]) {
    let len = (rx[0] * rx[0] + rx[1] * rx[1] + rx[2] * rx[2]).sqrt();
    let eps = len - 1.0;
    if tension_only && eps < 0.0 {
        return (0.0, [0.0; 3], [[0.0; 3]; 3]);
    }
    let (u, t, s) = curve.at(eps);
    let n = [rx[0] / len, rx[1] / len, rx[2] / len];
    let grad = n.map(|c| t * c);
    let mut hess = [[0.0; 3]; 3];
    if with_hessian {
        let c = t / len;
        for i in 0..3 {
            for j in 0..3 {
                hess[i][j] = (s - c) * n[i] * n[j];
            }
            hess[i][i] += c;
        }
    }
    (u, grad, hess)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn rope() -> AxialCurve {
        AxialCurve::new(
            &[(0.0, 0.0), (0.01, 2.0e5), (0.03, 1.0e6), (0.05, 2.4e6)],
            "ea_curve",
        )
        .unwrap()
    }

    /// T is dU/deps and the slope dT/deps, by central differences inside
    /// every segment, below zero and beyond the table; T meets the table's
    /// points; U at a point is the trapezoid sum of the segments before.
    #[test]
    fn the_curves_tension_is_its_energys_derivative_and_meets_its_points() {
        let c = rope();
        for (x, t) in c.points() {
            assert!((c.at(x).1 - t).abs() < 1e-9 * (1.0 + t), "{x} {t}");
        }
        for eps in [-0.004, 0.003, 0.017, 0.029, 0.041, 0.07] {
            let h = 1e-7;
            let (u, t, s) = c.at(eps);
            let du = (c.at(eps + h).0 - c.at(eps - h).0) / (2.0 * h);
            let dt = (c.at(eps + h).1 - c.at(eps - h).1) / (2.0 * h);
            assert!(
                (du - t).abs() < 1e-6 * (1.0 + t.abs()),
                "{eps}: {du} vs {t}"
            );
            assert!((dt - s).abs() < 1e-6 * s, "{eps}: {dt} vs {s}");
            assert!(u.is_finite());
        }
        let u_end =
            0.5 * 2.0e5 * 0.01 + 0.5 * (2.0e5 + 1.0e6) * 0.02 + 0.5 * (1.0e6 + 2.4e6) * 0.02;
        assert!((c.at(0.05).0 - u_end).abs() < 1e-9 * u_end);
        assert!((c.largest_slope() - 7.0e7).abs() < 1e-6);
        assert!((c.secant_stiffness() - 4.8e7).abs() < 1e-6);
    }

    /// The density's gradient and Hessian in r_x against central
    /// differences, stretched into every segment, shortened and beyond
    /// the table, turned off the axes.
    #[test]
    fn the_curves_density_derivatives_in_r_x_are_exact() {
        let c = rope();
        let dir = [0.48, -0.6, 0.64];
        for len in [0.996, 1.004, 1.02, 1.04, 1.07] {
            let rx = dir.map(|d| d * len);
            let (_, g, h) = curve_energy_terms(&c, &rx, true, false);
            let step = 1e-7;
            for k in 0..3 {
                let (mut p, mut m) = (rx, rx);
                p[k] += step;
                m[k] -= step;
                let (up, gp, _) = curve_energy_terms(&c, &p, true, false);
                let (um, gm, _) = curve_energy_terms(&c, &m, true, false);
                let scale = 1.0 + g.iter().map(|x| x.abs()).fold(0.0, f64::max);
                assert!(
                    ((up - um) / (2.0 * step) - g[k]).abs() < 1e-6 * scale,
                    "{len} {k}"
                );
                for i in 0..3 {
                    let fd = (gp[i] - gm[i]) / (2.0 * step);
                    assert!(
                        (fd - h[i][k]).abs() < 1e-6 * c.largest_slope(),
                        "{len} {i} {k}: {fd} {}",
                        h[i][k]
                    );
                }
            }
        }
        let shortened = dir.map(|d| d * 0.99);
        assert_eq!(curve_energy_terms(&c, &shortened, true, true).1, [0.0; 3]);
    }

    #[test]
    fn a_curve_that_falls_or_does_not_start_at_zero_is_refused() {
        let falls = AxialCurve::new(&[(0.0, 0.0), (0.01, 5.0), (0.02, 4.0)], "k").unwrap_err();
        assert!(
            falls
                .to_string()
                .contains("point 3: the tension 4 N falls below"),
            "{falls}"
        );
        let offset = AxialCurve::new(&[(0.01, 0.0), (0.02, 4.0)], "k").unwrap_err();
        assert!(
            offset.to_string().contains("must start at zero strain"),
            "{offset}"
        );
        let back = AxialCurve::new(&[(0.0, 0.0), (0.02, 4.0), (0.02, 5.0)], "k").unwrap_err();
        assert!(
            back.to_string().contains("not above the one before"),
            "{back}"
        );
    }
}
