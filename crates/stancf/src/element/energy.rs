//! The elastic energy U of eq. (12), integrated in space over the element
//! with the axial and the bending Gauss rules, and its gradient and exact
//! Hessian with respect to the element coordinates q (docs/method.md §2.4,
//! from the densities of §2.2 and §2.3; rules in §3.3).

use super::axial_curve::curve_energy_terms;
use super::curvature::{bending_energy_terms, curvature};
use super::strain::{axial_energy_terms, axial_strain};
use super::CableElement;

impl<const NS: usize, const ND: usize> CableElement<NS, ND> {
    /// Strain energy U of eq. (12) at element coordinates q.
    pub fn strain_energy(&self, q: &[f64; ND]) -> f64 {
        let mut u = 0.0;
        for p in &self.axial_points {
            let (rx, _) = p.shape.gradients(q);
            if let Some(c) = &self.section.curve {
                u += p.wl * curve_energy_terms(c, &rx, false, self.section.tension_only).0;
                continue;
            }
            let eps = axial_strain(self.measures.axial_strain, &rx);
            if !(self.section.tension_only && eps < 0.0) {
                u += p.wl * 0.5 * self.section.ea * eps * eps;
            }
        }
        u + self.bending_energy(q)
    }

    /// The bending share of [`Self::strain_energy`].
    pub fn bending_energy(&self, q: &[f64; ND]) -> f64 {
        self.bending_points
            .iter()
            .map(|p| {
                let (rx, rxx) = p.shape.gradients(q);
                let k = curvature(self.measures.curvature, &rx, &rxx);
                p.wl * 0.5 * self.section.ei * k * k
            })
            .sum()
    }

    /// Strain energy, its gradient dU/dq and (if asked) its Hessian d2U/dq2.
    ///
    /// With a = N_x and b = N_xx at a point, dU/dq_k = a_k dU/dr_x + b_k
    /// dU/dr_xx and the (k, l) 3x3 block of the Hessian is
    /// a_k a_l H_xx + a_k b_l H_xy + b_k a_l H_yx + b_k b_l H_yy.
    pub fn strain_energy_derivatives(
        &self,
        q: &[f64; ND],
        grad: &mut [f64; ND],
        hess: Option<&mut [[f64; ND]; ND]>,
    ) -> f64 {
        self.energy_derivatives_in::<3>(q, grad, hess, true)
    }

    /// [`Self::strain_energy_derivatives`] of a line held in the plane
    /// z = const (the planar reduction, docs/method.md §7.10): the x and y
    /// entries of the gradient and Hessian, the very numbers of the 3-D
    /// kernel (the densities are still those of the 3-vectors r_x, r_xx),
    /// and zero in every z row and column, which the reduced step has no
    /// unknowns or rows for. The accumulation, most of a Jacobian's cost,
    /// runs over 2 components instead of 3 (4 Hessian entries per block
    /// instead of 9).
    pub fn strain_energy_derivatives_in_plane(
        &self,
        q: &[f64; ND],
        grad: &mut [f64; ND],
        hess: Option<&mut [[f64; ND]; ND]>,
    ) -> f64 {
        self.energy_derivatives_in::<2>(q, grad, hess, true)
    }

    /// The strain energy's derivatives in a slab (3 or, `in_plane`, 2
    /// components): of a viscoelastic line only the bending energy's,
    /// its axial force being the history's (docs/method.md §2.11).
    pub(super) fn slab_energy_derivatives(
        &self,
        in_plane: bool,
        q: &[f64; ND],
        grad: &mut [f64; ND],
        hess: Option<&mut [[f64; ND]; ND]>,
    ) -> f64 {
        let axial = self.section.visco.is_none();
        if in_plane {
            self.energy_derivatives_in::<2>(q, grad, hess, axial)
        } else {
            self.energy_derivatives_in::<3>(q, grad, hess, axial)
        }
    }

    /// The derivatives in the first D components of every vector (3: all;
    /// 2: x and y); without the axial energy unless `axial`.
    #[inline(always)]
    fn energy_derivatives_in<const D: usize>(
        &self,
        q: &[f64; ND],
        grad: &mut [f64; ND],
        hess: Option<&mut [[f64; ND]; ND]>,
        axial: bool,
    ) -> f64 {
        *grad = [0.0; ND];
        let mut hess = hess;
        if let Some(h) = hess.as_deref_mut() {
            *h = [[0.0; ND]; ND];
        }
        let mut u = 0.0;
        let with_hessian = hess.is_some();
        let axial_points = if axial { &self.axial_points[..] } else { &[] };
        for p in axial_points {
            let (rx, _) = p.shape.gradients(q);
            let (e, g, h) = match &self.section.curve {
                Some(c) => curve_energy_terms(c, &rx, with_hessian, self.section.tension_only),
                None => axial_energy_terms(
                    self.measures.axial_strain,
                    self.section.ea,
                    &rx,
                    with_hessian,
                    self.section.tension_only,
                ),
            };
            u += p.wl * e;
            let a = &p.shape.n_x;
            for k in 0..NS {
                for i in 0..D {
                    grad[3 * k + i] += p.wl * a[k] * g[i];
                }
            }
            if let Some(hm) = hess.as_deref_mut() {
                for k in 0..NS {
                    for l in k..NS {
                        let c = p.wl * a[k] * a[l];
                        for i in 0..D {
                            for j in 0..D {
                                hm[3 * k + i][3 * l + j] += c * h[i][j];
                            }
                        }
                    }
                }
            }
        }
        for p in &self.bending_points {
            let (rx, rxx) = p.shape.gradients(q);
            let (e, g, h) = bending_energy_terms(
                self.measures.curvature,
                self.section.ei,
                &rx,
                &rxx,
                with_hessian,
            );
            u += p.wl * e;
            let a = &p.shape.n_x;
            let b = &p.shape.n_xx;
            for k in 0..NS {
                for i in 0..D {
                    grad[3 * k + i] += p.wl * (a[k] * g[i] + b[k] * g[3 + i]);
                }
            }
            if let Some(hm) = hess.as_deref_mut() {
                for k in 0..NS {
                    for l in k..NS {
                        let aa = p.wl * a[k] * a[l];
                        let ab = p.wl * a[k] * b[l];
                        let ba = p.wl * b[k] * a[l];
                        let bb = p.wl * b[k] * b[l];
                        for i in 0..D {
                            for j in 0..D {
                                hm[3 * k + i][3 * l + j] += aa * h[i][j]
                                    + ab * h[i][3 + j]
                                    + ba * h[3 + i][j]
                                    + bb * h[3 + i][3 + j];
                            }
                        }
                    }
                }
            }
        }
        if let Some(hm) = hess {
            // Mirror the blocks l < k from the computed upper block triangle.
            for k in 0..NS {
                for l in 0..k {
                    for i in 0..D {
                        for j in 0..D {
                            hm[3 * k + i][3 * l + j] = hm[3 * l + j][3 * k + i];
                        }
                    }
                }
            }
        }
        u
    }
}
