//! `[[loads]]`: gravity, a point force, an end moment, air drag.

use super::context::{Ctx, Field};
use super::messages::clip;
use super::raw::{RawAirDrag, RawEndMoment, RawGravity, RawPointForce};
use super::ScenarioError;
use stancf::loads::{AirDrag, DragModel};
use stancf::Load;

/// Every `[[loads]]` entry, in file order (the first wrong entry is
/// reported): its `type` ("gravity", "point-force", "end-moment" or
/// "air-drag", required) and then the keys of that type. `elements` bounds
/// the node indices; `diameter` is `material.diameter`, drag's default.
pub(super) fn loads(
    ctx: &Ctx,
    tables: &[toml::Table],
    elements: usize,
    diameter: f64,
) -> Result<Vec<Load>, ScenarioError> {
    let mut loads = Vec::with_capacity(tables.len());
    for (i, table) in tables.iter().enumerate() {
        let key = format!("loads[{i}]");
        let load = match ctx.type_of(&key, table)?.as_str() {
            "gravity" => gravity(ctx, &key, table)?,
            "point-force" => point_force(ctx, &key, table, elements)?,
            "end-moment" => end_moment(ctx, &key, table, elements)?,
            "air-drag" => air_drag(ctx, &key, table, diameter)?,
            other => {
                return Err(ctx.err(
                    &format!("{key}.type"),
                    format!(
                        "unknown load type \"{}\" (expected \"gravity\", \"point-force\", \"end-moment\" or \"air-drag\")",
                        clip(other, 60)
                    ),
                ))
            }
        };
        loads.push(load);
    }
    Ok(loads)
}

/// `type = "gravity"`: `acceleration` (a vector, required).
fn gravity(ctx: &Ctx, key: &str, table: &toml::Table) -> Result<Load, ScenarioError> {
    ctx.field_types(key, table, &[("acceleration", Field::Vector)])?;
    let g: RawGravity = ctx.entry(key, table)?;
    let ak = format!("{key}.acceleration");
    let a = ctx.required(&ak, g.acceleration)?;
    Ok(Load::Gravity {
        acceleration: ctx.vector(&ak, &a)?,
    })
}

/// `type = "point-force"`: `node` (required, not "all"), then `force` (a
/// vector, required).
fn point_force(
    ctx: &Ctx,
    key: &str,
    table: &toml::Table,
    elements: usize,
) -> Result<Load, ScenarioError> {
    ctx.field_types(key, table, &[("force", Field::Vector)])?;
    let p: RawPointForce = ctx.entry(key, table)?;
    let node = ctx.one_node(&format!("{key}.node"), p.node, elements)?;
    let fk = format!("{key}.force");
    let f = ctx.required(&fk, p.force)?;
    Ok(Load::PointForce {
        node,
        force: ctx.vector(&fk, &f)?,
    })
}

/// `type = "end-moment"`: `node` (required, not "all"), then `moment` (a
/// vector, required).
fn end_moment(
    ctx: &Ctx,
    key: &str,
    table: &toml::Table,
    elements: usize,
) -> Result<Load, ScenarioError> {
    ctx.field_types(key, table, &[("moment", Field::Vector)])?;
    let p: RawEndMoment = ctx.entry(key, table)?;
    let node = ctx.one_node(&format!("{key}.node"), p.node, elements)?;
    let mk = format!("{key}.moment");
    let m = ctx.required(&mk, p.moment)?;
    Ok(Load::EndMoment {
        node,
        moment: ctx.vector(&mk, &m)?,
    })
}

/// `type = "air-drag"` (eq. 17 of the paper): `drag_coefficient` and
/// `fluid_density` (>= 0, required), `diameter` (> 0; default
/// `material.diameter`), `fluid_velocity` (a vector; default zero),
/// `model` ("full", the default, or "normal") and
/// `tangential_coefficient` (>= 0, default 0; "normal" only), checked in
/// that order.
fn air_drag(
    ctx: &Ctx,
    key: &str,
    table: &toml::Table,
    diameter: f64,
) -> Result<Load, ScenarioError> {
    ctx.field_types(
        key,
        table,
        &[
            ("drag_coefficient", Field::Number),
            ("fluid_density", Field::Number),
            ("diameter", Field::Number),
            ("fluid_velocity", Field::Vector),
            ("model", Field::Text),
            ("tangential_coefficient", Field::Number),
        ],
    )?;
    let d: RawAirDrag = ctx.entry(key, table)?;
    let required_non_negative = |name: &str, v: Option<f64>| {
        let k = format!("{key}.{name}");
        ctx.non_negative(&k, ctx.required(&k, v)?)
    };
    let drag_coefficient = required_non_negative("drag_coefficient", d.drag_coefficient)?;
    let fluid_density = required_non_negative("fluid_density", d.fluid_density)?;
    let diameter = match d.diameter {
        Some(v) => ctx.positive(&format!("{key}.diameter"), v)?,
        None => diameter,
    };
    let fluid_velocity = ctx.vector_or(
        &format!("{key}.fluid_velocity"),
        d.fluid_velocity.as_deref(),
        [0.0; 3],
    )?;
    let tk = format!("{key}.tangential_coefficient");
    let model = match ctx.choice(
        &format!("{key}.model"),
        d.model.as_deref(),
        "full",
        &["full", "normal"],
    )? {
        "normal" => DragModel::Normal {
            tangential_coefficient: match d.tangential_coefficient {
                Some(v) => ctx.non_negative(&tk, v)?,
                None => 0.0,
            },
        },
        _ => {
            if d.tangential_coefficient.is_some() {
                return Err(ctx.err(
                    &tk,
                    "only the \"normal\" drag model has a tangential coefficient",
                ));
            }
            DragModel::Full
        }
    };
    Ok(Load::AirDrag(AirDrag {
        drag_coefficient,
        fluid_density,
        diameter,
        fluid_velocity,
        model,
    }))
}
