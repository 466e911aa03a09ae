//! Time stepping with the P2 formula, eq. (22): one space-time slab per
//! step, optionally several element layers in time per step.
//!
//! [`Simulation::step`] advances the state by one step with Newton's method;
//! [`run`] steps to a final time, hands every converged state to an
//! observer and stops at the first step that fails or makes the mechanical
//! energy grow without a source (method notes: P2 is only conditionally
//! stable, and an unstable step must end the run, not write garbage).

use crate::assembly::{AssemblyScratch, Kind, Scales, SlabLayout, StepProblem, StepStart};
use crate::band::BandMatrix;
use crate::element::TimeSlab;
use crate::error::{FailureKind, ModelError, SolverError};
use crate::model::{Model, State};
use crate::observe::{energies, Energies};
use crate::quadrature::GaussRule;
use std::ops::ControlFlow;

use crate::solver::{newton, NewtonReport, NewtonSettings, NewtonWorkspace, NonlinearSystem};

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
}

impl Default for StepSettings {
    fn default() -> Self {
        StepSettings {
            time_step: 1e-4,
            time_layers: 1,
            time_points: 3,
            newton: NewtonSettings::default(),
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
    /// The state before the last step and its acceleration estimate, so
    /// that a step can be undone.
    previous: State,
    previous_acceleration: Vec<f64>,
    /// Acceleration estimate from the last step, for the predictor.
    acceleration: Vec<f64>,
    start: StepStart,
    x: Vec<f64>,
    workspace: NewtonWorkspace,
    scratch: AssemblyScratch,
    steps: usize,
}

impl Simulation {
    /// Prepares a simulation from `initial` (which must have the model's
    /// size).
    pub fn new(model: Model, initial: State, settings: StepSettings) -> Result<Self, ModelError> {
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
        let layout = SlabLayout::new(&model, settings.time_layers);
        let h = dt / settings.time_layers as f64;
        let slab = TimeSlab::new(h, &time_rule);
        let scales = Scales::new(&model, &layout, h);
        let (kl, ku) = layout.bandwidths();
        let workspace = NewtonWorkspace::new(layout.size(), kl, ku, settings.newton.max_iterations);
        let scratch = AssemblyScratch::new(&model);
        let mut start = StepStart {
            e: initial.e.clone(),
            v: initial.v.clone(),
            mass_v: vec![0.0; n],
        };
        model.mass_times(&start.v, &mut start.mass_v);
        Ok(Simulation {
            x: vec![0.0; layout.size()],
            acceleration: vec![0.0; n],
            previous: initial.clone(),
            previous_acceleration: vec![0.0; n],
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
        })
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
    pub fn unknowns_per_step(&self) -> usize {
        self.layout.size()
    }

    /// Scaled residual norms of every evaluation of the last step.
    pub fn residual_history(&self) -> &[f64] {
        &self.workspace.residual_history
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
    }

    /// Predictor: Taylor expansion with the last step's acceleration,
    /// e(t_i) = e_a + tau v_a + tau^2 a / 2, v(t_i) = v_a + tau a.
    fn predict(&mut self) {
        let h = self.slab.dt;
        let dpn = self.layout.dpn;
        for node in 0..self.layout.nodes {
            for i in 1..=self.layout.layers {
                let tau = h * i as f64;
                let ue = self.layout.unknown(i, Kind::Position, node).expect("e_i");
                let uv = self.layout.unknown(i, Kind::Velocity, node).expect("v_i");
                for c in 0..dpn {
                    let g = node * dpn + c;
                    let (e, v, a) = (self.state.e[g], self.state.v[g], self.acceleration[g]);
                    self.x[ue + c] = e + tau * v + 0.5 * tau * tau * a;
                    self.x[uv + c] = v + tau * a;
                }
            }
        }
    }

    /// Returns to the state before the last converged step (once).
    pub fn undo_last_step(&mut self) {
        if self.steps == 0 || self.previous.t == self.state.t {
            return;
        }
        self.state.clone_from(&self.previous);
        self.acceleration
            .copy_from_slice(&self.previous_acceleration);
        self.steps -= 1;
        self.start.e.copy_from_slice(&self.state.e);
        self.start.v.copy_from_slice(&self.state.v);
        self.model.mass_times(&self.start.v, &mut self.start.mass_v);
    }

    /// Advances the state by one step. On failure the state is left at the
    /// last converged step.
    pub fn step(&mut self) -> Result<StepReport, SolverError> {
        let dt = self.settings.time_step;
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
        let result = newton(
            &mut system,
            &mut self.x,
            &self.settings.newton,
            &mut self.workspace,
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
        let last = self.layout.layers;
        let dpn = self.layout.dpn;
        self.previous.clone_from(&self.state);
        self.previous_acceleration
            .copy_from_slice(&self.acceleration);
        for node in 0..self.layout.nodes {
            let ue = self
                .layout
                .unknown(last, Kind::Position, node)
                .expect("e_L");
            let uv = self
                .layout
                .unknown(last, Kind::Velocity, node)
                .expect("v_L");
            for c in 0..dpn {
                let g = node * dpn + c;
                let v_new = self.x[uv + c];
                self.acceleration[g] = (v_new - self.state.v[g]) / dt;
                self.state.e[g] = self.x[ue + c];
                self.state.v[g] = v_new;
            }
        }
        self.state.t += dt;
        self.steps += 1;
        self.start.e.copy_from_slice(&self.state.e);
        self.start.v.copy_from_slice(&self.state.v);
        self.model.mass_times(&self.start.v, &mut self.start.mass_v);
        Ok(StepReport {
            step: self.steps,
            t: self.state.t,
            newton: report,
        })
    }
}

/// Watches the mechanical energy of a run for growth without a source.
///
/// The cable under gravity and constant point forces conserves
/// E = T + U + V_g + V_F; P2 keeps it within a bounded oscillation when the
/// step is stable. A change of E by more than `ratio` times the energy
/// scale of the motion so far (the largest T + U seen, plus the largest
/// change of the potentials) can only come from an unstable step.
#[derive(Clone, Debug)]
pub struct EnergyWatch {
    pub ratio: f64,
    initial: Energies,
    scale: f64,
}

impl EnergyWatch {
    pub fn new(initial: Energies, ratio: f64) -> Self {
        EnergyWatch {
            ratio,
            initial,
            scale: initial.kinetic.abs() + initial.strain.abs(),
        }
    }

    /// Records a state's energies; Err(drift) if they grew without a source.
    pub fn check(&mut self, en: &Energies) -> Result<(), f64> {
        let potential_change = (en.gravity - self.initial.gravity).abs()
            + (en.load_potential - self.initial.load_potential).abs();
        self.scale = self
            .scale
            .max(en.kinetic.abs() + en.strain.abs() + potential_change);
        let drift = en.mechanical() - self.initial.mechanical();
        let floor = 1e3 * f64::EPSILON * (en.magnitude() + self.initial.magnitude());
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
    let mut watch = EnergyWatch::new(energies(&sim.model, &sim.state), ENERGY_GROWTH_RATIO);
    for k in 1..=n_steps {
        let h = if k == n_steps {
            t0 + duration - sim.state.t
        } else {
            dt
        };
        sim.set_time_step(h);
        let report = sim.step()?;
        let en = energies(&sim.model, &sim.state);
        if !en.mechanical().is_finite() {
            sim.undo_last_step();
            return Err(SolverError {
                kind: FailureKind::NonFinite,
                time: sim.state.t,
                step: report.step,
                residual: report.newton.residual,
                iterations: report.newton.iterations,
                detail: "the energy is not finite".into(),
            });
        }
        if let Err(drift) = watch.check(&en) {
            sim.undo_last_step();
            return Err(SolverError {
                kind: FailureKind::EnergyGrowth,
                time: sim.state.t,
                step: report.step,
                residual: report.newton.residual,
                iterations: report.newton.iterations,
                detail: format!(
                    "energy {:.6e} J, {:.3e} J above the initial {:.6e} J; reduce the time step",
                    en.mechanical(),
                    drift,
                    watch.initial.mechanical()
                ),
            });
        }
        if observer(sim, &report, &en).is_break() {
            return Ok(false);
        }
    }
    Ok(true)
}
