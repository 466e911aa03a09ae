//! Seabed contact on the element (docs/method.md §12.2, (W40)-(W49)): the
//! contact force per unit length of [`crate::water::SeabedContact`], its
//! push integrated exactly on the element's pieces in the bed and its
//! friction at the axial rule (W47a), its virtual work over a slab with the matrices
//! C_g, G_g of its exact Jacobian at the time points, and its static form.

use super::point_force::seabed_parts;
use super::slab::SlabDerivatives;
use super::CableElement;
use crate::water::SeabedContact;

impl<const NS: usize, const ND: usize> CableElement<NS, ND> {
    /// The seabed at one time point of a slab, weight `w_dt` (W47): its
    /// generalized contact force into `fq`, its work into
    /// `out.seabed_work`, its derivatives into the point's C_g, G_g (see
    /// [`Self::slab_force_per_length`]). The push (W42) is integrated
    /// exactly where the element is in the bed, the friction (W44) at the
    /// axial rule (W47a).
    pub(super) fn slab_seabed_at_point(
        &self,
        contact: &SeabedContact,
        w_dt: f64,
        state: (&[f64; ND], &[f64; ND]),
        hessian_at: Option<usize>,
        fq: &mut [f64; ND],
        out: &mut SlabDerivatives<ND>,
    ) {
        for (along, part) in seabed_parts(contact) {
            out.seabed_work += self.slab_force_per_length(
                along,
                w_dt,
                state,
                hessian_at,
                fq,
                out,
                |_, r, rx, rdot, d| contact.part_at(part, r, rx, rdot, d),
            );
        }
    }

    /// Static contact (a line at rest on the bed, docs/method.md §12.2,
    /// (W48)): subtracts `factor int N^T f dx` of the contact force with
    /// friction against the slide from the seed coordinates `seed` from
    /// `grad` (= dU/dq) and its derivative from `hess`; integrated as in
    /// [`Self::slab_seabed_at_point`].
    pub fn add_static_seabed(
        &self,
        contact: &SeabedContact,
        factor: f64,
        (q, seed): (&[f64; ND], &[f64; ND]),
        grad: &mut [f64; ND],
        mut hess: Option<&mut [[f64; ND]; ND]>,
    ) {
        for (along, part) in seabed_parts(contact) {
            let h = hess.as_deref_mut();
            self.add_static_force_per_length(along, factor, (q, seed), grad, h, |r, rx, r0| {
                contact.static_part(part, r, rx, &std::array::from_fn(|i| r[i] - r0[i]))
            });
        }
    }
}
