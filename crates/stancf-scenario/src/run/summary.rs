//! What a run says about itself: the running figures ([`Tally`]), the
//! fields of summary.json every analysis writes, and the printed report.

use super::io_err;
use crate::output::{json_num, Dest};
use crate::scenario::{AnalysisKind, Scenario};
use crate::Failure;
use serde_json::{json, Value};
use stancf::observe::StressSample;
use stancf::{Model, State};
use std::path::Path;

/// Running figures of a run for summary.json.
#[derive(Default)]
pub(super) struct Tally {
    pub(super) iterations: usize,
    pub(super) factorizations: usize,
    pub(super) max_iterations: usize,
    pub(super) max_residual: f64,
    pub(super) energy_max_abs_drift: f64,
    pub(super) energy_scale: f64,
    /// Largest |axial stress| over all samples and steps: (value, s, t).
    pub(super) stress_peak: (f64, f64, f64),
    /// Sum and count of the per-step convergence-rate estimates.
    pub(super) rate_sum: f64,
    pub(super) rate_steps: usize,
}

impl Tally {
    /// Takes the stress samples of time `t` into the peak.
    pub(super) fn record_stress(&mut self, t: f64, samples: &[StressSample]) {
        for s in samples {
            if s.axial_stress.abs() > self.stress_peak.0.abs() {
                self.stress_peak = (s.axial_stress, s.s, t);
            }
        }
    }

    /// summary.json's `iterations` over `steps` steps (or increments).
    pub(super) fn iterations_json(&self, steps: usize) -> Value {
        json!({
            "total": self.iterations,
            "mean_per_step": json_num(if steps > 0 { self.iterations as f64 / steps as f64 } else { 0.0 }),
            "max_per_step": self.max_iterations,
            "factorizations": self.factorizations,
        })
    }

    /// summary.json's `stress_peak`.
    pub(super) fn stress_json(&self) -> Value {
        json!({
            "axial_stress": json_num(self.stress_peak.0),
            "s": json_num(self.stress_peak.1),
            "t": json_num(self.stress_peak.2),
        })
    }
}

/// A vector as a JSON array of three numbers.
pub(super) fn vec3(v: [f64; 3]) -> Value {
    json!([json_num(v[0]), json_num(v[1]), json_num(v[2])])
}

/// Reactions as summary.json lists them: `{"node", "force"}` objects.
pub(super) fn reactions_json(reactions: &[(usize, [f64; 3])]) -> Value {
    Value::Array(
        reactions
            .iter()
            .map(|(n, f)| json!({"node": n, "force": vec3(*f)}))
            .collect(),
    )
}

/// The fields of summary.json every analysis writes.
pub(super) fn common_summary(
    sc: &Scenario,
    model: &Model,
    state: &State,
    wall: f64,
) -> serde_json::Map<String, Value> {
    let nodes_final: Vec<Value> = (0..model.nodes())
        .map(|j| vec3(model.node_position(&state.e, j)))
        .collect();
    let tip = model.node_position(&state.e, model.nodes() - 1);
    let mut m = serde_json::Map::new();
    m.insert("title".into(), json!(sc.title));
    m.insert(
        "analysis".into(),
        json!(match sc.analysis.kind {
            AnalysisKind::Dynamic => "dynamic",
            AnalysisKind::Static => "static",
        }),
    );
    m.insert("element".into(), json!(model.element_type().name()));
    m.insert("elements".into(), json!(sc.cable.elements));
    m.insert("length".into(), json_num(sc.cable.length));
    if let Some(g) = grading_json(&sc.cable.grading) {
        m.insert("grading".into(), g);
    }
    m.insert("dofs".into(), json!(model.dofs()));
    m.insert("wall_time_s".into(), json_num(wall));
    m.insert("tip".into(), vec3(tip));
    m.insert("nodes_final".into(), Value::Array(nodes_final));
    m
}

/// A graded mesh's `{"toward": "A" | "B" | "both", "ratio": R}` or a
/// sectioned one's `{"sections": [{"length", "elements"}, ...]}` for
/// summary.json (docs/method.md §1.6); None for a uniform mesh, which
/// summary.json does not mention. The command line's figures read it
/// (`stancf_cli::figure_data::grading_of`).
pub(crate) fn grading_json(grading: &stancf::Grading) -> Option<Value> {
    match grading {
        stancf::Grading::Geometric { toward, ratio } if !grading.is_uniform() => {
            Some(json!({"toward": toward.name(), "ratio": json_num(*ratio)}))
        }
        stancf::Grading::Sections(sections) => Some(json!({
            "sections": sections
                .iter()
                .map(|s| json!({"length": json_num(s.length), "elements": s.elements}))
                .collect::<Vec<_>>()
        })),
        _ => None,
    }
}

/// Writes summary.json: the common fields followed by `extra`'s.
pub(super) fn write_summary(
    dest: Dest,
    mut summary: serde_json::Map<String, Value>,
    extra: Value,
) -> Result<(), Failure> {
    if let Value::Object(extra) = extra {
        summary.extend(extra);
    }
    let text = serde_json::to_string_pretty(&Value::Object(summary)).expect("serializable") + "\n";
    dest.write("summary.json", text.as_bytes())
        .map_err(io_err(dest.dir))
}

/// summary.json's `error`: "interrupted", or the solver's failure if any.
pub(super) fn error_json(interrupted: bool, failure: Option<&stancf::SolverError>) -> Value {
    json!(if interrupted {
        Some("interrupted".to_string())
    } else {
        failure.map(|f| f.to_string())
    })
}

/// Appends a line to a run's report (printed once its results are in place).
macro_rules! say {
    ($report:expr, $($arg:tt)*) => {{
        use std::fmt::Write as _;
        let _ = writeln!($report, $($arg)*);
    }};
}
pub(super) use say;

/// The closing line of a run: the tip and where the results are.
pub(super) fn tip_line(model: &Model, state: &State, dir: &Path) -> String {
    let tip = model.node_position(&state.e, model.nodes() - 1);
    format!(
        "tip (end B): [{:.9}, {:.9}, {:.9}] m; results in {}",
        tip[0],
        tip[1],
        tip[2],
        dir.display()
    )
}
