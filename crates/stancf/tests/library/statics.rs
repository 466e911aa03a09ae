//! Static analysis against analytic solutions: the cantilever under a tip
//! load (small deflection), the elastic catenary, circle bending (the
//! paper's Table 3), and the two constraint routes against each other.

use stancf::quadrature::GaussRule;
use stancf::{
    AxialStrain, Cable, Constraint, ConstraintKind, ConstraintMethod, ElementType, Load, Material,
    Measures, Model, ModelOptions, StaticSettings, StaticSolver,
};
use std::ops::ControlFlow;

fn solve(model: Model, settings: StaticSettings) -> (StaticSolver, usize, usize) {
    let mut s = StaticSolver::new(model, settings).unwrap();
    let (mut iterations, mut increments) = (0, 0);
    s.solve(|_, inc| {
        iterations += inc.iterations;
        increments += 1;
        ControlFlow::Continue(())
    })
    .unwrap();
    (s, iterations, increments)
}

/// Tension as a function of the stretch for each strain measure: the
/// force on the cable is EA eps dEps/dr_x, so T = EA (lambda - 1)
/// (engineering) or EA lambda (lambda^2 - 1) / 2 (Green).
fn tension(measure: AxialStrain, ea: f64, stretch: f64) -> f64 {
    match measure {
        AxialStrain::Engineering => ea * (stretch - 1.0),
        AxialStrain::Green => ea * stretch * (stretch * stretch - 1.0) / 2.0,
    }
}

/// The stretch for a tension (Newton on the monotone T(lambda)).
fn stretch(measure: AxialStrain, ea: f64, t: f64) -> f64 {
    let mut l = 1.0 + t / ea;
    for _ in 0..50 {
        let f = tension(measure, ea, l) - t;
        let h = 1e-7 * l;
        let d = (tension(measure, ea, l + h) - tension(measure, ea, l - h)) / (2.0 * h);
        l -= f / d;
    }
    l
}

/// The elastic catenary of a perfectly flexible cable of unstretched length
/// L and weight w per unstretched length between two supports at the same
/// height `span` apart: with H the horizontal tension and V(s) = w (L/2 - s)
/// the vertical one, T = sqrt(H^2 + V^2) and the stretch from the
/// constitutive law,
///   x(s) = int_0^s lambda H / T ds,   y(s) = int_0^s lambda V / T ds (downward).
/// H solves x(L) = span (bisection); returns (H, sag at midspan).
fn elastic_catenary(measure: AxialStrain, ea: f64, w: f64, length: f64, span: f64) -> (f64, f64) {
    let rule = GaussRule::new(10).unwrap();
    let pieces = 200;
    let integrate = |h: f64, upto: f64| -> (f64, f64) {
        let (mut x, mut y) = (0.0, 0.0);
        let ds = upto / pieces as f64;
        for k in 0..pieces {
            for (p, wq) in rule.iter() {
                let s = (k as f64 + p) * ds;
                let v = w * (length / 2.0 - s);
                let t = (h * h + v * v).sqrt();
                let lam = stretch(measure, ea, t);
                x += wq * ds * lam * h / t;
                y += wq * ds * lam * v / t;
            }
        }
        (x, y)
    };
    let (mut lo, mut hi) = (1e-9 * w * length, 1e3 * w * length + ea);
    for _ in 0..200 {
        let mid = 0.5 * (lo + hi);
        if integrate(mid, length).0 > span {
            hi = mid;
        } else {
            lo = mid;
        }
    }
    let h = 0.5 * (lo + hi);
    (h, integrate(h, length / 2.0).1)
}

/// A catenary between two pins, gravity only, from the straight cable
/// (which has no transverse stiffness but its tiny bending one): it
/// converges, and sag and support reactions match the elastic catenary of
/// the same strain measure within 0.5 %, for axial stiffnesses from 100 N
/// (sag 17 % of the span) to 1e5 N (sag 1.7 %). EI is small (bending
/// boundary layers of sqrt(EI / T) ~ 1 cm at the supports); 40 SAC-2
/// elements.
#[test]
fn catenary_between_two_pins_matches_the_elastic_catenary() {
    for modulus in [1.0e6, 1.0e7, 1.0e9] {
        catenary(modulus);
    }
}

fn catenary(youngs_modulus: f64) {
    let material = Material {
        youngs_modulus,
        density: 1000.0,
        area: 1.0e-4,
        second_moment: 1.0e-11,
        axial_damping: 0.0,
    };
    let length = 10.0;
    let g = 9.81;
    for measure in [AxialStrain::Green, AxialStrain::Engineering] {
        for method in [ConstraintMethod::Multiplier, ConstraintMethod::Elimination] {
            let n = 40;
            let model = Model::new(
                Cable::straight(length, n, ElementType::Sac2),
                material,
                ModelOptions {
                    measures: Measures {
                        axial_strain: measure,
                        ..Measures::default()
                    },
                    space_points: None,
                },
                vec![Load::Gravity {
                    acceleration: [0.0, -g, 0.0],
                }],
            )
            .unwrap()
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
            .unwrap();
            let ea = material.youngs_modulus * material.area;
            let w = material.density * material.area * g;
            let (h, sag) = elastic_catenary(measure, ea, w, length, length);
            let (s, iterations, increments) = solve(
                model,
                StaticSettings {
                    load_steps: 10,
                    constraint_method: method,
                    ..StaticSettings::default()
                },
            );
            let mid = s.model().node_position(&s.state().e, n / 2);
            let r = s.reactions();
            eprintln!(
                "catenary EA = {ea:e} N, {measure:?} {method:?}: sag {:.6} m (analytic {sag:.6}), H {:.6} N \
                 (analytic {h:.6}), V {:.6} N (analytic {:.6}); {increments} increments, \
                 {iterations} iterations",
                -mid[1],
                -r[0].1[0],
                r[0].1[1],
                w * length / 2.0
            );
            assert!(
                (-mid[1] / sag - 1.0).abs() < 5e-3,
                "sag {} vs {sag}",
                -mid[1]
            );
            // Reactions: A pulls left (-x) and up; B mirrors it.
            assert!((-r[0].1[0] / h - 1.0).abs() < 5e-3);
            assert!((r[1].1[0] / h - 1.0).abs() < 5e-3);
            for (_, f) in r {
                assert!((f[1] / (w * length / 2.0) - 1.0).abs() < 5e-3);
            }
        }
    }
}

fn cantilever(
    element: ElementType,
    elements: usize,
    points: Option<stancf::SpacePoints>,
    fix_curvature: bool,
    load: Load,
) -> Model {
    Model::new(
        Cable::straight(1.0, elements, element),
        pvc(),
        ModelOptions {
            measures: Measures::default(),
            space_points: points,
        },
        vec![load],
    )
    .unwrap()
    .with_constraints(vec![Constraint {
        node: 0,
        kind: ConstraintKind::Clamped { fix_curvature },
    }])
    .unwrap()
}

fn pvc() -> Material {
    Material::chen2023_pvc()
}

/// A small tip load P on the 1 m PVC cantilever: the tip deflection of
/// Euler-Bernoulli theory, P L^3 / (3 E I), within 0.5 % with 10 SAC-2
/// elements (cubic Hermite elements are exact for it in linear theory; the
/// load gives a deflection of 1e-3 L, so the geometric nonlinearity is
/// ~1e-6 relative).
#[test]
fn cantilever_tip_load_matches_euler_bernoulli() {
    let ei = 3.4e9 * 1.25e-13;
    let p = 3.0 * ei * 1e-3; // deflection 1 mm
    let model = cantilever(
        ElementType::Sac2,
        10,
        None,
        false,
        Load::PointForce {
            node: 10,
            force: [0.0, -p, 0.0],
        },
    );
    let (s, ..) = solve(model, StaticSettings::default());
    let tip = s.model().node_position(&s.state().e, 10);
    let analytic = p / (3.0 * ei);
    eprintln!(
        "cantilever: tip {:.9e} m, P L^3 / 3EI = {analytic:.9e} m",
        -tip[1]
    );
    assert!((-tip[1] / analytic - 1.0).abs() < 5e-3);
    // The clamp reacts with the load.
    let r = s.reactions()[0].1;
    assert!((r[1] - p).abs() < 1e-9 * p && r[0].abs() < 1e-6 * p);
}

/// Circle bending (Table 3): with 10 SAC-3 elements the full circle closes
/// to within 1e-5 L of the clamp; the SAC-2 error falls with refinement at
/// a measured rate of at least 2; multipliers and elimination agree.
#[test]
fn chen2023_table3_circle_bending() {
    let ei = 3.4e9 * 1.25e-13;
    let moment = |lambda: f64, n: usize| Load::EndMoment {
        node: n,
        moment: [0.0, 0.0, lambda * std::f64::consts::PI * ei],
    };
    let settings = |method| StaticSettings {
        load_steps: 40,
        tolerance: 1e-12,
        constraint_method: method,
        ..StaticSettings::default()
    };
    let (s, ..) = solve(
        cantilever(ElementType::Sac3, 10, None, false, moment(2.0, 10)),
        settings(ConstraintMethod::Multiplier),
    );
    let tip = s.model().node_position(&s.state().e, 10);
    let gap = (tip[0] * tip[0] + tip[1] * tip[1]).sqrt();
    eprintln!("SAC-3, 10 elements, full circle: tip {tip:?}, {gap:.3e} m from the clamp");
    assert!(gap < 1e-5, "gap {gap}");
    let (e, ..) = solve(
        cantilever(ElementType::Sac3, 10, None, false, moment(2.0, 10)),
        settings(ConstraintMethod::Elimination),
    );
    let diff = s
        .state()
        .e
        .iter()
        .zip(&e.state().e)
        .map(|(a, b)| (a - b).abs())
        .fold(0.0, f64::max);
    assert!(
        diff < 1e-10,
        "multipliers and elimination differ by {diff:e}"
    );

    let mut errors = Vec::new();
    for n in [5, 10, 20, 40] {
        let points = Some(stancf::SpacePoints {
            axial: 5,
            bending: 3,
        });
        let (s, ..) = solve(
            cantilever(ElementType::Sac2, n, points, false, moment(1.0, n)),
            settings(ConstraintMethod::Multiplier),
        );
        errors.push(s.model().node_position(&s.state().e, n)[0].abs());
    }
    let orders: Vec<f64> = errors.windows(2).map(|w| (w[0] / w[1]).log2()).collect();
    eprintln!("SAC-2 semicircle errors {errors:?}, orders {orders:?}");
    assert!(orders.iter().all(|&o| o >= 2.0), "{orders:?}");
}

/// A static problem without constraints that stop the rigid motions has
/// no unique solution and is refused.
#[test]
fn static_analysis_needs_constraints_against_rigid_motions() {
    let m = Model::new(
        Cable::straight(1.0, 4, ElementType::Sac2),
        pvc(),
        ModelOptions::default(),
        vec![],
    )
    .unwrap();
    for (cons, ok) in [
        (vec![], false),
        (
            vec![Constraint {
                node: 2,
                kind: ConstraintKind::Pinned,
            }],
            false,
        ),
        (
            vec![Constraint {
                node: 0,
                kind: ConstraintKind::Clamped {
                    fix_curvature: false,
                },
            }],
            true,
        ),
        (
            vec![
                Constraint {
                    node: 0,
                    kind: ConstraintKind::Pinned,
                },
                Constraint {
                    node: 4,
                    kind: ConstraintKind::Pinned,
                },
            ],
            true,
        ),
    ] {
        let r = StaticSolver::new(
            m.clone().with_constraints(cons).unwrap(),
            StaticSettings::default(),
        );
        assert_eq!(r.is_ok(), ok);
        if let Err(e) = r {
            assert_eq!(e.key, "constraints");
            assert!(e.message.contains("rigid motions"));
        }
    }
}

/// The full circle in a single load increment does not converge; the
/// increment is cut and retried until it does, and the answer is the one
/// of 20 increments.
#[test]
fn failed_increments_are_cut_and_retried() {
    let ei = 3.4e9 * 1.25e-13;
    let circle = || {
        cantilever(
            ElementType::Sac2,
            10,
            None,
            false,
            Load::EndMoment {
                node: 10,
                moment: [0.0, 0.0, 2.0 * std::f64::consts::PI * ei],
            },
        )
    };
    let mut s = StaticSolver::new(
        circle(),
        StaticSettings {
            load_steps: 1,
            ..StaticSettings::default()
        },
    )
    .unwrap();
    let mut cuts = 0;
    s.solve(|_, inc| {
        cuts += inc.cuts;
        ControlFlow::Continue(())
    })
    .unwrap();
    let (r, ..) = solve(circle(), StaticSettings::default());
    let a = s.model().node_position(&s.state().e, 10);
    let b = r.model().node_position(&r.state().e, 10);
    assert!(cuts > 0, "the single increment needed no cut");
    assert!(
        (a[0] - b[0]).abs() < 1e-10 && (a[1] - b[1]).abs() < 1e-10,
        "{a:?} {b:?}"
    );
}

/// A slack catenary: end B's support is moved 1 m towards A by a
/// prescribed constraint (r(0) = r0 + a sin(phase), frequency 0), applied
/// in proportion to the load factor, with gravity. Sag and reactions match
/// the elastic catenary with a 9 m span; both routes agree to 1e-10 m.
#[test]
fn slack_catenary_with_a_prescribed_support() {
    let material = Material {
        youngs_modulus: 1.0e7,
        density: 1000.0,
        area: 1.0e-4,
        second_moment: 1.0e-11,
        axial_damping: 0.0,
    };
    let (length, span, n, g) = (10.0, 9.0, 40, 9.81);
    let run = |method| {
        let model = Model::new(
            Cable::straight(length, n, ElementType::Sac2),
            material,
            ModelOptions::default(),
            vec![Load::Gravity {
                acceleration: [0.0, -g, 0.0],
            }],
        )
        .unwrap()
        .with_constraints(vec![
            Constraint {
                node: 0,
                kind: ConstraintKind::Pinned,
            },
            Constraint {
                node: n,
                kind: ConstraintKind::Prescribed {
                    velocity: [0.0; 3],
                    amplitude: [span - length, 0.0, 0.0],
                    frequency: 0.0,
                    phase: std::f64::consts::FRAC_PI_2,
                },
            },
        ])
        .unwrap();
        solve(
            model,
            StaticSettings {
                load_steps: 10,
                constraint_method: method,
                ..StaticSettings::default()
            },
        )
        .0
    };
    let a = run(ConstraintMethod::Multiplier);
    let b = run(ConstraintMethod::Elimination);
    let ea = material.youngs_modulus * material.area;
    let w = material.density * material.area * g;
    let (h, sag) = elastic_catenary(AxialStrain::Green, ea, w, length, span);
    let end = a.model().node_position(&a.state().e, n);
    let mid = a.model().node_position(&a.state().e, n / 2);
    let r = a.reactions();
    eprintln!(
        "slack catenary: end B at x = {:.9}, sag {:.6} m (analytic {sag:.6}), H {:.6} N (analytic {h:.6})",
        end[0], -mid[1], -r[0].1[0]
    );
    assert!((end[0] - span).abs() < 1e-12);
    assert!((-mid[1] / sag - 1.0).abs() < 5e-3);
    assert!((-r[0].1[0] / h - 1.0).abs() < 5e-3);
    let diff = a
        .state()
        .e
        .iter()
        .zip(&b.state().e)
        .map(|(x, y)| (x - y).abs())
        .fold(0.0, f64::max);
    assert!(diff < 1e-10, "routes differ by {diff}");
}
