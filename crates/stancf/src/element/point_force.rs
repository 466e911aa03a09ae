//! A force per unit length at the points of the axial rule, as the slab
//! sees it (docs/method.md §3.2, (M14)): the position of a point and the
//! derivatives of the generalized force, shared by the seabed (§12.2) and
//! the water (§12.3-12.4).

use super::slab::SlabDerivatives;
use super::{CableElement, SpacePoint};
use crate::shape::SpatialShape;
use crate::water::seabed::Part;
use crate::water::{ForceAtPoint, SeabedContact};

/// Where a force per length is integrated along an element: at the
/// points of its axial rule, or exactly on its pieces in the bed (the
/// seabed's push, (W47a)).
#[derive(Clone, Copy, Debug)]
pub(super) enum Along<'a> {
    AxialRule,
    InTheBed(&'a SeabedContact),
}

impl<const NS: usize, const ND: usize> CableElement<NS, ND> {
    /// A force per unit length `force(xi, r, r_x, r_dot, derivatives)` (xi:
    /// where the point is along the element, 0 to 1; its derivatives asked
    /// for only where the Jacobian is) at one time point of a slab, weight
    /// `w_dt`: adds the generalized force `f_q,k = sum_s w_s l N_k f` to
    /// `fq`, returns its work `w_dt sum_s w_s l f . r_dot` and, if
    /// `hessian_at` names the time point, adds its derivatives to the
    /// point's matrices (the position part joins G_g):
    ///
    /// ```text
    ///   C_g += sum_s w_s l N_k N_l df/dr_dot
    ///   G_g += sum_s w_s l N_k (N_l df/dr + N_x,l df/dr_x)
    /// ```
    #[allow(clippy::too_many_arguments)]
    pub(super) fn slab_force_per_length(
        &self,
        along: Along,
        w_dt: f64,
        (q, qdot): (&[f64; ND], &[f64; ND]),
        hessian_at: Option<usize>,
        fq: &mut [f64; ND],
        out: &mut SlabDerivatives<ND>,
        force: impl Fn(f64, &[f64; 3], &[f64; 3], &[f64; 3], bool) -> ForceAtPoint,
    ) -> f64 {
        let mut work = 0.0;
        self.for_each_point(along, q, |p| {
            let r = position(&p.shape, q);
            let rdot = position(&p.shape, qdot);
            let (rx, _) = p.shape.gradients(q);
            let f = force(p.xi, &r, &rx, &rdot, hessian_at.is_some());
            // Without a Hessian the derivatives are zero: the force says
            // whether the point adds anything.
            let nothing = match hessian_at {
                Some(_) => f == ForceAtPoint::default(),
                None => f.force == [0.0; 3],
            };
            if nothing {
                return;
            }
            work += w_dt * p.wl * (0..3).map(|i| f.force[i] * rdot[i]).sum::<f64>();
            for k in 0..NS {
                for i in 0..3 {
                    fq[3 * k + i] += p.wl * p.shape.n[k] * f.force[i];
                }
            }
            if let Some(gi) = hessian_at {
                let (c, g) = (&mut out.c_at_points[gi], &mut out.g_at_points[gi]);
                add_point_derivatives(&p.shape, p.wl, &f, c, g);
            }
        });
        work
    }

    /// Calls `visit` at the points `along` says, for coordinates `q`.
    fn for_each_point(&self, along: Along, q: &[f64; ND], visit: impl FnMut(&SpacePoint<NS>)) {
        match along {
            Along::AxialRule => self.axial_points.iter().for_each(visit),
            Along::InTheBed(contact) => self.for_each_contact_point(contact, q, visit),
        }
    }

    /// The generalized force `f_q,k = sum_s w_s l N_k f` of a force per
    /// unit length `force(xi, r, r_x, r_dot)` (xi: where the point is
    /// along the element, 0 to 1) at the element's coordinates `q` and
    /// rates `qdot` (the consistent nodal loads; (M14)).
    pub fn generalized_force_per_length(
        &self,
        q: &[f64; ND],
        qdot: &[f64; ND],
        force: impl Fn(f64, &[f64; 3], &[f64; 3], &[f64; 3]) -> ForceAtPoint,
    ) -> [f64; ND] {
        self.generalized_force_at_points(q, qdot, |(_, xi), r, rx, rdot| {
            force(xi, r, rx, rdot).force
        })
    }

    /// [`Self::generalized_force_per_length`] of `force(xi, part, r, r_x,
    /// rate)`: with `bed`, the seabed's contact force integrated as the
    /// slab and the static rows integrate it, the push exactly where the
    /// element is in the bed and the friction at the axial rule (W47a);
    /// without, any force at the axial rule (`part` Whole).
    pub(crate) fn generalized_force_on_bed(
        &self,
        bed: Option<&SeabedContact>,
        (q, rates): (&[f64; ND], &[f64; ND]),
        force: impl Fn(f64, Part, &[f64; 3], &[f64; 3], &[f64; 3]) -> ForceAtPoint,
    ) -> [f64; ND] {
        let mut fq = [0.0; ND];
        let parts = match bed {
            Some(contact) => {
                let mut parts = seabed_parts(contact);
                [parts.next(), parts.next()]
            }
            None => [Some((Along::AxialRule, Part::Whole)), None],
        };
        for (along, part) in parts.into_iter().flatten() {
            self.for_each_point(along, q, |p| {
                let r = position(&p.shape, q);
                let rate = position(&p.shape, rates);
                let (rx, _) = p.shape.gradients(q);
                let f = force(p.xi, part, &r, &rx, &rate).force;
                for k in 0..NS {
                    for i in 0..3 {
                        fq[3 * k + i] += p.wl * p.shape.n[k] * f[i];
                    }
                }
            });
        }
        fq
    }

    /// [`Self::generalized_force_per_length`] of a force per unit length
    /// `force((s, xi), r, r_x, r_dot)` that also depends on the axial
    /// point s (0, 1, ... in the element's axial rule: a state held there).
    pub fn generalized_force_at_points(
        &self,
        q: &[f64; ND],
        qdot: &[f64; ND],
        force: impl Fn((usize, f64), &[f64; 3], &[f64; 3], &[f64; 3]) -> [f64; 3],
    ) -> [f64; ND] {
        let mut fq = [0.0; ND];
        for (s, p) in self.axial_points.iter().enumerate() {
            let r = position(&p.shape, q);
            let rdot = position(&p.shape, qdot);
            let (rx, _) = p.shape.gradients(q);
            let f = force((s, p.xi), &r, &rx, &rdot);
            for k in 0..NS {
                for i in 0..3 {
                    fq[3 * k + i] += p.wl * p.shape.n[k] * f[i];
                }
            }
        }
        fq
    }

    /// A force per unit length `force(r, r_x, r_0)` on a line at rest, in
    /// the static rows (r_0: where the point was in the coordinates
    /// `seed`): subtracts `factor int N^T f dx` from `grad` (= dU/dq) and
    /// its derivative from `hess`.
    pub(super) fn add_static_force_per_length(
        &self,
        along: Along,
        factor: f64,
        (q, seed): (&[f64; ND], &[f64; ND]),
        grad: &mut [f64; ND],
        mut hess: Option<&mut [[f64; ND]; ND]>,
        force: impl Fn(&[f64; 3], &[f64; 3], &[f64; 3]) -> ForceAtPoint,
    ) {
        let mut unused = [[0.0; ND]; ND];
        self.for_each_point(along, q, |p| {
            let r = position(&p.shape, q);
            let r0 = position(&p.shape, seed);
            let (rx, _) = p.shape.gradients(q);
            let f = force(&r, &rx, &r0);
            if f == ForceAtPoint::default() {
                return;
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
        });
    }
}

/// r = sum_k N_k q_k at a spatial point.
pub(super) fn position<const NS: usize>(shape: &SpatialShape<NS>, q: &[f64]) -> [f64; 3] {
    let mut r = [0.0; 3];
    for k in 0..NS {
        for (i, ri) in r.iter_mut().enumerate() {
            *ri += shape.n[k] * q[3 * k + i];
        }
    }
    r
}

/// The derivatives of the generalized force of a force per length at one
/// spatial point of weight `wl`: velocity part into `c`, position and
/// tangent parts into `g` (the formulas of
/// [`CableElement::slab_force_per_length`]).
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

/// Where each part of the seabed's contact force is integrated (W47a):
/// the push exactly in the bed, the friction (if any) at the axial rule.
pub(super) fn seabed_parts(contact: &SeabedContact) -> impl Iterator<Item = (Along<'_>, Part)> {
    let friction = contact.seabed.has_friction();
    [(Along::InTheBed(contact), Part::Normal)]
        .into_iter()
        .chain(friction.then_some((Along::AxialRule, Part::Friction)))
}
