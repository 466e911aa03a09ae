//! The plausibility of a system's scales (issue 28, item 8): every value
//! of its line types, lines, points, gravity, water and time step, and
//! every figure derived from them before anything is built (a line type's
//! area, modulus and density, a line's element length, axial stiffness,
//! weight, buoyancy and highest frequency, a point's weight and buoyancy,
//! a wave's length), must be finite and within the range the solver
//! computes in ([`super::MAX_SCALE`]), as a single cable's are
//! ([`super::scales`]). A value out of range is an input error naming the
//! values it is made of as the user wrote them: TOML keys, or the deck's
//! line and column ([`crate::scenario::names`]).

use super::rules::{largest, Figures, Rule};
use super::MAX_FREQUENCY;
use crate::moordyn::SupportedOption as Opt;
use crate::scenario::{AnalysisKind, SystemScenario, Water};
use crate::Failure;

/// The slowest slip of a seabed's regularized friction (m/s): below it
/// the friction's derivative, mu N / v_slip, overflows the Jacobian at
/// the forces of a mooring (1e6 N needs 1e-300 m/s to reach 1e306) and the
/// slip is far below any velocity a step resolves.
pub const MIN_SLIP_VELOCITY: f64 = 1e-9;

/// The derived figures of `sc` (see the module documentation); `file`
/// names the file in the message.
pub(crate) fn system_scales(file: &str, sc: &SystemScenario) -> Result<(), Failure> {
    let n = &sc.names;
    let g_key = n.option("system.gravity", Opt::Gravity);
    let g = magnitude(&sc.gravity);
    let mut values = vec![(g_key.clone(), g)];
    let step_key = n.option("analysis.time_step", Opt::TimeStep);
    // A dynamic run's step, or the step a deck gives (dtM) for a coupled
    // run of it.
    let stepped = sc.analysis.kind == AnalysisKind::Dynamic || sc.analysis.time_step != 0.0;
    if stepped {
        values.push((step_key.clone(), sc.analysis.time_step));
        values.push(("analysis.duration".into(), sc.analysis.duration));
    }
    let water = sc.water.as_ref().map(|w| water_values(sc, w, &mut values));
    for (i, t) in sc.line_types.iter().enumerate() {
        let key = |k: &str, c: &str| n.line_type(i, k, c);
        values.extend([
            (key("diameter", "Diam"), t.diameter),
            (key("mass_per_length", "Mass/m"), t.mass_per_length),
            (key("ea", "EA"), t.ea),
            (key("ei", "EI"), t.ei),
            (key("ba", "BA/-zeta"), t.ba.abs()),
            (key("cd", "Cd"), t.cd_normal),
            (key("ca", "Ca"), t.ca_normal),
            (key("cdax", "CdAx"), t.cd_axial),
            (key("caax", "CaAx"), t.ca_axial),
        ]);
    }
    for (j, l) in sc.lines.iter().enumerate() {
        values.push((n.line(j, "length", "UnstrLen"), l.length));
        values.push((n.line(j, "elements", "NumSegs"), l.elements as f64));
    }
    for (p, pt) in sc.points.iter().enumerate() {
        let key = |k: &str, c: &str| n.point(p, k, c);
        values.extend([
            (key("position", "X, Y, Z"), largest(&pt.position)),
            (key("mass", "Mass"), pt.mass),
            (key("volume", "Volume"), pt.volume),
            (key("drag_area", "CdA"), pt.drag_area),
            (key("ca", "Ca"), pt.ca),
            (key("force", "FX, FY, FZ"), magnitude(&pt.force)),
        ]);
    }
    for (b, body) in sc.bodies.iter().enumerate() {
        let key = |k: &str, c: &str| n.body(b, k, c);
        values.extend([
            (key("position", "X0, Y0, Z0"), largest(&body.position)),
            (key("angles", "r0, p0, y0"), largest(&body.angles)),
            (key("mass", "Mass"), body.mass),
            (key("centre_of_mass", "CG"), largest(&body.centre_of_mass)),
            (key("inertia", "I"), largest(&body.moments)),
            (key("volume", "Volume"), body.volume),
            (key("cda", "CdA"), largest(&body.drag_areas)),
            (
                key("rotational_cda", "CdA"),
                largest(&body.rotational_drag_areas),
            ),
            (key("ca", "Ca"), largest(&body.ca)),
            (key("velocity", "velocity"), magnitude(&body.velocity)),
            (
                key("angular_velocity", "angular velocity"),
                magnitude(&body.angular_velocity),
            ),
        ]);
    }
    rod_values(sc, &mut values);
    let f = Figures { file, values };
    // Every value as given.
    for (k, v) in &f.values {
        f.need(
            "the value given",
            *v,
            "",
            std::slice::from_ref(k),
            Rule::Scale,
        )?;
    }
    f.need(
        "|g|",
        g,
        " m/s^2",
        std::slice::from_ref(&g_key),
        Rule::Scale,
    )?;
    if stepped {
        f.need(
            "the time step",
            sc.analysis.time_step,
            " s",
            &[step_key],
            Rule::Divisor,
        )?;
    }
    if let Some(w) = &water {
        water_figures(&f, sc, w, &g_key)?;
    }
    for i in 0..sc.line_types.len() {
        line_type_figures(&f, sc, i)?;
    }
    for j in 0..sc.lines.len() {
        line_figures(&f, sc, j, &g_key, water.as_ref())?;
    }
    weights_of_points_and_bodies(&f, sc, &g_key, water.as_ref())?;
    Ok(())
}

/// |v| without overflow: max |v_i| times the norm of v / max |v_i|.
fn magnitude(v: &[f64]) -> f64 {
    let scale = largest(v);
    if scale == 0.0 || !scale.is_finite() {
        return scale;
    }
    scale * v.iter().map(|c| (c / scale).powi(2)).sum::<f64>().sqrt()
}

/// The keys of the water's values, as the user wrote them.
struct WaterKeys {
    depth: String,
    density: String,
}

/// Adds the water's values to `values`; returns the keys of its depth
/// and density.
fn water_values(sc: &SystemScenario, w: &Water, values: &mut Vec<(String, f64)>) -> WaterKeys {
    let n = &sc.names;
    let keys = WaterKeys {
        depth: n.option("water.depth", Opt::WaterDepth),
        density: n.option("water.density", Opt::WaterDensity),
    };
    let b = &w.seabed;
    values.extend([
        (keys.depth.clone(), w.depth),
        (keys.density.clone(), w.density),
        (
            n.option("water.seabed.stiffness", Opt::BottomStiffness),
            b.stiffness,
        ),
        (
            n.option("water.seabed.damping", Opt::BottomDamping),
            b.damping,
        ),
        (
            n.option("water.seabed.friction_axial", Opt::FrictionCoefficient),
            b.friction_axial.max(b.friction_transverse),
        ),
        ("water.seabed.slip_velocity".into(), b.slip_velocity),
        ("water.seabed.slope".into(), largest(&b.slope)),
        ("water.wave_ramp".into(), w.wave_ramp),
    ]);
    for (k, wave) in w.waves.iter().enumerate() {
        values.push((format!("water.waves[{k}].amplitude"), wave.amplitude));
        values.push((format!("water.waves[{k}].period"), wave.period));
    }
    if let Some(j) = &w.jonswap {
        values.push(("water.jonswap.hs".into(), j.hs));
        values.push(("water.jonswap.tp".into(), j.tp));
    }
    if let Some(c) = &w.current {
        let fastest = c.fastest();
        let deepest = match &c.field {
            crate::scenario::CurrentField::Profile(rows) => {
                rows.iter().map(|r| r.z.abs()).fold(0.0, f64::max)
            }
            crate::scenario::CurrentField::Grid(g) => {
                g.axes()[2].iter().map(|z| z.abs()).fold(0.0, f64::max)
            }
        };
        values.push(("water.current".into(), fastest.max(deepest)));
    }
    if let Some(bed) = &b.bathymetry {
        let [xs, ys] = bed.grid.axes();
        let farthest = largest(xs)
            .max(largest(ys))
            .max(largest(bed.grid.heights()));
        values.push((n.option("water.seabed.file", Opt::SeafloorFile), farthest));
    }
    keys
}

/// The water's divisors and its waves' lengths (deep water, g T^2 / 2 pi).
fn water_figures(
    f: &Figures,
    sc: &SystemScenario,
    w: &WaterKeys,
    g_key: &str,
) -> Result<(), Failure> {
    let water = sc
        .water
        .as_ref()
        .expect("the water's keys are of its water");
    let n = &sc.names;
    f.need(
        "the water depth",
        water.depth,
        " m",
        std::slice::from_ref(&w.depth),
        Rule::Divisor,
    )?;
    // Nothing divides by the density: 0 leaves the water's loads out.
    f.need(
        "the water density",
        water.density,
        " kg/m^3",
        std::slice::from_ref(&w.density),
        Rule::Scale,
    )?;
    f.need(
        "the seabed stiffness",
        water.seabed.stiffness,
        " Pa/m",
        &[n.option("water.seabed.stiffness", Opt::BottomStiffness)],
        Rule::Divisor,
    )?;
    let slip = water.seabed.slip_velocity;
    if slip < MIN_SLIP_VELOCITY {
        return Err(Failure::Input(format!(
            "{}: water.seabed.slip_velocity: {slip:e} m/s is below {MIN_SLIP_VELOCITY:e} m/s: \
             friction regularized below a slip that slow has a derivative that overflows the \
             solver, and no step resolves such a slip; give at least {MIN_SLIP_VELOCITY:e} m/s \
             (MoorDyn's FricDamp of 200 s/m is 5e-3 m/s)",
            f.file
        )));
    }
    if let Some(j) = &water.jonswap {
        // The spectrum's density goes with Hs^2.
        f.need(
            "Hs^2, which the JONSWAP spectrum goes with",
            j.hs * j.hs,
            " m^2",
            &["water.jonswap.hs".into()],
            Rule::Scale,
        )?;
    }
    let g = magnitude(&sc.gravity);
    let periods = water
        .waves
        .iter()
        .enumerate()
        .map(|(k, wave)| (format!("water.waves[{k}].period"), wave.period))
        .chain(
            water
                .jonswap
                .map(|j| ("water.jonswap.tp".to_string(), j.tp)),
        );
    for (key, period) in periods {
        f.need(
            "the wave period",
            period,
            " s",
            std::slice::from_ref(&key),
            Rule::Divisor,
        )?;
        let length = g * period * period / (2.0 * std::f64::consts::PI);
        f.need(
            "the deep-water wave length g T^2 / 2 pi",
            length,
            " m",
            &[key, g_key.to_string()],
            Rule::Scale,
        )?;
    }
    Ok(())
}

/// Line type i's area, modulus and density.
fn line_type_figures(f: &Figures, sc: &SystemScenario, i: usize) -> Result<(), Failure> {
    let t = &sc.line_types[i];
    let key = |k: &str, c: &str| sc.names.line_type(i, k, c);
    let (d, m, ea) = (
        key("diameter", "Diam"),
        key("mass_per_length", "Mass/m"),
        key("ea", "EA"),
    );
    let area = t.area();
    f.need(
        "the area pi d^2 / 4",
        area,
        " m^2",
        std::slice::from_ref(&d),
        Rule::Divisor,
    )?;
    f.need(
        "the modulus EA / A",
        t.ea / area,
        " Pa",
        &[ea, d.clone()],
        Rule::Divisor,
    )?;
    f.need(
        "the density m / A",
        t.mass_per_length / area,
        " kg/m^3",
        &[m, d],
        Rule::Divisor,
    )
}

/// Line j's element length, stiffness, weight, buoyancy, bending
/// stiffness, damping and highest frequency.
fn line_figures(
    f: &Figures,
    sc: &SystemScenario,
    j: usize,
    g_key: &str,
    water: Option<&WaterKeys>,
) -> Result<(), Failure> {
    let l = &sc.lines[j];
    let t = &sc.line_types[l.line_type];
    let n = &sc.names;
    let (length, elements) = (
        n.line(j, "length", "UnstrLen"),
        n.line(j, "elements", "NumSegs"),
    );
    let ty = |k: &str, c: &str| n.line_type(l.line_type, k, c);
    let (d, m, ea) = (
        ty("diameter", "Diam"),
        ty("mass_per_length", "Mass/m"),
        ty("ea", "EA"),
    );
    f.need(
        "the line length",
        l.length,
        " m",
        std::slice::from_ref(&length),
        Rule::Divisor,
    )?;
    let element = l.length / l.elements as f64;
    f.need(
        "the element length",
        element,
        " m",
        &[length.clone(), elements.clone()],
        Rule::Divisor,
    )?;
    f.need(
        "the element stiffness EA / l",
        t.ea / element,
        " N/m",
        &[ea.clone(), length.clone(), elements.clone()],
        Rule::Scale,
    )?;
    let g = magnitude(&sc.gravity);
    f.need(
        "the line's weight m L g",
        t.mass_per_length * l.length * g,
        " N",
        &[m.clone(), length.clone(), g_key.to_string()],
        Rule::Scale,
    )?;
    if let (Some(w), Some(water)) = (water, sc.water.as_ref()) {
        f.need(
            "the line's buoyancy rho_w g A L",
            water.density * g * t.area() * l.length,
            " N",
            &[
                w.density.clone(),
                d.clone(),
                length.clone(),
                g_key.to_string(),
            ],
            Rule::Scale,
        )?;
    }
    let ei = sc.bending_stiffness(j);
    f.need(
        "the bending stiffness the line is simulated with",
        ei,
        " N m^2",
        &[ty("ei", "EI"), m.clone(), length.clone(), g_key.to_string()],
        Rule::Divisor,
    )?;
    f.need(
        "the axial damping BA",
        sc.axial_damping(j),
        " N s",
        &[
            ty("ba", "BA/-zeta"),
            ea.clone(),
            m.clone(),
            elements.clone(),
        ],
        Rule::Scale,
    )?;
    // The fastest axial mode of an element, 2 c / l with c = sqrt(EA/m).
    let frequency = 2.0 * (t.ea / t.mass_per_length).sqrt() / element;
    f.need(
        "the highest axial frequency 2 sqrt(EA/m) / l",
        frequency,
        " rad/s",
        &[ea, m.clone(), length.clone(), elements.clone()],
        Rule::Below(MAX_FREQUENCY),
    )?;
    // The fastest bending mode of an element, of the order of
    // (2 / l)^2 sqrt(EI/m) (the bending counterpart of the axial
    // estimate; an order-one factor is immaterial against 1e70).
    let bending = 4.0 * (ei / t.mass_per_length).sqrt() / (element * element);
    f.need(
        "the highest bending frequency 4 sqrt(EI/m) / l^2",
        bending,
        " rad/s",
        &[ty("ei", "EI"), m, length, elements],
        Rule::Below(MAX_FREQUENCY),
    )
}

/// Every point's and every body's weight and buoyancy
/// ([`weight_figures`]).
fn weights_of_points_and_bodies(
    f: &Figures,
    sc: &SystemScenario,
    g_key: &str,
    water: Option<&WaterKeys>,
) -> Result<(), Failure> {
    for (p, pt) in sc.points.iter().enumerate() {
        let key = |k: &str, c: &str| sc.names.point(p, k, c);
        weight_figures(f, sc, ("point", pt.mass, pt.volume), key, g_key, water)?;
    }
    for (b, body) in sc.bodies.iter().enumerate() {
        let key = |k: &str, c: &str| sc.names.body(b, k, c);
        weight_figures(f, sc, ("body", body.mass, body.volume), key, g_key, water)?;
    }
    for r in &sc.rods {
        let Some(rod) = &r.rod else { continue };
        // Its weight is its type's Mass/m's, its volume its Diam's.
        let key = |k: &str, _: &str| match k {
            "mass" => sc.names.rod_type(r.type_index, "mass_per_length", "Mass/m"),
            _ => sc.names.rod_type(r.type_index, "diameter", "Diam"),
        };
        let (mass, volume) = (rod.mass_per_length * rod.length(), rod.volume());
        weight_figures(f, sc, ("rod", mass, volume), key, g_key, water)?;
    }
    Ok(())
}

/// Each rod's values (its ends, its type's numbers), named by their keys
/// or deck columns.
fn rod_values(sc: &SystemScenario, values: &mut Vec<(String, f64)>) {
    let n = &sc.names;
    for (k, r) in sc.rods.iter().enumerate() {
        let Some(rod) = &r.rod else { continue };
        let key = |k_: &str, c: &str| n.rod_type(r.type_index, k_, c);
        values.extend([
            (n.rod_key(k, "end_a", "Xa, Ya, Za"), largest(&r.ends[0])),
            (n.rod_key(k, "end_b", "Xb, Yb, Zb"), largest(&r.ends[1])),
            (key("diameter", "Diam"), rod.diameter),
            (key("mass_per_length", "Mass/m"), rod.mass_per_length),
            (key("cd", "Cd"), rod.drag_coefficient),
            (key("ca", "Ca"), rod.added_mass_coefficient),
            (key("cd_end", "CdEnd"), rod.end_drag_coefficient),
            (key("ca_end", "CaEnd"), rod.end_added_mass_coefficient),
        ]);
    }
}

/// The weight m g and, in water, the buoyancy rho_w g V of a point or a
/// body (`what`), their keys named by `key(key, deck column)`.
fn weight_figures(
    f: &Figures,
    sc: &SystemScenario,
    (what, mass, volume): (&str, f64, f64),
    key: impl Fn(&str, &str) -> String,
    g_key: &str,
    water: Option<&WaterKeys>,
) -> Result<(), Failure> {
    let g = magnitude(&sc.gravity);
    f.need(
        &format!("the {what}'s weight m g"),
        mass * g,
        " N",
        &[key("mass", "Mass"), g_key.to_string()],
        Rule::Scale,
    )?;
    if let (Some(w), Some(water)) = (water, sc.water.as_ref()) {
        f.need(
            &format!("the {what}'s buoyancy rho_w g V"),
            water.density * g * volume,
            " N",
            &[
                key("volume", "Volume"),
                w.density.clone(),
                g_key.to_string(),
            ],
            Rule::Scale,
        )?;
    }
    Ok(())
}
