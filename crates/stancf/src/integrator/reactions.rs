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
        for k in 0..self.reactions.len() {
            let node = self.reactions[k].0;
            for c in 0..3 {
                let g = coordinate(dpn, node, SLOT_R, c);
                let mut impulse = 0.0;
                for (s, &(_, kind)) in self.layout.row_slots.iter().enumerate() {
                    if kind == Kind::Position {
                        impulse += self.reaction_row(s, g);
                    }
                }
                if self.settings.time_scheme.carries_momentum() {
                    // Galerkin: the end part, p_b - dA/de_b with p_b = M v_b.
                    impulse += self.mass_v[g] - self.scratch.end_momentum[g];
                }
                let force = impulse / dt;
                self.reactions[k].1[c] = force;
                let moved = self.scratch.node_e[last * n + g] - self.state.e[g];
                self.constraint_work += force * moved;
            }
        }
    }

    /// The constraint's generalized impulse on row slot `s` of coordinate
    /// `g`: its multiplier, or the eliminated row's value with its sign
    /// turned (§6.3-6.4). On the row of the variation of e along the time
    /// function T_j it is int R T_j dt (§6.5).
    fn reaction_row(&self, s: usize, g: usize) -> f64 {
        match self.layout.multiplier_at(s, g) {
            Some(m) => self.x[m],
            None => -self.scratch.reaction_rows[s * self.model.dofs() + g],
        }
    }

    /// The Galerkin step's four moments of the reaction on node `node`'s
    /// r over the step, int R T_j dt for the time functions T1..T4 of
    /// eq. (6) (T2, T4 the slopes' times dt): the multipliers of the rows
    /// of e_a, w_a and w_b, and the end part M v_b - dA/de_b for T3
    /// (docs/method.md §5.1, §6.5, (M23b)). After a converged step, until
    /// the next one starts; None for P2 (its rows give T1 and T3 only) or
    /// a node with no reaction.
    pub(crate) fn reaction_moments(&self, node: usize) -> Option<[[f64; 3]; 4]> {
        if !self.settings.time_scheme.carries_momentum()
            || !self.reactions.iter().any(|(k, _)| *k == node)
        {
            return None;
        }
        let dpn = self.layout.dpn;
        let mut moments = [[0.0; 3]; 4];
        for c in 0..3 {
            let g = coordinate(dpn, node, SLOT_R, c);
            for (s, &(i, kind)) in self.layout.row_slots.iter().enumerate() {
                let j = time_function(i, kind);
                moments[j][c] += self.reaction_row(s, g);
            }
            moments[2][c] += self.mass_v[g] - self.scratch.end_momentum[g];
        }
        Some(moments)
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

/// The index j of the time function T_(j+1) of eq. (6) whose variation a
/// one-layer step's row slot (time node i, kind) is: T1, T2 at the start
/// (value, slope), T3, T4 at the end.
pub(crate) fn time_function(i: usize, kind: Kind) -> usize {
    2 * i + usize::from(kind == Kind::Velocity)
}
