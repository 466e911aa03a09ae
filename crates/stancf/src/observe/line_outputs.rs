//! The water's velocity, the hydrodynamic and VIV forces, the strain rate
//! and the internal damping force along a line: what MoorDyn's
//! `LineOutputs` flags `U`, `D`, `V`, `d` and `c` ask for (its
//! `Line::Output`), for its per-line output files.

use super::{add_to_end_nodes, nodal_forces_per_length};
use crate::model::{coordinate, gather, Model, State, SLOT_R};
use crate::shape::{cubic_hermite, quintic_hermite};

/// The sea's velocity u(r, t) (its current and waves, and a host's flow
/// where it sets the waves, (W2g), as the line's water load takes it,
/// (W19)) at each node at time `t`, or at rest (`t` None:
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
            match (t, &water.host) {
                // (W2g) at node k.
                (Some(t), Some(host)) => {
                    let u = water.water.sea.kinematics(&r, t).velocity;
                    std::array::from_fn(|i| u[i] + host.velocity[k][i])
                }
                (Some(t), None) => water.water.sea.kinematics(&r, t).velocity,
                (None, _) => water.water.sea.steady_current(&r).velocity,
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
    let states = (&state.e[..], &state.v[..]);
    nodal_forces_per_length(model, states, None, |(k, xi), _, r, rx, rdot| match t {
        Some(t) => {
            let host = water.host.as_ref().map(|h| h.element(k).at(xi));
            water.force_at(r, rx, rdot, t, &[0.0; 3], true, host)
        }
        None => water.static_force(r, rx, &[0.0; 3]),
    })
}

/// r_x and its rate r_x_dot at the middle of element k.
fn middle_tangent(model: &Model, state: &State, k: usize) -> ([f64; 3], [f64; 3]) {
    let l = model.element_length(k);
    let o = coordinate(model.dofs_per_node(), k, SLOT_R, 0);
    let (q, qdot) = (&state.e[o..], &state.v[o..]);
    match model.element_type() {
        crate::model::ElementType::Sac2 => {
            let shape = cubic_hermite(0.5, l);
            (shape.gradients(q).0, shape.gradients(qdot).0)
        }
        crate::model::ElementType::Sac3 => {
            let shape = quintic_hermite(0.5, l);
            (shape.gradients(q).0, shape.gradients(qdot).0)
        }
    }
}

/// The engineering strain rate d|r_x|/dt = r_x . r_x_dot / |r_x| at each
/// element's middle: MoorDyn's `d`, its segments' stretch rate over their
/// unstretched length (the strain of `s` is the element's middle too).
pub fn element_strain_rates(model: &Model, state: &State) -> Vec<f64> {
    (0..model.cable.elements)
        .map(|k| {
            let (rx, rx_dot) = middle_tangent(model, state, k);
            crate::vec3::dot(rx, rx_dot) / crate::vec3::norm(rx)
        })
        .collect()
}

/// The axial damping force BA eps_dot t (N, docs/method.md §2.10) at
/// each element's middle, eps_dot the rate of the model's strain
/// (a . r_x_dot, a = r_x for Green's, r_x / |r_x| for the engineering
/// one) and t the unit tangent: MoorDyn's `c`, its segments' internal
/// damping force. None for a viscoelastic line, whose damping is its
/// law's (docs/method.md §2.11).
pub fn element_damping_forces(model: &Model, state: &State) -> Option<Vec<[f64; 3]>> {
    if model.viscoelastic().is_some() {
        return None;
    }
    let ba = model.material.axial_damping;
    let forces = (0..model.cable.elements)
        .map(|k| {
            let (rx, rx_dot) = middle_tangent(model, state, k);
            let t = crate::vec3::normalized(rx);
            let rate = match model.options.measures.axial_strain {
                crate::AxialStrain::Green => crate::vec3::dot(rx, rx_dot),
                crate::AxialStrain::Engineering => crate::vec3::dot(t, rx_dot),
            };
            t.map(|c| ba * rate * c)
        })
        .collect();
    Some(forces)
}

/// The consistent nodal forces (N) of the VIV lift (V23) at time `t`,
/// each axial point's lift with its phase in the state's internal values
/// (docs/method.md §12.7): MoorDyn's `V`, its nodes' cross-flow lift.
/// Zero on a line without VIV, in air, or without its internal state (a
/// static equilibrium, which has no lift).
pub fn viv_nodal_forces(model: &Model, state: &State, t: f64) -> Vec<[f64; 3]> {
    let mut out = vec![[0.0; 3]; model.nodes()];
    let Some(water) = &model.water else {
        return out;
    };
    if state.internal.is_empty() {
        return out;
    }
    let dpn = model.dofs_per_node();
    crate::with_elements!(&model.mesh, els => {
        for (k, el) in els.iter().enumerate() {
            let o = coordinate(dpn, k, SLOT_R, 0);
            let (q, qdot) = (gather(&state.e, o), gather(&state.v, o));
            let internal = model.element_internal(&state.internal, k);
            let (_, viv_state) = el.split_internal(internal);
            let fq = el.viv_generalized_force((&q, &qdot), viv_state, t, water);
            add_to_end_nodes(&mut out, k, &fq);
        }
    });
    out
}
