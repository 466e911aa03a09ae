//! The step Jacobian of a system of cable lines, factorized and solved
//! two ways, per Newton iteration:
//!
//! - `BorderedLu` (stancf): a band LU per line, condensed onto the free
//!   points' unknowns with a dense Schur complement. Timed as Newton does
//!   it: copy the assembled matrix into the factors' storage, factorize
//!   in place, solve.
//! - faer's sparse LU: the symbolic analysis (COLAMD column ordering,
//!   elimination tree, supernode detection) done once per model, then per
//!   iteration the numeric factorization with partial pivoting and the
//!   solve, into one `NumericLu` and one scratch buffer reused from
//!   iteration to iteration. faer picks simplicial or supernodal from a
//!   flop estimate ("auto"); both are also forced.
//!
//! faer is given three sparsity patterns:
//! - "bordered structure": every entry `BorderedMatrix` stores (the full
//!   band of each line, its border columns and rows, the dense point
//!   block);
//! - "node pattern": what the assembly can fill, an unknown of node i
//!   coupled with those of nodes i - 1, i, i + 1 of its line, a free
//!   point's unknowns among themselves (built from the public
//!   `SlabLayout`; every Jacobian of the run is checked to lie inside);
//! - "observed nonzeros": the entries nonzero in any of 6 Jacobians of
//!   the first 30 steps. Tighter still but not usable: later Jacobians
//!   have nonzeros outside it (counted), so it is an optimistic bound.
//!
//! Then one full `SystemSimulation::step()` of the 3 x 40 system is timed
//! against one `Simulation::step()` of a single 120-element line.
//!
//! Each time is the median of many repetitions, the methods interleaved
//! round by round (the machine is shared). Sequential faer (`Par::Seq`),
//! as the band LU is sequential.
//!
//! cargo run --release --manifest-path bench/sparse-lu/Cargo.toml

mod case;
mod faer_lu;
mod patterns;
mod stats;
mod systems;

use stancf::system::{straight_states, SystemSimulation};
use stats::{median, micros};
use std::time::Instant;
use systems::{chain, one_line, one_line_system, settings, three_to_a_point, twelve_to_a_point};

fn run_steps(rounds: usize) {
    let s = settings();
    let system = three_to_a_point();
    let start = straight_states(&system);
    let mut sys = SystemSimulation::new(system, start, s).unwrap();
    let mut single = one_line(true);
    let system = one_line_system();
    let start = straight_states(&system);
    let mut sys_one = SystemSimulation::new(system, start, settings()).unwrap();
    println!(
        "\n== one step: 3 x 40 system ({} unknowns) against one 120-element line \
         ({} unknowns; planar reduction allowed, is_planar = {})",
        sys.unknowns_per_step(),
        single.unknowns_per_step(),
        single.is_planar()
    );
    let (mut t_sys, mut t_one, mut t_sys_one) = (Vec::new(), Vec::new(), Vec::new());
    let (mut it_sys, mut it_one) = (Vec::new(), Vec::new());
    let (mut f_sys, mut f_one) = (Vec::new(), Vec::new());
    for round in 0..rounds + 5 {
        let warm = round < 5;
        let t0 = Instant::now();
        let r = sys.step().unwrap();
        let a = micros(t0);
        let t0 = Instant::now();
        let q = single.step().unwrap();
        let b = micros(t0);
        let t0 = Instant::now();
        sys_one.step().unwrap();
        let c = micros(t0);
        if !warm {
            t_sys_one.push(c);
            t_sys.push(a);
            t_one.push(b);
            it_sys.push(r.newton.iterations as f64);
            it_one.push(q.newton.iterations as f64);
            f_sys.push(r.newton.factorizations as f64);
            f_one.push(q.newton.factorizations as f64);
        }
    }
    let (ms, mo) = (median(&mut t_sys), median(&mut t_one));
    println!(
        "   median of {rounds} steps (us): system {ms:.1} (median Newton iterations {}, \
         factorizations {}), single line {mo:.1} ({}, {})",
        median(&mut it_sys),
        median(&mut f_sys),
        median(&mut it_one),
        median(&mut f_one)
    );
    println!("   ratio system / single line: {:.2}", ms / mo);
    let m1 = median(&mut t_sys_one);
    println!(
        "   the same 120-element line stepped as a system of one line (no free point, {} unknowns): \
         {m1:.1} us, {:.2}x the single line; 3 x 40 system / this: {:.2}",
        sys_one.unknowns_per_step(),
        m1 / mo,
        ms / m1
    );
}

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let scale: usize = args
        .iter()
        .position(|a| a == "--rounds")
        .and_then(|i| args.get(i + 1))
        .and_then(|v| v.parse().ok())
        .unwrap_or(300);
    println!(
        "faer sparse LU (Par::Seq) against stancf::bordered::BorderedLu; times are medians of \
         interleaved repetitions"
    );
    case::run_case("3 x 40 to one free point", three_to_a_point(), scale);
    case::run_case("3 x 40 in a chain through two free points", chain(), scale);
    case::run_case("12 x 40 to one free point", twelve_to_a_point(), scale / 3);
    case::run_case(
        "1 x 120, no free point (one band, no border)",
        one_line_system(),
        scale,
    );
    run_steps(scale);
}
