//! The sweep's tables for the Python package's `stancf.sweep`
//! (`python/stancf/sweeps.py`): the document a sweep varies, each run's
//! figures from its summary.json, sweep.csv's columns and extremes.csv,
//! computed by `stancf_scenario::sweep` as for `stancf sweep`.

use crate::ScenarioError;
use pyo3::prelude::*;
use stancf_scenario::{scenario, sweep};
use std::path::Path;

/// One run's figures: (column, value or None).
type Figures = Vec<(String, Option<f64>)>;

/// The scenario a sweep varies, as TOML text (a bare MoorDyn deck's is
/// `[system] moordyn = "<deck>"`, `name` its path), and whether it is a
/// system of lines. ScenarioError for a driver file or a scenario that is
/// not valid.
#[pyfunction]
pub(crate) fn sweep_base(text: &str, name: &str) -> PyResult<(String, bool)> {
    let path = Path::new(name);
    let doc = sweep::base_document(text, path).map_err(ScenarioError::new_err)?;
    let base = toml::to_string(&doc).map_err(|e| ScenarioError::new_err(e.to_string()))?;
    let input =
        scenario::parse_input(&base, name, path).map_err(|e| ScenarioError::new_err(e.0))?;
    Ok((base, matches!(input, scenario::Input::System(_))))
}

/// A run's figures from the text of its summary.json (the cells of its
/// sweep.csv row).
#[pyfunction]
pub(crate) fn summary_figures(summary: &str) -> PyResult<Figures> {
    let v: serde_json::Value =
        serde_json::from_str(summary).map_err(|e| ScenarioError::new_err(e.to_string()))?;
    Ok(sweep::figures(&v))
}

/// sweep.csv's figure columns: a single cable's or a system's fixed ones,
/// then those the runs' figures add, in the order they first appear.
#[pyfunction]
pub(crate) fn sweep_columns(system: bool, rows: Vec<Figures>) -> Vec<String> {
    let fixed: Figures = if system {
        sweep::SYSTEM_FIGURES
            .iter()
            .map(|(n, _)| (n.to_string(), None))
            .collect()
    } else {
        sweep::FIGURES
            .iter()
            .map(|(n, _)| (n.to_string(), None))
            .collect()
    };
    sweep::columns(std::iter::once(&fixed[..]).chain(rows.iter().map(|r| &r[..])))
}

/// extremes.csv's text for a sweep over `keys` whose rows are (their axis
/// values as text, whether the run ended well, its figures), or None
/// without a seed axis.
#[pyfunction]
pub(crate) fn sweep_extremes(
    keys: Vec<String>,
    columns: Vec<String>,
    rows: Vec<(Vec<String>, bool, Figures)>,
) -> Option<String> {
    let seed = sweep::seed_axis(&keys)?;
    let rows: Vec<sweep::RunRow> = rows
        .iter()
        .map(|(cells, ok, figures)| sweep::RunRow {
            cells: cells.clone(),
            ok: *ok,
            figures,
        })
        .collect();
    Some(sweep::extremes_csv(&keys, seed, &columns, &rows))
}
