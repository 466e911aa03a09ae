//! One step (docs/method.md §4; the Galerkin step, §5): the predictor
//! (§4.8), the Newton solve of the slab's equations, the end values and,
//! for the Galerkin step, the momentum carried to the next step; and the
//! undo of the last step.

use super::{CubicBasis, Simulation, StepReport, TimeCubic};
use crate::assembly::{AssemblyScratch, Kind, Scales, StepProblem};
use crate::band::BandMatrix;
use crate::constraints::ConstraintMethod;
use crate::error::SolverError;
use crate::model::{coordinate, SLOT_R_X};
use crate::solver::{solve, NewtonReport, NonlinearSystem};

/// The system of one step as seen by Newton.
struct StepSystem<'a> {
    problem: StepProblem<'a>,
    scales: &'a Scales,
    scratch: &'a mut AssemblyScratch,
}

impl NonlinearSystem for StepSystem<'_> {
    fn evaluate(&mut self, x: &[f64], residual: &mut [f64], jacobian: Option<&mut BandMatrix>) {
        self.problem.assemble(x, residual, jacobian, self.scratch);
    }
    fn residual_norm(&self, r: &[f64]) -> f64 {
        Scales::norm(&self.scales.equation, r)
    }
    fn increment_norm(&self, dx: &[f64]) -> f64 {
        Scales::norm(&self.scales.unknown, dx)
    }
}

impl Simulation {
    /// Predictor (docs/method.md §4.8). A guide cubic, where one is set
    /// ([`Self::guide_next_step`]: a doubled step's whole, §11.17), is
    /// evaluated over the step. Otherwise, after a converged step of the
    /// same length: the last step's cubic in time (end values e, end
    /// slopes, eq. 6) extrapolated over the new step, which is third order
    /// in dt (a predictor error of O(dt^4) in e), so the corrector needs
    /// fewer iterations. Otherwise (first step, after an undo or a change
    /// of step): Taylor expansion with the last step's acceleration,
    /// e(t_i) = e_a + tau v_a + tau^2 a / 2,
    /// v(t_i) = v_a + tau a. Constrained coordinates take their
    /// prescribed values; the multipliers keep their last values.
    fn predict(&mut self) {
        let h = self.slab.dt;
        let n = self.model.dofs();
        // A guide is a cubic from this step's start (none other is taken).
        let guide = self.guide.take().filter(|c| c.t0 == self.state.t);
        // Extrapolated over a step of the same length only: over a longer
        // one the cubic of a short step (a halved one's) can carry Newton
        // to a root that is not the motion's (an energy jump; the rope
        // swung in tests/cli/moordyn_out.rs did).
        let last = self.last_dt.filter(|&l| l == self.settings.time_step);
        for (slot, &(i, kind)) in self.layout.unknown_slots.iter().enumerate() {
            let tau = h * i as f64;
            let guided = guide
                .as_ref()
                .map(|c| CubicBasis::new(c.length, tau / c.length));
            let extrapolated = last.map(|l| CubicBasis::new(l, 1.0 + tau / l));
            for g in 0..n {
                let Some(u) = self.layout.unknown_at(slot, g) else {
                    continue;
                };
                let pick = |(e, v): (f64, f64)| match kind {
                    Kind::Position => e,
                    Kind::Velocity => v,
                };
                self.x[u] = if self.model.constraints.is_constrained(g) {
                    match kind {
                        Kind::Position => self.start.fixed_e[i * n + g],
                        Kind::Velocity => self.start.fixed_v[i * n + g],
                    }
                } else if let (Some(c), Some(basis)) = (&guide, &guided) {
                    pick(c.at(g, basis))
                } else if let Some(basis) = &extrapolated {
                    pick(basis.on([
                        self.previous.state.e[g],
                        self.last_slopes[g],
                        self.state.e[g],
                        self.last_slopes[n + g],
                    ]))
                } else {
                    let (e, v, a) = (self.state.e[g], self.state.v[g], self.acceleration[g]);
                    match kind {
                        Kind::Position => e + tau * v + 0.5 * tau * tau * a,
                        Kind::Velocity => v + tau * a,
                    }
                };
            }
        }
    }

    /// The last converged step's cubic in time (None before the first
    /// step and after an undo).
    pub fn last_cubic(&self) -> Option<TimeCubic> {
        self.last_dt.map(|l| self.last_cubic_of(l))
    }

    fn last_cubic_of(&self, length: f64) -> TimeCubic {
        let n = self.model.dofs();
        TimeCubic {
            e0: self.previous.state.e.clone(),
            w0: self.last_slopes[..n].to_vec(),
            e1: self.state.e.clone(),
            w1: self.last_slopes[n..].to_vec(),
            length,
            t0: self.previous.state.t,
        }
    }

    /// The next step's predictor evaluates `cubic` from its start (a
    /// step over the same start, e.g. a doubled step's whole for its
    /// first half, docs/method.md §11.17), once.
    pub fn guide_next_step(&mut self, cubic: TimeCubic) {
        self.guide = Some(cubic);
    }

    /// Returns to the state before the last converged step (once).
    pub fn undo_last_step(&mut self) {
        if self.steps == 0 || self.previous.state.t == self.state.t {
            return;
        }
        self.state.clone_from(&self.previous.state);
        self.momentum.copy_from_slice(&self.previous.momentum);
        self.acceleration
            .copy_from_slice(&self.previous.acceleration);
        self.constraint_work = self.previous.constraint_work;
        self.drag_work = self.previous.drag_work;
        self.damping_work = self.previous.damping_work;
        self.seabed_work = self.previous.seabed_work;
        self.water_work = self.previous.water_work;
        self.moment_angles
            .copy_from_slice(&self.previous.moment_angles);
        self.reactions.copy_from_slice(&self.previous.reactions);
        self.steps -= 1;
        self.last_dt = None;
        let h = self.slab.dt;
        self.start
            .set(&self.model, self.state.t, &self.state.e, &self.state.v, h);
        self.start.set_internal(&self.state.internal);
    }

    /// Advances the state by one step. On failure the state is left at the
    /// last converged step.
    pub fn step(&mut self) -> Result<StepReport, SolverError> {
        let dt = self.settings.time_step;
        self.begin_step();
        let newton = self.solve_slab(dt)?;
        Ok(self.finish_step(newton))
    }

    /// The known data of the next step and the predicted unknowns in
    /// [`Self::unknowns`].
    pub(crate) fn begin_step(&mut self) {
        let h = self.slab.dt;
        self.start
            .set(&self.model, self.state.t, &self.state.e, &self.state.v, h);
        self.start.set_internal(&self.state.internal);
        self.predict();
    }

    /// Completes the step whose converged unknowns are in
    /// [`Self::unknowns`].
    pub(crate) fn finish_step(&mut self, newton: NewtonReport) -> StepReport {
        self.expand_step();
        self.galerkin_end_rates();
        self.close_step(newton)
    }

    /// First part of [`Self::finish_step`]: keeps the undo data and
    /// expands the converged unknowns to the time nodes (the Galerkin
    /// step's end momentum dA/de_b included).
    pub(crate) fn expand_step(&mut self) {
        self.save_undo();
        self.expand_solution(self.settings.time_step);
    }

    /// Last part of [`Self::finish_step`], once the end rates are set:
    /// the reactions and the new state.
    pub(crate) fn close_step(&mut self, newton: NewtonReport) -> StepReport {
        let dt = self.settings.time_step;
        self.collect_reactions(dt);
        self.advance(dt);
        StepReport {
            step: self.steps,
            t: self.state.t,
            newton,
        }
    }

    /// Galerkin step of a line in a system whose end rates v_b come from
    /// the system's mass matrix (docs/method.md §11.10): the momentum
    /// its free coordinates must carry, `q = p_b - M_fc v_c` (p_b =
    /// dA/de_b, v_c the prescribed end rates of the constrained
    /// coordinates, M with the added mass M_a(e_b) of a line in water,
    /// (W31)), in `self.rhs` at the free coordinates (zero at the
    /// constrained ones). Call after [`Self::expand_step`]. `held`
    /// receives each direction hold's r_x momentum before (M43) turns it
    /// (a clamp at a free body carries it to the body, §15.19).
    pub(crate) fn free_end_momentum(&mut self, held: &mut Vec<[f64; 3]>) -> &[f64] {
        let n = self.model.dofs();
        for g in 0..n {
            self.mass_v[g] = self.prescribed_end_rate(g).unwrap_or(0.0);
        }
        let last = self.layout.layers();
        let end_e = &self.scratch.node_e[last * n..(last + 1) * n];
        self.model.momentum(end_e, &self.mass_v, &mut self.rhs);
        for g in 0..n {
            self.rhs[g] = if self.model.constraints.is_constrained(g) {
                0.0
            } else {
                self.scratch.end_momentum[g] - self.rhs[g]
            };
        }
        held.clear();
        for hold in &self.model.constraints.directions {
            let o = coordinate(self.layout.dpn, hold.node, SLOT_R_X, 0);
            held.push([self.rhs[o], self.rhs[o + 1], self.rhs[o + 2]]);
        }
        self.model
            .constraints
            .turn_hold_momentum(self.layout.dpn, &mut self.rhs);
        &self.rhs
    }

    /// The Galerkin step's impulse at t_b on direction hold h's r_x, M v_b
    /// - dA/de_b (M43), after the end rates are set.
    pub(crate) fn hold_end_impulse(&self, h: usize) -> [f64; 3] {
        let hold = &self.model.constraints.directions[h];
        let o = coordinate(self.layout.dpn, hold.node, SLOT_R_X, 0);
        std::array::from_fn(|c| self.mass_v[o + c] - self.scratch.end_momentum[o + c])
    }

    /// Sets direction hold h's frame (a clamp at a free body turned to the
    /// body's pose at the step's end, docs/method.md §15.19).
    pub(crate) fn set_direction_hold(&mut self, h: usize, hold: crate::constraints::DirectionHold) {
        self.model.constraints.directions[h] = hold;
    }

    /// The coordinates e_b at the step's end (after [`Self::expand_step`]).
    pub(crate) fn end_coordinates(&self) -> &[f64] {
        let n = self.model.dofs();
        let last = self.layout.layers();
        &self.scratch.node_e[last * n..(last + 1) * n]
    }

    /// Sets the Galerkin step's end rates v_b (the prescribed ones at
    /// constrained coordinates, `free_rate(g)` at the others) and M v_b,
    /// in place of the line's own mass solve. Call between
    /// [`Self::expand_step`] and [`Self::close_step`].
    pub(crate) fn set_end_rates(&mut self, free_rate: impl Fn(usize) -> f64) {
        let n = self.model.dofs();
        let last = self.layout.layers();
        for g in 0..n {
            self.rhs[g] = self.prescribed_end_rate(g).unwrap_or_else(|| free_rate(g));
            self.scratch.node_v[last * n + g] = self.rhs[g];
        }
        let end_e = &self.scratch.node_e[last * n..(last + 1) * n];
        self.model.momentum(end_e, &self.rhs, &mut self.mass_v);
    }

    /// The prescribed rate of coordinate g at the step's end (None if it
    /// is free).
    fn prescribed_end_rate(&self, g: usize) -> Option<f64> {
        let n = self.model.dofs();
        let last = self.layout.layers();
        self.model
            .constraints
            .is_constrained(g)
            .then(|| self.start.fixed_v[last * n + g])
    }

    /// Galerkin: the line's share of the end impulse at coordinate g,
    /// `dA/de_b - M v_b` (the end row's part that P2 carries in its
    /// e_L row, docs/method.md §5.1); zero for P2.
    pub(crate) fn galerkin_end_term(&self, g: usize) -> f64 {
        if self.layout.scheme.end_variation_is_momentum() {
            self.scratch.end_momentum[g] - self.mass_v[g]
        } else {
            0.0
        }
    }

    /// The step's unknowns (the predictor's, or the converged ones).
    pub(crate) fn unknowns(&mut self) -> &mut [f64] {
        &mut self.x
    }

    /// The step's rows at `x` (this line's numbering) into `residual` and
    /// their derivatives added to `jacobian`.
    pub(crate) fn assemble_line<J: crate::linear::AddEntries>(
        &mut self,
        x: &[f64],
        residual: &mut [f64],
        jacobian: Option<&mut J>,
    ) {
        let problem = StepProblem {
            model: &self.model,
            layout: &self.layout,
            slab: &self.slab,
            start: &self.start,
        };
        problem.assemble_into(x, residual, jacobian, &mut self.scratch);
    }

    /// Keeps the predicted unknowns (see [`Self::restore_prediction`]).
    pub(crate) fn keep_prediction(&mut self) {
        self.x_predicted.copy_from_slice(&self.x);
    }

    /// Puts back the unknowns kept by [`Self::keep_prediction`]: after a
    /// failed solve the Lagrange multipliers would otherwise start the
    /// retried step from the failed iterate's values.
    pub(crate) fn restore_prediction(&mut self) {
        self.x.copy_from_slice(&self.x_predicted);
    }

    /// The convergence scales of the step's unknowns and rows.
    pub(crate) fn scales(&self) -> &Scales {
        &self.scales
    }

    /// Newton's solve of the step's equations from the predicted `x`
    /// (docs/method.md §4.2-4.3, §5.1; the solvers, §7).
    pub(crate) fn solve_slab(&mut self, dt: f64) -> Result<NewtonReport, SolverError> {
        let mut system = StepSystem {
            problem: StepProblem {
                model: &self.model,
                layout: &self.layout,
                slab: &self.slab,
                start: &self.start,
            },
            scales: &self.scales,
            scratch: &mut self.scratch,
        };
        let result = solve(
            &mut system,
            &mut self.x,
            &self.settings.newton,
            &mut self.workspace,
            self.clock.as_deref(),
        );
        match result {
            Ok(r) => Ok(r),
            Err(f) => Err(SolverError {
                kind: f.kind,
                time: self.state.t,
                step: self.steps + 1,
                residual: f.report.residual,
                iterations: f.report.iterations,
                detail: format!("time step {dt:e} s"),
            }),
        }
    }

    /// Keeps what [`Simulation::undo_last_step`] needs to return to the
    /// state before this step.
    fn save_undo(&mut self) {
        self.previous.state.clone_from(&self.state);
        self.previous.momentum.copy_from_slice(&self.momentum);
        self.previous
            .acceleration
            .copy_from_slice(&self.acceleration);
        self.previous.constraint_work = self.constraint_work;
        self.previous.drag_work = self.drag_work;
        self.previous.damping_work = self.damping_work;
        self.previous.seabed_work = self.seabed_work;
        self.previous.water_work = self.water_work;
        self.previous
            .moment_angles
            .copy_from_slice(&self.moment_angles);
        self.previous.reactions.copy_from_slice(&self.reactions);
    }

    /// The time-node values at the solution (and, for eliminated
    /// constraints, the freed rows: the reactions; with drag and damping,
    /// their work, docs/method.md §2.8, §2.10), and the end slopes of the step for the next
    /// predictor (§4.8).
    fn expand_solution(&mut self, dt: f64) {
        let problem = StepProblem {
            model: &self.model,
            layout: &self.layout,
            slab: &self.slab,
            start: &self.start,
        };
        let eliminated = !self.model.constraints.is_empty()
            && (self.layout.method == ConstraintMethod::Elimination
                || self.model.constraints.has_inactive());
        let galerkin = self.settings.time_scheme.carries_momentum();
        let works = !self.model.drag.is_empty()
            || self.model.has_axial_damping()
            || self.model.has_internal_state()
            || self.model.seabed.is_some()
            || self.model.water.is_some();
        if eliminated || galerkin || works {
            problem.residual(&self.x, &mut self.workspace.spare, &mut self.scratch);
            self.drag_work += self.scratch.drag_work;
            self.damping_work += self.scratch.damping_work;
            self.seabed_work += self.scratch.seabed_work;
            self.water_work += self.scratch.water_work;
        } else {
            problem.expand(&self.x, &mut self.scratch);
        }
        let n = self.model.dofs();
        let last = self.layout.layers();
        self.last_slopes[..n].copy_from_slice(&self.scratch.node_v[..n]);
        self.last_slopes[n..].copy_from_slice(&self.scratch.node_v[last * n..(last + 1) * n]);
        self.last_dt = Some(dt);
    }

    /// Galerkin step, after convergence (docs/method.md §5.1, (M22)):
    /// p_b = dA/de_b; v_b = M^-1 p_b with the constrained rates, written
    /// to the end time node; p(e_b, v_b) kept for the reactions and the
    /// momentum. With added mass M is M + M_a(e_b) (W31), factorized here.
    fn galerkin_end_rates(&mut self) {
        let n = self.model.dofs();
        let last = self.layout.layers();
        let end_e = &self.scratch.node_e[last * n..(last + 1) * n];
        if let (Some(lu), true) = (&mut self.mass_lu, self.model.added_mass().is_some()) {
            super::entrained::factorize_constrained_mass(lu, &self.model, end_e)
                .expect("M + M_a is positive definite (Ca >= 0, validated)");
        }
        if let Some(lu) = &self.mass_lu {
            // p_b = dA/de_b; v_b = M^-1 p_b with the constrained rates.
            for g in 0..n {
                self.rhs[g] = self
                    .prescribed_end_rate(g)
                    .unwrap_or(self.scratch.end_momentum[g]);
            }
            let dpn = self.layout.dpn;
            self.model
                .constraints
                .turn_hold_momentum(dpn, &mut self.rhs);
            lu.solve(&mut self.rhs);
            let end_e = &self.scratch.node_e[last * n..(last + 1) * n];
            self.model.momentum(end_e, &self.rhs, &mut self.mass_v);
            for g in 0..n {
                self.scratch.node_v[last * n + g] = self.rhs[g];
            }
        }
    }

    /// Moves the state to the end of the step: e, v, the acceleration for
    /// the predictor, the carried momentum (Galerkin), the time, the step
    /// count and the unwrapped end-moment angles (docs/method.md §2.7).
    fn advance(&mut self, dt: f64) {
        let n = self.model.dofs();
        let last = self.layout.layers();
        let galerkin = self.settings.time_scheme.carries_momentum();
        for g in 0..n {
            let e_new = self.scratch.node_e[last * n + g];
            let v_new = self.scratch.node_v[last * n + g];
            self.acceleration[g] = (v_new - self.state.v[g]) / dt;
            self.state.e[g] = e_new;
            self.state.v[g] = v_new;
            if galerkin {
                // A constrained coordinate, and a held r_x (its hold's
                // impulse at t_b is in M v_b, (M43)), carry M v_b.
                let held = |g| self.model.constraints.held_direction(self.layout.dpn, g);
                self.momentum[g] = if self.model.constraints.is_constrained(g) || held(g).is_some()
                {
                    self.mass_v[g]
                } else {
                    self.scratch.end_momentum[g]
                };
            }
        }
        // A viscoelastic line's internal state at the step's end, from
        // the residual at the solution (docs/method.md §2.11), taken with
        // e, v and t (a system's step may still fail after its lines'
        // expand_step, and is then retried from the start).
        if !self.state.internal.is_empty() {
            self.state
                .internal
                .copy_from_slice(&self.scratch.internal_end);
        }
        self.state.t += dt;
        self.steps += 1;
        for a in &mut self.moment_angles {
            let o = coordinate(self.layout.dpn, a.node, SLOT_R_X, 0);
            a.update(&[self.state.e[o], self.state.e[o + 1], self.state.e[o + 2]]);
        }
    }
}
