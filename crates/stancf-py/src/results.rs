//! The result files of a run handed to Python from memory
//! (`RunOptions::collect`): each file's name in the run's folder, its
//! bytes (the very bytes written to disk) and, for a numeric CSV file,
//! its table parsed in Rust (`stancf_scenario::results::FlatTable`: header,
//! row count and the values as little-endian f64 bytes, which numpy takes
//! without a copy per value). Reading them is reading the files: the same
//! bytes, parsed correctly rounded as Python's `float` parses them.

use pyo3::prelude::*;
use pyo3::types::PyBytes;
use stancf_scenario::results::FlatTable;
use std::collections::BTreeMap;

/// One file: (name, bytes, numeric table or None).
pub type File = (
    String,
    Py<PyBytes>,
    Option<(Vec<String>, usize, Py<PyBytes>)>,
);

/// The collected files as Python values (CSV files whose fields are not
/// all numbers, as tensions.csv's ends "A" and "B", come without a table).
pub fn files(py: Python<'_>, collected: BTreeMap<String, Vec<u8>>) -> Vec<File> {
    collected
        .into_iter()
        .map(|(name, bytes)| {
            let table = name
                .ends_with(".csv")
                .then(|| std::str::from_utf8(&bytes).ok())
                .flatten()
                .and_then(|text| FlatTable::parse(text, &name).ok())
                .map(|t| {
                    let values: Vec<u8> = t.values.iter().flat_map(|v| v.to_le_bytes()).collect();
                    (t.header, t.rows, PyBytes::new(py, &values).unbind())
                });
            (name, PyBytes::new(py, &bytes).unbind(), table)
        })
        .collect()
}
