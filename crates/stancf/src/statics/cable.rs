//! The static equations of one cable (docs/method.md §6.8, (M25)): the
//! time-invariant slab's rows dU/de - lambda f and the constraints, the
//! load path with moving supports, the state and reactions at a
//! converged increment.

use super::newton::StaticEquations;
use crate::assembly::{AssemblyScratch, Scheme, SlabLayout, StepProblem, StepStart};
use crate::band::BandMatrix;
use crate::constraints::{ConstraintMethod, DirectionHold};
use crate::element::TimeSlab;
use crate::linear::AddEntries;
use crate::model::{coordinate, Model, State, SLOT_R, SLOT_R_X};
use crate::quadrature::GaussRule;

/// One cable's static equations and what a converged increment gives.
pub(crate) struct CableStatics {
    pub model: Model,
    pub layout: SlabLayout,
    slab: TimeSlab,
    pub start: StepStart,
    pub scratch: AssemblyScratch,
    /// The current equilibrium (t holds the load path parameter).
    pub state: State,
    /// Force each position constraint exerts on the cable.
    pub reactions: Vec<(usize, [f64; 3])>,
    /// Moment each direction hold exerts on the cable (M42).
    pub clamp_moments: Vec<(usize, [f64; 3])>,
    /// The initial axial forces of a system's static path at its start
    /// (M32b; empty: none).
    initial_axial_force: Vec<f64>,
}

impl CableStatics {
    /// The equations of `model` starting from the state `start_e` (the
    /// reference shape for a single cable, a seed for a system's line).
    pub fn new(model: Model, method: ConstraintMethod, start_e: Vec<f64>) -> Self {
        let layout = SlabLayout::new(&model, Scheme::Static, method);
        let state = State {
            t: 0.0,
            v: vec![0.0; model.dofs()],
            e: start_e,
            internal: Vec::new(),
        };
        let mut start = StepStart::new(&model, 1);
        start.set(&model, 0.0, &state.e, &state.v, 0.0);
        let reactions = model
            .constraints
            .position_nodes
            .iter()
            .map(|&nd| (nd, [0.0; 3]))
            .collect();
        let scratch = AssemblyScratch::new(&model, &layout);
        CableStatics {
            slab: TimeSlab::new(1.0, &GaussRule::new(1).expect("1 point")),
            layout,
            start,
            scratch,
            state,
            reactions,
            clamp_moments: model
                .constraints
                .directions
                .iter()
                .map(|h| (h.node, [0.0; 3]))
                .collect(),
            initial_axial_force: Vec::new(),
            model,
        }
    }

    /// Takes the axial strain defects of the current state (the seed's)
    /// as the path's initial axial forces, -EA times the defect at every
    /// point of every element's axial rule (docs/method.md §11.6, (M32b)),
    /// whole until [`Self::scale_initial_axial_forces`] says otherwise.
    pub fn take_strain_defects(&mut self) {
        let dpn = self.model.dofs_per_node();
        let e = &self.state.e;
        let forces: Vec<f64> = crate::with_elements!(&self.model.mesh, els => els
            .iter()
            .enumerate()
            .flat_map(|(k, el)| {
                let ea = el.section.ea;
                el.axial_strain_defects(&e[coordinate(dpn, k, SLOT_R, 0)..])
                    .into_iter()
                    .map(move |d| -ea * d)
            })
            .collect());
        self.initial_axial_force = forces.clone();
        self.start.initial_axial_force = forces;
    }

    /// The static friction's targets (W48): where each point of the line
    /// is taken to have been before it slid (the seed, unless set).
    pub fn friction_targets(&self) -> &[f64] {
        &self.start.e
    }

    /// Puts the static friction's targets at the coordinates `targets`
    /// (docs/method.md §12.2, (W49)).
    pub fn set_friction_targets(&mut self, targets: &[f64]) {
        self.start.e.copy_from_slice(targets);
    }

    /// The initial axial forces times `factor` (1 - t on the path).
    /// At factor 0 (the path's end) there are none left to evaluate.
    pub fn scale_initial_axial_forces(&mut self, factor: f64) {
        let forces = &mut self.start.initial_axial_force;
        forces.clear();
        if factor != 0.0 {
            forces.extend(self.initial_axial_force.iter().map(|f0| factor * f0));
        }
    }

    /// The unknowns of the state's coordinates.
    pub fn unknowns_of_state(&self) -> Vec<f64> {
        let mut x = vec![0.0; self.layout.size()];
        for g in 0..self.model.dofs() {
            if let Some(u) = self.layout.unknown_at(0, g) {
                x[u] = self.state.e[g];
            }
        }
        x
    }

    /// Weights of the unknowns in the increment norm: each coordinate's
    /// length scale over the cable length (0 for multipliers).
    pub fn unknown_weights(&self) -> Vec<f64> {
        let len = self.model.cable.length;
        let dpn = self.layout.dpn;
        let mut w = vec![0.0; self.layout.size()];
        for g in 0..self.model.dofs() {
            if let Some(u) = self.layout.unknown_at(0, g) {
                w[u] = self.model.coordinate_length_scale(g / dpn, g % dpn) / len;
            }
        }
        w
    }

    /// Each multiplier's unknown and the equilibrium rows of its node's
    /// three coordinates of the kind it holds (r for a position's, r_x for
    /// a direction hold's), for the increment norm's weights
    /// (`StaticNewton::set_weight_rows`).
    pub fn multiplier_rows(&self) -> Vec<(usize, [usize; 3])> {
        let dpn = self.layout.dpn;
        let rows = |node: usize, slot: usize, own: usize| -> [usize; 3] {
            std::array::from_fn(|c| {
                let g = coordinate(dpn, node, slot, c);
                self.layout.row_at(0, g).unwrap_or(own)
            })
        };
        let mut out = Vec::new();
        for g in 0..self.model.dofs() {
            if let (Some(m), Some(r)) = (self.layout.multiplier_at(0, g), self.layout.row_at(0, g))
            {
                out.push((m, rows(g / dpn, (g % dpn) / 3, r)));
            }
        }
        for (h, hold) in self.model.constraints.directions.iter().enumerate() {
            let rx = coordinate(dpn, hold.node, SLOT_R_X, 0);
            let Some(r) = self.layout.row_at(0, rx) else {
                continue;
            };
            for k in 0..2 {
                if let Some(m) = self.layout.hold_multiplier(h, 0, k) {
                    out.push((m, rows(hold.node, SLOT_R_X, r)));
                }
            }
        }
        out
    }

    /// Whether a prescribed support moves away from its reference position.
    pub fn moves_supports(&self) -> bool {
        self.model
            .constraints
            .motion
            .iter()
            .flatten()
            .any(|m| m.value(0.0) != m.base())
    }

    /// The rows (and Jacobian entries, added to `jacobian`) at x.
    pub fn assemble_into<J: AddEntries>(
        &mut self,
        x: &[f64],
        residual: &mut [f64],
        jacobian: Option<&mut J>,
    ) {
        let p = StepProblem {
            model: &self.model,
            layout: &self.layout,
            slab: &self.slab,
            start: &self.start,
        };
        p.assemble_into(x, residual, jacobian, &mut self.scratch);
    }

    /// Row weights from the Jacobian's diagonal `diagonal(r)`: each
    /// coordinate's length scale over |K_rr| (floored at 1e-12 of the
    /// largest, `kmax`); constraint rows are positions already.
    pub fn row_weights(&self, diagonal: impl Fn(usize) -> f64, kmax: f64, weights: &mut [f64]) {
        let len = self.model.cable.length;
        let dpn = self.layout.dpn;
        let floor = 1e-12 * kmax.max(f64::MIN_POSITIVE);
        for w in weights.iter_mut() {
            *w = 0.0;
        }
        for g in 0..self.model.dofs() {
            let s = self.model.coordinate_length_scale(g / dpn, g % dpn) / len;
            if let Some(r) = self.layout.row_at(0, g) {
                weights[r] = s / diagonal(r).abs().max(floor);
            }
            if let Some(r) = self.layout.constraint_row_at(0, g) {
                weights[r] = s;
            }
        }
        // A direction hold's equations n . r_x = 0, like r_x's.
        for (h, hold) in self.model.constraints.directions.iter().enumerate() {
            let s = self.model.coordinate_length_scale(hold.node, SLOT_R_X * 3) / len;
            for k in 0..2 {
                if let Some(r) = self.layout.hold_row(h, 0, k) {
                    weights[r] = s;
                }
            }
        }
    }

    /// The state and reactions at the converged x (`residual` is scratch).
    pub fn converged(&mut self, x: &[f64], residual: &mut [f64]) {
        let p = StepProblem {
            model: &self.model,
            layout: &self.layout,
            slab: &self.slab,
            start: &self.start,
        };
        p.residual(x, residual, &mut self.scratch);
        let n = self.model.dofs();
        self.state.e.copy_from_slice(&self.scratch.node_e[..n]);
        self.state.t = self.start.load_factor;
        let dpn = self.layout.dpn;
        for (node, force) in self.reactions.iter_mut() {
            for c in 0..3 {
                let g = coordinate(dpn, *node, SLOT_R, c);
                force[c] = match self.layout.multiplier_at(0, g) {
                    Some(m) => x[m],
                    None => self.scratch.reaction_rows[g],
                };
            }
        }
        // The hold's multipliers are its generalized reaction on r_x
        // (statics: lambda is the force itself), M = r_x x Q (M42).
        for (h, hold) in self.model.constraints.directions.iter().enumerate() {
            let mut q = [0.0; 3];
            for (k, n) in hold.normals.iter().enumerate() {
                if let Some(m) = self.layout.hold_multiplier(h, 0, k) {
                    for c in 0..3 {
                        q[c] += x[m] * n[c];
                    }
                }
            }
            let o = coordinate(dpn, hold.node, SLOT_R_X, 0);
            let r_x = [self.state.e[o], self.state.e[o + 1], self.state.e[o + 2]];
            self.clamp_moments[h].1 = DirectionHold::moment(r_x, q);
        }
    }
}

/// A single cable's static solve: its equations on the load path that
/// puts the loads on, then moves the supports (see `set_load_factor`).
pub(crate) struct SingleCable {
    pub cable: CableStatics,
    /// Scratch rows for [`CableStatics::converged`].
    rows: Vec<f64>,
}

impl SingleCable {
    pub fn new(cable: CableStatics) -> Self {
        let n = cable.layout.size();
        SingleCable {
            cable,
            rows: vec![0.0; n],
        }
    }
}

impl StaticEquations for SingleCable {
    type Matrix = BandMatrix;

    fn evaluate(&mut self, x: &[f64], residual: &mut [f64], jacobian: Option<&mut BandMatrix>) {
        match jacobian {
            Some(j) => {
                j.clear();
                self.cable.assemble_into(x, residual, Some(j));
            }
            None => self.cable.assemble_into::<BandMatrix>(x, residual, None),
        }
    }

    fn row_weights(&mut self, jacobian: &BandMatrix, weights: &mut [f64]) {
        let n = self.cable.layout.size();
        let kmax = (0..n).map(|i| jacobian.get(i, i).abs()).fold(0.0, f64::max);
        self.cable
            .row_weights(|r| jacobian.get(r, r), kmax, weights);
    }

    /// Sets the point t in [0, 1] of the load path. Without support
    /// motion the loads are t times the full loads. With it the path has
    /// two legs: the loads grow to full while the supports stay at their
    /// reference positions (t <= 1/2), then the supports move to their
    /// prescribed positions c(0) under the full loads (t > 1/2). Moving a
    /// support first would compress the straight cable far beyond its
    /// buckling load (pi^2 EI / L^2), where Newton has nothing to go by;
    /// under load it merely slackens a sagging cable. For an elastic cable
    /// under conservative loads the end state is the same.
    fn set_load_factor(&mut self, t: f64) {
        let (loads, supports) = if self.cable.moves_supports() {
            ((2.0 * t).min(1.0), (2.0 * t - 1.0).max(0.0))
        } else {
            (t, t)
        };
        let start = &mut self.cable.start;
        start.load_factor = loads;
        for (g, m) in self.cable.model.constraints.motion.iter().enumerate() {
            if let Some(m) = m {
                start.fixed_e[g] = m.base() + supports * (m.value(0.0) - m.base());
            }
        }
    }

    fn legs(&self) -> usize {
        if self.cable.moves_supports() {
            2
        } else {
            1
        }
    }

    fn converged(&mut self, x: &[f64]) {
        self.cable.converged(x, &mut self.rows);
    }
}
