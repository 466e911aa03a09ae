//! The spatial quadrature must give the stiffness full rank: the only
//! zero-energy modes of a straight, stress-free 3-D cable are its 5 rigid
//! motions (3 translations, 2 rotations about transverse axes; a rotation
//! about its own axis moves no coordinate). A coarser rule adds spurious
//! modes that drift without bound (SAC-3 with 3 points: the end strain of
//! the axial impact grew linearly to 1.2 GPa in 2 ms at constant energy).

use stancf::assembly::stiffness_and_mass;
use stancf::{Cable, ElementType, Material, Model, ModelOptions, SpacePoints};

/// Dimension of the null space of a symmetric positive semi-definite
/// matrix: pivoted Cholesky, pivots below 1e-9 of the largest diagonal
/// entry count as zero (the smallest physical eigenvalue here, bending of
/// the whole cable, is ~1e-6 of the largest, axial, one).
fn null_space_dimension(model: &Model) -> usize {
    let s = model.initial_state();
    let (k, _) = stiffness_and_mass(model, &s.e);
    let n = model.dofs();
    let mut a: Vec<Vec<f64>> = (0..n)
        .map(|i| (0..n).map(|j| k.get(i, j)).collect())
        .collect();
    let scale = (0..n).map(|i| a[i][i]).fold(0.0, f64::max);
    let mut rank = 0;
    let mut used = vec![false; n];
    for _ in 0..n {
        let (p, d) = (0..n)
            .filter(|&i| !used[i])
            .map(|i| (i, a[i][i]))
            .fold((usize::MAX, f64::MIN), |b, c| if c.1 > b.1 { c } else { b });
        if d <= 1e-9 * scale {
            break;
        }
        used[p] = true;
        rank += 1;
        let row = a[p].clone();
        for i in 0..n {
            for j in 0..n {
                a[i][j] -= row[i] * row[j] / d;
            }
        }
    }
    n - rank
}

fn model(kind: ElementType, elements: usize, points: Option<SpacePoints>) -> Model {
    // A stiff short cable, so that bending is not negligible against axial
    // stiffness (EI / (EA l^2) ~ 1e-4).
    let material = Material {
        youngs_modulus: 1e7,
        density: 1000.0,
        area: 1e-4,
        second_moment: 1e-9,
        axial_damping: 0.0,
    };
    Model::new(
        Cable::straight(1.0, elements, kind).with_direction([0.6, 0.0, 0.8]),
        material,
        ModelOptions {
            space_points: points,
            ..ModelOptions::default()
        },
        vec![],
    )
    .unwrap()
}

#[test]
fn default_quadrature_leaves_only_rigid_modes() {
    for kind in [ElementType::Sac2, ElementType::Sac3] {
        let m = model(kind, 4, None);
        assert_eq!(null_space_dimension(&m), 5, "{kind:?}");
        assert!(m.warnings().is_empty());
        let min = kind.minimal_space_points();
        let m = model(kind, 4, Some(min));
        assert_eq!(null_space_dimension(&m), 5, "{kind:?} with {min:?}");
        assert!(m.warnings().is_empty());
    }
}

#[test]
fn coarse_quadrature_has_spurious_modes_and_is_warned_about() {
    // The count of ElementType::minimal_space_points is an element-level
    // criterion: below it an element has a zero-energy mode of its own.
    // Continuity between elements can suppress such a mode in a mesh
    // (SAC-3 with 4 axial points is singular on one element, not on
    // four), so the warning is conservative.
    for (kind, elements, points) in [
        (
            ElementType::Sac3,
            4,
            SpacePoints {
                axial: 3,
                bending: 3,
            },
        ),
        (
            ElementType::Sac3,
            1,
            SpacePoints {
                axial: 4,
                bending: 5,
            },
        ),
        (
            ElementType::Sac3,
            4,
            SpacePoints {
                axial: 5,
                bending: 3,
            },
        ),
        (
            ElementType::Sac2,
            4,
            SpacePoints {
                axial: 2,
                bending: 3,
            },
        ),
        (
            ElementType::Sac2,
            4,
            SpacePoints {
                axial: 3,
                bending: 1,
            },
        ),
    ] {
        let m = model(kind, elements, Some(points));
        let d = null_space_dimension(&m);
        assert!(d > 5, "{kind:?} {points:?}: null space {d}");
        assert!(!m.warnings().is_empty(), "{kind:?} {points:?} not warned");
    }
}
