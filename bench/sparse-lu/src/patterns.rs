//! Sparsity patterns of a system's step Jacobian, column by column
//! (sorted rows, global numbering): the bordered structure the library
//! stores, the node pattern the assembly can fill, and a test for
//! nonzeros outside a pattern.

use stancf::assembly::Scheme;
use stancf::bordered::BorderedMatrix;
use stancf::linear::Jacobian;
use stancf::system::{SystemLayout, SystemSimulation};
use stancf::{Model, StepSettings, TimeScheme};

/// The layout the simulation numbers its step with, rebuilt through the
/// public API (the simulation keeps its own private).
pub fn layout_of(sim: &SystemSimulation, s: &StepSettings) -> SystemLayout {
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
pub fn structure(layout: &SystemLayout) -> Vec<Vec<usize>> {
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
pub fn node_pattern(layout: &SystemLayout) -> Vec<Vec<usize>> {
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
pub fn outside(j: &BorderedMatrix, pattern: &[Vec<usize>], structure: &[Vec<usize>]) -> usize {
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
