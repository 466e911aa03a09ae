//! The system at a time inside its recent steps (docs/method.md §6.5a):
//! what a run writes at output times that the steps do not land on (a step of
//! 1 s written every 0.1 s), from the step's own functions of time, not
//! by shortening the steps.
//!
//! - A line's coordinates: the step's cubic in time, eq. (6) (the Hermite
//!   cubic of the end values e_a, e_b and the end slopes w_a, w_b the step
//!   solved for), and its rates from the same cubic:
//!
//!   ```text
//!     e(t_a + s h) = H1(s) e_a + H2(s) h w_a + H3(s) e_b + H4(s) h w_b      (M23d)
//!   ```
//!
//! - A line end's force: the step's force cubic, whose four moments are
//!   the step's rows (M23b), at s (the force's L2 projection on the step's
//!   cubics; at s = 1 it is (M23b) itself).
//! - A free point: the Hermite cubic of its positions and velocities at
//!   the step's ends; a fixed or coupled point: its motion at t.
//!
//! A run step may be crossed in several steps (a halved step, §11.13; a
//! tolerance's steps, §11.17): with [`SystemSimulation::record_steps`]
//! each converged step keeps its record ([`StepRecord`]) until the run
//! loop moves on to its next step, so every output time inside the run
//! step finds the step that holds it.
//!
//! Each is the step's own approximation of the motion, O(h^4) where the
//! step resolves it, as the values at the steps' ends are. The Galerkin
//! step only: P2's rows give two moments of the force, not its cubic.
//! Not interpolated in this version (refused naming them): free bodies'
//! poses, and a line's internal state (a viscoelastic line's static
//! strain, a VIV line's phase), which are states of the steps' ends.

use super::simulation::SystemSimulation;
use super::EndForce;
use crate::error::ModelError;
use crate::integrator::TimeCubic;
use crate::State;

/// What a converged step leaves to be evaluated inside it: its start and
/// length, each line's cubic in time (M23d), each free point's positions
/// and velocities at its ends (None for a fixed or coupled point), each
/// line end's force cubic (M23b; None at a loose end).
#[derive(Clone, Debug)]
pub struct StepRecord {
    t_a: f64,
    h: f64,
    lines: Vec<TimeCubic>,
    points: Vec<Option<[[f64; 3]; 4]>>,
    forces: Vec<[Option<[[f64; 3]; 4]>; 2]>,
}

impl StepRecord {
    fn holds(&self, t: f64) -> bool {
        let slack = 1e-9 * self.h;
        t >= self.t_a - slack && t <= self.t_a + self.h + slack
    }

    fn unit_time(&self, t: f64) -> f64 {
        (t - self.t_a) / self.h
    }
}

impl SystemSimulation {
    /// Whether each converged step keeps its [`StepRecord`] (off by
    /// default): a run that writes at times between the steps turns it
    /// on; the run loops ([`super::run`], [`super::run_to_tolerance`])
    /// clear the records before each of their steps. Refused with P2
    /// (its rows give no force cubic), free bodies and lines with an
    /// internal state (see the module's doc).
    pub fn record_steps(&mut self, on: bool) -> Result<(), ModelError> {
        if on {
            self.interpolable()?;
        }
        self.step_records = on.then(Vec::new);
        Ok(())
    }

    /// The records of the steps taken since the run loop's last step
    /// began (empty unless [`Self::record_steps`]).
    pub fn step_records(&self) -> &[StepRecord] {
        self.step_records.as_deref().unwrap_or(&[])
    }

    /// Forgets the steps recorded so far (the run loops, before each of
    /// their steps).
    pub(crate) fn clear_step_records(&mut self) {
        if let Some(r) = self.step_records.as_mut() {
            r.clear();
        }
    }

    /// Refuses a system whose state between the ends of a step is not
    /// interpolated (see the module's doc).
    fn interpolable(&self) -> Result<(), ModelError> {
        if !self.settings.time_scheme.carries_momentum() {
            return Err(ModelError::invalid(
                "time_scheme",
                "the state between the ends of a step comes from the Galerkin step's cubics \
                 (docs/method.md (M23d)); P2's rows do not give the end forces' cubic",
            ));
        }
        if !self.bodies.is_empty() {
            return Err(ModelError::invalid(
                "bodies",
                "a free body's pose between the ends of a step is not interpolated in this \
                 version",
            ));
        }
        if let Some(i) = self
            .lines
            .iter()
            .position(|l| l.model().internal_state_len() > 0)
        {
            return Err(ModelError::invalid(
                format!("lines[{i}]"),
                "a viscoelastic or VIV line's internal state between the ends of a step is not \
                 interpolated in this version",
            ));
        }
        Ok(())
    }

    /// Keeps the record of the step just converged, from `t_a` of length
    /// `h` (with [`Self::record_steps`]).
    pub(super) fn keep_step_record(&mut self, t_a: f64, h: f64) {
        if self.step_records.is_none() {
            return;
        }
        // Every line has its cubic after a converged step; should one not,
        // the step is not recorded and a time inside it is refused.
        let Some(lines) = self.lines.iter().map(|l| l.last_cubic()).collect() else {
            return;
        };
        let points = (0..self.points.len())
            .map(|p| {
                let m = &self.points[p];
                (!self.point_index[p].is_empty()).then(|| {
                    let ((e0, v0), (e1, v1)) = (m.previous, (m.e, m.v));
                    [e0, v0, e1, v1]
                })
            })
            .collect();
        let record = StepRecord {
            t_a,
            h,
            lines,
            points,
            forces: self.force_cubics.clone(),
        };
        if let Some(r) = self.step_records.as_mut() {
            r.push(record);
        }
    }

    /// The undone step's record goes with it.
    pub(super) fn drop_last_step_record(&mut self) {
        if let Some(r) = self.step_records.as_mut() {
            r.pop();
        }
    }

    /// The recorded step that holds time `t` (the last one, at a time two
    /// steps share).
    fn record_at(&self, t: f64) -> Result<&StepRecord, ModelError> {
        self.step_records()
            .iter()
            .rev()
            .find(|r| r.holds(t))
            .ok_or_else(|| {
                ModelError::invalid(
                    "t",
                    format!("{t} s is in no step recorded since the run's last step began"),
                )
            })
    }

    /// Line `line`'s coordinates and rates at time `t` (M23d), into `out`
    /// (its `internal` left empty), from the recorded step holding t.
    pub fn line_state_within(
        &self,
        line: usize,
        t: f64,
        out: &mut State,
    ) -> Result<(), ModelError> {
        let record = self.record_at(t)?;
        let n = self.lines[line].model().dofs();
        out.t = t;
        out.e.resize(n, 0.0);
        out.v.resize(n, 0.0);
        out.internal.clear();
        record.lines[line].state_at(t, &mut out.e, &mut out.v);
        Ok(())
    }

    /// Point `p`'s position and velocity at time `t`: a free point's
    /// Hermite cubic of its positions and velocities at the recorded
    /// step's ends, a fixed or coupled point's motion at t.
    pub fn point_state_within(&self, p: usize, t: f64) -> Result<([f64; 3], [f64; 3]), ModelError> {
        let record = self.record_at(t)?;
        let Some(kept) = record.points.get(p) else {
            return Err(ModelError::invalid(
                format!("points[{p}]"),
                "the point was added after the recorded step (a line end released, §11.16)",
            ));
        };
        let Some([e0, v0, e1, v1]) = *kept else {
            return Ok(self.topology.points()[p].state_at(t));
        };
        let h = record.h;
        let [value, slope, _] = crate::shape::hermite3(record.unit_time(t), 1.0);
        let x = std::array::from_fn(|c| {
            value[0] * e0[c] + value[1] * h * v0[c] + value[2] * e1[c] + value[3] * h * v1[c]
        });
        let v = std::array::from_fn(|c| {
            (slope[0] * e0[c] + slope[2] * e1[c]) / h + slope[1] * v0[c] + slope[3] * v1[c]
        });
        Ok((x, v))
    }

    /// The force each end of line `line` exerts on its point at time `t`:
    /// the recorded step's force cubic there (M23b), zero at a loose end.
    pub fn end_forces_within(&self, line: usize, t: f64) -> Result<[EndForce; 2], ModelError> {
        let record = self.record_at(t)?;
        let [value, _, _] = crate::shape::hermite3(record.unit_time(t), 1.0);
        Ok(record.forces[line].map(|cubic| EndForce {
            force: cubic.map_or([0.0; 3], |b| {
                std::array::from_fn(|c| (0..4).map(|j| value[j] * b[j][c]).sum())
            }),
        }))
    }

    /// The net force the attached lines exert on point `p` at time `t`
    /// ([`Self::end_forces_within`] summed).
    pub fn point_force_within(&self, p: usize, t: f64) -> Result<[f64; 3], ModelError> {
        let mut f = [0.0; 3];
        for (line, end) in self.topology.attachments(p) {
            let force = self.end_forces_within(line, t)?[end].force;
            for c in 0..3 {
                f[c] += force[c];
            }
        }
        Ok(f)
    }
}
