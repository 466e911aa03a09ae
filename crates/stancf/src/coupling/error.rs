//! Why a coupling call failed.

use crate::error::{ModelError, SolverError};
use std::fmt;

/// Why a coupling call failed: its input (sizes, values, the order of
/// calls, a state of another system, an interval of too many steps: the
/// handle is untouched), the solver, or its caller's request to stop
/// (for both, the state stays at the last converged step).
#[derive(Clone, Debug, PartialEq)]
pub enum CouplingError {
    Input(ModelError),
    Solver(SolverError),
    /// The caller asked to stop ([`CoupledSystem::step_to_with`]); the
    /// system is at its last converged step, at `time` (s).
    Interrupted {
        time: f64,
    },
}

impl fmt::Display for CouplingError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            CouplingError::Input(e) => write!(f, "{e}"),
            CouplingError::Solver(e) => write!(f, "{e}"),
            CouplingError::Interrupted { time } => write!(
                f,
                "interrupted at t = {time} s, the last converged step; the next call \
                 continues from there"
            ),
        }
    }
}

impl std::error::Error for CouplingError {}

impl From<ModelError> for CouplingError {
    fn from(e: ModelError) -> Self {
        CouplingError::Input(e)
    }
}

impl From<SolverError> for CouplingError {
    fn from(e: SolverError) -> Self {
        CouplingError::Solver(e)
    }
}
