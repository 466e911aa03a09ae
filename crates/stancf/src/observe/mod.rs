//! What can be observed of a state: energies, momentum, centre of mass,
//! axial stress and curvature along the cable (docs/method.md §2.1-2.6 for
//! the energies and momentum, §2.9 for stress and curvature, §8 for the
//! conserved energy).

use crate::element::{axial_strain, curvature, CableElement};
use crate::model::{coordinate, gather, Model, State, SLOT_R};
use crate::shape::{cubic_hermite, quintic_hermite};

mod line_outputs;
mod nodal_forces;
pub use line_outputs::{
    element_damping_forces, element_strain_rates, hydrodynamic_nodal_forces, node_water_velocities,
    viv_nodal_forces,
};
pub(crate) use nodal_forces::{add_to_end_nodes, nodal_forces_per_length};
pub use nodal_forces::{seabed_nodal_forces, static_seabed_nodal_forces};

/// Energies of a state (J).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Energies {
    /// T = 1/2 v^T M v (eq. 11), plus the entrained water's T_a of a line
    /// in water with added mass (W25), (W32).
    pub kinetic: f64,
    /// U of eq. (12), with the model's spatial quadrature.
    pub strain: f64,
    /// Gravitational potential -int rho A g . r dx (eq. 13).
    pub gravity: f64,
    /// Potential of the constant point forces, -sum F . r (eq. 14).
    pub load_potential: f64,
}

impl Energies {
    /// kinetic + strain + gravity (the `total` column of history.csv).
    pub fn total(&self) -> f64 {
        self.kinetic + self.strain + self.gravity
    }

    /// Total mechanical energy including the point-force potential: the
    /// conserved quantity of a free cable under constant loads.
    pub fn mechanical(&self) -> f64 {
        self.total() + self.load_potential
    }

    /// A magnitude to compare energy changes with.
    pub fn magnitude(&self) -> f64 {
        self.kinetic.abs() + self.strain.abs() + self.gravity.abs() + self.load_potential.abs()
    }
}

fn element_energies<const NS: usize, const ND: usize>(
    els: &[CableElement<NS, ND>],
    dpn: usize,
    state: &State,
    g: &[f64; 3],
) -> Energies {
    let mut en = Energies::default();
    for (k, el) in els.iter().enumerate() {
        let o = coordinate(dpn, k, SLOT_R, 0);
        let q: [f64; ND] = gather(&state.e, o);
        let qd: [f64; ND] = gather(&state.v, o);
        let mq = el.mass_times(&qd);
        en.kinetic += 0.5 * qd.iter().zip(mq.iter()).map(|(a, b)| a * b).sum::<f64>();
        en.strain += match &el.section.visco {
            // A viscoelastic line's springs (docs/method.md §2.11).
            Some(_) if !state.internal.is_empty() => {
                let per = el.axial_rule_points() * el.internal_values_per_point();
                let (internal, _) = el.split_internal(&state.internal[k * per..(k + 1) * per]);
                el.bending_energy(&q) + el.visco_stored_energy(&q, internal)
            }
            _ => el.strain_energy(&q),
        };
        let fg = el.gravity_load(g);
        en.gravity -= fg.iter().zip(q.iter()).map(|(a, b)| a * b).sum::<f64>();
    }
    en
}

/// Energies of a state.
pub fn energies(model: &Model, state: &State) -> Energies {
    let dpn = model.dofs_per_node();
    let mut en = crate::with_elements!(&model.mesh, els => {
        element_energies(els, dpn, state, &model.gravity)
    });
    en.kinetic += model.entrained_energy(&state.e, &state.v);
    for (node, f) in model.point_forces() {
        let r = model.node_position(&state.e, node);
        en.load_potential -= f[0] * r[0] + f[1] * r[1] + f[2] * r[2];
    }
    en
}

/// Total mass, linear momentum int rho A rdot dx and first mass moment
/// int rho A r dx.
pub fn momentum(model: &Model, state: &State) -> (f64, [f64; 3], [f64; 3]) {
    let dpn = model.dofs_per_node();
    let vpn = model.element_type().vectors_per_node();
    let mut mass = 0.0;
    let mut p = [0.0; 3];
    let mut s = [0.0; 3];
    crate::with_elements!(&model.mesh, els => {
        for (k, el) in els.iter().enumerate() {
            for (a, w) in el.weight_integrals.iter().enumerate() {
                let o = coordinate(dpn, k, a, 0);
                if a % vpn == 0 {
                    mass += w;
                }
                for i in 0..3 {
                    p[i] += w * state.v[o + i];
                    s[i] += w * state.e[o + i];
                }
            }
        }
    });
    (mass, p, s)
}

/// Angular momentum about the origin, int rho A r x r_dot dx: with r and
/// r_dot interpolated by the same shape functions, the consistent mass
/// matrix gives it exactly, sum_ab M_ab e_a x v_b (docs/method.md §2.1).
pub fn angular_momentum(model: &Model, state: &State) -> [f64; 3] {
    let dpn = model.dofs_per_node();
    let mut l = [0.0; 3];
    crate::with_elements!(&model.mesh, els => {
        for (k, el) in els.iter().enumerate() {
            for (a, row) in el.mass.iter().enumerate() {
                let oa = coordinate(dpn, k, a, 0);
                let e = [state.e[oa], state.e[oa + 1], state.e[oa + 2]];
                for (b, &m_ab) in row.iter().enumerate() {
                    let ob = coordinate(dpn, k, b, 0);
                    let v = [state.v[ob], state.v[ob + 1], state.v[ob + 2]];
                    let exv = crate::vec3::cross(e, v);
                    for i in 0..3 {
                        l[i] += m_ab * exv[i];
                    }
                }
            }
        }
    });
    l
}

/// Centre of mass.
pub fn center_of_mass(model: &Model, state: &State) -> [f64; 3] {
    let (m, _, s) = momentum(model, state);
    s.map(|c| c / m)
}

/// E eps, or 0 where a line without compression is shortened ((M4a)).
fn axial_stress(compression: bool, e_mod: f64, eps: f64) -> f64 {
    if eps < 0.0 && !compression {
        0.0
    } else {
        e_mod * eps
    }
}

/// The elastic axial stress of `model` at the strain eps: E eps
/// ([`axial_stress`]), or the nonlinear law's T(eps) / A (docs/method.md
/// §2.2a, (M4b)).
fn model_axial_stress(model: &Model, compression: bool, eps: f64) -> f64 {
    match model.axial_curve() {
        Some(_) if eps < 0.0 && !compression => 0.0,
        Some(c) => c.at(eps).1 / model.material.area,
        None => axial_stress(compression, model.material.youngs_modulus, eps),
    }
}

/// A viscoelastic line's axial force at xi of element k (None without
/// the law).
fn visco_force(model: &Model, state: &State, k: usize, xi: f64) -> Option<f64> {
    let o = coordinate(model.dofs_per_node(), k, SLOT_R, 0);
    if state.internal.is_empty() {
        return None;
    }
    let internal = model.element_internal(&state.internal, k);
    let (internal, _) = crate::with_elements!(&model.mesh, els => els[k].split_internal(internal));
    crate::with_elements!(&model.mesh, els => {
        els[k].visco_axial_force(xi, &state.e[o..], &state.v[o..], internal)
    })
}

/// One sample of the axial stress and curvature.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct StressSample {
    pub element: usize,
    /// Material coordinate (0 at end A).
    pub s: f64,
    /// E eps (a nonlinear or viscoelastic line's law's N / A).
    pub axial_stress: f64,
    /// The axial strain eps of the model's measure.
    pub axial_strain: f64,
    pub curvature: f64,
}

/// Axial stress E eps and curvature at `per_element` evenly spaced points
/// of every element, both ends included (so interior nodes appear twice,
/// once per element). The axial strain depends on r_x alone, a nodal
/// coordinate of both elements, so the two values at a node agree; the
/// curvature of SAC-2 (from r_xx, not nodal) jumps there (docs/method.md
/// §1.2).
pub fn stress_samples(
    model: &Model,
    state: &State,
    per_element: usize,
    out: &mut Vec<StressSample>,
) {
    out.clear();
    let dpn = model.dofs_per_node();
    let compression = model.carries_compression();
    let m = model.options.measures;
    let n = per_element.max(2);
    for k in 0..model.cable.elements {
        let l = model.element_length(k);
        let q = &state.e[coordinate(dpn, k, SLOT_R, 0)..];
        for p in 0..n {
            let xi = p as f64 / (n - 1) as f64;
            let (rx, rxx) = match model.element_type() {
                crate::model::ElementType::Sac2 => cubic_hermite(xi, l).gradients(q),
                crate::model::ElementType::Sac3 => quintic_hermite(xi, l).gradients(q),
            };
            let eps = axial_strain(m.axial_strain, &rx);
            out.push(StressSample {
                element: k,
                axial_strain: eps,
                s: model.material_coordinate(k, xi),
                axial_stress: match visco_force(model, state, k, xi) {
                    Some(n) => n / model.material.area,
                    _ => model_axial_stress(model, compression, eps),
                },
                curvature: curvature(m.curvature, &rx, &rxx),
            });
        }
    }
}

/// The axial force N = EA eps + BA eps_dot (N, docs/method.md §2.10) at
/// every node, eps the model's strain of the node's r_x and eps_dot =
/// a . r_x_dot (a = r_x for Green's strain, r_x / |r_x| for the
/// engineering one); a line without compression has no elastic part
/// where shortened ((M4a)). Nodal: r_x is a nodal coordinate, so both
/// elements at a node give it (MoorDyn's node tension, `L<n>N<k>T`, is
/// the mean of its two segments').
pub fn node_axial_forces(model: &Model, state: &State) -> Vec<f64> {
    (0..model.nodes())
        .map(|k| node_axial_force(model, state, k))
        .collect()
}

/// [`node_axial_forces`] at node k alone. A viscoelastic line's (with
/// its internal state, docs/method.md §2.11): the law's N (V1) at the
/// node, the mean of its elements' values there.
pub fn node_axial_force(model: &Model, state: &State, k: usize) -> f64 {
    if model.viscoelastic().is_some() && !state.internal.is_empty() {
        let elements = model.cable.elements;
        let sides = [(k.checked_sub(1), 1.0), ((k < elements).then_some(k), 0.0)];
        let values: Vec<f64> = sides
            .iter()
            .filter_map(|&(el, xi)| visco_force(model, state, el?, xi))
            .collect();
        return values.iter().sum::<f64>() / values.len() as f64;
    }
    let material = &model.material;
    let ea = material.youngs_modulus * material.area;
    let measure = model.options.measures.axial_strain;
    let o = coordinate(model.dofs_per_node(), k, crate::model::SLOT_R_X, 0);
    let rx = [state.e[o], state.e[o + 1], state.e[o + 2]];
    let vx = [state.v[o], state.v[o + 1], state.v[o + 2]];
    let elastic = match model.axial_curve() {
        Some(_) => {
            let compression = model.carries_compression();
            model.material.area * model_axial_stress(model, compression, axial_strain(measure, &rx))
        }
        None => axial_stress(model.carries_compression(), ea, axial_strain(measure, &rx)),
    };
    let a = match measure {
        crate::AxialStrain::Green => rx,
        crate::AxialStrain::Engineering => crate::vec3::normalized(rx),
    };
    elastic + material.axial_damping * crate::vec3::dot(a, vx)
}

/// The largest axial compression -EA eps (N) at the points of the axial
/// rule of any element (0 if the line is nowhere shortened): what a line
/// without compression (docs/method.md §2.2, (M4a)) would shed from a
/// state found with its compressive stiffness kept, as its static
/// equilibrium is.
pub fn largest_compression(model: &Model, state: &State) -> f64 {
    let dpn = model.dofs_per_node();
    crate::with_elements!(&model.mesh, els => els
        .iter()
        .enumerate()
        .map(|(k, el)| {
            let q = &state.e[coordinate(dpn, k, SLOT_R, 0)..];
            let least = el.least_axial_strain(q);
            -el.section.curve.as_ref().map_or(el.section.ea * least, |c| c.at(least).1)
        })
        .fold(0.0, f64::max))
}

/// The largest shortening -eps at the points of the axial rule of any
/// element (0 if the line is nowhere shortened; see
/// [`largest_compression`]).
pub fn largest_shortening(model: &Model, state: &State) -> f64 {
    let dpn = model.dofs_per_node();
    crate::with_elements!(&model.mesh, els => els
        .iter()
        .enumerate()
        .map(|(k, el)| -el.least_axial_strain(&state.e[coordinate(dpn, k, SLOT_R, 0)..]))
        .fold(0.0, f64::max))
}

/// Points of the centre line: `per_element` evenly spaced points in every
/// element (both ends; shared nodes once), as (material coordinate, r).
pub fn centre_line(model: &Model, state: &State, per_element: usize) -> Vec<(f64, [f64; 3])> {
    let dpn = model.dofs_per_node();
    let n = per_element.max(2);
    let mut out = Vec::with_capacity(model.cable.elements * (n - 1) + 1);
    for k in 0..model.cable.elements {
        let l = model.element_length(k);
        let first = if k == 0 { 0 } else { 1 };
        for p in first..n {
            let xi = p as f64 / (n - 1) as f64;
            let q = &state.e[coordinate(dpn, k, SLOT_R, 0)..];
            let shape: Vec<f64> = match model.element_type() {
                crate::model::ElementType::Sac2 => cubic_hermite(xi, l).n.to_vec(),
                crate::model::ElementType::Sac3 => quintic_hermite(xi, l).n.to_vec(),
            };
            let mut r = [0.0; 3];
            for (a, na) in shape.iter().enumerate() {
                for i in 0..3 {
                    r[i] += na * q[3 * a + i];
                }
            }
            out.push((model.material_coordinate(k, xi), r));
        }
    }
    out
}

/// The state along the cable at one point of the centre line.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CablePoint {
    /// Material coordinate (m).
    pub s: f64,
    pub r: [f64; 3],
    /// Velocity r_dot (the same interpolation of the nodal rates).
    pub v: [f64; 3],
    /// E eps at this point; at a shared node, the mean of the two
    /// elements' values (equal up to round-off: the strain is continuous,
    /// docs/method.md §1.2).
    pub axial_stress: f64,
    pub curvature: f64,
}

/// The centre line with velocity, axial stress and curvature at
/// `per_element` evenly spaced points of every element (both ends; a node
/// shared by two elements once): for drawing and for ParaView.
pub fn cable_points(model: &Model, state: &State, per_element: usize) -> Vec<CablePoint> {
    let dpn = model.dofs_per_node();
    let n = per_element.max(2);
    let compression = model.carries_compression();
    let m = model.options.measures;
    let mut out: Vec<CablePoint> = Vec::with_capacity(model.cable.elements * (n - 1) + 1);
    for k in 0..model.cable.elements {
        let l = model.element_length(k);
        let o = coordinate(dpn, k, SLOT_R, 0);
        let (q, qd) = (&state.e[o..], &state.v[o..]);
        for p in 0..n {
            let xi = p as f64 / (n - 1) as f64;
            let (shape, (rx, rxx)): (Vec<f64>, _) = match model.element_type() {
                crate::model::ElementType::Sac2 => {
                    let sh = cubic_hermite(xi, l);
                    (sh.n.to_vec(), sh.gradients(q))
                }
                crate::model::ElementType::Sac3 => {
                    let sh = quintic_hermite(xi, l);
                    (sh.n.to_vec(), sh.gradients(q))
                }
            };
            let mut r = [0.0; 3];
            let mut v = [0.0; 3];
            for (a, na) in shape.iter().enumerate() {
                for i in 0..3 {
                    r[i] += na * q[3 * a + i];
                    v[i] += na * qd[3 * a + i];
                }
            }
            let point = CablePoint {
                s: model.material_coordinate(k, xi),
                r,
                v,
                axial_stress: match visco_force(model, state, k, xi) {
                    Some(n) => n / model.material.area,
                    None => {
                        model_axial_stress(model, compression, axial_strain(m.axial_strain, &rx))
                    }
                },
                curvature: curvature(m.curvature, &rx, &rxx),
            };
            if p == 0 && k > 0 {
                // The node shared with the previous element.
                let last = out.last_mut().expect("previous element");
                last.axial_stress = 0.5 * (last.axial_stress + point.axial_stress);
                last.curvature = 0.5 * (last.curvature + point.curvature);
                continue;
            }
            out.push(point);
        }
    }
    out
}

/// The state of bending at a node: curvature and bending moment.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct NodeBending {
    /// Material coordinate (m).
    pub s: f64,
    /// Curvature (1/m) at the node; for SAC-2, whose r_xx is not nodal,
    /// the mean of the two elements' values (docs/method.md §1.2).
    pub curvature: f64,
    /// EI kappa (N m), with the EI the line is simulated with.
    pub bending_moment: f64,
}

/// Curvature and bending moment EI kappa at every node (the values users
/// check against a cable's minimum bend radius, 1 / kappa).
pub fn node_bending(model: &Model, state: &State) -> Vec<NodeBending> {
    let ei = model.material.youngs_modulus * model.material.second_moment;
    cable_points(model, state, 2)
        .iter()
        .map(|p| NodeBending {
            s: p.s,
            curvature: p.curvature,
            bending_moment: ei * p.curvature,
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::{Cable, ElementType, Material, ModelOptions};

    /// The sampled centre line passes through the nodes with their
    /// velocities, at the right material coordinates, for both elements.
    #[test]
    fn cable_points_pass_through_the_nodes() {
        for kind in [ElementType::Sac2, ElementType::Sac3] {
            let model = Model::new(
                Cable::straight(3.0, 3, kind).with_direction([0.6, 0.8, 0.0]),
                Material::chen2023_pvc(),
                ModelOptions::default(),
                vec![],
            )
            .unwrap();
            let mut state = model.initial_state();
            for j in 0..model.nodes() {
                model.set_node_velocity(&mut state, j, [j as f64, -1.0, 0.5]);
            }
            let pts = cable_points(&model, &state, 6);
            assert_eq!(pts.len(), 3 * 5 + 1);
            for j in 0..model.nodes() {
                let p = &pts[5 * j];
                assert!((p.s - j as f64).abs() < 1e-15);
                let r = model.node_position(&state.e, j);
                for c in 0..3 {
                    assert!((p.r[c] - r[c]).abs() < 1e-15, "{kind:?} node {j}");
                }
                assert!((p.v[0] - j as f64).abs() < 1e-15 && p.v[1] == -1.0 && p.v[2] == 0.5);
                // Straight and unstretched: no stress, no curvature.
                assert!(p.axial_stress.abs() < 1e-3 && p.curvature.abs() < 1e-12);
            }
        }
    }

    /// A cable bent into a circle of radius R (nodes on the circle, r_x
    /// and r_xx its exact tangent and curvature vector) has curvature 1/R
    /// and moment EI / R at every node, for both elements.
    #[test]
    fn a_cable_bent_into_a_circle_has_curvature_one_over_the_radius_at_its_nodes() {
        let radius = 2.0;
        for kind in [ElementType::Sac2, ElementType::Sac3] {
            let model = Model::new(
                Cable::straight(3.0, 6, kind),
                Material::chen2023_pvc(),
                ModelOptions::default(),
                vec![],
            )
            .unwrap();
            let mut state = model.initial_state();
            let dpn = model.dofs_per_node();
            for j in 0..model.nodes() {
                let phi = j as f64 * 0.5 / radius;
                let (c, s) = (phi.cos(), phi.sin());
                let values = [
                    [radius * s, radius * (1.0 - c), 0.0],
                    [c, s, 0.0],
                    [-s / radius, c / radius, 0.0],
                ];
                for (slot, v) in values.iter().enumerate().take(dpn / 3) {
                    for i in 0..3 {
                        state.e[model.coordinate(j, slot, i)] = v[i];
                    }
                }
            }
            let ei = model.material.youngs_modulus * model.material.second_moment;
            for (j, b) in node_bending(&model, &state).iter().enumerate() {
                // SAC-2 interpolates the arc with cubics, whose r_xx at
                // an element's ends is off by (h / R)^2 / 12 (the leading
                // term, 5.2e-3 here; the next is (h / R)^4 smaller); SAC-3
                // carries r_xx as a node's coordinate.
                let expected = match kind {
                    ElementType::Sac2 => (0.5f64 / radius).powi(2) / 12.0,
                    ElementType::Sac3 => 0.0,
                };
                let err = b.curvature * radius - 1.0;
                let next = (0.5f64 / radius).powi(2) * expected;
                assert!(
                    (err - expected).abs() <= next + 1e-12,
                    "{kind:?} node {j}: {err}"
                );
                assert!((b.bending_moment - ei * b.curvature).abs() < 1e-12 * ei);
                assert!((b.s - 0.5 * j as f64).abs() < 1e-15);
            }
        }
    }
}
