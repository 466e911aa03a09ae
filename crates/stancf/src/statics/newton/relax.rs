//! Pseudo-transient continuation (docs/method.md §6.9, (M26b)): the
//! static equations at the full load, reached along implicit Euler steps
//! of the flow
//!
//! ```text
//!   D dx/dtau = -R(x)
//! ```
//!
//! each step one Newton iteration of `D (x_{k+1} - x_k) / dtau_k +
//! R(x_{k+1}) = 0`:
//!
//! ```text
//!   (K + mu_k D + N) dx = R(x_k),   x_{k+1} = x_k - dx,   mu_k = 1 / dtau_k
//! ```
//!
//! K = dR/dx; D the stiffness each coordinate's row is scaled by in the
//! scaled residual (§6.9, 1 / w_i: |K_ii|, or what the equations put in
//! its place where K_ii vanishes, a body's sway on slack lines), zero at
//! a multiplier's row (a constraint, which every step keeps); N twice the
//! negative part of K's diagonal at the coordinates, so that no
//! coordinate is drawn up its energy to a maximum (a buoyant rod pinned
//! above the water, upside down). The shift follows the scaled residual
//! r (switched evolution relaxation, Mulder and van Leer 1985; Kelley
//! and Keyes 1998), `mu_{k+1} = mu_k r_{k+1} / r_k`, raised fourfold
//! while a step leaves the trust radius, and dropped below
//! [`NEWTON_SHIFT`]; from every tenfold fall of r below [`HANDOFF`] the
//! load path's own Newton iteration is tried, and kept if it converges.
//!
//! Unlike the load path (M32), the flow does not stop where the path's
//! Jacobian turns singular (a body on slack lines that must sink until
//! its rods float it), and it takes every step, whatever the step does to
//! the residual, so it leaves a local minimum of |R| that is not a root.
//! Measured on MoorDyn's BodiesAndRods.dat, whose load path stalls at
//! load factor 0: 9631 steps, 27 s; without N the flow ended on the
//! flap hanging upside down from its pin above the water, and with D =
//! diag |K| alone (no stiffness where K_ii vanishes) the first step was
//! unbounded (docs/method.md §6.9).

use super::convergence::Convergence;
use super::{StaticEquations, StaticNewton};
use crate::error::{FailureKind, Sig, SolverError, STATIC_SOLVE};
use crate::linear::{AddEntries, Factorization, Jacobian};
use crate::statics::StaticIncrement;

/// The shift of the first step: the step then moves each unknown by its
/// row's scaled residual over 2 at most (where nothing couples it).
const FIRST_SHIFT: f64 = 1.0;

/// A shift below this is dropped: the step is Newton's.
const NEWTON_SHIFT: f64 = 1e-8;

/// The largest shift: a step of 1e-8 of its rows' scaled residuals has
/// stalled.
const LARGEST_SHIFT: f64 = 1e8;

/// The largest scaled step of a coordinate, as on the load path.
const MAX_STEP: f64 = 0.2;

/// The scaled residual below which the load path's Newton iteration is
/// tried (and again at every tenfold fall since the last try).
const HANDOFF: f64 = 1e-3;

/// The most steps of the flow.
const RELAXATION_STEPS: usize = 20_000;

impl<F: Factorization> StaticNewton<F> {
    /// The equilibrium at the full load (the load factor set to 1) by
    /// pseudo-transient continuation from the current x (see the module's
    /// doc), as one increment of the load path; the path is then at its
    /// end. On failure x is where the flow stopped.
    pub fn relax<E>(&mut self, eq: &mut E) -> Result<StaticIncrement, SolverError>
    where
        E: StaticEquations<Matrix = F::Matrix>,
    {
        eq.set_load_factor(1.0);
        let mut flow = Flow::new(self.settings.tolerance);
        let mut failure = (FailureKind::NotConverged, None);
        let mut steps = 0;
        while steps <= RELAXATION_STEPS {
            eq.evaluate(&self.x, &mut self.residual, Some(&mut self.jacobian));
            eq.row_weights(&self.jacobian, &mut self.row_weight);
            let r = self.residual_norm();
            if !r.is_finite() {
                failure = (
                    FailureKind::NonFinite,
                    Some("a residual that is not finite"),
                );
                break;
            }
            let mut done = flow.convergence.at_iterate(r, flow.increment);
            if !done && r <= flow.newton_below {
                done = self.newton_from_flow(eq, &mut flow, r);
            }
            if done {
                return Ok(self.relaxed(eq, steps, flow.increment));
            }
            if steps == RELAXATION_STEPS {
                break;
            }
            flow.follow(r);
            let Some(full) = self.flow_step(&mut flow) else {
                failure = (
                    FailureKind::SingularJacobian,
                    Some("a step that no shift kept within the trust radius"),
                );
                break;
            };
            for (x, dx) in self.x.iter_mut().zip(&self.dx) {
                *x -= dx;
            }
            flow.increment = full;
            steps += 1;
        }
        Err(SolverError {
            kind: failure.0,
            time: 1.0,
            step: self.increments + 1,
            residual: self.residual_norm(),
            iterations: steps,
            detail: match failure.1 {
                None => format!(
                    "{STATIC_SOLVE}: pseudo-transient continuation at the full load did not \
                     reach the tolerance {} in {RELAXATION_STEPS} steps",
                    Sig(self.settings.tolerance)
                ),
                Some(why) => format!(
                    "{STATIC_SOLVE}: pseudo-transient continuation at the full load stopped \
                     after {steps} steps at {why}"
                ),
            },
        })
    }

    /// The load path's Newton iteration from the flow's x at scaled
    /// residual r (near a root it converges in a few iterations where
    /// the shifted steps creep); true if it converged, else x is back
    /// where the flow was, its residual and Jacobian evaluated there.
    fn newton_from_flow<E>(&mut self, eq: &mut E, flow: &mut Flow, r: f64) -> bool
    where
        E: StaticEquations<Matrix = F::Matrix>,
    {
        flow.newton_below = 0.1 * r;
        self.x_saved.copy_from_slice(&self.x);
        if let Ok((_, _, increment)) = self.newton(eq) {
            flow.increment = increment;
            return true;
        }
        self.x.copy_from_slice(&self.x_saved);
        eq.evaluate(&self.x, &mut self.residual, Some(&mut self.jacobian));
        eq.row_weights(&self.jacobian, &mut self.row_weight);
        false
    }

    /// The converged end of the flow after `steps` steps: the load path
    /// at its end.
    fn relaxed<E>(&mut self, eq: &mut E, steps: usize, increment: f64) -> StaticIncrement
    where
        E: StaticEquations<Matrix = F::Matrix>,
    {
        self.lambda = 1.0;
        self.increments += 1;
        self.cuts = 0;
        eq.converged(&self.x);
        StaticIncrement {
            step: self.increments,
            load_factor: 1.0,
            iterations: steps,
            residual: self.residual_norm(),
            increment,
            cuts: 0,
        }
    }

    /// The flow's step dx of (K + mu D + N) dx = R (the module's doc),
    /// the shift raised fourfold until the step's coordinates stay within
    /// the trust radius; its scaled norm, or None if no shift up to
    /// [`LARGEST_SHIFT`] brings it there.
    fn flow_step(&mut self, flow: &mut Flow) -> Option<f64> {
        loop {
            let a = self.lu.matrix_mut();
            a.copy_from(&self.jacobian);
            for i in 0..a.size() {
                if self.unknown_weight[i] > 0.0 {
                    let k = self.jacobian.get(i, i);
                    let d = if self.row_weight[i] > 0.0 {
                        1.0 / self.row_weight[i]
                    } else {
                        0.0
                    };
                    a.add(i, i, flow.shift * d + (-2.0 * k).max(0.0));
                }
            }
            if self.lu.factorize().is_ok() {
                self.dx.copy_from_slice(&self.residual);
                self.lu.solve(&mut self.dx);
                let full = self.coordinate_increment_norm();
                if full.is_finite() && full <= MAX_STEP {
                    return Some(full);
                }
            }
            flow.shift = (4.0 * flow.shift).max(NEWTON_SHIFT);
            if flow.shift > LARGEST_SHIFT {
                return None;
            }
        }
    }

    /// The largest weighted increment of a coordinate. The multipliers
    /// are left out: forces that hold the constraints while the shifted
    /// rows move the coordinates, they follow the coordinates and are
    /// not a state of the flow (weighted as in [`Self::increment_norm`]
    /// they grow with the shift).
    fn coordinate_increment_norm(&self) -> f64 {
        self.dx
            .iter()
            .zip(&self.unknown_weight)
            .filter(|(_, &w)| w > 0.0)
            .fold(0.0, |m: f64, (d, w)| m.max((d * w).abs()))
    }
}

/// The flow between its steps.
struct Flow {
    convergence: Convergence,
    /// mu = 1 / dtau.
    shift: f64,
    /// The scaled residual at the last step (switched evolution
    /// relaxation's measure).
    residual: Option<f64>,
    /// The last step's scaled norm.
    increment: f64,
    /// The scaled residual below which Newton's iteration is tried next.
    newton_below: f64,
}

impl Flow {
    fn new(tolerance: f64) -> Self {
        Flow {
            convergence: Convergence::new(tolerance),
            shift: FIRST_SHIFT,
            residual: None,
            increment: f64::INFINITY,
            newton_below: HANDOFF,
        }
    }

    /// The next step's shift from the scaled residual r (switched
    /// evolution relaxation): the last one's times r over the last r.
    fn follow(&mut self, r: f64) {
        if let Some(before) = self.residual {
            if before > 0.0 {
                self.shift = (self.shift * r / before).min(LARGEST_SHIFT);
            }
            if self.shift < NEWTON_SHIFT {
                self.shift = 0.0;
            }
        }
        self.residual = Some(r);
    }
}
