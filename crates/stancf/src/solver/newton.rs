//! Newton-Raphson with the exact Jacobian, eq. (25) (docs/method.md §7.2).

use super::{
    now, Clock, NewtonFailure, NewtonReport, NewtonSettings, NewtonWorkspace, NonlinearSystem,
};
use crate::error::FailureKind;
use crate::linear::Factorization;

/// Newton's method from the guess in `x` (see the module documentation).
///
/// One evaluation per Newton iteration: where the Jacobian will be needed
/// (at the guess, which always gets a Newton update, and wherever the
/// residual is not expected within the tolerance), the residual is
/// evaluated with it (docs/method.md §7.2). Expected: after a Newton update
/// from r_k, whose predecessor was r_{k-1}, the next residual is about
/// r_k^2 / r_{k-1} (the ratio of the last two, once more); after the
/// first update, as it was after the first update of the last solve; a residual
/// predicted within the tolerance is evaluated alone, and the Jacobian is
/// evaluated afterwards if the prediction fails. The iterates are those of
/// evaluating the residual first and the Jacobian where needed, to the bit:
/// the residual does not depend on whether the Jacobian comes with it.
pub fn newton<F: Factorization, S: NonlinearSystem<F::Matrix>>(
    system: &mut S,
    x: &mut [f64],
    settings: &NewtonSettings,
    ws: &mut NewtonWorkspace<F>,
    clock: Option<&dyn Clock>,
) -> Result<NewtonReport, NewtonFailure> {
    let tol = settings.tolerance;
    let mut report = NewtonReport::default();
    ws.residual_history.clear();
    // Newton's factors are of the last iterate's Jacobian, not a Broyden
    // start for the next solve.
    ws.factors_valid = false;
    let fail = |kind, report| Err(NewtonFailure { kind, report });
    let mut want_jacobian = true;
    let mut before_update: Option<f64> = None;
    // The Jacobian is evaluated into `next` and factorized there, then
    // swapped with `lu`: a Jacobian evaluated for nothing (the residual
    // came within the tolerance) leaves the factors of the last update
    // for the chord step.
    if ws.next.is_none() {
        ws.next = Some(ws.lu.clone());
    }
    loop {
        let with_jacobian = want_jacobian && report.factorizations < settings.max_iterations;
        let t0 = now(clock);
        let next = ws.next.as_mut().expect("made above");
        if with_jacobian {
            system.evaluate(x, &mut ws.residual, Some(next.matrix_mut()));
        } else {
            system.evaluate(x, &mut ws.residual, None);
        }
        ws.timing.part_a += now(clock) - t0;
        let r = system.residual_norm(&ws.residual);
        report.residual = r;
        if ws.residual_history.len() < ws.residual_history.capacity() {
            ws.residual_history.push(r);
        }
        if !r.is_finite() {
            return fail(FailureKind::NonFinite, report);
        }
        if before_update.is_some_and(|b| super::at_residual_floor(b, r, report.increment, tol)) {
            return Ok(report);
        }
        if report.iterations == 1 {
            ws.one_update_sufficed = r <= tol;
        }
        if r <= tol && report.iterations > 0 {
            if report.increment <= tol {
                return Ok(report);
            }
            // Chord steps count against the iteration limit (one beyond it
            // to confirm the last Newton update): where round-off keeps the
            // increment above the tolerance, they would go on for ever.
            if report.iterations > settings.max_iterations {
                return fail(FailureKind::NotConverged, report);
            }
            // Confirm with a chord step on the factors in hand (a Jacobian
            // evaluated with this residual is not factorized: the factors
            // in hand are the last Newton update's).
            let t0 = now(clock);
            ws.update_with_factors(x);
            ws.timing.part_b += now(clock) - t0;
            report.iterations += 1;
            report.increment = system.increment_norm(&ws.dx);
            if report.increment <= tol {
                return Ok(report);
            }
            want_jacobian = false;
            continue;
        }
        if report.factorizations >= settings.max_iterations {
            return fail(FailureKind::NotConverged, report);
        }
        if let Err(kind) = newton_update(system, x, ws, &mut report, with_jacobian, clock) {
            return fail(kind, report);
        }
        if r <= tol && report.increment <= tol {
            // The guess was already within the tolerance and the Newton
            // update confirms it.
            return Ok(report);
        }
        want_jacobian = match before_update {
            Some(previous) if previous > 0.0 => r * (r / previous) > tol,
            Some(_) => false,
            None => !ws.one_update_sufficed,
        };
        before_update = Some(r);
    }
}

/// One Newton update (docs/method.md §7.2): the Jacobian at x (unless it
/// was evaluated with the residual), factorized and swapped into `lu`,
/// and x <- x - J^-1 R; the increment's norm into the report.
fn newton_update<F: Factorization, S: NonlinearSystem<F::Matrix>>(
    system: &mut S,
    x: &mut [f64],
    ws: &mut NewtonWorkspace<F>,
    report: &mut NewtonReport,
    with_jacobian: bool,
    clock: Option<&dyn Clock>,
) -> Result<(), FailureKind> {
    let t1 = now(clock);
    let next = ws.next.as_mut().expect("made by newton");
    if !with_jacobian {
        system.evaluate(x, &mut ws.residual, Some(next.matrix_mut()));
    }
    let t2 = now(clock);
    ws.timing.part_a += t2 - t1;
    report.factorizations += 1;
    let factorized = next.factorize();
    std::mem::swap(&mut ws.lu, next);
    if factorized.is_err() {
        return Err(FailureKind::SingularJacobian);
    }
    ws.update_with_factors(x);
    ws.timing.part_b += now(clock) - t2;
    report.iterations += 1;
    report.increment = system.increment_norm(&ws.dx);
    if !report.increment.is_finite() {
        return Err(FailureKind::NonFinite);
    }
    Ok(())
}
