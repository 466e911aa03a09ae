//! The global consistent mass matrix, eq. (11) (docs/method.md §2.1):
//! its product with a vector and its diagonal, assembled from the
//! elements' mass matrices over the coordinate numbering of §1.1.

use super::{coordinate, Model, SLOT_R};

impl Model {
    /// y = M x with the global consistent mass matrix.
    pub fn mass_times(&self, x: &[f64], y: &mut [f64]) {
        y.fill(0.0);
        let dpn = self.dofs_per_node();
        crate::with_elements!(&self.mesh, els => {
            for (k, el) in els.iter().enumerate() {
                let o = coordinate(dpn, k, SLOT_R, 0);
                let mq = el.mass_times(&gather(x, o));
                for (d, v) in mq.iter().enumerate() {
                    y[o + d] += v;
                }
            }
        });
    }

    /// Diagonal of the global mass matrix.
    pub fn mass_diagonal(&self) -> Vec<f64> {
        let dpn = self.dofs_per_node();
        let mut diag = vec![0.0; self.dofs()];
        crate::with_elements!(&self.mesh, els => {
            for (k, el) in els.iter().enumerate() {
                for (s, row) in el.mass.iter().enumerate() {
                    for i in 0..3 {
                        diag[coordinate(dpn, k, s, i)] += row[s];
                    }
                }
            }
        });
        diag
    }
}

/// The `N` consecutive entries of `x` starting at `offset`.
#[inline]
pub(crate) fn gather<const N: usize>(x: &[f64], offset: usize) -> [f64; N] {
    let mut out = [0.0; N];
    out.copy_from_slice(&x[offset..offset + N]);
    out
}
