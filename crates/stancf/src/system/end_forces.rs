//! The forces of the line ends on their points: the step means of (M23)
//! (docs/method.md §6.5, §11.4), and their value at the end of a step:
//! from the Galerkin step's own four moments of the force (M23b,
//! [`force_at_end`]), or for P2 the second-order estimate (M23a) below.
//!
//! A step's reaction is an impulse, so what it gives is the *mean* end
//! force over the step, R_k = (1/dt_k) int R dt, which is the force at the
//! step's middle to O(dt^2) but the force at its end t_k only to O(dt):
//! R(t_k) = R_k + (dt_k / 2) R'(t_k) + O(dt^2). The line through the last
//! two means, placed at their mid-times t_k - dt_k / 2 and
//! t_(k-1) - dt_(k-1) / 2 (half a step length plus half the one before
//! apart), gives R at t_k to O(dt^2):
//!
//! ```text
//!   R(t_k) = R_k + w (R_k - R_(k-1)),   w = dt_k / (dt_k + dt_(k-1))   (M23a)
//! ```
//!
//! (w = 1/2 at a constant step; halved steps and changed step lengths
//! take their own w). The first step after a start has no step before it
//! and gives its mean. The estimate uses only steps already taken, so a
//! result at t_k is final when step k is.

use crate::assembly::{Kind, SlabLayout};

/// The force a line end exerts on the point it is attached to (N): the
/// mean over the last step, or its estimate at the step's end (M23a); its
/// magnitude is the effective tension there.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct EndForce {
    pub force: [f64; 3],
}

impl EndForce {
    pub fn tension(&self) -> f64 {
        self.force.iter().map(|f| f * f).sum::<f64>().sqrt()
    }
}

/// Sum over the position rows of a step of the rows of r at `node`.
pub(super) fn position_row_sum(layout: &SlabLayout, node: usize, rows: &[f64]) -> [f64; 3] {
    let mut out = [0.0; 3];
    for (s, &(_, kind)) in layout.row_slots.iter().enumerate() {
        if kind != Kind::Position {
            continue;
        }
        for c in 0..3 {
            if let Some(r) = layout.row_of_node(s, node, c) {
                out[c] += rows[r];
            }
        }
    }
    out
}

/// The force over a Galerkin step from its four moments over the step,
/// `m_j = int R T_j dt` (T1..T4 the time functions of eq. (6), T2 and T4
/// the slopes' times dt): the cubic with these moments, the force's L2
/// projection on the step's cubics. With the Gram matrix of the four
/// functions, `dt D g D` (D = diag(1, dt, 1, dt), g the unit step's,
/// [156, 22, 54, -13; 22, 4, 13, -3; 54, 13, 156, -22; -13, -3, -22, 4] / 420)
/// inverted in closed form, the cubic is `R(t_a + s dt) = sum_j b_j H_j(s)`
/// in the unit Hermite basis (values at s = 0 and 1, slopes per unit s),
///
/// ```text
///   b = g^-1 (m1, m2 / dt, m3, m4 / dt) / dt,
///   g^-1 = [16, -120, -4, -60; -120, 1200, 60, 840; -4, 60, 16, 120; -60, 840, 120, 1200]
/// ```
///
/// exact for a force cubic in time (docs/method.md §6.5, (M23b)).
pub(crate) fn force_cubic(moments: &[[f64; 3]; 4], dt: f64) -> [[f64; 3]; 4] {
    const G_INV: [[f64; 4]; 4] = [
        [16.0, -120.0, -4.0, -60.0],
        [-120.0, 1200.0, 60.0, 840.0],
        [-4.0, 60.0, 16.0, 120.0],
        [-60.0, 840.0, 120.0, 1200.0],
    ];
    let scaled: [[f64; 3]; 4] = std::array::from_fn(|k| {
        let w = if k % 2 == 1 { 1.0 / dt } else { 1.0 };
        moments[k].map(|m| m * w)
    });
    std::array::from_fn(|j| {
        std::array::from_fn(|c| (0..4).map(|k| G_INV[j][k] * scaled[k][c]).sum::<f64>() / dt)
    })
}

/// The force at the end of a Galerkin step from its four moments,
///
/// ```text
///   R(t_b) = (16 m3 - 4 m1) / dt + (60 m2 + 120 m4) / dt^2           (M23b)
/// ```
///
/// ([`force_cubic`] at s = 1), O(dt^4) for a smooth force, from the step
/// alone. Its mean, (m1 + m3) / dt, is (M23).
pub(crate) fn force_at_end(moments: &[[f64; 3]; 4], dt: f64) -> [f64; 3] {
    force_cubic(moments, dt)[2]
}

/// The moments over a one-layer step of the rows of r at `node`: row slot
/// (time node i, kind) is the variation along T_j, j = 2 i (+1 for a
/// slope); [`force_at_end`] takes them. A Galerkin step has no row of
/// e_b: its moment is the caller's to add.
pub(super) fn row_moments(layout: &SlabLayout, node: usize, rows: &[f64]) -> [[f64; 3]; 4] {
    let mut out = [[0.0; 3]; 4];
    for (s, &(i, kind)) in layout.row_slots.iter().enumerate() {
        let j = crate::integrator::time_function(i, kind);
        for c in 0..3 {
            if let Some(r) = layout.row_of_node(s, node, c) {
                out[j][c] += rows[r];
            }
        }
    }
    out
}

/// The previous step's mean end forces and the estimate at the end of the
/// last step.
#[derive(Clone, Debug)]
pub(super) struct ForcesAtTime {
    previous_mean: Vec<[EndForce; 2]>,
    /// The previous step's length (0: no step before the last one).
    previous_dt: f64,
    at_time: Vec<[EndForce; 2]>,
    /// Ends whose force history starts again at the next step (a line
    /// end released, docs/method.md §11.16): (M23a) has no step before.
    fresh: Vec<[bool; 2]>,
}

impl ForcesAtTime {
    pub(super) fn new(lines: usize) -> Self {
        ForcesAtTime {
            previous_mean: vec![[EndForce::default(); 2]; lines],
            previous_dt: 0.0,
            at_time: vec![[EndForce::default(); 2]; lines],
            fresh: vec![[false; 2]; lines],
        }
    }

    /// Starts the history of line `line`'s end `end` again: its next
    /// estimate is the next step's mean (the end was released, its force
    /// before is not the same function of time).
    pub(super) fn restart(&mut self, line: usize, end: usize) {
        self.fresh[line][end] = true;
    }

    /// The forces at t = 0, before any step (a static equilibrium's): read
    /// until the first step, which does not use them (its estimate is its
    /// means themselves).
    pub(super) fn start(&mut self, forces: &[[EndForce; 2]]) {
        self.at_time.copy_from_slice(forces);
    }

    /// Takes the means of a step of length `dt` just converged: (M23a)
    /// with the step before it, or the means themselves after a start.
    pub(super) fn update(&mut self, mean: &[[EndForce; 2]], dt: f64) {
        let w = if self.previous_dt > 0.0 {
            dt / (dt + self.previous_dt)
        } else {
            0.0
        };
        for (((now, m), before), fresh) in self
            .at_time
            .iter_mut()
            .zip(mean)
            .zip(self.previous_mean.iter_mut())
            .zip(self.fresh.iter_mut())
        {
            for k in 0..2 {
                let w = if fresh[k] { 0.0 } else { w };
                now[k].force = std::array::from_fn(|c| {
                    m[k].force[c] + w * (m[k].force[c] - before[k].force[c])
                });
                before[k] = m[k];
                fresh[k] = false;
            }
        }
        self.previous_dt = dt;
    }

    /// Takes a Galerkin step of length `dt` just converged: its end
    /// forces at its end from its own moments (M23b); its means and
    /// length are kept as [`Self::update`] keeps them, so the history
    /// stays that of the steps taken.
    pub(super) fn set_at_end(&mut self, mean: &[[EndForce; 2]], at_end: &[[EndForce; 2]], dt: f64) {
        self.at_time.copy_from_slice(at_end);
        self.previous_mean.copy_from_slice(mean);
        for fresh in &mut self.fresh {
            *fresh = [false; 2];
        }
        self.previous_dt = dt;
    }

    /// The estimate of line `line`'s end forces at the end of the last
    /// step.
    pub(super) fn line(&self, line: usize) -> [EndForce; 2] {
        self.at_time[line]
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn one(f: f64) -> Vec<[EndForce; 2]> {
        vec![[
            EndForce {
                force: [f, 0.0, 0.0],
            },
            EndForce::default(),
        ]]
    }

    /// A force linear in time, R = 3 + 2 t, has the step means R at the
    /// steps' mid-times, and (M23a) gives R at the steps' ends exactly,
    /// at a constant step and across a change of step; the first step
    /// gives its mean.
    #[test]
    fn a_force_linear_in_time_is_found_at_the_ends_of_the_steps() {
        let force = |t: f64| 3.0 + 2.0 * t;
        let mut f = ForcesAtTime::new(1);
        let mut t = 0.0;
        for (k, dt) in [0.1, 0.1, 0.05, 0.05, 0.2].into_iter().enumerate() {
            f.update(&one(force(t + 0.5 * dt)), dt);
            t += dt;
            let got = f.line(0)[0].force[0];
            let want = if k == 0 { force(t - 0.05) } else { force(t) };
            assert!(
                (got - want).abs() <= 4.0 * f64::EPSILON * want,
                "step {k}: {got} {want}"
            );
        }
    }
}
