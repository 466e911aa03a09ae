//! A step's known data ([`StepStart`]), the scratch of its assembly and
//! the driver that evaluates its rows and Jacobian
//! ([`StepProblem::assemble`]; docs/method.md §4.3, §5.1, §6.8).

use super::layout::SlabLayout;
use super::Kind;
use crate::band::BandMatrix;
use crate::element::{SlabDerivatives, TimeSlab};
use crate::linear::{AddEntries, Jacobian};
use crate::model::{coordinate, Model, SLOT_R};

/// The known data of a step: its start (t_a, e_a, v_a and the momentum
/// p_a = M v_a + dT_a/dv, (W30)), and
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
    /// Statics only: initial axial forces (N) at the points of every
    /// element's axial rule, element after element (empty: none), taken
    /// off the elastic axial force (docs/method.md §11.6, (M32b)).
    pub initial_axial_force: Vec<f64>,
    /// The internal state at the start ([`crate::State::internal`]).
    pub internal: Vec<f64>,
}

impl StepStart {
    /// Sets the internal state at the start.
    pub fn set_internal(&mut self, internal: &[f64]) {
        self.internal.clear();
        self.internal.extend_from_slice(internal);
    }

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
            initial_axial_force: Vec::new(),
            internal: Vec::new(),
        }
    }

    /// Sets the start to `(t, e, v)` and the prescribed values at the time
    /// nodes t + i h.
    /// The internal state is set apart ([`Self::set_internal`]).
    pub fn set(&mut self, model: &Model, t: f64, e: &[f64], v: &[f64], h: f64) {
        self.t = t;
        self.e.copy_from_slice(e);
        self.v.copy_from_slice(v);
        model.momentum(&self.e, &self.v, &mut self.mass_v);
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
    /// The slab derivatives of a batch of elements (one, evaluated
    /// serially, or a batch evaluated on several threads).
    derivs2: Vec<SlabDerivatives<12>>,
    derivs3: Vec<SlabDerivatives<18>>,
    /// Where each element's gradient entries go, `[((layer elements +
    /// element) 4 + slot) ND + entry]`: fixed by the layout this scratch
    /// serves, found at the first evaluation.
    pub(super) element_targets: Vec<Target>,
    /// e and v at every time node, `[i * dofs + g]`, from the unknowns and
    /// the prescribed values.
    pub node_e: Vec<f64>,
    pub node_v: Vec<f64>,
    /// p_L = M v_L + dT_a/dv (W30).
    pub(super) mass_v_end: Vec<f64>,
    /// Values of the eliminated rows, `[slot * dofs + g]`: the generalized
    /// reactions (elimination route).
    pub reaction_rows: Vec<f64>,
    /// Work of the drag loads over the step (int int f . r_dot dx dt).
    pub drag_work: f64,
    /// Work of the axial damping over the step (-int int BA eps_dot^2 dx
    /// dt; docs/method.md §2.10).
    pub damping_work: f64,
    /// A viscoelastic line's internal state at the end of the slab of the
    /// last evaluation (docs/method.md §2.11).
    pub internal_end: Vec<f64>,
    /// Work of the seabed contact over the step (W47).
    pub seabed_work: f64,
    pub water_work: f64,
    /// Galerkin: dA/de_b, the momentum at the end of the step.
    pub end_momentum: Vec<f64>,
}

impl AssemblyScratch {
    pub fn new(model: &Model, layout: &SlabLayout) -> Self {
        let n = model.dofs();
        AssemblyScratch {
            derivs2: Vec::new(),
            derivs3: Vec::new(),
            element_targets: Vec::new(),
            node_e: vec![0.0; layout.time_nodes() * n],
            node_v: vec![0.0; layout.time_nodes() * n],
            mass_v_end: vec![0.0; n],
            reaction_rows: vec![0.0; layout.row_slots.len() * n],
            drag_work: 0.0,
            damping_work: 0.0,
            seabed_work: 0.0,
            water_work: 0.0,
            end_momentum: vec![0.0; n],
            internal_end: vec![0.0; model.internal_state_len()],
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
#[derive(Clone, Copy, Debug)]
pub(super) enum Target {
    Row(usize),
    Reaction(usize),
    /// Galerkin: a term of dA/de_b (the end momentum) of coordinate g.
    Momentum(usize),
    Nothing,
}

impl StepProblem<'_> {
    /// Where the gradient entry of (time node i, kind, coordinate g) goes.
    pub(super) fn target_at(&self, i: usize, kind: Kind, g: usize) -> Target {
        if self.layout.scheme.end_variation_is_momentum() && (i, kind) == (1, Kind::Position) {
            return Target::Momentum(g);
        }
        self.target(self.layout.row_slot(i, kind), g)
    }

    pub(super) fn target(&self, slot: Option<usize>, g: usize) -> Target {
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
        let start = self.start;
        for i in 0..layout.time_nodes() {
            let (e_out, v_out) = (
                &mut scratch.node_e[i * n..(i + 1) * n],
                &mut scratch.node_v[i * n..(i + 1) * n],
            );
            if i == 0 && layout.scheme.has_known_start() {
                // e_a is known; P2's v_a too, Galerkin's w_a is an unknown
                // (prescribed, i.e. the start's rate, where constrained).
                e_out.copy_from_slice(&start.e);
                let sv = layout.unknown_slot(0, Kind::Velocity);
                for node in 0..layout.nodes {
                    let o = coordinate(dpn, node, SLOT_R, 0);
                    for d in 0..dpn {
                        let g = o + d;
                        v_out[g] = match sv.and_then(|s| layout.unknown_of_node(s, node, d)) {
                            Some(u) => x[u],
                            None => start.v[g],
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
                let o = coordinate(dpn, node, SLOT_R, 0);
                for d in 0..dpn {
                    let g = o + d;
                    let pick = |slot: Option<usize>, fixed: f64| match slot
                        .and_then(|s| layout.unknown_of_node(s, node, d))
                    {
                        Some(u) => x[u],
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
    pub fn assemble<J: Jacobian>(
        &self,
        x: &[f64],
        residual: &mut [f64],
        mut jacobian: Option<&mut J>,
        scratch: &mut AssemblyScratch,
    ) {
        if let Some(j) = jacobian.as_deref_mut() {
            j.clear();
        }
        self.assemble_into(x, residual, jacobian, scratch);
    }

    /// The residual R(x) alone (see [`Self::assemble`]).
    pub fn residual(&self, x: &[f64], residual: &mut [f64], scratch: &mut AssemblyScratch) {
        self.assemble_into::<BandMatrix>(x, residual, None, scratch);
    }

    /// As [`Self::assemble`], but the Jacobian's entries are added to
    /// what `jacobian` holds (one line's share of a system's Jacobian);
    /// the residual and the scratch are overwritten.
    pub fn assemble_into<J: AddEntries>(
        &self,
        x: &[f64],
        residual: &mut [f64],
        mut jacobian: Option<&mut J>,
        scratch: &mut AssemblyScratch,
    ) {
        residual.fill(0.0);
        scratch.reaction_rows.fill(0.0);
        scratch.end_momentum.fill(0.0);
        scratch.drag_work = 0.0;
        scratch.damping_work = 0.0;
        scratch.seabed_work = 0.0;
        scratch.water_work = 0.0;
        self.expand(x, scratch);
        let jac = jacobian.as_deref_mut();
        let mut derivs2 = std::mem::take(&mut scratch.derivs2);
        let mut derivs3 = std::mem::take(&mut scratch.derivs3);
        match &self.model.mesh {
            crate::model::Mesh::Sac2(els) if self.layout.scheme.is_static() => {
                self.static_elements(els, residual, jac, scratch)
            }
            crate::model::Mesh::Sac2(els) => {
                self.slab_elements(els, &mut derivs2, residual, jac, scratch)
            }
            crate::model::Mesh::Sac3(els) if self.layout.scheme.is_static() => {
                self.static_elements(els, residual, jac, scratch)
            }
            crate::model::Mesh::Sac3(els) => {
                self.slab_elements(els, &mut derivs3, residual, jac, scratch)
            }
        }
        scratch.derivs2 = derivs2;
        scratch.derivs3 = derivs3;
        self.nodal_loads(residual, jacobian.as_deref_mut(), scratch);
        if self.layout.scheme.has_inertia() {
            self.momentum_terms(residual, jacobian.as_deref_mut(), scratch);
        }
        self.constraint_terms(x, residual, jacobian);
    }

    pub(super) fn add(
        &self,
        t: Target,
        v: f64,
        residual: &mut [f64],
        scratch: &mut AssemblyScratch,
    ) {
        match t {
            Target::Row(r) => residual[r] += v,
            Target::Reaction(k) => scratch.reaction_rows[k] += v,
            Target::Momentum(g) => scratch.end_momentum[g] += v,
            Target::Nothing => {}
        }
    }
}
