//! Air drag on the element (docs/method.md §2.8, eq. (17), (M11)): its
//! virtual work over a slab and the Jacobian matrices C_g, G_g at the time
//! points, and the static drag of a cable at rest in a moving fluid (§6.8).
//! Drag is integrated in space with the axial rule.

use super::slab::SlabDerivatives;
use super::CableElement;
use crate::loads::AirDrag;

impl<const NS: usize, const ND: usize> CableElement<NS, ND> {
    /// Static drag (a cable at rest in a moving fluid; docs/method.md §2.8,
    /// §6.8): subtracts the generalized force int N^T f(0, r_x) dx, times
    /// `factor`, from `grad` (= dU/dq) and its derivative from `hess`.
    pub fn add_static_drag(
        &self,
        drag: &AirDrag,
        factor: f64,
        q: &[f64; ND],
        grad: &mut [f64; ND],
        hess: Option<&mut [[f64; ND]; ND]>,
    ) {
        let mut hess = hess;
        for p in &self.axial_points {
            let (rx, _) = p.shape.gradients(q);
            let (f, _, dx) = drag.force(&[0.0; 3], &rx);
            for k in 0..NS {
                for i in 0..3 {
                    grad[3 * k + i] -= factor * p.wl * p.shape.n[k] * f[i];
                }
            }
            if let Some(h) = hess.as_deref_mut() {
                for k in 0..NS {
                    for l in 0..NS {
                        let b = factor * p.wl * p.shape.n[k] * p.shape.n_x[l];
                        for i in 0..3 {
                            for j in 0..3 {
                                h[3 * k + i][3 * l + j] -= b * dx[i][j];
                            }
                        }
                    }
                }
            }
        }
    }

    /// Drag at one time point of a slab, weight `w_dt`, for every load in
    /// `drags` (docs/method.md §2.8, (M11)): returns the generalized drag
    /// force on q, `f_q = sum_s w_s l N_k f`, adds its work
    /// `w_dt sum_s w_s l f . r_dot` to `out.drag_work` and, if `hessian_at`
    /// names the time point, adds to its matrices (zeroed by the caller)
    ///
    /// ```text
    ///   C_g = sum_s w_s l N_k N_l df/dr_dot,   G_g = sum_s w_s l N_k N_x,l df/dr_x
    /// ```
    pub(super) fn slab_drag_at_point(
        &self,
        drags: &[AirDrag],
        w_dt: f64,
        q: &[f64; ND],
        qdot: &[f64; ND],
        hessian_at: Option<usize>,
        out: &mut SlabDerivatives<ND>,
    ) -> [f64; ND] {
        let mut fq = [0.0; ND];
        for drag in drags {
            for p in &self.axial_points {
                let (rx, _) = p.shape.gradients(q);
                let mut rdot = [0.0; 3];
                for k in 0..NS {
                    for i in 0..3 {
                        rdot[i] += p.shape.n[k] * qdot[3 * k + i];
                    }
                }
                let (f, dv, dx) = drag.force(&rdot, &rx);
                out.drag_work += w_dt * p.wl * (f[0] * rdot[0] + f[1] * rdot[1] + f[2] * rdot[2]);
                for k in 0..NS {
                    for i in 0..3 {
                        fq[3 * k + i] += p.wl * p.shape.n[k] * f[i];
                    }
                }
                if let Some(gi) = hessian_at {
                    let (c, g) = (&mut out.c_at_points[gi], &mut out.g_at_points[gi]);
                    for k in 0..NS {
                        for l in 0..NS {
                            let a = p.wl * p.shape.n[k] * p.shape.n[l];
                            let b = p.wl * p.shape.n[k] * p.shape.n_x[l];
                            for i in 0..3 {
                                for j in 0..3 {
                                    c[3 * k + i][3 * l + j] += a * dv[i][j];
                                    g[3 * k + i][3 * l + j] += b * dx[i][j];
                                }
                            }
                        }
                    }
                }
            }
        }
        fq
    }
}
