//! The `check` command: a scenario validated and its derived figures
//! (DOFs, wave speed, Courant number, highest frequency, stable step)
//! printed; nothing is run. `run` starts from the same figures. The
//! plausibility of a scenario's scales is [`crate::input_scales`], the
//! bounds on a run's work [`crate::work_bounds`].

use crate::input_scales::scales;
use crate::scenario::{self, AnalysisKind, Scenario};
use crate::work_bounds::{bytes_text, size, size_problem};
use crate::Failure;
use stancf::error::Sig;
use stancf::integrator::step_count;
use stancf::quadrature::GaussRule;
use stancf::{stability, Model, State};
use std::path::Path;

/// Figures derived from a dynamic scenario before running it.
pub(crate) struct Derived {
    /// The shortest element's length (all of them on a uniform mesh): the
    /// one that bounds the step (docs/method.md §1.6, §4.6).
    pub(crate) shortest_element: f64,
    pub(crate) wave_speed: f64,
    pub(crate) courant: f64,
    pub(crate) w_max: f64,
    pub(crate) critical_w_dt: Option<f64>,
    pub(crate) stable_step: Option<f64>,
    pub(crate) steps: usize,
}

/// Validates scenario text (`path` names it in messages and gives the
/// default title) and builds its model and initial state. A derived scale
/// out of the range the solver computes in (non-finite, or beyond
/// [`MAX_SCALE`](crate::input_scales::MAX_SCALE)) is an input error naming
/// the keys it is made of.
pub(crate) fn load_text(text: &str, path: &Path) -> Result<(Scenario, Model, State), Failure> {
    let sc = scenario::parse(text, &path.display().to_string(), path)
        .map_err(|e| Failure::Input(e.0))?;
    let model = sc
        .model()
        .map_err(|e| Failure::Input(format!("{}: {}", path.display(), e)))?;
    let state = sc.initial_state(&model);
    scales(&path.display().to_string(), &sc, &model, &state)?;
    Ok((sc, model, state))
}

pub(crate) fn derive(sc: &Scenario, model: &Model, state: &State) -> Derived {
    let a = &sc.analysis;
    let rule = GaussRule::new(a.time_points).expect("validated");
    let w_max = stability::highest_frequency(model, &state.e);
    let critical_w_dt = stability::p2_critical_w_dt(&rule, a.time_layers);
    let wave_speed = model.material.wave_speed();
    let shortest_element = model.shortest_element_length();
    Derived {
        shortest_element,
        wave_speed,
        courant: wave_speed * a.time_step / shortest_element,
        w_max,
        critical_w_dt,
        stable_step: critical_w_dt.map(|w| w / w_max),
        steps: step_count(a.duration, a.time_step),
    }
}

/// The figures [`derive()`] computed, checked: the highest frequency (from
/// an eigenvalue computation on the mesh), the stable step and the Courant
/// number must be finite and positive, or the scenario is an input error
/// naming the keys they are made of. `check` prints them and `run` starts
/// from them.
pub(crate) fn check_derived(path: &Path, d: &Derived) -> Result<(), Failure> {
    let keys = "material.youngs_modulus, material.density, material.area, \
                material.second_moment, cable.length, cable.elements";
    let bad = |what: &str, v: f64| {
        Failure::Input(format!(
            "{}: {keys}: {what} is {} (not a finite positive number): the stiffness and the \
             mass of the mesh are out of the range the solver can compute with; check these \
             values and their units",
            path.display(),
            Sig(v)
        ))
    };
    if !(d.w_max.is_finite() && d.w_max > 0.0) {
        return Err(bad("the highest frequency w_max of the mesh", d.w_max));
    }
    if let Some(st) = d.stable_step.filter(|s| !(s.is_finite() && *s > 0.0)) {
        return Err(bad("the stable step of P2", st));
    }
    if !d.courant.is_finite() {
        return Err(bad("the Courant number", d.courant));
    }
    Ok(())
}

/// w_max dt up to which its results are shown to be meaningful
/// ([`stability::GALERKIN_ACCURATE_W_DT`]).
pub(crate) fn warnings(sc: &Scenario, model: &Model, d: Option<&Derived>) -> Vec<String> {
    let mut w = model.warnings();
    w.extend(sc.notes.iter().cloned());
    let Some(d) = d else {
        return w;
    };
    let dt = sc.analysis.time_step;
    match sc.analysis.time_scheme {
        stancf::TimeScheme::P2 => {
            if let Some(s) = d.stable_step.filter(|&s| dt > s) {
                w.push(format!(
                    "analysis.time_step = {:e} s exceeds the stable step estimate of P2, {:.4e} s \
                     (w_max dt = {:.3} > {:.3}): the run may blow up; reduce the step",
                    dt,
                    s,
                    d.w_max * dt,
                    d.critical_w_dt.unwrap_or(f64::NAN)
                ));
            }
        }
        stancf::TimeScheme::Galerkin => {
            if d.w_max * dt > stability::GALERKIN_ACCURATE_W_DT {
                w.push(format!(
                    "analysis.time_step = {dt:e} s puts the Galerkin step at w_max dt = {:.1}, \
                     beyond {:.2}, the largest at which its results are shown to be meaningful \
                     (ten times P2's stable step): the fastest modes move at frequencies \
                     unrelated to theirs, and runs this far beyond stop with spurious energy \
                     jumps; use a step of at most {:.4e} s",
                    d.w_max * dt,
                    stability::GALERKIN_ACCURATE_W_DT,
                    stability::galerkin_accurate_step(d.w_max)
                ));
            }
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
    line("title", crate::echo::clip(&sc.title, crate::echo::MAX_ECHO));
    line("mesh", mesh_text(model));
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
    let ba = model.material.axial_damping;
    if ba != 0.0 {
        let ea = model.material.section().ea;
        line(
            "axial damping BA",
            format!(
                "{ba:.6e} N s: damping ratio BA w / (2 EA) of an axial mode of frequency w, \
                 {:.4e} at w_max (docs/method.md §2.10)",
                ba * d.w_max / (2.0 * ea)
            ),
        );
    }
    line("wave speed sqrt(E/rho)", format!("{:.6} m/s", d.wave_speed));
    line("Courant number c dt/dx", format!("{:.6}", d.courant));
    line(
        "highest frequency w_max",
        format!(
            "{:.6e} rad/s ({:.4} c/l)",
            d.w_max,
            d.w_max * d.shortest_element / d.wave_speed
        ),
    );
    match (a.time_scheme, d.stable_step, d.critical_w_dt) {
        (stancf::TimeScheme::Galerkin, ..) => line(
            "time scheme",
            format!(
                "Galerkin (unconditionally stable); w_max dt = {:.4}: modes with w dt above ~1 \
                 are carried without damping but with a wrong phase; results shown meaningful \
                 up to w_max dt = {:.2} (a step of {:.4e} s)",
                d.w_max * a.time_step,
                stability::GALERKIN_ACCURATE_W_DT,
                stability::galerkin_accurate_step(d.w_max)
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

/// "n x SAC-2, element length l m" for a uniform mesh; a graded or
/// sectioned one's shortest and longest elements and its grading
/// (docs/method.md §1.6).
pub(crate) fn mesh_text(model: &Model) -> String {
    let c = &model.cable;
    let kind = model.element_type().name();
    match c.grading {
        stancf::Grading::Sections(ref s) => format!(
            "{} x {kind}, element lengths {} m (shortest) to {} m (longest), in {} sections",
            c.elements,
            model.shortest_element_length(),
            model.longest_element_length(),
            s.len()
        ),
        stancf::Grading::Geometric { toward, ratio } if !c.grading.is_uniform() => format!(
            "{} x {kind}, element lengths {} m (shortest) to {} m (longest), graded toward {} \
             with ratio {ratio}",
            c.elements,
            model.shortest_element_length(),
            model.longest_element_length(),
            toward.name()
        ),
        _ => format!(
            "{} x {kind}, element length {} m",
            c.elements,
            model.element_length(0)
        ),
    }
}

/// `stancf check`: validates the scenario or deck at `path` and prints
/// what it is; `allow_large` as `run --allow-large` (a system beyond the
/// bounds of [`crate::work_bounds`] is refused as `run` refuses it).
pub fn check(path: &Path, allow_large: bool) -> Result<(), Failure> {
    check_in(path, allow_large, &scenario::HostEnvironment::NONE)
}

/// [`check`] with what the command line gives a MoorDyn deck that leaves
/// it out (`check --water-depth`).
pub fn check_in(
    path: &Path,
    allow_large: bool,
    host: &scenario::HostEnvironment,
) -> Result<(), Failure> {
    let text = crate::input_file::read_text(path)
        .map_err(|e| Failure::Input(format!("{}: {e}", path.display())))?;
    let file = path.display().to_string();
    if let scenario::Input::System(sc) =
        scenario::parse_input_with(&text, &file, path, host).map_err(|e| Failure::Input(e.0))?
    {
        crate::work_bounds::admit_system(&file, &sc, allow_large)?;
        print!("{}", crate::check_system::check_system(path, &sc)?);
        return Ok(());
    }
    let (sc, model, state) = load_text(&text, path)?;
    let d = (sc.analysis.kind == AnalysisKind::Dynamic).then(|| derive(&sc, &model, &state));
    if let Some(d) = &d {
        check_derived(path, d)?;
    }
    let unknowns = if sc.analysis.kind == AnalysisKind::Dynamic {
        // The same checks and count as the simulation a run builds, without
        // building it (O(nodes): check stays fast on large meshes).
        Some(
            stancf::integrator::step_unknowns(&model, &state, &sc.step_settings())
                .map_err(|e| Failure::Input(format!("{}: {}", path.display(), e)))?,
        )
    } else {
        None
    };
    if sc.analysis.kind == AnalysisKind::Static {
        stancf::StaticSolver::new(model.clone(), sc.static_settings())
            .map_err(|e| Failure::Input(format!("{}: {}", path.display(), e)))?;
    }
    print!("{}", describe(&sc, &model, d.as_ref(), unknowns));
    let size = size(&sc, false);
    println!(
        "{:<28}about {} ({} written step{}; more with --vtk)",
        "result files",
        bytes_text(size.bytes),
        Sig(size.written),
        if size.written == 1.0 { "" } else { "s" }
    );
    let mut w = warnings(&sc, &model, d.as_ref());
    if let Some((keys, what)) = size_problem(&sc, &size) {
        w.push(format!(
            "{keys}: this run would take {what}; `stancf run` refuses it unless given \
             --allow-large"
        ));
    }
    if w.is_empty() {
        println!("{:<28}none", "warnings");
    }
    for w in &w {
        println!("warning: {w}");
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn derived(w_max: f64) -> Derived {
        Derived {
            shortest_element: 0.5,
            wave_speed: 1569.6,
            courant: 0.16,
            w_max,
            critical_w_dt: Some(10f64.sqrt()),
            stable_step: Some(10f64.sqrt() / w_max),
            steps: 4,
        }
    }

    #[test]
    fn a_highest_frequency_that_could_not_be_computed_is_an_input_error_naming_the_keys() {
        assert!(check_derived(Path::new("t.toml"), &derived(3.0e4)).is_ok());
        for w in [f64::NAN, 0.0, f64::INFINITY] {
            match check_derived(Path::new("t.toml"), &derived(w)) {
                Err(Failure::Input(m)) => {
                    assert!(m.starts_with("t.toml: material.youngs_modulus"), "{m}");
                    assert!(m.contains("cable.length") && m.contains("w_max"), "{m}");
                }
                other => panic!("w_max {w}: {other:?}"),
            }
        }
    }
}
