//! `stancf._stancf`: the native part of the Python package. A thin layer
//! over `stancf_scenario`: the same scenario validation, the same run, the same
//! result files; the Python side (`python/stancf/__init__.py`) reads the
//! files into numpy arrays and runs sweeps on any executor.

mod results;
mod simulation;
mod sweeps;

use pyo3::create_exception;
use pyo3::exceptions::{PyException, PyKeyboardInterrupt, PyOSError, PyTypeError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::{PyBool, PyDict, PyFloat, PyInt, PyList, PyString, PyTuple};
use stancf_scenario::output::Collector;
use stancf_scenario::run::{run_text, Cancel, RunOptions};
use stancf_scenario::{scenario, sweep, Failure};
use std::path::{Path, PathBuf};
use std::sync::{Arc, Mutex};
use std::time::{Duration, Instant};

create_exception!(
    _stancf,
    ScenarioError,
    PyValueError,
    "A scenario or an argument that is not valid (a ValueError): the message names the key."
);
create_exception!(
    _stancf,
    RunFailed,
    PyException,
    "A run that stopped: the solver failed (results up to the last converged step are kept)."
);

fn scenario_err(e: scenario::ScenarioError) -> PyErr {
    ScenarioError::new_err(e.0)
}

/// Validates scenario text (`name` names it in messages): a single
/// cable, a system of lines, or a MoorDyn v2 deck.
#[pyfunction]
fn validate(text: &str, name: &str) -> PyResult<()> {
    scenario::parse_input(text, name, Path::new(name))
        .map(|_| ())
        .map_err(scenario_err)
}

/// Whether scenario text is a MoorDyn input (not TOML): a v2 deck, or
/// a MoorDyn driver file that names one.
#[pyfunction]
fn is_moordyn(text: &str) -> bool {
    stancf_scenario::moordyn::looks_like_moordyn(text)
        || stancf_scenario::moordyn::driver::looks_like_driver(text)
}

/// The text of an input file as the command line reads it: a regular
/// file of at most 64 MiB of UTF-8 (`stancf_scenario::input_file`); anything
/// else raises ScenarioError naming the file.
#[pyfunction]
fn read_input(path: PathBuf) -> PyResult<String> {
    stancf_scenario::input_file::read_text(&path)
        .map_err(|e| ScenarioError::new_err(format!("{}: {e}", path.display())))
}

/// A Python value as a TOML value.
fn to_toml(v: &Bound<'_, PyAny>, key: &str) -> PyResult<toml::Value> {
    if v.is_instance_of::<PyBool>() {
        return Ok(toml::Value::Boolean(v.extract()?));
    }
    if v.is_instance_of::<PyInt>() {
        return Ok(toml::Value::Integer(v.extract()?));
    }
    if v.is_instance_of::<PyFloat>() {
        return Ok(toml::Value::Float(v.extract()?));
    }
    if v.is_instance_of::<PyString>() {
        return Ok(toml::Value::String(v.extract()?));
    }
    if let Ok(d) = v.downcast::<PyDict>() {
        return Ok(toml::Value::Table(dict_to_table(d, key)?));
    }
    if v.is_instance_of::<PyList>() || v.is_instance_of::<PyTuple>() {
        let items: PyResult<Vec<toml::Value>> = v.try_iter()?.map(|x| to_toml(&x?, key)).collect();
        return Ok(toml::Value::Array(items?));
    }
    // numpy scalars and anything else that is a number.
    if let Ok(x) = v.extract::<f64>() {
        return Ok(toml::Value::Float(x));
    }
    Err(PyTypeError::new_err(format!(
        "{key}: cannot put a {} into a scenario",
        v.get_type().name()?
    )))
}

fn dict_to_table(d: &Bound<'_, PyDict>, prefix: &str) -> PyResult<toml::Table> {
    let mut t = toml::Table::new();
    for (k, v) in d.iter() {
        let k: String = k.extract()?;
        let key = if prefix.is_empty() {
            k.clone()
        } else {
            format!("{prefix}.{k}")
        };
        t.insert(k, to_toml(&v, &key)?);
    }
    Ok(t)
}

/// A scenario dictionary (the keys of the TOML contract) as TOML text.
#[pyfunction]
fn dict_to_toml(d: &Bound<'_, PyDict>) -> PyResult<String> {
    let t = dict_to_table(d, "")?;
    toml::to_string(&t).map_err(|e| ScenarioError::new_err(e.to_string()))
}

/// Scenario text with dotted keys set (`{"analysis.time_step": 1e-4,
/// "loads.1.drag_coefficient": 0.5}`), validated. A MoorDyn deck's keys
/// are set in the scenario that takes it (`[system] moordyn = "<deck>"`,
/// `name` the deck's path), as a sweep varies it.
#[pyfunction]
fn with_values(text: &str, name: &str, values: &Bound<'_, PyDict>) -> PyResult<String> {
    let mut doc = sweep::base_document(text, Path::new(name)).map_err(ScenarioError::new_err)?;
    for (k, v) in values.iter() {
        let key: String = k.extract()?;
        let value = to_toml(&v, &key)?;
        sweep::apply(&mut doc, &key, value)
            .map_err(|e| ScenarioError::new_err(format!("{name}: {key}: {e}")))?;
    }
    let out = toml::to_string(&doc).map_err(|e| ScenarioError::new_err(e.to_string()))?;
    scenario::parse_input(&out, name, Path::new(name)).map_err(scenario_err)?;
    Ok(out)
}

/// Runs scenario text into the folder `out` (its `scenario.toml` and the
/// result files of docs/interface.md), with the GIL released, and returns
/// the files as they were written (see [`results::files`]; none unless
/// `collect`). Ctrl-C stops
/// the run after the current step (KeyboardInterrupt; the files up to it
/// are kept); a solver failure raises RunFailed(message, files) (the
/// files up to the last converged step are kept).
#[pyfunction]
#[pyo3(signature = (text, name, out, progress = false, allow_large = false, collect = true))]
fn run(
    py: Python<'_>,
    text: &str,
    name: &str,
    out: PathBuf,
    progress: bool,
    allow_large: bool,
    collect: bool,
) -> PyResult<Vec<results::File>> {
    // The run validates the text and writes it, as scenario.toml, with its
    // results into `out`, replaced whole (one transaction).
    // Python's signal handlers run only with the GIL: take it for a
    // moment, at most ten times a second, to see whether Ctrl-C came.
    let last = Mutex::new(Instant::now());
    let cancel = Cancel(Arc::new(move || {
        let mut l = last.lock().expect("not poisoned");
        if l.elapsed() < Duration::from_millis(100) {
            return false;
        }
        *l = Instant::now();
        Python::with_gil(|py| py.check_signals().is_err())
    }));
    let collector = Collector::default();
    let opts = RunOptions {
        out: Some(out.clone()),
        quiet: !progress,
        allow_large,
        cancel: Some(cancel),
        collect: collect.then(|| collector.clone()),
        ..RunOptions::default()
    };
    let result = py.allow_threads(|| run_text(text, Path::new(name), opts));
    match result {
        Ok(()) => Ok(results::files(py, collector.take())),
        Err(Failure::Input(m)) => Err(ScenarioError::new_err(m)),
        Err(Failure::Solver(m)) => Err(RunFailed::new_err((
            m,
            results::files(py, collector.take()),
        ))),
        Err(Failure::Interrupted(m)) => Err(PyKeyboardInterrupt::new_err(m)),
        Err(Failure::Other(m)) => Err(PyOSError::new_err(m)),
    }
}

/// The summary figures a sweep gathers: (name, path in summary.json),
/// the same list as `stancf sweep`'s sweep.csv.
#[pyfunction]
fn sweep_figures() -> Vec<(&'static str, Vec<&'static str>)> {
    sweep::FIGURES
        .iter()
        .map(|(n, p)| (*n, p.to_vec()))
        .collect()
}

/// The number of points of a sweep grid, checked as `stancf sweep` checks
/// its `--set`s: `keys` (distinct, none inside another) and the lengths
/// of their value lists (a list of points: no keys and `[len]`).
/// ScenarioError above `SWEEP_LIMIT` points, counted before any is built.
#[pyfunction]
fn sweep_points(keys: Vec<String>, lengths: Vec<usize>) -> PyResult<usize> {
    let keys: Vec<&str> = keys.iter().map(String::as_str).collect();
    sweep::check_keys(&keys).map_err(ScenarioError::new_err)?;
    sweep::grid_size(&lengths).map_err(ScenarioError::new_err)
}

/// A result folder written as one transaction (`stancf_scenario`'s
/// `ResultFolder`, as `stancf run` and `stancf sweep` write theirs):
/// `ResultFolder(target)` locks `target` (ScenarioError if another run or
/// sweep is writing into it, or if it is a folder of a user's files) and
/// makes an empty private folder beside it, `staging`, for the whole new
/// set; `commit()` swaps it in at once (the old set, with everything in
/// it, is gone); `abort()`, or dropping the object, deletes it and leaves
/// `target` as it was.
#[pyclass(module = "stancf._stancf", name = "ResultFolder")]
struct PyResultFolder(Option<stancf_scenario::output::ResultFolder>);

#[pymethods]
impl PyResultFolder {
    #[new]
    fn new(target: PathBuf) -> PyResult<Self> {
        match stancf_scenario::output::ResultFolder::open(&target) {
            Ok(f) => Ok(PyResultFolder(Some(f))),
            Err(Failure::Input(m)) => Err(ScenarioError::new_err(m)),
            Err(e) => Err(PyOSError::new_err(e.to_string())),
        }
    }

    /// Where the new set is written.
    #[getter]
    fn staging(&self) -> PyResult<PathBuf> {
        self.open().map(|f| f.staging().to_path_buf())
    }

    /// Swaps the new set in and releases the lock.
    fn commit(&mut self) -> PyResult<()> {
        self.open()?;
        let f = self.0.take().expect("open");
        let target = f.target().to_path_buf();
        f.commit()
            .map_err(|e| PyOSError::new_err(format!("{}: {e}", target.display())))
    }

    /// Deletes the new set and releases the lock; `target` is untouched.
    fn abort(&mut self) {
        self.0.take();
    }
}

impl PyResultFolder {
    fn open(&self) -> PyResult<&stancf_scenario::output::ResultFolder> {
        self.0
            .as_ref()
            .ok_or_else(|| PyOSError::new_err("this result folder is already committed or aborted"))
    }
}

#[pymodule]
fn _stancf(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add("ScenarioError", m.py().get_type::<ScenarioError>())?;
    m.add("RunFailed", m.py().get_type::<RunFailed>())?;
    m.add("__version__", env!("CARGO_PKG_VERSION"))?;
    m.add_function(wrap_pyfunction!(validate, m)?)?;
    m.add_function(wrap_pyfunction!(read_input, m)?)?;
    m.add_function(wrap_pyfunction!(is_moordyn, m)?)?;
    m.add_function(wrap_pyfunction!(dict_to_toml, m)?)?;
    m.add_function(wrap_pyfunction!(with_values, m)?)?;
    m.add_function(wrap_pyfunction!(run, m)?)?;
    m.add_function(wrap_pyfunction!(sweep_figures, m)?)?;
    m.add_function(wrap_pyfunction!(sweep_points, m)?)?;
    m.add_function(wrap_pyfunction!(sweeps::sweep_base, m)?)?;
    m.add_function(wrap_pyfunction!(sweeps::summary_figures, m)?)?;
    m.add_function(wrap_pyfunction!(sweeps::sweep_columns, m)?)?;
    m.add_function(wrap_pyfunction!(sweeps::sweep_extremes, m)?)?;
    m.add("SWEEP_LIMIT", sweep::MAX_POINTS)?;
    m.add_class::<PyResultFolder>()?;
    m.add_class::<simulation::PySimulation>()?;
    m.add_class::<simulation::PyState>()?;
    Ok(())
}
