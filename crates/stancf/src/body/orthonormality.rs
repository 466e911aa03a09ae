//! The six conditions that keep a body's columns a rotation
//! (docs/method.md §15.3):
//!
//! ```text
//!   g(q) = [a_1.a_1 - 1, a_2.a_2 - 1, a_3.a_3 - 1, a_2.a_3, a_3.a_1, a_1.a_2] = 0      (B5)
//! ```
//!
//! quadratic in q, so the Jacobian G = dg/dq is linear in q and the
//! multipliers' second derivative sum_j lambda_j d2g_j/dq2 is constant.
//! The handedness (det = +1) is not a condition: it is kept by continuity
//! from the start.

use super::natural::{column, Natural};
use crate::vec3::dot;

/// The pairs (k, l) of columns (1..3) of each condition of (B5).
pub const PAIRS: [(usize, usize); 6] = [(1, 1), (2, 2), (3, 3), (2, 3), (3, 1), (1, 2)];

/// g(q) of (B5).
pub fn conditions(q: &Natural) -> [f64; 6] {
    let mut g = [0.0; 6];
    for (j, &(k, l)) in PAIRS.iter().enumerate() {
        g[j] = dot(column(q, k), column(q, l)) - if k == l { 1.0 } else { 0.0 };
    }
    g
}

/// G = dg/dq (6 x 12): d(a_k . a_l)/da_k = a_l, d/da_l = a_k (2 a_k when
/// k = l).
pub fn jacobian(q: &Natural) -> [[f64; 12]; 6] {
    let mut g = [[0.0; 12]; 6];
    for (j, &(k, l)) in PAIRS.iter().enumerate() {
        let (ak, al) = (column(q, k), column(q, l));
        for i in 0..3 {
            g[j][3 * k + i] += al[i];
            g[j][3 * l + i] += ak[i];
        }
    }
    g
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_jacobian_is_the_derivative_of_the_conditions() {
        let q: Natural = std::array::from_fn(|i| ((i * 7 + 3) % 11) as f64 * 0.17 - 0.8);
        let g = jacobian(&q);
        let h = 1e-7;
        for c in 0..12 {
            let (mut up, mut down) = (q, q);
            up[c] += h;
            down[c] -= h;
            let (gu, gd) = (conditions(&up), conditions(&down));
            for j in 0..6 {
                let fd = (gu[j] - gd[j]) / (2.0 * h);
                assert!((fd - g[j][c]).abs() < 1e-8, "condition {j}, coordinate {c}");
            }
        }
    }
}
