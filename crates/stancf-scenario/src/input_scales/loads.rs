//! The figures of the loads: what the loads give, key by key, and the
//! scales they set: the weight and the fall under gravity, a point force
//! and the push it gives the cable over the run, an end moment, the air
//! drag (eq. 17) and the potential of the loads at t = 0 (eqs. 13 and 14).

use super::rules::{key, keys, largest, norm, with, Figures, Rule};
use super::{Placement, Section, Speed};
use crate::scenario::{AnalysisKind, Scenario};
use crate::Failure;
use stancf::loads::AirDrag;
use stancf::{Energies, Load};

/// The gravity of all the gravity loads together.
pub(super) struct Gravity {
    /// The summed acceleration g (m/s^2).
    acceleration: [f64; 3],
    /// The keys it comes from (none without gravity).
    keys: Vec<String>,
}

/// The loads' values added to `values`, and their total gravity.
pub(super) fn load_values(sc: &Scenario, values: &mut Vec<(String, f64)>) -> Gravity {
    let mut gravity = Gravity {
        acceleration: [0.0; 3],
        keys: Vec::new(),
    };
    for (i, load) in sc.loads.iter().enumerate() {
        match load {
            Load::Gravity { acceleration } => {
                let k = format!("loads[{i}].acceleration");
                values.push((k.clone(), largest(acceleration)));
                gravity.keys.push(k);
                for c in 0..3 {
                    gravity.acceleration[c] += acceleration[c];
                }
            }
            Load::PointForce { force: v, .. } => {
                values.push((format!("loads[{i}].force"), largest(v)));
            }
            Load::EndMoment { moment: v, .. } => {
                values.push((format!("loads[{i}].moment"), largest(v)));
            }
            Load::AirDrag(d) => {
                let k = format!("loads[{i}]");
                values.push((format!("{k}.drag_coefficient"), d.drag_coefficient));
                values.push((format!("{k}.fluid_density"), d.fluid_density));
                values.push((format!("{k}.diameter"), d.diameter));
                values.push((format!("{k}.fluid_velocity"), largest(&d.fluid_velocity)));
            }
            Load::Seabed(c) => {
                let k = format!("loads[{i}]");
                values.push((format!("{k}.stiffness"), c.seabed.stiffness));
                values.push((format!("{k}.damping"), c.seabed.damping));
                values.push((format!("{k}.diameter"), c.diameter));
            }
            Load::Water(w) => {
                let k = format!("loads[{i}]");
                let m = &w.morison;
                values.push((format!("{k}.density"), w.water.density));
                values.push((format!("{k}.diameter"), m.diameter));
                values.push((format!("{k}.cd_normal"), m.cd_normal));
                values.push((format!("{k}.cd_axial"), m.cd_axial));
                values.push((format!("{k}.ca_normal"), m.ca_normal));
                values.push((format!("{k}.ca_axial"), m.ca_axial));
            }
        }
    }
    gravity
}

/// The scales of the loads, in this order: gravity (when there is any),
/// each point force, end moment and air drag in the order given, and the
/// potential of the point forces and end moments at t = 0. `en`: the
/// energies at t = 0.
pub(super) fn loads(
    f: &Figures,
    sc: &Scenario,
    gravity: &Gravity,
    s: &Section,
    place: &Placement,
    speed: &Speed,
    en: &Energies,
) -> Result<(), Failure> {
    // The loads act over the whole run (a static run has no duration).
    let t = if sc.analysis.kind == AnalysisKind::Dynamic {
        sc.analysis.duration
    } else {
        0.0
    };
    if !gravity.keys.is_empty() {
        weight(f, gravity, s, place, en.gravity, t)?;
    }
    for (i, load) in sc.loads.iter().enumerate() {
        match load {
            Load::PointForce { force, .. } => point_force(f, i, force, s, place, t)?,
            Load::EndMoment { moment, .. } => end_moment(f, i, moment, s)?,
            Load::AirDrag(d) => drag(f, i, d, s, speed)?,
            Load::Gravity { .. } | Load::Seabed(_) | Load::Water(_) => {}
        }
    }
    load_potential(f, sc, place, en.load_potential)
}

/// Gravity: the weight rho A L |g|, the gravitational potential at t = 0
/// (eq. 13), the fall over the duration g T^2 / 2 of a cable falling
/// freely for the whole run, and the gravitational energy scale
/// rho A L |g| (extent + g T^2 / 2).
fn weight(
    f: &Figures,
    gravity: &Gravity,
    s: &Section,
    place: &Placement,
    potential: f64,
    t: f64,
) -> Result<(), Failure> {
    let g = norm(&gravity.acceleration);
    let gk = with(
        with(keys(&[key::DENSITY, key::AREA, key::LENGTH]), &gravity.keys),
        &place.keys,
    );
    f.need(
        "the weight rho A length |g|",
        s.mass * g,
        " N",
        &gk,
        Rule::Scale,
    )?;
    f.need(
        "the gravitational potential at t = 0",
        potential,
        " J",
        &gk,
        Rule::Scale,
    )?;
    let fall = with(gk, &keys(&[key::DURATION]));
    f.need(
        "the fall under gravity over the duration g T^2 / 2",
        0.5 * g * t * t,
        " m",
        &fall,
        Rule::Scale,
    )?;
    f.need(
        "the gravitational energy scale rho A length |g| (extent + g T^2 / 2)",
        s.mass * g * (place.extent + 0.5 * g * t * t),
        " J",
        &fall,
        Rule::Scale,
    )
}

/// The point force `loads[i]`: its magnitude |F|, the travel
/// |F| T^2 / (2 m) of the free cable it pushes for the whole run, and its
/// work scale |F| (extent + |F| T^2 / (2 m)).
fn point_force(
    f: &Figures,
    i: usize,
    force: &[f64; 3],
    s: &Section,
    place: &Placement,
    t: f64,
) -> Result<(), Failure> {
    let fk = with(vec![format!("loads[{i}].force")], &place.keys);
    let fnorm = norm(force);
    f.need("the point force |F|", fnorm, " N", &fk, Rule::Scale)?;
    let push = with(
        with(fk, &keys(&[key::DENSITY, key::AREA, key::LENGTH])),
        &keys(&[key::DURATION]),
    );
    let travel = 0.5 * fnorm / s.mass * t * t;
    f.need(
        "the travel of the cable pushed by the force |F| T^2 / (2 m)",
        travel,
        " m",
        &push,
        Rule::Scale,
    )?;
    f.need(
        "the work scale of the point force |F| (extent + |F| T^2 / (2 m))",
        fnorm * (place.extent + travel),
        " J",
        &push,
        Rule::Scale,
    )
}

/// The end moment `loads[i]`: its magnitude |M| and the force |M| / l it
/// puts on an element.
fn end_moment(f: &Figures, i: usize, moment: &[f64; 3], s: &Section) -> Result<(), Failure> {
    let mk = with(
        vec![format!("loads[{i}].moment")],
        &keys(&[key::LENGTH, key::ELEMENTS]),
    );
    f.need("the end moment |M|", norm(moment), " N m", &mk, Rule::Scale)?;
    f.need(
        "the end moment's force on an element |M| / l",
        norm(moment) / s.l,
        " N",
        &mk,
        Rule::Scale,
    )
}

/// The air drag `loads[i]` (eq. 17): its factor C rho_fluid d / 2, the
/// largest relative speed of the fluid |u| + v_max and the drag force
/// scale C rho_fluid d L v^2 / 2.
fn drag(f: &Figures, i: usize, d: &AirDrag, s: &Section, speed: &Speed) -> Result<(), Failure> {
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
    let relative = norm(&d.fluid_velocity) + speed.largest;
    let vk = with(with(dk, &[format!("{k}.fluid_velocity")]), &speed.given);
    f.need(
        "the largest relative speed of the fluid",
        relative,
        " m/s",
        &vk,
        Rule::Scale,
    )?;
    f.need(
        "the drag force scale C rho_fluid d length v^2 / 2",
        coefficient * s.length * relative * relative,
        " N",
        &with(vk, &keys(&[key::LENGTH])),
        Rule::Scale,
    )
}

/// The potential of the point forces and end moments at t = 0 (eq. 14).
fn load_potential(
    f: &Figures,
    sc: &Scenario,
    place: &Placement,
    potential: f64,
) -> Result<(), Failure> {
    let load_keys: Vec<String> = sc
        .loads
        .iter()
        .enumerate()
        .filter_map(|(i, l)| match l {
            Load::PointForce { .. } => Some(format!("loads[{i}].force")),
            Load::EndMoment { .. } => Some(format!("loads[{i}].moment")),
            Load::Gravity { .. } | Load::AirDrag(_) | Load::Seabed(_) | Load::Water(_) => None,
        })
        .collect();
    f.need(
        "the load potential at t = 0",
        potential,
        " J",
        &with(load_keys, &place.keys),
        Rule::Scale,
    )
}
