//! The energy watchdog of `stancf::run` (`integrator::EnergyWatch`): a
//! cable at rest runs for ever whatever holds or loads it, and a blow-up
//! from near rest is still stopped while it is physically nothing.

use stancf::integrator::{energy_resolution, model_energy_scale};
use stancf::quadrature::GaussRule;
use stancf::stability::stable_step;
use stancf::{
    run, Cable, Constraint, ConstraintKind, ConstraintMethod, ElementType, FailureKind, Load,
    Material, Model, ModelOptions, Simulation, StepSettings, TimeScheme,
};
use std::ops::ControlFlow;

/// A cable at rest, with what holds and loads it.
struct Rest {
    name: &'static str,
    kind: ElementType,
    direction: [f64; 3],
    constraints: Vec<Constraint>,
    loads: Vec<Load>,
    scheme: TimeScheme,
    method: ConstraintMethod,
    /// Whether the motion is solved in the plane (the z coordinates
    /// eliminated) or in 3-D.
    planar: bool,
}

fn rest(name: &'static str) -> Rest {
    Rest {
        name,
        kind: ElementType::Sac2,
        direction: [1.0, 0.0, 0.0],
        constraints: vec![],
        loads: vec![],
        scheme: TimeScheme::P2,
        method: ConstraintMethod::Multiplier,
        planar: true,
    }
}

/// The cases of issue 11, item 2, each of which stopped at step 3 with
/// "energy grows without a source": free, pinned, clamped, 3-D, Galerkin,
/// zero gravity, a zero end moment (and the other element and constraint
/// route).
fn cases() -> Vec<Rest> {
    let at = |node, kind| Constraint { node, kind };
    let clamped = ConstraintKind::Clamped {
        fix_curvature: false,
    };
    vec![
        rest("free"),
        Rest {
            constraints: vec![at(0, ConstraintKind::Pinned)],
            ..rest("pinned")
        },
        Rest {
            constraints: vec![at(0, clamped.clone())],
            method: ConstraintMethod::Elimination,
            ..rest("clamped, eliminated")
        },
        Rest {
            kind: ElementType::Sac3,
            direction: [0.6, 0.48, 0.64],
            planar: false,
            ..rest("3-D, SAC-3")
        },
        Rest {
            scheme: TimeScheme::Galerkin,
            constraints: vec![at(2, ConstraintKind::Pinned)],
            ..rest("Galerkin, pinned")
        },
        Rest {
            loads: vec![Load::Gravity {
                acceleration: [0.0; 3],
            }],
            ..rest("zero gravity")
        },
        Rest {
            constraints: vec![at(0, clamped)],
            loads: vec![Load::EndMoment {
                node: 2,
                moment: [0.0; 3],
            }],
            ..rest("clamped, zero end moment")
        },
    ]
}

/// Ten thousand steps of each case: the run completes, and the cable stays
/// where it was. Every step reproduces the state at rest to round-off, a
/// few eps of the coordinates, so 10^4 steps could move it by ~1e4 x 10
/// eps ~ 2e-11 of its length at worst; 1e-9 leaves a factor 50.
#[test]
fn a_cable_at_rest_runs_for_ever() {
    let steps = 10_000;
    for case in cases() {
        let model = Model::new(
            Cable::straight(1.0, 2, case.kind).with_direction(case.direction),
            Material::chen2023_pvc(),
            ModelOptions::default(),
            case.loads,
        )
        .unwrap()
        .with_constraints(case.constraints)
        .unwrap();
        let state = model.initial_state();
        let e0 = state.e.clone();
        // w_max dt = 0.60 (SAC-2) and 1.29 (SAC-3), within P2's limit of 3.16.
        let dt = 2e-5;
        let settings = StepSettings {
            time_step: dt,
            time_scheme: case.scheme,
            constraint_method: case.method,
            ..StepSettings::default()
        };
        let mut sim = Simulation::new(model, state, settings).unwrap();
        assert_eq!(sim.is_planar(), case.planar, "{}", case.name);
        let mut moved = 0.0f64;
        let done = run(&mut sim, steps as f64 * dt, |sim, _, _| {
            for (a, b) in sim.state().e.iter().zip(&e0) {
                moved = moved.max((a - b).abs());
            }
            ControlFlow::Continue(())
        });
        assert_eq!(done, Ok(true), "{}", case.name);
        assert_eq!(sim.steps(), steps, "{}", case.name);
        eprintln!(
            "{}: {steps} steps, largest coordinate change {moved:.1e}, energy {:.1e} J \
             (resolution {:.1e} J)",
            case.name,
            sim.energies().mechanical(),
            energy_resolution(sim.model())
        );
        assert!(moved < 1e-9 * 1.0, "{}: moved by {moved}", case.name);
    }
}

/// The model's energy unit is E A L + E I / L + m |g| L + sum |F| L +
/// sum |M|: never zero, and each load adds its own term.
#[test]
fn the_model_energy_scale_counts_every_source() {
    let m = Material::chen2023_pvc();
    let cable = Cable::straight(4.0, 8, ElementType::Sac2);
    let model = |loads| Model::new(cable.clone(), m, ModelOptions::default(), loads).unwrap();
    let ea_l = m.youngs_modulus * m.area * 4.0;
    let ei_over_l = m.youngs_modulus * m.second_moment / 4.0;
    let bare = model_energy_scale(&model(vec![]));
    assert!((bare / (ea_l + ei_over_l) - 1.0).abs() < 1e-15, "{bare}");
    let loaded = model_energy_scale(&model(vec![
        Load::Gravity {
            acceleration: [0.0, -3.0, 4.0],
        },
        Load::PointForce {
            node: 8,
            force: [0.0, 6.0, 8.0],
        },
        Load::EndMoment {
            node: 8,
            moment: [0.0, 0.0, -2.0],
        },
    ]));
    let weight = m.density * m.area * 4.0 * 5.0;
    let expect = ea_l + ei_over_l + (weight + 10.0) * 4.0 + 2.0;
    assert!(
        (loaded / expect - 1.0).abs() < 1e-15,
        "{loaded} vs {expect}"
    );
    assert_eq!(energy_resolution(&model(vec![])), 1e3 * f64::EPSILON * bare);
}

/// A cable at rest nudged by 1e-9 m/s along its axis, stepped at three
/// times P2's stable step (w_max dt = 9.49, where P2's amplification has
/// spectral radius rho = 2.74: (tr + sqrt(tr^2 - 4)) / 2 with tr = 3.104
/// from the closed form (M20) of docs/method.md §4.5). The nudge's energy,
/// 3.8e-22 J, grows by up to rho^2 = 7.5 per step; the watchdog lets it
/// pass its floor, 1e3 eps E_model = 9.1e-9 J, which takes at least
/// ln(9.1e-9 / 3.8e-22) / ln 7.5 = 15 steps, and more as the fastest
/// growing modes hold only part of it: by 40 steps they need only hold
/// 1e-11 of it. The run then stops with the energy-growth failure, the
/// cable still at rest to the eye: the last state kept holds at most the
/// floor, 9.1e-9 J, the strain energy of a strain of sqrt(2 E / (E A l)) =
/// 1.9e-6 in one 0.5 m element, so no slope moved by much more than that
/// nor any node by more than l times it, 1e-6 m; 1e-5 leaves a factor 5.
#[test]
fn a_blow_up_from_near_rest_is_still_stopped() {
    let model = Model::new(
        Cable::straight(4.0, 8, ElementType::Sac2),
        Material::chen2023_pvc(),
        ModelOptions::default(),
        vec![],
    )
    .unwrap();
    let mut state = model.initial_state();
    let e0 = state.e.clone();
    state.v[8 * 6] = 1e-9;
    let limit = stable_step(&model, &state.e, &GaussRule::new(3).unwrap(), 1).unwrap();
    let settings = StepSettings {
        time_step: 3.0 * limit,
        ..StepSettings::default()
    };
    let mut sim = Simulation::new(model, state, settings).unwrap();
    let e_start = sim.energies().mechanical();
    assert!((e_start / 3.8e-22 - 1.0).abs() < 0.05, "{e_start}");
    let err = run(&mut sim, 1.0, |_, _, _| ControlFlow::Continue(())).unwrap_err();
    eprintln!("stopped: {err}");
    assert_eq!(err.kind, FailureKind::EnergyGrowth);
    assert!((15..=40).contains(&err.step), "step {}", err.step);
    let moved = sim
        .state()
        .e
        .iter()
        .zip(&e0)
        .fold(0.0f64, |m, (a, b)| m.max((a - b).abs()));
    eprintln!("largest coordinate change {moved:.2e}");
    assert!(moved < 1e-5, "{moved}");
}
