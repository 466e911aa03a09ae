//! Static equilibrium of systems of lines joined at points
//! (docs/method.md §11.6): a hanging mass, a bridle, and a one-line
//! system against the single cable's static solve.

use stancf::system::{End, Line, Point, System, SystemStatics};
use stancf::{
    Cable, Constraint, ConstraintKind, ConstraintMethod, ElementType, Load, Material, Model,
    ModelOptions, StaticSettings, StaticSolver,
};

const G: [f64; 3] = [0.0, 0.0, -9.81];

/// A light rope: 2 mm^2 at 1 MPa (EA = 2 N), 1000 kg/m^3.
fn rope(density: f64) -> Material {
    Material {
        youngs_modulus: 1e6,
        density,
        area: 2e-6,
        second_moment: 2e-12,
        axial_damping: 0.0,
    }
}

/// A straight line of `length` from a along the direction to b.
fn line_between(
    a: [f64; 3],
    b: [f64; 3],
    length: f64,
    elements: usize,
    material: Material,
) -> Model {
    let d: [f64; 3] = std::array::from_fn(|i| b[i] - a[i]);
    let cable = Cable::straight(length, elements, ElementType::Sac2)
        .with_origin(a)
        .with_direction(d);
    Model::new(
        cable,
        material,
        ModelOptions::default(),
        vec![Load::Gravity { acceleration: G }],
    )
    .expect("model")
}

fn settings(method: ConstraintMethod) -> StaticSettings {
    StaticSettings {
        constraint_method: method,
        tolerance: 1e-12,
        ..StaticSettings::default()
    }
}

fn norm(v: [f64; 3]) -> f64 {
    v.iter().map(|x| x * x).sum::<f64>().sqrt()
}

/// A mass m on a vertical line hanging from an anchor: the line's end
/// pulls the mass up with m g, and the anchor carries m g + w L. Both
/// are exact for the discrete equilibrium too (the line's rows sum to
/// its weight), so the tolerance is the solver's: 1e-9 relative.
#[test]
fn a_hanging_mass_pulls_its_line_with_its_weight() {
    for method in [ConstraintMethod::Multiplier, ConstraintMethod::Elimination] {
        let (length, mass) = (2.0, 0.01);
        let top = [0.0, 0.0, 0.0];
        let bottom = [0.0, 0.0, -length];
        let model = line_between(top, bottom, length, 8, rope(1000.0));
        let weight = 1000.0 * 2e-6 * 9.81 * length;
        let seed = model.initial_state();
        let system = System::new(
            vec![Line {
                model,
                ends: [End::Point(0), End::Point(1)],
            }],
            vec![Point::fixed(top), Point::free(bottom, mass)],
            G,
        )
        .expect("system");
        let mut s = SystemStatics::new(system, vec![seed], settings(method)).expect("statics");
        assert!(s
            .solve(|_, _| std::ops::ControlFlow::Continue(()))
            .expect("solve"));
        let [at_top, at_mass] = s.end_forces(0);
        let mg = mass * 9.81;
        assert!(
            (at_mass.force[2] - mg).abs() <= 1e-9 * mg,
            "{method:?}: line on the mass {:?}, m g = {mg}",
            at_mass.force
        );
        assert!(
            (at_top.force[2] + mg + weight).abs() <= 1e-9 * (mg + weight),
            "{method:?}: line on the anchor {:?}, m g + w L = {}",
            at_top.force,
            mg + weight
        );
        // The stretch under the mass: the point sits lower than L.
        assert!(s.point_position(1)[2] < -length);
    }
}

/// A bridle: two lines from anchors at different heights meet at a
/// free point carrying a clump weight. At the point, the two lines'
/// forces balance the weight to round-off (1e-10 of m g: the residual
/// tolerance of the point's rows).
#[test]
fn a_bridles_two_tensions_balance_its_clump_weight() {
    for method in [ConstraintMethod::Multiplier, ConstraintMethod::Elimination] {
        let mass = 0.05;
        let a = [0.0, 0.0, 0.0];
        let b = [3.0, 0.0, 1.0];
        let joint = [1.2, 0.0, -1.5];
        let la = norm(std::array::from_fn(|i| joint[i] - a[i]));
        let lb = norm(std::array::from_fn(|i| joint[i] - b[i]));
        let line_a = line_between(a, joint, la, 10, rope(1000.0));
        let line_b = line_between(b, joint, lb, 10, rope(1000.0));
        let seeds = vec![line_a.initial_state(), line_b.initial_state()];
        let system = System::new(
            vec![
                Line {
                    model: line_a,
                    ends: [End::Point(0), End::Point(2)],
                },
                Line {
                    model: line_b,
                    ends: [End::Point(1), End::Point(2)],
                },
            ],
            vec![Point::fixed(a), Point::fixed(b), Point::free(joint, mass)],
            G,
        )
        .expect("system");
        let mut s = SystemStatics::new(system, seeds, settings(method)).expect("statics");
        assert!(s
            .solve(|_, _| std::ops::ControlFlow::Continue(()))
            .expect("solve"));
        let f = s.point_force(2);
        let mg = mass * 9.81;
        let imbalance = [f[0], f[1], f[2] - mg];
        assert!(
            norm(imbalance) <= 1e-10 * mg,
            "{method:?}: lines on the point {f:?}, weight {mg}"
        );
        let (ta, tb) = (s.end_forces(0)[1].tension(), s.end_forces(1)[1].tension());
        assert!(ta > 0.0 && tb > 0.0);
        eprintln!(
            "{method:?}: tensions {ta} N and {tb} N, point at {:?}",
            s.point_position(2)
        );
    }
}

/// A one-line system from its catenary start and the single cable's
/// static solve (loads ramped from the straight cable) reach the same
/// equilibrium: positions to 1e-9 of the length (both converge to a
/// scaled residual of 1e-12).
#[test]
fn a_one_line_system_is_in_equilibrium_where_the_single_cable_is() {
    let length = 2.0;
    let n = 16;
    let model = line_between([0.0; 3], [length, 0.0, 0.0], length, n, rope(1000.0));
    let single = model
        .clone()
        .with_constraints(vec![
            Constraint {
                node: 0,
                kind: ConstraintKind::Pinned,
            },
            Constraint {
                node: n,
                kind: ConstraintKind::Pinned,
            },
        ])
        .expect("pinned");
    let mut cable =
        StaticSolver::new(single, settings(ConstraintMethod::Multiplier)).expect("solver");
    assert!(cable
        .solve(|_, _| std::ops::ControlFlow::Continue(()))
        .expect("solve"));
    let seed = model.initial_state();
    let system = System::new(
        vec![Line {
            model,
            ends: [End::Point(0), End::Point(1)],
        }],
        vec![Point::fixed([0.0; 3]), Point::fixed([length, 0.0, 0.0])],
        G,
    )
    .expect("system");
    let mut s = SystemStatics::new(system, vec![seed], settings(ConstraintMethod::Multiplier))
        .expect("statics");
    assert!(s
        .solve(|_, _| std::ops::ControlFlow::Continue(()))
        .expect("solve"));
    let diff = cable
        .state()
        .e
        .iter()
        .zip(&s.line_state(0).e)
        .map(|(a, b)| (a - b).abs())
        .fold(0.0, f64::max);
    assert!(diff <= 1e-9 * length, "largest difference {diff} m");
}

/// A line type's section as a material: EA, EI, mass per length over
/// an area of 1e-4 m^2.
fn section(ea: f64, ei: f64, mass_per_length: f64) -> Material {
    let area = 1e-4;
    Material {
        youngs_modulus: ea / area,
        density: mass_per_length / area,
        area,
        second_moment: ei * area / ea,
        axial_damping: 0.0,
    }
}

/// The static equilibrium of one line between two fixed points at
/// different heights, from its catenary seed: (end forces on A and B,
/// sag below the chord at midspan measured along gravity).
fn hanging_line(ei: f64, elements: usize, element: ElementType) -> ([f64; 3], [f64; 3], [f64; 3]) {
    let (a, b) = ([0.0, 0.0, 0.0], [80.0, 0.0, 30.0]);
    let cable = Cable::straight(100.0, elements, element)
        .with_origin(a)
        .with_direction([80.0, 0.0, 30.0]);
    let options = ModelOptions {
        measures: stancf::Measures {
            axial_strain: stancf::AxialStrain::Engineering,
            ..Default::default()
        },
        space_points: None,
    };
    let model = Model::new(
        cable,
        section(1e5, ei, 1.0),
        options,
        vec![Load::Gravity { acceleration: G }],
    )
    .expect("model");
    let system = System::new(
        vec![Line {
            model,
            ends: [End::Point(0), End::Point(1)],
        }],
        vec![Point::fixed(a), Point::fixed(b)],
        G,
    )
    .expect("system");
    let seeds = stancf::system::catenary_states(&system);
    let mut s =
        SystemStatics::new(system, seeds, settings(ConstraintMethod::Multiplier)).expect("statics");
    assert!(s
        .solve(|_, _| std::ops::ControlFlow::Continue(()))
        .expect("solve"));
    let [fa, fb] = s.end_forces(0);
    let model = &s.system().lines()[0].model;
    let mid = model.node_position(&s.line_state(0).e, elements / 2);
    (fa.force, fb.force, mid)
}

/// Irvine's elastic catenary (crate::catenary) against the finite
/// elements with a vanishing bending stiffness (the EI = 0 rule of
/// docs/method.md §11.7, 1e-7 w L^3): the end forces agree to 1e-5
/// relative. The elements' error at 40 SAC-2 is far below that (their
/// statics converge at O(h^4)); bending changes tensions by about
/// EI / (T L^2) ~ 1e-7.
#[test]
fn an_elastic_catenary_between_two_heights_has_irvines_end_forces() {
    let (a, b) = ([0.0, 0.0, 0.0], [80.0, 0.0, 30.0]);
    let exact = stancf::catenary::Catenary::between(
        stancf::catenary::CatenaryLine {
            length: 100.0,
            weight: 9.81,
            ea: 1e5,
        },
        a,
        b,
        G,
    )
    .expect("catenary");
    let w_l3 = 9.81 * 1e6;
    let (fa, fb, _) = hanging_line(1e-7 * w_l3, 40, ElementType::Sac2);
    for (got, end) in [
        (fa, stancf::catenary::LineEnd::A),
        (fb, stancf::catenary::LineEnd::B),
    ] {
        let want = exact.end_force(end);
        let err = norm(std::array::from_fn(|k| got[k] - want[k])) / norm(want);
        eprintln!("end {end:?}: {got:?} against {want:?}: {err:e}");
        assert!(err <= 1e-5, "end {end:?}: relative error {err:e}");
    }
}

/// As EI -> 0 the sag converges to the catenary's: the difference
/// falls with EI (measured ratios printed) and is below 1e-6 of the
/// length at EI = 1e-7 w L^3.
#[test]
fn a_hanging_lines_sag_converges_as_its_bending_stiffness_vanishes() {
    let exact = stancf::catenary::Catenary::between(
        stancf::catenary::CatenaryLine {
            length: 100.0,
            weight: 9.81,
            ea: 1e5,
        },
        [0.0; 3],
        [80.0, 0.0, 30.0],
        G,
    )
    .expect("catenary");
    let want = exact.position(50.0);
    let mut last = f64::INFINITY;
    for k in [1e-3, 1e-4, 1e-5, 1e-6, 1e-7] {
        let (_, _, mid) = hanging_line(k * 9.81e6, 40, ElementType::Sac2);
        let d = norm(std::array::from_fn(|i| mid[i] - want[i]));
        eprintln!("EI = {k:e} w L^3: midpoint {d:e} m from the catenary's");
        assert!(
            d < last,
            "no convergence at EI = {k:e} w L^3: {d:e} after {last:e}"
        );
        last = d;
    }
    assert!(last <= 1e-6 * 100.0, "{last:e} m");
}
