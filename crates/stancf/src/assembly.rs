//! Assembly of the equations of one time step, eq. (22), with any number
//! of element layers in time (the paper's "time direction assembly"), and
//! of a static solve (the time-invariant slab, docs/method.md §6.8).
//! The step's unknowns and rows: docs/method.md §4.3 (P2) and §5.1
//! (Galerkin); constraints: §6.3-6.4.
//!
//! A P2 step [t_a, t_b] holds L layers with time nodes t_0 = t_a, ...,
//! t_L = t_b. The unknowns are e_i, v_i at t_1 .. t_L; the rows are
//!
//! ```text
//!   dA/de_0 + M v_0 = 0                      (P2 row at the input node)
//!   dA/de_i = 0,  dA/dv_i = 0,  0 < i < L    (interior time nodes)
//!   dA/de_L - M v_L = 0                      (P2 row at the output node)
//! ```
//!
//! with A the action of all space-time elements of the step and the
//! virtual work of the nodal loads. The Galerkin step (docs/method.md
//! §5.1, (M22)) uses the same slab action with the end slopes w_a, w_b
//! as unknowns in place of the velocities and carries the momentum p:
//!
//! ```text
//!   dA/de_a + p_a = 0,   dA/dw_a = 0,   dA/dw_b = 0      (unknowns w_a, e_b, w_b)
//!   p_b = dA/de_b,       v_b = M^-1 p_b                    (after convergence)
//! ```
//!
//! A static solve has one unknown e and one row per coordinate,
//! dU/de - dW/de = 0 (A = dt (W - U) for a time-invariant slab; (M25)).
//!
//! A constrained coordinate (see [`crate::constraints`]) has prescribed
//! values at the time nodes and its rows are freed: with elimination they
//! and its unknowns leave the system (the rows' values are kept as the
//! reaction); with multipliers every freed row gets a multiplier unknown
//! and every fixed value a constraint equation.
//!
//! Unknowns and rows are numbered spatial node by spatial node, so the
//! Jacobian is a band matrix (see [`crate::band`]; docs/method.md §7.6):
//!
//! ```text
//!   unknowns of node n:  [slot 1: free coords, slot 2: ..., multipliers]
//!   rows of node n:      [slot 1: free coords, slot 2: ..., constraint eqs]
//! ```

use crate::band::BandMatrix;
use crate::constraints::ConstraintMethod;
use crate::element::{CableElement, SlabDerivatives, SlabLoads, TimeSlab};
use crate::loads::EndMoment;
use crate::model::{gather, Model};

/// Position (e) or velocity (v) coordinates of a time node.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Kind {
    Position,
    Velocity,
}

/// What is solved for.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Scheme {
    /// A P2 step with `layers` element layers in time.
    P2 { layers: usize },
    /// A Galerkin step (all four variations of the slab action).
    Galerkin,
    /// A static solve.
    Static,
}

const NONE: usize = usize::MAX;

/// Numbering of the unknowns and rows of one step or static solve.
#[derive(Clone, Debug, PartialEq)]
pub struct SlabLayout {
    pub nodes: usize,
    /// Scalar coordinates per spatial node.
    pub dpn: usize,
    pub scheme: Scheme,
    pub method: ConstraintMethod,
    /// (time node, kind) of each unknown slot and each row slot.
    pub unknown_slots: Vec<(usize, Kind)>,
    pub row_slots: Vec<(usize, Kind)>,
    /// Indexed [(node * slots + slot) * dpn + dof]; NONE where absent.
    unknowns: Vec<usize>,
    rows: Vec<usize>,
    /// Multiplier unknown of a freed row, same indexing as `rows`.
    multipliers: Vec<usize>,
    /// Constraint equation of a fixed unknown, same indexing as `unknowns`.
    constraint_rows: Vec<usize>,
    /// First index of each node's block, and the total.
    block_start: Vec<usize>,
    kl: usize,
    ku: usize,
}

impl SlabLayout {
    pub fn new(model: &Model, scheme: Scheme, method: ConstraintMethod) -> Self {
        let (unknown_slots, row_slots) = match scheme {
            Scheme::P2 { layers } => {
                let u: Vec<(usize, Kind)> = (1..=layers)
                    .flat_map(|i| [(i, Kind::Position), (i, Kind::Velocity)])
                    .collect();
                let mut r = vec![(0, Kind::Position)];
                for i in 1..layers {
                    r.push((i, Kind::Position));
                    r.push((i, Kind::Velocity));
                }
                r.push((layers, Kind::Position));
                (u, r)
            }
            Scheme::Galerkin => (
                vec![
                    (0, Kind::Velocity),
                    (1, Kind::Position),
                    (1, Kind::Velocity),
                ],
                vec![
                    (0, Kind::Position),
                    (0, Kind::Velocity),
                    (1, Kind::Velocity),
                ],
            ),
            Scheme::Static => (vec![(0, Kind::Position)], vec![(0, Kind::Position)]),
        };
        let nodes = model.nodes();
        let dpn = model.dofs_per_node();
        let nu = unknown_slots.len();
        let nr = row_slots.len();
        let mut unknowns = vec![NONE; nodes * nu * dpn];
        let mut rows = vec![NONE; nodes * nr * dpn];
        let mut multipliers = vec![NONE; nodes * nr * dpn];
        let mut constraint_rows = vec![NONE; nodes * nu * dpn];
        let mut block_start = Vec::with_capacity(nodes + 1);
        let mut next = 0;
        for n in 0..nodes {
            block_start.push(next);
            // Coordinates held by the planar reduction are always
            // eliminated; constraints by the chosen method.
            let inactive = |d: usize| model.constraints.is_inactive(n * dpn + d);
            let constrained =
                |d: usize| model.constraints.is_constrained(n * dpn + d) && !inactive(d);
            let eliminated = |d: usize| {
                inactive(d) || (method == ConstraintMethod::Elimination && constrained(d))
            };
            // Unknowns and rows share the same count per node; number both.
            let mut u = next;
            let mut r = next;
            for s in 0..nu {
                for d in 0..dpn {
                    if !eliminated(d) {
                        unknowns[(n * nu + s) * dpn + d] = u;
                        u += 1;
                    }
                }
            }
            for s in 0..nr {
                for d in 0..dpn {
                    if !eliminated(d) {
                        rows[(n * nr + s) * dpn + d] = r;
                        r += 1;
                    }
                }
            }
            if method == ConstraintMethod::Multiplier {
                for s in 0..nr {
                    for d in (0..dpn).filter(|&d| constrained(d)) {
                        multipliers[(n * nr + s) * dpn + d] = u;
                        u += 1;
                    }
                }
                for s in 0..nu {
                    for d in (0..dpn).filter(|&d| constrained(d)) {
                        constraint_rows[(n * nu + s) * dpn + d] = r;
                        r += 1;
                    }
                }
            }
            debug_assert_eq!(u, r, "square blocks");
            next = u;
        }
        block_start.push(next);
        // A row of node n couples with unknowns of nodes n - 1 ..= n + 1.
        let mut kl = 0;
        let mut ku = 0;
        for n in 0..nodes {
            let lo = block_start[n.saturating_sub(1)];
            let hi = block_start[(n + 2).min(nodes)];
            if block_start[n + 1] > block_start[n] {
                kl = kl.max(block_start[n + 1] - 1 - lo);
                ku = ku.max(hi.saturating_sub(1) - block_start[n]);
            }
        }
        SlabLayout {
            nodes,
            dpn,
            scheme,
            method,
            unknown_slots,
            row_slots,
            unknowns,
            rows,
            multipliers,
            constraint_rows,
            block_start,
            kl,
            ku,
        }
    }

    /// Element layers per step (0 for a static solve).
    pub fn layers(&self) -> usize {
        match self.scheme {
            Scheme::P2 { layers } => layers,
            Scheme::Galerkin => 1,
            Scheme::Static => 0,
        }
    }

    /// Time nodes 0..=L (a static solve has one).
    pub fn time_nodes(&self) -> usize {
        self.layers() + 1
    }

    /// Unknowns (= rows) of the system.
    pub fn size(&self) -> usize {
        *self.block_start.last().expect("nodes")
    }

    /// Lower and upper bandwidth of the Jacobian.
    pub fn bandwidths(&self) -> (usize, usize) {
        (self.kl, self.ku)
    }

    pub fn unknown_slot(&self, i: usize, kind: Kind) -> Option<usize> {
        self.unknown_slots.iter().position(|&s| s == (i, kind))
    }

    pub fn row_slot(&self, i: usize, kind: Kind) -> Option<usize> {
        self.row_slots.iter().position(|&s| s == (i, kind))
    }

    #[inline]
    fn at(table: &[usize], slots: usize, dpn: usize, slot: usize, g: usize) -> Option<usize> {
        let (n, d) = (g / dpn, g % dpn);
        let v = table[(n * slots + slot) * dpn + d];
        (v != NONE).then_some(v)
    }

    /// Index of the unknown of coordinate d of node n in unknown slot s.
    #[inline]
    pub fn unknown_of_node(&self, slot: usize, node: usize, d: usize) -> Option<usize> {
        let v = self.unknowns[(node * self.unknown_slots.len() + slot) * self.dpn + d];
        (v != NONE).then_some(v)
    }

    /// Index of the row of coordinate d of node n in row slot s.
    #[inline]
    pub fn row_of_node(&self, slot: usize, node: usize, d: usize) -> Option<usize> {
        let v = self.rows[(node * self.row_slots.len() + slot) * self.dpn + d];
        (v != NONE).then_some(v)
    }

    /// Index of the unknown of global coordinate g in unknown slot s.
    pub fn unknown_at(&self, slot: usize, g: usize) -> Option<usize> {
        Self::at(&self.unknowns, self.unknown_slots.len(), self.dpn, slot, g)
    }

    /// Index of the row of global coordinate g in row slot s.
    pub fn row_at(&self, slot: usize, g: usize) -> Option<usize> {
        Self::at(&self.rows, self.row_slots.len(), self.dpn, slot, g)
    }

    /// Multiplier of the freed row (slot s, coordinate g).
    pub fn multiplier_at(&self, slot: usize, g: usize) -> Option<usize> {
        Self::at(&self.multipliers, self.row_slots.len(), self.dpn, slot, g)
    }

    /// Constraint equation fixing the unknown (slot s, coordinate g).
    pub fn constraint_row_at(&self, slot: usize, g: usize) -> Option<usize> {
        Self::at(
            &self.constraint_rows,
            self.unknown_slots.len(),
            self.dpn,
            slot,
            g,
        )
    }

    /// Index of the unknown (time node i, kind, coordinate g), if any.
    pub fn unknown(&self, i: usize, kind: Kind, g: usize) -> Option<usize> {
        self.unknown_slot(i, kind)
            .and_then(|s| self.unknown_at(s, g))
    }

    /// Index of the row (time node i, kind, coordinate g), if any.
    pub fn equation(&self, i: usize, kind: Kind, g: usize) -> Option<usize> {
        self.row_slot(i, kind).and_then(|s| self.row_at(s, g))
    }
}

/// The known data of a step: its start (t_a, e_a, v_a and M v_a), and
/// the prescribed values of constrained coordinates at every time node.
#[derive(Clone, Debug)]
pub struct StepStart {
    pub t: f64,
    pub e: Vec<f64>,
    pub v: Vec<f64>,
    pub mass_v: Vec<f64>,
    /// Prescribed e and v at time node i: `[i * dofs + g]` (only the
    /// constrained coordinates are read).
    pub fixed_e: Vec<f64>,
    pub fixed_v: Vec<f64>,
    /// Factor on every load (load stepping in statics; 1 in dynamics).
    pub load_factor: f64,
}

impl StepStart {
    pub fn new(model: &Model, time_nodes: usize) -> Self {
        let n = model.dofs();
        StepStart {
            t: 0.0,
            e: vec![0.0; n],
            v: vec![0.0; n],
            mass_v: vec![0.0; n],
            fixed_e: vec![0.0; time_nodes * n],
            fixed_v: vec![0.0; time_nodes * n],
            load_factor: 1.0,
        }
    }

    /// Sets the start to `(t, e, v)` and the prescribed values at the time
    /// nodes t + i h.
    pub fn set(&mut self, model: &Model, t: f64, e: &[f64], v: &[f64], h: f64) {
        self.t = t;
        self.e.copy_from_slice(e);
        self.v.copy_from_slice(v);
        model.mass_times(&self.v, &mut self.mass_v);
        let n = model.dofs();
        let nodes = self.fixed_e.len() / n;
        for (g, m) in model.constraints.motion.iter().enumerate() {
            if let Some(m) = m {
                for i in 0..nodes {
                    let ti = t + i as f64 * h;
                    self.fixed_e[i * n + g] = m.value(ti);
                    self.fixed_v[i * n + g] = m.rate_at(ti);
                }
            }
        }
    }
}

/// Scratch for the assembly, allocated once.
#[derive(Clone, Debug)]
pub struct AssemblyScratch {
    derivs2: SlabDerivatives<12>,
    derivs3: SlabDerivatives<18>,
    /// e and v at every time node, `[i * dofs + g]`, from the unknowns and
    /// the prescribed values.
    pub node_e: Vec<f64>,
    pub node_v: Vec<f64>,
    /// M v_L.
    mass_v_end: Vec<f64>,
    /// Values of the eliminated rows, `[slot * dofs + g]`: the generalized
    /// reactions (elimination route).
    pub reaction_rows: Vec<f64>,
    /// Work of the drag loads over the step (int int f . r_dot dx dt).
    pub drag_work: f64,
    /// Galerkin: dA/de_b, the momentum at the end of the step.
    pub end_momentum: Vec<f64>,
}

impl AssemblyScratch {
    pub fn new(model: &Model, layout: &SlabLayout) -> Self {
        let n = model.dofs();
        AssemblyScratch {
            derivs2: SlabDerivatives::default(),
            derivs3: SlabDerivatives::default(),
            node_e: vec![0.0; layout.time_nodes() * n],
            node_v: vec![0.0; layout.time_nodes() * n],
            mass_v_end: vec![0.0; n],
            reaction_rows: vec![0.0; layout.row_slots.len() * n],
            drag_work: 0.0,
            end_momentum: vec![0.0; n],
        }
    }
}

/// The equations of one step (or static solve): the model, their
/// numbering, the time slab of one layer (dt / L; unused in statics) and
/// the known data.
#[derive(Clone, Copy)]
pub struct StepProblem<'a> {
    pub model: &'a Model,
    pub layout: &'a SlabLayout,
    pub slab: &'a TimeSlab,
    pub start: &'a StepStart,
}

/// Where the rows of one element slot go: a row index, or the reaction
/// buffer for an eliminated constrained coordinate, or nowhere.
#[derive(Clone, Copy)]
enum Target {
    Row(usize),
    Reaction(usize),
    /// Galerkin: a term of dA/de_b (the end momentum) of coordinate g.
    Momentum(usize),
    Nothing,
}

impl StepProblem<'_> {
    /// Where the gradient entry of (time node i, kind, coordinate g) goes.
    fn target_at(&self, i: usize, kind: Kind, g: usize) -> Target {
        if self.layout.scheme == Scheme::Galerkin && (i, kind) == (1, Kind::Position) {
            return Target::Momentum(g);
        }
        self.target(self.layout.row_slot(i, kind), g)
    }

    fn target(&self, slot: Option<usize>, g: usize) -> Target {
        let Some(s) = slot else {
            return Target::Nothing;
        };
        match self.layout.row_at(s, g) {
            Some(r) => Target::Row(r),
            None if self.model.constraints.is_constrained(g) => {
                Target::Reaction(s * self.model.dofs() + g)
            }
            None => Target::Nothing,
        }
    }

    /// Fills the time-node values from the unknowns and the prescribed
    /// values.
    pub fn expand(&self, x: &[f64], scratch: &mut AssemblyScratch) {
        let layout = self.layout;
        let n = self.model.dofs();
        let dpn = layout.dpn;
        let nu = layout.unknown_slots.len();
        let start = self.start;
        for i in 0..layout.time_nodes() {
            let (e_out, v_out) = (
                &mut scratch.node_e[i * n..(i + 1) * n],
                &mut scratch.node_v[i * n..(i + 1) * n],
            );
            if i == 0 && layout.scheme != Scheme::Static {
                // e_a is known; P2's v_a too, Galerkin's w_a is an unknown
                // (prescribed, i.e. the start's rate, where constrained).
                e_out.copy_from_slice(&start.e);
                let sv = layout.unknown_slot(0, Kind::Velocity);
                for node in 0..layout.nodes {
                    for d in 0..dpn {
                        let g = node * dpn + d;
                        v_out[g] = match sv.map(|s| layout.unknowns[(node * nu + s) * dpn + d]) {
                            Some(u) if u != NONE => x[u],
                            _ => start.v[g],
                        };
                    }
                }
                continue;
            }
            let se = layout.unknown_slot(i, Kind::Position);
            let sv = layout.unknown_slot(i, Kind::Velocity);
            let fixed_e = &start.fixed_e[i * n..(i + 1) * n];
            let fixed_v = &start.fixed_v[i * n..(i + 1) * n];
            for node in 0..layout.nodes {
                for d in 0..dpn {
                    let g = node * dpn + d;
                    let pick = |slot: Option<usize>, fixed: f64| match slot {
                        Some(s) => match layout.unknowns[(node * nu + s) * dpn + d] {
                            NONE => fixed,
                            u => x[u],
                        },
                        None => fixed,
                    };
                    e_out[g] = pick(se, fixed_e[g]);
                    v_out[g] = if sv.is_some() {
                        pick(sv, fixed_v[g])
                    } else {
                        0.0
                    };
                }
            }
        }
    }

    /// Residual R(x) of the rows and, if asked, the Jacobian dR/dx; the
    /// values of eliminated rows go to `scratch.reaction_rows`. All
    /// outputs are overwritten.
    pub fn assemble(
        &self,
        x: &[f64],
        residual: &mut [f64],
        mut jacobian: Option<&mut BandMatrix>,
        scratch: &mut AssemblyScratch,
    ) {
        residual.fill(0.0);
        scratch.reaction_rows.fill(0.0);
        scratch.end_momentum.fill(0.0);
        scratch.drag_work = 0.0;
        if let Some(j) = jacobian.as_deref_mut() {
            j.clear();
        }
        self.expand(x, scratch);
        let jac = jacobian.as_deref_mut();
        let mut derivs2 = std::mem::take(&mut scratch.derivs2);
        let mut derivs3 = std::mem::take(&mut scratch.derivs3);
        match &self.model.mesh {
            crate::model::Mesh::Sac2(els) => match self.layout.scheme {
                Scheme::Static => self.static_elements(els, residual, jac, scratch),
                _ => self.slab_elements(els, &mut derivs2, residual, jac, scratch),
            },
            crate::model::Mesh::Sac3(els) => match self.layout.scheme {
                Scheme::Static => self.static_elements(els, residual, jac, scratch),
                _ => self.slab_elements(els, &mut derivs3, residual, jac, scratch),
            },
        }
        scratch.derivs2 = derivs2;
        scratch.derivs3 = derivs3;
        self.nodal_loads(residual, jacobian.as_deref_mut(), scratch);
        if self.layout.scheme != Scheme::Static {
            self.momentum_terms(residual, jacobian.as_deref_mut(), scratch);
        }
        self.constraint_terms(x, residual, jacobian);
    }

    fn add(&self, t: Target, v: f64, residual: &mut [f64], scratch: &mut AssemblyScratch) {
        match t {
            Target::Row(r) => residual[r] += v,
            Target::Reaction(k) => scratch.reaction_rows[k] += v,
            Target::Momentum(g) => scratch.end_momentum[g] += v,
            Target::Nothing => {}
        }
    }

    /// Element actions of every layer, eq. (10) (docs/method.md §3.1-3.2,
    /// (M13)-(M14)).
    fn slab_elements<const NS: usize, const ND: usize>(
        &self,
        elements: &[CableElement<NS, ND>],
        derivs: &mut SlabDerivatives<ND>,
        residual: &mut [f64],
        mut jacobian: Option<&mut BandMatrix>,
        scratch: &mut AssemblyScratch,
    ) {
        let layout = self.layout;
        let n = self.model.dofs();
        let dpn = layout.dpn;
        let g = &self.model.gravity;
        let loads = SlabLoads {
            gravity: g.map(|c| c * self.start.load_factor),
            drag: &self.model.drag,
        };
        let mut block = [[0.0; ND]; ND];
        let galerkin = layout.scheme == Scheme::Galerkin;
        for j in 0..layout.layers() {
            let slots: [(usize, Kind); 4] = [
                (j, Kind::Position),
                (j, Kind::Velocity),
                (j + 1, Kind::Position),
                (j + 1, Kind::Velocity),
            ];
            let row_slots = slots.map(|(i, k)| layout.row_slot(i, k));
            let col_slots = slots.map(|(i, k)| layout.unknown_slot(i, k));
            for (k, el) in elements.iter().enumerate() {
                let o = k * dpn;
                let mut y = [[0.0; ND]; 4];
                for (m, &(i, kind)) in slots.iter().enumerate() {
                    let src = match kind {
                        Kind::Position => &scratch.node_e,
                        Kind::Velocity => &scratch.node_v,
                    };
                    y[m] = gather(src, i * n + o);
                }
                el.slab_derivatives(self.slab, &y, &loads, jacobian.is_some(), derivs);
                scratch.drag_work += derivs.drag_work;
                // Where each entry of the element's gradient goes, per slot.
                let mut targets = row_slots.map(|rs| {
                    let mut out = [Target::Nothing; ND];
                    if let Some(s) = rs {
                        for (d, t) in out.iter_mut().enumerate() {
                            let (node, dd) = if d < dpn { (k, d) } else { (k + 1, d - dpn) };
                            *t = match layout.row_of_node(s, node, dd) {
                                Some(r) => Target::Row(r),
                                None if self.model.constraints.is_constrained(o + d) => {
                                    Target::Reaction(s * n + o + d)
                                }
                                None => Target::Nothing,
                            };
                        }
                    }
                    out
                });
                if galerkin {
                    // Slot 2 is e_b: its gradient is the end momentum.
                    for (d, t) in targets[2].iter_mut().enumerate() {
                        *t = Target::Momentum(o + d);
                    }
                }
                for m in 0..4 {
                    for d in 0..ND {
                        self.add(targets[m][d], derivs.grad[m][d], residual, scratch);
                    }
                }
                let Some(jac) = jacobian.as_deref_mut() else {
                    continue;
                };
                // Global rows and columns of the element's entries, per slot.
                let index = |slot: Option<usize>| {
                    let mut out = [NONE; ND];
                    if let Some(s) = slot {
                        for (d, v) in out.iter_mut().enumerate() {
                            let (node, dd) = if d < dpn { (k, d) } else { (k + 1, d - dpn) };
                            *v = layout.unknown_of_node(s, node, dd).unwrap_or(NONE);
                        }
                    }
                    out
                };
                let rows = targets.map(|t| {
                    t.map(|t| match t {
                        Target::Row(r) => r,
                        _ => NONE,
                    })
                });
                let cols = col_slots.map(index);
                for m in 0..4 {
                    if row_slots[m].is_none() {
                        continue;
                    }
                    for nn in 0..4 {
                        if col_slots[nn].is_none() {
                            continue;
                        }
                        el.slab_hessian_block(self.slab, derivs, m, nn, &mut block);
                        for (a, brow) in block.iter().enumerate() {
                            let r = rows[m][a];
                            if r == NONE {
                                continue;
                            }
                            for (b, &val) in brow.iter().enumerate() {
                                let c = cols[nn][b];
                                if c != NONE && val != 0.0 {
                                    jac.add(r, c, val);
                                }
                            }
                        }
                    }
                }
            }
        }
    }

    /// Static rows dU/de - f_g (the load factor scales the loads).
    fn static_elements<const NS: usize, const ND: usize>(
        &self,
        elements: &[CableElement<NS, ND>],
        residual: &mut [f64],
        mut jacobian: Option<&mut BandMatrix>,
        scratch: &mut AssemblyScratch,
    ) {
        let layout = self.layout;
        let dpn = layout.dpn;
        let gravity = self.model.gravity.map(|c| c * self.start.load_factor);
        let mut grad = [0.0; ND];
        let mut hess = [[0.0; ND]; ND];
        for (k, el) in elements.iter().enumerate() {
            let o = k * dpn;
            let q: [f64; ND] = gather(&scratch.node_e, o);
            let want = jacobian.is_some();
            el.strain_energy_derivatives(&q, &mut grad, if want { Some(&mut hess) } else { None });
            // A cable at rest in a moving fluid: drag f(0, r_x) is a load.
            for drag in &self.model.drag {
                el.add_static_drag(
                    drag,
                    self.start.load_factor,
                    &q,
                    &mut grad,
                    want.then_some(&mut hess),
                );
            }
            let fg = el.gravity_load(&gravity);
            for d in 0..ND {
                let t = self.target(Some(0), o + d);
                self.add(t, grad[d] - fg[d], residual, scratch);
            }
            if let Some(jac) = jacobian.as_deref_mut() {
                for a in 0..ND {
                    let Some(r) = layout.row_at(0, o + a) else {
                        continue;
                    };
                    for b in 0..ND {
                        if let Some(c) = layout.unknown_at(0, o + b) {
                            jac.add(r, c, hess[a][b]);
                        }
                    }
                }
            }
        }
    }

    /// Point forces (eq. 14) and end moments (eqs. 15-16): in a P2 step
    /// their work over each layer, sum_g w_g dt F(q(t_g)) . q(t_g); in
    /// statics minus the force (docs/method.md §2.6-2.7, (M7)).
    fn nodal_loads(
        &self,
        residual: &mut [f64],
        mut jacobian: Option<&mut BandMatrix>,
        scratch: &mut AssemblyScratch,
    ) {
        let layout = self.layout;
        let n = self.model.dofs();
        let dpn = layout.dpn;
        let lf = self.start.load_factor;
        let is_static = layout.scheme == Scheme::Static;
        for (node, f) in self.model.point_forces() {
            let f = f.map(|c| c * lf);
            for c in 0..3 {
                let g = node * dpn + c;
                if is_static {
                    let t = self.target(Some(0), g);
                    self.add(t, -f[c], residual, scratch);
                    continue;
                }
                for j in 0..layout.layers() {
                    for (m, (di, kind)) in [
                        (0, Kind::Position),
                        (0, Kind::Velocity),
                        (1, Kind::Position),
                        (1, Kind::Velocity),
                    ]
                    .into_iter()
                    .enumerate()
                    {
                        let t = self.target_at(j + di, kind, g);
                        self.add(t, self.slab.load[m] * f[c], residual, scratch);
                    }
                }
            }
        }
        for (node, mv) in self.model.end_moments() {
            let Some(moment) = EndMoment::from_vector(&mv.map(|c| c * lf)) else {
                continue;
            };
            let g0 = node * dpn + 3;
            if is_static {
                let rx = [
                    scratch.node_e[g0],
                    scratch.node_e[g0 + 1],
                    scratch.node_e[g0 + 2],
                ];
                let (q, dq) = moment.generalized_force(&rx);
                for a in 0..3 {
                    let t = self.target(Some(0), g0 + a);
                    self.add(t, -q[a], residual, scratch);
                    if let (Some(jac), Some(r)) =
                        (jacobian.as_deref_mut(), layout.row_at(0, g0 + a))
                    {
                        for b in 0..3 {
                            if let Some(c) = layout.unknown_at(0, g0 + b) {
                                jac.add(r, c, -dq[a][b]);
                            }
                        }
                    }
                }
                continue;
            }
            for j in 0..layout.layers() {
                let slots = [
                    (j, Kind::Position),
                    (j, Kind::Velocity),
                    (j + 1, Kind::Position),
                    (j + 1, Kind::Velocity),
                ];
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
    }

    /// Momentum terms: + p_a (= M v_a) on row e_0; P2 also - M v_L on row
    /// e_L (the Galerkin step computes p_b = dA/de_b afterwards instead;
    /// docs/method.md §4.3 and §5.1).
    fn momentum_terms(
        &self,
        residual: &mut [f64],
        jacobian: Option<&mut BandMatrix>,
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
        if layout.scheme == Scheme::Galerkin {
            return;
        }
        let vl = &scratch.node_v[last * n..(last + 1) * n];
        self.model.mass_times(vl, &mut scratch.mass_v_end);
        for g in 0..n {
            let t = self.target(last_slot, g);
            let v = -scratch.mass_v_end[g];
            self.add(t, v, residual, scratch);
        }
        let Some(jac) = jacobian else { return };
        let (Some(rs), Some(cs)) = (last_slot, layout.unknown_slot(last, Kind::Velocity)) else {
            return;
        };
        let dpn = layout.dpn;
        crate::with_elements!(&self.model.mesh, els => {
            for (k, el) in els.iter().enumerate() {
                for (a, mrow) in el.mass.iter().enumerate() {
                    for (b, &mab) in mrow.iter().enumerate() {
                        for i in 0..3 {
                            let ga = k * dpn + 3 * a + i;
                            let gb = k * dpn + 3 * b + i;
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
    fn constraint_terms(
        &self,
        x: &[f64],
        residual: &mut [f64],
        mut jacobian: Option<&mut BandMatrix>,
    ) {
        let layout = self.layout;
        if layout.method != ConstraintMethod::Multiplier || self.model.constraints.is_empty() {
            return;
        }
        let n = self.model.dofs();
        let sign = if layout.scheme == Scheme::Static {
            -1.0
        } else {
            1.0
        };
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
    }
}

/// Scales that turn increments and residuals of a P2 step into fractions
/// of the cable length (docs/method.md §7.1, (M27)):
///
/// - an unknown e of kind r, r_x, r_xx is weighted by 1, l, l^2 (its effect
///   on the centre line inside an element), a velocity unknown also by h = dt/L;
/// - a row dA/de of coordinate c is weighted by h s_c / m_c, m_c the
///   diagonal of the mass matrix (kinetic part of the Jacobian ~ M / h),
///   a row dA/dv by s_c / m_c; a multiplier like its row, a constraint
///   equation like its unknown;
///
/// and everything is divided by the cable length.
#[derive(Clone, Debug)]
pub struct Scales {
    pub unknown: Vec<f64>,
    pub equation: Vec<f64>,
}

impl Scales {
    pub fn new(model: &Model, layout: &SlabLayout, layer_dt: f64) -> Self {
        let size = layout.size();
        let mut unknown = vec![0.0; size];
        let mut equation = vec![0.0; size];
        let mass = model.mass_diagonal();
        let len = model.cable.length;
        let dpn = layout.dpn;
        for g in 0..model.dofs() {
            let s = model.coordinate_length_scale(g % dpn) / len;
            let m = mass[g];
            for (slot, &(_, kind)) in layout.unknown_slots.iter().enumerate() {
                let w = match kind {
                    Kind::Position => s,
                    Kind::Velocity => s * layer_dt,
                };
                if let Some(u) = layout.unknown_at(slot, g) {
                    unknown[u] = w;
                }
                if let Some(r) = layout.constraint_row_at(slot, g) {
                    equation[r] = w;
                }
            }
            for (slot, &(_, kind)) in layout.row_slots.iter().enumerate() {
                let w = match kind {
                    Kind::Position => s * layer_dt / m,
                    Kind::Velocity => s / m,
                };
                if let Some(r) = layout.row_at(slot, g) {
                    equation[r] = w;
                }
                if let Some(u) = layout.multiplier_at(slot, g) {
                    unknown[u] = w;
                }
            }
        }
        Scales { unknown, equation }
    }

    /// max_i |w_i z_i|, NaN if any entry is not finite.
    pub fn norm(weights: &[f64], z: &[f64]) -> f64 {
        let mut m = 0.0f64;
        for (w, v) in weights.iter().zip(z.iter()) {
            let a = (w * v).abs();
            if !a.is_finite() {
                return f64::NAN;
            }
            m = m.max(a);
        }
        m
    }
}

fn add_stiffness_and_mass<const NS: usize, const ND: usize>(
    els: &[CableElement<NS, ND>],
    dpn: usize,
    e: &[f64],
    k: &mut BandMatrix,
    m: &mut BandMatrix,
) {
    let mut grad = [0.0; ND];
    let mut hess = [[0.0; ND]; ND];
    for (j, el) in els.iter().enumerate() {
        let q: [f64; ND] = gather(e, j * dpn);
        el.strain_energy_derivatives(&q, &mut grad, Some(&mut hess));
        let o = j * dpn;
        for a in 0..ND {
            for b in 0..ND {
                k.add(o + a, o + b, hess[a][b]);
            }
        }
        for a in 0..NS {
            for b in 0..NS {
                for i in 0..3 {
                    m.add(o + 3 * a + i, o + 3 * b + i, el.mass[a][b]);
                }
            }
        }
    }
}

/// The global tangent stiffness K = d2U/de2 at coordinates `e` and the
/// consistent mass matrix M, as band matrices (bandwidth 2 dpn - 1).
pub fn stiffness_and_mass(model: &Model, e: &[f64]) -> (BandMatrix, BandMatrix) {
    let n = model.dofs();
    let dpn = model.dofs_per_node();
    let bw = 2 * dpn - 1;
    let mut k = BandMatrix::new(n, bw, bw);
    let mut m = BandMatrix::new(n, bw, bw);
    crate::with_elements!(&model.mesh, els => add_stiffness_and_mass(els, dpn, e, &mut k, &mut m));
    (k, m)
}
