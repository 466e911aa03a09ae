//! Time stepping of a system (docs/method.md §11.3): every line is a
//! [`Simulation`] (its predictor, end values, reactions and undo are the
//! single cable's); the system's step gathers the lines' unknowns and the
//! free points' into one vector, solves the slab equations of all lines
//! and points together with the bordered Jacobian ([`BorderedLu`]), and
//! hands each line its converged unknowns. Without free points the lines
//! are independent and each is solved apart with its own solver
//! (§11.14, [`super::apart`]). This file holds the simulation, its
//! construction and its readings; the step itself is `stepping.rs`.

use super::body_terms::{BodyPoint, PinHold, StepBody};
pub use super::end_forces::EndForce;
use super::end_forces::ForcesAtTime;
use super::frame::Frame;
use super::layout::SystemLayout;
use super::mass::SystemMass;
use super::point_terms::PointNodes;
use super::step_equations::{system_scales, PointMotion, StepOfSystem};
use super::{PointKind, System, Topology};
use crate::bordered::{BorderedLu, BorderedMatrix};
use crate::element::TimeSlab;
use crate::error::{ModelError, SolverError};
use crate::integrator::{Simulation, StepReport, StepSettings};
use crate::model::{coordinate, State, SLOT_R};
use crate::quadrature::GaussRule;
use crate::solver::{NewtonWorkspace, NonlinearSystem};

/// The step's equations as Newton sees them, borrowing the fields of a
/// [`SystemSimulation`] they need (and no others: Newton takes `x` and
/// the workspace beside them).
macro_rules! step_problem {
    ($sim:expr) => {
        StepOfSystem {
            topology: &$sim.topology,
            lines: &mut $sim.lines,
            layout: &$sim.layout,
            slab: &$sim.slab,
            points: &$sim.points,
            bodies: &$sim.bodies,
            point_index: &$sim.point_index,
            point_nodes: &mut $sim.point_nodes,
            x_local: &mut $sim.x_local,
            residual_local: &mut $sim.residual_local,
            unknown_scale: &$sim.unknown_scale,
            equation_scale: &$sim.equation_scale,
            time: $sim.t,
        }
    };
}

pub(super) use step_problem;

/// A running simulation of a system. A clone is an independent copy of
/// the whole state, kept factors included: it steps on to the same bits
/// (a coupling code's save and restore, docs/method.md §13.4).
#[derive(Clone)]
pub struct SystemSimulation {
    /// The system's points and line ends; the line models are the line
    /// simulations' (each exists once).
    pub(super) topology: Topology,
    /// The line simulations, owners of the line models.
    pub(super) lines: Vec<Simulation>,
    /// The most Newton iterations of a line in the last step its lines
    /// were solved apart (0 before): the step's work, which decides
    /// whether they are solved on rayon's threads (§11.14).
    pub(super) apart_iterations: usize,
    pub(super) layout: SystemLayout,
    pub(super) settings: StepSettings,
    pub(super) slab: TimeSlab,
    /// The slab's time Gauss rule.
    pub(super) time_rule: GaussRule,
    pub(super) points: Vec<PointMotion>,
    /// The free bodies and their points (docs/method.md §15.7).
    pub(super) bodies: Vec<StepBody>,
    /// The lines' rows at the body points' slots (a step's end, B14).
    pub(super) body_rows: Vec<f64>,
    /// The free bodies' generalized momenta at a step's end (B14).
    pub(super) body_momentum: Vec<[f64; 6]>,
    /// Per clamp at a free body (§15.19): what the converged step leaves
    /// of it, and its mean moment on the body over the last step.
    pub(super) clamp_ends: Vec<super::body_clamps::ClampStepEnd>,
    pub(super) clamp_moments: Vec<[f64; 3]>,
    /// Global indices of free point p's unknowns, `[3 slot + c]`.
    pub(super) point_index: Vec<Vec<usize>>,
    pub(super) point_nodes: Vec<PointNodes>,
    pub(super) x: Vec<f64>,
    pub(super) x_local: Vec<Vec<f64>>,
    pub(super) residual_local: Vec<Vec<f64>>,
    pub(super) workspace: NewtonWorkspace<BorderedLu>,
    pub(super) unknown_scale: Vec<f64>,
    pub(super) equation_scale: Vec<f64>,
    pub(super) end_forces: Vec<[EndForce; 2]>,
    /// The last Galerkin step's end forces at its end (M23b), before
    /// [`ForcesAtTime`] takes them.
    pub(super) end_forces_at_end: Vec<[EndForce; 2]>,
    /// The end forces at the end of the last step (M23a).
    pub(super) forces_at_time: ForcesAtTime,
    /// The last Galerkin step's end forces over it, each end's cubic in
    /// the unit Hermite basis ([`super::end_forces::force_cubic`], (M23b);
    /// None at a loose end and with P2), and the step's start and length:
    /// [`super::StepRecord`] (docs/method.md §6.5).
    pub(super) force_cubics: Vec<[Option<[[f64; 3]; 4]>; 2]>,
    /// The steps' records kept for output between their ends (None: not
    /// kept; [`Self::record_steps`]).
    pub(super) step_records: Option<Vec<super::StepRecord>>,
    /// The Galerkin step's system mass matrix (free points only).
    pub(super) mass: Option<SystemMass>,
    /// The Galerkin step's end momenta of the free points.
    pub(super) point_momentum: Vec<[f64; 3]>,
    /// Work done on the free points by the water's drag and inertia.
    pub(super) point_water_work: f64,
    /// The bed's work on the free points so far (W42p).
    pub(super) point_bed_work: f64,
    /// How many times a step that Newton fails is halved (see
    /// [`SystemSimulation::set_step_halvings`]).
    pub(super) step_halvings: u32,
    /// The line failures still to come and those that happened
    /// (docs/method.md §11.16).
    pub(super) failures: super::failures::Failures,
    pub(super) steps: usize,
    pub(super) t: f64,
}

impl SystemSimulation {
    /// Prepares the simulation of `system` from the lines' states
    /// `initial` (one per line, at a common time) with the points' free
    /// positions taken from the attached line ends and at rest.
    pub fn new(
        system: System,
        initial: Vec<State>,
        settings: StepSettings,
    ) -> Result<Self, ModelError> {
        super::host_waves::refuse_untaken(&system)?;
        if initial.len() != system.lines().len() {
            return Err(ModelError::invalid(
                "initial_state",
                format!(
                    "expected {} line states, got {}",
                    system.lines().len(),
                    initial.len()
                ),
            ));
        }
        // A system of bodies alone (no line) starts at t = 0.
        let t = initial.first().map_or(0.0, |s| s.t);
        let (topology, models) = system.into_parts();
        if topology.has_free_bodies() && !settings.time_scheme.carries_momentum() {
            return Err(ModelError::invalid(
                "analysis.scheme",
                "a system with a free body is stepped by the Galerkin scheme; the P2 step of \
                 bodies in a system is not built",
            ));
        }
        let mut bodies = step_bodies(&topology, settings.time_step)?;
        for body in &mut bodies {
            body.body.set_time(t);
        }
        let mut line_settings = settings.clone();
        // Free points or free bodies (a body that holds no line too) are
        // unknowns of the system's step beside its lines'.
        let joined = topology.has_free_points() || topology.has_free_bodies();
        // The planar reduction holds coordinates line by line; lines
        // joined at free points must hold the same ones, so it is left off.
        line_settings.planar_reduction &= !joined;
        // Without free points or bodies the lines are independent: each is
        // solved apart, with its own solver (docs/method.md §11.14).
        let apart = !joined;
        let mut initial = initial;
        let spins: Vec<[f64; 3]> = topology
            .bodies()
            .iter()
            .map(|b| b.angular_velocity)
            .collect();
        super::clamp_checks::start_rates(topology.body_clamps(), &models, &spins, &mut initial);
        let lines = models
            .into_iter()
            .zip(initial)
            .enumerate()
            .map(|(i, (model, state))| {
                Simulation::line_of_system(model, state, line_settings.clone(), apart)
                    .map_err(|e| e.under(&format!("lines[{i}]")))
            })
            .collect::<Result<Vec<_>, _>>()?;
        let h = settings.time_step / settings.time_layers as f64;
        let rule = GaussRule::new(settings.time_points)
            .map_err(|e| ModelError::invalid("analysis.quadrature", e.message))?;
        let slab = TimeSlab::new(h, &rule);
        let points = point_motions(&topology, &lines, t)?;
        let frame = Frame::new(&topology, &lines, &bodies, &settings)?;
        let (x_local, residual_local) = (frame.line_buffers(), frame.line_buffers());
        let Frame {
            layout,
            point_index,
            workspace,
            unknown_scale,
            equation_scale,
            mass,
        } = frame;
        let n = layout.size;
        Ok(SystemSimulation {
            apart_iterations: 0,
            failures: Default::default(),
            mass,
            body_rows: vec![0.0; n],
            body_momentum: vec![[0.0; 6]; bodies.len()],
            clamp_ends: Vec::with_capacity(topology.body_clamps().len()),
            clamp_moments: vec![[0.0; 3]; topology.body_clamps().len()],
            bodies,
            point_momentum: vec![[0.0; 3]; topology.points().len()],
            point_water_work: 0.0,
            point_bed_work: 0.0,
            step_halvings: super::halving::DEFAULT_STEP_HALVINGS,
            end_forces: vec![[EndForce::default(); 2]; lines.len()],
            end_forces_at_end: vec![[EndForce::default(); 2]; lines.len()],
            force_cubics: vec![[None; 2]; lines.len()],
            step_records: None,
            forces_at_time: ForcesAtTime::new(lines.len()),
            point_nodes: vec![PointNodes::default(); topology.points().len()],
            topology,
            lines,
            layout,
            settings,
            slab,
            time_rule: rule,
            points,
            point_index,
            x: vec![0.0; n],
            x_local,
            residual_local,
            workspace,
            unknown_scale,
            equation_scale,
            steps: 0,
            t,
        })
    }

    /// The system's points, line ends and gravity (its coupled points on
    /// their current motion); the line models are [`Self::lines`]'.
    pub fn topology(&self) -> &Topology {
        &self.topology
    }

    /// The line simulations (their models, states, reactions and
    /// energies).
    pub fn lines(&self) -> &[Simulation] {
        &self.lines
    }

    /// Position and velocity of point p (fixed and coupled points: as
    /// given by their motion at the current time).
    pub fn point_state(&self, p: usize) -> ([f64; 3], [f64; 3]) {
        let m = &self.points[p];
        (m.e, m.v)
    }

    /// Free body b's state (its pose, rates and energies); None for a
    /// fixed body.
    pub fn free_body(&self, b: usize) -> Option<&crate::body::FreeBody> {
        self.bodies.iter().find(|s| s.index == b).map(|s| &s.body)
    }

    /// The mean force of body b's pin on it over the last step (global;
    /// docs/method.md §15.17, (B35)): None if b is not a pinned free body.
    /// The body's pull on what holds it is its negative.
    pub fn pin_force(&self, b: usize) -> Option<[f64; 3]> {
        let body = self.bodies.iter().find(|s| s.index == b)?;
        body.pin.map(|pin| pin.force)
    }

    pub fn time(&self) -> f64 {
        self.t
    }

    /// Work done on the lines by their axial damping so far (never
    /// positive; docs/method.md §2.10, (M35)).
    pub fn damping_work(&self) -> f64 {
        self.lines.iter().map(Simulation::damping_work).sum()
    }

    /// Work done by the seabed so far: on the lines (W47) and on the
    /// free points (W42p).
    pub fn seabed_work(&self) -> f64 {
        self.lines.iter().map(Simulation::seabed_work).sum::<f64>() + self.point_bed_work
    }

    /// Work done by the water so far: on the lines (W24), on the free
    /// points by their drag and inertia (W34) and on the free bodies by
    /// their drag (B10) (buoyancy is a constant load, a potential).
    pub fn water_work(&self) -> f64 {
        self.lines.iter().map(Simulation::water_work).sum::<f64>()
            + self.point_water_work
            + self.body_water_work()
    }

    pub fn steps(&self) -> usize {
        self.steps
    }

    /// Unknowns solved for in every step.
    pub fn unknowns_per_step(&self) -> usize {
        self.layout.size
    }

    /// The Jacobian of the next step's equations at its predicted
    /// unknowns (x, for inspection and for measuring linear solvers
    /// against [`BorderedLu`]; allocates, unlike stepping). Leaves the
    /// simulation as it was.
    pub fn next_step_jacobian(&mut self) -> (BorderedMatrix, Vec<f64>) {
        for line in &mut self.lines {
            line.begin_step();
        }
        self.gather_prediction();
        let mut jacobian = BorderedMatrix::new(&self.layout.shapes, self.layout.border);
        let mut residual = vec![0.0; self.layout.size];
        let x = self.x.clone();
        let mut problem = step_problem!(self);
        problem.evaluate(&x, &mut residual, Some(&mut jacobian));
        (jacobian, x)
    }

    /// The residual of the next step's equations at the unknowns `x` (for
    /// checking [`Self::next_step_jacobian`] by finite differences;
    /// allocates). Leaves the simulation as it was.
    pub fn next_step_residual(&mut self, x: &[f64]) -> Vec<f64> {
        for line in &mut self.lines {
            line.begin_step();
        }
        let mut residual = vec![0.0; self.layout.size];
        let mut problem = step_problem!(self);
        problem.evaluate(x, &mut residual, None);
        residual
    }

    /// Moves coupled point p along `motion` from the next step on (a
    /// coupling code's next interval, (K1)-(K2), docs/method.md §13.2):
    /// the point and the constraints of the line ends attached to it.
    pub fn set_point_motion(
        &mut self,
        p: usize,
        motion: crate::motion::CoupledMotion,
    ) -> Result<(), ModelError> {
        self.topology.check_coupled(p)?;
        let attached: Vec<(usize, usize)> = self.topology.attachments(p).collect();
        for (li, end) in attached {
            let line = &mut self.lines[li];
            let node = super::end_node(line.model(), end);
            line.set_attached_motion(node, motion.clone())
                .map_err(|e| e.under(&format!("lines[{li}]")))?;
        }
        self.topology.set_point_motion(p, motion);
        Ok(())
    }

    /// The step length.
    pub fn time_step(&self) -> f64 {
        self.settings.time_step
    }

    /// Changes the step length from the next step on (a coupling interval
    /// that is not a multiple of the step, §13.3): the slab, the lines'
    /// steps and the scales; the kept factors are dropped.
    pub fn set_time_step(&mut self, dt: f64) {
        if dt == self.settings.time_step {
            return;
        }
        self.settings.time_step = dt;
        let h = dt / self.settings.time_layers as f64;
        self.slab = TimeSlab::new(h, &self.time_rule);
        for line in &mut self.lines {
            line.set_time_step(dt);
        }
        for body in &mut self.bodies {
            body.body.set_time_step(dt);
        }
        (self.unknown_scale, self.equation_scale) =
            system_scales(&self.topology, &self.lines, &self.layout, &self.bodies, dt);
        self.workspace.factors_valid = false;
    }

    /// Advances the system by one step of the step length (in halves
    /// where Newton fails, see [`SystemSimulation::set_step_halvings`]),
    /// then releases the line ends whose failure came due at its end
    /// ([`SystemSimulation::set_failures`]).
    /// On failure every line and point is left at the last converged
    /// step.
    pub fn step(&mut self) -> Result<StepReport, SolverError> {
        let report = self.step_halving(self.step_halvings)?;
        self.trigger_failures(&report)?;
        Ok(report)
    }
}

/// The points' states at the start: free points where their first
/// attached line end is (its position and velocity), the others on
/// their motion.
fn point_motions(
    system: &Topology,
    lines: &[Simulation],
    t: f64,
) -> Result<Vec<PointMotion>, ModelError> {
    let mut out = Vec::with_capacity(system.points().len());
    for (p, point) in system.points().iter().enumerate() {
        let (e, v) = if let PointKind::Body { body, local } = point.kind {
            let b = &system.bodies()[body];
            let here = (b.point(local), b.point_velocity(local));
            check_ends_on_body(system, lines, p, here)?;
            here
        } else if point.is_free() {
            let mut at = None;
            for (li, end) in system.attachments(p) {
                let sim = &lines[li];
                let node = super::end_node(sim.model(), end);
                let o = coordinate(sim.model().dofs_per_node(), node, SLOT_R, 0);
                let s = sim.state();
                let here = (
                    [s.e[o], s.e[o + 1], s.e[o + 2]],
                    [s.v[o], s.v[o + 1], s.v[o + 2]],
                );
                match at {
                    None => at = Some(here),
                    Some(first) if first != here => {
                        return Err(ModelError::invalid(
                            format!("points[{p}]"),
                            format!(
                                "the ends of the lines attached to this free point do not \
                                 start at the same position and velocity ({:?} and {:?})",
                                first, here
                            ),
                        ));
                    }
                    Some(_) => {}
                }
            }
            at.expect("a free point has a line")
        } else {
            point.state_at(t)
        };
        out.push(PointMotion {
            e,
            v,
            previous: (e, v),
            acceleration: [0.0; 3],
        });
    }
    Ok(out)
}

/// The free bodies of `system` as a step holds them: each one's state
/// (stepped with steps of `dt`) and its points with their arms from its
/// centre of mass.
fn step_bodies(system: &Topology, dt: f64) -> Result<Vec<StepBody>, ModelError> {
    system
        .free_bodies_children_first()
        .into_iter()
        .map(|b| {
            let body = &system.bodies()[b];
            let state = body
                .free_body(system.gravity(), dt)
                .map_err(|e| e.under(&format!("bodies[{b}]")))?;
            let c = body.inertia.centre_of_mass;
            let points = system
                .points()
                .iter()
                .enumerate()
                .filter_map(|(p, pt)| match pt.kind {
                    PointKind::Body { body: on, local } if on == b => Some(BodyPoint {
                        point: p,
                        arm: crate::vec3::sub(local, c),
                    }),
                    _ => None,
                })
                .collect();
            let pin = body.pin.map(|pin| {
                let point = &system.points()[pin.point];
                let hold = match (system.joint_point(b), &point.kind) {
                    (Some(p), _) => PinHold::Point(p),
                    (None, PointKind::Coupled(_)) => PinHold::Moving(pin.point),
                    (None, _) => PinHold::Fixed(point.position),
                };
                super::body_terms::StepPin {
                    arm: crate::vec3::sub(pin.local, c),
                    hold,
                    held: [[0.0; 3], point.position, [0.0; 3]],
                    momentum_a: [0.0; 3],
                    force: [0.0; 3],
                    moved: [0.0; 3],
                    work: 0.0,
                }
            });
            // A pinned body keeps its own loads' impulse: its pin's force
            // is the rest of its momentum change (B35).
            let state = if pin.is_some() {
                state.with_own_impulse()
            } else {
                state
            };
            Ok(StepBody {
                index: b,
                body: state,
                points,
                pin,
            })
        })
        .collect()
}

/// The line ends at point p on a body start where the body puts the
/// point and move with it (`here`: its position and velocity), to 1e-9
/// of the system's size (round-off of a state written and read back).
fn check_ends_on_body(
    system: &Topology,
    lines: &[Simulation],
    p: usize,
    here: ([f64; 3], [f64; 3]),
) -> Result<(), ModelError> {
    let size = super::extent(
        lines.iter().map(|l| l.model().cable.length),
        system.points().iter().map(|pt| pt.position),
    );
    for (li, end) in system.attachments(p) {
        let sim = &lines[li];
        let node = super::end_node(sim.model(), end);
        let o = coordinate(sim.model().dofs_per_node(), node, SLOT_R, 0);
        let s = sim.state();
        let gap = (0..3)
            .map(|c| {
                (s.e[o + c] - here.0[c])
                    .abs()
                    .max((s.v[o + c] - here.1[c]).abs())
            })
            .fold(0.0, f64::max);
        if gap > 1e-9 * size.max(1.0) {
            return Err(ModelError::invalid(
                format!("points[{p}]"),
                format!(
                    "line {li}'s end {} does not start where its body puts the point and as it \
                     moves it (position {:?} and velocity {:?} against the line's)",
                    ["A", "B"][end],
                    here.0,
                    here.1
                ),
            ));
        }
    }
    Ok(())
}
