//! Stepping a system while another code moves its coupled points
//! (docs/method.md §13): a floating platform's solver, a vessel code or a
//! cable robot's controller gives the positions (and velocities) of the
//! fairleads at the end of each coupling interval and takes back the
//! forces of the lines on them, in memory, as through MoorDyn's step API
//! (create, init, step, close).
//!
//! - [`CoupledSystem::initialize`] solves the static equilibrium with the
//!   coupled points where the coupling code puts them (§13.1);
//! - [`CoupledSystem::step_to`] moves them over the interval along (K1) or
//!   (K2) (§13.2), takes the steps that fit the interval (§13.3) and
//!   returns the lines' force on each coupled point: the mean over the
//!   last step and the mean over the whole interval (its impulse divided
//!   by its length, (K3));
//! - [`CoupledSystem::save`] and [`CoupledSystem::restore`] keep and bring
//!   back the whole state, so a predictor-corrector coupling can repeat an
//!   interval and step on to the same bits (§13.4); a state carries its
//!   system's identity and is refused by another system;
//! - one call takes at most [`MAX_INTERVAL_STEPS`] internal steps unless
//!   the handle is told otherwise, and [`CoupledSystem::step_to_with`]
//!   stops between two of them when its caller asks (Ctrl-C in Python).

mod bodies;
mod bounds;
mod catenary_start;
mod error;
mod held_loads;
mod host_waves;
mod identity;
mod interval;
mod rates;
mod readings;
mod stiffness;

pub use bounds::{interval_steps, MAX_COUPLED_COORDINATE, MAX_COUPLED_SPEED, MAX_INTERVAL_STEPS};
pub use error::CouplingError;

use crate::error::ModelError;
use crate::integrator::StepSettings;
use crate::model::Model;
use crate::motion::{CoupledMotion, MotionInterval};
use crate::statics::StaticSettings;
use crate::system::{PointKind, System, SystemSimulation, SystemStatics, Topology};
use bodies::{array_layout, ArrayLayout};
use identity::{Identity, SystemDigest};

/// The forces of the lines on the coupled points after an interval,
/// 3 per point in the order of [`CoupledSystem::coupled_points`] (N).
#[derive(Clone, Debug, PartialEq)]
pub struct CoupledForces {
    /// The mean force over the interval's last step (the force `stancf
    /// run` writes for that step).
    pub last_step: Vec<f64>,
    /// The mean force over the whole interval: its impulse divided by its
    /// length (K3), for couplings that exchange impulses.
    pub interval_mean: Vec<f64>,
    /// Steps taken inside the interval.
    pub steps: usize,
}

/// A point of a [`CoupledSystem`] at its current time (see
/// [`CoupledSystem::point`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PointReading {
    /// Position (m).
    pub position: [f64; 3],
    /// Velocity (m/s).
    pub velocity: [f64; 3],
    /// The net force of the attached lines on the point (N).
    pub force: [f64; 3],
}

/// The running part of a [`CoupledSystem`]: the simulation and where the
/// coupling code last put the coupled points.
#[derive(Clone)]
struct Running {
    sim: SystemSimulation,
    /// The energy watchdog over the run since the initial equilibrium
    /// (docs/method.md §11.15): a step whose balance grows without a
    /// source fails the call (a P2 step above its stable step), a
    /// Galerkin step's jump is taken again in halves.
    watch: crate::integrator::EnergyWatch,
    /// Positions and (when given) velocities of the last call, 3 per
    /// coupled point (those on coupled bodies included).
    position: Vec<f64>,
    velocity: Option<Vec<f64>>,
    /// The coupled bodies' reference points and their velocities.
    reference: Vec<[f64; 3]>,
    reference_rate: Option<Vec<[f64; 3]>>,
    /// The coupled bodies' poses and rates of the last call, for their
    /// own push (None for a body pinned to the host; §15.18).
    held: Vec<Option<held_loads::HeldEnd>>,
    /// The host's positions of its last calls, for the rates it does not
    /// give ((K2a), `rates.rs`).
    samples: rates::Samples,
    /// The free and coupled bodies' mooring stiffness at the initial
    /// equilibrium, and the coupled points' not on a body.
    stiffness: BodyStiffness,
    point_stiffness: PointStiffness,
    /// The next step's length of a handle whose steps a tolerance chooses
    /// ([`CoupledSystem::with_force_tolerance`]), None before its first.
    next_step: Option<f64>,
}

/// Each free and coupled body's mooring stiffness (body index, 6 x 6).
type BodyStiffness = Vec<(usize, Option<[[f64; 6]; 6]>)>;
/// Each coupled point's not on a body (point index, 3 x 3).
type PointStiffness = Vec<(usize, Option<[[f64; 3]; 3]>)>;

/// The whole state of a [`CoupledSystem`] (opaque; [`CoupledSystem::save`])
/// and the identity of the system it was saved from.
#[derive(Clone)]
pub struct CoupledState {
    running: Option<Running>,
    identity: Identity,
}

/// A system whose coupled points another code moves (see the module).
#[derive(Clone)]
pub struct CoupledSystem {
    /// The system as built; its coupled points are moved to the coupling
    /// code's positions by [`Self::initialize`].
    system: System,
    /// The system whose lines' catenaries seed the static solve (the same
    /// system in air; with the lines' wet weights in water).
    seed: System,
    statics: StaticSettings,
    steps: StepSettings,
    /// Halvings of a step that Newton fails (see
    /// [`SystemSimulation::set_step_halvings`]).
    step_halvings: u32,
    /// Every coupled point (those on coupled bodies included), in the
    /// system's order: the simulation's moving points.
    coupled: Vec<usize>,
    /// The coupling arrays' layout: coupled bodies, then coupled points.
    layout: ArrayLayout,
    /// The coupled points of the arrays (not on a body), in their order.
    array_points: Vec<usize>,
    /// The system and step settings hashed once, for `identity`.
    digest: SystemDigest,
    /// Whose states this handle takes (see [`CoupledState`]); set by the
    /// constructor and the builders.
    identity: Identity,
    /// The most internal steps one call may take.
    max_interval_steps: usize,
    /// The line failures the simulation starts with (docs/method.md
    /// §11.16).
    failures: Vec<crate::system::LineFailure>,
    running: Option<Running>,
    /// [`Self::initialize`] starts from MoorDyn's start without initial
    /// conditions (a deck's `TmaxIC 0`), not from the static equilibrium
    /// ([`Self::with_catenary_start`]).
    catenary_start: bool,
    /// The tolerance on the end forces that chooses the internal steps
    /// ([`Self::with_force_tolerance`]); None: equal steps.
    control: Option<crate::system::StepControl>,
}

/// Where [`CoupledSystem::initialize`] puts the coupled points: the
/// coupling arrays and the points' positions and velocities from them.
struct Start<'a> {
    x: &'a [f64],
    xd: Option<&'a [f64]>,
    position: Vec<f64>,
    velocity: Option<Vec<f64>>,
}

impl CoupledSystem {
    /// The handle of `system`, its coupled points in index order; `seed`
    /// is the system whose catenaries seed the static solve (see
    /// [`crate::system::catenary_states`]). The planar reduction is left
    /// off: the coupling code may move the points out of any plane.
    pub fn new(
        system: System,
        seed: System,
        statics: StaticSettings,
        mut steps: StepSettings,
    ) -> Result<Self, ModelError> {
        statics.validate()?;
        steps.planar_reduction = false;
        if seed.points().len() != system.points().len()
            || seed.lines().len() != system.lines().len()
        {
            return Err(ModelError::invalid(
                "seed",
                "the seed system must have the system's points and lines",
            ));
        }
        let coupled: Vec<usize> = (0..system.points().len())
            .filter(|&p| matches!(system.points()[p].kind, PointKind::Coupled(_)))
            .collect();
        let layout = array_layout(&system, &coupled);
        if layout.dof() == 0 {
            return Err(ModelError::invalid(
                "points",
                "the system has no coupled point or coupled body for a coupling code to move",
            ));
        }
        let array_points: Vec<usize> = layout.plain.iter().map(|&k| coupled[k]).collect();
        let digest = SystemDigest::of(&system, &steps);
        Ok(CoupledSystem {
            identity: Identity::of(&digest, &identity_order(&layout, &array_points), 0),
            digest,
            system,
            seed,
            statics,
            steps,
            step_halvings: 0,
            coupled,
            layout,
            array_points,
            max_interval_steps: MAX_INTERVAL_STEPS,
            failures: Vec::new(),
            running: None,
            catenary_start: false,
            control: None,
        })
    }

    /// The handle whose simulation lets go of line ends as `failures`
    /// say (docs/method.md §11.16; checked here, keys `failures[i]`): the
    /// releases happen inside [`Self::step_to`]'s steps; the coupled
    /// points stay what they are.
    pub fn with_failures(
        mut self,
        failures: Vec<crate::system::LineFailure>,
    ) -> Result<Self, ModelError> {
        let models: Vec<&crate::Model> = self.system.lines().iter().map(|l| &l.model).collect();
        crate::system::check_failures(&self.system, &models, &failures)?;
        self.failures = failures;
        Ok(self)
    }

    /// The line failures that happened so far (none before
    /// [`Self::initialize`]).
    pub fn releases(&self) -> &[crate::system::Release] {
        self.running.as_ref().map_or(&[], |r| r.sim.releases())
    }

    /// The handle whose internal steps are chosen by a tolerance on the
    /// end forces (docs/method.md §11.17, (M23c)), as `stancf run` with
    /// `analysis.force_tolerance` chooses them: each interval is crossed
    /// in steps of at most the step length, each taken whole and in two
    /// halves, kept when the forces at its end differ by at most
    /// `tolerance` of each end's force (or its line's weight), the halves
    /// kept; the next step's length is carried from call to call. Needs
    /// the Galerkin step. [`CoupledForces::steps`] counts the halves.
    pub fn with_force_tolerance(mut self, tolerance: f64) -> Result<Self, ModelError> {
        self.control = Some(crate::system::StepControl::for_steps(
            &self.steps,
            tolerance,
        )?);
        Ok(self)
    }

    /// The tolerance on the end forces that chooses the internal steps,
    /// if one does ([`Self::with_force_tolerance`]).
    pub fn force_tolerance(&self) -> Option<f64> {
        self.control.map(|c| c.tolerance())
    }

    /// The handle whose steps that Newton fails are taken again in halves,
    /// `halvings` levels deep ([`SystemSimulation::set_step_halvings`]).
    pub fn with_step_halvings(mut self, halvings: u32) -> Result<Self, ModelError> {
        if halvings > crate::system::MAX_STEP_HALVINGS {
            return Err(ModelError::invalid(
                "step_halvings",
                format!(
                    "{halvings} is above the {} a step may take",
                    crate::system::MAX_STEP_HALVINGS
                ),
            ));
        }
        self.step_halvings = halvings;
        self.identity = Identity::of(
            &self.digest,
            &identity_order(&self.layout, &self.array_points),
            halvings,
        );
        Ok(self)
    }

    /// Orders the coupled points of the arrays as `order` (a permutation
    /// of [`Self::coupled_points`]; e.g. by the points' ids).
    pub fn with_order(mut self, order: Vec<usize>) -> Result<Self, ModelError> {
        if self.running.is_some() {
            return Err(ModelError::invalid(
                "order",
                "the coupled points are ordered before initialize, not after",
            ));
        }
        let mut sorted = order.clone();
        sorted.sort_unstable();
        let mut own = self.array_points.clone();
        own.sort_unstable();
        if sorted != own {
            return Err(ModelError::invalid(
                "order",
                format!(
                    "must list the coupled points {:?} once each, got {order:?}",
                    own
                ),
            ));
        }
        self.layout.plain = order
            .iter()
            .map(|p| {
                self.coupled
                    .iter()
                    .position(|q| q == p)
                    .expect("a coupled point")
            })
            .collect();
        self.array_points = order;
        self.identity = Identity::of(
            &self.digest,
            &identity_order(&self.layout, &self.array_points),
            self.step_halvings,
        );
        Ok(self)
    }

    /// The most internal steps one [`Self::step_to`] takes
    /// ([`MAX_INTERVAL_STEPS`] unless set).
    pub fn max_interval_steps(&self) -> usize {
        self.max_interval_steps
    }

    /// Lets one call take up to `n` internal steps (at least 1): the
    /// opt-in for a host that steps over long intervals on purpose.
    pub fn set_max_interval_steps(&mut self, n: usize) -> Result<(), ModelError> {
        if n == 0 {
            return Err(ModelError::invalid(
                "max_interval_steps",
                "must be at least 1 (an interval takes at least one step)",
            ));
        }
        self.max_interval_steps = n;
        Ok(())
    }

    /// The coupled points not on a body (indices in the system), in the
    /// order of the coupling arrays (after the coupled bodies).
    pub fn coupled_points(&self) -> &[usize] {
        &self.array_points
    }

    /// The coupled bodies (indices in the system), in the order of the
    /// coupling arrays (first, 6 numbers each).
    pub fn coupled_bodies(&self) -> Vec<usize> {
        self.layout.bodies.iter().map(|b| b.body).collect()
    }

    /// The coupled bodies' poses (their reference points and MoorDyn's
    /// roll, pitch and yaw in radians) and the coupled points' positions
    /// where the system puts them as built (the scenario's or deck's), in
    /// the order of the coupling arrays: known before
    /// [`Self::initialize`], a start the coupling code may give it.
    pub fn initial_positions(&self) -> Vec<f64> {
        let mut x = Vec::with_capacity(self.coupled_dof());
        for b in &self.layout.bodies {
            let body = &self.system.bodies()[b.body];
            x.extend(body.position);
            if b.pin.is_some() {
                continue;
            }
            let angles = crate::body::pose::moordyn_angles(&body.rotation);
            x.extend(angles.map(f64::to_radians));
        }
        for &p in &self.array_points {
            x.extend(self.system.points()[p].position);
        }
        x
    }

    /// Length of the coupling arrays: 6 per coupled body (3 per body
    /// pinned to the host, MoorDyn's CoupledPinned), 3 per coupled point.
    pub fn coupled_dof(&self) -> usize {
        self.layout.dof()
    }

    /// The system as built (its coupled points where the scenario puts
    /// them, at rest; the running simulation's points and lines are
    /// [`Self::topology`] and [`Self::line_model`]).
    pub fn system(&self) -> &System {
        &self.system
    }

    /// The system's points and line ends: as built before
    /// [`Self::initialize`], then the running simulation's (its coupled
    /// points on the coupling code's motion).
    pub fn topology(&self) -> &Topology {
        self.running
            .as_ref()
            .map_or(&self.system, |r| r.sim.topology())
    }

    /// The model of line `line` (None past the last line): the system's
    /// as built before [`Self::initialize`], then the running line
    /// simulation's (its attachments on the coupling code's motion).
    pub fn line_model(&self, line: usize) -> Option<&Model> {
        match &self.running {
            Some(r) => r.sim.lines().get(line).map(|l| l.model()),
            None => self.system.lines().get(line).map(|l| &l.model),
        }
    }

    /// The running simulation (after [`Self::initialize`]): its lines'
    /// states, points and end forces.
    pub fn simulation(&self) -> Option<&SystemSimulation> {
        self.running.as_ref().map(|r| &r.sim)
    }

    /// The time reached (0 before the first interval).
    pub fn time(&self) -> f64 {
        self.simulation().map_or(0.0, SystemSimulation::time)
    }

    /// Solves the static equilibrium with the coupled points at `x` (3 per
    /// point), at rest, and starts the simulation there at t = 0 (§13.1);
    /// returns the arrays' forces (the lines' on the coupled points; on a coupled
    /// body their force and moment with its rods' push at rest, §15.18). `xd`, when given,
    /// is the points' velocity at t = 0: the start of the first interval's
    /// cubic (K2) (the lines start at rest, but for those on a free body
    /// that starts moving: [`System::start_lines_with_bodies`]). May be
    /// called again to start
    /// over. The solve is bounded: its load increments, their halvings and
    /// Newton's iterations all have limits (docs/method.md §6.8).
    pub fn initialize(&mut self, x: &[f64], xd: Option<&[f64]>) -> Result<Vec<f64>, CouplingError> {
        self.initialize_with(x, xd, &mut || false)
    }

    /// [`Self::initialize`], asking `stop` after every load increment of
    /// the static solve: when it says true, the solve ends with
    /// [`CouplingError::Interrupted`] and the handle is as before the call.
    pub fn initialize_with(
        &mut self,
        x: &[f64],
        xd: Option<&[f64]>,
        stop: &mut dyn FnMut() -> bool,
    ) -> Result<Vec<f64>, CouplingError> {
        self.check_values("x", x)?;
        if let Some(v) = xd {
            self.check_values("xd", v)?;
        }
        let mut system = self.system.clone();
        let mut seed = self.seed.clone();
        let n = self.coupled.len();
        let position = self.layout.positions(x, n);
        let velocity = xd.map(|v| self.layout.velocities(x, v, n));
        for (k, &p) in self.coupled.iter().enumerate() {
            let at = CoupledMotion::Interval(MotionInterval::at_rest(triple(&position, k)));
            system.set_point_motion(p, at.clone())?;
            seed.set_point_motion(p, at)?;
        }
        if self.catenary_start {
            let start = Start {
                x,
                xd,
                position,
                velocity,
            };
            return self.start_from_catenaries(system, &seed, start);
        }
        let mut statics = SystemStatics::seeded(system.clone(), &seed, self.statics.clone())?;
        let finished = statics.solve(|_, _| {
            if stop() {
                std::ops::ControlFlow::Break(())
            } else {
                std::ops::ControlFlow::Continue(())
            }
        })?;
        if !finished {
            return Err(CouplingError::Interrupted { time: self.time() });
        }
        let coupled = &self.coupled;
        let mut forces = self.layout.forces(
            |k| statics.point_force(coupled[k]),
            |k| statics.point_position(coupled[k]),
            |b| self.layout.reference(x, b),
        );
        let held = self.held_ends(&system, x, xd, &mut forces);
        let stiffness = stiffness::body_stiffness(&mut statics, &self.layout, x);
        let point_stiffness = stiffness::point_stiffness(&statics, &self.layout, &self.coupled);
        let mut sim = stiffness::start_at(&statics, self.steps.clone(), self.step_halvings)?;
        sim.set_failures(self.failures.clone())?;
        let start = Start {
            x,
            xd,
            position,
            velocity,
        };
        self.running = Some(self.running(sim, start, held, (stiffness, point_stiffness)));
        Ok(forces)
    }

    /// The running part from `sim` at the start `start`, the coupled
    /// bodies' `held` ends and the mooring stiffness at the start's
    /// equilibrium (none without one).
    fn running(
        &self,
        sim: SystemSimulation,
        start: Start<'_>,
        held: Vec<Option<held_loads::HeldEnd>>,
        (stiffness, point_stiffness): (BodyStiffness, PointStiffness),
    ) -> Running {
        let bodies = 0..self.layout.bodies.len();
        let Start {
            x,
            xd,
            position,
            velocity,
        } = start;
        let t0 = sim.time();
        Running {
            watch: sim.energy_watch(),
            sim,
            position,
            velocity,
            reference: bodies
                .clone()
                .map(|b| self.layout.reference(x, b))
                .collect(),
            reference_rate: xd.map(|v| bodies.map(|b| self.layout.reference(v, b)).collect()),
            held,
            samples: vec![(t0, x.to_vec())],
            stiffness,
            point_stiffness,
            next_step: None,
        }
    }

    /// The coupled bodies' poses and rates of `x`, `xd` (None for a body
    /// pinned to the host), each body's own parts' push at rest at its
    /// pose, in the static solve's steady water (B36), added to `forces`.
    fn held_ends(
        &self,
        system: &System,
        x: &[f64],
        xd: Option<&[f64]>,
        forces: &mut [f64],
    ) -> Vec<Option<held_loads::HeldEnd>> {
        let held: Vec<_> = (0..self.layout.bodies.len())
            .map(|b| self.layout.held_end(x, xd, b))
            .collect();
        for (k, end) in held.iter().enumerate() {
            let body = &system.bodies()[self.layout.bodies[k].body];
            if let (Some(end), true) = (end, held_loads::carries_loads(body)) {
                let push = held_loads::rest_push(body, system.gravity(), end);
                self.layout.add_push(forces, k, &push);
            }
        }
        held
    }

    /// The whole state: the simulation (its kept factors included), the
    /// coupled points' last positions and velocities, and this system's
    /// identity.
    pub fn save(&self) -> CoupledState {
        CoupledState {
            running: self.running.clone(),
            identity: self.identity,
        }
    }

    /// Brings back a state from [`Self::save`] of this handle, or of a
    /// handle of the same system (built from the same scenario text: a
    /// restart): stepping on from it gives the same bits as the first
    /// time. A state of another system is refused (an input error naming
    /// both systems' lines and points) and the handle is untouched.
    pub fn restore(&mut self, state: &CoupledState) -> Result<(), CouplingError> {
        self.identity.admit(&state.identity)?;
        self.running.clone_from(&state.running);
        Ok(())
    }
}

/// The error of a step before [`CoupledSystem::initialize`].
fn not_initialized() -> ModelError {
    ModelError::invalid("step", "initialize the coupled system before stepping it")
}

fn triple(values: &[f64], k: usize) -> [f64; 3] {
    [values[3 * k], values[3 * k + 1], values[3 * k + 2]]
}

/// What a state's identity records of the arrays' order: the coupled
/// bodies (as usize::MAX - b) and the coupled points.
fn identity_order(layout: &ArrayLayout, points: &[usize]) -> Vec<usize> {
    layout
        .bodies
        .iter()
        .map(|b| usize::MAX - b.body)
        .chain(points.iter().copied())
        .collect()
}
