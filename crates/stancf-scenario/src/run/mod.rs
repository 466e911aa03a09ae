//! The `run` command: a scenario stepped (or solved statically) with its
//! results streamed to the output folder and summary.json written last.
//!
//! - this file: the options, the output folder and its transaction
//!   ([`run_text`]), and `stancf plot`;
//! - `dynamic.rs`: the time-stepping run;
//! - `statics.rs`: the static run (load stepping);
//! - `summary.rs`: the running figures, summary.json and the printed report;
//! - `writers.rs`: the streamed result files.

mod dynamic;
mod statics;
mod summary;
mod system;
pub(crate) mod writers;

use crate::check::{derive, load_text};
use crate::output::{Collector, Dest, ResultFolder};
use crate::scenario::{AnalysisKind, Input};
use crate::Failure;
use std::path::{Path, PathBuf};

pub use crate::check::{check, check_in};
pub use crate::scenario::HostEnvironment;

/// A request to stop a run, polled after every step (the Python layer
/// answers it from Ctrl-C).
#[derive(Clone)]
pub struct Cancel(pub std::sync::Arc<dyn Fn() -> bool + Send + Sync>);

impl std::fmt::Debug for Cancel {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str("Cancel")
    }
}

/// Draws the figures of the result set in a folder; the names of the
/// figures drawn. The command line gives its own (PNG and SVG, `stancf
/// run --plot`); this library draws none.
#[derive(Clone)]
pub struct Figures(pub std::sync::Arc<DrawFigures>);

/// What draws the figures of the result set in a folder.
pub type DrawFigures = dyn Fn(&Path) -> std::io::Result<Vec<String>> + Send + Sync;

impl std::fmt::Debug for Figures {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str("Figures")
    }
}

/// What `stancf run` writes besides the result files.
#[derive(Clone, Debug, Default)]
pub struct RunOptions {
    /// Output folder (default: `out/<scenario file stem>/`).
    pub out: Option<PathBuf>,
    /// Also draw the run's figures next to its results, with this
    /// (the command line's PNG and SVG figures).
    pub plot: Option<Figures>,
    /// Also write ParaView files (one .vtp per written step, cable.pvd).
    pub vtk: bool,
    /// No progress bar and no summary on standard output (errors and
    /// warnings still go to standard error).
    pub quiet: bool,
    /// Run even when the step count or the result size exceeds the
    /// bounds that otherwise refuse a run.
    pub allow_large: bool,
    /// Stop when this says so (checked after every step).
    pub cancel: Option<Cancel>,
    /// The folder messages name when `out` is itself moved after the run
    /// (a sweep's runs live in the sweep's staging folder until it commits).
    pub shown_as: Option<PathBuf>,
    /// Also keep every result file in memory as it is written, the same
    /// bytes (Python's `stancf.run` takes its arrays from here).
    pub collect: Option<Collector>,
    /// What the command line gives a MoorDyn deck that leaves it out
    /// (`--water-depth`).
    pub host: crate::scenario::HostEnvironment,
}

impl RunOptions {
    /// Whether the run is asked to stop now (see [`RunOptions::cancel`]).
    fn cancelled(&self) -> bool {
        self.cancel.as_ref().is_some_and(|c| (c.0)())
    }
}

/// Where a run writes (`dir`, the staging folder of its [`ResultFolder`])
/// and the folder its results appear in (`shown`, named in messages).
struct Place<'a> {
    dir: &'a Path,
    shown: &'a Path,
    /// Keeps a copy of every file written (see [`RunOptions::collect`]).
    collect: Option<&'a Collector>,
}

impl Place<'_> {
    /// Where the run's files go.
    fn dest(&self) -> Dest<'_> {
        Dest {
            dir: self.dir,
            collect: self.collect,
        }
    }
}

/// A write error as the failure of a run whose results go to `dir`.
fn io_err(dir: &Path) -> impl Fn(std::io::Error) -> Failure + '_ {
    move |e| Failure::Other(format!("{}: cannot write results: {e}", dir.display()))
}

/// The output folder: `--out`, or `out/<stem>` with the scenario file's
/// stem made safe as a folder name (letters, digits, `-`, `_`, `.`, no
/// leading dot; `run` when nothing is left), so the default is always a
/// folder of its own under `out/`.
fn output_dir(path: &Path, out: Option<PathBuf>) -> PathBuf {
    out.unwrap_or_else(|| {
        let stem = path
            .file_stem()
            .map(|s| s.to_string_lossy().into_owned())
            .unwrap_or_default();
        PathBuf::from("out").join(safe_folder_name(&stem))
    })
}

/// A file stem as a folder name of its own (see [`output_dir`]).
pub(crate) fn safe_folder_name(stem: &str) -> String {
    let name: String = stem
        .chars()
        .map(|c| {
            if c.is_ascii_alphanumeric() || "-_.".contains(c) {
                c
            } else {
                '_'
            }
        })
        .collect();
    let name = name.trim_start_matches('.');
    if name.is_empty() {
        "run".into()
    } else {
        name.chars().take(100).collect()
    }
}

/// `stancf run`: reads the scenario file and runs it ([`run_text`]).
pub fn run(path: &Path, opts: RunOptions) -> Result<(), Failure> {
    let text = crate::input_file::read_text(path)
        .map_err(|e| Failure::Input(format!("{}: {e}", path.display())))?;
    run_text(&text, path, opts)
}

/// Runs scenario text (`path` names it in messages and gives the default
/// output folder and title). The results are written as one transaction
/// ([`ResultFolder`]): the output folder holds the complete old set until
/// the complete new one replaces it, the scenario text included
/// (`scenario.toml`), also when the solver fails or the run is
/// interrupted; an invalid scenario or a write error leaves it untouched.
pub fn run_text(text: &str, path: &Path, opts: RunOptions) -> Result<(), Failure> {
    let file = path.display().to_string();
    if let Input::System(sc) = crate::scenario::parse_input_with(text, &file, path, &opts.host)
        .map_err(|e| Failure::Input(e.0))?
    {
        return in_result_folder(text, path, &opts, |place| {
            system::run_system(path, place, &opts, *sc)
        });
    }
    let (sc, model, state) = load_text(text, path)?;
    crate::work_bounds::admit(path, &sc, opts.vtk, opts.allow_large)?;
    // Everything that can refuse the input is decided before anything is
    // written.
    let derived = match sc.analysis.kind {
        AnalysisKind::Dynamic => {
            let d = derive(&sc, &model, &state);
            crate::check::check_derived(path, &d)?;
            Some(d)
        }
        AnalysisKind::Static => None,
    };
    in_result_folder(text, path, &opts, |place| match sc.analysis.kind {
        AnalysisKind::Dynamic => {
            let d = derived.expect("derived for every dynamic run");
            dynamic::run_dynamic(path, place, &opts, sc, model, state, d)
        }
        AnalysisKind::Static => statics::run_static(path, place, &opts, sc, model),
    })
}

/// Runs `body` into the staging folder of the run's [`ResultFolder`]
/// (with the scenario text as `scenario.toml`), then commits it, draws
/// the figures if asked, and prints the report `body` returns. An input
/// or write error leaves the output folder untouched; a solver failure or
/// an interruption commits the results up to it.
fn in_result_folder(
    text: &str,
    path: &Path,
    opts: &RunOptions,
    body: impl FnOnce(&Place) -> Result<String, Failure>,
) -> Result<(), Failure> {
    let target = output_dir(path, opts.out.clone());
    let folder = ResultFolder::open(&target)?;
    let place = Place {
        dir: folder.staging(),
        shown: opts.shown_as.as_deref().unwrap_or(folder.target()),
        collect: opts.collect.as_ref(),
    };
    place
        .dest()
        .write("scenario.toml", text.as_bytes())
        .map_err(io_err(place.shown))?;
    let result = body(&place);
    if let Err(Failure::Input(_) | Failure::Other(_)) = result {
        return result.map(|_| ());
    }
    // The figures are drawn from the new files, also those of a run that
    // stopped early (they hold every converged step).
    let figures = opts.plot.as_ref().map(|draw| (draw.0)(place.dir));
    folder.commit().map_err(io_err(&target))?;
    if let Ok(report) = &result {
        print!("{report}");
    }
    match figures {
        Some(Ok(names)) => println!(
            "figures: {} (PNG and SVG) in {}",
            names.join(", "),
            target.display()
        ),
        Some(Err(e)) => return Err(io_err(&target)(e)),
        None => {}
    }
    result.map(|_| ())
}

/// How the times of a dynamic run of `a` are written: k dt in the
/// decimals of the step and the duration as the user wrote them (a run
/// starts at t = 0; see [`crate::output::TimeGrid`]).
pub(crate) fn times_of(a: &crate::scenario::Analysis) -> crate::output::TimeGrid {
    crate::output::TimeGrid::of(&[a.time_step, a.duration])
}
