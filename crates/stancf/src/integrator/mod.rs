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
//!
//! The files: this one holds the settings, the [`Simulation`] and its
//! accessors; `setup` builds a simulation and holds the checks it shares
//! with [`step_unknowns`]; `step` takes one step (predictor, Newton solve,
//! the Galerkin end terms, undo); `reactions` the constraint forces and
//! work; `watchdog` the energy watchdog; `run` the run loop.

mod entrained;
mod reactions;
mod run;
mod setup;
mod step;
mod watchdog;

pub use crate::scheme::TimeScheme;
pub(crate) use reactions::time_function;
pub use run::{run, step_count, step_length};
pub use setup::step_unknowns;
pub use watchdog::{
    energy_resolution, model_energy_scale, EnergyWatch, ENERGY_GROWTH_RATIO, ENERGY_ROUND_OFF,
};

use crate::assembly::{AssemblyScratch, Scales, SlabLayout, StepStart};
use crate::band::BandLu;
use crate::constraints::ConstraintMethod;
use crate::element::TimeSlab;
use crate::loads::MomentAngle;
use crate::model::{Model, State};
use crate::observe::{energies, Energies};
use crate::quadrature::GaussRule;
use crate::solver::{Clock, NewtonReport, NewtonSettings, NewtonWorkspace, Timing};

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

/// A running simulation: the model, the current state and everything a step
/// needs, allocated once. A clone is an independent copy of the whole
/// state, kept factors included (it steps on to the same bits).
#[derive(Clone)]
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
    /// A cubic in time the next step's predictor takes instead of the
    /// last step's (a doubled step's whole, for its first half; §11.17).
    guide: Option<TimeCubic>,
    start: StepStart,
    x: Vec<f64>,
    /// The step's predicted unknowns, kept while a system's lines are
    /// solved apart and put back when any line fails, so a retried step
    /// starts from the prediction (docs/method.md §11.14).
    x_predicted: Vec<f64>,
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
    /// Work done on the cable by its axial damping (never positive).
    damping_work: f64,
    /// Work done on the cable by the seabed (penalty, damping, friction).
    seabed_work: f64,
    /// Work done on the cable by the water (buoyancy, drag, inertia).
    water_work: f64,
    /// Unwrapped angles of the end moments.
    moment_angles: Vec<MomentAngle>,
    /// What is needed to undo the last step.
    previous: Undo,
    /// Wall clock for the Part A / Part B split of eq. (32), if given.
    clock: Option<std::sync::Arc<dyn Clock>>,
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
    damping_work: f64,
    seabed_work: f64,
    water_work: f64,
    moment_angles: Vec<MomentAngle>,
    reactions: Vec<(usize, [f64; 3])>,
}

impl Simulation {
    /// Times Part A (element evaluation and assembly) and Part B (linear
    /// algebra) of every step with this clock (eq. 32).
    pub fn set_clock(&mut self, clock: Box<dyn Clock>) {
        self.clock = Some(clock.into());
    }

    /// Accumulated Part A / Part B times (zero without a clock).
    pub fn timing(&self) -> Timing {
        self.workspace.timing
    }

    pub fn model(&self) -> &Model {
        &self.model
    }

    /// Sets the flow a host gives at the line's nodes (docs/method.md
    /// §12.1, (W2f)); a line whose sea's waves are not a host's keeps
    /// none.
    pub(crate) fn set_host_flow(&mut self, flow: crate::water::NodeFlow) {
        if let Some(w) = self.model.water.as_mut().filter(|w| w.host.is_some()) {
            w.host = Some(flow);
        }
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

    /// Whether the out-of-plane coordinates are eliminated (planar motion,
    /// [`StepSettings::planar_reduction`]).
    pub fn is_planar(&self) -> bool {
        self.model.constraints.has_inactive()
    }

    /// Unknowns solved for in every step.
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

    /// Work done on the cable by its axial damping so far: the slab
    /// integral of -BA eps_dot^2 over every step (never positive;
    /// docs/method.md §2.10, (M35)).
    pub fn damping_work(&self) -> f64 {
        self.damping_work
    }

    /// Work done on the cable by the seabed so far: the slab integral of
    /// f . r_dot of the contact force (W47), its penalty's elastic part
    /// included (the bed's potential is not in the energies).
    pub fn seabed_work(&self) -> f64 {
        self.seabed_work
    }

    /// Work done on the cable by the water so far: the slab integral of
    /// f . r_dot of buoyancy, drag and the fluid's inertia (W24) (the
    /// buoyancy's potential is not in the energies).
    pub fn water_work(&self) -> f64 {
        self.water_work
    }

    /// Work done on the cable by everything that is not a potential:
    /// moving constraints, drag, axial damping, the seabed and the water, so that
    /// `energies().mechanical() - external_work()` stays at its initial
    /// value up to the scheme's error (docs/method.md §8).
    pub fn external_work(&self) -> f64 {
        self.constraint_work
            + self.drag_work
            + self.damping_work
            + self.seabed_work
            + self.water_work
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

    /// Moves node `node`'s attachment to a point onto `motion` from the
    /// next step on (a coupling code's next interval, docs/method.md
    /// §13.2).
    pub(crate) fn set_attached_motion(
        &mut self,
        node: usize,
        motion: crate::motion::CoupledMotion,
    ) -> Result<(), crate::ModelError> {
        let dpn = self.model.dofs_per_node();
        self.model
            .constraints
            .set_attached_motion(node, dpn, motion)
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
}

/// A step's motion as the cubic of eq. (6) in time of every coordinate:
/// its end values e0, e1, its end slopes de/dt w0, w1, its length and
/// its start time.
#[derive(Clone, Debug, PartialEq)]
pub struct TimeCubic {
    e0: Vec<f64>,
    w0: Vec<f64>,
    e1: Vec<f64>,
    w1: Vec<f64>,
    length: f64,
    /// The time at its start.
    t0: f64,
}

impl TimeCubic {
    /// Coordinate g's value and rate at the point of `basis`.
    fn at(&self, g: usize, basis: &CubicBasis) -> (f64, f64) {
        basis.on([self.e0[g], self.w0[g], self.e1[g], self.w1[g]])
    }

    /// Every coordinate's value and rate at time `t` of the step (eq. (6)
    /// in time: the Hermite cubic of the end values and slopes), into `e`
    /// and `v` (the model's coordinate count each). A `t` outside the
    /// step extrapolates; the caller keeps it inside.
    pub fn state_at(&self, t: f64, e: &mut [f64], v: &mut [f64]) {
        let basis = CubicBasis::new(self.length, (t - self.t0) / self.length);
        for (g, (e, v)) in e.iter_mut().zip(v.iter_mut()).enumerate() {
            (*e, *v) = self.at(g, &basis);
        }
    }
}

/// The cubic of eq. (6) of length `l` evaluated at s (units of its
/// length from its start; s > 1 extrapolates): the Hermite values and
/// slopes there, computed once for every coordinate.
pub(crate) struct CubicBasis {
    value: [f64; 4],
    slope: [f64; 4],
    l: f64,
}

impl CubicBasis {
    pub(crate) fn new(l: f64, s: f64) -> Self {
        let [value, slope, _] = crate::shape::hermite3(s, 1.0);
        CubicBasis { value, slope, l }
    }

    /// The value and rate of the cubic with end values and slopes
    /// `[e0, w0, e1, w1]` (slopes de/dt).
    pub(crate) fn on(&self, [e0, w0, e1, w1]: [f64; 4]) -> (f64, f64) {
        let (value, slope, l) = (&self.value, &self.slope, self.l);
        let e = value[0] * e0 + value[1] * l * w0 + value[2] * e1 + value[3] * l * w1;
        let v = (slope[0] * e0 + slope[2] * e1) / l + slope[1] * w0 + slope[3] * w1;
        (e, v)
    }
}
