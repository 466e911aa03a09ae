//! The run of a system: stepping a [`SystemSimulation`] to a final time
//! with the single cable's step count and its shortened last step
//! (docs/method.md §11.15, as `integrator::run` does for a cable, §8).

use super::SystemSimulation;
use crate::error::{FailureKind, SolverError};
use crate::integrator::{step_count, step_length, EnergyWatch, StepReport};
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
/// on at the scenario's step).
///
/// The energy watchdog of a single cable's run (§8, (M29)) watches the
/// system's balance, `energies().mechanical() - external_work()`: a step
/// that raises it by more than a tenth of the motion's energy scale (and
/// above round-off) is an unstable step, P2 above its stable step, and
/// ends the run with [`FailureKind::EnergyGrowth`] (exit 3 on the command
/// line). That step is not observed (nothing of it is written); `sim` is
/// left after it.
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
    let mut watch = sim.energy_watch();
    for step in 1..=steps {
        sim.clear_step_records();
        if step == steps {
            let h = step_length(step, steps, duration, dt);
            if h != dt {
                sim.set_time_step(h);
            }
        }
        let report = watched_step(sim, &mut watch, sim.step_halvings())?;
        if observer(sim, &report, RunProgress { step, steps }).is_break() {
            return Ok(false);
        }
    }
    Ok(true)
}

/// One step of the run through the energy watchdog, then the line
/// failures due at its end (§11.16; after the watch, so that a step
/// undone sets none off). A Galerkin step whose balance jumps is taken
/// again in halves, each watched, as a step Newton fails is (up to
/// `halvings` levels, §11.13): the Galerkin step is stable at any length,
/// so its energy can only jump where Newton converged to a root that is
/// not the motion's (a rope on the bed at a long step, its contact's kink
/// between the iterates), and a shorter step starts nearer the motion's.
/// A P2 step above its stable step is the step the scenario chose and is
/// reported as it is.
pub(crate) fn watched_step(
    sim: &mut SystemSimulation,
    watch: &mut EnergyWatch,
    halvings: u32,
) -> Result<StepReport, SolverError> {
    let report = watched_part(sim, watch, halvings)?;
    sim.trigger_failures(&report)?;
    Ok(report)
}

/// [`watched_step`] without the failures' check (a part of a halved
/// step).
fn watched_part(
    sim: &mut SystemSimulation,
    watch: &mut EnergyWatch,
    halvings: u32,
) -> Result<StepReport, SolverError> {
    let retry = halvings > 0 && sim.settings.time_scheme.carries_momentum();
    let saved = retry.then(|| (sim.undo_point(), watch.clone()));
    let report = sim.step_before_failures()?;
    let Err(e) = watched(sim, &report, watch) else {
        return Ok(report);
    };
    let Some((undo, watch_before)) = saved.filter(|_| e.kind == FailureKind::EnergyGrowth) else {
        return Err(e);
    };
    if !sim.undo(undo) {
        return Err(e);
    }
    *watch = watch_before;
    let dt = sim.time_step();
    sim.set_time_step(0.5 * dt);
    let first = watched_part(sim, watch, halvings - 1);
    let first_means = sim.mean_forces();
    let halves = first.and_then(|a| watched_part(sim, watch, halvings - 1).map(|b| (a, b)));
    sim.set_time_step(dt);
    let (a, mut b) = halves?;
    sim.average_mean_forces(&first_means);
    b.newton.iterations += a.newton.iterations + report.newton.iterations;
    b.newton.factorizations += a.newton.factorizations + report.newton.factorizations;
    Ok(b)
}

/// The energy balance after the step `report` through `watch`: an error
/// where it is not finite or grew without a source.
fn watched(
    sim: &SystemSimulation,
    report: &StepReport,
    watch: &mut EnergyWatch,
) -> Result<(), SolverError> {
    let en = sim.energies();
    let work = sim.external_work();
    let failure = |kind, detail: String| SolverError {
        kind,
        time: sim.time(),
        step: report.step,
        residual: report.newton.residual,
        iterations: report.newton.iterations,
        detail,
    };
    if !(en.mechanical().is_finite() && work.is_finite()) {
        return Err(failure(
            FailureKind::NonFinite,
            "the energy is not finite".into(),
        ));
    }
    watch.check(&en, work).map_err(|drift| {
        failure(
            FailureKind::EnergyGrowth,
            format!(
                "the system's mechanical energy {:.6e} J plus the {:.6e} J that its moving \
                 points, drag, damping, the water and the seabed took out is {:.6e} J, \
                 {:.3e} J above the initial {:.6e} J: energy came from no source; reduce the \
                 time step",
                en.mechanical(),
                -work,
                en.mechanical() - work,
                drift,
                watch.initial().mechanical()
            ),
        )
    })
}
