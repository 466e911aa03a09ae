//! The sea's flow where a body's water acts (docs/method.md §15.15): the
//! water's velocity U, local acceleration a_f and dynamic pressure p_d at
//! a point of the body, on jets in the body's pose.
//!
//! The point x(q) moves with the pose q = (r_G, theta); the flow there is
//! U(x(q), t), whose first derivatives in q follow by the chain rule from
//! the sea's gradients (W6), (W7), (W8a):
//!
//! ```text
//!   dU/dq = G_u dx/dq,   da_f/dq = G_a dx/dq,   dp_d/dq = grad p_d . dx/dq      (B31)
//! ```
//!
//! The jets built here carry these first derivatives exactly; their
//! second derivatives leave out the flow's own (U's Hessian in x): the
//! water's loads enter the rows as virtual work, by their values and
//! first derivatives only (§15.6), never as a potential.

use super::jet::{Jet, JetVec};
use crate::water::kinematics::{FluidKinematics, Sea};

/// The flow at a point, on jets: velocity and local acceleration
/// (in the axes the caller turns them to) and p_d / rho.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Flow<const N: usize, const H: usize = N> {
    pub velocity: JetVec<N, H>,
    pub acceleration: JetVec<N, H>,
    pub pressure: Jet<N, H>,
}

/// When the flow is taken: at a time of a step (waves, the current with
/// its ramp), or the steady current at full strength alone (statics,
/// [`Sea::steady_current`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum FlowTime {
    At(f64),
    Steady,
}

/// f(x0) + grad f . (x - x0) on jets: the value at the point and the
/// first derivatives through x's (B31).
fn linear<const N: usize, const H: usize>(
    value: f64,
    gradient: &[f64; 3],
    x: &JetVec<N, H>,
) -> Jet<N, H> {
    let mut out = Jet::constant(value);
    for j in 0..3 {
        if gradient[j] != 0.0 {
            out = out + (x[j] - Jet::constant(x[j].v)).scale(gradient[j]);
        }
    }
    out
}

/// The sea's flow at the point `x` (global, on jets) at `time`, in global
/// axes (B31).
pub(crate) fn flow_at<const N: usize, const H: usize>(
    sea: &Sea,
    x: &JetVec<N, H>,
    time: FlowTime,
) -> Flow<N, H> {
    let at = x.map(|c| c.v);
    let k: FluidKinematics = match time {
        FlowTime::At(t) => sea.kinematics(&at, t),
        FlowTime::Steady => sea.steady_current(&at),
    };
    Flow {
        velocity: std::array::from_fn(|i| linear(k.velocity[i], &k.velocity_gradient[i], x)),
        acceleration: std::array::from_fn(|i| {
            linear(k.acceleration[i], &k.acceleration_gradient[i], x)
        }),
        pressure: linear(k.pressure, &k.pressure_gradient, x),
    }
}

impl<const N: usize, const H: usize> Flow<N, H> {
    /// The flow with its vectors turned by `turn` (to a body's axes).
    pub fn turned(self, turn: impl Fn(&JetVec<N, H>) -> JetVec<N, H>) -> Self {
        Flow {
            velocity: turn(&self.velocity),
            acceleration: turn(&self.acceleration),
            pressure: self.pressure,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::water::waves::AiryWave;

    /// The jets' first derivatives are the flow's gradients: against
    /// central differences of the sea's values along a point that moves
    /// with two variables.
    #[test]
    fn the_flows_jets_carry_the_seas_gradients() {
        let wave = AiryWave {
            amplitude: 1.5,
            period: 8.0,
            heading_deg: 30.0,
            phase_deg: 20.0,
        };
        let sea = Sea::new(60.0, 9.81, &[wave]).unwrap();
        // x = (s, 2 s + r, -5 - r): a point moved by the variables s and r.
        let point = |s: f64, r: f64| [s, 2.0 * s + r, -5.0 - r];
        let x: JetVec<2> = {
            let (s, r) = (Jet::variable(1.2, 0), Jet::variable(0.3, 1));
            [s, s.scale(2.0) + r, Jet::constant(-5.0) - r]
        };
        let f = flow_at(&sea, &x, FlowTime::At(2.5));
        let h = 1e-6;
        for (var, (ds, dr)) in [(0usize, (h, 0.0)), (1, (0.0, h))] {
            let plus = sea.kinematics(&point(1.2 + ds, 0.3 + dr), 2.5);
            let minus = sea.kinematics(&point(1.2 - ds, 0.3 - dr), 2.5);
            let d = |a: f64, b: f64| (a - b) / (2.0 * h);
            for i in 0..3 {
                let fd = d(plus.velocity[i], minus.velocity[i]);
                assert!((fd - f.velocity[i].g[var]).abs() < 1e-7, "u{i}");
                let fd = d(plus.acceleration[i], minus.acceleration[i]);
                assert!((fd - f.acceleration[i].g[var]).abs() < 1e-7, "a{i}");
            }
            let fd = d(plus.pressure, minus.pressure);
            assert!((fd - f.pressure.g[var]).abs() < 1e-6, "p");
        }
    }
}
