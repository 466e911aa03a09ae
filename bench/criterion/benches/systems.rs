//! Benchmark: one P2 step of a system of three 40-element lines meeting
//! at a free point (the bordered band LU, docs/method.md §11.3) against
//! one step of a single 120-element line (the band LU) of the same
//! rope, both under gravity with a moving end. The single line lies out
//! of every coordinate plane, as the system's lines do, so both
//! Jacobians have the same nonzeros per unknown (`one_line_end`). The
//! issue's bound: the system's step within 1.5x of the single line's.
//! Report the ratio of one run (the machine is shared).
//!
//! cargo bench --manifest-path bench/criterion/Cargo.toml --bench systems

use criterion::{criterion_group, criterion_main, Criterion};
use stancf::system::{straight_states, SystemSimulation};

#[path = "../../../crates/stancf/tests/library/common/rope_systems.rs"]
mod rope_systems;
use rope_systems::{one_line, settings, three_to_a_point};

/// Three 40-element lines from two fixed anchors and a swinging one to
/// a free point of 0.2 kg.
fn three_lines() -> SystemSimulation {
    let system = three_to_a_point(40);
    let start = straight_states(&system);
    SystemSimulation::new(system, start, settings()).unwrap()
}

fn benches(c: &mut Criterion) {
    let mut g = c.benchmark_group("p2_step_120_elements");
    let mut system = three_lines();
    g.bench_function("three_lines_of_40_at_a_free_point", |b| {
        b.iter(|| system.step().unwrap())
    });
    let mut single = one_line(false);
    g.bench_function("one_line_of_120", |b| b.iter(|| single.step().unwrap()));
    g.finish();
}

criterion_group! {
    name = systems;
    config = Criterion::default().sample_size(30);
    targets = benches
}
criterion_main!(systems);
