//! Static analysis (paper section 4.1; docs/method.md §6.8, (M25), and
//! §6.9, (M26)).
//!
//! A static solve is the space-time solve of a time-invariant slab:
//! e_a = e_b = e, all velocities zero, so A = dt (W - U)(e) and the
//! equations reduce to
//!
//! ```text
//!   R(e) = dU/de - lambda f(e) - mu = 0,      e_c = c    (constraints)
//! ```
//!
//! with f the loads (gravity, point forces, end moments) and lambda the
//! load factor. stancf solves this reduced form directly: the time
//! quadrature of the slab would only multiply every term by dt.
//!
//! The load is applied in increments from 0 to 1 (`load_steps`), each
//! solved by Newton from the previous solution (extrapolated); supports
//! that move are moved after the loads are on (see `set_load_factor`). The tangent
//! can be nearly or exactly singular: a straight cable loaded sideways has
//! only its tiny bending stiffness, and a planar cable clamped at one end
//! can rotate about its clamped tangent without strain (a cable carries no
//! torsion). So each Newton step is
//!
//! - solved with a Levenberg shift K + mu D (D = diag |K|) when K is
//!   singular (the shift only steers the path; the converged solution
//!   solves R = 0),
//! - limited to a trust radius (at most 0.2 L for the scaled step): the
//!   first step of a straight cable loaded sideways is its load over its
//!   bending stiffness, kilometres, whatever the load factor. A full Newton
//!   step inside the radius is taken as it is; a step the radius had to cap
//!   is taken only if it lowers the scaled residual, else the radius is
//!   halved and the step retried (and doubled again after a success);
//!
//! and an increment that still fails is cut in half and retried, up to
//! `max_cuts` times (an increment too short to move the load factor
//! counts as failed), before the solve gives up.
//!
//! Measured, and why there is no line search along the Newton direction:
//! the tangent step of a large rotation stretches the cable (Green strain),
//! so the residual and the potential jump along the full step although the
//! solution is close. Backtracking on the residual, and a line search to
//! the minimum of the potential along the step (Crisfield), shortened the
//! first step of circle bending to 3 % and made convergence linear (50
//! iterations without converging); full steps inside the trust region
//! converge in about 10 iterations per increment there (a thin cable's
//! basin of quadratic convergence scales with EI / (EA l^2) ~ 1e-6) and
//! in 4 to 7 on catenaries. A fixed radius instead of the adaptive one
//! failed on a catenary with EA = 1e3 N: the capped steps bounced between
//! 2 m sags at every load factor, however much the increment was cut.

mod cable;
mod newton;

pub(crate) use cable::CableStatics;
pub(crate) use newton::{StaticEquations, StaticNewton};

use crate::band::{BandLu, BandMatrix};
use crate::constraints::ConstraintMethod;
use crate::error::{ModelError, SolverError};
use crate::model::{Model, State};
use cable::SingleCable;
use std::ops::ControlFlow;

/// How a static solve proceeds.
#[derive(Clone, Debug, PartialEq)]
pub struct StaticSettings {
    /// Load increments from 0 to the full load (and as many again for
    /// moving supports, see [`StaticSolver::moves_supports`]).
    pub load_steps: usize,
    pub tolerance: f64,
    /// Newton iterations per increment.
    pub max_iterations: usize,
    pub constraint_method: ConstraintMethod,
    /// Halvings of a failed increment before giving up.
    pub max_cuts: usize,
    /// What seabed friction holds at a system's equilibrium
    /// (docs/method.md §12.2, [`StaticFriction`]). A single
    /// cable's static solve resists the slide from its reference shape,
    /// along its load path and moving supports, whatever this says.
    pub seabed_friction: StaticFriction,
}

impl Default for StaticSettings {
    fn default() -> Self {
        StaticSettings {
            load_steps: 20,
            tolerance: 1e-10,
            max_iterations: 50,
            constraint_method: ConstraintMethod::default(),
            max_cuts: 10,
            seabed_friction: StaticFriction::AsLaid,
        }
    }
}

impl StaticSettings {
    /// Checks the figures (keys as in a scenario's `[analysis]`).
    pub(crate) fn validate(&self) -> Result<(), ModelError> {
        if self.load_steps == 0 {
            return Err(ModelError::invalid(
                "analysis.load_steps",
                "must be at least 1",
            ));
        }
        if !self.tolerance.is_finite() || self.tolerance <= 0.0 {
            return Err(ModelError::invalid(
                "analysis.tolerance",
                format!("must be > 0, got {}", self.tolerance),
            ));
        }
        if self.max_iterations == 0 {
            return Err(ModelError::invalid(
                "analysis.max_iterations",
                "must be at least 1",
            ));
        }
        Ok(())
    }
}

/// Where the static friction's targets are, what friction holds at a
/// system's equilibrium (docs/method.md §12.2; the policies are
/// accounted for in `crate::system`'s `static_friction` module).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum StaticFriction {
    /// Laid in the equilibrium: friction holds nothing.
    #[default]
    AsLaid,
    /// Pulled out along the bed from an unstretched lay towards the
    /// fairlead (the closed form with friction).
    Pulled,
    /// Against the slide from the seeds the solve started from (W48).
    FromSeed,
}

impl StaticFriction {
    /// The policy named as a scenario names it (`as_laid`, `pulled`).
    pub fn from_name(name: &str) -> Option<Self> {
        match name {
            "as_laid" => Some(StaticFriction::AsLaid),
            "pulled" => Some(StaticFriction::Pulled),
            _ => None,
        }
    }

    /// The scenario's name of the policy.
    pub fn name(self) -> &'static str {
        match self {
            StaticFriction::AsLaid => "as_laid",
            StaticFriction::Pulled => "pulled",
            StaticFriction::FromSeed => "from_seed",
        }
    }
}

/// One converged load increment.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct StaticIncrement {
    /// Index of the converged increment (1 = first).
    pub step: usize,
    pub load_factor: f64,
    pub iterations: usize,
    /// Scaled residual and last increment norms at convergence.
    pub residual: f64,
    pub increment: f64,
    /// Halvings this increment needed.
    pub cuts: usize,
}

/// A static solve of one cable: its equations and the Newton driver.
pub struct StaticSolver {
    equations: SingleCable,
    newton: StaticNewton<BandLu>,
}

impl StaticSolver {
    pub fn new(model: Model, settings: StaticSettings) -> Result<Self, ModelError> {
        settings.validate()?;
        model
            .constraints
            .check_direction_route(settings.constraint_method)?;
        if !model.constraints.remove_rigid_motions() {
            return Err(ModelError::invalid(
                "constraints",
                "a static analysis needs constraints that remove the rigid motions (a clamped \
                 node, or the positions of two nodes held): otherwise the equilibrium has no \
                 unique solution",
            ));
        }
        // The reference shape: supports start at their reference positions
        // and move along the load path (see `SingleCable::set_load_factor`).
        let reference = model.reference_coordinates();
        let cable = CableStatics::new(model, settings.constraint_method, reference);
        let n = cable.layout.size();
        let (kl, ku) = cable.layout.bandwidths();
        let mut newton = StaticNewton::new(
            cable.unknowns_of_state(),
            cable.unknown_weights(),
            BandLu::new(n, kl, ku),
            BandMatrix::new(n, kl, ku),
            settings,
        );
        newton.set_weight_rows(&cable.multiplier_rows());
        Ok(StaticSolver {
            equations: SingleCable::new(cable),
            newton,
        })
    }

    pub fn model(&self) -> &Model {
        &self.equations.cable.model
    }

    /// The current equilibrium (t holds the load path parameter, see
    /// `set_load_factor`; v is zero).
    pub fn state(&self) -> &State {
        &self.equations.cable.state
    }

    /// Force each position constraint exerts on the cable.
    pub fn reactions(&self) -> &[(usize, [f64; 3])] {
        &self.equations.cable.reactions
    }

    /// The moment each direction hold (a clamp in a direction,
    /// docs/method.md §6.10) exerts on the cable at equilibrium: (node,
    /// M = r_x x Q), Q the hold's reaction on r_x (M42).
    pub fn clamp_moments(&self) -> &[(usize, [f64; 3])] {
        &self.equations.cable.clamp_moments
    }

    /// Unknowns of the static system.
    pub fn unknowns(&self) -> usize {
        self.equations.cable.layout.size()
    }

    /// Whether a prescribed support moves away from its reference position.
    pub fn moves_supports(&self) -> bool {
        self.equations.cable.moves_supports()
    }

    /// Applies the load in increments, calling `observer` after each
    /// converged increment. Stops with an error naming the load factor
    /// when an increment fails after `max_cuts` halvings; the increments
    /// already observed stay valid.
    pub fn solve<F>(&mut self, mut observer: F) -> Result<bool, SolverError>
    where
        F: FnMut(&StaticSolver, &StaticIncrement) -> ControlFlow<()>,
    {
        while let Some(inc) = self.newton.advance(&mut self.equations)? {
            if observer(self, &inc).is_break() {
                return Ok(false);
            }
        }
        Ok(true)
    }
}
