//! `[deck]` of a scenario that takes a MoorDyn deck (`system.moordyn`):
//! values of the deck set by name, so that a sweep reaches them as it
//! reaches a TOML system's (docs/interface.md, "MoorDyn decks"):
//!
//! - `deck.line_types.<TypeName>.<column>`: `diameter`, `mass_per_length`,
//!   `ea`, `ba`, `ei`, `cd`, `ca`, `cdax`, `caax` (the LINE TYPES columns
//!   Diam, Mass/m, EA, BA/-zeta, EI, Cd, Ca, CdAx, CaAx);
//! - `deck.lines.<ID>.length` (UnstrLen) and `.segments` (NumSegs);
//! - `deck.points.<ID>.position` (X Y Z), `.mass`, `.volume`, `.cda`,
//!   `.ca`.
//!
//! Each value is checked as the deck's column is (a diameter above 0, a
//! drag coefficient not below 0, ...); an unknown type, id or column is
//! an input error naming the key, and so is `ea` of a type whose EA is a
//! curve file or a viscoelastic or Syrope law (its column is not one
//! number).

use super::context::Ctx;
use super::ScenarioError;
use crate::moordyn::Deck;

/// The deck's values set from `[deck]` (see the module).
pub(super) fn set_deck_values(
    ctx: &Ctx,
    table: &toml::Table,
    deck: &mut Deck,
) -> Result<(), ScenarioError> {
    for (section, entries) in table {
        let key = format!("deck.{section}");
        let entries = sub_table(ctx, &key, entries)?;
        match section.as_str() {
            "line_types" => line_types(ctx, entries, deck)?,
            "lines" => lines(ctx, entries, deck)?,
            "points" => points(ctx, entries, deck)?,
            _ => {
                return Err(ctx.err(
                    &key,
                    "is not a deck section whose values a scenario sets (line_types, lines, \
                     points)",
                ))
            }
        }
    }
    Ok(())
}

fn sub_table<'a>(
    ctx: &Ctx,
    key: &str,
    v: &'a toml::Value,
) -> Result<&'a toml::Table, ScenarioError> {
    v.as_table()
        .ok_or_else(|| ctx.err(key, "must be a table of the deck's entries by name or id"))
}

/// A number (an integer is taken as one).
pub(super) fn number(ctx: &Ctx, key: &str, v: &toml::Value) -> Result<f64, ScenarioError> {
    let x = match v {
        toml::Value::Float(x) => *x,
        toml::Value::Integer(i) => *i as f64,
        other => return Err(ctx.err(key, format!("{other} is not a number"))),
    };
    ctx.finite(key, x)
}

/// The index of the entry of `id` (written as the deck's ID, 1, 2, ...)
/// among `count` entries numbered from 1.
fn by_id(ctx: &Ctx, key: &str, id: &str, count: usize, what: &str) -> Result<usize, ScenarioError> {
    match id.parse::<usize>() {
        Ok(n) if n >= 1 && n <= count && n.to_string() == id => Ok(n - 1),
        _ => Err(ctx.err(
            key,
            format!("the deck has no {what} {id} (its {what}s are 1 to {count})"),
        )),
    }
}

/// The index of the deck's line type `name` among `names` (its
/// TypeNames, in order), or an error at `key` listing them.
pub(super) fn type_named<'a>(
    ctx: &Ctx,
    key: &str,
    name: &str,
    names: impl Iterator<Item = &'a str> + Clone,
) -> Result<usize, ScenarioError> {
    names.clone().position(|n| n == name).ok_or_else(|| {
        let all: Vec<&str> = names.collect();
        ctx.err(
            key,
            format!(
                "the deck has no line type \"{name}\" (its types: {})",
                all.join(", ")
            ),
        )
    })
}

fn line_types(ctx: &Ctx, entries: &toml::Table, deck: &mut Deck) -> Result<(), ScenarioError> {
    for (name, columns) in entries {
        let key = format!("deck.line_types.{name}");
        let names = deck.line_types.iter().map(|t| t.name.as_str());
        let k = type_named(ctx, &key, name, names)?;
        for (column, v) in sub_table(ctx, &key, columns)? {
            let key = format!("{key}.{column}");
            let x = number(ctx, &key, v)?;
            let t = &mut deck.line_types[k];
            match column.as_str() {
                "diameter" => t.diameter = ctx.positive(&key, x)?,
                "mass_per_length" => t.mass_per_length = ctx.positive(&key, x)?,
                "ea" => {
                    if t.ea_curve_file.is_some() || t.ea_dynamic.is_some() || t.syrope.is_some() {
                        return Err(ctx.err(
                            &key,
                            "the type's EA is a curve file, a viscoelastic or a Syrope law, \
                             not one number",
                        ));
                    }
                    t.ea = ctx.positive(&key, x)?;
                }
                "ba" => t.ba = x,
                "ei" => t.ei = ctx.non_negative(&key, x)?,
                "cd" => t.cd_normal = ctx.non_negative(&key, x)?,
                "ca" => t.ca_normal = ctx.non_negative(&key, x)?,
                "cdax" => t.cd_axial = ctx.non_negative(&key, x)?,
                "caax" => t.ca_axial = ctx.non_negative(&key, x)?,
                _ => {
                    return Err(ctx.err(
                        &key,
                        "is not a line type column a scenario sets (diameter, \
                         mass_per_length, ea, ba, ei, cd, ca, cdax, caax)",
                    ))
                }
            }
        }
    }
    Ok(())
}

fn lines(ctx: &Ctx, entries: &toml::Table, deck: &mut Deck) -> Result<(), ScenarioError> {
    for (id, columns) in entries {
        let key = format!("deck.lines.{id}");
        let k = by_id(ctx, &key, id, deck.lines.len(), "line")?;
        for (column, v) in sub_table(ctx, &key, columns)? {
            let key = format!("{key}.{column}");
            match column.as_str() {
                "length" => {
                    let x = number(ctx, &key, v)?;
                    deck.lines[k].unstretched_length = ctx.positive(&key, x)?;
                }
                "segments" => {
                    let n = v
                        .as_integer()
                        .ok_or_else(|| ctx.err(&key, format!("{v} is not a whole number")))?;
                    let max = stancf::model::MAX_ELEMENTS as i64;
                    deck.lines[k].segments = ctx.count(&key, n, 1, max)?;
                }
                _ => {
                    return Err(ctx.err(
                        &key,
                        "is not a line column a scenario sets (length, segments)",
                    ))
                }
            }
        }
    }
    Ok(())
}

fn points(ctx: &Ctx, entries: &toml::Table, deck: &mut Deck) -> Result<(), ScenarioError> {
    for (id, columns) in entries {
        let key = format!("deck.points.{id}");
        let k = by_id(ctx, &key, id, deck.points.len(), "point")?;
        for (column, v) in sub_table(ctx, &key, columns)? {
            let key = format!("{key}.{column}");
            let p = &mut deck.points[k];
            if column == "position" {
                let xyz = v
                    .as_array()
                    .map(|a| a.iter().map(|c| number(ctx, &key, c)).collect())
                    .transpose()?
                    .ok_or_else(|| ctx.err(&key, "must be [x, y, z]"))?;
                let xyz: Vec<f64> = xyz;
                p.position = ctx.vector(&key, &xyz)?;
                continue;
            }
            let x = ctx.non_negative(&key, number(ctx, &key, v)?)?;
            match column.as_str() {
                "mass" => p.mass = x,
                "volume" => p.volume = x,
                "cda" => p.cda = x,
                "ca" => p.ca = x,
                _ => {
                    return Err(ctx.err(
                        &key,
                        "is not a point column a scenario sets (position, mass, volume, cda, \
                         ca)",
                    ))
                }
            }
        }
    }
    Ok(())
}
