//! The motion of a coupled point between two calls of the code that
//! drives it (docs/method.md §13.2, (K1)-(K2)): a coupling code gives the
//! point's position, and optionally its velocity, at the ends of each
//! coupling interval [t_0, t_0 + T]; between them the point moves
//!
//! ```text
//!   linearly (K1):   r(t) = r_0 + s (r_1 - r_0),            s = (t - t_0) / T,
//!                    r_dot = (r_1 - r_0) / T;
//!   cubically (K2):  r(t) = H_00(s) r_0 + T H_10(s) v_0 + H_01(s) r_1 + T H_11(s) v_1,
//! ```
//!
//! with the cubic Hermite basis H_00 = 2s^3 - 3s^2 + 1, H_10 = s^3 - 2s^2 + s,
//! H_01 = 3s^2 - 2s^3, H_11 = s^3 - s^2 (the time basis of the slab, eq. 6).
//! The cubic matches position and velocity at both ends, so a step whose
//! time nodes are the interval's ends sees exactly the given values; its
//! error inside is T^4 max|r''''| / 384. Outside the interval the
//! polynomial continues.

/// One coordinate's motion over a coupling interval, (K1) or (K2).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct IntervalMotion {
    /// Start of the interval t_0 (s).
    pub t0: f64,
    /// Length T > 0 (s).
    pub duration: f64,
    /// Values at t_0 and t_0 + T.
    pub start: f64,
    pub end: f64,
    /// Rates at t_0 and t_0 + T: the cubic (K2); None: the line (K1).
    pub rates: Option<(f64, f64)>,
}

impl IntervalMotion {
    /// Value and rate at t.
    pub fn at(&self, t: f64) -> (f64, f64) {
        let big_t = self.duration;
        let s = (t - self.t0) / big_t;
        // A step's end node t_a + h lands on t_0 + T up to the last bits
        // of t_a: taken as the end itself, so that the given values are
        // met exactly.
        let s = if (s - 1.0).abs() <= 1e-12 { 1.0 } else { s };
        let Some((v0, v1)) = self.rates else {
            let slope = (self.end - self.start) / big_t;
            return (self.start + s * (self.end - self.start), slope);
        };
        // The cubic Hermite basis in s (docs/method.md §1.4, eq. 6).
        let [[h00, h10, h01, h11], [d00, d10, d01, d11], _] = crate::shape::hermite3(s, 1.0);
        let value = h00 * self.start + big_t * h10 * v0 + h01 * self.end + big_t * h11 * v1;
        let rate = (d00 * self.start + d01 * self.end) / big_t + d10 * v0 + d11 * v1;
        (value, rate)
    }

    /// The second derivative at t: the cubic's (K2), zero on the line
    /// (K1).
    pub fn acceleration(&self, t: f64) -> f64 {
        let Some((v0, v1)) = self.rates else {
            return 0.0;
        };
        let big_t = self.duration;
        let s = (t - self.t0) / big_t;
        let [_, _, [a00, a10, a01, a11]] = crate::shape::hermite3(s, 1.0);
        (a00 * self.start + a01 * self.end) / (big_t * big_t) + (a10 * v0 + a11 * v1) / big_t
    }

    /// Whether the value stays the same for all t.
    pub fn is_still(&self) -> bool {
        self.start == self.end && self.rates.is_none_or(|(a, b)| a == 0.0 && b == 0.0)
    }
}

/// A point's motion over a coupling interval, (K1) or (K2), per
/// coordinate.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MotionInterval {
    pub t0: f64,
    pub duration: f64,
    pub start: [f64; 3],
    pub end: [f64; 3],
    /// Velocities at both ends (the cubic), or None (the line).
    pub rates: Option<([f64; 3], [f64; 3])>,
}

impl MotionInterval {
    /// At rest at `position` for all t.
    pub fn at_rest(position: [f64; 3]) -> Self {
        MotionInterval {
            t0: 0.0,
            duration: 1.0,
            start: position,
            end: position,
            rates: None,
        }
    }

    /// Coordinate c's motion.
    pub fn coordinate(&self, c: usize) -> IntervalMotion {
        IntervalMotion {
            t0: self.t0,
            duration: self.duration,
            start: self.start[c],
            end: self.end[c],
            rates: self.rates.map(|(a, b)| (a[c], b[c])),
        }
    }

    /// Position and velocity at t.
    pub fn state(&self, t: f64) -> ([f64; 3], [f64; 3]) {
        let at: [(f64, f64); 3] = std::array::from_fn(|c| self.coordinate(c).at(t));
        (at.map(|a| a.0), at.map(|a| a.1))
    }

    /// Acceleration at t (zero on the line).
    pub fn acceleration(&self, t: f64) -> [f64; 3] {
        std::array::from_fn(|c| self.coordinate(c).acceleration(t))
    }

    /// Whether every value is finite and the length positive.
    pub fn is_valid(&self) -> bool {
        let finite = |v: &[f64; 3]| v.iter().all(|x| x.is_finite());
        self.t0.is_finite()
            && self.duration.is_finite()
            && self.duration > 0.0
            && finite(&self.start)
            && finite(&self.end)
            && self.rates.is_none_or(|(a, b)| finite(&a) && finite(&b))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_cubic_matches_both_ends_and_reproduces_a_cubic() {
        let f = |t: f64| 1.0 - 2.0 * t + 0.5 * t * t * t;
        let df = |t: f64| -2.0 + 1.5 * t * t;
        let (t0, big_t) = (0.3, 0.7);
        let m = IntervalMotion {
            t0,
            duration: big_t,
            start: f(t0),
            end: f(t0 + big_t),
            rates: Some((df(t0), df(t0 + big_t))),
        };
        assert_eq!(m.at(t0), (f(t0), df(t0)));
        for k in 0..=20 {
            let t = t0 - 0.2 + 1.2 * big_t * k as f64 / 20.0;
            let (v, r) = m.at(t);
            assert!((v - f(t)).abs() < 1e-14, "value at {t}");
            assert!((r - df(t)).abs() < 1e-13, "rate at {t}");
        }
    }

    #[test]
    fn the_line_moves_at_constant_rate() {
        let m = IntervalMotion {
            t0: 1.0,
            duration: 2.0,
            start: 4.0,
            end: 1.0,
            rates: None,
        };
        assert_eq!(m.at(2.0), (2.5, -1.5));
        assert!(!m.is_still());
        assert!(MotionInterval::at_rest([1.0, 2.0, 3.0])
            .coordinate(1)
            .is_still());
    }
}
