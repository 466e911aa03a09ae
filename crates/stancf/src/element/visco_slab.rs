//! A viscoelastic line's axial force on a slab (docs/method.md §2.11,
//! (V5)-(V6)): the internal strain eps1 of every point of the axial rule
//! collocated over the slab ([`Viscoelastic::collocate`]), the virtual
//! work of the axial forces N_sg at the slab's time points in place of the
//! axial strain energy, and its exact Jacobian. N_sg depends on the
//! strains of its axial point s at every time node of the slab (its Gauss
//! points and its end), so the Jacobian couples the time points:
//!
//! ```text
//!   dW/dy_m   = -sum_g w_g dt phi_m(g) sum_s w_s l N_sg d eps_sg/dq
//!   d eps_sh/dy_n     = phi_n(h) N_x (x) a_sh
//!   d eps_dot_sh/dy_n = N_x (x) (phi_n(h) H_sh r_x_dot + phidot_n(h) a_sh)
//!   V_sgn = sum_h dN_sg/d eps_sh phi_n(h) a_sh
//!                 + dN_sg/d eps_dot_sh (phi_n(h) H_sh r_x_dot + phidot_n(h) a_sh)
//!   block_mn += -sum_s w_s l N_x N_x^T (x) sum_g w_g dt phi_m(g) a_sg V_sgn^T
//! ```
//!
//! (a = d eps/d r_x, H = d2 eps/d r_x2), beside the time-local geometric
//! part sum_s w_s l N_sg N_x N_x^T (x) H_sg that joins the strain
//! Hessian K_g. The dashpots' work, -sum w dt w_s l (c1 eps1_dot^2 +
//! c2 (eps_dot - eps1_dot)^2), is the damping work of the slab.

use super::slab::{interpolate_in_time, SlabDerivatives, TimeSlab};
use super::strain::{axial_strain, axial_strain_derivatives};
use super::viscoelastic::{Viscoelastic, MAX_NODES};
use super::CableElement;

impl<const NS: usize, const ND: usize> CableElement<NS, ND> {
    /// The viscoelastic axial forces of the slab from the internal state
    /// `start` at its start ([`Viscoelastic::values_per_point`] per axial
    /// point): fills `out.visco` and adds the dashpots' work to
    /// `out.damping_work`.
    pub(super) fn slab_viscoelastic(
        &self,
        visco: &Viscoelastic,
        slab: &TimeSlab,
        y: &[[f64; ND]; 4],
        start: &[f64],
        with_hessian: bool,
        out: &mut SlabDerivatives<ND>,
    ) {
        let np = slab.points.len();
        let nodes = np + 1;
        let ns = self.axial_points.len();
        let per = visco.values_per_point();
        assert_eq!(
            start.len(),
            ns * per,
            "the internal state of every axial point"
        );
        let v_out = &mut out.visco;
        v_out.active = true;
        v_out.force.resize(np * ns, 0.0);
        v_out.end.resize(ns * per, 0.0);
        if with_hessian {
            v_out.a.resize(ns * np, [0.0; 3]);
            v_out.v.resize(ns * np, [[0.0; 3]; 4]);
        }
        let shapes: [_; MAX_NODES] = std::array::from_fn(|h| {
            if h < np {
                slab.points[h].shape
            } else {
                slab.end
            }
        });
        let mut q = [[0.0; ND]; MAX_NODES];
        let mut qdot = [[0.0; ND]; MAX_NODES];
        for h in 0..nodes {
            (q[h], qdot[h]) = interpolate_in_time(&shapes[h], y);
        }
        let ea = self.section.ea;
        let measure = self.measures.axial_strain;
        let mut eps = [0.0; MAX_NODES];
        let mut eps_dot = [0.0; MAX_NODES];
        let mut slack = [false; MAX_NODES];
        let mut a = [[0.0; 3]; MAX_NODES];
        let mut hv = [[0.0; 3]; MAX_NODES];
        for (s, p) in self.axial_points.iter().enumerate() {
            for h in 0..nodes {
                let (rx, _) = p.shape.gradients(&q[h]);
                let (rx_dot, _) = p.shape.gradients(&qdot[h]);
                let (d, hh) = axial_strain_derivatives(measure, &rx);
                eps[h] = axial_strain(measure, &rx);
                eps_dot[h] = (0..3).map(|i| d[i] * rx_dot[i]).sum();
                slack[h] = self.section.tension_only && eps[h] < 0.0;
                a[h] = d;
                hv[h] = std::array::from_fn(|i| (0..3).map(|j| hh[i][j] * rx_dot[j]).sum());
            }
            let history = if per > 1 { start[s * per + 1] } else { 0.0 };
            let c = visco.collocate(
                ea,
                &slab.collocation,
                (start[s * per], history),
                &eps,
                &eps_dot,
                &slack,
            );
            v_out.end[s * per] = c.state[np];
            if per > 1 {
                v_out.end[s * per + 1] = visco.history_after(history, &c.state[..nodes]);
            }
            if per > 2 {
                v_out.end[s * per + 2] = start[s * per + 2];
            }
            for (g, tp) in slab.points.iter().enumerate() {
                v_out.force[g * ns + s] = c.force[g];
                if per > 2 {
                    // Syrope: the law's work is its energy (V11).
                    v_out.end[s * per + 2] += tp.w_dt * c.force[g] * eps_dot[g];
                } else {
                    out.damping_work -= tp.w_dt * p.wl * visco.dissipation(c.rate[g], eps_dot[g]);
                }
            }
            if !with_hessian {
                continue;
            }
            for g in 0..np {
                v_out.a[s * np + g] = a[g];
                let mut vg = [[0.0; 3]; 4];
                for (n, vn) in vg.iter_mut().enumerate() {
                    for h in 0..nodes {
                        let (phi, phidot) = (shapes[h].t[n], shapes[h].t_dot[n]);
                        let (de, dr) = (c.d_eps[g][h], c.d_rate[g][h]);
                        for i in 0..3 {
                            vn[i] += de * phi * a[h][i] + dr * (phi * hv[h][i] + phidot * a[h][i]);
                        }
                    }
                }
                v_out.v[s * np + g] = vg;
            }
        }
    }

    /// The viscoelastic forces' coupling of the time points in block
    /// (m, n) of the slab Hessian (the last line of the module's
    /// formulas), added to `out`.
    pub(super) fn add_visco_block(
        &self,
        slab: &TimeSlab,
        derivs: &SlabDerivatives<ND>,
        m: usize,
        n: usize,
        out: &mut [[f64; ND]; ND],
    ) {
        let np = slab.points.len();
        let v = &derivs.visco;
        for (s, p) in self.axial_points.iter().enumerate() {
            let mut block = [[0.0; 3]; 3];
            for (g, tp) in slab.points.iter().enumerate() {
                let w = tp.w_dt * tp.shape.t[m];
                let (a, vg) = (&v.a[s * np + g], &v.v[s * np + g][n]);
                for i in 0..3 {
                    for j in 0..3 {
                        block[i][j] += w * a[i] * vg[j];
                    }
                }
            }
            let nx = &p.shape.n_x;
            for k in 0..NS {
                for l in 0..NS {
                    let c = -p.wl * nx[k] * nx[l];
                    for i in 0..3 {
                        for j in 0..3 {
                            out[3 * k + i][3 * l + j] += c * block[i][j];
                        }
                    }
                }
            }
        }
    }

    /// The rest state of the element's internal strains at coordinates
    /// `q` ([`Viscoelastic::rest_state`] at every axial point), or none.
    pub fn rest_internal_state(&self, q: &[f64; ND]) -> Vec<f64> {
        let Some(visco) = &self.section.visco else {
            return Vec::new();
        };
        let measure = self.measures.axial_strain;
        let (ea, history) = (self.section.ea, visco.initial_history());
        let mut out = Vec::with_capacity(self.axial_points.len() * visco.values_per_point());
        for p in &self.axial_points {
            let eps = axial_strain(measure, &p.shape.gradients(q).0);
            let eps1 = visco.rest_state(ea, eps, history);
            out.push(eps1);
            if visco.values_per_point() > 1 {
                out.push(visco.history_after(history, &[eps1]));
            }
            if visco.values_per_point() > 2 {
                out.push(0.0); // the law's work since the start
            }
        }
        out
    }

    /// A viscoelastic element's axial force N (V1) at xi (0 to 1) for
    /// coordinates `q`, rates `qdot` and internal strains `internal` at
    /// its axial points, eps1 at xi being their Lagrange polynomial
    /// (extrapolated to the ends); None for an element without the law.
    pub fn visco_axial_force(
        &self,
        xi: f64,
        q: &[f64],
        qdot: &[f64],
        internal: &[f64],
    ) -> Option<f64> {
        let visco = self.section.visco.as_ref()?;
        let pts = &self.axial_points;
        let per = visco.values_per_point();
        // The Lagrange polynomial through the axial points' value k.
        let at_xi = |k: usize| -> f64 {
            pts.iter()
                .enumerate()
                .map(|(j, pj)| {
                    let basis: f64 = pts
                        .iter()
                        .enumerate()
                        .filter(|&(m, _)| m != j)
                        .map(|(_, pm)| (xi - pm.xi) / (pj.xi - pm.xi))
                        .product();
                    basis * internal[j * per + k]
                })
                .sum()
        };
        let eps1 = at_xi(0);
        let history = if per > 1 { at_xi(1) } else { 0.0 };
        let shape = (self.shape)(xi, self.length);
        let (rx, _) = shape.gradients(q);
        let (rx_dot, _) = shape.gradients(qdot);
        let measure = self.measures.axial_strain;
        let (a, _) = axial_strain_derivatives(measure, &rx);
        let eps = axial_strain(measure, &rx);
        let eps_dot = (0..3).map(|i| a[i] * rx_dot[i]).sum();
        let slack = self.section.tension_only && eps < 0.0;
        Some(
            visco
                .force(self.section.ea, eps1, history, eps, eps_dot, slack)
                .force,
        )
    }

    /// A viscoelastic element as the elastic one it is to a fast motion
    /// (what the P2 step's stable step is judged on, docs/method.md
    /// §2.11): the static spring's dashpot holds it, so its axial
    /// stiffness is the dynamic k2, of the mean-load form at the rest
    /// state of the element's largest strain at coordinates `q`. None
    /// for an elastic element.
    pub fn instantaneous(&self, q: &[f64]) -> Option<Self> {
        let visco = self.section.visco.as_ref()?;
        let ea = self.section.ea;
        let measure = self.measures.axial_strain;
        let largest = self
            .axial_points
            .iter()
            .map(|p| axial_strain(measure, &p.shape.gradients(q).0))
            .fold(0.0, f64::max);
        let k2 = visco.fast_stiffness(ea, largest, visco.initial_history());
        let mut stiff = self.clone();
        stiff.section.visco = None;
        stiff.section.ea = k2;
        Some(stiff)
    }

    /// The energy stored in a viscoelastic element's springs at
    /// coordinates `q` with internal strains `internal`: sum_s w_s l
    /// [`Viscoelastic::stored_energy`].
    pub fn visco_stored_energy(&self, q: &[f64; ND], internal: &[f64]) -> f64 {
        let Some(visco) = &self.section.visco else {
            return 0.0;
        };
        let measure = self.measures.axial_strain;
        let per = visco.values_per_point();
        self.axial_points
            .iter()
            .zip(internal.chunks(per))
            .map(|(p, state)| {
                let eps = axial_strain(measure, &p.shape.gradients(q).0);
                p.wl * visco.stored_energy(self.section.ea, state, eps)
            })
            .sum()
    }
}
