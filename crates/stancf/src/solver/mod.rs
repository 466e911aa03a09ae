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
//! the previous one); when it stops contracting (for modified Newton also
//! when its rate predicts too many more chord steps, (M28a)), the Jacobian
//! is rebuilt and factorized at the current iterate and the corrections
//! dropped.

mod broyden;
mod newton;
#[cfg(test)]
mod tests;

pub use broyden::broyden;
pub use newton::newton;

use crate::band::{BandLu, BandMatrix};
use crate::error::FailureKind;
use crate::linear::Factorization;

/// The tangent policy of modified Newton (docs/method.md §7.4, (M28a)):
/// the Jacobian is rebuilt where the chord steps would
/// still need more than this many iterations at their measured
/// contraction. A new Jacobian and its factors cost about as much as 5 to
/// 6 chord steps (measured: the 16-element transverse impact, Galerkin,
/// 130 us against 24 us), after which about 3 steps converge; so it pays
/// beyond 8 predicted steps.
pub const CHORD_STEPS_WORTH_A_TANGENT: f64 = 8.0;

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
    /// halving or contracts too slowly ((M28a),
    /// [`CHORD_STEPS_WORTH_A_TANGENT`]); Broyden without the rank-one
    /// corrections.
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
    /// Newton: where the next Jacobian is evaluated and factorized before
    /// it takes the place of `lu` (made at the first Newton solve).
    next: Option<F>,
    /// Newton: whether the last solve's residual after its first update
    /// was within the tolerance (the guess for this solve's first).
    one_update_sufficed: bool,
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
            next: None,
            one_update_sufficed: false,
            previous: Vec::new(),
            y: Vec::new(),
            by: Vec::new(),
            updates_a: Vec::new(),
            updates_s: Vec::new(),
            updates: 0,
            timing: Timing::default(),
        }
    }

    /// The update with the factors in hand: dx = J^-1 R (R the last
    /// residual evaluated), x <- x - dx.
    fn update_with_factors(&mut self, x: &mut [f64]) {
        self.dx.copy_from_slice(&self.residual);
        self.lu.solve(&mut self.dx);
        for (xi, d) in x.iter_mut().zip(self.dx.iter()) {
            *xi -= d;
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

/// An update that moved the unknowns by at most this fraction of the
/// tolerance has left them at their round-off ([`at_residual_floor`]).
const FLOOR_INCREMENT: f64 = 1e-2;
/// A residual at its floor is accepted up to this multiple of the
/// tolerance ([`at_residual_floor`]).
const FLOOR_RESIDUAL: f64 = 1e2;

/// Whether an iterate whose last update moved the unknowns by `increment`
/// and took the scaled residual from `before` to `after` is at the
/// residual's round-off floor (docs/method.md §7.2): the update moved the
/// unknowns by at most [`FLOOR_INCREMENT`] of the tolerance `tol` (they
/// have settled to their last bits), the residual did not halve over it
/// (Newton's convergence has ended), and it is within [`FLOOR_RESIDUAL`]
/// times the tolerance. What is left is the round-off of the residual's
/// sums, which no update can lower: measured on Lowe and Langley's jumper
/// at a 1 s Galerkin step, scaled residuals of 1.3e-10 to 4.2e-10 for 47
/// iterations running, every increment 1e-14, against the tolerance
/// 1e-10 (every step failed and was taken again in halves, 7 times the
/// work of the 0.5 s step).
pub(crate) fn at_residual_floor(before: f64, after: f64, increment: f64, tol: f64) -> bool {
    increment <= FLOOR_INCREMENT * tol && after <= FLOOR_RESIDUAL * tol && after > 0.5 * before
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
