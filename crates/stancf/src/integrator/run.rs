//! Runs: stepping a [`Simulation`] to a final time under the energy
//! watchdog (docs/method.md §4.5, §8).

use super::{EnergyWatch, Simulation, StepReport, ENERGY_GROWTH_RATIO};
use crate::error::{FailureKind, SolverError};
use crate::observe::Energies;
use std::ops::ControlFlow;

/// Number of steps [`run`] takes to cover `duration` with steps `dt` (the
/// last one shortened to land on it).
pub fn step_count(duration: f64, dt: f64) -> usize {
    ((duration / dt) - 1e-9).ceil().max(1.0) as usize
}

/// The length of step `k` (1-based) of the `steps` = [`step_count`] steps
/// of `dt` that cover `duration` (docs/method.md §8, §11.15): dt, but the
/// last lands on the duration, what is left after n - 1 steps of dt. It is
/// taken from the grid (not from the time reached, which carries the
/// round-off of adding the steps), and within 1e-9 of dt it is dt itself,
/// as a coupling interval's steps are (§13.3): a whole number of steps
/// keeps the kept factors and repeats the run of single steps to the bit.
pub fn step_length(k: usize, steps: usize, duration: f64, dt: f64) -> f64 {
    if k < steps {
        return dt;
    }
    let h = duration - (steps - 1) as f64 * dt;
    if (h - dt).abs() <= 1e-9 * dt {
        dt
    } else {
        h
    }
}

/// Steps `sim` until `duration` is covered (the last step is shortened to
/// land on it), calling `observer` after every converged step; the
/// observer may stop the run early with `ControlFlow::Break` (the result
/// is then `Ok(false)`). Stops at the first failure and leaves `sim` at
/// the last good state (a step that converged but made the energy grow is
/// undone); the states already observed stay valid.
pub fn run<F>(sim: &mut Simulation, duration: f64, mut observer: F) -> Result<bool, SolverError>
where
    F: FnMut(&Simulation, &StepReport, &Energies) -> ControlFlow<()>,
{
    let dt = sim.settings.time_step;
    let n_steps = step_count(duration, dt);
    let mut watch = EnergyWatch::new(&sim.model, sim.energies(), ENERGY_GROWTH_RATIO);
    for k in 1..=n_steps {
        sim.set_time_step(step_length(k, n_steps, duration, dt));
        let report = sim.step()?;
        let en = sim.energies();
        let failure = |kind, detail: String, sim: &Simulation| SolverError {
            kind,
            time: sim.state.t,
            step: report.step,
            residual: report.newton.residual,
            iterations: report.newton.iterations,
            detail,
        };
        if !en.mechanical().is_finite() {
            sim.undo_last_step();
            return Err(failure(
                FailureKind::NonFinite,
                "the energy is not finite".into(),
                sim,
            ));
        }
        let work = sim.external_work();
        if let Err(drift) = watch.check(&en, work) {
            // The message is of the step that made the energy grow: its
            // energies and its work, taken before the step is undone.
            sim.undo_last_step();
            // The balance compared: the mechanical energy now plus what
            // drag and the constraints took out (their work W, negative
            // when they take energy out), against the energy at the start.
            // A drag that takes out more than the motion had is a growth
            // too, though the mechanical energy itself fell.
            let detail = format!(
                "the mechanical energy {:.6e} J plus the {:.6e} J that drag and the constraints \
                 took out is {:.6e} J, {:.3e} J above the initial {:.6e} J: energy came from \
                 no source; reduce the time step",
                en.mechanical(),
                -work,
                en.mechanical() - work,
                drift,
                watch.initial.mechanical()
            );
            return Err(failure(FailureKind::EnergyGrowth, detail, sim));
        }
        if observer(sim, &report, &en).is_break() {
            return Ok(false);
        }
    }
    Ok(true)
}
