//! Time stepping with the P2 formula, eq. (22): one space-time slab per
//! step, optionally several element layers in time per step
//! (docs/method.md §4; the Galerkin step, §5).
//!
//! [`Simulation::step`] advances the state by one step with Newton's method;
//! [`run`] steps to a final time, hands every converged state to an
//! observer and stops at the first step that fails or makes the mechanical
//! energy grow without a source (docs/method.md §4.5 and §8: P2 is only
//! conditionally stable, and an unstable step must end the run, not write
//! garbage).

use crate::assembly::{AssemblyScratch, Kind, Scales, Scheme, SlabLayout, StepProblem, StepStart};
use crate::band::{BandLu, BandMatrix};
use crate::constraints::ConstraintMethod;
use crate::element::TimeSlab;
use crate::error::{FailureKind, ModelError, SolverError};
use crate::loads::{EndMoment, MomentAngle};
use crate::model::{Model, State};
use crate::observe::{energies, Energies};
use crate::quadrature::GaussRule;
use std::ops::ControlFlow;

use crate::solver::{
    solve, Clock, NewtonReport, NewtonSettings, NewtonWorkspace, NonlinearSystem, Timing,
};

/// How a step is taken.
#[derive(Clone, Debug, PartialEq)]
pub struct StepSettings {
    /// Step (slab) length dt.
    pub time_step: f64,
    /// Element layers in time per step.
    pub time_layers: usize,
    /// Gauss points in time per layer.
    pub time_points: usize,
    pub newton: NewtonSettings,
    /// How constraints are enforced.
    pub constraint_method: ConstraintMethod,
    /// P2 (the paper's, eq. 22) or the Galerkin step (all four variations).
    pub time_scheme: TimeScheme,
    /// Eliminate the out-of-plane coordinates when the motion is planar
    /// ([`Model::reduce_to_plane`]): the same motion, a third fewer
    /// unknowns.
    pub planar_reduction: bool,
}

/// Which equations a step solves (docs/method.md §4.2-4.3 for P2, §5 for
/// the Galerkin step).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum TimeScheme {
    /// Hamilton's law with the P2 formula, eq. (22): conditionally stable,
    /// fourth order.
    #[default]
    P2,
    /// The Galerkin variational integrator on the cubic slab: with 3 Gauss
    /// points in time the 3-stage Gauss-Legendre method, unconditionally
    /// stable, sixth order, symplectic; one layer per step.
    Galerkin,
}

impl Default for StepSettings {
    fn default() -> Self {
        StepSettings {
            time_step: 1e-4,
            time_layers: 1,
            time_points: 3,
            newton: NewtonSettings::default(),
            constraint_method: ConstraintMethod::default(),
            time_scheme: TimeScheme::default(),
            planar_reduction: true,
        }
    }
}

/// How one step went.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct StepReport {
    /// Index of the step (1 = first).
    pub step: usize,
    /// Time at the end of the step.
    pub t: f64,
    pub newton: NewtonReport,
}

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

/// A running simulation: the model, the current state and everything a step
/// needs, allocated once.
pub struct Simulation {
    model: Model,
    settings: StepSettings,
    time_rule: GaussRule,
    layout: SlabLayout,
    slab: TimeSlab,
    scales: Scales,
    state: State,
    /// Acceleration estimate from the last step, for the predictor.
    acceleration: Vec<f64>,
    /// Slopes de/dt of the last step's cubic at its start and end,
    /// `[g]` and `[n + g]` (P2: v_a, v_b; Galerkin: w_a, w_b), for the
    /// extrapolating predictor; valid when `last_dt` is the current step.
    last_slopes: Vec<f64>,
    last_dt: Option<f64>,
    start: StepStart,
    x: Vec<f64>,
    workspace: NewtonWorkspace,
    scratch: AssemblyScratch,
    steps: usize,
    /// Mean force of each position constraint over the last step:
    /// (node, force on the cable).
    reactions: Vec<(usize, [f64; 3])>,
    /// Work done on the cable by the constraints (prescribed motion).
    constraint_work: f64,
    /// Work done on the cable by the drag loads (negative in still air).
    drag_work: f64,
    /// Unwrapped angles of the end moments.
    moment_angles: Vec<MomentAngle>,
    /// What is needed to undo the last step.
    previous: Undo,
    /// Wall clock for the Part A / Part B split of eq. (32), if given.
    clock: Option<Box<dyn Clock>>,
    /// Galerkin: the momentum p carried from step to step, and the factors
    /// of the mass matrix with the rows of constrained coordinates replaced
    /// by identity rows (v_b = M^-1 p_b with prescribed constrained rates).
    momentum: Vec<f64>,
    mass_lu: Option<BandLu>,
    /// v_b and M v_b (Galerkin scratch).
    rhs: Vec<f64>,
    mass_v: Vec<f64>,
}

#[derive(Clone, Debug)]
struct Undo {
    state: State,
    momentum: Vec<f64>,
    acceleration: Vec<f64>,
    constraint_work: f64,
    drag_work: f64,
    moment_angles: Vec<MomentAngle>,
    reactions: Vec<(usize, [f64; 3])>,
}

impl Simulation {
    /// Prepares a simulation from `initial` (which must have the model's
    /// size; its constrained coordinates are set to their prescribed values
    /// and rates at `initial.t`).
    pub fn new(model: Model, initial: State, settings: StepSettings) -> Result<Self, ModelError> {
        let mut model = model;
        let dt = settings.time_step;
        let time_rule = check_settings(&settings)?;
        check_initial_state(&model, &initial)?;
        let n = model.dofs();
        let mut initial = initial;
        model.apply_constraints(&mut initial);
        check_end_moments(&model, &initial.e)?;
        if settings.planar_reduction {
            model.reduce_to_plane(&initial);
        }
        let layers = settings.time_layers;
        let scheme = match settings.time_scheme {
            TimeScheme::P2 => Scheme::P2 { layers },
            TimeScheme::Galerkin => Scheme::Galerkin,
        };
        let layout = SlabLayout::new(&model, scheme, settings.constraint_method);
        let h = dt / layers as f64;
        let slab = TimeSlab::new(h, &time_rule);
        let scales = Scales::new(&model, &layout, h);
        let (kl, ku) = layout.bandwidths();
        let workspace = NewtonWorkspace::new(layout.size(), kl, ku, settings.newton.max_iterations);
        let scratch = AssemblyScratch::new(&model, &layout);
        let mut start = StepStart::new(&model, layout.time_nodes());
        start.set(&model, initial.t, &initial.e, &initial.v, h);
        let reference = model.reference_coordinates();
        let mut moment_angles = Vec::new();
        for (node, m) in model.end_moments() {
            let Some(moment) = EndMoment::from_vector(&m) else {
                continue;
            };
            let o = model.node_offset(node) + 3;
            let r0 = [reference[o], reference[o + 1], reference[o + 2]];
            let rx = [initial.e[o], initial.e[o + 1], initial.e[o + 2]];
            moment_angles.push(MomentAngle::new(moment, node, r0, &rx));
        }
        let reactions: Vec<(usize, [f64; 3])> = model
            .constraints
            .position_nodes
            .iter()
            .map(|&nd| (nd, [0.0; 3]))
            .collect();
        let mut momentum = vec![0.0; n];
        model.mass_times(&initial.v, &mut momentum);
        let mass_lu = if scheme == Scheme::Galerkin {
            let (_, mass) = crate::assembly::stiffness_and_mass(&model, &initial.e);
            let (kl, ku) = (mass.lower_bandwidth(), mass.upper_bandwidth());
            let mut lu = BandLu::new(n, kl, ku);
            let a = lu.matrix_mut();
            for i in 0..n {
                if model.constraints.is_constrained(i) {
                    a.add(i, i, 1.0);
                    continue;
                }
                for j in i.saturating_sub(kl)..=(i + ku).min(n - 1) {
                    a.add(i, j, mass.get(i, j));
                }
            }
            lu.factorize()
                .map_err(|_| ModelError::invalid("material", "the mass matrix is singular"))?;
            Some(lu)
        } else {
            None
        };
        let previous = Undo {
            momentum: vec![0.0; n],
            state: initial.clone(),
            acceleration: vec![0.0; n],
            constraint_work: 0.0,
            drag_work: 0.0,
            moment_angles: moment_angles.clone(),
            reactions: reactions.clone(),
        };
        Ok(Simulation {
            x: vec![0.0; layout.size()],
            acceleration: vec![0.0; n],
            last_slopes: vec![0.0; 2 * n],
            last_dt: None,
            model,
            settings,
            time_rule,
            layout,
            slab,
            scales,
            state: initial,
            start,
            workspace,
            scratch,
            steps: 0,
            reactions,
            constraint_work: 0.0,
            drag_work: 0.0,
            moment_angles,
            previous,
            clock: None,
            momentum,
            mass_lu,
            rhs: vec![0.0; n],
            mass_v: vec![0.0; n],
        })
    }

    /// Times Part A (element evaluation and assembly) and Part B (linear
    /// algebra) of every step with this clock (eq. 32).
    pub fn set_clock(&mut self, clock: Box<dyn Clock>) {
        self.clock = Some(clock);
    }

    /// Accumulated Part A / Part B times (zero without a clock).
    pub fn timing(&self) -> Timing {
        self.workspace.timing
    }

    pub fn model(&self) -> &Model {
        &self.model
    }

    pub fn state(&self) -> &State {
        &self.state
    }

    pub fn settings(&self) -> &StepSettings {
        &self.settings
    }

    pub fn time_rule(&self) -> &GaussRule {
        &self.time_rule
    }

    /// Steps taken so far.
    pub fn steps(&self) -> usize {
        self.steps
    }

    /// Unknowns solved for in every step.
    /// Whether the out-of-plane coordinates are eliminated (planar motion,
    /// [`StepSettings::planar_reduction`]).
    pub fn is_planar(&self) -> bool {
        self.model.constraints.has_inactive()
    }

    pub fn unknowns_per_step(&self) -> usize {
        self.layout.size()
    }

    /// Scaled residual norms of every evaluation of the last step.
    pub fn residual_history(&self) -> &[f64] {
        &self.workspace.residual_history
    }

    /// The force each position constraint exerted on the cable, averaged
    /// over the last step: its impulse (the multipliers of the freed P2
    /// rows of r, or the values of the eliminated rows) divided by dt.
    /// With it the discrete momentum balance is exact:
    /// P_b - P_a = (m g + sum of reactions) dt (docs/method.md §6.5, (M23);
    /// §4.4, (M18)).
    pub fn reactions(&self) -> &[(usize, [f64; 3])] {
        &self.reactions
    }

    /// Work done on the cable by the constraints so far (zero unless a
    /// constraint moves): sum over steps of reaction . displacement
    /// (docs/method.md §6.6, (M24)).
    pub fn constraint_work(&self) -> f64 {
        self.constraint_work
    }

    /// Work done on the cable by the drag loads so far: the slab integral
    /// of f . r_dot over every step (negative in still air; docs/method.md
    /// §2.8, (M12)).
    pub fn drag_work(&self) -> f64 {
        self.drag_work
    }

    /// Energies of the current state; `load_potential` includes -M theta
    /// of the end moments with theta followed continuously (docs/method.md
    /// §2.7, (M8)).
    pub fn energies(&self) -> Energies {
        let mut en = energies(&self.model, &self.state);
        en.load_potential += self
            .moment_angles
            .iter()
            .map(|a| a.potential())
            .sum::<f64>();
        en
    }

    /// Changes the step length (e.g. to land exactly on the final time).
    pub fn set_time_step(&mut self, dt: f64) {
        if dt == self.settings.time_step {
            return;
        }
        self.settings.time_step = dt;
        let h = dt / self.settings.time_layers as f64;
        self.slab = TimeSlab::new(h, &self.time_rule);
        self.scales = Scales::new(&self.model, &self.layout, h);
        self.workspace.factors_valid = false;
    }

    /// Predictor (docs/method.md §4.8). After a converged step of the same
    /// length: the last step's cubic in time (end values e, end slopes,
    /// eq. 6) extrapolated over the new step, which is third order in dt
    /// (a predictor error of O(dt^4) in e), so the corrector needs fewer
    /// iterations. Otherwise (first step, after an undo or a change of
    /// step): Taylor expansion with the last step's acceleration,
    /// e(t_i) = e_a + tau v_a + tau^2 a / 2, v(t_i) = v_a + tau a.
    /// Constrained coordinates take their prescribed values; the
    /// multipliers keep their last values.
    fn predict(&mut self) {
        let h = self.slab.dt;
        let dt = self.settings.time_step;
        let n = self.model.dofs();
        let extrapolate = self.last_dt == Some(dt);
        for (slot, &(i, kind)) in self.layout.unknown_slots.iter().enumerate() {
            let tau = h * i as f64;
            // Hermite basis of the last step at s = 1 + tau / dt.
            let s = 1.0 + tau / dt;
            let (s2, s3) = (s * s, s * s * s);
            let value = [
                2.0 * s3 - 3.0 * s2 + 1.0,
                s3 - 2.0 * s2 + s,
                -2.0 * s3 + 3.0 * s2,
                s3 - s2,
            ];
            let slope = [
                6.0 * s2 - 6.0 * s,
                3.0 * s2 - 4.0 * s + 1.0,
                -6.0 * s2 + 6.0 * s,
                3.0 * s2 - 2.0 * s,
            ];
            for g in 0..n {
                let Some(u) = self.layout.unknown_at(slot, g) else {
                    continue;
                };
                self.x[u] = if self.model.constraints.is_constrained(g) {
                    match kind {
                        Kind::Position => self.start.fixed_e[i * n + g],
                        Kind::Velocity => self.start.fixed_v[i * n + g],
                    }
                } else if extrapolate {
                    let (e0, e1) = (self.previous.state.e[g], self.state.e[g]);
                    let (w0, w1) = (self.last_slopes[g], self.last_slopes[n + g]);
                    match kind {
                        Kind::Position => {
                            value[0] * e0 + value[1] * dt * w0 + value[2] * e1 + value[3] * dt * w1
                        }
                        Kind::Velocity => {
                            (slope[0] * e0 + slope[2] * e1) / dt + slope[1] * w0 + slope[3] * w1
                        }
                    }
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

    /// Returns to the state before the last converged step (once).
    pub fn undo_last_step(&mut self) {
        if self.steps == 0 || self.previous.state.t == self.state.t {
            return;
        }
        self.state.clone_from(&self.previous.state);
        self.acceleration
            .copy_from_slice(&self.previous.acceleration);
        self.constraint_work = self.previous.constraint_work;
        self.drag_work = self.previous.drag_work;
        self.moment_angles
            .copy_from_slice(&self.previous.moment_angles);
        self.reactions.copy_from_slice(&self.previous.reactions);
        self.steps -= 1;
        self.last_dt = None;
        let h = self.slab.dt;
        self.start
            .set(&self.model, self.state.t, &self.state.e, &self.state.v, h);
    }

    /// Advances the state by one step. On failure the state is left at the
    /// last converged step.
    pub fn step(&mut self) -> Result<StepReport, SolverError> {
        let dt = self.settings.time_step;
        let h = self.slab.dt;
        self.start
            .set(&self.model, self.state.t, &self.state.e, &self.state.v, h);
        self.predict();
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
        let report = match result {
            Ok(r) => r,
            Err(f) => {
                return Err(SolverError {
                    kind: f.kind,
                    time: self.state.t,
                    step: self.steps + 1,
                    residual: f.report.residual,
                    iterations: f.report.iterations,
                    detail: format!("time step {dt:e} s"),
                })
            }
        };
        self.previous.state.clone_from(&self.state);
        self.previous.momentum.copy_from_slice(&self.momentum);
        self.previous
            .acceleration
            .copy_from_slice(&self.acceleration);
        self.previous.constraint_work = self.constraint_work;
        self.previous.drag_work = self.drag_work;
        self.previous
            .moment_angles
            .copy_from_slice(&self.moment_angles);
        self.previous.reactions.copy_from_slice(&self.reactions);
        // The time-node values at the solution (and, for eliminated
        // constraints, the freed rows: the reactions).
        let problem = StepProblem {
            model: &self.model,
            layout: &self.layout,
            slab: &self.slab,
            start: &self.start,
        };
        let eliminated = !self.model.constraints.is_empty()
            && (self.layout.method == ConstraintMethod::Elimination
                || self.model.constraints.has_inactive());
        let galerkin = self.mass_lu.is_some();
        if eliminated || galerkin || !self.model.drag.is_empty() {
            problem.assemble(&self.x, &mut self.workspace.spare, None, &mut self.scratch);
            self.drag_work += self.scratch.drag_work;
        } else {
            problem.expand(&self.x, &mut self.scratch);
        }
        let n = self.model.dofs();
        let last = self.layout.layers();
        self.last_slopes[..n].copy_from_slice(&self.scratch.node_v[..n]);
        self.last_slopes[n..].copy_from_slice(&self.scratch.node_v[last * n..(last + 1) * n]);
        self.last_dt = Some(dt);
        if let Some(lu) = &self.mass_lu {
            // p_b = dA/de_b; v_b = M^-1 p_b with the constrained rates.
            for g in 0..n {
                self.rhs[g] = if self.model.constraints.is_constrained(g) {
                    self.start.fixed_v[n + g]
                } else {
                    self.scratch.end_momentum[g]
                };
            }
            lu.solve(&mut self.rhs);
            self.model.mass_times(&self.rhs, &mut self.mass_v);
            for g in 0..n {
                self.scratch.node_v[last * n + g] = self.rhs[g];
            }
        }
        self.collect_reactions(dt);
        for g in 0..n {
            let e_new = self.scratch.node_e[last * n + g];
            let v_new = self.scratch.node_v[last * n + g];
            self.acceleration[g] = (v_new - self.state.v[g]) / dt;
            self.state.e[g] = e_new;
            self.state.v[g] = v_new;
            if galerkin {
                self.momentum[g] = if self.model.constraints.is_constrained(g) {
                    self.mass_v[g]
                } else {
                    self.scratch.end_momentum[g]
                };
            }
        }
        self.state.t += dt;
        self.steps += 1;
        for a in &mut self.moment_angles {
            let o = a.node * self.layout.dpn + 3;
            a.update(&[self.state.e[o], self.state.e[o + 1], self.state.e[o + 2]]);
        }
        Ok(StepReport {
            step: self.steps,
            t: self.state.t,
            newton: report,
        })
    }

    /// Reaction impulses of the step from the multipliers (or eliminated
    /// rows) of the position rows e_0, e_i, e_L, and the work of moving
    /// constraints (docs/method.md §6.5-6.6, (M23)-(M24)).
    fn collect_reactions(&mut self, dt: f64) {
        let n = self.model.dofs();
        let dpn = self.layout.dpn;
        let last = self.layout.layers();
        for (node, force) in self.reactions.iter_mut() {
            for c in 0..3 {
                let g = *node * dpn + c;
                let mut impulse = 0.0;
                for (s, &(_, kind)) in self.layout.row_slots.iter().enumerate() {
                    if kind != Kind::Position {
                        continue;
                    }
                    impulse += match self.layout.multiplier_at(s, g) {
                        Some(m) => self.x[m],
                        None => -self.scratch.reaction_rows[s * n + g],
                    };
                }
                if self.mass_lu.is_some() {
                    // Galerkin: the end part, p_b - dA/de_b with p_b = M v_b.
                    impulse += self.mass_v[g] - self.scratch.end_momentum[g];
                }
                force[c] = impulse / dt;
                let moved = self.scratch.node_e[last * n + g] - self.state.e[g];
                self.constraint_work += force[c] * moved;
            }
        }
    }
}

/// The checks of [`Simulation::new`] on the settings alone; the time
/// quadrature they ask for.
fn check_settings(settings: &StepSettings) -> Result<GaussRule, ModelError> {
    let dt = settings.time_step;
    if !dt.is_finite() || dt <= 0.0 {
        return Err(ModelError::invalid(
            "analysis.time_step",
            format!("must be > 0, got {dt}"),
        ));
    }
    if settings.time_layers == 0 {
        return Err(ModelError::invalid(
            "analysis.time_layers",
            "must be at least 1, got 0",
        ));
    }
    let time_rule = GaussRule::new(settings.time_points)
        .map_err(|e| ModelError::invalid("analysis.quadrature", e.message))?;
    let tol = settings.newton.tolerance;
    if !tol.is_finite() || tol <= 0.0 {
        return Err(ModelError::invalid(
            "analysis.tolerance",
            format!("must be > 0, got {tol}"),
        ));
    }
    if settings.newton.max_iterations == 0 {
        return Err(ModelError::invalid(
            "analysis.max_iterations",
            "must be at least 1",
        ));
    }
    let layers = settings.time_layers;
    if settings.time_scheme == TimeScheme::Galerkin && layers != 1 {
        return Err(ModelError::invalid(
            "analysis.time_layers",
            format!(
                "the Galerkin step takes one layer per step (got {layers}): joining \
                 layers by C1 interior nodes inside a Galerkin step is unstable \
                 (docs/method.md §5.4)"
            ),
        ));
    }
    Ok(time_rule)
}

/// The initial state has the model's size and is finite.
fn check_initial_state(model: &Model, initial: &State) -> Result<(), ModelError> {
    let n = model.dofs();
    if initial.e.len() != n || initial.v.len() != n {
        return Err(ModelError::invalid(
            "initial_state",
            format!(
                "expected {n} coordinates, got {} and {}",
                initial.e.len(),
                initial.v.len()
            ),
        ));
    }
    if initial
        .e
        .iter()
        .chain(initial.v.iter())
        .any(|v| !v.is_finite())
        || !initial.t.is_finite()
    {
        return Err(ModelError::invalid("initial_state", "must be finite"));
    }
    Ok(())
}

/// An end moment must bend the cable at coordinates `e`: a moment about
/// the end's own tangent is a torsion, which a cable cannot carry.
fn check_end_moments(model: &Model, e: &[f64]) -> Result<(), ModelError> {
    for (i, (node, m)) in model.end_moments().enumerate() {
        let Some(moment) = EndMoment::from_vector(&m) else {
            continue;
        };
        let o = model.node_offset(node) + 3;
        if !moment.acts_on(&[e[o], e[o + 1], e[o + 2]]) {
            return Err(ModelError::invalid(
                format!("loads[{i}].moment"),
                "the moment is about the cable's own tangent (a torsion, which a cable cannot carry)",
            ));
        }
    }
    Ok(())
}

/// The unknowns of the system every step of a [`Simulation`] of `model`
/// from `initial` with `settings` solves, and whether the planar reduction
/// applies ([`Simulation::unknowns_per_step`], [`Simulation::is_planar`]),
/// after the same checks as [`Simulation::new`] but without building it:
/// no copy of the model, no matrices, O(nodes) time and the memory of one
/// state (`stancf check` on a large mesh). The count is the numbering of
/// [`SlabLayout::new`]: every coordinate has one unknown per slot (2 per
/// time layer with P2, 3 with the Galerkin step) unless it is eliminated
/// (held by the planar reduction, or constrained with elimination), and a
/// constrained coordinate with multipliers has one multiplier per slot too.
pub fn step_unknowns(
    model: &Model,
    initial: &State,
    settings: &StepSettings,
) -> Result<(usize, bool), ModelError> {
    check_settings(settings)?;
    check_initial_state(model, initial)?;
    let mut state = initial.clone();
    model.apply_constraints(&mut state);
    check_end_moments(model, &state.e)?;
    // Model::reduce_to_plane holds the z coordinates, g = 2 mod 3.
    let reduces = settings.planar_reduction && model.planar_coordinates(&state).is_some();
    let planar = reduces || model.constraints.has_inactive();
    let slots = match settings.time_scheme {
        TimeScheme::P2 => 2 * settings.time_layers,
        TimeScheme::Galerkin => 3,
    };
    let elimination = settings.constraint_method == ConstraintMethod::Elimination;
    let held = |g: usize| model.constraints.is_inactive(g) || (reduces && g % 3 == 2);
    let mut size = 0;
    for g in 0..model.dofs() {
        let inactive = held(g);
        let constrained = model.constraints.is_constrained(g) && !inactive;
        if !(inactive || (elimination && constrained)) {
            size += slots;
        }
        if constrained && !elimination {
            size += slots;
        }
    }
    Ok((size, planar))
}

/// The model's own energy unit (J), never zero (`E_model` of docs/method.md
/// §8, (M29)): the energies of deformations and motions of order one of
/// this cable,
///
/// ```text
///   E_model = E A L + E I / L + m |g| L + sum |F| L + sum |M|
/// ```
///
/// (twice the strain energy of a unit axial strain over the length L and
/// of a bend to curvature 1 / L; the work of the weight m g and of the
/// point forces over a displacement L; that of the end moments over one
/// radian). E A > 0, so it is positive whatever the loads.
pub fn model_energy_scale(model: &Model) -> f64 {
    let m = &model.material;
    let l = model.cable.length;
    let norm = |v: [f64; 3]| (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt();
    let weight = m.density * m.area * l * norm(model.gravity);
    let forces: f64 = model.point_forces().map(|(_, f)| norm(f)).sum();
    let moments: f64 = model.end_moments().map(|(_, mo)| norm(mo)).sum();
    m.youngs_modulus * m.area * l
        + m.youngs_modulus * m.second_moment / l
        + (weight + forces) * l
        + moments
}

/// Relative size of the round-off in an energy evaluation and in the
/// energy balance of a step (a sum of many terms, each rounded to eps of
/// its size): changes of the energy below this times the magnitudes
/// involved are not resolved.
const ROUND_OFF: f64 = 1e3 * f64::EPSILON;

/// Energy changes of this model below this are round-off (J):
/// `1e3 eps E_model` ([`model_energy_scale`]). A cable at rest, or nearly,
/// has energies of O(eps^2 E_model): positions and slopes rounded to eps
/// give strains of O(eps), so 1/2 E A L eps^2; this is eps^-1 ~ 4.5e15 times
/// more, yet still nothing physical (for the paper's 4 m PVC cable 9e-9 J,
/// the energy of a strain of 7e-7).
pub fn energy_resolution(model: &Model) -> f64 {
    ROUND_OFF * model_energy_scale(model)
}

/// Watches the mechanical energy of a run for growth without a source
/// (docs/method.md §8, (M29)).
///
/// The cable under gravity, constant point forces and end moments
/// conserves E = T + U + V_g + V_F; P2 keeps it within a bounded
/// oscillation when the step is stable. Moving constraints and drag add
/// their work W. A rise of E - W by more than `ratio` times the energy
/// scale of the motion so far (the largest T + U seen, plus the largest
/// change of the potentials and the largest |W|) can only come from an
/// unstable step, provided it is also above the round-off of the energy
/// balance: `1e3 eps` times the magnitudes summed (the energies, |W|) and
/// the model's own energy unit ([`energy_resolution`]). Without that unit a
/// cable at rest, whose energy scale is itself round-off (1e-28 J), trips
/// on its own round-off. An unstable mode grows geometrically (P2 beyond
/// its limit: by up to 3 + 2 sqrt(2) per step in amplitude, docs/method.md
/// §4.5), so from round-off, O(eps^2 E_model), it passes the floor
/// within ln(1e3 / eps) / ln(rho^2) steps: about 20 at rho = 3.
#[derive(Clone, Debug)]
pub struct EnergyWatch {
    pub ratio: f64,
    initial: Energies,
    scale: f64,
    resolution: f64,
}

impl EnergyWatch {
    pub fn new(model: &Model, initial: Energies, ratio: f64) -> Self {
        EnergyWatch {
            ratio,
            initial,
            scale: initial.kinetic.abs() + initial.strain.abs(),
            resolution: energy_resolution(model),
        }
    }

    /// The energy scale of the motion so far.
    pub fn scale(&self) -> f64 {
        self.scale
    }

    /// Records a state's energies and the work of the constraints and the
    /// drag so far; Err(drift) if the energy grew without a source.
    pub fn check(&mut self, en: &Energies, external_work: f64) -> Result<(), f64> {
        let potential_change = (en.gravity - self.initial.gravity).abs()
            + (en.load_potential - self.initial.load_potential).abs();
        self.scale = self
            .scale
            .max(en.kinetic.abs() + en.strain.abs() + potential_change + external_work.abs());
        let drift = en.mechanical() - self.initial.mechanical() - external_work;
        let floor = ROUND_OFF * (en.magnitude() + self.initial.magnitude() + external_work.abs())
            + self.resolution;
        if drift > self.ratio * self.scale && drift > floor {
            Err(drift)
        } else {
            Ok(())
        }
    }
}

/// Default `ratio` of [`EnergyWatch`].
pub const ENERGY_GROWTH_RATIO: f64 = 0.1;

/// Number of steps [`run`] takes to cover `duration` with steps `dt` (the
/// last one shortened to land on it).
pub fn step_count(duration: f64, dt: f64) -> usize {
    ((duration / dt) - 1e-9).ceil().max(1.0) as usize
}

/// Steps `sim` until `duration` is covered (the last step is shortened to
/// land on it), calling `observer` after every converged step; the
/// observer may stop the run early with `ControlFlow::Break` (the result
/// is then `Ok(false)`). Stops at the first failure and leaves `sim` at
/// the last good state (a step that converged but made the energy grow is
/// undone); the states already observed stay valid.
pub fn run<F>(sim: &mut Simulation, duration: f64, mut observer: F) -> Result<bool, SolverError>
where
    F: FnMut(&Simulation, &StepReport, &Energies) -> ControlFlow<()>,
{
    let dt = sim.settings.time_step;
    let t0 = sim.state.t;
    let n_steps = step_count(duration, dt);
    let mut watch = EnergyWatch::new(&sim.model, sim.energies(), ENERGY_GROWTH_RATIO);
    for k in 1..=n_steps {
        let h = if k == n_steps {
            t0 + duration - sim.state.t
        } else {
            dt
        };
        sim.set_time_step(h);
        let report = sim.step()?;
        let en = sim.energies();
        let failure = |kind, detail: String, sim: &Simulation| SolverError {
            kind,
            time: sim.state.t,
            step: report.step,
            residual: report.newton.residual,
            iterations: report.newton.iterations,
            detail,
        };
        if !en.mechanical().is_finite() {
            sim.undo_last_step();
            return Err(failure(
                FailureKind::NonFinite,
                "the energy is not finite".into(),
                sim,
            ));
        }
        if let Err(drift) = watch.check(&en, sim.constraint_work + sim.drag_work) {
            sim.undo_last_step();
            let detail = format!(
                "energy {:.6e} J, {:.3e} J above the initial {:.6e} J; reduce the time step",
                en.mechanical() - sim.constraint_work - sim.drag_work,
                drift,
                watch.initial.mechanical()
            );
            return Err(failure(FailureKind::EnergyGrowth, detail, sim));
        }
        if observer(sim, &report, &en).is_break() {
            return Ok(false);
        }
    }
    Ok(true)
}
