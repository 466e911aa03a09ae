//! The matrix in faer's compressed columns ([`Csc`]) and faer's sparse
//! LU with its symbolic analysis done once ([`FaerLu`]).

use faer::dyn_stack::{MemBuffer, MemStack, StackReq};
use faer::sparse::linalg::lu::{factorize_symbolic_lu, LuSymbolicParams, NumericLu, SymbolicLu};
use faer::sparse::linalg::SupernodalThreshold;
use faer::sparse::{SparseColMatRef, SymbolicSparseColMatRef};
use faer::{Conj, MatMut, Par};
use stancf::bordered::BorderedMatrix;
use stancf::linear::Jacobian;

/// A matrix in faer's compressed columns, its values taken from `j`.
pub struct Csc {
    n: usize,
    col_ptr: Vec<usize>,
    row_idx: Vec<usize>,
    values: Vec<f64>,
}

impl Csc {
    pub fn new(cols: &[Vec<usize>]) -> Self {
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

    pub fn fill_from(&mut self, j: &BorderedMatrix) {
        for c in 0..self.n {
            for k in self.col_ptr[c]..self.col_ptr[c + 1] {
                self.values[k] = j.get(self.row_idx[k], c);
            }
        }
    }

    pub fn symbolic(&self) -> SymbolicSparseColMatRef<'_, usize> {
        SymbolicSparseColMatRef::new_checked(self.n, self.n, &self.col_ptr, None, &self.row_idx)
    }

    pub fn matrix(&self) -> SparseColMatRef<'_, usize, f64> {
        SparseColMatRef::new(self.symbolic(), &self.values)
    }
}

/// faer's sparse LU with its symbolic analysis done once and everything
/// the numeric factorization and the solve need allocated up front.
pub struct FaerLu {
    symbolic: SymbolicLu<usize>,
    numeric: NumericLu<usize, f64>,
    buffer: MemBuffer,
}

impl FaerLu {
    pub fn new(a: &Csc, threshold: SupernodalThreshold) -> Self {
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
    pub fn factorize_solve(&mut self, a: &Csc, b: &mut [f64]) {
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
