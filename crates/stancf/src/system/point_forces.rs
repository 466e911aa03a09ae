//! The forces of the line ends on their points, as a system's
//! simulation gives them: the last step's means (docs/method.md (M23)),
//! their values at its end ((M23b), or (M23a) for P2), and their sums at
//! each point with the pull of the bodies pinned there.

use super::simulation::SystemSimulation;
use super::EndForce;
use crate::error::ModelError;

impl SystemSimulation {
    /// The force each end of line i exerts on its point (zero at a loose
    /// end), averaged over the last step.
    pub fn end_forces(&self, line: usize) -> [EndForce; 2] {
        self.end_forces[line]
    }

    /// Sets the lines' end forces read before the first step (both the
    /// step mean and the force at the time) to `forces`, one pair per
    /// line: a static equilibrium's, where the run starts from it. Refused
    /// after a step or with a count that is not the lines'.
    pub fn set_start_forces(&mut self, forces: &[[EndForce; 2]]) -> Result<(), ModelError> {
        if self.steps > 0 || forces.len() != self.end_forces.len() {
            return Err(ModelError::invalid(
                "start_forces",
                format!(
                    "{} pairs given for {} lines, after {} steps: only before the first step, \
                     one pair per line",
                    forces.len(),
                    self.end_forces.len(),
                    self.steps
                ),
            ));
        }
        self.end_forces.copy_from_slice(forces);
        self.forces_at_time.start(forces);
        Ok(())
    }

    /// The net force the attached lines (and the bodies pinned there)
    /// exert on point p, averaged over the last step.
    pub fn point_force(&self, p: usize) -> [f64; 3] {
        self.sum_at_point(p, |li| self.end_forces[li])
    }

    /// The force each end of line i exerts on its point at the end of the
    /// last step: with the Galerkin step, from the step's own moments
    /// (M23b); with P2, the second-order estimate (M23a) from the last two
    /// steps' means (the mean itself after the first step).
    pub fn end_forces_at_time(&self, line: usize) -> [EndForce; 2] {
        self.forces_at_time.line(line)
    }

    /// The net force the attached lines exert on point p at the end of the
    /// last step ((M23b) or (M23a), as [`Self::end_forces_at_time`]).
    pub fn point_force_at_time(&self, p: usize) -> [f64; 3] {
        self.sum_at_point(p, |li| self.forces_at_time.line(li))
    }

    /// The sum over the lines attached to point p of their ends' forces,
    /// and the pull of the bodies pinned there (minus their pins' forces
    /// on them, the last step's mean, (B35)).
    fn sum_at_point(&self, p: usize, ends: impl Fn(usize) -> [EndForce; 2]) -> [f64; 3] {
        let mut f = [0.0; 3];
        for (li, end) in self.topology.attachments(p) {
            let force = ends(li)[end].force;
            for c in 0..3 {
                f[c] += force[c];
            }
        }
        for body in &self.bodies {
            let Some(pin) = body.pin else { continue };
            if self.topology.bodies()[body.index]
                .pin
                .is_some_and(|held| held.point == p)
            {
                for c in 0..3 {
                    f[c] -= pin.force[c];
                }
            }
        }
        f
    }
}
