//! The added mass of a line in water as the kinetic energy of the water it
//! entrains (docs/method.md §12.5, (W25)-(W27)).
//!
//! Per unit unstretched length, at a point of the axis with position r,
//! slope x = r_x and velocity v = r_dot, with c = rho_w A (A = pi d^2 / 4),
//! s the submerged fraction (W17) at z = r_3, t = x / |x| and
//! k = Cat - Can:
//!
//! ```text
//!   T_a = 1/2 c s(z) v^T B v,   B = Can I + k t t^T                    (W25)
//!       = 1/2 c s (Can v.v + k w^2 / g),   g = x . x,  w = x . v
//! ```
//!
//! Its first derivatives (W26) and second derivatives (W27), with
//! u = w / g and Q = v^T B v:
//!
//! ```text
//!   dT/dv = c s B v = c s (Can v + k u x)
//!   dT/dz = 1/2 c s' Q
//!   dT/dx = c s k u (v - u x)
//!   T_vv = c s B                        T_vz = c s' B v
//!   T_vx = c s k (x v^T / g + u I - 2 u x x^T / g)
//!   T_zz = 1/2 c s'' Q                  T_zx = c s' k u (v - u x)^T
//!   T_xx = c s k (v v^T / g - 2 u (v x^T + x v^T) / g - u^2 I + 4 u^2 x x^T / g)
//! ```
//!
//! (T_vz, T_zz, T_zx are the z column or row of T_vr, T_rr, T_rx; the
//! other entries vanish: s depends on z alone.)

use super::hydro::LineInWater;
use crate::vec3::dot;

type M3 = [[f64; 3]; 3];

/// The entrained water's inertia of a line: rho_w A, the coefficients and
/// the diameter that sets the submerged fraction.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct AddedMass {
    /// rho_w A (kg/m): the displaced water's mass per unit length.
    pub displaced: f64,
    /// Normal added-mass coefficient Can.
    pub ca_normal: f64,
    /// Axial added-mass coefficient Cat.
    pub ca_axial: f64,
    /// The hydrodynamic diameter d (m) of the submerged fraction (W17).
    pub diameter: f64,
}

/// T_a of (W25) at a point with its first (W26) and second (W27)
/// derivatives with respect to r_dot (v), r and r_x (x).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct EntrainedAtPoint {
    pub energy: f64,
    pub d_v: [f64; 3],
    pub d_r: [f64; 3],
    pub d_x: [f64; 3],
    pub vv: M3,
    /// `[i][j] = d2T / dv_i dr_j`.
    pub vr: M3,
    /// `[i][j] = d2T / dv_i dx_j`.
    pub vx: M3,
    pub rr: M3,
    /// `[i][j] = d2T / dr_i dx_j`.
    pub rx: M3,
    pub xx: M3,
}

impl AddedMass {
    /// The added mass of a line in `water`, or None if both coefficients
    /// are zero (the line then costs what it costs in air).
    pub fn of(water: &LineInWater) -> Option<AddedMass> {
        let m = &water.morison;
        if m.ca_normal == 0.0 && m.ca_axial == 0.0 {
            return None;
        }
        Some(AddedMass {
            displaced: water.water.density * m.area(),
            ca_normal: m.ca_normal,
            ca_axial: m.ca_axial,
            diameter: m.diameter,
        })
    }

    /// c s(z) B, the added mass per unit length at a point (the T_vv of
    /// (W27); it does not depend on the velocity).
    pub fn matrix(&self, r: &[f64; 3], x: &[f64; 3]) -> M3 {
        let s = super::SubmergedFraction::at(r[2], self.diameter).value;
        let cs = self.displaced * s;
        let k = self.ca_axial - self.ca_normal;
        let g = dot(x, x);
        let mut b = [[0.0; 3]; 3];
        for i in 0..3 {
            for j in 0..3 {
                b[i][j] = cs * k * x[i] * x[j] / g;
            }
            b[i][i] += cs * self.ca_normal;
        }
        b
    }

    /// T_a (W25) and its first derivatives (W26): what a residual needs.
    /// None where the section is dry (all zero).
    pub fn first_derivatives(
        &self,
        r: &[f64; 3],
        x: &[f64; 3],
        v: &[f64; 3],
    ) -> Option<EntrainedFirst> {
        self.terms(r, x, v).map(|t| t.first(self.displaced))
    }

    /// T_a (W25) and, if `second`, its second derivatives (W27); the first
    /// derivatives (W26) always. All zero where the section is dry.
    pub fn at_point(
        &self,
        r: &[f64; 3],
        x: &[f64; 3],
        v: &[f64; 3],
        second: bool,
    ) -> EntrainedAtPoint {
        let mut out = EntrainedAtPoint::default();
        let Some(t) = self.terms(r, x, v) else {
            return out;
        };
        let c = self.displaced;
        let first = t.first(c);
        out.energy = first.energy;
        out.d_v = first.d_v;
        out.d_r[2] = first.d_rz;
        out.d_x = first.d_x;
        if !second {
            return out;
        }
        let EntrainedTerms {
            s,
            s1,
            s2,
            k,
            g,
            u,
            bv,
            q,
            vux,
        } = t;
        let can = self.ca_normal;
        let (csk, csk1) = (c * s * k, c * s1 * k);
        out.rr[2][2] = 0.5 * c * s2 * q;
        for i in 0..3 {
            out.vr[i][2] = c * s1 * bv[i];
            out.rx[2][i] = csk1 * u * vux[i];
            for j in 0..3 {
                let id = if i == j { 1.0 } else { 0.0 };
                out.vv[i][j] = c * s * (can * id + k * x[i] * x[j] / g);
                out.vx[i][j] = csk * (x[i] * v[j] / g + u * id - 2.0 * u * x[i] * x[j] / g);
                out.xx[i][j] = csk
                    * (v[i] * v[j] / g - 2.0 * u * (v[i] * x[j] + x[i] * v[j]) / g - u * u * id
                        + 4.0 * u * u * x[i] * x[j] / g);
            }
        }
        out
    }

    /// The quantities (W25)-(W27) are made of, None where the section is
    /// dry.
    fn terms(&self, r: &[f64; 3], x: &[f64; 3], v: &[f64; 3]) -> Option<EntrainedTerms> {
        let sf = super::SubmergedFraction::at(r[2], self.diameter);
        if sf.is_dry() {
            return None;
        }
        let (can, k) = (self.ca_normal, self.ca_axial - self.ca_normal);
        let g = dot(x, x);
        let u = dot(x, v) / g;
        let bv: [f64; 3] = std::array::from_fn(|i| can * v[i] + k * u * x[i]);
        Some(EntrainedTerms {
            s: sf.value,
            s1: sf.slope,
            s2: sf.curvature,
            k,
            g,
            u,
            bv,
            q: dot(v, bv),
            vux: std::array::from_fn(|i| v[i] - u * x[i]),
        })
    }
}

/// T_a (W25) and its first derivatives (W26) at a point; of dT/dr only
/// the z component is not zero.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct EntrainedFirst {
    pub energy: f64,
    pub d_v: [f64; 3],
    pub d_rz: f64,
    pub d_x: [f64; 3],
}

/// The quantities of (W25)-(W27) at a wet point: s, s', s'', k, g, u,
/// B v, Q = v^T B v and v - u x.
struct EntrainedTerms {
    s: f64,
    s1: f64,
    s2: f64,
    k: f64,
    g: f64,
    u: f64,
    bv: [f64; 3],
    q: f64,
    vux: [f64; 3],
}

impl EntrainedTerms {
    /// (W25)-(W26) with c = rho_w A.
    fn first(&self, c: f64) -> EntrainedFirst {
        let (s, k, u) = (self.s, self.k, self.u);
        EntrainedFirst {
            energy: 0.5 * c * s * self.q,
            d_v: self.bv.map(|b| c * s * b),
            d_rz: 0.5 * c * self.s1 * self.q,
            d_x: self.vux.map(|a| c * s * k * u * a),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::AddedMass;

    fn added() -> AddedMass {
        AddedMass {
            displaced: 80.5,
            ca_normal: 1.0,
            ca_axial: 0.3,
            diameter: 0.3,
        }
    }

    /// Central differences of each level against the next (W25)-(W27) at a
    /// point in the surface band (s, s', s'' all nonzero).
    #[test]
    fn the_entrained_energy_derivatives_match_central_differences() {
        let am = added();
        let r = [0.3, -0.2, -0.04];
        let x = [0.8, -0.3, 0.5];
        let v = [1.1, 0.4, -0.7];
        let p = am.at_point(&r, &x, &v, true);
        let h = 1e-6;
        let shift = |a: &[f64; 3], i: usize, d: f64| {
            let mut b = *a;
            b[i] += d;
            b
        };
        for j in 0..3 {
            let dv = (am.at_point(&r, &x, &shift(&v, j, h), true).d_v[0]
                - am.at_point(&r, &x, &shift(&v, j, -h), true).d_v[0])
                / (2.0 * h);
            let e = |pp: super::EntrainedAtPoint| pp.energy;
            let fv = (e(am.at_point(&r, &x, &shift(&v, j, h), false))
                - e(am.at_point(&r, &x, &shift(&v, j, -h), false)))
                / (2.0 * h);
            let fr = (e(am.at_point(&shift(&r, j, h), &x, &v, false))
                - e(am.at_point(&shift(&r, j, -h), &x, &v, false)))
                / (2.0 * h);
            let fx = (e(am.at_point(&r, &shift(&x, j, h), &v, false))
                - e(am.at_point(&r, &shift(&x, j, -h), &v, false)))
                / (2.0 * h);
            assert!((fv - p.d_v[j]).abs() < 1e-6, "d_v {j}");
            assert!((fr - p.d_r[j]).abs() < 1e-6, "d_r {j}");
            assert!((fx - p.d_x[j]).abs() < 1e-6, "d_x {j}");
            assert!((dv - p.vv[0][j]).abs() < 1e-6, "vv {j}");
            for i in 0..3 {
                let by = |rr: &[f64; 3], xx: &[f64; 3], vv: &[f64; 3]| {
                    let q = am.at_point(rr, xx, vv, false);
                    (q.d_v[i], q.d_r[i], q.d_x[i])
                };
                let (a, b) = (by(&shift(&r, j, h), &x, &v), by(&shift(&r, j, -h), &x, &v));
                assert!(((a.0 - b.0) / (2.0 * h) - p.vr[i][j]).abs() < 1e-5, "vr");
                assert!(((a.1 - b.1) / (2.0 * h) - p.rr[i][j]).abs() < 1e-5, "rr");
                let (a, b) = (by(&r, &shift(&x, j, h), &v), by(&r, &shift(&x, j, -h), &v));
                assert!(((a.0 - b.0) / (2.0 * h) - p.vx[i][j]).abs() < 1e-5, "vx");
                assert!(((a.1 - b.1) / (2.0 * h) - p.rx[i][j]).abs() < 1e-5, "rx");
                assert!(((a.2 - b.2) / (2.0 * h) - p.xx[i][j]).abs() < 1e-5, "xx");
            }
        }
        let b = am.matrix(&r, &x);
        for i in 0..3 {
            for j in 0..3 {
                assert!((b[i][j] - p.vv[i][j]).abs() < 1e-12);
            }
        }
    }
}
