//! Scenario files (TOML, docs/interface.md): parsing and validation.
//!
//! Every problem is reported as `<file>: <key>: <what is wrong>`, before
//! anything is written. Unknown keys are errors at every level.
//!
//! [`parse`] reads the file (`raw`) and validates it part by part, in
//! the file's order, so that the first wrong key is the one reported:
//! `cable` (`[cable]`, `[material]`), `constraints`, `loads`,
//! `initial_velocity`, `analysis` (`[analysis]`, `[output]`). The checks
//! they share are in `context`, the words of the messages in `messages`.

mod analysis;
mod bodies;
mod body_water;
mod cable;
mod constraints;
mod context;
mod deck_files;
mod deck_line_types;
mod deck_mesh;
mod deck_system;
mod deck_values;
mod ea_curves;
mod external_loads;
mod failures;
mod farm;
mod host_environment;
mod host_order;
mod initial_velocity;
mod loads;
mod messages;
mod moordyn;
mod moordyn_current_grids;
mod moordyn_driver;
mod moordyn_driver_motions;
mod moordyn_driver_platforms;
mod moordyn_option_notes;
mod moordyn_seafloor;
mod moordyn_water;
mod moordyn_waterkin;
mod moordyn_waterkin_waves;
mod moordyn_wave_frequencies;
mod moordyn_wave_grids;
mod moordyn_waves;
mod motions;
pub mod names;
mod output;
mod output_interval;
pub(crate) mod overstretch;
mod raw;
mod rod_parts;
mod rod_toml;
mod rods;
mod sea_limits;
mod syrope_files;
mod system;
mod system_model;
mod system_parts;
mod visco_types;
mod viv_types;
mod water;

pub use analysis::InitialShape;
pub use analysis::{Analysis, AnalysisKind, MAX_COUNTABLE_STEPS, MAX_STEPS};
pub use bodies::{moments_of_a_body, uniform_current, BodyType, SystemBody};
pub use failures::{describe_failure, failure_events, FailureEvent};
pub use host_environment::HostEnvironment;
pub use initial_velocity::{InitialVelocity, NodeSet};
pub use messages::{clip, MAX_ECHO};
pub use moordyn_water::{read_current_profile, CURRENT_PROFILE_FILE};
pub use output::{EndForces, OutputFiles, SYSTEM_FILES};
pub use rod_parts::{RodHolder, RodTypeValues, SystemRod};
pub use system_model::EI_FACTOR;
pub use system_parts::{
    LineType, MoorDynOutFile, OutputChannel, PointType, SystemFailure, SystemLine, SystemPoint,
    SystemScenario,
};
pub use viv_types::viv_words;
pub use water::{Current, CurrentField, SeabedFile, SeabedOptions, Water};

use context::Ctx;
use raw::RawScenario;
use stancf::{Load, Material, ModelOptions};
use std::path::Path;

/// An invalid scenario: the message names the file and the key.
#[derive(Debug)]
pub struct ScenarioError(pub String);

impl std::fmt::Display for ScenarioError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.0)
    }
}

/// A validated scenario.
#[derive(Clone, Debug)]
pub struct Scenario {
    pub title: String,
    pub cable: stancf::Cable,
    pub material: Material,
    pub diameter: f64,
    pub options: ModelOptions,
    pub loads: Vec<Load>,
    pub constraints: Vec<stancf::Constraint>,
    pub initial_velocity: Vec<InitialVelocity>,
    pub analysis: Analysis,
    pub output_every: usize,
    /// Things worth saying that do not make the scenario invalid.
    pub notes: Vec<String>,
}

/// Reads and validates a scenario file.
pub fn load(path: &Path) -> Result<Scenario, ScenarioError> {
    let file = path.display().to_string();
    let text =
        crate::input_file::read_text(path).map_err(|e| ScenarioError(format!("{file}: {e}")))?;
    parse(&text, &file, path)
}

/// What a scenario file describes: one cable or a system of lines.
#[derive(Clone, Debug)]
pub enum Input {
    /// Boxed, as a system is: both are hundreds of bytes.
    Cable(Box<Scenario>),
    System(Box<SystemScenario>),
}

/// Parses and validates the text of a scenario of either kind: a system
/// when it is a MoorDyn v2 deck (dashed section headers) or a TOML file
/// with `[system]`, `[[line_types]]`, `[[points]]`, `[[lines]]` or
/// `[[motions]]`; else a single cable.
pub fn parse_input(text: &str, file: &str, path: &Path) -> Result<Input, ScenarioError> {
    parse_input_with(text, file, path, &HostEnvironment::NONE)
}

/// [`parse_input`] with what a host gives a MoorDyn deck (bare or taken
/// by a scenario): the water depth, density and gravity the deck leaves
/// out ([`HostEnvironment`]).
pub fn parse_input_with(
    text: &str,
    file: &str,
    path: &Path,
    host: &HostEnvironment,
) -> Result<Input, ScenarioError> {
    let host = host
        .checked()
        .map_err(|e| ScenarioError(format!("{file}: {e}")))?;
    if moordyn_driver::is_driver(text) {
        let sc = moordyn_driver::driver_scenario(text, file, path)?;
        return Ok(Input::System(Box::new(sc)));
    }
    if crate::moordyn::looks_like_moordyn(text) {
        let deck =
            crate::moordyn::parse(text).map_err(|e| ScenarioError(format!("{file}: {e}")))?;
        let title = title_of(None, path);
        let sc = moordyn::deck_scenario(&deck, file, path, title, None, host, None)?;
        return Ok(Input::System(Box::new(sc)));
    }
    let ctx = Ctx { file };
    let raw = raw_scenario(text, file)?;
    if raw.is_system() {
        let title = title_of(raw.title.clone(), path);
        return system::system_scenario(&ctx, raw, title, path, host)
            .map(|sc| Input::System(Box::new(sc)));
    }
    cable_scenario(&ctx, raw, path).map(|sc| Input::Cable(Box::new(sc)))
}

/// Whether `text` is a MoorDyn driver file (`md_driver.inp`: docs/interface.md,
/// "MoorDyn driver files").
pub fn is_moordyn_driver(text: &str) -> bool {
    moordyn_driver::is_driver(text)
}

/// The TOML tables of a scenario; a file that is not TOML at all is told
/// what stancf reads (a TOML scenario or a MoorDyn v2 deck, known by its
/// dashed section headers).
fn raw_scenario(text: &str, file: &str) -> Result<RawScenario, ScenarioError> {
    toml::from_str(text).map_err(|e| {
        let mut err = messages::toml_error(file, text, &e);
        // Told only to a file with no TOML in its look: no key = value, no
        // [table] (a number too large is a TOML file's error of its own).
        let looks_toml = text
            .lines()
            .map(str::trim)
            .any(|l| !l.starts_with('#') && (l.contains('=') || l.starts_with('[')));
        if !looks_toml {
            err.0.push_str(
                "\n(stancf reads TOML scenarios and MoorDyn v2 decks; this file is not TOML, and \
                 it has no MoorDyn section header, a line such as --- LINE TYPES ---)",
            );
        }
        err
    })
}

/// The title: the file's `title`, or its stem.
fn title_of(title: Option<String>, path: &Path) -> String {
    title.unwrap_or_else(|| {
        path.file_stem()
            .map(|s| s.to_string_lossy().into_owned())
            .unwrap_or_default()
    })
}

/// Parses and validates the text of a single-cable scenario; `file`
/// names it in messages. The `title` defaults to the file's stem (from
/// `path`). A system is refused (see [`parse_input`]).
pub fn parse(text: &str, file: &str, path: &Path) -> Result<Scenario, ScenarioError> {
    let ctx = Ctx { file };
    if crate::moordyn::looks_like_moordyn(text) {
        return Err(ScenarioError(format!(
            "{file}: a MoorDyn deck describes a system of lines, which this command does not \
             take in this version (it takes a single-cable TOML scenario; run the deck with \
             `stancf run` or check it with `stancf check`)"
        )));
    }
    let raw = raw_scenario(text, file)?;
    if raw.is_system() {
        return Err(ctx.err(
            "lines",
            "this file describes a system of lines, which this command does not take in this \
             version (use `stancf run` or `stancf check`)",
        ));
    }
    cable_scenario(&ctx, raw, path)
}

/// The single-cable parts of a scenario file.
fn cable_scenario(ctx: &Ctx, raw: RawScenario, path: &Path) -> Result<Scenario, ScenarioError> {
    if raw.water.is_some() {
        return Err(ctx.err(
            "water",
            "[water] acts on the lines of a system ([[line_types]], [[points]], [[lines]]) in \
             this version; a single cable takes an \"air-drag\" load in a fluid",
        ));
    }
    if let Some(initial) = raw.analysis.as_ref().and_then(|a| a.initial.as_deref()) {
        if initial != "reference" {
            return Err(ctx.err(
                "analysis.initial",
                format!(
                    "\"{}\": a single cable starts from its reference shape (\"reference\"); \
                     a start from the static equilibrium is available for systems \
                     ([[lines]]) in this version",
                    clip(initial, 60)
                ),
            ));
        }
    }
    let title = title_of(raw.title, path);
    let cable = cable::cable(ctx, raw.cable)?;
    let (material, diameter) = cable::material(ctx, raw.material)?;
    let constraints = constraints::constraints(ctx, &raw.constraints, cable.elements)?;
    let loads = loads::loads(ctx, &raw.loads, cable.elements, diameter)?;
    let initial_velocity =
        initial_velocity::initial_velocities(ctx, &raw.initial_velocity, cable.elements)?;
    let others = analysis::Others {
        initial_velocity: !raw.initial_velocity.is_empty(),
        constraints: !constraints.is_empty(),
    };
    let (analysis, measures, notes) = analysis::analysis(ctx, raw.analysis, others)?;
    if analysis.step_halvings > 0 {
        return Err(ctx.err(
            "analysis.step_halvings",
            "halving failed steps is for systems of lines in this version, not a single cable",
        ));
    }
    if analysis.force_tolerance.is_some() {
        return Err(ctx.err(
            "analysis.force_tolerance",
            "steps chosen by a tolerance on the end forces are for systems of lines in this \
             version, not a single cable (give the cable as a [system] of one line)",
        ));
    }
    initial_velocity::check_initial_velocities(ctx, &initial_velocity, &constraints)?;
    output::no_output_files(ctx, raw.output.as_ref())?;
    let output_every = output::output_every(ctx, raw.output.as_ref())?;
    Ok(Scenario {
        title,
        cable,
        material,
        diameter,
        options: ModelOptions {
            measures,
            space_points: analysis.space_points,
        },
        loads,
        constraints,
        initial_velocity,
        analysis,
        output_every,
        notes,
    })
}

impl Scenario {
    /// The library model.
    pub fn model(&self) -> Result<stancf::Model, stancf::ModelError> {
        stancf::Model::new(
            self.cable.clone(),
            self.material,
            self.options.clone(),
            self.loads.clone(),
        )?
        .with_constraints(self.constraints.clone())
    }
}
