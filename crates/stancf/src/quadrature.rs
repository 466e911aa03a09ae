//! Gauss-Legendre quadrature on the unit interval.
//!
//! The space-time action (eq. 10) is integrated with a tensor product of two
//! such rules, one over the element's dimensionless material coordinate
//! xi in [0, 1] and one over the slab's dimensionless time tau in [0, 1]
//! (the paper's "3 x 3", "5 x 3" and "6 x 3" integration; docs/method.md
//! §3.1, (M13), and the choice of rules, §3.3-3.4).
//!
//! An n-point rule integrates polynomials of degree 2n - 1 exactly.

use crate::error::ModelError;

/// Largest number of points offered (the paper uses at most 6).
pub const MAX_POINTS: usize = 10;

/// A Gauss-Legendre rule mapped to [0, 1]: `sum w_i f(x_i) ~ int_0^1 f`.
#[derive(Clone, Debug, PartialEq)]
pub struct GaussRule {
    /// Abscissae in (0, 1), ascending.
    pub points: Vec<f64>,
    /// Weights; they sum to 1.
    pub weights: Vec<f64>,
}

impl GaussRule {
    /// The n-point rule (1 <= n <= [`MAX_POINTS`], else a panic), computed
    /// once and kept: for the rules a kernel takes at every evaluation
    /// (a rod's wet band, its thin cut band).
    pub fn shared(n: usize) -> &'static GaussRule {
        static RULES: [std::sync::OnceLock<GaussRule>; MAX_POINTS] =
            [const { std::sync::OnceLock::new() }; MAX_POINTS];
        RULES[n - 1].get_or_init(|| GaussRule::new(n).expect("1 to MAX_POINTS points"))
    }

    /// The n-point rule, 1 <= n <= 10.
    ///
    /// Roots of the Legendre polynomial P_n found by Newton's method from
    /// the Chebyshev-like guess cos(pi (i - 1/4) / (n + 1/2)); weights
    /// 2 / ((1 - x^2) P_n'(x)^2) on [-1, 1], halved for [0, 1].
    pub fn new(n: usize) -> Result<Self, ModelError> {
        if n == 0 || n > MAX_POINTS {
            return Err(ModelError::invalid(
                "quadrature",
                format!("a Gauss rule needs 1 to {MAX_POINTS} points, got {n}"),
            ));
        }
        let mut points = vec![0.0; n];
        let mut weights = vec![0.0; n];
        for i in 0..n {
            let mut x = (std::f64::consts::PI * (i as f64 + 0.75) / (n as f64 + 0.5)).cos();
            let mut dp = 0.0;
            for _ in 0..100 {
                let (p, d) = legendre(n, x);
                dp = d;
                let dx = p / d;
                x -= dx;
                if dx.abs() < 1e-16 {
                    break;
                }
            }
            let (_, d) = legendre(n, x);
            if d != 0.0 {
                dp = d;
            }
            // x descends with i; store ascending on [0, 1].
            points[n - 1 - i] = 0.5 * (1.0 + x);
            weights[n - 1 - i] = 1.0 / ((1.0 - x * x) * dp * dp);
        }
        Ok(GaussRule { points, weights })
    }

    /// Number of points.
    pub fn len(&self) -> usize {
        self.points.len()
    }

    /// Always false: a rule has at least one point.
    pub fn is_empty(&self) -> bool {
        self.points.is_empty()
    }

    /// `(point, weight)` pairs.
    pub fn iter(&self) -> impl Iterator<Item = (f64, f64)> + '_ {
        self.points
            .iter()
            .copied()
            .zip(self.weights.iter().copied())
    }
}

/// P_n(x) and P_n'(x) by the three-term recurrence.
fn legendre(n: usize, x: f64) -> (f64, f64) {
    let mut p0 = 1.0;
    let mut p1 = x;
    if n == 0 {
        return (1.0, 0.0);
    }
    for k in 2..=n {
        let kf = k as f64;
        let p2 = ((2.0 * kf - 1.0) * x * p1 - (kf - 1.0) * p0) / kf;
        p0 = p1;
        p1 = p2;
    }
    let d = n as f64 * (x * p1 - p0) / (x * x - 1.0);
    (p1, d)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// An n-point rule is exact for x^k, k <= 2n - 1, and not for x^{2n}.
    #[test]
    fn exact_on_monomials_up_to_degree_2n_minus_1() {
        for n in 1..=MAX_POINTS {
            let rule = GaussRule::new(n).unwrap();
            assert_eq!(rule.len(), n);
            for k in 0..=(2 * n) {
                let q: f64 = rule.iter().map(|(x, w)| w * x.powi(k as i32)).sum();
                let exact = 1.0 / (k as f64 + 1.0);
                let err = (q - exact).abs();
                if k < 2 * n {
                    assert!(err < 4e-16 * (n as f64), "n={n} k={k} err={err:e}");
                } else {
                    // The first monomial the rule misses: its error is the
                    // known remainder (n!)^4 / ((2n+1) ((2n)!)^3) of degree 2n.
                    let mut fact_n = 1.0f64;
                    for i in 1..=n {
                        fact_n *= i as f64;
                    }
                    let mut fact_2n = 1.0f64;
                    for i in 1..=(2 * n) {
                        fact_2n *= i as f64;
                    }
                    let remainder =
                        fact_n.powi(4) / ((2 * n + 1) as f64 * fact_2n.powi(3)) * fact_2n;
                    assert!(
                        ((exact - q) - remainder).abs() < 1e-12 + 1e-9 * remainder,
                        "n={n}: remainder {:e} vs {:e}",
                        exact - q,
                        remainder
                    );
                }
            }
            assert!(rule.points.windows(2).all(|p| p[0] < p[1]));
            assert!(rule.points.iter().all(|&x| x > 0.0 && x < 1.0));
        }
    }

    #[test]
    fn rejects_zero_and_too_many_points() {
        assert!(GaussRule::new(0).is_err());
        assert!(GaussRule::new(MAX_POINTS + 1).is_err());
    }
}
