//! The cable model: geometry, material, mesh, loads and DOF numbering.
//!
//! Global coordinates are numbered node by node: node j owns
//! `e[j * dpn .. (j + 1) * dpn]` = `[r, r_x]` (SAC-2, dpn = 6) or
//! `[r, r_x, r_xx]` (SAC-3, dpn = 9). Element k spans nodes k and k + 1, so
//! its coordinates are the contiguous slice starting at `k * dpn`, in the
//! element's own order (docs/method.md §1.1). [`coordinate`] computes
//! every such index; the rest of the crate calls it.

use crate::constraints::{Constraint, Constraints};
use crate::element::{CableElement, Measures, Section, SpaceRules};
use crate::error::ModelError;
use crate::quadrature::GaussRule;
use crate::shape::{cubic_hermite, quintic_hermite};
use std::ops::Range;

/// Vector slot of the position r in a node's coordinates.
pub const SLOT_R: usize = 0;
/// Vector slot of the gradient r_x.
pub const SLOT_R_X: usize = 1;
/// Vector slot of the second gradient r_xx (SAC-3 only).
pub const SLOT_R_XX: usize = 2;

/// Global index of component `component` (x, y, z = 0, 1, 2) of vector
/// `slot` ([`SLOT_R`], [`SLOT_R_X`], [`SLOT_R_XX`]) of node `node`, with
/// `dpn` scalar coordinates per node: `node dpn + 3 slot + component`
/// (docs/method.md §1.1). The one place the numbering is written; every
/// index of a coordinate is computed here. An element's coordinates are
/// contiguous from its first node's, so a slot past the node's own
/// vectors counts on into the next node: element k's vector a (its own
/// order, 0..NS) is `coordinate(dpn, k, a, i)`, and `coordinate(dpn, k,
/// SLOT_R, 0)` is the start of element k's slice.
#[inline]
pub const fn coordinate(dpn: usize, node: usize, slot: usize, component: usize) -> usize {
    node * dpn + 3 * slot + component
}

/// The coordinates of node `node`: `[r, r_x(, r_xx)]`.
#[inline]
pub const fn node_range(dpn: usize, node: usize) -> Range<usize> {
    coordinate(dpn, node, SLOT_R, 0)..coordinate(dpn, node + 1, SLOT_R, 0)
}

/// The two space-time elements of the paper (Table 1).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ElementType {
    /// Cubic Hermite in space (eq. 4): nodal r, r_x.
    Sac2,
    /// Quintic Hermite in space (eq. 5): nodal r, r_x, r_xx.
    Sac3,
}

impl ElementType {
    /// Vector coordinates per node (2 or 3).
    pub fn vectors_per_node(self) -> usize {
        match self {
            ElementType::Sac2 => 2,
            ElementType::Sac3 => 3,
        }
    }

    /// Scalar coordinates per node (6 or 9).
    pub fn dofs_per_node(self) -> usize {
        3 * self.vectors_per_node()
    }

    /// Gauss points in space (axial, bending) used when none are given:
    /// the paper's choices, 3 for SAC-2 ("3 x 3") and 5 for SAC-3
    /// ("5 x 3", Table 5); docs/method.md §3.3.
    pub fn default_space_points(self) -> SpacePoints {
        match self {
            ElementType::Sac2 => SpacePoints {
                axial: 3,
                bending: 3,
            },
            ElementType::Sac3 => SpacePoints {
                axial: 5,
                bending: 5,
            },
        }
    }

    /// The fewest Gauss points that leave no spurious zero-energy mode in
    /// any element (continuity can suppress such a mode in a mesh, so
    /// fewer points are not always singular).
    /// With NS shape functions the linearized axial strain u' is a
    /// polynomial of degree NS - 2 in each element and the curvature
    /// (r_xx) one of degree NS - 3; n points annihilate a nonzero
    /// polynomial of degree d only if n <= d, so the rank needs NS - 1
    /// axial and NS - 2 bending points (SAC-2: 3 and 2; SAC-3: 5 and 4;
    /// docs/method.md §3.4, (M15)).
    pub fn minimal_space_points(self) -> SpacePoints {
        let ns = 2 * self.vectors_per_node();
        SpacePoints {
            axial: ns - 1,
            bending: ns - 2,
        }
    }

    pub fn name(self) -> &'static str {
        match self {
            ElementType::Sac2 => "SAC-2",
            ElementType::Sac3 => "SAC-3",
        }
    }
}

/// Material and cross-section (Tables 2 and 9).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Material {
    /// E (Pa).
    pub youngs_modulus: f64,
    /// rho (kg/m^3).
    pub density: f64,
    /// A (m^2).
    pub area: f64,
    /// I (m^4).
    pub second_moment: f64,
}

impl Material {
    /// The paper's PVC cable (Table 2): E 3.4 GPa, rho 1380 kg/m^3,
    /// I 1.25e-13 m^4, A 3e-6 m^2.
    pub fn chen2023_pvc() -> Self {
        Material {
            youngs_modulus: 3.4e9,
            density: 1380.0,
            area: 3.0e-6,
            second_moment: 1.25e-13,
        }
    }

    /// The paper's gutta-percha cable (Table 9): E 0.91 MPa,
    /// rho 1202 kg/m^3, I 9.15e-12 m^4, A 1.075e-5 m^2.
    pub fn chen2023_gutta_percha() -> Self {
        Material {
            youngs_modulus: 0.91e6,
            density: 1202.0,
            area: 1.075e-5,
            second_moment: 9.15e-12,
        }
    }

    pub fn section(&self) -> Section {
        Section {
            ea: self.youngs_modulus * self.area,
            ei: self.youngs_modulus * self.second_moment,
            rho_a: self.density * self.area,
        }
    }

    /// Longitudinal wave speed c = sqrt(E / rho).
    pub fn wave_speed(&self) -> f64 {
        (self.youngs_modulus / self.density).sqrt()
    }
}

/// A straight cable in its stress-free reference state.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Cable {
    pub length: f64,
    pub elements: usize,
    pub element_type: ElementType,
    /// Position of end A (x = 0).
    pub origin: [f64; 3],
    /// Unit tangent of the reference shape (normalized on construction).
    pub direction: [f64; 3],
}

impl Cable {
    /// A cable along +x from the origin.
    pub fn straight(length: f64, elements: usize, element_type: ElementType) -> Self {
        Cable {
            length,
            elements,
            element_type,
            origin: [0.0; 3],
            direction: [1.0, 0.0, 0.0],
        }
    }

    pub fn with_origin(mut self, origin: [f64; 3]) -> Self {
        self.origin = origin;
        self
    }

    pub fn with_direction(mut self, direction: [f64; 3]) -> Self {
        self.direction = direction;
        self
    }
}

/// A load on the cable.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Load {
    /// Distributed weight rho A g, eq. (13).
    Gravity { acceleration: [f64; 3] },
    /// Constant force on the position of a node, eq. (14).
    PointForce { node: usize, force: [f64; 3] },
    /// Moment vector M n (N m) on the tangent r_x of a node, eqs. (15)-(16):
    /// work M theta, theta the rotation of r_x about n (see [`crate::loads`]).
    EndMoment { node: usize, moment: [f64; 3] },
    /// Air drag along the whole cable, eq. (17) (see [`crate::loads::AirDrag`]).
    AirDrag(crate::loads::AirDrag),
}

/// Gauss points per element in space for the axial and the bending
/// energy (the paper uses one rule for both).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct SpacePoints {
    pub axial: usize,
    pub bending: usize,
}

/// How the strain energy is computed.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct ModelOptions {
    pub measures: Measures,
    /// Spatial quadrature; `None` takes the element's default
    /// ([`ElementType::default_space_points`]).
    pub space_points: Option<SpacePoints>,
}

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
    /// Constraints, resolved to coordinates (none for a free cable).
    pub constraints: Constraints,
}

/// Positions e and velocities v of all coordinates at time t.
#[derive(Debug, PartialEq)]
pub struct State {
    pub t: f64,
    pub e: Vec<f64>,
    pub v: Vec<f64>,
}

impl Clone for State {
    fn clone(&self) -> Self {
        State {
            t: self.t,
            e: self.e.clone(),
            v: self.v.clone(),
        }
    }

    /// Reuses the buffers (the derived `clone_from` would allocate).
    fn clone_from(&mut self, source: &Self) {
        self.t = source.t;
        self.e.clone_from(&source.e);
        self.v.clone_from(&source.v);
    }
}

fn check_positive(key: &str, value: f64) -> Result<(), ModelError> {
    if !value.is_finite() {
        return Err(ModelError::invalid(
            key,
            format!("must be a finite number, got {value}"),
        ));
    }
    if value <= 0.0 {
        return Err(ModelError::invalid(
            key,
            format!("must be > 0, got {value}"),
        ));
    }
    Ok(())
}

fn check_vector(key: &str, v: &[f64; 3]) -> Result<(), ModelError> {
    if v.iter().any(|x| !x.is_finite()) {
        return Err(ModelError::invalid(
            key,
            format!("must have finite components, got {v:?}"),
        ));
    }
    Ok(())
}

impl Model {
    /// Validates the data and builds the mesh.
    pub fn new(
        cable: Cable,
        material: Material,
        options: ModelOptions,
        loads: Vec<Load>,
    ) -> Result<Self, ModelError> {
        check_positive("cable.length", cable.length)?;
        if cable.elements == 0 {
            return Err(ModelError::invalid(
                "cable.elements",
                "must be at least 1, got 0",
            ));
        }
        check_vector("cable.origin", &cable.origin)?;
        check_vector("cable.direction", &cable.direction)?;
        let norm = crate::element::dot(&cable.direction, &cable.direction).sqrt();
        if norm == 0.0 {
            return Err(ModelError::invalid(
                "cable.direction",
                "must not be the zero vector",
            ));
        }
        let mut cable = cable;
        cable.direction = cable.direction.map(|c| c / norm);
        check_positive("material.youngs_modulus", material.youngs_modulus)?;
        check_positive("material.density", material.density)?;
        check_positive("material.area", material.area)?;
        check_positive("material.second_moment", material.second_moment)?;
        let points = options
            .space_points
            .unwrap_or_else(|| cable.element_type.default_space_points());
        let rules = SpaceRules {
            axial: GaussRule::new(points.axial)
                .map_err(|e| ModelError::invalid("analysis.quadrature", e.message))?,
            bending: GaussRule::new(points.bending)
                .map_err(|e| ModelError::invalid("analysis.quadrature", e.message))?,
        };
        let mut gravity = [0.0; 3];
        let mut drag = Vec::new();
        for (i, load) in loads.iter().enumerate() {
            match load {
                Load::AirDrag(d) => {
                    let k = format!("loads[{i}]");
                    let nonneg = |name: &str, v: f64| -> Result<(), ModelError> {
                        if v.is_finite() && v >= 0.0 {
                            Ok(())
                        } else {
                            Err(ModelError::invalid(
                                format!("{k}.{name}"),
                                format!("must be a finite number >= 0, got {v}"),
                            ))
                        }
                    };
                    nonneg("drag_coefficient", d.drag_coefficient)?;
                    nonneg("fluid_density", d.fluid_density)?;
                    check_positive(&format!("{k}.diameter"), d.diameter)?;
                    check_vector(&format!("{k}.fluid_velocity"), &d.fluid_velocity)?;
                    if let crate::loads::DragModel::Normal {
                        tangential_coefficient,
                    } = d.model
                    {
                        nonneg("tangential_coefficient", tangential_coefficient)?;
                    }
                    drag.push(*d);
                }
                Load::Gravity { acceleration } => {
                    check_vector(&format!("loads[{i}].acceleration"), acceleration)?;
                    for c in 0..3 {
                        gravity[c] += acceleration[c];
                    }
                }
                Load::PointForce { node, force: v } | Load::EndMoment { node, moment: v } => {
                    let name = match load {
                        Load::PointForce { .. } => "force",
                        _ => "moment",
                    };
                    check_vector(&format!("loads[{i}].{name}"), v)?;
                    if *node > cable.elements {
                        return Err(ModelError::invalid(
                            format!("loads[{i}].node"),
                            format!(
                                "node {node} does not exist (nodes are 0..={})",
                                cable.elements
                            ),
                        ));
                    }
                }
            }
        }
        let l = cable.length / cable.elements as f64;
        let section = material.section();
        let measures = options.measures;
        let mesh = match cable.element_type {
            ElementType::Sac2 => Mesh::Sac2(
                (0..cable.elements)
                    .map(|_| CableElement::new(cubic_hermite, l, section, measures, &rules))
                    .collect(),
            ),
            ElementType::Sac3 => Mesh::Sac3(
                (0..cable.elements)
                    .map(|_| CableElement::new(quintic_hermite, l, section, measures, &rules))
                    .collect(),
            ),
        };
        let nodes = cable.elements + 1;
        Ok(Model {
            cable,
            material,
            options,
            loads,
            mesh,
            gravity,
            drag,
            constraints: Constraints {
                motion: vec![None; nodes * cable.element_type.dofs_per_node()],
                ..Constraints::default()
            },
        })
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

    /// The spatial quadrature in use.
    pub fn space_points(&self) -> SpacePoints {
        self.options
            .space_points
            .unwrap_or_else(|| self.cable.element_type.default_space_points())
    }

    /// Warnings about the model that do not make it invalid: a spatial
    /// quadrature too coarse to give every element's stiffness full rank
    /// (the mesh may then have spurious zero-energy modes that drift
    /// without bound; docs/method.md §3.4, (M15)).
    pub fn warnings(&self) -> Vec<String> {
        let p = self.space_points();
        let min = self.cable.element_type.minimal_space_points();
        let mut w = Vec::new();
        let name = self.cable.element_type.name();
        if p.axial < min.axial {
            w.push(format!(
                "{} Gauss points for the axial energy of {name} may leave spurious zero-energy modes \
                 ({} or more avoid them)",
                p.axial, min.axial
            ));
        }
        if p.bending < min.bending {
            w.push(format!(
                "{} Gauss points for the bending energy of {name} may leave spurious zero-energy modes \
                 ({} or more avoid them)",
                p.bending, min.bending
            ));
        }
        w
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

    /// Element length l.
    pub fn element_length(&self) -> f64 {
        self.cable.length / self.cable.elements as f64
    }

    /// Material coordinate of node j.
    pub fn node_coordinate(&self, node: usize) -> f64 {
        node as f64 * self.element_length()
    }

    /// Index of the first coordinate of node j.
    pub fn node_offset(&self, node: usize) -> usize {
        self.coordinate(node, SLOT_R, 0)
    }

    /// Global index of component `component` of vector `slot` of node
    /// `node` (see [`coordinate`]).
    #[inline]
    pub fn coordinate(&self, node: usize, slot: usize, component: usize) -> usize {
        coordinate(self.dofs_per_node(), node, slot, component)
    }

    /// The coordinates of node j (see [`node_range`]).
    #[inline]
    pub fn node_range(&self, node: usize) -> Range<usize> {
        node_range(self.dofs_per_node(), node)
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
        };
        self.apply_constraints(&mut s);
        s
    }

    /// The out-of-plane coordinates (the z components of r, r_x, r_xx at
    /// every node) if the motion from `state` stays in the plane z = z0:
    /// every node at z0 with r_x, r_xx and all rates in the plane; gravity,
    /// point forces and the fluid velocity of drag in the plane; end
    /// moments about z; constraints that do not move out of it. Then, by
    /// the mirror symmetry about the plane, the z equations hold for
    /// z = z0 and zero slopes at every step, and their Jacobian does not
    /// couple them to the in-plane ones at such states (every coupling
    /// term carries an out-of-plane component), so eliminating them gives
    /// the same motion with a third fewer unknowns (docs/method.md §6.7).
    /// `None` otherwise.
    pub fn planar_coordinates(&self, state: &State) -> Option<Vec<usize>> {
        let dpn = self.dofs_per_node();
        let n = self.dofs();
        if state.e.len() != n || state.v.len() != n {
            return None;
        }
        let z0 = state.e[2];
        let mut out = Vec::with_capacity(n / 3);
        for g in (2..n).step_by(3) {
            let value = if g % dpn == 2 { z0 } else { 0.0 };
            if state.e[g] != value || state.v[g] != 0.0 {
                return None;
            }
            if let Some(m) = &self.constraints.motion[g] {
                let still = m.rate == 0.0 && (m.amplitude == 0.0 || m.omega == 0.0);
                if !still || m.value(0.0) != value {
                    return None;
                }
            }
            out.push(g);
        }
        let in_plane = self.loads.iter().all(|l| match l {
            Load::Gravity { acceleration } => acceleration[2] == 0.0,
            Load::PointForce { force, .. } => force[2] == 0.0,
            Load::EndMoment { moment, .. } => moment[0] == 0.0 && moment[1] == 0.0,
            Load::AirDrag(d) => d.fluid_velocity[2] == 0.0,
        });
        in_plane.then_some(out)
    }

    /// Holds the out-of-plane coordinates at their values when the motion
    /// from `state` is planar (see [`Self::planar_coordinates`]); returns
    /// whether it did.
    pub fn reduce_to_plane(&mut self, state: &State) -> bool {
        match self.planar_coordinates(state) {
            Some(dofs) => {
                for g in dofs {
                    self.constraints.hold_inactive(g, state.e[g]);
                }
                true
            }
            None => false,
        }
    }

    /// Sets every constrained coordinate of `state` to its prescribed value
    /// and rate at `state.t`.
    pub fn apply_constraints(&self, state: &mut State) {
        for (g, m) in self.constraints.motion.iter().enumerate() {
            if let Some(m) = m {
                state.e[g] = m.value(state.t);
                state.v[g] = m.rate_at(state.t);
            }
        }
    }

    /// End moments: (node, moment vector).
    pub fn end_moments(&self) -> impl Iterator<Item = (usize, [f64; 3])> + '_ {
        self.loads.iter().filter_map(|l| match l {
            Load::EndMoment { node, moment } => Some((*node, *moment)),
            _ => None,
        })
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
                let w = crate::element::cross(&omega, &arm);
                for i in 0..3 {
                    state.v[b + i] += w[i];
                }
            }
        }
    }

    /// Point forces acting on node j (summed).
    pub fn point_forces(&self) -> impl Iterator<Item = (usize, [f64; 3])> + '_ {
        self.loads.iter().filter_map(|l| match l {
            Load::PointForce { node, force } => Some((*node, *force)),
            _ => None,
        })
    }

    /// y = M x with the global consistent mass matrix.
    pub fn mass_times(&self, x: &[f64], y: &mut [f64]) {
        y.fill(0.0);
        let dpn = self.dofs_per_node();
        crate::with_elements!(&self.mesh, els => {
            for (k, el) in els.iter().enumerate() {
                let o = coordinate(dpn, k, SLOT_R, 0);
                let mq = el.mass_times(&gather(x, o));
                for (d, v) in mq.iter().enumerate() {
                    y[o + d] += v;
                }
            }
        });
    }

    /// Diagonal of the global mass matrix.
    pub fn mass_diagonal(&self) -> Vec<f64> {
        let dpn = self.dofs_per_node();
        let mut diag = vec![0.0; self.dofs()];
        crate::with_elements!(&self.mesh, els => {
            for (k, el) in els.iter().enumerate() {
                for (s, row) in el.mass.iter().enumerate() {
                    for i in 0..3 {
                        diag[coordinate(dpn, k, s, i)] += row[s];
                    }
                }
            }
        });
        diag
    }

    /// Length scale of each coordinate kind within a node: a change of r
    /// by 1 m, of r_x by 1/l or of r_xx by 1/l^2 moves the centre line by
    /// about 1 m inside an element of length l.
    pub fn coordinate_length_scale(&self, dof_in_node: usize) -> f64 {
        let l = self.element_length();
        match dof_in_node / 3 {
            0 => 1.0,
            1 => l,
            _ => l * l,
        }
    }
}

/// The `N` consecutive entries of `x` starting at `offset`.
#[inline]
pub(crate) fn gather<const N: usize>(x: &[f64], offset: usize) -> [f64; N] {
    let mut out = [0.0; N];
    out.copy_from_slice(&x[offset..offset + N]);
    out
}
