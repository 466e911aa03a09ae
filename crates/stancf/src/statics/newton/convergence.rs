//! When a static Newton iteration at one load factor is converged
//! (docs/method.md §6.9): its scaled residual and increment within the
//! tolerance; or its residual within it a few iterations running,
//! whatever the increments; or its residual at the round-off floor,
//! which a Newton step cannot lower.

/// A static Newton iteration whose scaled residual has met the tolerance
/// at this many iterations in a row is converged, whatever its
/// increments. A well-conditioned iteration meets both criteria within an
/// iteration or two of the residual's (Newton converges quadratically);
/// one whose increments keep wandering with the forces balanced moves the
/// unknowns along a direction the forces do not determine: a nearly
/// singular Jacobian (a slack line's soft bending, EI_eff of (M33), a
/// free point between slack lines) turns the residual's round-off into
/// increments of 1e-8 to 1e-6 (the midwater bridles of docs/method.md
/// §6.8, at residuals of 5e-15 to 4e-13).
pub(super) const SETTLED_ITERATIONS: usize = 4;

/// A scaled residual this small is at the round-off of the rows' sums:
/// 64 machine epsilons, 1.4e-14 (measured floors 2e-16 to 2e-15 on
/// MoorDyn's and MoorPy's decks, issue 35). Above it, a residual that a
/// Newton step does not lower is a nonlinear step on its way (the
/// tangent step of a large rotation raises the residual, docs/method.md
/// §6.9) or an ill-conditioned one whose unknowns still move (a slender
/// cantilever at 1e-13 whose clamp moment is off by 5e-8), not a floor.
const ROUND_OFF_RESIDUAL: f64 = 64.0 * f64::EPSILON;

/// Whether a Newton step took the scaled residual from `before` to
/// `after` without lowering it by half (round-off moves a residual at
/// its floor by factors of order one either way, a converging Newton
/// step lowers it by orders of magnitude).
fn at_round_off_floor(before: f64, after: f64) -> bool {
    after >= 0.5 * before
}

/// The convergence of one Newton iteration (docs/method.md §6.9).
pub(super) struct Convergence {
    tolerance: f64,
    /// Iterations running whose residual met the tolerance.
    settled: usize,
}

impl Convergence {
    pub(super) fn new(tolerance: f64) -> Self {
        Convergence {
            tolerance,
            settled: 0,
        }
    }

    /// Whether the iterate of scaled residual `r`, reached by an increment
    /// of scaled norm `increment` (infinite at the first), is converged:
    /// both within the tolerance, or the residual within it
    /// [`SETTLED_ITERATIONS`] iterations running.
    pub(super) fn at_iterate(&mut self, r: f64, increment: f64) -> bool {
        let tol = self.tolerance;
        if r <= tol && increment <= tol {
            return true;
        }
        self.settled = if r <= tol { self.settled + 1 } else { 0 };
        self.settled >= SETTLED_ITERATIONS
    }

    /// Whether iterate `k` of scaled residual `r`, whose Newton step took
    /// the residual to `after`, is at the round-off floor: the forces
    /// balance, and the increment is that round-off turned into motion
    /// along a direction the forces hardly determine (issue 35: a simply
    /// supported beam at 2.6e-16, a slack mooring at 9e-16); the iterate
    /// is the equilibrium, whatever the increments do. Only after one
    /// Newton step at least (k > 0): the first iterate is the predictor,
    /// whose residual may be small only because the increment's load is
    /// (a slack line at zero force).
    pub(super) fn at_floor(&self, k: usize, r: f64, after: f64) -> bool {
        k > 0 && r <= self.tolerance.min(ROUND_OFF_RESIDUAL) && at_round_off_floor(r, after)
    }
}

#[cfg(test)]
mod tests {
    use super::super::{StaticEquations, StaticNewton};
    use super::{ROUND_OFF_RESIDUAL, SETTLED_ITERATIONS};
    use crate::band::{BandLu, BandMatrix};
    use crate::statics::StaticSettings;

    /// R(x; t) = K x - (t, t) + s (1, -1) n with K = [[1, 1], [1,
    /// 1 + 1e-6]], nearly singular, and s = +1, -1, +1... at successive
    /// iterations: noise n in the residual that K turns into increments
    /// of 2e6 n along (1, -1), above the tolerance 1e-10 for n = 1e-15
    /// (round-off) and 1e-12 (above it, within the tolerance), however
    /// long Newton iterates (a slack line's soft mode).
    struct SoftMode {
        t: f64,
        evaluations: usize,
        noise: f64,
    }

    impl StaticEquations for SoftMode {
        type Matrix = BandMatrix;
        fn evaluate(&mut self, x: &[f64], residual: &mut [f64], jacobian: Option<&mut BandMatrix>) {
            self.evaluations += 1;
            // Two evaluations an iteration (with the Jacobian, then the
            // trial step): the sign changes from iteration to iteration.
            let noise = if (self.evaluations / 2).is_multiple_of(2) {
                self.noise
            } else {
                -self.noise
            };
            residual[0] = x[0] + x[1] - self.t + noise;
            residual[1] = x[0] + (1.0 + 1e-6) * x[1] - self.t - noise;
            if let Some(j) = jacobian {
                j.clear();
                j.add(0, 0, 1.0);
                j.add(0, 1, 1.0);
                j.add(1, 0, 1.0);
                j.add(1, 1, 1.0 + 1e-6);
            }
        }
        fn row_weights(&mut self, _jacobian: &BandMatrix, weights: &mut [f64]) {
            weights.fill(1.0);
        }
        fn set_load_factor(&mut self, t: f64) {
            self.t = t;
        }
        fn legs(&self) -> usize {
            1
        }
        fn converged(&mut self, _x: &[f64]) {}
    }

    /// The soft mode with noise `noise` and its Newton from x = 0.
    fn soft_mode(noise: f64) -> (SoftMode, StaticNewton<BandLu>) {
        let eq = SoftMode {
            t: 0.0,
            evaluations: 0,
            noise,
        };
        let newton = StaticNewton::new(
            vec![0.0, 0.0],
            vec![0.0, 0.0],
            BandLu::new(2, 1, 1),
            BandMatrix::new(2, 1, 1),
            StaticSettings::default(),
        );
        (eq, newton)
    }

    /// Item 10 of issue 28: a residual at its round-off floor is
    /// converged though the increments wander in a direction the forces
    /// do not determine; the path used to fail with "did not converge" at
    /// a scaled residual of 1e-15.
    #[test]
    fn a_residual_met_four_iterations_running_is_converged_whatever_the_increments() {
        // Noise above the round-off floor, within the tolerance.
        let (mut eq, mut newton) = soft_mode(1e-12);
        let mut increments = 0;
        loop {
            match newton.advance(&mut eq) {
                Ok(Some(inc)) => {
                    increments += 1;
                    assert!(inc.residual <= 1e-10, "{inc:?}");
                    // The increments wandered above the tolerance.
                    assert!(inc.increment > 1e-10, "{inc:?}");
                    assert!(inc.iterations <= SETTLED_ITERATIONS + 1, "{inc:?}");
                }
                Ok(None) => break,
                Err(e) => panic!("{e}"),
            }
        }
        assert_eq!(increments, 20);
        // The forces balance: x0 + x1 = 1 to the tolerance.
        assert!(
            (newton.x[0] + newton.x[1] - 1.0).abs() <= 1e-10,
            "{:?}",
            newton.x
        );
    }

    /// Issue 35, item 3: a residual at round-off that the Newton step
    /// does not lower is at its floor, and converged at once: the soft
    /// mode's path takes the first Newton step of each increment (the
    /// linear problem's solution to round-off) and stops as soon as a
    /// step leaves the residual where it was, before it could have
    /// settled four iterations running.
    #[test]
    fn a_residual_the_newton_step_cannot_lower_is_converged_at_once() {
        let (mut eq, mut newton) = soft_mode(1e-15);
        while let Some(inc) = newton.advance(&mut eq).unwrap() {
            assert!(inc.residual <= ROUND_OFF_RESIDUAL, "{inc:?}");
            // Before the residual could have settled four iterations.
            assert!(inc.iterations < SETTLED_ITERATIONS, "{inc:?}");
        }
        assert!(
            (newton.x[0] + newton.x[1] - 1.0).abs() <= 1e-10,
            "{:?}",
            newton.x
        );
    }
}
