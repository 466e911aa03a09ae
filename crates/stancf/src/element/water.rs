//! The water on the element (docs/method.md §12.3-12.4, (W18)-(W24)):
//! buoyancy, Morison drag and the fluid's inertia of
//! [`crate::water::LineInWater`] per unit length at the points of the
//! axial rule, evaluated with the sea's kinematics at each time point of
//! the slab (t = slab start + tau dt), its virtual work with the matrices
//! C_g, G_g of its exact Jacobian, and its static form (buoyancy and the
//! steady current).

use super::point_force::Along;
use super::slab::SlabDerivatives;
use super::CableElement;
use crate::water::{ElementFlow, LineInWater};

impl<const NS: usize, const ND: usize> CableElement<NS, ND> {
    /// The water at one time point of a slab, at time `t`, weight `w_dt`,
    /// under gravity `gravity` (W24): its generalized force into `fq`, its
    /// work into `out.water_work`, its derivatives into the point's C_g,
    /// G_g (see [`Self::slab_force_per_length`]). `host`: the flow a host
    /// has set at the element's end nodes, interpolated to each point of
    /// the axial rule (W2f) and added to the sea's (W2g).
    #[allow(clippy::too_many_arguments)]
    pub(super) fn slab_water_at_point(
        &self,
        (water, host): (&LineInWater, Option<&ElementFlow>),
        (t, w_dt): (f64, f64),
        gravity: &[f64; 3],
        state: (&[f64; ND], &[f64; ND]),
        hessian_at: Option<usize>,
        fq: &mut [f64; ND],
        out: &mut SlabDerivatives<ND>,
    ) {
        out.water_work += self.slab_force_per_length(
            Along::AxialRule,
            w_dt,
            state,
            hessian_at,
            fq,
            out,
            |xi, r, rx, rdot, d| water.force_at(r, rx, rdot, t, gravity, d, host.map(|h| h.at(xi))),
        );
    }

    /// The water on a line at rest (docs/method.md §12.4): subtracts
    /// `factor int N^T f dx` of buoyancy under `gravity` and the steady
    /// current's drag from `grad` (= dU/dq) and its derivative from `hess`.
    pub fn add_static_water(
        &self,
        water: &LineInWater,
        factor: f64,
        gravity: &[f64; 3],
        q: &[f64; ND],
        grad: &mut [f64; ND],
        hess: Option<&mut [[f64; ND]; ND]>,
    ) {
        self.add_static_force_per_length(
            Along::AxialRule,
            factor,
            (q, q),
            grad,
            hess,
            |r, rx, _| water.static_force(r, rx, gravity),
        );
    }
}
