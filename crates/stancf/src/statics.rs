//! Static analysis (paper section 4.1; docs/method.md §6.8, (M25), and
//! §6.9, (M26)).
//!
//! A static solve is the space-time solve of a time-invariant slab:
//! e_a = e_b = e, all velocities zero, so A = dt (W - U)(e) and the
//! equations reduce to
//!
//! ```text
//!   R(e) = dU/de - lambda f(e) - mu = 0,      e_c = c    (constraints)
//! ```
//!
//! with f the loads (gravity, point forces, end moments) and lambda the
//! load factor. stancf solves this reduced form directly: the time
//! quadrature of the slab would only multiply every term by dt.
//!
//! The load is applied in increments from 0 to 1 (`load_steps`), each
//! solved by Newton from the previous solution (extrapolated); supports
//! that move are moved after the loads are on (see `set_load_factor`). The tangent
//! can be nearly or exactly singular: a straight cable loaded sideways has
//! only its tiny bending stiffness, and a planar cable clamped at one end
//! can rotate about its clamped tangent without strain (a cable carries no
//! torsion). So each Newton step is
//!
//! - solved with a Levenberg shift K + mu D (D = diag |K|) when K is
//!   singular (the shift only steers the path; the converged solution
//!   solves R = 0),
//! - limited to a trust radius (at most 0.2 L for the scaled step): the
//!   first step of a straight cable loaded sideways is its load over its
//!   bending stiffness, kilometres, whatever the load factor. A full Newton
//!   step inside the radius is taken as it is; a step the radius had to cap
//!   is taken only if it lowers the scaled residual, else the radius is
//!   halved and the step retried (and doubled again after a success);
//!
//! and an increment that still fails is cut in half and retried, up to
//! `max_cuts` times, before the solve gives up.
//!
//! Measured, and why there is no line search along the Newton direction:
//! the tangent step of a large rotation stretches the cable (Green strain),
//! so the residual and the potential jump along the full step although the
//! solution is close. Backtracking on the residual, and a line search to
//! the minimum of the potential along the step (Crisfield), shortened the
//! first step of circle bending to 3 % and made convergence linear (50
//! iterations without converging); full steps inside the trust region
//! converge in about 10 iterations per increment there (a thin cable's
//! basin of quadratic convergence scales with EI / (EA l^2) ~ 1e-6) and
//! in 4 to 7 on catenaries. A fixed radius instead of the adaptive one
//! failed on a catenary with EA = 1e3 N: the capped steps bounced between
//! 2 m sags at every load factor, however much the increment was cut.

use crate::assembly::{AssemblyScratch, Scheme, SlabLayout, StepProblem, StepStart};
use crate::band::{BandLu, BandMatrix};
use crate::constraints::ConstraintMethod;
use crate::element::TimeSlab;
use crate::error::{FailureKind, ModelError, Sig, SolverError, STATIC_SOLVE};
use crate::model::{coordinate, Model, State, SLOT_R};
use crate::quadrature::GaussRule;
use std::ops::ControlFlow;

/// How a static solve proceeds.
#[derive(Clone, Debug, PartialEq)]
pub struct StaticSettings {
    /// Load increments from 0 to the full load (and as many again for
    /// moving supports, see [`StaticSolver::moves_supports`]).
    pub load_steps: usize,
    pub tolerance: f64,
    /// Newton iterations per increment.
    pub max_iterations: usize,
    pub constraint_method: ConstraintMethod,
    /// Halvings of a failed increment before giving up.
    pub max_cuts: usize,
}

impl Default for StaticSettings {
    fn default() -> Self {
        StaticSettings {
            load_steps: 20,
            tolerance: 1e-10,
            max_iterations: 50,
            constraint_method: ConstraintMethod::default(),
            max_cuts: 10,
        }
    }
}

/// One converged load increment.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct StaticIncrement {
    /// Index of the converged increment (1 = first).
    pub step: usize,
    pub load_factor: f64,
    pub iterations: usize,
    /// Scaled residual and last increment norms at convergence.
    pub residual: f64,
    pub increment: f64,
    /// Halvings this increment needed.
    pub cuts: usize,
}

/// A static solve: the model and everything the increments need.
pub struct StaticSolver {
    model: Model,
    settings: StaticSettings,
    layout: SlabLayout,
    slab: TimeSlab,
    start: StepStart,
    x: Vec<f64>,
    x_trial: Vec<f64>,
    x_prev: Vec<f64>,
    residual: Vec<f64>,
    dx: Vec<f64>,
    /// Row weights 1 / |K_ii| (refreshed with every Jacobian).
    row_weight: Vec<f64>,
    unknown_weight: Vec<f64>,
    lu: BandLu,
    jacobian: BandMatrix,
    scratch: AssemblyScratch,
    state: State,
    reactions: Vec<(usize, [f64; 3])>,
    increments: usize,
}

impl StaticSolver {
    pub fn new(model: Model, settings: StaticSettings) -> Result<Self, ModelError> {
        if settings.load_steps == 0 {
            return Err(ModelError::invalid(
                "analysis.load_steps",
                "must be at least 1",
            ));
        }
        if !settings.tolerance.is_finite() || settings.tolerance <= 0.0 {
            return Err(ModelError::invalid(
                "analysis.tolerance",
                format!("must be > 0, got {}", settings.tolerance),
            ));
        }
        if settings.max_iterations == 0 {
            return Err(ModelError::invalid(
                "analysis.max_iterations",
                "must be at least 1",
            ));
        }
        if !model.constraints.remove_rigid_motions() {
            return Err(ModelError::invalid(
                "constraints",
                "a static analysis needs constraints that remove the rigid motions (a clamped \
                 node, or the positions of two nodes held): otherwise the equilibrium has no \
                 unique solution",
            ));
        }
        let layout = SlabLayout::new(&model, Scheme::Static, settings.constraint_method);
        let n = layout.size();
        let (kl, ku) = layout.bandwidths();
        // The reference shape: supports start at their reference positions
        // and move along the load path (see `set_load_factor`).
        let state = State {
            t: 0.0,
            e: model.reference_coordinates(),
            v: vec![0.0; model.dofs()],
        };
        let mut start = StepStart::new(&model, 1);
        start.set(&model, 0.0, &state.e, &state.v, 0.0);
        let mut x = vec![0.0; n];
        for g in 0..model.dofs() {
            if let Some(u) = layout.unknown_at(0, g) {
                x[u] = state.e[g];
            }
        }
        let len = model.cable.length;
        let dpn = layout.dpn;
        let mut unknown_weight = vec![0.0; n];
        for g in 0..model.dofs() {
            if let Some(u) = layout.unknown_at(0, g) {
                unknown_weight[u] = model.coordinate_length_scale(g % dpn) / len;
            }
        }
        let reactions = model
            .constraints
            .position_nodes
            .iter()
            .map(|&nd| (nd, [0.0; 3]))
            .collect();
        let scratch = AssemblyScratch::new(&model, &layout);
        Ok(StaticSolver {
            slab: TimeSlab::new(1.0, &GaussRule::new(1).expect("1 point")),
            x_trial: x.clone(),
            x_prev: x.clone(),
            x,
            residual: vec![0.0; n],
            dx: vec![0.0; n],
            row_weight: vec![1.0; n],
            unknown_weight,
            lu: BandLu::new(n, kl, ku),
            jacobian: BandMatrix::new(n, kl, ku),
            scratch,
            state,
            reactions,
            increments: 0,
            model,
            settings,
            layout,
            start,
        })
    }

    pub fn model(&self) -> &Model {
        &self.model
    }

    /// The current equilibrium (t holds the load path parameter, see
    /// `set_load_factor`; v is zero).
    pub fn state(&self) -> &State {
        &self.state
    }

    /// Force each position constraint exerts on the cable.
    pub fn reactions(&self) -> &[(usize, [f64; 3])] {
        &self.reactions
    }

    /// Unknowns of the static system.
    pub fn unknowns(&self) -> usize {
        self.layout.size()
    }

    /// Whether a prescribed support moves away from its reference position.
    pub fn moves_supports(&self) -> bool {
        self.model
            .constraints
            .motion
            .iter()
            .flatten()
            .any(|m| m.value(0.0) != m.base)
    }

    /// Sets the point t in [0, 1] of the load path. Without support
    /// motion the loads are t times the full loads. With it the path has
    /// two legs: the loads grow to full while the supports stay at their
    /// reference positions (t <= 1/2), then the supports move to their
    /// prescribed positions c(0) under the full loads (t > 1/2). Moving a
    /// support first would compress the straight cable far beyond its
    /// buckling load (pi^2 EI / L^2), where Newton has nothing to go by;
    /// under load it merely slackens a sagging cable. For an elastic cable
    /// under conservative loads the end state is the same.
    fn set_load_factor(&mut self, t: f64) {
        let (loads, supports) = if self.moves_supports() {
            ((2.0 * t).min(1.0), (2.0 * t - 1.0).max(0.0))
        } else {
            (t, t)
        };
        self.start.load_factor = loads;
        for (g, m) in self.model.constraints.motion.iter().enumerate() {
            if let Some(m) = m {
                self.start.fixed_e[g] = m.base + supports * (m.value(0.0) - m.base);
            }
        }
    }

    fn evaluate(&mut self, x_is_trial: bool, with_jacobian: bool) {
        let p = StepProblem {
            model: &self.model,
            layout: &self.layout,
            slab: &self.slab,
            start: &self.start,
        };
        let x = if x_is_trial { &self.x_trial } else { &self.x };
        let jac = if with_jacobian {
            Some(&mut self.jacobian)
        } else {
            None
        };
        p.assemble(x, &mut self.residual, jac, &mut self.scratch);
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

    fn increment_norm(&self, dx: &[f64]) -> f64 {
        let mut m = 0.0f64;
        for (i, d) in dx.iter().enumerate() {
            let w = if self.unknown_weight[i] > 0.0 {
                self.unknown_weight[i]
            } else {
                self.row_weight[i]
            };
            m = m.max((d * w).abs());
        }
        m
    }

    /// Row weights from the Jacobian's diagonal.
    fn refresh_weights(&mut self) {
        let n = self.layout.size();
        let len = self.model.cable.length;
        let dpn = self.layout.dpn;
        let kmax = (0..n)
            .map(|i| self.jacobian.get(i, i).abs())
            .fold(0.0, f64::max);
        let floor = 1e-12 * kmax.max(f64::MIN_POSITIVE);
        for w in self.row_weight.iter_mut() {
            *w = 0.0;
        }
        for g in 0..self.model.dofs() {
            let s = self.model.coordinate_length_scale(g % dpn) / len;
            if let Some(r) = self.layout.row_at(0, g) {
                self.row_weight[r] = s / self.jacobian.get(r, r).abs().max(floor);
            }
            if let Some(r) = self.layout.constraint_row_at(0, g) {
                self.row_weight[r] = s;
            }
        }
    }

    /// Newton at the current load factor from the current x.
    fn newton(&mut self) -> Result<(usize, f64, f64), FailureKind> {
        let tol = self.settings.tolerance;
        let max_step = 0.2;
        let mut radius = max_step;
        let mut increment = f64::INFINITY;
        for k in 0..=self.settings.max_iterations {
            self.evaluate(false, true);
            self.refresh_weights();
            let r = self.residual_norm();
            if !r.is_finite() {
                return Err(FailureKind::NonFinite);
            }
            if r <= tol && increment <= tol {
                return Ok((k, r, increment));
            }
            if k == self.settings.max_iterations {
                return Err(FailureKind::NotConverged);
            }
            // Solve K dx = R, with a Levenberg shift if K is singular.
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
                    break;
                }
                shift = if shift == 0.0 { 1e-10 } else { shift * 100.0 };
                if shift > 1e2 {
                    return Err(FailureKind::SingularJacobian);
                }
            }
            self.dx.copy_from_slice(&self.residual);
            self.lu.solve(&mut self.dx);
            let full = self.increment_norm(&self.dx);
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
                self.evaluate(true, false);
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
            std::mem::swap(&mut self.x, &mut self.x_trial);
            increment = alpha * full;
        }
        Err(FailureKind::NotConverged)
    }

    /// Applies the load in increments, calling `observer` after each
    /// converged increment. Stops with an error naming the load factor
    /// when an increment fails after `max_cuts` halvings; the increments
    /// already observed stay valid.
    pub fn solve<F>(&mut self, mut observer: F) -> Result<bool, SolverError>
    where
        F: FnMut(&StaticSolver, &StaticIncrement) -> ControlFlow<()>,
    {
        let legs = if self.moves_supports() { 2.0 } else { 1.0 };
        let nominal = 1.0 / (legs * self.settings.load_steps as f64);
        let mut lambda = 0.0;
        let mut step = nominal;
        let mut previous_step = 0.0;
        let mut cuts = 0;
        self.x_prev.copy_from_slice(&self.x);
        while lambda < 1.0 - 1e-12 {
            let target = (lambda + step).min(1.0);
            let h = target - lambda;
            // Predictor: secant extrapolation from the last two solutions.
            let saved = self.x.clone();
            if previous_step > 0.0 {
                let f = h / previous_step;
                for i in 0..self.x.len() {
                    self.x[i] += f * (self.x[i] - self.x_prev[i]);
                }
            }
            self.set_load_factor(target);
            match self.newton() {
                Ok((iterations, residual, increment)) => {
                    self.x_prev.copy_from_slice(&saved);
                    previous_step = h;
                    lambda = target;
                    self.increments += 1;
                    self.finish_increment();
                    let inc = StaticIncrement {
                        step: self.increments,
                        load_factor: lambda,
                        iterations,
                        residual,
                        increment,
                        cuts,
                    };
                    if observer(self, &inc).is_break() {
                        return Ok(false);
                    }
                    cuts = 0;
                    step = (2.0 * step).min(nominal);
                }
                Err(kind) => {
                    self.x.copy_from_slice(&saved);
                    cuts += 1;
                    if cuts > self.settings.max_cuts {
                        self.set_load_factor(lambda);
                        return Err(SolverError {
                            kind,
                            time: lambda,
                            step: self.increments + 1,
                            residual: self.residual_norm(),
                            iterations: self.settings.max_iterations,
                            detail: format!(
                                "{STATIC_SOLVE}: the load increment from load factor {} could \
                                 not be converged even after {} halvings",
                                Sig(lambda),
                                self.settings.max_cuts
                            ),
                        });
                    }
                    step *= 0.5;
                }
            }
        }
        Ok(true)
    }

    /// The state and reactions at the converged x.
    fn finish_increment(&mut self) {
        let p = StepProblem {
            model: &self.model,
            layout: &self.layout,
            slab: &self.slab,
            start: &self.start,
        };
        p.residual(&self.x, &mut self.residual, &mut self.scratch);
        let n = self.model.dofs();
        self.state.e.copy_from_slice(&self.scratch.node_e[..n]);
        self.state.t = self.start.load_factor;
        let dpn = self.layout.dpn;
        for (node, force) in self.reactions.iter_mut() {
            for c in 0..3 {
                let g = coordinate(dpn, *node, SLOT_R, c);
                force[c] = match self.layout.multiplier_at(0, g) {
                    Some(m) => self.x[m],
                    None => self.scratch.reaction_rows[g],
                };
            }
        }
    }
}
