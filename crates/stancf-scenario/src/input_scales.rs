//! The plausibility of a scenario's scales: every figure derived from its
//! input (section, mesh, frequencies, energies and stresses at t = 0,
//! loads, drag, prescribed motions, the time step) and the quantities that
//! grow predictably during a run (the fall under gravity, the travel of a
//! prescribed motion, the push of a point force over the duration) must be
//! finite and within the range the solver computes in, 1e-150 to 1e150 in
//! SI units ([`MAX_SCALE`]), so that the product or quotient of any two
//! stays a finite, nonzero double. A figure out of range is an input error
//! naming the scenario keys it is made of, the most extreme value first.

mod loads;
mod rules;
mod system;

pub(crate) use system::system_scales;

use crate::scenario::{AnalysisKind, Scenario};
use crate::Failure;
use rules::{key, keys, largest, norm, with, Figures, Rule};
use stancf::error::Sig;
use stancf::model::SLOT_R;
use stancf::{ConstraintKind, Energies, Model, State};

pub use crate::scale_range::MAX_SCALE;

/// The largest highest-frequency estimate of a mesh (rad/s): its
/// eigenvalue computation works with w^4.
pub const MAX_FREQUENCY: f64 = 1e70;

/// The derived figures of a scenario and its state at t = 0 (section,
/// mesh, frequencies, energies and their scales over the run, loads,
/// drag, the initial stresses): every one finite and within the range the
/// solver computes in, or an input error naming the keys it comes from.
/// Also the quantities that grow predictably during a run (the fall under
/// gravity, the travel of a prescribed motion, the push of a point force
/// over the duration).
pub(crate) fn scales(
    file: &str,
    sc: &Scenario,
    model: &Model,
    state: &State,
) -> Result<(), Failure> {
    let mut values = cable_values(sc);
    let mut velocity_keys = initial_velocities(sc, &mut values);
    let motions = prescribed_motions(sc, &mut values);
    velocity_keys.extend(motions.iter().flat_map(|m| m.keys.iter().cloned()));
    let gravity = loads::load_values(sc, &mut values);
    let f = Figures { file, values };

    let s = section(&f, sc, model)?;
    let frequency = element(&f, model, &s)?;
    let place = placement(&f, sc, &s)?;
    let speed = initial_speed(&f, sc, model, state, &motions, velocity_keys)?;
    let en = initial_energies(&f, model, state, &s, &speed)?;
    initial_stresses(&f, model, state, &place)?;
    loads::loads(&f, sc, &gravity, &s, &place, &speed, &en)?;
    // The coordinates at t = 0: finite.
    if !state.e.iter().all(|v| v.is_finite()) {
        f.need(
            "a coordinate at t = 0",
            f64::NAN,
            "",
            &place.keys,
            Rule::Finite,
        )?;
    }
    if sc.analysis.kind == AnalysisKind::Dynamic {
        time_step(&f, sc, &s, &frequency)?;
    }
    Ok(())
}

/// The values of the cable, its material and the analysis, key by key.
fn cable_values(sc: &Scenario) -> Vec<(String, f64)> {
    let m = &sc.material;
    let mut values = vec![
        (key::YOUNGS_MODULUS.into(), m.youngs_modulus),
        (key::DENSITY.into(), m.density),
        (key::AREA.into(), m.area),
        (key::SECOND_MOMENT.into(), m.second_moment),
        (key::LENGTH.into(), sc.cable.length),
        (key::ELEMENTS.into(), sc.cable.elements as f64),
        (key::ORIGIN.into(), largest(&sc.cable.origin)),
        (key::TIME_STEP.into(), sc.analysis.time_step),
        (key::DURATION.into(), sc.analysis.duration),
        ("material.diameter".into(), sc.diameter),
    ];
    match &sc.cable.grading {
        stancf::Grading::Geometric { ratio, .. } if !sc.cable.grading.is_uniform() => {
            values.push((key::GRADING_RATIO.into(), *ratio));
        }
        stancf::Grading::Sections(sections) => {
            let element = |s: &stancf::MeshSection| s.length / s.elements as f64;
            let shortest = sections
                .iter()
                .enumerate()
                .min_by(|a, b| element(a.1).total_cmp(&element(b.1)));
            if let Some((i, s)) = shortest {
                values.push((format!("{}[{i}].length", key::SECTIONS), s.length));
            }
        }
        _ => {}
    }
    values
}

/// The initial velocities' values added to `values`; returns the keys of
/// the velocities they give (a rigid rotation's centre among them when it
/// is off the origin).
fn initial_velocities(sc: &Scenario, values: &mut Vec<(String, f64)>) -> Vec<String> {
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
    velocity_keys
}

/// A prescribed motion r(t) = r0 + v t + a sin(w t + phase), w = 2 pi f,
/// bounded over a run of duration T.
struct Motion {
    /// The keys of its nonzero terms (v, a, and f when a is nonzero).
    keys: Vec<String>,
    /// The largest speed |v| + |a| w.
    speed: f64,
    /// The largest acceleration |a| w^2.
    acceleration: f64,
    /// The largest travel from r0, |v| T + |a|.
    travel: f64,
}

/// The prescribed motions' values added to `values`, and their bounds.
fn prescribed_motions(sc: &Scenario, values: &mut Vec<(String, f64)>) -> Vec<Motion> {
    let mut motions = Vec::new();
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
            let keys: Vec<String> = [
                ("velocity", largest(&velocity)),
                ("amplitude", a),
                ("frequency", if a > 0.0 { frequency } else { 0.0 }),
            ]
            .iter()
            .filter(|(_, v)| *v != 0.0)
            .map(|(f, _)| format!("{k}.{f}"))
            .collect();
            motions.push(Motion {
                keys,
                speed: norm(&velocity) + a * w,
                acceleration: a * w * w,
                travel: norm(&velocity) * sc.analysis.duration + a,
            });
        }
    }
    motions
}

/// The section and the mesh, the scales every other figure is made of.
struct Section {
    /// The axial stiffness E A (N).
    ea: f64,
    /// The bending stiffness E I (N m^2).
    ei: f64,
    /// The mass per length rho A (kg/m).
    rho_a: f64,
    /// The cable's length L (m).
    length: f64,
    /// The element length l = L / elements (m); on a graded mesh the
    /// shortest element's (docs/method.md §1.6).
    l: f64,
    /// The mass rho A L (kg).
    mass: f64,
}

/// The section and the mesh: the stiffnesses E A and E I within range, and
/// the mass per length rho A, the element length l = L / n (the shortest
/// on a graded mesh) and the mass rho A L also at least 1e-150, as the
/// solver divides by them.
fn section(f: &Figures, sc: &Scenario, model: &Model) -> Result<Section, Failure> {
    use key::{AREA, DENSITY, ELEMENTS, LENGTH, SECOND_MOMENT, YOUNGS_MODULUS};
    let m = &sc.material;
    let length = sc.cable.length;
    let s = Section {
        ea: m.youngs_modulus * m.area,
        ei: m.youngs_modulus * m.second_moment,
        rho_a: m.density * m.area,
        length,
        l: model.shortest_element_length(),
        mass: m.density * m.area * length,
    };
    f.need(
        "the axial stiffness E A",
        s.ea,
        " N",
        &keys(&[YOUNGS_MODULUS, AREA]),
        Rule::Scale,
    )?;
    f.need(
        "the bending stiffness E I",
        s.ei,
        " N m^2",
        &keys(&[YOUNGS_MODULUS, SECOND_MOMENT]),
        Rule::Scale,
    )?;
    f.need(
        "the mass per length rho A",
        s.rho_a,
        " kg/m",
        &keys(&[DENSITY, AREA]),
        Rule::Divisor,
    )?;
    f.need(
        if sc.cable.grading.is_uniform() {
            "the element length l = length / elements"
        } else {
            "the shortest element length l of the graded or sectioned mesh"
        },
        s.l,
        " m",
        &keys(&[LENGTH, ELEMENTS]),
        Rule::Divisor,
    )?;
    f.need(
        "the mass rho A length",
        s.mass,
        " kg",
        &keys(&[DENSITY, AREA, LENGTH]),
        Rule::Divisor,
    )?;
    Ok(s)
}

/// The wave speed and the highest frequency of the mesh.
struct Frequency {
    /// The wave speed c = sqrt(E / rho) (m/s).
    wave_speed: f64,
    /// The highest frequency w_max, estimated (rad/s).
    w_max: f64,
    /// The keys the estimate is made of.
    keys: Vec<String>,
}

/// One element: the nodal inertia rho A l^p of the highest slope a node
/// carries (p = 3 for SAC-2's r_x, 5 for SAC-3's r_xx; the solver divides
/// by it), the stiffnesses E A / l and E I / l^p, the wave speed
/// c = sqrt(E / rho) and the highest frequency, estimated as the larger of
/// the axial 14 c / l and the bending 8 sqrt(E I / (rho A)) / l^2 (from the
/// computed spectra of uniform meshes): at most [`MAX_FREQUENCY`], as the
/// eigenvalue computation of `check` needs w^4 to be finite.
fn element(f: &Figures, model: &Model, s: &Section) -> Result<Frequency, Failure> {
    use key::{AREA, DENSITY, ELEMENTS, LENGTH, SECOND_MOMENT, YOUNGS_MODULUS};
    let power = match model.element_type() {
        stancf::ElementType::Sac2 => 3,
        stancf::ElementType::Sac3 => 5,
    };
    f.need(
        &format!("the nodal inertia of the element's slopes rho A l^{power}"),
        s.rho_a * s.l.powi(power),
        " kg m^2",
        &keys(&[DENSITY, AREA, LENGTH, ELEMENTS]),
        Rule::Divisor,
    )?;
    f.need(
        "the element's axial stiffness E A / l",
        s.ea / s.l,
        " N/m",
        &keys(&[YOUNGS_MODULUS, AREA, LENGTH, ELEMENTS]),
        Rule::Scale,
    )?;
    f.need(
        &format!("the element's bending stiffness E I / l^{power}"),
        s.ei / s.l.powi(power),
        " N/m",
        &keys(&[YOUNGS_MODULUS, SECOND_MOMENT, LENGTH, ELEMENTS]),
        Rule::Scale,
    )?;
    let c = model.material.wave_speed();
    f.need(
        "the wave speed sqrt(E / rho)",
        c,
        " m/s",
        &keys(&[YOUNGS_MODULUS, DENSITY]),
        Rule::Scale,
    )?;
    let w_axial = 14.0 * c / s.l;
    let w_bending = 8.0 * (s.ei / s.rho_a).sqrt() / (s.l * s.l);
    let frequency = if w_axial.is_nan() || w_axial >= w_bending {
        Frequency {
            wave_speed: c,
            w_max: w_axial,
            keys: keys(&[YOUNGS_MODULUS, DENSITY, LENGTH, ELEMENTS]),
        }
    } else {
        Frequency {
            wave_speed: c,
            w_max: w_bending,
            keys: keys(&[
                YOUNGS_MODULUS,
                SECOND_MOMENT,
                DENSITY,
                AREA,
                LENGTH,
                ELEMENTS,
            ]),
        }
    };
    f.need(
        "the highest frequency of the mesh (estimate)",
        frequency.w_max,
        " rad/s",
        &frequency.keys,
        Rule::Below(MAX_FREQUENCY),
    )?;
    Ok(frequency)
}

/// Where the cable lies.
struct Placement {
    /// The extent |origin| + length (m): no coordinate starts farther
    /// from 0.
    extent: f64,
    /// The keys it is made of.
    keys: Vec<String>,
}

/// The placement of the cable: its extent |origin| + L within range, and
/// its coordinates rounded to less than Newton's tolerance: a coordinate
/// x is rounded to eps |x|, and Newton's tolerance is a fraction of an
/// element length, so eps (|origin| + L) / l above it could never converge.
fn placement(f: &Figures, sc: &Scenario, s: &Section) -> Result<Placement, Failure> {
    let place = Placement {
        extent: largest(&sc.cable.origin) + s.length,
        keys: keys(&[key::ORIGIN, key::LENGTH]),
    };
    f.need(
        "the extent of the cable |origin| + length",
        place.extent,
        " m",
        &place.keys,
        Rule::Scale,
    )?;
    let rounding = f64::EPSILON * place.extent;
    if rounding / s.l > sc.analysis.tolerance {
        let (grading, which) = match f.grading_key() {
            Some(k) => (format!(", {k}"), "the shortest element's length"),
            None => (String::new(), "an element length"),
        };
        return Err(Failure::Input(format!(
            "{}: cable.origin, analysis.tolerance, cable.length, cable.elements{grading}: the \
             coordinates (up to {} m from 0) are rounded to {} m, {} of {which}, \
             more than analysis.tolerance = {} (a fraction of an element length): Newton could \
             not converge; place the cable nearer to the origin of coordinates or loosen \
             analysis.tolerance",
            f.file,
            Sig(place.extent),
            Sig(rounding),
            Sig(rounding / s.l),
            Sig(sc.analysis.tolerance)
        )));
    }
    Ok(place)
}

/// The speeds of the cable at t = 0.
struct Speed {
    /// The largest speed of a node or a prescribed motion, v_max (m/s).
    largest: f64,
    /// The keys it is made of (with the placement's under a rigid
    /// rotation, whose speed grows with the distance from its centre).
    keys: Vec<String>,
    /// The keys of the velocities the input gives.
    given: Vec<String>,
}

/// The speeds at t = 0: those of the nodes, and of each prescribed motion
/// its speed |v| + |a| w, acceleration |a| w^2 and travel over the
/// duration |v| T + |a|, each within range; then the largest of them all.
fn initial_speed(
    f: &Figures,
    sc: &Scenario,
    model: &Model,
    state: &State,
    motions: &[Motion],
    velocity_keys: Vec<String>,
) -> Result<Speed, Failure> {
    let mut speed = 0.0f64;
    for j in 0..model.nodes() {
        let o = model.coordinate(j, SLOT_R, 0);
        speed = speed.max(norm(&state.v[o..o + 3]));
        if !state.v[model.node_range(j)].iter().all(|v| v.is_finite()) {
            speed = f64::INFINITY;
        }
    }
    for m in motions {
        f.need(
            "the speed of a prescribed motion",
            m.speed,
            " m/s",
            &m.keys,
            Rule::Scale,
        )?;
        speed = speed.max(m.speed);
        f.need(
            "the acceleration of a prescribed motion",
            m.acceleration,
            " m/s^2",
            &m.keys,
            Rule::Scale,
        )?;
        f.need(
            "the travel of a prescribed motion over the duration",
            m.travel,
            " m",
            &with(m.keys.clone(), &keys(&[key::DURATION])),
            Rule::Scale,
        )?;
    }
    let rotating = sc
        .initial_velocity
        .iter()
        .any(|iv| iv.angular_velocity.is_some());
    let speed = Speed {
        largest: speed,
        keys: if rotating {
            with(keys(&[key::ORIGIN, key::LENGTH]), &velocity_keys)
        } else {
            velocity_keys.clone()
        },
        given: velocity_keys,
    };
    f.need(
        "the largest initial speed",
        speed.largest,
        " m/s",
        &speed.keys,
        Rule::Scale,
    )?;
    Ok(speed)
}

/// The energies at t = 0 (eqs. 11 and 12) and their scales over the run:
/// the kinetic energy T and its scale rho A L v_max^2 / 2, the strain
/// energy U and its axial E A L and bending E I L / l^2 scales.
fn initial_energies(
    f: &Figures,
    model: &Model,
    state: &State,
    s: &Section,
    speed: &Speed,
) -> Result<Energies, Failure> {
    use key::{AREA, DENSITY, ELEMENTS, LENGTH, SECOND_MOMENT, YOUNGS_MODULUS};
    let kinetic_keys = with(keys(&[DENSITY, AREA, LENGTH]), &speed.keys);
    let en = stancf::energies(model, state);
    f.need(
        "the kinetic energy at t = 0",
        en.kinetic,
        " J",
        &kinetic_keys,
        Rule::Scale,
    )?;
    f.need(
        "the kinetic energy scale rho A length v_max^2 / 2",
        0.5 * s.rho_a * s.length * speed.largest * speed.largest,
        " J",
        &kinetic_keys,
        Rule::Scale,
    )?;
    let strain_keys = keys(&[YOUNGS_MODULUS, AREA, SECOND_MOMENT, LENGTH, ELEMENTS]);
    f.need(
        "the strain energy at t = 0",
        en.strain,
        " J",
        &strain_keys,
        Rule::Scale,
    )?;
    f.need(
        "the axial energy scale E A length",
        s.ea * s.length,
        " J",
        &keys(&[YOUNGS_MODULUS, AREA, LENGTH]),
        Rule::Scale,
    )?;
    f.need(
        "the bending energy scale E I length / l^2",
        s.ei * s.length / (s.l * s.l),
        " J",
        &strain_keys,
        Rule::Scale,
    )?;
    Ok(en)
}

/// The axial stress and the curvature at t = 0, sampled along every
/// element: finite.
fn initial_stresses(
    f: &Figures,
    model: &Model,
    state: &State,
    place: &Placement,
) -> Result<(), Failure> {
    use key::{AREA, ELEMENTS, LENGTH, SECOND_MOMENT, YOUNGS_MODULUS};
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
            &with(
                keys(&[YOUNGS_MODULUS, AREA, SECOND_MOMENT, LENGTH, ELEMENTS]),
                &place.keys,
            ),
            Rule::Finite,
        )?;
    }
    Ok(())
}

/// The time step of a dynamic run: the Courant number c dt / l and
/// w_max dt, with the estimated highest frequency, within range.
fn time_step(
    f: &Figures,
    sc: &Scenario,
    s: &Section,
    frequency: &Frequency,
) -> Result<(), Failure> {
    use key::{DENSITY, ELEMENTS, LENGTH, TIME_STEP, YOUNGS_MODULUS};
    let dt = sc.analysis.time_step;
    f.need(
        "the Courant number c dt / l",
        frequency.wave_speed * dt / s.l,
        "",
        &keys(&[YOUNGS_MODULUS, DENSITY, TIME_STEP, LENGTH, ELEMENTS]),
        Rule::Scale,
    )?;
    f.need(
        "w_max dt (estimate)",
        frequency.w_max * dt,
        "",
        &with(frequency.keys.clone(), &keys(&[TIME_STEP])),
        Rule::Scale,
    )
}
