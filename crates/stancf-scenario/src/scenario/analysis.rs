//! `[analysis]` (dynamic or static, the time step, quadrature, solver and
//! strain measures) and `[output]`, and the settings the library's solvers
//! take from them.

use super::context::Ctx;
use super::raw::RawAnalysis;
use super::{Scenario, ScenarioError};
use stancf::error::Sig;
use stancf::{AxialStrain, ConstraintMethod, Curvature, Measures, SolverMethod, TimeScheme};

/// The most steps a dynamic analysis can have: 2^53, above which f64
/// cannot count them (t + dt == t).
pub const MAX_COUNTABLE_STEPS: f64 = 9_007_199_254_740_992.0;

/// A run is refused above this many steps unless `--allow-large` is given
/// (`check` warns; the bounds on work are `work_bounds.rs`).
pub const MAX_STEPS: usize = 100_000_000;

/// Where a dynamic run of a system starts.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum InitialShape {
    /// Every line straight between its end points, at rest.
    Reference,
    /// The static equilibrium (solved first).
    Static,
    /// Every line in its elastic catenary of its wet weight between its
    /// ends where the scenario places them, free points and bodies at
    /// their given positions, at rest: MoorDyn's start when it generates
    /// no initial conditions (a deck's `TmaxIC 0`; docs/method.md §13.7).
    Catenary,
}

/// Dynamic (P2 steps in time) or static (load steps).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum AnalysisKind {
    Dynamic,
    Static,
}

/// The analysis settings.
#[derive(Clone, Debug, PartialEq)]
pub struct Analysis {
    pub kind: AnalysisKind,
    /// Dynamic only (0 for a static analysis).
    pub time_step: f64,
    pub duration: f64,
    pub time_layers: usize,
    /// Spatial Gauss points (None: the element's default).
    pub space_points: Option<stancf::SpacePoints>,
    pub time_points: usize,
    pub tolerance: f64,
    pub max_iterations: usize,
    pub solver: SolverMethod,
    pub time_scheme: TimeScheme,
    pub load_steps: usize,
    pub constraint_method: ConstraintMethod,
    /// Eliminate the out-of-plane coordinates of a planar motion.
    pub planar_reduction: bool,
    /// A system's step that Newton fails is taken again in halves, this
    /// many levels deep (docs/method.md §11.13; 0: fail at once).
    pub step_halvings: u32,
    /// A system's steps chosen by this tolerance on the end forces'
    /// estimated error (docs/method.md §11.17, (M23c)), `time_step` the
    /// first and largest; None: every step `time_step`.
    pub force_tolerance: Option<f64>,
}

/// What the rest of the file holds that a static analysis refuses.
pub(super) struct Others {
    /// There are `[[initial_velocity]]` entries.
    pub(super) initial_velocity: bool,
    /// There are `[[constraints]]`.
    pub(super) constraints: bool,
}

/// `[analysis]`, in this order: `type`, the time (see [`time`]),
/// `time_layers` (1..=16, default 1), `quadrature` (see [`quadrature`]),
/// `solver`, `time_scheme` (the Galerkin step with one layer only),
/// `tolerance` (> 0, default 1e-10), `max_iterations` (1..=10000, default
/// 50), `load_steps` (1..=1000000, default 20), `curvature`,
/// `axial_strain`, `constraint_method`; `planar_reduction` defaults to
/// true; `step_halvings` (0..=10, default 0 here; a system's
/// [`stancf::system::DEFAULT_STEP_HALVINGS`]; systems only, refused by the
/// single cable's reader). Returns the settings, the strain measures and
/// the notes.
pub(super) fn analysis(
    ctx: &Ctx,
    raw: Option<RawAnalysis>,
    others: Others,
) -> Result<(Analysis, Measures, Vec<String>), ScenarioError> {
    let ra = raw.unwrap_or_default();
    let kind = match ctx.choice(
        "analysis.type",
        ra.kind.as_deref(),
        "dynamic",
        &["dynamic", "static"],
    )? {
        "static" => AnalysisKind::Static,
        _ => AnalysisKind::Dynamic,
    };
    let mut notes = Vec::new();
    let (time_step, duration) = time(ctx, &ra, kind, &others, &mut notes)?;
    let time_layers = match ra.time_layers {
        Some(n) => ctx.count("analysis.time_layers", n, 1, 16)?,
        None => 1,
    };
    let (space_points, time_points) = quadrature(ctx, ra.quadrature.as_deref())?;
    let solver = match ctx.choice(
        "analysis.solver",
        ra.solver.as_deref(),
        "newton",
        &["newton", "broyden", "modified-newton"],
    )? {
        "broyden" => SolverMethod::Broyden,
        "modified-newton" => SolverMethod::ModifiedNewton,
        _ => SolverMethod::Newton,
    };
    let time_scheme = time_scheme(ctx, &ra, time_layers)?;
    let tolerance = match ra.tolerance {
        Some(t) => ctx.positive("analysis.tolerance", t)?,
        None => 1e-10,
    };
    let max_iterations = match ra.max_iterations {
        Some(n) => ctx.count("analysis.max_iterations", n, 1, 10_000)?,
        None => 50,
    };
    let load_steps = match ra.load_steps {
        Some(n) => ctx.count("analysis.load_steps", n, 1, 1_000_000)?,
        None => 20,
    };
    let measures = measures(ctx, &ra)?;
    let constraint_method = match ctx.choice(
        "analysis.constraint_method",
        ra.constraint_method.as_deref(),
        "multiplier",
        &["multiplier", "elimination"],
    )? {
        "elimination" => ConstraintMethod::Elimination,
        _ => ConstraintMethod::Multiplier,
    };
    let step_halvings = match ra.step_halvings {
        Some(n) => ctx.count(
            "analysis.step_halvings",
            n,
            0,
            stancf::system::MAX_STEP_HALVINGS as i64,
        )? as u32,
        None => 0,
    };
    let force_tolerance = match ra.force_tolerance {
        Some(t) => Some(force_tolerance(ctx, t, kind)?),
        None => None,
    };
    let analysis = Analysis {
        step_halvings,
        force_tolerance,
        kind,
        time_step,
        duration,
        time_layers,
        space_points,
        time_points,
        tolerance,
        max_iterations,
        solver,
        time_scheme,
        load_steps,
        constraint_method,
        planar_reduction: ra.planar_reduction.unwrap_or(true),
    };
    Ok((analysis, measures, notes))
}

/// The time of `[analysis]`. Dynamic: `time_step` and `duration` (> 0,
/// required), the step no longer than the duration, at most
/// [`MAX_COUNTABLE_STEPS`] steps. Static: no time (0, 0); `time_step`,
/// `duration` and `planar_reduction` given are noted as unused, and
/// `[[initial_velocity]]` entries or no `[[constraints]]` are errors.
fn time(
    ctx: &Ctx,
    ra: &RawAnalysis,
    kind: AnalysisKind,
    others: &Others,
    notes: &mut Vec<String>,
) -> Result<(f64, f64), ScenarioError> {
    match kind {
        AnalysisKind::Dynamic => {
            let time_step = ctx.required_positive("analysis.time_step", ra.time_step)?;
            let duration = ctx.required_positive("analysis.duration", ra.duration)?;
            if time_step > duration {
                return Err(ctx.err(
                    "analysis.time_step",
                    format!(
                        "the step ({time_step:e} s) is longer than the duration ({duration:e} s)"
                    ),
                ));
            }
            let steps = duration / time_step;
            if steps > MAX_COUNTABLE_STEPS {
                return Err(ctx.err(
                    "analysis.duration, analysis.time_step",
                    format!(
                        "duration / time_step = {} steps cannot be counted: above 2^53 = {:.4e} \
                         the simulated time no longer advances by exactly one step \
                         (a run is refused above {:e} steps anyway, see `stancf check`)",
                        Sig(steps),
                        MAX_COUNTABLE_STEPS,
                        MAX_STEPS as f64
                    ),
                ));
            }
            Ok((time_step, duration))
        }
        AnalysisKind::Static => {
            for (name, v) in [("time_step", ra.time_step), ("duration", ra.duration)] {
                if v.is_some() {
                    notes.push(format!("analysis.{name} is not used by a static analysis"));
                }
            }
            if ra.planar_reduction.is_some() {
                notes.push("analysis.planar_reduction is not used by a static analysis".into());
            }
            if others.initial_velocity {
                return Err(ctx.err("initial_velocity", "a static analysis has no velocities"));
            }
            if !others.constraints {
                return Err(ctx.err(
                    "constraints",
                    "a static analysis needs constraints that remove the rigid motions; there are none",
                ));
            }
            Ok((0.0, 0.0))
        }
    }
}

/// `analysis.quadrature`: [space, time] or [axial, bending, time] Gauss
/// points, each 1..=`stancf::quadrature::MAX_POINTS`; default: the
/// element's spatial points (None) and 3 in time.
fn quadrature(
    ctx: &Ctx,
    q: Option<&[i64]>,
) -> Result<(Option<stancf::SpacePoints>, usize), ScenarioError> {
    let qmax = stancf::quadrature::MAX_POINTS as i64;
    let qkey = "analysis.quadrature";
    match q {
        None => Ok((None, 3)),
        Some([s, t]) => {
            let s = ctx.count(qkey, *s, 1, qmax)?;
            let points = stancf::SpacePoints {
                axial: s,
                bending: s,
            };
            Ok((Some(points), ctx.count(qkey, *t, 1, qmax)?))
        }
        Some([a, b, t]) => {
            let points = stancf::SpacePoints {
                axial: ctx.count(qkey, *a, 1, qmax)?,
                bending: ctx.count(qkey, *b, 1, qmax)?,
            };
            Ok((Some(points), ctx.count(qkey, *t, 1, qmax)?))
        }
        Some(q) => Err(ctx.err(
            qkey,
            format!(
                "expected [space, time] or [axial, bending, time] Gauss points, got {} numbers",
                q.len()
            ),
        )),
    }
}

/// `analysis.time_scheme`: "p2" (the default) or "galerkin"; the Galerkin
/// step refuses `analysis.time_layers` > 1.
fn time_scheme(
    ctx: &Ctx,
    ra: &RawAnalysis,
    time_layers: usize,
) -> Result<TimeScheme, ScenarioError> {
    let time_scheme = match ctx.choice(
        "analysis.time_scheme",
        ra.time_scheme.as_deref(),
        "p2",
        &["p2", "galerkin"],
    )? {
        "galerkin" => TimeScheme::Galerkin,
        _ => TimeScheme::P2,
    };
    if !time_scheme.layers_allowed() && time_layers > 1 {
        return Err(ctx.err(
            "analysis.time_layers",
            format!(
                "the Galerkin step takes one layer per step (got {time_layers}): joining layers \
                 by C1 interior nodes inside a Galerkin step is unstable"
            ),
        ));
    }
    Ok(time_scheme)
}

/// The strain measures: `analysis.curvature` ("paper", the default, or
/// "exact"), then `analysis.axial_strain` ("green", the default, or
/// "engineering").
fn measures(ctx: &Ctx, ra: &RawAnalysis) -> Result<Measures, ScenarioError> {
    let curvature = match ctx.choice(
        "analysis.curvature",
        ra.curvature.as_deref(),
        "paper",
        &["paper", "exact"],
    )? {
        "exact" => Curvature::Exact,
        _ => Curvature::Paper,
    };
    let axial_strain = match ctx.choice(
        "analysis.axial_strain",
        ra.axial_strain.as_deref(),
        "green",
        &["green", "engineering"],
    )? {
        "engineering" => AxialStrain::Engineering,
        _ => AxialStrain::Green,
    };
    Ok(Measures {
        axial_strain,
        curvature,
    })
}

impl Scenario {
    /// The step settings for the library.
    pub fn step_settings(&self) -> stancf::StepSettings {
        self.analysis.step_settings()
    }

    /// The static solve settings for the library.
    pub fn static_settings(&self) -> stancf::StaticSettings {
        self.analysis.static_settings()
    }
}

impl Analysis {
    /// The step settings for the library.
    pub fn step_settings(&self) -> stancf::StepSettings {
        stancf::StepSettings {
            time_step: self.time_step,
            time_layers: self.time_layers,
            time_points: self.time_points,
            newton: stancf::NewtonSettings {
                tolerance: self.tolerance,
                max_iterations: self.max_iterations,
                method: self.solver,
            },
            constraint_method: self.constraint_method,
            time_scheme: self.time_scheme,
            planar_reduction: self.planar_reduction,
        }
    }

    /// The static solve settings for the library.
    pub fn static_settings(&self) -> stancf::StaticSettings {
        stancf::StaticSettings {
            load_steps: self.load_steps,
            tolerance: self.tolerance,
            max_iterations: self.max_iterations,
            constraint_method: self.constraint_method,
            ..stancf::StaticSettings::default()
        }
    }
}

/// `[analysis]` of a system: the single cable's keys and `initial`
/// ("reference" or "static"; `default` when missing). Lines are elastic
/// in the engineering strain (T = EA (|r'| - 1)), as MoorDyn's and the
/// elastic catenary's are, unless `axial_strain` says otherwise. A
/// system with a free body (`free_bodies`) is stepped by the Galerkin
/// scheme, its default there; "p2" is refused (docs/method.md §15.7).
/// Its constraints are eliminated unless `analysis.constraint_method`
/// says otherwise or a line is clamped in a direction (`clamps`), which
/// only multipliers hold ([`system_constraint_route`]).
pub(super) fn analysis_part(
    ctx: &Ctx,
    mut raw: Option<RawAnalysis>,
    (default, free_bodies, clamps): (InitialShape, bool, bool),
) -> Result<(Analysis, Measures, InitialShape, Vec<String>), ScenarioError> {
    let others = Others {
        initial_velocity: false,
        constraints: true,
    };
    if free_bodies {
        galerkin_for_bodies(ctx, &mut raw)?;
    }
    if raw.as_ref().is_some_and(|a| a.force_tolerance.is_some()) {
        galerkin_for_tolerance(ctx, &mut raw)?;
    }
    let initial_key = raw.as_ref().and_then(|a| a.initial.clone());
    let axial_given = raw.as_ref().is_some_and(|a| a.axial_strain.is_some());
    let halvings_given = raw.as_ref().is_some_and(|a| a.step_halvings.is_some());
    let route_given = raw.as_ref().is_some_and(|a| a.constraint_method.is_some());
    let (mut analysis, mut measures, notes) = analysis(ctx, raw, others)?;
    if !route_given {
        analysis.constraint_method = system_constraint_route(clamps);
    }
    if !halvings_given {
        // A system's failed step is halved unless the scenario says
        // otherwise (docs/method.md §11.13).
        analysis.step_halvings = stancf::system::DEFAULT_STEP_HALVINGS;
    }
    if !axial_given {
        measures.axial_strain = stancf::AxialStrain::Engineering;
    }
    let default_word = match default {
        InitialShape::Static => "static",
        InitialShape::Reference => "reference",
        InitialShape::Catenary => "catenary",
    };
    let initial = match ctx.choice(
        "analysis.initial",
        initial_key.as_deref(),
        default_word,
        &["reference", "static", "catenary"],
    )? {
        "static" => InitialShape::Static,
        "catenary" => InitialShape::Catenary,
        _ => InitialShape::Reference,
    };
    Ok((analysis, measures, initial, notes))
}

/// How a system's constraints are enforced unless the scenario says
/// (docs/method.md §6.4, §11.3): by elimination, whose step solves the
/// free coordinates alone. The multipliers of the other route are
/// unknowns of their own in each node's block: on the OC4 race deck (18
/// SAC-2 per chain, Galerkin, 2 s steps) a chain's step has half-bandwidths
/// 44 with them and 35 without, and its factorization fills 79 to 81 of
/// the 88 super-diagonals its pivoting may reach against 62 to 63 of 70.
/// A clamp in a direction holds a combination of coordinates, which only
/// multipliers hold (docs/method.md §6.10).
fn system_constraint_route(clamps: bool) -> ConstraintMethod {
    if clamps {
        ConstraintMethod::Multiplier
    } else {
        ConstraintMethod::Elimination
    }
}

/// A system with a free body is stepped by the Galerkin scheme: the
/// default `analysis.time_scheme` there; "p2" is refused, and so are the
/// time layers the Galerkin step does not take, naming the keys.
/// `analysis.force_tolerance`: a relative error in (0, 0.5), dynamic
/// analyses only.
fn force_tolerance(ctx: &Ctx, t: f64, kind: AnalysisKind) -> Result<f64, ScenarioError> {
    if kind == AnalysisKind::Static {
        return Err(ctx.err(
            "analysis.force_tolerance",
            "a static analysis has no time steps to choose",
        ));
    }
    if !(t.is_finite() && t > 0.0 && t < 0.5) {
        return Err(ctx.err(
            "analysis.force_tolerance",
            format!(
                "{t}: the largest relative error of an end force, above 0 and below 0.5 \
                 (0.01 is 1 %)"
            ),
        ));
    }
    Ok(t)
}

/// A system whose steps a tolerance chooses is stepped by the Galerkin
/// scheme: its rows give the end forces over a step (docs/method.md
/// (M23b)), P2's do not.
fn galerkin_for_tolerance(ctx: &Ctx, raw: &mut Option<RawAnalysis>) -> Result<(), ScenarioError> {
    galerkin_required(
        ctx,
        raw,
        "\"p2\" with analysis.force_tolerance: steps chosen by a tolerance need the Galerkin \
         step, whose rows give the end forces over a step (docs/method.md (M23b)); leave \
         time_scheme out, or give \"galerkin\"",
        "steps chosen by analysis.force_tolerance are Galerkin steps, one layer each",
    )
}

fn galerkin_for_bodies(ctx: &Ctx, raw: &mut Option<RawAnalysis>) -> Result<(), ScenarioError> {
    galerkin_required(
        ctx,
        raw,
        "\"p2\": a system with a free body is stepped by the Galerkin scheme (the P2 step of \
         bodies in a system is not built); leave time_scheme out, or give \"galerkin\"",
        "a system with a free body is stepped by the Galerkin scheme, which takes one layer \
         per step",
    )
}

/// The Galerkin scheme where a scenario needs it: "p2" is refused with
/// `why_p2`, more than one time layer with `why_layers`, and an absent
/// `time_scheme` becomes "galerkin".
fn galerkin_required(
    ctx: &Ctx,
    raw: &mut Option<RawAnalysis>,
    why_p2: &str,
    why_layers: &str,
) -> Result<(), ScenarioError> {
    let ra = raw.get_or_insert_with(RawAnalysis::default);
    match ra.time_scheme.as_deref() {
        Some("p2") => Err(ctx.err("analysis.time_scheme", why_p2)),
        Some(_) => Ok(()),
        None => {
            if ra.time_layers.is_some_and(|n| n > 1) {
                return Err(ctx.err("analysis.time_layers", why_layers));
            }
            ra.time_scheme = Some("galerkin".into());
            Ok(())
        }
    }
}
