//! The time direction of a slab (eq. (6) at the time Gauss points) and the
//! space-time quadrature loop of one element over it: the slab action of
//! eq. (10), its gradient with respect to y = [e_a, v_a, e_b, v_b] (with the
//! virtual work of drag, eq. (17), and of the axial damping, (M34)) and its
//! exact Hessian, block by block (docs/method.md §3.1-3.2, (M13)-(M14);
//! time layers §3.5; damping §2.10; the entrained water's kinetic energy
//! of a line in water, §12.5, (W28)-(W29)).

use super::{dot_n, CableElement};
use crate::quadrature::GaussRule;
use crate::shape::TimeShape;

impl<const NS: usize, const ND: usize> CableElement<NS, ND> {
    /// Slab action A^e of eq. (10) for unknowns `y = [e_a, v_a, e_b, v_b]`.
    pub fn slab_action(&self, slab: &TimeSlab, y: &[[f64; ND]; 4], g: &[f64; 3]) -> f64 {
        let fg = self.gravity_load(g);
        let mut action = 0.0;
        for tp in &slab.points {
            let (q, qdot) = interpolate_in_time(&tp.shape, y);
            let mq = self.mass_times(&qdot);
            let kinetic = 0.5 * dot_n(&qdot, &mq);
            let strain = self.strain_energy(&q);
            let gravity = dot_n(&fg, &q);
            action += tp.w_dt * (kinetic - strain + gravity);
        }
        action
    }

    /// Gradient of the slab action with respect to `y` (plus the virtual
    /// work of the drag loads, eq. 17, and of the axial damping, (M34)) and,
    /// if `with_hessian`, the
    /// matrices at the time points from which every block of its Jacobian
    /// follows (see [`SlabDerivatives`] and [`Self::slab_hessian_block`]).
    ///
    /// Drag, per unit length f(r_dot, r_x), integrated with the axial rule
    /// (docs/method.md §2.8, (M11); the rest is (M14) of §3.2):
    ///
    /// ```text
    ///   dW/dy_m   = sum_g w_g dt phi_m sum_s w_s l N_k f
    ///   C_g = sum_s w_s l N_k N_l df/dr_dot,   G_g = sum_s w_s l N_k N_x,l df/dr_x
    ///   block_mn += sum_g w_g dt phi_m (phidot_n C_g + phi_n G_g)
    /// ```
    ///
    /// The axial damping (BA != 0; docs/method.md §2.10, (M34)) adds its
    /// generalized force to the drag's and its derivatives to the same
    /// C_g, G_g.
    pub fn slab_derivatives(
        &self,
        slab: &TimeSlab,
        y: &[[f64; ND]; 4],
        loads: &SlabLoads,
        with_hessian: bool,
        out: &mut SlabDerivatives<ND>,
    ) {
        self.slab_derivatives_from(slab, y, loads, &[], with_hessian, out);
    }

    /// [`Self::slab_derivatives`] from the internal state `history` of a
    /// viscoelastic element at the slab's start (eps1 at each point of the
    /// axial rule, docs/method.md §2.11; empty: at rest at e_a); its
    /// state at the slab's end is left in `out.visco.end`.
    pub fn slab_derivatives_from(
        &self,
        slab: &TimeSlab,
        y: &[[f64; ND]; 4],
        loads: &SlabLoads,
        history: &[f64],
        with_hessian: bool,
        out: &mut SlabDerivatives<ND>,
    ) {
        let fg = self.gravity_load(&loads.gravity);
        out.grad = [[0.0; ND]; 4];
        out.action = 0.0;
        out.drag_work = 0.0;
        out.damping_work = 0.0;
        out.seabed_work = 0.0;
        out.water_work = 0.0;
        out.has_drag = !loads.drag.is_empty() || loads.seabed.is_some() || loads.water.is_some();
        out.has_damping = self.section.ba != 0.0;
        out.in_plane = loads.in_plane;
        let rates = out.has_drag || out.has_damping;
        let np = slab.points.len();
        // The entrained water's kinetic energy (docs/method.md §12.5).
        let added = loads.water.and_then(crate::water::AddedMass::of);
        out.added_mass.active = added.is_some();
        if added.is_some() && with_hessian {
            out.added_mass.reserve(np);
        }
        if out.k_at_points.len() < np {
            out.k_at_points.resize(np, [[0.0; ND]; ND]);
        }
        if rates && with_hessian && out.c_at_points.len() < np {
            out.c_at_points.resize(np, [[0.0; ND]; ND]);
            out.g_at_points.resize(np, [[0.0; ND]; ND]);
        }
        out.visco.active = false;
        out.viv.active = false;
        let rest;
        let history = if history.is_empty() && self.internal_values_per_point() > 0 {
            rest = self.rest_internal(&y[0], 0.0, self.length);
            &rest[..]
        } else {
            history
        };
        let (visco_start, viv_start) = self.split_internal(history);
        if let Some(visco) = &self.section.visco {
            self.slab_viscoelastic(visco, slab, y, visco_start, with_hessian, out);
        }
        if let (Some(viv), Some(water)) = (&self.section.viv, loads.water) {
            let start = (viv_start, loads.time);
            self.slab_viv(viv, water, slab, y, start, with_hessian, out);
        }
        let ns = self.axial_points.len();
        let mut du = [0.0; ND];
        for (gi, tp) in slab.points.iter().enumerate() {
            let (q, qdot) = interpolate_in_time(&tp.shape, y);
            let mut mq = self.mass_times(&qdot);
            let mut hess = if with_hessian {
                Some(&mut out.k_at_points[gi])
            } else {
                None
            };
            let strain =
                self.slab_energy_derivatives(loads.in_plane, &q, &mut du, hess.as_deref_mut());
            if out.visco.active {
                let force = &out.visco.force[gi * ns..(gi + 1) * ns];
                self.add_axial_forces(&q, force, &mut du, hess);
            }
            out.action += tp.w_dt * (0.5 * dot_n(&qdot, &mq) - strain + dot_n(&fg, &q));
            // Generalized drag and damping forces on q at this time point.
            let at = with_hessian.then_some(gi);
            if rates && with_hessian {
                out.c_at_points[gi] = [[0.0; ND]; ND];
                out.g_at_points[gi] = [[0.0; ND]; ND];
            }
            let mut fq = if out.has_drag {
                self.slab_drag_at_point(loads.drag, tp.w_dt, &q, &qdot, at, out)
            } else {
                [0.0; ND]
            };
            if out.has_damping {
                self.slab_damping_at_point(tp.w_dt, &q, &qdot, at, &mut fq, out);
            }
            if let Some(contact) = loads.seabed {
                self.slab_seabed_at_point(contact, tp.w_dt, (&q, &qdot), at, &mut fq, out);
            }
            if let Some(water) = loads.water {
                let when = (loads.time + tp.offset, tp.w_dt);
                let g = &loads.gravity;
                let water = (water, loads.host_flow.as_ref());
                self.slab_water_at_point(water, when, g, (&q, &qdot), at, &mut fq, out);
            }
            if out.viv.active {
                self.add_viv_lift(&out.viv, gi, &mut fq);
            }
            if let Some(am) = &added {
                // (W28): dT_a/dqdot joins M qdot, dT_a/dq the forces.
                let am_out = &mut out.added_mass;
                let blocks = at.map(|g| (&mut am_out.vv[g], &mut am_out.vq[g], &mut am_out.qq[g]));
                let t_a = self.entrained_energy(am, (&q, &qdot), &mut fq, &mut mq, blocks);
                out.action += tp.w_dt * t_a;
            }
            for m in 0..4 {
                let a = tp.w_dt * tp.shape.t_dot[m];
                let b = tp.w_dt * tp.shape.t[m];
                for d in 0..ND {
                    out.grad[m][d] += a * mq[d] - b * (du[d] - fg[d] - fq[d]);
                }
            }
        }
        out.combined = with_hessian && rates;
        if out.combined {
            combine_at_points(out, np);
        }
    }

    /// Hessian block d2A^e / dy_m dy_n (ND x ND) from the derivatives
    /// evaluated by [`Self::slab_derivatives`] with `with_hessian = true`:
    /// `C_mn M (x) I_3 - sum_g w_g dt phi_m phi_n K_g`, with drag's and
    /// the entrained water's blocks ((M11), (W29)).
    pub fn slab_hessian_block(
        &self,
        slab: &TimeSlab,
        derivs: &SlabDerivatives<ND>,
        m: usize,
        n: usize,
        out: &mut [[f64; ND]; ND],
    ) {
        *out = [[0.0; ND]; ND];
        // The strain energy's -w T_m T_n K_g, alone or (combined) in
        // G_g; then the kinetic part. (In this order a line in water with
        // zero coefficients, C_g = 0 and G_g = -K_g exactly, gets the
        // line's blocks in air to the bit.)
        if derivs.combined {
            for (gi, tp) in slab.points.iter().enumerate() {
                let a = tp.w_dt * tp.shape.t[m] * tp.shape.t_dot[n];
                let b = tp.w_dt * tp.shape.t[m] * tp.shape.t[n];
                let (c, g) = (&derivs.c_at_points[gi], &derivs.g_at_points[gi]);
                for (orow, (crow, grow)) in out.iter_mut().zip(c.iter().zip(g.iter())) {
                    for (o, (cv, gv)) in orow.iter_mut().zip(crow.iter().zip(grow.iter())) {
                        *o += a * cv + b * gv;
                    }
                }
            }
        } else if derivs.in_plane {
            self.elastic_block::<2>(slab, derivs, m, n, out);
        } else {
            self.elastic_block::<3>(slab, derivs, m, n, out);
        }
        if derivs.in_plane {
            self.kinetic_block::<2>(slab, m, n, out);
        } else {
            self.kinetic_block::<3>(slab, m, n, out);
        }
        if derivs.added_mass.active {
            self.add_entrained_block(slab, &derivs.added_mass, m, n, out);
        }
        if derivs.visco.active {
            self.add_visco_block(slab, derivs, m, n, out);
        }
        if derivs.viv.active {
            self.add_viv_block(&derivs.viv, m, n, out);
        }
    }

    /// The strain energy's share of block (m, n) of
    /// [`Self::slab_hessian_block`], added to `out` in the first D
    /// components of every node vector (2 for a line held in a plane:
    /// its z rows and columns stay zero, §7.10):
    /// `- sum_g w_g dt phi_m phi_n K_g`.
    #[inline(always)]
    fn elastic_block<const D: usize>(
        &self,
        slab: &TimeSlab,
        derivs: &SlabDerivatives<ND>,
        m: usize,
        n: usize,
        out: &mut [[f64; ND]; ND],
    ) {
        for (gi, tp) in slab.points.iter().enumerate() {
            let c = -tp.w_dt * tp.shape.t[m] * tp.shape.t[n];
            let k = &derivs.k_at_points[gi];
            for ka in 0..NS {
                for i in 0..D {
                    let (orow, krow) = (&mut out[3 * ka + i], &k[3 * ka + i]);
                    for kb in 0..NS {
                        for j in 0..D {
                            orow[3 * kb + j] += c * krow[3 * kb + j];
                        }
                    }
                }
            }
        }
    }

    /// The kinetic energy's share of block (m, n), `C_mn M (x) I_D`, in
    /// the first D components as [`Self::elastic_block`].
    #[inline(always)]
    fn kinetic_block<const D: usize>(
        &self,
        slab: &TimeSlab,
        m: usize,
        n: usize,
        out: &mut [[f64; ND]; ND],
    ) {
        let cm = slab.kinetic[m][n];
        for k in 0..NS {
            for l in 0..NS {
                let v = cm * self.mass[k][l];
                for i in 0..D {
                    out[3 * k + i][3 * l + i] += v;
                }
            }
        }
    }
}

/// Gradient of the slab action and the strain-energy Hessians at the time
/// quadrature points, for one element and one slab.
#[derive(Clone, Debug)]
pub struct SlabDerivatives<const ND: usize> {
    /// A^e without the drag (for diagnostics and tests).
    pub action: f64,
    /// dA^e/dy_m (with the virtual work of drag and damping) for m = e_a,
    /// v_a, e_b, v_b.
    pub grad: [[f64; ND]; 4],
    /// d2U/dq2 at q(t_g), one per time Gauss point.
    pub k_at_points: Vec<[[f64; ND]; ND]>,
    /// Drag (and the seabed, which shares its matrices): whether there is
    /// any, int f . r_dot over the slab (the drag's work, negative in
    /// still air), and the matrices C_g, G_g per time point.
    pub has_drag: bool,
    pub drag_work: f64,
    /// Axial damping (docs/method.md §2.10): whether there is any (BA !=
    /// 0; its derivatives share C_g, G_g with the drag's) and its work
    /// over the slab, -int int BA eps_dot^2 dx dt (never positive).
    pub has_damping: bool,
    /// Evaluated for a line held in a plane ([`SlabLoads::in_plane`]): the
    /// Hessian's z rows and columns are zero.
    pub in_plane: bool,
    pub damping_work: f64,
    /// The seabed's work over the slab, int int f . r_dot dx dt (W47).
    pub seabed_work: f64,
    /// The water's work over the slab, int int f . r_dot dx dt (W24).
    pub water_work: f64,
    pub c_at_points: Vec<[[f64; ND]; ND]>,
    pub g_at_points: Vec<[[f64; ND]; ND]>,
    /// Whether the time points' matrices are combined by the time
    /// shapes' products they take in a block ([`combine_at_points`]):
    /// then G_g holds `G_g - K_g + Z_g` and C_g holds `C_g + X_g^T`.
    pub combined: bool,
    /// The entrained water's matrices (W28) at the time points, used
    /// only if the line is in water with added mass (docs/method.md §12.5).
    pub added_mass: super::AddedMassDerivatives<ND>,
    /// A viscoelastic line's axial forces and their coupling of the time
    /// points (docs/method.md §2.11).
    pub visco: super::viscoelastic::ViscoDerivatives,
    /// A line's VIV lift and its coupling of the time points
    /// (docs/method.md §12.7).
    pub viv: super::viv::VivDerivatives,
}

impl<const ND: usize> Default for SlabDerivatives<ND> {
    fn default() -> Self {
        SlabDerivatives {
            action: 0.0,
            grad: [[0.0; ND]; 4],
            k_at_points: Vec::new(),
            has_drag: false,
            drag_work: 0.0,
            has_damping: false,
            in_plane: false,
            damping_work: 0.0,
            seabed_work: 0.0,
            water_work: 0.0,
            c_at_points: Vec::new(),
            g_at_points: Vec::new(),
            combined: false,
            added_mass: super::AddedMassDerivatives::default(),
            visco: super::viscoelastic::ViscoDerivatives::default(),
            viv: super::viv::VivDerivatives::default(),
        }
    }
}

/// Combines each time point's matrices by the product of time shapes
/// they take in a Hessian block (M11), (W29): the strain energy's K_g and
/// the entrained water's Z_g go with `T_m T_n` as drag's G_g does, X_g^T
/// with `T_m Tdot_n` as C_g does. A block then sums four matrices a time
/// point (C, G and the water's V, X) instead of seven.
fn combine_at_points<const ND: usize>(out: &mut SlabDerivatives<ND>, np: usize) {
    let added = out.added_mass.active;
    for gi in 0..np {
        let (k, g) = (&out.k_at_points[gi], &mut out.g_at_points[gi]);
        for (grow, krow) in g.iter_mut().zip(k) {
            for (gv, kv) in grow.iter_mut().zip(krow) {
                *gv -= kv;
            }
        }
        if added {
            let (x, z) = (&out.added_mass.vq[gi], &out.added_mass.qq[gi]);
            let c = &mut out.c_at_points[gi];
            for i in 0..ND {
                for j in 0..ND {
                    g[i][j] += z[i][j];
                    c[i][j] += x[j][i];
                }
            }
        }
    }
}

/// The distributed loads an element sees in a slab: gravity (eq. 13) and
/// air drag (eq. 17).
#[derive(Clone, Copy, Debug)]
pub struct SlabLoads<'a> {
    pub gravity: [f64; 3],
    pub drag: &'a [crate::loads::AirDrag],
    /// The seabed, if the line can touch one (docs/method.md §12.2).
    pub seabed: Option<&'a crate::water::SeabedContact>,
    /// The water, if the line is in water (docs/method.md §12.3-12.5).
    pub water: Option<&'a crate::water::LineInWater>,
    /// The flow a host has set at the element's end nodes (MoorDyn's
    /// `WaveKin 1`, docs/method.md §12.1, (W2f)-(W2g)), if it sets one.
    pub host_flow: Option<crate::water::ElementFlow>,
    /// The time at the slab's start (s): time point g is at
    /// `time + offset_g` (the sea's kinematics depend on it).
    pub time: f64,
    /// The line is held in the plane z = const (the planar reduction):
    /// the strain energy's z rows and columns are not wanted and are left
    /// zero (docs/method.md §7.10).
    pub in_plane: bool,
}

impl SlabLoads<'_> {
    /// Gravity only.
    pub fn gravity(g: [f64; 3]) -> SlabLoads<'static> {
        SlabLoads {
            gravity: g,
            drag: &[],
            seabed: None,
            water: None,
            host_flow: None,
            time: 0.0,
            in_plane: false,
        }
    }
}

/// One time quadrature point of a slab: the time shape functions and the
/// weight times the slab length.
#[derive(Clone, Copy, Debug)]
pub struct TimePoint {
    pub w_dt: f64,
    /// tau dt: the point's time after the slab's start.
    pub offset: f64,
    pub shape: TimeShape,
}

/// The time direction of a slab (one layer of space-time elements):
/// eq. (6) evaluated at the time Gauss points.
#[derive(Clone, Debug)]
pub struct TimeSlab {
    pub dt: f64,
    pub points: Vec<TimePoint>,
    /// `C_mn = sum_g w_g dt phidot_m phidot_n`: the kinetic part of the
    /// Hessian is C (x) M.
    pub kinetic: [[f64; 4]; 4],
    /// `b_m = sum_g w_g dt phi_m`: a constant force F does work b_m F . y_m.
    pub load: [f64; 4],
    /// The time shapes at the slab's end (tau = 1).
    pub end: TimeShape,
    /// The collocation of a viscoelastic line's internal strain at the
    /// time points and the end (docs/method.md §2.11, (V5)).
    pub collocation: super::viscoelastic::Collocation,
}

impl TimeSlab {
    pub fn new(dt: f64, rule: &GaussRule) -> Self {
        let points: Vec<TimePoint> = rule
            .iter()
            .map(|(tau, w)| TimePoint {
                w_dt: w * dt,
                offset: tau * dt,
                shape: crate::shape::time_hermite(tau, dt),
            })
            .collect();
        let mut kinetic = [[0.0; 4]; 4];
        let mut load = [0.0; 4];
        for p in &points {
            for m in 0..4 {
                load[m] += p.w_dt * p.shape.t[m];
                for n in 0..4 {
                    kinetic[m][n] += p.w_dt * p.shape.t_dot[m] * p.shape.t_dot[n];
                }
            }
        }
        let mut taus: Vec<f64> = rule.iter().map(|(tau, _)| tau).collect();
        taus.push(1.0);
        TimeSlab {
            dt,
            points,
            kinetic,
            load,
            end: crate::shape::time_hermite(1.0, dt),
            collocation: super::viscoelastic::Collocation::new(&taus, dt),
        }
    }
}

/// q(t) and qdot(t) from the slab unknowns (eq. 6).
pub(super) fn interpolate_in_time<const ND: usize>(
    shape: &TimeShape,
    y: &[[f64; ND]; 4],
) -> ([f64; ND], [f64; ND]) {
    let mut q = [0.0; ND];
    let mut qdot = [0.0; ND];
    for m in 0..4 {
        let a = shape.t[m];
        let b = shape.t_dot[m];
        for d in 0..ND {
            q[d] += a * y[m][d];
            qdot[d] += b * y[m][d];
        }
    }
    (q, qdot)
}
