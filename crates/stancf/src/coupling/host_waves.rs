//! A host that sets the water's kinematics (MoorDyn's `WaveKin 1`,
//! `MoorDyn_ExternalWaveKinInit`, `..GetCoordinates`, `..Set`;
//! docs/method.md §12.1, (W2f)-(W2h)): where it is asked, and the
//! values it gives, held over the intervals until it gives them again.

use super::{CoupledSystem, CouplingError};
use crate::error::ModelError;

impl CoupledSystem {
    /// Whether a host sets the sea's waves (a deck's `WaveKin 1`).
    pub fn takes_host_waves(&self) -> bool {
        let models = self.system.lines().iter().map(|l| &l.model);
        crate::system::takes_host_waves(models, &self.system)
    }

    /// How many points [`Self::host_flow_points`] names (None before
    /// [`Self::initialize`]; 0 if no host sets the waves).
    pub fn host_flow_count(&self) -> Option<usize> {
        self.simulation().map(|s| s.host_flow_count())
    }

    /// Where the host is asked for the water's velocity and acceleration
    /// now, in MoorDyn's order: every line's nodes, every rod's nodes,
    /// every point, then MoorDyn's ground body at the origin and every
    /// body ([`crate::system::SystemSimulation::host_flow_points_with`]),
    /// a coupled body where the host's last call put it. None before
    /// [`Self::initialize`]; empty if no host sets the waves.
    pub fn host_flow_points(&self) -> Option<Vec<[f64; 3]>> {
        let running = self.running.as_ref()?;
        let pose = |b: usize| {
            let k = self.layout.bodies.iter().position(|c| c.body == b)?;
            running.held[k].map(|end| (end.position, end.rotation))
        };
        Some(running.sim.host_flow_points_with(pose))
    }

    /// Sets the water's velocity and local acceleration at the points of
    /// [`Self::host_flow_points`], one each in its order, for the steps
    /// from now until they are set again. Refused: before
    /// [`Self::initialize`], a sea whose waves are not a host's, a count
    /// other than the points', a value that is not finite.
    pub fn set_host_flow(
        &mut self,
        velocity: &[[f64; 3]],
        acceleration: &[[f64; 3]],
    ) -> Result<(), CouplingError> {
        let Some(running) = self.running.as_mut() else {
            return Err(ModelError::invalid(
                "water",
                "the host's water kinematics are set after initialize, at the points it \
                 names then",
            )
            .into());
        };
        running.sim.set_host_flow(velocity, acceleration)?;
        Ok(())
    }
}
