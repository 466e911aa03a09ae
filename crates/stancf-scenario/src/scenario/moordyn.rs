//! A MoorDyn v2 deck ([`crate::moordyn::Deck`]) as a system scenario:
//! LINE TYPES become line types, BODIES bodies (fixed, coupled, or free
//! with their mass, inertia and water), ROD TYPES and RODS rods (super::rods),
//! POINTS points (Fixed, Free with their mass
//! and buoyant volume, Coupled at rest, on a body), LINES lines of NumSegs
//! SAC-2 elements, OPTIONS gravity and water, OUTPUTS the channels of
//! channels.csv. MoorDyn's frame is ours: z up, the still water surface
//! at z = 0, the seabed at z = -WtrDpth.
//!
//! What stancf cannot compute from a deck is refused by name, naming the
//! deck's line: output channels stancf has no value for; in a dynamic
//! analysis, a free point's drag (CdA) and added mass (Ca), which this
//! version does not model. The lines are in the deck's water (buoyancy,
//! Morison drag and inertia with the line types' Cd, Ca, CdAx, CaAx,
//! docs/method.md §12.3-12.5) on the seabed at z = -WtrDpth (kBot, cBot,
//! FrictionCoefficient; §12.2); see [`super::moordyn_water`].

use super::analysis::{analysis_part, InitialShape};
use super::bodies::{moments_of_a_body, BodyType, SystemBody};
use super::context::Ctx;
use super::moordyn_water::{deck_water, deck_water_keys};
use super::raw::RawAnalysis;
use super::system_parts::{OutputChannel, PointType, SystemLine, SystemPoint, SystemScenario};
use super::water::WaterKeys;
use super::ScenarioError;
use crate::moordyn::{
    self, Attachment, BodyAttachment, BodyQuantity, Channel, Deck, DeckBody, DeckRod, LineQuantity,
    PointQuantity, RodAttachment, RodQuantity, SupportedOption,
};
use stancf::motion::CoupledMotion;
use stancf::ElementType;
use std::path::Path;

/// The deck in the file at `path`, as the scenario's `key` names it
/// (under `ctx`); errors name the deck and its line, or, for a file that
/// cannot be read at all, the scenario's key too.
pub(super) fn load_deck(ctx: &Ctx, key: &str, path: &Path) -> Result<Deck, ScenarioError> {
    let file = path.display().to_string();
    moordyn::load(path).map_err(|e| match e.line {
        Some(_) => ScenarioError(format!("{file}: {e}")),
        None => ctx.err(key, e.message),
    })
}

/// The scenario of a deck read from `path` (named `file` in messages): a
/// static analysis from the lines' catenaries, as a deck alone says
/// nothing of time, in the deck's water with the `[water]` keys of the
/// scenario that takes the deck (`added`, checked under that scenario's
/// context) added.
pub(super) fn deck_scenario(
    deck: &Deck,
    file: &str,
    path: &Path,
    title: String,
    added: Option<(&Ctx, WaterKeys)>,
    host: &super::HostEnvironment,
    farm: Option<super::farm::Farm>,
) -> Result<SystemScenario, ScenarioError> {
    // The line types' laws: EA curve files, Syrope's files and SYROPE IC,
    // viscoelastic forms (the deck knows their files' names only).
    let laws = super::deck_line_types::deck_line_laws(deck, file, path)?;
    let deck: &Deck = &laws.deck;
    let (curves, tmax0) = (laws.curves.clone(), laws.tmax0.clone());
    let g = deck_gravity(deck, file, host)?;
    let farm = farm.or_else(|| {
        host.turbines.clone().map(|positions| super::farm::Farm {
            positions,
            source: "the host".into(),
        })
    });
    let (farm, farm_note) = super::farm::deck_farm(deck, file, path, farm)?;
    let (waves, wave_notes) =
        super::moordyn_waves::every_deck_wave(deck, file, path, host.run_length)?;
    let (keys, current_note) = deck_water_keys(deck, file, path)?;
    let deck_keys = super::water::WaterKeys { waves, ..keys };
    let (water, depth_note) = deck_water(deck_keys, file, deck, added, host)?;
    let (channels, channel_notes) = deck_channels(deck);
    let ctx = Ctx { file };
    let raw = RawAnalysis {
        kind: Some("static".into()),
        ..RawAnalysis::default()
    };
    let mut bodies =
        deck.bodies
            .iter()
            .map(|b| {
                let rods = deck.rods.iter().any(|r| {
                    r.attachment == crate::moordyn::RodAttachment::Body(b.id) && r.segments > 0
                });
                let masses = deck.points.iter().any(|p| {
                    p.attachment == crate::moordyn::Attachment::Body(b.id) && p.mass > 0.0
                });
                deck_body(b, rods || masses, file)
            })
            .collect::<Result<Vec<_>, _>>()?;
    let turbines = farm
        .as_ref()
        .map_or(0, |f| super::farm::turbine_bodies(f, &mut bodies));
    let mut points: Vec<SystemPoint> = deck
        .points
        .iter()
        .map(|p| deck_point(p, &bodies, turbines))
        .collect();
    let external_notes = super::external_loads::deck_external_loads(deck, &mut bodies, &mut points);
    host_pins(deck, &mut bodies, &mut points);
    // Rods after the deck's bodies and points: a free rod's body and the
    // points at rod ends come after them (super::rods).
    let (rods, ends) = super::rods::deck_rods(deck, file, &mut bodies, &mut points)?;
    let free_bodies = bodies.iter().any(SystemBody::is_free);
    let clamps = ends.iter().any(super::rods::DeckLineEnds::clamped);
    let (mut analysis, measures, initial, mut notes) =
        analysis_part(&ctx, Some(raw), (InitialShape::Static, free_bodies, clamps))?;
    notes.extend(deck.bodies.iter().filter_map(free_word_note));
    notes.extend(super::rods::rod_file_notes(deck));
    // A deck alone is static; its dtM (or MoorDyn's step from its CFL) is
    // the step of a coupled run of it (checked with the other values,
    // crate::input_scales).
    analysis.time_step = deck.time_step().unwrap_or(0.0);
    notes.extend(super::moordyn_option_notes::option_notes(deck));
    notes.extend(channel_notes);
    notes.extend(host.notes(deck));
    notes.extend(depth_note);
    notes.extend(farm_note);
    notes.extend(wave_notes);
    notes.extend(current_note);
    notes.extend(line_output_notes(deck, path));
    notes.extend(external_notes);
    notes.extend(laws.notes.iter().cloned());
    let names = super::names::Names::of_deck(deck, None)
        .with_rods(&rods, deck.points.len())
        .with_host_pins(&bodies);
    let lines = deck_lines(deck, ends, &tmax0);
    let (failures, failure_notes) = super::failures::deck_failures(deck, file, &points, &lines);
    notes.extend(failure_notes);
    let mut sc = SystemScenario {
        failures,
        title,
        line_types: super::deck_line_types::deck_line_types(deck, curves),
        points,
        bodies,
        rods,
        lines,
        gravity: [0.0, 0.0, -g],
        analysis,
        measures,
        initial,
        output_every: 1,
        output_interval: None,
        output_files: super::OutputFiles::all(),
        end_forces: super::output::EndForces::StepMean,
        statistics_after: 0.0,
        notes,
        water: Some(water),
        static_only: super::moordyn_waves::static_only(deck, file),
        moordyn_out: moordyn_out_file(deck, path, &channels).map(Box::new),
        channels,
        names,
        start_without_equilibrium: true,
        moordyn_relaxation: deck.initial_conditions_time(),
    };
    sc.notes.extend(system_notes(&sc));
    Ok(sc)
}

/// The notes on the system a deck makes: breaking waves, VIV, lines
/// stretched past any material's breaking strain.
fn system_notes(sc: &SystemScenario) -> Vec<String> {
    let mut notes = super::sea_limits::breaking_wave_notes(sc);
    notes.extend(super::viv_types::viv_notes(sc));
    notes.extend(super::overstretch::overstretched_notes(sc));
    notes
}

/// The notes on `LineOutputs` flags whose quantities stancf does not
/// compute (`<deck>_Line<n>.out` has no columns for them).
fn line_output_notes(deck: &Deck, path: &Path) -> Vec<String> {
    let stem = path
        .file_stem()
        .map_or(String::new(), |s| s.to_string_lossy().into_owned());
    deck.lines
        .iter()
        .filter_map(|l| {
            let viscoelastic = deck
                .line_types
                .iter()
                .any(|t| t.name == l.line_type && t.ea_dynamic.is_some());
            let missing: Vec<String> = moordyn::uncomputed_line_flags(viscoelastic)
                .iter()
                .filter(|(f, _)| l.outputs.contains(*f))
                .map(|(f, what)| format!("{f} ({what})"))
                .collect();
            (!missing.is_empty() && l.outputs != "-").then(|| {
                format!(
                    "line {}: LineOutputs \"{}\" of line {}: {} not computed by stancf; \
                     {stem}_Line{}.out has no columns for them",
                    l.line,
                    l.outputs,
                    l.id,
                    missing.join(", "),
                    l.id
                )
            })
        })
        .collect()
}

/// MoorDyn's output files of a deck at `path` (None: it asks for none,
/// or says `disableOutput 1`): `<stem>.out` where its OUTPUTS give
/// `channels`, `<stem>_Line<n>.out` for each line whose `LineOutputs`
/// hold one of the flags MoorDyn opens a file for (`pvUDVKctsd`, MoorDyn2.cpp;
/// `b` alone opens none), the units rows unless `WriteUnits` is 0.
fn moordyn_out_file(
    deck: &Deck,
    path: &Path,
    channels: &[OutputChannel],
) -> Option<super::system_parts::MoorDynOutFile> {
    let option = |name: &str| {
        deck.options
            .iter()
            .find(|o| o.name.eq_ignore_ascii_case(name))
    };
    let disabled = option("disableoutput")
        .is_some_and(|o| matches!(o.value, moordyn::OptionValue::Number(v) if v == 1.0));
    if disabled {
        return None;
    }
    let stem = path.file_stem()?.to_string_lossy().into_owned();
    let lines: Vec<(usize, String, String)> = deck
        .lines
        .iter()
        .enumerate()
        .filter(|(_, l)| l.outputs.contains(|c| "pvUDVKctsd".contains(c)))
        .map(|(i, l)| (i, format!("{stem}_Line{}.out", l.id), l.outputs.clone()))
        .collect();
    // MoorDyn-C opens a file for every body (MoorDyn2.cpp, readBody).
    let bodies: Vec<(usize, String)> = deck
        .bodies
        .iter()
        .enumerate()
        .map(|(i, b)| (i, format!("{stem}_Body{}.out", b.id)))
        .collect();
    let rods: Vec<(usize, String, String)> = deck
        .rods
        .iter()
        .enumerate()
        .filter(|(_, r)| r.wants_rod_file())
        .map(|(i, r)| (i, format!("{stem}_Rod{}.out", r.id), r.outputs.clone()))
        .collect();
    if channels.is_empty() && lines.is_empty() && bodies.is_empty() && rods.is_empty() {
        return None;
    }
    let units = option("writeunits")
        .is_none_or(|o| !matches!(o.value, moordyn::OptionValue::Number(v) if v <= 0.0));
    Some(super::system_parts::MoorDynOutFile {
        main: (!channels.is_empty()).then(|| format!("{stem}.out")),
        lines,
        bodies,
        rods,
        units,
    })
}

/// The deck's acceleration of gravity (m/s^2): its `g`, else the host's,
/// else MoorDyn's 9.80665. It is the water's too (its pressure, its
/// waves): out of range it is refused here by its line, before the water
/// is built with it.
fn deck_gravity(
    deck: &Deck,
    file: &str,
    host: &super::HostEnvironment,
) -> Result<f64, ScenarioError> {
    let g = deck
        .option(SupportedOption::Gravity)
        .or(host.gravity)
        .unwrap_or(9.80665);
    let range = 1.0 / crate::scale_range::MAX_SCALE..=crate::scale_range::MAX_SCALE;
    if g == 0.0 || (g.is_finite() && range.contains(&g)) {
        return Ok(g);
    }
    let (name, line) = deck
        .options
        .iter()
        .find(|o| o.kind == crate::moordyn::OptionKind::Supported(SupportedOption::Gravity))
        .map_or(("g".to_string(), 0), |o| (o.name.clone(), o.line));
    Err(ScenarioError(format!(
        "{file}: line {line}: {name}: {g:e} m/s^2 is out of the range the solver computes in \
         (1e-150 to 1e150 in SI units); give the acceleration of gravity in m/s^2"
    )))
}

/// The points the host moves for the deck's CoupledPinned bodies: a
/// coupled point at each one's reference point (its id after the deck's
/// points), the body pinned there (docs/method.md §15.17).
fn host_pins(deck: &Deck, bodies: &mut [SystemBody], points: &mut Vec<SystemPoint>) {
    for (b, row) in deck.bodies.iter().enumerate() {
        if row.attachment != BodyAttachment::CoupledPinned {
            continue;
        }
        let id = SystemPoint::next_id(points);
        points.push(SystemPoint::made(
            id,
            PointType::Coupled,
            bodies[b].position,
        ));
        bodies[b].host_pin = Some(points.len() - 1);
    }
}

/// A POINTS row as a point: mass, volume, CdA and Ca act on free points
/// only (a fixed or coupled point's motion is given; a point on a body
/// has none, checked on reading). A point on a body (`bodies`: the
/// deck's, then a farm's turbines from index `turbines`) is where the
/// body's pose puts its X, Y, Z.
fn deck_point(
    p: &crate::moordyn::DeckPoint,
    bodies: &[SystemBody],
    turbines: usize,
) -> SystemPoint {
    // A free point's mass and water, and a point's on a body (its mass
    // and volume, which become the body's; checked on reading).
    let free = matches!(p.attachment, Attachment::Free | Attachment::Body(_));
    let if_free = |v: f64| if free { v } else { 0.0 };
    let (kind, position) = match p.attachment {
        Attachment::Fixed => (PointType::Fixed, p.position),
        Attachment::Free => (PointType::Free, p.position),
        Attachment::Coupled => (PointType::Coupled, p.position),
        Attachment::Body(n) => {
            let kind = PointType::Body {
                body: n - 1,
                local: p.position,
            };
            (kind, bodies[n - 1].point(p.position))
        }
        Attachment::Turbine(n) => {
            let body = turbines + n - 1;
            let kind = PointType::Body {
                body,
                local: p.position,
            };
            (kind, bodies[body].point(p.position))
        }
    };
    SystemPoint {
        id: p.id as i64,
        kind,
        position,
        mass: if_free(p.mass),
        force: p.force,
        volume: if_free(p.volume),
        drag_area: if_free(p.cda),
        ca: if_free(p.ca),
        motion: CoupledMotion::NONE,
        motion_file: None,
        damping: Default::default(),
    }
}

/// A BODIES row as a body. A fixed or coupled body's mass, inertia and
/// water are zero, as MoorDyn's `Body::setup` zeroes them (a coupled
/// body's are the coupling code's). A free body needs what
/// stancf's rigid body has (docs/method.md §15.2): a positive mass and
/// moments of a body with extent in all three directions; MoorDyn also
/// takes a zero mass or zero moments, its body's mass matrix holding the
/// masses of the line ends and rods attached to it
/// (docs/moordyn-bodies-rods.md §2.3): refused naming the deck's line,
/// unless rods or points with mass on the body (`parts`) give it their
/// mass and inertia (a float made of rods, MoorDyn's md_float; point
/// masses, its orbitalBody; the library folds them in, completes the
/// inertia of mass on a line (docs/method.md (B2a)) and refuses a sum
/// that is no body's).
fn deck_body(b: &DeckBody, parts: bool, file: &str) -> Result<SystemBody, ScenarioError> {
    let fixed = SystemBody::fixed(b.id as i64, b.position, b.angles);
    match b.attachment {
        BodyAttachment::Fixed => return Ok(fixed),
        BodyAttachment::Coupled => {
            return Ok(SystemBody {
                kind: BodyType::Coupled,
                ..fixed
            })
        }
        // Free, or pinned at its reference point to the host's point
        // (the point is made with the deck's points, [`host_pins`]).
        BodyAttachment::Free | BodyAttachment::CoupledPinned => {}
    }
    let moordyn_differs = "MoorDyn accepts it, its body's mass matrix also holding the masses \
                           of the line ends and rods attached to the body; stancf's body \
                           carries its own mass and inertia (the lines' ends are the lines')";
    if b.mass < 0.0 || (b.mass == 0.0 && !parts) {
        return Err(ScenarioError(format!(
            "{file}: line {}: Mass: free body {} has mass {} kg; a free body needs a positive \
             mass ({moordyn_differs})",
            b.line, b.id, b.mass
        )));
    }
    // Zero moments: a point mass (md_BdyExtLdDmpg), which the library
    // takes where everything acts at its centre (docs/method.md (B2a)).
    let point_mass = b.moments == [0.0; 3] && b.mass > 0.0;
    if !(moments_of_a_body(b.moments)
        || point_mass
        || (parts && b.moments.iter().all(|m| *m >= 0.0)))
    {
        return Err(ScenarioError(format!(
            "{file}: line {}: I: free body {} has the moments of inertia {:?} kg m^2; a free \
             body needs those of a body with extent in all three directions, each less than \
             the sum of the other two ({moordyn_differs})",
            b.line, b.id, b.moments
        )));
    }
    Ok(SystemBody {
        kind: BodyType::Free,
        mass: b.mass,
        centre_of_mass: b.centre_of_mass,
        moments: b.moments,
        volume: b.volume,
        drag_areas: b.drag_areas,
        rotational_drag_areas: b.rotational_drag_areas,
        ca: b.ca,
        ..fixed
    })
}

/// A note for a free body whose attachment word is neither `Free` nor
/// `Body`: MoorDyn-C takes every word it does not know as free, and so
/// does stancf, saying so.
fn free_word_note(b: &DeckBody) -> Option<String> {
    let upper = b.attachment_word.to_ascii_uppercase();
    let plain = ["FREE", "BODY"].iter().any(|w| upper.starts_with(w));
    (b.attachment == BodyAttachment::Free && !plain).then(|| {
        format!(
            "line {}: body {} is attached to \"{}\", which MoorDyn-C (and stancf) take as a \
             free body",
            b.line,
            b.id,
            crate::echo::clip(&b.attachment_word, 60)
        )
    })
}

/// The deck's LINES rows as lines ([`deck_line`]), their ends' points
/// and clamps `ends`, each with its Syrope line's largest mean tension
/// before the run of `tmax0` (a deck's SYROPE IC).
fn deck_lines(
    deck: &Deck,
    ends: Vec<super::rods::DeckLineEnds>,
    tmax0: &[Option<f64>],
) -> Vec<SystemLine> {
    deck.lines
        .iter()
        .zip(ends)
        .map(deck_line)
        .zip(tmax0)
        .map(|(l, t)| SystemLine { tmax0: *t, ..l })
        .collect()
}

/// A LINES row as a line of SAC-2 elements, one per segment, pinned at
/// its points (MoorDyn's lines are) but where clamped to a fixed rod's
/// axis; `ends` its points' indices (a rod end's point, super::rods).
fn deck_line((l, ends): (&crate::moordyn::DeckLine, super::rods::DeckLineEnds)) -> SystemLine {
    SystemLine {
        id: l.id as i64,
        line_type: l.type_index,
        length: l.unstretched_length,
        elements: l.segments,
        element_type: ElementType::Sac2,
        ends: ends.points.map(Some),
        grading: stancf::Grading::Uniform,
        clamps: ends.clamps,
        tmax0: None,
    }
}

/// The deck's OUTPUTS as channels, and a note for each one stancf does
/// not compute or MoorDyn does not know (its column left empty), naming
/// its line and why.
fn deck_channels(deck: &Deck) -> (Vec<OutputChannel>, Vec<String>) {
    let mut channels = Vec::with_capacity(deck.outputs.len());
    let mut notes = Vec::new();
    for o in &deck.outputs {
        let why = match (&o.unrecognized, o.channel) {
            (Some(why), _) => Some(format!(
                "not a channel MoorDyn knows ({why}); MoorDyn warns and skips it"
            )),
            (None, Channel::Rod { rod, quantity }) => {
                rod_not_computed(&deck.rods[rod - 1], quantity)
            }
            _ => not_computed(&o.channel).map(str::to_string),
        };
        if let Some(why) = &why {
            notes.push(format!(
                "line {}: output channel {}: {why}; its column in channels.csv is left empty, \
                 and the deck's .out file has none",
                o.line, o.name
            ));
        }
        channels.push(OutputChannel {
            name: o.name.clone(),
            channel: o.channel,
            computed: why.is_none(),
        });
    }
    (channels, notes)
}

/// What stancf does not compute in this version.
const NOT: &str = "stancf does not compute this value in this version (it writes line end \
                   tensions, point positions, velocities and net forces, line node positions, \
                   velocities and tensions, body poses, velocities, net forces and moments, and rods' \
                   poses, velocities, end tensions and submerged fractions)";

/// Why stancf does not have the value of a channel, or None where it
/// does: line end tensions, point positions, velocities and net forces
/// (MoorDyn's `Fnet`), line node positions, velocities and tensions, bodies' all
/// but accelerations (rods: [`rod_not_computed`]).
fn not_computed(c: &Channel) -> Option<&'static str> {
    match c {
        Channel::FairleadTension { .. }
        | Channel::AnchorTension { .. }
        | Channel::LineEndTension { .. } => None,
        Channel::LineNode { quantity, .. } => {
            matches!(quantity, LineQuantity::Force(_)).then_some(NOT)
        }
        Channel::Point { quantity, .. } => {
            matches!(quantity, PointQuantity::Acceleration(_)).then_some(NOT)
        }
        Channel::Body { quantity, .. } => matches!(
            quantity,
            BodyQuantity::Acceleration(_) | BodyQuantity::AngularAcceleration(_)
        )
        .then_some(NOT),
        Channel::Rod { .. } => None,
        Channel::Unrecognized => Some(NOT),
    }
}

/// Why stancf does not have the value of quantity `q` of rod `r`, or
/// None where it does: accelerations are not computed (as a body's); a
/// rod of zero length (NumSegs 0) is a point, with a position and a
/// velocity only; a rod fixed in a body has no net force of its own, its
/// loads being its body's.
fn rod_not_computed(r: &DeckRod, q: RodQuantity) -> Option<String> {
    use RodQuantity as Q;
    match q {
        Q::Acceleration(_) | Q::AngularAcceleration(_) => Some(NOT.to_string()),
        Q::NodeOther(_) => Some(
            "of a rod's nodes stancf writes the positions and velocities (the rigid rod's); \
             their forces, tensions and accelerations are not computed in this version"
                .to_string(),
        ),
        Q::Position(_) | Q::Velocity(_) | Q::NodePosition(..) | Q::NodeVelocity(..) => None,
        _ if r.segments == 0 => Some(format!(
            "rod {} has NumSegs 0, a rod of zero length that stancf builds as a point: it \
             has a position and a velocity (PX PY PZ VX VY VZ), no axis, volume or ends of \
             its own",
            r.id
        )),
        Q::Force(_) | Q::Moment(_) => match r.attachment {
            RodAttachment::Body(b) => Some(format!(
                "rod {} is fixed in body {b}: its share of the body's loads is not separated \
                 in this version (the body's net force and moment are Body{b}FX ... Body{b}MZ)",
                r.id
            )),
            _ => None,
        },
        _ => None,
    }
}
