//! What a coupled system takes from the static equilibrium its
//! initialization finds: the simulation that starts there, and the
//! mooring stiffness of its free bodies there (docs/method.md §15.9,
//! (B16)), what a designer takes from MoorPy, here from the condensed
//! tangent, kept with the handle for the coupling code to ask.

use super::CoupledSystem;
use crate::error::ModelError;
use crate::system::{SystemSimulation, SystemStatics};
use crate::StepSettings;

/// The simulation from the equilibrium of `statics`: the free bodies
/// where it put them, the lines at rest but for those on a body that
/// starts moving ([`crate::system::System::start_lines_with_bodies`]),
/// the end forces read before the first step the equilibrium's.
pub(super) fn start_at(
    statics: &SystemStatics,
    steps: StepSettings,
    halvings: u32,
) -> Result<SystemSimulation, ModelError> {
    let at_rest = statics.system_at_equilibrium();
    let mut states = statics.line_states();
    at_rest.start_lines_with_bodies(&mut states);
    let lines = at_rest.lines().len();
    let mut sim = SystemSimulation::new(at_rest, states, steps)?;
    sim.set_step_halvings(halvings)?;
    sim.set_start_forces(
        &(0..lines)
            .map(|l| statics.end_forces(l))
            .collect::<Vec<_>>(),
    )?;
    Ok(sim)
}

/// Each free body's (B16) at the converged equilibrium of `statics`:
/// (body index, 6 x 6), None where the rest of the system is singular
/// with the body held.
pub(super) fn free_body_stiffness(
    statics: &mut SystemStatics,
) -> Vec<(usize, Option<[[f64; 6]; 6]>)> {
    let free: Vec<usize> = statics.system().free_bodies().collect();
    free.into_iter()
        .map(|b| (b, statics.body_stiffness(b)))
        .collect()
}

impl CoupledSystem {
    /// The mooring stiffness (B16) of free body `b` at the static
    /// equilibrium of the last [`Self::initialize`]: rows F_x, F_y, F_z,
    /// M_x, M_y, M_z of the lines' force and moment about the body's
    /// reference point (global axes), columns the reference point's
    /// displacement and a small rotation about global axes through it
    /// ([`SystemStatics::body_stiffness`]). None before initialization,
    /// for a body that is not free, or where the rest of the system is
    /// singular with the body held.
    pub fn body_stiffness(&self, b: usize) -> Option<[[f64; 6]; 6]> {
        let running = self.running.as_ref()?;
        running
            .stiffness
            .iter()
            .find(|(k, _)| *k == b)
            .and_then(|(_, k)| *k)
    }
}
