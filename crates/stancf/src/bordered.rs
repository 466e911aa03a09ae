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

use crate::band::{BandLu, SingularMatrix};
use crate::linear::{AddEntries, Factorization, Jacobian};

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
        let blk = &mut self.blocks[b];
        let n = blk.n;
        match (i < n, j < n) {
            (true, true) => blk.a.matrix_mut().add(i, j, v),
            (true, false) => blk.b[(j - n) * n + i] += v,
            (false, true) => blk.c[(i - n) * n + j] += v,
            (false, false) => {
                self.d[blk.border[i - n] * self.nb + blk.border[j - n]] += v;
            }
        }
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

/// The LU factors of a [`BorderedMatrix`] by block elimination, computed in
/// the matrix's storage: the blocks' band factors, Z_i in place of B_i,
/// and the factors of S in place of D with their row interchanges.
#[derive(Clone, Debug)]
pub struct BorderedLu {
    m: BorderedMatrix,
    /// Row interchanges of S's LU: row k was swapped with row `pivots[k]`.
    pivots: Vec<usize>,
}

impl BorderedLu {
    /// Storage for factorizing matrices of this shape.
    pub fn new(blocks: &[BlockShape], border: usize) -> Self {
        BorderedLu {
            m: BorderedMatrix::new(blocks, border),
            pivots: vec![0; border],
        }
    }
}

impl Factorization for BorderedLu {
    type Matrix = BorderedMatrix;

    fn matrix_mut(&mut self) -> &mut BorderedMatrix {
        &mut self.m
    }

    fn matrix(&self) -> &BorderedMatrix {
        &self.m
    }

    /// Block elimination in place; a singular block or S is reported with
    /// the global column of the failing pivot.
    fn factorize(&mut self) -> Result<(), SingularMatrix> {
        let m = &mut self.m;
        let nb = m.nb;
        for blk in &mut m.blocks {
            blk.a.factorize().map_err(|e| SingularMatrix {
                column: e.column + blk.start,
            })?;
            let n = blk.n;
            // Z_i = A_i^-1 B_i, column by column, over B_i.
            for z in blk.b.chunks_exact_mut(n) {
                blk.a.solve(z);
            }
            // S -= C_i Z_i at border_i x border_i.
            for (r, c_row) in blk.c.chunks_exact(n).enumerate() {
                let s_row = &mut m.d[blk.border[r] * nb..(blk.border[r] + 1) * nb];
                for (z, &g) in blk.b.chunks_exact(n).zip(&blk.border) {
                    s_row[g] -= dot(c_row, z);
                }
            }
        }
        dense_lu(&mut m.d, nb, &mut self.pivots).map_err(|k| SingularMatrix {
            column: m.border_start + k,
        })
    }

    /// Solves A x = b in place with the factors (see the module's
    /// documentation for the steps).
    fn solve(&self, b: &mut [f64]) {
        let m = &self.m;
        let (nb, bs) = (m.nb, m.border_start);
        let (b_blocks, b_border) = b.split_at_mut(bs);
        let b_border = &mut b_border[..nb];
        for blk in &m.blocks {
            let n = blk.n;
            let y = &mut b_blocks[blk.start..blk.start + n];
            blk.a.solve(y);
            for (c_row, &g) in blk.c.chunks_exact(n).zip(&blk.border) {
                b_border[g] -= dot(c_row, y);
            }
        }
        dense_solve(&m.d, nb, &self.pivots, b_border);
        for blk in &m.blocks {
            let n = blk.n;
            let y = &mut b_blocks[blk.start..blk.start + n];
            for (z, &g) in blk.b.chunks_exact(n).zip(&blk.border) {
                axpy(-b_border[g], z, y);
            }
        }
    }
}

/// Dense LU with partial pivoting of the row-major n x n `s`, in place
/// (LAPACK `dgetf2`: whole rows swapped, unit L below the diagonal). A
/// pivot below `max|s| max(1e-300, 1e-8 eps)` or not finite is singular:
/// `Err(column)`.
fn dense_lu(s: &mut [f64], n: usize, pivots: &mut [usize]) -> Result<(), usize> {
    let tiny = max_abs(s) * 1e-300_f64.max(f64::EPSILON * 1e-8);
    for k in 0..n {
        let mut p = k;
        let mut best = s[k * n + k].abs();
        for r in k + 1..n {
            let v = s[r * n + k].abs();
            if v > best {
                best = v;
                p = r;
            }
        }
        pivots[k] = p;
        if best <= tiny || !best.is_finite() {
            return Err(k);
        }
        if p != k {
            let (top, bottom) = s.split_at_mut(p * n);
            top[k * n..(k + 1) * n].swap_with_slice(&mut bottom[..n]);
        }
        let (top, rest) = s.split_at_mut((k + 1) * n);
        let row_k = &top[k * n..];
        let inv = 1.0 / row_k[k];
        for row in rest.chunks_exact_mut(n) {
            let l = row[k] * inv;
            row[k] = l;
            if l != 0.0 {
                axpy(-l, &row_k[k + 1..], &mut row[k + 1..]);
            }
        }
    }
    Ok(())
}

/// x <- S^-1 x with the factors of [`dense_lu`].
fn dense_solve(s: &[f64], n: usize, pivots: &[usize], x: &mut [f64]) {
    for (k, &p) in pivots.iter().enumerate() {
        x.swap(k, p);
    }
    for i in 0..n {
        x[i] -= dot(&s[i * n..i * n + i], &x[..i]);
    }
    for i in (0..n).rev() {
        x[i] = (x[i] - dot(&s[i * n + i + 1..(i + 1) * n], &x[i + 1..])) / s[i * n + i];
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

#[cfg(test)]
mod tests {
    use super::*;

    fn shape(size: usize, kl: usize, ku: usize, border: &[usize]) -> BlockShape {
        BlockShape {
            size,
            kl,
            ku,
            border: border.to_vec(),
        }
    }

    /// Three blocks with overlapping borders of 7 points.
    fn three_blocks() -> Vec<BlockShape> {
        vec![
            shape(17, 2, 3, &[0, 1, 2]),
            shape(9, 1, 1, &[2, 3, 4, 5]),
            shape(23, 4, 2, &[5, 6]),
        ]
    }

    /// A tiny LCG (Knuth's MMIX constants): values in [-1, 1).
    fn lcg(state: &mut u64) -> f64 {
        *state = state
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        (*state >> 11) as f64 / (1u64 << 52) as f64 - 1.0
    }

    /// Global unknown -> (block, local index), `None` on the border; worked
    /// out from the shapes alone, independently of the implementation.
    fn owner(shapes: &[BlockShape], mut i: usize) -> Option<(usize, usize)> {
        for (b, s) in shapes.iter().enumerate() {
            if i < s.size {
                return Some((b, i));
            }
            i -= s.size;
        }
        None
    }

    fn in_structure(shapes: &[BlockShape], nb: usize, i: usize, j: usize) -> bool {
        let bs: usize = shapes.iter().map(|s| s.size).sum();
        assert!(i < bs + nb && j < bs + nb);
        match (owner(shapes, i), owner(shapes, j)) {
            (Some((a, li)), Some((b, lj))) => {
                let s = &shapes[a];
                a == b && li + s.ku >= lj && lj + s.kl >= li
            }
            (Some((a, _)), None) => shapes[a].border.contains(&(j - bs)),
            (None, Some((b, _))) => shapes[b].border.contains(&(i - bs)),
            (None, None) => true,
        }
    }

    /// The test matrix, dense: pseudo-random entries in the structure,
    /// the diagonal above the sum of its row's other magnitudes (strictly
    /// diagonally dominant, so every block and S are nonsingular).
    fn dense_matrix(shapes: &[BlockShape], nb: usize, seed: u64) -> Vec<Vec<f64>> {
        let size = shapes.iter().map(|s| s.size).sum::<usize>() + nb;
        let mut state = seed;
        let mut a = vec![vec![0.0; size]; size];
        for (i, row) in a.iter_mut().enumerate() {
            for (j, v) in row.iter_mut().enumerate() {
                if in_structure(shapes, nb, i, j) {
                    *v = lcg(&mut state);
                }
            }
            let off: f64 = row.iter().map(|v| v.abs()).sum::<f64>() - row[i].abs();
            row[i] = 1.0 + off + row[i].abs();
        }
        a
    }

    fn fill_global(m: &mut BorderedMatrix, a: &[Vec<f64>]) {
        for (i, row) in a.iter().enumerate() {
            for (j, &v) in row.iter().enumerate() {
                if v != 0.0 {
                    m.add(i, j, v);
                }
            }
        }
    }

    /// Fills the blocks' entries through `add_local` and D through `add`.
    fn fill_local(m: &mut BorderedMatrix, shapes: &[BlockShape], a: &[Vec<f64>]) {
        let bs = m.border_start();
        for (b, s) in shapes.iter().enumerate() {
            let global = |l: usize| {
                if l < s.size {
                    m.block_start(b) + l
                } else {
                    bs + s.border[l - s.size]
                }
            };
            let nl = s.size + s.border.len();
            let mut entries = Vec::new();
            for li in 0..nl {
                for lj in 0..nl {
                    let (i, j) = (global(li), global(lj));
                    if (i < bs || j < bs) && a[i][j] != 0.0 {
                        entries.push((li, lj, a[i][j]));
                    }
                }
            }
            for (li, lj, v) in entries {
                m.add_local(b, li, lj, v);
            }
        }
        for i in bs..a.len() {
            for j in bs..a.len() {
                m.add(i, j, a[i][j]);
            }
        }
    }

    fn dense_of(m: &BorderedMatrix) -> Vec<Vec<f64>> {
        let n = m.size();
        (0..n)
            .map(|i| (0..n).map(|j| m.get(i, j)).collect())
            .collect()
    }

    fn assert_close(x: &[f64], reference: &[f64], tol: f64, what: &str) {
        let scale = reference.iter().fold(0.0f64, |s, v| s.max(v.abs()));
        for (i, (a, b)) in x.iter().zip(reference).enumerate() {
            assert!(
                (a - b).abs() <= tol * scale,
                "{what}: x[{i}] = {a}, expected {b}"
            );
        }
    }

    /// Fills `lu` from `a`, checks `get` and `mul_vec` against the dense
    /// matrix, then solves A x = b against x_true and a dense LU.
    fn solve_and_check(lu: &mut BorderedLu, a: &[Vec<f64>], seed: u64) {
        let n = a.len();
        lu.matrix_mut().clear();
        fill_global(lu.matrix_mut(), a);
        assert_eq!(dense_of(lu.matrix()), a);
        let mut state = seed;
        let x_true: Vec<f64> = (0..n).map(|_| lcg(&mut state)).collect();
        let mut b = vec![0.0; n];
        lu.matrix().mul_vec(&x_true, &mut b);
        let b_dense: Vec<f64> = a.iter().map(|row| dot(row, &x_true)).collect();
        assert_close(&b, &b_dense, 1e-14, "mul_vec");
        // The whole matrix by the dense LU.
        let mut full: Vec<f64> = a.iter().flatten().copied().collect();
        let mut pivots = vec![0; n];
        dense_lu(&mut full, n, &mut pivots).unwrap();
        let mut x_dense = b.clone();
        dense_solve(&full, n, &pivots, &mut x_dense);
        lu.factorize().unwrap();
        let mut x = b;
        lu.solve(&mut x);
        assert_close(&x, &x_true, 1e-12, "block elimination vs x_true");
        assert_close(&x, &x_dense, 1e-12, "block elimination vs dense LU");
    }

    #[test]
    fn block_elimination_solves_like_a_dense_lu() {
        let shapes = three_blocks();
        let mut lu = BorderedLu::new(&shapes, 7);
        assert_eq!(lu.matrix().size(), 17 + 9 + 23 + 7);
        assert_eq!(lu.matrix().border_start(), 49);
        assert_eq!(lu.matrix().block_start(2), 26);
        for seed in [1u64, 2] {
            let a = dense_matrix(&shapes, 7, seed);
            solve_and_check(&mut lu, &a, seed + 10);
        }
    }

    #[test]
    fn a_border_without_blocks_and_blocks_without_border_work() {
        // No border: independent band LUs.
        let shapes = vec![shape(6, 1, 2, &[]), shape(11, 3, 0, &[])];
        let mut lu = BorderedLu::new(&shapes, 0);
        solve_and_check(&mut lu, &dense_matrix(&shapes, 0, 3), 4);
        // One block with a border of 3; border index 1 only in D.
        let shapes = vec![shape(8, 2, 2, &[0, 2])];
        let mut lu = BorderedLu::new(&shapes, 3);
        solve_and_check(&mut lu, &dense_matrix(&shapes, 3, 5), 6);
        // A block without border next to one with.
        let shapes = vec![shape(5, 1, 1, &[0, 1, 2]), shape(4, 0, 3, &[])];
        let mut lu = BorderedLu::new(&shapes, 3);
        solve_and_check(&mut lu, &dense_matrix(&shapes, 3, 7), 8);
    }

    #[test]
    fn pivoting_is_needed_and_done() {
        // A = [0 1 0; 1 0 1; 0 1 2] (det -2), B = C^T = e_0 e_0^T, and
        // D chosen so that S = D - C A^-1 B = [0 2; 3 1].
        let shapes = vec![shape(3, 1, 1, &[0, 1])];
        let mut lu = BorderedLu::new(&shapes, 2);
        let m = lu.matrix_mut();
        for (i, j, v) in [
            (0, 1, 1.0),
            (1, 0, 1.0),
            (1, 2, 1.0),
            (2, 1, 1.0),
            (2, 2, 2.0),
        ] {
            m.add(i, j, v);
        }
        m.add(0, 3, 1.0);
        m.add(3, 0, 1.0);
        // A^-1 e_0 = (1/2, 1, -1/2), so S_00 = D_00 - 1/2 = 0.
        m.add(3, 3, 0.5);
        m.add(3, 4, 2.0);
        m.add(4, 3, 3.0);
        m.add(4, 4, 1.0);
        let x_true = [1.0, -2.0, 3.0, 0.5, -1.5];
        let mut b = [0.0; 5];
        lu.matrix().mul_vec(&x_true, &mut b);
        lu.factorize().unwrap();
        assert_eq!(lu.matrix().d[0], 3.0, "S's rows were swapped");
        assert_eq!(lu.pivots, [1, 1]);
        lu.solve(&mut b);
        assert_close(&b, &x_true, 1e-15, "pivoted solve");
    }

    #[test]
    fn a_singular_border_is_reported() {
        // A = B = C = I (2 x 2), D = I + [1 2; 2 4]: S = [1 2; 2 4], rank 1.
        let shapes = vec![shape(2, 0, 0, &[0, 1])];
        let mut lu = BorderedLu::new(&shapes, 2);
        let m = lu.matrix_mut();
        for k in 0..2 {
            m.add(k, k, 1.0);
            m.add(k, 2 + k, 1.0);
            m.add(2 + k, k, 1.0);
            m.add(2 + k, 2 + k, 1.0);
        }
        m.add(2, 2, 1.0);
        m.add(2, 3, 2.0);
        m.add(3, 2, 2.0);
        m.add(3, 3, 4.0);
        let err = lu.factorize().unwrap_err();
        assert!(err.column >= lu.matrix().border_start());
        assert_eq!(err, SingularMatrix { column: 3 });
        // A singular block reports its global column: block 1 (unknowns
        // 3..7) has an empty third column, global 5.
        let shapes = vec![shape(3, 1, 1, &[0]), shape(4, 1, 1, &[0])];
        let mut lu = BorderedLu::new(&shapes, 1);
        let m = lu.matrix_mut();
        for i in [0, 1, 2, 3, 4, 6, 7] {
            m.add(i, i, 1.0);
        }
        assert_eq!(lu.factorize(), Err(SingularMatrix { column: 5 }));
    }

    #[test]
    fn add_local_and_add_agree() {
        let shapes = three_blocks();
        let a = dense_matrix(&shapes, 7, 9);
        let mut global = BorderedMatrix::new(&shapes, 7);
        let mut local = BorderedMatrix::new(&shapes, 7);
        fill_global(&mut global, &a);
        fill_local(&mut local, &shapes, &a);
        assert_eq!(dense_of(&global), a);
        assert_eq!(dense_of(&local), a);
        assert_eq!(global.max_abs(), local.max_abs());
        let mut copy = BorderedMatrix::new(&shapes, 7);
        copy.copy_from(&local);
        assert_eq!(dense_of(&copy), a);
    }

    #[test]
    #[should_panic(expected = "outside the bordered structure")]
    fn an_entry_coupling_two_blocks_is_refused() {
        let shapes = three_blocks();
        let mut m = BorderedMatrix::new(&shapes, 7);
        m.add(16, 17, 1.0);
    }

    #[test]
    #[should_panic(expected = "not sorted and distinct")]
    fn an_unsorted_border_is_refused() {
        BorderedMatrix::new(&[shape(3, 1, 1, &[2, 1])], 3);
    }

    /// No allocator hook in unit tests: the buffers' addresses and
    /// capacities must not change through factorize and solve.
    #[test]
    fn factorize_and_solve_do_not_allocate() {
        fn buffers(lu: &BorderedLu) -> Vec<(usize, usize)> {
            let m = &lu.m;
            let mut v = vec![
                (m.d.as_ptr() as usize, m.d.capacity()),
                (m.block_of.as_ptr() as usize, m.block_of.capacity()),
                (lu.pivots.as_ptr() as usize, lu.pivots.capacity()),
            ];
            for blk in &m.blocks {
                v.push((blk.b.as_ptr() as usize, blk.b.capacity()));
                v.push((blk.c.as_ptr() as usize, blk.c.capacity()));
                v.push((blk.border.as_ptr() as usize, blk.border.capacity()));
            }
            v
        }
        let shapes = three_blocks();
        let mut lu = BorderedLu::new(&shapes, 7);
        fill_global(lu.matrix_mut(), &dense_matrix(&shapes, 7, 11));
        let before = buffers(&lu);
        lu.factorize().unwrap();
        let mut b = vec![1.0; lu.matrix().size()];
        lu.solve(&mut b);
        assert_eq!(buffers(&lu), before);
    }
}
