//! Curvature of the centre line, eq. (9) as printed or the exact form, and
//! the bending energy density `1/2 EI kappa^2` with its gradient and Hessian
//! with respect to (r_x, r_xx), written in the smooth squared form
//! kappa^2 = |r_x x r_xx|^2 / (|r_x|^2)^p (docs/method.md §2.3, (M5)-(M6);
//! the second term of eq. (12), §2.4).

use super::Curvature;
use crate::vec3::{cross, dot};

/// Curvature of the centre line from r_x and r_xx (eq. 9 or the exact form).
pub fn curvature(form: Curvature, rx: &[f64; 3], rxx: &[f64; 3]) -> f64 {
    let c = cross(rx, rxx);
    let g = dot(rx, rx);
    dot(c, c).sqrt() / g.powf(0.5 * form.power() as f64)
}

/// Bending energy density `1/2 EI kappa^2` (eq. 12, second term), with its
/// gradient and Hessian with respect to `(r_x, r_xx)` (6 numbers;
/// docs/method.md §2.3, (M5)-(M6)).
///
/// Written with x = r_x, y = r_xx, g = x.x, h = y.y, m = x.y and
/// s = |x cross y|^2 = g h - m^2, so kappa^2 = s g^-p (p = 2 for eq. 9,
/// p = 3 for the exact curvature): a form that is smooth at the straight
/// state (s = 0), unlike kappa itself.
///
/// ```text
///   ds/dx = 2h x - 2m y                 ds/dy = 2g y - 2m x
///   d2s/dxdx = 2h I - 2 y y^T           d2s/dydy = 2g I - 2 x x^T
///   d2s/dxdy = 4 x y^T - 2 y x^T - 2m I
///   f = s g^-p:
///   df/dx = g^-p ds/dx - 2p s g^-p-1 x,           df/dy = g^-p ds/dy
///   d2f/dxdx = g^-p d2s/dxdx - 2p g^-p-1 (ds/dx x^T + x ds/dx^T)
///              + 4p(p+1) s g^-p-2 x x^T - 2p s g^-p-1 I
///   d2f/dxdy = g^-p d2s/dxdy - 2p g^-p-1 x ds/dy^T,  d2f/dydy = g^-p d2s/dydy
/// ```
pub fn bending_energy_density(
    form: Curvature,
    ei: f64,
    rx: &[f64; 3],
    rxx: &[f64; 3],
) -> (f64, [f64; 6], [[f64; 6]; 6]) {
    bending_energy_terms(form, ei, rx, rxx, true)
}

/// [`bending_energy_density`] without the Hessian (a residual evaluation).
#[inline]
pub fn bending_energy_gradient(
    form: Curvature,
    ei: f64,
    rx: &[f64; 3],
    rxx: &[f64; 3],
) -> (f64, [f64; 6]) {
    let (e, g, _) = bending_energy_terms(form, ei, rx, rxx, false);
    (e, g)
}

#[inline(always)]
pub(super) fn bending_energy_terms(
    form: Curvature,
    ei: f64,
    rx: &[f64; 3],
    rxx: &[f64; 3],
    with_hessian: bool,
) -> (f64, [f64; 6], [[f64; 6]; 6]) {
    let x = rx;
    let y = rxx;
    let g = dot(x, x);
    let h = dot(y, y);
    let m = dot(x, y);
    let s = g * h - m * m;
    let p = form.power();
    let pf = p as f64;
    // g^-p as 1 / g^p with the products powi itself forms (the same
    // bits, without its library call).
    let gp = match p {
        2 => 1.0 / (g * g),
        _ => 1.0 / (g * (g * g)),
    };
    let gp1 = gp / g;
    let gp2 = gp1 / g;
    let mut ds_x = [0.0; 3];
    let mut ds_y = [0.0; 3];
    for i in 0..3 {
        ds_x[i] = 2.0 * h * x[i] - 2.0 * m * y[i];
        ds_y[i] = 2.0 * g * y[i] - 2.0 * m * x[i];
    }
    let c = 0.5 * ei;
    let mut grad = [0.0; 6];
    for i in 0..3 {
        grad[i] = c * (gp * ds_x[i] - 2.0 * pf * s * gp1 * x[i]);
        grad[3 + i] = c * gp * ds_y[i];
    }
    let mut hess = [[0.0; 6]; 6];
    if !with_hessian {
        return (c * s * gp, grad, hess);
    }
    for i in 0..3 {
        for j in 0..3 {
            let d = if i == j { 1.0 } else { 0.0 };
            let s_xx = 2.0 * h * d - 2.0 * y[i] * y[j];
            let s_yy = 2.0 * g * d - 2.0 * x[i] * x[j];
            let s_xy = 4.0 * x[i] * y[j] - 2.0 * y[i] * x[j] - 2.0 * m * d;
            let f_xx = gp * s_xx - 2.0 * pf * gp1 * (ds_x[i] * x[j] + x[i] * ds_x[j])
                + 4.0 * pf * (pf + 1.0) * s * gp2 * x[i] * x[j]
                - 2.0 * pf * s * gp1 * d;
            let f_xy = gp * s_xy - 2.0 * pf * gp1 * x[i] * ds_y[j];
            let f_yy = gp * s_yy;
            hess[i][3 + j] = c * f_xy;
            hess[3 + j][i] = c * f_xy;
            if j >= i {
                // Exactly symmetric diagonal blocks: computed once, mirrored.
                hess[i][j] = c * f_xx;
                hess[j][i] = c * f_xx;
                hess[3 + i][3 + j] = c * f_yy;
                hess[3 + j][3 + i] = c * f_yy;
            }
        }
    }
    (c * s * gp, grad, hess)
}
