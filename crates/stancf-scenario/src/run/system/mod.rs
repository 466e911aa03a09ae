//! The run of a system of lines (docs/interface.md, "Systems"): the
//! static equilibrium from the lines' catenaries (a static analysis, or
//! the start of a dynamic one with `analysis.initial = "static"`), then
//! the time stepping; results per line, per point and per line end.

mod between;
mod bodies;
mod channel_values;
mod moordyn_body_out;
mod moordyn_line_out;
mod moordyn_out;
mod moordyn_rod_out;
mod releases;
mod rods;
mod rows;
mod static_report;
mod statistics;
mod stiffness;
mod summary_file;
mod vtk_parts;
mod writers;

use super::summary::vec3;
use super::{io_err, Place, RunOptions};
use crate::scenario::{AnalysisKind, EndForces, SystemScenario};
use crate::Failure;
use between::Between;
use rows::{dynamic_row, static_row, step_end_forces};
use stancf::error::Sig;
use stancf::system::{
    run_to_tolerance, ControlledSteps, EndForce, StepControl, SystemSimulation, SystemStatics,
};
use stancf::SolverError;
use std::ops::ControlFlow;
use std::path::Path;
use std::time::Instant;
use summary_file::{report, write_summary};
use writers::SystemWriters;

/// How the run went: the largest tension at each line end, counts, the
/// failure or interruption.
struct Outcome {
    max_tension: Vec<[f64; 2]>,
    steps: usize,
    iterations: usize,
    increments: usize,
    t: f64,
    failure: Option<SolverError>,
    /// The failure was a time step's (not the static solve's).
    failed_stepping: bool,
    interrupted: bool,
    /// How the steps went where a tolerance chose them.
    controlled: Option<ControlledSteps>,
    /// The wall time of the time steps and their writing (s), after the
    /// static solve.
    stepping_wall: Option<f64>,
    /// Why a deck alone has no static equilibrium: its run wrote
    /// MoorDyn's start instead (`Prepared::unbalanced`).
    unbalanced: Option<String>,
}

impl Outcome {
    /// The outcome of a run of `lines` lines before it starts.
    fn new(lines: usize) -> Self {
        Outcome {
            max_tension: vec![[0.0; 2]; lines],
            steps: 0,
            iterations: 0,
            increments: 0,
            t: 0.0,
            failure: None,
            failed_stepping: false,
            interrupted: false,
            controlled: None,
            stepping_wall: None,
            unbalanced: None,
        }
    }

    /// Takes the end tensions of a simulation's last step into the
    /// largest ones (every step, without building a written row).
    fn record_step_tensions(&mut self, sim: &SystemSimulation, kind: EndForces) {
        for (i, (m, ends)) in self
            .max_tension
            .iter_mut()
            .zip(sim.topology().line_ends())
            .enumerate()
        {
            let forces = step_end_forces(sim, kind, i);
            for k in 0..2 {
                if ends[k] != stancf::system::End::Loose {
                    m[k] = m[k].max(forces[k].tension());
                }
            }
        }
    }

    fn record_tensions(&mut self, ends: &[[Option<EndForce>; 2]]) {
        for (m, e) in self.max_tension.iter_mut().zip(ends) {
            for k in 0..2 {
                if let Some(f) = e[k] {
                    m[k] = m[k].max(f.tension());
                }
            }
        }
    }
}

/// A system run into `place`; on success, the text to print.
pub(super) fn run_system(
    path: &Path,
    place: &Place,
    opts: &RunOptions,
    sc: SystemScenario,
) -> Result<String, Failure> {
    let crate::check_system::Prepared {
        system,
        statics: mut static_solve,
        dynamics: mut sim,
        unbalanced,
    } = admit(path, opts, &sc)?;
    let line_ids: Vec<i64> = sc.lines.iter().map(|l| l.id).collect();
    let point_ids: Vec<i64> = sc.points.iter().map(|p| p.id).collect();
    let body_ids: Vec<i64> = sc.bodies.iter().map(|b| b.id).collect();
    let clock = Instant::now();
    let mut outcome = Outcome::new(sc.lines.len());
    outcome.unbalanced = unbalanced;
    // history.csv accounts for the damping's work in a damped dynamic run.
    let damped = sc.analysis.kind == AnalysisKind::Dynamic
        && system
            .lines()
            .iter()
            .any(|l| l.model.has_axial_damping() || l.model.viscoelastic().is_some());
    // ... and for the water's and the seabed's work in water.
    let wet = sc.analysis.kind == AnalysisKind::Dynamic && sc.water.is_some();
    let models: Vec<&stancf::Model> = system.lines().iter().map(|l| &l.model).collect();
    let mut writers = SystemWriters::create(
        place.dest(),
        (&line_ids, &point_ids, &body_ids),
        (&sc.channels, sc.moordyn_out.as_deref(), &models),
        &sc.output_files,
        writers::Extras {
            vtk: opts.vtk,
            damping: damped,
            water: wet,
            dynamic: sc.analysis.kind == AnalysisKind::Dynamic,
            rod_nodes: sc
                .rods
                .iter()
                .map(|r| r.rod.as_ref().map_or(0, |r| r.segments) + 1)
                .collect(),
        },
    )
    .map_err(io_err(place.shown))?;
    if sc.analysis.kind == AnalysisKind::Dynamic {
        writers.times = time_grid(&sc);
    }
    writers.rods = rods::frames(&sc);
    writers.statistics = statistics::Statistics::new(&sc);
    writers.parts = vtk_parts::BodyParts::of(&sc);
    let mut from_static = false;
    let mut matrices = Vec::new();
    if let Some(st) = static_solve.as_mut() {
        solve_statics(st, opts, &mut outcome);
        if outcome.failure.is_some() || outcome.interrupted {
            sim = None;
        } else {
            let t = if sc.analysis.kind == AnalysisKind::Static {
                1.0
            } else {
                0.0
            };
            static_report::warn_of_static_compression(&sc, st);
            static_report::note_static_path(st);
            matrices = stiffness::at_equilibrium(st, &sc);
            stiffness::write_csv(place.dest(), &sc, &matrices).map_err(io_err(place.shown))?;
            let mut row = static_row(st, t);
            outcome.record_tensions(&row.ends);
            if sim.is_some() {
                // The free bodies where the equilibrium put them, with
                // their points: the lines' static shapes end there.
                let states = st.line_states();
                let start =
                    crate::check_system::simulation(&sc, st.system_at_equilibrium(), states)
                        .map_err(|e| Failure::Input(format!("{}: {}", path.display(), e)))?;
                // The run's start: the equilibrium with the bodies' starting rates.
                rows::with_start_rates(&mut row, &start);
                sim = Some(start);
                from_static = true;
            }
            writers.write(&row).map_err(io_err(place.shown))?;
        }
    }
    if let Some(s) = sim.as_mut().filter(|_| outcome.unbalanced.is_some()) {
        // A deck alone without an equilibrium: MoorDyn's start, as its
        // Init leaves it (docs/method.md §13.7), its one row.
        let row = dynamic_row(s, Some(sc.end_forces));
        outcome.record_tensions(&row.ends);
        writers.write(&row).map_err(io_err(place.shown))?;
    } else if let Some(s) = sim.as_mut() {
        if !from_static {
            // MoorDyn's start without initial conditions: its lines'
            // shapes' forces at t = 0 (docs/method.md §13.7, where MoorDyn
            // writes zeros); a straight start, none.
            let catenary = sc.initial == crate::scenario::InitialShape::Catenary;
            writers
                .write(&dynamic_row(s, catenary.then_some(sc.end_forces)))
                .map_err(io_err(place.shown))?;
        }
        let stepping = Instant::now();
        let stepped = step_through(s, &sc, opts, &mut writers, &mut outcome);
        outcome.stepping_wall = Some(stepping.elapsed().as_secs_f64());
        stepped.map_err(io_err(place.shown))?;
    }
    let statistics = std::mem::take(&mut writers.statistics).to_json(&sc);
    writers.commit().map_err(io_err(place.shown))?;
    let wall = clock.elapsed().as_secs_f64();
    write_summary(
        place.dest(),
        &sc,
        (&outcome, statistics),
        wall,
        (sim.as_ref(), static_solve.as_ref()),
        &matrices,
    )?;
    ending(path, place, opts, &sc, &outcome, wall)
}

/// Admits the system of `sc` (its files for `--plot`, its work bounds)
/// and prepares its static solve and simulation; warns of a time step
/// above the stable one.
fn admit(
    path: &Path,
    opts: &RunOptions,
    sc: &SystemScenario,
) -> Result<crate::check_system::Prepared, Failure> {
    // The figures of a system are drawn from these files (figures_system).
    let drawn_from = ["nodes.csv", "node_loads.csv", "tensions.csv", "history.csv"];
    let missing: Vec<&str> = drawn_from
        .into_iter()
        .filter(|n| !sc.output_files.writes(n))
        .collect();
    if opts.plot.is_some() && !missing.is_empty() {
        return Err(Failure::Input(format!(
            "{}: output.files: --plot draws from {}; the scenario leaves out {}",
            path.display(),
            drawn_from.join(", "),
            missing.join(", ")
        )));
    }
    crate::work_bounds::admit_system(&path.display().to_string(), sc, opts.allow_large)?;
    let prepared = crate::check_system::prepare(path, sc)?;
    for n in &sc.notes {
        eprintln!("warning: {n}");
    }
    if sc.analysis.kind == AnalysisKind::Dynamic {
        if let Some(stable) = crate::check_system::stable_step(sc, &prepared.system) {
            if sc.analysis.time_step > stable {
                eprintln!(
                    "warning: analysis.time_step: {} s is above the stable step of P2 for the \
                     stiffest line ({} s, see `stancf check`): the run may grow unstable",
                    Sig(sc.analysis.time_step),
                    Sig(stable)
                );
            }
        }
    }
    Ok(prepared)
}

/// How a run that wrote its files ends: interrupted, failed (with what
/// was kept), or the text to print.
fn ending(
    path: &Path,
    place: &Place,
    opts: &RunOptions,
    sc: &SystemScenario,
    outcome: &Outcome,
    wall: f64,
) -> Result<String, Failure> {
    let shown = place.shown.display();
    if outcome.interrupted {
        return Err(Failure::Interrupted(format!(
            "{}: interrupted; results up to t = {} s are in {shown}",
            path.display(),
            Sig(outcome.t)
        )));
    }
    if let Some(f) = &outcome.failure {
        let kept = if outcome.steps > 0 {
            format!("results up to t = {} s are in {shown}", Sig(outcome.t))
        } else {
            format!("no equilibrium was reached; {shown} holds the result files' headers")
        };
        // A Galerkin step whose energy jumps is halved too (docs/method.md
        // §11.15); a P2 step above its stable step is not.
        let galerkin_jump = f.kind == stancf::error::FailureKind::EnergyGrowth
            && sc.analysis.time_scheme == stancf::TimeScheme::Galerkin;
        let hint = if outcome.failed_stepping && (f.newton_failed() || galerkin_jump) {
            halving_hint(sc.analysis.step_halvings)
        } else {
            String::new()
        };
        return Err(Failure::Solver(format!(
            "{}: {f}{hint}; {kept}",
            path.display()
        )));
    }
    if opts.quiet {
        return Ok(String::new());
    }
    Ok(report(sc, outcome, wall, place))
}

/// What a failed time step's message adds on its halvings
/// (docs/method.md §11.13): that none were taken, or that `halvings` were
/// taken and what to try next.
fn halving_hint(halvings: u32) -> String {
    use stancf::system::{DEFAULT_STEP_HALVINGS, MAX_STEP_HALVINGS};
    if halvings == 0 {
        format!(
            " (analysis.step_halvings = 0: the failed step was not taken again in halves; \
             leave step_halvings out for the default {DEFAULT_STEP_HALVINGS}, or take a \
             shorter analysis.time_step)"
        )
    } else if halvings < MAX_STEP_HALVINGS {
        format!(
            " (after the step was halved {halvings} times, analysis.step_halvings: raise it, \
             up to {MAX_STEP_HALVINGS}, or take a shorter analysis.time_step)"
        )
    } else {
        format!(
            " (after the step was halved {halvings} times, the most there are: take a shorter \
             analysis.time_step)"
        )
    }
}

/// Follows the static path to the equilibrium; a failure or a cancel is
/// kept in `outcome`.
fn solve_statics(st: &mut SystemStatics, opts: &RunOptions, outcome: &mut Outcome) {
    let mut interrupted = false;
    let mut increments = 0;
    let mut iterations = 0;
    let result = st.solve(|_, inc| {
        increments += 1;
        iterations += inc.iterations;
        if opts.cancelled() {
            interrupted = true;
            return ControlFlow::Break(());
        }
        ControlFlow::Continue(())
    });
    outcome.increments = increments;
    outcome.iterations += iterations;
    outcome.interrupted = interrupted;
    if let Err(f) = result {
        outcome.failure = Some(f);
    }
}

/// The times a dynamic run writes, on the decimals of its step, its
/// duration and its output interval.
fn time_grid(sc: &SystemScenario) -> crate::output::TimeGrid {
    let a = &sc.analysis;
    let mut given = vec![a.time_step, a.duration];
    given.extend(sc.output_interval);
    crate::output::TimeGrid::of(&given)
}

/// Steps to the end of the analysis with the core's run of a system
/// (docs/method.md §11.15: the single cable's step count, the last step
/// shortened to land on the duration), writing every `output.every`-th
/// step and the last, or with `output.interval` the state at the
/// interval's multiples from the steps' cubics (§6.5a) and every step's
/// row of history.csv; a solver failure or a cancel ends it early.
fn step_through(
    sim: &mut SystemSimulation,
    sc: &SystemScenario,
    opts: &RunOptions,
    writers: &mut SystemWriters,
    outcome: &mut Outcome,
) -> std::io::Result<()> {
    let times = time_grid(sc);
    let mut last_written = 0;
    let mut written = Ok(());
    let mut reported = releases::Reported::default();
    let mut controlled = None;
    let mut between = sc
        .output_interval
        .map(|interval| Between::new(sim, interval))
        .transpose()?;
    let observe = |sim: &SystemSimulation,
                   rep: &stancf::integrator::StepReport,
                   at: stancf::system::RunProgress| {
        reported.catch_up(sim, sc, writers);
        outcome.steps = at.step;
        outcome.iterations += rep.newton.iterations;
        outcome.t = times.time(sim.time());
        outcome.record_step_tensions(sim, sc.end_forces);
        if let Some(between) = between.as_mut() {
            let mut row = dynamic_row(sim, Some(sc.end_forces));
            row.iterations = rep.newton.iterations;
            row.residual = rep.newton.residual;
            written = writers
                .write_step(&row)
                .and_then(|()| between.write(sim, writers, at.is_last()));
            if written.is_err() {
                return ControlFlow::Break(());
            }
            last_written = at.step;
        } else if at.step.is_multiple_of(sc.output_every) || at.is_last() {
            let mut row = dynamic_row(sim, Some(sc.end_forces));
            row.iterations = rep.newton.iterations;
            row.residual = rep.newton.residual;
            written = writers.write(&row);
            if written.is_err() {
                return ControlFlow::Break(());
            }
            last_written = at.step;
        }
        if opts.cancelled() {
            outcome.interrupted = true;
            return ControlFlow::Break(());
        }
        ControlFlow::Continue(())
    };
    let result = match sc.analysis.force_tolerance {
        None => stancf::system::run(sim, sc.analysis.duration, observe).map(|_| ()),
        Some(tolerance) => {
            let control = StepControl::new(sim, tolerance).map_err(|e| SolverError {
                kind: stancf::FailureKind::NotConverged,
                time: sim.time(),
                step: sim.steps(),
                residual: 0.0,
                iterations: 0,
                detail: e.to_string(),
            });
            control.and_then(|c| {
                run_to_tolerance(sim, sc.analysis.duration, c, observe)
                    .map(|(_, steps)| controlled = Some(steps))
            })
        }
    };
    outcome.controlled = controlled;
    written?;
    if let Err(f) = result {
        outcome.failure = Some(f);
        outcome.failed_stepping = true;
    }
    if outcome.steps > last_written {
        writers.write(&dynamic_row(sim, Some(sc.end_forces)))?;
    }
    if let Some(c) = controlled {
        // The steps the tolerance kept (each taken whole and in halves),
        // not the intervals written.
        outcome.steps = c.accepted;
    }
    Ok(())
}
