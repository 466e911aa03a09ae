//! The LU factors of a [`BorderedMatrix`] by block elimination (see the
//! module's formulas; docs/method.md §7.6, §11.3).

use super::{axpy, dot, max_abs, BlockShape, BorderedMatrix};
use crate::band::SingularMatrix;
use crate::linear::Factorization;

/// The LU factors of a [`BorderedMatrix`] by block elimination, computed in
/// the matrix's storage: the blocks' band factors, Z_i in place of B_i,
/// and the factors of S in place of D with their row interchanges.
#[derive(Clone, Debug)]
pub struct BorderedLu {
    pub(super) m: BorderedMatrix,
    /// Row interchanges of S's LU: row k was swapped with row `pivots[k]`.
    pub(super) pivots: Vec<usize>,
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
pub(crate) fn dense_lu(s: &mut [f64], n: usize, pivots: &mut [usize]) -> Result<(), usize> {
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
pub(crate) fn dense_solve(s: &[f64], n: usize, pivots: &[usize], x: &mut [f64]) {
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
