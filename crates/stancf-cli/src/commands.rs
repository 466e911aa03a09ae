//! The `run` command: a scenario stepped (or solved statically) with its
//! results streamed to the output folder and summary.json written last.

use crate::check::{derive, load_text, warnings, Derived};
use crate::output::{json_num, write_atomic, ResultFolder};
use crate::scenario::{AnalysisKind, Scenario};
use crate::writers::{Row, SolverRow, WallClock, Writers, STRESS_POINTS_PER_ELEMENT};
use crate::Failure;
use serde_json::{json, Value};
use stancf::error::Sig;
use stancf::observe::{momentum, stress_samples, Energies, StressSample};
use stancf::{energies, Model, Simulation, State, StaticSolver};
use std::ops::ControlFlow;
use std::path::{Path, PathBuf};
use std::time::Instant;

pub use crate::check::check;

/// Running figures of a run for summary.json.
#[derive(Default)]
struct Tally {
    iterations: usize,
    factorizations: usize,
    max_iterations: usize,
    max_residual: f64,
    energy_max_abs_drift: f64,
    energy_scale: f64,
    /// Largest |axial stress| over all samples and steps: (value, s, t).
    stress_peak: (f64, f64, f64),
    /// Sum and count of the per-step convergence-rate estimates.
    rate_sum: f64,
    rate_steps: usize,
}

impl Tally {
    fn record_stress(&mut self, t: f64, samples: &[StressSample]) {
        for s in samples {
            if s.axial_stress.abs() > self.stress_peak.0.abs() {
                self.stress_peak = (s.axial_stress, s.s, t);
            }
        }
    }

    fn iterations_json(&self, steps: usize) -> Value {
        json!({
            "total": self.iterations,
            "mean_per_step": json_num(if steps > 0 { self.iterations as f64 / steps as f64 } else { 0.0 }),
            "max_per_step": self.max_iterations,
            "factorizations": self.factorizations,
        })
    }

    fn stress_json(&self) -> Value {
        json!({
            "axial_stress": json_num(self.stress_peak.0),
            "s": json_num(self.stress_peak.1),
            "t": json_num(self.stress_peak.2),
        })
    }
}

fn io_err(dir: &Path) -> impl Fn(std::io::Error) -> Failure + '_ {
    move |e| Failure::Other(format!("{}: cannot write results: {e}", dir.display()))
}

fn vec3(v: [f64; 3]) -> Value {
    json!([json_num(v[0]), json_num(v[1]), json_num(v[2])])
}

fn reactions_json(reactions: &[(usize, [f64; 3])]) -> Value {
    Value::Array(
        reactions
            .iter()
            .map(|(n, f)| json!({"node": n, "force": vec3(*f)}))
            .collect(),
    )
}

/// The fields of summary.json every analysis writes.
fn common_summary(
    sc: &Scenario,
    model: &Model,
    state: &State,
    wall: f64,
) -> serde_json::Map<String, Value> {
    let nodes_final: Vec<Value> = (0..model.nodes())
        .map(|j| vec3(model.node_position(&state.e, j)))
        .collect();
    let tip = model.node_position(&state.e, model.nodes() - 1);
    let mut m = serde_json::Map::new();
    m.insert("title".into(), json!(sc.title));
    m.insert(
        "analysis".into(),
        json!(match sc.analysis.kind {
            AnalysisKind::Dynamic => "dynamic",
            AnalysisKind::Static => "static",
        }),
    );
    m.insert("element".into(), json!(model.element_type().name()));
    m.insert("elements".into(), json!(sc.cable.elements));
    m.insert("length".into(), json_num(sc.cable.length));
    m.insert("dofs".into(), json!(model.dofs()));
    m.insert("wall_time_s".into(), json_num(wall));
    m.insert("tip".into(), vec3(tip));
    m.insert("nodes_final".into(), Value::Array(nodes_final));
    m
}

/// Writes summary.json: the common fields followed by `extra`'s.
fn write_summary(
    dir: &Path,
    mut summary: serde_json::Map<String, Value>,
    extra: Value,
) -> Result<(), Failure> {
    if let Value::Object(extra) = extra {
        summary.extend(extra);
    }
    let text = serde_json::to_string_pretty(&Value::Object(summary)).expect("serializable") + "\n";
    write_atomic(dir, "summary.json", text.as_bytes()).map_err(io_err(dir))
}

/// Appends a line to a run's report (printed once its results are in place).
macro_rules! say {
    ($report:expr, $($arg:tt)*) => {{
        use std::fmt::Write as _;
        let _ = writeln!($report, $($arg)*);
    }};
}

/// The closing line of a run: the tip and where the results are.
fn tip_line(model: &Model, state: &State, dir: &Path) -> String {
    let tip = model.node_position(&state.e, model.nodes() - 1);
    format!(
        "tip (end B): [{:.9}, {:.9}, {:.9}] m; results in {}",
        tip[0],
        tip[1],
        tip[2],
        dir.display()
    )
}

/// The output folder: `--out`, or `out/<stem>` with the scenario file's
/// stem made safe as a folder name (letters, digits, `-`, `_`, `.`, no
/// leading dot; `run` when nothing is left), so the default is always a
/// folder of its own under `out/`.
fn output_dir(path: &Path, out: Option<PathBuf>) -> PathBuf {
    out.unwrap_or_else(|| {
        let stem = path
            .file_stem()
            .map(|s| s.to_string_lossy().into_owned())
            .unwrap_or_default();
        PathBuf::from("out").join(safe_folder_name(&stem))
    })
}

/// A file stem as a folder name of its own (see [`output_dir`]).
pub(crate) fn safe_folder_name(stem: &str) -> String {
    let name: String = stem
        .chars()
        .map(|c| {
            if c.is_ascii_alphanumeric() || "-_.".contains(c) {
                c
            } else {
                '_'
            }
        })
        .collect();
    let name = name.trim_start_matches('.');
    if name.is_empty() {
        "run".into()
    } else {
        name.chars().take(100).collect()
    }
}

/// A request to stop a run, polled after every step (the Python layer
/// answers it from Ctrl-C).
#[derive(Clone)]
pub struct Cancel(pub std::sync::Arc<dyn Fn() -> bool + Send + Sync>);

impl std::fmt::Debug for Cancel {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str("Cancel")
    }
}

/// What `stancf run` writes besides the result files.
#[derive(Clone, Debug, Default)]
pub struct RunOptions {
    /// Output folder (default: out/<scenario file stem>/).
    pub out: Option<PathBuf>,
    /// Also draw the run's figures (PNG and SVG) next to its results.
    pub plot: bool,
    /// Also write ParaView files (one .vtp per written step, cable.pvd).
    pub vtk: bool,
    /// No progress bar and no summary on standard output (errors and
    /// warnings still go to standard error).
    pub quiet: bool,
    /// Run even when the step count or the result size exceeds the
    /// bounds that otherwise refuse a run.
    pub allow_large: bool,
    /// Stop when this says so (checked after every step).
    pub cancel: Option<Cancel>,
}

/// Where a run writes (`dir`, the staging folder of its [`ResultFolder`])
/// and the folder its results appear in (`shown`, named in messages).
struct Place<'a> {
    dir: &'a Path,
    shown: &'a Path,
}

/// `stancf run`: reads the scenario file and runs it ([`run_text`]).
pub fn run(path: &Path, opts: RunOptions) -> Result<(), Failure> {
    let text = std::fs::read_to_string(path)
        .map_err(|e| Failure::Input(format!("{}: cannot read the file: {e}", path.display())))?;
    run_text(&text, path, opts)
}

/// Runs scenario text (`path` names it in messages and gives the default
/// output folder and title). The results are written as one transaction
/// ([`ResultFolder`]): the output folder holds the complete old set until
/// the complete new one replaces it, the scenario text included
/// (`scenario.toml`), also when the solver fails or the run is
/// interrupted; an invalid scenario or a write error leaves it untouched.
pub fn run_text(text: &str, path: &Path, opts: RunOptions) -> Result<(), Failure> {
    let (sc, model, state) = load_text(text, path)?;
    crate::work_bounds::admit(path, &sc, &opts)?;
    // Everything that can refuse the input is decided before anything is
    // written.
    let derived = match sc.analysis.kind {
        AnalysisKind::Dynamic => {
            let d = derive(&sc, &model, &state);
            crate::check::check_derived(path, &d)?;
            Some(d)
        }
        AnalysisKind::Static => None,
    };
    let target = output_dir(path, opts.out.clone());
    let folder = ResultFolder::open(&target)?;
    let place = Place {
        dir: folder.staging(),
        shown: folder.target(),
    };
    write_atomic(place.dir, "scenario.toml", text.as_bytes()).map_err(io_err(place.shown))?;
    let result = match sc.analysis.kind {
        AnalysisKind::Dynamic => run_dynamic(path, &place, &opts, sc, model, state, derived),
        AnalysisKind::Static => run_static(path, &place, &opts, sc, model),
    };
    if let Err(Failure::Input(_) | Failure::Other(_)) = result {
        return result.map(|_| ());
    }
    // The figures are drawn from the new files, also those of a run that
    // stopped early (they hold every converged step).
    let figures = opts.plot.then(|| crate::figures::plot_results(place.dir));
    folder.commit().map_err(io_err(&target))?;
    if let Ok(report) = &result {
        print!("{report}");
    }
    match figures {
        Some(Ok(names)) => println!(
            "figures: {} (PNG and SVG) in {}",
            names.join(", "),
            target.display()
        ),
        Some(Err(e)) => return Err(io_err(&target)(e)),
        None => {}
    }
    result.map(|_| ())
}

/// `stancf plot DIR`: the figures of the results already in DIR.
pub fn plot(dir: &Path) -> Result<(), Failure> {
    if !dir.join("summary.json").exists() {
        return Err(Failure::Input(format!(
            "{}: no summary.json here: not a folder of stancf results",
            dir.display()
        )));
    }
    let names = crate::figures::plot_results(dir).map_err(|e| Failure::Input(e.to_string()))?;
    println!(
        "figures: {} (PNG and SVG) in {}",
        names.join(", "),
        dir.display()
    );
    Ok(())
}

/// A dynamic run into `place`; on success, the text to print.
fn run_dynamic(
    path: &Path,
    place: &Place,
    opts: &RunOptions,
    sc: Scenario,
    model: Model,
    state: State,
    derived: Option<Derived>,
) -> Result<String, Failure> {
    let mut report = String::new();
    let d = derived.expect("derived for every dynamic run");
    for w in warnings(&sc, &model, Some(&d)) {
        eprintln!("warning: {w}");
    }
    let mut sim = Simulation::new(model, state, sc.step_settings())
        .map_err(|e| Failure::Input(format!("{}: {}", path.display(), e)))?;
    sim.set_clock(Box::new(WallClock(Instant::now())));
    let dir = place.dir.to_path_buf();
    let constrained = !sim.model().constraints.is_empty();
    let mut writers =
        Writers::create(&dir, constrained, true, opts.vtk).map_err(io_err(place.shown))?;

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
    };
    writers
        .write(sim.model(), &first)
        .map_err(io_err(place.shown))?;
    let mut tally = Tally {
        // Never zero: at rest the energies are round-off, and so would be a
        // drift measured against them (docs/method.md §8).
        energy_scale: (e0.kinetic.abs() + e0.strain.abs())
            .max(stancf::integrator::energy_resolution(sim.model())),
        ..Tally::default()
    };
    tally.record_stress(0.0, &writers.samples);
    let mut peak_samples = Vec::new();
    let mut last_written = 0;
    let mut last_newton = (0, 0.0, 0.0);
    let mut io_failure: Option<std::io::Error> = None;
    let every = sc.output_every;
    let clock = Instant::now();
    let mut last_timing = stancf::Timing::default();
    let rate_floor = sc.analysis.tolerance;
    let mut progress = crate::progress::Progress::new(d.steps, !opts.quiet);
    let mut interrupted = false;
    let result = stancf::run(&mut sim, sc.analysis.duration, |sim, rep, en| {
        if opts.cancel.as_ref().is_some_and(|c| (c.0)()) {
            interrupted = true;
            return ControlFlow::Break(());
        }
        last_newton = (
            rep.newton.iterations,
            rep.newton.residual,
            rep.newton.increment,
        );
        let timing = sim.timing();
        let solver_row = SolverRow {
            t: rep.t,
            step: rep.step,
            report: &rep.newton,
            residuals: sim.residual_history(),
            part_a: timing.part_a - last_timing.part_a,
            part_b: timing.part_b - last_timing.part_b,
            rate_floor,
        };
        last_timing = timing;
        if let Some(r) = stancf::convergence_rate(sim.residual_history(), rate_floor) {
            tally.rate_sum += r;
            tally.rate_steps += 1;
        }
        if let Err(e) = writers.write_solver(&solver_row) {
            io_failure = Some(e);
            return ControlFlow::Break(());
        }
        tally.iterations += rep.newton.iterations;
        progress.update(rep.step, rep.t, tally.iterations);
        tally.factorizations += rep.newton.factorizations;
        tally.max_iterations = tally.max_iterations.max(rep.newton.iterations);
        tally.max_residual = tally.max_residual.max(rep.newton.residual);
        let work = sim.constraint_work() + sim.drag_work();
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
            &mut peak_samples,
        );
        tally.record_stress(rep.t, &peak_samples);
        if rep.step % every == 0 {
            let row = Row {
                state: sim.state(),
                energies: en,
                iterations: rep.newton.iterations,
                residual: rep.newton.residual,
                increment: rep.newton.increment,
                reactions: Some(sim.reactions()),
                constraint_work: sim.constraint_work(),
                drag_work: sim.drag_work(),
            };
            match writers.write(sim.model(), &row) {
                Ok(()) => last_written = rep.step,
                Err(e) => {
                    io_failure = Some(e);
                    return ControlFlow::Break(());
                }
            }
        }
        ControlFlow::Continue(())
    });
    progress.finish();
    let wall = clock.elapsed().as_secs_f64();
    if let Some(e) = io_failure {
        return Err(io_err(place.shown)(e));
    }
    let failure = result.as_ref().err().cloned();
    // The last converged step when `output.every` skipped it (also of a
    // run that failed or was interrupted), with its own solver figures.
    if last_written != sim.steps() {
        let en = sim.energies();
        let (iterations, residual, increment) = last_newton;
        let row = Row {
            state: sim.state(),
            energies: &en,
            iterations,
            residual,
            increment,
            reactions: Some(sim.reactions()),
            constraint_work: sim.constraint_work(),
            drag_work: sim.drag_work(),
        };
        writers
            .write(sim.model(), &row)
            .map_err(io_err(place.shown))?;
    }
    writers.commit().map_err(io_err(place.shown))?;

    let state = sim.state();
    let model = sim.model();
    let en = sim.energies();
    let (mass, p, first_moment) = momentum(model, state);
    let steps = sim.steps();
    let rel = tally.energy_max_abs_drift / tally.energy_scale;
    let mut summary = common_summary(&sc, model, state, wall);
    summary.insert("steps".into(), json!(steps));
    summary.insert("time".into(), json_num(state.t));
    summary.insert("converged".into(), json!(failure.is_none()));
    summary.insert("iterations".into(), tally.iterations_json(steps));
    summary.insert(
        "energy".into(),
        json!({
            "initial": json_num(e0.mechanical()),
            "final": json_num(en.mechanical()),
            "max_abs_drift": json_num(tally.energy_max_abs_drift),
            "max_rel_drift": json_num(rel),
            "scale": json_num(tally.energy_scale),
            "constraint_work": json_num(sim.constraint_work()),
            "drag_work": json_num(sim.drag_work()),
        }),
    );
    let timing = sim.timing();
    summary.insert(
        "solver".into(),
        json!({
            "method": match sc.analysis.solver {
                stancf::SolverMethod::Newton => "newton",
                stancf::SolverMethod::Broyden => "broyden",
                stancf::SolverMethod::ModifiedNewton => "modified-newton",
            },
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
        }),
    );
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
            .filter(|_| sc.analysis.time_scheme == stancf::TimeScheme::P2)
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
        "error": if interrupted {
            Some("interrupted".to_string())
        } else {
            failure.as_ref().map(|f| f.to_string())
        },
        // Where the solver failed: the step it could not take.
        "failure": failure.as_ref().map(|f| json!({
            "time": json_num(f.time),
            "step": f.step,
            "residual": json_num(f.residual),
            "iterations": f.iterations,
        })),
        "interrupted": interrupted,
    });
    write_summary(&dir, summary, extra)?;

    if interrupted {
        return Err(Failure::Interrupted(format!(
            "{}: interrupted; results up to t = {} s (step {}) are in {}",
            path.display(),
            Sig(state.t),
            steps,
            place.shown.display()
        )));
    }
    if let Some(f) = failure {
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
        return Err(Failure::Solver(format!(
            "{}: {f}{beyond}; results up to t = {} s (step {}) are in {}",
            path.display(),
            Sig(state.t),
            steps,
            place.shown.display()
        )));
    }
    if opts.quiet {
        return Ok(report);
    }
    say!(report,
        "{}: {} steps to t = {} s in {:.3} s wall time, {:.2} {} iterations per step, {} factorizations",
        sc.title,
        steps,
        Sig(state.t),
        wall,
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
        e0.mechanical(),
        en.mechanical(),
        tally.energy_max_abs_drift,
        rel
    );
    say!(
        report,
        "peak axial stress: {:.6e} Pa at s = {} m, t = {:.6e} s",
        tally.stress_peak.0,
        Sig(tally.stress_peak.1),
        tally.stress_peak.2
    );
    say!(report, "{}", tip_line(model, state, place.shown));
    Ok(report)
}

/// Energies of a static state at load factor lambda: the potentials of the
/// applied loads (lambda times the full ones), no kinetic energy.
fn static_energies(model: &Model, state: &State) -> Energies {
    let mut en = energies(model, state);
    en.gravity *= state.t;
    en.load_potential *= state.t;
    en
}

/// A static run into `place`; on success, the text to print.
fn run_static(
    path: &Path,
    place: &Place,
    opts: &RunOptions,
    sc: Scenario,
    model: Model,
) -> Result<String, Failure> {
    let mut report = String::new();
    for w in warnings(&sc, &model, None) {
        eprintln!("warning: {w}");
    }
    let mut solver = StaticSolver::new(model, sc.static_settings())
        .map_err(|e| Failure::Input(format!("{}: {}", path.display(), e)))?;
    let dir = place.dir.to_path_buf();
    let mut writers = Writers::create(&dir, true, false, opts.vtk).map_err(io_err(place.shown))?;
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
    };
    writers
        .write(solver.model(), &first)
        .map_err(io_err(place.shown))?;
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
        };
        match writers.write(s.model(), &row) {
            Ok(()) => {
                tally.record_stress(s.state().t, &writers.samples);
                // Stopped after a written increment.
                if opts.cancel.as_ref().is_some_and(|c| (c.0)()) {
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
        return Err(io_err(place.shown)(e));
    }
    writers.commit().map_err(io_err(place.shown))?;
    let failure = result.as_ref().err().cloned();
    let state = solver.state();
    let model = solver.model();
    let en = static_energies(model, state);
    let mut summary = common_summary(&sc, model, state, wall);
    summary.insert("steps".into(), json!(increments));
    summary.insert("time".into(), json_num(state.t));
    summary.insert("converged".into(), json!(failure.is_none()));
    summary.insert("iterations".into(), tally.iterations_json(increments));
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
        "increment_cuts": cuts,
        "unknowns": solver.unknowns(),
        "max_residual": json_num(tally.max_residual),
        "stress_peak": tally.stress_json(),
        "reactions": reactions_json(solver.reactions()),
        "error": if interrupted {
            Some("interrupted".to_string())
        } else {
            failure.as_ref().map(|f| f.to_string())
        },
        "interrupted": interrupted,
    });
    write_summary(&dir, summary, extra)?;
    if interrupted {
        return Err(Failure::Interrupted(format!(
            "{}: interrupted; results up to load factor {} are in {}",
            path.display(),
            Sig(state.t),
            place.shown.display()
        )));
    }
    if let Some(f) = failure {
        return Err(Failure::Solver(format!(
            "{}: {f}; results up to load factor {} are in {}",
            path.display(),
            Sig(state.t),
            place.shown.display()
        )));
    }
    if opts.quiet {
        return Ok(report);
    }
    let tip = model.node_position(&state.e, model.nodes() - 1);
    say!(report,
        "{}: static, {increments} load increments ({cuts} cuts) in {:.3} s wall time, {:.2} Newton iterations per increment",
        sc.title,
        wall,
        tally.iterations as f64 / increments.max(1) as f64
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
    say!(
        report,
        "tip (end B): [{:.9}, {:.9}, {:.9}] m; results in {}",
        tip[0],
        tip[1],
        tip[2],
        place.shown.display()
    );
    Ok(report)
}
