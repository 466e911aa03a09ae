//! MoorDyn's cross-flow vortex-induced vibration model (docs/method.md
//! §12.7, (V20)-(V25)), after Thorsen, Sævik and Larsen's synchronisation
//! model: at every point of the line a vortex-shedding phase phi, a state
//! that runs at the shedding frequency and locks onto the phase of the
//! line's own cross-flow motion, and a lift force across the flow that
//! follows cos(phi).
//!
//! With the relative flow v = u - r_dot, its part normal to the tangent
//! t = r_x / |r_x|, v_n = v - (v . t) t, the cross-flow direction
//! e_y = t x v_n / |v_n|, the cross-flow velocity and acceleration
//! y_dot = r_dot . e_y, y_ddot = r_ddot . e_y and their running mean
//! squares A^2, B^2:
//!
//! ```text
//!   psi     = atan2(-y_ddot / B, y_dot / A)                         (V21)
//!   phi_dot = 2 pi |v_n| / d (cF + dF sin(psi - phi))               (V22)
//!   f_L     = 1/2 rho_w d Cl s cos(phi) |v_n| (t x v_n)              (V23)
//! ```
//!
//! (per unit unstretched length, s the submerged fraction; psi with the
//! unscaled velocity and acceleration while A or B is 0).

use super::dual::{cross3, dot3, Dual, Vec3D};
use crate::water::LineInWater;

/// Inputs of the pointwise law: r (0..3), r_x (3..6), r_dot (6..9),
/// r_ddot (9..12) and phi (12).
pub(crate) const INPUTS: usize = 13;
pub(crate) const PHI: usize = 12;
/// The values of the internal state per point: phi, A^2, B^2.
pub const VIV_VALUES: usize = 3;

/// MoorDyn's VIV law of a line type (its LINE TYPES columns Cl, dF, cF).
#[derive(Clone, Debug, PartialEq)]
pub struct Viv {
    /// The cross-flow lift coefficient Cl (> 0).
    pub lift: f64,
    /// The centre cF of the synchronisation's range of non-dimensional
    /// frequencies f d / |v_n| (MoorDyn's default 0.18).
    pub centre: f64,
    /// Its half-width dF (MoorDyn's default 0.08).
    pub range: f64,
    /// The time over which the mean squares A^2, B^2 of the cross-flow
    /// velocity and acceleration are taken (V24): MoorDyn's running RMS
    /// over n_m = 500 of its steps, 500 dtM.
    pub averaging_time: f64,
}

/// The law at one point of the line at one time: the phase rate (V22)
/// and the lift (V23) (without cos(phi)) with their derivatives in the
/// point's [`INPUTS`], and the cross-flow velocity and acceleration.
pub(crate) struct VivAtPoint {
    /// |v_n| 2 pi / d: the rate is this times (cF + dF sin(psi - phi)).
    pub frequency: Dual<INPUTS>,
    /// psi (V21).
    pub response_phase: Dual<INPUTS>,
    /// 1/2 rho_w d Cl s |v_n| (t x v_n): the lift is this times cos(phi).
    pub lift: Vec3D<INPUTS>,
    pub y_dot: f64,
    pub y_ddot: f64,
}

impl VivAtPoint {
    /// Where the water does not move past the line: no shedding, no lift.
    pub(crate) fn still() -> Self {
        VivAtPoint {
            frequency: Dual::constant(0.0),
            response_phase: Dual::constant(0.0),
            lift: [Dual::constant(0.0); 3],
            y_dot: 0.0,
            y_ddot: 0.0,
        }
    }
}

impl Viv {
    /// Refuses a law MoorDyn's model cannot take, naming `what`.
    pub fn check(&self, what: &str) -> Result<(), crate::error::ModelError> {
        let bad = |m: String| Err(crate::error::ModelError::invalid(what, m));
        if !(self.lift.is_finite() && self.lift > 0.0) {
            return bad(format!(
                "the lift coefficient Cl must be > 0 (found {})",
                self.lift
            ));
        }
        if !(self.centre.is_finite() && self.centre > 0.0) {
            return bad(format!(
                "the synchronisation centre cF must be > 0 (found {})",
                self.centre
            ));
        }
        if !(self.range.is_finite() && self.range >= 0.0 && self.range < self.centre) {
            return bad(format!(
                "the synchronisation range dF must be >= 0 and below cF = {} (found {})",
                self.centre, self.range
            ));
        }
        if !(self.averaging_time.is_finite() && self.averaging_time > 0.0) {
            return bad(format!(
                "the averaging time of the cross-flow mean squares must be > 0 (found {})",
                self.averaging_time
            ));
        }
        Ok(())
    }

    /// The rate phi_dot (V22) at phase `phi` from the point's law `at`.
    pub(crate) fn rate(&self, at: &VivAtPoint, phi: Dual<INPUTS>) -> Dual<INPUTS> {
        let sync = (at.response_phase - phi).sin() * self.range + Dual::constant(self.centre);
        at.frequency * sync
    }

    /// The law at a point at `r` with tangent `rx`, velocity `rdot` and
    /// acceleration `rddot` at time `t` in the water `water`, with the
    /// mean squares `(a2, b2)` (V21)-(V23).
    pub(crate) fn at_point(
        &self,
        water: &LineInWater,
        (r, rx, rdot, rddot): (&[f64; 3], &[f64; 3], &[f64; 3], &[f64; 3]),
        t: f64,
        (a2, b2): (f64, f64),
    ) -> VivAtPoint {
        let input = |v: &[f64; 3], o: usize| -> Vec3D<INPUTS> {
            std::array::from_fn(|i| Dual::input(v[i], o + i))
        };
        let (rx_d, rdot_d, rddot_d) = (input(rx, 3), input(rdot, 6), input(rddot, 9));
        let flow = water.water.sea.kinematics(r, t);
        // u(r) and its gradient in r (inputs 0..3): the flow where the
        // point is.
        let u: Vec3D<INPUTS> = std::array::from_fn(|i| {
            let mut d = [0.0; INPUTS];
            d[..3].copy_from_slice(&flow.velocity_gradient[i]);
            Dual {
                v: flow.velocity[i],
                d,
            }
        });
        let len = dot3(&rx_d, &rx_d).sqrt();
        let tangent = rx_d.map(|c| c / len);
        let v: Vec3D<INPUTS> = std::array::from_fn(|i| u[i] - rdot_d[i]);
        let along = dot3(&v, &tangent);
        let v_n: Vec3D<INPUTS> = std::array::from_fn(|i| v[i] - along * tangent[i]);
        let speed = dot3(&v_n, &v_n).sqrt();
        if speed.v == 0.0 {
            return VivAtPoint::still();
        }
        let across = cross3(&tangent, &v_n);
        let e_y = across.map(|c| c / speed);
        let y_dot = dot3(&rdot_d, &e_y);
        let y_ddot = dot3(&rddot_d, &e_y);
        let (x, y) = if a2 > 0.0 && b2 > 0.0 {
            (y_dot * (1.0 / a2.sqrt()), -y_ddot * (1.0 / b2.sqrt()))
        } else {
            (y_dot, -y_ddot)
        };
        let diameter = water.morison.diameter;
        let wet = water.submerged(r);
        // s(z): its slope in r_z.
        let mut s = Dual::constant(wet.value);
        s.d[2] = wet.slope;
        let scale = s * speed * (0.5 * water.water.density * diameter * self.lift);
        VivAtPoint {
            frequency: speed * (2.0 * std::f64::consts::PI / diameter),
            response_phase: y.atan2(x),
            lift: across.map(|c| c * scale),
            y_dot: y_dot.v,
            y_ddot: y_ddot.v,
        }
    }

    /// The mean squares after a slab of length `dt` from `(a2, b2)` at its
    /// start (V24): m^2' = (y^2 - m^2) / T integrated exactly for the
    /// samples `(w_dt, offset, y_dot, y_ddot)` of the slab's time rule.
    pub(crate) fn mean_squares_after(
        &self,
        dt: f64,
        (a2, b2): (f64, f64),
        samples: impl Iterator<Item = (f64, f64, f64, f64)>,
    ) -> (f64, f64) {
        let tau = self.averaging_time;
        let decay = (-dt / tau).exp();
        let (mut a, mut b) = (decay * a2, decay * b2);
        for (w_dt, offset, yd, ydd) in samples {
            let k = w_dt * (-(dt - offset) / tau).exp() / tau;
            a += k * yd * yd;
            b += k * ydd * ydd;
        }
        (a, b)
    }
}

/// A line's VIV over a slab: the lift at the time points, the state at
/// the slab's end and the matrices of the Jacobian.
#[derive(Clone, Debug, Default)]
pub struct VivDerivatives {
    pub active: bool,
    /// The lift per unit length at [g * axial points + s].
    pub lift: Vec<[f64; 3]>,
    /// phi, A^2, B^2 of every axial point at the slab's end.
    pub end: Vec<f64>,
    /// The matrices multiplying N_s (position-like: r, r_dot, r_ddot) and
    /// N_x,s (r_x) in block (m, n), at [(s * 4 + m) * 4 + n].
    pub by_shape: Vec<[[f64; 3]; 3]>,
    pub by_slope: Vec<[[f64; 3]; 3]>,
}
