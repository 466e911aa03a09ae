//! Small 3-vector (and 3x3) kernels, one home for the whole workspace (issue 29).
//!
//! Vectors are plain `[f64; 3]`. Every function takes its vectors by value
//! or by reference (`Borrow`), so hot loops pass `&r_x` without a copy and
//! short formulas pass values; each is `#[inline]` and evaluates the
//! components in the fixed order written here (results bit for bit as the
//! copies these replace).

use std::borrow::Borrow;

/// The dot product a . b = a0 b0 + a1 b1 + a2 b2.
#[inline]
pub fn dot(a: impl Borrow<[f64; 3]>, b: impl Borrow<[f64; 3]>) -> f64 {
    let (a, b) = (a.borrow(), b.borrow());
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

/// The cross product a x b.
#[inline]
pub fn cross(a: impl Borrow<[f64; 3]>, b: impl Borrow<[f64; 3]>) -> [f64; 3] {
    let (a, b) = (a.borrow(), b.borrow());
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

/// The Euclidean length |a| = sqrt(a . a).
#[inline]
pub fn norm(a: impl Borrow<[f64; 3]>) -> f64 {
    let a = a.borrow();
    dot(a, a).sqrt()
}

/// a - b.
#[inline]
pub fn sub(a: impl Borrow<[f64; 3]>, b: impl Borrow<[f64; 3]>) -> [f64; 3] {
    let (a, b) = (a.borrow(), b.borrow());
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

/// a + b.
#[inline]
pub fn add(a: impl Borrow<[f64; 3]>, b: impl Borrow<[f64; 3]>) -> [f64; 3] {
    let (a, b) = (a.borrow(), b.borrow());
    [a[0] + b[0], a[1] + b[1], a[2] + b[2]]
}

/// s a, component by component.
#[inline]
pub fn scale(s: f64, a: impl Borrow<[f64; 3]>) -> [f64; 3] {
    a.borrow().map(|c| s * c)
}

/// a / |a| (not finite for a = 0).
#[inline]
pub fn normalized(a: impl Borrow<[f64; 3]>) -> [f64; 3] {
    let a = a.borrow();
    scale(1.0 / norm(a), a)
}

/// The 3x3 product a b (rows of a times columns of b).
#[inline]
pub fn mat3_mul(a: &[[f64; 3]; 3], b: &[[f64; 3]; 3]) -> [[f64; 3]; 3] {
    std::array::from_fn(|i| std::array::from_fn(|j| (0..3).map(|k| a[i][k] * b[k][j]).sum()))
}

/// The transpose of a 3x3 matrix.
#[inline]
pub fn mat3_transpose(a: &[[f64; 3]; 3]) -> [[f64; 3]; 3] {
    std::array::from_fn(|i| std::array::from_fn(|j| a[j][i]))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_right_handed_basis_crosses_and_dots_as_it_should() {
        let (x, y, z) = ([1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]);
        assert_eq!(cross(x, y), z);
        assert_eq!(cross(y, z), x);
        assert_eq!(dot(x, y), 0.0);
        assert_eq!(norm([3.0, 4.0, 12.0]), 13.0);
        assert_eq!(sub([1.0, 2.0, 3.0], [1.0, 1.0, 1.0]), [0.0, 1.0, 2.0]);
        assert_eq!(add([1.0, 2.0, 3.0], [1.0, 1.0, 1.0]), [2.0, 3.0, 4.0]);
        assert_eq!(scale(2.0, [1.0, 2.0, 3.0]), [2.0, 4.0, 6.0]);
        assert_eq!(normalized([0.0, 0.0, 2.0]), z);
    }
}
