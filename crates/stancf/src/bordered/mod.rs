//! Band matrices bordered by a dense block, and their LU by block
//! elimination (docs/method.md §7.6).
//!
//! Cable lines joined at points give a Jacobian made of one band block per
//! line, `A_i`, coupled only through the points' unknowns, which are
//! numbered last (the border):
//!
//! ```text
//!   [ A_1              B_1 ]      A_i  band, n_i x n_i (kl_i, ku_i)
//!   [      A_2         B_2 ]      B_i  dense, n_i x k_i
//!   [           ...    ... ]      C_i  dense, k_i x n_i
//!   [ C_1  C_2  ...    D   ]      D    dense, nb x nb
//! ```
//!
//! Line i touches only the k_i border unknowns listed in `border_i`
//! (sorted, distinct), so B_i and C_i hold just those columns and rows.
//! Block i's unknowns are `start_i .. start_i + n_i`, the blocks one after
//! the other from 0; the border is `N - nb .. N`, `N = sum n_i + nb`.
//!
//! The factors come from eliminating the blocks first (the Schur
//! complement of the blocks is the small dense S):
//!
//! ```text
//!   A_i = P_i L_i U_i              band LU with partial pivoting, per block
//!   Z_i = A_i^-1 B_i               k_i band solves, kept
//!   S   = D - sum_i C_i Z_i        each k_i x k_i product added at border_i x border_i
//!   S   = P L U                    dense LU with partial pivoting, nb x nb
//! ```
//!
//! and A x = b is solved as
//!
//! ```text
//!   y_i      = A_i^-1 b_i
//!   s        = b_border - sum_i C_i y_i
//!   x_border = S^-1 s
//!   x_i      = y_i - Z_i x_border[border_i]
//! ```
//!
//! Everything happens in place in the matrix's own storage (Z_i overwrites
//! B_i, S overwrites D), so factorization and solves never allocate. The
//! cost is that of the band LUs plus `sum k_i^2 n_i` for S and `nb^3 / 3`
//! for its LU.
//!
//! This file holds the matrix ([`BorderedMatrix`]); `lu.rs` its factors
//! ([`BorderedLu`]) and the dense LU of S; `tests.rs` the checks against a
//! dense LU.

mod lu;
#[cfg(test)]
mod tests;

pub use lu::BorderedLu;
pub(crate) use lu::{dense_lu, dense_solve};

use crate::band::BandLu;
use crate::linear::{AddEntries, Jacobian};

/// The shape of one block: its size, its bandwidths, and the border
/// indices (0..nb, sorted, distinct) its rows and columns couple with.
#[derive(Clone, Debug, PartialEq)]
pub struct BlockShape {
    pub size: usize,
    pub kl: usize,
    pub ku: usize,
    pub border: Vec<usize>,
}

/// Marks a border index that a block does not touch.
const UNTOUCHED: usize = usize::MAX;

/// One block's part of the matrix: A_i (with room for its pivots), B_i
/// column-major (k_i columns of n_i), C_i row-major (k_i rows of n_i).
#[derive(Clone, Debug)]
struct Block {
    start: usize,
    n: usize,
    border: Vec<usize>,
    /// Border index -> position in `border`, or [`UNTOUCHED`]; length nb.
    local_of: Vec<usize>,
    a: BandLu,
    b: Vec<f64>,
    c: Vec<f64>,
}

/// A square matrix of band blocks bordered by a dense block (see the
/// module's documentation for the structure and numbering).
#[derive(Clone, Debug)]
pub struct BorderedMatrix {
    blocks: Vec<Block>,
    nb: usize,
    border_start: usize,
    /// Global unknown (below `border_start`) -> its block.
    block_of: Vec<u32>,
    /// D, row-major nb x nb.
    d: Vec<f64>,
}

impl BorderedMatrix {
    /// A zero matrix with these blocks and `border` border unknowns.
    /// Panics if a block is empty or its border indices are not sorted,
    /// distinct and below `border`: a programming error.
    pub fn new(blocks: &[BlockShape], border: usize) -> Self {
        assert!(
            blocks.len() < u32::MAX as usize,
            "too many blocks: {}",
            blocks.len()
        );
        let mut start = 0;
        let mut block_of = Vec::new();
        let mut parts = Vec::with_capacity(blocks.len());
        for (i, shape) in blocks.iter().enumerate() {
            assert!(shape.size > 0, "block {i} is empty");
            let mut local_of = vec![UNTOUCHED; border];
            for (k, &g) in shape.border.iter().enumerate() {
                assert!(g < border, "block {i}: border index {g} >= {border}");
                assert!(
                    k == 0 || shape.border[k - 1] < g,
                    "block {i}: border indices not sorted and distinct: {:?}",
                    shape.border
                );
                local_of[g] = k;
            }
            let (n, k) = (shape.size, shape.border.len());
            block_of.resize(start + n, i as u32);
            parts.push(Block {
                start,
                n,
                border: shape.border.clone(),
                local_of,
                a: BandLu::new(n, shape.kl, shape.ku),
                b: vec![0.0; n * k],
                c: vec![0.0; k * n],
            });
            start += n;
        }
        BorderedMatrix {
            blocks: parts,
            nb: border,
            border_start: start,
            block_of,
            d: vec![0.0; border * border],
        }
    }

    /// Number of band blocks.
    pub fn blocks(&self) -> usize {
        self.blocks.len()
    }

    /// Global index of block `i`'s first unknown.
    pub fn block_start(&self, i: usize) -> usize {
        self.blocks[i].start
    }

    /// Global index of the first border unknown, N - nb.
    pub fn border_start(&self) -> usize {
        self.border_start
    }

    /// Number of border unknowns, nb.
    pub fn border_size(&self) -> usize {
        self.nb
    }

    /// y = A x (before factorization):
    /// `y_i = A_i x_i + B_i x_border[border_i]`,
    /// `y_border = D x_border + sum_i C_i x_i`.
    pub fn mul_vec(&self, x: &[f64], y: &mut [f64]) {
        let (nb, bs) = (self.nb, self.border_start);
        assert!(x.len() >= bs + nb && y.len() >= bs + nb);
        let xb = &x[bs..bs + nb];
        let (y_blocks, yb) = y.split_at_mut(bs);
        let yb = &mut yb[..nb];
        for (r, yr) in yb.iter_mut().enumerate() {
            *yr = dot(&self.d[r * nb..(r + 1) * nb], xb);
        }
        for blk in &self.blocks {
            let (s, n) = (blk.start, blk.n);
            let xi = &x[s..s + n];
            let yi = &mut y_blocks[s..s + n];
            blk.a.matrix().mul_vec(xi, yi);
            for (k, &g) in blk.border.iter().enumerate() {
                axpy(xb[g], &blk.b[k * n..(k + 1) * n], yi);
                yb[g] += dot(&blk.c[k * n..(k + 1) * n], xi);
            }
        }
    }

    /// A(i, j) += v in the numbering LOCAL to block `b`: local index < n_b is
    /// the block's own unknown; local index n_b + k is border index
    /// `border_b[k]`. This is the fast path the assembly of one line uses (no
    /// search).
    #[inline]
    pub fn add_local(&mut self, b: usize, i: usize, j: usize, v: f64) {
        self.block_entries(b).add(i, j, v);
    }

    /// Block `b`'s share of the matrix, for adding many entries in its
    /// local numbering (see [`BlockEntries::add`]).
    pub fn block_entries(&mut self, b: usize) -> BlockEntries<'_> {
        let blk = &mut self.blocks[b];
        BlockEntries {
            n: blk.n,
            nb: self.nb,
            a: blk.a.matrix_mut(),
            b: &mut blk.b,
            c: &mut blk.c,
            border: &blk.border,
            d: &mut self.d,
        }
    }

    /// Row `to` += w row `from`, both border rows (global indices): a
    /// change of the border's equations (a point's rows carried to its
    /// body's, docs/method.md §15.7). Every block that touches `from`
    /// must touch `to`.
    pub fn add_border_row(&mut self, to: usize, from: usize, w: f64) {
        let (t, f) = (to - self.border_start, from - self.border_start);
        assert!(t != f, "a border row added to itself");
        for blk in &mut self.blocks {
            let (kt, kf) = (blk.local_of[t], blk.local_of[f]);
            if kf == UNTOUCHED {
                continue;
            }
            assert!(
                kt != UNTOUCHED,
                "border row {to} is outside block's structure"
            );
            let n = blk.n;
            for j in 0..n {
                blk.c[kt * n + j] += w * blk.c[kf * n + j];
            }
        }
        let nb = self.nb;
        for j in 0..nb {
            self.d[t * nb + j] += w * self.d[f * nb + j];
        }
    }

    /// Sets border column `column` (a global index) to zero.
    pub fn clear_border_column(&mut self, column: usize) {
        let c = column - self.border_start;
        for blk in &mut self.blocks {
            let k = blk.local_of[c];
            if k != UNTOUCHED {
                let n = blk.n;
                blk.b[k * n..(k + 1) * n].fill(0.0);
            }
        }
        let nb = self.nb;
        for r in 0..nb {
            self.d[r * nb + c] = 0.0;
        }
    }

    /// Sets border row `row` (a global index) to zero.
    pub fn clear_border_row(&mut self, row: usize) {
        let r = row - self.border_start;
        for blk in &mut self.blocks {
            let k = blk.local_of[r];
            if k != UNTOUCHED {
                let n = blk.n;
                blk.c[k * n..(k + 1) * n].fill(0.0);
            }
        }
        let nb = self.nb;
        self.d[r * nb..(r + 1) * nb].fill(0.0);
    }

    /// The block holding global unknown `i` (below the border) and its
    /// local index.
    #[inline]
    fn locate(&self, i: usize) -> (usize, usize) {
        let b = self.block_of[i] as usize;
        (b, i - self.blocks[b].start)
    }

    /// Position of (i, j) in the storage, `None` outside the structure.
    fn slot(&self, i: usize, j: usize) -> Option<Slot> {
        let bs = self.border_start;
        assert!(
            i < bs + self.nb && j < bs + self.nb,
            "({i}, {j}) outside the matrix"
        );
        match (i < bs, j < bs) {
            (true, true) => {
                let ((bi, li), (bj, lj)) = (self.locate(i), self.locate(j));
                (bi == bj).then_some(Slot::Band(bi, li, lj))
            }
            (true, false) => {
                let (bi, li) = self.locate(i);
                let k = self.blocks[bi].local_of[j - bs];
                (k != UNTOUCHED).then(|| Slot::B(bi, k * self.blocks[bi].n + li))
            }
            (false, true) => {
                let (bj, lj) = self.locate(j);
                let k = self.blocks[bj].local_of[i - bs];
                (k != UNTOUCHED).then(|| Slot::C(bj, k * self.blocks[bj].n + lj))
            }
            (false, false) => Some(Slot::D((i - bs) * self.nb + j - bs)),
        }
    }
}

/// One block's share of a [`BorderedMatrix`], borrowed once for many
/// entries (the assembly of one line).
pub struct BlockEntries<'a> {
    n: usize,
    nb: usize,
    a: &'a mut crate::band::BandMatrix,
    b: &'a mut [f64],
    c: &'a mut [f64],
    border: &'a [usize],
    d: &'a mut [f64],
}

impl BlockEntries<'_> {
    /// A(i, j) += v in the block's local numbering, as
    /// [`BorderedMatrix::add_local`].
    #[inline]
    pub fn add(&mut self, i: usize, j: usize, v: f64) {
        let n = self.n;
        match (i < n, j < n) {
            (true, true) => self.a.add(i, j, v),
            (true, false) => self.b[(j - n) * n + i] += v,
            (false, true) => self.c[(i - n) * n + j] += v,
            (false, false) => {
                self.d[self.border[i - n] * self.nb + self.border[j - n]] += v;
            }
        }
    }
}

/// Where a global entry lives.
enum Slot {
    Band(usize, usize, usize),
    B(usize, usize),
    C(usize, usize),
    D(usize),
}

impl AddEntries for BorderedMatrix {
    /// A(i, j) += value in the global numbering. Panics on an entry that
    /// couples two different blocks, or a block with a border unknown it
    /// does not touch: those lie outside the structure.
    fn add(&mut self, i: usize, j: usize, value: f64) {
        match self.slot(i, j) {
            Some(Slot::Band(b, li, lj)) => self.blocks[b].a.matrix_mut().add(li, lj, value),
            Some(Slot::B(b, k)) => self.blocks[b].b[k] += value,
            Some(Slot::C(b, k)) => self.blocks[b].c[k] += value,
            Some(Slot::D(k)) => self.d[k] += value,
            None => panic!("({i}, {j}) lies outside the bordered structure"),
        }
    }
}

impl Jacobian for BorderedMatrix {
    fn clear(&mut self) {
        for blk in &mut self.blocks {
            blk.a.matrix_mut().clear();
            blk.b.fill(0.0);
            blk.c.fill(0.0);
        }
        self.d.fill(0.0);
    }

    fn get(&self, i: usize, j: usize) -> f64 {
        match self.slot(i, j) {
            Some(Slot::Band(b, li, lj)) => self.blocks[b].a.matrix().get(li, lj),
            Some(Slot::B(b, k)) => self.blocks[b].b[k],
            Some(Slot::C(b, k)) => self.blocks[b].c[k],
            Some(Slot::D(k)) => self.d[k],
            None => 0.0,
        }
    }

    fn size(&self) -> usize {
        self.border_start + self.nb
    }

    fn max_abs(&self) -> f64 {
        let m = max_abs(&self.d);
        self.blocks.iter().fold(m, |m, blk| {
            m.max(blk.a.matrix().max_abs())
                .max(max_abs(&blk.b))
                .max(max_abs(&blk.c))
        })
    }

    /// Copies the entries of a matrix built from the same shapes.
    fn copy_from(&mut self, other: &Self) {
        assert_eq!(self.nb, other.nb, "different borders");
        assert_eq!(self.blocks.len(), other.blocks.len(), "different blocks");
        for (a, b) in self.blocks.iter_mut().zip(&other.blocks) {
            assert_eq!(a.border, b.border, "different block borders");
            a.a.matrix_mut().copy_from(b.a.matrix());
            a.b.copy_from_slice(&b.b);
            a.c.copy_from_slice(&b.c);
        }
        self.d.copy_from_slice(&other.d);
    }
}

#[inline]
fn dot(a: &[f64], b: &[f64]) -> f64 {
    a.iter().zip(b).map(|(x, y)| x * y).sum()
}

/// y += a x.
#[inline]
fn axpy(a: f64, x: &[f64], y: &mut [f64]) {
    for (yi, &xi) in y.iter_mut().zip(x) {
        *yi += a * xi;
    }
}

fn max_abs(v: &[f64]) -> f64 {
    v.iter().fold(0.0f64, |m, x| m.max(x.abs()))
}
