//! A point fixed to a body, as the step sees it (docs/method.md §15.7,
//! (B11)): over a step the body's centre moves on its cubic and its
//! rotation is R_a exp([theta(t)]), so a point at xi' from the centre of
//! mass (body axes) is at, and moves with,
//!
//! ```text
//!   x     = r_G + R_a exp([theta]) xi'                                   (B11)
//!   x_dot = r_G_dot + R_a exp([theta]) (J_r(theta) theta_dot x xi')
//! ```
//!
//! The offsets from the centre are evaluated on jets over (theta,
//! theta_dot): their first derivatives carry a line end's rows to the
//! body's (the chain rule of §15.7), their second derivatives the
//! change of that map along Newton's iterations.

use super::jet::{cross, Jet, JetVec};
use super::rotation::{body_rate, times, turn};

/// Variables of the offsets: theta (0..3) and theta_dot (3..6).
pub const NA: usize = 6;

/// The offsets (R_a exp([theta]) xi', R_a exp([theta]) (J_r theta_dot x
/// xi')) of (B11) at theta, theta_dot, on jets over both.
pub fn offsets(
    rotation_a: &[[f64; 3]; 3],
    xi: [f64; 3],
    theta: [f64; 3],
    theta_dot: [f64; 3],
) -> (JetVec<NA>, JetVec<NA>) {
    let th: JetVec<NA> = std::array::from_fn(|i| Jet::variable(theta[i], i));
    let td: JetVec<NA> = std::array::from_fn(|i| Jet::variable(theta_dot[i], 3 + i));
    let xi: JetVec<NA> = xi.map(Jet::constant);
    let position = times(rotation_a, &turn(&th, &xi, 1.0));
    let omega = body_rate(&th, &td);
    let velocity = times(rotation_a, &turn(&th, &cross(&omega, &xi), 1.0));
    (position, velocity)
}

/// w . v on jets with a constant vector w.
pub fn project(w: [f64; 3], v: &JetVec<NA>) -> Jet<NA> {
    v[0].scale(w[0]) + v[1].scale(w[1]) + v[2].scale(w[2])
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::body::rotation::{exp_map, right_jacobian};

    /// (B11) against the closed forms, and its derivatives against
    /// central differences.
    #[test]
    fn a_body_points_offsets_and_their_derivatives_are_exact() {
        let ra = exp_map([0.3, -0.2, 0.5]);
        let xi = [1.2, -0.4, 0.7];
        let theta = [0.4, 0.1, -0.6];
        let td = [0.2, -1.1, 0.5];
        let (p, v) = offsets(&ra, xi, theta, td);
        let rot = crate::vec3::mat3_mul(&ra, &exp_map(theta));
        let omega = crate::body::pose::rotate(&right_jacobian(theta), td);
        let px = crate::body::pose::rotate(&rot, xi);
        let vx = crate::body::pose::rotate(&rot, crate::vec3::cross(omega, xi));
        for c in 0..3 {
            assert!((p[c].v - px[c]).abs() < 1e-14);
            assert!((v[c].v - vx[c]).abs() < 1e-14);
        }
        let h = 1e-6;
        for k in 0..NA {
            let shift = |s: f64| {
                let mut t = theta;
                let mut d = td;
                if k < 3 {
                    t[k] += s;
                } else {
                    d[k - 3] += s;
                }
                offsets(&ra, xi, t, d)
            };
            let (pu, vu) = shift(h);
            let (pd, vd) = shift(-h);
            for c in 0..3 {
                assert!((p[c].g[k] - (pu[c].v - pd[c].v) / (2.0 * h)).abs() < 1e-8);
                assert!((v[c].g[k] - (vu[c].v - vd[c].v) / (2.0 * h)).abs() < 1e-8);
                for l in 0..NA {
                    let fd = (vu[c].g[l] - vd[c].g[l]) / (2.0 * h);
                    assert!((v[c].h[k][l] - fd).abs() < 1e-7, "v{c} h[{k}][{l}]");
                }
            }
        }
    }
}
