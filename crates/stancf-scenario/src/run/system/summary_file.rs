//! summary.json of a system run and the run's closing report
//! (docs/interface.md "summary.json").

use super::super::summary::{self, error_json, say, vec3};
use super::super::{io_err, Place};
use super::{bodies, releases, static_report, stiffness, Outcome};
use crate::output::{json_num, Dest};
use crate::scenario::{AnalysisKind, InitialShape, SystemScenario};
use crate::Failure;
use serde_json::{json, Value};
use stancf::error::Sig;
use stancf::system::{SystemSimulation, SystemStatics};

/// summary.json of a system run: `sim` the simulation and `statics` the
/// static solve of the run (either may be absent), `matrices` the free
/// bodies' mooring stiffness at the equilibrium.
pub(super) fn write_summary(
    dest: Dest,
    sc: &SystemScenario,
    (outcome, statistics): (&Outcome, Value),
    wall: f64,
    (sim, statics): (Option<&SystemSimulation>, Option<&SystemStatics>),
    matrices: &[stiffness::BodyStiffness],
) -> Result<(), Failure> {
    let lines: Vec<Value> = sc
        .lines
        .iter()
        .enumerate()
        .map(|(i, l)| {
            let mut line = json!({
                "id": l.id,
                "type": sc.line_types[l.line_type].name,
                "length": json_num(l.length),
                "elements": l.elements,
                "element": l.element_type.name(),
                "bending_stiffness": json_num(sc.bending_stiffness(i)),
                "max_tension_a": json_num(outcome.max_tension[i][0]),
                "max_tension_b": json_num(outcome.max_tension[i][1]),
            });
            if let Some(g) = summary::grading_json(&l.grading) {
                line["grading"] = g;
            }
            line
        })
        .collect();
    let points: Vec<Value> = sc
        .points
        .iter()
        .enumerate()
        .map(|(p, pt)| {
            let position = match (sim, statics) {
                (Some(s), _) => s.point_state(p).0,
                (None, Some(st)) => st.point_position(p),
                _ => pt.position,
            };
            json!({
                "id": pt.id,
                "type": match pt.kind {
                    crate::scenario::PointType::Fixed => "fixed",
                    crate::scenario::PointType::Free => "free",
                    crate::scenario::PointType::Coupled => "coupled",
                    crate::scenario::PointType::Body { .. } => "body",
                },
                "position_final": vec3(position),
            })
        })
        .collect();
    let mut summary = json!({
        "title": sc.title,
        "analysis": match sc.analysis.kind {
            AnalysisKind::Dynamic => "dynamic",
            AnalysisKind::Static => "static",
        },
        "system": true,
        "initial": match sc.initial {
            InitialShape::Static => "static",
            InitialShape::Reference => "reference",
            InitialShape::Catenary => "catenary",
        },
        "end_forces": sc.end_forces.name(),
        "lines": lines,
        "points": points,
        "steps": outcome.steps,
        "t_final": json_num(outcome.t),
        "load_increments": outcome.increments,
        "iterations": outcome.iterations,

        "wall_time_s": json_num(wall),
        "stepping_wall_time_s": outcome.stepping_wall.map(json_num),
        "error": error_json(outcome.interrupted, outcome.failure.as_ref()),
        "interrupted": outcome.interrupted,
        "statistics": statistics,
    });
    if let Some(st) = statics.filter(|_| outcome.failure.is_none()) {
        summary["static_path"] = json!(static_report::static_path(st));
    }
    how_it_started_and_stepped(&mut summary, sc, outcome);
    if !sc.bodies.is_empty() {
        let mut entries = bodies::bodies_json(sc, sim, statics);
        stiffness::add_to_summary(&mut entries, matrices);
        summary["bodies"] = Value::Array(entries);
    }
    if !sc.rods.is_empty() {
        summary["rods"] = Value::Array(bodies::rods_json(sc));
    }
    if !sc.failures.is_empty() {
        summary["failures"] = releases::failures_json(sc, sim);
    }
    if !sc.notes.is_empty() {
        summary["notes"] = json!(sc.notes);
    }
    if let Some(out) = sc
        .moordyn_out
        .as_ref()
        .filter(|_| sc.output_files.writes("moordyn.out"))
    {
        // Named here so that a later run may replace the folder
        // (crate::result_layout: the files of free names it writes).
        summary["moordyn_out"] = json!(out.names());
    }
    let text = serde_json::to_string_pretty(&summary).expect("serializable") + "\n";
    dest.write("summary.json", text.as_bytes())
        .map_err(io_err(dest.dir))
}

/// summary.json's `step_control` (where a tolerance chose the steps) and
/// `no_static_equilibrium` (a deck alone without an
/// equilibrium: MoorDyn's start was written, its `initial` "catenary").
fn how_it_started_and_stepped(summary: &mut Value, sc: &SystemScenario, outcome: &Outcome) {
    if let (Some(c), Some(tol)) = (outcome.controlled, sc.analysis.force_tolerance) {
        summary["step_control"] = json!({
            "force_tolerance": json_num(tol),
            "steps": c.accepted,
            "rejected": c.rejected,
            "shortest_step": json_num(c.shortest),
            "longest_step": json_num(c.longest),
        });
    }
    if let Some(why) = &outcome.unbalanced {
        summary["initial"] = json!("catenary");
        summary["no_static_equilibrium"] = json!(why);
    }
}

/// The printed report: the largest end tensions and where the results are.
pub(super) fn report(sc: &SystemScenario, outcome: &Outcome, wall: f64, place: &Place) -> String {
    let mut r = String::new();
    let bodies = match sc.bodies.len() {
        0 => String::new(),
        1 => ", 1 body".to_string(),
        n => format!(", {n} bodies"),
    };
    say!(
        r,
        "{}: {} line{}, {} point{}{bodies}; {} in {:.2} s",
        crate::echo::clip(&sc.title, crate::echo::MAX_ECHO),
        sc.lines.len(),
        if sc.lines.len() == 1 { "" } else { "s" },
        sc.points.len(),
        if sc.points.len() == 1 { "" } else { "s" },
        match (sc.analysis.kind, &outcome.unbalanced) {
            (AnalysisKind::Static, Some(_)) => {
                "no static equilibrium: MoorDyn's start written at t = 0".to_string()
            }
            (AnalysisKind::Static, None) => {
                format!("equilibrium in {} increments", outcome.increments)
            }
            (AnalysisKind::Dynamic, _) => {
                format!("{} steps to t = {} s", outcome.steps, Sig(outcome.t))
            }
        },
        wall
    );
    // Tensions in one form, 6 significant digits in exponent form
    // (1.10601e6, 9.08050e5), as the cable summaries print their figures;
    // a static run's are those at equilibrium, a dynamic run's the largest.
    let what = match (sc.analysis.kind, &outcome.unbalanced) {
        (AnalysisKind::Static, Some(_)) => "tension at the start",
        (AnalysisKind::Static, None) => "tension at equilibrium",
        (AnalysisKind::Dynamic, _) => "largest tension",
    };
    if let Some(why) = &outcome.unbalanced {
        say!(r, "no static equilibrium: {why}");
    }
    for (l, m) in sc.lines.iter().zip(&outcome.max_tension) {
        say!(
            r,
            "line {}: {what} {:.5e} N at end A, {:.5e} N at end B",
            l.id,
            m[0],
            m[1]
        );
    }
    say!(r, "results in {}", place.shown.display());
    r
}
