//! The moments of the lines clamped to a free body on it (docs/method.md
//! §15.19): minus each clamp's moment on its line, r_x x Q (M42), Q the
//! hold's reaction on r_x: at a static equilibrium its multipliers times
//! the frame's normals; over a step, as a fixed hold's (§6.10), the
//! reaction of r_x's row (0,e) (B38) and the impulse at t_b, over dt.

use super::body_clamps::{static_moment, step_end, BodyClamp, ClampStepEnd};
use super::{SystemSimulation, SystemStatics};
use crate::constraints::DirectionHold;
use crate::model::{coordinate, SLOT_R_X};
use crate::vec3::{add, scale, sub};

impl SystemSimulation {
    /// The moment (global, N m) of the lines clamped to free body b on
    /// it, averaged over the last step; zero before the first, and for a
    /// body nothing is clamped to.
    pub fn clamp_moment(&self, b: usize) -> [f64; 3] {
        let moments = self.clamp_moments.iter().copied();
        sum_at_body(self.topology.body_clamps(), moments, b)
    }

    /// What the converged step leaves of each clamp ([`ClampStepEnd`]),
    /// at the bodies' step start (before they move to its end).
    pub(super) fn clamp_step_ends(&mut self) {
        self.clamp_ends.clear();
        for clamp in self.topology.body_clamps() {
            let body = self.bodies.iter().find(|b| b.index == clamp.body);
            let body = body.expect("a clamp's body is free");
            let xb = body.unknowns(&self.layout, &self.x);
            let dpn = self.lines[clamp.line].model().dofs_per_node();
            let rotation = body.body.rotation();
            let end = step_end(clamp, &self.layout, dpn, &rotation, &xb, &self.x);
            self.clamp_ends.push(end);
        }
    }

    /// The clamps' mean moments on their bodies over the step, once the
    /// end rates are set: Q = (the row (0,e)'s reaction + M v_b - p_b) /
    /// dt with p_b the line's end momentum and the clamp's share of (B39).
    pub(super) fn collect_clamp_moments(&mut self, dt: f64) {
        self.clamp_moments.clear();
        let clamps = self.topology.body_clamps();
        for (k, clamp) in clamps.iter().enumerate() {
            let line = &self.lines[clamp.line];
            let o = coordinate(line.model().dofs_per_node(), clamp.node, SLOT_R_X, 0);
            let e = line.end_coordinates();
            let end = &self.clamp_ends[k];
            let impulse = sub(line.hold_end_impulse(clamp.hold), end.on_line);
            let q = scale(1.0 / dt, add(end.reaction, impulse));
            let moment = DirectionHold::moment([e[o], e[o + 1], e[o + 2]], q);
            self.clamp_moments.push(scale(-1.0, moment));
        }
    }
}

impl SystemStatics {
    /// The moment (global, N m) of the lines clamped to free body b on it
    /// at the last converged increment; zero for a body nothing is
    /// clamped to.
    pub fn clamp_moment(&self, b: usize) -> [f64; 3] {
        let eq = &self.equations;
        let x = &self.newton.x;
        let mut m = [0.0; 3];
        for clamp in eq.system.body_clamps().iter().filter(|c| c.body == b) {
            let body = eq.bodies.iter().find(|s| s.index == b);
            let rotation = body.expect("a clamp's body is free").rotation;
            let dpn = eq.system.lines()[clamp.line].model.dofs_per_node();
            m = add(m, static_moment(clamp, &eq.layout, dpn, &rotation, x));
        }
        m
    }
}

/// The share of body b's dA/dtheta_b of the clamps `clamps` at the ends
/// `ends` of a step (B39).
pub(super) fn clamp_turn(clamps: &[BodyClamp], ends: &[ClampStepEnd], b: usize) -> [f64; 3] {
    sum_at_body(clamps, ends.iter().map(|end| end.on_body), b)
}

/// The sum of `values` (one per clamp of `clamps`) over the clamps at body
/// b.
fn sum_at_body(clamps: &[BodyClamp], values: impl Iterator<Item = [f64; 3]>, b: usize) -> [f64; 3] {
    clamps
        .iter()
        .zip(values)
        .filter(|(c, _)| c.body == b)
        .fold([0.0; 3], |m, (_, v)| add(m, v))
}
