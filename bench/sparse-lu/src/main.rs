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

use std::hint::black_box;
use std::time::Instant;

use faer::dyn_stack::{MemBuffer, MemStack, StackReq};
use faer::sparse::linalg::lu::{factorize_symbolic_lu, LuSymbolicParams, NumericLu, SymbolicLu};
use faer::sparse::linalg::SupernodalThreshold;
use faer::sparse::{SparseColMatRef, SymbolicSparseColMatRef};
use faer::{Conj, MatMut, Par};

use stancf::assembly::Scheme;
use stancf::bordered::{BorderedLu, BorderedMatrix};
use stancf::constraints::Oscillation;
use stancf::linear::{Factorization, Jacobian};
use stancf::system::{straight_states, End, Line, Point, System, SystemLayout, SystemSimulation};
use stancf::{
    Cable, Constraint, ConstraintKind, ElementType, Load, Material, Model, ModelOptions,
    Simulation, StepSettings, TimeScheme,
};

const G: [f64; 3] = [0.0, 0.0, -9.81];

const SWING: Oscillation = Oscillation {
    amplitude: [0.05, 0.0, 0.0],
    period: 0.5,
    phase: 0.0,
    ramp: 0.0,
};

fn rope() -> Material {
    Material {
        youngs_modulus: 1e7,
        density: 1000.0,
        area: 1e-5,
        second_moment: 1e-12,
    }
}

fn settings() -> StepSettings {
    StepSettings {
        time_step: 1e-4,
        ..StepSettings::default()
    }
}

fn line_model(a: [f64; 3], b: [f64; 3], elements: usize) -> Model {
    let d = [b[0] - a[0], b[1] - a[1], b[2] - a[2]];
    let length = (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).sqrt();
    Model::new(
        Cable::straight(length, elements, ElementType::Sac2)
            .with_origin(a)
            .with_direction(d),
        rope(),
        ModelOptions::default(),
        vec![Load::Gravity { acceleration: G }],
    )
    .unwrap()
}

/// `anchors.len()` lines of `elements` elements from one free point of
/// 0.2 kg to the anchors (the first swinging, the others fixed). The
/// lines start at the free point, so their first nodes coincide there
/// exactly (the system checks that they do).
fn star(anchors: &[[f64; 3]], elements: usize) -> System {
    let hub: [f64; 3] = [0.0, 0.0, -1.0];
    let k = anchors.len();
    let lines = anchors
        .iter()
        .enumerate()
        .map(|(i, a)| Line {
            model: line_model(hub, *a, elements),
            ends: [End::Point(k), End::Point(i)],
        })
        .collect();
    let mut points: Vec<Point> = anchors
        .iter()
        .enumerate()
        .map(|(i, a)| {
            if i == 0 {
                Point::coupled(*a, SWING)
            } else {
                Point::fixed(*a)
            }
        })
        .collect();
    points.push(Point::free(hub, 0.2));
    System::new(lines, points, G).unwrap()
}

/// The 3 x 40 system of `crates/stancf/benches/systems.rs`: two fixed
/// anchors and a swinging one, to a free point.
fn three_to_a_point() -> System {
    let hub: [f64; 3] = [0.0, 0.0, -1.0];
    let anchors: [[f64; 3]; 3] = [[2.0, 0.0, 0.0], [-1.0, 1.7, 0.0], [-1.0, -1.7, 0.5]];
    let lines = anchors
        .iter()
        .enumerate()
        .map(|(i, a)| Line {
            model: line_model(*a, hub, 40),
            ends: [End::Point(i), End::Point(3)],
        })
        .collect();
    let points = vec![
        Point::fixed(anchors[0]),
        Point::fixed(anchors[1]),
        Point::coupled(anchors[2], SWING),
        Point::free(hub, 0.2),
    ];
    System::new(lines, points, G).unwrap()
}

/// anchor - line - free point - line - free point - line - swinging anchor.
fn chain() -> System {
    let p: [[f64; 3]; 4] = [
        [0.0, 0.0, 0.0],
        [2.0, 0.4, -0.8],
        [4.0, -0.4, -0.8],
        [6.0, 0.0, 0.0],
    ];
    let lines = (0..3)
        .map(|i| Line {
            model: line_model(p[i], p[i + 1], 40),
            ends: [End::Point(i), End::Point(i + 1)],
        })
        .collect();
    let points = vec![
        Point::fixed(p[0]),
        Point::free(p[1], 0.2),
        Point::free(p[2], 0.2),
        Point::coupled(p[3], SWING),
    ];
    System::new(lines, points, G).unwrap()
}

/// The single 120-element line as a system: one line from a fixed point
/// to a swinging one, no free point (no border).
fn one_line_system() -> System {
    let a = [0.0; 3];
    let b = [6.0 / 1.044, 0.0, -1.8 / 1.044];
    let lines = vec![Line {
        model: line_model(a, b, 120),
        ends: [End::Point(0), End::Point(1)],
    }];
    let points = vec![Point::fixed(a), Point::coupled(b, SWING)];
    System::new(lines, points, G).unwrap()
}

fn twelve_to_a_point() -> System {
    let anchors: Vec<[f64; 3]> = (0..12)
        .map(|k| {
            let a = k as f64 * std::f64::consts::TAU / 12.0;
            [2.0 * a.cos(), 2.0 * a.sin(), 0.1 * (k % 3) as f64]
        })
        .collect();
    star(&anchors, 40)
}

/// One 120-element line of the same rope, pinned at one end and swinging
/// at the other (as in `crates/stancf/benches/systems.rs`).
fn one_line(planar_reduction: bool) -> Simulation {
    let m = line_model([0.0; 3], [6.0 / 1.044, 0.0, -1.8 / 1.044], 120)
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
    Simulation::new(
        m,
        s,
        StepSettings {
            planar_reduction,
            ..settings()
        },
    )
    .unwrap()
}

/// The layout the simulation numbers its step with, rebuilt through the
/// public API (the simulation keeps its own private).
fn layout_of(sim: &SystemSimulation, s: &StepSettings) -> SystemLayout {
    let models: Vec<&Model> = sim.lines().iter().map(|l| l.model()).collect();
    let scheme = match s.time_scheme {
        TimeScheme::P2 => Scheme::P2 {
            layers: s.time_layers,
        },
        TimeScheme::Galerkin => Scheme::Galerkin,
    };
    SystemLayout::new(sim.system(), &models, scheme, s.constraint_method)
}

/// The bordered structure, column by column (sorted rows).
fn structure(layout: &SystemLayout) -> Vec<Vec<usize>> {
    let bs = layout.border_start();
    let nb = layout.border;
    let mut cols: Vec<Vec<usize>> = vec![Vec::new(); layout.size];
    let mut start = 0;
    for shape in &layout.shapes {
        let n = shape.size;
        let (kl, ku) = (shape.kl.min(n - 1), shape.ku.min(n - 1));
        for c in 0..n {
            for r in c.saturating_sub(ku)..=(c + kl).min(n - 1) {
                cols[start + c].push(start + r);
            }
            for &g in &shape.border {
                cols[start + c].push(bs + g);
            }
        }
        for &g in &shape.border {
            cols[bs + g].extend(start..start + n);
        }
        start += n;
    }
    assert_eq!(start, bs);
    for g in 0..nb {
        cols[bs + g].extend(bs..bs + nb);
    }
    for c in &mut cols {
        c.sort_unstable();
        c.dedup();
    }
    cols
}

/// The pattern the element assembly can fill: within a line, an unknown
/// of node i couples only with the unknowns of nodes i - 1, i, i + 1
/// (SAC-2 elements join two nodes; multipliers and constraint rows sit in
/// their node's block); a free point's unknowns couple among themselves.
/// Column by column, sorted rows, in the global numbering. Built from the
/// public `SlabLayout` (node n's block starts at its first unknown).
fn node_pattern(layout: &SystemLayout) -> Vec<Vec<usize>> {
    let mut cols: Vec<Vec<usize>> = vec![Vec::new(); layout.size];
    for (slab, map) in layout.lines.iter().zip(&layout.maps) {
        let slots = slab.unknown_slots.len();
        let mut starts: Vec<usize> = (0..slab.nodes)
            .map(|n| {
                (0..slots)
                    .flat_map(|s| (0..slab.dpn).map(move |d| (s, d)))
                    .filter_map(|(s, d)| slab.unknown_of_node(s, n, d))
                    .min()
                    .expect("every node keeps an unknown")
            })
            .collect();
        starts.push(slab.size());
        assert!(
            starts.windows(2).all(|w| w[0] < w[1]),
            "node blocks in order"
        );
        for n in 0..slab.nodes {
            for m in n.saturating_sub(1)..=(n + 1).min(slab.nodes - 1) {
                for c in starts[m]..starts[m + 1] {
                    for r in starts[n]..starts[n + 1] {
                        cols[map.global[c]].push(map.global[r]);
                    }
                }
            }
        }
    }
    let bs = layout.border_start();
    for base in layout.point_base.iter().flatten() {
        let group = bs + base..bs + base + 3 * layout.slots;
        for c in group.clone() {
            cols[c].extend(group.clone());
        }
    }
    for c in &mut cols {
        c.sort_unstable();
        c.dedup();
    }
    cols
}

/// Entries of `j` that are nonzero outside `pattern`.
fn outside(j: &BorderedMatrix, pattern: &[Vec<usize>], structure: &[Vec<usize>]) -> usize {
    let mut count = 0;
    for (c, rows) in structure.iter().enumerate() {
        for &r in rows {
            if j.get(r, c) != 0.0 && pattern[c].binary_search(&r).is_err() {
                count += 1;
            }
        }
    }
    count
}

/// A matrix in faer's compressed columns, its values taken from `j`.
struct Csc {
    n: usize,
    col_ptr: Vec<usize>,
    row_idx: Vec<usize>,
    values: Vec<f64>,
}

impl Csc {
    fn new(cols: &[Vec<usize>]) -> Self {
        let mut col_ptr = vec![0];
        let mut row_idx = Vec::new();
        for c in cols {
            row_idx.extend_from_slice(c);
            col_ptr.push(row_idx.len());
        }
        let nnz = row_idx.len();
        Csc {
            n: cols.len(),
            col_ptr,
            row_idx,
            values: vec![0.0; nnz],
        }
    }

    fn fill_from(&mut self, j: &BorderedMatrix) {
        for c in 0..self.n {
            for k in self.col_ptr[c]..self.col_ptr[c + 1] {
                self.values[k] = j.get(self.row_idx[k], c);
            }
        }
    }

    fn symbolic(&self) -> SymbolicSparseColMatRef<'_, usize> {
        SymbolicSparseColMatRef::new_checked(self.n, self.n, &self.col_ptr, None, &self.row_idx)
    }

    fn matrix(&self) -> SparseColMatRef<'_, usize, f64> {
        SparseColMatRef::new(self.symbolic(), &self.values)
    }

    fn nnz(&self) -> usize {
        self.row_idx.len()
    }
}

/// faer's sparse LU with its symbolic analysis done once and everything
/// the numeric factorization and the solve need allocated up front.
struct FaerLu {
    symbolic: SymbolicLu<usize>,
    numeric: NumericLu<usize, f64>,
    buffer: MemBuffer,
}

impl FaerLu {
    fn new(a: &Csc, threshold: SupernodalThreshold) -> Self {
        let params = LuSymbolicParams {
            supernodal_flop_ratio_threshold: threshold,
            ..Default::default()
        };
        let symbolic = factorize_symbolic_lu(a.symbolic(), params).unwrap();
        let req = StackReq::any_of(&[
            symbolic.factorize_numeric_lu_scratch::<f64>(Par::Seq, Default::default()),
            symbolic.solve_in_place_scratch::<f64>(1, Par::Seq),
        ]);
        FaerLu {
            symbolic,
            numeric: NumericLu::new(),
            buffer: MemBuffer::new(req),
        }
    }

    /// Numeric factorization of `a` (same pattern as the symbolic) and
    /// the solve of a x = b in place.
    fn factorize_solve(&mut self, a: &Csc, b: &mut [f64]) {
        let stack = MemStack::new(&mut self.buffer);
        let lu = self
            .symbolic
            .factorize_numeric_lu(
                &mut self.numeric,
                a.matrix(),
                Par::Seq,
                stack,
                Default::default(),
            )
            .unwrap();
        let n = b.len();
        lu.solve_in_place_with_conj(
            Conj::No,
            MatMut::from_column_major_slice_mut(b, n, 1),
            Par::Seq,
            stack,
        );
    }
}

fn median(v: &mut [f64]) -> f64 {
    v.sort_by(|a, b| a.partial_cmp(b).unwrap());
    let n = v.len();
    if n % 2 == 1 {
        v[n / 2]
    } else {
        0.5 * (v[n / 2 - 1] + v[n / 2])
    }
}

fn micros(t: Instant) -> f64 {
    t.elapsed().as_secs_f64() * 1e6
}

fn norm(v: &[f64]) -> f64 {
    v.iter().map(|x| x * x).sum::<f64>().sqrt()
}

fn relative_residual(j: &BorderedMatrix, x: &[f64], b: &[f64]) -> f64 {
    let mut ax = vec![0.0; b.len()];
    j.mul_vec(x, &mut ax);
    let r: Vec<f64> = ax.iter().zip(b).map(|(p, q)| p - q).collect();
    norm(&r) / norm(b)
}

/// A deterministic pseudo-random vector in [-1, 1].
fn test_vector(n: usize) -> Vec<f64> {
    let mut s: u64 = 0x2545_f491_4f6c_dd1d;
    (0..n)
        .map(|_| {
            s ^= s << 13;
            s ^= s >> 7;
            s ^= s << 17;
            (s >> 11) as f64 / (1u64 << 53) as f64 * 2.0 - 1.0
        })
        .collect()
}

fn run_case(name: &str, system: System, rounds: usize) {
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

    // A few Jacobians along the run: their union of nonzeros is faer's
    // tight pattern; the last one is timed.
    let mut jacobians = Vec::new();
    let mut iterations = Vec::new();
    for _ in 0..6 {
        for _ in 0..5 {
            iterations.push(sim.step().unwrap().newton.iterations as f64);
        }
        jacobians.push(sim.next_step_jacobian().0);
    }
    let jac = jacobians.last().unwrap();
    let n = jac.size();
    assert_eq!(n, layout.size);

    let full = structure(&layout);
    let tight: Vec<Vec<usize>> = full
        .iter()
        .enumerate()
        .map(|(c, rows)| {
            rows.iter()
                .copied()
                .filter(|&r| jacobians.iter().any(|j| j.get(r, c) != 0.0))
                .collect()
        })
        .collect();
    // faer's pattern: the node blocks the assembly can fill. Every
    // Jacobian's nonzeros must lie inside.
    let nodes = node_pattern(&layout);
    for j in &jacobians {
        assert_eq!(
            outside(j, &nodes, &full),
            0,
            "nonzeros outside the node pattern"
        );
    }
    let mut a_full = Csc::new(&full);
    a_full.fill_from(jac);
    let mut a_nodes = Csc::new(&nodes);
    a_nodes.fill_from(jac);
    let mut a_tight = Csc::new(&tight);
    a_tight.fill_from(jac);
    let tight_nnz = a_tight.nnz();
    // Nothing outside the bordered structure (a dense scan when small).
    if n <= 2500 {
        let mut outside = 0;
        for c in 0..n {
            let rows = &full[c];
            for r in 0..n {
                if rows.binary_search(&r).is_err() && jac.get(r, c) != 0.0 {
                    outside += 1;
                }
            }
        }
        assert_eq!(outside, 0, "entries outside the bordered structure");
    }

    // The bandwidths the nonzeros of the blocks actually reach.
    let (mut kl_used, mut ku_used) = (0usize, 0usize);
    {
        let bs = layout.border_start();
        for (c, rows) in tight.iter().enumerate().take(bs) {
            for &r in rows.iter().filter(|&&r| r < bs) {
                if r > c {
                    kl_used = kl_used.max(r - c);
                } else {
                    ku_used = ku_used.max(c - r);
                }
            }
        }
    }
    let band: Vec<String> = layout
        .shapes
        .iter()
        .take(1)
        .map(|sh| {
            format!(
                "n_i {} kl {} ku {} k_i {}",
                sh.size,
                sh.kl,
                sh.ku,
                sh.border.len()
            )
        })
        .collect();
    println!(
        "\n== {name}: N = {n} unknowns, {} lines ({}), border nb = {}",
        layout.shapes.len(),
        band.join(""),
        layout.border
    );
    println!(
        "   nnz: bordered structure {} ({:.1} per row), node pattern {} ({:.1} per row), \
         observed nonzeros (6 Jacobians to step 30) {} ({:.1} per row); \
         the blocks' observed nonzeros reach kl {kl_used} ku {ku_used}; \
         Newton iterations per step (median of the warm-up) {}",
        a_full.nnz(),
        a_full.nnz() as f64 / n as f64,
        a_nodes.nnz(),
        a_nodes.nnz() as f64 / n as f64,
        tight_nnz,
        tight_nnz as f64 / n as f64,
        median(&mut iterations)
    );

    let x_true = test_vector(n);
    let mut b = vec![0.0; n];
    jac.mul_vec(&x_true, &mut b);

    let mut bordered = BorderedLu::new(&layout.shapes, layout.border);
    let mut faer_variants: Vec<(&str, &Csc, FaerLu)> = Vec::new();
    let mut symbolic_us = Vec::new();
    for (label, a, th) in [
        (
            "faer auto, bordered structure",
            &a_full,
            SupernodalThreshold::AUTO,
        ),
        (
            "faer auto, node pattern",
            &a_nodes,
            SupernodalThreshold::AUTO,
        ),
        (
            "faer simplicial, node pattern",
            &a_nodes,
            SupernodalThreshold::FORCE_SIMPLICIAL,
        ),
        (
            "faer supernodal, node pattern",
            &a_nodes,
            SupernodalThreshold::FORCE_SUPERNODAL,
        ),
        // Optimistic: this pattern misses entries that fill in later in
        // the run (counted below), so it could not be used as it is.
        (
            "faer auto, observed nonzeros",
            &a_tight,
            SupernodalThreshold::AUTO,
        ),
        (
            "faer supernodal, observed nonzeros",
            &a_tight,
            SupernodalThreshold::FORCE_SUPERNODAL,
        ),
    ] {
        let t0 = Instant::now();
        let lu = FaerLu::new(a, th);
        symbolic_us.push((label, micros(t0)));
        faer_variants.push((label, a, lu));
    }

    // Accuracy, once.
    let mut x_b = b.clone();
    bordered.matrix_mut().copy_from(jac);
    bordered.factorize().unwrap();
    bordered.solve(&mut x_b);
    let res_b = relative_residual(jac, &x_b, &b);
    let err_b = {
        let d: Vec<f64> = x_b.iter().zip(&x_true).map(|(p, q)| p - q).collect();
        norm(&d) / norm(&x_true)
    };
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
    println!("   BorderedLu: ||Ax-b||/||b|| = {res_b:.2e}, ||x-x_true||/||x_true|| = {err_b:.2e}");
    for (label, a, lu) in &mut faer_variants {
        let mut x_f = b.clone();
        lu.factorize_solve(a, &mut x_f);
        let res_f = relative_residual(jac, &x_f, &b);
        let d: Vec<f64> = x_f.iter().zip(&x_b).map(|(p, q)| p - q).collect();
        let agree = norm(&d) / norm(&x_b);
        let d: Vec<f64> = x_f.iter().zip(&x_true).map(|(p, q)| p - q).collect();
        let err_f = norm(&d) / norm(&x_true);
        println!(
            "   {label}: ||Ax-b||/||b|| = {res_f:.2e}, ||x-x_true||/||x_true|| = {err_f:.2e}, \
             ||x_faer - x_bordered||/||x_bordered|| = {agree:.2e}"
        );
        // Both are backward stable; the forward difference is bounded by
        // cond(A) times that (see the condition number printed above).
        assert!(res_f < 1e-12, "{label}: residual {res_f:e}");
    }

    // Timing, interleaved round by round.
    let mut t_copy = Vec::with_capacity(rounds);
    let mut t_bordered = Vec::with_capacity(rounds);
    let mut t_bordered_nocopy = Vec::with_capacity(rounds);
    let mut t_faer: Vec<Vec<f64>> = vec![Vec::with_capacity(rounds); faer_variants.len()];
    let mut rhs = b.clone();
    for round in 0..rounds + 5 {
        let warm = round < 5;
        rhs.copy_from_slice(&b);
        let t0 = Instant::now();
        bordered.matrix_mut().copy_from(jac);
        let t_c = micros(t0);
        bordered.factorize().unwrap();
        bordered.solve(&mut rhs);
        let t_all = micros(t0);
        black_box(&rhs);
        if !warm {
            t_copy.push(t_c);
            t_bordered.push(t_all);
            t_bordered_nocopy.push(t_all - t_c);
        }
        for (k, (_, a, lu)) in faer_variants.iter_mut().enumerate() {
            rhs.copy_from_slice(&b);
            let t0 = Instant::now();
            lu.factorize_solve(a, &mut rhs);
            let t_f = micros(t0);
            black_box(&rhs);
            if !warm {
                t_faer[k].push(t_f);
            }
        }
    }
    let m_b = median(&mut t_bordered);
    println!(
        "   median of {rounds} (us): BorderedLu copy+factorize+solve {m_b:.1} \
         (copy {:.1}, factorize+solve {:.1})",
        median(&mut t_copy),
        median(&mut t_bordered_nocopy)
    );
    for ((label, _, _), times) in faer_variants.iter().zip(&mut t_faer) {
        let m = median(times);
        let sym = symbolic_us.iter().find(|(l, _)| l == label).unwrap().1;
        println!(
            "   median of {rounds} (us): {label}: numeric factorize+solve {m:.1} = {:.2}x BorderedLu \
             (symbolic analysis once: {sym:.0} us)",
            m / m_b
        );
    }

    // faer's symbolic analysis is done once: its pattern must hold for
    // the rest of the run. The node pattern does by construction; the
    // observed nonzeros of the first steps do not.
    let (mut escaped_nodes, mut escaped_observed) = (0, 0);
    for _ in 0..4 {
        for _ in 0..25 {
            sim.step().unwrap();
        }
        let later = sim.next_step_jacobian().0;
        escaped_nodes += outside(&later, &nodes, &full);
        escaped_observed += outside(&later, &tight, &full);
    }
    println!(
        "   nonzeros of 4 later Jacobians (to step 130) outside the node pattern: {escaped_nodes}; \
         outside the nonzeros observed in the first 30 steps: {escaped_observed}"
    );
    assert_eq!(escaped_nodes, 0);
}

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
    run_case("3 x 40 to one free point", three_to_a_point(), scale);
    run_case("3 x 40 in a chain through two free points", chain(), scale);
    run_case("12 x 40 to one free point", twelve_to_a_point(), scale / 3);
    run_case(
        "1 x 120, no free point (one band, no border)",
        one_line_system(),
        scale,
    );
    run_steps(scale);
}
