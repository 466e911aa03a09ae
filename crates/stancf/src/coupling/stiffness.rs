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

/// Each free and coupled body's (B16) at the converged equilibrium of
/// `statics`, a coupled body's about its reference point where the
/// host's `x` holds it: (body index, 6 x 6), None where the rest of the
/// system is singular with the body held.
pub(super) fn body_stiffness(
    statics: &mut SystemStatics,
    layout: &super::bodies::ArrayLayout,
    x: &[f64],
) -> Vec<(usize, Option<[[f64; 6]; 6]>)> {
    let free: Vec<usize> = statics.system().free_bodies().collect();
    let mut out: Vec<(usize, Option<[[f64; 6]; 6]>)> = free
        .into_iter()
        .map(|b| (b, statics.body_stiffness(b)))
        .collect();
    // A body pinned to the host is a free body (above), not a coupled one.
    for (k, body) in layout
        .bodies
        .iter()
        .enumerate()
        .filter(|(_, b)| b.pin.is_none())
    {
        let reference = layout.reference(x, k);
        out.push((
            body.body,
            statics.coupled_body_stiffness(body.body, reference),
        ));
    }
    out
}

/// Each coupled point's (not on a body) 3 x 3 mooring stiffness at the
/// equilibrium of `statics`: (point index, 3 x 3), the points those of
/// `layout.plain` (`coupled[place]`).
pub(super) fn point_stiffness(
    statics: &SystemStatics,
    layout: &super::bodies::ArrayLayout,
    coupled: &[usize],
) -> Vec<(usize, Option<[[f64; 3]; 3]>)> {
    layout
        .plain
        .iter()
        .map(|&place| {
            let p = coupled[place];
            (p, statics.coupled_point_stiffness(p))
        })
        .collect()
}

impl CoupledSystem {
    /// The mooring stiffness (B16) of free or coupled body `b` at the
    /// static equilibrium of the last [`Self::initialize`]: rows F_x,
    /// F_y, F_z, M_x, M_y, M_z of the lines' force and moment about the
    /// body's reference point (global axes), columns the reference
    /// point's displacement and a small rotation about global axes
    /// through it ([`SystemStatics::body_stiffness`],
    /// [`SystemStatics::coupled_body_stiffness`]). None before
    /// initialization, for a fixed body, or where the rest of the system
    /// is singular with the body held.
    pub fn body_stiffness(&self, b: usize) -> Option<[[f64; 6]; 6]> {
        let running = self.running.as_ref()?;
        running
            .stiffness
            .iter()
            .find(|(k, _)| *k == b)
            .and_then(|(_, k)| *k)
    }

    /// The mooring stiffness of coupled point `p` (the system's point
    /// index; a coupled point not on a body) at the static equilibrium of
    /// the last [`Self::initialize`]: -d f / d x of the lines' force on it
    /// (N/m, global axes), the rest in equilibrium
    /// ([`SystemStatics::coupled_point_stiffness`]). None before
    /// initialization, for another point, or where the rest is singular.
    pub fn point_stiffness(&self, p: usize) -> Option<[[f64; 3]; 3]> {
        let running = self.running.as_ref()?;
        running
            .point_stiffness
            .iter()
            .find(|(q, _)| *q == p)
            .and_then(|(_, k)| *k)
    }
}
