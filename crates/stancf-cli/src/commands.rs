//! The `run` and `check` commands.

use crate::output::{json_num, write_atomic, AtomicFile, Num};
use crate::scenario::{self, Scenario};
use crate::Failure;
use stancf::integrator::step_count;
use stancf::observe::{momentum, stress_samples, Energies, StressSample};
use stancf::quadrature::GaussRule;
use stancf::{energies, stability, Model, Simulation, State};
use std::io::Write;
use std::ops::ControlFlow;
use std::path::{Path, PathBuf};
use std::time::Instant;

/// Stress samples per element in stress.csv (ends included).
const STRESS_POINTS_PER_ELEMENT: usize = 5;

/// Figures derived from a scenario before running it.
struct Derived {
    dofs: usize,
    unknowns_per_step: usize,
    element_length: f64,
    wave_speed: f64,
    courant: f64,
    w_max: f64,
    critical_w_dt: Option<f64>,
    stable_step: Option<f64>,
    steps: usize,
    warnings: Vec<String>,
}

fn load(path: &Path) -> Result<(Scenario, Model, State), Failure> {
    let sc = scenario::load(path).map_err(|e| Failure::Input(e.0))?;
    let model = sc
        .model()
        .map_err(|e| Failure::Input(format!("{}: {}", path.display(), e)))?;
    let state = sc.initial_state(&model);
    Ok((sc, model, state))
}

fn derive(sc: &Scenario, model: &Model, state: &State) -> Derived {
    let a = &sc.analysis;
    let rule = GaussRule::new(a.time_points).expect("validated");
    let w_max = stability::highest_frequency(model, &state.e);
    let critical_w_dt = stability::p2_critical_w_dt(&rule, a.time_layers);
    let stable_step = critical_w_dt.map(|w| w / w_max);
    let wave_speed = model.material.wave_speed();
    let element_length = model.element_length();
    let mut warnings = model.warnings();
    if let Some(s) = stable_step {
        if a.time_step > s {
            warnings.push(format!(
                "analysis.time_step = {:e} s exceeds the stable step estimate of P2, {:.4e} s \
                 (w_max dt = {:.3} > {:.3}): the run may blow up; reduce the step",
                a.time_step,
                s,
                w_max * a.time_step,
                critical_w_dt.unwrap_or(f64::NAN)
            ));
        }
    }
    Derived {
        dofs: model.dofs(),
        unknowns_per_step: model.dofs() * 2 * a.time_layers,
        element_length,
        wave_speed,
        courant: wave_speed * a.time_step / element_length,
        w_max,
        critical_w_dt,
        stable_step,
        steps: step_count(a.duration, a.time_step),
        warnings,
    }
}

fn describe(sc: &Scenario, model: &Model, d: &Derived) -> String {
    let a = &sc.analysis;
    let mut s = String::new();
    let mut line = |k: &str, v: String| s.push_str(&format!("{k:<28}{v}\n"));
    line("title", sc.title.clone());
    line(
        "mesh",
        format!(
            "{} x {}, element length {} m",
            sc.cable.elements,
            model.element_type().name(),
            d.element_length
        ),
    );
    line("DOFs", d.dofs.to_string());
    line(
        "unknowns per step",
        format!(
            "{} ({} time layer{})",
            d.unknowns_per_step,
            a.time_layers,
            if a.time_layers == 1 { "" } else { "s" }
        ),
    );
    let sp = model.space_points();
    line(
        "quadrature",
        format!(
            "space {} (axial) / {} (bending), time {}",
            sp.axial, sp.bending, a.time_points
        ),
    );
    line("diameter (drag)", format!("{:.6e} m", sc.diameter));
    line("wave speed sqrt(E/rho)", format!("{:.6} m/s", d.wave_speed));
    line("Courant number c dt/dx", format!("{:.6}", d.courant));
    line(
        "highest frequency w_max",
        format!(
            "{:.6e} rad/s ({:.4} c/l)",
            d.w_max,
            d.w_max * d.element_length / d.wave_speed
        ),
    );
    match (d.stable_step, d.critical_w_dt) {
        (Some(st), Some(wc)) => line(
            "stable step (P2)",
            format!(
                "{st:.6e} s (w_max dt < {wc:.4}); this step: w_max dt = {:.4}",
                d.w_max * a.time_step
            ),
        ),
        _ => line(
            "stable step (P2)",
            "no limit found for this time quadrature".into(),
        ),
    }
    line("time step", format!("{:e} s", a.time_step));
    line("duration", format!("{:e} s", a.duration));
    line("steps", d.steps.to_string());
    s
}

pub fn check(path: &Path) -> Result<(), Failure> {
    let (sc, model, state) = load(path)?;
    let d = derive(&sc, &model, &state);
    print!("{}", describe(&sc, &model, &d));
    if d.warnings.is_empty() {
        println!("{:<28}none", "warnings");
    }
    for w in &d.warnings {
        println!("warning: {w}");
    }
    Ok(())
}

/// The streamed result files of a run.
struct Writers {
    history: AtomicFile,
    nodes: AtomicFile,
    stress: AtomicFile,
    samples: Vec<StressSample>,
}

impl Writers {
    fn create(dir: &Path) -> std::io::Result<Self> {
        let mut w = Writers {
            history: AtomicFile::create(dir, "history.csv")?,
            nodes: AtomicFile::create(dir, "nodes.csv")?,
            stress: AtomicFile::create(dir, "stress.csv")?,
            samples: Vec::new(),
        };
        writeln!(
            w.history.writer(),
            "t,kinetic,strain,gravity,total,iterations,residual,increment,load_potential"
        )?;
        writeln!(w.nodes.writer(), "t,node,x,y,z")?;
        writeln!(w.stress.writer(), "t,s,axial_stress,curvature,element")?;
        Ok(w)
    }

    /// One written step. Refuses non-finite values (none may reach a file).
    fn write(
        &mut self,
        model: &Model,
        state: &State,
        en: &Energies,
        iterations: usize,
        residual: f64,
        increment: f64,
    ) -> std::io::Result<()> {
        stress_samples(model, state, STRESS_POINTS_PER_ELEMENT, &mut self.samples);
        let finite = state.e.iter().all(|v| v.is_finite())
            && [
                en.kinetic,
                en.strain,
                en.gravity,
                en.load_potential,
                residual,
                increment,
            ]
            .iter()
            .all(|v| v.is_finite())
            && self
                .samples
                .iter()
                .all(|s| s.axial_stress.is_finite() && s.curvature.is_finite());
        if !finite {
            return Err(std::io::Error::new(
                std::io::ErrorKind::InvalidData,
                format!("non-finite result at t = {}", state.t),
            ));
        }
        let t = Num(state.t);
        writeln!(
            self.history.writer(),
            "{t},{},{},{},{},{iterations},{},{},{}",
            Num(en.kinetic),
            Num(en.strain),
            Num(en.gravity),
            Num(en.total()),
            Num(residual),
            Num(increment),
            Num(en.load_potential)
        )?;
        let w = self.nodes.writer();
        for j in 0..model.nodes() {
            let r = model.node_position(&state.e, j);
            writeln!(w, "{t},{j},{},{},{}", Num(r[0]), Num(r[1]), Num(r[2]))?;
        }
        let w = self.stress.writer();
        for s in &self.samples {
            writeln!(
                w,
                "{t},{},{},{},{}",
                Num(s.s),
                Num(s.axial_stress),
                Num(s.curvature),
                s.element
            )?;
        }
        Ok(())
    }

    fn commit(self) -> std::io::Result<()> {
        self.history.commit()?;
        self.nodes.commit()?;
        self.stress.commit()
    }
}

/// Running figures of a run for summary.json.
#[derive(Default)]
struct Tally {
    steps: usize,
    iterations: usize,
    factorizations: usize,
    max_iterations: usize,
    max_residual: f64,
    energy_max_abs_drift: f64,
    energy_scale: f64,
    /// Largest |axial stress| over all samples and steps: (value, s, t).
    stress_peak: (f64, f64, f64),
}

impl Tally {
    fn record_stress(&mut self, t: f64, samples: &[StressSample]) {
        for s in samples {
            if s.axial_stress.abs() > self.stress_peak.0.abs() {
                self.stress_peak = (s.axial_stress, s.s, t);
            }
        }
    }
}

fn io_err(dir: &Path) -> impl Fn(std::io::Error) -> Failure + '_ {
    move |e| Failure::Other(format!("{}: cannot write results: {e}", dir.display()))
}

pub fn run(path: &Path, out: Option<PathBuf>) -> Result<(), Failure> {
    let (sc, model, state) = load(path)?;
    let d = derive(&sc, &model, &state);
    for w in &d.warnings {
        eprintln!("warning: {w}");
    }
    let settings = sc.step_settings();
    let mut sim = Simulation::new(model, state, settings)
        .map_err(|e| Failure::Input(format!("{}: {}", path.display(), e)))?;
    let dir = out.unwrap_or_else(|| {
        let stem = path.file_stem().map(|s| s.to_string_lossy().into_owned());
        PathBuf::from("out").join(stem.unwrap_or_else(|| "run".into()))
    });
    std::fs::create_dir_all(&dir).map_err(io_err(&dir))?;
    let mut writers = Writers::create(&dir).map_err(io_err(&dir))?;

    let e0 = energies(sim.model(), sim.state());
    writers
        .write(sim.model(), sim.state(), &e0, 0, 0.0, 0.0)
        .map_err(io_err(&dir))?;
    let mut tally = Tally {
        energy_scale: e0.kinetic.abs() + e0.strain.abs(),
        ..Tally::default()
    };
    tally.record_stress(0.0, &writers.samples);
    let mut peak_samples = Vec::new();
    let mut last_written = 0;
    let mut io_failure: Option<std::io::Error> = None;
    let every = sc.output_every;
    let clock = Instant::now();
    let result = stancf::run(&mut sim, sc.analysis.duration, |sim, rep, en| {
        tally.steps = rep.step;
        tally.iterations += rep.newton.iterations;
        tally.factorizations += rep.newton.factorizations;
        tally.max_iterations = tally.max_iterations.max(rep.newton.iterations);
        tally.max_residual = tally.max_residual.max(rep.newton.residual);
        stress_samples(
            sim.model(),
            sim.state(),
            STRESS_POINTS_PER_ELEMENT,
            &mut peak_samples,
        );
        tally.record_stress(rep.t, &peak_samples);
        let potential_change =
            (en.gravity - e0.gravity).abs() + (en.load_potential - e0.load_potential).abs();
        tally.energy_scale = tally
            .energy_scale
            .max(en.kinetic.abs() + en.strain.abs() + potential_change);
        tally.energy_max_abs_drift = tally
            .energy_max_abs_drift
            .max((en.mechanical() - e0.mechanical()).abs());
        if rep.step % every == 0 {
            let w = writers.write(
                sim.model(),
                sim.state(),
                en,
                rep.newton.iterations,
                rep.newton.residual,
                rep.newton.increment,
            );
            match w {
                Ok(()) => last_written = rep.step,
                Err(e) => {
                    io_failure = Some(e);
                    return ControlFlow::Break(());
                }
            }
        }
        ControlFlow::Continue(())
    });
    let wall = clock.elapsed().as_secs_f64();
    if let Some(e) = io_failure {
        return Err(io_err(&dir)(e));
    }
    let failure = result.as_ref().err().cloned();
    if failure.is_none() && last_written != sim.steps() {
        let en = energies(sim.model(), sim.state());
        let hist = sim.residual_history();
        let residual = hist.last().copied().unwrap_or(0.0);
        writers
            .write(sim.model(), sim.state(), &en, 0, residual, 0.0)
            .map_err(io_err(&dir))?;
    }
    writers.commit().map_err(io_err(&dir))?;

    let state = sim.state();
    let model = sim.model();
    let en = energies(model, state);
    let (mass, p, first_moment) = momentum(model, state);
    let nodes_final: Vec<serde_json::Value> = (0..model.nodes())
        .map(|j| {
            let r = model.node_position(&state.e, j);
            serde_json::json!([json_num(r[0]), json_num(r[1]), json_num(r[2])])
        })
        .collect();
    let tip = model.node_position(&state.e, model.nodes() - 1);
    let steps = sim.steps();
    let mean = if steps > 0 {
        tally.iterations as f64 / steps as f64
    } else {
        0.0
    };
    let summary = serde_json::json!({
        "title": sc.title,
        "analysis": "dynamic",
        "element": model.element_type().name(),
        "elements": sc.cable.elements,
        "dofs": model.dofs(),
        "steps": steps,
        "time": json_num(state.t),
        "converged": failure.is_none(),
        "wall_time_s": json_num(wall),
        "iterations": {
            "total": tally.iterations,
            "mean_per_step": json_num(mean),
            "max_per_step": tally.max_iterations,
            "factorizations": tally.factorizations,
        },
        "energy": {
            "initial": json_num(e0.mechanical()),
            "final": json_num(en.mechanical()),
            "max_abs_drift": json_num(tally.energy_max_abs_drift),
            "max_rel_drift": json_num(if tally.energy_scale > 0.0 {
                tally.energy_max_abs_drift / tally.energy_scale
            } else {
                0.0
            }),
            "scale": json_num(tally.energy_scale),
        },
        "tip": [json_num(tip[0]), json_num(tip[1]), json_num(tip[2])],
        "nodes_final": nodes_final,
        "time_step": json_num(sc.analysis.time_step),
        "time_layers": sc.analysis.time_layers,
        "unknowns_per_step": d.unknowns_per_step,
        "max_residual": json_num(tally.max_residual),
        "courant_number": json_num(d.courant),
        "highest_frequency": json_num(d.w_max),
        "stable_time_step": d.stable_step.map(json_num).unwrap_or(serde_json::Value::Null),
        "stress_peak": {
            "axial_stress": json_num(tally.stress_peak.0),
            "s": json_num(tally.stress_peak.1),
            "t": json_num(tally.stress_peak.2),
        },
        "linear_momentum": [json_num(p[0]), json_num(p[1]), json_num(p[2])],
        "center_of_mass": [
            json_num(first_moment[0] / mass),
            json_num(first_moment[1] / mass),
            json_num(first_moment[2] / mass)
        ],
        "error": failure.as_ref().map(|f| f.to_string()),
    });
    let text = serde_json::to_string_pretty(&summary).expect("serializable") + "\n";
    write_atomic(&dir, "summary.json", text.as_bytes()).map_err(io_err(&dir))?;

    if let Some(f) = failure {
        return Err(Failure::Solver(format!(
            "{}: {f}; results up to t = {} s (step {}) are in {}",
            path.display(),
            state.t,
            steps,
            dir.display()
        )));
    }
    println!(
        "{}: {} steps to t = {} s in {:.3} s wall time, {:.2} Newton iterations per step",
        sc.title, steps, state.t, wall, mean
    );
    println!(
        "energy: initial {:.9e} J, final {:.9e} J, max drift {:.3e} J ({:.3e} of the energy scale)",
        e0.mechanical(),
        en.mechanical(),
        tally.energy_max_abs_drift,
        if tally.energy_scale > 0.0 {
            tally.energy_max_abs_drift / tally.energy_scale
        } else {
            0.0
        }
    );
    println!(
        "peak axial stress: {:.6e} Pa at s = {} m, t = {:.6e} s",
        tally.stress_peak.0, tally.stress_peak.1, tally.stress_peak.2
    );
    println!(
        "tip (end B): [{:.9}, {:.9}, {:.9}] m; results in {}",
        tip[0],
        tip[1],
        tip[2],
        dir.display()
    );
    Ok(())
}
