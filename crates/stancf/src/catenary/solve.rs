//! Solving for the end forces: the closed-form weightless (C10) and
//! vertical (C11) lines, and Newton on (C7) for the hanging line (H, V_A)
//! with the exact Jacobian (C8), the starting guesses (C9)/(C9') and the
//! safeguarded step.

use super::profile::Plane;
use super::{CatenaryError, CatenaryLine, Profile};

/// Relative closure residual at which Newton stops (before its polishing
/// step), relative to max(L, chord).
const CLOSURE_TOLERANCE: f64 = 1e-13;
const MAX_NEWTON_ITERATIONS: usize = 200;

/// The weightless line (C10).
pub(super) fn straight_profile(line: &CatenaryLine, chord: f64) -> Result<Profile, CatenaryError> {
    if chord < line.length {
        return Err(CatenaryError::NoSolution {
            reason: "a weightless line longer than its chord is slack and has no \
                     defined shape",
        });
    }
    if line.ea == f64::INFINITY {
        return Err(CatenaryError::NoSolution {
            reason: if chord == line.length {
                "a weightless inextensible line exactly as long as its chord has an \
                 indeterminate tension"
            } else {
                "an inextensible line cannot reach a chord longer than itself"
            },
        });
    }
    Ok(Profile::Straight {
        tension: line.ea * ((chord - line.length) / line.length),
    })
}

/// The vertical line (C11): V_A and sigma = sign(v).
pub(super) fn vertical_profile(
    line: &CatenaryLine,
    rise: f64,
) -> Result<(f64, f64), CatenaryError> {
    let fold = CatenaryError::NoSolution {
        reason: "a vertical (zero-span) line that is slack would fold onto itself",
    };
    if rise == 0.0 {
        return Err(fold);
    }
    if line.ea == f64::INFINITY {
        return Err(CatenaryError::NoSolution {
            reason: if rise.abs() < line.length {
                "a vertical (zero-span) line that is slack would fold onto itself"
            } else if rise.abs() == line.length {
                "a vertical inextensible line exactly as long as its chord has an \
                 indeterminate tension"
            } else {
                "an inextensible line cannot reach a chord longer than itself"
            },
        });
    }
    let (length, w) = (line.length, line.weight);
    let sigma = rise.signum();
    let vertical_a = line.ea * ((rise - sigma * length) / length) - 0.5 * w * length;
    let vertical_b = vertical_a + w * length;
    if sigma * vertical_a < 0.0 || sigma * vertical_b < 0.0 {
        return Err(fold);
    }
    Ok((vertical_a, sigma))
}

/// The Newton side of the in-plane catenary: (C8) and steps in (H, V_A).
impl Plane {
    /// The Jacobian (C8) of (x(L), z(L)) with respect to (H, V_A):
    /// [J_HH, J_HV, J_VV].
    fn jacobian(&self, length: f64) -> [f64; 3] {
        let (h, w, va) = (self.horizontal, self.weight, self.vertical_a);
        let vb = va + w * length;
        let (ta, tb) = (h.hypot(va), h.hypot(vb));
        let k = if va * vb > 0.0 {
            h * h * length * (va + vb) / ((vb * ta + va * tb) * ta * tb)
        } else if w != 0.0 {
            (vb / tb - va / ta) / w
        } else {
            length * h * h / (ta * ta * ta)
        };
        let elastic = length * self.compliance;
        let j_hh = elastic + (self.inverse_tension_integral(length) - k).max(0.0);
        let j_hv = -h * length * (va + vb) / ((ta + tb) * ta * tb);
        [j_hh, j_hv, elastic + k]
    }

    fn stepped(&self, alpha: f64, step: [f64; 2]) -> Plane {
        Plane {
            horizontal: self.horizontal + alpha * step[0],
            vertical_a: self.vertical_a + alpha * step[1],
            ..*self
        }
    }
}

/// The closure residual (x(L) - h, z(L) - v), the gradient of (C7).
fn closure_residual(plane: &Plane, length: f64, span: f64, rise: f64) -> [f64; 2] {
    let (x, z) = plane.position(length);
    [x - span, z - rise]
}

/// Newton on (C7) with the exact Jacobian (C8), from the guess (C9),
/// each step shortened by [`safeguarded_step_length`].
pub(super) fn solve_hanging(
    line: &CatenaryLine,
    compliance: f64,
    span: f64,
    rise: f64,
) -> Result<(Plane, usize), CatenaryError> {
    let length = line.length;
    let residual_of = |plane: &Plane| closure_residual(plane, length, span, rise);
    newton_on_closure(
        initial_guess(line, compliance, span, rise),
        length.max(span.hypot(rise)),
        ClosureSteps {
            residual: &residual_of,
            newton_step: &|plane, residual| newton_step(plane, length, residual),
            polish: &|plane, step| {
                let candidate = plane.stepped(1.0, step);
                (candidate.horizontal > 0.0).then_some(candidate)
            },
            advance: &|plane, step, residual| {
                let alpha = safeguarded_step_length(plane, step, residual, length, span, rise);
                let next = plane.stepped(alpha, step);
                let r = residual_of(&next);
                (next, r)
            },
        },
    )
}

/// The two closure equations' residual (or Newton step) at a state.
type Pair = [f64; 2];

/// What [`newton_on_closure`] needs of one closure problem with unknowns
/// of type S: its residual (the fairlead's miss, in metres), the Newton
/// step -J^-1 r (None where J is singular), the full step used to
/// polish a converged state (None if it leaves the admissible states),
/// and a safeguarded step with its new residual.
pub(super) struct ClosureSteps<'a, S> {
    pub residual: &'a dyn Fn(&S) -> Pair,
    pub newton_step: &'a dyn Fn(&S, Pair) -> Option<Pair>,
    pub polish: &'a dyn Fn(&S, Pair) -> Option<S>,
    pub advance: &'a dyn Fn(&S, Pair, Pair) -> (S, Pair),
}

/// Newton on a two-equation closure (C7) or (C18) from `start`: stops
/// when |r| <= 1e-13 `scale` after one polishing step, kept only if it
/// does not undo the closure (round-off can make it useless, never
/// harmful). Returns the state and the iterations, or the residual
/// relative to `scale` where it stopped.
pub(super) fn newton_on_closure<S>(
    start: S,
    scale: f64,
    steps: ClosureSteps<S>,
) -> Result<(S, usize), CatenaryError> {
    let tolerance = CLOSURE_TOLERANCE * scale;
    let mut state = start;
    let mut residual = (steps.residual)(&state);
    let mut polished = false;
    for iteration in 0..MAX_NEWTON_ITERATIONS {
        let residual_norm = residual[0].hypot(residual[1]);
        let converged = residual_norm <= tolerance;
        let failure = CatenaryError::NotConverged {
            iterations: iteration,
            residual: residual_norm / scale,
        };
        if !residual_norm.is_finite() {
            return Err(failure);
        }
        if converged && polished {
            return Ok((state, iteration));
        }
        let Some(step) = (steps.newton_step)(&state, residual) else {
            return if converged {
                Ok((state, iteration))
            } else {
                Err(failure)
            };
        };
        if converged {
            polished = true;
            if let Some(candidate) = (steps.polish)(&state, step) {
                let candidate_residual = (steps.residual)(&candidate);
                if candidate_residual[0].hypot(candidate_residual[1]) <= residual_norm {
                    (state, residual) = (candidate, candidate_residual);
                }
            }
            continue;
        }
        (state, residual) = (steps.advance)(&state, step, residual);
    }
    Err(CatenaryError::NotConverged {
        iterations: MAX_NEWTON_ITERATIONS,
        residual: residual[0].hypot(residual[1]) / scale,
    })
}

/// d = -J^-1 residual, or None if J is not positive definite in floating
/// point.
fn newton_step(plane: &Plane, length: f64, residual: [f64; 2]) -> Option<[f64; 2]> {
    let [j_hh, j_hv, j_vv] = plane.jacobian(length);
    let determinant = j_hh * j_vv - j_hv * j_hv;
    if !(determinant > 0.0 && determinant.is_finite()) {
        return None;
    }
    Some([
        -(j_vv * residual[0] - j_hv * residual[1]) / determinant,
        -(j_hh * residual[1] - j_hv * residual[0]) / determinant,
    ])
}

/// The step length along the Newton direction: the full step, shortened
/// to keep H above a tenth of its value, unless the slope of the convex
/// (C7) along it, g(a) = step . residual(a), overshoots past |g(0)|/2;
/// then the Illinois method finds a with |g(a)| <= |g(0)|/2.
fn safeguarded_step_length(
    plane: &Plane,
    step: [f64; 2],
    residual: [f64; 2],
    length: f64,
    span: f64,
    rise: f64,
) -> f64 {
    let slope = |alpha: f64| {
        let r = closure_residual(&plane.stepped(alpha, step), length, span, rise);
        step[0] * r[0] + step[1] * r[1]
    };
    let slope_0 = step[0] * residual[0] + step[1] * residual[1];
    let mut alpha_max = 1.0;
    if step[0] < 0.0 {
        alpha_max = f64::min(1.0, 0.9 * plane.horizontal / -step[0]);
    }
    let accepted = 0.5 * slope_0.abs();
    let slope_max = slope(alpha_max);
    if slope_0.is_nan() || slope_0 >= 0.0 || slope_max <= accepted {
        return alpha_max;
    }
    // Bracket [lo, hi] with g(lo) < 0 < g(hi); Illinois regula falsi.
    let (mut lo, mut slope_lo, mut hi, mut slope_hi) = (0.0, slope_0, alpha_max, slope_max);
    let mut last_side = 0;
    for _ in 0..60 {
        let alpha = (lo * slope_hi - hi * slope_lo) / (slope_hi - slope_lo);
        let slope_alpha = slope(alpha);
        if slope_alpha.abs() <= accepted || !slope_alpha.is_finite() {
            return if slope_alpha.is_finite() { alpha } else { lo };
        }
        if slope_alpha < 0.0 {
            (lo, slope_lo) = (alpha, slope_alpha);
            if last_side == -1 {
                slope_hi *= 0.5;
            }
            last_side = -1;
        } else {
            (hi, slope_hi) = (alpha, slope_alpha);
            if last_side == 1 {
                slope_lo *= 0.5;
            }
            last_side = 1;
        }
    }
    if lo > 0.0 {
        lo
    } else {
        0.5 * hi
    }
}

/// The starting (H, V_A) of (C9), or of (C9') for a nearly straight line.
fn initial_guess(line: &CatenaryLine, compliance: f64, span: f64, rise: f64) -> Plane {
    let (length, w) = (line.length, line.weight);
    let chord = span.hypot(rise);
    let shallow_tension = shallow_line_tension(length, compliance, w.abs() * span / chord, chord);
    let (horizontal, vertical_a) = if shallow_tension >= 4.0 * w.abs() * length {
        (
            shallow_tension * span / chord,
            shallow_tension * rise / chord - 0.5 * w * length,
        )
    } else {
        let sign = w.signum();
        let lambda = if chord >= length {
            0.2
        } else {
            (3.0 * ((length * length - rise * rise) / (span * span) - 1.0)).sqrt()
        };
        (
            0.5 * w.abs() * span / lambda,
            0.5 * w * (sign * rise / lambda.tanh() - length),
        )
    };
    Plane {
        horizontal: horizontal.max(f64::MIN_POSITIVE),
        vertical_a,
        weight: w,
        compliance,
    }
}

/// The root T of (C9'): f(T) = a T - b/T^2 - (c - L) with a = L/EA,
/// b = w_n^2 L^3/24. f increases and is concave, so Newton started below
/// the root climbs to it monotonically; the start is the larger of
/// (c - L)/a and (b/a)^(1/3) when c >= L (f < 0 at both), and
/// sqrt(b/(a (b/a)^(1/3) + L - c)) when c < L (since b/T^2 = a T + L - c
/// and T <= (b/a)^(1/3) there). Returns 0 when there is no positive root.
fn shallow_line_tension(length: f64, compliance: f64, weight_normal: f64, chord: f64) -> f64 {
    let a = length * compliance;
    let b = weight_normal * weight_normal * length.powi(3) / 24.0;
    let excess = chord - length;
    if b == 0.0 || a == 0.0 {
        return if a > 0.0 && excess > 0.0 {
            excess / a
        } else if a == 0.0 && excess < 0.0 {
            (b / -excess).sqrt()
        } else {
            0.0
        };
    }
    let balanced = (b / a).cbrt();
    let mut tension = if excess >= 0.0 {
        f64::max(excess / a, balanced)
    } else {
        (b / (a * balanced - excess)).sqrt()
    };
    for _ in 0..100 {
        let residual = a * tension - b / (tension * tension) - excess;
        let slope = a + 2.0 * b / (tension * tension * tension);
        let step = residual / slope;
        tension -= step;
        if step.abs() <= 1e-10 * tension {
            break;
        }
    }
    tension
}
