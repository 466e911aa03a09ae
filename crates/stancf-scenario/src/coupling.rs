//! A coupled system from a scenario file or a MoorDyn v2 deck
//! (docs/interface.md, "Coupling"): the same validation and the same
//! system as `stancf run`, stepped by another code through
//! [`stancf::coupling::CoupledSystem`]. The Python `stancf.Simulation`
//! and the C library `stancf_c` open their systems here.

use crate::scenario::{parse_input_with, HostEnvironment, InitialShape, Input, SystemScenario};
use crate::Failure;
use stancf::coupling::CoupledSystem;
use std::path::Path;

/// A coupled system with the ids its scenario gives its points and lines.
pub struct Coupled {
    pub handle: CoupledSystem,
    /// The coupled bodies' ids, in the order of the coupling arrays
    /// (first, 6 numbers each): by id, as MoorDyn orders them.
    pub coupled_body_ids: Vec<i64>,
    /// The coupled points' ids (points on coupled bodies are not among
    /// them: their bodies move them), in the order of the coupling arrays
    /// after the bodies.
    pub coupled_ids: Vec<i64>,
    /// The lines' ids, in the order of the system's lines.
    pub line_ids: Vec<i64>,
    /// The points' ids, in the order of the system's points.
    pub point_ids: Vec<i64>,
    /// The bodies' ids (fixed, coupled and free; a free rod is a body),
    /// in the order of the system's bodies: index b here is body b of
    /// [`CoupledSystem::body_stiffness`].
    pub body_ids: Vec<i64>,
    /// The line failures' ids (docs/method.md §11.16), in the scenario's
    /// order.
    pub failure_ids: Vec<i64>,
}

impl Coupled {
    /// The line failures that happened so far, by ids (the new points
    /// numbered as a run numbers them in points.csv).
    pub fn releases(&self) -> Vec<crate::scenario::FailureEvent> {
        crate::scenario::failure_events(
            self.handle.releases(),
            &self.failure_ids,
            (&self.line_ids, &self.point_ids),
        )
    }
}

/// Reads the scenario or deck at `path` and builds its coupled system,
/// within the bounds `stancf run` applies ([`crate::work_bounds`]).
pub fn open(path: &Path) -> Result<Coupled, Failure> {
    open_with(path, false)
}

/// [`open`], with `allow_large` the opt-in for a system beyond the bound
/// on elements without `--allow-large` (the hard bound holds).
pub fn open_with(path: &Path, allow_large: bool) -> Result<Coupled, Failure> {
    open_in(path, allow_large, &HostEnvironment::NONE)
}

/// [`open_with`] in the host's sea: the water depth, density and gravity
/// a MoorDyn deck leaves out are the host's ([`HostEnvironment`], as
/// OpenFAST gives MoorDyn-F its `WtrDepth`, `rhoW` and `g` before init).
pub fn open_in(path: &Path, allow_large: bool, host: &HostEnvironment) -> Result<Coupled, Failure> {
    let text = crate::input_file::read_text(path)
        .map_err(|e| Failure::Input(format!("{}: {e}", path.display())))?;
    from_text_in(&text, path, allow_large, host)
}

/// The coupled system of scenario text (`path` names it in messages and
/// resolves the files it refers to); a MoorDyn deck steps with its
/// `dtM`, and with `TmaxIC 0` starts from its lines' catenaries as
/// MoorDyn does (as does a scenario's `initial = "catenary"`; docs/method.md
/// §13.7). Refused: a single cable (no points)
/// and a system without coupled points or coupled bodies. The coupled
/// points' motions in the scenario are replaced by the coupling code's;
/// the coupling arrays hold the coupled bodies first, in the order of
/// their ids, then the coupled points in the order of theirs.
pub fn from_text(text: &str, path: &Path) -> Result<Coupled, Failure> {
    from_text_with(text, path, false)
}

/// [`from_text`] with the opt-in for large systems of [`open_with`].
pub fn from_text_with(text: &str, path: &Path, allow_large: bool) -> Result<Coupled, Failure> {
    from_text_in(text, path, allow_large, &HostEnvironment::NONE)
}

/// [`from_text_with`] in the host's sea ([`open_in`]).
pub fn from_text_in(
    text: &str,
    path: &Path,
    allow_large: bool,
    host: &HostEnvironment,
) -> Result<Coupled, Failure> {
    let file = path.display().to_string();
    // A coupling code may set the waves at the nodes (WaveKin 1).
    let host = HostEnvironment {
        sets_waves: true,
        run_length: None,
        ..host.clone()
    };
    let parsed = parse_input_with(text, &file, path, &host).map_err(|e| Failure::Input(e.0))?;
    let mut sc = match parsed {
        Input::System(sc) => *sc,
        Input::Cable(_) => {
            return Err(Failure::Input(format!(
                "{file}: a single cable has no points for a coupling code to move; give a \
                 system with coupled points ([[points]] with type = \"coupled\", or a MoorDyn \
                 deck with Coupled or Vessel points)"
            )))
        }
    };
    if crate::moordyn::looks_like_moordyn(text) {
        let deck =
            crate::moordyn::parse(text).map_err(|e| Failure::Input(format!("{file}: {e}")))?;
        sc.analysis.time_step = deck_time_step(&deck, &file)?;
        // A deck whose TmaxIC is 0 starts as MoorDyn starts without
        // initial conditions (docs/method.md §13.7).
        if !deck.generates_initial_conditions() {
            sc.initial = InitialShape::Catenary;
        }
    }
    // The coupling code decides the duration: the elements are bounded
    // here, the steps of each coupling call by the handle.
    crate::work_bounds::admit_elements(&file, &sc, allow_large)?;
    of_scenario(&sc, &file)
}

/// A deck alone is a static analysis; coupled, it steps with its `dtM`,
/// as MoorDyn does.
fn deck_time_step(deck: &crate::moordyn::Deck, file: &str) -> Result<f64, Failure> {
    deck.time_step().ok_or_else(|| {
        Failure::Input(format!(
            "{file}: OPTIONS: the deck gives no dtM and has no lines to derive MoorDyn's step \
             from, the time step a coupled run takes"
        ))
    })
}

/// The coupled system of a validated system scenario.
pub fn of_scenario(sc: &SystemScenario, file: &str) -> Result<Coupled, Failure> {
    let input = |e: stancf::ModelError| {
        let key = sc.names.library_key(&e.key);
        Failure::Input(format!("{file}: {key}: {}", e.message))
    };
    crate::input_scales::system_scales(file, sc)?;
    // The coupling code places the coupled points (stancf_init).
    crate::system_geometry::check_geometry(file, sc, false)?;
    let system = sc.system().map_err(input)?;
    let seed = sc.seed_system().map_err(input)?;
    let handle = CoupledSystem::new(
        system,
        seed,
        sc.static_settings(),
        sc.analysis.step_settings(),
    )
    .map_err(input)?;
    // The coupled points of the arrays' last part (not on a coupled body,
    // not a pinned body's or rod's host point: the core decides), by id.
    let mut order = handle.coupled_points().to_vec();
    order.sort_by_key(|&p| sc.points[p].id);
    // The coupled bodies by id, as MoorDyn orders them (a deck's BODIES
    // are numbered in order; a TOML file's `[[bodies]]` may not be).
    let mut bodies = handle.coupled_bodies();
    bodies.sort_by_key(|&b| sc.bodies[b].id);
    // `initial = "catenary"` (a deck's TmaxIC 0): MoorDyn's start without
    // initial conditions at initialize, not the static equilibrium.
    let handle = match sc.initial {
        InitialShape::Catenary => handle.with_catenary_start(),
        _ => handle,
    };
    let handle = handle
        .with_body_order(bodies.clone())
        .and_then(|h| h.with_failures(sc.failures.iter().map(|f| f.to_library()).collect()))
        .map_err(input)?;
    Ok(Coupled {
        coupled_body_ids: bodies.iter().map(|&b| sc.bodies[b].id).collect(),
        coupled_ids: order.iter().map(|&p| sc.points[p].id).collect(),
        line_ids: sc.lines.iter().map(|l| l.id).collect(),
        point_ids: sc.points.iter().map(|p| p.id).collect(),
        body_ids: sc.bodies.iter().map(|b| b.id).collect(),
        failure_ids: sc.failures.iter().map(|f| f.id).collect(),
        handle: handle
            .with_order(order)
            .and_then(|h| h.with_step_halvings(sc.analysis.step_halvings))
            .and_then(|h| match sc.analysis.force_tolerance {
                Some(tolerance) => h.with_force_tolerance(tolerance),
                None => Ok(h),
            })
            .map_err(input)?,
    })
}
