//! `stancf._stancf.Simulation`: a system stepped by a coupling code, the
//! Rust handle `stancf::coupling::CoupledSystem` (docs/method.md §13)
//! with its arrays as Python lists (the Python class `stancf.Simulation`
//! checks the arguments and turns the arrays into numpy arrays). Nothing
//! here touches a file; stepping and the static solve run without the
//! GIL and stop at Ctrl-C between two internal steps. A Simulation is
//! used by one thread at a time: a call while another thread is inside
//! one is refused with a RuntimeError saying so.

use crate::{RunFailed, ScenarioError};
use pyo3::exceptions::{PyIndexError, PyKeyboardInterrupt, PyRuntimeError, PyValueError};
use pyo3::prelude::*;
use stancf::coupling::{CoupledForces, CoupledState, CoupledSystem, CouplingError};
use std::path::PathBuf;
use std::sync::{Mutex, MutexGuard, TryLockError};
use std::time::{Duration, Instant};

/// A coupling error as a Python exception: bad input as ScenarioError (a
/// ValueError), a failed step as RunFailed(message, time, step,
/// residual), an interruption as KeyboardInterrupt.
fn coupling_err(e: CouplingError) -> PyErr {
    match e {
        CouplingError::Input(m) => ScenarioError::new_err(m.to_string()),
        CouplingError::Solver(s) => RunFailed::new_err((s.to_string(), s.time, s.step, s.residual)),
        e @ CouplingError::Interrupted { .. } => PyKeyboardInterrupt::new_err(e.to_string()),
    }
}

/// How often a call without the GIL runs Python's signal handlers: every
/// few ms of wall time, so Ctrl-C answers at once while a step of a few
/// microseconds does not wait for the GIL each time.
const SIGNAL_CHECK_EVERY: Duration = Duration::from_millis(5);

/// Python's signal handlers, run from a call without the GIL between its
/// steps; the exception one raised (KeyboardInterrupt for Ctrl-C) is
/// kept for the call to raise.
struct Signals {
    checked: Option<Instant>,
    raised: Option<PyErr>,
}

impl Signals {
    fn new() -> Self {
        Signals {
            checked: None,
            raised: None,
        }
    }

    /// Whether a signal handler raised: checked with the GIL at most every
    /// [`SIGNAL_CHECK_EVERY`].
    fn raised(&mut self) -> bool {
        if self
            .checked
            .is_some_and(|t| t.elapsed() < SIGNAL_CHECK_EVERY)
        {
            return false;
        }
        self.checked = Some(Instant::now());
        if let Err(e) = Python::with_gil(|py| py.check_signals()) {
            self.raised = Some(e);
        }
        self.raised.is_some()
    }

    /// The error of a call that ran with these checks: the exception a
    /// signal handler raised when the call stopped for it.
    fn error(self, e: CouplingError) -> PyErr {
        match (e, self.raised) {
            (CouplingError::Interrupted { .. }, Some(raised)) => raised,
            (e, _) => coupling_err(e),
        }
    }
}

/// A line's node positions, velocities (flat, 3 per node), axial forces
/// and curvatures.
type LineArrays = (Vec<f64>, Vec<f64>, Vec<f64>, Vec<f64>);

/// The native coupled system (see `stancf.Simulation`): the handle behind
/// a lock, taken by one call at a time.
#[pyclass(module = "stancf._stancf", name = "Simulation", frozen)]
pub struct PySimulation {
    inner: Mutex<Inner>,
    /// The coupling arrays' length (the handle's).
    coupled_dof: usize,
    coupled_body_ids: Vec<i64>,
    coupled_ids: Vec<i64>,
    line_ids: Vec<i64>,
    point_ids: Vec<i64>,
    body_ids: Vec<i64>,
    failure_ids: Vec<i64>,
}

/// A line failure that happened (docs/method.md §11.16): its id, the
/// time, "time" or "tension", the tension that set it off, the released
/// lines' ids and the new point's id.
type Released = (i64, f64, &'static str, Option<f64>, Vec<i64>, i64);

/// What a call of a Simulation changes: the handle and the forces of its
/// last `step_to`.
struct Inner {
    handle: CoupledSystem,
    last: Option<CoupledForces>,
}

/// A saved state of a Simulation (opaque).
#[pyclass(module = "stancf._stancf", name = "SimulationState")]
pub struct PyState(CoupledState);

impl PySimulation {
    /// The handle for this call; refused while another thread is inside a
    /// call (pyo3 would say "Already mutably borrowed").
    fn inner(&self) -> PyResult<MutexGuard<'_, Inner>> {
        self.inner.try_lock().map_err(|e| match e {
            TryLockError::WouldBlock => PyRuntimeError::new_err(
                "a Simulation is used by one thread at a time; another thread is inside one of \
                 its calls: wait for that call to return, or give each thread its own \
                 Simulation",
            ),
            TryLockError::Poisoned(_) => PyRuntimeError::new_err(
                "this Simulation is unusable after an internal error in an earlier call (please \
                 report it); open a new one",
            ),
        })
    }
}

#[pymethods]
impl PySimulation {
    /// The coupled system of scenario or deck text; `path` names it in
    /// messages and resolves the files it refers to; `allow_large` opens
    /// a system beyond the element bound `stancf run` applies without
    /// `--allow-large` (the hard bound holds); the host's water depth,
    /// density and gravity fill what a MoorDyn deck leaves out.
    #[new]
    #[pyo3(signature = (text, path, allow_large = false, water_depth = None, water_density = None, gravity = None, turbines = None))]
    fn new(
        text: &str,
        path: PathBuf,
        allow_large: bool,
        water_depth: Option<f64>,
        water_density: Option<f64>,
        gravity: Option<f64>,
        turbines: Option<Vec<[f64; 3]>>,
    ) -> PyResult<Self> {
        let host = stancf_scenario::scenario::HostEnvironment {
            water_depth,
            water_density,
            gravity,
            turbines,
            sets_waves: false,
            run_length: None,
        };
        let opened = stancf_scenario::coupling::from_text_in(text, &path, allow_large, &host)
            .map_err(|e| ScenarioError::new_err(e.to_string()))?;
        Ok(PySimulation {
            coupled_dof: opened.handle.coupled_dof(),
            inner: Mutex::new(Inner {
                handle: opened.handle,
                last: None,
            }),
            coupled_body_ids: opened.coupled_body_ids,
            coupled_ids: opened.coupled_ids,
            line_ids: opened.line_ids,
            point_ids: opened.point_ids,
            body_ids: opened.body_ids,
            failure_ids: opened.failure_ids,
        })
    }

    /// The line failures that happened so far, in order (see
    /// [`Released`]).
    #[getter]
    fn releases(&self) -> PyResult<Vec<Released>> {
        let inner = self.inner()?;
        let events = stancf_scenario::scenario::failure_events(
            inner.handle.releases(),
            &self.failure_ids,
            (&self.line_ids, &self.point_ids),
        );
        Ok(events
            .into_iter()
            .map(|e| (e.failure, e.t, e.trigger, e.tension, e.lines, e.new_point))
            .collect())
    }

    /// 6 per coupled body (3 per body pinned to the host, MoorDyn's
    /// CoupledPinned), then 3 per coupled point.
    #[getter]
    fn coupled_dof(&self) -> usize {
        self.coupled_dof
    }

    /// The coupled bodies' ids, in the order of the coupling arrays
    /// (first, 6 numbers each).
    #[getter]
    fn coupled_body_ids(&self) -> Vec<i64> {
        self.coupled_body_ids.clone()
    }

    #[getter]
    fn coupled_ids(&self) -> Vec<i64> {
        self.coupled_ids.clone()
    }

    /// The coupled bodies' poses (reference point, MoorDyn's roll, pitch
    /// and yaw in radians; in the order of `coupled_body_ids`), then the
    /// coupled points' positions (3 per point, in the order of
    /// `coupled_ids`), from the scenario or deck: known before
    /// `initialize`.
    #[getter]
    fn initial_positions(&self) -> PyResult<Vec<f64>> {
        Ok(self.inner()?.handle.initial_positions())
    }

    /// Whether `initialize` has run (point and line values exist).
    #[getter]
    fn initialized(&self) -> PyResult<bool> {
        Ok(self.inner()?.handle.simulation().is_some())
    }

    #[getter]
    fn line_ids(&self) -> Vec<i64> {
        self.line_ids.clone()
    }

    #[getter]
    fn point_ids(&self) -> Vec<i64> {
        self.point_ids.clone()
    }

    /// The bodies' ids (fixed, coupled and free; a free rod is a body),
    /// in the system's order.
    #[getter]
    fn body_ids(&self) -> Vec<i64> {
        self.body_ids.clone()
    }

    /// The indices (in the order of `body_ids`) of the free bodies, those
    /// with a mooring stiffness.
    #[getter]
    fn free_bodies(&self) -> PyResult<Vec<usize>> {
        Ok(self.inner()?.handle.system().free_bodies().collect())
    }

    #[getter]
    fn time(&self) -> PyResult<f64> {
        Ok(self.inner()?.handle.time())
    }

    /// The most internal steps one `step_to` takes
    /// (`stancf::coupling::MAX_INTERVAL_STEPS` unless set).
    #[getter]
    fn max_interval_steps(&self) -> PyResult<usize> {
        Ok(self.inner()?.handle.max_interval_steps())
    }

    #[setter]
    fn set_max_interval_steps(&self, n: usize) -> PyResult<()> {
        self.inner()?
            .handle
            .set_max_interval_steps(n)
            .map_err(|e| coupling_err(e.into()))
    }

    /// The mean forces of the last `step_to` over its interval (None
    /// before the first).
    #[getter]
    fn interval_mean_force(&self) -> PyResult<Option<Vec<f64>>> {
        Ok(self.inner()?.last.as_ref().map(|f| f.interval_mean.clone()))
    }

    /// The steps the last `step_to` took (0 before the first).
    #[getter]
    fn last_steps(&self) -> PyResult<usize> {
        Ok(self.inner()?.last.as_ref().map_or(0, |f| f.steps))
    }

    /// The scenario's `analysis.force_tolerance`, which chooses the
    /// internal steps (None: equal steps).
    #[getter]
    fn force_tolerance(&self) -> PyResult<Option<f64>> {
        Ok(self.inner()?.handle.force_tolerance())
    }

    #[pyo3(signature = (x, xd = None))]
    fn initialize(&self, py: Python<'_>, x: Vec<f64>, xd: Option<Vec<f64>>) -> PyResult<Vec<f64>> {
        let mut guard = self.inner()?;
        let inner = &mut *guard;
        let mut signals = Signals::new();
        let result = py.allow_threads(|| {
            inner
                .handle
                .initialize_with(&x, xd.as_deref(), &mut || signals.raised())
        });
        let forces = result.map_err(|e| signals.error(e))?;
        inner.last = None;
        Ok(forces)
    }

    #[pyo3(signature = (t, x, xd = None))]
    fn step_to(
        &self,
        py: Python<'_>,
        t: f64,
        x: Vec<f64>,
        xd: Option<Vec<f64>>,
    ) -> PyResult<Vec<f64>> {
        let mut guard = self.inner()?;
        let inner = &mut *guard;
        let mut signals = Signals::new();
        let result = py.allow_threads(|| {
            inner
                .handle
                .step_to_with(t, &x, xd.as_deref(), &mut || signals.raised())
        });
        let forces = result.map_err(|e| signals.error(e))?;
        let out = forces.last_step.clone();
        inner.last = Some(forces);
        Ok(out)
    }

    fn save(&self) -> PyResult<PyState> {
        Ok(PyState(self.inner()?.handle.save()))
    }

    /// Brings back a state from `save()` of this Simulation or of one of
    /// the same scenario; ValueError for a state of another system (the
    /// Simulation untouched) or an object that is not a state.
    fn restore(&self, state: &Bound<'_, PyAny>) -> PyResult<()> {
        let state = state.downcast::<PyState>().map_err(|_| {
            PyValueError::new_err(format!(
                "state: expected a state from Simulation.save(), got {}",
                state
                    .get_type()
                    .name()
                    .map_or_else(|_| "another object".into(), |n| format!("a {n}"))
            ))
        })?;
        let mut inner = self.inner()?;
        inner
            .handle
            .restore(&state.borrow().0)
            .map_err(coupling_err)?;
        inner.last = None;
        Ok(())
    }

    /// Point `index`'s (in the order of `point_ids`) position, velocity
    /// and the net force of its lines on it.
    fn point_arrays(&self, index: usize) -> PyResult<([f64; 3], [f64; 3], [f64; 3])> {
        let p = self.inner()?.handle.point(index).ok_or_else(|| {
            PyIndexError::new_err(format!("no point {index} (or not initialized)"))
        })?;
        Ok((p.position, p.velocity, p.force))
    }

    /// Free or coupled body `index`'s (in the order of `body_ids`)
    /// mooring stiffness at the equilibrium of the last `initialize`
    /// (docs/method.md §15.9, (B16)): 6 rows of 6, None before
    /// `initialize`, for a fixed body, or where the rest of the system is
    /// singular with the body held.
    fn body_stiffness(&self, index: usize) -> PyResult<Option<[[f64; 6]; 6]>> {
        Ok(self.inner()?.handle.body_stiffness(index))
    }

    /// Coupled point `index`'s (in the order of `point_ids`; a coupled
    /// point not on a body) mooring stiffness at the equilibrium of the
    /// last `initialize`: 3 rows of 3, -df/dx of its lines' force (N/m),
    /// None before `initialize`, for another point, or where the rest of
    /// the system is singular with it held.
    fn point_stiffness(&self, index: usize) -> PyResult<Option<[[f64; 3]; 3]>> {
        Ok(self.inner()?.handle.point_stiffness(index))
    }

    /// Whether `initialize` starts from MoorDyn's start without initial
    /// conditions (a deck's `TmaxIC 0`), not from an equilibrium.
    #[getter]
    fn starts_from_catenaries(&self) -> PyResult<bool> {
        Ok(self.inner()?.handle.starts_from_catenaries())
    }

    /// Whether a host sets the sea's waves (a deck's `WaveKin 1`, a
    /// scenario's `water.host_waves`).
    #[getter]
    fn takes_host_waves(&self) -> PyResult<bool> {
        Ok(self.inner()?.handle.takes_host_waves())
    }

    /// Where the host is asked for the water's kinematics now, flat (3
    /// per point, MoorDyn's order: the lines' and rods' nodes, the points,
    /// the ground at the origin, the bodies); None before `initialize`.
    fn wave_kinematics_points(&self) -> PyResult<Option<Vec<f64>>> {
        let points = self.inner()?.handle.host_flow_points();
        Ok(points.map(|p| p.into_iter().flatten().collect()))
    }

    /// How many points `wave_kinematics_points` names (0 before
    /// `initialize`).
    fn wave_kinematics_count(&self) -> PyResult<usize> {
        Ok(self.inner()?.handle.host_flow_count().unwrap_or(0))
    }

    /// Sets the water's velocity and local acceleration at those points
    /// (flat, 3 per point) for the steps from now on (docs/method.md
    /// §12.1, (W2f)-(W2h)).
    fn set_wave_kinematics(&self, u: Vec<f64>, a: Vec<f64>) -> PyResult<()> {
        let triples = |v: &[f64]| -> Vec<[f64; 3]> {
            v.chunks(3)
                .map(|c| std::array::from_fn(|i| c.get(i).copied().unwrap_or(f64::NAN)))
                .collect()
        };
        self.inner()?
            .handle
            .set_host_flow(&triples(&u), &triples(&a))
            .map_err(coupling_err)
    }

    /// Line `index`'s (in the order of `line_ids`) node positions, node
    /// velocities (flat, 3 per node), axial forces and curvatures.
    fn line_arrays(&self, index: usize) -> PyResult<LineArrays> {
        let missing = || PyIndexError::new_err(format!("no line {index} (or not initialized)"));
        let flat = |v: Vec<[f64; 3]>| v.into_iter().flatten().collect::<Vec<f64>>();
        let inner = self.inner()?;
        let h = &inner.handle;
        Ok((
            flat(h.line_nodes(index).ok_or_else(missing)?),
            flat(h.line_velocities(index).ok_or_else(missing)?),
            h.line_tensions(index).ok_or_else(missing)?,
            h.line_curvatures(index).ok_or_else(missing)?,
        ))
    }
}
