//! Axial (Kelvin-Voigt) damping of the element (docs/method.md §2.10,
//! (M34)-(M35)): the axial force EA eps + BA eps_dot; its virtual work over
//! a slab, `-int int BA eps_dot delta eps dx dt`, with the matrices C_g,
//! G_g of its exact Jacobian at the time points, on the points of the
//! axial rule (those of the axial strain energy).

use super::slab::SlabDerivatives;
use super::strain::axial_strain_derivatives;
use super::CableElement;

impl<const NS: usize, const ND: usize> CableElement<NS, ND> {
    /// The axial damping at one time point of a slab, weight `w_dt`
    /// (docs/method.md §2.10, (M34)): adds the generalized damping force
    /// to `fq`,
    ///
    /// ```text
    ///   s = -BA eps_dot a,   eps_dot = a . r_x_dot,   a = d eps / d r_x
    ///   f_q,k += sum_s w_s l N_x,k s
    /// ```
    ///
    /// adds its work `w_dt sum_s w_s l s . r_x_dot = -w_dt sum_s w_s l BA
    /// eps_dot^2` to `out.damping_work` and, if `hessian_at` names the
    /// time point, adds to its matrices (zeroed by the caller)
    ///
    /// ```text
    ///   ds/dr_x_dot = -BA a a^T,   ds/dr_x = -BA (a (H r_x_dot)^T + eps_dot H)
    ///   C_g += sum_s w_s l N_x,k N_x,l ds/dr_x_dot
    ///   G_g += sum_s w_s l N_x,k N_x,l ds/dr_x
    /// ```
    ///
    /// (`H = d2 eps / d r_x2`). Only called with BA != 0.
    pub(super) fn slab_damping_at_point(
        &self,
        w_dt: f64,
        q: &[f64; ND],
        qdot: &[f64; ND],
        hessian_at: Option<usize>,
        fq: &mut [f64; ND],
        out: &mut SlabDerivatives<ND>,
    ) {
        let ba = self.section.ba;
        for p in &self.axial_points {
            let (rx, _) = p.shape.gradients(q);
            let (rx_dot, _) = p.shape.gradients(qdot);
            let (a, h) = axial_strain_derivatives(self.measures.axial_strain, &rx);
            let eps_dot = a[0] * rx_dot[0] + a[1] * rx_dot[1] + a[2] * rx_dot[2];
            let s = a.map(|c| -ba * eps_dot * c);
            out.damping_work -= w_dt * p.wl * ba * eps_dot * eps_dot;
            let nx = &p.shape.n_x;
            for k in 0..NS {
                for i in 0..3 {
                    fq[3 * k + i] += p.wl * nx[k] * s[i];
                }
            }
            let Some(gi) = hessian_at else { continue };
            // H r_x_dot: the derivative of eps_dot with respect to r_x.
            let mut hv = [0.0; 3];
            for i in 0..3 {
                hv[i] = h[i][0] * rx_dot[0] + h[i][1] * rx_dot[1] + h[i][2] * rx_dot[2];
            }
            let mut ds_dv = [[0.0; 3]; 3];
            let mut ds_dx = [[0.0; 3]; 3];
            for i in 0..3 {
                for j in 0..3 {
                    ds_dv[i][j] = -ba * a[i] * a[j];
                    ds_dx[i][j] = -ba * (a[i] * hv[j] + eps_dot * h[i][j]);
                }
            }
            let (c, g) = (&mut out.c_at_points[gi], &mut out.g_at_points[gi]);
            for k in 0..NS {
                for l in 0..NS {
                    let b = p.wl * nx[k] * nx[l];
                    for i in 0..3 {
                        for j in 0..3 {
                            c[3 * k + i][3 * l + j] += b * ds_dv[i][j];
                            g[3 * k + i][3 * l + j] += b * ds_dx[i][j];
                        }
                    }
                }
            }
        }
    }
}
