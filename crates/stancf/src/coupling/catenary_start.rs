//! A coupled system that starts as MoorDyn starts without initial
//! conditions (a deck's `TmaxIC 0`; docs/method.md §13.7): at
//! [`CoupledSystem::initialize`] every line is laid in its seed shape
//! between its ends where the coupling code puts the coupled points, at
//! rest, with no static solve, and the coupling code gets the forces
//! those shapes put on their ends (MoorDyn 2.7 gives zero until its first
//! step: docs/method.md §13.7). There is no equilibrium, so no mooring
//! stiffness.

use super::{CoupledSystem, CouplingError, Start};
use crate::error::ModelError;
use crate::system::{moordyn_start_forces, moordyn_start_states, System, SystemSimulation};

impl CoupledSystem {
    /// The same handle, whose [`Self::initialize`] starts from MoorDyn's
    /// start without initial conditions instead of the static
    /// equilibrium (see the module).
    pub fn with_catenary_start(mut self) -> Self {
        self.catenary_start = true;
        self
    }

    /// Whether [`Self::initialize`] starts from MoorDyn's start without
    /// initial conditions ([`Self::with_catenary_start`]).
    pub fn starts_from_catenaries(&self) -> bool {
        self.catenary_start
    }

    /// [`Self::initialize`]'s start from the lines' seed shapes of `seed`
    /// between the coupled points placed in `system` (and `seed`): the
    /// simulation at rest there, its start forces the shapes' end
    /// forces; the forces on the coupled points (and bodies) returned.
    /// Refused: a line that carries compression and is longer than its
    /// catenary can hold (it would start pushing its ends apart).
    pub(super) fn start_from_catenaries(
        &mut self,
        system: System,
        seed: &System,
        start: Start<'_>,
    ) -> Result<Vec<f64>, CouplingError> {
        let mut states = moordyn_start_states(&system, seed).map_err(|l| {
            ModelError::invalid(
                format!("lines[{}]", l.line),
                "is longer than its catenary can hold between its ends and carries \
                 compression: it has no MoorDyn start without initial conditions (it would \
                 start pushing its ends apart)",
            )
        })?;
        let forces = moordyn_start_forces(seed);
        system.start_lines_with_bodies(&mut states);
        let mut sim = SystemSimulation::new(system.clone(), states, self.steps.clone())?;
        sim.set_step_halvings(self.step_halvings)?;
        sim.set_start_forces(&forces)?;
        sim.set_failures(self.failures.clone())?;
        let coupled = &self.coupled;
        let mut out = self.layout.forces(
            |k| sim.point_force(coupled[k]),
            |k| sim.point_state(coupled[k]).0,
            |b| self.layout.reference(start.x, b),
        );
        let held = self.held_ends(&system, start.x, start.xd, &mut out);
        self.running = Some(self.running(sim, start, held, (Vec::new(), Vec::new())));
        Ok(out)
    }
}
