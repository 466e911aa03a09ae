//! A system without free points steps each line apart (docs/method.md
//! §11.14): each line as it would step alone, to the bit, whatever the
//! threads.

use crate::common::rope_systems::independent_ropes;
use stancf::system::{straight_states, System, SystemSimulation};
use stancf::{StepSettings, TimeScheme};

/// The ropes `which` of `lines` independent ropes of 12 elements.
fn ropes(which: &[usize], lines: usize) -> System {
    independent_ropes(which, lines, 12)
}

/// 30 Galerkin steps of 2 ms from the straight lines (the ropes sag and
/// swing: Newton works every step); each line's final state.
fn stepped(system: System) -> Vec<stancf::State> {
    let start = straight_states(&system);
    let settings = StepSettings {
        time_step: 2e-3,
        time_scheme: TimeScheme::Galerkin,
        ..StepSettings::default()
    };
    let mut sim = SystemSimulation::new(system, start, settings).unwrap();
    for _ in 0..30 {
        sim.step().unwrap();
    }
    sim.lines().iter().map(|l| l.state().clone()).collect()
}

#[test]
fn independent_lines_step_each_as_it_would_alone() {
    // 48 elements in all: on rayon's threads (PARALLEL_LINES_WORK at 2
    // iterations a step).
    let together = stepped(ropes(&[0, 1, 2, 3], 4));
    for (k, line) in together.iter().enumerate() {
        let alone = stepped(ropes(&[k], 4));
        assert_eq!(line.e, alone[0].e, "line {k}: positions");
        assert_eq!(line.v, alone[0].v, "line {k}: velocities");
    }
    // The lines do move: a test of nothing would pass as well.
    let start = straight_states(&ropes(&[0, 1, 2, 3], 4));
    assert!(together[0]
        .e
        .iter()
        .zip(&start[0].e)
        .any(|(a, b)| (a - b).abs() > 1e-3));
}

#[test]
fn the_threads_do_not_change_a_step() {
    let on = |threads: usize| {
        rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .unwrap()
            .install(|| stepped(ropes(&[0, 1, 2, 3], 4)))
    };
    let (one, two) = (on(1), on(2));
    for (a, b) in one.iter().zip(&two) {
        assert_eq!(a.e, b.e);
        assert_eq!(a.v, b.v);
    }
}

/// One step of `sim` halved by hand (docs/method.md §11.13): from a clone
/// of the last converged state, two halves, each halved again if it
/// fails, `levels` deep; counts the failed attempts in `failed`.
fn halved_by_hand(sim: &mut SystemSimulation, levels: u32, failed: &mut usize) -> bool {
    let saved = sim.clone();
    if sim.step().is_ok() {
        return true;
    }
    if levels == 0 {
        return false;
    }
    *failed += 1;
    *sim = saved;
    let dt = sim.time_step();
    sim.set_time_step(0.5 * dt);
    let done = halved_by_hand(sim, levels - 1, failed) && halved_by_hand(sim, levels - 1, failed);
    sim.set_time_step(dt);
    done
}

/// A step that Newton fails is taken again in halves from the last
/// converged state of every line: with the lines solved apart, the
/// system's own halving gives the bits of halving by hand from a clone
/// (a failed attempt leaves nothing behind, the lines' multipliers
/// included), over steps long enough and iteration limits short enough
/// that Newton fails some.
#[test]
fn a_halved_step_starts_from_the_last_converged_state() {
    let mut halvings = 0;
    for scheme in [TimeScheme::P2, TimeScheme::Galerkin] {
        for (dt, max_iterations) in [(5e-3, 3), (1e-2, 4), (2e-2, 6)] {
            let mut settings = StepSettings {
                time_step: dt,
                time_scheme: scheme,
                ..StepSettings::default()
            };
            settings.newton.max_iterations = max_iterations;
            let system = ropes(&[0, 1], 2);
            let start = straight_states(&system);
            let mut own =
                SystemSimulation::new(system.clone(), start.clone(), settings.clone()).unwrap();
            own.set_step_halvings(3).unwrap();
            let mut by_hand = SystemSimulation::new(system, start, settings).unwrap();
            // Halved here by hand, one level at a time.
            by_hand.set_step_halvings(0).unwrap();
            for _ in 0..(0.2 / dt) as usize {
                let a = own.step().is_ok();
                let b = halved_by_hand(&mut by_hand, 3, &mut halvings);
                assert_eq!(a, b, "{scheme:?} dt {dt}: one failed, the other did not");
                if !a {
                    break;
                }
            }
            for (a, b) in own.lines().iter().zip(by_hand.lines()) {
                assert_eq!(a.state().e, b.state().e, "{scheme:?} dt {dt}");
                assert_eq!(a.state().v, b.state().v, "{scheme:?} dt {dt}");
            }
        }
    }
    assert!(halvings > 0, "no step was halved: the test checks nothing");
}
