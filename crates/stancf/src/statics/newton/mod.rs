//! The static Newton iteration and its load path (docs/method.md §6.8,
//! (M25), and §6.9, (M26)): Levenberg-shifted Newton steps inside an
//! adaptive trust radius, load increments cut in half when they fail.
//! One driver for a single cable (a band) and a system of lines (bands
//! bordered by the free points), through [`StaticEquations`].

mod convergence;
mod relax;

use super::{StaticIncrement, StaticSettings};
use crate::error::{FailureKind, Sig, SolverError, STATIC_SOLVE};
use crate::linear::{AddEntries, Factorization, Jacobian};
use convergence::Convergence;

/// The static equations R(x; t) = 0 along a load path t in [0, 1], as the
/// driver sees them.
pub(crate) trait StaticEquations {
    type Matrix: Jacobian;
    /// R(x) and, if asked, its Jacobian (every entry set, none added to
    /// what was there before).
    fn evaluate(&mut self, x: &[f64], residual: &mut [f64], jacobian: Option<&mut Self::Matrix>);
    /// The weights of the scaled residual's rows, from the Jacobian.
    fn row_weights(&mut self, jacobian: &Self::Matrix, weights: &mut [f64]);
    /// Sets the point t of the load path.
    fn set_load_factor(&mut self, t: f64);
    /// The legs of the load path (increments are `load_steps` per leg).
    fn legs(&self) -> usize;
    /// Takes the converged unknowns of an increment (states, reactions).
    fn converged(&mut self, x: &[f64]);
}

/// The unknowns, the factors and the position on the load path.
pub(crate) struct StaticNewton<F: Factorization> {
    pub x: Vec<f64>,
    x_trial: Vec<f64>,
    x_prev: Vec<f64>,
    /// The start of the increment being tried (restored if it fails).
    x_saved: Vec<f64>,
    residual: Vec<f64>,
    dx: Vec<f64>,
    /// Row weights 1 / |K_ii| (refreshed with every Jacobian).
    row_weight: Vec<f64>,
    /// Weights of the unknowns in the increment norm (0: take the weight
    /// of row `weight_row[i]`).
    unknown_weight: Vec<f64>,
    /// The rows whose smallest weight an unknown of weight 0 takes: its
    /// own index, but for a multiplier the equilibrium rows of the node's
    /// coordinates of the kind it holds ([`Self::set_weight_rows`]).
    weight_rows: Vec<[usize; 3]>,
    lu: F,
    jacobian: F::Matrix,
    settings: StaticSettings,
    /// Load path: the converged point, the next increment, the last one.
    lambda: f64,
    step: f64,
    previous_step: f64,
    cuts: usize,
    pub increments: usize,
}

impl<F: Factorization> StaticNewton<F> {
    /// The driver from the start x, with factors `lu` and a matrix of the
    /// same structure `jacobian`.
    pub fn new(
        x: Vec<f64>,
        unknown_weight: Vec<f64>,
        lu: F,
        jacobian: F::Matrix,
        settings: StaticSettings,
    ) -> Self {
        let n = x.len();
        StaticNewton {
            x_trial: x.clone(),
            x_prev: x.clone(),
            x_saved: x.clone(),
            x,
            residual: vec![0.0; n],
            dx: vec![0.0; n],
            row_weight: vec![1.0; n],
            unknown_weight,
            weight_rows: (0..n).map(|i| [i; 3]).collect(),
            lu,
            jacobian,
            settings,
            lambda: 0.0,
            step: 0.0,
            previous_step: 0.0,
            cuts: 0,
            increments: 0,
        }
    }

    /// Whether the Jacobian of `eq` at the current x factorizes without
    /// the Levenberg shift: the equilibrium there is isolated (a line
    /// with a direction that nothing stiffens, e.g. one at zero tension
    /// without compression, gives a zero pivot).
    pub fn regular_at<E>(&mut self, eq: &mut E) -> bool
    where
        E: StaticEquations<Matrix = F::Matrix>,
    {
        eq.evaluate(&self.x, &mut self.residual, Some(&mut self.jacobian));
        self.lu.matrix_mut().copy_from(&self.jacobian);
        self.lu.factorize().is_ok()
    }

    /// Scaled residual: each row as the coordinate change |R_i| / |K_ii|
    /// would cause, as a fraction of the cable length; constraint rows are
    /// already positions.
    fn residual_norm(&self) -> f64 {
        let mut m = 0.0f64;
        for (r, w) in self.residual.iter().zip(self.row_weight.iter()) {
            let a = (r * w).abs();
            if !a.is_finite() {
                return f64::NAN;
            }
            m = m.max(a);
        }
        m
    }

    /// The largest weighted increment: a coordinate's over its length
    /// scale; a multiplier's (a force) as the displacement it would
    /// cause at the node it holds, its weight the smallest of that node's
    /// equilibrium rows' of the coordinates' kind, s / |K_rr|, the stiffest
    /// direction's (docs/method.md §6.9): not a soft direction's, whose
    /// near-zero diagonal (a slack line's bending) would make any force
    /// huge. Weighted by its own constraint row's s instead, a multiplier
    /// would move by at most the trust radius times L newtons per
    /// iteration, and a stiff line seeded without its tension would creep
    /// to it for thousands of iterations.
    fn increment_norm(&self) -> f64 {
        let mut m = 0.0f64;
        for (i, d) in self.dx.iter().enumerate() {
            let w = if self.unknown_weight[i] > 0.0 {
                self.unknown_weight[i]
            } else {
                let rows = self.weight_rows[i];
                rows.iter()
                    .map(|&r| self.row_weight[r])
                    .fold(f64::INFINITY, f64::min)
            };
            m = m.max((d * w).abs());
        }
        m
    }

    /// The multipliers' weight rows: (multiplier unknown, the equilibrium
    /// rows of the node's coordinates it holds) (see
    /// [`Self::increment_norm`]).
    pub fn set_weight_rows(&mut self, pairs: &[(usize, [usize; 3])]) {
        for &(m, rows) in pairs {
            self.weight_rows[m] = rows;
        }
    }

    /// Factorizes K, or K + mu D (D = diag |K|) with the smallest shift
    /// mu in 1e-10, 1e-8, ... 1e2 that makes it regular.
    fn factorize_shifted(&mut self) -> Result<(), FailureKind> {
        let mut shift = 0.0;
        let kmax = self.jacobian.max_abs();
        loop {
            let a = self.lu.matrix_mut();
            a.copy_from(&self.jacobian);
            if shift > 0.0 {
                for i in 0..a.size() {
                    let d = a.get(i, i).abs().max(1e-12 * kmax);
                    a.add(i, i, shift * d);
                }
            }
            if self.lu.factorize().is_ok() {
                return Ok(());
            }
            shift = if shift == 0.0 { 1e-10 } else { shift * 100.0 };
            if shift > 1e2 {
                return Err(FailureKind::SingularJacobian);
            }
        }
    }

    /// Newton at the current load factor from the current x.
    fn newton<E>(&mut self, eq: &mut E) -> Result<(usize, f64, f64), FailureKind>
    where
        E: StaticEquations<Matrix = F::Matrix>,
    {
        let mut convergence = Convergence::new(self.settings.tolerance);
        let max_step = 0.2;
        let mut radius = max_step;
        let mut increment = f64::INFINITY;
        for k in 0..=self.settings.max_iterations {
            eq.evaluate(&self.x, &mut self.residual, Some(&mut self.jacobian));
            eq.row_weights(&self.jacobian, &mut self.row_weight);
            let r = self.residual_norm();
            if !r.is_finite() {
                return Err(FailureKind::NonFinite);
            }
            if convergence.at_iterate(r, increment) {
                return Ok((k, r, increment));
            }
            if k == self.settings.max_iterations {
                return Err(FailureKind::NotConverged);
            }
            self.factorize_shifted()?;
            self.dx.copy_from_slice(&self.residual);
            self.lu.solve(&mut self.dx);
            let full = self.increment_norm();
            if !full.is_finite() {
                return Err(FailureKind::NonFinite);
            }
            // Step control: a full Newton step inside the trust radius is
            // taken as it is (the tangent step of a large rotation may raise
            // the residual on its way to convergence). A step the radius had
            // to cap is only trusted if it lowers the scaled residual; if not,
            // the radius is halved and the step retried. Non-finite trials
            // are halved too.
            let mut alpha = if full > radius { radius / full } else { 1.0 };
            for _ in 0..60 {
                for i in 0..self.x.len() {
                    self.x_trial[i] = self.x[i] - alpha * self.dx[i];
                }
                eq.evaluate(&self.x_trial, &mut self.residual, None);
                let rt = self.residual_norm();
                if !rt.is_finite() {
                    alpha *= 0.5;
                    radius = radius.min(alpha * full);
                    continue;
                }
                if alpha < 1.0 && rt >= r && alpha * full > 1e-9 {
                    alpha *= 0.5;
                    radius = alpha * full;
                    continue;
                }
                if alpha < 1.0 {
                    radius = (2.0 * radius).min(max_step);
                }
                break;
            }
            if convergence.at_floor(k, r, self.residual_norm()) {
                return Ok((k, r, increment));
            }
            std::mem::swap(&mut self.x, &mut self.x_trial);
            increment = alpha * full;
        }
        Err(FailureKind::NotConverged)
    }

    /// The next converged increment of the load path (None when the full
    /// load is on). An increment that fails is cut in half and retried,
    /// up to `max_cuts` times or until it would no longer move the load
    /// factor; then the error names the load factor, and the increments
    /// already returned stay valid.
    pub fn advance<E>(&mut self, eq: &mut E) -> Result<Option<StaticIncrement>, SolverError>
    where
        E: StaticEquations<Matrix = F::Matrix>,
    {
        let nominal = 1.0 / (eq.legs() as f64 * self.settings.load_steps as f64);
        if self.increments == 0 && self.cuts == 0 && self.step == 0.0 {
            self.step = nominal;
            self.x_prev.copy_from_slice(&self.x);
        } else if self.cuts == 0 {
            // The increment after a success may double again.
            self.step = (2.0 * self.step).min(nominal);
        }
        while self.lambda < 1.0 - 1e-12 {
            if self.increments >= self.max_increments(eq.legs()) {
                return Err(self.creeping(eq.legs()));
            }
            let target = (self.lambda + self.step).min(1.0);
            let h = target - self.lambda;
            // Predictor: secant extrapolation from the last two solutions.
            self.x_saved.copy_from_slice(&self.x);
            if self.previous_step > 0.0 {
                let f = h / self.previous_step;
                for i in 0..self.x.len() {
                    self.x[i] += f * (self.x[i] - self.x_prev[i]);
                }
            }
            eq.set_load_factor(target);
            // An increment below the load factor's resolution moves
            // nothing: a failure, cut like the others (else a path that
            // cannot pass a load factor would take such increments, double
            // the step, fail and cut back to them forever).
            let solved = if h > 0.0 {
                self.newton(eq)
            } else {
                Err(FailureKind::NotConverged)
            };
            match solved {
                Ok((iterations, residual, increment)) => {
                    self.x_prev.copy_from_slice(&self.x_saved);
                    self.previous_step = h;
                    self.lambda = target;
                    self.increments += 1;
                    eq.converged(&self.x);
                    let inc = StaticIncrement {
                        step: self.increments,
                        load_factor: self.lambda,
                        iterations,
                        residual,
                        increment,
                        cuts: self.cuts,
                    };
                    self.cuts = 0;
                    return Ok(Some(inc));
                }
                Err(kind) => {
                    self.x.copy_from_slice(&self.x_saved);
                    self.cuts += 1;
                    if self.cuts > self.settings.max_cuts {
                        eq.set_load_factor(self.lambda);
                        return Err(SolverError {
                            kind,
                            time: self.lambda,
                            step: self.increments + 1,
                            residual: self.residual_norm(),
                            iterations: self.settings.max_iterations,
                            detail: format!(
                                "{STATIC_SOLVE}: the load increment from load factor {} could \
                                 not be converged even after {} halvings (converged: the scaled \
                                 residual and increment both within the tolerance {}, or the \
                                 residual within it {} iterations running)",
                                Sig(self.lambda),
                                self.settings.max_cuts,
                                Sig(self.settings.tolerance),
                                convergence::SETTLED_ITERATIONS
                            ),
                        });
                    }
                    self.step *= 0.5;
                }
            }
        }
        Ok(None)
    }

    /// The most increments a load path takes: `max_cuts + 1` per nominal
    /// increment (and at least 10 nominal ones' worth). A cut of c
    /// halvings is made good by c doublings of the increments after it,
    /// so a path whose every nominal increment were cut `max_cuts` times
    /// would take about that many; a path that takes more creeps toward a
    /// load factor it cannot pass, and would go on for hours.
    fn max_increments(&self, legs: usize) -> usize {
        (legs * self.settings.load_steps)
            .max(10)
            .saturating_mul(self.settings.max_cuts + 1)
    }

    /// The error of a load path past [`Self::max_increments`].
    fn creeping(&self, legs: usize) -> SolverError {
        SolverError {
            kind: FailureKind::PathStalled,
            time: self.lambda,
            step: self.increments + 1,
            residual: self.residual_norm(),
            iterations: 0,
            detail: format!(
                "{STATIC_SOLVE}: the load path took {} increments, the most for its {} \
                 nominal ones ({} each, with up to {} halvings), and reached load factor {} \
                 only: it creeps toward a load it cannot pass",
                self.increments,
                legs * self.settings.load_steps,
                self.settings.max_cuts + 1,
                self.settings.max_cuts,
                Sig(self.lambda)
            ),
        }
    }
}

#[cfg(test)]
mod tests;
