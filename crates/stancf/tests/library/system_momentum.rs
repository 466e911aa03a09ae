//! The discrete momentum balance of a system (docs/method.md §4.4,
//! (M18); §11.10): a star of three lines joined at a free point with a
//! mass, spinning and drifting in empty space, keeps its linear momentum
//! to round-off with either time scheme. With the Galerkin step this
//! holds only if the free point's end rates come from the system's mass
//! matrix: the momentum the next step starts from, M v_a, must be the
//! momentum the last step ended with, p_b.

use crate::common::light_rope;
use stancf::observe::momentum;
use stancf::system::{End, Line, Point, System, SystemSimulation};
use stancf::{Cable, ElementType, Model, ModelOptions, StepSettings, TimeScheme};

const POINT_MASS: f64 = 0.2;

/// Three 1 m lines from the origin at 120 degrees in the x-y plane, ends
/// A at a free point of 0.2 kg, ends B loose, no loads; spinning at
/// 3 rad/s about z (the centrifugal pull stretches them and sets them
/// oscillating) and drifting at `drift`.
fn spinning_star(element_type: ElementType, drift: [f64; 3]) -> (System, Vec<stancf::State>) {
    let mut lines = Vec::new();
    let mut states = Vec::new();
    for k in 0..3 {
        let angle = 2.0 * std::f64::consts::PI * k as f64 / 3.0;
        let cable =
            Cable::straight(1.0, 8, element_type).with_direction([angle.cos(), angle.sin(), 0.0]);
        let model =
            Model::new(cable, light_rope(), ModelOptions::default(), vec![]).expect("model");
        let mut state = model.initial_state();
        model.add_rigid_rotation(&mut state, [0.0, 0.0, 3.0], [0.0; 3]);
        for node in 0..model.nodes() {
            let o = model.coordinate(node, 0, 0);
            for c in 0..3 {
                state.v[o + c] += drift[c];
            }
        }
        states.push(state);
        lines.push(Line {
            model,
            ends: [End::Point(0), End::Loose],
        });
    }
    let system =
        System::new(lines, vec![Point::free([0.0; 3], POINT_MASS)], [0.0; 3]).expect("system");
    (system, states)
}

/// The [`spinning_star`]'s simulation in steps of 1 ms of `scheme`, Newton
/// to 1e-13 (the rows sum to the momentum balance: what Newton leaves of
/// them enters it).
fn spinning_star_simulation(
    element_type: ElementType,
    scheme: TimeScheme,
    drift: [f64; 3],
) -> SystemSimulation {
    let (system, states) = spinning_star(element_type, drift);
    let mut settings = StepSettings {
        time_step: 1e-3,
        time_scheme: scheme,
        ..StepSettings::default()
    };
    settings.newton.tolerance = 1e-13;
    SystemSimulation::new(system, states, settings).expect("simulation")
}

/// Linear momentum of the lines (int rho A r_dot dx each) and the point.
fn linear_momentum(sim: &SystemSimulation) -> [f64; 3] {
    let mut p = sim.point_state(0).1.map(|v| POINT_MASS * v);
    for line in sim.lines() {
        let (_, pl, _) = momentum(line.model(), line.state());
        for c in 0..3 {
            p[c] += pl[c];
        }
    }
    p
}

/// Every line end at the free point moves with the point (the Galerkin
/// step's rates solve the system's M v = p, not each line's own), and
/// over 0.5 s (500 steps) the momentum stays at its start, the total
/// mass (3 x 2 g and 0.2 kg) times the drift, to 1e-12 of its size: round-off (measured
/// 3e-15 with P2; 9e-14 and 4e-13 with the Galerkin step, whose mass
/// solve multiplies round-off by the mass matrix's condition number,
/// larger for SAC-3's r_xx). The rows sum to the momentum balance (M18)
/// (the free point's rows sum the lines' and the point's), so what Newton
/// leaves of them enters too: its tolerance is set to 1e-13 here.
#[test]
fn a_spinning_star_of_lines_keeps_its_momentum_with_either_scheme() {
    let drift = [0.5, -0.2, 0.1];
    for element_type in [ElementType::Sac2, ElementType::Sac3] {
        for scheme in [TimeScheme::P2, TimeScheme::Galerkin] {
            let mut sim = spinning_star_simulation(element_type, scheme, drift);
            let total_mass = 3.0 * 2e-3 + POINT_MASS;
            let expected = drift.map(|v| total_mass * v);
            let size = expected.iter().map(|p| p * p).sum::<f64>().sqrt();
            let mut worst: f64 = 0.0;
            let mut stretched: f64 = 0.0;
            let mut joint: f64 = 0.0;
            for _ in 0..500 {
                sim.step().expect("step");
                let v_point = sim.point_state(0).1;
                for line in sim.lines() {
                    let v = &line.state().v;
                    for c in 0..3 {
                        joint = joint.max((v[c] - v_point[c]).abs() / 3.0);
                    }
                }
                let p = linear_momentum(&sim);
                for c in 0..3 {
                    worst = worst.max((p[c] - expected[c]).abs() / size);
                }
                let line = &sim.lines()[0];
                let tip = line.model().node_position(&line.state().e, 8);
                let root = sim.point_state(0).0;
                let reach = (0..3)
                    .map(|c| (tip[c] - root[c]).powi(2))
                    .sum::<f64>()
                    .sqrt();
                stretched = stretched.max(reach - 1.0);
            }
            eprintln!(
                "{element_type:?} {scheme:?}: momentum error {worst:e} of its size, \
                 joint velocity mismatch {joint:e} of the tip speed, \
                 largest stretch {stretched:e} m"
            );
            assert!(
                stretched > 1e-3,
                "the spin must stretch the lines: {stretched}"
            );
            assert!(worst <= 1e-12, "{element_type:?} {scheme:?}: {worst:e}");
            assert!(joint <= 1e-12, "{element_type:?} {scheme:?}: {joint:e}");
        }
    }
}

/// The star lets go of line 0 at 0.25 s (a failure at its free point,
/// docs/method.md §11.16): the line flies off from a new free point of no
/// mass, and the momentum of the whole stays at its start to the same
/// round-off as without the release, with either scheme and element: the
/// released end's momentum goes with it, none is made or lost.
#[test]
fn a_spinning_star_that_lets_go_of_a_line_keeps_its_momentum() {
    let drift = [0.5, -0.2, 0.1];
    for element_type in [ElementType::Sac2, ElementType::Sac3] {
        for scheme in [TimeScheme::P2, TimeScheme::Galerkin] {
            let mut sim = spinning_star_simulation(element_type, scheme, drift);
            sim.set_failures(vec![stancf::system::LineFailure {
                point: 0,
                lines: vec![0],
                time: Some(0.25),
                tension: None,
            }])
            .expect("failure");
            let total_mass = 3.0 * 2e-3 + POINT_MASS;
            let expected = drift.map(|v| total_mass * v);
            let size = expected.iter().map(|p| p * p).sum::<f64>().sqrt();
            let mut worst: f64 = 0.0;
            for _ in 0..500 {
                sim.step().expect("step");
                let p = linear_momentum(&sim);
                for c in 0..3 {
                    worst = worst.max((p[c] - expected[c]).abs() / size);
                }
            }
            let apart = (0..3)
                .map(|c| (sim.point_state(1).0[c] - sim.point_state(0).0[c]).powi(2))
                .sum::<f64>()
                .sqrt();
            eprintln!(
                "{element_type:?} {scheme:?}: momentum error {worst:e} of its size; the \
                 released end is {apart:.3} m from the hub"
            );
            assert_eq!(sim.releases().len(), 1);
            assert!(apart > 0.1, "the released line flies off: {apart}");
            assert!(worst <= 1e-12, "{element_type:?} {scheme:?}: {worst:e}");
        }
    }
}
