//! The P2 output row's momentum with the entrained water (docs/method.md
//! §12.5, (W30)): p_L = M v_L + dT_a/dv(e_L, v_L) depends on e_L as well
//! as on v_L, so the row e_L gets -dp_L/de_L besides -dp_L/dv_L.

use super::system::{AssemblyScratch, StepProblem};
use super::Kind;
use crate::linear::AddEntries;

impl StepProblem<'_> {
    /// Adds -dT_a,v/de_L and -dT_a,v/dv_L (the X and V of (W28) at the
    /// output node) to the rows of row slot `rs` (P2's e_L rows); nothing
    /// without added mass (the constant -M is added by the caller).
    pub(super) fn entrained_end_momentum<J: AddEntries>(
        &self,
        rs: usize,
        jac: &mut J,
        scratch: &AssemblyScratch,
    ) {
        let layout = self.layout;
        let n = self.model.dofs();
        let last = layout.layers();
        let e_slot = layout.unknown_slot(last, Kind::Position);
        let v_slot = layout.unknown_slot(last, Kind::Velocity);
        let e = &scratch.node_e[last * n..(last + 1) * n];
        let v = &scratch.node_v[last * n..(last + 1) * n];
        self.model
            .for_entrained_momentum_derivatives(e, v, |a, b, d_e, d_v| {
                let Some(r) = layout.row_at(rs, a) else {
                    return;
                };
                for (slot, d) in [(e_slot, d_e), (v_slot, d_v)] {
                    if let Some(c) = slot.and_then(|s| layout.unknown_at(s, b)) {
                        if d != 0.0 {
                            jac.add(r, c, -d);
                        }
                    }
                }
            });
    }
}
