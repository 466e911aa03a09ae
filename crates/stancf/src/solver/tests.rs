//! Tests of the nonlinear solvers on small model systems.

use super::*;

/// R_i(x) = x_i^3 + x_i - c_i + 0.1 (x_{i-1} + x_{i+1}): tridiagonal.
struct Cubic {
    c: Vec<f64>,
}

impl NonlinearSystem for Cubic {
    fn evaluate(&mut self, x: &[f64], r: &mut [f64], jac: Option<&mut BandMatrix>) {
        let n = x.len();
        for i in 0..n {
            let left = if i > 0 { x[i - 1] } else { 0.0 };
            let right = if i + 1 < n { x[i + 1] } else { 0.0 };
            r[i] = x[i].powi(3) + x[i] - self.c[i] + 0.1 * (left + right);
        }
        if let Some(j) = jac {
            j.clear();
            for i in 0..n {
                j.add(i, i, 3.0 * x[i] * x[i] + 1.0);
                if i > 0 {
                    j.add(i, i - 1, 0.1);
                }
                if i + 1 < n {
                    j.add(i, i + 1, 0.1);
                }
            }
        }
    }
    fn residual_norm(&self, r: &[f64]) -> f64 {
        r.iter().fold(0.0, |m: f64, v| m.max(v.abs()))
    }
    fn increment_norm(&self, dx: &[f64]) -> f64 {
        self.residual_norm(dx)
    }
}

#[test]
fn converges_quadratically_to_the_root() {
    let n = 20;
    let mut sys = Cubic {
        c: (0..n).map(|i| 1.0 + 0.1 * i as f64).collect(),
    };
    let mut x = vec![0.0; n];
    let mut ws = NewtonWorkspace::new(n, 1, 1, 50);
    let rep = newton(&mut sys, &mut x, &NewtonSettings::default(), &mut ws, None).unwrap();
    let mut r = vec![0.0; n];
    sys.evaluate(&x, &mut r, None);
    assert!(sys.residual_norm(&r) < 1e-12);
    assert!(rep.factorizations <= 8, "{rep:?}");
    // Quadratic convergence: in the last factorized steps the residual
    // ratio r_{k+1} / r_k^2 stays bounded.
    let h = &ws.residual_history;
    let k = h.iter().position(|&v| v < 1e-2).unwrap();
    if k + 1 < h.len() && h[k + 1] > 1e-15 {
        assert!(h[k + 1] < 10.0 * h[k] * h[k], "{h:?}");
    }
}

/// Broyden converges to the same root, superlinearly, with fewer
/// factorizations than Newton, and reuses its factors for a nearby
/// system.
#[test]
fn broyden_finds_the_same_root_with_fewer_factorizations() {
    let n = 20;
    let c: Vec<f64> = (0..n).map(|i| 1.0 + 0.1 * i as f64).collect();
    let settings = NewtonSettings {
        tolerance: 1e-12,
        max_iterations: 50,
        method: SolverMethod::Broyden,
    };
    let mut sys = Cubic { c: c.clone() };
    let mut xb = vec![0.8; n];
    let mut ws = NewtonWorkspace::new(n, 1, 1, 50);
    let rb = broyden(&mut sys, &mut xb, &settings, &mut ws, None).unwrap();
    let mut xn = vec![0.8; n];
    let mut wn = NewtonWorkspace::new(n, 1, 1, 50);
    let rn = newton(&mut sys, &mut xn, &NewtonSettings::default(), &mut wn, None).unwrap();
    let diff = xb
        .iter()
        .zip(&xn)
        .map(|(a, b)| (a - b).abs())
        .fold(0.0, f64::max);
    assert!(diff < 1e-11, "{diff}");
    assert!(rb.factorizations < rn.factorizations, "{rb:?} vs {rn:?}");
    // A nearby system starts from the factors in hand.
    sys.c.iter_mut().for_each(|v| *v += 1e-4);
    let rb2 = broyden(&mut sys, &mut xb, &settings, &mut ws, None).unwrap();
    assert!(rb2.factorizations <= 1, "{rb2:?}");
    let mut r = vec![0.0; n];
    sys.evaluate(&xb, &mut r, None);
    assert!(sys.residual_norm(&r) < 1e-12);
}

#[test]
fn convergence_rate_of_model_sequences() {
    let quadratic = [1e-1, 1e-2, 1e-4, 1e-8];
    assert!((convergence_rate(&quadratic, 0.0).unwrap() - 2.0).abs() < 1e-12);
    let linear = [1.0, 0.5, 0.25];
    assert!((convergence_rate(&linear, 0.0).unwrap() - 1.0).abs() < 1e-12);
    assert_eq!(convergence_rate(&[1.0, 0.1], 0.0), None);
    // A round-off plateau below the floor is left out.
    let plateau = [1e-2, 1e-4, 1e-8, 3e-17, 2e-17];
    assert!((convergence_rate(&plateau, 1e-15).unwrap() - 2.0).abs() < 1e-12);
}

#[test]
fn reports_non_convergence() {
    let n = 3;
    let mut sys = Cubic { c: vec![1e6; n] };
    let mut x = vec![0.0; n];
    let mut ws = NewtonWorkspace::new(n, 1, 1, 3);
    let s = NewtonSettings {
        tolerance: 1e-12,
        max_iterations: 3,
        ..NewtonSettings::default()
    };
    let err = newton(&mut sys, &mut x, &s, &mut ws, None).unwrap_err();
    assert_eq!(err.kind, FailureKind::NotConverged);
    assert_eq!(err.report.factorizations, 3);
}

/// A residual with a noise floor above what the increment test can
/// see through: r = x - 1 + (-1)^k 1e-14 at the k-th evaluation, with
/// increments weighted 1e6. The residual drops below the tolerance at
/// once, but no increment ever does (it is at least 2e-14 x 1e6 = 2e-8).
struct NoisyFloor {
    evaluations: usize,
}

impl NonlinearSystem for NoisyFloor {
    fn evaluate(&mut self, x: &[f64], r: &mut [f64], jac: Option<&mut BandMatrix>) {
        self.evaluations += 1;
        let noise = if self.evaluations.is_multiple_of(2) {
            1e-14
        } else {
            -1e-14
        };
        r[0] = x[0] - 1.0 + noise;
        if let Some(j) = jac {
            j.clear();
            j.add(0, 0, 1.0);
        }
    }
    fn residual_norm(&self, r: &[f64]) -> f64 {
        r[0].abs()
    }
    fn increment_norm(&self, dx: &[f64]) -> f64 {
        1e6 * dx[0].abs()
    }
}

/// Issue 11 (found by the property tests): Newton's confirming chord
/// steps used to repeat for ever when round-off kept the increment above
/// the tolerance; they count against the iteration limit (plus one).
#[test]
fn newton_ends_when_round_off_keeps_the_increment_above_the_tolerance() {
    let settings = NewtonSettings {
        tolerance: 1e-10,
        max_iterations: 5,
        method: SolverMethod::Newton,
    };
    let mut sys = NoisyFloor { evaluations: 0 };
    let mut x = [0.0];
    let mut ws = NewtonWorkspace::new(1, 0, 0, 10);
    let err = newton(&mut sys, &mut x, &settings, &mut ws, None).unwrap_err();
    assert_eq!(err.kind, FailureKind::NotConverged);
    assert_eq!(err.report.iterations, settings.max_iterations + 1);
    assert!((x[0] - 1.0).abs() < 1e-13);
}

/// R(x) = A x - b with A = diag(1e-3, 1): a guess 1e-8 off in the first
/// coordinate has a residual of 1e-11, below the tolerance 1e-10, but
/// its error is not. No solver may accept it unchecked: each applies an
/// update and lands on the root.
struct Stiff;

impl NonlinearSystem for Stiff {
    fn evaluate(&mut self, x: &[f64], r: &mut [f64], jac: Option<&mut BandMatrix>) {
        r[0] = 1e-3 * x[0] - 1e-3;
        r[1] = x[1] - 2.0;
        if let Some(j) = jac {
            j.clear();
            j.add(0, 0, 1e-3);
            j.add(1, 1, 1.0);
        }
    }
    fn residual_norm(&self, r: &[f64]) -> f64 {
        r.iter().fold(0.0, |m: f64, v| m.max(v.abs()))
    }
    fn increment_norm(&self, dx: &[f64]) -> f64 {
        self.residual_norm(dx)
    }
}

#[test]
fn a_guess_within_the_residual_tolerance_is_still_corrected() {
    for method in [
        SolverMethod::Newton,
        SolverMethod::Broyden,
        SolverMethod::ModifiedNewton,
    ] {
        let settings = NewtonSettings {
            tolerance: 1e-10,
            max_iterations: 10,
            method,
        };
        let mut x = [1.0 + 1e-8, 2.0];
        let mut ws = NewtonWorkspace::new(2, 1, 1, 10);
        let rep = solve(&mut Stiff, &mut x, &settings, &mut ws, None).unwrap();
        assert!(rep.iterations >= 1, "{method:?}: {rep:?}");
        assert!((x[0] - 1.0).abs() < 1e-14, "{method:?}: {x:?}");
        assert!((x[1] - 2.0).abs() < 1e-14, "{method:?}: {x:?}");
    }
}

/// Counts a system's evaluations, with and without the Jacobian.
struct Counted<S> {
    inner: S,
    alone: usize,
    with_jacobian: usize,
}

impl<S: NonlinearSystem> NonlinearSystem for Counted<S> {
    fn evaluate(&mut self, x: &[f64], r: &mut [f64], jac: Option<&mut BandMatrix>) {
        match jac {
            Some(_) => self.with_jacobian += 1,
            None => self.alone += 1,
        }
        self.inner.evaluate(x, r, jac);
    }
    fn residual_norm(&self, r: &[f64]) -> f64 {
        self.inner.residual_norm(r)
    }
    fn increment_norm(&self, dx: &[f64]) -> f64 {
        self.inner.increment_norm(dx)
    }
}

/// Newton assembles the Jacobian with the residual where it will need
/// it (docs/method.md §7.2): one evaluation per update and one to confirm
/// the last, where evaluating the residual first and the Jacobian after
/// it would take two per Newton update. The second solve of a nearby
/// system predicts its first update's residual from the first solve's.
#[test]
fn newton_evaluates_once_per_iteration() {
    let n = 20;
    let c: Vec<f64> = (0..n).map(|i| 1.0 + 0.1 * i as f64).collect();
    let settings = NewtonSettings {
        tolerance: 1e-12,
        ..NewtonSettings::default()
    };
    let mut sys = Counted {
        inner: Cubic { c },
        alone: 0,
        with_jacobian: 0,
    };
    let mut ws = NewtonWorkspace::new(n, 1, 1, 50);
    for solve in 0..3 {
        sys.alone = 0;
        sys.with_jacobian = 0;
        let mut x = vec![0.8 + 0.01 * solve as f64; n];
        let report = newton(&mut sys, &mut x, &settings, &mut ws, None).unwrap();
        let evaluations = sys.alone + sys.with_jacobian;
        assert!(report.factorizations >= 3, "{report:?}");
        assert!(
            evaluations <= report.iterations + 2,
            "solve {solve}: {evaluations} evaluations ({} with the Jacobian) for {report:?}",
            sys.with_jacobian
        );
        assert!(sys.with_jacobian >= report.factorizations, "{report:?}");
    }
}

/// R(x) = s A x - b with A tridiagonal: linear, so a chord step on the
/// factors of another scale s0 contracts every error by 1 - s / s0.
struct Scaled {
    scale: f64,
}

impl NonlinearSystem for Scaled {
    fn evaluate(&mut self, x: &[f64], r: &mut [f64], jac: Option<&mut BandMatrix>) {
        let n = x.len();
        for i in 0..n {
            let left = if i > 0 { x[i - 1] } else { 0.0 };
            let right = if i + 1 < n { x[i + 1] } else { 0.0 };
            r[i] = self.scale * (4.0 * x[i] - left - right) - 1.0;
        }
        if let Some(j) = jac {
            j.clear();
            for i in 0..n {
                j.add(i, i, 4.0 * self.scale);
                if i > 0 {
                    j.add(i, i - 1, -self.scale);
                }
                if i + 1 < n {
                    j.add(i, i + 1, -self.scale);
                }
            }
        }
    }
    fn residual_norm(&self, r: &[f64]) -> f64 {
        r.iter().fold(0.0, |m: f64, v| m.max(v.abs()))
    }
    fn increment_norm(&self, dx: &[f64]) -> f64 {
        self.residual_norm(dx)
    }
}

/// Factors kept from a system 1.4 times stiffer contract the error by
/// 1 - 1/1.4 = 0.29 a chord step: the residual halves at every step, so
/// the halving rule alone would keep them for the ~22 steps to 1e-12.
/// (M28a) predicts those steps after two and rebuilds the Jacobian, after
/// which the linear system is solved in one update and confirmed by one
/// more (docs/method.md §7.4).
#[test]
fn modified_newton_rebuilds_a_tangent_that_contracts_slowly() {
    let n = 12;
    let settings = NewtonSettings {
        tolerance: 1e-12,
        max_iterations: 50,
        method: SolverMethod::ModifiedNewton,
    };
    let mut ws = NewtonWorkspace::new(n, 1, 1, 50);
    let mut stiff = Scaled { scale: 1.4 };
    let mut x = vec![0.0; n];
    broyden(&mut stiff, &mut x, &settings, &mut ws, None).unwrap();
    assert!(ws.factors_valid);
    let mut soft = Scaled { scale: 1.0 };
    let mut x = vec![0.0; n];
    let report = broyden(&mut soft, &mut x, &settings, &mut ws, None).unwrap();
    assert_eq!(report.factorizations, 1, "{report:?}");
    assert!(report.iterations <= 5, "{report:?}");
    // Broyden keeps the halving rule only: its corrections learn the
    // scale instead.
    let broyden_settings = NewtonSettings {
        method: SolverMethod::Broyden,
        ..settings
    };
    let mut wb = NewtonWorkspace::new(n, 1, 1, 50);
    let mut x = vec![0.0; n];
    broyden(&mut stiff, &mut x, &broyden_settings, &mut wb, None).unwrap();
    let mut x = vec![0.0; n];
    let report = broyden(&mut soft, &mut x, &broyden_settings, &mut wb, None).unwrap();
    assert_eq!(report.factorizations, 0, "{report:?}");
}

/// r = 1e4 (x - 1) + (-1)^k 2e-10 at the k-th evaluation: a residual
/// whose round-off floor, 2e-10 to 4e-10, is above the tolerance 1e-10,
/// while the unknown settles to 4e-14 (a stiff line at a long Galerkin
/// step: scaled residuals of 1.3e-10 to 4.2e-10 for 47 iterations
/// running, increments 1e-14, docs/method.md §7.2).
struct FloorAboveTolerance {
    evaluations: usize,
}

impl NonlinearSystem for FloorAboveTolerance {
    fn evaluate(&mut self, x: &[f64], r: &mut [f64], jac: Option<&mut BandMatrix>) {
        self.evaluations += 1;
        let noise = if self.evaluations.is_multiple_of(2) {
            -2e-10
        } else {
            2e-10
        };
        r[0] = 1e4 * (x[0] - 1.0) + noise;
        if let Some(j) = jac {
            j.clear();
            j.add(0, 0, 1e4);
        }
    }
    fn residual_norm(&self, r: &[f64]) -> f64 {
        r[0].abs()
    }
    fn increment_norm(&self, dx: &[f64]) -> f64 {
        dx[0].abs()
    }
}

/// Newton ends at the residual's round-off floor (`at_residual_floor`):
/// once an update has moved the unknown by less than 1e-2 of the
/// tolerance and the residual, within 100 times it, did not halve, the
/// iterate is the root to the unknowns' last bits. It used to iterate
/// to the limit and fail, and the step was taken again in halves.
#[test]
fn newton_ends_at_a_residual_floor_above_the_tolerance() {
    let settings = NewtonSettings {
        tolerance: 1e-10,
        max_iterations: 50,
        method: SolverMethod::Newton,
    };
    let mut sys = FloorAboveTolerance { evaluations: 0 };
    let mut x = [0.0];
    let mut ws = NewtonWorkspace::new(1, 0, 0, 60);
    let report = newton(&mut sys, &mut x, &settings, &mut ws, None).unwrap();
    assert!(report.iterations <= 3, "{report:?}");
    assert!(report.residual > settings.tolerance, "{report:?}");
    assert!((x[0] - 1.0).abs() < 1e-13, "{x:?}");
}
