//! A system of lines joined at points (docs/interface.md, "Systems"):
//! `[system]`, `[[line_types]]`, `[[bodies]]`, `[[points]]`, `[[lines]]`
//! and `[[motions]]`, validated into a [`SystemScenario`] that builds the
//! library's [`stancf::system::System`].

use super::analysis::{analysis_part, AnalysisKind, InitialShape};
use super::bodies::{optional_non_negative, SystemBody};
use super::context::Ctx;
use super::motions::motions;
use super::raw::{RawLine, RawLineType, RawPoint, RawScenario};
use super::system_parts::{LineType, PointType, SystemLine, SystemPoint, SystemScenario};
use super::water::scenario_water;
use super::{Analysis, ScenarioError};
use stancf::motion::CoupledMotion;
use stancf::ElementType;
use std::path::Path;

/// Refuses a single cable's sections in a system's file, naming the first.
fn refuse_cable_keys(ctx: &Ctx, raw: &RawScenario) -> Result<(), ScenarioError> {
    for (present, key) in [
        (raw.cable.is_some(), "cable"),
        (raw.material.is_some(), "material"),
        (!raw.constraints.is_empty(), "constraints"),
        (!raw.loads.is_empty(), "loads"),
        (!raw.initial_velocity.is_empty(), "initial_velocity"),
    ] {
        if present {
            return Err(ctx.err(
                key,
                "belongs to a single-cable scenario; this file describes a system \
                 ([system], [[line_types]], [[points]], [[lines]]): give the sections \
                 of a line through its line type and its points",
            ));
        }
    }
    Ok(())
}

/// The system parts of a scenario file, in the file's order.
pub(super) fn system_scenario(
    ctx: &Ctx,
    mut raw: RawScenario,
    title: String,
    path: &Path,
    host: &super::HostEnvironment,
) -> Result<SystemScenario, ScenarioError> {
    refuse_cable_keys(ctx, &raw)?;
    let rs = raw.system.take().unwrap_or_default();
    if let Some(deck) = rs.moordyn.as_deref() {
        let deck_path = path.parent().unwrap_or(Path::new("")).join(deck);
        return super::deck_system::deck_system(ctx, raw, (rs, &deck_path), (title, path), host);
    }
    super::deck_system::refuse_deck_keys(ctx, &raw)?;
    if rs.mbl.is_some() {
        return Err(ctx.err(
            "system.mbl",
            "names the breaking loads of a MoorDyn deck's line types (with system.moordyn); \
             give a [[line_types]] entry's own mbl",
        ));
    }
    let gravity = ctx.vector_or("system.gravity", rs.gravity.as_deref(), [0.0, 0.0, -9.81])?;
    let dir = path.parent().unwrap_or(Path::new(""));
    let water = scenario_water(ctx, raw.water, gravity, dir)?;
    let line_types = line_types(ctx, &raw.line_types)?;
    let mut bodies = super::bodies::bodies(ctx, &raw.bodies)?;
    let rod_types = super::rod_toml::rod_types(ctx, &raw.rod_types)?;
    let mut rods = super::rod_toml::rods(ctx, (&rod_types, &raw.rods), &mut bodies)?;
    let mut points = points(ctx, &raw.points, &bodies, &mut rods)?;
    let lines = lines(ctx, &raw.lines, &line_types, (&points, &bodies))?;
    super::rod_toml::pin_points(&mut rods, &mut points);
    let free_bodies = bodies.iter().any(SystemBody::is_free);
    let clamps = lines.iter().any(SystemLine::clamped);
    let (analysis, measures, initial, mut notes) = analysis_part(
        ctx,
        raw.analysis,
        (InitialShape::Reference, free_bodies, clamps),
    )?;
    check_clamp_route(ctx, &lines, &analysis)?;
    let lengths: Vec<f64> = lines.iter().map(|l| l.length).collect();
    motions(ctx, &raw.motions, &mut points, &lengths, path, &analysis)?;
    notes.extend(super::rod_toml::rod_types_in_air(
        &rod_types,
        water.is_some(),
    ));
    for (i, t) in line_types.iter().enumerate() {
        if water.is_none()
            && [t.cd_normal, t.ca_normal, t.cd_axial, t.ca_axial]
                .iter()
                .any(|&c| c != 0.0)
        {
            notes.push(format!(
                "line_types[{i}]: cd, ca, cdax and caax act in water, which this scenario \
                 does not have ([water]): unused"
            ));
        }
    }
    let output_every = super::output::output_every(ctx, raw.output.as_ref())?;
    let output_files = super::output::output_files(ctx, raw.output.as_ref())?;
    super::output::channels_to_write(ctx, &output_files, false, 0)?;
    super::output::bodies_to_write(ctx, &output_files, bodies.len())?;
    let statics = analysis.kind == AnalysisKind::Static || initial == InitialShape::Static;
    super::output::stiffness_to_write(ctx, &output_files, free_bodies, statics)?;
    let end_forces = super::output::output_end_forces(
        ctx,
        raw.output.as_ref(),
        analysis.force_tolerance.is_some()
            || raw.output.as_ref().is_some_and(|o| o.interval.is_some()),
    )?;
    let statistics_after = super::output::statistics_after(ctx, raw.output.as_ref())?;
    let names = super::names::Names::default().with_rods(&rods, usize::MAX);
    let failures = super::failures::failures(ctx, &raw.failures, &points, &lines)?;
    let static_only = host_waves_static_only(ctx.file, water.as_ref());
    let dynamic = analysis.kind == AnalysisKind::Dynamic;
    if let Some(why) = static_only.as_ref().filter(|_| dynamic && !host.sets_waves) {
        return Err(ScenarioError(why.clone()));
    }
    let mut sc = SystemScenario {
        failures,
        title,
        line_types,
        bodies,
        rods,
        points,
        lines,
        gravity,
        analysis,
        measures,
        initial,
        output_every,
        output_interval: None,
        output_files,
        end_forces,
        statistics_after,
        notes,
        water,
        channels: Vec::new(),
        static_only,
        moordyn_out: None,
        names,
        start_without_equilibrium: false,
        moordyn_relaxation: None,
    };
    sc.notes.extend(super::sea_limits::static_waves_note(&sc));
    sc.notes
        .extend(super::overstretch::overstretched_notes(&sc));
    sc.notes.extend(super::sea_limits::breaking_wave_notes(&sc));
    sc.notes.extend(super::viv_types::viv_notes(&sc));
    super::body_water::refuse_water_in_air(ctx.file, &sc)?;
    super::viv_types::refuse_viv_in_air(ctx.file, &sc)?;
    sc.output_interval = super::output_interval::output_interval(ctx, raw.output.as_ref(), &sc)?;
    Ok(sc)
}

/// Why a scenario whose waves a host sets (`water.host_waves`) runs its
/// static equilibrium only from the command line: a run there has no
/// host; the coupling API steps it (docs/method.md §12.1, (W2f)-(W2g)).
fn host_waves_static_only(file: &str, water: Option<&super::Water>) -> Option<String> {
    water.filter(|w| w.host_waves).map(|_| {
        format!(
            "{file}: water.host_waves: a host sets the water's kinematics at the nodes through \
             the coupling API (stancf_wave_kin_set in C, Simulation.set_wave_kinematics in \
             Python), and a run from the command line has no host, so it runs its static \
             equilibrium only; give the waves as [[water.waves]] or [water.jonswap] instead"
        )
    })
}

/// `[[line_types]]` (none for a system of bodies and rods alone): `name`
/// (required, unique), `diameter` (> 0),
/// `mass_per_length` (> 0), `ea` (> 0), each required; `ei` (>= 0,
/// default 0), `ba` (default 0; < 0: minus a damping ratio), `cd`, `ca`,
/// `cdax`, `caax` (>= 0, default 0).
fn line_types(ctx: &Ctx, raw: &[RawLineType]) -> Result<Vec<LineType>, ScenarioError> {
    let mut out: Vec<LineType> = Vec::with_capacity(raw.len());
    for (i, r) in raw.iter().enumerate() {
        let key = |k: &str| format!("line_types[{i}].{k}");
        let name = ctx.required(&key("name"), r.name.clone())?;
        if out.iter().any(|t| t.name == name) {
            return Err(ctx.err(&key("name"), format!("\"{name}\" is defined twice")));
        }
        let optional = |k: &str, v: Option<f64>| match v {
            Some(v) => ctx.non_negative(&key(k), v),
            None => Ok(0.0),
        };
        let ea_curve = super::ea_curves::toml_curve(ctx, &key("ea_curve"), r)?;
        let (ea_dynamic, ba_dynamic) = super::visco_types::toml_dynamic(ctx, i, r)?;
        out.push(LineType {
            diameter: ctx.required_positive(&key("diameter"), r.diameter)?,
            mass_per_length: ctx.required_positive(&key("mass_per_length"), r.mass_per_length)?,
            ea: match (
                &ea_curve,
                ea_dynamic.as_ref().and_then(super::syrope_files::syrope_ea),
            ) {
                (Some(c), _) => c.secant_stiffness(),
                (None, Some(syrope)) => syrope,
                (None, None) => ctx.required_positive(&key("ea"), r.ea)?,
            },
            ea_curve,
            ea_dynamic,
            ba_dynamic,
            ei: optional("ei", r.ei)?,
            ba: match r.ba {
                Some(v) => ctx.finite(&key("ba"), v)?,
                None => 0.0,
            },
            cd_normal: optional("cd", r.cd)?,
            ca_normal: optional("ca", r.ca)?,
            cd_axial: optional("cdax", r.cdax)?,
            ca_axial: optional("caax", r.caax)?,
            compression: r.compression.unwrap_or(true),
            viv: super::viv_types::toml_viv(ctx, &key("viv"), r.viv.as_ref())?,
            mbl: r.mbl.map(|v| ctx.positive(&key("mbl"), v)).transpose()?,
            name,
        });
        let t = out.last().expect("pushed");
        super::visco_types::check_law(t).map_err(|(k, m)| ctx.err(&key(k), m))?;
    }
    Ok(out)
}

/// `[[points]]`: `id` (required, unique), `type` ("fixed", "free",
/// "coupled", "body" or "rod", required), `position` (required but for a
/// rod's point; on a body, in the body's axes from its reference point);
/// a free point's `mass` (>= 0, default 0) and `force` (default 0); a
/// body point's `body` (a body's id, required); a rod point's `rod` (a
/// rod's id) and `end` ("A" or "B"), required (the point is recorded
/// at that end of `rods`).
fn points(
    ctx: &Ctx,
    raw: &[RawPoint],
    bodies: &[SystemBody],
    rods: &mut [super::rod_parts::SystemRod],
) -> Result<Vec<SystemPoint>, ScenarioError> {
    let mut out: Vec<SystemPoint> = Vec::with_capacity(raw.len());
    for (i, r) in raw.iter().enumerate() {
        let key = |k: &str| format!("points[{i}].{k}");
        let id = ctx.required(&key("id"), r.id)?;
        if out.iter().any(|p| p.id == id) {
            return Err(ctx.err(&key("id"), format!("point {id} is defined twice")));
        }
        let word = ctx.choice(
            &key("type"),
            Some(ctx.required(&key("type"), r.kind.as_deref())?),
            "",
            &["fixed", "free", "coupled", "body", "rod"],
        )?;
        super::rod_toml::refuse_rod_keys(ctx, i, r, word)?;
        let position = match word {
            "rod" => [0.0; 3],
            _ => ctx.vector(
                &key("position"),
                &ctx.required(&key("position"), r.position.clone())?,
            )?,
        };
        let (kind, position) = match word {
            "fixed" => (PointType::Fixed, position),
            "free" => (PointType::Free, position),
            "coupled" => (PointType::Coupled, position),
            "rod" => {
                let at = super::rod_toml::rod_point(ctx, i, r, rods)?;
                rods[at.rod].points[at.end].get_or_insert(out.len());
                (at.kind, at.position)
            }
            _ => {
                let body = body_of(ctx, i, r.body, bodies)?;
                let kind = PointType::Body {
                    body,
                    local: position,
                };
                (kind, bodies[body].point(position))
            }
        };
        if word != "body" && r.body.is_some() {
            return Err(ctx.err(
                &key("body"),
                format!("names the body of a point of type \"body\"; this point is \"{word}\""),
            ));
        }
        let given = [
            ("mass", r.mass.is_some()),
            ("force", r.force.is_some()),
            ("volume", r.volume.is_some()),
            ("cda", r.cda.is_some()),
            ("ca", r.ca.is_some()),
            ("damping_linear", r.damping_linear.is_some()),
            ("damping_quadratic", r.damping_quadratic.is_some()),
        ];
        // A point on a free body may carry a mass, a force and a volume:
        // they become the body's (docs/method.md §15.8); its drag and added
        // mass are not built.
        let on_free_body = word == "body"
            && matches!(kind, PointType::Body { body, .. } if bodies[body].is_free());
        let allowed = |k: &str| {
            kind == PointType::Free
                || (on_free_body
                    && !matches!(k, "cda" | "ca" | "damping_linear" | "damping_quadratic"))
        };
        if let Some((k, _)) = given.iter().find(|g| g.1 && !allowed(g.0)) {
            let why = if word == "rod" {
                "a point at a rod's end carries no mass, force or water of its own (the rod's \
                 type gives the rod's)"
            } else if word == "body" && on_free_body {
                "the drag, added mass and damping of a point on a body are not built (give \
                 them to the body)"
            } else if word == "body" {
                "a point on a fixed or coupled body carries no mass, force or water of its own \
                 (a coupled body's are the coupling code's)"
            } else {
                "only a free point carries a mass, a force or water loads (a fixed or coupled \
                 point's position is given)"
            };
            return Err(ctx.err(&key(k), why));
        }
        let non_negative = |name: &str, v: Option<f64>| match v {
            Some(v) => ctx.non_negative(&key(name), v),
            None => Ok(0.0),
        };
        out.push(SystemPoint {
            id,
            kind,
            position,
            mass: match r.mass {
                Some(m) => ctx.non_negative(&key("mass"), m)?,
                None => 0.0,
            },
            force: ctx.vector_or(&key("force"), r.force.as_deref(), [0.0; 3])?,
            volume: non_negative("volume", r.volume)?,
            drag_area: non_negative("cda", r.cda)?,
            ca: non_negative("ca", r.ca)?,
            motion: CoupledMotion::NONE,
            motion_file: None,
            damping: stancf::damping::AxisDamping {
                linear: optional_non_negative(ctx, &key("damping_linear"), &r.damping_linear)?,
                quadratic: optional_non_negative(
                    ctx,
                    &key("damping_quadratic"),
                    &r.damping_quadratic,
                )?,
            },
        });
    }
    Ok(out)
}

/// The body (its index) a point of type "body" is on: `body`, a body's
/// id, required.
fn body_of(
    ctx: &Ctx,
    i: usize,
    id: Option<i64>,
    bodies: &[SystemBody],
) -> Result<usize, ScenarioError> {
    let key = format!("points[{i}].body");
    let id = ctx.required(&key, id)?;
    bodies.iter().position(|b| b.id == id).ok_or_else(|| {
        let known: Vec<String> = bodies.iter().map(|b| b.id.to_string()).collect();
        let known = if known.is_empty() {
            "there are no [[bodies]]".to_string()
        } else {
            format!("known: {}", known.join(", "))
        };
        ctx.err(&key, format!("body {id} is not defined ({known})"))
    })
}

/// `[[lines]]` `clamp_a` / `clamp_b` of line i: a direction (a vector,
/// not zero) for an end attached to a fixed or coupled point.
fn clamp(
    ctx: &Ctx,
    i: usize,
    name: &str,
    raw: Option<&[f64]>,
    end: Option<usize>,
    (points, bodies): (&[SystemPoint], &[SystemBody]),
) -> Result<Option<[f64; 3]>, ScenarioError> {
    let Some(raw) = raw else { return Ok(None) };
    let key = format!("lines[{i}].{name}");
    let d = ctx.vector(&key, raw)?;
    if d == [0.0; 3] {
        return Err(ctx.err(&key, "the clamp's direction must not be the zero vector"));
    }
    let end_name = &name[name.len() - 1..].to_uppercase();
    match end.map(|p| &points[p]) {
        None => Err(ctx.err(
            &key,
            format!("end {end_name} is loose: a clamp needs a fixed or coupled point"),
        )),
        Some(p) if p.kind == PointType::Free => Err(ctx.err(
            &key,
            format!(
                "end {end_name} is at free point {}, which has no rotation to clamp to: \
                 a clamp needs a fixed or coupled point",
                p.id
            ),
        )),
        Some(SystemPoint {
            kind: PointType::Body { body, .. },
            id,
            ..
        }) if bodies[*body].kind == super::BodyType::Coupled => Err(ctx.err(
            &key,
            format!(
                "end {end_name} is at point {id} on coupled body {}: a clamp that turns with \
                 a body the host moves is not built yet (a clamp needs a fixed or coupled \
                 point, or a point on a fixed or free body)",
                bodies[*body].id
            ),
        )),
        Some(_) => Ok(Some(d)),
    }
}

/// A clamp in a direction is enforced by multipliers (docs/method.md
/// §6.10, in both steps and statics): the elimination route is refused
/// naming the clamp.
fn check_clamp_route(
    ctx: &Ctx,
    lines: &[SystemLine],
    analysis: &Analysis,
) -> Result<(), ScenarioError> {
    let Some((i, name)) = lines.iter().enumerate().find_map(|(i, l)| {
        let k = l.clamps.iter().position(Option::is_some)?;
        Some((i, ["clamp_a", "clamp_b"][k]))
    }) else {
        return Ok(());
    };
    let key = format!("lines[{i}].{name}");
    if analysis.constraint_method == stancf::ConstraintMethod::Elimination {
        return Err(ctx.err(
            &key,
            "a clamp in a direction holds a combination of coordinates, which only the \
             multiplier route enforces: remove analysis.constraint_method = \"elimination\"",
        ));
    }
    Ok(())
}

/// `[[lines]]`: `id` (required, unique), `type` (a line type's name,
/// required), `length` (> 0, required), `elements` (1..=1000000,
/// required unless the grading has sections), `element` ("SAC-2", the
/// default, or "SAC-3"), `a` and `b` (point ids; a missing one leaves that
/// end loose, not both), `grading` (`{ toward, ratio }` or `{ sections }`,
/// default uniform; see [`super::cable::mesh`]).
fn lines(
    ctx: &Ctx,
    raw: &[RawLine],
    types: &[LineType],
    (points, bodies): (&[SystemPoint], &[SystemBody]),
) -> Result<Vec<SystemLine>, ScenarioError> {
    if raw.is_empty() && bodies.is_empty() {
        return Err(ctx.err(
            "lines",
            "a system needs at least one line, body or rod (a free rod is a body of its own)",
        ));
    }
    let mut out: Vec<SystemLine> = Vec::with_capacity(raw.len());
    for (i, r) in raw.iter().enumerate() {
        let key = |k: &str| format!("lines[{i}].{k}");
        let id = ctx.required(&key("id"), r.id)?;
        if out.iter().any(|l| l.id == id) {
            return Err(ctx.err(&key("id"), format!("line {id} is defined twice")));
        }
        let type_name = ctx.required(&key("type"), r.line_type.as_deref())?;
        let Some(line_type) = types.iter().position(|t| t.name == type_name) else {
            let known: Vec<&str> = types.iter().map(|t| t.name.as_str()).collect();
            return Err(ctx.err(
                &key("type"),
                format!(
                    "line type \"{}\" is not defined (known: {})",
                    super::clip(type_name, 60),
                    known.join(", ")
                ),
            ));
        };
        let length = ctx.required_positive(&key("length"), r.length)?;
        let (elements, grading) = super::cable::mesh(
            ctx,
            &format!("lines[{i}]"),
            length,
            r.elements,
            r.grading.as_ref(),
        )?;
        let element_type = match ctx.choice(
            &key("element"),
            r.element.as_deref(),
            "SAC-2",
            &["SAC-2", "SAC-3"],
        )? {
            "SAC-3" => ElementType::Sac3,
            _ => ElementType::Sac2,
        };
        let end = |k: &str, v: Option<i64>| -> Result<Option<usize>, ScenarioError> {
            let Some(id) = v else { return Ok(None) };
            match points.iter().position(|p| p.id == id) {
                Some(p) => Ok(Some(p)),
                None => Err(ctx.err(&key(k), format!("point {id} is not defined"))),
            }
        };
        let ends = [end("a", r.a)?, end("b", r.b)?];
        if ends == [None, None] {
            return Err(ctx.err(
                &key("a"),
                "a line needs at least one end attached to a point (a and b are both missing)",
            ));
        }
        if ends[0].is_some() && ends[0] == ends[1] {
            return Err(ctx.err(&key("b"), "both ends are attached to the same point"));
        }
        if types[line_type].ba < 0.0 && !grading.is_uniform() {
            return Err(ctx.err(
                &key("grading"),
                format!(
                    "line type \"{}\" gives its axial damping as a damping ratio (ba = {}), \
                     which is defined on elements of one length: give ba in N s, or leave the \
                     line's mesh uniform",
                    types[line_type].name, types[line_type].ba
                ),
            ));
        }
        let clamps = [
            clamp(
                ctx,
                i,
                "clamp_a",
                r.clamp_a.as_deref(),
                ends[0],
                (points, bodies),
            )?,
            clamp(
                ctx,
                i,
                "clamp_b",
                r.clamp_b.as_deref(),
                ends[1],
                (points, bodies),
            )?,
        ];
        out.push(SystemLine {
            id,
            line_type,
            length,
            elements,
            element_type,
            ends,
            grading,
            clamps,
            tmax0: super::visco_types::toml_tmax0(ctx, i, r, &types[line_type])?,
        });
    }
    for (p, point) in points.iter().enumerate() {
        let attached = out.iter().any(|l| l.ends.contains(&Some(p)));
        if !attached {
            return Err(ctx.err(
                &format!("points[{p}]"),
                format!("no line is attached to point {}", point.id),
            ));
        }
    }
    Ok(out)
}
