//! Line failures of a system (docs/interface.md, "Line failures";
//! docs/method.md §11.16): `[[failures]]` of a TOML system, or a deck's
//! FAILURE rows (`crate::moordyn::failures`). Each lets go of some line
//! ends at a point at a time or a tension, whichever comes first; the
//! library releases them during the run
//! ([`stancf::system::SystemSimulation::set_failures`]).

use super::context::Ctx;
use super::raw::RawFailure;
use super::system_parts::{PointType, SystemFailure, SystemLine, SystemPoint, SystemScenario};
use super::ScenarioError;
use crate::moordyn::{Deck, LineAttachment};
use stancf::error::Sig;
use stancf::system::{Release, Trigger};

/// What failure `f` of `sc` does, for `check` and the notes: "failure 1:
/// line 2 lets go of point 5 at t = 15 s or at a tension of 1e5 N".
pub fn describe_failure(f: &SystemFailure, sc: &SystemScenario) -> String {
    let ids: Vec<String> = f
        .lines
        .iter()
        .map(|&l| sc.lines[l].id.to_string())
        .collect();
    let when: Vec<String> = f
        .time
        .map(|t| format!("at t = {} s", Sig(t)))
        .into_iter()
        .chain(f.tension.map(|t| format!("at a tension of {} N", Sig(t))))
        .collect();
    format!(
        "failure {}: line{} {} let{} go of {} {}",
        f.id,
        if ids.len() > 1 { "s" } else { "" },
        ids.join(", "),
        if ids.len() > 1 { "" } else { "s" },
        f.place,
        when.join(" or ")
    )
}

/// `[[failures]]`: `point` (a point's id) and `lines` (line ids, each
/// attached there), required; `time` (s) and `tension` (N), positive, at
/// least one; `id` (default the entry's place from 1), unique. Every
/// line of a free point is refused (the point would hold nothing).
pub(super) fn failures(
    ctx: &Ctx,
    raw: &[RawFailure],
    points: &[SystemPoint],
    lines: &[SystemLine],
) -> Result<Vec<SystemFailure>, ScenarioError> {
    let mut out: Vec<SystemFailure> = Vec::with_capacity(raw.len());
    for (i, r) in raw.iter().enumerate() {
        let key = |k: &str| format!("failures[{i}].{k}");
        let id = r.id.unwrap_or(i as i64 + 1);
        if out.iter().any(|f| f.id == id) {
            return Err(ctx.err(&key("id"), format!("failure {id} is defined twice")));
        }
        let point_id = ctx.required(&key("point"), r.point)?;
        let Some(point) = points.iter().position(|p| p.id == point_id) else {
            return Err(ctx.err(&key("point"), format!("point {point_id} is not defined")));
        };
        let line_ids = ctx.required(&key("lines"), r.lines.as_ref())?;
        if line_ids.is_empty() {
            return Err(ctx.err(&key("lines"), "a failure releases at least one line"));
        }
        let mut released = Vec::with_capacity(line_ids.len());
        for &lid in line_ids {
            let Some(l) = lines.iter().position(|l| l.id == lid) else {
                return Err(ctx.err(&key("lines"), format!("line {lid} is not defined")));
            };
            if !lines[l].ends.contains(&Some(point)) {
                return Err(ctx.err(
                    &key("lines"),
                    format!("line {lid} is not attached to point {point_id}"),
                ));
            }
            if released.contains(&l) {
                return Err(ctx.err(&key("lines"), format!("line {lid} is given twice")));
            }
            released.push(l);
        }
        let time = r.time.map(|t| ctx.positive(&key("time"), t)).transpose()?;
        let tension = r
            .tension
            .map(|f| ctx.positive(&key("tension"), f))
            .transpose()?;
        if time.is_none() && tension.is_none() {
            return Err(ctx.err(
                &key("time"),
                "a failure needs a time or a tension (or both) to happen",
            ));
        }
        let failure = SystemFailure {
            id,
            point,
            lines: released,
            time,
            tension,
            place: format!("point {point_id}"),
        };
        if releases_everything(&failure, points, lines) {
            return Err(ctx.err(
                &key("lines"),
                format!(
                    "these are every line at free point {point_id}: releasing them all lets go \
                     of nothing (the point would hold no line)"
                ),
            ));
        }
        out.push(failure);
    }
    Ok(out)
}

/// A deck's FAILURE rows as failures of the scenario whose `lines` were
/// made from the deck's in order, and the notes on those MoorDyn-F
/// ignores (neither a time nor a tension; every line of a free point),
/// which stancf leaves out too.
pub(super) fn deck_failures(
    deck: &Deck,
    file: &str,
    points: &[SystemPoint],
    lines: &[SystemLine],
) -> (Vec<SystemFailure>, Vec<String>) {
    let mut out = Vec::new();
    let mut notes = Vec::new();
    for f in &deck.failures {
        let released: Vec<usize> = f.lines.iter().map(|n| n - 1).collect();
        // The point is where the first line's end at the failure's node
        // attaches (the deck checked that every line has one there).
        let first = &deck.lines[released[0]];
        let end = usize::from(first.end_a != f.node);
        let point = lines[released[0]].ends[end].expect("a deck line end has a point");
        let node = match f.node {
            LineAttachment::Point(n) => format!("point {n}"),
            LineAttachment::Rod(n, e) => format!("R{n}{}", e.letter()),
        };
        let failure = SystemFailure {
            id: f.id as i64,
            point,
            lines: released,
            time: (f.time > 0.0).then_some(f.time),
            tension: (f.tension > 0.0).then_some(f.tension),
            place: node.clone(),
        };
        if failure.time.is_none() && failure.tension.is_none() {
            notes.push(format!(
                "{file}: line {}: failure {} at {node} has neither a FailTime nor a FailTen: it \
                 never happens (MoorDyn-F ignores it too)",
                f.line, f.id
            ));
        } else if releases_everything(&failure, points, lines) {
            notes.push(format!(
                "{file}: line {}: failure {} releases every line at free {node}, which lets go \
                 of nothing: ignored (as MoorDyn-F ignores it)",
                f.line, f.id
            ));
        } else {
            out.push(failure);
        }
    }
    (out, notes)
}

/// Whether `failure` names every line attached at its point, a free one
/// (the point would be left holding nothing).
fn releases_everything(
    failure: &SystemFailure,
    points: &[SystemPoint],
    lines: &[SystemLine],
) -> bool {
    let attached = lines
        .iter()
        .filter(|l| l.ends.contains(&Some(failure.point)))
        .count();
    points[failure.point].kind == PointType::Free && attached <= failure.lines.len()
}

/// A failure that happened, by the ids of what it names.
#[derive(Clone, Debug, PartialEq)]
pub struct FailureEvent {
    /// The failure's id.
    pub failure: i64,
    /// When (s): the end of the step at which it came due.
    pub t: f64,
    /// "time" or "tension".
    pub trigger: &'static str,
    /// The tension that set it off (N), for "tension".
    pub tension: Option<f64>,
    /// The lines released (ids).
    pub lines: Vec<i64>,
    /// The id of the new free point the released ends go on at.
    pub new_point: i64,
}

/// The library's `releases` by ids: `failure_ids`, `line_ids` and
/// `point_ids` (the system's, in order). The k-th release's new point
/// has the id after the largest of `point_ids` plus k, as MoorDyn numbers
/// the point it adds after its own.
pub fn failure_events(
    releases: &[Release],
    failure_ids: &[i64],
    (line_ids, point_ids): (&[i64], &[i64]),
) -> Vec<FailureEvent> {
    let first = point_ids.iter().copied().max().unwrap_or(0) + 1;
    releases
        .iter()
        .enumerate()
        .map(|(k, r)| {
            let (trigger, tension) = match r.trigger {
                Trigger::Time => ("time", None),
                Trigger::Tension { tension, .. } => ("tension", Some(tension)),
            };
            FailureEvent {
                failure: failure_ids[r.failure],
                t: r.time,
                trigger,
                tension,
                lines: r.lines.iter().map(|&l| line_ids[l]).collect(),
                new_point: first + k as i64,
            }
        })
        .collect()
}
