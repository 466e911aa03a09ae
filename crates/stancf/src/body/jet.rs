//! Numbers that carry their first and second derivatives with respect to
//! N variables (forward-mode automatic differentiation to second order):
//! a body's rotational action is a composition of products and smooth
//! functions of |theta|^2 (docs/method.md §15.4), and evaluating it on
//! jets gives its gradient and its exact Hessian, to round-off, in one
//! pass. A jet whose Hessian is left out (`Jet<N, 0>`, [`Grad`]) carries
//! the first derivatives alone, at a twelfth of the cost for N = 12: the
//! water's virtual work enters the rows by its value and first
//! derivatives (§15.6), so its terms are evaluated on those.

use std::ops::{Add, Mul, Neg, Sub};

/// A value with its gradient and Hessian with respect to N variables;
/// H is N, or 0 for a jet of first order (no Hessian).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Jet<const N: usize, const H: usize = N> {
    pub v: f64,
    pub g: [f64; N],
    pub h: [[f64; H]; H],
}

/// A value with its gradient alone: a jet of first order.
pub type Grad<const N: usize> = Jet<N, 0>;

impl<const N: usize> Jet<N> {
    /// The same value and gradient without the Hessian.
    pub fn first_order(self) -> Grad<N> {
        Jet {
            v: self.v,
            g: self.g,
            h: [],
        }
    }
}

impl<const N: usize, const H: usize> Jet<N, H> {
    /// A constant.
    pub fn constant(v: f64) -> Self {
        Jet {
            v,
            g: [0.0; N],
            h: [[0.0; H]; H],
        }
    }

    /// Variable number `i` at value `v`.
    pub fn variable(v: f64, i: usize) -> Self {
        let mut j = Self::constant(v);
        j.g[i] = 1.0;
        j
    }

    /// f(self) from f and its first two derivatives at self's value
    /// (the chain rule to second order).
    pub fn compose(self, f: f64, df: f64, d2f: f64) -> Self {
        let mut out = self;
        out.v = f;
        for i in 0..N {
            out.g[i] = df * self.g[i];
        }
        for i in 0..H {
            for k in i..H {
                let x = df * self.h[i][k] + d2f * self.g[i] * self.g[k];
                out.h[i][k] = x;
                out.h[k][i] = x;
            }
        }
        out
    }

    pub fn scale(self, s: f64) -> Self {
        let mut out = self;
        out.v *= s;
        for i in 0..N {
            out.g[i] *= s;
        }
        for i in 0..H {
            for k in 0..H {
                out.h[i][k] *= s;
            }
        }
        out
    }
}

impl<const N: usize, const H: usize> Add for Jet<N, H> {
    type Output = Self;
    fn add(self, o: Self) -> Self {
        let mut out = self;
        out.v += o.v;
        for i in 0..N {
            out.g[i] += o.g[i];
        }
        for i in 0..H {
            for k in 0..H {
                out.h[i][k] += o.h[i][k];
            }
        }
        out
    }
}

impl<const N: usize, const H: usize> Sub for Jet<N, H> {
    type Output = Self;
    fn sub(self, o: Self) -> Self {
        self + (-o)
    }
}

impl<const N: usize, const H: usize> Neg for Jet<N, H> {
    type Output = Self;
    fn neg(self) -> Self {
        self.scale(-1.0)
    }
}

/// The product rule to second order: (ab)'' = a'' b + a' b'^T + b' a'^T + a b''.
impl<const N: usize, const H: usize> Mul for Jet<N, H> {
    type Output = Self;
    /// The Hessians of jets are symmetric (every operation keeps them so):
    /// the upper triangle is computed and mirrored.
    fn mul(self, o: Self) -> Self {
        let mut out = self;
        out.v = self.v * o.v;
        for i in 0..N {
            out.g[i] = self.g[i] * o.v + self.v * o.g[i];
        }
        for i in 0..H {
            for k in i..H {
                let x = self.h[i][k] * o.v
                    + self.g[i] * o.g[k]
                    + o.g[i] * self.g[k]
                    + self.v * o.h[i][k];
                out.h[i][k] = x;
                out.h[k][i] = x;
            }
        }
        out
    }
}

/// A 3-vector of jets.
pub type JetVec<const N: usize, const H: usize = N> = [Jet<N, H>; 3];

pub fn dot<const N: usize, const H: usize>(a: &JetVec<N, H>, b: &JetVec<N, H>) -> Jet<N, H> {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

pub fn cross<const N: usize, const H: usize>(a: &JetVec<N, H>, b: &JetVec<N, H>) -> JetVec<N, H> {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

/// |x| on jets, with zero derivatives at x = 0 (where the drags' x |x|
/// has them).
pub fn norm<const N: usize, const H: usize>(x: &JetVec<N, H>) -> Jet<N, H> {
    let s = dot(x, x);
    if s.v <= 0.0 {
        return Jet::constant(0.0);
    }
    let r = s.v.sqrt();
    s.compose(r, 0.5 / r, -0.25 / (r * s.v))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// f(x, y) = x^2 y + sin(x y) against its derivatives by hand.
    #[test]
    fn jets_carry_exact_second_derivatives() {
        let (x0, y0) = (0.7, -1.3);
        let x = Jet::<2>::variable(x0, 0);
        let y = Jet::<2>::variable(y0, 1);
        let xy = x * y;
        let f = x * x * y + xy.compose(xy.v.sin(), xy.v.cos(), -xy.v.sin());
        let (s, c) = ((x0 * y0).sin(), (x0 * y0).cos());
        assert!((f.v - (x0 * x0 * y0 + s)).abs() < 1e-15);
        assert!((f.g[0] - (2.0 * x0 * y0 + y0 * c)).abs() < 1e-14);
        assert!((f.g[1] - (x0 * x0 + x0 * c)).abs() < 1e-14);
        assert!((f.h[0][0] - (2.0 * y0 - y0 * y0 * s)).abs() < 1e-14);
        assert!((f.h[0][1] - (2.0 * x0 + c - x0 * y0 * s)).abs() < 1e-14);
        assert!((f.h[1][1] - (-x0 * x0 * s)).abs() < 1e-14);
        assert_eq!(f.h[0][1], f.h[1][0]);
    }
}
