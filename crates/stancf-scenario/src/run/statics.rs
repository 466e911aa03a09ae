//! The static run: the load stepped up to its full value, each converged
//! increment written as a row of the result files.

use super::summary::{
    common_summary, error_json, reactions_json, say, tip_line, write_summary, Tally,
};
use super::writers::{Row, Writers};
use super::{io_err, Place, RunOptions};
use crate::check::warnings;
use crate::output::json_num;
use crate::scenario::Scenario;
use crate::Failure;
use serde_json::json;
use stancf::error::Sig;
use stancf::observe::Energies;
use stancf::{energies, Model, SolverError, State, StaticSolver};
use std::ops::ControlFlow;
use std::time::Instant;

/// Energies of a static state at load factor lambda: the potentials of the
/// applied loads (lambda times the full ones), no kinetic energy.
fn static_energies(model: &Model, state: &State) -> Energies {
    let mut en = energies(model, state);
    en.gravity *= state.t;
    en.load_potential *= state.t;
    en
}

/// What the load stepping did: its running figures and how it ended.
struct Stepping {
    tally: Tally,
    /// Load increments taken, and the increment cuts over all of them.
    increments: usize,
    cuts: usize,
    interrupted: bool,
    /// Wall time of the solve, s.
    wall: f64,
    failure: Option<SolverError>,
}

/// A static run into `place`; on success, the text to print.
pub(super) fn run_static(
    path: &std::path::Path,
    place: &Place,
    opts: &RunOptions,
    sc: Scenario,
    model: Model,
) -> Result<String, Failure> {
    for w in warnings(&sc, &model, None) {
        eprintln!("warning: {w}");
    }
    let mut solver = StaticSolver::new(model, sc.static_settings())
        .map_err(|e| Failure::Input(format!("{}: {}", path.display(), e)))?;
    let mut writers =
        Writers::create(place.dest(), true, false, opts.vtk, false).map_err(io_err(place.shown))?;
    let e0 = static_energies(solver.model(), solver.state());
    let first = Row {
        state: solver.state(),
        energies: &e0,
        iterations: 0,
        residual: 0.0,
        increment: 0.0,
        reactions: Some(solver.reactions()),
        constraint_work: 0.0,
        drag_work: 0.0,
        damping_work: 0.0,
    };
    writers
        .write(solver.model(), &first)
        .map_err(io_err(place.shown))?;
    let stepping = step_loads(&mut solver, &mut writers, opts).map_err(io_err(place.shown))?;
    writers.commit().map_err(io_err(place.shown))?;
    write_static_summary(place, &sc, &solver, &e0, &stepping)?;
    let state = solver.state();
    if stepping.interrupted {
        return Err(Failure::Interrupted(format!(
            "{}: interrupted; results up to load factor {} are in {}",
            path.display(),
            Sig(state.t),
            place.shown.display()
        )));
    }
    if let Some(f) = &stepping.failure {
        return Err(Failure::Solver(format!(
            "{}: {f}; results up to load factor {} are in {}",
            path.display(),
            Sig(state.t),
            place.shown.display()
        )));
    }
    if opts.quiet {
        return Ok(String::new());
    }
    Ok(static_report(&sc, &solver, &stepping, place))
}

/// Solves for the load increments, writing each converged one; stops after
/// a written increment when the run is cancelled. A write error is the
/// error; a solver failure is in the answer.
fn step_loads(
    solver: &mut StaticSolver,
    writers: &mut Writers,
    opts: &RunOptions,
) -> std::io::Result<Stepping> {
    let mut tally = Tally::default();
    let mut increments = 0;
    let mut cuts = 0;
    let mut io_failure = None;
    let clock = Instant::now();
    let mut interrupted = false;
    let result = solver.solve(|s, inc| {
        increments = inc.step;
        cuts += inc.cuts;
        tally.iterations += inc.iterations;
        tally.factorizations += inc.iterations;
        tally.max_iterations = tally.max_iterations.max(inc.iterations);
        tally.max_residual = tally.max_residual.max(inc.residual);
        let en = static_energies(s.model(), s.state());
        let row = Row {
            state: s.state(),
            energies: &en,
            iterations: inc.iterations,
            residual: inc.residual,
            increment: inc.increment,
            reactions: Some(s.reactions()),
            constraint_work: 0.0,
            drag_work: 0.0,
            damping_work: 0.0,
        };
        match writers.write(s.model(), &row) {
            Ok(()) => {
                tally.record_stress(s.state().t, &writers.samples);
                // Stopped after a written increment.
                if opts.cancelled() {
                    interrupted = true;
                    return ControlFlow::Break(());
                }
                ControlFlow::Continue(())
            }
            Err(e) => {
                io_failure = Some(e);
                ControlFlow::Break(())
            }
        }
    });
    let wall = clock.elapsed().as_secs_f64();
    if let Some(e) = io_failure {
        return Err(e);
    }
    Ok(Stepping {
        tally,
        increments,
        cuts,
        interrupted,
        wall,
        failure: result.err(),
    })
}

/// Writes summary.json of a static run (`e0`: the energies of the start).
fn write_static_summary(
    place: &Place,
    sc: &Scenario,
    solver: &StaticSolver,
    e0: &Energies,
    run: &Stepping,
) -> Result<(), Failure> {
    let state = solver.state();
    let model = solver.model();
    let en = static_energies(model, state);
    let tally = &run.tally;
    let mut summary = common_summary(sc, model, state, run.wall);
    summary.insert("steps".into(), json!(run.increments));
    summary.insert("time".into(), json_num(state.t));
    summary.insert("converged".into(), json!(run.failure.is_none()));
    summary.insert("iterations".into(), tally.iterations_json(run.increments));
    summary.insert(
        "energy".into(),
        json!({
            "initial": json_num(e0.strain),
            "final": json_num(en.strain),
            "strain": json_num(en.strain),
        }),
    );
    let extra = json!({
        "load_steps": sc.analysis.load_steps,
        "increment_cuts": run.cuts,
        "unknowns": solver.unknowns(),
        "max_residual": json_num(tally.max_residual),
        "stress_peak": tally.stress_json(),
        "reactions": reactions_json(solver.reactions()),
        "error": error_json(run.interrupted, run.failure.as_ref()),
        "interrupted": run.interrupted,
    });
    write_summary(place.dest(), summary, extra)
}

/// The printed report of a static run that converged.
fn static_report(sc: &Scenario, solver: &StaticSolver, run: &Stepping, place: &Place) -> String {
    let mut report = String::new();
    let (state, model) = (solver.state(), solver.model());
    let en = static_energies(model, state);
    say!(report,
        "{}: static, {} load increments ({} cuts) in {:.3} s wall time, {:.2} Newton iterations per increment",
        crate::echo::clip(&sc.title, crate::echo::MAX_ECHO),
        run.increments,
        run.cuts,
        run.wall,
        run.tally.iterations as f64 / run.increments.max(1) as f64
    );
    say!(report, "strain energy: {:.9e} J", en.strain);
    for (node, f) in solver.reactions() {
        say!(
            report,
            "reaction at node {node}: [{:.9e}, {:.9e}, {:.9e}] N",
            f[0],
            f[1],
            f[2]
        );
    }
    say!(report, "{}", tip_line(model, state, place.shown));
    report
}
