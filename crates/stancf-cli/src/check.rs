//! The `check` command: a scenario validated and its derived figures
//! (DOFs, wave speed, Courant number, highest frequency, stable step)
//! printed; nothing is run. `run` starts from the same figures.

use crate::scenario::{self, AnalysisKind, Scenario};
use crate::Failure;
use stancf::integrator::step_count;
use stancf::quadrature::GaussRule;
use stancf::{stability, Model, Simulation, State};
use std::path::Path;

/// Figures derived from a dynamic scenario before running it.
pub(crate) struct Derived {
    pub(crate) element_length: f64,
    pub(crate) wave_speed: f64,
    pub(crate) courant: f64,
    pub(crate) w_max: f64,
    pub(crate) critical_w_dt: Option<f64>,
    pub(crate) stable_step: Option<f64>,
    pub(crate) steps: usize,
}

pub(crate) fn load(path: &Path) -> Result<(Scenario, Model, State), Failure> {
    let sc = scenario::load(path).map_err(|e| Failure::Input(e.0))?;
    let model = sc
        .model()
        .map_err(|e| Failure::Input(format!("{}: {}", path.display(), e)))?;
    let state = sc.initial_state(&model);
    Ok((sc, model, state))
}

pub(crate) fn derive(sc: &Scenario, model: &Model, state: &State) -> Derived {
    let a = &sc.analysis;
    let rule = GaussRule::new(a.time_points).expect("validated");
    let w_max = stability::highest_frequency(model, &state.e);
    let critical_w_dt = stability::p2_critical_w_dt(&rule, a.time_layers);
    let wave_speed = model.material.wave_speed();
    let element_length = model.element_length();
    Derived {
        element_length,
        wave_speed,
        courant: wave_speed * a.time_step / element_length,
        w_max,
        critical_w_dt,
        stable_step: critical_w_dt.map(|w| w / w_max),
        steps: step_count(a.duration, a.time_step),
    }
}

/// Warnings about a scenario: the model's own (quadrature), the scenario's
/// notes, and a step above P2's stable limit.
pub(crate) fn warnings(sc: &Scenario, model: &Model, d: Option<&Derived>) -> Vec<String> {
    let mut w = model.warnings();
    w.extend(sc.notes.iter().cloned());
    let p2 = sc.analysis.time_scheme == stancf::TimeScheme::P2;
    if let Some(d) = d.filter(|_| p2) {
        if let Some(s) = d.stable_step.filter(|&s| sc.analysis.time_step > s) {
            w.push(format!(
                "analysis.time_step = {:e} s exceeds the stable step estimate of P2, {:.4e} s \
                 (w_max dt = {:.3} > {:.3}): the run may blow up; reduce the step",
                sc.analysis.time_step,
                s,
                d.w_max * sc.analysis.time_step,
                d.critical_w_dt.unwrap_or(f64::NAN)
            ));
        }
    }
    w
}

/// `unknowns`: a dynamic run's unknowns per step and whether the planar
/// reduction applies (from the simulation the run would build).
fn describe(
    sc: &Scenario,
    model: &Model,
    d: Option<&Derived>,
    unknowns: Option<(usize, bool)>,
) -> String {
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
            model.element_length()
        ),
    );
    line("DOFs", model.dofs().to_string());
    let constrained = (0..model.dofs())
        .filter(|&g| model.constraints.is_constrained(g))
        .count();
    line(
        "constraints",
        format!(
            "{} ({} constrained coordinates, {:?})",
            model.constraints.list.len(),
            constrained,
            a.constraint_method
        ),
    );
    let sp = model.space_points();
    let Some(d) = d else {
        line("analysis", format!("static, {} load steps", a.load_steps));
        line(
            "unknowns",
            stancf::assembly::SlabLayout::new(
                model,
                stancf::assembly::Scheme::Static,
                a.constraint_method,
            )
            .size()
            .to_string(),
        );
        line(
            "quadrature",
            format!("space {} (axial) / {} (bending)", sp.axial, sp.bending),
        );
        return s;
    };
    if let Some((n, planar)) = unknowns {
        line(
            "unknowns per step",
            format!(
                "{n} ({} time layer{}{})",
                a.time_layers,
                if a.time_layers == 1 { "" } else { "s" },
                if planar {
                    "; planar motion: z coordinates eliminated"
                } else {
                    ""
                }
            ),
        );
    }
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
    match (a.time_scheme, d.stable_step, d.critical_w_dt) {
        (stancf::TimeScheme::Galerkin, ..) => line(
            "time scheme",
            format!(
                "Galerkin (unconditionally stable); w_max dt = {:.4}: modes with w dt above ~1 \
                 are carried without damping but with a wrong phase",
                d.w_max * a.time_step
            ),
        ),
        (_, Some(st), Some(wc)) => line(
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
    let d = (sc.analysis.kind == AnalysisKind::Dynamic).then(|| derive(&sc, &model, &state));
    let unknowns = if sc.analysis.kind == AnalysisKind::Dynamic {
        let sim = Simulation::new(model.clone(), state.clone(), sc.step_settings())
            .map_err(|e| Failure::Input(format!("{}: {}", path.display(), e)))?;
        Some((sim.unknowns_per_step(), sim.is_planar()))
    } else {
        None
    };
    print!("{}", describe(&sc, &model, d.as_ref(), unknowns));
    if sc.analysis.kind == AnalysisKind::Static {
        stancf::StaticSolver::new(model.clone(), sc.static_settings())
            .map_err(|e| Failure::Input(format!("{}: {}", path.display(), e)))?;
    }
    let w = warnings(&sc, &model, d.as_ref());
    if w.is_empty() {
        println!("{:<28}none", "warnings");
    }
    for w in &w {
        println!("warning: {w}");
    }
    Ok(())
}
