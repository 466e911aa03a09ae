//! Evaluation of a solved catenary: the tension, position and its
//! derivatives along the line ((C1)-(C6), (C10), (C11)), the end forces
//! (C12) and the sag (C13); the in-plane catenary of given (H, V_A) with
//! the cancellation-free forms (C5); small vector helpers.

use super::{Catenary, LineEnd, Profile};
use crate::vec3::{norm, scale, sub};

impl Catenary {
    /// The effective tension T(s) (N) at unstretched arc length s.
    pub fn tension(&self, s: f64) -> f64 {
        match self.profile {
            Profile::Hanging => self.plane().tension(s),
            Profile::Vertical { sigma } => sigma * self.vertical_tension(s),
            Profile::Straight { tension } => tension,
        }
    }

    /// The point r(s) at unstretched arc length s from A ((C3), (C4); s is
    /// not clamped to [0, L], the formulas continue the curve).
    pub fn position(&self, s: f64) -> [f64; 3] {
        let (x, z) = match self.profile {
            Profile::Hanging => self.plane().position(s),
            Profile::Vertical { sigma } => (
                0.0,
                sigma * s
                    + self.compliance
                        * (self.vertical_force_a * s + 0.5 * self.line.weight * s * s),
            ),
            Profile::Straight { .. } => {
                let fraction = s / self.line.length;
                (fraction * self.span, fraction * self.rise)
            }
        };
        self.to_space(self.origin, x, z)
    }

    /// dr/ds (C2), of length 1 + T(s)/EA.
    pub fn derivative(&self, s: f64) -> [f64; 3] {
        let (dx, dz) = match self.profile {
            Profile::Hanging => {
                let stretch = 1.0 / self.tension(s) + self.compliance;
                (
                    self.horizontal_tension * stretch,
                    self.vertical_tension(s) * stretch,
                )
            }
            Profile::Vertical { sigma } => {
                (0.0, sigma + self.compliance * self.vertical_tension(s))
            }
            Profile::Straight { .. } => {
                (self.span / self.line.length, self.rise / self.line.length)
            }
        };
        self.to_space([0.0; 3], dx, dz)
    }

    /// d2r/ds2 (C6).
    pub fn second_derivative(&self, s: f64) -> [f64; 3] {
        let w = self.line.weight;
        let (ddx, ddz) = match self.profile {
            Profile::Hanging => {
                let h = self.horizontal_tension;
                let t = self.tension(s);
                let t3 = t * t * t;
                (
                    -w * h * self.vertical_tension(s) / t3,
                    w * h * h / t3 + w * self.compliance,
                )
            }
            Profile::Vertical { .. } => (0.0, w * self.compliance),
            Profile::Straight { .. } => (0.0, 0.0),
        };
        self.to_space([0.0; 3], ddx, ddz)
    }

    /// The force the line exerts on the point at `end` (C12): the tension
    /// pulling the point along the line.
    pub fn end_force(&self, end: LineEnd) -> [f64; 3] {
        let (s, sign) = match end {
            LineEnd::A => (0.0, 1.0),
            LineEnd::B => (self.line.length, -1.0),
        };
        self.to_space(
            [0.0; 3],
            sign * self.horizontal_tension,
            sign * self.vertical_tension(s),
        )
    }

    /// The sag (C13): the largest distance from the chord to the curve,
    /// measured along gravity (positive below the chord, negative for a
    /// buoyant line above it, 0 for a straight line).
    pub fn sag(&self) -> f64 {
        if self.profile != Profile::Hanging {
            return 0.0;
        }
        let slope = self.rise / self.span;
        let s_extreme = ((self.horizontal_tension * slope - self.vertical_force_a)
            / self.line.weight)
            .clamp(0.0, self.line.length);
        let (x, z) = self.plane().position(s_extreme);
        slope * x - z
    }

    fn plane(&self) -> Plane {
        Plane {
            horizontal: self.horizontal_tension,
            vertical_a: self.vertical_force_a,
            weight: self.line.weight,
            compliance: self.compliance,
        }
    }

    /// base + x e_x + z e_z.
    fn to_space(&self, base: [f64; 3], x: f64, z: f64) -> [f64; 3] {
        std::array::from_fn(|i| base[i] + x * self.horizontal_axis[i] + z * self.up[i])
    }
}

/// The in-plane catenary of given (H, V_A): (C1)-(C5), (C8).
#[derive(Clone, Copy, Debug)]
pub(super) struct Plane {
    pub(super) horizontal: f64,
    pub(super) vertical_a: f64,
    pub(super) weight: f64,
    pub(super) compliance: f64,
}

impl Plane {
    fn tension(&self, s: f64) -> f64 {
        self.horizontal.hypot(self.vertical_a + self.weight * s)
    }

    /// int_0^s 1/T ds' (so that the catenary part of (C3) is H times it),
    /// by (C5).
    pub(super) fn inverse_tension_integral(&self, s: f64) -> f64 {
        let (h, w, va) = (self.horizontal, self.weight, self.vertical_a);
        let v = va + w * s;
        let (ta, t) = (h.hypot(va), h.hypot(v));
        if v * va > 0.0 {
            let q = (v + va) / (v * ta + va * t);
            s * q * asinh_over_argument(w * s * q)
        } else if w * s != 0.0 {
            ((v / h).asinh() - (va / h).asinh()) / w
        } else {
            s / ta
        }
    }

    /// (x(s), z(s)) by (C3)-(C5).
    pub(super) fn position(&self, s: f64) -> (f64, f64) {
        let (h, w, va) = (self.horizontal, self.weight, self.vertical_a);
        let v = va + w * s;
        let (ta, t) = (h.hypot(va), h.hypot(v));
        let x = h * (s * self.compliance + self.inverse_tension_integral(s));
        let z = (va * s + 0.5 * w * s * s) * self.compliance + s * (v + va) / (t + ta);
        (x, z)
    }
}

/// asinh(y)/y, with its series near y = 0 (error below y^8/30).
fn asinh_over_argument(y: f64) -> f64 {
    if y.abs() < 1e-3 {
        let y2 = y * y;
        1.0 - y2 * (1.0 / 6.0 - y2 * (3.0 / 40.0 - y2 * (5.0 / 112.0)))
    } else {
        y.asinh() / y
    }
}

/// A unit vector perpendicular to the unit vector `axis`.
pub(super) fn any_perpendicular(axis: [f64; 3]) -> [f64; 3] {
    let mut least = 0;
    for i in 1..3 {
        if axis[i].abs() < axis[least].abs() {
            least = i;
        }
    }
    let mut unit = [0.0; 3];
    unit[least] = 1.0;
    let perpendicular = sub(unit, scale(axis[least], axis));
    scale(1.0 / norm(perpendicular), perpendicular)
}
