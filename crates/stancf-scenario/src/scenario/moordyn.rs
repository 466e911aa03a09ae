//! A MoorDyn v2 deck ([`crate::moordyn::Deck`]) as a system scenario:
//! LINE TYPES become line types, POINTS points (Fixed, Free with their
//! mass and buoyant volume, Coupled at rest), LINES lines of NumSegs
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

use super::context::Ctx;
use super::moordyn_water::{deck_water, deck_water_keys};
use super::raw::RawAnalysis;
use super::system::{
    analysis_part, InitialShape, LineType, OutputChannel, PointType, SystemLine, SystemPoint,
    SystemScenario,
};
use super::water::WaterKeys;
use super::ScenarioError;
use crate::moordyn::{
    self, Attachment, Channel, Deck, LineQuantity, PointQuantity, SupportedOption,
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
) -> Result<SystemScenario, ScenarioError> {
    let at = |line: usize, msg: String| ScenarioError(format!("{file}: line {line}: {msg}"));
    let g = deck.option(SupportedOption::Gravity).unwrap_or(9.80665);
    // g is the water's too (its pressure, its waves): out of range it is
    // refused here by its line, before the water is built with it.
    if !(g.is_finite()
        && (1.0 / crate::scale_range::MAX_SCALE..=crate::scale_range::MAX_SCALE).contains(&g))
    {
        let (name, line) = deck
            .options
            .iter()
            .find(|o| o.kind == crate::moordyn::OptionKind::Supported(SupportedOption::Gravity))
            .map_or(("g".to_string(), 0), |o| (o.name.clone(), o.line));
        return Err(at(
            line,
            format!(
                "{name}: {g:e} m/s^2 is out of the range the solver computes in (1e-150 to \
                 1e150 in SI units); give the acceleration of gravity in m/s^2"
            ),
        ));
    }
    let water = deck_water(deck_water_keys(deck, file, path)?, file, deck, added)?;
    let line_types = deck
        .line_types
        .iter()
        .map(|t| LineType {
            name: t.name.clone(),
            diameter: t.diameter,
            mass_per_length: t.mass_per_length,
            ea: t.ea,
            ei: t.ei,
            ba: t.ba,
            cd: t.cd,
            ca: t.ca,
            cdax: t.cd_ax,
            caax: t.ca_ax,
            // MoorDyn's segments carry no compression (Line.cpp: T = 0
            // when l_str <= l); the static solve keeps it (docs/method.md
            // §2.2, (M4a)).
            compression: false,
        })
        .collect();
    let points = deck
        .points
        .iter()
        .map(|p| SystemPoint {
            id: p.id as i64,
            kind: match p.attachment {
                Attachment::Fixed => PointType::Fixed,
                Attachment::Free => PointType::Free,
                Attachment::Coupled => PointType::Coupled,
            },
            position: p.position,
            mass: if p.attachment == Attachment::Free {
                p.mass
            } else {
                0.0
            },
            force: [0.0; 3],
            volume: if p.attachment == Attachment::Free {
                p.volume
            } else {
                0.0
            },
            drag_area: if p.attachment == Attachment::Free {
                p.cda
            } else {
                0.0
            },
            ca: if p.attachment == Attachment::Free {
                p.ca
            } else {
                0.0
            },
            motion: CoupledMotion::NONE,
            motion_file: None,
        })
        .collect();
    let lines = deck
        .lines
        .iter()
        .map(|l| SystemLine {
            id: l.id as i64,
            line_type: l.type_index,
            length: l.unstretched_length,
            elements: l.segments,
            element_type: ElementType::Sac2,
            ends: [Some(l.end_a - 1), Some(l.end_b - 1)],
            grading: stancf::Grading::Uniform,
            // MoorDyn's lines are pinned at their points.
            clamps: [None; 2],
        })
        .collect();
    let mut channels = Vec::with_capacity(deck.outputs.len());
    for o in &deck.outputs {
        if !computable(&o.channel) {
            return Err(at(
                o.line,
                format!(
                    "output channel {}: stancf does not compute this value in this version \
                     (it writes line end tensions, point positions and velocities, and line \
                     node positions and velocities)",
                    o.name
                ),
            ));
        }
        channels.push(OutputChannel {
            name: o.name.clone(),
            channel: o.channel,
        });
    }
    let ctx = Ctx { file };
    let raw = RawAnalysis {
        kind: Some("static".into()),
        ..RawAnalysis::default()
    };
    let (mut analysis, measures, initial, notes) =
        analysis_part(&ctx, Some(raw), InitialShape::Static)?;
    // A deck alone is static; its dtM is the step of a coupled run of it
    // (checked with the other values, crate::input_scales).
    analysis.time_step = deck.option(SupportedOption::TimeStep).unwrap_or(0.0);
    Ok(SystemScenario {
        title,
        line_types,
        points,
        lines,
        gravity: [0.0, 0.0, -g],
        analysis,
        measures,
        initial,
        output_every: 1,
        output_files: super::OutputFiles::all(),
        end_forces: super::output::EndForces::StepMean,
        notes,
        water: Some(water),
        channels,
        names: super::names::Names::of_deck(deck, None),
    })
}

/// Whether stancf has the value of a channel: line end tensions, point
/// positions and velocities, line node positions and velocities.
fn computable(c: &Channel) -> bool {
    match c {
        Channel::FairleadTension { .. }
        | Channel::AnchorTension { .. }
        | Channel::LineEndTension { .. } => true,
        Channel::LineNode { quantity, .. } => matches!(
            quantity,
            LineQuantity::Position(_) | LineQuantity::Velocity(_)
        ),
        Channel::Point { quantity, .. } => matches!(
            quantity,
            PointQuantity::Position(_) | PointQuantity::Velocity(_)
        ),
    }
}
