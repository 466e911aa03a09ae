//! Broyden's rank-one method and modified Newton (docs/method.md §7.3-7.4).

use super::{
    now, Clock, NewtonFailure, NewtonReport, NewtonSettings, NewtonWorkspace, NonlinearSystem,
    SolverMethod, CHORD_STEPS_WORTH_A_TANGENT,
};
use crate::error::FailureKind;
use crate::linear::Factorization;

/// Broyden's rank-one method (see the module documentation), or modified
/// Newton when `settings.method` says so (no rank-one corrections).
pub fn broyden<F: Factorization, S: NonlinearSystem<F::Matrix>>(
    system: &mut S,
    x: &mut [f64],
    settings: &NewtonSettings,
    ws: &mut NewtonWorkspace<F>,
    clock: Option<&dyn Clock>,
) -> Result<NewtonReport, NewtonFailure> {
    let tol = settings.tolerance;
    let mut report = NewtonReport::default();
    ws.prepare_broyden(settings.max_iterations);
    ws.residual_history.clear();
    ws.updates = 0;
    let fail = |kind, report| Err(NewtonFailure { kind, report });
    let t0 = now(clock);
    system.evaluate(x, &mut ws.residual, None);
    ws.timing.part_a += now(clock) - t0;
    let mut r = system.residual_norm(&ws.residual);
    report.residual = r;
    ws.residual_history.push(r);
    if !r.is_finite() {
        return fail(FailureKind::NonFinite, report);
    }
    let mut refactorize = !ws.factors_valid;
    let mut last_theta = 0.0f64;
    loop {
        if refactorize {
            if report.factorizations >= settings.max_iterations {
                return fail(FailureKind::NotConverged, report);
            }
            if let Err(kind) = fresh_jacobian(system, x, ws, &mut report, clock) {
                return fail(kind, report);
            }
            refactorize = false;
        }
        if report.iterations >= settings.max_iterations {
            return fail(FailureKind::NotConverged, report);
        }
        // dx = B R; x <- x - dx; s = -dx.
        let t0 = now(clock);
        ws.dx.copy_from_slice(&ws.residual);
        NewtonWorkspace::apply_inverse(
            &ws.lu,
            &ws.updates_a,
            &ws.updates_s,
            ws.updates,
            &mut ws.dx,
        );
        for (xi, d) in x.iter_mut().zip(ws.dx.iter()) {
            *xi -= d;
        }
        ws.timing.part_b += now(clock) - t0;
        report.iterations += 1;
        report.increment = system.increment_norm(&ws.dx);
        if r <= tol && report.increment <= tol {
            // Converged: the residual before this update and the update
            // itself are within the tolerance.
            return Ok(report);
        }
        ws.previous.copy_from_slice(&ws.residual);
        let t0 = now(clock);
        system.evaluate(x, &mut ws.residual, None);
        ws.timing.part_a += now(clock) - t0;
        let r_new = system.residual_norm(&ws.residual);
        report.residual = r_new;
        if ws.residual_history.len() < ws.residual_history.capacity() {
            ws.residual_history.push(r_new);
        }
        if !r_new.is_finite() || !report.increment.is_finite() {
            ws.factors_valid = false;
            return fail(FailureKind::NonFinite, report);
        }
        if r_new <= tol && report.increment <= tol {
            return Ok(report);
        }
        // Modified Newton (M28a): the contraction of the chord steps so
        // far, the larger of the last two ratios (they alternate where J0
        // has turned), and the steps it still needs to the tolerance.
        let theta = r_new / r;
        let rate = theta.max(last_theta);
        last_theta = theta;
        let too_slow = settings.method == SolverMethod::ModifiedNewton
            && (tol / r_new).ln() / rate.ln() > CHORD_STEPS_WORTH_A_TANGENT;
        if r_new > 0.5 * r || ws.updates == ws.updates_a.len() || too_slow {
            last_theta = 0.0;
            // Not contracting, too slowly, or out of room: a fresh
            // Jacobian here.
            refactorize = true;
            r = r_new;
            continue;
        }
        if settings.method == SolverMethod::ModifiedNewton {
            r = r_new;
            continue;
        }
        refactorize = !broyden_update(ws, clock);
        r = r_new;
    }
}

/// A fresh Jacobian at x, factorized; the stored updates dropped
/// (docs/method.md §7.3-7.4).
fn fresh_jacobian<F: Factorization, S: NonlinearSystem<F::Matrix>>(
    system: &mut S,
    x: &[f64],
    ws: &mut NewtonWorkspace<F>,
    report: &mut NewtonReport,
    clock: Option<&dyn Clock>,
) -> Result<(), FailureKind> {
    let t0 = now(clock);
    system.evaluate(x, &mut ws.residual, Some(ws.lu.matrix_mut()));
    let t1 = now(clock);
    ws.timing.part_a += t1 - t0;
    report.factorizations += 1;
    ws.updates = 0;
    let ok = ws.lu.factorize().is_ok();
    ws.timing.part_b += now(clock) - t1;
    if !ok {
        ws.factors_valid = false;
        return Err(FailureKind::SingularJacobian);
    }
    ws.factors_valid = true;
    Ok(())
}

/// Broyden's good update of the inverse (docs/method.md §7.3, eq. 27):
/// y = R_new - R_old, B y, a = (s - B y) / (s . B y) with s = -dx, stored
/// as the next rank-one pair. False when s . B y vanishes (a fresh
/// Jacobian is needed instead).
fn broyden_update<F: Factorization>(
    ws: &mut NewtonWorkspace<F>,
    clock: Option<&dyn Clock>,
) -> bool {
    let t0 = now(clock);
    for ((y, rn), ro) in
        ws.y.iter_mut()
            .zip(ws.residual.iter())
            .zip(ws.previous.iter())
    {
        *y = rn - ro;
    }
    ws.by.copy_from_slice(&ws.y);
    NewtonWorkspace::apply_inverse(&ws.lu, &ws.updates_a, &ws.updates_s, ws.updates, &mut ws.by);
    let denom: f64 = ws.dx.iter().zip(ws.by.iter()).map(|(d, b)| -d * b).sum();
    let k = ws.updates;
    let updated = denom.abs() > f64::EPSILON * 1e3;
    if updated {
        for (((a, s), d), b) in ws.updates_a[k]
            .iter_mut()
            .zip(ws.updates_s[k].iter_mut())
            .zip(ws.dx.iter())
            .zip(ws.by.iter())
        {
            *s = -d;
            *a = (-d - b) / denom;
        }
        ws.updates += 1;
    }
    ws.timing.part_b += now(clock) - t0;
    updated
}
