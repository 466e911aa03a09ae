//! Seabed contact on the element (docs/method.md §12.2, (W40)-(W47)): the
//! contact force per unit length of [`crate::water::SeabedContact`] at the
//! points of the axial rule, its virtual work over a slab with the matrices
//! C_g, G_g of its exact Jacobian at the time points, and its static form.

use super::slab::SlabDerivatives;
use super::CableElement;
use crate::shape::SpatialShape;
use crate::water::{ForceAtPoint, SeabedContact};

/// r = sum_k N_k q_k at a spatial point.
fn position<const NS: usize>(shape: &SpatialShape<NS>, q: &[f64]) -> [f64; 3] {
    let mut r = [0.0; 3];
    for k in 0..NS {
        for (i, ri) in r.iter_mut().enumerate() {
            *ri += shape.n[k] * q[3 * k + i];
        }
    }
    r
}

impl<const NS: usize, const ND: usize> CableElement<NS, ND> {
    /// The seabed at one time point of a slab, weight `w_dt` (W47): adds
    /// the generalized contact force `f_q,k = sum_s w_s l N_k f` to `fq`,
    /// its work `w_dt sum_s w_s l f . r_dot` to `out.seabed_work` and, if
    /// `hessian_at` names the time point, its derivatives to the point's
    /// matrices (the position part joins G_g):
    ///
    /// ```text
    ///   C_g += sum_s w_s l N_k N_l df/dr_dot
    ///   G_g += sum_s w_s l N_k (N_l df/dr + N_x,l df/dr_x)
    /// ```
    pub(super) fn slab_seabed_at_point(
        &self,
        contact: &SeabedContact,
        w_dt: f64,
        (q, qdot): (&[f64; ND], &[f64; ND]),
        hessian_at: Option<usize>,
        fq: &mut [f64; ND],
        out: &mut SlabDerivatives<ND>,
    ) {
        for p in &self.axial_points {
            let r = position(&p.shape, q);
            let rdot = position(&p.shape, qdot);
            let (rx, _) = p.shape.gradients(q);
            let f = contact.force(&r, &rx, &rdot);
            if f == ForceAtPoint::default() {
                continue;
            }
            out.seabed_work += w_dt * p.wl * (0..3).map(|i| f.force[i] * rdot[i]).sum::<f64>();
            for k in 0..NS {
                for i in 0..3 {
                    fq[3 * k + i] += p.wl * p.shape.n[k] * f.force[i];
                }
            }
            if let Some(gi) = hessian_at {
                let (c, g) = (&mut out.c_at_points[gi], &mut out.g_at_points[gi]);
                add_point_derivatives(&p.shape, p.wl, &f, c, g);
            }
        }
    }

    /// Static contact (a line at rest on the bed, docs/method.md §12.2):
    /// subtracts `factor int N^T f(r, r_x, 0) dx` from `grad` (= dU/dq)
    /// and its derivative from `hess`.
    pub fn add_static_seabed(
        &self,
        contact: &SeabedContact,
        factor: f64,
        q: &[f64; ND],
        grad: &mut [f64; ND],
        mut hess: Option<&mut [[f64; ND]; ND]>,
    ) {
        let mut unused = [[0.0; ND]; ND];
        for p in &self.axial_points {
            let r = position(&p.shape, q);
            let (rx, _) = p.shape.gradients(q);
            let f = contact.force(&r, &rx, &[0.0; 3]);
            if f == ForceAtPoint::default() {
                continue;
            }
            for k in 0..NS {
                for i in 0..3 {
                    grad[3 * k + i] -= factor * p.wl * p.shape.n[k] * f.force[i];
                }
            }
            if let Some(h) = hess.as_deref_mut() {
                let mut g = [[0.0; ND]; ND];
                add_point_derivatives(&p.shape, p.wl, &f, &mut unused, &mut g);
                for (hr, gr) in h.iter_mut().zip(&g) {
                    for (hv, gv) in hr.iter_mut().zip(gr) {
                        *hv -= factor * gv;
                    }
                }
            }
        }
    }
}

/// The derivatives of the generalized force of a force per length at one
/// spatial point of weight `wl`: velocity part into `c`, position and
/// tangent parts into `g` (the formulas of
/// [`CableElement::slab_seabed_at_point`]).
fn add_point_derivatives<const NS: usize, const ND: usize>(
    shape: &SpatialShape<NS>,
    wl: f64,
    f: &ForceAtPoint,
    c: &mut [[f64; ND]; ND],
    g: &mut [[f64; ND]; ND],
) {
    for k in 0..NS {
        for l in 0..NS {
            let a = wl * shape.n[k] * shape.n[l];
            let b = wl * shape.n[k] * shape.n_x[l];
            for i in 0..3 {
                for j in 0..3 {
                    c[3 * k + i][3 * l + j] += a * f.d_rdot[i][j];
                    g[3 * k + i][3 * l + j] += a * f.d_r[i][j] + b * f.d_rx[i][j];
                }
            }
        }
    }
}
