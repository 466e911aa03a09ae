//! Systems of cable lines joined at points (docs/method.md §11): a
//! mooring of lines from anchors to fairleads, a bridle of two lines
//! meeting at a shackle, a clump weight or a buoy on a line.
//!
//! A *point* is `fixed` (an anchor), `free` (three translational
//! unknowns, with a mass and a constant force: a shackle, a clump weight,
//! a buoy) or `coupled` (its position is given as a function of time: a
//! fairlead on a vessel). A *line* is a cable model ([`Model`]) whose ends
//! A (node 0) and B (last node) are each attached to a point or left
//! loose. An attached end shares the point's position and is free to
//! rotate:
//!
//! - at a fixed or coupled point, its position r is prescribed, a
//!   constraint of the line ([`ConstraintKind::Attached`]), enforced by
//!   multipliers or elimination like every constraint (§6.3-6.4);
//! - at a free point, its position coordinates *are* the point's: every
//!   line attached there refers to the same unknowns, so the point's rows
//!   sum the forces of all its lines with the point's own inertia and
//!   load (§11.2). Lines are coupled only through free points.
//!
//! The step of a system ([`SystemSimulation`]) solves the lines' slab
//! equations and the free points' rows together; its Jacobian is each
//! line's band bordered by the free points' unknowns
//! ([`crate::bordered`]), factorized by block elimination.

mod apart;
mod balance;
mod bodies;
mod body_clamps;
mod body_holds;
mod body_pins;
mod body_statics;
mod body_terms;
mod clamp_checks;
mod clamp_mass;
mod clamp_moments;
mod end_forces;
mod energy;
mod failures;
mod frame;
mod halving;
mod held;
mod host_order;
mod host_waves;
mod layout;
mod line_body;
mod line_type;
mod mass;
mod moordyn_start;
mod network;
mod pins;
mod point;
mod point_bed;
mod point_forces;
mod point_terms;
mod release;
mod run;
mod seed;
mod simulation;
mod static_friction;
mod static_lines;
mod static_paths;
mod static_stability;
mod static_water;
mod statics;
mod step_control;
mod step_equations;
mod stepping;
mod stiffness;
mod topology;
mod undo;
mod within_step;
pub use within_step::StepRecord;

pub use balance::{balanced_bodies, balanced_points, static_seed_states};
pub use bodies::{Body, BodyKind, Pin};
pub use failures::{Dropped, LineFailure, Release, Trigger};
pub use halving::{DEFAULT_STEP_HALVINGS, MAX_STEP_HALVINGS};
pub use held::{held_push, HeldMotion};
pub use host_order::{HostOrder, HostRod};
pub(crate) use host_waves::takes_host_waves;
pub use layout::SystemLayout;
pub use line_type::{stable_step, LineSection, EI_FACTOR};
pub use moordyn_start::{moordyn_start_forces, moordyn_start_states};
pub use point::{Point, PointKind};
pub use point_bed::{steady_point_force, PointBed};
pub use release::check_failures;
pub(crate) use run::watched_step;
pub use run::{run, RunProgress};
pub use seed::{
    catenary_states, catenary_states_at, end_positions, end_positions_at, overlong_lines, shaped,
    straight_between, straight_states, taut_states, OverlongLine,
};
pub use simulation::{EndForce, SystemSimulation};
pub use static_friction::StaticFriction;
pub use statics::SystemStatics;
pub(crate) use step_control::Stepper;
pub use step_control::{run_to_tolerance, ControlledSteps, StepControl, MIN_STEP_FRACTION};
pub use topology::{attached_ends, AttachedEnd, Topology};

use crate::constraints::{Constraint, ConstraintKind};
use crate::error::ModelError;
use crate::model::Model;
use crate::motion::{CoupledMotion, MotionTable};

/// The node of line end `end` (0 = A, 1 = B) of a line of `model`: node 0
/// and the last node (docs/method.md §11.1).
pub fn end_node(model: &Model, end: usize) -> usize {
    if end == 0 {
        0
    } else {
        model.nodes() - 1
    }
}

/// What a line end is attached to: a point (its index in the system) or
/// nothing.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum End {
    Loose,
    Point(usize),
}

/// A line of a system: a cable model and what its ends A (node 0) and B
/// (last node) attach to.
#[derive(Clone, Debug)]
pub struct Line {
    pub model: Model,
    pub ends: [End; 2],
}

impl Line {
    /// The line with its end (0 = A, 1 = B) clamped in `direction`: the
    /// end's r_x held parallel to it (docs/method.md §6.10; a riser
    /// hang-off). The end must be attached to a fixed or coupled point
    /// (checked by [`System::new`]); the direction need not be a unit
    /// vector.
    pub fn clamped(self, end: usize, direction: [f64; 3]) -> Result<Self, ModelError> {
        let node = end_node(&self.model, end);
        let mut list = self.model.constraints.list.clone();
        list.push(Constraint {
            node,
            kind: ConstraintKind::Parallel { direction },
        });
        Ok(Line {
            model: self.model.with_constraints(list)?,
            ends: self.ends,
        })
    }
}

/// A system of lines and points, validated; the lines' models carry the
/// constraints of their ends at fixed and coupled points. It reads as its
/// [`Topology`] (points, line ends, gravity) through `Deref`.
#[derive(Clone, Debug)]
pub struct System {
    lines: Vec<Line>,
    topology: Topology,
}

impl std::ops::Deref for System {
    type Target = Topology;

    fn deref(&self) -> &Topology {
        &self.topology
    }
}

impl System {
    /// Validates the points and lines and adds to every line the
    /// constraints of its ends at fixed and coupled points (after its own).
    /// Keys in errors: `points[i]`, `lines[i]`.
    pub fn new(
        lines: Vec<Line>,
        points: Vec<Point>,
        gravity: [f64; 3],
    ) -> Result<Self, ModelError> {
        Self::with_bodies(lines, points, Vec::new(), gravity)
    }

    /// [`System::new`] with rigid bodies (docs/method.md §15.7): points of
    /// kind [`PointKind::Body`] are placed where their body puts them (on
    /// a fixed body they become fixed points). Keys in errors also
    /// `bodies[i]`.
    pub fn with_bodies(
        lines: Vec<Line>,
        mut points: Vec<Point>,
        mut bodies: Vec<Body>,
        gravity: [f64; 3],
    ) -> Result<Self, ModelError> {
        let (body_points, on_a_line) = bodies::place_points(&mut bodies, &mut points, gravity)?;
        if lines.is_empty() && bodies.is_empty() {
            return Err(ModelError::invalid(
                "lines",
                "a system needs at least one line or one body",
            ));
        }
        for (i, p) in points.iter().enumerate() {
            check_point(i, p)?;
        }
        if gravity.iter().any(|g| !g.is_finite()) {
            return Err(ModelError::invalid("gravity", "must be finite"));
        }
        let size = extent(
            lines.iter().map(|l| l.model.cable.length),
            points.iter().map(|p| p.position),
        );
        for (i, p) in points.iter().enumerate() {
            check_table_start(i, p, size)?;
        }
        let mut attached = vec![0usize; points.len()];
        let mut out = Vec::with_capacity(lines.len());
        let mut clamps = Vec::new();
        for (li, line) in lines.into_iter().enumerate() {
            let mut list = line.model.constraints.list.clone();
            for AttachedEnd { point: p, node, .. } in attached_ends(&line.ends, &line.model) {
                let Some(point) = points.get(p) else {
                    return Err(ModelError::invalid(
                        format!("lines[{li}]"),
                        format!("attached to point {p}, which does not exist"),
                    ));
                };
                attached[p] += 1;
                let motion = match &point.kind {
                    PointKind::Free | PointKind::Body { .. } => continue,
                    PointKind::Fixed => CoupledMotion::NONE,
                    PointKind::Coupled(m) => m.clone(),
                };
                list.push(Constraint {
                    node,
                    kind: ConstraintKind::Attached {
                        position: point.position,
                        motion,
                    },
                });
            }
            if line.ends[0] == line.ends[1] && line.ends[0] != End::Loose {
                return Err(ModelError::invalid(
                    format!("lines[{li}]"),
                    "both ends are attached to the same point",
                ));
            }
            let model = line
                .model
                .with_constraints(list)
                .map_err(|e| e.under(&format!("lines[{li}]")))?;
            let mut line = Line {
                model,
                ends: line.ends,
            };
            let found = clamp_checks::line_clamps(li, &mut line, &points, &bodies, &body_points)?;
            clamps.extend(found);
            out.push(line);
        }
        for (i, p) in points.iter().enumerate() {
            if p.is_free() && attached[i] == 0 {
                return Err(ModelError::invalid(
                    format!("points[{i}]"),
                    "a free point needs at least one line attached (nothing else holds it)",
                ));
            }
        }
        clamp_checks::check_connectors(&bodies, &body_points, &clamps)?;
        if let Some(c) = clamps.iter().find(|c| on_a_line[c.body]) {
            return Err(ModelError::invalid(
                format!("lines[{}]", c.line),
                format!(
                    "is clamped in a direction at body {}, whose mass lies on a line and which \
                     has no inertia about it: the clamp's moment would turn it about the line \
                     (docs/method.md (B2a))",
                    c.body
                ),
            ));
        }
        let point_beds = (points.iter().enumerate())
            .map(|(p, pt)| {
                pt.is_free()
                    .then(|| point_bed::PointBed::of(&out, p))
                    .flatten()
            })
            .collect();
        let mut topology = Topology {
            ends: out.iter().map(|l| l.ends).collect(),
            point_beds,
            points,
            bodies,
            body_points,
            clamps,
            gravity,
            host_order: None,
        };
        host_waves::start_still(&mut out, &mut topology);
        Ok(System {
            lines: out,
            topology,
        })
    }

    pub fn lines(&self) -> &[Line] {
        &self.lines
    }

    /// Moves body b to `position` (its reference point) and `rotation`,
    /// with its points (a free body at a static equilibrium).
    pub fn set_body_pose(&mut self, b: usize, position: [f64; 3], rotation: [[f64; 3]; 3]) {
        let body = &mut self.topology.bodies[b];
        body.position = position;
        body.rotation = rotation;
        let body = body.clone();
        for clamp in self.topology.clamps.iter().filter(|c| c.body == b) {
            let hold = &mut self.lines[clamp.line].model.constraints.directions[clamp.hold];
            *hold = clamp.local.turned(&rotation);
        }
        for p in &mut self.topology.points {
            if let PointKind::Body { body: on, local } = p.kind {
                if on == b {
                    p.position = body.point(local);
                }
            }
        }
    }

    /// The system's topology (its points, line ends and gravity) and its
    /// lines' models, apart: a running simulation keeps the one and hands
    /// the models to its line simulations.
    pub fn into_parts(self) -> (Topology, Vec<Model>) {
        let models = self.lines.into_iter().map(|l| l.model).collect();
        (self.topology, models)
    }

    /// The same system with the fixed or coupled points `points` made
    /// free points of nothing of their own where they are at t = 0, their
    /// lines' attachments there released: where a coupled point's
    /// mooring stiffness is read (docs/method.md §15.9).
    pub fn with_points_freed(&self, points: &[usize]) -> Result<System, ModelError> {
        let mut all = self.topology.points.clone();
        for &p in points {
            let point = all
                .get_mut(p)
                .ok_or_else(|| ModelError::invalid(format!("points[{p}]"), "does not exist"))?;
            *point = Point::free(point.state_at(0.0).0, 0.0);
        }
        let lines = self
            .lines
            .iter()
            .map(|line| {
                let released: Vec<usize> = attached_ends(&line.ends, &line.model)
                    .map(|a| a.node)
                    .collect();
                let own: Vec<Constraint> = line
                    .model
                    .constraints
                    .list
                    .iter()
                    .filter(|c| {
                        !(released.contains(&c.node)
                            && matches!(c.kind, ConstraintKind::Attached { .. }))
                    })
                    .cloned()
                    .collect();
                Ok(Line {
                    model: line.model.clone().with_constraints(own)?,
                    ends: line.ends,
                })
            })
            .collect::<Result<Vec<Line>, ModelError>>()?;
        System::with_bodies(
            lines,
            all,
            self.topology.bodies.clone(),
            self.topology.gravity,
        )
    }

    /// Moves coupled point p along `motion` (a coupling code's next
    /// interval, docs/method.md §13.2): the point and the attachment
    /// constraints of its lines. Refused for a fixed or free point.
    pub fn set_point_motion(&mut self, p: usize, motion: CoupledMotion) -> Result<(), ModelError> {
        self.topology.check_coupled(p)?;
        let attached: Vec<(usize, usize)> = self.attachments(p).collect();
        for (li, end) in attached {
            let model = &mut self.lines[li].model;
            let node = end_node(model, end);
            let dpn = model.dofs_per_node();
            model
                .constraints
                .set_attached_motion(node, dpn, motion.clone())
                .map_err(|e| e.under(&format!("lines[{li}]")))?;
        }
        self.topology.set_point_motion(p, motion);
        Ok(())
    }
}

/// The size of a system (m): the largest of its lines' unstretched
/// lengths and the diagonal of its points' bounding box.
pub fn extent(
    lengths: impl IntoIterator<Item = f64>,
    positions: impl IntoIterator<Item = [f64; 3]>,
) -> f64 {
    let mut lo = [f64::INFINITY; 3];
    let mut hi = [f64::NEG_INFINITY; 3];
    let mut any = false;
    for r in positions {
        any = true;
        for c in 0..3 {
            lo[c] = lo[c].min(r[c]);
            hi[c] = hi[c].max(r[c]);
        }
    }
    let diagonal = if any {
        (0..3).map(|c| (hi[c] - lo[c]).powi(2)).sum::<f64>().sqrt()
    } else {
        0.0
    };
    lengths.into_iter().fold(diagonal, f64::max)
}

/// How far a tabulated motion may start from its point: 1e-9 of the
/// system's [`extent`] (round-off of positions written to a file and read
/// back, not a modelling tolerance).
pub const TABLE_START_TOLERANCE: f64 = 1e-9;

/// The distance between a coupled point's tabulated position at t = 0
/// and its position, when it exceeds [`TABLE_START_TOLERANCE`] of `size`.
pub fn table_start_mismatch(position: &[f64; 3], table: &MotionTable, size: f64) -> Option<f64> {
    let r0 = table.state(0.0).0;
    let d = (0..3)
        .map(|c| (r0[c] - position[c]).powi(2))
        .sum::<f64>()
        .sqrt();
    (d > TABLE_START_TOLERANCE * size).then_some(d)
}

/// A coupled point moved by a table starts where the table is at t = 0.
fn check_table_start(i: usize, p: &Point, size: f64) -> Result<(), ModelError> {
    let PointKind::Coupled(CoupledMotion::Table(table)) = &p.kind else {
        return Ok(());
    };
    match table_start_mismatch(&p.position, table, size) {
        None => Ok(()),
        Some(d) => Err(ModelError::invalid(
            format!("points[{i}].motion"),
            format!(
                "the table's position at t = 0, {:?}, is {d:e} m from the point's position \
                 {:?} (allowed: {TABLE_START_TOLERANCE:e} of the system's size {size} m)",
                table.state(0.0).0,
                p.position
            ),
        )),
    }
}

fn check_point(i: usize, p: &Point) -> Result<(), ModelError> {
    let key = format!("points[{i}]");
    if p.position.iter().any(|x| !x.is_finite()) {
        return Err(ModelError::invalid(
            format!("{key}.position"),
            "must be finite",
        ));
    }
    if !p.mass.is_finite() || p.mass < 0.0 {
        return Err(ModelError::invalid(
            format!("{key}.mass"),
            format!("must be a finite number >= 0, got {}", p.mass),
        ));
    }
    if p.force.iter().any(|x| !x.is_finite()) {
        return Err(ModelError::invalid(
            format!("{key}.force"),
            "must be finite",
        ));
    }
    if !p.is_free() && (p.mass != 0.0 || p.force != [0.0; 3] || p.water.is_some()) {
        return Err(ModelError::invalid(
            key,
            "only a free point carries a mass, a force or water loads (a fixed or coupled \
             point's position is given)",
        ));
    }
    p.damping.check(&key)?;
    if !p.damping.is_zero() && !p.is_free() {
        return Err(ModelError::invalid(
            format!("{key}.damping"),
            "only a free point is damped (a fixed or coupled point's motion is given; a point \
             on a body: give the body its damping)",
        ));
    }
    if let Some(w) = &p.water {
        w.check(&key)?;
    }
    Ok(())
}
