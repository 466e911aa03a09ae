//! The grid of `stancf sweep`: the scenario files (several make one more
//! axis, `scenario`, the slowest), the `--set` axes, each point's text,
//! the runs, and the tables sweep.csv and extremes.csv.

use super::extremes::{extremes_csv, seed_axis, RunRow};
use super::figures::{self, columns, figures, FIGURES, SYSTEM_FIGURES};
use super::{apply, cell, check_keys, csv_field, grid_size, parse_set, point, Axis};
use crate::output::Num;
use crate::run::{run_text, RunOptions};
use crate::scenario;
use crate::Failure;
use std::fmt::Write as _;
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::Mutex;

/// The name of the axis of the scenario files, when a sweep has several.
pub const SCENARIO_AXIS: &str = "scenario";

/// The TOML document a sweep varies: the scenario's own, or for a bare
/// MoorDyn deck a scenario that takes it (`[system] moordyn = "<deck>"`,
/// resolved beside the deck), so that its keys reach what a system
/// scenario adds to a deck (`water.jonswap.hs`, `motions.0.amplitude`,
/// `analysis.duration`, `output.statistics_after`, `system.mbl.<type>`).
/// A MoorDyn driver file is refused: the scenario that takes its deck is
/// what a sweep varies.
pub fn base_document(text: &str, path: &Path) -> Result<toml::Table, String> {
    let file = path.display().to_string();
    if scenario::is_moordyn_driver(text) {
        return Err(format!(
            "{file}: a MoorDyn driver file is not swept; sweep a scenario that takes its deck \
             ([system] moordyn = \"...\", with the driver's [analysis] and [[motions]])"
        ));
    }
    if crate::moordyn::looks_like_moordyn(text) {
        let name = path
            .file_name()
            .map(|n| n.to_string_lossy().into_owned())
            .unwrap_or_default();
        let mut system = toml::Table::new();
        system.insert("moordyn".into(), toml::Value::String(name));
        let mut doc = toml::Table::new();
        doc.insert("system".into(), toml::Value::Table(system));
        return Ok(doc);
    }
    text.parse()
        .map_err(|e: toml::de::Error| format!("{file}: {e}"))
}

/// One scenario file of a sweep: where it is (its relative files are
/// resolved beside it), its name in messages and its document.
struct Base {
    path: PathBuf,
    file: String,
    doc: toml::Table,
}

impl Base {
    /// Reads and validates the file at `path` as it is (a bare deck's
    /// errors are its own), then its document; whether it is a system.
    fn read(path: &Path) -> Result<(Base, bool), Failure> {
        let file = path.display().to_string();
        let text = crate::input_file::read_text(path)
            .map_err(|e| Failure::Input(format!("{file}: {e}")))?;
        let doc = base_document(&text, path).map_err(Failure::Input)?;
        scenario::parse_input(&text, &file, path).map_err(|e| Failure::Input(e.0))?;
        let whole = toml::to_string(&doc).map_err(|e| Failure::Other(format!("{file}: {e}")))?;
        let system = matches!(
            scenario::parse_input(&whole, &file, path).map_err(|e| Failure::Input(e.0))?,
            scenario::Input::System(_)
        );
        let path = path.to_path_buf();
        Ok((Base { path, file, doc }, system))
    }
}

/// How a run of the sweep ended: its status (`ok`, `failed`,
/// `interrupted`) and message; None if it never started.
pub(super) type Outcome = Option<(&'static str, String)>;

/// The grid of a sweep: the scenario files, the axes, how many points.
pub(super) struct Grid {
    bases: Vec<Base>,
    axes: Vec<Axis>,
    /// The points of one scenario file's grid (the axes' product).
    per_file: usize,
    pub(super) points: usize,
    /// Whether the scenarios are systems of lines (their rows' figures
    /// are a system's, [`figures`]).
    system: bool,
}

/// sweep.csv's text (and extremes.csv's, with a seed axis), the runs
/// that failed and whether any was cut short.
pub(super) struct Table {
    pub(super) csv: String,
    pub(super) extremes: Option<String>,
    pub(super) failed: Vec<usize>,
    pub(super) interrupted: bool,
}

impl Grid {
    /// The scenario files at `paths` and the axes of `sets`; every point
    /// is built and validated before anything runs, one at a time and
    /// then dropped (its run builds the text again).
    pub(super) fn read(paths: &[PathBuf], sets: &[String]) -> Result<Grid, Failure> {
        if sets.is_empty() && paths.len() < 2 {
            return Err(Failure::Input(
                "sweep: give at least one --set key=v1,v2,... (or several scenario files)".into(),
            ));
        }
        let mut bases = Vec::with_capacity(paths.len());
        let mut kinds = Vec::with_capacity(paths.len());
        for p in paths {
            let (base, system) = Base::read(p)?;
            bases.push(base);
            kinds.push(system);
        }
        if kinds.iter().any(|&s| s != kinds[0]) {
            let systems: Vec<&str> = (bases.iter().zip(&kinds))
                .filter(|(_, s)| **s)
                .map(|(b, _)| b.file.as_str())
                .collect();
            return Err(Failure::Input(format!(
                "sweep: the scenario files are systems of lines ({}) and single cables (the \
                 others); a sweep's files are all of one kind, their rows of one table",
                systems.join(", ")
            )));
        }
        let axes: Vec<Axis> = sets
            .iter()
            .map(|s| parse_set(s))
            .collect::<Result<_, _>>()
            .map_err(Failure::Input)?;
        let keys: Vec<&str> = axes.iter().map(|a| a.key.as_str()).collect();
        check_keys(&keys).map_err(Failure::Input)?;
        if axes.iter().any(|a| a.key == SCENARIO_AXIS) && bases.len() > 1 {
            return Err(Failure::Input(format!(
                "sweep: --set {SCENARIO_AXIS}: the key names the axis of the scenario files"
            )));
        }
        let lengths: Vec<usize> = axes.iter().map(|a| a.values.len()).collect();
        let per_file = grid_size(&lengths).map_err(Failure::Input)?;
        let points = grid_size(&[bases.len(), per_file]).map_err(Failure::Input)?;
        let grid = Grid {
            bases,
            axes,
            per_file,
            points,
            system: kinds[0],
        };
        for k in 0..points {
            let (text, name, path) = grid.point_text(k)?;
            scenario::parse_input(&text, &name, path).map_err(|e| Failure::Input(e.0))?;
        }
        Ok(grid)
    }

    /// The scenario text of point `k` (the file's document with the
    /// point's values put in), its name for messages (`file with
    /// key=value, ...`) and the file's path.
    fn point_text(&self, k: usize) -> Result<(String, String, &Path), Failure> {
        let base = &self.bases[k / self.per_file];
        let file = &base.file;
        let values = point(&self.axes, k % self.per_file);
        let mut doc = base.doc.clone();
        for (a, v) in self.axes.iter().zip(&values) {
            apply(&mut doc, &a.key, (*v).clone())
                .map_err(|e| Failure::Input(format!("{file}: --set {}: {e}", a.key)))?;
        }
        let text =
            toml::to_string(&doc).map_err(|e| Failure::Other(format!("{file}: run {k}: {e}")))?;
        let label: Vec<String> = (self.axes.iter().zip(&values))
            .map(|(a, v)| format!("{}={}", a.key, cell(v)))
            .collect();
        let name = if label.is_empty() {
            file.clone()
        } else {
            format!("{file} with {}", label.join(", "))
        };
        Ok((text, name, &base.path))
    }

    /// The axis values of point `k` as sweep.csv writes them: its
    /// scenario file first where there are several.
    fn cells(&self, k: usize) -> Vec<String> {
        let mut cells = Vec::with_capacity(self.axes.len() + 1);
        if self.bases.len() > 1 {
            cells.push(self.bases[k / self.per_file].file.clone());
        }
        cells.extend(point(&self.axes, k % self.per_file).into_iter().map(cell));
        cells
    }

    /// The axes' names: `scenario` first where there are several files.
    fn keys(&self) -> Vec<String> {
        let files = (self.bases.len() > 1).then(|| SCENARIO_AXIS.to_string());
        files
            .into_iter()
            .chain(self.axes.iter().map(|a| a.key.clone()))
            .collect()
    }

    /// Runs every point into `dir/run_<k>`, `jobs` at a time; after
    /// Ctrl-C or SIGTERM no further run starts. Messages name the folders
    /// as they will be after the sweep's commit, under `target`.
    pub(super) fn run_all(&self, dir: &Path, target: &Path, jobs: usize) -> Vec<Outcome> {
        let cancel = crate::signals::cancel();
        let next = AtomicUsize::new(0);
        let outcomes: Mutex<Vec<Outcome>> = Mutex::new(vec![None; self.points]);
        std::thread::scope(|s| {
            for _ in 0..jobs {
                s.spawn(|| loop {
                    if (cancel.0)() {
                        break;
                    }
                    let k = next.fetch_add(1, Ordering::SeqCst);
                    if k >= self.points {
                        break;
                    }
                    // The run writes its results and its scenario.toml.
                    let run_dir = format!("run_{k:04}");
                    let result = self.point_text(k).and_then(|(text, _, path)| {
                        run_text(
                            &text,
                            path,
                            RunOptions {
                                out: Some(dir.join(&run_dir)),
                                quiet: true,
                                cancel: Some(cancel.clone()),
                                shown_as: Some(target.join(&run_dir)),
                                ..RunOptions::default()
                            },
                        )
                    });
                    let outcome = match result {
                        Ok(()) => ("ok", String::new()),
                        Err(Failure::Interrupted(m)) => ("interrupted", m),
                        Err(e) => ("failed", e.to_string()),
                    };
                    outcomes.lock().expect("no run panics holding it")[k] = Some(outcome);
                });
            }
        });
        outcomes.into_inner().expect("all runs joined")
    }

    /// sweep.csv: a row per run with its point, status, the figures of
    /// its summary.json ([`figures`]: the columns every run has, then
    /// those some run has) and its error; and extremes.csv where an axis
    /// is a seed ([`seed_axis`]).
    pub(super) fn table(&self, dir: &Path, outcomes: Vec<Outcome>) -> Table {
        let figures: Vec<Vec<(String, Option<f64>)>> = (0..outcomes.len())
            .map(|k| {
                std::fs::read_to_string(dir.join(format!("run_{k:04}")).join("summary.json"))
                    .ok()
                    .and_then(|t| serde_json::from_str(&t).ok())
                    .map(|s| figures(&s))
                    .unwrap_or_default()
            })
            .collect();
        let names = self.columns(&figures);
        let keys = self.keys();
        let mut csv = String::from("run");
        for key in &keys {
            write!(csv, ",{}", csv_field(key)).ok();
        }
        csv.push_str(",status");
        for name in &names {
            write!(csv, ",{}", csv_field(name)).ok();
        }
        csv.push_str(",error\n");
        let mut failed = Vec::new();
        let mut interrupted = false;
        let mut rows = Vec::with_capacity(outcomes.len());
        for (k, outcome) in outcomes.into_iter().enumerate() {
            let (status, error) = outcome.unwrap_or_else(|| {
                (
                    "not run",
                    "the sweep was interrupted before this run started".into(),
                )
            });
            let cells = self.cells(k);
            write!(csv, "{k}").ok();
            for c in &cells {
                write!(csv, ",{}", csv_field(c)).ok();
            }
            write!(csv, ",{status}").ok();
            for name in &names {
                let v = figures::value(&figures[k], name);
                write!(
                    csv,
                    ",{}",
                    v.map(|v| Num(v).to_string()).unwrap_or_default()
                )
                .ok();
            }
            writeln!(csv, ",{}", csv_field(&error)).ok();
            match status {
                "ok" => {}
                "failed" => failed.push(k),
                _ => interrupted = true,
            }
            rows.push(RunRow {
                cells,
                ok: status == "ok",
                figures: &figures[k],
            });
        }
        let extremes = seed_axis(&keys).map(|seed| extremes_csv(&keys, seed, &names, &rows));
        Table {
            csv,
            extremes,
            failed,
            interrupted,
        }
    }

    /// The figure columns of sweep.csv: those of the scenarios' kind
    /// (single cable or system), then the design statistics' in the order
    /// the runs first give them.
    fn columns(&self, figures: &[Vec<(String, Option<f64>)>]) -> Vec<String> {
        let fixed: Vec<(String, Option<f64>)> = if self.system {
            SYSTEM_FIGURES
                .iter()
                .map(|(n, _)| (n.to_string(), None))
                .collect()
        } else {
            FIGURES.iter().map(|(n, _)| (n.to_string(), None)).collect()
        };
        columns(std::iter::once(&fixed[..]).chain(figures.iter().map(|f| &f[..])))
    }
}
