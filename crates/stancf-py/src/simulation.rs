//! `stancf._stancf.Simulation`: a system stepped by a coupling code, the
//! Rust handle `stancf::coupling::CoupledSystem` (docs/method.md §13)
//! with its arrays as Python lists (the Python class `stancf.Simulation`
//! turns them into numpy arrays). Nothing here touches a file; stepping
//! and the static solve run without the GIL.

use crate::{RunFailed, ScenarioError};
use pyo3::exceptions::{PyIndexError, PyKeyboardInterrupt};
use pyo3::prelude::*;
use stancf::coupling::{CoupledForces, CoupledState, CoupledSystem, CouplingError};
use std::path::PathBuf;

/// A coupling error as a Python exception: bad input as ScenarioError,
/// a failed step as RunFailed(message, time, step, residual).
fn coupling_err(e: CouplingError) -> PyErr {
    match e {
        CouplingError::Input(m) => ScenarioError::new_err(m.to_string()),
        CouplingError::Solver(s) => RunFailed::new_err((s.to_string(), s.time, s.step, s.residual)),
        e @ CouplingError::Interrupted { .. } => PyKeyboardInterrupt::new_err(e.to_string()),
    }
}

/// A line's node positions, velocities (flat, 3 per node), axial forces
/// and curvatures.
type LineArrays = (Vec<f64>, Vec<f64>, Vec<f64>, Vec<f64>);

/// The native coupled system (see `stancf.Simulation`).
#[pyclass(module = "stancf._stancf", name = "Simulation")]
pub struct PySimulation {
    handle: CoupledSystem,
    coupled_ids: Vec<i64>,
    line_ids: Vec<i64>,
    point_ids: Vec<i64>,
    last: Option<CoupledForces>,
}

/// A saved state of a Simulation (opaque).
#[pyclass(module = "stancf._stancf", name = "SimulationState")]
pub struct PyState(CoupledState);

#[pymethods]
impl PySimulation {
    /// The coupled system of scenario or deck text; `path` names it in
    /// messages and resolves the files it refers to.
    #[new]
    fn new(text: &str, path: PathBuf) -> PyResult<Self> {
        let opened = stancf_cli::coupling::from_text(text, &path)
            .map_err(|e| ScenarioError::new_err(e.to_string()))?;
        Ok(PySimulation {
            handle: opened.handle,
            coupled_ids: opened.coupled_ids,
            line_ids: opened.line_ids,
            point_ids: opened.point_ids,
            last: None,
        })
    }

    #[getter]
    fn coupled_dof(&self) -> usize {
        self.handle.coupled_dof()
    }

    #[getter]
    fn coupled_ids(&self) -> Vec<i64> {
        self.coupled_ids.clone()
    }

    #[getter]
    fn line_ids(&self) -> Vec<i64> {
        self.line_ids.clone()
    }

    #[getter]
    fn point_ids(&self) -> Vec<i64> {
        self.point_ids.clone()
    }

    #[getter]
    fn time(&self) -> f64 {
        self.handle.time()
    }

    /// The mean forces of the last `step_to` over its interval (None
    /// before the first).
    #[getter]
    fn interval_mean_force(&self) -> Option<Vec<f64>> {
        self.last.as_ref().map(|f| f.interval_mean.clone())
    }

    /// The steps the last `step_to` took (0 before the first).
    #[getter]
    fn last_steps(&self) -> usize {
        self.last.as_ref().map_or(0, |f| f.steps)
    }

    #[pyo3(signature = (x, xd = None))]
    fn initialize(
        &mut self,
        py: Python<'_>,
        x: Vec<f64>,
        xd: Option<Vec<f64>>,
    ) -> PyResult<Vec<f64>> {
        let handle = &mut self.handle;
        let forces = py
            .allow_threads(|| handle.initialize(&x, xd.as_deref()))
            .map_err(coupling_err)?;
        self.last = None;
        Ok(forces)
    }

    #[pyo3(signature = (t, x, xd = None))]
    fn step_to(
        &mut self,
        py: Python<'_>,
        t: f64,
        x: Vec<f64>,
        xd: Option<Vec<f64>>,
    ) -> PyResult<Vec<f64>> {
        let handle = &mut self.handle;
        let forces = py
            .allow_threads(|| handle.step_to(t, &x, xd.as_deref()))
            .map_err(coupling_err)?;
        let out = forces.last_step.clone();
        self.last = Some(forces);
        Ok(out)
    }

    fn save(&self) -> PyState {
        PyState(self.handle.save())
    }

    fn restore(&mut self, state: &PyState) -> PyResult<()> {
        self.handle.restore(&state.0).map_err(coupling_err)?;
        self.last = None;
        Ok(())
    }

    /// Point `index`'s (in the order of `point_ids`) position, velocity
    /// and the net force of its lines on it.
    fn point_arrays(&self, index: usize) -> PyResult<([f64; 3], [f64; 3], [f64; 3])> {
        let p = self.handle.point(index).ok_or_else(|| {
            PyIndexError::new_err(format!("no point {index} (or not initialized)"))
        })?;
        Ok((p.position, p.velocity, p.force))
    }

    /// Line `index`'s (in the order of `line_ids`) node positions, node
    /// velocities (flat, 3 per node), axial forces and curvatures.
    fn line_arrays(&self, index: usize) -> PyResult<LineArrays> {
        let missing = || PyIndexError::new_err(format!("no line {index} (or not initialized)"));
        let flat = |v: Vec<[f64; 3]>| v.into_iter().flatten().collect::<Vec<f64>>();
        let h = &self.handle;
        Ok((
            flat(h.line_nodes(index).ok_or_else(missing)?),
            flat(h.line_velocities(index).ok_or_else(missing)?),
            h.line_tensions(index).ok_or_else(missing)?,
            h.line_curvatures(index).ok_or_else(missing)?,
        ))
    }
}
