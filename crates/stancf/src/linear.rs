//! What the nonlinear solvers and the assembly need of a linear system
//! (docs/method.md §7.6): a matrix that takes entries ([`AddEntries`],
//! [`Jacobian`]) and its factors ([`Factorization`]). A single cable's
//! step is a band ([`crate::band`]); a system of lines joined at points
//! is a set of bands bordered by the points' unknowns
//! ([`crate::bordered`]). Nothing here allocates.

pub use crate::band::SingularMatrix;

/// Something entries of a matrix can be added to: the matrix itself, or a
/// view that translates one line's local numbering into a system's.
pub trait AddEntries {
    /// A(i, j) += value. (i, j) must lie inside the matrix's structure.
    fn add(&mut self, i: usize, j: usize, value: f64);
}

/// A square sparse matrix with a fixed structure.
pub trait Jacobian: AddEntries {
    /// Sets every entry to zero.
    fn clear(&mut self);
    /// A(i, j), zero outside the structure.
    fn get(&self, i: usize, j: usize) -> f64;
    /// Rows (= columns).
    fn size(&self) -> usize;
    /// Largest |A(i, j)|: a scale for singularity tests.
    fn max_abs(&self) -> f64;
    /// Copies the entries of a matrix of the same structure.
    fn copy_from(&mut self, other: &Self);
}

/// The factors of a [`Jacobian`], computed in place without allocation.
pub trait Factorization: Clone {
    type Matrix: Jacobian;
    /// The matrix to fill before [`Self::factorize`].
    fn matrix_mut(&mut self) -> &mut Self::Matrix;
    fn matrix(&self) -> &Self::Matrix;
    /// Factorizes the matrix (destroying it).
    fn factorize(&mut self) -> Result<(), SingularMatrix>;
    /// b <- A^-1 b with the factors.
    fn solve(&self, b: &mut [f64]);
}

impl AddEntries for crate::band::BandMatrix {
    #[inline]
    fn add(&mut self, i: usize, j: usize, value: f64) {
        crate::band::BandMatrix::add(self, i, j, value);
    }
}

impl Jacobian for crate::band::BandMatrix {
    fn clear(&mut self) {
        crate::band::BandMatrix::clear(self);
    }
    fn get(&self, i: usize, j: usize) -> f64 {
        crate::band::BandMatrix::get(self, i, j)
    }
    fn size(&self) -> usize {
        crate::band::BandMatrix::size(self)
    }
    fn max_abs(&self) -> f64 {
        crate::band::BandMatrix::max_abs(self)
    }
    fn copy_from(&mut self, other: &Self) {
        crate::band::BandMatrix::copy_from(self, other);
    }
}

impl Factorization for crate::band::BandLu {
    type Matrix = crate::band::BandMatrix;
    fn matrix_mut(&mut self) -> &mut Self::Matrix {
        crate::band::BandLu::matrix_mut(self)
    }
    fn matrix(&self) -> &Self::Matrix {
        crate::band::BandLu::matrix(self)
    }
    fn factorize(&mut self) -> Result<(), SingularMatrix> {
        crate::band::BandLu::factorize(self)
    }
    fn solve(&self, b: &mut [f64]) {
        crate::band::BandLu::solve(self, b);
    }
}
