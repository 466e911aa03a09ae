//! Line failures (docs/method.md §11.16; MoorDyn-F's FAILURE section): a
//! group of line ends let go of the point that holds them, at a time or
//! when the tension of one of them reaches a threshold, whichever comes
//! first. The ends stay joined to one another at a new free point of no
//! mass, no volume and no water of its own, where the old point was and
//! moving as it moved: the lines carry on from their states with nothing
//! added or taken, so the system's energy and momentum pass the release
//! unchanged (the constraint that held the ends is gone, not a force
//! applied).
//!
//! A release changes the step's unknowns: the new point's three (shared
//! by the released ends, §11.2), and at a fixed or coupled point the
//! released ends' constraint rows go (§6.3). The lines so changed are
//! rebuilt at their states, carrying their Galerkin momentum, and the
//! system's layout, solver and mass matrix are laid out again
//! ([`super::frame::Frame`]).

use super::failures::{Dropped, LineFailure, Release, Trigger};
use super::frame::Frame;
use super::simulation::SystemSimulation;
use super::step_equations::PointMotion;
use super::{end_node, End, Point, PointKind, Topology};
use crate::constraints::ConstraintKind;
use crate::error::{FailureKind, ModelError, SolverError};
use crate::integrator::{Simulation, StepReport};
use crate::model::{coordinate, Model, SLOT_R};

impl SystemSimulation {
    /// Sets the line failures of the run (checked: keys `failures[i]`).
    /// After every converged step each one still to come is checked, in
    /// order: its time first, then the tension at the end of the step of
    /// each of its line ends (the force the end exerts on the point,
    /// (M23a)); a failure due releases its ends ([`Self::release`]). The
    /// lines it released are taken out of the failures still to come at
    /// the same point; one left without lines is dropped
    /// ([`Self::dropped_failures`]).
    pub fn set_failures(&mut self, failures: Vec<LineFailure>) -> Result<(), ModelError> {
        let models: Vec<&Model> = self.lines.iter().map(Simulation::model).collect();
        check_failures(&self.topology, &models, &failures)?;
        self.failures.pending = failures.into_iter().enumerate().collect();
        Ok(())
    }

    /// The failures that happened so far, in the order they did.
    pub fn releases(&self) -> &[Release] {
        &self.failures.releases
    }

    /// The failures that will not happen, and why.
    pub fn dropped_failures(&self) -> &[Dropped] {
        &self.failures.dropped
    }

    /// Releases the ends of `lines` attached at `point` now: they move to
    /// a new free point of no mass at their position and velocity, which
    /// is returned. At a free point at least one line must stay; a
    /// released end must carry no constraint but its attachment (a clamp
    /// in a direction is not released).
    pub fn release(&mut self, point: usize, lines: &[usize]) -> Result<usize, ModelError> {
        let models: Vec<&Model> = self.lines.iter().map(Simulation::model).collect();
        check_release(&self.topology, &models, point, lines)?;
        let was_joined = self.topology.has_free_points() || self.topology.has_free_bodies();
        let held = !self.topology.points[point].is_unknown();
        let junction: Vec<(usize, usize)> = self
            .topology
            .attachments(point)
            .map(|(li, end)| (li, end_node(self.lines[li].model(), end)))
            .collect();
        let (first, end) = attached_end(&self.topology, point, lines[0]).expect("checked");
        let (e, v) = end_state(&self.lines[first], end);
        let new_point = self.topology.points.len();
        self.topology.points.push(Point::free(e, 0.0));
        let mut released_nodes = vec![None; self.lines.len()];
        for &li in lines {
            let (_, end) = attached_end(&self.topology, point, li).expect("checked");
            self.topology.ends[li][end] = End::Point(new_point);
            self.forces_at_time.restart(li, end);
            if held {
                released_nodes[li] = Some(end_node(self.lines[li].model(), end));
            }
        }
        for (li, node) in released_nodes.into_iter().enumerate() {
            if node.is_none() && was_joined {
                continue;
            }
            let line = &self.lines[li];
            let mut list = line.model().constraints.list.clone();
            list.retain(|c| {
                Some(c.node) != node || !matches!(c.kind, ConstraintKind::Attached { .. })
            });
            let model = line.model().clone().with_constraints(list)?;
            let mut settings = line.settings().clone();
            settings.planar_reduction = false;
            self.lines[li] = line
                .rebuilt(model, settings, false, node)
                .map_err(|e| e.under(&format!("lines[{li}]")))?;
        }
        // Each line's share of the junction's momentum restarts as its
        // own M v: apart, each part carries its own (docs/method.md §11.16).
        if !held {
            for (li, node) in junction {
                self.lines[li].restart_momentum_at(node);
            }
        }
        self.points.push(PointMotion {
            e,
            v,
            previous: (e, v),
            acceleration: [0.0; 3],
        });
        self.point_nodes.push(Default::default());
        self.point_momentum.push([0.0; 3]);
        self.lay_out_again()?;
        Ok(new_point)
    }

    /// The step's layout, solver, scales and mass matrix for the current
    /// topology and lines (after a release).
    fn lay_out_again(&mut self) -> Result<(), ModelError> {
        let frame = Frame::new(&self.topology, &self.lines, &self.bodies, &self.settings)?;
        let n = frame.layout.size;
        self.x_local = frame.line_buffers();
        self.residual_local = frame.line_buffers();
        self.x = vec![0.0; n];
        self.body_rows = vec![0.0; n];
        self.layout = frame.layout;
        self.point_index = frame.point_index;
        self.workspace = frame.workspace;
        self.unknown_scale = frame.unknown_scale;
        self.equation_scale = frame.equation_scale;
        self.mass = frame.mass;
        Ok(())
    }

    /// Releases the ends of every failure due at the end of the step
    /// `report` (see [`Self::set_failures`]).
    pub(crate) fn trigger_failures(&mut self, report: &StepReport) -> Result<(), SolverError> {
        let mut k = 0;
        while k < self.failures.pending.len() {
            let (index, failure) = self.failures.pending[k].clone();
            let Some(trigger) = self.due(&failure) else {
                k += 1;
                continue;
            };
            self.failures.pending.remove(k);
            let point = &self.topology.points[failure.point];
            let stays = self.topology.attachments(failure.point).count() > failure.lines.len();
            if point.kind == PointKind::Free && !stays {
                self.failures.dropped.push(Dropped {
                    failure: index,
                    time: self.t,
                    why: format!(
                        "it would release every line left at free point {}: that point would \
                         hold nothing",
                        failure.point
                    ),
                });
                continue;
            }
            let new_point =
                self.release(failure.point, &failure.lines)
                    .map_err(|e| SolverError {
                        kind: FailureKind::OutsideModel,
                        time: self.t,
                        step: report.step,
                        residual: report.newton.residual,
                        iterations: report.newton.iterations,
                        detail: format!("releasing the line ends of failure {index}: {e}"),
                    })?;
            self.failures.releases.push(Release {
                failure: index,
                time: self.t,
                step: self.steps,
                point: failure.point,
                lines: failure.lines.clone(),
                new_point,
                trigger,
            });
            self.forget_released(failure.point, &failure.lines);
            // Failures before this one may have been dropped (their lines
            // released here): scan again from the first.
            k = 0;
        }
        Ok(())
    }

    /// Whether `failure` is due at the current time, and why: its time
    /// reached (to a millionth of a step, the round-off of summed steps),
    /// else one of its ends' tension at the end of the step at or above
    /// its threshold.
    fn due(&self, failure: &LineFailure) -> Option<Trigger> {
        let slack = 1e-6 * self.settings.time_step;
        if failure.time.is_some_and(|t| self.t >= t - slack) {
            return Some(Trigger::Time);
        }
        let threshold = failure.tension?;
        failure.lines.iter().find_map(|&li| {
            let (_, end) = attached_end(&self.topology, failure.point, li)?;
            let tension = self.forces_at_time.line(li)[end].tension();
            (tension >= threshold).then_some(Trigger::Tension { line: li, tension })
        })
    }

    /// Takes `lines`, just released from `point`, out of the failures
    /// still to come there, dropping those left without lines.
    fn forget_released(&mut self, point: usize, lines: &[usize]) {
        let t = self.t;
        let dropped = &mut self.failures.dropped;
        self.failures.pending.retain_mut(|(index, f)| {
            if f.point != point {
                return true;
            }
            f.lines.retain(|li| !lines.contains(li));
            if f.lines.is_empty() {
                dropped.push(Dropped {
                    failure: *index,
                    time: t,
                    why: "its lines were all released by a failure before it".into(),
                });
            }
            !f.lines.is_empty()
        });
    }
}

/// Checks `failures` on a system of `topology` whose lines' models are
/// `models` (keys `failures[i]`): each one's numbers, and its lines
/// attached at its point, releasable there (see
/// [`SystemSimulation::release`]).
pub fn check_failures(
    topology: &Topology,
    models: &[&Model],
    failures: &[LineFailure],
) -> Result<(), ModelError> {
    for (i, f) in failures.iter().enumerate() {
        check_failure(f)
            .and_then(|()| check_release(topology, models, f.point, &f.lines))
            .map_err(|e| e.under(&format!("failures[{i}]")))?;
    }
    Ok(())
}

/// A failure's own numbers: lines given, without repeats; a positive
/// finite time or tension, at least one of them.
fn check_failure(f: &LineFailure) -> Result<(), ModelError> {
    if f.lines.is_empty() {
        return Err(ModelError::invalid(
            "lines",
            "a failure releases at least one line",
        ));
    }
    for (k, li) in f.lines.iter().enumerate() {
        if f.lines[..k].contains(li) {
            return Err(ModelError::invalid(
                "lines",
                format!("line {li} is given twice"),
            ));
        }
    }
    for (key, value) in [("time", f.time), ("tension", f.tension)] {
        if let Some(x) = value {
            if !(x.is_finite() && x > 0.0) {
                return Err(ModelError::invalid(
                    key,
                    format!("must be positive and finite (got {x})"),
                ));
            }
        }
    }
    if f.time.is_none() && f.tension.is_none() {
        return Err(ModelError::invalid(
            "time",
            "a failure needs a time or a tension (or both) to happen",
        ));
    }
    Ok(())
}

/// Whether the ends of `lines` at `point` can be released: each line
/// attached there, its end carrying no constraint but the attachment, and
/// at a free point a line left.
fn check_release(
    topology: &Topology,
    models: &[&Model],
    point: usize,
    released: &[usize],
) -> Result<(), ModelError> {
    let Some(p) = topology.points.get(point) else {
        return Err(ModelError::invalid(
            "point",
            format!("point {point} does not exist"),
        ));
    };
    if released.is_empty() {
        return Err(ModelError::invalid("lines", "no line to release"));
    }
    for &li in released {
        let Some((_, end)) = attached_end(topology, point, li) else {
            return Err(ModelError::invalid(
                "lines",
                format!("line {li} is not attached to point {point}"),
            ));
        };
        let model = models[li];
        let node = end_node(model, end);
        let held = model
            .constraints
            .list
            .iter()
            .any(|c| c.node == node && !matches!(c.kind, ConstraintKind::Attached { .. }));
        if held {
            return Err(ModelError::invalid(
                "lines",
                format!(
                    "line {li}'s end {} at point {point} is clamped in a direction: releasing a \
                     clamped end is not built",
                    ["A", "B"][end]
                ),
            ));
        }
        // A clamp at a free body's point is a frame in the line's model
        // that the steps turn with the body; a line rebuilt without its
        // released end's constraint would start it again from the given
        // direction.
        if topology.clamps.iter().any(|c| c.line == li) {
            return Err(ModelError::invalid(
                "lines",
                format!(
                    "line {li} is clamped at a free body's point: releasing a line clamped to a \
                     body is not built"
                ),
            ));
        }
    }
    if p.kind == PointKind::Free && topology.attachments(point).count() <= released.len() {
        return Err(ModelError::invalid(
            "lines",
            format!(
                "these are every line at free point {point}: releasing them all lets go of \
                 nothing (the point would hold no line)"
            ),
        ));
    }
    Ok(())
}

/// The line `line`'s end attached at `point`: (line, end).
fn attached_end(topology: &Topology, point: usize, line: usize) -> Option<(usize, usize)> {
    topology.attachments(point).find(|&(li, _)| li == line)
}

/// Position and velocity of `line`'s end `end` (0 = A, 1 = B).
fn end_state(line: &Simulation, end: usize) -> ([f64; 3], [f64; 3]) {
    let model = line.model();
    let o = coordinate(model.dofs_per_node(), end_node(model, end), SLOT_R, 0);
    let s = line.state();
    (
        [s.e[o], s.e[o + 1], s.e[o + 2]],
        [s.v[o], s.v[o + 1], s.v[o + 2]],
    )
}
