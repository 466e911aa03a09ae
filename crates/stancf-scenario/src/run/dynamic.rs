//! The dynamic run: the scenario stepped through its duration, every
//! `output.every`-th step (and the last) written to the result files, the
//! solver's diagnostics of every step to solver.csv and convergence.csv.

use super::summary::{
    common_summary, error_json, reactions_json, say, tip_line, vec3, write_summary, Tally,
};
use super::writers::{Row, SolverRow, WallClock, Writers, STRESS_POINTS_PER_ELEMENT};
use super::{io_err, Place, RunOptions};
use crate::check::{warnings, Derived};
use crate::output::json_num;
use crate::progress::Progress;
use crate::scenario::Scenario;
use crate::Failure;
use serde_json::{json, Value};
use stancf::error::Sig;
use stancf::observe::{momentum, stress_samples, Energies, StressSample};
use stancf::{Model, Simulation, SolverError, State, StepReport, Timing};
use std::ops::ControlFlow;
use std::path::Path;
use std::time::Instant;

/// A dynamic run into `place`; on success, the text to print.
pub(super) fn run_dynamic(
    path: &Path,
    place: &Place,
    opts: &RunOptions,
    sc: Scenario,
    model: Model,
    state: State,
    d: Derived,
) -> Result<String, Failure> {
    for w in warnings(&sc, &model, Some(&d)) {
        eprintln!("warning: {w}");
    }
    let mut sim = Simulation::new(model, state, sc.step_settings())
        .map_err(|e| Failure::Input(format!("{}: {}", path.display(), e)))?;
    sim.set_clock(Box::new(WallClock(Instant::now())));
    let constrained = !sim.model().constraints.is_empty();
    let damped = sim.model().has_axial_damping();
    let mut writers = Writers::create(place.dest(), constrained, true, opts.vtk, damped)
        .map_err(io_err(place.shown))?;
    writers.times = super::times_of(&sc.analysis);
    let e0 = sim.energies();
    let first = Row {
        state: sim.state(),
        energies: &e0,
        iterations: 0,
        residual: 0.0,
        increment: 0.0,
        reactions: None,
        constraint_work: 0.0,
        drag_work: 0.0,
        damping_work: 0.0,
    };
    writers
        .write(sim.model(), &first)
        .map_err(io_err(place.shown))?;
    let stepped =
        step_through(&mut sim, &mut writers, &sc, &d, opts, e0).map_err(io_err(place.shown))?;
    writers.commit().map_err(io_err(place.shown))?;
    write_dynamic_summary(place, &sc, &sim, &d, &stepped)?;
    if let Some(stop) = early_end(path, place, &sc, &sim, &d, &stepped) {
        return Err(stop);
    }
    if opts.quiet {
        return Ok(String::new());
    }
    Ok(dynamic_report(&sc, &sim, &stepped, place))
}

/// What the time stepping did: its running figures and how it ended.
struct Stepped {
    tally: Tally,
    /// The energies at the start.
    e0: Energies,
    /// Wall time of the stepping, s.
    wall: f64,
    failure: Option<SolverError>,
    interrupted: bool,
}

/// The bookkeeping after every converged step: solver diagnostics, the
/// running figures, the progress bar, the rows every `every` steps, and
/// the requests to stop.
struct StepObserver<'a> {
    opts: &'a RunOptions,
    writers: &'a mut Writers,
    e0: Energies,
    tally: Tally,
    /// Write every `every`-th step.
    every: usize,
    /// Residuals below this are round-off for the rate estimate.
    rate_floor: f64,
    progress: Progress,
    /// The stress samples of the latest step (for the peak).
    peak_samples: Vec<StressSample>,
    /// The last step written, and the solver figures of the latest step
    /// (iterations, residual, increment).
    last_written: usize,
    last_newton: (usize, f64, f64),
    /// The library's timing after the previous step.
    last_timing: Timing,
    /// The write error that stopped the run, if any.
    io_failure: Option<std::io::Error>,
    interrupted: bool,
}

impl StepObserver<'_> {
    /// After the step `rep`: stops on a cancel request or a write error,
    /// else records the step (see [`StepObserver`]).
    fn observe(&mut self, sim: &Simulation, rep: &StepReport, en: &Energies) -> ControlFlow<()> {
        if self.opts.cancelled() {
            self.interrupted = true;
            return ControlFlow::Break(());
        }
        self.last_newton = (
            rep.newton.iterations,
            rep.newton.residual,
            rep.newton.increment,
        );
        if let Err(e) = self.write_solver(sim, rep) {
            self.io_failure = Some(e);
            return ControlFlow::Break(());
        }
        self.record(sim, rep, en);
        if rep.step.is_multiple_of(self.every) {
            let row = Row {
                state: sim.state(),
                energies: en,
                iterations: rep.newton.iterations,
                residual: rep.newton.residual,
                increment: rep.newton.increment,
                reactions: Some(sim.reactions()),
                constraint_work: sim.constraint_work(),
                drag_work: sim.drag_work(),
                damping_work: sim.damping_work(),
            };
            match self.writers.write(sim.model(), &row) {
                Ok(()) => self.last_written = rep.step,
                Err(e) => {
                    self.io_failure = Some(e);
                    return ControlFlow::Break(());
                }
            }
        }
        ControlFlow::Continue(())
    }

    /// The step's line of solver.csv and convergence.csv, with its share
    /// of the Part A / Part B time; takes its convergence rate into the
    /// tally.
    fn write_solver(&mut self, sim: &Simulation, rep: &StepReport) -> std::io::Result<()> {
        let timing = sim.timing();
        let solver_row = SolverRow {
            t: rep.t,
            step: rep.step,
            report: &rep.newton,
            residuals: sim.residual_history(),
            part_a: timing.part_a - self.last_timing.part_a,
            part_b: timing.part_b - self.last_timing.part_b,
            rate_floor: self.rate_floor,
        };
        self.last_timing = timing;
        if let Some(r) = stancf::convergence_rate(sim.residual_history(), self.rate_floor) {
            self.tally.rate_sum += r;
            self.tally.rate_steps += 1;
        }
        self.writers.write_solver(&solver_row)
    }

    /// Takes the step into the tally (iterations, residuals, the energy
    /// drift against the work done, the stress peak) and the progress bar.
    fn record(&mut self, sim: &Simulation, rep: &StepReport, en: &Energies) {
        let (tally, e0) = (&mut self.tally, &self.e0);
        tally.iterations += rep.newton.iterations;
        self.progress.update(rep.step, rep.t, tally.iterations);
        tally.factorizations += rep.newton.factorizations;
        tally.max_iterations = tally.max_iterations.max(rep.newton.iterations);
        tally.max_residual = tally.max_residual.max(rep.newton.residual);
        let work = sim.external_work();
        let potential_change =
            (en.gravity - e0.gravity).abs() + (en.load_potential - e0.load_potential).abs();
        tally.energy_scale = tally
            .energy_scale
            .max(en.kinetic.abs() + en.strain.abs() + potential_change + work.abs());
        tally.energy_max_abs_drift = tally
            .energy_max_abs_drift
            .max((en.mechanical() - e0.mechanical() - work).abs());
        stress_samples(
            sim.model(),
            sim.state(),
            STRESS_POINTS_PER_ELEMENT,
            &mut self.peak_samples,
        );
        tally.record_stress(rep.t, &self.peak_samples);
    }
}

/// Steps `sim` through the scenario's duration, observing every step
/// ([`StepObserver`]), then writes the last converged step if
/// `output.every` skipped it. A write error is the error; a solver failure
/// or an interruption is in the answer.
fn step_through(
    sim: &mut Simulation,
    writers: &mut Writers,
    sc: &Scenario,
    d: &Derived,
    opts: &RunOptions,
    e0: Energies,
) -> std::io::Result<Stepped> {
    let mut tally = Tally {
        // Never zero: at rest the energies are round-off, and so would be a
        // drift measured against them (docs/method.md §8).
        energy_scale: (e0.kinetic.abs() + e0.strain.abs())
            .max(stancf::integrator::energy_resolution(sim.model())),
        ..Tally::default()
    };
    tally.record_stress(0.0, &writers.samples);
    let clock = Instant::now();
    let mut obs = StepObserver {
        opts,
        writers,
        e0,
        tally,
        every: sc.output_every,
        rate_floor: sc.analysis.tolerance,
        progress: Progress::new(d.steps, !opts.quiet),
        peak_samples: Vec::new(),
        last_written: 0,
        last_newton: (0, 0.0, 0.0),
        last_timing: Timing::default(),
        io_failure: None,
        interrupted: false,
    };
    let result = stancf::run(sim, sc.analysis.duration, |sim, rep, en| {
        obs.observe(sim, rep, en)
    });
    obs.progress.finish();
    let wall = clock.elapsed().as_secs_f64();
    if let Some(e) = obs.io_failure.take() {
        return Err(e);
    }
    // The last converged step when `output.every` skipped it (also of a
    // run that failed or was interrupted), with its own solver figures.
    if obs.last_written != sim.steps() {
        let en = sim.energies();
        let (iterations, residual, increment) = obs.last_newton;
        let row = Row {
            state: sim.state(),
            energies: &en,
            iterations,
            residual,
            increment,
            reactions: Some(sim.reactions()),
            constraint_work: sim.constraint_work(),
            drag_work: sim.drag_work(),
            damping_work: sim.damping_work(),
        };
        obs.writers.write(sim.model(), &row)?;
    }
    Ok(Stepped {
        tally: obs.tally,
        e0,
        wall,
        failure: result.err(),
        interrupted: obs.interrupted,
    })
}

/// The solver's name in summary.json.
fn solver_name(method: stancf::SolverMethod) -> &'static str {
    match method {
        stancf::SolverMethod::Newton => "newton",
        stancf::SolverMethod::Broyden => "broyden",
        stancf::SolverMethod::ModifiedNewton => "modified-newton",
    }
}

/// summary.json's `solver`: the method, its factorizations and
/// convergence rate, and the Part A / Part B times.
fn solver_json(sc: &Scenario, sim: &Simulation, tally: &Tally, steps: usize) -> Value {
    let timing = sim.timing();
    json!({
        "method": solver_name(sc.analysis.solver),
        "factorizations": tally.factorizations,
        "tangents_per_step": json_num(tally.factorizations as f64 / steps.max(1) as f64),
        "convergence_rate": if tally.rate_steps > 0 {
            json_num(tally.rate_sum / tally.rate_steps as f64)
        } else {
            Value::Null
        },
        "convergence_rate_steps": tally.rate_steps,
        "part_a_s": json_num(timing.part_a),
        "part_b_s": json_num(timing.part_b),
    })
}

/// Writes summary.json of a dynamic run.
fn write_dynamic_summary(
    place: &Place,
    sc: &Scenario,
    sim: &Simulation,
    d: &Derived,
    run: &Stepped,
) -> Result<(), Failure> {
    let (state, model, tally) = (sim.state(), sim.model(), &run.tally);
    let en = sim.energies();
    let (mass, p, first_moment) = momentum(model, state);
    let steps = sim.steps();
    let mut summary = common_summary(sc, model, state, run.wall);
    summary.insert("steps".into(), json!(steps));
    summary.insert(
        "time".into(),
        json_num(super::times_of(&sc.analysis).time(state.t)),
    );
    summary.insert("converged".into(), json!(run.failure.is_none()));
    summary.insert("iterations".into(), tally.iterations_json(steps));
    summary.insert(
        "energy".into(),
        json!({
            "initial": json_num(run.e0.mechanical()),
            "final": json_num(en.mechanical()),
            "max_abs_drift": json_num(tally.energy_max_abs_drift),
            "max_rel_drift": json_num(tally.energy_max_abs_drift / tally.energy_scale),
            "scale": json_num(tally.energy_scale),
            "constraint_work": json_num(sim.constraint_work()),
            "drag_work": json_num(sim.drag_work()),
            "damping_work": json_num(sim.damping_work()),
        }),
    );
    summary.insert("solver".into(), solver_json(sc, sim, tally, steps));
    let extra = json!({
        "time_step": json_num(sc.analysis.time_step),
        "time_layers": sc.analysis.time_layers,
        "unknowns_per_step": sim.unknowns_per_step(),
        "planar": sim.is_planar(),
        "max_residual": json_num(tally.max_residual),
        "courant_number": json_num(d.courant),
        "highest_frequency": json_num(d.w_max),
        // P2's limit; the Galerkin step has none.
        "stable_time_step": d
            .stable_step
            .filter(|_| sc.analysis.time_scheme.conditionally_stable())
            .map(json_num)
            .unwrap_or(Value::Null),
        "time_scheme": match sc.analysis.time_scheme {
            stancf::TimeScheme::P2 => "p2",
            stancf::TimeScheme::Galerkin => "galerkin",
        },
        "w_max_dt": json_num(d.w_max * sc.analysis.time_step),
        "stress_peak": tally.stress_json(),
        "linear_momentum": vec3(p),
        "center_of_mass": vec3(first_moment.map(|c| c / mass)),
        "reactions": reactions_json(sim.reactions()),
        "error": error_json(run.interrupted, run.failure.as_ref()),
        // Where the solver failed: the step it could not take.
        "failure": run.failure.as_ref().map(|f| json!({
            "time": json_num(f.time),
            "step": f.step,
            "residual": json_num(f.residual),
            "iterations": f.iterations,
        })),
        "interrupted": run.interrupted,
    });
    write_summary(place.dest(), summary, extra)
}

/// The failure of a run that was interrupted or that the solver could not
/// finish (its results up to the last converged step are kept); `None`
/// when it ran to the end.
fn early_end(
    path: &Path,
    place: &Place,
    sc: &Scenario,
    sim: &Simulation,
    d: &Derived,
    run: &Stepped,
) -> Option<Failure> {
    let (t, steps) = (sim.state().t, sim.steps());
    if run.interrupted {
        return Some(Failure::Interrupted(format!(
            "{}: interrupted; results up to t = {} s (step {}) are in {}",
            path.display(),
            Sig(t),
            steps,
            place.shown.display()
        )));
    }
    let f = run.failure.as_ref()?;
    // A Galerkin step beyond its meaningful range (warned at the start).
    let w_dt = d.w_max * sc.analysis.time_step;
    let beyond = if sc.analysis.time_scheme == stancf::TimeScheme::Galerkin
        && w_dt > stancf::stability::GALERKIN_ACCURATE_W_DT
    {
        format!(
            "; the Galerkin step's w_max dt = {w_dt:.1} is beyond {:.2}, the largest at which \
             its results are shown to be meaningful: use a step of at most {:.4e} s",
            stancf::stability::GALERKIN_ACCURATE_W_DT,
            stancf::stability::galerkin_accurate_step(d.w_max)
        )
    } else {
        String::new()
    };
    Some(Failure::Solver(format!(
        "{}: {f}{beyond}; results up to t = {} s (step {}) are in {}",
        path.display(),
        Sig(t),
        steps,
        place.shown.display()
    )))
}

/// The printed report of a dynamic run that reached its end.
fn dynamic_report(sc: &Scenario, sim: &Simulation, run: &Stepped, place: &Place) -> String {
    let mut report = String::new();
    let (state, tally, steps) = (sim.state(), &run.tally, sim.steps());
    let en = sim.energies();
    say!(report,
        "{}: {} steps to t = {} s in {:.3} s wall time, {:.2} {} iterations per step, {} factorizations",
        crate::echo::clip(&sc.title, crate::echo::MAX_ECHO),
        steps,
        Sig(state.t),
        run.wall,
        tally.iterations as f64 / steps.max(1) as f64,
        match sc.analysis.solver {
            stancf::SolverMethod::Newton => "Newton",
            stancf::SolverMethod::Broyden => "Broyden",
            stancf::SolverMethod::ModifiedNewton => "modified Newton",
        },
        tally.factorizations
    );
    say!(
        report,
        "energy: initial {:.9e} J, final {:.9e} J, max drift {:.3e} J ({:.3e} of the energy scale)",
        run.e0.mechanical(),
        en.mechanical(),
        tally.energy_max_abs_drift,
        tally.energy_max_abs_drift / tally.energy_scale
    );
    say!(
        report,
        "peak axial stress: {:.6e} Pa at s = {} m, t = {:.6e} s",
        tally.stress_peak.0,
        Sig(tally.stress_peak.1),
        tally.stress_peak.2
    );
    say!(report, "{}", tip_line(sim.model(), state, place.shown));
    report
}
