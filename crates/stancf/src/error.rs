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

    /// The same error with its key under `prefix` (`lines[2]` +
    /// `constraints[0]` = `lines[2].constraints[0]`).
    pub fn under(self, prefix: &str) -> Self {
        let key = if self.key.is_empty() {
            prefix.to_string()
        } else {
            format!("{prefix}.{}", self.key)
        };
        ModelError { key, ..self }
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
    /// scheme's stability limit (docs/method.md §4.5 and §8).
    EnergyGrowth,
    /// A static load path took the most increments it may and still
    /// creeps toward a load factor it cannot pass (each increment
    /// converged).
    PathStalled,
    /// The motion left what the model covers (a rod under water reached
    /// the surface, where its buoyancy and water are not built): the
    /// steps before are valid, the run cannot go on.
    OutsideModel,
}

/// A step that failed. Everything before `step` converged and is valid.
///
/// A static solve reports a load increment: `time` is then the load factor
/// at its start and `detail` begins with [`STATIC_SOLVE`], which makes the
/// message say "load factor" instead of "t = ... s".
#[derive(Clone, Debug, PartialEq)]
pub struct SolverError {
    pub kind: FailureKind,
    /// Simulated time at the start of the failed step (a static solve:
    /// the load factor).
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

impl SolverError {
    /// Whether Newton failed the step (no convergence, a value that is not
    /// finite, a singular Jacobian): what a system takes again in halves
    /// (docs/method.md §11.13). Not the energy watchdog's unstable step, a
    /// stalled static path, or a motion outside the model, which a
    /// shorter step does not mend.
    pub fn newton_failed(&self) -> bool {
        matches!(
            self.kind,
            FailureKind::NotConverged | FailureKind::NonFinite | FailureKind::SingularJacobian
        )
    }
}

impl fmt::Display for SolverError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let what = match self.kind {
            FailureKind::NotConverged => "Newton did not converge",
            FailureKind::NonFinite => "the iteration produced a non-finite value",
            FailureKind::SingularJacobian => "the Jacobian is singular",
            FailureKind::EnergyGrowth => "the energy grows without a source (unstable step)",
            FailureKind::PathStalled => "the static load path stalled",
            FailureKind::OutsideModel => "the motion left what the model covers",
        };
        if self.detail.starts_with(STATIC_SOLVE) {
            write!(f, "{what} at load factor {} (increment", Sig(self.time))?;
        } else {
            write!(f, "{what} at t = {} s (step", Sig(self.time))?;
        }
        write!(
            f,
            " {}, {} iteration{}, scaled residual {:.3e})",
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

/// How the `detail` of a static solve's [`SolverError`] begins.
pub const STATIC_SOLVE: &str = "static solve";

/// A number for a message: at most 6 significant digits, trailing zeros
/// dropped, exponent form outside [1e-4, 1e6): `0.0063288` for
/// 0.006328800000000001, `1e-5`, `2.5e8`, `-3`, `inf`, `NaN`.
#[derive(Clone, Copy, Debug)]
pub struct Sig(pub f64);

impl fmt::Display for Sig {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let x = self.0;
        if !x.is_finite() || x == 0.0 {
            return write!(f, "{}", if x == 0.0 { 0.0 } else { x });
        }
        // Round to 6 significant digits first: the decision between the
        // two forms uses the rounded value (999999.7 prints as 1e6).
        let e = format!("{x:.5e}");
        let (mantissa, exp) = e.split_once('e').expect("exponent form");
        let exp: i32 = exp.parse().expect("integer exponent");
        let mantissa = trim_zeros(mantissa);
        if (-4..6).contains(&exp) {
            let decimals = (5 - exp).max(0) as usize;
            let s = format!("{:.*}", decimals, x);
            f.write_str(trim_zeros(&s))
        } else {
            write!(f, "{mantissa}e{exp}")
        }
    }
}

/// "1.50000" -> "1.5", "2.000" -> "2", "10" -> "10".
fn trim_zeros(s: &str) -> &str {
    if s.contains('.') {
        s.trim_end_matches('0').trim_end_matches('.')
    } else {
        s
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numbers_in_messages_have_at_most_six_significant_digits() {
        let cases = [
            (0.006328800000000001, "0.0063288"),
            (1e-5, "1e-5"),
            (2.0e-4, "0.0002"),
            (0.1 + 0.2, "0.3"),
            (4.0, "4"),
            (-3.0, "-3"),
            (1234567.0, "1.23457e6"),
            (999999.7, "1e6"),
            (123456.4, "123456"),
            (0.0, "0"),
            (-0.0, "0"),
            (f64::INFINITY, "inf"),
            (f64::NAN, "NaN"),
            (1.5e-300, "1.5e-300"),
        ];
        for (x, want) in cases {
            assert_eq!(Sig(x).to_string(), want, "{x:e}");
        }
    }

    #[test]
    fn a_static_failure_names_the_load_factor_not_a_time() {
        let e = SolverError {
            kind: FailureKind::NotConverged,
            time: 0.35000000000000003,
            step: 8,
            residual: 1e-3,
            iterations: 50,
            detail: format!("{STATIC_SOLVE}: the load increment could not be converged"),
        };
        let m = e.to_string();
        assert!(m.contains("at load factor 0.35 (increment 8,"), "{m}");
        assert!(!m.contains("t = "), "{m}");
        let d = SolverError {
            detail: String::new(),
            time: 0.006328800000000001,
            ..e
        };
        assert!(d.to_string().contains("at t = 0.0063288 s (step 8,"), "{d}");
    }
}
