//! Graded and sectioned meshes (docs/method.md §1.6, (M38), (M38a)):
//! where the nodes sit, a
//! ratio-1 grading as the uniform mesh to the bit, a graded line's
//! statics against Irvine's elastic catenary, and the energy of a graded
//! swinging line.

use stancf::catenary::{Catenary, CatenaryLine, LineEnd};
use stancf::observe::stress_samples;
use stancf::system::{catenary_states, End, Line, Point, System, SystemStatics};
use stancf::{
    run, Cable, Constraint, ConstraintKind, ConstraintMethod, ElementType, GradedEnd, Grading,
    Load, Material, MeshSection, Model, ModelOptions, NewtonSettings, Simulation, StaticSettings,
    StepSettings,
};
use std::ops::ControlFlow;

fn graded(toward: GradedEnd, ratio: f64) -> Grading {
    Grading::Geometric { toward, ratio }
}

fn norm(v: [f64; 3]) -> f64 {
    v.iter().map(|x| x * x).sum::<f64>().sqrt()
}

/// The node coordinates of a graded model: x_0 = 0 and x_n = L exactly,
/// strictly increasing, the element lengths their differences and in
/// the requested ratio (shortest at the fine end, longest at the other
/// or in the middle), each element a constant factor longer than the
/// one before it. The lengths are differences of coordinates of size L,
/// so they carry a round-off of a few eps L: the ratio holds to 1e-12.
#[test]
fn grading_toward_an_end_makes_the_elements_there_shorter() {
    let (length, n, ratio) = (7.3, 11, 5.0);
    for toward in [GradedEnd::A, GradedEnd::B, GradedEnd::Both] {
        for kind in [ElementType::Sac2, ElementType::Sac3] {
            let cable = Cable::straight(length, n, kind).with_grading(graded(toward, ratio));
            let model = Model::new(
                cable,
                Material::chen2023_pvc(),
                ModelOptions::default(),
                vec![],
            )
            .unwrap();
            let x = model.node_coordinates();
            assert_eq!(x.len(), n + 1);
            assert_eq!((x[0], x[n]), (0.0, length), "{toward:?}");
            let l: Vec<f64> = (0..n).map(|k| model.element_length(k)).collect();
            let sum: f64 = l.iter().sum();
            assert!((sum - length).abs() <= 4.0 * f64::EPSILON * length, "{sum}");
            for k in 0..n {
                assert!(x[k + 1] > x[k], "{toward:?}: not increasing at {k}");
                assert_eq!(l[k], x[k + 1] - x[k]);
                assert_eq!(model.node_coordinate(k), x[k]);
            }
            let (fine, coarse) = match toward {
                GradedEnd::A => (l[0], l[n - 1]),
                GradedEnd::B => (l[n - 1], l[0]),
                GradedEnd::Both => {
                    // Equal but for the round-off of the differences.
                    assert!((l[0] / l[n - 1] - 1.0).abs() <= 1e-12);
                    (l[0].min(l[n - 1]), l[n / 2])
                }
            };
            assert_eq!(fine, model.shortest_element_length());
            assert_eq!(coarse, model.longest_element_length());
            assert!((coarse / fine - ratio).abs() <= 1e-12 * ratio, "{toward:?}");
            // A geometric progression: a constant factor between neighbours
            // (toward both ends, within each half).
            let growth: Vec<f64> = (0..n - 1).map(|k| l[k + 1] / l[k]).collect();
            let q = match toward {
                GradedEnd::A => ratio.powf(1.0 / (n - 1) as f64),
                GradedEnd::B => ratio.powf(-1.0 / (n - 1) as f64),
                GradedEnd::Both => ratio.powf(1.0 / ((n - 1) / 2) as f64),
            };
            for (k, g) in growth.iter().enumerate() {
                let want = if toward == GradedEnd::Both && k >= n / 2 {
                    1.0 / q
                } else {
                    q
                };
                assert!((g - want).abs() <= 1e-12, "{toward:?} {k}: {g} vs {want}");
            }
            // The reference shape puts node j at origin + x_j d.
            let e = model.reference_coordinates();
            for j in 0..=n {
                assert_eq!(model.node_position(&e, j), [x[j], 0.0, 0.0]);
            }
        }
    }
}

/// The stress samples (stress.csv's s column) run from x_k to x_(k+1)
/// over element k of a graded mesh: the node coordinates at the
/// element ends, evenly spaced within.
#[test]
fn stress_samples_follow_the_graded_arc_length() {
    let cable = Cable::straight(3.0, 6, ElementType::Sac2).with_grading(graded(GradedEnd::A, 3.0));
    let model = Model::new(
        cable,
        Material::chen2023_pvc(),
        ModelOptions::default(),
        vec![],
    )
    .unwrap();
    let mut samples = Vec::new();
    stress_samples(&model, &model.initial_state(), 5, &mut samples);
    let x = model.node_coordinates();
    for (i, s) in samples.iter().enumerate() {
        let (k, p) = (i / 5, (i % 5) as f64 / 4.0);
        assert_eq!(s.element, k);
        let want = x[k] + p * (x[k + 1] - x[k]);
        assert!((s.s - want).abs() <= 2.0 * f64::EPSILON * 3.0, "{i}");
        assert!(s.axial_stress.abs() <= 1e-3, "stress-free reference");
    }
    assert_eq!(samples[0].s, 0.0);
    assert_eq!(samples.last().unwrap().s, 3.0);
}

/// The gutta-percha pendulum of the paper (0.5 m, pinned at A, released
/// horizontal under gravity) with `elements` SAC-2 graded by `grading`.
fn pendulum(elements: usize, grading: Grading) -> Model {
    Model::new(
        Cable::straight(0.5, elements, ElementType::Sac2).with_grading(grading),
        Material::chen2023_gutta_percha(),
        ModelOptions::default(),
        vec![Load::Gravity {
            acceleration: [0.0, -9.81, 0.0],
        }],
    )
    .unwrap()
    .with_constraints(vec![Constraint {
        node: 0,
        kind: ConstraintKind::Pinned,
    }])
    .unwrap()
}

fn step_settings(dt: f64) -> StepSettings {
    StepSettings {
        time_step: dt,
        constraint_method: ConstraintMethod::Multiplier,
        newton: NewtonSettings {
            tolerance: 1e-12,
            max_iterations: 50,
            ..NewtonSettings::default()
        },
        ..StepSettings::default()
    }
}

/// A line of 100 m between fixed points 80 m apart horizontally and 30 m
/// vertically, EA = 1e5 N, 1 kg/m in gravity, with bending stiffness
/// `ei` and `elements` SAC-2 graded by `grading`: the system.
fn hanging_line(elements: usize, grading: Grading, ei: f64) -> System {
    let (a, b) = ([0.0, 0.0, 0.0], [80.0, 0.0, 30.0]);
    let area = 1e-4;
    let material = Material {
        youngs_modulus: 1e5 / area,
        density: 1.0 / area,
        area,
        second_moment: ei * area / 1e5,
        axial_damping: 0.0,
    };
    let options = ModelOptions {
        measures: stancf::Measures {
            axial_strain: stancf::AxialStrain::Engineering,
            ..Default::default()
        },
        space_points: None,
    };
    let cable = Cable::straight(100.0, elements, ElementType::Sac2)
        .with_origin(a)
        .with_direction([80.0, 0.0, 30.0])
        .with_grading(grading);
    let model = Model::new(
        cable,
        material,
        options,
        vec![Load::Gravity {
            acceleration: [0.0, 0.0, -9.81],
        }],
    )
    .unwrap();
    System::new(
        vec![Line {
            model,
            ends: [End::Point(0), End::Point(1)],
        }],
        vec![Point::fixed(a), Point::fixed(b)],
        [0.0, 0.0, -9.81],
    )
    .unwrap()
}

/// The static equilibrium of [`hanging_line`] from its catenary seed.
fn solve_statics(system: System) -> SystemStatics {
    let seeds = catenary_states(&system);
    let settings = StaticSettings {
        constraint_method: ConstraintMethod::Multiplier,
        tolerance: 1e-13,
        ..StaticSettings::default()
    };
    let mut s = SystemStatics::new(system, seeds, settings).unwrap();
    assert!(s.solve(|_, _| ControlFlow::Continue(())).unwrap());
    s
}

/// A grading of ratio 1 is the uniform mesh: the same node coordinates,
/// the same static equilibrium and the same dynamic steps, to the bit
/// (the uniform formulas are kept for it, docs/method.md §1.6).
#[test]
fn a_ratio_one_grading_is_the_uniform_mesh_bit_for_bit() {
    for toward in [GradedEnd::A, GradedEnd::B, GradedEnd::Both] {
        let one = graded(toward, 1.0);
        let (u, g) = (pendulum(5, Grading::Uniform), pendulum(5, one.clone()));
        assert_eq!(u.node_coordinates(), g.node_coordinates());
        let statics = |grading| {
            let s = solve_statics(hanging_line(12, grading, 1e-2));
            (s.line_state(0).e.clone(), s.end_forces(0).map(|f| f.force))
        };
        assert_eq!(statics(Grading::Uniform), statics(one), "{toward:?}");
        let dynamics = |model: Model| {
            let s = model.initial_state();
            let mut sim = Simulation::new(model, s, step_settings(2e-4)).unwrap();
            run(&mut sim, 20.0 * 2e-4, |_, _, _| ControlFlow::Continue(())).unwrap();
            (sim.state().clone(), sim.reactions().to_vec())
        };
        assert_eq!(dynamics(u), dynamics(g), "{toward:?}");
    }
}

/// A graded line between two fixed points is Irvine's elastic catenary
/// (`crate::catenary`) at its nodes' material coordinates, with its end
/// forces (C12), to the elements' error. Refining at a fixed ratio keeps
/// the shape of the grading (the node map x(j / n) tends to a smooth
/// map, M34), so the error falls at the uniform mesh's fourth order
/// (SAC-2 statics, docs/method.md §11.6): the node error's order from 16
/// to 128 elements must be above 3.5 (measured 4.2, 4.1 and 3.9), and
/// above 3 over every halving (measured 3.8 to 4.7; 3.4 once in
/// sections, where the largest node error moves from one section to the
/// other between meshes, and 4.1 on the next). The bending stiffness is 1e-12 w L^3: its effect is linear in EI
/// (1.9e-5 m at 1e-7 w L^3, §11.6), 2e-10 m here, below the finest
/// mesh's error (~1e-7 m), and on the end forces ~c w L / T ~ 1e-12
/// (§11.7). So at 128 elements the end forces agree to 1e-9 (4.6e-6 at
/// 16, falling by 2^4 or more per halving gives < 1.2e-9; measured
/// 9e-11). A sectioned mesh (M38a: 20 m in n/2 elements, then 80 m in
/// n/2, four times longer) is refined by halving each section's
/// elements, the same smooth-map argument: the same order and bounds.
#[test]
fn a_graded_line_between_two_points_is_irvines_elastic_catenary() {
    let exact = Catenary::between(
        CatenaryLine {
            length: 100.0,
            weight: 9.81,
            ea: 1e5,
        },
        [0.0; 3],
        [80.0, 0.0, 30.0],
        [0.0, 0.0, -9.81],
    )
    .unwrap();
    let ei = 1e-12 * 9.81 * 1e6;
    let sections = |n: usize| {
        Grading::Sections(vec![
            MeshSection {
                length: 20.0,
                elements: n / 2,
            },
            MeshSection {
                length: 80.0,
                elements: n / 2,
            },
        ])
    };
    let meshes: [(&str, &dyn Fn(usize) -> Grading); 3] = [
        ("toward B", &|_| graded(GradedEnd::B, 4.0)),
        ("toward both", &|_| graded(GradedEnd::Both, 4.0)),
        ("in sections", &sections),
    ];
    for (toward, grading) in meshes {
        let mut errors: Vec<(f64, f64)> = Vec::new();
        for n in [16, 32, 64, 128] {
            let s = solve_statics(hanging_line(n, grading(n), ei));
            let model = &s.system().lines()[0].model;
            let e = &s.line_state(0).e;
            let position = (0..=n)
                .map(|j| {
                    let want = exact.position(model.node_coordinate(j));
                    let got = model.node_position(e, j);
                    norm(std::array::from_fn(|k| got[k] - want[k]))
                })
                .fold(0.0, f64::max);
            let force = [LineEnd::A, LineEnd::B]
                .iter()
                .zip(s.end_forces(0))
                .map(|(&end, got)| {
                    let want = exact.end_force(end);
                    norm(std::array::from_fn(|k| got.force[k] - want[k])) / norm(want)
                })
                .fold(0.0, f64::max);
            eprintln!(
                "{toward}, ratio 4, {n} SAC-2 (shortest {:.3} m, longest {:.3} m): \
                 nodes within {position:.3e} m of the catenary, end forces {force:.3e} relative",
                model.shortest_element_length(),
                model.longest_element_length()
            );
            if let Some(&(last, _)) = errors.last() {
                let order = (last / position).log2();
                eprintln!("  order of the node error {order:.2}");
                assert!(order > 3.0, "{toward}, {n} elements: order {order:.2}");
            }
            errors.push((position, force));
        }
        let (first, last) = (errors[0].0, errors[errors.len() - 1].0);
        let order = (first / last).log2() / (errors.len() - 1) as f64;
        assert!(
            order > 3.5,
            "{toward}: order {order:.2} from 16 to 128 elements"
        );
        let (_, force) = errors[errors.len() - 1];
        assert!(force <= 1e-9, "{toward}: end forces {force:e} off");
    }
}

/// The energy band of a run: the largest |E(t) - E(0)| over the run, E
/// the mechanical energy (kinetic, strain, gravity; the pin does no
/// work), relative to the energy scale of the motion (kinetic + strain +
/// |change of gravity|, its largest value), as in the uniform pendulum's
/// test (`constrained_dynamics.rs`).
fn energy_band(model: Model, dt: f64, duration: f64) -> f64 {
    let s = model.initial_state();
    let mut sim = Simulation::new(model, s, step_settings(dt)).unwrap();
    let e0 = sim.energies();
    let (mut scale, mut worst) = (0.0f64, 0.0f64);
    run(&mut sim, duration, |_, _, en| {
        scale = scale.max(en.kinetic + en.strain + (en.gravity - e0.gravity).abs());
        worst = worst.max((en.mechanical() - e0.mechanical()).abs());
        ControlFlow::Continue(())
    })
    .unwrap();
    worst / scale
}

/// The paper's pendulum (gutta-percha, 0.5 m, pinned at A, released
/// horizontal), 8 SAC-2 graded toward either end or both with ratio 4
/// (shortest element 2.8 cm against 6.25 cm uniform, well inside P2's
/// stable step at these steps), swings 0.8 s without damping: its
/// energy is conserved as the uniform mesh's is. The energy error of P2
/// is that of the time integration (docs/method.md §4.4, §4.7), so it
/// falls at order ~4 from dt = 2e-4 to 1e-4 (above 3.5 asserted) and is
/// below 1e-9 of the energy scale at 1e-4 (the uniform pendulum's
/// bound, `chen2023_pendulum_pinned_without_drag`); the uniform 8-element
/// mesh is measured beside it.
#[test]
fn a_graded_swinging_line_conserves_its_energy_like_the_uniform_one() {
    for grading in [
        Grading::Uniform,
        graded(GradedEnd::A, 4.0),
        graded(GradedEnd::B, 4.0),
        graded(GradedEnd::Both, 4.0),
    ] {
        let coarse = energy_band(pendulum(8, grading.clone()), 2e-4, 0.8);
        let fine = energy_band(pendulum(8, grading.clone()), 1e-4, 0.8);
        let order = (coarse / fine).log2();
        eprintln!(
            "pendulum {grading:?}: energy band {coarse:.3e} (dt 2e-4), {fine:.3e} (dt 1e-4), \
             order {order:.2}"
        );
        assert!(fine < 1e-9, "{grading:?}: band {fine:e}");
        assert!(order > 3.5, "{grading:?}: order {order:.2}");
    }
}
