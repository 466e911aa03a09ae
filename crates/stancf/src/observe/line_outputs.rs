//! The water's velocity, the hydrodynamic force and the strain rate
//! along a line: what MoorDyn's `LineOutputs` flags `U`, `D` and `d` ask
//! for (its `Line::Output`), for its per-line output files.

use super::nodal_forces_per_length;
use crate::model::{coordinate, Model, State, SLOT_R};
use crate::shape::{cubic_hermite, quintic_hermite};

/// The sea's velocity u(r, t) (its current and waves, as the line's water
/// load takes it, (W19)) at each node at time `t`, or at rest (`t` None:
/// the steady current, as a static solve takes it, §12.4): MoorDyn's `U`.
/// Zero on a line in air.
pub fn node_water_velocities(model: &Model, state: &State, t: Option<f64>) -> Vec<[f64; 3]> {
    let Some(water) = &model.water else {
        return vec![[0.0; 3]; model.nodes()];
    };
    (0..model.nodes())
        .map(|k| {
            let o = coordinate(model.dofs_per_node(), k, SLOT_R, 0);
            let r = [state.e[o], state.e[o + 1], state.e[o + 2]];
            match t {
                Some(t) => water.water.sea.kinematics(&r, t).velocity,
                None => water.water.sea.steady_current(&r).velocity,
            }
        })
        .collect()
}

/// The consistent nodal forces (N) of the water's drag and fluid inertia
/// on the line at time `t`, or at rest in the steady current (`t` None,
/// §12.4), (W19)-(W20) integrated against the shape functions as the step
/// integrates them (the buoyancy (W18) left out, with gravity zero):
/// MoorDyn's `D`, its nodes' drag and fluid acceleration forces. Zero on
/// a line in air.
pub fn hydrodynamic_nodal_forces(model: &Model, state: &State, t: Option<f64>) -> Vec<[f64; 3]> {
    let Some(water) = &model.water else {
        return vec![[0.0; 3]; model.nodes()];
    };
    nodal_forces_per_length(model, &state.e, &state.v, |r, rx, rdot| match t {
        Some(t) => water.force(r, rx, rdot, t, &[0.0; 3]),
        None => water.static_force(r, rx, &[0.0; 3]),
    })
}

/// The engineering strain rate d|r_x|/dt = r_x . r_x_dot / |r_x| at each
/// element's middle: MoorDyn's `d`, its segments' stretch rate over their
/// unstretched length (the strain of `s` is the element's middle too).
pub fn element_strain_rates(model: &Model, state: &State) -> Vec<f64> {
    let dpn = model.dofs_per_node();
    (0..model.cable.elements)
        .map(|k| {
            let l = model.element_length(k);
            let o = coordinate(dpn, k, SLOT_R, 0);
            let (q, qdot) = (&state.e[o..], &state.v[o..]);
            let (rx, rx_dot) = match model.element_type() {
                crate::model::ElementType::Sac2 => {
                    let shape = cubic_hermite(0.5, l);
                    (shape.gradients(q).0, shape.gradients(qdot).0)
                }
                crate::model::ElementType::Sac3 => {
                    let shape = quintic_hermite(0.5, l);
                    (shape.gradients(q).0, shape.gradients(qdot).0)
                }
            };
            crate::vec3::dot(rx, rx_dot) / crate::vec3::norm(rx)
        })
        .collect()
}
