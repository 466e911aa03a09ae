//! The line resting on the seabed for given fairlead forces (HF, VF): its
//! profile (C14)-(C17), closure (C18) and Jacobian (C19); Newton on (C18)
//! from the guess (C21) within the bound (C20).

use super::super::profile::Plane;
use super::TouchdownLine;
use crate::catenary::solve::{newton_on_closure, ClosureSteps};
use crate::catenary::CatenaryError;

/// A line with its anchor on the seabed and fairlead forces (HF, VF),
/// 0 < VF <= W L, HF > 0, W > 0.
#[derive(Clone, Copy, Debug)]
pub(in crate::catenary) struct RestingLine {
    pub(in crate::catenary) hf: f64,
    pub(in crate::catenary) vf: f64,
    pub(in crate::catenary) length: f64,
    pub(in crate::catenary) weight: f64,
    /// 1/EA (0 for an inextensible line).
    pub(in crate::catenary) compliance: f64,
    pub(in crate::catenary) friction: f64,
}

impl RestingLine {
    /// Ls = VF/W (C14).
    pub(in crate::catenary) fn suspended_length(&self) -> f64 {
        self.vf / self.weight
    }

    /// LB = L - VF/W (C14).
    pub(in crate::catenary) fn resting_length(&self) -> f64 {
        self.length - self.suspended_length()
    }

    /// The friction force per resting length, CB W.
    fn friction_per_length(&self) -> f64 {
        self.friction * self.weight
    }

    /// s0 = max(LB - HF/(CB W), 0) (C15).
    pub(in crate::catenary) fn slack_length(&self) -> f64 {
        let friction = self.friction_per_length();
        if friction == 0.0 {
            0.0
        } else {
            (self.resting_length() - self.hf / friction).max(0.0)
        }
    }

    /// HA = max(HF - CB W LB, 0) (C15).
    pub(in crate::catenary) fn anchor_tension(&self) -> f64 {
        (self.hf - self.friction_per_length() * self.resting_length()).max(0.0)
    }

    /// T(s) of (C15).
    pub(in crate::catenary) fn tension(&self, s: f64) -> f64 {
        let resting_length = self.resting_length();
        if s >= resting_length {
            self.hf.hypot(self.weight * (s - resting_length))
        } else {
            let slack_length = self.slack_length();
            if s <= slack_length {
                0.0
            } else {
                self.anchor_tension() + self.friction_per_length() * (s - slack_length)
            }
        }
    }

    /// S(s) = int_0^s T ds' on the seabed, 0 <= s <= LB (C16).
    fn stretch_integral(&self, s: f64) -> f64 {
        let taut = s - self.slack_length();
        if taut <= 0.0 {
            0.0
        } else {
            taut * (self.anchor_tension() + 0.5 * self.friction_per_length() * taut)
        }
    }

    /// The suspended part: the catenary (C3)-(C5) with H = HF and V = 0 at
    /// its start.
    fn suspended(&self) -> Plane {
        Plane {
            horizontal: self.hf,
            vertical_a: 0.0,
            weight: self.weight,
            compliance: self.compliance,
        }
    }

    /// (x(s), z(s)) by (C16) on the seabed, (C17) above it.
    pub(in crate::catenary) fn position(&self, s: f64) -> (f64, f64) {
        let resting_length = self.resting_length();
        if s <= resting_length {
            return (s + self.stretch_integral(s) * self.compliance, 0.0);
        }
        let touchdown_x = resting_length + self.stretch_integral(resting_length) * self.compliance;
        let (x, z) = self.suspended().position(s - resting_length);
        (touchdown_x + x, z)
    }

    /// The Jacobian (C19) of (x(L), z(L)) with respect to (HF, VF):
    /// [[dXF/dHF, dXF/dVF], [dZF/dHF, dZF/dVF]].
    pub(in crate::catenary) fn jacobian(&self) -> [[f64; 2]; 2] {
        let (hf, vf, w, c) = (self.hf, self.vf, self.weight, self.compliance);
        let suspended_length = self.suspended_length();
        let taut_resting_length = self.resting_length() - self.slack_length();
        let tf = hf.hypot(vf);
        let a = vf * vf / (w * tf * (tf + hf));
        let dx_dh =
            (suspended_length + taut_resting_length) * c + asinh_minus_sine_of_angle(vf / hf) / w;
        let dx_dv = -a + (hf - self.anchor_tension()) * c / w;
        let dz_dv = suspended_length * (1.0 / tf + c);
        [[dx_dh, dx_dv], [-a, dz_dv]]
    }

    /// The forces moved by alpha step, VF projected onto VF <= W L (LB >= 0).
    fn stepped(&self, alpha: f64, step: [f64; 2]) -> RestingLine {
        let full_weight = self.weight * self.length;
        self.with_forces(
            self.hf + alpha * step[0],
            (self.vf + alpha * step[1]).min(full_weight),
        )
    }

    /// The same line under other fairlead forces.
    pub(in crate::catenary) fn with_forces(&self, hf: f64, vf: f64) -> RestingLine {
        RestingLine { hf, vf, ..*self }
    }
}

/// asinh(y) - y/sqrt(1 + y^2), the integral of y^2 (1 + y^2)^(-3/2), by its
/// series for |y| < 1e-2 (next term 315 y^11/1408, below 1e-16 y^3):
/// y^3/3 - 3 y^5/10 + 15 y^7/56 - 35 y^9/144.
fn asinh_minus_sine_of_angle(y: f64) -> f64 {
    if y.abs() < 1e-2 {
        let y2 = y * y;
        y * y2 * (1.0 / 3.0 - y2 * (3.0 / 10.0 - y2 * (15.0 / 56.0 - y2 * (35.0 / 144.0))))
    } else {
        y.asinh() - y / y.hypot(1.0)
    }
}

/// V0/W of (C20): the suspended length of the "L"-shaped line (HF -> 0)
/// reaching height ZF, 2 ZF/(1 + sqrt(1 + 2 W ZF/EA)).
pub(super) fn vertical_reach_length(weight: f64, compliance: f64, zf: f64) -> f64 {
    2.0 * zf / (1.0 + (1.0 + 2.0 * weight * zf * compliance).sqrt())
}

/// Newton on (C18) with the Jacobian (C19) from the guess (C21); the
/// caller has established that the line touches down (W > 0, the free
/// catenary's V_A < 0). Refuses lines longer than L_max (C20).
pub(in crate::catenary) fn solve_resting(
    line: &TouchdownLine,
    xf: f64,
    zf: f64,
) -> Result<(RestingLine, usize), CatenaryError> {
    let compliance = 1.0 / line.ea;
    let (length, weight) = (line.length, line.weight);
    let vertical_reach = vertical_reach_length(weight, compliance, zf);
    if length >= xf + vertical_reach {
        return Err(CatenaryError::NoSolution {
            reason: "the line is too long to lie straight on the seabed (L >= L_max): \
                     it would fold back on itself",
        });
    }
    let residual_of = |r: &RestingLine| {
        let (x, z) = r.position(length);
        [x - xf, z - zf]
    };
    newton_on_closure(
        initial_guess(line, compliance, xf, zf, vertical_reach),
        length.max(xf.hypot(zf)),
        ClosureSteps {
            residual: &residual_of,
            newton_step: &newton_step,
            polish: &|resting, step| Some(resting.stepped(step_length_inside(resting, step), step)),
            advance: &|resting, step, residual| armijo_step(resting, step, residual, &residual_of),
        },
    )
}

/// The step from `resting` along `step`, from the longest that stays
/// inside the admissible states, halved until the squared residual falls
/// by the Armijo fraction 1e-4 of its linear prediction (-2 alpha |r|^2);
/// the new state and its residual.
fn armijo_step(
    resting: &RestingLine,
    step: [f64; 2],
    residual: [f64; 2],
    residual_of: &dyn Fn(&RestingLine) -> [f64; 2],
) -> (RestingLine, [f64; 2]) {
    let residual_norm = residual[0].hypot(residual[1]);
    let mut alpha = step_length_inside(resting, step);
    loop {
        let candidate = resting.stepped(alpha, step);
        let candidate_residual = residual_of(&candidate);
        let candidate_norm = candidate_residual[0].hypot(candidate_residual[1]);
        if candidate_norm * candidate_norm <= (1.0 - 2e-4 * alpha) * residual_norm * residual_norm
            || alpha < 1e-10
        {
            return (candidate, candidate_residual);
        }
        alpha *= 0.5;
    }
}

/// d = -J^-1 residual with J of (C19), or None if J is singular in
/// floating point.
fn newton_step(resting: &RestingLine, residual: [f64; 2]) -> Option<[f64; 2]> {
    let [[j_xh, j_xv], [j_zh, j_zv]] = resting.jacobian();
    let determinant = j_xh * j_zv - j_xv * j_zh;
    if !(determinant != 0.0 && determinant.is_finite()) {
        return None;
    }
    Some([
        -(j_zv * residual[0] - j_xv * residual[1]) / determinant,
        -(j_xh * residual[1] - j_zh * residual[0]) / determinant,
    ])
}

/// The largest step fraction, at most 1, that keeps HF above a tenth of
/// its value and VF above a tenth of its value (VF's upper bound W L is
/// kept by projection, [`RestingLine::stepped`]).
fn step_length_inside(resting: &RestingLine, step: [f64; 2]) -> f64 {
    let mut alpha: f64 = 1.0;
    if step[0] < 0.0 {
        alpha = alpha.min(0.9 * resting.hf / -step[0]);
    }
    if step[1] < 0.0 {
        alpha = alpha.min(0.9 * resting.vf / -step[1]);
    }
    alpha
}

/// (C21): the Peyrot-Goulois guess of Jonkman's and MoorDyn's `Catenary`,
/// VF0 moved into [V0 + (W L - V0)/10, W L - (W L - V0)/10] (C20).
fn initial_guess(
    line: &TouchdownLine,
    compliance: f64,
    xf: f64,
    zf: f64,
    vertical_reach: f64,
) -> RestingLine {
    let (length, weight) = (line.length, line.weight);
    let lambda = if length <= xf.hypot(zf) {
        0.2
    } else {
        (3.0 * ((length * length - zf * zf) / (xf * xf) - 1.0)).sqrt()
    };
    let hf = (0.5 * weight * xf / lambda).max(f64::MIN_POSITIVE);
    let (lowest, highest) = (weight * vertical_reach, weight * length);
    let margin = 0.1 * (highest - lowest);
    let vf =
        (0.5 * weight * (zf / lambda.tanh() + length)).clamp(lowest + margin, highest - margin);
    RestingLine {
        hf,
        vf,
        length,
        weight,
        compliance,
        friction: line.friction,
    }
}
