//! Seabed contact (docs/method.md §12.2, (W40)-(W49)): the assembled
//! step's Jacobian with a line in the bed, sliding with friction, against
//! finite differences in both time schemes and in statics; a line laid on
//! a flat bed sinks in by its weight over k d; a line dropped on the bed
//! loses what the bed's work says, in both schemes.

use crate::common::step_checks::{check_elements_schemes_and_routes, clamped_start};
use crate::common::*;
use stancf::assembly::Scheme;
use stancf::water::{Seabed, SeabedContact};
use stancf::{
    run, Cable, Constraint, ConstraintKind, ElementType, Load, Material, Model, ModelOptions,
    Simulation, StaticSettings, StaticSolver, StepSettings, TimeScheme,
};
use std::ops::ControlFlow;

/// As in the damping tests: central differences with h = 1e-6 agree with
/// an exact derivative to ~1e-9 relative; the contact's ramp (W41) is
/// 1e-3 d = 2e-4 m wide, far wider than the differences' step.
const FD_TOL: f64 = 1e-7;

/// In statics friction resists the slide from the seed, regularized over
/// u_s = 1e-3 d = 2e-4 m (W48): central differences with h = 1e-6 across
/// it carry a truncation error of order (h / u_s)^2 = 2.5e-5 of the
/// friction's stiffness (measured 4.2e-6 overall); a wrong derivative of
/// the friction would be off by its whole size, 1e-2 of the rows or more.
const FD_TOL_STATIC_FRICTION: f64 = 5e-5;

fn rope() -> Material {
    Material {
        youngs_modulus: 2.0e3,
        density: 900.0,
        area: 1.0e-3,
        second_moment: 2.0e-7,
        axial_damping: 0.0,
    }
}

/// A tilted bed with friction that cuts the cable of [`cable_in_the_bed`].
fn tilted_bed() -> SeabedContact {
    SeabedContact {
        seabed: Seabed::plane([0.0, 0.0, 0.17], [0.1, -0.2, 1.0], 2e4, 50.0)
            .with_friction(0.4, 0.8, 0.2),
        diameter: 0.2,
    }
}

/// A cable of 3 elements running down through the tilted bed.
fn cable_in_the_bed(kind: ElementType, constraints: Vec<Constraint>) -> Model {
    let cable = Cable::straight(1.2, 3, kind)
        .with_origin([0.1, -0.2, 0.3])
        .with_direction([1.0, 0.5, -0.25]);
    let loads = vec![
        Load::Gravity {
            acceleration: [0.0, 0.0, -9.81],
        },
        Load::Seabed(tilted_bed()),
    ];
    Model::new(cable, rope(), ModelOptions::default(), loads)
        .unwrap()
        .with_constraints(constraints)
        .unwrap()
}

/// Assembled steps with the line partly in the bed and sliding: P2 with 1
/// and 2 layers and the Galerkin step, SAC-2 and SAC-3, free and with a
/// clamped end by both constraint routes: the Jacobian against central
/// differences to 1e-7; the static rows, with friction against the slide
/// from the seed, to 5e-5.
#[test]
fn step_jacobian_with_seabed_contact_matches_finite_differences() {
    let mut rng = Rng(0x5eab_ed00_0000_0013);
    let model = |kind, constrained| cable_in_the_bed(kind, clamped_start(constrained));
    let schemes = [
        Scheme::P2 { layers: 1 },
        Scheme::P2 { layers: 2 },
        Scheme::Galerkin,
    ];
    let dynamic = check_elements_schemes_and_routes(&model, &schemes, &mut rng, "", FD_TOL);
    let statics = check_elements_schemes_and_routes(
        &model,
        &[Scheme::Static],
        &mut rng,
        "",
        FD_TOL_STATIC_FRICTION,
    );
    let worst = dynamic.max(statics);
    eprintln!("step Jacobians with the seabed: worst rel. error {worst:.1e}");
}

/// A cable under gravity (0, 0, -9.81) on the bed `contact`, its nodes
/// `pinned` held.
fn cable_on(cable: Cable, material: Material, contact: SeabedContact, pinned: &[usize]) -> Model {
    let loads = vec![
        Load::Gravity {
            acceleration: [0.0, 0.0, -9.81],
        },
        Load::Seabed(contact),
    ];
    let pins = pinned
        .iter()
        .map(|&node| Constraint {
            node,
            kind: ConstraintKind::Pinned,
        })
        .collect();
    Model::new(cable, material, ModelOptions::default(), loads)
        .unwrap()
        .with_constraints(pins)
        .unwrap()
}

/// A 20 m line laid along a flat bed at z = -50 m, pinned at both ends on
/// the bed surface: away from the ends every point carries its weight w =
/// m g on the bed alone, so it sinks in until d k (g - delta/2) = w (W42):
/// g = w / (k d) + delta / 2 (0.37 mm here). The consistent loads of weight
/// and contact are the same quadrature of the same uniform force, so the
/// middle node's penetration is exact up to the static solve's tolerance
/// and the pinned ends' reach (the line's tension is ~0, so they bend it
/// only within an element or two).
#[test]
fn a_line_laid_on_a_flat_bed_sinks_in_by_its_weight_over_k_d() {
    let depth = 50.0;
    let contact = SeabedContact {
        seabed: Seabed::flat(depth, 3e6, 3e5),
        diameter: 0.0766,
    };
    let material = Material {
        youngs_modulus: 1e11,
        density: 7800.0,
        area: 1e-3,
        second_moment: 1e-9,
        axial_damping: 0.0,
    };
    let w = 7800.0 * 1e-3 * 9.81;
    let cable = Cable::straight(20.0, 20, ElementType::Sac2).with_origin([0.0, 0.0, -depth]);
    let model = cable_on(cable, material, contact.clone(), &[0, 20]);
    let mut solver = StaticSolver::new(model, StaticSettings::default()).unwrap();
    solver.solve(|_, _| ControlFlow::Continue(())).unwrap();
    let m = solver.model();
    let z_mid = solver.state().e[m.coordinate(10, 0, 2)];
    let expected = w / (3e6 * 0.0766) + 0.5 * contact.ramp_width();
    let sunk = -depth - z_mid;
    eprintln!("sunk {sunk:.9e} m, expected {expected:.9e} m");
    assert!(
        (sunk - expected).abs() < 1e-6 * expected,
        "sunk {sunk:e} m, w / (k d) + delta / 2 = {expected:e} m"
    );
}

fn drop_settings(dt: f64, scheme: TimeScheme) -> StepSettings {
    step_settings(dt, scheme, 1e-12)
}

/// A 2 m rope pinned at one end, released horizontal 5 cm above a flat
/// bed with damping and friction: it swings down, hits the bed, slides
/// and bounces. Returns the largest |E - E_0 - W_bed| over 0.5 s, the
/// work the bed took, -W_bed, and the largest kinetic energy.
fn dropped_rope(dt: f64, scheme: TimeScheme) -> (f64, f64, f64) {
    let contact = SeabedContact {
        seabed: Seabed::flat(1.0, 2e4, 2e2).with_friction(0.3, 0.6, 0.05),
        diameter: 0.05,
    };
    let material = Material {
        youngs_modulus: 1e6,
        density: 1000.0,
        area: 1e-3,
        second_moment: 1e-10,
        axial_damping: 0.0,
    };
    let cable = Cable::straight(2.0, 8, ElementType::Sac2)
        .with_origin([0.0, 0.0, -0.95])
        .with_direction([1.0, 0.3, 0.0]);
    let model = cable_on(cable, material, contact, &[0]);
    let s = model.initial_state();
    let mut sim = Simulation::new(model, s, drop_settings(dt, scheme)).unwrap();
    let e0 = sim.energies().mechanical();
    let (mut worst, mut scale) = (0.0f64, 0.0f64);
    run(&mut sim, 0.5, |sim, _, en| {
        worst = worst.max((en.mechanical() - e0 - sim.seabed_work()).abs());
        scale = scale.max(en.kinetic);
        ControlFlow::Continue(())
    })
    .unwrap();
    (worst, -sim.seabed_work(), scale)
}

/// The energy a line loses on the bed is the work the bed does on it
/// (W47): both sides are the same slab quadrature of the discrete motion,
/// so the balance error is the scheme's energy error. The Galerkin step's
/// balance sits at round-off (5e-13 J of the 1.06 J the bed takes). P2's
/// falls by 7.7 when dt halves from 1e-3 s: the contact force is only C1
/// (its ramp's second derivative jumps, W41), which costs P2's fourth
/// order some of its rate, so the claim is an order above 2 (ratio > 4)
/// and an error below 1e-5 of the work at 1e-3 s (measured 3.5e-7).
#[test]
fn a_rope_dropped_on_the_bed_loses_what_the_bed_takes() {
    let (p2_coarse, taken, scale) = dropped_rope(1e-3, TimeScheme::P2);
    let (p2_fine, _, _) = dropped_rope(5e-4, TimeScheme::P2);
    let (g_coarse, g_taken, _) = dropped_rope(1e-3, TimeScheme::Galerkin);
    eprintln!(
        "bed took {taken:.6e} J ({:.3} of the largest kinetic energy); balance error: P2 \
         {p2_coarse:.2e} J at 1e-3, {p2_fine:.2e} J at 5e-4; Galerkin {g_coarse:.2e} J; \
         Galerkin took {g_taken:.6e} J",
        taken / scale
    );
    assert!(taken > 0.05 * scale, "the bed dissipates");
    assert!(g_coarse < 1e-10 * taken, "Galerkin balance {g_coarse:e}");
    assert!(p2_coarse < 1e-5 * taken, "P2 balance {p2_coarse:e}");
    assert!(p2_coarse / p2_fine > 4.0, "P2 rate {}", p2_coarse / p2_fine);
    assert!(
        (taken - g_taken).abs() < 1e-4 * taken,
        "schemes: {taken} {g_taken}"
    );
}

/// A 20 m line set straight into a flat bed at a uniform penetration g =
/// 2 mm, at rest: the bed pushes with d k (g - delta/2) per metre
/// (W42), so its consistent nodal forces (`seabed_nodal_forces`) sum to
/// that times the length, push only upwards, and give an interior node of
/// SAC-2 the share of its two half elements, d k (g - delta/2) l (the
/// quadrature of a uniform force is exact; the penetration is the
/// difference of two heights near -50 m, known to ~1e-14 m: 1e-10 of g).
#[test]
fn the_seabed_s_nodal_forces_add_up_to_the_bed_s_push() {
    let depth = 50.0;
    let (k, d, g) = (3e6, 0.0766, 2e-3);
    let contact = SeabedContact {
        seabed: Seabed::flat(depth, k, 3e5),
        diameter: d,
    };
    let cable = Cable::straight(20.0, 10, ElementType::Sac2)
        .with_origin([0.0, 0.0, -depth - g])
        .with_direction([0.6, 0.8, 0.0]);
    let model = cable_on(cable, rope(), contact.clone(), &[]);
    let state = model.initial_state();
    let per_metre = d * k * (g - 0.5 * contact.ramp_width());
    let forces = stancf::observe::seabed_nodal_forces(&model, &state);
    let total: f64 = forces.iter().map(|f| f[2]).sum();
    assert!(
        (total - per_metre * 20.0).abs() < 1e-10 * per_metre * 20.0,
        "{total}"
    );
    for (j, f) in forces.iter().enumerate() {
        assert!(f[0].abs() < 1e-9 * per_metre && f[1].abs() < 1e-9 * per_metre);
        if j > 0 && j < 10 {
            assert!(
                (f[2] - per_metre * 2.0).abs() < 1e-10 * per_metre,
                "node {j}: {}",
                f[2]
            );
        }
    }
}
