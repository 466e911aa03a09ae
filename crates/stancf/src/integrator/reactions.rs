//! The forces of the position constraints on the cable and their work
//! (docs/method.md §6.5-6.6, (M23)-(M24)).

use super::Simulation;
use crate::assembly::Kind;
use crate::constraints::DirectionHold;
use crate::model::{coordinate, SLOT_R, SLOT_R_X};

impl Simulation {
    /// Reaction impulses of the step from the multipliers (or eliminated
    /// rows) of the position rows e_0, e_i, e_L, and the work of moving
    /// constraints (docs/method.md §6.5-6.6, (M23)-(M24)).
    pub(super) fn collect_reactions(&mut self, dt: f64) {
        let n = self.model.dofs();
        let dpn = self.layout.dpn;
        let last = self.layout.layers();
        for (node, force) in self.reactions.iter_mut() {
            for c in 0..3 {
                let g = coordinate(dpn, *node, SLOT_R, c);
                let mut impulse = 0.0;
                for (s, &(_, kind)) in self.layout.row_slots.iter().enumerate() {
                    if kind != Kind::Position {
                        continue;
                    }
                    impulse += match self.layout.multiplier_at(s, g) {
                        Some(m) => self.x[m],
                        None => -self.scratch.reaction_rows[s * n + g],
                    };
                }
                if self.settings.time_scheme.carries_momentum() {
                    // Galerkin: the end part, p_b - dA/de_b with p_b = M v_b.
                    impulse += self.mass_v[g] - self.scratch.end_momentum[g];
                }
                force[c] = impulse / dt;
                let moved = self.scratch.node_e[last * n + g] - self.state.e[g];
                self.constraint_work += force[c] * moved;
            }
        }
    }

    /// The moment each direction hold (a line end clamped in a direction,
    /// docs/method.md §6.10) exerted on the cable, averaged over the last
    /// step: (node, moment). The generalized impulse on r_x is the sum of
    /// the hold's multipliers of the position rows times their normals,
    /// Q dt = sum lambda_k n_k (with the Galerkin step, plus the impulse
    /// at t_b, M v_b - dA/de_b, (M43)), and the moment M = r_x x Q at the
    /// step's end (M42). Zero before the first step; not restored by an undo.
    pub fn clamp_moments(&self) -> Vec<(usize, [f64; 3])> {
        let dt = self.settings.time_step;
        let dpn = self.layout.dpn;
        let holds = &self.model.constraints.directions;
        holds
            .iter()
            .enumerate()
            .map(|(h, hold)| {
                let mut q = [0.0; 3];
                for (s, &(_, kind)) in self.layout.row_slots.iter().enumerate() {
                    if kind != Kind::Position {
                        continue;
                    }
                    for (k, n) in hold.normals.iter().enumerate() {
                        if let Some(m) = self.layout.hold_multiplier(h, s, k) {
                            for c in 0..3 {
                                q[c] += self.x[m] * n[c] / dt;
                            }
                        }
                    }
                }
                let o = coordinate(dpn, hold.node, SLOT_R_X, 0);
                if self.settings.time_scheme.carries_momentum() {
                    // Galerkin: the hold's impulse at t_b, M v_b - dA/de_b
                    // on r_x (M43).
                    for c in 0..3 {
                        q[c] += (self.mass_v[o + c] - self.scratch.end_momentum[o + c]) / dt;
                    }
                }
                let r_x = [self.state.e[o], self.state.e[o + 1], self.state.e[o + 2]];
                (hold.node, DirectionHold::moment(r_x, q))
            })
            .collect()
    }
}
