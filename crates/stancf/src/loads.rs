//! Loads that depend on the motion: the end moment of eqs. (15)-(16) and
//! the air drag of eq. (17) (docs/method.md §2.7-2.8).
//!
//! The paper's work of a moment is W = M theta with theta the rotation of
//! the end tangent, written as an arctangent of a ratio of components
//! (eq. 16), which jumps at theta = +-pi/2 and cannot follow a full circle.
//! stancf uses the smooth generalized force of docs/method.md §2.7, (M7):
//! for a moment of magnitude M about the unit axis n, with
//! p = r_x - (r_x . n) n the part of r_x normal to n,
//!
//! ```text
//!   dtheta/dr_x = (n x p) / |p|^2          Q = M (n x p) / |p|^2
//!   dQ/dr_x = M ( [n]x |p|^2 - 2 (n x p) p^T ) / |p|^4    (symmetric)
//! ```
//!
//! which is exact through theta = pi and 2 pi.

use crate::vec3::{cross, dot, mat3_mul};

/// Which part of the relative velocity the drag acts on.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum DragModel {
    /// The paper's eq. (17): f = -1/2 C rho d |v| v on the whole relative
    /// velocity.
    Full,
    /// Cross-flow: -1/2 C rho d |v_n| v_n on the component normal to the
    /// cable tangent, plus -1/2 C_t rho d |v_t| v_t on the tangential one
    /// (C_t = `tangential_coefficient`, often 0).
    Normal { tangential_coefficient: f64 },
}

/// Air drag per unit length (eq. 17; docs/method.md §2.8, (M9)-(M10)), a
/// non-conservative load entering the action as virtual work
/// int int f . dr dx dt.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct AirDrag {
    pub drag_coefficient: f64,
    pub fluid_density: f64,
    /// Windward width per unit length (m).
    pub diameter: f64,
    /// Uniform fluid velocity u (wind or current); v_rel = r_dot - u.
    pub fluid_velocity: [f64; 3],
    pub model: DragModel,
}

/// f = -k |v| v and df/dv = -k (|v| I + v v^T / |v|) (bounded; zero at v = 0).
pub(crate) fn quadratic_drag(k: f64, v: &[f64; 3]) -> ([f64; 3], [[f64; 3]; 3]) {
    let speed = dot(v, v).sqrt();
    let mut d = [[0.0; 3]; 3];
    if speed == 0.0 || k == 0.0 {
        return ([0.0; 3], d);
    }
    for i in 0..3 {
        for j in 0..3 {
            d[i][j] = -k * v[i] * v[j] / speed;
        }
        d[i][i] -= k * speed;
    }
    (quadratic_drag_force(k, v), d)
}

/// f = -k |v| v alone (the value of [`quadratic_drag`], the same bits).
pub(crate) fn quadratic_drag_force(k: f64, v: &[f64; 3]) -> [f64; 3] {
    let speed = dot(v, v).sqrt();
    if speed == 0.0 || k == 0.0 {
        return [0.0; 3];
    }
    v.map(|c| -k * speed * c)
}

impl AirDrag {
    /// Force per unit length f(r_dot, r_x) and its derivatives df/dr_dot
    /// and df/dr_x (the latter zero for the full model; docs/method.md
    /// §2.8, (M9)-(M10)).
    ///
    /// ```text
    ///   full:    f = q(k, v),  v = r_dot - u,  q(k, v) = -k |v| v,  k = C rho d / 2
    ///   normal:  t = r_x / |r_x|,  v_n = (I - t t^T) v,  v_t = t t^T v
    ///            f = q(k, v_n) + q(k_t, v_t)
    ///            df/dv   = Q_n (I - t t^T) + Q_t t t^T       (Q = dq/dv at v_n, v_t)
    ///            df/dr_x = (Q_n - Q_t) dv_n/dr_x,
    ///            dv_n/dr_x = -(t v^T + (v . t) I)(I - t t^T) / |r_x|
    /// ```
    pub fn force(
        &self,
        rdot: &[f64; 3],
        rx: &[f64; 3],
    ) -> ([f64; 3], [[f64; 3]; 3], [[f64; 3]; 3]) {
        let k = 0.5 * self.drag_coefficient * self.fluid_density * self.diameter;
        let v = [
            rdot[0] - self.fluid_velocity[0],
            rdot[1] - self.fluid_velocity[1],
            rdot[2] - self.fluid_velocity[2],
        ];
        match self.model {
            DragModel::Full => {
                let (f, d) = quadratic_drag(k, &v);
                (f, d, [[0.0; 3]; 3])
            }
            DragModel::Normal {
                tangential_coefficient,
            } => {
                let kt = 0.5 * tangential_coefficient * self.fluid_density * self.diameter;
                let len = dot(rx, rx).sqrt();
                let t = rx.map(|c| c / len);
                let vt_s = dot(v, t);
                let vt = t.map(|c| vt_s * c);
                let vn = [v[0] - vt[0], v[1] - vt[1], v[2] - vt[2]];
                let (fn_, qn) = quadratic_drag(k, &vn);
                let (ft, qt) = quadratic_drag(kt, &vt);
                let mut p = [[0.0; 3]; 3];
                let mut tt = [[0.0; 3]; 3];
                for i in 0..3 {
                    for j in 0..3 {
                        tt[i][j] = t[i] * t[j];
                        p[i][j] = if i == j { 1.0 } else { 0.0 } - tt[i][j];
                    }
                }
                let a = mat3_mul(&qn, &p);
                let b = mat3_mul(&qt, &tt);
                let mut dv = [[0.0; 3]; 3];
                // dv_n/dr_x
                let mut m = [[0.0; 3]; 3];
                for i in 0..3 {
                    for j in 0..3 {
                        m[i][j] = -(t[i] * v[j] + if i == j { vt_s } else { 0.0 });
                    }
                }
                let dvn_dx = mat3_mul(&m, &p).map(|row| row.map(|c| c / len));
                let mut qd = [[0.0; 3]; 3];
                for i in 0..3 {
                    for j in 0..3 {
                        dv[i][j] = a[i][j] + b[i][j];
                        qd[i][j] = qn[i][j] - qt[i][j];
                    }
                }
                let dx = mat3_mul(&qd, &dvn_dx);
                ([fn_[0] + ft[0], fn_[1] + ft[1], fn_[2] + ft[2]], dv, dx)
            }
        }
    }
}

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
        let a = dot(rx, self.axis);
        [
            rx[0] - a * self.axis[0],
            rx[1] - a * self.axis[1],
            rx[2] - a * self.axis[2],
        ]
    }

    /// Generalized force Q = dW/dr_x and its Jacobian dQ/dr_x
    /// (docs/method.md §2.7, (M7)).
    pub fn generalized_force(&self, rx: &[f64; 3]) -> ([f64; 3], [[f64; 3]; 3]) {
        let n = &self.axis;
        let p = self.normal_part(rx);
        let pp = dot(p, p);
        let np = cross(n, p);
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
        dot(self.axis, cross(p0, p)).atan2(dot(p0, p))
    }

    /// Whether `rx` has a part normal to the axis (a moment about the
    /// tangent itself is a torsion, which a cable cannot carry).
    pub fn acts_on(&self, rx: &[f64; 3]) -> bool {
        let p = self.normal_part(rx);
        dot(p, p) > 1e-12 * dot(rx, rx)
    }
}

/// The unwrapped angle of an end moment, followed step by step so that the
/// moment's potential -M theta stays continuous through +-pi
/// (docs/method.md §2.7, (M8)).
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
    fn drag_derivatives_match_finite_differences() {
        let h = 1e-7;
        for model in [
            DragModel::Full,
            DragModel::Normal {
                tangential_coefficient: 0.0,
            },
            DragModel::Normal {
                tangential_coefficient: 0.3,
            },
        ] {
            let d = AirDrag {
                drag_coefficient: 1.2,
                fluid_density: 1.225,
                diameter: 0.01,
                fluid_velocity: [0.3, -0.1, 0.2],
                model,
            };
            for (rdot, rx) in [
                ([1.0, 2.0, -0.5], [1.0, 0.2, 0.1]),
                ([-0.3, 0.1, 0.9], [0.6, -0.8, 0.3]),
                ([0.31, -0.1, 0.2], [1.1, 0.0, 0.0]),
            ] {
                let (_, dv, dx) = d.force(&rdot, &rx);
                for j in 0..3 {
                    let (mut vp, mut vm, mut xp, mut xm) = (rdot, rdot, rx, rx);
                    vp[j] += h;
                    vm[j] -= h;
                    xp[j] += h;
                    xm[j] -= h;
                    let (fvp, ..) = d.force(&vp, &rx);
                    let (fvm, ..) = d.force(&vm, &rx);
                    let (fxp, ..) = d.force(&rdot, &xp);
                    let (fxm, ..) = d.force(&rdot, &xm);
                    for i in 0..3 {
                        let a = (fvp[i] - fvm[i]) / (2.0 * h);
                        let b = (fxp[i] - fxm[i]) / (2.0 * h);
                        assert!(
                            (a - dv[i][j]).abs() < 1e-7,
                            "{model:?} dv {i}{j}: {a} {}",
                            dv[i][j]
                        );
                        assert!(
                            (b - dx[i][j]).abs() < 1e-7,
                            "{model:?} dx {i}{j}: {b} {}",
                            dx[i][j]
                        );
                    }
                }
            }
        }
    }

    /// The full model is the paper's eq. (17): magnitude 1/2 C rho d |v|^2
    /// against the relative velocity; the normal model ignores motion along
    /// the tangent.
    #[test]
    fn drag_force_values() {
        let d = AirDrag {
            drag_coefficient: 1.5,
            fluid_density: 1.225,
            diameter: 3.7e-3,
            fluid_velocity: [0.0; 3],
            model: DragModel::Full,
        };
        let (f, ..) = d.force(&[0.0, -2.0, 0.0], &[1.0, 0.0, 0.0]);
        let expect = 0.5 * 1.5 * 1.225 * 3.7e-3 * 4.0;
        assert!((f[1] - expect).abs() < 1e-15 && f[0] == 0.0);
        let n = AirDrag {
            model: DragModel::Normal {
                tangential_coefficient: 0.0,
            },
            ..d
        };
        let (f, ..) = n.force(&[3.0, 0.0, 0.0], &[1.0, 0.0, 0.0]);
        assert_eq!(f, [0.0; 3]);
    }

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
