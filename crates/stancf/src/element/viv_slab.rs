//! The VIV lift on a slab (docs/method.md §12.7, (V24)-(V26)): the
//! shedding phase phi of every point of the axial rule collocated over
//! the slab with the rule (V5) of the viscoelastic state, the lift's
//! virtual work at the slab's time points, and its exact Jacobian.
//!
//! The lift at time point g depends on the point's kinematics there and,
//! through phi_g, on the kinematics w_h = (r, r_x, r_dot, r_ddot) at every
//! node h of the collocation (its time points and its end). By the
//! implicit function theorem on (V5) with the rate (V22),
//!
//! ```text
//!   J = I - dt A diag(d rate / d phi),
//!   dZ/dw_h = J^-1 dt A e_h (d rate_h / d w_h)
//!   D_sgh = df_sg/dw_sh = delta_gh cos(phi_g) dL_sg/dw_sg
//!                         - sin(phi_g) L_sg (dZ_g/dw_h)^T
//!   dw_sh/dy_n: r, r_dot, r_ddot = (phi_n, phidot_n, phiddot_n)(h) N_s,
//!               r_x = phi_n(h) N_x,s
//!   block_mn += sum_s w_s l N_s (x) sum_g w_g dt phi_m(g) sum_h D_sgh dw_sh/dy_n
//! ```
//!
//! (L the lift without cos(phi), [`VivAtPoint::lift`]). The sums over g
//! and h are taken here, leaving per axial point and block (m, n) the two
//! 3 x 3 matrices that multiply N_s and N_x,s.

use super::slab::{SlabDerivatives, TimeSlab};
use super::viscoelastic::MAX_NODES;
use super::viv::{Viv, VivAtPoint, VivDerivatives, INPUTS, PHI, VIV_VALUES};
use super::CableElement;
use crate::water::LineInWater;

/// The kinematics of one axial point at the nodes of the collocation.
struct NodeKinematics {
    r: [f64; 3],
    rx: [f64; 3],
    rdot: [f64; 3],
    rddot: [f64; 3],
}

impl<const NS: usize, const ND: usize> CableElement<NS, ND> {
    /// The lift of `viv` in `water` over the slab from the state `start`
    /// (phi, A^2, B^2 per axial point) at time `t0`: fills `out.viv`.
    #[allow(clippy::too_many_arguments)]
    pub(super) fn slab_viv(
        &self,
        viv: &Viv,
        water: &LineInWater,
        slab: &TimeSlab,
        y: &[[f64; ND]; 4],
        (start, t0): (&[f64], f64),
        with_hessian: bool,
        out: &mut SlabDerivatives<ND>,
    ) {
        let np = slab.points.len();
        let nodes = np + 1;
        let ns = self.axial_points.len();
        assert_eq!(
            start.len(),
            ns * VIV_VALUES,
            "phi, A^2, B^2 of every axial point"
        );
        let shapes = time_shapes(slab);
        let o = &mut out.viv;
        o.active = true;
        o.lift.clear();
        o.lift.resize(np * ns, [0.0; 3]);
        o.end.clear();
        o.end.resize(ns * VIV_VALUES, 0.0);
        if with_hessian {
            o.by_shape.clear();
            o.by_shape.resize(ns * 16, [[0.0; 3]; 3]);
            o.by_slope.clear();
            o.by_slope.resize(ns * 16, [[0.0; 3]; 3]);
        }
        let a = &slab.collocation.dt_a;
        for (s, p) in self.axial_points.iter().enumerate() {
            let state = &start[s * VIV_VALUES..(s + 1) * VIV_VALUES];
            let squares = (state[1], state[2]);
            // The law at the nodes, and the point's velocity there (on
            // the stack: the residual allocates nothing per point).
            let mut rdot = [[0.0; 3]; MAX_NODES];
            let law: [VivAtPoint; MAX_NODES] = std::array::from_fn(|h| {
                if h >= nodes {
                    return VivAtPoint::still();
                }
                let k = self.kinematics_at(&p.shape, &shapes[h], y);
                rdot[h] = k.rdot;
                let when = t0 + shapes[h].0 * slab.dt;
                viv.at_point(water, (&k.r, &k.rx, &k.rdot, &k.rddot), when, squares)
            });
            let law = &law[..nodes];
            let (z, jac) = collocate_phase(viv, a, nodes, state[0], law);
            let end = &mut out.viv.end[s * VIV_VALUES..(s + 1) * VIV_VALUES];
            end[0] = z[np].rem_euclid(std::f64::consts::TAU);
            let samples = slab
                .points
                .iter()
                .zip(law)
                .map(|(tp, l)| (tp.w_dt, tp.offset, l.y_dot, l.y_ddot));
            (end[1], end[2]) = viv.mean_squares_after(slab.dt, squares, samples);
            for (g, tp) in slab.points.iter().enumerate() {
                let c = z[g].cos();
                let f = law[g].lift.map(|l| l.v * c);
                out.viv.lift[g * ns + s] = f;
                out.water_work += tp.w_dt * p.wl * (0..3).map(|i| f[i] * rdot[g][i]).sum::<f64>();
            }
            if with_hessian {
                let jacobian = PhaseJacobian {
                    z: &z,
                    jac: &jac,
                    law,
                };
                jacobian.add_blocks(viv, slab, &shapes, &mut out.viv, s);
            }
        }
    }

    /// The point's r, r_x, r_dot, r_ddot at a node with time shapes
    /// `(tau, phi, phidot, phiddot)`.
    fn kinematics_at(
        &self,
        shape: &crate::shape::SpatialShape<NS>,
        (_, t, tdot, tddot): &NodeShapes,
        y: &[[f64; ND]; 4],
    ) -> NodeKinematics {
        let mut out = NodeKinematics {
            r: [0.0; 3],
            rx: [0.0; 3],
            rdot: [0.0; 3],
            rddot: [0.0; 3],
        };
        for m in 0..4 {
            for k in 0..NS {
                for i in 0..3 {
                    let c = y[m][3 * k + i];
                    out.r[i] += t[m] * shape.n[k] * c;
                    out.rx[i] += t[m] * shape.n_x[k] * c;
                    out.rdot[i] += tdot[m] * shape.n[k] * c;
                    out.rddot[i] += tddot[m] * shape.n[k] * c;
                }
            }
        }
        out
    }

    /// The VIV's share of block (m, n) of the slab Hessian (see the
    /// file's header).
    pub(super) fn add_viv_block(
        &self,
        viv: &VivDerivatives,
        m: usize,
        n: usize,
        out: &mut [[f64; ND]; ND],
    ) {
        for (s, p) in self.axial_points.iter().enumerate() {
            let at = (s * 4 + m) * 4 + n;
            let (bs, bx) = (&viv.by_shape[at], &viv.by_slope[at]);
            for k in 0..NS {
                let nk = p.wl * p.shape.n[k];
                if nk == 0.0 {
                    continue;
                }
                for l in 0..NS {
                    let (nl, nxl) = (p.shape.n[l], p.shape.n_x[l]);
                    for i in 0..3 {
                        for j in 0..3 {
                            out[3 * k + i][3 * l + j] += nk * (bs[i][j] * nl + bx[i][j] * nxl);
                        }
                    }
                }
            }
        }
    }

    /// The generalized lift on the coordinates at time point `g`:
    /// `fq_k += sum_s w_s l N_k f_sg`.
    pub(super) fn add_viv_lift(&self, viv: &VivDerivatives, g: usize, fq: &mut [f64; ND]) {
        let ns = self.axial_points.len();
        for (s, p) in self.axial_points.iter().enumerate() {
            let f = viv.lift[g * ns + s];
            for k in 0..NS {
                for i in 0..3 {
                    fq[3 * k + i] += p.wl * p.shape.n[k] * f[i];
                }
            }
        }
    }

    /// The generalized force of the VIV lift (V23), f_L = 1/2 rho_w d Cl
    /// s cos(phi) |v_n| (t x v_n) at each axial point with its phase phi
    /// from `viv_state` (phi, A^2, B^2 per point), at the coordinates `q`,
    /// rates `qdot` and time `t` in `water` (the consistent nodal loads,
    /// (M14)). Zero for an element without VIV.
    pub fn viv_generalized_force(
        &self,
        (q, qdot): (&[f64; ND], &[f64; ND]),
        viv_state: &[f64],
        t: f64,
        water: &LineInWater,
    ) -> [f64; ND] {
        let Some(viv) = &self.section.viv else {
            return [0.0; ND];
        };
        self.generalized_force_at_points(q, qdot, |(s, _), r, rx, rdot| {
            // The lift does not depend on the acceleration or the mean
            // squares (they set the phase's rate only).
            let at = viv.at_point(water, (r, rx, rdot, &[0.0; 3]), t, (0.0, 0.0));
            let phi = viv_state[VIV_VALUES * s];
            at.lift.map(|c| c.v * phi.cos())
        })
    }

    /// The values of the internal state per axial point: the
    /// viscoelastic law's, then the VIV's (phi, A^2, B^2).
    pub fn internal_values_per_point(&self) -> usize {
        self.section
            .visco
            .as_ref()
            .map_or(0, super::Viscoelastic::values_per_point)
            + if self.section.viv.is_some() {
                VIV_VALUES
            } else {
                0
            }
    }

    /// An element's internal state split into the viscoelastic law's
    /// part (every axial point's) and the VIV's.
    pub fn split_internal<'a>(&self, internal: &'a [f64]) -> (&'a [f64], &'a [f64]) {
        let visco = self
            .section
            .visco
            .as_ref()
            .map_or(0, super::Viscoelastic::values_per_point);
        internal.split_at((self.axial_points.len() * visco).min(internal.len()))
    }

    /// The element's internal state at rest at coordinates `q`, its start
    /// at arc length `x0` of a line of length `length`: the
    /// viscoelastic law's rest ([`Self::rest_internal_state`]), then the
    /// VIV's ([`Self::rest_viv_state`]).
    pub fn rest_internal(&self, q: &[f64; ND], x0: f64, length: f64) -> Vec<f64> {
        let mut out = self.rest_internal_state(q);
        if self.section.viv.is_some() {
            out.extend(self.rest_viv_state(x0, length));
        }
        out
    }

    /// The VIV state at rest of an element whose start is at arc length
    /// `x0` of a line of length `length`: phi spread over 0..2 pi along
    /// the line (MoorDyn spreads its nodes' phases so), no mean squares.
    pub fn rest_viv_state(&self, x0: f64, length: f64) -> Vec<f64> {
        let l = self.length;
        self.axial_points
            .iter()
            .flat_map(|p| [std::f64::consts::TAU * (x0 + p.xi * l) / length, 0.0, 0.0])
            .collect()
    }
}

/// The phase's collocation at one axial point, solved: Z at the nodes,
/// J of (V25) and the law at every node.
struct PhaseJacobian<'a> {
    z: &'a [f64; MAX_NODES],
    jac: &'a [[f64; MAX_NODES]; MAX_NODES],
    law: &'a [VivAtPoint],
}

impl PhaseJacobian<'_> {
    /// Adds axial point s's share of every block (m, n) (V26): D_sgh
    /// = df_sg/dw_sh summed against dw_sh/dy_n and the test functions
    /// phi_m(g) w_g dt into the matrices of N_s and N_x,s.
    fn add_blocks(
        &self,
        viv: &Viv,
        slab: &TimeSlab,
        shapes: &[NodeShapes],
        out: &mut VivDerivatives,
        s: usize,
    ) {
        let (z, law) = (self.z, self.law);
        let np = slab.points.len();
        let nodes = np + 1;
        let a = &slab.collocation.dt_a;
        // dZ_g/dw_h (12 inputs), column h: J^-1 (dt A e_h) d rate_h/d w_h.
        let mut dz = [[[0.0; PHI]; MAX_NODES]; MAX_NODES];
        for h in 0..nodes {
            let rate = viv.rate(&law[h], super::dual::Dual::<INPUTS>::input(z[h], PHI));
            let col: [f64; MAX_NODES] = std::array::from_fn(|i| a[i][h]);
            let x = super::viscoelastic::solve_small(nodes, self.jac, &col);
            for g in 0..np {
                for k in 0..PHI {
                    dz[g][h][k] = x[g] * rate.d[k];
                }
            }
        }
        for (g, tp) in slab.points.iter().enumerate() {
            let (c, sn) = (z[g].cos(), z[g].sin());
            for h in 0..nodes {
                // D_sgh, 3 x 12.
                let d: [[f64; PHI]; 3] = std::array::from_fn(|i| {
                    std::array::from_fn(|k| {
                        let local = if g == h { c * law[g].lift[i].d[k] } else { 0.0 };
                        local - sn * law[g].lift[i].v * dz[g][h][k]
                    })
                });
                let (_, t, tdot, tddot) = &shapes[h];
                for m in 0..4 {
                    let wm = tp.w_dt * tp.shape.t[m];
                    for n in 0..4 {
                        let at = (s * 4 + m) * 4 + n;
                        let (bs, bx) = (&mut out.by_shape[at], &mut out.by_slope[at]);
                        for i in 0..3 {
                            for j in 0..3 {
                                bs[i][j] += wm
                                    * (d[i][j] * t[n]
                                        + d[i][6 + j] * tdot[n]
                                        + d[i][9 + j] * tddot[n]);
                                bx[i][j] += wm * d[i][3 + j] * t[n];
                            }
                        }
                    }
                }
            }
        }
    }
}

/// (tau, phi_m, phidot_m, phiddot_m) at a node of the collocation.
type NodeShapes = (f64, [f64; 4], [f64; 4], [f64; 4]);

/// The time shapes at the slab's time points and its end (the entries
/// past them unused).
fn time_shapes(slab: &TimeSlab) -> [NodeShapes; MAX_NODES] {
    let np = slab.points.len();
    std::array::from_fn(|h| {
        let tau = match h {
            _ if h < np => slab.points[h].offset / slab.dt,
            _ if h == np => 1.0,
            _ => return (0.0, [0.0; 4], [0.0; 4], [0.0; 4]),
        };
        let [t, tdot, tddot] = crate::shape::hermite3(tau, slab.dt);
        (tau, t, tdot, tddot)
    })
}

/// Solves (V5) for the phase: Z_i = phi0 + sum_j dt A_ij rate(Z_j), by
/// Newton from phi0; returns Z and J = I - dt A diag(d rate/d phi) at the
/// solution.
fn collocate_phase(
    viv: &Viv,
    a: &[[f64; MAX_NODES]; MAX_NODES],
    n: usize,
    phi0: f64,
    law: &[VivAtPoint],
) -> ([f64; MAX_NODES], [[f64; MAX_NODES]; MAX_NODES]) {
    use super::dual::Dual;
    let mut z = [phi0; MAX_NODES];
    let mut jac = [[0.0; MAX_NODES]; MAX_NODES];
    let mut rate = [(0.0, 0.0); MAX_NODES];
    let evaluate = |z: &[f64; MAX_NODES], rate: &mut [(f64, f64); MAX_NODES]| {
        for i in 0..n {
            let r = viv.rate(&law[i], Dual::input(z[i], PHI));
            rate[i] = (r.v, r.d[PHI]);
        }
    };
    for _ in 0..50 {
        evaluate(&z, &mut rate);
        let mut res = [0.0; MAX_NODES];
        for i in 0..n {
            res[i] = -(z[i] - phi0 - (0..n).map(|j| a[i][j] * rate[j].0).sum::<f64>());
            for j in 0..n {
                jac[i][j] = f64::from(u8::from(i == j)) - a[i][j] * rate[j].1;
            }
        }
        let dz = super::viscoelastic::solve_small(n, &jac, &res);
        let mut size = 0.0f64;
        for i in 0..n {
            z[i] += dz[i];
            size = size.max(dz[i].abs());
        }
        if size <= 1e-14 * (1.0 + phi0.abs()) {
            break;
        }
    }
    evaluate(&z, &mut rate);
    for i in 0..n {
        for j in 0..n {
            jac[i][j] = f64::from(u8::from(i == j)) - a[i][j] * rate[j].1;
        }
    }
    (z, jac)
}
