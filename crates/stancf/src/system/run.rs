//! The run of a system: stepping a [`SystemSimulation`] to a final time
//! with the single cable's step count and its shortened last step
//! (docs/method.md §11.15, as `integrator::run` does for a cable, §8).

use super::SystemSimulation;
use crate::error::SolverError;
use crate::integrator::{step_count, step_length, StepReport};
use std::ops::ControlFlow;

/// Where a run is: the step just taken is the `step`-th of `steps`
/// ([`step_count`] of the duration and the step length).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct RunProgress {
    /// The step just taken (1 = first).
    pub step: usize,
    /// The steps of the whole run.
    pub steps: usize,
}

impl RunProgress {
    /// Whether the step just taken is the run's last.
    pub fn is_last(&self) -> bool {
        self.step == self.steps
    }
}

/// Steps `sim` until `duration` is covered (docs/method.md §11.15): the
/// [`step_count`] of the duration and the simulation's step length, the
/// last one shortened to land on the duration (a single cable's run,
/// `crate::integrator::run`). Calls `observer` after every converged step;
/// the observer may stop the run early with `ControlFlow::Break` (the
/// result is then `Ok(false)`). Stops at the first failure (after the
/// step's halvings, §11.13) and leaves `sim` at the last converged step;
/// the states already observed stay valid.
///
/// The step length is the shortened one after a run whose last step was
/// shortened (set it back with [`SystemSimulation::set_time_step`] to run
/// on at the scenario's step). A system run has no energy watchdog (§8):
/// see §11.15.
pub fn run<F>(
    sim: &mut SystemSimulation,
    duration: f64,
    mut observer: F,
) -> Result<bool, SolverError>
where
    F: FnMut(&SystemSimulation, &StepReport, RunProgress) -> ControlFlow<()>,
{
    let dt = sim.time_step();
    let steps = step_count(duration, dt);
    for step in 1..=steps {
        if step == steps {
            let h = step_length(step, steps, duration, dt);
            if h != dt {
                sim.set_time_step(h);
            }
        }
        let report = sim.step()?;
        if observer(sim, &report, RunProgress { step, steps }).is_break() {
            return Ok(false);
        }
    }
    Ok(true)
}
