//! Added mass in a system of lines (docs/method.md §11.10, §12.5): the
//! Galerkin step of a system with a free point solves the system's
//! (M + M_a(e_b)) v_b = p_b, refactorized at every step because the
//! entrained water's mass turns with the lines (W31); P2 carries each
//! line's p = M v + dT_a/dv (W30). Either way the energy with T_a is kept.

use crate::common::light_rope;
use crate::common::water_lines::*;
use stancf::system::{End, Line, Point, System, SystemSimulation};
use stancf::{Cable, ElementType, Model, ModelOptions, StepSettings, TimeScheme};

const POINT_MASS: f64 = 0.01;

/// Three 1 m lines (2 g/m) from a free point of 10 g at 120 degrees,
/// 5 m under still water, their ends B loose, no gravity; d = 2 mm
/// (rho_w A = 3.2 g/m), Can = 1, Cat = 0.5. Spinning at 3 rad/s about an
/// axis tilted from z, so the lines' added mass turns with them.
fn spinning_star_in_water(element_type: ElementType) -> (System, Vec<stancf::State>) {
    let mut lines = Vec::new();
    let mut states = Vec::new();
    for k in 0..3 {
        let angle = 2.0 * std::f64::consts::PI * k as f64 / 3.0;
        let cable = Cable::straight(1.0, 6, element_type)
            .with_origin([0.0, 0.0, -5.0])
            .with_direction([angle.cos(), angle.sin(), 0.0]);
        let water = vec![in_still_water(50.0, 2e-3, 1.0, 0.5)];
        let model = Model::new(cable, light_rope(), ModelOptions::default(), water).unwrap();
        let mut state = model.initial_state();
        model.add_rigid_rotation(&mut state, [0.0, 1.0, 3.0], [0.0, 0.0, -5.0]);
        states.push(state);
        lines.push(Line {
            model,
            ends: [End::Point(0), End::Loose],
        });
    }
    let point = Point::free([0.0, 0.0, -5.0], POINT_MASS);
    (System::new(lines, vec![point], [0.0; 3]).unwrap(), states)
}

/// The lines' energies (with T_a) and the point's kinetic energy.
fn system_energy(sim: &SystemSimulation) -> f64 {
    let v = sim.point_state(0).1;
    let point = 0.5 * POINT_MASS * (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    point
        + sim
            .lines()
            .iter()
            .map(|l| l.energies().mechanical())
            .sum::<f64>()
}

/// Over 0.5 s (500 steps of 1 ms) the energy stays at its start: the
/// Galerkin step to 1e-10 of it (measured 5e-13 to 8e-13: its O(dt^6)
/// error is below round-off at this step; with the system's mass matrix
/// missing M_a(e_b) the step fails within ten steps), P2 to 1e-8 (its
/// O(dt^4) error, measured 4.4e-11). The water carries 0.62 of the
/// kinetic energy.
#[test]
fn a_spinning_star_of_lines_in_water_keeps_its_energy_with_either_scheme() {
    for element_type in [ElementType::Sac2, ElementType::Sac3] {
        for scheme in [TimeScheme::P2, TimeScheme::Galerkin] {
            let (system, states) = spinning_star_in_water(element_type);
            let mut settings = StepSettings {
                time_step: 1e-3,
                time_scheme: scheme,
                ..StepSettings::default()
            };
            settings.newton.tolerance = 1e-12;
            let mut sim = SystemSimulation::new(system, states, settings).unwrap();
            let e0 = system_energy(&sim);
            let line = &sim.lines()[0];
            let share = line
                .model()
                .entrained_energy(&line.state().e, &line.state().v)
                / line.energies().kinetic;
            let mut worst = 0.0f64;
            for _ in 0..500 {
                sim.step().unwrap();
                worst = worst.max((system_energy(&sim) - e0).abs() / e0);
            }
            eprintln!("{element_type:?} {scheme:?}: T_a / T {share:.3}, |dE|/E {worst:.2e}");
            assert!(share > 0.3, "the water's share {share}");
            let bound = if scheme == TimeScheme::Galerkin {
                1e-10
            } else {
                1e-8
            };
            assert!(worst < bound, "{element_type:?} {scheme:?}: {worst:e}");
        }
    }
}
