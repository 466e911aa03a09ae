//! `[output]`: how often a run writes (`every`), which of a system's
//! result files it writes (`files`) and which end forces (`end_forces`;
//! docs/interface.md "Systems").

use super::context::Ctx;
use super::raw::RawOutput;
use super::ScenarioError;

/// The result tables of a system run `files` may name (docs/interface.md,
/// "Systems"): nodes.csv, stress.csv and node_loads.csv are written for
/// every line, in `lines/<id>/`; bodies.csv where the system has bodies;
/// stiffness.csv where it has free bodies and a static equilibrium;
/// `moordyn.out` names MoorDyn's output files of a deck that asks for
/// them (`<deck>.out`, `<deck>_Line<n>.out`). summary.json and
/// scenario.toml are always written.
pub const SYSTEM_FILES: [&str; 10] = [
    "points.csv",
    "tensions.csv",
    "history.csv",
    "channels.csv",
    "nodes.csv",
    "stress.csv",
    "node_loads.csv",
    "bodies.csv",
    "stiffness.csv",
    "moordyn.out",
];

/// Which of a system's result tables a run writes (all by default).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct OutputFiles {
    /// The names chosen (None: every file).
    chosen: Option<Vec<String>>,
}

impl OutputFiles {
    /// Every file.
    pub fn all() -> Self {
        OutputFiles { chosen: None }
    }

    /// Whether the table `name` (one of [`SYSTEM_FILES`]) is written.
    pub fn writes(&self, name: &str) -> bool {
        self.chosen
            .as_ref()
            .is_none_or(|c| c.iter().any(|n| n == name))
    }

    /// The tables of [`SYSTEM_FILES`] not written.
    pub fn left_out(&self) -> Vec<&'static str> {
        SYSTEM_FILES
            .into_iter()
            .filter(|n| !self.writes(n))
            .collect()
    }
}

/// The end forces a system's dynamic run writes (points.csv, tensions.csv,
/// the deck's tension channels and the largest tensions of summary.json).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum EndForces {
    /// The mean over the step ending at t (docs/method.md §6.5, (M23)).
    #[default]
    StepMean,
    /// The estimate at t, second order in the step (M23a).
    AtTime,
}

impl EndForces {
    /// The scenario's name: "step_mean" or "at_time".
    pub fn name(self) -> &'static str {
        match self {
            EndForces::StepMean => "step_mean",
            EndForces::AtTime => "at_time",
        }
    }
}

/// `output.end_forces` of a system: "step_mean" or "at_time"; the
/// default is "step_mean", but "at_time" where a tolerance chooses the
/// steps (`controlled`: the tolerance bounds the forces at t, (M23c)).
pub(super) fn output_end_forces(
    ctx: &Ctx,
    raw: Option<&RawOutput>,
    controlled: bool,
) -> Result<EndForces, ScenarioError> {
    let chosen = raw.and_then(|r| r.end_forces.as_deref());
    let default = if controlled { "at_time" } else { "step_mean" };
    match ctx.choice(
        "output.end_forces",
        chosen,
        default,
        &["step_mean", "at_time"],
    )? {
        "at_time" => Ok(EndForces::AtTime),
        _ => Ok(EndForces::StepMean),
    }
}

/// `output.statistics_after` of a system (s, >= 0, default 0): the
/// design statistics of summary.json (docs/interface.md, "Design
/// statistics") take the written moments at this time and after, so that
/// a start-up transient stays out of them.
pub(super) fn statistics_after(ctx: &Ctx, raw: Option<&RawOutput>) -> Result<f64, ScenarioError> {
    match raw.and_then(|r| r.statistics_after) {
        Some(t) => ctx.non_negative("output.statistics_after", t),
        None => Ok(0.0),
    }
}

/// `output.every` (at least 1, default 1): the steps between two written
/// steps.
pub(super) fn output_every(ctx: &Ctx, raw: Option<&RawOutput>) -> Result<usize, ScenarioError> {
    match raw.and_then(|r| r.every) {
        Some(n) => ctx.count("output.every", n, 1, i64::MAX),
        None => Ok(1),
    }
}

/// `output.files` of a system: names from [`SYSTEM_FILES`], each once
/// (absent: every file).
pub(super) fn output_files(
    ctx: &Ctx,
    raw: Option<&RawOutput>,
) -> Result<OutputFiles, ScenarioError> {
    let Some(names) = raw.and_then(|r| r.files.as_ref()) else {
        return Ok(OutputFiles::all());
    };
    for (i, name) in names.iter().enumerate() {
        if !SYSTEM_FILES.contains(&name.as_str()) {
            return Err(ctx.err(
                "output.files",
                format!(
                    "\"{name}\" is not a result file of a system; the files are {}",
                    SYSTEM_FILES.join(", ")
                ),
            ));
        }
        if names[..i].contains(name) {
            return Err(ctx.err("output.files", format!("\"{name}\" is named twice")));
        }
    }
    Ok(OutputFiles {
        chosen: Some(names.clone()),
    })
}

/// `output.files` naming channels.csv where nothing would fill it: the
/// file holds a MoorDyn deck's OUTPUTS channels, and a scenario without a
/// deck (`deck` false) or a deck without channels has none.
pub(super) fn channels_to_write(
    ctx: &Ctx,
    files: &OutputFiles,
    deck: bool,
    channels: usize,
) -> Result<(), ScenarioError> {
    if files.chosen.is_none() || !files.writes("channels.csv") || channels > 0 {
        return Ok(());
    }
    let why = if deck {
        "the deck lists no OUTPUTS channels"
    } else {
        "it holds a MoorDyn deck's OUTPUTS channels, and this system has no deck (system.moordyn)"
    };
    Err(ctx.err(
        "output.files",
        format!("\"channels.csv\" would stay empty: {why}"),
    ))
}

/// `output.files` naming bodies.csv for a system without bodies (it
/// would stay empty).
pub(super) fn bodies_to_write(
    ctx: &Ctx,
    files: &OutputFiles,
    bodies: usize,
) -> Result<(), ScenarioError> {
    if files.chosen.is_none() || !files.writes("bodies.csv") || bodies > 0 {
        return Ok(());
    }
    Err(ctx.err(
        "output.files",
        "\"bodies.csv\" would stay empty: it holds the system's rigid bodies, and this system \
         has none",
    ))
}

/// `output.files` naming stiffness.csv where nothing would fill it: a
/// system without free bodies (`free_bodies` false), or a run without a
/// static equilibrium (`statics` false: a dynamic run from the reference
/// shape).
pub(super) fn stiffness_to_write(
    ctx: &Ctx,
    files: &OutputFiles,
    free_bodies: bool,
    statics: bool,
) -> Result<(), ScenarioError> {
    if files.chosen.is_none() || !files.writes("stiffness.csv") || (free_bodies && statics) {
        return Ok(());
    }
    let why = if free_bodies {
        "it holds the free bodies' mooring stiffness at the static equilibrium, and this run \
         has none (a dynamic run from the reference shape: analysis.initial = \"static\" \
         starts from the equilibrium)"
    } else {
        "it holds the free bodies' mooring stiffness, and this system has no free body"
    };
    Err(ctx.err(
        "output.files",
        format!("\"stiffness.csv\" would stay empty: {why}"),
    ))
}

/// A single cable writes all its files, and its reactions as step means:
/// `output.files` and `output.end_forces` are refused there.
pub(super) fn no_output_files(ctx: &Ctx, raw: Option<&RawOutput>) -> Result<(), ScenarioError> {
    if raw.is_some_and(|r| r.files.is_some()) {
        return Err(ctx.err(
            "output.files",
            "chooses the result files of a system of lines ([system] or [[lines]]); a single \
             cable writes all of its files",
        ));
    }
    if raw.is_some_and(|r| r.end_forces.is_some()) {
        return Err(ctx.err(
            "output.end_forces",
            "chooses the end forces of a system of lines ([system] or [[lines]]); a single \
             cable's reactions.csv holds the mean over each step in this version",
        ));
    }
    if raw.is_some_and(|r| r.interval.is_some()) {
        return Err(ctx.err(
            "output.interval",
            "writes a system of lines ([system] or [[lines]]) between its steps; a single \
             cable writes at its steps (output.every) in this version",
        ));
    }
    if raw.is_some_and(|r| r.statistics_after.is_some()) {
        return Err(ctx.err(
            "output.statistics_after",
            "starts the design statistics of a system of lines ([system] or [[lines]]): its \
             line ends' tensions and its points' offsets; a single cable has none",
        ));
    }
    Ok(())
}
