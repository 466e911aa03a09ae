//! Nonlinear solvers on a banded system: Newton-Raphson with the exact
//! Jacobian, eq. (25), and Broyden's rank-one method, eq. (27), with the
//! convergence test of eq. (26) plus a residual test (docs/method.md
//! §7.1-7.5: the scaled measures (M27), Newton, Broyden (M28), modified
//! Newton, no unchecked guess).
//!
//! Convergence (both norms scaled, see [`crate::assembly::Scales`]): a
//! residual at most `tolerance` followed by an update (from it) at most
//! `tolerance`; the update is applied and the residual is not evaluated
//! again. A guess is never accepted without an update, however small its
//! residual: the extrapolated guess of a small step can have a residual
//! below the tolerance, and accepting it unchecked turns the step into an
//! explicit extrapolation (the transverse impact at dt = 5e-6 drifted by
//! 1.6e-4 of its energy that way). When the residual is small but the last
//! Newton update was not, the confirming update is a chord step with the
//! factors in hand (a back-substitution, no new Jacobian). Nothing here
//! allocates.
//!
//! Broyden (eq. 27 is garbled in the paper; docs/method.md §7.3, (M28):
//! the "good" update of the inverse). With B ~ J^-1, s the step and y the
//! change of residual,
//!
//! ```text
//!   B+ = B + (s - B y) s^T B / (s^T B y) = (I + a s^T) B,   a = (s - B y) / (s^T B y)
//! ```
//!
//! so B_k = (I + a_{k-1} s_{k-1}^T) ... (I + a_0 s_0^T) J0^-1 is applied as a
//! back-substitution with the band LU of J0 followed by k rank-one
//! corrections; no dense inverse is formed. J0 is the exact Jacobian, kept
//! across steps while the iteration contracts (each residual at most half
//! the previous one); when it stops contracting, the Jacobian is rebuilt
//! and factorized at the current iterate and the corrections dropped.

use crate::band::{BandLu, BandMatrix};
use crate::error::FailureKind;
use crate::linear::Factorization;

/// A square nonlinear system R(x) = 0 whose Jacobian is a `M` (a band
/// matrix for one cable, a bordered one for a system of lines).
pub trait NonlinearSystem<M = BandMatrix> {
    /// Writes R(x) and, if asked, dR/dx (both overwritten).
    fn evaluate(&mut self, x: &[f64], residual: &mut [f64], jacobian: Option<&mut M>);
    /// Scaled norm of a residual.
    fn residual_norm(&self, residual: &[f64]) -> f64;
    /// Scaled norm of an increment.
    fn increment_norm(&self, dx: &[f64]) -> f64;
}

/// Which nonlinear solver a step uses.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum SolverMethod {
    /// Newton-Raphson with the exact Jacobian, eq. (25).
    #[default]
    Newton,
    /// Broyden rank one, eq. (27) (the "good" update of the inverse).
    Broyden,
    /// Modified Newton: the factorized exact Jacobian kept across
    /// iterations and steps (chord steps), rebuilt where the residual stops
    /// halving; Broyden without the rank-one corrections.
    ModifiedNewton,
}

/// Tolerance, iteration limit and method.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct NewtonSettings {
    pub tolerance: f64,
    pub max_iterations: usize,
    pub method: SolverMethod,
}

impl Default for NewtonSettings {
    fn default() -> Self {
        NewtonSettings {
            tolerance: 1e-10,
            max_iterations: 50,
            method: SolverMethod::Newton,
        }
    }
}

/// A source of wall-clock time in seconds, injected by the caller: the
/// library itself never reads the clock.
pub trait Clock: Send + Sync {
    fn seconds(&self) -> f64;
}

/// Time spent in the two parts of eq. (32): Part A evaluates the elements
/// and assembles residual and Jacobian, Part B factorizes and solves (and
/// applies Broyden's corrections).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Timing {
    pub part_a: f64,
    pub part_b: f64,
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

/// Buffers of a Newton or Broyden solve, sized once for a system; `F`
/// the factors of its Jacobian.
#[derive(Clone, Debug)]
pub struct NewtonWorkspace<F = BandLu> {
    pub lu: F,
    residual: Vec<f64>,
    dx: Vec<f64>,
    /// A residual-sized buffer for the caller (e.g. a last evaluation at
    /// the solution); the solvers do not touch it.
    pub spare: Vec<f64>,
    /// Scaled residual norm of every evaluation of the last solve.
    pub residual_history: Vec<f64>,
    /// Whether `lu` holds factors Broyden may start from (the caller
    /// clears it when the system changes, e.g. with the step length).
    pub factors_valid: bool,
    /// Broyden: previous residual, y, B y, and the rank-one factors (a, s).
    previous: Vec<f64>,
    y: Vec<f64>,
    by: Vec<f64>,
    updates_a: Vec<Vec<f64>>,
    updates_s: Vec<Vec<f64>>,
    updates: usize,
    /// Accumulated Part A / Part B times (with a clock).
    pub timing: Timing,
}

impl NewtonWorkspace {
    /// Buffers for a system of n unknowns with a band Jacobian.
    pub fn new(n: usize, kl: usize, ku: usize, max_iterations: usize) -> Self {
        NewtonWorkspace::with_factors(BandLu::new(n, kl, ku), n, max_iterations)
    }
}

impl<F: Factorization> NewtonWorkspace<F> {
    /// Buffers for a system of n unknowns whose Jacobian `lu` factorizes.
    pub fn with_factors(lu: F, n: usize, max_iterations: usize) -> Self {
        NewtonWorkspace {
            lu,
            residual: vec![0.0; n],
            dx: vec![0.0; n],
            spare: vec![0.0; n],
            residual_history: Vec::with_capacity(2 * max_iterations + 2),
            factors_valid: false,
            previous: Vec::new(),
            y: Vec::new(),
            by: Vec::new(),
            updates_a: Vec::new(),
            updates_s: Vec::new(),
            updates: 0,
            timing: Timing::default(),
        }
    }

    /// Allocates Broyden's buffers (once).
    fn prepare_broyden(&mut self, max_iterations: usize) {
        let n = self.residual.len();
        if self.updates_a.len() < max_iterations {
            self.previous = vec![0.0; n];
            self.y = vec![0.0; n];
            self.by = vec![0.0; n];
            self.updates_a = vec![vec![0.0; n]; max_iterations];
            self.updates_s = vec![vec![0.0; n]; max_iterations];
        }
    }

    /// v <- B v: back-substitution with J0, then the rank-one factors.
    fn apply_inverse(lu: &F, a: &[Vec<f64>], s: &[Vec<f64>], k: usize, v: &mut [f64]) {
        lu.solve(v);
        for i in 0..k {
            let c: f64 = s[i].iter().zip(v.iter()).map(|(p, q)| p * q).sum();
            if c != 0.0 {
                for (vj, aj) in v.iter_mut().zip(a[i].iter()) {
                    *vj += c * aj;
                }
            }
        }
    }
}

/// The convergence-rate estimate of the paper's Table 7 (docs/method.md §7.7),
/// log(r_{k+1} / r_k) / log(r_k / r_{k-1}), from the last three residual
/// norms of an iteration above `floor`: about 2 for Newton's quadratic
/// convergence, 1 for linear, in between for Broyden's superlinear.
/// Residuals at or below the floor are left out: take the tolerance, since
/// a converged residual is often at the round-off level, where its ratios
/// mean nothing. None with fewer than three residuals
/// above the floor, or a stalled one (r_k = r_{k-1}).
pub fn convergence_rate(residuals: &[f64], floor: f64) -> Option<f64> {
    let mut it = residuals.iter().rev().filter(|&&r| r > floor);
    let (Some(&c), Some(&b), Some(&a)) = (it.next(), it.next(), it.next()) else {
        return None;
    };
    if a == b {
        return None;
    }
    let rate = (c / b).ln() / (b / a).ln();
    rate.is_finite().then_some(rate)
}

/// Seconds from an optional clock (0 without one).
fn now(clock: Option<&dyn Clock>) -> f64 {
    clock.map_or(0.0, |c| c.seconds())
}

/// Solves R(x) = 0 by the method of `settings`, timing Parts A and B with
/// `clock` if given.
pub fn solve<F: Factorization, S: NonlinearSystem<F::Matrix>>(
    system: &mut S,
    x: &mut [f64],
    settings: &NewtonSettings,
    ws: &mut NewtonWorkspace<F>,
    clock: Option<&dyn Clock>,
) -> Result<NewtonReport, NewtonFailure> {
    match settings.method {
        SolverMethod::Newton => newton(system, x, settings, ws, clock),
        SolverMethod::Broyden | SolverMethod::ModifiedNewton => {
            broyden(system, x, settings, ws, clock)
        }
    }
}

/// Broyden's rank-one method (see the module documentation), or modified
/// Newton when `settings.method` says so (no rank-one corrections).
pub fn broyden<F: Factorization, S: NonlinearSystem<F::Matrix>>(
    system: &mut S,
    x: &mut [f64],
    settings: &NewtonSettings,
    ws: &mut NewtonWorkspace<F>,
    clock: Option<&dyn Clock>,
) -> Result<NewtonReport, NewtonFailure> {
    let tol = settings.tolerance;
    let mut report = NewtonReport::default();
    ws.prepare_broyden(settings.max_iterations);
    ws.residual_history.clear();
    ws.updates = 0;
    let fail = |kind, report| Err(NewtonFailure { kind, report });
    let t0 = now(clock);
    system.evaluate(x, &mut ws.residual, None);
    ws.timing.part_a += now(clock) - t0;
    let mut r = system.residual_norm(&ws.residual);
    report.residual = r;
    ws.residual_history.push(r);
    if !r.is_finite() {
        return fail(FailureKind::NonFinite, report);
    }
    let mut refactorize = !ws.factors_valid;
    loop {
        if refactorize {
            if report.factorizations >= settings.max_iterations {
                return fail(FailureKind::NotConverged, report);
            }
            let t0 = now(clock);
            system.evaluate(x, &mut ws.residual, Some(ws.lu.matrix_mut()));
            let t1 = now(clock);
            ws.timing.part_a += t1 - t0;
            report.factorizations += 1;
            ws.updates = 0;
            let ok = ws.lu.factorize().is_ok();
            ws.timing.part_b += now(clock) - t1;
            if !ok {
                ws.factors_valid = false;
                return fail(FailureKind::SingularJacobian, report);
            }
            ws.factors_valid = true;
            refactorize = false;
        }
        if report.iterations >= settings.max_iterations {
            return fail(FailureKind::NotConverged, report);
        }
        // dx = B R; x <- x - dx; s = -dx.
        let t0 = now(clock);
        ws.dx.copy_from_slice(&ws.residual);
        NewtonWorkspace::apply_inverse(
            &ws.lu,
            &ws.updates_a,
            &ws.updates_s,
            ws.updates,
            &mut ws.dx,
        );
        for (xi, d) in x.iter_mut().zip(ws.dx.iter()) {
            *xi -= d;
        }
        ws.timing.part_b += now(clock) - t0;
        report.iterations += 1;
        report.increment = system.increment_norm(&ws.dx);
        if r <= tol && report.increment <= tol {
            // Converged: the residual before this update and the update
            // itself are within the tolerance.
            return Ok(report);
        }
        ws.previous.copy_from_slice(&ws.residual);
        let t0 = now(clock);
        system.evaluate(x, &mut ws.residual, None);
        ws.timing.part_a += now(clock) - t0;
        let r_new = system.residual_norm(&ws.residual);
        report.residual = r_new;
        if ws.residual_history.len() < ws.residual_history.capacity() {
            ws.residual_history.push(r_new);
        }
        if !r_new.is_finite() || !report.increment.is_finite() {
            ws.factors_valid = false;
            return fail(FailureKind::NonFinite, report);
        }
        if r_new <= tol && report.increment <= tol {
            return Ok(report);
        }
        if r_new > 0.5 * r || ws.updates == ws.updates_a.len() {
            // Not contracting (or out of room): a fresh Jacobian here.
            refactorize = true;
            r = r_new;
            continue;
        }
        if settings.method == SolverMethod::ModifiedNewton {
            r = r_new;
            continue;
        }
        // y = R_new - R_old; B y; a = (s - B y) / (s . B y) with s = -dx.
        let t0 = now(clock);
        for ((y, rn), ro) in
            ws.y.iter_mut()
                .zip(ws.residual.iter())
                .zip(ws.previous.iter())
        {
            *y = rn - ro;
        }
        ws.by.copy_from_slice(&ws.y);
        NewtonWorkspace::apply_inverse(
            &ws.lu,
            &ws.updates_a,
            &ws.updates_s,
            ws.updates,
            &mut ws.by,
        );
        let denom: f64 = ws.dx.iter().zip(ws.by.iter()).map(|(d, b)| -d * b).sum();
        let k = ws.updates;
        if denom.abs() <= f64::EPSILON * 1e3 {
            refactorize = true;
        } else {
            for (((a, s), d), b) in ws.updates_a[k]
                .iter_mut()
                .zip(ws.updates_s[k].iter_mut())
                .zip(ws.dx.iter())
                .zip(ws.by.iter())
            {
                *s = -d;
                *a = (-d - b) / denom;
            }
            ws.updates += 1;
        }
        ws.timing.part_b += now(clock) - t0;
        r = r_new;
    }
}

/// Newton's method from the guess in `x` (see the module documentation).
pub fn newton<F: Factorization, S: NonlinearSystem<F::Matrix>>(
    system: &mut S,
    x: &mut [f64],
    settings: &NewtonSettings,
    ws: &mut NewtonWorkspace<F>,
    clock: Option<&dyn Clock>,
) -> Result<NewtonReport, NewtonFailure> {
    let tol = settings.tolerance;
    let mut report = NewtonReport::default();
    ws.residual_history.clear();
    // Newton's factors are of the last iterate's Jacobian, not a Broyden
    // start for the next solve.
    ws.factors_valid = false;
    let fail = |kind, report| Err(NewtonFailure { kind, report });
    loop {
        let t0 = now(clock);
        system.evaluate(x, &mut ws.residual, None);
        ws.timing.part_a += now(clock) - t0;
        let r = system.residual_norm(&ws.residual);
        report.residual = r;
        if ws.residual_history.len() < ws.residual_history.capacity() {
            ws.residual_history.push(r);
        }
        if !r.is_finite() {
            return fail(FailureKind::NonFinite, report);
        }
        if r <= tol && report.iterations > 0 {
            if report.increment <= tol {
                return Ok(report);
            }
            // Chord steps count against the iteration limit (one beyond it
            // to confirm the last Newton update): where round-off keeps the
            // increment above the tolerance, they would go on for ever.
            if report.iterations > settings.max_iterations {
                return fail(FailureKind::NotConverged, report);
            }
            // Confirm with a chord step on the factors in hand.
            let t0 = now(clock);
            ws.dx.copy_from_slice(&ws.residual);
            ws.lu.solve(&mut ws.dx);
            for (xi, d) in x.iter_mut().zip(ws.dx.iter()) {
                *xi -= d;
            }
            ws.timing.part_b += now(clock) - t0;
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
        let t0 = now(clock);
        system.evaluate(x, &mut ws.residual, Some(ws.lu.matrix_mut()));
        let t1 = now(clock);
        ws.timing.part_a += t1 - t0;
        report.factorizations += 1;
        if ws.lu.factorize().is_err() {
            return fail(FailureKind::SingularJacobian, report);
        }
        ws.dx.copy_from_slice(&ws.residual);
        ws.lu.solve(&mut ws.dx);
        for (xi, d) in x.iter_mut().zip(ws.dx.iter()) {
            *xi -= d;
        }
        ws.timing.part_b += now(clock) - t1;
        report.iterations += 1;
        report.increment = system.increment_norm(&ws.dx);
        if !report.increment.is_finite() {
            return fail(FailureKind::NonFinite, report);
        }
        if r <= tol && report.increment <= tol {
            // The guess was already within the tolerance and the Newton
            // update confirms it.
            return Ok(report);
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
        let rep = newton(&mut sys, &mut x, &NewtonSettings::default(), &mut ws, None).unwrap();
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

    /// Broyden converges to the same root, superlinearly, with fewer
    /// factorizations than Newton, and reuses its factors for a nearby
    /// system.
    #[test]
    fn broyden_finds_the_same_root_with_fewer_factorizations() {
        let n = 20;
        let c: Vec<f64> = (0..n).map(|i| 1.0 + 0.1 * i as f64).collect();
        let settings = NewtonSettings {
            tolerance: 1e-12,
            max_iterations: 50,
            method: SolverMethod::Broyden,
        };
        let mut sys = Cubic { c: c.clone() };
        let mut xb = vec![0.8; n];
        let mut ws = NewtonWorkspace::new(n, 1, 1, 50);
        let rb = broyden(&mut sys, &mut xb, &settings, &mut ws, None).unwrap();
        let mut xn = vec![0.8; n];
        let mut wn = NewtonWorkspace::new(n, 1, 1, 50);
        let rn = newton(&mut sys, &mut xn, &NewtonSettings::default(), &mut wn, None).unwrap();
        let diff = xb
            .iter()
            .zip(&xn)
            .map(|(a, b)| (a - b).abs())
            .fold(0.0, f64::max);
        assert!(diff < 1e-11, "{diff}");
        assert!(rb.factorizations < rn.factorizations, "{rb:?} vs {rn:?}");
        // A nearby system starts from the factors in hand.
        sys.c.iter_mut().for_each(|v| *v += 1e-4);
        let rb2 = broyden(&mut sys, &mut xb, &settings, &mut ws, None).unwrap();
        assert!(rb2.factorizations <= 1, "{rb2:?}");
        let mut r = vec![0.0; n];
        sys.evaluate(&xb, &mut r, None);
        assert!(sys.residual_norm(&r) < 1e-12);
    }

    #[test]
    fn convergence_rate_of_model_sequences() {
        let quadratic = [1e-1, 1e-2, 1e-4, 1e-8];
        assert!((convergence_rate(&quadratic, 0.0).unwrap() - 2.0).abs() < 1e-12);
        let linear = [1.0, 0.5, 0.25];
        assert!((convergence_rate(&linear, 0.0).unwrap() - 1.0).abs() < 1e-12);
        assert_eq!(convergence_rate(&[1.0, 0.1], 0.0), None);
        // A round-off plateau below the floor is left out.
        let plateau = [1e-2, 1e-4, 1e-8, 3e-17, 2e-17];
        assert!((convergence_rate(&plateau, 1e-15).unwrap() - 2.0).abs() < 1e-12);
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
            ..NewtonSettings::default()
        };
        let err = newton(&mut sys, &mut x, &s, &mut ws, None).unwrap_err();
        assert_eq!(err.kind, FailureKind::NotConverged);
        assert_eq!(err.report.factorizations, 3);
    }

    /// A residual with a noise floor above what the increment test can
    /// see through: r = x - 1 + (-1)^k 1e-14 at the k-th evaluation, with
    /// increments weighted 1e6. The residual drops below the tolerance at
    /// once, but no increment ever does (it is at least 2e-14 x 1e6 = 2e-8).
    struct NoisyFloor {
        evaluations: usize,
    }

    impl NonlinearSystem for NoisyFloor {
        fn evaluate(&mut self, x: &[f64], r: &mut [f64], jac: Option<&mut BandMatrix>) {
            self.evaluations += 1;
            let noise = if self.evaluations.is_multiple_of(2) {
                1e-14
            } else {
                -1e-14
            };
            r[0] = x[0] - 1.0 + noise;
            if let Some(j) = jac {
                j.clear();
                j.add(0, 0, 1.0);
            }
        }
        fn residual_norm(&self, r: &[f64]) -> f64 {
            r[0].abs()
        }
        fn increment_norm(&self, dx: &[f64]) -> f64 {
            1e6 * dx[0].abs()
        }
    }

    /// Issue 11 (found by the property tests): Newton's confirming chord
    /// steps used to repeat for ever when round-off kept the increment above
    /// the tolerance; they count against the iteration limit (plus one).
    #[test]
    fn newton_ends_when_round_off_keeps_the_increment_above_the_tolerance() {
        let settings = NewtonSettings {
            tolerance: 1e-10,
            max_iterations: 5,
            method: SolverMethod::Newton,
        };
        let mut sys = NoisyFloor { evaluations: 0 };
        let mut x = [0.0];
        let mut ws = NewtonWorkspace::new(1, 0, 0, 10);
        let err = newton(&mut sys, &mut x, &settings, &mut ws, None).unwrap_err();
        assert_eq!(err.kind, FailureKind::NotConverged);
        assert_eq!(err.report.iterations, settings.max_iterations + 1);
        assert!((x[0] - 1.0).abs() < 1e-13);
    }

    /// R(x) = A x - b with A = diag(1e-3, 1): a guess 1e-8 off in the first
    /// coordinate has a residual of 1e-11, below the tolerance 1e-10, but
    /// its error is not. No solver may accept it unchecked: each applies an
    /// update and lands on the root.
    struct Stiff;

    impl NonlinearSystem for Stiff {
        fn evaluate(&mut self, x: &[f64], r: &mut [f64], jac: Option<&mut BandMatrix>) {
            r[0] = 1e-3 * x[0] - 1e-3;
            r[1] = x[1] - 2.0;
            if let Some(j) = jac {
                j.clear();
                j.add(0, 0, 1e-3);
                j.add(1, 1, 1.0);
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
    fn a_guess_within_the_residual_tolerance_is_still_corrected() {
        for method in [
            SolverMethod::Newton,
            SolverMethod::Broyden,
            SolverMethod::ModifiedNewton,
        ] {
            let settings = NewtonSettings {
                tolerance: 1e-10,
                max_iterations: 10,
                method,
            };
            let mut x = [1.0 + 1e-8, 2.0];
            let mut ws = NewtonWorkspace::new(2, 1, 1, 10);
            let rep = solve(&mut Stiff, &mut x, &settings, &mut ws, None).unwrap();
            assert!(rep.iterations >= 1, "{method:?}: {rep:?}");
            assert!((x[0] - 1.0).abs() < 1e-14, "{method:?}: {x:?}");
            assert!((x[1] - 2.0).abs() < 1e-14, "{method:?}: {x:?}");
        }
    }
}
