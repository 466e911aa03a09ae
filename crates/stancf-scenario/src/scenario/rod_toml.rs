//! `[[rod_types]]`, `[[rods]]` and the `[[points]]` of type "rod" of a
//! TOML system (docs/interface.md, "Rods"); what a rod is, `rods.rs`.

use super::bodies::SystemBody;
use super::context::Ctx;
use super::raw::{RawPoint, RawRod, RawRodType};
use super::rod_parts::{free_rod_body, next_body_id, rod_of, RodHolder, RodTypeValues, SystemRod};
use super::system_parts::{PointType, SystemPoint};
use super::ScenarioError;
use stancf::vec3::sub;

/// `[[rod_types]]`: `name` (required, unique), `diameter` (> 0,
/// required), `mass_per_length` (>= 0, required), `cd`, `ca`, `cd_end`,
/// `ca_end` (>= 0, default 0).
pub(super) fn rod_types(
    ctx: &Ctx,
    raw: &[RawRodType],
) -> Result<Vec<RodTypeValues>, ScenarioError> {
    let mut out: Vec<RodTypeValues> = Vec::with_capacity(raw.len());
    for (i, r) in raw.iter().enumerate() {
        let key = |k: &str| format!("rod_types[{i}].{k}");
        let name = ctx.required(&key("name"), r.name.clone())?;
        if out.iter().any(|t| t.name == name) {
            return Err(ctx.err(&key("name"), format!("\"{name}\" is defined twice")));
        }
        let optional = |k: &str, v: Option<f64>| match v {
            Some(v) => ctx.non_negative(&key(k), v),
            None => Ok(0.0),
        };
        out.push(RodTypeValues {
            diameter: ctx.required_positive(&key("diameter"), r.diameter)?,
            mass_per_length: ctx.non_negative(
                &key("mass_per_length"),
                ctx.required(&key("mass_per_length"), r.mass_per_length)?,
            )?,
            cd: optional("cd", r.cd)?,
            ca: optional("ca", r.ca)?,
            cd_end: optional("cd_end", r.cd_end)?,
            ca_end: optional("ca_end", r.ca_end)?,
            name,
        });
    }
    Ok(out)
}

/// `[[rods]]`: `id` (required, unique), `type` ("free", "fixed",
/// "pinned", "coupled" (a coupled body of its own, reference point at
/// end A), "coupled_pinned" (end A on a coupled point) or "body",
/// required), `body` (a body's id, for type "body"
/// only), `rod_type` (a `[[rod_types]]` name, required), `end_a`, `end_b`
/// (required, apart; global, or in the body's axes from its reference
/// point for type "body"), `segments` (>= 1, default 1: the drag's
/// quadrature). A free or pinned rod's body is pushed onto `bodies`, its
/// id one more than the largest there; a pinned rod's end A is held at a
/// fixed point there ([`pin_points`]).
pub(super) fn rods(
    ctx: &Ctx,
    (types, raw): (&[RodTypeValues], &[RawRod]),
    bodies: &mut Vec<SystemBody>,
) -> Result<Vec<SystemRod>, ScenarioError> {
    let mut out: Vec<SystemRod> = Vec::with_capacity(raw.len());
    for (i, r) in raw.iter().enumerate() {
        let key = |k: &str| format!("rods[{i}].{k}");
        let id = ctx.required(&key("id"), r.id)?;
        if out.iter().any(|o| o.id == id) {
            return Err(ctx.err(&key("id"), format!("rod {id} is defined twice")));
        }
        let word = ctx.choice(
            &key("type"),
            Some(ctx.required(&key("type"), r.kind.as_deref())?),
            "",
            &[
                "free",
                "fixed",
                "pinned",
                "coupled",
                "coupled_pinned",
                "body",
            ],
        )?;
        let type_name = ctx.required(&key("rod_type"), r.rod_type.as_deref())?;
        let Some(type_index) = types.iter().position(|t| t.name == type_name) else {
            let known: Vec<&str> = types.iter().map(|t| t.name.as_str()).collect();
            let known = if known.is_empty() {
                "there are no [[rod_types]]".to_string()
            } else {
                format!("known: {}", known.join(", "))
            };
            return Err(ctx.err(
                &key("rod_type"),
                format!(
                    "rod type \"{}\" is not defined ({known})",
                    super::clip(type_name, 60)
                ),
            ));
        };
        let t = &types[type_index];
        let end =
            |k: &str, v: &Option<Vec<f64>>| ctx.vector(&key(k), &ctx.required(&key(k), v.clone())?);
        let (a, b) = (end("end_a", &r.end_a)?, end("end_b", &r.end_b)?);
        let segments = match r.segments {
            Some(n) => ctx.count(&key("segments"), n, 1, 10_000)?,
            None => 1,
        };
        if !matches!(word, "body" | "pinned") && r.body.is_some() {
            return Err(ctx.err(
                &key("body"),
                format!(
                    "names the body of a rod of type \"body\" or \"pinned\"; this rod is \
                     \"{word}\""
                ),
            ));
        }
        let (holder, local, ends) = match word {
            "fixed" => (RodHolder::Fixed, [a, b], [a, b]),
            "free" | "pinned" | "coupled_pinned" => {
                // A rod pinned to a body: its ends in the body's axes from
                // its reference point, end A held at that body point.
                let (ends, host) = match r.body {
                    Some(_) if word == "pinned" => {
                        let on = body_index(ctx, &key("body"), r.body, bodies)?;
                        // A joint on a free body (§15.14), a pin on a coupled
                        // body's motion (§15.17): at a point of the body.
                        let fixed = bodies[on].kind == super::bodies::BodyType::Fixed;
                        let host = (!fixed).then_some((on, a));
                        ([bodies[on].point(a), bodies[on].point(b)], host)
                    }
                    _ => ([a, b], None),
                };
                let body = bodies.len();
                bodies.push(free_rod_body(next_body_id(bodies), ends[0]));
                let holder = match word {
                    "free" => RodHolder::Free { body },
                    _ => RodHolder::Pinned {
                        body,
                        host,
                        coupled: word == "coupled_pinned",
                    },
                };
                (holder, [[0.0; 3], sub(ends[1], ends[0])], ends)
            }
            "coupled" => {
                // MoorDyn's coupled rod: a coupled body of its own at end A.
                let body = bodies.len();
                bodies.push(SystemBody {
                    kind: super::bodies::BodyType::Coupled,
                    ..free_rod_body(next_body_id(bodies), a)
                });
                (RodHolder::Coupled { body }, [[0.0; 3], sub(b, a)], [a, b])
            }
            _ => {
                // On a coupled body its weight, water and inertia push the
                // host (docs/method.md §15.18).
                let body = body_index(ctx, &key("body"), r.body, bodies)?;
                let ends = [bodies[body].point(a), bodies[body].point(b)];
                (RodHolder::Body { body }, [a, b], ends)
            }
        };
        let rod = rod_of(t, local[0], local[1], segments);
        rod.validate(&format!("rods[{i}]"))
            .map_err(|e| ctx.err(&e.key, e.message))?;
        let rod = SystemRod {
            id,
            holder,
            type_name: t.name.clone(),
            type_index,
            rod: Some(rod),
            ends,
            local,
            points: [None; 2],
        };
        out.push(rod);
    }
    Ok(out)
}

/// The body (its index) `id` names, required.
fn body_index(
    ctx: &Ctx,
    key: &str,
    id: Option<i64>,
    bodies: &[SystemBody],
) -> Result<usize, ScenarioError> {
    let id = ctx.required(key, id)?;
    bodies.iter().position(|b| b.id == id).ok_or_else(|| {
        let known: Vec<String> = bodies.iter().map(|b| b.id.to_string()).collect();
        let known = if known.is_empty() {
            "there are no [[bodies]]".to_string()
        } else {
            format!("known: {}", known.join(", "))
        };
        ctx.err(key, format!("body {id} is not defined ({known})"))
    })
}

/// A point at a rod's end: its kind, its position at t = 0, and the rod
/// (index) and end (0 for A, 1 for B) it is at.
pub(super) struct RodPoint {
    pub(super) kind: PointType,
    pub(super) position: [f64; 3],
    pub(super) rod: usize,
    pub(super) end: usize,
}

/// A `[[points]]` entry i of type "rod": `rod` (a rod's id) and `end`
/// ("A" or "B"), both required, and no `position` (the rod's end is
/// where the point is).
pub(super) fn rod_point(
    ctx: &Ctx,
    i: usize,
    r: &RawPoint,
    rods: &[SystemRod],
) -> Result<RodPoint, ScenarioError> {
    let key = |k: &str| format!("points[{i}].{k}");
    if r.position.is_some() {
        return Err(ctx.err(
            &key("position"),
            "a point of type \"rod\" is at the rod's end (rod and end name it): leave the \
             position out",
        ));
    }
    let id = ctx.required(&key("rod"), r.rod)?;
    let Some(k) = rods.iter().position(|o| o.id == id) else {
        let known: Vec<String> = rods.iter().map(|o| o.id.to_string()).collect();
        let known = if known.is_empty() {
            "there are no [[rods]]".to_string()
        } else {
            format!("known: {}", known.join(", "))
        };
        return Err(ctx.err(&key("rod"), format!("rod {id} is not defined ({known})")));
    };
    let end = match ctx.choice(
        &key("end"),
        Some(ctx.required(&key("end"), r.end.as_deref())?),
        "",
        &["A", "B"],
    )? {
        "A" => 0,
        _ => 1,
    };
    Ok(RodPoint {
        kind: super::rods::end_kind(&rods[k], end),
        position: rods[k].ends[end],
        rod: k,
        end,
    })
}

/// The fixed point each pinned rod's end A is held at: the `[[points]]`
/// entry of type "rod" at that end if there is one, else a fixed point
/// pushed onto `points` there, its id one more than the largest (call
/// after the lines are read: no line can name it).
pub(super) fn pin_points(rods: &mut [SystemRod], points: &mut Vec<SystemPoint>) {
    for rod in rods.iter_mut() {
        if !matches!(rod.holder, RodHolder::Pinned { .. }) || rod.points[0].is_some() {
            continue;
        }
        let id = SystemPoint::next_id(points);
        points.push(super::rods::end_point(rod, 0, id));
        rod.points[0] = Some(points.len() - 1);
    }
}

/// Refuses `rod` and `end` on a point whose type is not "rod".
pub(super) fn refuse_rod_keys(
    ctx: &Ctx,
    i: usize,
    r: &RawPoint,
    word: &str,
) -> Result<(), ScenarioError> {
    if word == "rod" {
        return Ok(());
    }
    for (k, given) in [("rod", r.rod.is_some()), ("end", r.end.is_some())] {
        if given {
            return Err(ctx.err(
                &format!("points[{i}].{k}"),
                format!("names the rod end of a point of type \"rod\"; this point is \"{word}\""),
            ));
        }
    }
    Ok(())
}

/// Notes for rod types whose water coefficients a scenario without water
/// leaves unused.
pub(super) fn rod_types_in_air(types: &[RodTypeValues], in_water: bool) -> Vec<String> {
    if in_water {
        return Vec::new();
    }
    types
        .iter()
        .enumerate()
        .filter(|(_, t)| [t.cd, t.ca, t.cd_end, t.ca_end].iter().any(|&c| c != 0.0))
        .map(|(i, _)| {
            format!(
                "rod_types[{i}]: cd, ca, cd_end and ca_end act in water, which this scenario \
                 does not have ([water]): unused"
            )
        })
        .collect()
}
