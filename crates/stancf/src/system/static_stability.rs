//! Whether a system's static equilibrium is stable at its bodies
//! (docs/method.md §6.9, (M26c)), and leaving one that is not.
//!
//! At an equilibrium of a conservative system the static Jacobian
//! condensed onto a free body's unknowns q = [r_G; theta] (theta in the
//! chart centred at the equilibrium's rotation), everything else in
//! equilibrium, is the Hessian of the energy as the body moves, and
//! symmetric: the body is stable where it is positive semi-definite
//! (zero where nothing holds it: a drift in still water, a turn about
//! the vertical), and the equilibrium is a saddle or a maximum where it
//! has a negative eigenvalue (a spar floating upside down, its ballast
//! above its centre of buoyancy). Where it is not symmetric the loads
//! have no potential (a moment fixed in space, a current's drag,
//! friction), and the body is not judged.
//! A pinned body (a flap, §15.12) is judged by its turn
//! about its pin alone. The load path (M32) goes to whichever
//! equilibrium is nearest its seeds, stable or not; from an unstable
//! one the body is moved along its eigenvector of the negative
//! eigenvalue and the flow of (M26b), which runs downhill, is followed
//! from there.

use super::body_statics::StaticBody;
use super::statics::SystemStatics;
use crate::error::{SolverError, STATIC_SOLVE};
use crate::statics::StaticIncrement;
use std::ops::ControlFlow;

/// An eigenvalue of the scaled condensed Hessian (its diagonal's
/// magnitudes 1) below -this is negative, not round-off: the static
/// tolerance leaves the rows at 1e-10 of their scale. Its asymmetry
/// above this marks loads without a potential (a moment fixed in space,
/// a current's drag, friction): the body is then not judged.
const NEGATIVE: f64 = 1e-6;

/// How far an unstable body is moved along its eigenvector before the
/// flow: its largest turn, 0.2 rad, or its largest move, a fifth of its
/// length scale.
const NUDGE: f64 = 0.2;

/// The most times an equilibrium is left for another.
const MOST_NUDGES: usize = 3;

impl SystemStatics {
    /// The direction (in body b's unknowns [r_G; theta]: metres and
    /// radians) along which its equilibrium
    /// loses energy: the eigenvector of the condensed Hessian's most
    /// negative eigenvalue, scaled to its diagonal; None where the body
    /// is stable there (or is fixed, coupled or a connector, or the rest
    /// of the system is singular with it held).
    pub fn body_downhill(&mut self, b: usize) -> Option<Vec<f64>> {
        let k = self.equations.bodies.iter().position(|s| s.index == b)?;
        if self.system().bodies()[b].connector {
            return None;
        }
        let first = if self.equations.bodies[k].pin.is_some() {
            3
        } else {
            0
        };
        // The chart centred at the equilibrium, the body whole.
        let ((s, _), _) = self.condensed_body(b, first, |body, rotation| StaticBody {
            rotation,
            ..body.clone()
        })?;
        let m = 6 - first;
        let scale: Vec<f64> = (0..m).map(|i| s[i * m + i].abs()).collect();
        let largest = scale.iter().fold(0.0f64, |a, &b| a.max(b));
        if largest == 0.0 {
            return None;
        }
        let scale: Vec<f64> = scale
            .iter()
            .map(|d| d.max(1e-12 * largest).sqrt())
            .collect();
        let mut a = vec![0.0; m * m];
        for i in 0..m {
            for j in 0..m {
                a[i * m + j] = 0.5 * (s[i * m + j] + s[j * m + i]) / (scale[i] * scale[j]);
            }
        }
        let asymmetry = (0..m)
            .flat_map(|i| (0..m).map(move |j| (i, j)))
            .map(|(i, j)| (s[i * m + j] - s[j * m + i]).abs() / (scale[i] * scale[j]))
            .fold(0.0f64, f64::max);
        if asymmetry > NEGATIVE {
            // Loads without a potential (a moment fixed in space, a
            // current's drag, friction): no energy to judge by.
            return None;
        }
        let (value, vector) = lowest_eigenpair(&mut a, m);
        (value < -NEGATIVE).then(|| {
            let mut full = vec![0.0; 6];
            for i in 0..m {
                full[first + i] = vector[i] / scale[i];
            }
            full
        })
    }

    /// From an equilibrium unstable at a body, the flow (M26b) from it
    /// moved along its downhill direction, up to [`MOST_NUDGES`] times:
    /// Ok(true) when the equilibrium reached is stable at every body (or
    /// was), Ok(false) when the observer stopped a flow; Err: a flow
    /// failed.
    pub(super) fn leave_unstable<F>(&mut self, observer: &mut F) -> Result<bool, SolverError>
    where
        F: FnMut(&SystemStatics, &StaticIncrement) -> ControlFlow<()>,
    {
        for _ in 0..MOST_NUDGES {
            let bodies: Vec<usize> = self.equations.bodies.iter().map(|s| s.index).collect();
            let Some((b, direction)) = bodies
                .into_iter()
                .find_map(|b| self.body_downhill(b).map(|d| (b, d)))
            else {
                return Ok(true);
            };
            self.nudge(b, &direction);
            let increment = self.newton.relax(&mut self.equations).map_err(|e| {
                let then = e.detail.trim_start_matches(STATIC_SOLVE);
                SolverError {
                    detail: format!(
                        "{STATIC_SOLVE}: the equilibrium reached is unstable at bodies[{b}] (its \
                         condensed stiffness has a negative eigenvalue: docs/method.md §6.9, \
                         (M26c)); moved off it, {}",
                        then.trim_start_matches(": ")
                    ),
                    ..e
                }
            })?;
            self.relaxed = true;
            if observer(self, &increment).is_break() {
                return Ok(false);
            }
        }
        Ok(true)
    }

    /// Moves body b's unknowns along `direction` (see
    /// [`Self::body_downhill`]): its largest turn or move [`NUDGE`].
    fn nudge(&mut self, b: usize, direction: &[f64]) {
        let k = self
            .equations
            .bodies
            .iter()
            .position(|s| s.index == b)
            .expect("a free body");
        let length = self.equations.bodies[k].length;
        let size = (0..6)
            .map(|i| {
                let unit = if i < 3 { length } else { 1.0 };
                direction[i].abs() / unit
            })
            .fold(0.0f64, f64::max);
        if size == 0.0 {
            return;
        }
        for (i, d) in direction.iter().enumerate() {
            let g = self
                .equations
                .layout
                .body_unknown(b, 0, i)
                .expect("a free body");
            self.newton.x[g] += NUDGE * d / size;
        }
    }
}

/// The lowest eigenvalue of the symmetric m x m matrix `a` (row-major,
/// overwritten) and its unit eigenvector, by Jacobi's rotations.
fn lowest_eigenpair(a: &mut [f64], m: usize) -> (f64, Vec<f64>) {
    let mut v = vec![0.0; m * m];
    for i in 0..m {
        v[i * m + i] = 1.0;
    }
    for _ in 0..100 {
        let off: f64 = (0..m)
            .flat_map(|i| (0..m).filter(move |&j| j != i).map(move |j| (i, j)))
            .map(|(i, j)| a[i * m + j] * a[i * m + j])
            .sum();
        if off < 1e-30 {
            break;
        }
        for p in 0..m {
            for q in p + 1..m {
                let apq = a[p * m + q];
                if apq.abs() < 1e-300 {
                    continue;
                }
                let theta = (a[q * m + q] - a[p * m + p]) / (2.0 * apq);
                let t = theta.signum() / (theta.abs() + (theta * theta + 1.0).sqrt());
                let c = 1.0 / (t * t + 1.0).sqrt();
                let s = t * c;
                for k in 0..m {
                    let (akp, akq) = (a[k * m + p], a[k * m + q]);
                    a[k * m + p] = c * akp - s * akq;
                    a[k * m + q] = s * akp + c * akq;
                }
                for k in 0..m {
                    let (apk, aqk) = (a[p * m + k], a[q * m + k]);
                    a[p * m + k] = c * apk - s * aqk;
                    a[q * m + k] = s * apk + c * aqk;
                }
                for k in 0..m {
                    let (vkp, vkq) = (v[k * m + p], v[k * m + q]);
                    v[k * m + p] = c * vkp - s * vkq;
                    v[k * m + q] = s * vkp + c * vkq;
                }
            }
        }
    }
    let lowest = (0..m)
        .min_by(|&i, &j| a[i * m + i].total_cmp(&a[j * m + j]))
        .unwrap_or(0);
    (
        a[lowest * m + lowest],
        (0..m).map(|k| v[k * m + lowest]).collect(),
    )
}
