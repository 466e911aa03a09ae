//! The line failures of a run (docs/method.md §11.16) as it reports them:
//! a line on stderr when one happens or is dropped, the new free point's
//! rows in points.csv from then on (its id the next after the
//! scenario's largest, in release order: [`failure_events`]), and each
//! failure's outcome in summary.json.

use super::writers::SystemWriters;
use crate::output::json_num;
use crate::scenario::{failure_events, FailureEvent, SystemScenario};
use serde_json::{json, Value};
use stancf::error::Sig;
use stancf::system::SystemSimulation;

/// How many releases and dropped failures have been reported.
#[derive(Default)]
pub(super) struct Reported {
    releases: usize,
    dropped: usize,
}

impl Reported {
    /// Reports what happened since the last call: each release on stderr
    /// with its new point's id given to `writers`, each dropped failure.
    pub(super) fn catch_up(
        &mut self,
        sim: &SystemSimulation,
        sc: &SystemScenario,
        writers: &mut SystemWriters,
    ) {
        // Called after every step: nothing to build until something happened.
        if sim.releases().len() == self.releases && sim.dropped_failures().len() == self.dropped {
            return;
        }
        let events = events(sc, sim);
        for (e, r) in events.iter().zip(sim.releases()).skip(self.releases) {
            writers.add_point(e.new_point);
            let why = match e.tension {
                None => "its time".to_string(),
                Some(tension) => format!("a tension of {} N", Sig(tension)),
            };
            eprintln!(
                "note: t = {} s: {} (set off by {why}); the released {} on at the new free \
                 point {}",
                Sig(e.t),
                crate::scenario::describe_failure(&sc.failures[r.failure], sc),
                if e.lines.len() > 1 {
                    "ends go"
                } else {
                    "end goes"
                },
                e.new_point
            );
        }
        self.releases = events.len();
        for d in sim.dropped_failures().iter().skip(self.dropped) {
            eprintln!(
                "note: t = {} s: failure {} will not happen: {}",
                Sig(d.time),
                sc.failures[d.failure].id,
                d.why
            );
        }
        self.dropped = sim.dropped_failures().len();
    }
}

/// The releases of `sim` by the ids of `sc`.
fn events(sc: &SystemScenario, sim: &SystemSimulation) -> Vec<FailureEvent> {
    let failure_ids: Vec<i64> = sc.failures.iter().map(|f| f.id).collect();
    let line_ids: Vec<i64> = sc.lines.iter().map(|l| l.id).collect();
    let point_ids: Vec<i64> = sc.points.iter().map(|p| p.id).collect();
    failure_events(sim.releases(), &failure_ids, (&line_ids, &point_ids))
}

/// summary.json's `failures`: each failure as given and what became of
/// it in the run `sim` (released: when, why, the lines, the new point;
/// dropped: when and why; else null).
pub(super) fn failures_json(sc: &SystemScenario, sim: Option<&SystemSimulation>) -> Value {
    let events = sim.map(|s| events(sc, s)).unwrap_or_default();
    // The times as the tables write them (the decimals of the step).
    let times = super::super::times_of(&sc.analysis);
    let entries = sc.failures.iter().enumerate().map(|(i, f)| {
        let mut entry = json!({
            "id": f.id,
            "point": f.place,
            "lines": f.lines.iter().map(|&l| sc.lines[l].id).collect::<Vec<_>>(),
            "time": f.time.map(json_num),
            "tension": f.tension.map(json_num),
            "released": Value::Null,
            "dropped": Value::Null,
        });
        if let Some(e) = events.iter().find(|e| e.failure == f.id) {
            entry["released"] = json!({
                "t": json_num(times.time(e.t)),
                "trigger": e.trigger,
                "tension": e.tension.map(json_num),
                "lines": e.lines,
                "new_point": e.new_point,
            });
        }
        let dropped = sim.and_then(|s| s.dropped_failures().iter().find(|d| d.failure == i));
        if let Some(d) = dropped {
            entry["dropped"] = json!({ "t": json_num(times.time(d.time)), "why": d.why });
        }
        entry
    });
    Value::Array(entries.collect())
}
