//! Benchmark: how a step's cost grows with the size of a system (issue
//! 15, "Scale"). One Galerkin step of 1, 3 and 12 lines of 100 SAC-2
//! elements each (anchored on a circle, their fairleads swinging, no line
//! in a coordinate plane) and of a single line of 10 000 elements, every
//! element 0.05 m of the same rope with the same sag per element. The
//! claim to read off one run: the time per element of the largest within
//! 1.2x of the smallest. Each configuration also prints its Newton
//! iterations per step (a cost per element that grows because Newton
//! needs more iterations is the physics, not the linear algebra).
//!
//! cargo bench --manifest-path bench/criterion/Cargo.toml --bench scale

use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion};
use stancf::system::{straight_states, End, Line, Point, System, SystemSimulation};
use stancf::{StepSettings, TimeScheme};

#[path = "../../../crates/stancf/tests/library/common/rope_systems.rs"]
mod rope_systems;
use rope_systems::{line_model, G, SWING};

/// Element length (m).
const ELEMENT: f64 = 0.05;

/// `lines` lines of `elements` elements: line k runs from an anchor at
/// angle 2 pi k / lines on a circle to a swinging fairlead above and
/// inside it, its chord 0.98 of its length (a slight sag).
fn lines_on_a_circle(lines: usize, elements: usize) -> System {
    let length = ELEMENT * elements as f64;
    // Chord along (0.8, 0.3, 0.52) of unit length, turned about z by the
    // line's angle plus a little, so no line lies in a coordinate plane.
    let along = {
        let v = [0.8f64, 0.3, 0.52];
        let n = (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt();
        v.map(|c| c / n)
    };
    let mut points = Vec::new();
    let mut line_list = Vec::new();
    for k in 0..lines {
        let angle = 0.1 + 2.0 * std::f64::consts::PI * k as f64 / lines as f64;
        let (s, c) = angle.sin_cos();
        let d = [
            c * along[0] - s * along[1],
            s * along[0] + c * along[1],
            along[2],
        ];
        let anchor = [-length * d[0], -length * d[1], -length * d[2]];
        let fairlead = anchor.map(|_| 0.0);
        let chord = 0.98;
        let fairlead: [f64; 3] =
            std::array::from_fn(|i| anchor[i] + chord * (fairlead[i] - anchor[i]));
        let model = line_model(anchor, fairlead, elements);
        points.push(Point::fixed(anchor));
        points.push(Point::coupled(fairlead, SWING));
        line_list.push(Line {
            model,
            ends: [End::Point(2 * k), End::Point(2 * k + 1)],
        });
    }
    System::new(line_list, points, G).unwrap()
}

/// Galerkin steps of 1 ms.
fn galerkin() -> StepSettings {
    StepSettings {
        time_step: 1e-3,
        time_scheme: TimeScheme::Galerkin,
        ..StepSettings::default()
    }
}

fn simulation(lines: usize, elements: usize) -> SystemSimulation {
    let system = lines_on_a_circle(lines, elements);
    let start = straight_states(&system);
    let mut sim = SystemSimulation::new(system, start, galerkin()).unwrap();
    // Past the first steps' transient from the straight start.
    for _ in 0..5 {
        sim.step().unwrap();
    }
    sim
}

fn benches(c: &mut Criterion) {
    let mut g = c.benchmark_group("galerkin_step_per_size");
    for (lines, elements) in [(1, 100), (3, 100), (12, 100), (1, 10_000)] {
        let mut sim = simulation(lines, elements);
        let steps = 10;
        let iterations: usize = (0..steps)
            .map(|_| sim.step().unwrap().newton.iterations)
            .sum();
        let per_step = iterations as f64 / steps as f64;
        eprintln!("{lines} x {elements} elements: {per_step:.2} Newton iterations per step");
        let id = BenchmarkId::from_parameter(format!("{lines}x{elements}"));
        g.bench_function(id, |b| b.iter(|| sim.step().unwrap()));
    }
    g.finish();
}

criterion_group! {
    name = scale;
    config = Criterion::default().sample_size(10);
    targets = benches
}
criterion_main!(scale);
