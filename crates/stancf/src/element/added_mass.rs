//! The entrained water's kinetic energy on the element (docs/method.md
//! §12.5, (W28)-(W31)): T_a of [`AddedMass`] integrated over the element at
//! the NS Gauss points of its mass matrix, its part of the slab action,
//! gradient and exact Hessian, and the momentum it adds at a time node.
//!
//! At a spatial point of weight `wl` with shape functions N_k, N_x,k, for
//! element coordinates q and rates qdot (W28):
//!
//! ```text
//!   dT/dqdot_k = wl N_k T_v          dT/dq_k = wl (N_k T_r + N_x,k T_x)
//!   V[k,l] = wl N_k N_l T_vv                                 (qdot qdot)
//!   X[k,l] = wl N_k (N_l T_vr + N_x,l T_vx)                  (qdot q)
//!   Z[k,l] = wl (N_k N_l T_rr + N_k N_x,l T_rx + N_x,k N_l T_rx^T
//!               + N_x,k N_x,l T_xx)                          (q q)
//! ```
//!
//! and the slab's Hessian block (m, n) gains (W29)
//! `sum_g w_g dt (Tdot_m Tdot_n V_g + Tdot_m T_n X_g + T_m Tdot_n X_g^T
//! + T_m T_n Z_g)`.

use super::slab::TimeSlab;
use super::CableElement;
use crate::water::{AddedMass, EntrainedAtPoint, EntrainedFirst};

type Block<const ND: usize> = [[f64; ND]; ND];

/// The matrices V_g, X_g, Z_g of (W28) at the slab's time points, and
/// whether the element has added mass in this slab.
#[derive(Clone, Debug, Default)]
pub struct AddedMassDerivatives<const ND: usize> {
    pub active: bool,
    pub vv: Vec<Block<ND>>,
    pub vq: Vec<Block<ND>>,
    pub qq: Vec<Block<ND>>,
}

impl<const ND: usize> AddedMassDerivatives<ND> {
    /// Room for `np` time points (allocates only when it grows).
    pub(super) fn reserve(&mut self, np: usize) {
        if self.vv.len() < np {
            self.vv.resize(np, [[0.0; ND]; ND]);
            self.vq.resize(np, [[0.0; ND]; ND]);
            self.qq.resize(np, [[0.0; ND]; ND]);
        }
    }
}

impl<const NS: usize, const ND: usize> CableElement<NS, ND> {
    /// T_a integrated over the element (W28) at coordinates q and rates
    /// qdot; its derivatives added to `d_q` and `d_qdot`, and, if
    /// `hessian` is given, V, X, Z written to it.
    pub fn entrained_energy(
        &self,
        am: &AddedMass,
        (q, qdot): (&[f64; ND], &[f64; ND]),
        d_q: &mut [f64; ND],
        d_qdot: &mut [f64; ND],
        mut hessian: Option<(&mut Block<ND>, &mut Block<ND>, &mut Block<ND>)>,
    ) -> f64 {
        if let Some((v, x, z)) = hessian.as_mut() {
            **v = [[0.0; ND]; ND];
            **x = [[0.0; ND]; ND];
            **z = [[0.0; ND]; ND];
        }
        let mut energy = 0.0;
        for p in &self.mass_points {
            let (n, nx) = (&p.shape.n, &p.shape.n_x);
            let r = combine(n, q);
            let rx = combine(nx, q);
            let rdot = combine(n, qdot);
            let t = match hessian.as_mut() {
                Some((v, x, z)) => {
                    let t = am.at_point(&r, &rx, &rdot, true);
                    add_point_blocks(n, nx, p.wl, &t, v, x, z);
                    EntrainedFirst {
                        energy: t.energy,
                        d_v: t.d_v,
                        d_rz: t.d_r[2],
                        d_x: t.d_x,
                    }
                }
                None => match am.first_derivatives(&r, &rx, &rdot) {
                    Some(t) => t,
                    None => continue,
                },
            };
            energy += p.wl * t.energy;
            let d_r = [0.0, 0.0, t.d_rz];
            for k in 0..NS {
                for i in 0..3 {
                    d_qdot[3 * k + i] += p.wl * n[k] * t.d_v[i];
                    d_q[3 * k + i] += p.wl * (n[k] * d_r[i] + nx[k] * t.d_x[i]);
                }
            }
        }
        energy
    }

    /// The momentum the entrained water adds at a time node, dT_a/dqdot
    /// (W30), added to `p`; with `derivatives`, its Jacobians d/dq (X)
    /// and d/dqdot (V) written there.
    pub fn entrained_momentum(
        &self,
        am: &AddedMass,
        (q, qdot): (&[f64; ND], &[f64; ND]),
        p: &mut [f64; ND],
        derivatives: Option<(&mut Block<ND>, &mut Block<ND>)>,
    ) {
        let mut unused = [0.0; ND];
        match derivatives {
            Some((dq, dqdot)) => {
                let mut z = [[0.0; ND]; ND];
                self.entrained_energy(am, (q, qdot), &mut unused, p, Some((dqdot, dq, &mut z)));
            }
            None => {
                self.entrained_energy(am, (q, qdot), &mut unused, p, None);
            }
        }
    }

    /// The element's added mass matrix at coordinates q,
    /// `sum_s wl N_k N_l c s B` (the V of (W28), independent of the rates).
    pub fn entrained_mass(&self, am: &AddedMass, q: &[f64; ND], out: &mut Block<ND>) {
        *out = [[0.0; ND]; ND];
        for p in &self.mass_points {
            let (n, nx) = (&p.shape.n, &p.shape.n_x);
            let b = am.matrix(&combine(n, q), &combine(nx, q));
            for k in 0..NS {
                for l in 0..NS {
                    let a = p.wl * n[k] * n[l];
                    for i in 0..3 {
                        for j in 0..3 {
                            out[3 * k + i][3 * l + j] += a * b[i][j];
                        }
                    }
                }
            }
        }
    }

    /// Adds the added mass's part of Hessian block (m, n) (W29) that the
    /// time points' C_g and G_g do not carry: `sum_g w_g dt (Tdot_m Tdot_n
    /// V_g + Tdot_m T_n X_g)` (its `T_m Tdot_n X_g^T` and `T_m T_n Z_g` are
    /// combined into them, [`super::slab`]'s `combine_at_points`).
    pub(super) fn add_entrained_block(
        &self,
        slab: &TimeSlab,
        derivs: &AddedMassDerivatives<ND>,
        m: usize,
        n: usize,
        out: &mut Block<ND>,
    ) {
        for (gi, tp) in slab.points.iter().enumerate() {
            let (t, td) = (&tp.shape.t, &tp.shape.t_dot);
            let a = tp.w_dt * td[m] * td[n];
            let b = tp.w_dt * td[m] * t[n];
            let (v, x) = (&derivs.vv[gi], &derivs.vq[gi]);
            for ((orow, vrow), xrow) in out.iter_mut().zip(v).zip(x) {
                for ((o, vv), xv) in orow.iter_mut().zip(vrow).zip(xrow) {
                    *o += a * vv + b * xv;
                }
            }
        }
    }
}

/// sum_k w_k q_k (a 3-vector at a spatial point).
fn combine<const NS: usize>(w: &[f64; NS], q: &[f64]) -> [f64; 3] {
    let mut r = [0.0; 3];
    for k in 0..NS {
        for (i, ri) in r.iter_mut().enumerate() {
            *ri += w[k] * q[3 * k + i];
        }
    }
    r
}

/// One spatial point's V, X, Z of (W28).
fn add_point_blocks<const NS: usize, const ND: usize>(
    n: &[f64; NS],
    nx: &[f64; NS],
    wl: f64,
    t: &EntrainedAtPoint,
    v: &mut Block<ND>,
    x: &mut Block<ND>,
    z: &mut Block<ND>,
) {
    for k in 0..NS {
        for l in 0..NS {
            let nn = wl * n[k] * n[l];
            let nnx = wl * n[k] * nx[l];
            let nxn = wl * nx[k] * n[l];
            let nxnx = wl * nx[k] * nx[l];
            for i in 0..3 {
                for j in 0..3 {
                    let (a, b) = (3 * k + i, 3 * l + j);
                    v[a][b] += nn * t.vv[i][j];
                    x[a][b] += nn * t.vr[i][j] + nnx * t.vx[i][j];
                    z[a][b] +=
                        nn * t.rr[i][j] + nnx * t.rx[i][j] + nxn * t.rx[j][i] + nxnx * t.xx[i][j];
                }
            }
        }
    }
}
