//! The static Newton iteration and its load path (docs/method.md §6.8,
//! (M25), and §6.9, (M26)): Levenberg-shifted Newton steps inside an
//! adaptive trust radius, load increments cut in half when they fail.
//! One driver for a single cable (a band) and a system of lines (bands
//! bordered by the free points), through [`StaticEquations`].

use super::{StaticIncrement, StaticSettings};
use crate::error::{FailureKind, Sig, SolverError, STATIC_SOLVE};
use crate::linear::{AddEntries, Factorization, Jacobian};

/// The static equations R(x; t) = 0 along a load path t in [0, 1], as the
/// driver sees them.
pub(crate) trait StaticEquations {
    type Matrix: Jacobian;
    /// R(x) and, if asked, its Jacobian (every entry set, none added to
    /// what was there before).
    fn evaluate(&mut self, x: &[f64], residual: &mut [f64], jacobian: Option<&mut Self::Matrix>);
    /// The weights of the scaled residual's rows, from the Jacobian.
    fn row_weights(&mut self, jacobian: &Self::Matrix, weights: &mut [f64]);
    /// Sets the point t of the load path.
    fn set_load_factor(&mut self, t: f64);
    /// The legs of the load path (increments are `load_steps` per leg).
    fn legs(&self) -> usize;
    /// Takes the converged unknowns of an increment (states, reactions).
    fn converged(&mut self, x: &[f64]);
}

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
const SETTLED_ITERATIONS: usize = 4;

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

/// The unknowns, the factors and the position on the load path.
pub(crate) struct StaticNewton<F: Factorization> {
    pub x: Vec<f64>,
    x_trial: Vec<f64>,
    x_prev: Vec<f64>,
    /// The start of the increment being tried (restored if it fails).
    x_saved: Vec<f64>,
    residual: Vec<f64>,
    dx: Vec<f64>,
    /// Row weights 1 / |K_ii| (refreshed with every Jacobian).
    row_weight: Vec<f64>,
    /// Weights of the unknowns in the increment norm (0: take the row's).
    unknown_weight: Vec<f64>,
    lu: F,
    jacobian: F::Matrix,
    settings: StaticSettings,
    /// Load path: the converged point, the next increment, the last one.
    lambda: f64,
    step: f64,
    previous_step: f64,
    cuts: usize,
    pub increments: usize,
}

impl<F: Factorization> StaticNewton<F> {
    /// The driver from the start x, with factors `lu` and a matrix of the
    /// same structure `jacobian`.
    pub fn new(
        x: Vec<f64>,
        unknown_weight: Vec<f64>,
        lu: F,
        jacobian: F::Matrix,
        settings: StaticSettings,
    ) -> Self {
        let n = x.len();
        StaticNewton {
            x_trial: x.clone(),
            x_prev: x.clone(),
            x_saved: x.clone(),
            x,
            residual: vec![0.0; n],
            dx: vec![0.0; n],
            row_weight: vec![1.0; n],
            unknown_weight,
            lu,
            jacobian,
            settings,
            lambda: 0.0,
            step: 0.0,
            previous_step: 0.0,
            cuts: 0,
            increments: 0,
        }
    }

    /// Whether the Jacobian of `eq` at the current x factorizes without
    /// the Levenberg shift: the equilibrium there is isolated (a line
    /// with a direction that nothing stiffens, e.g. one at zero tension
    /// without compression, gives a zero pivot).
    pub fn regular_at<E>(&mut self, eq: &mut E) -> bool
    where
        E: StaticEquations<Matrix = F::Matrix>,
    {
        eq.evaluate(&self.x, &mut self.residual, Some(&mut self.jacobian));
        self.lu.matrix_mut().copy_from(&self.jacobian);
        self.lu.factorize().is_ok()
    }

    /// Scaled residual: each row as the coordinate change |R_i| / |K_ii|
    /// would cause, as a fraction of the cable length; constraint rows are
    /// already positions.
    fn residual_norm(&self) -> f64 {
        let mut m = 0.0f64;
        for (r, w) in self.residual.iter().zip(self.row_weight.iter()) {
            let a = (r * w).abs();
            if !a.is_finite() {
                return f64::NAN;
            }
            m = m.max(a);
        }
        m
    }

    fn increment_norm(&self) -> f64 {
        let mut m = 0.0f64;
        for (i, d) in self.dx.iter().enumerate() {
            let w = if self.unknown_weight[i] > 0.0 {
                self.unknown_weight[i]
            } else {
                self.row_weight[i]
            };
            m = m.max((d * w).abs());
        }
        m
    }

    /// Factorizes K, or K + mu D (D = diag |K|) with the smallest shift
    /// mu in 1e-10, 1e-8, ... 1e2 that makes it regular.
    fn factorize_shifted(&mut self) -> Result<(), FailureKind> {
        let mut shift = 0.0;
        let kmax = self.jacobian.max_abs();
        loop {
            let a = self.lu.matrix_mut();
            a.copy_from(&self.jacobian);
            if shift > 0.0 {
                for i in 0..a.size() {
                    let d = a.get(i, i).abs().max(1e-12 * kmax);
                    a.add(i, i, shift * d);
                }
            }
            if self.lu.factorize().is_ok() {
                return Ok(());
            }
            shift = if shift == 0.0 { 1e-10 } else { shift * 100.0 };
            if shift > 1e2 {
                return Err(FailureKind::SingularJacobian);
            }
        }
    }

    /// Newton at the current load factor from the current x.
    fn newton<E>(&mut self, eq: &mut E) -> Result<(usize, f64, f64), FailureKind>
    where
        E: StaticEquations<Matrix = F::Matrix>,
    {
        let tol = self.settings.tolerance;
        let max_step = 0.2;
        let mut radius = max_step;
        let mut increment = f64::INFINITY;
        let mut settled = 0;
        for k in 0..=self.settings.max_iterations {
            eq.evaluate(&self.x, &mut self.residual, Some(&mut self.jacobian));
            eq.row_weights(&self.jacobian, &mut self.row_weight);
            let r = self.residual_norm();
            if !r.is_finite() {
                return Err(FailureKind::NonFinite);
            }
            if r <= tol && increment <= tol {
                return Ok((k, r, increment));
            }
            settled = if r <= tol { settled + 1 } else { 0 };
            if settled >= SETTLED_ITERATIONS {
                return Ok((k, r, increment));
            }
            if k == self.settings.max_iterations {
                return Err(FailureKind::NotConverged);
            }
            self.factorize_shifted()?;
            self.dx.copy_from_slice(&self.residual);
            self.lu.solve(&mut self.dx);
            let full = self.increment_norm();
            if !full.is_finite() {
                return Err(FailureKind::NonFinite);
            }
            // Step control: a full Newton step inside the trust radius is
            // taken as it is (the tangent step of a large rotation may raise
            // the residual on its way to convergence). A step the radius had
            // to cap is only trusted if it lowers the scaled residual; if not,
            // the radius is halved and the step retried. Non-finite trials
            // are halved too.
            let mut alpha = if full > radius { radius / full } else { 1.0 };
            for _ in 0..60 {
                for i in 0..self.x.len() {
                    self.x_trial[i] = self.x[i] - alpha * self.dx[i];
                }
                eq.evaluate(&self.x_trial, &mut self.residual, None);
                let rt = self.residual_norm();
                if !rt.is_finite() {
                    alpha *= 0.5;
                    radius = radius.min(alpha * full);
                    continue;
                }
                if alpha < 1.0 && rt >= r && alpha * full > 1e-9 {
                    alpha *= 0.5;
                    radius = alpha * full;
                    continue;
                }
                if alpha < 1.0 {
                    radius = (2.0 * radius).min(max_step);
                }
                break;
            }
            // A residual at round-off that the Newton step cannot lower is
            // at its floor: the forces balance, and the increment is that
            // round-off turned into motion along a direction the forces
            // hardly determine (issue 35: a simply supported beam at
            // 2.6e-16, a slack mooring at 9e-16). x is the equilibrium,
            // whatever the increments do.
            // After one Newton step at least: the first iterate is the
            // predictor, whose residual may be small only because the
            // increment's load is (a slack line at zero force).
            if k > 0
                && r <= tol.min(ROUND_OFF_RESIDUAL)
                && at_round_off_floor(r, self.residual_norm())
            {
                return Ok((k, r, increment));
            }
            std::mem::swap(&mut self.x, &mut self.x_trial);
            increment = alpha * full;
        }
        Err(FailureKind::NotConverged)
    }

    /// The next converged increment of the load path (None when the full
    /// load is on). An increment that fails is cut in half and retried,
    /// up to `max_cuts` times or until it would no longer move the load
    /// factor; then the error names the load factor, and the increments
    /// already returned stay valid.
    pub fn advance<E>(&mut self, eq: &mut E) -> Result<Option<StaticIncrement>, SolverError>
    where
        E: StaticEquations<Matrix = F::Matrix>,
    {
        let nominal = 1.0 / (eq.legs() as f64 * self.settings.load_steps as f64);
        if self.increments == 0 && self.cuts == 0 && self.step == 0.0 {
            self.step = nominal;
            self.x_prev.copy_from_slice(&self.x);
        } else if self.cuts == 0 {
            // The increment after a success may double again.
            self.step = (2.0 * self.step).min(nominal);
        }
        while self.lambda < 1.0 - 1e-12 {
            if self.increments >= self.max_increments(eq.legs()) {
                return Err(self.creeping(eq.legs()));
            }
            let target = (self.lambda + self.step).min(1.0);
            let h = target - self.lambda;
            // Predictor: secant extrapolation from the last two solutions.
            self.x_saved.copy_from_slice(&self.x);
            if self.previous_step > 0.0 {
                let f = h / self.previous_step;
                for i in 0..self.x.len() {
                    self.x[i] += f * (self.x[i] - self.x_prev[i]);
                }
            }
            eq.set_load_factor(target);
            // An increment below the load factor's resolution moves
            // nothing: a failure, cut like the others (else a path that
            // cannot pass a load factor would take such increments, double
            // the step, fail and cut back to them forever).
            let solved = if h > 0.0 {
                self.newton(eq)
            } else {
                Err(FailureKind::NotConverged)
            };
            match solved {
                Ok((iterations, residual, increment)) => {
                    self.x_prev.copy_from_slice(&self.x_saved);
                    self.previous_step = h;
                    self.lambda = target;
                    self.increments += 1;
                    eq.converged(&self.x);
                    let inc = StaticIncrement {
                        step: self.increments,
                        load_factor: self.lambda,
                        iterations,
                        residual,
                        increment,
                        cuts: self.cuts,
                    };
                    self.cuts = 0;
                    return Ok(Some(inc));
                }
                Err(kind) => {
                    self.x.copy_from_slice(&self.x_saved);
                    self.cuts += 1;
                    if self.cuts > self.settings.max_cuts {
                        eq.set_load_factor(self.lambda);
                        return Err(SolverError {
                            kind,
                            time: self.lambda,
                            step: self.increments + 1,
                            residual: self.residual_norm(),
                            iterations: self.settings.max_iterations,
                            detail: format!(
                                "{STATIC_SOLVE}: the load increment from load factor {} could \
                                 not be converged even after {} halvings (converged: the scaled \
                                 residual and increment both within the tolerance {}, or the \
                                 residual within it {SETTLED_ITERATIONS} iterations running)",
                                Sig(self.lambda),
                                self.settings.max_cuts,
                                Sig(self.settings.tolerance)
                            ),
                        });
                    }
                    self.step *= 0.5;
                }
            }
        }
        Ok(None)
    }

    /// The most increments a load path takes: `max_cuts + 1` per nominal
    /// increment (and at least 10 nominal ones' worth). A cut of c
    /// halvings is made good by c doublings of the increments after it,
    /// so a path whose every nominal increment were cut `max_cuts` times
    /// would take about that many; a path that takes more creeps toward a
    /// load factor it cannot pass, and would go on for hours.
    fn max_increments(&self, legs: usize) -> usize {
        (legs * self.settings.load_steps)
            .max(10)
            .saturating_mul(self.settings.max_cuts + 1)
    }

    /// The error of a load path past [`Self::max_increments`].
    fn creeping(&self, legs: usize) -> SolverError {
        SolverError {
            kind: FailureKind::PathStalled,
            time: self.lambda,
            step: self.increments + 1,
            residual: self.residual_norm(),
            iterations: 0,
            detail: format!(
                "{STATIC_SOLVE}: the load path took {} increments, the most for its {} \
                 nominal ones ({} each, with up to {} halvings), and reached load factor {} \
                 only: it creeps toward a load it cannot pass",
                self.increments,
                legs * self.settings.load_steps,
                self.settings.max_cuts + 1,
                self.settings.max_cuts,
                Sig(self.lambda)
            ),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::{StaticEquations, StaticNewton};
    use crate::band::{BandLu, BandMatrix};
    use crate::error::SolverError;
    use crate::statics::StaticSettings;

    /// Whether Newton converges at load factor t after an increment
    /// converged at `last`: (t, last) -> yes or no.
    type Admits = fn(f64, f64) -> bool;

    /// R(x; t) = x - t, not finite where `admits` says no.
    struct Path {
        t: f64,
        last: f64,
        admits: Admits,
    }

    impl StaticEquations for Path {
        type Matrix = BandMatrix;
        fn evaluate(&mut self, x: &[f64], residual: &mut [f64], jacobian: Option<&mut BandMatrix>) {
            residual[0] = if (self.admits)(self.t, self.last) {
                x[0] - self.t
            } else {
                f64::NAN
            };
            if let Some(j) = jacobian {
                j.clear();
                j.add(0, 0, 1.0);
            }
        }
        fn row_weights(&mut self, _jacobian: &BandMatrix, weights: &mut [f64]) {
            weights[0] = 1.0;
        }
        fn set_load_factor(&mut self, t: f64) {
            self.t = t;
        }
        fn legs(&self) -> usize {
            1
        }
        fn converged(&mut self, _x: &[f64]) {
            self.last = self.t;
        }
    }

    /// Advances along `admits`'s path (20 nominal increments) until the
    /// driver ends it, or 10^6 increments: the increments taken and the
    /// error.
    fn walk(admits: Admits) -> (usize, Option<SolverError>) {
        let mut eq = Path {
            t: 0.0,
            last: 0.0,
            admits,
        };
        let mut newton = StaticNewton::new(
            vec![0.0],
            vec![1.0],
            BandLu::new(1, 0, 0),
            BandMatrix::new(1, 0, 0),
            StaticSettings::default(),
        );
        for n in 0..1_000_000 {
            match newton.advance(&mut eq) {
                Ok(Some(_)) => {}
                Ok(None) => return (n, None),
                Err(e) => return (n, Some(e)),
            }
        }
        panic!("a load path still going after 10^6 increments");
    }

    #[test]
    fn a_load_path_that_cannot_pass_a_load_factor_ends_with_an_error_naming_it() {
        // 0.123456789 is not met by sums of 0.05 and its halves: the
        // driver used to take increments of zero below it forever.
        let ledges: [(f64, Admits); 5] = [
            (0.5, |t, _| t <= 0.5),
            (0.3, |t, _| t <= 0.3),
            (0.7, |t, _| t <= 0.7),
            (0.55, |t, _| t <= 0.55),
            (0.123456789, |t, _| t <= 0.123456789),
        ];
        for (ledge, admits) in ledges {
            let (n, e) = walk(admits);
            let e = e.unwrap_or_else(|| panic!("ledge {ledge}: the path went through"));
            assert!(n <= 220, "ledge {ledge}: {n} increments");
            assert!((e.time - ledge).abs() <= 1e-15, "ledge {ledge}: {e}");
            assert!(e.to_string().contains("10 halvings"), "{e}");
        }
    }

    #[test]
    fn a_load_path_of_far_more_increments_than_nominal_is_refused_where_it_stands() {
        // Newton converges only for increments up to 1e-4: 10^4 of them,
        // 500 times the 20 nominal ones.
        let (n, e) = walk(|t, last| t - last <= 1e-4);
        let e = e.expect("refused");
        assert_eq!(n, 220, "{e}");
        let m = e.to_string();
        assert!(
            m.contains("took 220 increments") && m.contains("creeps"),
            "{m}"
        );
        assert!(e.time > 0.0 && e.time < 0.1, "{m}");
    }

    #[test]
    fn a_load_path_of_few_cuts_reaches_the_full_load() {
        // Increments up to 0.02 converge (the nominal is 0.05): cut once
        // or twice, then at 0.0125 to 0.025 each.
        let (n, e) = walk(|t, last| t - last <= 0.02);
        assert!(e.is_none(), "{e:?}");
        assert!((50..=110).contains(&n), "{n}");
    }

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
                    assert!(inc.iterations <= super::SETTLED_ITERATIONS + 1, "{inc:?}");
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
            assert!(inc.residual <= super::ROUND_OFF_RESIDUAL, "{inc:?}");
            // Before the residual could have settled four iterations.
            assert!(inc.iterations < super::SETTLED_ITERATIONS, "{inc:?}");
        }
        assert!(
            (newton.x[0] + newton.x[1] - 1.0).abs() <= 1e-10,
            "{:?}",
            newton.x
        );
    }
}
