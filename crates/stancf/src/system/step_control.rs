//! A run whose steps are chosen by a tolerance on the end forces
//! (docs/method.md §11.17): the run is written at the multiples of its
//! step length, as [`super::run`] writes it, and each such interval is
//! crossed in as many equal steps as the tolerance needs; the step length
//! is the first and the largest step.
//!
//! The estimate is step doubling: each step is taken once whole and once
//! as two halves from the same state, and the largest difference of the
//! line ends' forces at its end (M23b), relative to the larger of each
//! end's force and its line's weight, is the step's error
//!
//! ```text
//!   err = max_ends |R_whole(t_b) - R_halves(t_b)| / max(|R_halves(t_b)|, w L g)   (M23c)
//! ```
//!
//! and the same at the step's middle, the whole step's force cubic there
//! (what a run writes between the ends of its steps, docs/method.md
//! §6.5a) against the first half's force at its end. The halves are
//! kept. No asymptotic constant enters: where the step
//! resolves the motion the halves' own error is about err / 15 (M23b is
//! O(dt^4), the state's error smaller still), and where it does not (a
//! mode the step carries at a wrong frequency, a force noisy from step to
//! step) the two differ by about what each is off. Estimates from one
//! step's smoothness (the last step's force cubic extrapolated, the jump
//! between two steps' cubics at their common end) were tried on the
//! jumper of examples/jumper-tolerance.toml and missed that second case
//! by about 40 times.
//! A step is kept when err is within the tolerance; otherwise it is taken
//! again shorter. The next step is `0.9 (tol / err)^(1/4)` times this
//! one, at most twice and at least a fifth, never longer than the step
//! length and never past the interval's end. A step costs three solves
//! (whole and halves) and advances as two halves do: 1.5 times the cost
//! of a fixed step of its half, less for the first half, which starts
//! from the whole step's cubic (§4.8).

use super::run::{watched_step, RunProgress};
use super::{EndForce, SystemSimulation};
use crate::error::{FailureKind, ModelError, SolverError};
use crate::integrator::{step_count, step_length, StepReport, StepSettings};
use std::ops::ControlFlow;

/// The step control of a run: the tolerance on the end forces' estimated
/// error, relative to each end's force (or its line's weight, if more).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct StepControl {
    tolerance: f64,
}

impl StepControl {
    /// The control of `sim`'s run at `tolerance`, the largest relative
    /// error of an end force at a step's end (M23c): positive and finite,
    /// and the Galerkin step (P2's rows do not give the forces' cubics).
    pub fn new(sim: &SystemSimulation, tolerance: f64) -> Result<Self, ModelError> {
        Self::for_steps(&sim.settings, tolerance)
    }

    /// [`Self::new`] for a simulation stepped with `settings`.
    pub fn for_steps(settings: &StepSettings, tolerance: f64) -> Result<Self, ModelError> {
        if !(tolerance.is_finite() && tolerance > 0.0) {
            return Err(ModelError::invalid(
                "tolerance",
                format!("must be positive and finite, got {tolerance}"),
            ));
        }
        if !settings.time_scheme.carries_momentum() {
            return Err(ModelError::invalid(
                "tolerance",
                "a step chosen by a tolerance needs the Galerkin step: P2's rows do not give \
                 the end forces over a step (docs/method.md (M23b))",
            ));
        }
        Ok(StepControl { tolerance })
    }

    /// The tolerance.
    pub fn tolerance(&self) -> f64 {
        self.tolerance
    }
}

/// How a controlled run stepped. A step is checked whole and kept as its
/// two halves (M23c): its length is the whole's.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct ControlledSteps {
    /// Steps kept.
    pub accepted: usize,
    /// Steps taken again shorter (their error above the tolerance, or
    /// their halves not converged).
    pub rejected: usize,
    /// The shortest and the longest step kept (s).
    pub shortest: f64,
    pub longest: f64,
}

/// The smallest step the control may take, as a fraction of the run's
/// step length: a tolerance that needs shorter steps is not met
/// ([`FailureKind::NotConverged`] names it).
pub const MIN_STEP_FRACTION: f64 = 1e-6;

/// The largest relative difference between the end forces of `whole`,
/// after one step, and of `halves`, after two steps of half its length
/// from the same state (M23c): at the step's end, each one's force at t
/// (M23b); and at its middle, where the whole step kept its record, the
/// whole step's force cubic there (what a run writes between the ends of
/// its steps, §6.5a) against the first half's force at its end,
/// `middle`. Each end's difference is over the larger of its force and
/// its line's weight (a slack end is judged against the weight, not
/// against nothing).
fn force_difference(
    whole: &SystemSimulation,
    halves: &SystemSimulation,
    (t_middle, middle): (f64, &[[EndForce; 2]]),
) -> f64 {
    let g = crate::vec3::norm(halves.topology.gravity());
    let mut worst = 0.0f64;
    let mut compare = |a: &EndForce, b: &EndForce, weight: f64| {
        let scale = b.tension().max(weight);
        if scale > 0.0 {
            let d = crate::vec3::norm(crate::vec3::sub(a.force, b.force));
            worst = worst.max(d / scale);
        }
    };
    for (i, line) in halves.lines.iter().enumerate() {
        let model = line.model();
        let weight = model.material.density * model.material.area * model.cable.length * g;
        let (a, b) = (whole.end_forces_at_time(i), halves.end_forces_at_time(i));
        for k in 0..2 {
            compare(&a[k], &b[k], weight);
        }
        if let (Ok(a), Some(b)) = (whole.end_forces_within(i, t_middle), middle.get(i)) {
            for k in 0..2 {
                compare(&a[k], &b[k], weight);
            }
        }
    }
    worst
}

/// The next step's length after a step of `dt` whose error was `error`
/// of the tolerance `tol`.
fn next_step(dt: f64, error: f64, tol: f64) -> f64 {
    let factor = if error > 0.0 {
        0.9 * (tol / error).powf(0.25)
    } else {
        2.0
    };
    dt * factor.clamp(0.2, 2.0)
}

/// Steps `sim` until `duration` is covered, as [`super::run`] does, but
/// each of its steps (of the simulation's step length, the last
/// shortened) crossed in steps chosen by `control` (M23c): `observer` is
/// called at the end of each such interval, with the interval's Newton
/// iterations summed, and may stop the run. Needs the Galerkin step (its
/// end forces' cubics); the step length is the simulation's again after
/// the run. Fails where the tolerance needs a step below
/// [`MIN_STEP_FRACTION`] of the step length, with the time, the step and
/// the estimated error; the states already observed stay valid.
pub fn run_to_tolerance<F>(
    sim: &mut SystemSimulation,
    duration: f64,
    control: StepControl,
    mut observer: F,
) -> Result<(bool, ControlledSteps), SolverError>
where
    F: FnMut(&SystemSimulation, &StepReport, RunProgress) -> ControlFlow<()>,
{
    let big = sim.time_step();
    let intervals = step_count(duration, big);
    let t0 = sim.time();
    let mut stepper = Stepper::new(sim, control, big);
    let mut interval_start = t0;
    for k in 1..=intervals {
        let end = interval_start + step_length(k, intervals, duration, big);
        sim.clear_step_records();
        let report = stepper.cross(sim, end);
        sim.set_time_step(big);
        let report = report?;
        interval_start = end;
        if observer(
            sim,
            &report,
            RunProgress {
                step: k,
                steps: intervals,
            },
        )
        .is_break()
        {
            return Ok((false, stepper.steps));
        }
    }
    Ok((true, stepper.steps))
}

/// A doubled step's whole: the copy it was taken on and its report.
type Whole = Result<(SystemSimulation, StepReport), SolverError>;

/// A doubled step's halves: the second half's report, what the
/// caller's `half` gave after each, and each line's end forces at t
/// (M23b) after the first.
type Halves<T> = Result<(StepReport, [T; 2], Vec<[EndForce; 2]>), SolverError>;

/// One kept step of a controlled run: taken whole and as two halves
/// (M23c), the halves kept.
pub(crate) struct Kept<T> {
    /// The second half's report, with the Newton iterations and
    /// factorizations of every solve the step took (its whole steps and
    /// halves, those of rejected tries included).
    pub report: StepReport,
    /// What the caller's `half` gave after each kept half step.
    pub halves: [T; 2],
}

/// The control's state across intervals (and across a coupling code's
/// calls): the next step's length and how the steps went.
pub(crate) struct Stepper {
    control: StepControl,
    big: f64,
    next: f64,
    watch: crate::integrator::EnergyWatch,
    steps: ControlledSteps,
}

impl Stepper {
    fn new(sim: &SystemSimulation, control: StepControl, big: f64) -> Self {
        Self::resume(control, big, big, sim.energy_watch())
    }

    /// A control of steps of at most `big` whose next step is `next`
    /// (clamped to `big`), its energy watch `watch`.
    pub(crate) fn resume(
        control: StepControl,
        big: f64,
        next: f64,
        watch: crate::integrator::EnergyWatch,
    ) -> Self {
        Stepper {
            control,
            big,
            next: next.min(big),
            watch,
            steps: ControlledSteps::default(),
        }
    }

    /// The next step's length and the energy watch.
    pub(crate) fn into_parts(self) -> (f64, crate::integrator::EnergyWatch) {
        (self.next, self.watch)
    }

    /// Steps `sim` to `end` exactly; the report of the last step with the
    /// Newton iterations of all (whole steps and halves) summed.
    fn cross(&mut self, sim: &mut SystemSimulation, end: f64) -> Result<StepReport, SolverError> {
        let (mut iterations, mut factorizations) = (0, 0);
        loop {
            let kept = self.advance(sim, end, &mut |_: &SystemSimulation, _: f64| ())?;
            iterations += kept.report.newton.iterations;
            factorizations += kept.report.newton.factorizations;
            if self.reached(sim, end) {
                let mut report = kept.report;
                report.newton.iterations = iterations;
                report.newton.factorizations = factorizations;
                return Ok(report);
            }
        }
    }

    /// Whether `sim` is at `end` (to a billionth of the step length).
    pub(crate) fn reached(&self, sim: &SystemSimulation, end: f64) -> bool {
        sim.time() >= end - 1e-9 * self.big
    }

    /// Takes one step toward `end` that the tolerance keeps: the next
    /// step's length shortened to divide what is left of the way to `end`
    /// into equal steps, taken whole and in halves, and taken again
    /// shorter until its error (M23c) is within the tolerance. `half` is
    /// called after each half step with the half's length; what it gives
    /// for a rejected try is dropped. On failure (a step below
    /// [`MIN_STEP_FRACTION`] of the step length needed) `sim` is where
    /// the step started.
    pub(crate) fn advance<T>(
        &mut self,
        sim: &mut SystemSimulation,
        end: f64,
        half: &mut dyn FnMut(&SystemSimulation, f64) -> T,
    ) -> Result<Kept<T>, SolverError> {
        let (mut iterations, mut factorizations) = (0, 0);
        loop {
            let left = end - sim.time();
            let n = (left / self.next - 1e-9).ceil().max(1.0);
            let dt = left / n;
            let start = sim.clone();
            let watch = self.watch.clone();
            let t_middle = sim.time() + 0.5 * dt;
            let (whole, halves) = self.doubled(sim, dt, half);
            let tol = self.control.tolerance;
            let (error, mut report, given) = match (whole, halves) {
                (Ok((whole, w)), Ok((h, given, middle))) => {
                    iterations += w.newton.iterations + h.newton.iterations;
                    factorizations += w.newton.factorizations + h.newton.factorizations;
                    let error = force_difference(&whole, sim, (t_middle, &middle));
                    (error, h, given)
                }
                // The whole step failed where its halves did not: too long.
                (Err(_), Ok((h, given, _))) => (f64::INFINITY, h, given),
                (_, Err(e)) => {
                    sim.clone_from(&start);
                    self.watch = watch;
                    if 0.25 * dt < MIN_STEP_FRACTION * self.big {
                        return Err(e);
                    }
                    self.steps.rejected += 1;
                    self.next = 0.25 * dt;
                    continue;
                }
            };
            if error > tol {
                let shorter = next_step(dt, error, tol).min(0.5 * dt);
                let failure = (shorter < MIN_STEP_FRACTION * self.big)
                    .then(|| too_short(sim, &report, error, tol, shorter));
                sim.clone_from(&start);
                self.watch = watch;
                if let Some(failure) = failure {
                    return Err(failure);
                }
                self.steps.rejected += 1;
                self.next = shorter;
                continue;
            }
            self.keep(dt, error);
            report.newton.iterations = iterations;
            report.newton.factorizations = factorizations;
            return Ok(Kept {
                report,
                halves: given,
            });
        }
    }

    /// A step of `dt` taken whole on a copy of `sim` and in two halves
    /// on `sim` (the second half's report, the halves' iterations summed),
    /// `half` called after each half.
    fn doubled<T>(
        &mut self,
        sim: &mut SystemSimulation,
        dt: f64,
        half: &mut dyn FnMut(&SystemSimulation, f64) -> T,
    ) -> (Whole, Halves<T>) {
        let mut whole = sim.clone();
        whole.set_time_step(dt);
        // Its force cubic is compared with the halves' at the middle
        // (M23c), where the system's state between the ends of a step is
        // interpolated (§6.5a; not with a free body or an internal state).
        let _ = whole.record_steps(true);
        let mut watch = self.watch.clone();
        let halvings = sim.step_halvings();
        let whole = watched_step(&mut whole, &mut watch, halvings).map(|r| (whole, r));
        if let Ok((w, _)) = &whole {
            // The first half starts from the whole step's cubic (§4.8).
            for (line, done) in sim.lines.iter_mut().zip(&w.lines) {
                if let Some(cubic) = done.last_cubic() {
                    line.guide_next_step(cubic);
                }
            }
        }
        sim.set_time_step(0.5 * dt);
        let halves = watched_step(sim, &mut self.watch, halvings).and_then(|a| {
            let first = half(sim, 0.5 * dt);
            let middle = (0..sim.lines.len())
                .map(|i| sim.end_forces_at_time(i))
                .collect();
            let mut b = watched_step(sim, &mut self.watch, halvings)?;
            let second = half(sim, 0.5 * dt);
            b.newton.iterations += a.newton.iterations;
            b.newton.factorizations += a.newton.factorizations;
            Ok((b, [first, second], middle))
        });
        (whole, halves)
    }

    /// Books a kept step of `dt` (its halves) and chooses the next.
    fn keep(&mut self, dt: f64, error: f64) {
        let s = &mut self.steps;
        s.accepted += 1;
        s.shortest = if s.accepted == 1 {
            dt
        } else {
            s.shortest.min(dt)
        };
        s.longest = s.longest.max(dt);
        let tol = self.control.tolerance;
        self.next = next_step(dt, error, tol).min(self.big);
    }
}

fn too_short(
    sim: &SystemSimulation,
    report: &StepReport,
    error: f64,
    tol: f64,
    shorter: f64,
) -> SolverError {
    SolverError {
        kind: FailureKind::NotConverged,
        time: sim.time(),
        step: report.step,
        residual: report.newton.residual,
        iterations: report.newton.iterations,
        detail: format!(
            "the end forces' estimated error {error:.3e} is above the tolerance {tol:.3e} and \
             needs a step of {shorter:.3e} s, below {MIN_STEP_FRACTION:e} of the step length \
             (docs/method.md (M23c)); loosen the tolerance or look for a motion the lines \
             cannot follow"
        ),
    }
}
