//! What a coupled body's own parts push the host with (docs/method.md
//! §15.18): the rods fixed in it (MoorDyn's coupled rod is a coupled body
//! that is one rod) weigh, float, meet the water and must be accelerated
//! with their added mass; the host carries them. Their push (B36) joins
//! the lines' force and moment in the coupling arrays.
//!
//! Over an interval the body moves as the host says at its ends: its
//! reference point along the points' motion (K1)-(K2), its rotation in
//! the chart of the interval's start, R(t) = R_a exp([phi(t)]), phi's
//! components on the same cubic between phi(t_a) = 0, phi_b =
//! log(R_a^T R_b) and the chart's rates Omega_a, J_r(phi_b)^-1 Omega_b
//! (the line without rates). The push is averaged over each step by
//! three-point Gauss in time.

use crate::body::flow::FlowTime;
use crate::body::jet::{Jet, JetVec};
use crate::body::pose::{rotate, rotate_back};
use crate::body::rotation::{body_rate, chart_rate, exp_map, log_map};
use crate::motion::MotionInterval;
use crate::system::{held_push, Body, HeldMotion};
use crate::vec3::{mat3_mul, mat3_transpose};

/// A coupled body's pose at an interval's end: its reference point and
/// rotation, with their rates (global velocity and angular velocity) when
/// the host gives them.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) struct HeldEnd {
    pub position: [f64; 3],
    pub rotation: [[f64; 3]; 3],
    pub rates: Option<([f64; 3], [f64; 3])>,
}

/// A coupled body's motion over an interval.
pub(super) struct HeldPath {
    reference: MotionInterval,
    start: [[f64; 3]; 3],
    chart: MotionInterval,
}

impl HeldPath {
    /// From `a` at `t0` to `b` at `t0 + span`: the cubic where both ends
    /// have rates, else the line.
    pub fn new(t0: f64, span: f64, a: &HeldEnd, b: &HeldEnd) -> Self {
        let turn = mat3_mul(&mat3_transpose(&a.rotation), &b.rotation);
        let phi_b = log_map(&turn);
        let both = a.rates.zip(b.rates);
        HeldPath {
            reference: MotionInterval {
                t0,
                duration: span,
                start: a.position,
                end: b.position,
                rates: both.map(|((va, _), (vb, _))| (va, vb)),
            },
            start: a.rotation,
            chart: MotionInterval {
                t0,
                duration: span,
                start: [0.0; 3],
                end: phi_b,
                rates: both.map(|((_, wa), (_, wb))| {
                    let omega_b = rotate_back(&b.rotation, wb);
                    (rotate_back(&a.rotation, wa), chart_rate(phi_b, omega_b))
                }),
            },
        }
    }

    /// The body's motion at t: R = R_a exp([phi]), Omega = J_r(phi)
    /// phi_dot (B3) and its rate, on jets in t, turned to global axes
    /// (d/dt (R Omega) = R Omega_dot: R_dot Omega = R (Omega x Omega)).
    pub fn at(&self, t: f64) -> HeldMotion {
        let (position, velocity) = self.reference.state(t);
        let (phi, phi_dot) = self.chart.state(t);
        let phi_ddot = self.chart.acceleration(t);
        let jet = |v: f64, d: f64| Jet::<1, 0> { v, g: [d], h: [] };
        let angle: JetVec<1, 0> = std::array::from_fn(|i| jet(phi[i], phi_dot[i]));
        let rate: JetVec<1, 0> = std::array::from_fn(|i| jet(phi_dot[i], phi_ddot[i]));
        let omega = body_rate(&angle, &rate);
        let rotation = mat3_mul(&self.start, &exp_map(phi));
        HeldMotion {
            position,
            velocity,
            acceleration: self.reference.acceleration(t),
            rotation,
            angular_velocity: rotate(&rotation, omega.map(|w| w.v)),
            angular_acceleration: rotate(&rotation, omega.map(|w| w.g[0])),
        }
    }
}

/// Whether the coupled `body` pushes the host with anything of its own:
/// it carries rods (its own mass and water are the host's).
pub(super) fn carries_loads(body: &Body) -> bool {
    !body.rods.is_empty()
}

/// The push of `body` (B36) held at rest at `end`'s pose, in the static
/// solve's steady water: force, then moment about the reference point.
pub(super) fn rest_push(body: &Body, gravity: [f64; 3], end: &HeldEnd) -> [f64; 6] {
    let rest = HeldMotion::at_rest(end.position, end.rotation);
    let (f, m) = held_push(body, gravity, &rest, FlowTime::Steady);
    [f[0], f[1], f[2], m[0], m[1], m[2]]
}

/// The push of `body` (B36) averaged over [t_a, t_a + h] on `path`, by
/// three-point Gauss-Legendre in time: force, then moment about the
/// reference point.
pub(super) fn mean_push(
    body: &Body,
    gravity: [f64; 3],
    path: &HeldPath,
    t_a: f64,
    h: f64,
) -> [f64; 6] {
    let rule = crate::quadrature::GaussRule::shared(3);
    let mut out = [0.0; 6];
    for (x, w) in rule.points.iter().zip(&rule.weights) {
        let t = t_a + h * x;
        let (f, m) = held_push(body, gravity, &path.at(t), FlowTime::At(t));
        for c in 0..3 {
            out[c] += w * f[c];
            out[3 + c] += w * m[c];
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::body::pose::rotation_from_moordyn_angles;

    /// The path meets its ends (pose and rates), and its velocity and
    /// angular velocity are its position's and rotation's derivatives
    /// (central differences to 1e-8), its accelerations theirs.
    #[test]
    fn a_held_path_meets_its_ends_and_its_rates_are_its_derivatives() {
        let a = HeldEnd {
            position: [1.0, -2.0, -5.0],
            rotation: rotation_from_moordyn_angles([10.0, -20.0, 35.0]),
            rates: Some(([0.3, 0.1, -0.2], [0.2, -0.4, 0.6])),
        };
        let b = HeldEnd {
            position: [1.5, -1.7, -5.4],
            rotation: rotation_from_moordyn_angles([25.0, -5.0, 70.0]),
            rates: Some(([0.1, 0.5, 0.0], [-0.3, 0.2, 0.9])),
        };
        let path = HeldPath::new(2.0, 0.8, &a, &b);
        let close = |x: [f64; 3], y: [f64; 3], tol: f64, what: &str| {
            for k in 0..3 {
                assert!((x[k] - y[k]).abs() < tol, "{what}: {x:?} {y:?}");
            }
        };
        for (t, end) in [(2.0, &a), (2.8, &b)] {
            let m = path.at(t);
            close(m.position, end.position, 1e-14, "position");
            for r in 0..3 {
                close(m.rotation[r], end.rotation[r], 1e-13, "rotation");
            }
            let (v, w) = end.rates.unwrap();
            close(m.velocity, v, 1e-13, "velocity");
            close(m.angular_velocity, w, 1e-13, "angular velocity");
        }
        let h = 1e-5;
        for t in [2.13, 2.5, 2.71] {
            let (m, p, q) = (path.at(t), path.at(t + h), path.at(t - h));
            let d = |f: fn(&HeldMotion) -> [f64; 3]| -> [f64; 3] {
                std::array::from_fn(|k| (f(&p)[k] - f(&q)[k]) / (2.0 * h))
            };
            close(d(|m| m.position), m.velocity, 1e-8, "velocity");
            close(d(|m| m.velocity), m.acceleration, 1e-8, "acceleration");
            close(
                d(|m| m.angular_velocity),
                m.angular_acceleration,
                1e-8,
                "angular acceleration",
            );
            // R_dot R^T = [w].
            let r_dot: [[f64; 3]; 3] = std::array::from_fn(|i| {
                std::array::from_fn(|j| (p.rotation[i][j] - q.rotation[i][j]) / (2.0 * h))
            });
            let spin = mat3_mul(&r_dot, &mat3_transpose(&m.rotation));
            close(
                [spin[2][1], spin[0][2], spin[1][0]],
                m.angular_velocity,
                1e-8,
                "spin",
            );
        }
    }
}
