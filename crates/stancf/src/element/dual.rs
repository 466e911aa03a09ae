//! Forward-mode dual numbers: a value with its gradient in N inputs,
//! carried through the arithmetic and the few functions a pointwise law
//! needs (sqrt, sin, atan2). The VIV law (docs/method.md §12.7)
//! composes many small maps (relative flow, its normal part, the
//! cross-flow direction, the response phase); its exact Jacobian is the
//! chain rule, which a dual number applies operation by operation: no
//! hand-derived derivative to get wrong, and the finite-difference checks
//! of the slab's rows test the whole.

use std::ops::{Add, Div, Mul, Neg, Sub};

/// A value and its derivatives `d[k] = d value / d input_k`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Dual<const N: usize> {
    pub v: f64,
    pub d: [f64; N],
}

impl<const N: usize> Dual<N> {
    /// A constant (no derivative).
    pub fn constant(v: f64) -> Self {
        Dual { v, d: [0.0; N] }
    }

    /// Input k with value v.
    pub fn input(v: f64, k: usize) -> Self {
        let mut d = [0.0; N];
        d[k] = 1.0;
        Dual { v, d }
    }

    /// f(self) from f's value `f` and slope `df` at self's value.
    fn chain(self, f: f64, df: f64) -> Self {
        Dual {
            v: f,
            d: self.d.map(|x| df * x),
        }
    }

    pub fn sqrt(self) -> Self {
        let s = self.v.sqrt();
        // d sqrt = 1/(2 sqrt); at 0 the slope is taken as 0 (the callers
        // guard the points where it matters).
        let slope = if s > 0.0 { 0.5 / s } else { 0.0 };
        self.chain(s, slope)
    }

    pub fn sin(self) -> Self {
        self.chain(self.v.sin(), self.v.cos())
    }

    /// atan2(self, x): the angle of (x, self), d = (x dy - y dx)/(x^2 + y^2);
    /// at the origin, angle 0 (whatever the zeros' signs, which
    /// f64::atan2 would turn into 0 or +-pi) and no derivative.
    pub fn atan2(self, x: Self) -> Self {
        let r2 = self.v * self.v + x.v * x.v;
        if r2 == 0.0 {
            return Dual::constant(0.0);
        }
        let v = self.v.atan2(x.v);
        Dual {
            v,
            d: std::array::from_fn(|k| (x.v * self.d[k] - self.v * x.d[k]) / r2),
        }
    }
}

impl<const N: usize> Add for Dual<N> {
    type Output = Self;
    fn add(self, o: Self) -> Self {
        Dual {
            v: self.v + o.v,
            d: std::array::from_fn(|k| self.d[k] + o.d[k]),
        }
    }
}

impl<const N: usize> Sub for Dual<N> {
    type Output = Self;
    fn sub(self, o: Self) -> Self {
        Dual {
            v: self.v - o.v,
            d: std::array::from_fn(|k| self.d[k] - o.d[k]),
        }
    }
}

// The product and quotient rules mix the operations.
#[allow(clippy::suspicious_arithmetic_impl)]
impl<const N: usize> Mul for Dual<N> {
    type Output = Self;
    fn mul(self, o: Self) -> Self {
        Dual {
            v: self.v * o.v,
            d: std::array::from_fn(|k| self.d[k] * o.v + self.v * o.d[k]),
        }
    }
}

impl<const N: usize> Mul<f64> for Dual<N> {
    type Output = Self;
    fn mul(self, c: f64) -> Self {
        Dual {
            v: self.v * c,
            d: self.d.map(|x| x * c),
        }
    }
}

#[allow(clippy::suspicious_arithmetic_impl)]
impl<const N: usize> Div for Dual<N> {
    type Output = Self;
    fn div(self, o: Self) -> Self {
        let v = self.v / o.v;
        Dual {
            v,
            d: std::array::from_fn(|k| (self.d[k] - v * o.d[k]) / o.v),
        }
    }
}

impl<const N: usize> Neg for Dual<N> {
    type Output = Self;
    fn neg(self) -> Self {
        Dual {
            v: -self.v,
            d: self.d.map(|x| -x),
        }
    }
}

/// A 3-vector of duals.
pub(crate) type Vec3D<const N: usize> = [Dual<N>; 3];

pub(crate) fn dot3<const N: usize>(a: &Vec3D<N>, b: &Vec3D<N>) -> Dual<N> {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

pub(crate) fn cross3<const N: usize>(a: &Vec3D<N>, b: &Vec3D<N>) -> Vec3D<N> {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every operation's derivative against central differences of the
    /// same composition.
    #[test]
    fn a_composition_of_every_operation_has_the_central_difference_slope() {
        fn f<const N: usize>(x: Dual<N>, y: Dual<N>) -> Dual<N> {
            let a = (x * y + x.sin() - (y * 0.5).sin()) / (x * x + Dual::constant(1.5)).sqrt();
            -(a.atan2(y - x * 0.3)) * 2.0
        }
        let (x0, y0) = (0.7, -1.3);
        let d = f(Dual::<2>::input(x0, 0), Dual::<2>::input(y0, 1));
        let h = 1e-6;
        let g = |x: f64, y: f64| f(Dual::<2>::constant(x), Dual::<2>::constant(y)).v;
        let dx = (g(x0 + h, y0) - g(x0 - h, y0)) / (2.0 * h);
        let dy = (g(x0, y0 + h) - g(x0, y0 - h)) / (2.0 * h);
        // Central differences err by h^2 f''' ~ 1e-12, round-off by
        // 1e-16 / h ~ 1e-10.
        assert!((d.d[0] - dx).abs() < 1e-8, "{} vs {dx}", d.d[0]);
        assert!((d.d[1] - dy).abs() < 1e-8, "{} vs {dy}", d.d[1]);
    }
}
