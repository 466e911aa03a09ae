//! The elastic catenary: the closed-form static shape of a uniform line
//! hanging between two points (Irvine, *Cable Structures*, 1981, §2.2; the
//! form of MoorDyn's and MAP++'s catenary without seabed contact). It
//! seeds static solves of mooring lines and validates the finite-element
//! statics.
//!
//! # The line and its plane
//!
//! A line of unstretched length L, weight w per unstretched length (the
//! force per length along the gravity direction g_hat; w < 0 is a buoyant
//! line, w = 0 a weightless one) and axial stiffness EA (infinite:
//! inextensible) joins ends A and B. With e_z = -g_hat (up), the rise is
//! v = (B - A) . e_z and the horizontal span h = |B - A - v e_z|; e_x is the
//! unit horizontal from A towards B. The line lies in the plane of e_x and
//! e_z, r(s) = A + x(s) e_x + z(s) e_z, with s the unstretched arc length
//! from A.
//!
//! # Equations
//!
//! Let (H, V(s)) be the components along (e_x, e_z) of the tension force
//! T(s) t(s) that the part beyond s exerts on the part before it (t the unit
//! tangent towards B). The balance of the piece (s, s + ds) under its
//! weight w ds (along -e_z) makes the horizontal component constant and
//!
//! ```text
//!   V(s) = V_A + w s,    T(s) = sqrt(H^2 + V(s)^2)                        (C1)
//! ```
//!
//! V_A > 0 means the line leaves A upwards. An element ds stretches to
//! (1 + T/EA) ds along t = (H, V)/T, so
//!
//! ```text
//!   dx/ds = H (1/T + 1/EA),    dz/ds = V (1/T + 1/EA)                     (C2)
//! ```
//!
//! and, integrating with d/dV asinh(V/H) = 1/T and d/dV T = V/T (dV = w ds),
//!
//! ```text
//!   x(s) = H s/EA + (H/w) [asinh(V(s)/H) - asinh(V_A/H)]                  (C3)
//!   z(s) = (V_A s + w s^2/2)/EA + (T(s) - T_A)/w,      T_A = T(0)          (C4)
//! ```
//!
//! Both brackets cancel when V(s) is close to V_A (small w s) or when V/H
//! is large with one sign. They are evaluated in forms without the
//! cancellation and without the division by w (the identity
//! asinh a - asinh b = asinh(a sqrt(1 + b^2) - b sqrt(1 + a^2)), then
//! a^2 - b^2 = (a - b)(a + b)):
//!
//! ```text
//!   (T - T_A)/w = s (V + V_A)/(T + T_A)
//!   (H/w) [asinh(V/H) - asinh(V_A/H)] = H s q asinh(w s q)/(w s q),
//!        q = (V + V_A)/(V T_A + V_A T)          when V V_A > 0           (C5)
//! ```
//!
//! (asinh(y)/y by its series for |y| < 1e-3; when V and V_A differ in
//! sign the two asinh in (C3) add and are used as written). The second derivative follows from (C2) with
//! d/ds (V/T) = w H^2/T^3 and d/ds (H/T) = -w H V/T^3:
//!
//! ```text
//!   x'' = -w H V/T^3,    z'' = w H^2/T^3 + w/EA                           (C6)
//! ```
//!
//! # Solving for H and V_A
//!
//! The end conditions x(L) = h, z(L) = v are the stationarity conditions of
//!
//! ```text
//!   Psi(H, V_A) = int_0^L (T + T^2/(2 EA)) ds - H h - V_A v                 (C7)
//! ```
//!
//! (dPsi/dH = x(L) - h, dPsi/dV_A = z(L) - v by (C2)): the line's
//! complementary energy minus the work of the end forces. T is a norm of
//! an affine function of (H, V_A), so Psi is convex, and strictly so unless
//! w = 0 and EA is infinite; its Hessian, the exact Jacobian of the end
//! conditions, is
//!
//! ```text
//!   J = L/EA I + int_0^L [ V^2  -H V ; -H V  H^2 ] / T^3 ds,
//!   K = int H^2/T^3 ds = (V_B/T_B - V_A/T_A)/w,
//!   J_HH = L/EA + int 1/T ds - K,   J_VV = L/EA + K,
//!   J_HV = (H/w)(1/T_B - 1/T_A) = -H L (V_A + V_B)/((T_A + T_B) T_A T_B)   (C8)
//! ```
//!
//! with K, like (C5), evaluated as H^2 L (V_A + V_B)/((V_B T_A + V_A T_B)
//! T_A T_B) when V_A V_B > 0. Newton's step d = -J^-1 grad Psi is a descent
//! direction of the convex Psi; along it the slope g(a) = d . grad
//! Psi(x + a d) increases with a, so each step is safeguarded by a
//! one-dimensional search on g: the full step (shortened to keep H > 0) is
//! taken unless it overshoots the line minimum, i.e. g > |g(0)|/2, and
//! otherwise the Illinois method brackets a step with |g| <= |g(0)|/2. The
//! iteration stops when |(x(L) - h, z(L) - v)| <= 1e-13 max(L, chord),
//! after one more (polishing) Newton step. It starts from the guess of
//! Peyrot and Goulois (1979), as in MoorDyn, for w > 0 (mirrored for w < 0)
//!
//! ```text
//!   lambda0 = sqrt(3 ((L^2 - v^2)/h^2 - 1))  (slack),   0.2  (chord >= L)
//!   H0 = |w| h/(2 lambda0),   V_A0 = (|w|/2) (v_m / tanh(lambda0) - L)      (C9)
//! ```
//!
//! (v_m = v sign(w), V_A0 multiplied by sign(w)), except for a nearly
//! straight line, where (C9) is poor (it ignores EA): there the shallow
//! parabola, whose length exceeds the chord c by w_n^2 c^3/(24 T^2) with
//! w_n = |w| h/c the weight normal to the chord, gives the tension T0 as
//! the root of
//!
//! ```text
//!   c - L = T L/EA - w_n^2 L^3/(24 T^2),    H0 = T0 h/c,  V_A0 = T0 v/c - w L/2   (C9')
//! ```
//!
//! used when T0 >= 4 |w| L (the weight's share of the tension small).
//!
//! # Special cases, in closed form
//!
//! A weightless line (w = 0) that is taut (chord c >= L, EA finite) is
//! straight with the uniform tension
//!
//! ```text
//!   T = EA (c/L - 1),    r(s) = A + (s/L)(B - A)                          (C10)
//! ```
//!
//! A weighted line with h = 0 hangs vertically, straight, when its tension
//! is nowhere negative: with sigma = sign(v),
//!
//! ```text
//!   H = 0,  V_A = EA (v - sigma L)/L - w L/2,   z(s) = sigma s + (V_A s + w s^2/2)/EA,
//!   T(s) = sigma V(s) >= 0 on [0, L]  <=>  |v| >= L (1 + |w| L/(2 EA))       (C11)
//! ```
//!
//! No solution exists, and an error says why, when h = 0 and the line is
//! slack (it would fold onto itself), when w = 0 and c < L (no defined
//! shape), when an inextensible line (EA infinite) would have to stretch
//! (c > L; c = L too for a weighted line with h > 0), or when its tension
//! is indeterminate (c = L with w = 0, or with h = 0). A span below 8
//! machine epsilons of the chord is taken as h = 0.
//!
//! # Forces and sag
//!
//! The force the line exerts on the point at A is the tension pulling it
//! along the line, T t at s = 0; at B it is the opposite of T t at s = L:
//!
//! ```text
//!   F_A = H e_x + V_A e_z,   F_B = -H e_x - V_B e_z,   F_A + F_B = w L g_hat  (C12)
//! ```
//!
//! (the points carry the line's weight). The sag is the distance from the
//! chord to the curve measured along g_hat, at its extreme, the point where
//! the tangent is parallel to the chord (V(s*) = H v/h):
//!
//! ```text
//!   sag = z_chord(x(s*)) - z(s*) = v x(s*)/h - z(s*),  s* = (H v/h - V_A)/w   (C13)
//! ```
//!
//! positive for a line hanging below its chord (w > 0), negative for a
//! buoyant one bulging above it, zero for a straight line.

use std::fmt;

mod profile;
mod solve;
pub mod touchdown;

use crate::vec3::{dot, norm, scale, sub};
use profile::any_perpendicular;
use solve::{solve_hanging, straight_profile, vertical_profile};

/// The line: unstretched length (m), weight per unstretched length along
/// the gravity direction (N/m; negative for a buoyant line) and axial
/// stiffness EA (N; `f64::INFINITY` for an inextensible line).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CatenaryLine {
    pub length: f64,
    pub weight: f64,
    pub ea: f64,
}

/// Why no catenary was built.
#[derive(Clone, Debug, PartialEq)]
pub enum CatenaryError {
    /// An input is not finite or out of its range; `what` names it.
    InvalidInput { what: &'static str, value: f64 },
    /// The inputs are valid but no static shape exists (or it is not
    /// unique); `reason` says why.
    NoSolution { reason: &'static str },
    /// Newton did not reach the tolerance (should not happen for valid
    /// inputs; reported rather than returned as a wrong shape).
    NotConverged { iterations: usize, residual: f64 },
}

impl fmt::Display for CatenaryError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            CatenaryError::InvalidInput { what, value } => {
                write!(f, "catenary: invalid {what} ({value:e})")
            }
            CatenaryError::NoSolution { reason } => write!(f, "catenary: no solution: {reason}"),
            CatenaryError::NotConverged {
                iterations,
                residual,
            } => write!(
                f,
                "catenary: Newton did not converge in {iterations} iterations \
                 (relative closure residual {residual:e})"
            ),
        }
    }
}

impl std::error::Error for CatenaryError {}

/// An end of the line: A at s = 0, B at s = L.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum LineEnd {
    A,
    B,
}

/// The in-plane shape, by the case that produced it.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Profile {
    /// H > 0, w != 0: (C3)-(C6).
    Hanging,
    /// h = 0, w != 0: the vertical line (C11), sigma = sign(v).
    Vertical { sigma: f64 },
    /// w = 0, taut: the straight chord (C10) with its uniform tension.
    Straight { tension: f64 },
}

/// A solved elastic catenary between two points.
#[derive(Clone, Debug)]
pub struct Catenary {
    line: CatenaryLine,
    /// 1/EA (0 for an inextensible line).
    compliance: f64,
    origin: [f64; 3],
    horizontal_axis: [f64; 3],
    up: [f64; 3],
    span: f64,
    rise: f64,
    horizontal_tension: f64,
    vertical_force_a: f64,
    profile: Profile,
    iterations: usize,
}

/// A span below this fraction of the chord is a vertical line (h = 0).
const VERTICAL_SPAN_FRACTION: f64 = 8.0 * f64::EPSILON;

impl Catenary {
    /// The catenary of `line` from `a` to `b` under gravity along
    /// `gravity_direction` (any nonzero vector; only its direction counts).
    pub fn between(
        line: CatenaryLine,
        a: [f64; 3],
        b: [f64; 3],
        gravity_direction: [f64; 3],
    ) -> Result<Catenary, CatenaryError> {
        validate(&line, a, b, gravity_direction)?;
        let up = scale(-1.0 / norm(gravity_direction), gravity_direction);
        let chord_vector = sub(b, a);
        let rise = dot(chord_vector, up);
        let horizontal = sub(chord_vector, scale(rise, up));
        let mut span = norm(horizontal);
        let horizontal_axis = if span > VERTICAL_SPAN_FRACTION * norm(chord_vector) {
            scale(1.0 / span, horizontal)
        } else {
            span = 0.0;
            any_perpendicular(up)
        };
        let compliance = 1.0 / line.ea;
        let mut catenary = Catenary {
            line,
            compliance,
            origin: a,
            horizontal_axis,
            up,
            span,
            rise,
            horizontal_tension: 0.0,
            vertical_force_a: 0.0,
            profile: Profile::Hanging,
            iterations: 0,
        };
        let chord = span.hypot(rise);
        if line.weight == 0.0 {
            catenary.profile = straight_profile(&line, chord)?;
            if let Profile::Straight { tension } = catenary.profile {
                catenary.horizontal_tension = tension * span / chord;
                catenary.vertical_force_a = tension * rise / chord;
            }
        } else if span == 0.0 {
            let (vertical_force_a, sigma) = vertical_profile(&line, rise)?;
            catenary.vertical_force_a = vertical_force_a;
            catenary.profile = Profile::Vertical { sigma };
        } else {
            if line.ea == f64::INFINITY && chord >= line.length {
                return Err(CatenaryError::NoSolution {
                    reason: "an inextensible weighted line cannot reach a chord \
                             as long as or longer than itself",
                });
            }
            let (plane, iterations) = solve_hanging(&line, compliance, span, rise)?;
            catenary.horizontal_tension = plane.horizontal;
            catenary.vertical_force_a = plane.vertical_a;
            catenary.iterations = iterations;
        }
        Ok(catenary)
    }

    /// The line this catenary was built for.
    pub fn line(&self) -> CatenaryLine {
        self.line
    }

    /// Horizontal span h >= 0 and rise v = (B - A) . up of the chord.
    pub fn span_and_rise(&self) -> (f64, f64) {
        (self.span, self.rise)
    }

    /// Unit vectors e_x (horizontal, from A towards B; an arbitrary
    /// horizontal when h = 0) and e_z = -g_hat of the line's plane.
    pub fn plane_axes(&self) -> ([f64; 3], [f64; 3]) {
        (self.horizontal_axis, self.up)
    }

    /// Newton iterations of the solve (0 for the closed-form cases).
    pub fn iterations(&self) -> usize {
        self.iterations
    }

    /// The horizontal component H of the tension (N), constant along the
    /// line (C1).
    pub fn horizontal_tension(&self) -> f64 {
        self.horizontal_tension
    }

    /// The vertical component V(s) = V_A + w s of the tension force (N),
    /// positive when the tension pulls the part before s upwards (C1).
    pub fn vertical_tension(&self, s: f64) -> f64 {
        self.vertical_force_a + self.line.weight * s
    }
}

fn validate(
    line: &CatenaryLine,
    a: [f64; 3],
    b: [f64; 3],
    gravity_direction: [f64; 3],
) -> Result<(), CatenaryError> {
    let invalid = |what, value| Err(CatenaryError::InvalidInput { what, value });
    if !(line.length.is_finite() && line.length > 0.0) {
        return invalid("length (must be finite and > 0)", line.length);
    }
    if !line.weight.is_finite() {
        return invalid("weight per length (must be finite)", line.weight);
    }
    if line.ea.is_nan() || line.ea <= 0.0 {
        return invalid("axial stiffness EA (must be > 0, may be infinite)", line.ea);
    }
    if let Some(&value) = a.iter().find(|c| !c.is_finite()) {
        return invalid("end A (coordinates must be finite)", value);
    }
    if let Some(&value) = b.iter().find(|c| !c.is_finite()) {
        return invalid("end B (coordinates must be finite)", value);
    }
    let g = norm(gravity_direction);
    if !(g.is_finite() && g > 0.0) {
        return invalid("gravity direction (must be finite and nonzero)", g);
    }
    Ok(())
}

#[cfg(test)]
mod tests;
#[cfg(test)]
mod touchdown_tests;
