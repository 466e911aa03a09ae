//! Bounding the work of a scenario: a valid scenario drawn or mutated
//! into a long run is brought down to a few steps and elements, while an
//! absurd one is left for the CLI to refuse.

/// Valid step counts above this are clamped to a few steps; a scenario
/// asking for more steps than `ABSURD_STEPS` is left as it is: the CLI must
/// refuse it (exit 2), not run it for ever.
const MAX_STEPS: f64 = 16.0;
const ABSURD_STEPS: f64 = 1e10;

fn number(v: &toml::Value) -> Option<f64> {
    match v {
        toml::Value::Float(f) => Some(*f),
        toml::Value::Integer(i) => Some(*i as f64),
        _ => None,
    }
}

/// Keeps a valid scenario small: a valid step count above `MAX_STEPS` (but
/// not absurd), more than 64 elements (a cable's, a system line's or a
/// deck line's mesh) or 20 load steps are brought down.
/// Text that is not TOML, or needs no change, is returned as it is.
pub fn bound_work(text: String) -> String {
    let Ok(mut doc) = toml::from_str::<toml::Table>(&text) else {
        return text;
    };
    let mut changed = false;
    if let Some(toml::Value::Table(a)) = doc.get_mut("analysis") {
        let dt = a.get("time_step").and_then(number);
        let t = a.get("duration").and_then(number);
        if let (Some(dt), Some(t)) = (dt, t) {
            if dt > 0.0 && t > 0.0 && dt.is_finite() && t.is_finite() {
                let steps = t / dt;
                if steps > MAX_STEPS && steps < ABSURD_STEPS {
                    a.insert("duration".into(), toml::Value::Float(dt * 8.0));
                    changed = true;
                }
            }
        }
        if let Some(toml::Value::Integer(n)) = a.get("load_steps") {
            if (21..=1_000_000).contains(n) {
                a.insert("load_steps".into(), toml::Value::Integer(5));
                changed = true;
            }
        }
    }
    if let Some(toml::Value::Table(c)) = doc.get_mut("cable") {
        if let Some(toml::Value::Integer(n)) = c.get("elements") {
            if (65..=1_000_000).contains(n) {
                c.insert("elements".into(), toml::Value::Integer(8));
                changed = true;
            }
        }
    }
    // A system's lines and a deck's meshes: up to the 2000 elements a
    // system takes without --allow-large (more are refused at once).
    for entries in ["lines", "mesh"] {
        if let Some(toml::Value::Array(a)) = doc.get_mut(entries) {
            for e in a.iter_mut().filter_map(toml::Value::as_table_mut) {
                if let Some(toml::Value::Integer(n)) = e.get("elements") {
                    if (65..=2000).contains(n) {
                        e.insert("elements".into(), toml::Value::Integer(8));
                        changed = true;
                    }
                }
            }
        }
    }
    if changed {
        toml::to_string(&doc).unwrap_or(text)
    } else {
        text
    }
}
