//! A step that Newton fails, taken again in halves (docs/method.md
//! §11.13): from the last converged state, two steps of half the length,
//! each of which may halve again, `step_halvings` levels deep. Where a
//! line touches down on a stiff seabed the contact's force has a kink
//! that Newton can cycle around at a long step; half the step moves the
//! touchdown less. Until a step fails, the run is the one without
//! halvings, to the bit. A Galerkin step whose energy jumps is undone
//! and halved too, by the run (`run.rs`, §11.15); the energy watchdog's
//! unstable step (P2 above its stable step) is not halved: it is the
//! step the scenario chose, reported as such.

use super::end_forces::EndForce;
use super::SystemSimulation;
use crate::error::{ModelError, SolverError};
use crate::integrator::StepReport;

/// The most halvings a step may take (a step cut into 2^10 parts).
pub const MAX_STEP_HALVINGS: u32 = 10;

/// The halvings a system's failed step takes unless told otherwise: a
/// step cut into up to 32 parts. Until a step fails the run is the one
/// without halvings, to the bit, so the default costs nothing where it is
/// not needed; where it is, a line touching down or going slack at a long
/// step runs on (a 26 m rope from the bed to a fairlead heaving 0.5 m at
/// dt 0.1 s, tests/cli/step_halvings.rs of stancf-cli) instead of stopping.
pub const DEFAULT_STEP_HALVINGS: u32 = 5;

impl SystemSimulation {
    /// Where Newton fails a step (no convergence, a singular Jacobian, a
    /// value that is not finite), take it again as two halves, up to
    /// `halvings` levels ([`DEFAULT_STEP_HALVINGS`] unless set; 0: fail
    /// at once). At most [`MAX_STEP_HALVINGS`].
    pub fn set_step_halvings(&mut self, halvings: u32) -> Result<(), ModelError> {
        if halvings > MAX_STEP_HALVINGS {
            return Err(ModelError::invalid(
                "step_halvings",
                format!("{halvings} is above the {MAX_STEP_HALVINGS} a step may take"),
            ));
        }
        self.step_halvings = halvings;
        Ok(())
    }

    /// The halvings a failed step may take.
    pub fn step_halvings(&self) -> u32 {
        self.step_halvings
    }

    /// [`Self::step`] without its failures' check (the run's watched
    /// step checks the energy first, `run.rs`).
    pub(super) fn step_before_failures(&mut self) -> Result<StepReport, SolverError> {
        self.step_halving(self.step_halvings)
    }

    /// One step of the current length, in halves where Newton fails, up
    /// to `halvings` levels. The step length is the same after as before.
    /// The report counts the Newton iterations of the parts that
    /// converged and carries the last part's residual; the error is the
    /// deepest failed part's (its time, step and residual). The step's
    /// mean end forces and pin forces (what a coupling interval's impulse
    /// and the result files take) are the means of its halves'.
    pub(super) fn step_halving(&mut self, halvings: u32) -> Result<StepReport, SolverError> {
        match self.step_once() {
            Err(e) if halvings > 0 && e.newton_failed() => {}
            done => return done,
        }
        let dt = self.time_step();
        self.set_time_step(0.5 * dt);
        let first = self.step_halving(halvings - 1);
        let first_means = self.mean_forces();
        let halves = first.and_then(|a| self.step_halving(halvings - 1).map(|b| (a, b)));
        self.set_time_step(dt);
        let (a, b) = halves?;
        self.average_mean_forces(&first_means);
        let mut report = b;
        report.newton.iterations += a.newton.iterations;
        report.newton.factorizations += a.newton.factorizations;
        Ok(report)
    }

    /// The last step's mean end forces of every line and pin forces of
    /// every pinned body.
    pub(super) fn mean_forces(&self) -> MeanForces {
        let pins = self.bodies.iter().map(|b| b.pin.map(|p| p.force)).collect();
        (self.end_forces.clone(), pins)
    }

    /// The mean forces of a step taken in two equal halves: the first
    /// half's `first` and the second's (the current ones) averaged.
    pub(super) fn average_mean_forces(&mut self, first: &MeanForces) {
        let half = |a: [f64; 3], b: [f64; 3]| std::array::from_fn(|c| 0.5 * (a[c] + b[c]));
        for (now, before) in self.end_forces.iter_mut().zip(&first.0) {
            for k in 0..2 {
                now[k].force = half(before[k].force, now[k].force);
            }
        }
        for (body, before) in self.bodies.iter_mut().zip(&first.1) {
            if let (Some(pin), Some(f)) = (body.pin.as_mut(), before) {
                pin.force = half(*f, pin.force);
            }
        }
    }
}

/// A step's mean end forces of every line and pin forces of every body
/// (None: not pinned).
pub(super) type MeanForces = (Vec<[EndForce; 2]>, Vec<Option<[f64; 3]>>);
