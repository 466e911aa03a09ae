//! `output.interval` (s) of a system's dynamic run: the result tables
//! written at the multiples of this interval, whatever the steps, from
//! the Galerkin step's own cubics in time (docs/method.md §6.5a, (M23d))
//! instead of at every `output.every`-th step; history.csv stays the
//! steps' record. Refused naming the key where the state between the ends
//! of a step is not interpolated in this version (P2, bodies that move,
//! viscoelastic and VIV lines, line failures), in a static analysis, and beside
//! `output.every` or `output.end_forces = "step_mean"` (a step's mean is
//! not a force at a time between its ends).

use super::analysis::AnalysisKind;
use super::context::Ctx;
use super::raw::RawOutput;
use super::system_parts::SystemScenario;
use super::ScenarioError;
use crate::scenario::bodies::BodyType;
use stancf::TimeScheme;

/// The interval of `raw` checked against the system it writes (None:
/// not given).
pub(super) fn output_interval(
    ctx: &Ctx,
    raw: Option<&RawOutput>,
    sc: &SystemScenario,
) -> Result<Option<f64>, ScenarioError> {
    let Some(interval) = raw.and_then(|r| r.interval) else {
        return Ok(None);
    };
    let key = "output.interval";
    let interval = ctx.positive(key, interval)?;
    let refuse = |why: String| Err(ctx.err(key, why));
    if raw.is_some_and(|r| r.every.is_some()) {
        return refuse(
            "and output.every both say when the run writes: give one of them (the interval \
             writes at its multiples between the steps, every at the steps)"
                .into(),
        );
    }
    if raw.is_some_and(|r| r.end_forces.as_deref() == Some("step_mean")) {
        return refuse(
            "writes the end forces at times between the steps, and output.end_forces = \
             \"step_mean\" asks for a step's mean, which is no force at such a time: leave \
             end_forces out (the force at t is written)"
                .into(),
        );
    }
    if let Err(why) = refuse_where_not_interpolated(sc) {
        return refuse(why);
    }
    Ok(Some(interval))
}

/// The reason the system's state between the ends of its steps is not
/// interpolated, if it is not (see the module's doc).
fn refuse_where_not_interpolated(sc: &SystemScenario) -> Result<(), String> {
    let analysis = &sc.analysis;
    if analysis.kind != AnalysisKind::Dynamic {
        return Err(
            "is the writing of a dynamic analysis; a static one writes its \
                    equilibrium"
                .into(),
        );
    }
    if analysis.time_scheme != TimeScheme::Galerkin {
        return Err(
            "needs analysis.time_scheme = \"galerkin\": the state between the ends of \
                    a step is the Galerkin step's cubics (docs/method.md (M23d)), and P2's \
                    rows give no cubic of the end forces"
                .into(),
        );
    }
    if let Some(b) = sc.bodies.iter().find(|b| b.kind != BodyType::Fixed) {
        return Err(format!(
            "body {} moves (it is free or coupled, or a rod that is not fixed): a body's pose \
             between the ends of a step is not interpolated in this version; use output.every",
            b.id
        ));
    }
    if !sc.failures.is_empty() {
        return Err(
            "is not written with line failures in this version (a released end's new \
                    point has no state before its release); use output.every"
                .into(),
        );
    }
    if let Some(t) = sc
        .line_types
        .iter()
        .find(|t| t.ea_dynamic.is_some() || t.viv.is_some())
    {
        return Err(format!(
            "line type {} is viscoelastic or has VIV: its internal state between the ends of \
             a step is not interpolated in this version; use output.every",
            t.name
        ));
    }
    Ok(())
}
