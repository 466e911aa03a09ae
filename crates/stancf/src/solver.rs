//! Newton-Raphson on a banded nonlinear system, eq. (25), with the exact
//! Jacobian, and the convergence test of eq. (26) plus a residual test.
//!
//! Convergence (both norms scaled, see [`crate::assembly::Scales`]): the
//! scaled residual is at most `tolerance`, and so is the last increment.
//! When the residual is already small but the last Newton increment was
//! not, one chord step with the factors in hand (a back-substitution, no
//! new Jacobian) confirms the increment. Nothing here allocates.

use crate::band::{BandLu, BandMatrix};
use crate::error::FailureKind;

/// A square nonlinear system R(x) = 0 with a band Jacobian.
pub trait NonlinearSystem {
    /// Writes R(x) and, if asked, dR/dx (both overwritten).
    fn evaluate(&mut self, x: &[f64], residual: &mut [f64], jacobian: Option<&mut BandMatrix>);
    /// Scaled norm of a residual.
    fn residual_norm(&self, residual: &[f64]) -> f64;
    /// Scaled norm of an increment.
    fn increment_norm(&self, dx: &[f64]) -> f64;
}

/// Tolerance and iteration limit.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct NewtonSettings {
    pub tolerance: f64,
    pub max_iterations: usize,
}

impl Default for NewtonSettings {
    fn default() -> Self {
        NewtonSettings {
            tolerance: 1e-10,
            max_iterations: 50,
        }
    }
}

/// How one solve went.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct NewtonReport {
    /// Updates of x (Newton and chord steps).
    pub iterations: usize,
    /// Jacobians built and factorized.
    pub factorizations: usize,
    /// Scaled residual at the last evaluation.
    pub residual: f64,
    /// Scaled norm of the last increment (0 if none was needed).
    pub increment: f64,
}

/// A failed solve.
#[derive(Clone, Debug, PartialEq)]
pub struct NewtonFailure {
    pub kind: FailureKind,
    pub report: NewtonReport,
}

/// Buffers of a Newton solve, sized once for a system.
#[derive(Clone, Debug)]
pub struct NewtonWorkspace {
    pub lu: BandLu,
    residual: Vec<f64>,
    dx: Vec<f64>,
    /// A residual-sized buffer for the caller (e.g. a last evaluation at
    /// the solution); Newton does not touch it.
    pub spare: Vec<f64>,
    /// Scaled residual norm of every evaluation of the last solve.
    pub residual_history: Vec<f64>,
}

impl NewtonWorkspace {
    pub fn new(n: usize, kl: usize, ku: usize, max_iterations: usize) -> Self {
        NewtonWorkspace {
            lu: BandLu::new(n, kl, ku),
            residual: vec![0.0; n],
            dx: vec![0.0; n],
            spare: vec![0.0; n],
            residual_history: Vec::with_capacity(2 * max_iterations + 2),
        }
    }
}

/// Solves R(x) = 0 from the guess in `x`.
pub fn newton<S: NonlinearSystem>(
    system: &mut S,
    x: &mut [f64],
    settings: &NewtonSettings,
    ws: &mut NewtonWorkspace,
) -> Result<NewtonReport, NewtonFailure> {
    let tol = settings.tolerance;
    let mut report = NewtonReport::default();
    ws.residual_history.clear();
    let fail = |kind, report| Err(NewtonFailure { kind, report });
    loop {
        system.evaluate(x, &mut ws.residual, None);
        let r = system.residual_norm(&ws.residual);
        report.residual = r;
        if ws.residual_history.len() < ws.residual_history.capacity() {
            ws.residual_history.push(r);
        }
        if !r.is_finite() {
            return fail(FailureKind::NonFinite, report);
        }
        if r <= tol {
            if report.iterations == 0 || report.increment <= tol {
                return Ok(report);
            }
            // Confirm with a chord step on the factors in hand.
            ws.dx.copy_from_slice(&ws.residual);
            ws.lu.solve(&mut ws.dx);
            for (xi, d) in x.iter_mut().zip(ws.dx.iter()) {
                *xi -= d;
            }
            report.iterations += 1;
            report.increment = system.increment_norm(&ws.dx);
            if report.increment <= tol {
                return Ok(report);
            }
            continue;
        }
        if report.factorizations >= settings.max_iterations {
            return fail(FailureKind::NotConverged, report);
        }
        system.evaluate(x, &mut ws.residual, Some(ws.lu.matrix_mut()));
        report.factorizations += 1;
        if ws.lu.factorize().is_err() {
            return fail(FailureKind::SingularJacobian, report);
        }
        ws.dx.copy_from_slice(&ws.residual);
        ws.lu.solve(&mut ws.dx);
        for (xi, d) in x.iter_mut().zip(ws.dx.iter()) {
            *xi -= d;
        }
        report.iterations += 1;
        report.increment = system.increment_norm(&ws.dx);
        if !report.increment.is_finite() {
            return fail(FailureKind::NonFinite, report);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// R_i(x) = x_i^3 + x_i - c_i + 0.1 (x_{i-1} + x_{i+1}): tridiagonal.
    struct Cubic {
        c: Vec<f64>,
    }

    impl NonlinearSystem for Cubic {
        fn evaluate(&mut self, x: &[f64], r: &mut [f64], jac: Option<&mut BandMatrix>) {
            let n = x.len();
            for i in 0..n {
                let left = if i > 0 { x[i - 1] } else { 0.0 };
                let right = if i + 1 < n { x[i + 1] } else { 0.0 };
                r[i] = x[i].powi(3) + x[i] - self.c[i] + 0.1 * (left + right);
            }
            if let Some(j) = jac {
                j.clear();
                for i in 0..n {
                    j.add(i, i, 3.0 * x[i] * x[i] + 1.0);
                    if i > 0 {
                        j.add(i, i - 1, 0.1);
                    }
                    if i + 1 < n {
                        j.add(i, i + 1, 0.1);
                    }
                }
            }
        }
        fn residual_norm(&self, r: &[f64]) -> f64 {
            r.iter().fold(0.0, |m: f64, v| m.max(v.abs()))
        }
        fn increment_norm(&self, dx: &[f64]) -> f64 {
            self.residual_norm(dx)
        }
    }

    #[test]
    fn converges_quadratically_to_the_root() {
        let n = 20;
        let mut sys = Cubic {
            c: (0..n).map(|i| 1.0 + 0.1 * i as f64).collect(),
        };
        let mut x = vec![0.0; n];
        let mut ws = NewtonWorkspace::new(n, 1, 1, 50);
        let rep = newton(&mut sys, &mut x, &NewtonSettings::default(), &mut ws).unwrap();
        let mut r = vec![0.0; n];
        sys.evaluate(&x, &mut r, None);
        assert!(sys.residual_norm(&r) < 1e-12);
        assert!(rep.factorizations <= 8, "{rep:?}");
        // Quadratic convergence: in the last factorized steps the residual
        // ratio r_{k+1} / r_k^2 stays bounded.
        let h = &ws.residual_history;
        let k = h.iter().position(|&v| v < 1e-2).unwrap();
        if k + 1 < h.len() && h[k + 1] > 1e-15 {
            assert!(h[k + 1] < 10.0 * h[k] * h[k], "{h:?}");
        }
    }

    #[test]
    fn reports_non_convergence() {
        let n = 3;
        let mut sys = Cubic { c: vec![1e6; n] };
        let mut x = vec![0.0; n];
        let mut ws = NewtonWorkspace::new(n, 1, 1, 3);
        let s = NewtonSettings {
            tolerance: 1e-12,
            max_iterations: 3,
        };
        let err = newton(&mut sys, &mut x, &s, &mut ws).unwrap_err();
        assert_eq!(err.kind, FailureKind::NotConverged);
        assert_eq!(err.report.factorizations, 3);
    }
}
