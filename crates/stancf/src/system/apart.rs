//! The step of a system without free points (docs/method.md §11.14):
//! every line ends at fixed or coupled points, whose motion is given, so
//! the lines' slab equations do not share an unknown and the system's
//! Jacobian is block diagonal. Each line is then solved apart, by its own
//! Newton (its own tangent policy and kept factors) to the system's
//! tolerance on its own rows and unknowns, and the lines are solved on
//! rayon's threads. The step converges when every line does, as the
//! joint solve (whose max-norm criterion is the lines' criteria taken
//! together) would; a line no longer takes the updates another line
//! still needs, so the iterates differ from the joint solve's within the
//! tolerance. Which thread solves which line changes nothing: a line's
//! solve reads and writes that line alone.

use crate::error::SolverError;
use crate::integrator::Simulation;
use crate::solver::NewtonReport;
use rayon::prelude::*;

/// The least work of a step, elements in all times the Newton iterations
/// of the last step (at least 2), for which the lines are solved on
/// rayon's threads: below it waking a thread costs more than it saves
/// (docs/method.md §11.14). 48 elements at 2 iterations. Measured on this
/// 2-core machine, the OC4 race deck (3 lines, 300 s; stepping time, one
/// thread against two): 21 elements in sections at dt 0.1 (2.2
/// iterations a step) 0.99 s against 1.13 s, at dt 0.5 (4.8) 0.40 s
/// against 0.36 s, at dt 2 (7 to 10) 0.271 s against 0.207 s; 30
/// elements at dt 0.1 (2.2) 1.28 s against 1.40 s; before, at dt 0.1,
/// 60 elements 2.05 s against 1.95 s, 120 elements 5.0 s against 4.0 s.
pub const PARALLEL_LINES_WORK: usize = 96;

/// Solves every line's step apart (each predicted by its `begin_step`),
/// on rayon's threads if the step's work, its elements times
/// `last_iterations` (the last step's, 0 before the first), reaches
/// [`PARALLEL_LINES_WORK`]; on success the lines hold their converged
/// unknowns. The report: the
/// most iterations and factorizations of a line (the step's Newton
/// rounds, as the joint solve counts them) and the largest residual and
/// increment. On failure, the first failing line's error (in line
/// order); no line has finished its step and every line holds its
/// prediction again.
pub(super) fn solve_lines_apart(
    lines: &mut [Simulation],
    dt: f64,
    last_iterations: usize,
) -> Result<NewtonReport, SolverError> {
    for line in lines.iter_mut() {
        line.keep_prediction();
    }
    let solve = |(i, line): (usize, &mut Simulation)| line.solve_slab(dt).map_err(|e| (i, e));
    let elements: usize = lines.iter().map(|l| l.model().nodes() - 1).sum();
    let work = elements * last_iterations.max(2);
    let step = if lines.len() > 1 && work >= PARALLEL_LINES_WORK && crate::threads::usable() {
        lines
            .par_iter_mut()
            .enumerate()
            .map(solve)
            .reduce(|| Ok(NewtonReport::default()), combine)
    } else {
        lines
            .iter_mut()
            .enumerate()
            .map(solve)
            .fold(Ok(NewtonReport::default()), combine)
    };
    step.map_err(|(i, mut e)| {
        // Every line back to its prediction (the joint solve leaves the
        // lines' unknowns untouched until it converges): a halved retry
        // (§11.13) starts where the failed step did.
        for line in lines.iter_mut() {
            line.restore_prediction();
        }
        e.detail = format!("lines[{i}]: {}", e.detail);
        e
    })
}

/// Two lines' (or groups of lines') outcomes as one: the most iterations
/// and factorizations, the largest residual and increment; of two
/// failures the line first in line order (the same whichever thread
/// finished first).
fn combine(
    a: Result<NewtonReport, (usize, SolverError)>,
    b: Result<NewtonReport, (usize, SolverError)>,
) -> Result<NewtonReport, (usize, SolverError)> {
    match (a, b) {
        (Ok(a), Ok(b)) => Ok(NewtonReport {
            iterations: a.iterations.max(b.iterations),
            factorizations: a.factorizations.max(b.factorizations),
            residual: a.residual.max(b.residual),
            increment: a.increment.max(b.increment),
        }),
        (Err(a), Err(b)) => Err(if a.0 <= b.0 { a } else { b }),
        (Err(e), Ok(_)) | (Ok(_), Err(e)) => Err(e),
    }
}
