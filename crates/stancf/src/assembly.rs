//! Assembly of the P2 equations of one time step, eq. (22), with any number
//! of element layers in time (the paper's "time direction assembly").
//!
//! A step [t_a, t_b] holds L layers with time nodes t_0 = t_a, ..., t_L = t_b.
//! The unknowns are e_i, v_i at t_1 .. t_L; the equations are
//!
//! ```text
//!   dA/de_0 + M v_0 = 0                      (P2 row at the input node)
//!   dA/de_i = 0,  dA/dv_i = 0,  0 < i < L    (interior time nodes)
//!   dA/de_L - M v_L = 0                      (P2 row at the output node)
//! ```
//!
//! with A the action of all space-time elements of the step. Both are
//! numbered spatial node by spatial node, so the Jacobian is a band matrix
//! (see [`crate::band`]): node n owns the block `[n B, (n + 1) B)` of
//! unknowns and of equations, B = 2 L dpn.
//!
//! ```text
//!   unknowns of node n:  [e_1, v_1, e_2, v_2, ..., e_L, v_L]
//!   equations of node n: [row e_0, row e_1, row v_1, ..., row e_L]
//! ```

use crate::band::BandMatrix;
use crate::element::{CableElement, SlabDerivatives, TimeSlab};
use crate::model::{gather, Model};

/// Position (e) or velocity (v) coordinates of a time node.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Kind {
    Position,
    Velocity,
}

/// Numbering of the unknowns and equations of one step.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct SlabLayout {
    pub nodes: usize,
    /// Scalar coordinates per spatial node.
    pub dpn: usize,
    /// Element layers in time per step.
    pub layers: usize,
}

impl SlabLayout {
    pub fn new(model: &Model, layers: usize) -> Self {
        SlabLayout {
            nodes: model.nodes(),
            dpn: model.dofs_per_node(),
            layers,
        }
    }

    /// Unknowns (= equations) per spatial node.
    pub fn block(&self) -> usize {
        2 * self.layers * self.dpn
    }

    /// Unknowns of the step.
    pub fn size(&self) -> usize {
        self.nodes * self.block()
    }

    /// Index of the first unknown of (time node i, kind) at spatial node n;
    /// the node's dpn coordinates follow contiguously. None for i = 0 (known).
    pub fn unknown(&self, i: usize, kind: Kind, node: usize) -> Option<usize> {
        if i == 0 || i > self.layers {
            return None;
        }
        let k = match kind {
            Kind::Position => 0,
            Kind::Velocity => 1,
        };
        Some(node * self.block() + (2 * (i - 1) + k) * self.dpn)
    }

    /// Index of the first equation of (time node i, kind) at spatial node
    /// n, or None where eq. (22) has no such row (v at t_0 and t_L).
    pub fn equation(&self, i: usize, kind: Kind, node: usize) -> Option<usize> {
        let base = node * self.block();
        match kind {
            Kind::Position if i == 0 => Some(base),
            Kind::Position if i <= self.layers => Some(base + (2 * i - 1) * self.dpn),
            Kind::Velocity if i > 0 && i < self.layers => Some(base + 2 * i * self.dpn),
            _ => None,
        }
    }

    /// Lower and upper bandwidth of the Jacobian: a row of node n couples
    /// with unknowns of nodes n - 1 ..= n + 1.
    pub fn bandwidths(&self) -> (usize, usize) {
        let b = self.block();
        (2 * b - 1, 2 * b - 1)
    }
}

/// The step's start, t_a, with the constant term M v_a of the first P2 row.
#[derive(Clone, Debug)]
pub struct StepStart {
    pub e: Vec<f64>,
    pub v: Vec<f64>,
    pub mass_v: Vec<f64>,
}

/// Scratch for the assembly, allocated once.
#[derive(Clone, Debug)]
pub struct AssemblyScratch {
    derivs2: SlabDerivatives<12>,
    derivs3: SlabDerivatives<18>,
    /// v_L gathered as a global vector, and M v_L.
    v_end: Vec<f64>,
    mass_v_end: Vec<f64>,
}

impl AssemblyScratch {
    pub fn new(model: &Model) -> Self {
        AssemblyScratch {
            derivs2: SlabDerivatives::default(),
            derivs3: SlabDerivatives::default(),
            v_end: vec![0.0; model.dofs()],
            mass_v_end: vec![0.0; model.dofs()],
        }
    }
}

/// Coordinates of (time node i, kind) of element k: from the known start
/// for i = 0, from the unknowns otherwise.
fn element_values<const ND: usize>(
    layout: &SlabLayout,
    start: &StepStart,
    x: &[f64],
    i: usize,
    kind: Kind,
    k: usize,
) -> [f64; ND] {
    let dpn = layout.dpn;
    match layout.unknown(i, kind, k) {
        None => match kind {
            Kind::Position => gather(&start.e, k * dpn),
            Kind::Velocity => gather(&start.v, k * dpn),
        },
        Some(u0) => {
            let u1 = layout.unknown(i, kind, k + 1).expect("neighbour node");
            let mut out = [0.0; ND];
            out[..dpn].copy_from_slice(&x[u0..u0 + dpn]);
            out[dpn..].copy_from_slice(&x[u1..u1 + dpn]);
            out
        }
    }
}

/// Global index of element entry d at time node i of kind, through `map`
/// (equation or unknown numbering).
#[inline]
fn local_to_global(first: [Option<usize>; 2], dpn: usize, d: usize) -> Option<usize> {
    if d < dpn {
        first[0].map(|b| b + d)
    } else {
        first[1].map(|b| b + d - dpn)
    }
}

const SLOTS: [(usize, Kind); 4] = [
    (0, Kind::Position),
    (0, Kind::Velocity),
    (1, Kind::Position),
    (1, Kind::Velocity),
];

/// The equations of one step: the model, their numbering, the time slab of
/// one layer (dt / L) and the known start.
#[derive(Clone, Copy)]
pub struct StepProblem<'a> {
    pub model: &'a Model,
    pub layout: &'a SlabLayout,
    pub slab: &'a TimeSlab,
    pub start: &'a StepStart,
}

fn assemble_elements<const NS: usize, const ND: usize>(
    p: &StepProblem,
    elements: &[CableElement<NS, ND>],
    derivs: &mut SlabDerivatives<ND>,
    x: &[f64],
    residual: &mut [f64],
    mut jacobian: Option<&mut BandMatrix>,
) {
    let (layout, slab, start) = (p.layout, p.slab, p.start);
    let gravity = &p.model.gravity;
    let dpn = layout.dpn;
    let mut block = [[0.0; ND]; ND];
    for j in 0..layout.layers {
        for (k, el) in elements.iter().enumerate() {
            let mut y = [[0.0; ND]; 4];
            for (m, &(di, kind)) in SLOTS.iter().enumerate() {
                y[m] = element_values(layout, start, x, j + di, kind, k);
            }
            el.slab_derivatives(slab, &y, gravity, jacobian.is_some(), derivs);
            let rows: [[Option<usize>; 2]; 4] = SLOTS.map(|(di, kind)| {
                [
                    layout.equation(j + di, kind, k),
                    layout.equation(j + di, kind, k + 1),
                ]
            });
            let cols: [[Option<usize>; 2]; 4] = SLOTS.map(|(di, kind)| {
                [
                    layout.unknown(j + di, kind, k),
                    layout.unknown(j + di, kind, k + 1),
                ]
            });
            for m in 0..4 {
                if rows[m][0].is_none() {
                    continue;
                }
                for d in 0..ND {
                    let r = local_to_global(rows[m], dpn, d).expect("row");
                    residual[r] += derivs.grad[m][d];
                }
            }
            let Some(jac) = jacobian.as_deref_mut() else {
                continue;
            };
            for m in 0..4 {
                if rows[m][0].is_none() {
                    continue;
                }
                for n in 0..4 {
                    if cols[n][0].is_none() {
                        continue;
                    }
                    el.slab_hessian_block(slab, derivs, m, n, &mut block);
                    for (a, brow) in block.iter().enumerate() {
                        let r = local_to_global(rows[m], dpn, a).expect("row");
                        for (b, &val) in brow.iter().enumerate() {
                            if val != 0.0 {
                                let c = local_to_global(cols[n], dpn, b).expect("col");
                                jac.add(r, c, val);
                            }
                        }
                    }
                }
            }
        }
    }
}

impl StepProblem<'_> {
    /// Residual R(x) of the step's equations and, if asked, the Jacobian
    /// dR/dx. Both outputs are overwritten.
    pub fn assemble(
        &self,
        x: &[f64],
        residual: &mut [f64],
        jacobian: Option<&mut BandMatrix>,
        scratch: &mut AssemblyScratch,
    ) {
        assemble_step(self, x, residual, jacobian, scratch)
    }
}

fn assemble_step(
    p: &StepProblem,
    x: &[f64],
    residual: &mut [f64],
    mut jacobian: Option<&mut BandMatrix>,
    scratch: &mut AssemblyScratch,
) {
    let (model, layout, slab, start) = (p.model, p.layout, p.slab, p.start);
    residual.fill(0.0);
    if let Some(j) = jacobian.as_deref_mut() {
        j.clear();
    }
    let jac = jacobian.as_deref_mut();
    match &model.mesh {
        crate::model::Mesh::Sac2(els) => {
            assemble_elements(p, els, &mut scratch.derivs2, x, residual, jac)
        }
        crate::model::Mesh::Sac3(els) => {
            assemble_elements(p, els, &mut scratch.derivs3, x, residual, jac)
        }
    }
    let dpn = layout.dpn;
    let last = layout.layers;
    // Point forces, eq. (14): work sum_m b_m F . r_m on every layer.
    for (node, force) in model.point_forces() {
        for j in 0..layout.layers {
            for (m, &(di, kind)) in SLOTS.iter().enumerate() {
                if let Some(r) = layout.equation(j + di, kind, node) {
                    for c in 0..3 {
                        residual[r + c] += slab.load[m] * force[c];
                    }
                }
            }
        }
    }
    // P2 momentum terms: + M v_0 on row e_0, - M v_L on row e_L.
    for node in 0..layout.nodes {
        let r0 = layout.equation(0, Kind::Position, node).expect("row e_0");
        let u = layout.unknown(last, Kind::Velocity, node).expect("v_L");
        for c in 0..dpn {
            residual[r0 + c] += start.mass_v[node * dpn + c];
            scratch.v_end[node * dpn + c] = x[u + c];
        }
    }
    model.mass_times(&scratch.v_end, &mut scratch.mass_v_end);
    for node in 0..layout.nodes {
        let rl = layout
            .equation(last, Kind::Position, node)
            .expect("row e_L");
        for c in 0..dpn {
            residual[rl + c] -= scratch.mass_v_end[node * dpn + c];
        }
    }
    if let Some(jac) = jacobian {
        crate::with_elements!(&model.mesh, els => {
            for (k, el) in els.iter().enumerate() {
                for (a, mrow) in el.mass.iter().enumerate() {
                    for (b, &mab) in mrow.iter().enumerate() {
                        // shape function a of element k lives on node k + a / vpn
                        let na = k + (3 * a) / dpn;
                        let ca = (3 * a) % dpn;
                        let nb = k + (3 * b) / dpn;
                        let cb = (3 * b) % dpn;
                        let r = layout.equation(last, Kind::Position, na).expect("row") + ca;
                        let c = layout.unknown(last, Kind::Velocity, nb).expect("col") + cb;
                        for i in 0..3 {
                            jac.add(r + i, c + i, -mab);
                        }
                    }
                }
            }
        });
    }
}

/// Scales that turn increments and residuals into fractions of the cable
/// length (method notes, "Residual scaling"):
///
/// - an unknown e of kind r, r_x, r_xx is weighted by 1, l, l^2 (its effect
///   on the centre line inside an element), a velocity unknown also by h = dt/L;
/// - a row dA/de of coordinate c is weighted by h s_c / m_c, m_c the
///   diagonal of the mass matrix (kinetic part of the Jacobian ~ M / h),
///   a row dA/dv by s_c / m_c;
///
/// and everything is divided by the cable length.
#[derive(Clone, Debug)]
pub struct Scales {
    pub unknown: Vec<f64>,
    pub equation: Vec<f64>,
}

impl Scales {
    pub fn new(model: &Model, layout: &SlabLayout, layer_dt: f64) -> Self {
        let n = layout.size();
        let mut unknown = vec![0.0; n];
        let mut equation = vec![0.0; n];
        let mass = model.mass_diagonal();
        let len = model.cable.length;
        let dpn = layout.dpn;
        for node in 0..layout.nodes {
            for c in 0..dpn {
                let s = model.coordinate_length_scale(c) / len;
                let m = mass[node * dpn + c];
                for i in 0..=layout.layers {
                    if let Some(u) = layout.unknown(i, Kind::Position, node) {
                        unknown[u + c] = s;
                    }
                    if let Some(u) = layout.unknown(i, Kind::Velocity, node) {
                        unknown[u + c] = s * layer_dt;
                    }
                    if let Some(r) = layout.equation(i, Kind::Position, node) {
                        equation[r + c] = s * layer_dt / m;
                    }
                    if let Some(r) = layout.equation(i, Kind::Velocity, node) {
                        equation[r + c] = s / m;
                    }
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
