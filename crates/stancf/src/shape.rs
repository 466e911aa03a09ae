//! Hermite shape functions in space and time, eqs. (2)-(6)
//! (docs/method.md §1.2-1.5, (M1)).
//!
//! The space-time element interpolates every nodal coordinate separately in
//! space and time (eq. 2, the "Lagrange family" tensor product):
//!
//! ```text
//!   r(x, t) = sum_k N_k(xi) q_k(t),       xi  = x / l      (spatial, eq. 4 or 5)
//!   q_k(t)  = sum_m T_m(tau) y_km,        tau = t / dt     (temporal, eq. 6)
//! ```
//!
//! where `q_k` is a 3-vector nodal coordinate (r, r_x or r_xx of a node) and
//! `y_km` its value and velocity at the two time nodes. The slope functions
//! carry the factor l (space) or dt (time), the curvature functions l^2, so
//! every coordinate keeps its physical meaning (r_x is dr/dx, v is de/dt).

/// Values of the NS spatial shape functions of one element at one point,
/// and their first and second derivatives with respect to the material
/// coordinate x (not xi).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SpatialShape<const NS: usize> {
    pub n: [f64; NS],
    pub n_x: [f64; NS],
    pub n_xx: [f64; NS],
}

impl<const NS: usize> SpatialShape<NS> {
    /// r_x and r_xx at this point from the element coordinates q (entry
    /// 3 k + i is component i of the coordinate of shape function k).
    pub fn gradients(&self, q: &[f64]) -> ([f64; 3], [f64; 3]) {
        let mut rx = [0.0; 3];
        let mut rxx = [0.0; 3];
        for k in 0..NS {
            for i in 0..3 {
                rx[i] += self.n_x[k] * q[3 * k + i];
                rxx[i] += self.n_xx[k] * q[3 * k + i];
            }
        }
        (rx, rxx)
    }
}

/// The cubic Hermite basis on an interval of length h, the one kernel
/// behind eq. (4) in space, eq. (6) in time (docs/method.md §1.2, §1.4,
/// (M1)), a tabulated motion's interval and the step's predictor (§4.8).
/// With s = xi in [0, 1] for `[q(0), q'(0), q(h), q'(h)]`:
///
/// ```text
///   H1 = 1 - 3 s^2 + 2 s^3      H2 = h (s - 2 s^2 + s^3)
///   H3 = 3 s^2 - 2 s^3          H4 = h (-s^2 + s^3)
/// ```
///
/// Returns `[H, dH/dx, d2H/dx2]` with x = s h (the slope functions carry h,
/// so every coordinate keeps its physical meaning; h = 1 gives the basis
/// in s itself, bit for bit).
#[inline]
pub fn hermite3(xi: f64, h: f64) -> [[f64; 4]; 3] {
    let x = xi;
    let x2 = x * x;
    let x3 = x2 * x;
    [
        [
            1.0 - 3.0 * x2 + 2.0 * x3,
            h * (x - 2.0 * x2 + x3),
            3.0 * x2 - 2.0 * x3,
            h * (-x2 + x3),
        ],
        [
            (-6.0 * x + 6.0 * x2) / h,
            1.0 - 4.0 * x + 3.0 * x2,
            (6.0 * x - 6.0 * x2) / h,
            -2.0 * x + 3.0 * x2,
        ],
        [
            (-6.0 + 12.0 * x) / (h * h),
            (-4.0 + 6.0 * x) / h,
            (6.0 - 12.0 * x) / (h * h),
            (-2.0 + 6.0 * x) / h,
        ],
    ]
}

/// Cubic Hermite interpolation in space, eq. (4): coordinates
/// `[r(0), r_x(0), r(l), r_x(l)]` (SAC-2), the basis of [`hermite3`].
pub fn cubic_hermite(xi: f64, l: f64) -> SpatialShape<4> {
    let [n, n_x, n_xx] = hermite3(xi, l);
    SpatialShape { n, n_x, n_xx }
}

/// Quintic Hermite interpolation in space, eq. (5): coordinates
/// `[r(0), r_x(0), r_xx(0), r(l), r_x(l), r_xx(l)]` (SAC-3).
pub fn quintic_hermite(xi: f64, l: f64) -> SpatialShape<6> {
    let x = xi;
    let x2 = x * x;
    let x3 = x2 * x;
    let x4 = x3 * x;
    let x5 = x4 * x;
    let l2 = l * l;
    SpatialShape {
        n: [
            1.0 - 10.0 * x3 + 15.0 * x4 - 6.0 * x5,
            l * (x - 6.0 * x3 + 8.0 * x4 - 3.0 * x5),
            l2 * (0.5 * x2 - 1.5 * x3 + 1.5 * x4 - 0.5 * x5),
            10.0 * x3 - 15.0 * x4 + 6.0 * x5,
            l * (-4.0 * x3 + 7.0 * x4 - 3.0 * x5),
            l2 * (0.5 * x3 - x4 + 0.5 * x5),
        ],
        n_x: [
            (-30.0 * x2 + 60.0 * x3 - 30.0 * x4) / l,
            1.0 - 18.0 * x2 + 32.0 * x3 - 15.0 * x4,
            l * (x - 4.5 * x2 + 6.0 * x3 - 2.5 * x4),
            (30.0 * x2 - 60.0 * x3 + 30.0 * x4) / l,
            -12.0 * x2 + 28.0 * x3 - 15.0 * x4,
            l * (1.5 * x2 - 4.0 * x3 + 2.5 * x4),
        ],
        n_xx: [
            (-60.0 * x + 180.0 * x2 - 120.0 * x3) / l2,
            (-36.0 * x + 96.0 * x2 - 60.0 * x3) / l,
            1.0 - 9.0 * x + 18.0 * x2 - 10.0 * x3,
            (60.0 * x - 180.0 * x2 + 120.0 * x3) / l2,
            (-24.0 * x + 84.0 * x2 - 60.0 * x3) / l,
            3.0 * x - 12.0 * x2 + 10.0 * x3,
        ],
    }
}

/// Cubic Hermite interpolation in time, eq. (6), over a slab of length dt:
/// functions for `[e(t_a), v(t_a), e(t_b), v(t_b)]` and their time
/// derivatives d/dt.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TimeShape {
    pub t: [f64; 4],
    pub t_dot: [f64; 4],
}

/// Evaluates eq. (6) at tau = (t - t_a) / dt: the basis of [`hermite3`]
/// over the slab.
pub fn time_hermite(tau: f64, dt: f64) -> TimeShape {
    let [t, t_dot, _] = hermite3(tau, dt);
    TimeShape { t, t_dot }
}

#[cfg(test)]
mod tests {
    use super::*;

    const L: f64 = 0.37;

    fn fd_check<const NS: usize>(f: fn(f64, f64) -> SpatialShape<NS>) {
        let h = 1e-6;
        for &xi in &[0.0, 0.13, 0.5, 0.71, 1.0] {
            let s = f(xi, L);
            let p = f(xi + h, L);
            let m = f(xi - h, L);
            for k in 0..NS {
                let dx = (p.n[k] - m.n[k]) / (2.0 * h * L);
                let dxx = (p.n_x[k] - m.n_x[k]) / (2.0 * h * L);
                assert!((dx - s.n_x[k]).abs() < 1e-8, "N_x[{k}] at {xi}");
                assert!((dxx - s.n_xx[k]).abs() < 1e-6, "N_xx[{k}] at {xi}");
            }
        }
    }

    #[test]
    fn derivatives_match_finite_differences() {
        fd_check(cubic_hermite);
        fd_check(quintic_hermite);
        let h = 1e-6;
        let dt = 0.03;
        for &tau in &[0.0, 0.2, 0.5, 0.9] {
            let s = time_hermite(tau, dt);
            let p = time_hermite(tau + h, dt);
            let m = time_hermite(tau - h, dt);
            for k in 0..4 {
                let d = (p.t[k] - m.t[k]) / (2.0 * h * dt);
                assert!((d - s.t_dot[k]).abs() < 1e-7 * (1.0 + d.abs()));
            }
        }
    }

    /// Each function carries exactly one nodal value: the Kronecker property
    /// of r, r_x (and r_xx) at both ends.
    #[test]
    fn nodal_interpolation_property() {
        let c0 = cubic_hermite(0.0, L);
        let c1 = cubic_hermite(1.0, L);
        let expect = |v: [f64; 4], k: usize| {
            for (j, &x) in v.iter().enumerate() {
                assert!((x - if j == k { 1.0 } else { 0.0 }).abs() < 1e-14);
            }
        };
        expect(c0.n, 0);
        expect(c0.n_x, 1);
        expect(c1.n, 2);
        expect(c1.n_x, 3);
        let q0 = quintic_hermite(0.0, L);
        let q1 = quintic_hermite(1.0, L);
        let expect6 = |v: [f64; 6], k: usize| {
            for (j, &x) in v.iter().enumerate() {
                assert!(
                    (x - if j == k { 1.0 } else { 0.0 }).abs() < 1e-13,
                    "{v:?} {k}"
                );
            }
        };
        expect6(q0.n, 0);
        expect6(q0.n_x, 1);
        expect6(q0.n_xx, 2);
        expect6(q1.n, 3);
        expect6(q1.n_x, 4);
        expect6(q1.n_xx, 5);
        let t0 = time_hermite(0.0, 0.1);
        let t1 = time_hermite(1.0, 0.1);
        expect(t0.t, 0);
        expect(t0.t_dot, 1);
        expect(t1.t, 2);
        expect(t1.t_dot, 3);
    }

    /// Polynomials of the interpolation degree are reproduced exactly from
    /// their nodal values (cubic for eq. 4, quintic for eq. 5).
    #[test]
    fn reproduces_polynomials_of_full_degree() {
        let p = |x: f64| {
            0.3 - 1.2 * x + 0.7 * x * x + 2.1 * x.powi(3) - 0.9 * x.powi(4) + 0.4 * x.powi(5)
        };
        let dp = |x: f64| -1.2 + 1.4 * x + 6.3 * x * x - 3.6 * x.powi(3) + 2.0 * x.powi(4);
        let ddp = |x: f64| 1.4 + 12.6 * x - 10.8 * x * x + 8.0 * x.powi(3);
        let nodal = [p(0.0), dp(0.0), ddp(0.0), p(L), dp(L), ddp(L)];
        for &xi in &[0.1, 0.35, 0.8] {
            let s = quintic_hermite(xi, L);
            let v: f64 = (0..6).map(|k| s.n[k] * nodal[k]).sum();
            let vx: f64 = (0..6).map(|k| s.n_x[k] * nodal[k]).sum();
            let vxx: f64 = (0..6).map(|k| s.n_xx[k] * nodal[k]).sum();
            let x = xi * L;
            assert!((v - p(x)).abs() < 1e-13);
            assert!((vx - dp(x)).abs() < 1e-12);
            assert!((vxx - ddp(x)).abs() < 1e-11);
        }
        let c = |x: f64| 0.3 - 1.2 * x + 0.7 * x * x + 2.1 * x.powi(3);
        let dc = |x: f64| -1.2 + 1.4 * x + 6.3 * x * x;
        let nodal = [c(0.0), dc(0.0), c(L), dc(L)];
        for &xi in &[0.1, 0.35, 0.8] {
            let s = cubic_hermite(xi, L);
            let v: f64 = (0..4).map(|k| s.n[k] * nodal[k]).sum();
            assert!((v - c(xi * L)).abs() < 1e-14);
        }
    }
}
