//! The rates a host does not give (docs/method.md §13.3, (K2a)): a host
//! that passes positions only (MoorDyn's `MoorDyn_Step` always takes
//! velocities; a host may not have them) would move the coupled points
//! along a line over each interval, their velocity jumping at every
//! call by the motion's acceleration times the interval: impulses the
//! lines feel (on Lowe and Langley's jumper moved 10 m over 27 s, coupled
//! every 0.5 s, a 32 kN error in the top tension and a step the energy
//! watch stops). Instead each call's velocity is estimated from the
//! host's own positions, of this call and the two before it, by the
//! derivative at this call's time of the quadratic through them:
//!
//! ```text
//!   v_b = a,   y(tau) = a tau + b tau^2 through (tau_1, y_1), (tau_0, y_0),
//!   tau_i = t_i - t_b,  y_i = x_i - x_b:
//!   a = (y_1 tau_0^2 - y_0 tau_1^2) / (tau_1 tau_0 (tau_0 - tau_1))     (K2a)
//! ```
//!
//! (second order; (3 x_b - 4 x_1 + x_0) / (2 h) at equal intervals), the
//! chord y_1 / tau_1 with one call before it (the first interval, which
//! runs along the line as before). A body's rotation takes the same
//! formula on the rotation vectors y_i = log(R_i R_b^T) (R(t) = exp([phi])
//! R_b near t_b, dphi/dt = the angular velocity, global). The interval
//! then runs along the cubic (K2) between the last call's velocity and
//! this one's, so the points' velocities are continuous from call to
//! call.

use super::bodies::{pose, ArrayLayout};
use super::CoupledSystem;
use crate::body::rotation::log_map;
use crate::vec3::mat3_mul;

/// The host's positions of its last calls, at most two (time, the
/// coupling array x), times increasing.
pub(super) type Samples = Vec<(f64, Vec<f64>)>;

/// Takes the host's call `(t, x)` into `samples` (dropping any at or
/// after t, and all but the last two).
pub(super) fn remember(samples: &mut Samples, t: f64, x: &[f64]) {
    samples.retain(|(ts, _)| *ts < t);
    samples.push((t, x.to_vec()));
    if samples.len() > 2 {
        samples.remove(0);
    }
}

/// (K2a): the derivative at tau = 0 of the quadratic (the line, with one)
/// through (0, 0) and the earlier `(tau, y)`.
fn rate_at_end<const N: usize>(earlier: &[(f64, [f64; N])]) -> [f64; N] {
    match earlier {
        [(tau_1, y_1)] => y_1.map(|c| c / tau_1),
        [(tau_0, y_0), (tau_1, y_1)] => {
            let den = tau_1 * tau_0 * (tau_0 - tau_1);
            std::array::from_fn(|i| (y_1[i] * tau_0 * tau_0 - y_0[i] * tau_1 * tau_1) / den)
        }
        _ => [0.0; N],
    }
}

impl ArrayLayout {
    /// The coupling arrays' velocities at the call `(t, x)` estimated by
    /// (K2a) from the host's earlier `samples`; None without an earlier one.
    pub(super) fn estimated_rates(&self, samples: &Samples, t: f64, x: &[f64]) -> Option<Vec<f64>> {
        let earlier: Vec<&(f64, Vec<f64>)> = samples.iter().filter(|(ts, _)| *ts < t).collect();
        if earlier.is_empty() {
            return None;
        }
        let mut out = vec![0.0; x.len()];
        let translation = |s: usize, out: &mut [f64]| {
            let ys: Vec<(f64, [f64; 3])> = earlier
                .iter()
                .map(|(ts, xs)| (ts - t, std::array::from_fn(|i| xs[s + i] - x[s + i])))
                .collect();
            out[s..s + 3].copy_from_slice(&rate_at_end(&ys));
        };
        for k in 0..self.bodies.len() {
            let s = self.body_start(k);
            translation(s, &mut out);
            if self.bodies[k].pin.is_some() {
                continue;
            }
            let (_, r_b) = pose(&x[s..s + 6]);
            let back = crate::vec3::mat3_transpose(&r_b);
            let ys: Vec<(f64, [f64; 3])> = earlier
                .iter()
                .map(|(ts, xs)| (ts - t, log_map(&mat3_mul(&pose(&xs[s..s + 6]).1, &back))))
                .collect();
            out[s + 3..s + 6].copy_from_slice(&rate_at_end(&ys));
        }
        for k in 0..self.plain.len() {
            translation(self.point_start(k), &mut out);
        }
        Some(out)
    }
}

impl CoupledSystem {
    /// The velocities of the call `(t_next, x, xd)`: the host's `xd`, or
    /// without them (K2a)'s estimate from its earlier positions; its
    /// positions kept for the next call's.
    pub(super) fn call_rates(
        &mut self,
        t_next: f64,
        x: &[f64],
        xd: Option<&[f64]>,
    ) -> Option<Vec<f64>> {
        let running = self.running.as_mut()?;
        let rates = match xd {
            Some(v) => Some(v.to_vec()),
            None => self.layout.estimated_rates(&running.samples, t_next, x),
        };
        remember(&mut running.samples, t_next, x);
        rates
    }
}

#[cfg(test)]
mod tests {
    use super::super::bodies::{ArrayLayout, CoupledBody};
    use super::{rate_at_end, remember, Samples};
    use crate::body::pose::{moordyn_angles, rotation_from_moordyn_angles};
    use crate::body::rotation::exp_map;
    use crate::vec3::mat3_mul;

    /// A coupled body turning at a constant angular velocity w (global)
    /// from a pose pitched and yawed, its reference point on a quadratic
    /// path, and a coupled point on a quadratic: from the host's
    /// positions alone at unequal intervals, (K2a) gives the reference
    /// point's and the point's velocities and w, exactly (to round-off):
    /// R(t) = exp([w] t) R_0 has log(R_i R_b^T) = w (t_i - t_b).
    #[test]
    fn a_body_turning_steadily_has_its_angular_velocity_estimated() {
        let layout = ArrayLayout {
            bodies: vec![CoupledBody {
                body: 0,
                points: Vec::new(),
                pin: None,
            }],
            plain: vec![0],
        };
        let r0 = rotation_from_moordyn_angles([10.0, 20.0, 30.0]);
        let w = [0.05, -0.02, 0.1];
        let x_at = |t: f64| -> Vec<f64> {
            let r = mat3_mul(&exp_map(w.map(|c| c * t)), &r0);
            let a = moordyn_angles(&r).map(f64::to_radians);
            let reference = [1.0 + 0.5 * t - 0.1 * t * t, -2.0 + 0.3 * t * t, 0.2 * t];
            let point = [3.0 - t * t, 0.7 * t, -1.0];
            [&reference[..], &a[..], &point[..]].concat()
        };
        let mut samples = Samples::new();
        for t in [0.0, 0.4, 1.1] {
            remember(&mut samples, t, &x_at(t));
        }
        let tb = 1.5;
        let v = layout.estimated_rates(&samples, tb, &x_at(tb)).unwrap();
        let expected = [
            0.5 - 0.2 * tb,
            0.6 * tb,
            0.2,
            w[0],
            w[1],
            w[2],
            -2.0 * tb,
            0.7,
            0.0,
        ];
        for (i, (a, b)) in v.iter().zip(expected).enumerate() {
            assert!((a - b).abs() < 1e-12, "{i}: {a} against {b}");
        }
        // Only the last two calls are kept.
        assert_eq!(samples.len(), 2);
        assert_eq!(samples[0].0, 0.4);
    }

    /// (K2a) is exact for a quadratic at unequal intervals, and the
    /// second-order backward difference at equal ones.
    #[test]
    fn the_estimated_rate_is_the_quadratics_derivative() {
        let x = |t: f64| 1.0 + 2.0 * t - 3.0 * t * t;
        let (t0, t1, tb) = (0.3, 0.8, 1.5);
        let y = |t: f64| [x(t) - x(tb)];
        let v = rate_at_end(&[(t0 - tb, y(t0)), (t1 - tb, y(t1))]);
        assert!((v[0] - (2.0 - 6.0 * tb)).abs() < 1e-13, "{v:?}");
        let h = 0.5;
        let v = rate_at_end(&[(-2.0 * h, [4.0]), (-h, [1.0])]);
        // (3 x_b - 4 x_1 + x_0) / (2 h) with x_b = 0, x_1 = 1, x_0 = 4.
        assert!((v[0] - (-4.0 + 4.0) / (2.0 * h)).abs() < 1e-15, "{v:?}");
        assert_eq!(rate_at_end(&[(-h, [1.0])]), [-2.0]);
    }
}
