//! The highest frequency w_max of a mesh (`stability::highest_frequency`),
//! which sets P2's stable step, against the bar and beam matrices of the
//! same Hermite elements assembled independently and solved densely.
//!
//! A straight, stress-free cable along x has the tangent stiffness of an
//! axial bar in x (Green strain: d2U/dr_x2 = E A r_x r_x^T at eps = 0) and
//! of an Euler-Bernoulli beam in y and z (d2U/dr_xx2 = E I (I - r_x r_x^T)
//! at r_xx = 0, both curvature forms), with the consistent mass of the
//! same shape functions in each direction; the default quadratures (3
//! points for SAC-2, 5 for SAC-3) integrate these products exactly. So
//! w_max^2 is the largest eigenvalue of the bar or of the beam.

use crate::common::generalized_max_eigenvalue;
use stancf::quadrature::GaussRule;
use stancf::shape::{cubic_hermite, quintic_hermite, SpatialShape};
use stancf::stability::highest_frequency;
use stancf::{Cable, ElementType, GradedEnd, Grading, Material, Model, ModelOptions};

/// Assembles N equal elements of `size` scalar unknowns (the shape
/// functions of one direction, two nodes of size / 2) into dense matrices.
fn assemble(elements: usize, element: &[Vec<f64>]) -> Vec<Vec<f64>> {
    assemble_each(&vec![element.to_vec(); elements])
}

/// Assembles the elements' matrices, element k's from `elements[k]`.
fn assemble_each(elements: &[Vec<Vec<f64>>]) -> Vec<Vec<f64>> {
    let size = elements[0].len();
    let per_node = size / 2;
    let n = (elements.len() + 1) * per_node;
    let mut a = vec![vec![0.0; n]; n];
    for (e, element) in elements.iter().enumerate() {
        let o = e * per_node;
        for i in 0..size {
            for j in 0..size {
                a[o + i][o + j] += element[i][j];
            }
        }
    }
    a
}

/// The textbook matrices of the cubic Hermite element (unknowns u, u' at
/// both ends): axial stiffness E A int N'^T N', bending stiffness
/// E I int N''^T N'', mass rho A int N^T N.
fn sac2_bar_and_beam(m: &Material, l: f64) -> [Vec<Vec<f64>>; 3] {
    let (ea, ei, rho_a) = (
        m.youngs_modulus * m.area,
        m.youngs_modulus * m.second_moment,
        m.density * m.area,
    );
    let scale = |c: f64, a: [[f64; 4]; 4]| -> Vec<Vec<f64>> {
        a.iter()
            .map(|r| r.iter().map(|v| c * v).collect())
            .collect()
    };
    let l2 = l * l;
    let bar = scale(
        ea / (30.0 * l),
        [
            [36.0, 3.0 * l, -36.0, 3.0 * l],
            [3.0 * l, 4.0 * l2, -3.0 * l, -l2],
            [-36.0, -3.0 * l, 36.0, -3.0 * l],
            [3.0 * l, -l2, -3.0 * l, 4.0 * l2],
        ],
    );
    let beam = scale(
        ei / (l2 * l),
        [
            [12.0, 6.0 * l, -12.0, 6.0 * l],
            [6.0 * l, 4.0 * l2, -6.0 * l, 2.0 * l2],
            [-12.0, -6.0 * l, 12.0, -6.0 * l],
            [6.0 * l, 2.0 * l2, -6.0 * l, 4.0 * l2],
        ],
    );
    let mass = scale(
        rho_a * l / 420.0,
        [
            [156.0, 22.0 * l, 54.0, -13.0 * l],
            [22.0 * l, 4.0 * l2, 13.0 * l, -3.0 * l2],
            [54.0, 13.0 * l, 156.0, -22.0 * l],
            [-13.0 * l, -3.0 * l2, -22.0 * l, 4.0 * l2],
        ],
    );
    [bar, beam, mass]
}

/// The same three matrices from any Hermite basis by 8-point Gauss
/// quadrature (exact for the degree-10 products of quintics).
fn bar_and_beam<const NS: usize>(
    shape: fn(f64, f64) -> SpatialShape<NS>,
    m: &Material,
    l: f64,
) -> [Vec<Vec<f64>>; 3] {
    let rule = GaussRule::new(8).unwrap();
    let mut out = [
        vec![vec![0.0; NS]; NS],
        vec![vec![0.0; NS]; NS],
        vec![vec![0.0; NS]; NS],
    ];
    let ea = m.youngs_modulus * m.area;
    let ei = m.youngs_modulus * m.second_moment;
    let rho_a = m.density * m.area;
    for (xi, w) in rule.iter() {
        let s = shape(xi, l);
        for i in 0..NS {
            for j in 0..NS {
                out[0][i][j] += w * l * ea * s.n_x[i] * s.n_x[j];
                out[1][i][j] += w * l * ei * s.n_xx[i] * s.n_xx[j];
                out[2][i][j] += w * l * rho_a * s.n[i] * s.n[j];
            }
        }
    }
    out
}

/// w_max of the bar and beam of N elements: the larger of the two.
fn reference_w_max(elements: usize, matrices: &[Vec<Vec<f64>>; 3]) -> f64 {
    let mass = assemble(elements, &matrices[2]);
    let bar = generalized_max_eigenvalue(&assemble(elements, &matrices[0]), &mass);
    let beam = generalized_max_eigenvalue(&assemble(elements, &matrices[1]), &mass);
    bar.max(beam).sqrt()
}

fn straight(length: f64, elements: usize, kind: ElementType, material: Material) -> Model {
    Model::new(
        Cable::straight(length, elements, kind),
        material,
        ModelOptions::default(),
        vec![],
    )
    .unwrap()
}

/// Tolerance on w_max: both sides are converged eigenvalues, equal to
/// round-off of the matrices (~1e-15 relative); Lanczos stops with a
/// residual of 1e-10 theta, i.e. an error of (1e-10)^2 / gap, nothing here.
const TOLERANCE: f64 = 1e-10;

/// SAC-2 with the textbook bar and beam matrices: one element (13.04 c/l),
/// the paper's 8-element PVC impact mesh (9.5501 c/l, what `stancf check`
/// prints), 40 elements (246 unknowns, more Lanczos steps than the old
/// 120-step limit), and a soft, thick cable whose highest mode is a
/// bending one.
#[test]
fn sac2_highest_frequency_is_that_of_the_hermite_bar_and_beam() {
    let pvc = Material::chen2023_pvc();
    let thick = Material {
        youngs_modulus: 1e6,
        density: 1000.0,
        area: 1e-2,
        second_moment: 1e-4,
        axial_damping: 0.0,
    };
    for (material, length, elements) in [
        (pvc, 4.0, 1),
        (pvc, 4.0, 8),
        (pvc, 4.0, 40),
        (thick, 0.1, 6),
    ] {
        let model = straight(length, elements, ElementType::Sac2, material);
        let l = model.element_length(0);
        let w = highest_frequency(&model, &model.initial_state().e);
        let reference = reference_w_max(elements, &sac2_bar_and_beam(&material, l));
        let c_over_l = material.wave_speed() / l;
        eprintln!(
            "SAC-2 x {elements}: w_max {w:.10e} rad/s ({:.4} c/l), reference {reference:.10e}",
            w / c_over_l
        );
        assert!(
            (w / reference - 1.0).abs() < TOLERANCE,
            "{w} vs {reference}"
        );
        if elements == 8 {
            assert_eq!(format!("{:.4}", w / c_over_l), "9.5501");
        }
    }
    // The thick cable's top mode is a bending one (else the case tests
    // nothing new).
    let m = sac2_bar_and_beam(&thick, 0.1 / 6.0);
    let mass = assemble(6, &m[2]);
    assert!(
        generalized_max_eigenvalue(&assemble(6, &m[1]), &mass)
            > generalized_max_eigenvalue(&assemble(6, &m[0]), &mass)
    );
}

/// SAC-3 against the quintic Hermite bar and beam (20.46 c/l on 8
/// elements).
#[test]
fn sac3_highest_frequency_is_that_of_the_quintic_bar_and_beam() {
    let pvc = Material::chen2023_pvc();
    for elements in [1, 8, 30] {
        let model = straight(4.0, elements, ElementType::Sac3, pvc);
        let l = model.element_length(0);
        let w = highest_frequency(&model, &model.initial_state().e);
        let reference = reference_w_max(elements, &bar_and_beam(quintic_hermite, &pvc, l));
        eprintln!("SAC-3 x {elements}: w_max {w:.10e}, reference {reference:.10e}");
        assert!(
            (w / reference - 1.0).abs() < TOLERANCE,
            "{w} vs {reference}"
        );
    }
    // The quadrature route agrees with the textbook matrices for SAC-2.
    let l = 0.5;
    let a = reference_w_max(3, &bar_and_beam(cubic_hermite, &pvc, l));
    let b = reference_w_max(3, &sac2_bar_and_beam(&pvc, l));
    assert!((a / b - 1.0).abs() < 1e-13, "{a} vs {b}");
}

/// The highest mode of a free uniform cable is an end mode: it decays
/// into the cable (the interior band reaches only ~6.5 c/l for SAC-2), so
/// beyond a few tens of elements w_max l / c no longer depends on the
/// number of elements. 20 000 elements (120 006 unknowns) give the value
/// of 24 to the tolerance, by the same few tens of Lanczos steps.
#[test]
fn the_highest_mode_of_a_free_cable_is_an_end_mode() {
    let pvc = Material::chen2023_pvc();
    for (kind, expect) in [(ElementType::Sac2, 9.548), (ElementType::Sac3, 20.46)] {
        let l = 0.5;
        let w_of = |elements: usize| {
            let model = straight(l * elements as f64, elements, kind, pvc);
            highest_frequency(&model, &model.initial_state().e) * l / pvc.wave_speed()
        };
        let (short, long) = (w_of(24), w_of(20_000));
        eprintln!("{kind:?}: w_max l / c = {short:.10} (24 elements), {long:.10} (20 000)");
        assert!((long / short - 1.0).abs() < TOLERANCE, "{short} vs {long}");
        assert!((short - expect).abs() < 5e-3, "{short}");
    }
}

/// Linearized at a uniformly stretched state, r_x = s d: the axial tangent
/// E A (r_x r_x^T + eps I), eps = (s^2 - 1) / 2, is (3 s^2 - 1) / 2 times
/// that of the straight state along d, so every axial frequency, w_max
/// among them, grows by sqrt((3 s^2 - 1) / 2).
#[test]
fn a_stretched_cable_is_stiffer_by_its_tangent_modulus() {
    let pvc = Material::chen2023_pvc();
    for kind in [ElementType::Sac2, ElementType::Sac3] {
        let model = Model::new(
            Cable::straight(4.0, 8, kind).with_direction([0.6, 0.0, 0.8]),
            pvc,
            ModelOptions::default(),
            vec![],
        )
        .unwrap();
        let e0 = model.initial_state().e;
        let stretch = 1.01;
        let dpn = model.dofs_per_node();
        let e1: Vec<f64> = e0
            .iter()
            .enumerate()
            .map(|(g, v)| if g % dpn < 6 { stretch * v } else { *v })
            .collect();
        let (w0, w1) = (
            highest_frequency(&model, &e0),
            highest_frequency(&model, &e1),
        );
        let expect = ((3.0 * stretch * stretch - 1.0) / 2.0).sqrt();
        eprintln!(
            "{kind:?}: w_max ratio {:.12} (expected {expect:.12})",
            w1 / w0
        );
        assert!((w1 / w0 / expect - 1.0).abs() < TOLERANCE, "{}", w1 / w0);
    }
}

/// A graded mesh (docs/method.md §1.6): w_max is that of its unequal
/// textbook elements assembled (each of its own length), and its shortest
/// elements set it. By the element eigenvalue bound (the Rayleigh quotient
/// of the assembly is a weighted mean of the elements'), w_max is at most
/// the largest one-element value, 13.04 c / l_min for SAC-2. Measured:
/// w_max l_min / c = 9.08 to 9.47 for ratios 2 and 8 toward A, B and both,
/// against 9.55 on uniform meshes: the stable step W_crit / w_max (M21)
/// follows the shortest element.
#[test]
fn a_graded_meshs_highest_frequency_is_set_by_its_shortest_elements() {
    let pvc = Material::chen2023_pvc();
    let c = pvc.wave_speed();
    for toward in [GradedEnd::A, GradedEnd::B, GradedEnd::Both] {
        for ratio in [2.0, 8.0] {
            let model = Model::new(
                Cable::straight(4.0, 12, ElementType::Sac2)
                    .with_grading(Grading::Geometric { toward, ratio }),
                pvc,
                ModelOptions::default(),
                vec![],
            )
            .unwrap();
            let w = highest_frequency(&model, &model.initial_state().e);
            let matrices: Vec<[Vec<Vec<f64>>; 3]> = (0..12)
                .map(|k| sac2_bar_and_beam(&pvc, model.element_length(k)))
                .collect();
            let of = |i: usize| -> Vec<Vec<Vec<f64>>> {
                matrices.iter().map(|m| m[i].clone()).collect()
            };
            let mass = assemble_each(&of(2));
            let bar = generalized_max_eigenvalue(&assemble_each(&of(0)), &mass);
            let beam = generalized_max_eigenvalue(&assemble_each(&of(1)), &mass);
            let reference = bar.max(beam).sqrt();
            let short = model.shortest_element_length();
            eprintln!(
                "toward {toward:?}, ratio {ratio}: w_max {w:.10e} rad/s = {:.4} c/l_min, \
                 reference {reference:.10e}",
                w * short / c
            );
            assert!(
                (w / reference - 1.0).abs() < TOLERANCE,
                "{w} vs {reference}"
            );
            assert!(w * short / c <= 13.05, "{}", w * short / c);
        }
    }
}
