//! What a run of a system starts from (`stancf run` and `check` build it
//! before anything is written): the system, its static solve, or its
//! simulation from the straight lines or from the lines' catenaries
//! (MoorDyn's start without initial conditions, docs/method.md §13.7).

use crate::scenario::{AnalysisKind, InitialShape, SystemScenario};
use crate::Failure;
use stancf::system::{
    moordyn_start_forces, moordyn_start_states, straight_states, System, SystemSimulation,
    SystemStatics,
};
use std::path::Path;

/// What a run of a system starts from, built before anything is
/// written (each refuses what it cannot run): the system, its static
/// solve from the lines' catenaries (a static analysis, or
/// `initial = "static"`), and its simulation (a dynamic analysis) from
/// the straight lines, or from MoorDyn's start (`initial = "catenary"`).
pub struct Prepared {
    pub system: System,
    pub statics: Option<SystemStatics>,
    pub dynamics: Option<SystemSimulation>,
    /// Why a deck alone has no static equilibrium: its run writes
    /// MoorDyn's start, `dynamics` at t = 0, instead (where
    /// `writes_moordyns_start` allows it).
    pub unbalanced: Option<String>,
}

/// The dynamic simulation of `system` from the lines' `states` with the
/// scenario's step settings, step halvings and line failures; the lines attached to a
/// body that starts moving move with it
/// ([`stancf::system::System::start_lines_with_bodies`]).
pub fn simulation(
    sc: &SystemScenario,
    system: System,
    mut states: Vec<stancf::State>,
) -> Result<SystemSimulation, stancf::ModelError> {
    system.start_lines_with_bodies(&mut states);
    let mut sim = SystemSimulation::new(system, states, sc.analysis.step_settings())?;
    sim.set_step_halvings(sc.analysis.step_halvings)?;
    sim.set_failures(sc.failures.iter().map(|f| f.to_library()).collect())?;
    Ok(sim)
}

/// Builds what `sc` runs (see [`Prepared`]); errors are input errors
/// naming `path`.
pub fn prepare(path: &Path, sc: &SystemScenario) -> Result<Prepared, Failure> {
    let input = |e: stancf::ModelError| {
        let key = sc.names.library_key(&e.key);
        let route = dynamic_route(path, sc, &e.message);
        Failure::Input(format!("{}: {key}: {}{route}", path.display(), e.message))
    };
    crate::input_scales::system_scales(&path.display().to_string(), sc)?;
    crate::system_geometry::check_geometry(&path.display().to_string(), sc, true)?;
    let system = sc.system().map_err(input)?;
    let mut unbalanced = None;
    let statics = if sc.analysis.kind == AnalysisKind::Static || sc.initial == InitialShape::Static
    {
        let seed_system = sc.seed_system().map_err(input)?;
        let solve = match stancf::system::overlong_lines(&seed_system).first() {
            Some(l) => Err(Unbalanced::Overlong(
                overlong_refusal(path, sc, l),
                format!("line {}: {l}", sc.lines[l.line].id),
            )),
            None => SystemStatics::seeded(system.clone(), &seed_system, sc.static_settings())
                .map_err(|e| {
                    if sinks(&e.message) {
                        let why = e.message.trim_end_matches(NO_BODY_EQUILIBRIUM);
                        let why = format!(
                            "{}: {}",
                            sc.names.library_key(&e.key),
                            why.trim_end_matches([';', ' '])
                        );
                        Unbalanced::Sinks(input(e), why)
                    } else {
                        Unbalanced::Not(input(e))
                    }
                }),
        };
        match solve {
            Ok(statics) => Some(statics),
            Err(Unbalanced::Not(f)) => return Err(f),
            Err(Unbalanced::Overlong(_, why)) if writes_moordyns_start(sc, true) => {
                unbalanced = Some(why);
                None
            }
            Err(Unbalanced::Sinks(_, why)) if writes_moordyns_start(sc, false) => {
                unbalanced = Some(why);
                None
            }
            Err(Unbalanced::Overlong(f, _) | Unbalanced::Sinks(f, _)) => return Err(f),
        }
    } else {
        None
    };
    let start = if unbalanced.is_some() {
        Some(InitialShape::Catenary)
    } else {
        (sc.analysis.kind == AnalysisKind::Dynamic).then_some(sc.initial)
    };
    let dynamics = match start {
        Some(initial) => {
            let (start, forces) = match initial {
                // MoorDyn's start without initial conditions (§13.7): each line's
                // catenary of its wet weight between its ends as given, and
                // the forces it puts on its ends (the t = 0 row's).
                InitialShape::Catenary => {
                    let seed_system = sc.seed_system().map_err(input)?;
                    let states = moordyn_start_states(&system, &seed_system)
                        .map_err(|l| overlong_refusal(path, sc, &l))?;
                    (states, Some(moordyn_start_forces(&seed_system)))
                }
                InitialShape::Static | InitialShape::Reference => (straight_states(&system), None),
            };
            // MoorDyn's start written alone is never stepped: a deck
            // without dtM (or lines to take a step from) gets one second.
            let stepped = (unbalanced.is_some() && sc.analysis.time_step <= 0.0).then(|| {
                let mut sc = sc.clone();
                sc.analysis.time_step = 1.0;
                sc
            });
            let mut sim =
                simulation(stepped.as_ref().unwrap_or(sc), system.clone(), start).map_err(input)?;
            if let Some(forces) = forces {
                sim.set_start_forces(&forces).map_err(input)?;
            }
            Some(sim)
        }
        None => None,
    };
    Ok(Prepared {
        system,
        statics,
        dynamics,
        unbalanced,
    })
}

/// A static solve refused for want of an equilibrium (with the refusal
/// and its reason), or refused for another reason.
enum Unbalanced {
    Overlong(Failure, String),
    Sinks(Failure, String),
    Not(Failure),
}

/// Whether the library refused a static analysis because a body or rod
/// has no static equilibrium (it floats on no line and sinks).
fn sinks(message: &str) -> bool {
    message.ends_with(NO_BODY_EQUILIBRIUM)
}

/// How the library's refusal of a body without static equilibrium ends.
const NO_BODY_EQUILIBRIUM: &str = "start a dynamic run from its given pose instead";

/// Where the library refuses a static analysis because a body has no
/// static equilibrium ("start a dynamic run from its given pose
/// instead"), how to start one from the file at `path`: a deck alone is a
/// static run (MoorDyn's own tests of sinking rods start from the deck's
/// placement, TmaxIC 0), so from a scenario that takes it; a scenario by
/// its `[analysis]`. Empty otherwise.
fn dynamic_route(path: &Path, sc: &SystemScenario, message: &str) -> String {
    if sc.analysis.kind != AnalysisKind::Static || !sinks(message) {
        return String::new();
    }
    let toml = path
        .extension()
        .is_some_and(|e| e.eq_ignore_ascii_case("toml"));
    if sc.names.is_deck() && !toml {
        let name = path
            .file_name()
            .map_or(String::new(), |n| n.to_string_lossy().into_owned());
        format!(
            " (a deck alone is a static run: take it in a scenario, [system] moordyn = \"{name}\" \
             with [analysis] type = \"dynamic\" and initial = \"catenary\", MoorDyn's start \
             from the deck's positions, or run a MoorDyn driver file that names it)"
        )
    } else {
        " ([analysis] type = \"dynamic\" with initial = \"reference\")".into()
    }
}

/// The refusal of overlong line `l` (C20), naming it by its id.
fn overlong_refusal(path: &Path, sc: &SystemScenario, l: &stancf::system::OverlongLine) -> Failure {
    Failure::Input(format!(
        "{}: line {}: {l}. Shorten it, move its ends apart, or start a dynamic run as \
         MoorDyn starts it without initial conditions, the line laid straight and slack \
         ([analysis] initial = \"catenary\" for a line without compression, or a MoorDyn \
         driver file whose deck has TmaxIC 0)",
        path.display(),
        sc.lines[l.line].id,
    ))
}

/// What MoorDyn does from its start for a deck of `TmaxIC` `relaxation`
/// ([`SystemScenario::moordyn_relaxation`]): nothing (TmaxIC 0), or its
/// dynamic relaxation for initial conditions, which settles nowhere
/// where no static equilibrium is (docs/method.md §13.7).
pub(crate) fn relaxation_words(relaxation: Option<f64>) -> String {
    match relaxation {
        None => "the deck's TmaxIC is 0: no initial conditions".into(),
        Some(t) => {
            let given = if t.is_nan() {
                "its default TmaxIC".to_string()
            } else {
                format!("TmaxIC {} s", stancf::error::Sig(t))
            };
            format!(
                "MoorDyn relaxes from it for its initial conditions ({given}) and settles \
                 nowhere either: its Init ends with a remaining error; stancf writes the start"
            )
        }
    }
}

/// Whether a deck alone without a static equilibrium writes MoorDyn's
/// start (docs/method.md §13.7): with TmaxIC 0 always (MoorDyn's `Init`
/// leaves it there); otherwise only for a line longer than its path
/// (`overlong`), from which MoorDyn's relaxation settles nowhere either
/// (a sinking rod it relaxes onto the bed, a state stancf's statics would
/// have to find: refused).
fn writes_moordyns_start(sc: &SystemScenario, overlong: bool) -> bool {
    sc.start_without_equilibrium
        && sc.analysis.kind == AnalysisKind::Static
        && (sc.moordyn_relaxation.is_none() || overlong)
}
