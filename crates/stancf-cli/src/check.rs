//! The `check` command: a scenario validated and its derived figures
//! (DOFs, wave speed, Courant number, highest frequency, stable step)
//! printed; nothing is run. `run` starts from the same figures.

use crate::scenario::{self, AnalysisKind, Scenario};
use crate::Failure;
use stancf::error::Sig;
use stancf::integrator::step_count;
use stancf::quadrature::GaussRule;
use stancf::{stability, Model, State};
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
    let text = std::fs::read_to_string(path)
        .map_err(|e| Failure::Input(format!("{}: cannot read the file: {e}", path.display())))?;
    load_text(&text, path)
}

/// Validates scenario text (`path` names it in messages and gives the
/// default title) and builds its model and initial state. A derived scale
/// out of the range the solver computes in (non-finite, or beyond
/// [`MAX_SCALE`]) is an input error naming the keys it is made of.
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

/// A run is refused above this many steps unless `--allow-large` is given
/// (`check` warns).
pub const MAX_STEPS: usize = 100_000_000;

/// A run is refused when its result files would exceed this many bytes
/// (estimated from the steps, `output.every` and the mesh) unless
/// `--allow-large` is given (`check` warns).
pub const MAX_RESULT_BYTES: f64 = 4e9;

/// The range of the derived scales of a scenario (energies, forces,
/// lengths, masses, stiffnesses in SI units): at most `MAX_SCALE`, and the
/// ones the solver divides by at least `1 / MAX_SCALE`, so that the product
/// or quotient of any two stays a finite, nonzero double.
pub const MAX_SCALE: f64 = 1e150;

/// The largest highest-frequency estimate of a mesh (rad/s): its
/// eigenvalue computation works with w^4.
pub const MAX_FREQUENCY: f64 = 1e70;

/// What a derived figure must satisfy.
#[derive(Clone, Copy)]
enum Rule {
    /// A finite number.
    Finite,
    /// Finite and at most `MAX_SCALE` in magnitude.
    Scale,
    /// Finite, at most `MAX_SCALE` and at least `1 / MAX_SCALE` (the
    /// solver divides by it).
    Divisor,
    /// Finite and at most this.
    Below(f64),
}

/// The derived figures of a scenario, checked one by one; a figure that
/// breaks its rule is an input error naming the keys it is made of, the
/// most extreme value first.
struct Figures<'a> {
    file: &'a str,
    /// Magnitude of every key's value (largest component of a vector).
    values: Vec<(String, f64)>,
}

impl Figures<'_> {
    fn value(&self, key: &str) -> f64 {
        self.values
            .iter()
            .find(|(k, _)| k == key)
            .map_or(1.0, |(_, v)| *v)
    }

    fn need(
        &self,
        what: &str,
        value: f64,
        unit: &str,
        keys: &[String],
        rule: Rule,
    ) -> Result<(), Failure> {
        let v = value.abs();
        let problem = match rule {
            _ if value.is_nan() => Some("is not a number".to_string()),
            _ if value.is_infinite() => Some("overflows (it is beyond 1.8e308)".to_string()),
            Rule::Finite => None,
            Rule::Scale | Rule::Divisor if v > MAX_SCALE => {
                Some(format!("is beyond {MAX_SCALE:e}{unit}"))
            }
            Rule::Divisor if v < 1.0 / MAX_SCALE => {
                Some(format!("is below {:e}{unit}", 1.0 / MAX_SCALE))
            }
            Rule::Below(limit) if v > limit => Some(format!("is beyond {limit:e}{unit}")),
            _ => None,
        };
        let Some(problem) = problem else {
            return Ok(());
        };
        // The most extreme value first: the likely culprit.
        let extremeness = |k: &String| {
            let v = self.value(k);
            if !v.is_finite() {
                f64::INFINITY
            } else if v > 0.0 {
                v.log10().abs()
            } else {
                -1.0 // a zero is never the culprit
            }
        };
        let mut keys = keys.to_vec();
        keys.sort_by(|a, b| extremeness(b).total_cmp(&extremeness(a)));
        keys.dedup();
        let shown: Vec<String> = keys
            .iter()
            .map(|k| format!("{k} = {}", Sig(self.value(k))))
            .collect();
        Err(Failure::Input(format!(
            "{}: {}: {what} = {}{unit} {problem}: the solver computes in double precision and \
             needs the derived scales within 1e-150 to 1e150 (SI units); from {}: check these \
             values and their units",
            self.file,
            keys.join(", "),
            Sig(value),
            shown.join(", ")
        )))
    }
}

fn norm(v: &[f64]) -> f64 {
    v.iter().map(|c| c * c).sum::<f64>().sqrt()
}

fn largest(v: &[f64]) -> f64 {
    v.iter().fold(0.0f64, |m, c| m.max(c.abs()))
}

/// The derived figures of a scenario and its state at t = 0 (section,
/// mesh, frequencies, energies and their scales over the run, loads,
/// drag, the initial stresses): every one finite and within the range the
/// solver computes in, or an input error naming the keys it comes from.
/// Also the quantities that grow predictably during a run (the fall under
/// gravity, the travel of a prescribed motion, the push of a point force
/// over the duration).
fn scales(file: &str, sc: &Scenario, model: &Model, state: &State) -> Result<(), Failure> {
    use stancf::ConstraintKind;
    let m = &sc.material;
    let (ek, rk, ak, ik, lk, nk) = (
        "material.youngs_modulus",
        "material.density",
        "material.area",
        "material.second_moment",
        "cable.length",
        "cable.elements",
    );
    let (ok, dtk, tk) = ("cable.origin", "analysis.time_step", "analysis.duration");
    let dynamic = sc.analysis.kind == AnalysisKind::Dynamic;
    let length = sc.cable.length;
    let n = sc.cable.elements as f64;
    let mut values: Vec<(String, f64)> = vec![
        (ek.into(), m.youngs_modulus),
        (rk.into(), m.density),
        (ak.into(), m.area),
        (ik.into(), m.second_moment),
        (lk.into(), length),
        (nk.into(), n),
        (ok.into(), largest(&sc.cable.origin)),
        (dtk.into(), sc.analysis.time_step),
        (tk.into(), sc.analysis.duration),
        ("material.diameter".into(), sc.diameter),
    ];
    let keys = |ks: &[&str]| -> Vec<String> { ks.iter().map(|k| k.to_string()).collect() };

    // Velocities the input gives: initial velocities and prescribed motions.
    let mut velocity_keys = Vec::new();
    for (i, iv) in sc.initial_velocity.iter().enumerate() {
        let k = format!("initial_velocity[{i}]");
        if iv.velocity.iter().any(|&c| c != 0.0) {
            values.push((format!("{k}.velocity"), largest(&iv.velocity)));
            velocity_keys.push(format!("{k}.velocity"));
        }
        if let Some(w) = iv.angular_velocity {
            values.push((format!("{k}.angular_velocity"), largest(&w)));
            values.push((format!("{k}.center"), largest(&iv.center)));
            velocity_keys.push(format!("{k}.angular_velocity"));
            if iv.center.iter().any(|&c| c != 0.0) {
                velocity_keys.push(format!("{k}.center"));
            }
        }
    }
    // (rate, acceleration, travel over the duration) of each prescribed motion.
    let mut prescribed = Vec::new();
    for (i, c) in sc.constraints.iter().enumerate() {
        if let ConstraintKind::Prescribed {
            velocity,
            amplitude,
            frequency,
            ..
        } = c.kind
        {
            let k = format!("constraints[{i}]");
            let w = 2.0 * std::f64::consts::PI * frequency;
            let a = norm(&amplitude);
            values.push((format!("{k}.velocity"), largest(&velocity)));
            values.push((format!("{k}.amplitude"), largest(&amplitude)));
            values.push((format!("{k}.frequency"), frequency));
            let ks: Vec<String> = [
                ("velocity", largest(&velocity)),
                ("amplitude", a),
                ("frequency", if a > 0.0 { frequency } else { 0.0 }),
            ]
            .iter()
            .filter(|(_, v)| *v != 0.0)
            .map(|(f, _)| format!("{k}.{f}"))
            .collect();
            velocity_keys.extend(ks.iter().cloned());
            prescribed.push((
                ks,
                norm(&velocity) + a * w,
                a * w * w,
                norm(&velocity) * sc.analysis.duration + a,
            ));
        }
    }
    let mut gravity_keys = Vec::new();
    let mut gravity = [0.0; 3];
    for (i, load) in sc.loads.iter().enumerate() {
        match load {
            stancf::Load::Gravity { acceleration } => {
                let k = format!("loads[{i}].acceleration");
                values.push((k.clone(), largest(acceleration)));
                gravity_keys.push(k);
                for c in 0..3 {
                    gravity[c] += acceleration[c];
                }
            }
            stancf::Load::PointForce { force: v, .. } => {
                values.push((format!("loads[{i}].force"), largest(v)));
            }
            stancf::Load::EndMoment { moment: v, .. } => {
                values.push((format!("loads[{i}].moment"), largest(v)));
            }
            stancf::Load::AirDrag(d) => {
                let k = format!("loads[{i}]");
                values.push((format!("{k}.drag_coefficient"), d.drag_coefficient));
                values.push((format!("{k}.fluid_density"), d.fluid_density));
                values.push((format!("{k}.diameter"), d.diameter));
                values.push((format!("{k}.fluid_velocity"), largest(&d.fluid_velocity)));
            }
        }
    }
    let f = Figures { file, values };

    // Section and mesh.
    let ea = m.youngs_modulus * m.area;
    let ei = m.youngs_modulus * m.second_moment;
    let rho_a = m.density * m.area;
    let l = length / n;
    f.need(
        "the axial stiffness E A",
        ea,
        " N",
        &keys(&[ek, ak]),
        Rule::Scale,
    )?;
    f.need(
        "the bending stiffness E I",
        ei,
        " N m^2",
        &keys(&[ek, ik]),
        Rule::Scale,
    )?;
    f.need(
        "the mass per length rho A",
        rho_a,
        " kg/m",
        &keys(&[rk, ak]),
        Rule::Divisor,
    )?;
    f.need(
        "the element length l = length / elements",
        l,
        " m",
        &keys(&[lk, nk]),
        Rule::Divisor,
    )?;
    f.need(
        "the mass rho A length",
        rho_a * length,
        " kg",
        &keys(&[rk, ak, lk]),
        Rule::Divisor,
    )?;
    // The inertia of the highest derivative a node carries (r_x, r_xx).
    let power = match model.element_type() {
        stancf::ElementType::Sac2 => 3,
        stancf::ElementType::Sac3 => 5,
    };
    f.need(
        &format!("the nodal inertia of the element's slopes rho A l^{power}"),
        rho_a * l.powi(power),
        " kg m^2",
        &keys(&[rk, ak, lk, nk]),
        Rule::Divisor,
    )?;
    f.need(
        "the element's axial stiffness E A / l",
        ea / l,
        " N/m",
        &keys(&[ek, ak, lk, nk]),
        Rule::Scale,
    )?;
    f.need(
        &format!("the element's bending stiffness E I / l^{power}"),
        ei / l.powi(power),
        " N/m",
        &keys(&[ek, ik, lk, nk]),
        Rule::Scale,
    )?;
    let c = model.material.wave_speed();
    f.need(
        "the wave speed sqrt(E / rho)",
        c,
        " m/s",
        &keys(&[ek, rk]),
        Rule::Scale,
    )?;
    // The highest frequency, estimated (the eigenvalue computation of
    // `check` needs w^4 to be finite): the larger of the axial and the
    // bending estimates, from the computed spectra of uniform meshes.
    let w_axial = 14.0 * c / l;
    let w_bending = 8.0 * (ei / rho_a).sqrt() / (l * l);
    let (w_est, w_keys) = if w_axial.is_nan() || w_axial >= w_bending {
        (w_axial, keys(&[ek, rk, lk, nk]))
    } else {
        (w_bending, keys(&[ek, ik, rk, ak, lk, nk]))
    };
    f.need(
        "the highest frequency of the mesh (estimate)",
        w_est,
        " rad/s",
        &w_keys,
        Rule::Below(MAX_FREQUENCY),
    )?;

    // The state at t = 0.
    let with = |mut base: Vec<String>, more: &[String]| {
        base.extend(more.iter().cloned());
        base
    };
    let place_keys = keys(&[ok, lk]);
    let extent = largest(&sc.cable.origin) + length;
    f.need(
        "the extent of the cable |origin| + length",
        extent,
        " m",
        &place_keys,
        Rule::Scale,
    )?;
    // Coordinates far from 0 are rounded to more than Newton's tolerance
    // (a fraction of an element length): it could never converge.
    let rounding = f64::EPSILON * extent;
    if rounding / l > sc.analysis.tolerance {
        return Err(Failure::Input(format!(
            "{file}: cable.origin, analysis.tolerance, cable.length, cable.elements: the \
             coordinates (up to {} m from 0) are rounded to {} m, {} of an element length, \
             more than analysis.tolerance = {} (a fraction of an element length): Newton could \
             not converge; place the cable nearer to the origin of coordinates or loosen \
             analysis.tolerance",
            Sig(extent),
            Sig(rounding),
            Sig(rounding / l),
            Sig(sc.analysis.tolerance)
        )));
    }
    let dpn = model.dofs_per_node();
    let mut speed = 0.0f64;
    for j in 0..model.nodes() {
        let o = model.node_offset(j);
        speed = speed.max(norm(&state.v[o..o + 3]));
        if !state.v[o..o + dpn].iter().all(|v| v.is_finite()) {
            speed = f64::INFINITY;
        }
    }
    for (ks, rate, acceleration, travel) in &prescribed {
        f.need(
            "the speed of a prescribed motion",
            *rate,
            " m/s",
            ks,
            Rule::Scale,
        )?;
        speed = speed.max(*rate);
        f.need(
            "the acceleration of a prescribed motion",
            *acceleration,
            " m/s^2",
            ks,
            Rule::Scale,
        )?;
        let ks = with(ks.clone(), &keys(&[tk]));
        f.need(
            "the travel of a prescribed motion over the duration",
            *travel,
            " m",
            &ks,
            Rule::Scale,
        )?;
    }
    // A rigid rotation's speed grows with the distance from its centre.
    let rotating = sc
        .initial_velocity
        .iter()
        .any(|iv| iv.angular_velocity.is_some());
    let vk = if rotating {
        with(keys(&[ok, lk]), &velocity_keys)
    } else {
        velocity_keys.clone()
    };
    f.need("the largest initial speed", speed, " m/s", &vk, Rule::Scale)?;
    let mass_keys = keys(&[rk, ak, lk]);
    let ke_keys = with(mass_keys.clone(), &vk);
    let en = stancf::energies(model, state);
    f.need(
        "the kinetic energy at t = 0",
        en.kinetic,
        " J",
        &ke_keys,
        Rule::Scale,
    )?;
    f.need(
        "the kinetic energy scale rho A length v_max^2 / 2",
        0.5 * rho_a * length * speed * speed,
        " J",
        &ke_keys,
        Rule::Scale,
    )?;
    let strain_keys = keys(&[ek, ak, ik, lk, nk]);
    f.need(
        "the strain energy at t = 0",
        en.strain,
        " J",
        &strain_keys,
        Rule::Scale,
    )?;
    f.need(
        "the axial energy scale E A length",
        ea * length,
        " J",
        &keys(&[ek, ak, lk]),
        Rule::Scale,
    )?;
    f.need(
        "the bending energy scale E I length / l^2",
        ei * length / (l * l),
        " J",
        &strain_keys,
        Rule::Scale,
    )?;
    let mut samples = Vec::new();
    stancf::observe::stress_samples(model, state, 5, &mut samples);
    if let Some(bad) = samples
        .iter()
        .find(|s| !(s.axial_stress.is_finite() && s.curvature.is_finite()))
    {
        let v = if bad.axial_stress.is_finite() {
            bad.curvature
        } else {
            bad.axial_stress
        };
        f.need(
            "a stress or curvature at t = 0",
            v,
            "",
            &with(strain_keys.clone(), &place_keys),
            Rule::Finite,
        )?;
    }
    let t = if dynamic { sc.analysis.duration } else { 0.0 };
    let mass = rho_a * length;
    if !gravity_keys.is_empty() {
        let g = norm(&gravity);
        let gk = with(with(mass_keys.clone(), &gravity_keys), &place_keys);
        f.need(
            "the weight rho A length |g|",
            mass * g,
            " N",
            &gk,
            Rule::Scale,
        )?;
        f.need(
            "the gravitational potential at t = 0",
            en.gravity,
            " J",
            &gk,
            Rule::Scale,
        )?;
        // Falling freely for the whole run.
        let fall = with(gk.clone(), &keys(&[tk]));
        f.need(
            "the fall under gravity over the duration g T^2 / 2",
            0.5 * g * t * t,
            " m",
            &fall,
            Rule::Scale,
        )?;
        f.need(
            "the gravitational energy scale rho A length |g| (extent + g T^2 / 2)",
            mass * g * (extent + 0.5 * g * t * t),
            " J",
            &fall,
            Rule::Scale,
        )?;
    }
    for (i, load) in sc.loads.iter().enumerate() {
        match load {
            stancf::Load::PointForce { force, .. } => {
                let fk = with(vec![format!("loads[{i}].force")], &place_keys);
                let fnorm = norm(force);
                f.need("the point force |F|", fnorm, " N", &fk, Rule::Scale)?;
                // The push on the free cable over the whole run.
                let push = with(with(fk.clone(), &mass_keys), &keys(&[tk]));
                let travel = 0.5 * fnorm / mass * t * t;
                f.need(
                    "the travel of the cable pushed by the force |F| T^2 / (2 m)",
                    travel,
                    " m",
                    &push,
                    Rule::Scale,
                )?;
                f.need(
                    "the work scale of the point force |F| (extent + |F| T^2 / (2 m))",
                    fnorm * (extent + travel),
                    " J",
                    &push,
                    Rule::Scale,
                )?;
            }
            stancf::Load::EndMoment { moment, .. } => {
                let mk = with(vec![format!("loads[{i}].moment")], &keys(&[lk, nk]));
                f.need("the end moment |M|", norm(moment), " N m", &mk, Rule::Scale)?;
                f.need(
                    "the end moment's force on an element |M| / l",
                    norm(moment) / l,
                    " N",
                    &mk,
                    Rule::Scale,
                )?;
            }
            stancf::Load::AirDrag(d) => {
                let k = format!("loads[{i}]");
                let dk: Vec<String> = ["drag_coefficient", "fluid_density", "diameter"]
                    .iter()
                    .map(|n| format!("{k}.{n}"))
                    .collect();
                let coefficient = 0.5 * d.drag_coefficient * d.fluid_density * d.diameter;
                f.need(
                    "the drag factor C rho_fluid d / 2",
                    coefficient,
                    " kg/m^2",
                    &dk,
                    Rule::Scale,
                )?;
                let relative = norm(&d.fluid_velocity) + speed;
                let vk = with(
                    with(dk.clone(), &[format!("{k}.fluid_velocity")]),
                    &velocity_keys,
                );
                f.need(
                    "the largest relative speed of the fluid",
                    relative,
                    " m/s",
                    &vk,
                    Rule::Scale,
                )?;
                f.need(
                    "the drag force scale C rho_fluid d length v^2 / 2",
                    coefficient * length * relative * relative,
                    " N",
                    &with(vk.clone(), &keys(&[lk])),
                    Rule::Scale,
                )?;
            }
            stancf::Load::Gravity { .. } => {}
        }
    }
    f.need(
        "the load potential at t = 0",
        en.load_potential,
        " J",
        &with(
            sc.loads
                .iter()
                .enumerate()
                .filter(|(_, l)| {
                    matches!(
                        l,
                        stancf::Load::PointForce { .. } | stancf::Load::EndMoment { .. }
                    )
                })
                .map(|(i, l)| {
                    format!(
                        "loads[{i}].{}",
                        if matches!(l, stancf::Load::PointForce { .. }) {
                            "force"
                        } else {
                            "moment"
                        }
                    )
                })
                .collect(),
            &place_keys,
        ),
        Rule::Scale,
    )?;
    if !state.e.iter().all(|v| v.is_finite()) {
        f.need(
            "a coordinate at t = 0",
            f64::NAN,
            "",
            &place_keys,
            Rule::Finite,
        )?;
    }
    if dynamic {
        let dt = sc.analysis.time_step;
        f.need(
            "the Courant number c dt / l",
            c * dt / l,
            "",
            &keys(&[ek, rk, dtk, lk, nk]),
            Rule::Scale,
        )?;
        f.need(
            "w_max dt (estimate)",
            w_est * dt,
            "",
            &with(w_keys, &keys(&[dtk])),
            Rule::Scale,
        )?;
    }
    Ok(())
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

/// The figures [`derive`] computed, checked: the highest frequency (from
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

/// How much a run would do and write.
pub(crate) struct Size {
    /// Steps (dynamic) or load steps (static).
    pub(crate) steps: f64,
    /// Rows written (one per written step).
    pub(crate) written: f64,
    /// Estimated bytes of the result files.
    pub(crate) bytes: f64,
}

/// Bytes per step of solver.csv and convergence.csv (dynamic runs), and
/// per written row of history.csv, per node of nodes.csv, per sample of
/// stress.csv, per constrained node of reactions.csv and per element of a
/// `--vtk` file: measured on the examples, rounded up.
const BYTES_PER_STEP: f64 = 250.0;
const BYTES_PER_HISTORY_ROW: f64 = 150.0;
const BYTES_PER_NODE_ROW: f64 = 120.0;
const BYTES_PER_STRESS_ROW: f64 = 75.0;
const BYTES_PER_REACTION_ROW: f64 = 95.0;
const BYTES_PER_VTK_ELEMENT: f64 = 2700.0;

/// The size of a run of `sc` (with `--vtk` when `vtk`).
pub(crate) fn size(sc: &Scenario, vtk: bool) -> Size {
    let a = &sc.analysis;
    let (steps, per_step) = match a.kind {
        AnalysisKind::Dynamic => (
            (a.duration / a.time_step - 1e-9).ceil().max(1.0),
            BYTES_PER_STEP,
        ),
        AnalysisKind::Static => (a.load_steps as f64, 0.0),
    };
    // Every k-th step, the first row at t = 0 and the last step (a static
    // run writes every load step).
    let written = match a.kind {
        AnalysisKind::Dynamic => (steps / sc.output_every as f64).floor() + 2.0,
        AnalysisKind::Static => steps + 1.0,
    };
    let elements = sc.cable.elements as f64;
    let row = BYTES_PER_HISTORY_ROW
        + BYTES_PER_NODE_ROW * (elements + 1.0)
        + BYTES_PER_STRESS_ROW * 5.0 * elements
        + BYTES_PER_REACTION_ROW * sc.constraints.len() as f64
        + if vtk {
            BYTES_PER_VTK_ELEMENT * elements
        } else {
            0.0
        };
    Size {
        steps,
        written,
        bytes: steps * per_step + written * row,
    }
}

/// Bytes in words: "3.2 GB", "850 MB", "12 kB".
pub(crate) fn bytes_text(b: f64) -> String {
    let units = [(1e12, "TB"), (1e9, "GB"), (1e6, "MB"), (1e3, "kB")];
    for (scale, unit) in units {
        if b >= scale {
            return format!("{} {unit}", Sig((b / scale * 10.0).round() / 10.0));
        }
    }
    format!("{} bytes", b.round())
}

/// Why a run of this size is refused without `--allow-large`: the keys
/// that set its size and what is exceeded; `None` within the bounds.
pub(crate) fn size_problem(sc: &Scenario, size: &Size) -> Option<(String, String)> {
    let dynamic = sc.analysis.kind == AnalysisKind::Dynamic;
    let steps_key = if dynamic {
        "analysis.duration, analysis.time_step"
    } else {
        "analysis.load_steps"
    };
    let mut keys = Vec::new();
    let mut what = Vec::new();
    if size.steps > MAX_STEPS as f64 {
        keys.push(steps_key.to_string());
        what.push(format!(
            "{} steps (the bound is {:e})",
            Sig(size.steps),
            MAX_STEPS as f64
        ));
    }
    if size.bytes > MAX_RESULT_BYTES {
        if keys.is_empty() {
            keys.push(steps_key.to_string());
        }
        keys.push("output.every, cable.elements".to_string());
        what.push(format!(
            "about {} of result files ({} written steps; the bound is {})",
            bytes_text(size.bytes),
            Sig(size.written),
            bytes_text(MAX_RESULT_BYTES)
        ));
    }
    (!what.is_empty()).then(|| (keys.join(", "), what.join(" and ")))
}

/// `run`'s bound on work: a run above [`MAX_STEPS`] steps or
/// [`MAX_RESULT_BYTES`] of result files is an input error naming the keys
/// and `--allow-large`, unless `opts.allow_large`. Called before anything
/// is written.
pub(crate) fn admit(
    path: &Path,
    sc: &Scenario,
    opts: &crate::commands::RunOptions,
) -> Result<(), Failure> {
    if opts.allow_large {
        return Ok(());
    }
    let size = size(sc, opts.vtk);
    match size_problem(sc, &size) {
        None => Ok(()),
        Some((keys, what)) => Err(Failure::Input(format!(
            "{}: {keys}: this run would take {what}; shorten the run, write fewer steps \
             (a larger output.every) or pass --allow-large to run it anyway",
            path.display()
        ))),
    }
}

/// Warnings about a scenario: the model's own (quadrature), the scenario's
/// notes, a step above P2's stable limit, and a Galerkin step beyond the
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

pub fn check(path: &Path) -> Result<(), Failure> {
    let (sc, model, state) = load(path)?;
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
    use crate::commands::RunOptions;

    fn scenario(body: &str) -> Scenario {
        let text = format!(
            "[cable]\nlength = 4.0\nelements = 8\n[material]\nyoungs_modulus = 3.4e9\n\
             density = 1380.0\narea = 3.0e-6\nsecond_moment = 1.25e-13\n{body}"
        );
        scenario::parse(&text, "t.toml", Path::new("t.toml")).expect("valid")
    }

    fn derived(w_max: f64) -> Derived {
        Derived {
            element_length: 0.5,
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

    #[test]
    fn the_size_estimate_counts_every_written_step_and_the_per_step_files() {
        let sc = scenario("[analysis]\ntime_step = 1e-3\nduration = 1.0\n[output]\nevery = 10\n");
        let s = size(&sc, false);
        assert_eq!(s.steps, 1000.0);
        assert_eq!(s.written, 102.0);
        let row = 150.0 + 120.0 * 9.0 + 75.0 * 5.0 * 8.0;
        assert_eq!(s.bytes, 1000.0 * 250.0 + 102.0 * row);
        assert!(size(&sc, true).bytes > s.bytes);
        assert!(size_problem(&sc, &s).is_none());
    }

    #[test]
    fn a_run_above_the_bounds_is_refused_unless_allowed() {
        let sc = scenario("[analysis]\ntime_step = 1e-6\nduration = 200.0\n");
        let refused = admit(Path::new("t.toml"), &sc, &RunOptions::default());
        match refused {
            Err(Failure::Input(m)) => {
                assert!(
                    m.starts_with("t.toml: analysis.duration, analysis.time_step"),
                    "{m}"
                );
                assert!(
                    m.contains("2e8 steps") && m.contains("--allow-large"),
                    "{m}"
                );
            }
            other => panic!("{other:?}"),
        }
        let allowed = RunOptions {
            allow_large: true,
            ..RunOptions::default()
        };
        assert!(admit(Path::new("t.toml"), &sc, &allowed).is_ok());
    }

    #[test]
    fn bytes_read_in_words() {
        assert_eq!(bytes_text(4e9), "4 GB");
        assert_eq!(bytes_text(26_400.0), "26.4 kB");
        assert_eq!(bytes_text(5.04e13), "50.4 TB");
        assert_eq!(bytes_text(512.0), "512 bytes");
    }
}
