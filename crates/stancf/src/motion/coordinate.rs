//! The prescribed history of one coordinate (docs/method.md §6.1): a
//! harmonic motion with a smooth start ((M30)), one component of a
//! tabulated motion ((M39)) or of a coupling interval's ((K1)-(K2)). The
//! constraints hold a node's coordinates along these.

use super::{IntervalMotion, MotionTable};
use std::sync::Arc;

/// A periodic motion about a point with a smooth start,
/// `u(t) = f(t) amplitude sin(2 pi t / period + phase)`, with the ramp
/// f = s^3 (6 s^2 - 15 s + 10), s = min(t / ramp, 1) (f = 1 without a
/// ramp; f, f' and f'' are continuous, so the motion starts from rest
/// without a jerk).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Oscillation {
    pub amplitude: [f64; 3],
    /// Period (s); 0 for no motion.
    pub period: f64,
    /// Phase (rad).
    pub phase: f64,
    /// Ramp time (s); 0 for none.
    pub ramp: f64,
}

impl Oscillation {
    /// No motion.
    pub const NONE: Oscillation = Oscillation {
        amplitude: [0.0; 3],
        period: 0.0,
        phase: 0.0,
        ramp: 0.0,
    };

    /// The motion of component k of a point at `position` moving so.
    pub fn coordinate_motion(&self, position: &[f64; 3], k: usize) -> CoordinateMotion {
        let moving = self.period > 0.0 && self.amplitude.iter().any(|&a| a != 0.0);
        CoordinateMotion::Harmonic(HarmonicMotion {
            base: position[k],
            rate: 0.0,
            amplitude: if moving { self.amplitude[k] } else { 0.0 },
            omega: if moving {
                2.0 * std::f64::consts::PI / self.period
            } else {
                0.0
            },
            phase: self.phase,
            ramp: self.ramp,
        })
    }
}

/// The ramp f(t) = s^3 (6 s^2 - 15 s + 10), s = min(t / ramp, 1), and
/// df/dt (f = 1 when `ramp` is 0).
pub fn ramp_factor(t: f64, ramp: f64) -> (f64, f64) {
    if ramp <= 0.0 || t >= ramp {
        return (1.0, 0.0);
    }
    if t <= 0.0 {
        return (0.0, 0.0);
    }
    let s = t / ramp;
    let f = s * s * s * (s * (6.0 * s - 15.0) + 10.0);
    let df = 30.0 * s * s * (s - 1.0) * (s - 1.0) / ramp;
    (f, df)
}

/// The prescribed history of one coordinate.
#[derive(Clone, Debug, PartialEq)]
pub enum CoordinateMotion {
    /// c(t) = base + rate t + f(t) amplitude sin(omega t + phase).
    Harmonic(HarmonicMotion),
    /// Component `component` (0 = x, 1 = y, 2 = z) of a tabulated motion
    /// (M39).
    Table {
        table: Arc<MotionTable>,
        component: usize,
    },
    /// One coordinate of a coupling interval's motion, (K1) or (K2).
    Interval(IntervalMotion),
}

/// c(t) = base + rate t + f(t) amplitude sin(omega t + phase), f the ramp
/// of [`ramp_factor`] (1 when `ramp` is 0).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct HarmonicMotion {
    pub base: f64,
    pub rate: f64,
    pub amplitude: f64,
    pub omega: f64,
    pub phase: f64,
    pub ramp: f64,
}

impl CoordinateMotion {
    /// A coordinate held at `value`.
    pub fn fixed(value: f64) -> Self {
        CoordinateMotion::Harmonic(HarmonicMotion {
            base: value,
            rate: 0.0,
            amplitude: 0.0,
            omega: 0.0,
            phase: 0.0,
            ramp: 0.0,
        })
    }

    pub fn value(&self, t: f64) -> f64 {
        match self {
            CoordinateMotion::Harmonic(h) => h.value(t),
            CoordinateMotion::Table { table, component } => table.component(*component, t).0,
            CoordinateMotion::Interval(i) => i.at(t).0,
        }
    }

    pub fn rate_at(&self, t: f64) -> f64 {
        match self {
            CoordinateMotion::Harmonic(h) => h.rate_at(t),
            CoordinateMotion::Table { table, component } => table.component(*component, t).1,
            CoordinateMotion::Interval(i) => i.at(t).1,
        }
    }

    /// Whether the value stays the same for all t.
    pub fn is_still(&self) -> bool {
        match self {
            CoordinateMotion::Harmonic(h) => {
                h.rate == 0.0 && (h.amplitude == 0.0 || h.omega == 0.0)
            }
            CoordinateMotion::Table { table, component } => table.is_constant(*component),
            CoordinateMotion::Interval(i) => i.is_still(),
        }
    }

    /// The value the motion is referred to: a harmonic's base (a static
    /// solve moves a support from it to its value at t = 0), a table's
    /// or an interval's value at t = 0.
    pub fn base(&self) -> f64 {
        match self {
            CoordinateMotion::Harmonic(h) => h.base,
            CoordinateMotion::Table { .. } | CoordinateMotion::Interval(_) => self.value(0.0),
        }
    }
}

impl HarmonicMotion {
    pub fn value(&self, t: f64) -> f64 {
        let wave = self.amplitude * (self.omega * t + self.phase).sin();
        if self.ramp > 0.0 {
            self.base + self.rate * t + ramp_factor(t, self.ramp).0 * wave
        } else {
            self.base + self.rate * t + wave
        }
    }

    pub fn rate_at(&self, t: f64) -> f64 {
        let arg = self.omega * t + self.phase;
        let wave_rate = self.amplitude * self.omega * arg.cos();
        if self.ramp > 0.0 {
            let (f, df) = ramp_factor(t, self.ramp);
            self.rate + f * wave_rate + df * self.amplitude * arg.sin()
        } else {
            self.rate + wave_rate
        }
    }
}
