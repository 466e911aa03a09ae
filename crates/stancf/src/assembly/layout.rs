//! Numbering of the unknowns and rows of one step or static solve
//! (docs/method.md §4.3, §5.1, §6.3-6.4): node by node, so that the
//! Jacobian is a band matrix (§7.6).

use super::{Kind, Scheme};
use crate::constraints::ConstraintMethod;
use crate::model::{coordinate, Model, SLOT_R};

/// No unknown, row or multiplier at a table entry.
pub(super) const NONE: usize = usize::MAX;

/// Numbering of the unknowns and rows of one step or static solve.
#[derive(Clone, Debug, PartialEq)]
pub struct SlabLayout {
    pub nodes: usize,
    /// Scalar coordinates per spatial node.
    pub dpn: usize,
    pub scheme: Scheme,
    pub method: ConstraintMethod,
    /// (time node, kind) of each unknown slot and each row slot.
    pub unknown_slots: Vec<(usize, Kind)>,
    pub row_slots: Vec<(usize, Kind)>,
    /// Indexed by [`cell`]; NONE where absent.
    unknowns: Vec<usize>,
    rows: Vec<usize>,
    /// Multiplier unknown of a freed row, same indexing as `rows`.
    multipliers: Vec<usize>,
    /// Constraint equation of a fixed unknown, same indexing as `unknowns`.
    constraint_rows: Vec<usize>,
    /// Direction holds (§6.10, multiplier route): the multiplier of hold
    /// h, row slot s, normal k at `[(h nr + s) 2 + k]`, and its equation
    /// n_k . r_x = 0 in unknown slot s at `[(h nu + s) 2 + k]`.
    hold_multipliers: Vec<usize>,
    hold_rows: Vec<usize>,
    /// First index of each node's block, and the total.
    block_start: Vec<usize>,
    kl: usize,
    ku: usize,
}

/// Entry of (node, slot, coordinate d of the node) in a table of `slots`
/// slots per node: `(node slots + slot) dpn + d`.
#[inline]
fn cell(slots: usize, dpn: usize, node: usize, slot: usize, d: usize) -> usize {
    (node * slots + slot) * dpn + d
}

/// Lower and upper bandwidth of a Jacobian whose node blocks start at
/// `block_start`: a row of node n couples with unknowns of nodes
/// n - 1 ..= n + 1.
fn block_bandwidths(block_start: &[usize]) -> (usize, usize) {
    let nodes = block_start.len() - 1;
    let mut kl = 0;
    let mut ku = 0;
    for n in 0..nodes {
        let lo = block_start[n.saturating_sub(1)];
        let hi = block_start[(n + 2).min(nodes)];
        if block_start[n + 1] > block_start[n] {
            kl = kl.max(block_start[n + 1] - 1 - lo);
            ku = ku.max(hi.saturating_sub(1) - block_start[n]);
        }
    }
    (kl, ku)
}

impl SlabLayout {
    /// The slots of a step of `scheme` without a node: what a system's
    /// points and bodies take their time slots from (docs/method.md
    /// §11.3), with or without lines.
    pub fn of_time(scheme: Scheme, method: ConstraintMethod) -> Self {
        let (unknown_slots, row_slots) = scheme.slots();
        SlabLayout {
            nodes: 0,
            dpn: 0,
            scheme,
            method,
            unknown_slots,
            row_slots,
            unknowns: Vec::new(),
            rows: Vec::new(),
            multipliers: Vec::new(),
            constraint_rows: Vec::new(),
            hold_multipliers: Vec::new(),
            hold_rows: Vec::new(),
            block_start: vec![0],
            kl: 0,
            ku: 0,
        }
    }

    pub fn new(model: &Model, scheme: Scheme, method: ConstraintMethod) -> Self {
        let (unknown_slots, row_slots) = scheme.slots();
        let nodes = model.nodes();
        let dpn = model.dofs_per_node();
        let nu = unknown_slots.len();
        let nr = row_slots.len();
        let mut layout = SlabLayout {
            nodes,
            dpn,
            scheme,
            method,
            unknown_slots,
            row_slots,
            unknowns: vec![NONE; nodes * nu * dpn],
            rows: vec![NONE; nodes * nr * dpn],
            multipliers: vec![NONE; nodes * nr * dpn],
            constraint_rows: vec![NONE; nodes * nu * dpn],
            hold_multipliers: Vec::new(),
            hold_rows: Vec::new(),
            block_start: Vec::with_capacity(nodes + 1),
            kl: 0,
            ku: 0,
        };
        if method == ConstraintMethod::Multiplier {
            let holds = model.constraints.directions.len();
            layout.hold_multipliers = vec![NONE; holds * nr * 2];
            layout.hold_rows = vec![NONE; holds * nu * 2];
        }
        let mut next = 0;
        for n in 0..nodes {
            layout.block_start.push(next);
            next = layout.number_node(model, n, next);
        }
        layout.block_start.push(next);
        (layout.kl, layout.ku) = block_bandwidths(&layout.block_start);
        layout
    }

    /// Numbers the unknowns and rows of node n from `next` on; returns the
    /// first index of the next node's block.
    fn number_node(&mut self, model: &Model, n: usize, next: usize) -> usize {
        let (dpn, method) = (self.dpn, self.method);
        let (nu, nr) = (self.unknown_slots.len(), self.row_slots.len());
        let o = coordinate(dpn, n, SLOT_R, 0);
        // Coordinates held by the planar reduction are always
        // eliminated; constraints by the chosen method.
        let inactive = |d: usize| model.constraints.is_inactive(o + d);
        let constrained = |d: usize| model.constraints.is_constrained(o + d) && !inactive(d);
        let eliminated =
            |d: usize| inactive(d) || (method == ConstraintMethod::Elimination && constrained(d));
        // Unknowns and rows share the same count per node; number both.
        let mut u = next;
        let mut r = next;
        for s in 0..nu {
            for d in 0..dpn {
                if !eliminated(d) {
                    self.unknowns[cell(nu, dpn, n, s, d)] = u;
                    u += 1;
                }
            }
        }
        for s in 0..nr {
            for d in 0..dpn {
                if !eliminated(d) {
                    self.rows[cell(nr, dpn, n, s, d)] = r;
                    r += 1;
                }
            }
        }
        if method == ConstraintMethod::Multiplier {
            for s in 0..nr {
                for d in (0..dpn).filter(|&d| constrained(d)) {
                    self.multipliers[cell(nr, dpn, n, s, d)] = u;
                    u += 1;
                }
            }
            for s in 0..nu {
                for d in (0..dpn).filter(|&d| constrained(d)) {
                    self.constraint_rows[cell(nu, dpn, n, s, d)] = r;
                    r += 1;
                }
            }
            let holds = &model.constraints.directions;
            for h in (0..holds.len()).filter(|&h| holds[h].node == n) {
                for k in 0..2 {
                    for s in 0..nr {
                        self.hold_multipliers[(h * nr + s) * 2 + k] = u;
                        u += 1;
                    }
                    for s in 0..nu {
                        self.hold_rows[(h * nu + s) * 2 + k] = r;
                        r += 1;
                    }
                }
            }
        }
        debug_assert_eq!(u, r, "square blocks");
        u
    }

    /// Multiplier of direction hold h's normal k in row slot s
    /// (multiplier route).
    pub fn hold_multiplier(&self, h: usize, slot: usize, k: usize) -> Option<usize> {
        let v = *self
            .hold_multipliers
            .get((h * self.row_slots.len() + slot) * 2 + k)?;
        (v != NONE).then_some(v)
    }

    /// Equation n_k . r_x = 0 of direction hold h in unknown slot s
    /// (multiplier route).
    pub fn hold_row(&self, h: usize, slot: usize, k: usize) -> Option<usize> {
        let v = *self
            .hold_rows
            .get((h * self.unknown_slots.len() + slot) * 2 + k)?;
        (v != NONE).then_some(v)
    }

    /// Element layers per step (0 for a static solve).
    pub fn layers(&self) -> usize {
        self.scheme.layers()
    }

    /// Time nodes 0..=L (a static solve has one).
    pub fn time_nodes(&self) -> usize {
        self.layers() + 1
    }

    /// Unknowns (= rows) of the system.
    pub fn size(&self) -> usize {
        *self.block_start.last().expect("nodes")
    }

    /// Lower and upper bandwidth of the Jacobian.
    pub fn bandwidths(&self) -> (usize, usize) {
        (self.kl, self.ku)
    }

    pub fn unknown_slot(&self, i: usize, kind: Kind) -> Option<usize> {
        self.unknown_slots.iter().position(|&s| s == (i, kind))
    }

    pub fn row_slot(&self, i: usize, kind: Kind) -> Option<usize> {
        self.row_slots.iter().position(|&s| s == (i, kind))
    }

    #[inline]
    fn at(table: &[usize], slots: usize, dpn: usize, slot: usize, g: usize) -> Option<usize> {
        let (n, d) = (g / dpn, g % dpn);
        let v = table[cell(slots, dpn, n, slot, d)];
        (v != NONE).then_some(v)
    }

    /// Index of the unknown of coordinate d of node n in unknown slot s.
    #[inline]
    pub fn unknown_of_node(&self, slot: usize, node: usize, d: usize) -> Option<usize> {
        let v = self.unknowns[cell(self.unknown_slots.len(), self.dpn, node, slot, d)];
        (v != NONE).then_some(v)
    }

    /// Index of the row of coordinate d of node n in row slot s.
    #[inline]
    pub fn row_of_node(&self, slot: usize, node: usize, d: usize) -> Option<usize> {
        let v = self.rows[cell(self.row_slots.len(), self.dpn, node, slot, d)];
        (v != NONE).then_some(v)
    }

    /// Index of the unknown of global coordinate g in unknown slot s.
    pub fn unknown_at(&self, slot: usize, g: usize) -> Option<usize> {
        Self::at(&self.unknowns, self.unknown_slots.len(), self.dpn, slot, g)
    }

    /// Index of the row of global coordinate g in row slot s.
    pub fn row_at(&self, slot: usize, g: usize) -> Option<usize> {
        Self::at(&self.rows, self.row_slots.len(), self.dpn, slot, g)
    }

    /// Multiplier of the freed row (slot s, coordinate g).
    pub fn multiplier_at(&self, slot: usize, g: usize) -> Option<usize> {
        Self::at(&self.multipliers, self.row_slots.len(), self.dpn, slot, g)
    }

    /// Constraint equation fixing the unknown (slot s, coordinate g).
    pub fn constraint_row_at(&self, slot: usize, g: usize) -> Option<usize> {
        Self::at(
            &self.constraint_rows,
            self.unknown_slots.len(),
            self.dpn,
            slot,
            g,
        )
    }

    /// Index of the unknown (time node i, kind, coordinate g), if any.
    pub fn unknown(&self, i: usize, kind: Kind, g: usize) -> Option<usize> {
        self.unknown_slot(i, kind)
            .and_then(|s| self.unknown_at(s, g))
    }

    /// Index of the row (time node i, kind, coordinate g), if any.
    pub fn equation(&self, i: usize, kind: Kind, g: usize) -> Option<usize> {
        self.row_slot(i, kind).and_then(|s| self.row_at(s, g))
    }
}
