//! A MoorDyn v2 deck ([`crate::moordyn::Deck`]) as a system scenario:
//! LINE TYPES become line types, POINTS points (Fixed, Free with their
//! mass and buoyant volume, Coupled at rest), LINES lines of NumSegs
//! SAC-2 elements, OPTIONS gravity and water, OUTPUTS the channels of
//! channels.csv. MoorDyn's frame is ours: z up, the still water surface
//! at z = 0, the seabed at z = -WtrDpth.
//!
//! What stancf cannot compute from a deck is refused by name, naming the
//! deck's line: output channels stancf has no value for; in this version
//! also a dynamic analysis in water (added mass and drag are not
//! modelled) and lines through the surface (checked by the run). The
//! seabed at z = -WtrDpth holds the lines that reach it (kBot, cBot,
//! FrictionCoefficient; docs/method.md §12.2).

use super::analysis;
use super::context::Ctx;
use super::raw::RawAnalysis;
use super::system::{
    analysis_part, InitialShape, LineType, OutputChannel, PointType, SeabedOptions, SystemLine,
    SystemPoint, SystemScenario, Water,
};
use super::ScenarioError;
use crate::moordyn::{
    self, Attachment, Channel, Deck, LineQuantity, PointQuantity, SupportedOption,
};
use stancf::motion::CoupledMotion;
use stancf::ElementType;
use std::path::Path;

/// The scenario of the deck in the file at `path` (a static analysis
/// from the lines' catenaries, as a deck alone says nothing of time).
pub fn deck_file_scenario(path: &Path, title: String) -> Result<SystemScenario, ScenarioError> {
    let file = path.display().to_string();
    let deck = moordyn::load(path).map_err(|e| match e.line {
        Some(_) => ScenarioError(format!("{file}: {e}")),
        None => ScenarioError(e.message),
    })?;
    deck_scenario(&deck, &file, title)
}

/// The scenario of a deck read from `file` (named in messages).
pub fn deck_scenario(
    deck: &Deck,
    file: &str,
    title: String,
) -> Result<SystemScenario, ScenarioError> {
    let at = |line: usize, msg: String| ScenarioError(format!("{file}: line {line}: {msg}"));
    let g = deck.option(SupportedOption::Gravity).unwrap_or(9.80665);
    let water = Water {
        depth: deck.option(SupportedOption::WaterDepth).ok_or_else(|| {
            ScenarioError(format!(
                "{file}: OPTIONS: WtrDpth is missing: a deck's lines hang in water of a given \
                 depth"
            ))
        })?,
        density: deck.option(SupportedOption::WaterDensity).unwrap_or(1025.0),
        seabed: SeabedOptions {
            stiffness: deck
                .option(SupportedOption::BottomStiffness)
                .unwrap_or(SeabedOptions::MOORDYN.stiffness),
            damping: deck
                .option(SupportedOption::BottomDamping)
                .unwrap_or(SeabedOptions::MOORDYN.damping),
            friction: deck
                .option(SupportedOption::FrictionCoefficient)
                .unwrap_or(SeabedOptions::MOORDYN.friction),
        },
    };
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
    let (analysis, measures, initial, notes) =
        analysis_part(&ctx, Some(raw), InitialShape::Static)?;
    Ok(SystemScenario {
        title,
        line_types,
        points,
        lines,
        gravity: [0.0, 0.0, -g],
        analysis,
        measures,
        initial,
        output_every: analysis::output_every(&ctx, None)?,
        notes,
        water: Some(water),
        channels,
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
