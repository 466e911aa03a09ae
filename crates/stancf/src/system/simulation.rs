//! Time stepping of a system (docs/method.md §11.3): every line is a
//! [`Simulation`] (its predictor, end values, reactions and undo are the
//! single cable's); the system's step gathers the lines' unknowns and the
//! free points' into one vector, solves the slab equations of all lines
//! and points together with the bordered Jacobian ([`BorderedLu`]), and
//! hands each line its converged unknowns. Without free points the lines
//! are independent and each is solved apart with its own solver
//! (§11.14, [`super::apart`]).

pub use super::end_forces::EndForce;
use super::end_forces::{position_row_sum, ForcesAtTime};
use super::layout::SystemLayout;
use super::mass::SystemMass;
use super::point_terms::{PointNodes, PointTerms};
use super::step_equations::{system_scales, StepOfSystem};
use super::{End, System};
use crate::assembly::{Kind, Scheme};
use crate::bordered::{BorderedLu, BorderedMatrix};
use crate::element::TimeSlab;
use crate::error::{ModelError, SolverError};
use crate::integrator::{Simulation, StepReport, StepSettings, TimeScheme};
use crate::model::{coordinate, State, SLOT_R};
use crate::quadrature::GaussRule;
use crate::solver::{solve, NewtonReport, NewtonWorkspace, NonlinearSystem};

/// The step's equations as Newton sees them, borrowing the fields of a
/// [`SystemSimulation`] they need (and no others: Newton takes `x` and
/// the workspace beside them).
macro_rules! step_problem {
    ($sim:expr) => {
        StepOfSystem {
            system: &$sim.system,
            lines: &mut $sim.lines,
            layout: &$sim.layout,
            slab: &$sim.slab,
            points: &$sim.points,
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

/// Position, velocity and predictor history of a point.
#[derive(Clone, Debug, Default)]
pub(super) struct PointMotion {
    pub(super) e: [f64; 3],
    pub(super) v: [f64; 3],
    previous: ([f64; 3], [f64; 3]),
    acceleration: [f64; 3],
}

/// A running simulation of a system. A clone is an independent copy of
/// the whole state, kept factors included: it steps on to the same bits
/// (a coupling code's save and restore, docs/method.md §13.4).
#[derive(Clone)]
pub struct SystemSimulation {
    system: System,
    lines: Vec<Simulation>,
    layout: SystemLayout,
    settings: StepSettings,
    slab: TimeSlab,
    points: Vec<PointMotion>,
    /// Global indices of free point p's unknowns, `[3 slot + c]`.
    point_index: Vec<Vec<usize>>,
    point_nodes: Vec<PointNodes>,
    x: Vec<f64>,
    x_local: Vec<Vec<f64>>,
    residual_local: Vec<Vec<f64>>,
    workspace: NewtonWorkspace<BorderedLu>,
    unknown_scale: Vec<f64>,
    equation_scale: Vec<f64>,
    end_forces: Vec<[EndForce; 2]>,
    /// The end forces at the end of the last step (M23a).
    forces_at_time: ForcesAtTime,
    /// The Galerkin step's system mass matrix (free points only).
    mass: Option<SystemMass>,
    /// The Galerkin step's end momenta of the free points.
    point_momentum: Vec<[f64; 3]>,
    /// Work done on the free points by the water's drag and inertia.
    point_water_work: f64,
    /// How many times a step that Newton fails is halved (see
    /// [`SystemSimulation::set_step_halvings`]).
    pub(super) step_halvings: u32,
    steps: usize,
    t: f64,
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
        let t = initial[0].t;
        let mut line_settings = settings.clone();
        // The planar reduction holds coordinates line by line; lines
        // joined at free points must hold the same ones, so it is left off.
        line_settings.planar_reduction &= !system.has_free_points();
        // Without free points the lines are independent: each is solved
        // apart, with its own solver (docs/method.md §11.14).
        let apart = !system.has_free_points();
        let lines = system
            .lines()
            .iter()
            .zip(initial)
            .enumerate()
            .map(|(i, (line, state))| {
                Simulation::line_of_system(line.model.clone(), state, line_settings.clone(), apart)
                    .map_err(|e| e.under(&format!("lines[{i}]")))
            })
            .collect::<Result<Vec<_>, _>>()?;
        let models: Vec<_> = lines.iter().map(|l| l.model()).collect();
        let scheme = match settings.time_scheme {
            TimeScheme::P2 => Scheme::P2 {
                layers: settings.time_layers,
            },
            TimeScheme::Galerkin => Scheme::Galerkin,
        };
        let layout = SystemLayout::new(&system, &models, scheme, settings.constraint_method);
        let h = settings.time_step / settings.time_layers as f64;
        let rule = GaussRule::new(settings.time_points)
            .map_err(|e| ModelError::invalid("analysis.quadrature", e.message))?;
        let slab = TimeSlab::new(h, &rule);
        let points = point_motions(&system, &lines)?;
        let point_index = (0..system.points().len())
            .map(|p| match layout.point_base[p] {
                Some(_) => (0..3 * layout.slots)
                    .map(|k| layout.point_unknown(p, k / 3, k % 3).expect("free"))
                    .collect(),
                None => Vec::new(),
            })
            .collect();
        let lu = BorderedLu::new(&layout.shapes, layout.border);
        let n = layout.size;
        let workspace = NewtonWorkspace::with_factors(lu, n, settings.newton.max_iterations);
        let x_local = layout.lines.iter().map(|l| vec![0.0; l.size()]).collect();
        let residual_local = layout.lines.iter().map(|l| vec![0.0; l.size()]).collect();
        let (unknown_scale, equation_scale) = system_scales(&system, &lines, &layout);
        let mass = if system.has_free_points() && scheme == Scheme::Galerkin {
            Some(SystemMass::new(&system, &models)?)
        } else {
            None
        };
        Ok(SystemSimulation {
            mass,
            point_momentum: vec![[0.0; 3]; system.points().len()],
            point_water_work: 0.0,
            step_halvings: super::halving::DEFAULT_STEP_HALVINGS,
            end_forces: vec![[EndForce::default(); 2]; lines.len()],
            forces_at_time: ForcesAtTime::new(lines.len()),
            point_nodes: vec![PointNodes::default(); system.points().len()],
            system,
            lines,
            layout,
            settings,
            slab,
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

    pub fn system(&self) -> &System {
        &self.system
    }

    /// The line simulations (their states, reactions and energies).
    pub fn lines(&self) -> &[Simulation] {
        &self.lines
    }

    /// Position and velocity of point p (fixed and coupled points: as
    /// given by their motion at the current time).
    pub fn point_state(&self, p: usize) -> ([f64; 3], [f64; 3]) {
        let m = &self.points[p];
        (m.e, m.v)
    }

    /// The force each end of line i exerts on its point (zero at a loose
    /// end), averaged over the last step.
    pub fn end_forces(&self, line: usize) -> [EndForce; 2] {
        self.end_forces[line]
    }

    /// The net force the attached lines exert on point p, averaged over
    /// the last step.
    pub fn point_force(&self, p: usize) -> [f64; 3] {
        self.sum_at_point(p, |li| self.end_forces[li])
    }

    /// The force each end of line i exerts on its point at the end of the
    /// last step: the second-order estimate (M23a) from the last two
    /// steps' means (the mean itself after the first step).
    pub fn end_forces_at_time(&self, line: usize) -> [EndForce; 2] {
        self.forces_at_time.line(line)
    }

    /// The net force the attached lines exert on point p at the end of the
    /// last step (M23a).
    pub fn point_force_at_time(&self, p: usize) -> [f64; 3] {
        self.sum_at_point(p, |li| self.forces_at_time.line(li))
    }

    /// The sum over the lines attached to point p of their ends' forces.
    fn sum_at_point(&self, p: usize, ends: impl Fn(usize) -> [EndForce; 2]) -> [f64; 3] {
        let mut f = [0.0; 3];
        for (li, end) in self.system.attachments(p) {
            let force = ends(li)[end].force;
            for c in 0..3 {
                f[c] += force[c];
            }
        }
        f
    }

    pub fn time(&self) -> f64 {
        self.t
    }

    /// Work done on the lines by their axial damping so far (never
    /// positive; docs/method.md §2.10, (M35)).
    pub fn damping_work(&self) -> f64 {
        self.lines.iter().map(Simulation::damping_work).sum()
    }

    /// Work done on the lines by the seabed so far (W47).
    pub fn seabed_work(&self) -> f64 {
        self.lines.iter().map(Simulation::seabed_work).sum()
    }

    /// Work done by the water so far: on the lines (W24) and on the free
    /// points by their drag and inertia (W34) (the points' buoyancy is a
    /// constant load, a potential).
    pub fn water_work(&self) -> f64 {
        self.lines.iter().map(Simulation::water_work).sum::<f64>() + self.point_water_work
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
        self.system.set_point_motion(p, motion.clone())?;
        let attached: Vec<(usize, usize)> = self.system.attachments(p).collect();
        for (li, end) in attached {
            let line = &mut self.lines[li];
            let node = if end == 0 {
                0
            } else {
                line.model().nodes() - 1
            };
            line.set_attached_motion(node, motion.clone())
                .map_err(|e| e.under(&format!("lines[{li}]")))?;
        }
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
        self.slab = TimeSlab::new(h, self.lines[0].time_rule());
        for line in &mut self.lines {
            line.set_time_step(dt);
        }
        (self.unknown_scale, self.equation_scale) =
            system_scales(&self.system, &self.lines, &self.layout);
        self.workspace.factors_valid = false;
    }

    /// Advances the system by one step of the step length (in halves
    /// where Newton fails, see [`SystemSimulation::set_step_halvings`]).
    /// On failure every line and point is left at the last converged
    /// step.
    pub fn step(&mut self) -> Result<StepReport, SolverError> {
        self.step_halving(self.step_halvings)
    }

    /// One step of the step length, not halved.
    pub(super) fn step_once(&mut self) -> Result<StepReport, SolverError> {
        let dt = self.settings.time_step;
        for line in &mut self.lines {
            line.begin_step();
        }
        let report = if self.system.has_free_points() {
            self.gather_prediction();
            let report = self.solve_step(dt)?;
            for (i, line) in self.lines.iter_mut().enumerate() {
                let map = &self.layout.maps[i];
                let xl = line.unknowns();
                map.gather(&self.x, xl);
            }
            report
        } else {
            super::apart::solve_lines_apart(&mut self.lines, dt)?
        };
        self.finish_lines(report);
        self.add_point_water_work();
        self.collect_end_forces(dt);
        self.forces_at_time.update(&self.end_forces, dt);
        self.advance_points(dt);
        self.steps += 1;
        self.t += dt;
        Ok(StepReport {
            step: self.steps,
            t: self.t,
            newton: report,
        })
    }

    /// Adds the step's work of the water on the free points (W34).
    fn add_point_water_work(&mut self) {
        let layout = &self.layout.lines[0];
        for (p, idx) in self.point_index.iter().enumerate() {
            let point = &self.system.points()[p];
            if idx.is_empty() || point.water.is_none() {
                continue;
            }
            let m = &self.points[p];
            let terms = PointTerms::of(&self.system, p, self.t, idx, layout, &self.slab);
            terms.expand(&self.x, m.e, m.v, &mut self.point_nodes[p]);
            self.point_water_work += terms.water_work(&self.point_nodes[p]);
        }
    }

    /// Completes every line's step. The Galerkin step of a system with
    /// free points takes the end rates from the system's mass matrix
    /// (docs/method.md §11.10), the others from each line's own.
    fn finish_lines(&mut self, report: NewtonReport) {
        let Some(mass) = &mut self.mass else {
            for line in &mut self.lines {
                line.finish_step(report);
            }
            return;
        };
        for line in &mut self.lines {
            line.expand_step();
        }
        let layout = &self.layout.lines[0];
        for (p, idx) in self.point_index.iter().enumerate() {
            if idx.is_empty() {
                continue;
            }
            let m = &self.points[p];
            let terms = PointTerms::of(&self.system, p, self.t, idx, layout, &self.slab);
            terms.expand(&self.x, m.e, m.v, &mut self.point_nodes[p]);
            self.point_momentum[p] = terms.end_momentum(&self.point_nodes[p]);
        }
        mass.set_end_rates(&self.system, &mut self.lines, &self.point_momentum);
        for line in &mut self.lines {
            line.close_step(report);
        }
    }

    /// The lines' predicted unknowns and the free points' (Taylor
    /// expansion with the last step's acceleration, docs/method.md §4.8).
    fn gather_prediction(&mut self) {
        for (i, line) in self.lines.iter_mut().enumerate() {
            let map = &self.layout.maps[i];
            let xl = line.unknowns();
            map.scatter(xl, &mut self.x);
        }
        let layout = &self.layout.lines[0];
        let h = self.slab.dt;
        for (p, idx) in self.point_index.iter().enumerate() {
            if idx.is_empty() {
                continue;
            }
            let m = &self.points[p];
            for (s, &(i, kind)) in layout.unknown_slots.iter().enumerate() {
                let tau = h * i as f64;
                for c in 0..3 {
                    let (e, v, a) = (m.e[c], m.v[c], m.acceleration[c]);
                    self.x[idx[3 * s + c]] = match kind {
                        Kind::Position => e + tau * v + 0.5 * tau * tau * a,
                        Kind::Velocity => v + tau * a,
                    };
                }
            }
        }
    }

    fn solve_step(&mut self, dt: f64) -> Result<NewtonReport, SolverError> {
        let mut problem = step_problem!(self);
        solve(
            &mut problem,
            &mut self.x,
            &self.settings.newton,
            &mut self.workspace,
            None,
        )
        .map_err(|f| SolverError {
            kind: f.kind,
            time: self.t,
            step: self.steps + 1,
            residual: f.report.residual,
            iterations: f.report.iterations,
            detail: format!("time step {dt:e} s"),
        })
    }

    /// The forces of the line ends on their points over the step: at a
    /// free point the line's share of the point's position rows, summed
    /// over the step's position rows and divided by dt (the negative of
    /// the impulse the point gives the line, docs/method.md §11.4); at a
    /// fixed or coupled point minus the line's reaction (§6.5).
    fn collect_end_forces(&mut self, dt: f64) {
        for (i, line) in self.lines.iter_mut().enumerate() {
            let ends = self.system.lines()[i].ends;
            let last = line.model().nodes() - 1;
            let free_end = ends
                .iter()
                .any(|e| matches!(e, End::Point(p) if self.system.points()[*p].is_free()));
            if free_end {
                // The line's rows at the converged unknowns.
                let map = &self.layout.maps[i];
                let xl = &mut self.x_local[i];
                map.gather(&self.x, xl);
                line.assemble_line::<BorderedMatrix>(xl, &mut self.residual_local[i], None);
            }
            let layout = &self.layout.lines[i];
            for (k, (end, node)) in ends.iter().zip([0, last]).enumerate() {
                let End::Point(p) = *end else {
                    self.end_forces[i][k] = EndForce::default();
                    continue;
                };
                let force = if self.system.points()[p].is_free() {
                    let rows = position_row_sum(layout, node, &self.residual_local[i]);
                    let dpn = line.model().dofs_per_node();
                    std::array::from_fn(|c| {
                        let g = coordinate(dpn, node, SLOT_R, c);
                        (rows[c] + line.galerkin_end_term(g)) / dt
                    })
                } else {
                    let r = line
                        .reactions()
                        .iter()
                        .find(|(n, _)| *n == node)
                        .map_or([0.0; 3], |(_, f)| *f);
                    r.map(|f| -f)
                };
                self.end_forces[i][k] = EndForce { force };
            }
        }
    }

    /// Moves the points to the end of the step: free points to their
    /// converged unknowns, fixed and coupled ones along their motion.
    fn advance_points(&mut self, dt: f64) {
        let layout = &self.layout.lines[0];
        let last = layout.layers();
        let t_end = self.t + dt;
        for (p, point) in self.system.points().iter().enumerate() {
            let m = &mut self.points[p];
            m.previous = (m.e, m.v);
            let galerkin_rate = self.mass.as_ref().and_then(|mass| mass.point_rate(p));
            let (e, v) = if self.point_index[p].is_empty() {
                point.state_at(t_end)
            } else if let Some(v) = galerkin_rate {
                let idx = &self.point_index[p];
                let se = layout.unknown_slot(last, Kind::Position).expect("e_L");
                (std::array::from_fn(|c| self.x[idx[3 * se + c]]), v)
            } else {
                let idx = &self.point_index[p];
                let se = layout.unknown_slot(last, Kind::Position).expect("e_L");
                let sv = layout.unknown_slot(last, Kind::Velocity).expect("v_L");
                (
                    std::array::from_fn(|c| self.x[idx[3 * se + c]]),
                    std::array::from_fn(|c| self.x[idx[3 * sv + c]]),
                )
            };
            for c in 0..3 {
                m.acceleration[c] = (v[c] - m.v[c]) / dt;
            }
            m.e = e;
            m.v = v;
        }
    }
}

/// The points' states at the start: free points where their first
/// attached line end is (its position and velocity), the others on
/// their motion.
fn point_motions(system: &System, lines: &[Simulation]) -> Result<Vec<PointMotion>, ModelError> {
    let t = lines[0].state().t;
    let mut out = Vec::with_capacity(system.points().len());
    for (p, point) in system.points().iter().enumerate() {
        let (e, v) = if point.is_free() {
            let mut at = None;
            for (li, end) in system.attachments(p) {
                let sim = &lines[li];
                let node = if end == 0 { 0 } else { sim.model().nodes() - 1 };
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
