//! A system without free points steps each line apart (docs/method.md
//! §11.14): each line as it would step alone, to the bit, whatever the
//! threads.

#[path = "common/rope_systems.rs"]
mod rope_systems;

use rope_systems::{line_model, G, SWING};
use stancf::system::{straight_states, End, Line, Point, System, SystemSimulation};
use stancf::{StepSettings, TimeScheme};

/// Line k of `lines` ropes of 12 elements from anchors on a circle to
/// swinging fairleads (no two lines alike: each has its own direction).
fn rope_line(k: usize, lines: usize) -> (Point, Point, stancf::Model) {
    let angle = 0.3 + 2.0 * std::f64::consts::PI * k as f64 / lines as f64;
    let (s, c) = angle.sin_cos();
    let anchor = [1.2 * c, 1.2 * s, -1.0];
    let fairlead = [0.1 * c, 0.1 * s, 0.0];
    (
        Point::fixed(anchor),
        Point::coupled(fairlead, SWING),
        line_model(anchor, fairlead, 12),
    )
}

/// The system of the lines `which` of [`rope_line`] out of `lines`.
fn ropes(which: &[usize], lines: usize) -> System {
    let mut points = Vec::new();
    let mut line_list = Vec::new();
    for (j, &k) in which.iter().enumerate() {
        let (anchor, fairlead, model) = rope_line(k, lines);
        points.extend([anchor, fairlead]);
        line_list.push(Line {
            model,
            ends: [End::Point(2 * j), End::Point(2 * j + 1)],
        });
    }
    System::new(line_list, points, G).unwrap()
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
    // 48 elements in all: on rayon's threads (PARALLEL_LINES_ELEMENTS).
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
