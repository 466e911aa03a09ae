//! One case: a system's step Jacobians, the patterns faer is given, the
//! accuracy of both solvers, their interleaved timings, and whether the
//! patterns hold later in the run.

use crate::faer_lu::{Csc, FaerLu};
use crate::patterns::{layout_of, node_pattern, outside, structure};
use crate::stats::{median, micros, norm, relative_residual, test_vector};
use crate::systems::settings;
use faer::sparse::linalg::SupernodalThreshold;
use stancf::bordered::{BorderedLu, BorderedMatrix};
use stancf::linear::{Factorization, Jacobian};
use stancf::system::{straight_states, System, SystemLayout, SystemSimulation};
use std::hint::black_box;
use std::time::Instant;

/// The three patterns of a case (see the crate's doc comment).
struct Patterns {
    full: Vec<Vec<usize>>,
    nodes: Vec<Vec<usize>>,
    tight: Vec<Vec<usize>>,
}

impl Patterns {
    /// The patterns of `layout`, the observed one from `jacobians`;
    /// checks every Jacobian lies inside the node pattern and (when
    /// small enough for a dense scan) the bordered structure.
    fn of(layout: &SystemLayout, jacobians: &[BorderedMatrix]) -> Self {
        let full = structure(layout);
        let tight = full
            .iter()
            .enumerate()
            .map(|(c, rows)| {
                rows.iter()
                    .copied()
                    .filter(|&r| jacobians.iter().any(|j| j.get(r, c) != 0.0))
                    .collect()
            })
            .collect();
        let nodes = node_pattern(layout);
        for j in jacobians {
            assert_eq!(
                outside(j, &nodes, &full),
                0,
                "nonzeros outside the node pattern"
            );
        }
        let jac = jacobians.last().expect("a Jacobian");
        let n = jac.size();
        if n <= 2500 {
            let mut count = 0;
            for (c, rows) in full.iter().enumerate() {
                count += (0..n)
                    .filter(|r| rows.binary_search(r).is_err() && jac.get(*r, c) != 0.0)
                    .count();
            }
            assert_eq!(count, 0, "entries outside the bordered structure");
        }
        Patterns { full, nodes, tight }
    }

    /// The bandwidths the observed nonzeros of the lines' blocks reach.
    fn used_bandwidths(&self, border_start: usize) -> (usize, usize) {
        let (mut kl, mut ku) = (0usize, 0usize);
        for (c, rows) in self.tight.iter().enumerate().take(border_start) {
            for &r in rows.iter().filter(|&&r| r < border_start) {
                if r > c {
                    kl = kl.max(r - c);
                } else {
                    ku = ku.max(c - r);
                }
            }
        }
        (kl, ku)
    }
}

/// Prints the size, the first line's band and the patterns' densities.
fn describe(name: &str, layout: &SystemLayout, p: &Patterns, iterations: &mut [f64]) {
    let n = layout.size;
    let per_row = |cols: &[Vec<usize>]| {
        let nnz: usize = cols.iter().map(Vec::len).sum();
        (nnz, nnz as f64 / n as f64)
    };
    let sh = &layout.shapes[0];
    println!(
        "\n== {name}: N = {n} unknowns, {} lines (n_i {} kl {} ku {} k_i {}), border nb = {}",
        layout.shapes.len(),
        sh.size,
        sh.kl,
        sh.ku,
        sh.border.len(),
        layout.border
    );
    let (kl, ku) = p.used_bandwidths(layout.border_start());
    let (full, nodes, tight) = (per_row(&p.full), per_row(&p.nodes), per_row(&p.tight));
    println!(
        "   nnz: bordered structure {} ({:.1} per row), node pattern {} ({:.1} per row), \
         observed nonzeros (6 Jacobians to step 30) {} ({:.1} per row); \
         the blocks' observed nonzeros reach kl {kl} ku {ku}; \
         Newton iterations per step (median of the warm-up) {}",
        full.0,
        full.1,
        nodes.0,
        nodes.1,
        tight.0,
        tight.1,
        median(iterations)
    );
}

/// A faer variant: its label, its matrix, its factors and the time its
/// symbolic analysis took (us).
struct Variant {
    label: &'static str,
    matrix: Csc,
    lu: FaerLu,
    symbolic_us: f64,
}

/// faer on each pattern and each choice of simplicial or supernodal.
fn faer_variants(p: &Patterns, jac: &BorderedMatrix) -> Vec<Variant> {
    use SupernodalThreshold as S;
    let cases: [(&'static str, &Vec<Vec<usize>>, S); 6] = [
        ("faer auto, bordered structure", &p.full, S::AUTO),
        ("faer auto, node pattern", &p.nodes, S::AUTO),
        (
            "faer simplicial, node pattern",
            &p.nodes,
            S::FORCE_SIMPLICIAL,
        ),
        (
            "faer supernodal, node pattern",
            &p.nodes,
            S::FORCE_SUPERNODAL,
        ),
        // Optimistic: this pattern misses entries that fill in later in
        // the run (counted at the end), so it could not be used as it is.
        ("faer auto, observed nonzeros", &p.tight, S::AUTO),
        (
            "faer supernodal, observed nonzeros",
            &p.tight,
            S::FORCE_SUPERNODAL,
        ),
    ];
    cases
        .into_iter()
        .map(|(label, cols, threshold)| {
            let mut matrix = Csc::new(cols);
            matrix.fill_from(jac);
            let t0 = Instant::now();
            let lu = FaerLu::new(&matrix, threshold);
            Variant {
                label,
                matrix,
                lu,
                symbolic_us: micros(t0),
            }
        })
        .collect()
}

/// Both solvers' residuals and errors against a known solution, once;
/// the dense condition number when small enough.
fn check_accuracy(jac: &BorderedMatrix, bordered: &mut BorderedLu, variants: &mut [Variant]) {
    let n = jac.size();
    let x_true = test_vector(n);
    let mut b = vec![0.0; n];
    jac.mul_vec(&x_true, &mut b);
    let relative = |x: &[f64], y: &[f64]| {
        let d: Vec<f64> = x.iter().zip(y).map(|(p, q)| p - q).collect();
        norm(&d) / norm(y)
    };
    let mut x_b = b.clone();
    bordered.matrix_mut().copy_from(jac);
    bordered.factorize().unwrap();
    bordered.solve(&mut x_b);
    let res_b = relative_residual(jac, &x_b, &b);
    if n <= 2000 {
        let dense = faer::Mat::<f64>::from_fn(n, n, |i, j| jac.get(i, j));
        let sv = dense.as_ref().singular_values().unwrap();
        println!(
            "   2-norm condition number (dense SVD): {:.2e} (sigma_max {:.2e}, sigma_min {:.2e})",
            sv[0] / sv[n - 1],
            sv[0],
            sv[n - 1]
        );
    }
    assert!(res_b < 1e-12, "BorderedLu: residual {res_b:e}");
    println!(
        "   BorderedLu: ||Ax-b||/||b|| = {res_b:.2e}, ||x-x_true||/||x_true|| = {:.2e}",
        relative(&x_b, &x_true)
    );
    for v in variants.iter_mut() {
        let mut x_f = b.clone();
        v.lu.factorize_solve(&v.matrix, &mut x_f);
        let res_f = relative_residual(jac, &x_f, &b);
        println!(
            "   {}: ||Ax-b||/||b|| = {res_f:.2e}, ||x-x_true||/||x_true|| = {:.2e}, \
             ||x_faer - x_bordered||/||x_bordered|| = {:.2e}",
            v.label,
            relative(&x_f, &x_true),
            relative(&x_f, &x_b)
        );
        // Both are backward stable; the forward difference is bounded by
        // cond(A) times that (see the condition number printed above).
        assert!(res_f < 1e-12, "{}: residual {res_f:e}", v.label);
    }
}

/// Copy + factorize + solve of BorderedLu and numeric factorize + solve
/// of every faer variant, interleaved round by round (5 warm-up rounds);
/// prints the medians.
fn time_methods(
    jac: &BorderedMatrix,
    bordered: &mut BorderedLu,
    variants: &mut [Variant],
    rounds: usize,
) {
    let b = test_vector(jac.size());
    let (mut t_copy, mut t_all) = (Vec::with_capacity(rounds), Vec::with_capacity(rounds));
    let mut t_faer: Vec<Vec<f64>> = vec![Vec::with_capacity(rounds); variants.len()];
    let mut rhs = b.clone();
    for round in 0..rounds + 5 {
        let warm = round < 5;
        rhs.copy_from_slice(&b);
        let t0 = Instant::now();
        bordered.matrix_mut().copy_from(jac);
        let copy = micros(t0);
        bordered.factorize().unwrap();
        bordered.solve(&mut rhs);
        let all = micros(t0);
        black_box(&rhs);
        if !warm {
            t_copy.push(copy);
            t_all.push(all);
        }
        for (k, v) in variants.iter_mut().enumerate() {
            rhs.copy_from_slice(&b);
            let t0 = Instant::now();
            v.lu.factorize_solve(&v.matrix, &mut rhs);
            let t = micros(t0);
            black_box(&rhs);
            if !warm {
                t_faer[k].push(t);
            }
        }
    }
    let (m_b, m_copy) = (median(&mut t_all), median(&mut t_copy));
    println!(
        "   median of {rounds} (us): BorderedLu copy+factorize+solve {m_b:.1} \
         (copy {m_copy:.1}, factorize+solve {:.1})",
        m_b - m_copy
    );
    for (v, times) in variants.iter().zip(&mut t_faer) {
        let m = median(times);
        println!(
            "   median of {rounds} (us): {}: numeric factorize+solve {m:.1} = {:.2}x BorderedLu \
             (symbolic analysis once: {:.0} us)",
            v.label,
            m / m_b,
            v.symbolic_us
        );
    }
}

/// faer's symbolic analysis is done once: its pattern must hold for the
/// rest of the run. The node pattern does by construction; the nonzeros
/// observed in the first steps do not. Counts over 4 later Jacobians.
fn later_escapes(sim: &mut SystemSimulation, p: &Patterns) {
    let (mut nodes, mut observed) = (0, 0);
    for _ in 0..4 {
        for _ in 0..25 {
            sim.step().unwrap();
        }
        let later = sim.next_step_jacobian().0;
        nodes += outside(&later, &p.nodes, &p.full);
        observed += outside(&later, &p.tight, &p.full);
    }
    println!(
        "   nonzeros of 4 later Jacobians (to step 130) outside the node pattern: {nodes}; \
         outside the nonzeros observed in the first 30 steps: {observed}"
    );
    assert_eq!(nodes, 0);
}

/// One case: 30 warm-up steps (a Jacobian every 5th), then the patterns,
/// the accuracy, the timings of the last Jacobian and the later check.
pub fn run_case(name: &str, system: System, rounds: usize) {
    let s = settings();
    let start = straight_states(&system);
    let mut sim =
        SystemSimulation::new(system, start, s.clone()).unwrap_or_else(|e| panic!("{name}: {e:?}"));
    let layout = layout_of(&sim, &s);
    assert_eq!(
        layout.size,
        sim.unknowns_per_step(),
        "layout rebuilt differently"
    );
    let mut jacobians = Vec::new();
    let mut iterations = Vec::new();
    for _ in 0..6 {
        for _ in 0..5 {
            iterations.push(sim.step().unwrap().newton.iterations as f64);
        }
        jacobians.push(sim.next_step_jacobian().0);
    }
    let jac = jacobians.last().expect("a Jacobian");
    assert_eq!(jac.size(), layout.size);
    let patterns = Patterns::of(&layout, &jacobians);
    describe(name, &layout, &patterns, &mut iterations);
    let mut bordered = BorderedLu::new(&layout.shapes, layout.border);
    let mut variants = faer_variants(&patterns, jac);
    check_accuracy(jac, &mut bordered, &mut variants);
    time_methods(jac, &mut bordered, &mut variants, rounds);
    later_escapes(&mut sim, &patterns);
}
