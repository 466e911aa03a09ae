//! Errors of the library: invalid models and failed solves.

use std::fmt;

/// A model or setting that cannot be simulated. `key` names the offending
/// quantity with the dotted path of the scenario file (`cable.length`,
/// `analysis.time_step`), so a driver can report it as is.
#[derive(Clone, Debug, PartialEq)]
pub struct ModelError {
    pub key: String,
    pub message: String,
}

impl ModelError {
    pub fn invalid(key: impl Into<String>, message: impl Into<String>) -> Self {
        ModelError {
            key: key.into(),
            message: message.into(),
        }
    }
}

impl fmt::Display for ModelError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}: {}", self.key, self.message)
    }
}

impl std::error::Error for ModelError {}

/// Why a step could not be completed.
#[derive(Clone, Debug, PartialEq)]
pub enum FailureKind {
    /// Newton did not reach the tolerance within the iteration limit.
    NotConverged,
    /// The residual or the iterate stopped being finite.
    NonFinite,
    /// The linear system of a Newton iteration is singular.
    SingularJacobian,
    /// The mechanical energy grew without a source: the step is above the
    /// scheme's stability limit (method notes, "Stability").
    EnergyGrowth,
}

/// A step that failed. Everything before `step` converged and is valid.
#[derive(Clone, Debug, PartialEq)]
pub struct SolverError {
    pub kind: FailureKind,
    /// Simulated time at the start of the failed step.
    pub time: f64,
    /// Index of the failed step (1 = the first step).
    pub step: usize,
    /// Scaled residual norm at the last iterate (NaN when not finite).
    pub residual: f64,
    /// Newton iterations spent on the failed step.
    pub iterations: usize,
    /// Details for the user.
    pub detail: String,
}

impl fmt::Display for SolverError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let what = match self.kind {
            FailureKind::NotConverged => "Newton did not converge",
            FailureKind::NonFinite => "the iteration produced a non-finite value",
            FailureKind::SingularJacobian => "the Jacobian is singular",
            FailureKind::EnergyGrowth => "the energy grows without a source (unstable step)",
        };
        write!(
            f,
            "{what} at t = {:.6e} s (step {}, {} iteration{}, scaled residual {:.3e})",
            self.time,
            self.step,
            self.iterations,
            if self.iterations == 1 { "" } else { "s" },
            self.residual
        )?;
        if !self.detail.is_empty() {
            write!(f, ": {}", self.detail)?;
        }
        Ok(())
    }
}

impl std::error::Error for SolverError {}
