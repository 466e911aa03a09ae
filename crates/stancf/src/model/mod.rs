//! The cable model: geometry, material, mesh, loads and DOF numbering.
//!
//! Global coordinates are numbered node by node: node j owns
//! `e[j * dpn .. (j + 1) * dpn]` = `[r, r_x]` (SAC-2, dpn = 6) or
//! `[r, r_x, r_xx]` (SAC-3, dpn = 9). Element k spans nodes k and k + 1, so
//! its coordinates are the contiguous slice starting at `k * dpn`, in the
//! element's own order (docs/method.md §1.1). [`coordinate`] computes
//! every such index; the rest of the crate calls it.
//!
//! This module holds the [`Model`], its mesh and state and their core
//! accessors; the rest is split by meaning:
//!
//! | file | holds |
//! |---|---|
//! | `cable.rs` | [`Cable`] and [`ElementType`] (§1.1-§1.3) |
//! | `grading.rs` | [`Grading`]: the node coordinates of uniform and graded meshes (§1.6) |
//! | `material.rs` | [`Material`] and its derived figures (§2.1, §2.4) |
//! | `coordinates.rs` | the index function, slots, node ranges, planar coordinates (§1.1, §6.7) |
//! | `quadrature_choice.rs` | [`SpacePoints`], [`ModelOptions`], default points, rank warnings (§3.3-§3.4) |
//! | `applied_loads.rs` | [`Load`] and its validation (§2.5-§2.8) |
//! | `mass.rs` | the global mass matrix products (§2.1) |
//! | `validate.rs` | checks of the input figures |

use crate::constraints::{Constraint, Constraints};
use crate::element::{CableElement, Measures, Section, SpaceRules};
use crate::error::ModelError;
use crate::shape::{cubic_hermite, quintic_hermite};

mod applied_loads;
mod cable;
mod coordinates;
mod entrained;
mod grading;
mod internal_state;
mod mass;
mod material;
mod quadrature_choice;
mod validate;

pub use crate::numbering::{coordinate, node_range, ElementType, SLOT_R, SLOT_R_X, SLOT_R_XX};
pub use applied_loads::Load;
pub use cable::Cable;
pub use grading::{GradedEnd, Grading, MeshSection};
pub(crate) use mass::gather;
pub use material::Material;
pub use quadrature_choice::{ModelOptions, SpacePoints};

/// The elements of the mesh, one variant per element type so that the
/// generic kernel is monomorphized for SAC-2 and SAC-3.
#[derive(Clone, Debug)]
pub enum Mesh {
    Sac2(Vec<CableElement<4, 12>>),
    Sac3(Vec<CableElement<6, 18>>),
}

/// Runs `$body` with `$els` bound to the element slice of either type.
#[macro_export]
#[doc(hidden)]
macro_rules! with_elements {
    ($mesh:expr, $els:ident => $body:expr) => {
        match $mesh {
            $crate::model::Mesh::Sac2($els) => $body,
            $crate::model::Mesh::Sac3($els) => $body,
        }
    };
}

/// A cable model ready to simulate.
#[derive(Clone, Debug)]
pub struct Model {
    pub cable: Cable,
    pub material: Material,
    pub options: ModelOptions,
    pub loads: Vec<Load>,
    pub mesh: Mesh,
    /// Sum of the gravity loads.
    pub gravity: [f64; 3],
    /// The drag loads.
    pub drag: Vec<crate::loads::AirDrag>,
    /// The seabed the cable can touch (docs/method.md §12.2).
    pub seabed: Option<crate::water::SeabedContact>,
    /// The water the cable is in (docs/method.md §12.3-12.5).
    pub water: Option<crate::water::LineInWater>,
    /// Constraints, resolved to coordinates (none for a free cable).
    pub constraints: Constraints,
    /// Material coordinate x_j of every node ([`Grading::node_coordinates`]).
    node_x: Vec<f64>,
}

/// Positions e and velocities v of all coordinates at time t, and the
/// internal state of the line's material.
#[derive(Debug, PartialEq)]
pub struct State {
    pub t: f64,
    pub e: Vec<f64>,
    pub v: Vec<f64>,
    /// A viscoelastic line's strain eps1 of its static spring, and a VIV
    /// line's shedding phase and mean squares, at every point of every
    /// element's axial rule, element after element (docs/method.md
    /// §2.11, §12.7; [`Model::internal_state_len`]). Empty: no such line,
    /// or, given to a simulation, the line at rest at `e`.
    pub internal: Vec<f64>,
}

impl Clone for State {
    fn clone(&self) -> Self {
        State {
            t: self.t,
            e: self.e.clone(),
            v: self.v.clone(),
            internal: self.internal.clone(),
        }
    }

    /// Reuses the buffers (the derived `clone_from` would allocate).
    fn clone_from(&mut self, source: &Self) {
        self.t = source.t;
        self.e.clone_from(&source.e);
        self.v.clone_from(&source.v);
        self.internal.clone_from(&source.internal);
    }
}

impl Mesh {
    /// Elements of type `element_type`, element k of length `lengths[k]`.
    fn build(
        element_type: ElementType,
        lengths: &[f64],
        section: Section,
        measures: Measures,
        rules: &SpaceRules,
    ) -> Self {
        match element_type {
            ElementType::Sac2 => Mesh::Sac2(
                lengths
                    .iter()
                    .map(|&l| CableElement::new(cubic_hermite, l, section.clone(), measures, rules))
                    .collect(),
            ),
            ElementType::Sac3 => Mesh::Sac3(
                lengths
                    .iter()
                    .map(|&l| {
                        CableElement::new(quintic_hermite, l, section.clone(), measures, rules)
                    })
                    .collect(),
            ),
        }
    }
}

/// The most elements a cable (or a line of a system) may have: a line of
/// this many takes about 9 GB to build with its static solve and
/// simulation (8.6 kB per element, measured on a line of 1e5 elements)
/// and about 20 GB to solve statically, beyond what a run of a cable
/// needs (docs/interface.md, "Bounds and bad input").
pub const MAX_ELEMENTS: usize = 1_000_000;

impl Model {
    /// Validates the data and builds the mesh.
    pub fn new(
        cable: Cable,
        material: Material,
        options: ModelOptions,
        loads: Vec<Load>,
    ) -> Result<Self, ModelError> {
        let cable = validate::cable(cable)?;
        validate::material(&material)?;
        let points = options
            .space_points
            .unwrap_or_else(|| cable.element_type.default_space_points());
        let rules = quadrature_choice::space_rules(points)?;
        let (gravity, drag) = applied_loads::gravity_and_drag(&loads, cable.elements)?;
        let seabed = applied_loads::seabed(&loads)?;
        let water = applied_loads::water(&loads)?;
        let lengths = cable.grading.element_lengths(cable.length, cable.elements);
        let node_x = cable.grading.node_coordinates(cable.length, cable.elements);
        let section = material.section();
        let measures = options.measures;
        let mesh = Mesh::build(cable.element_type, &lengths, section, measures, &rules);
        let dofs = (cable.elements + 1) * cable.element_type.dofs_per_node();
        Ok(Model {
            cable,
            material,
            options,
            loads,
            mesh,
            gravity,
            drag,
            seabed,
            water,
            constraints: Constraints {
                motion: vec![None; dofs],
                ..Constraints::default()
            },
            node_x,
        })
    }

    /// The model of a line that carries no compression (chains, ropes):
    /// its axial energy is zero where it is shortened (docs/method.md
    /// §2.2, (M4a)).
    pub fn without_compression(mut self) -> Self {
        match &mut self.mesh {
            Mesh::Sac2(els) => els.iter_mut().for_each(|e| e.section.tension_only = true),
            Mesh::Sac3(els) => els.iter_mut().for_each(|e| e.section.tension_only = true),
        }
        self
    }

    /// The model whose elements' axial law is the table `curve` instead
    /// of EA eps (docs/method.md §2.2a, (M4b)). The table is in
    /// engineering strain: a model of Green's strain is refused.
    pub fn with_axial_curve(
        mut self,
        curve: std::sync::Arc<crate::element::AxialCurve>,
    ) -> Result<Self, ModelError> {
        if self.options.measures.axial_strain != crate::AxialStrain::Engineering {
            return Err(ModelError::invalid(
                "axial_curve",
                "a tension-strain curve is in engineering strain (|r_x| - 1); the model's axial \
                 strain is Green's",
            ));
        }
        match &mut self.mesh {
            Mesh::Sac2(els) => els
                .iter_mut()
                .for_each(|e| e.section.curve = Some(curve.clone())),
            Mesh::Sac3(els) => els
                .iter_mut()
                .for_each(|e| e.section.curve = Some(curve.clone())),
        }
        Ok(self)
    }

    /// The line's nonlinear axial law (M4b), if it has one.
    pub fn axial_curve(&self) -> Option<&crate::element::AxialCurve> {
        crate::with_elements!(&self.mesh, els => els.first().and_then(|e| e.section.curve.as_deref()))
    }

    /// The model with every element carrying compression again (what the
    /// static solve of a line without compression takes: docs/method.md
    /// §2.2, (M4a)).
    pub fn with_compression(mut self) -> Self {
        match &mut self.mesh {
            Mesh::Sac2(els) => els.iter_mut().for_each(|e| e.section.tension_only = false),
            Mesh::Sac3(els) => els.iter_mut().for_each(|e| e.section.tension_only = false),
        }
        self
    }

    /// Whether the line carries compression (see
    /// [`Self::without_compression`]).
    pub fn carries_compression(&self) -> bool {
        crate::with_elements!(&self.mesh, els => els.iter().all(|e| !e.section.tension_only))
    }

    /// The model with these constraints (replacing any before).
    pub fn with_constraints(mut self, list: Vec<Constraint>) -> Result<Self, ModelError> {
        let reference = self.reference_coordinates();
        self.constraints = Constraints::new(list, self.element_type(), self.nodes(), &reference)?;
        Ok(self)
    }

    /// Coordinates of the straight, stress-free reference shape:
    /// r_j = origin + x_j d, r_x = d, r_xx = 0.
    pub fn reference_coordinates(&self) -> Vec<f64> {
        let mut e = vec![0.0; self.dofs()];
        let d = self.cable.direction;
        for j in 0..self.nodes() {
            let o = self.node_offset(j);
            let x = self.node_coordinate(j);
            for i in 0..3 {
                e[o + i] = self.cable.origin[i] + x * d[i];
                e[o + 3 + i] = d[i];
            }
        }
        e
    }

    pub fn element_type(&self) -> ElementType {
        self.cable.element_type
    }

    /// Spatial nodes (elements + 1).
    pub fn nodes(&self) -> usize {
        self.cable.elements + 1
    }

    /// Scalar coordinates per node.
    pub fn dofs_per_node(&self) -> usize {
        self.cable.element_type.dofs_per_node()
    }

    /// Scalar coordinates of the mesh.
    pub fn dofs(&self) -> usize {
        self.nodes() * self.dofs_per_node()
    }

    /// Whether the cable has axial damping (BA > 0, docs/method.md §2.10).
    pub fn has_axial_damping(&self) -> bool {
        self.material.axial_damping != 0.0
    }

    /// Reference length l_k of element k (`L / n` on a uniform mesh;
    /// docs/method.md §1.6).
    pub fn element_length(&self, element: usize) -> f64 {
        crate::with_elements!(&self.mesh, els => els[element].length)
    }

    /// The shortest element's length: the one that bounds the stable
    /// step and the Courant number (docs/method.md §4.6).
    pub fn shortest_element_length(&self) -> f64 {
        crate::with_elements!(&self.mesh, els => {
            els.iter().map(|e| e.length).fold(f64::INFINITY, f64::min)
        })
    }

    /// The longest element's length.
    pub fn longest_element_length(&self) -> f64 {
        crate::with_elements!(&self.mesh, els => els.iter().map(|e| e.length).fold(0.0, f64::max))
    }

    /// Material coordinate (reference arc length from end A) of node j:
    /// `x_j` of [`Grading::node_coordinates`] (docs/method.md §1.6).
    pub fn node_coordinate(&self, node: usize) -> f64 {
        self.node_x[node]
    }

    /// The material coordinates of all nodes, x_0 = 0 to x_n.
    pub fn node_coordinates(&self) -> &[f64] {
        &self.node_x
    }

    /// Material coordinate of the point at `xi` in [0, 1] of element k:
    /// `x_k + xi l_k`, written `(k + xi) l` on a uniform mesh (the same
    /// number up to round-off; that form keeps the numbers of earlier
    /// versions).
    pub fn material_coordinate(&self, element: usize, xi: f64) -> f64 {
        let l = self.element_length(element);
        if self.cable.grading.is_uniform() {
            (element as f64 + xi) * l
        } else {
            self.node_x[element] + xi * l
        }
    }

    /// Position r of node j in state e.
    pub fn node_position(&self, e: &[f64], node: usize) -> [f64; 3] {
        let o = self.node_offset(node);
        [e[o], e[o + 1], e[o + 2]]
    }

    /// The straight reference shape at rest at t = 0, with constrained
    /// coordinates at their prescribed values and rates.
    pub fn initial_state(&self) -> State {
        let n = self.dofs();
        let mut s = State {
            t: 0.0,
            e: self.reference_coordinates(),
            v: vec![0.0; n],
            internal: Vec::new(),
        };
        self.apply_constraints(&mut s);
        s
    }

    /// Sets every constrained coordinate of `state` to its prescribed value
    /// and rate at `state.t`.
    /// A node whose r_x is held parallel to a direction d (§6.10) has r_x
    /// turned onto d with its length and sense kept, and the rate of r_x
    /// projected onto d; at a free body (a turning hold, §15.19) the rate
    /// is the system's to set (the body's spin turns d), and is kept.
    pub fn apply_constraints(&self, state: &mut State) {
        for (g, m) in self.constraints.motion.iter().enumerate() {
            if let Some(m) = m {
                state.e[g] = m.value(state.t);
                state.v[g] = m.rate_at(state.t);
            }
        }
        for h in &self.constraints.directions {
            let o = coordinate(self.dofs_per_node(), h.node, SLOT_R_X, 0);
            let d = h.direction;
            let along = |x: &[f64]| d[0] * x[o] + d[1] * x[o + 1] + d[2] * x[o + 2];
            let length = (0..3).map(|c| state.e[o + c].powi(2)).sum::<f64>().sqrt();
            let sense = if along(&state.e) < 0.0 { -1.0 } else { 1.0 };
            let rate = along(&state.v);
            for c in 0..3 {
                state.e[o + c] = sense * length * d[c];
                if !h.turning {
                    state.v[o + c] = rate * d[c];
                }
            }
        }
    }

    /// Sets the velocity of the position r of node j (its gradients keep
    /// their velocity).
    pub fn set_node_velocity(&self, state: &mut State, node: usize, velocity: [f64; 3]) {
        let o = self.node_offset(node);
        state.v[o..o + 3].copy_from_slice(&velocity);
    }

    /// Adds a rigid rotation w x (r - center) to every node's r velocity and
    /// w x r_x (w x r_xx) to its gradients' velocities.
    pub fn add_rigid_rotation(&self, state: &mut State, omega: [f64; 3], center: [f64; 3]) {
        let vpn = self.cable.element_type.vectors_per_node();
        for j in 0..self.nodes() {
            for k in 0..vpn {
                let b = self.coordinate(j, k, 0);
                let mut arm = [state.e[b], state.e[b + 1], state.e[b + 2]];
                if k == 0 {
                    for i in 0..3 {
                        arm[i] -= center[i];
                    }
                }
                let w = crate::vec3::cross(omega, arm);
                for i in 0..3 {
                    state.v[b + i] += w[i];
                }
            }
        }
    }
}
