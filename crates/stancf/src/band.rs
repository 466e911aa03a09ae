//! Banded matrices and their LU factorization with partial pivoting
//! (docs/method.md §7.6).
//!
//! The slab Jacobian couples a spatial node only with its two neighbours,
//! and its unknowns and equations are numbered node by node, so it is a band
//! matrix whose bandwidth is fixed by the element type and the number of
//! time layers, not by the mesh: factorizing it costs O(n kl (kl + ku)),
//! linear in the number of elements. The storage is LAPACK's (`dgbtrf`):
//! column j holds rows j - ku - kl ..= j + kl, with kl extra rows above the
//! band for the fill-in of row interchanges, so factorization happens in
//! place and never allocates.
//!
//! ```text
//!   A(i, j) = data[j * ld + kl + ku + i - j],   ld = 2 kl + ku + 1
//! ```

/// A square band matrix with `kl` sub- and `ku` super-diagonals, stored
/// with room for its LU factors.
#[derive(Clone, Debug)]
pub struct BandMatrix {
    n: usize,
    kl: usize,
    ku: usize,
    ld: usize,
    data: Vec<f64>,
}

impl BandMatrix {
    pub fn new(n: usize, kl: usize, ku: usize) -> Self {
        let kl = kl.min(n.saturating_sub(1));
        let ku = ku.min(n.saturating_sub(1));
        let ld = 2 * kl + ku + 1;
        BandMatrix {
            n,
            kl,
            ku,
            ld,
            data: vec![0.0; ld * n],
        }
    }

    pub fn size(&self) -> usize {
        self.n
    }

    pub fn lower_bandwidth(&self) -> usize {
        self.kl
    }

    pub fn upper_bandwidth(&self) -> usize {
        self.ku
    }

    /// Copies the entries of a matrix of the same shape.
    pub fn copy_from(&mut self, other: &BandMatrix) {
        assert_eq!((self.n, self.kl, self.ku), (other.n, other.kl, other.ku));
        self.data.copy_from_slice(&other.data);
    }

    /// Sets every entry (and the fill area) to zero.
    pub fn clear(&mut self) {
        self.data.fill(0.0);
    }

    #[inline]
    fn index(&self, i: usize, j: usize) -> usize {
        debug_assert!(i < self.n && j < self.n);
        debug_assert!(
            i + self.ku >= j && j + self.kl >= i,
            "({i}, {j}) outside the band"
        );
        j * self.ld + self.kl + self.ku + i - j
    }

    /// A(i, j) += value. (i, j) must lie inside the band.
    #[inline]
    pub fn add(&mut self, i: usize, j: usize, value: f64) {
        let k = self.index(i, j);
        self.data[k] += value;
    }

    /// A(i, j), zero outside the band.
    pub fn get(&self, i: usize, j: usize) -> f64 {
        if i + self.ku < j || j + self.kl < i {
            0.0
        } else {
            self.data[self.index(i, j)]
        }
    }

    /// y = A x (before factorization).
    pub fn mul_vec(&self, x: &[f64], y: &mut [f64]) {
        for (i, yi) in y.iter_mut().enumerate().take(self.n) {
            let lo = i.saturating_sub(self.kl);
            let hi = (i + self.ku).min(self.n - 1);
            *yi = (lo..=hi).map(|j| self.get(i, j) * x[j]).sum();
        }
    }

    /// Largest |A(i, j)|: a scale for the singularity test.
    pub fn max_abs(&self) -> f64 {
        self.data.iter().fold(0.0f64, |m, v| m.max(v.abs()))
    }
}

/// The LU factors of a band matrix, P A = L U, computed in place.
#[derive(Clone, Debug)]
pub struct BandLu {
    a: BandMatrix,
    pivots: Vec<usize>,
    /// Super-diagonals of U that the factorization filled: ku where no
    /// row was interchanged, at most kl + ku (the fill room); the
    /// back-substitution runs over these only (the rest are zeros).
    u_width: usize,
}

/// The factorization met a zero pivot in this column.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct SingularMatrix {
    pub column: usize,
}

impl BandLu {
    /// Storage for factorizing matrices of this shape.
    pub fn new(n: usize, kl: usize, ku: usize) -> Self {
        let a = BandMatrix::new(n, kl, ku);
        let u_width = a.kl + a.ku;
        BandLu {
            a,
            pivots: vec![0; n],
            u_width,
        }
    }

    /// The matrix to fill before [`Self::factorize`].
    pub fn matrix_mut(&mut self) -> &mut BandMatrix {
        &mut self.a
    }

    pub fn matrix(&self) -> &BandMatrix {
        &self.a
    }

    /// Gaussian elimination with partial pivoting (LAPACK `dgbtf2`), in
    /// place, without allocation. A pivot smaller than `tiny` times the
    /// largest entry counts as zero.
    pub fn factorize(&mut self) -> Result<(), SingularMatrix> {
        let n = self.a.n;
        let kl = self.a.kl;
        let ku = self.a.ku;
        let ld = self.a.ld;
        let diag = kl + ku;
        let scale = self.a.max_abs();
        let tiny = scale * 1e-300_f64.max(f64::EPSILON * 1e-8);
        let data = &mut self.a.data;
        let mut ju = 0usize;
        let mut u_width = 0usize;
        for j in 0..n {
            let km = kl.min(n - 1 - j);
            // Pivot: largest |A(j + i, j)|, i = 0..=km.
            let col = j * ld + diag;
            let mut p = 0;
            let mut best = data[col].abs();
            for i in 1..=km {
                let v = data[col + i].abs();
                if v > best {
                    best = v;
                    p = i;
                }
            }
            self.pivots[j] = j + p;
            if best <= tiny || !best.is_finite() {
                return Err(SingularMatrix { column: j });
            }
            ju = ju.max((j + ku + p).min(n - 1));
            u_width = u_width.max(ju - j);
            if p != 0 {
                // Swap rows j and j + p in columns j..=ju.
                for c in j..=ju {
                    let base = c * ld + diag - c;
                    data.swap(base + j, base + j + p);
                }
            }
            let pivot = data[col];
            let inv = 1.0 / pivot;
            // Column j's multipliers, then the rank-one update of rows
            // j+1..=j+km in columns j+1..=ju: columns are contiguous and
            // disjoint, so both sides are plain slices (no bounds checks in
            // the inner loop, which vectorizes).
            let (left, right) = data.split_at_mut((j + 1) * ld);
            let l = &mut left[col + 1..col + 1 + km];
            for v in l.iter_mut() {
                *v *= inv;
            }
            let l = &*l;
            // Two columns at a time (each column's update is its own, so
            // the order of the operations on every entry is unchanged):
            // the multipliers are loaded once for both.
            let mut c = j + 1;
            while c < ju {
                let base0 = (c - j - 1) * ld + diag + j - c;
                let base1 = base0 + ld - 1;
                let (a0, a1) = (right[base0], right[base1]);
                let (first, second) = right.split_at_mut(base1 + 1);
                let t0 = &mut first[base0 + 1..base0 + 1 + km];
                let t1 = &mut second[..km];
                if a0 != 0.0 && a1 != 0.0 {
                    for ((x0, x1), &li) in t0.iter_mut().zip(t1.iter_mut()).zip(l) {
                        *x0 -= li * a0;
                        *x1 -= li * a1;
                    }
                } else {
                    eliminate(t0, l, a0);
                    eliminate(t1, l, a1);
                }
                c += 2;
            }
            if c == ju {
                let base = (c - j - 1) * ld + diag + j - c;
                let a = right[base];
                eliminate(&mut right[base + 1..base + 1 + km], l, a);
            }
        }
        self.u_width = u_width;
        Ok(())
    }

    /// Solves A x = b in place with the factors.
    pub fn solve(&self, b: &mut [f64]) {
        let n = self.a.n;
        let kl = self.a.kl;
        let ku = self.a.ku;
        let ld = self.a.ld;
        let diag = kl + ku;
        let data = &self.a.data;
        // Forward: apply the interchanges and L column by column.
        for j in 0..n {
            let p = self.pivots[j];
            if p != j {
                b.swap(j, p);
            }
            let km = kl.min(n - 1 - j);
            let bj = b[j];
            if bj != 0.0 {
                let col = j * ld + diag;
                for (bi, &l) in b[j + 1..j + 1 + km]
                    .iter_mut()
                    .zip(&data[col + 1..col + 1 + km])
                {
                    *bi -= l * bj;
                }
            }
        }
        // Backward: U has kl + ku super-diagonals, of which the first
        // u_width hold the factors (the others are exact zeros).
        for j in (0..n).rev() {
            let base = j * ld + diag - j;
            b[j] /= data[base + j];
            let bj = b[j];
            if bj != 0.0 {
                let lo = j.saturating_sub(self.u_width);
                for (bi, &u) in b[lo..j].iter_mut().zip(&data[base + lo..base + j]) {
                    *bi -= u * bj;
                }
            }
        }
    }
}

/// One column's share of an elimination step: `column -= a l` (nothing
/// where `a` is zero).
#[inline(always)]
fn eliminate(column: &mut [f64], l: &[f64], a: f64) {
    if a != 0.0 {
        for (t, &li) in column.iter_mut().zip(l) {
            *t -= li * a;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Deterministic pseudo-random numbers in [-1, 1) (xorshift).
    fn rng(seed: &mut u64) -> f64 {
        *seed ^= *seed << 13;
        *seed ^= *seed >> 7;
        *seed ^= *seed << 17;
        (*seed >> 11) as f64 / (1u64 << 52) as f64 - 1.0
    }

    /// A x = b for random band matrices that need pivoting (small or zero
    /// diagonal), against a residual bound scaled by eps, n and the norms.
    #[test]
    fn solves_random_band_systems_with_pivoting() {
        let mut seed = 0x9E3779B97F4A7C15u64;
        for &(n, kl, ku) in &[(1, 0, 0), (7, 2, 1), (40, 5, 3), (60, 11, 11), (33, 0, 4)] {
            let mut lu = BandLu::new(n, kl, ku);
            let mut dense = vec![vec![0.0; n]; n];
            for i in 0..n {
                for j in i.saturating_sub(kl)..=(i + ku).min(n - 1) {
                    let mut v = rng(&mut seed);
                    if i == j && i % 3 == 0 && kl > 0 {
                        v = 0.0; // forces a row interchange
                    }
                    lu.matrix_mut().add(i, j, v);
                    dense[i][j] = v;
                }
            }
            let x: Vec<f64> = (0..n).map(|_| rng(&mut seed)).collect();
            let mut b = vec![0.0; n];
            lu.matrix().mul_vec(&x, &mut b);
            for i in 0..n {
                let d: f64 = (0..n).map(|j| dense[i][j] * x[j]).sum();
                assert!((d - b[i]).abs() < 1e-14);
            }
            if lu.factorize().is_err() {
                continue; // a singular random draw proves nothing here
            }
            let mut sol = b.clone();
            lu.solve(&mut sol);
            // Residual |A sol - b| <= c eps n |A| |sol|.
            let anorm = dense
                .iter()
                .map(|r| r.iter().map(|v| v.abs()).sum::<f64>())
                .fold(0.0, f64::max);
            let xnorm = sol.iter().fold(0.0f64, |m, v| m.max(v.abs()));
            for i in 0..n {
                let r: f64 = (0..n).map(|j| dense[i][j] * sol[j]).sum::<f64>() - b[i];
                assert!(
                    r.abs() <= 64.0 * f64::EPSILON * n as f64 * anorm * xnorm,
                    "n={n} kl={kl} ku={ku}: residual {r:e}"
                );
            }
        }
    }

    #[test]
    fn reports_a_singular_matrix() {
        let mut lu = BandLu::new(4, 1, 1);
        for i in 0..4 {
            lu.matrix_mut().add(i, i, 1.0);
        }
        // Row 2 and column 2 empty.
        let m = lu.matrix_mut();
        m.clear();
        m.add(0, 0, 1.0);
        m.add(1, 1, 1.0);
        m.add(3, 3, 1.0);
        assert_eq!(lu.factorize(), Err(SingularMatrix { column: 2 }));
    }
}
