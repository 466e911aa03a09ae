//! The contributions to a step's rows and Jacobian besides the elements'
//! (those are in `elements`): the nodal loads (§2.6-2.7), the momentum
//! terms (§4.3, §5.1) and the multipliers and constraint equations (§6.3,
//! §6.5).

use super::elements::layer_slots;
use super::system::{AssemblyScratch, StepProblem};
use super::Kind;
use crate::constraints::ConstraintMethod;
use crate::linear::AddEntries;
use crate::loads::EndMoment;
use crate::model::{coordinate, SLOT_R, SLOT_R_X};

impl StepProblem<'_> {
    /// Point forces (eq. 14) and end moments (eqs. 15-16): in a P2 step
    /// their work over each layer, sum_g w_g dt F(q(t_g)) . q(t_g); in
    /// statics minus the force (docs/method.md §2.6-2.7, (M7)).
    pub(super) fn nodal_loads<J: AddEntries>(
        &self,
        residual: &mut [f64],
        mut jacobian: Option<&mut J>,
        scratch: &mut AssemblyScratch,
    ) {
        self.point_forces(residual, scratch);
        let lf = self.start.load_factor;
        for (node, mv) in self.model.end_moments() {
            let Some(moment) = EndMoment::from_vector(&mv.map(|c| c * lf)) else {
                continue;
            };
            let g0 = coordinate(self.layout.dpn, node, SLOT_R_X, 0);
            if !self.layout.scheme.loads_as_work() {
                self.static_end_moment(&moment, g0, residual, jacobian.as_deref_mut(), scratch);
            } else {
                self.slab_end_moment(&moment, g0, residual, jacobian.as_deref_mut(), scratch);
            }
        }
    }

    /// Point forces, eq. (14): their work over each layer (the slab's
    /// load weights), or minus the force in statics (docs/method.md §2.6).
    fn point_forces(&self, residual: &mut [f64], scratch: &mut AssemblyScratch) {
        let layout = self.layout;
        let lf = self.start.load_factor;
        let as_work = layout.scheme.loads_as_work();
        for (node, f) in self.model.point_forces() {
            let f = f.map(|c| c * lf);
            for c in 0..3 {
                let g = coordinate(layout.dpn, node, SLOT_R, c);
                if !as_work {
                    let t = self.target(Some(0), g);
                    self.add(t, -f[c], residual, scratch);
                    continue;
                }
                for j in 0..layout.layers() {
                    for (m, (i, kind)) in layer_slots(j).into_iter().enumerate() {
                        let t = self.target_at(i, kind, g);
                        self.add(t, self.slab.load[m] * f[c], residual, scratch);
                    }
                }
            }
        }
    }

    /// An end moment in statics, eqs. (15)-(16): minus its generalized
    /// force on the r_x coordinates from `g0` and minus its derivative
    /// (docs/method.md §2.7).
    fn static_end_moment<J: AddEntries>(
        &self,
        moment: &EndMoment,
        g0: usize,
        residual: &mut [f64],
        mut jacobian: Option<&mut J>,
        scratch: &mut AssemblyScratch,
    ) {
        let layout = self.layout;
        let rx = [
            scratch.node_e[g0],
            scratch.node_e[g0 + 1],
            scratch.node_e[g0 + 2],
        ];
        let (q, dq) = moment.generalized_force(&rx);
        for a in 0..3 {
            let t = self.target(Some(0), g0 + a);
            self.add(t, -q[a], residual, scratch);
            if let (Some(jac), Some(r)) = (jacobian.as_deref_mut(), layout.row_at(0, g0 + a)) {
                for b in 0..3 {
                    if let Some(c) = layout.unknown_at(0, g0 + b) {
                        jac.add(r, c, -dq[a][b]);
                    }
                }
            }
        }
    }

    /// An end moment in a step, eqs. (15)-(16): its work over each layer,
    /// sum_g w_g dt Q(r_x(t_g)) . r_x(t_g), on the r_x coordinates from
    /// `g0` (docs/method.md §2.7, (M7)).
    fn slab_end_moment<J: AddEntries>(
        &self,
        moment: &EndMoment,
        g0: usize,
        residual: &mut [f64],
        mut jacobian: Option<&mut J>,
        scratch: &mut AssemblyScratch,
    ) {
        let layout = self.layout;
        let n = self.model.dofs();
        for j in 0..layout.layers() {
            let slots = layer_slots(j);
            for tp in &self.slab.points {
                let mut rx = [0.0; 3];
                for (m, &(i, kind)) in slots.iter().enumerate() {
                    let src = match kind {
                        Kind::Position => &scratch.node_e,
                        Kind::Velocity => &scratch.node_v,
                    };
                    for a in 0..3 {
                        rx[a] += tp.shape.t[m] * src[i * n + g0 + a];
                    }
                }
                let (q, dq) = moment.generalized_force(&rx);
                for (m, &(i, kind)) in slots.iter().enumerate() {
                    let rs = layout.row_slot(i, kind);
                    let wm = tp.w_dt * tp.shape.t[m];
                    for a in 0..3 {
                        let t = self.target_at(i, kind, g0 + a);
                        self.add(t, wm * q[a], residual, scratch);
                    }
                    let (Some(jac), Some(rs)) = (jacobian.as_deref_mut(), rs) else {
                        continue;
                    };
                    for (nn, &(i2, kind2)) in slots.iter().enumerate() {
                        let Some(cs) = layout.unknown_slot(i2, kind2) else {
                            continue;
                        };
                        let w = wm * tp.shape.t[nn];
                        for a in 0..3 {
                            let Some(r) = layout.row_at(rs, g0 + a) else {
                                continue;
                            };
                            for b in 0..3 {
                                if let Some(c) = layout.unknown_at(cs, g0 + b) {
                                    jac.add(r, c, w * dq[a][b]);
                                }
                            }
                        }
                    }
                }
            }
        }
    }

    /// Momentum terms: + p_a (= M v_a, with the entrained water's dT_a/dv,
    /// (W30)) on row e_0; P2 also - p_L on row e_L (the Galerkin step
    /// computes p_b = dA/de_b afterwards instead; docs/method.md §4.3 and
    /// §5.1).
    pub(super) fn momentum_terms<J: AddEntries>(
        &self,
        residual: &mut [f64],
        jacobian: Option<&mut J>,
        scratch: &mut AssemblyScratch,
    ) {
        let layout = self.layout;
        let n = self.model.dofs();
        let last = layout.layers();
        let first_slot = layout.row_slot(0, Kind::Position);
        let last_slot = layout.row_slot(last, Kind::Position);
        for g in 0..n {
            let t = self.target(first_slot, g);
            self.add(t, self.start.mass_v[g], residual, scratch);
        }
        if !layout.scheme.end_row_holds_momentum() {
            return;
        }
        let el = &scratch.node_e[last * n..(last + 1) * n];
        let vl = &scratch.node_v[last * n..(last + 1) * n];
        self.model.momentum(el, vl, &mut scratch.mass_v_end);
        for g in 0..n {
            let t = self.target(last_slot, g);
            let v = -scratch.mass_v_end[g];
            self.add(t, v, residual, scratch);
        }
        let Some(jac) = jacobian else { return };
        let (Some(rs), Some(cs)) = (last_slot, layout.unknown_slot(last, Kind::Velocity)) else {
            return;
        };
        self.entrained_end_momentum(rs, jac, scratch);
        let dpn = layout.dpn;
        crate::with_elements!(&self.model.mesh, els => {
            for (k, el) in els.iter().enumerate() {
                for (a, mrow) in el.mass.iter().enumerate() {
                    for (b, &mab) in mrow.iter().enumerate() {
                        for i in 0..3 {
                            let ga = coordinate(dpn, k, a, i);
                            let gb = coordinate(dpn, k, b, i);
                            if let (Some(r), Some(c)) = (layout.row_at(rs, ga), layout.unknown_at(cs, gb)) {
                                jac.add(r, c, -mab);
                            }
                        }
                    }
                }
            }
        });
    }

    /// Multipliers in the freed rows (+ in P2 rows, which are generalized
    /// impulses; - in static rows dU/de - f, so that a multiplier is the
    /// reaction on the cable either way) and the constraint equations
    /// x_c - c(t_i) = 0 (docs/method.md §6.3, §6.5).
    pub(super) fn constraint_terms<J: AddEntries>(
        &self,
        x: &[f64],
        residual: &mut [f64],
        mut jacobian: Option<&mut J>,
    ) {
        let layout = self.layout;
        if layout.method != ConstraintMethod::Multiplier || self.model.constraints.is_empty() {
            return;
        }
        let n = self.model.dofs();
        let sign = layout.scheme.multiplier_sign();
        for g in (0..n).filter(|&g| self.model.constraints.is_constrained(g)) {
            for s in 0..layout.row_slots.len() {
                if let (Some(r), Some(m)) = (layout.row_at(s, g), layout.multiplier_at(s, g)) {
                    residual[r] += sign * x[m];
                    if let Some(jac) = jacobian.as_deref_mut() {
                        jac.add(r, m, sign);
                    }
                }
            }
            for (s, &(i, kind)) in layout.unknown_slots.iter().enumerate() {
                if let (Some(r), Some(u)) =
                    (layout.constraint_row_at(s, g), layout.unknown_at(s, g))
                {
                    let target = match kind {
                        Kind::Position => self.start.fixed_e[i * n + g],
                        Kind::Velocity => self.start.fixed_v[i * n + g],
                    };
                    residual[r] = x[u] - target;
                    if let Some(jac) = jacobian.as_deref_mut() {
                        jac.add(r, u, 1.0);
                    }
                }
            }
        }
        self.direction_terms(x, sign, residual, jacobian);
    }

    /// The direction holds (docs/method.md §6.10, (M41)): in every row
    /// slot, the multipliers lambda_k enter the node's r_x rows as
    /// sign lambda_k n_k; in every unknown slot, n_k . r_x = 0 (value or
    /// rate: the direction is fixed in space).
    fn direction_terms<J: AddEntries>(
        &self,
        x: &[f64],
        sign: f64,
        residual: &mut [f64],
        mut jacobian: Option<&mut J>,
    ) {
        let layout = self.layout;
        for (h, hold) in self.model.constraints.directions.iter().enumerate() {
            if hold.turning {
                // A free body's clamp: the system's (§15.19).
                continue;
            }
            let g0 = coordinate(layout.dpn, hold.node, SLOT_R_X, 0);
            for (k, n) in hold.normals.iter().enumerate() {
                for s in 0..layout.row_slots.len() {
                    let Some(m) = layout.hold_multiplier(h, s, k) else {
                        continue;
                    };
                    for c in 0..3 {
                        if let Some(r) = layout.row_at(s, g0 + c) {
                            residual[r] += sign * n[c] * x[m];
                            if let Some(jac) = jacobian.as_deref_mut() {
                                jac.add(r, m, sign * n[c]);
                            }
                        }
                    }
                }
                for s in 0..layout.unknown_slots.len() {
                    let Some(r) = layout.hold_row(h, s, k) else {
                        continue;
                    };
                    residual[r] = 0.0;
                    for c in 0..3 {
                        let u = layout
                            .unknown_at(s, g0 + c)
                            .expect("a held r_x is not otherwise constrained");
                        residual[r] += n[c] * x[u];
                        if let Some(jac) = jacobian.as_deref_mut() {
                            jac.add(r, u, n[c]);
                        }
                    }
                }
            }
        }
    }
}
