//! Benchmark: one P2 step of a system of three 40-element lines meeting
//! at a free point (the bordered band LU, docs/method.md §11.3) against
//! one step of a single 120-element line (the band LU) of the same
//! rope, both under gravity with a moving end. The bound: the
//! system's step within 1.5x of the single line's. Report the ratio of
//! one run (the machine is shared).
//!
//! cargo bench -p stancf --bench systems

use criterion::{criterion_group, criterion_main, Criterion};
use stancf::constraints::Oscillation;
use stancf::system::{straight_states, End, Line, Point, System, SystemSimulation};
use stancf::{
    Cable, Constraint, ConstraintKind, ElementType, Load, Material, Model, ModelOptions,
    Simulation, StepSettings,
};

const G: [f64; 3] = [0.0, 0.0, -9.81];

fn rope() -> Material {
    Material {
        youngs_modulus: 1e7,
        density: 1000.0,
        area: 1e-5,
        second_moment: 1e-12,
    }
}

fn model(origin: [f64; 3], direction: [f64; 3], length: f64, elements: usize) -> Model {
    Model::new(
        Cable::straight(length, elements, ElementType::Sac2)
            .with_origin(origin)
            .with_direction(direction),
        rope(),
        ModelOptions::default(),
        vec![Load::Gravity { acceleration: G }],
    )
    .unwrap()
}

fn settings() -> StepSettings {
    StepSettings {
        time_step: 1e-4,
        ..StepSettings::default()
    }
}

const SWING: Oscillation = Oscillation {
    amplitude: [0.05, 0.0, 0.0],
    period: 0.5,
    phase: 0.0,
    ramp: 0.0,
};

/// Three 40-element lines from two fixed anchors and a swinging one to
/// a free point of 0.2 kg.
fn three_lines() -> SystemSimulation {
    let hub: [f64; 3] = [0.0, 0.0, -1.0];
    let anchors: [[f64; 3]; 3] = [[2.0, 0.0, 0.0], [-1.0, 1.7, 0.0], [-1.0, -1.7, 0.5]];
    let lines = anchors
        .iter()
        .enumerate()
        .map(|(i, a)| {
            let d = [hub[0] - a[0], hub[1] - a[1], hub[2] - a[2]];
            let length = (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).sqrt();
            Line {
                model: model(*a, d, length, 40),
                ends: [End::Point(i), End::Point(3)],
            }
        })
        .collect();
    let points = vec![
        Point::fixed(anchors[0]),
        Point::fixed(anchors[1]),
        Point::coupled(anchors[2], SWING),
        Point::free(hub, 0.2),
    ];
    let system = System::new(lines, points, G).unwrap();
    let start = straight_states(&system);
    SystemSimulation::new(system, start, settings()).unwrap()
}

/// One 120-element line of the same rope, pinned at one end and
/// swinging at the other.
fn one_line() -> Simulation {
    let m = model([0.0; 3], [1.0, 0.0, -0.3], 6.0, 120)
        .with_constraints(vec![
            Constraint {
                node: 0,
                kind: ConstraintKind::Pinned,
            },
            Constraint {
                node: 120,
                kind: ConstraintKind::Prescribed {
                    velocity: [0.0; 3],
                    amplitude: SWING.amplitude,
                    frequency: 1.0 / SWING.period,
                    phase: 0.0,
                },
            },
        ])
        .unwrap();
    let s = m.initial_state();
    Simulation::new(m, s, settings()).unwrap()
}

fn benches(c: &mut Criterion) {
    let mut g = c.benchmark_group("p2_step_120_elements");
    let mut system = three_lines();
    g.bench_function("three_lines_of_40_at_a_free_point", |b| {
        b.iter(|| system.step().unwrap())
    });
    let mut single = one_line();
    g.bench_function("one_line_of_120", |b| b.iter(|| single.step().unwrap()));
    g.finish();
}

criterion_group! {
    name = systems;
    config = Criterion::default().sample_size(30);
    targets = benches
}
criterion_main!(systems);
