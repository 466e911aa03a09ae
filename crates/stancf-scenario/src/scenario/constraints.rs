//! `[[constraints]]`: nodes held (`clamped`, `pinned`) or moved
//! (`prescribed`).

use super::context::{Ctx, Field};
use super::messages::clip;
use super::raw::{RawClamped, RawPinned, RawPrescribed};
use super::ScenarioError;
use stancf::{Constraint, ConstraintKind};

/// Every `[[constraints]]` entry, in file order (the first wrong entry is
/// reported): its `type` ("clamped", "pinned" or "prescribed", required)
/// and then the keys of that type. `elements` bounds the node indices.
pub(super) fn constraints(
    ctx: &Ctx,
    tables: &[toml::Table],
    elements: usize,
) -> Result<Vec<Constraint>, ScenarioError> {
    let mut constraints = Vec::with_capacity(tables.len());
    for (i, table) in tables.iter().enumerate() {
        let key = format!("constraints[{i}]");
        let c = match ctx.type_of(&key, table)?.as_str() {
            "clamped" => clamped(ctx, &key, table, elements)?,
            "pinned" => pinned(ctx, &key, table, elements)?,
            "prescribed" => prescribed(ctx, &key, table, elements)?,
            other => {
                return Err(ctx.err(
                    &format!("{key}.type"),
                    format!(
                        "unknown constraint type \"{}\" (expected \"clamped\", \"pinned\" or \"prescribed\")",
                        clip(other, 60)
                    ),
                ))
            }
        };
        constraints.push(c);
    }
    Ok(constraints)
}

/// `type = "clamped"`: `node` (required, not "all") and `fix_curvature`
/// (true or false, default false).
fn clamped(
    ctx: &Ctx,
    key: &str,
    table: &toml::Table,
    elements: usize,
) -> Result<Constraint, ScenarioError> {
    ctx.field_types(
        key,
        table,
        &[("node", Field::Node), ("fix_curvature", Field::Bool)],
    )?;
    let c: RawClamped = ctx.entry(key, table)?;
    Ok(Constraint {
        node: ctx.one_node(&format!("{key}.node"), c.node, elements)?,
        kind: ConstraintKind::Clamped {
            fix_curvature: c.fix_curvature.unwrap_or(false),
        },
    })
}

/// `type = "pinned"`: `node` (required, not "all").
fn pinned(
    ctx: &Ctx,
    key: &str,
    table: &toml::Table,
    elements: usize,
) -> Result<Constraint, ScenarioError> {
    let c: RawPinned = ctx.entry(key, table)?;
    Ok(Constraint {
        node: ctx.one_node(&format!("{key}.node"), c.node, elements)?,
        kind: ConstraintKind::Pinned,
    })
}

/// `type = "prescribed"`: `frequency` (>= 0, default 0), `phase` (finite,
/// default 0), `node` (required, not "all"), `velocity` and `amplitude`
/// (vectors, default zero), checked in that order.
fn prescribed(
    ctx: &Ctx,
    key: &str,
    table: &toml::Table,
    elements: usize,
) -> Result<Constraint, ScenarioError> {
    ctx.field_types(
        key,
        table,
        &[
            ("velocity", Field::Vector),
            ("amplitude", Field::Vector),
            ("frequency", Field::Number),
            ("phase", Field::Number),
        ],
    )?;
    let c: RawPrescribed = ctx.entry(key, table)?;
    let frequency = match c.frequency {
        Some(f) => ctx.non_negative(&format!("{key}.frequency"), f)?,
        None => 0.0,
    };
    let phase = match c.phase {
        Some(p) => ctx.finite(&format!("{key}.phase"), p)?,
        None => 0.0,
    };
    let node = ctx.one_node(&format!("{key}.node"), c.node, elements)?;
    let vector = |name: &str, v: &Option<Vec<f64>>| {
        ctx.vector_or(&format!("{key}.{name}"), v.as_deref(), [0.0; 3])
    };
    Ok(Constraint {
        node,
        kind: ConstraintKind::Prescribed {
            velocity: vector("velocity", &c.velocity)?,
            amplitude: vector("amplitude", &c.amplitude)?,
            frequency,
            phase,
        },
    })
}
