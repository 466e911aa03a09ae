//! Consistent nodal forces of a force per length along a line, sum_e
//! int N_k f dx on each node's position (docs/method.md (M14)): the
//! seabed's (§12.2, its push integrated as the slab integrates it,
//! (W47a)) and, through [`nodal_forces_per_length`], the water's.

use crate::model::{coordinate, gather, Model, State, SLOT_R};
use crate::water::seabed::Part;

/// The seabed's consistent nodal forces (N) on the nodes' positions,
/// `sum_e int N_k f dx` of the contact force per length f(r, r_x, r_dot)
/// (docs/method.md §12.2), friction included: what the bed exerts on the
/// line around each node. Zero without a seabed. Friction is the sliding
/// friction of the state's velocities (W43)-(W44); for a static
/// equilibrium, whose friction resists the slide from its targets (W48),
/// see [`static_seabed_nodal_forces`].
pub fn seabed_nodal_forces(model: &Model, state: &State) -> Vec<[f64; 3]> {
    let Some(contact) = &model.seabed else {
        return vec![[0.0; 3]; model.nodes()];
    };
    nodal_forces_per_length(
        model,
        (&state.e, &state.v),
        Some(contact),
        |_, part, r, rx, rdot| contact.part_at(part, r, rx, rdot, true),
    )
}

/// The seabed's consistent nodal forces (N) on a line at rest whose
/// friction resists the slide from the coordinates `targets` (W48): the
/// normal push and the static friction, as the static solve balances
/// them (`crate::system::SystemStatics::seabed_nodal_forces`).
pub fn static_seabed_nodal_forces(model: &Model, state: &State, targets: &[f64]) -> Vec<[f64; 3]> {
    let Some(contact) = &model.seabed else {
        return vec![[0.0; 3]; model.nodes()];
    };
    // The slide r - r_0 is linear in the coordinates: interpolated from
    // e - e_0 as a velocity is from v.
    let slide: Vec<f64> = state.e.iter().zip(targets).map(|(e, e0)| e - e0).collect();
    nodal_forces_per_length(
        model,
        (&state.e, &slide),
        Some(contact),
        |_, part, r, rx, slide| contact.static_part(part, r, rx, slide),
    )
}

/// `sum_e int N_k f dx` on the nodes' positions of a force per length
/// `force((k, xi), part, r, r_x, rdot)` (at xi, 0 to 1, along element k),
/// r and r_x from the coordinates `e` and rdot interpolated from `rates`
/// as a velocity; with `bed`, the seabed's contact force in its parts,
/// integrated as the slab integrates it (W47a), else at the axial rule.
pub(crate) fn nodal_forces_per_length(
    model: &Model,
    (e, rates): (&[f64], &[f64]),
    bed: Option<&crate::water::SeabedContact>,
    force: impl Fn((usize, f64), Part, &[f64; 3], &[f64; 3], &[f64; 3]) -> crate::water::ForceAtPoint
        + Copy,
) -> Vec<[f64; 3]> {
    let mut out = vec![[0.0; 3]; model.nodes()];
    let dpn = model.dofs_per_node();
    crate::with_elements!(&model.mesh, els => {
        for (k, el) in els.iter().enumerate() {
            let o = coordinate(dpn, k, SLOT_R, 0);
            let (q, qdot) = (gather(e, o), gather(rates, o));
            let fq = el.generalized_force_on_bed(bed, (&q, &qdot), |xi, part, r, rx, rdot| {
                force((k, xi), part, r, rx, rdot)
            });
            add_to_end_nodes(&mut out, k, &fq);
        }
    });
    out
}

/// Adds element k's generalized force `fq` on its two end nodes'
/// positions to their nodal forces `out`: each node holds half of the
/// element's coordinates, r first.
pub(crate) fn add_to_end_nodes(out: &mut [[f64; 3]], k: usize, fq: &[f64]) {
    for (end, node) in [(0, k), (1, k + 1)] {
        let a = end * fq.len() / 2;
        for i in 0..3 {
            out[node][i] += fq[a + i];
        }
    }
}
