//! Nodal loads that depend on the coordinates: the end moment of eqs.
//! (15)-(16).
//!
//! The paper's work of a moment is W = M theta with theta the rotation of
//! the end tangent, written as an arctangent of a ratio of components
//! (eq. 16), which jumps at theta = +-pi/2 and cannot follow a full circle.
//! stancf uses the smooth generalized force of the method notes: for a
//! moment of magnitude M about the unit axis n, with p = r_x - (r_x . n) n
//! the part of r_x normal to n,
//!
//! ```text
//!   dtheta/dr_x = (n x p) / |p|^2          Q = M (n x p) / |p|^2
//!   dQ/dr_x = M ( [n]x |p|^2 - 2 (n x p) p^T ) / |p|^4    (symmetric)
//! ```
//!
//! which is exact through theta = pi and 2 pi.

use crate::element::{cross, dot};

/// The end moment as magnitude and unit axis.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct EndMoment {
    pub magnitude: f64,
    pub axis: [f64; 3],
}

impl EndMoment {
    /// From a moment vector (N m); None for the zero vector.
    pub fn from_vector(m: &[f64; 3]) -> Option<Self> {
        let magnitude = dot(m, m).sqrt();
        if magnitude == 0.0 {
            return None;
        }
        Some(EndMoment {
            magnitude,
            axis: m.map(|c| c / magnitude),
        })
    }

    /// The part of r_x normal to the axis.
    fn normal_part(&self, rx: &[f64; 3]) -> [f64; 3] {
        let a = dot(rx, &self.axis);
        [
            rx[0] - a * self.axis[0],
            rx[1] - a * self.axis[1],
            rx[2] - a * self.axis[2],
        ]
    }

    /// Generalized force Q = dW/dr_x and its Jacobian dQ/dr_x.
    pub fn generalized_force(&self, rx: &[f64; 3]) -> ([f64; 3], [[f64; 3]; 3]) {
        let n = &self.axis;
        let p = self.normal_part(rx);
        let pp = dot(&p, &p);
        let np = cross(n, &p);
        let m = self.magnitude;
        let q = np.map(|c| m * c / pp);
        // [n]x maps v to n x v.
        let nx = [[0.0, -n[2], n[1]], [n[2], 0.0, -n[0]], [-n[1], n[0], 0.0]];
        let mut dq = [[0.0; 3]; 3];
        for i in 0..3 {
            for j in 0..3 {
                dq[i][j] = m * (nx[i][j] * pp - 2.0 * np[i] * p[j]) / (pp * pp);
            }
        }
        // [n]x restricted to the plane normal to n equals [n]x P, P = I - n n^T;
        // [n]x n = 0, so no projection is needed.
        (q, dq)
    }

    /// Angle in (-pi, pi] of r_x about the axis, measured from `reference`.
    pub fn angle(&self, reference: &[f64; 3], rx: &[f64; 3]) -> f64 {
        let p0 = self.normal_part(reference);
        let p = self.normal_part(rx);
        dot(&self.axis, &cross(&p0, &p)).atan2(dot(&p0, &p))
    }

    /// Whether `rx` has a part normal to the axis (a moment about the
    /// tangent itself is a torsion, which a cable cannot carry).
    pub fn acts_on(&self, rx: &[f64; 3]) -> bool {
        let p = self.normal_part(rx);
        dot(&p, &p) > 1e-12 * dot(rx, rx)
    }
}

/// The unwrapped angle of an end moment, followed step by step so that the
/// moment's potential -M theta stays continuous through +-pi.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MomentAngle {
    pub moment: EndMoment,
    pub node: usize,
    pub reference: [f64; 3],
    principal: f64,
    pub unwrapped: f64,
}

impl MomentAngle {
    pub fn new(moment: EndMoment, node: usize, reference: [f64; 3], rx: &[f64; 3]) -> Self {
        let principal = moment.angle(&reference, rx);
        MomentAngle {
            moment,
            node,
            reference,
            principal,
            unwrapped: principal,
        }
    }

    /// Follows r_x to its new value (its rotation in one update must stay
    /// below pi).
    pub fn update(&mut self, rx: &[f64; 3]) {
        let p = self.moment.angle(&self.reference, rx);
        let mut d = p - self.principal;
        let two_pi = 2.0 * std::f64::consts::PI;
        if d > std::f64::consts::PI {
            d -= two_pi;
        } else if d <= -std::f64::consts::PI {
            d += two_pi;
        }
        self.principal = p;
        self.unwrapped += d;
    }

    /// Potential -M theta of the moment.
    pub fn potential(&self) -> f64 {
        -self.moment.magnitude * self.unwrapped
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn force_is_the_gradient_of_the_angle_and_its_jacobian_matches() {
        let m = EndMoment::from_vector(&[0.3, -0.2, 1.1]).unwrap();
        let reference = [1.0, 0.2, 0.0];
        let h = 1e-6;
        for rx in [[0.9, 0.3, 0.1], [-1.0, 0.05, 0.2], [0.1, -1.2, -0.3]] {
            let (q, dq) = m.generalized_force(&rx);
            for j in 0..3 {
                let mut p = rx;
                let mut n = rx;
                p[j] += h;
                n[j] -= h;
                let dw =
                    m.magnitude * (m.angle(&reference, &p) - m.angle(&reference, &n)) / (2.0 * h);
                assert!((dw - q[j]).abs() < 1e-8 * (1.0 + q[j].abs()), "{rx:?} {j}");
                let (qp, _) = m.generalized_force(&p);
                let (qn, _) = m.generalized_force(&n);
                for i in 0..3 {
                    let d = (qp[i] - qn[i]) / (2.0 * h);
                    assert!(
                        (d - dq[i][j]).abs() < 1e-7 * (1.0 + d.abs()),
                        "{rx:?} {i} {j}"
                    );
                }
            }
            for i in 0..3 {
                for j in 0..3 {
                    assert!((dq[i][j] - dq[j][i]).abs() < 1e-14 * (1.0 + dq[i][j].abs()));
                }
            }
        }
    }

    #[test]
    fn the_unwrapped_angle_follows_a_full_turn() {
        let m = EndMoment::from_vector(&[0.0, 0.0, 2.0]).unwrap();
        let reference = [1.0, 0.0, 0.0];
        let mut a = MomentAngle::new(m, 0, reference, &reference);
        let turns = 2.5;
        let n = 100;
        for k in 1..=n {
            let th = 2.0 * std::f64::consts::PI * turns * k as f64 / n as f64;
            a.update(&[th.cos(), th.sin(), 0.0]);
        }
        assert!((a.unwrapped - 2.0 * std::f64::consts::PI * turns).abs() < 1e-12);
        assert!((a.potential() + 2.0 * a.unwrapped).abs() < 1e-12);
    }
}
