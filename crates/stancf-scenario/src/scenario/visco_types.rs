//! A line type's viscoelastic law (docs/method.md §2.11): the TOML keys
//! `ea_dynamic`, or `ea_dynamic_alpha` with `ea_dynamic_beta`, and
//! `ba_dynamic` of `[[line_types]]` (a deck's `EA|EA_D`, `EA|alphaMBL|vbeta`
//! and `BA|BA_D`, read in `moordyn/visco_columns.rs`), and the check of the
//! law a line type gives, with the key to name.

use super::context::Ctx;
use super::raw::{RawLine, RawLineType, RawSyrope};
use super::system_parts::LineType;
use super::ScenarioError;
use stancf::element::{DynamicStiffness, Syrope, Viscoelastic, WorkingCurveForm};

/// The dynamic stiffness and BA_D of `[[line_types]]` entry `i`.
pub(super) fn toml_dynamic(
    ctx: &Ctx,
    i: usize,
    r: &RawLineType,
) -> Result<(Option<DynamicStiffness>, f64), ScenarioError> {
    let key = |k: &str| format!("line_types[{i}].{k}");
    let dynamic =
        match (r.ea_dynamic, r.ea_dynamic_alpha, r.ea_dynamic_beta) {
            (None, None, None) => match &r.syrope {
                Some(s) => Some(toml_syrope(ctx, &key("syrope"), s, r)?),
                None => None,
            },
            _ if r.syrope.is_some() => {
                return Err(ctx.err(
                    &key("syrope"),
                    "Syrope's law has its own dynamic stiffness (alpha, beta): leave out \
                     ea_dynamic, ea_dynamic_alpha and ea_dynamic_beta",
                ))
            }
            (Some(k2), None, None) => Some(DynamicStiffness::Constant(
                ctx.finite(&key("ea_dynamic"), k2)?,
            )),
            (None, Some(alpha), Some(beta)) => Some(DynamicStiffness::MeanLoad {
                alpha: ctx.finite(&key("ea_dynamic_alpha"), alpha)?,
                beta: ctx.finite(&key("ea_dynamic_beta"), beta)?,
            }),
            (Some(_), _, _) => return Err(ctx.err(
                &key("ea_dynamic"),
                "a constant dynamic stiffness goes alone: give ea_dynamic, or ea_dynamic_alpha \
                 and ea_dynamic_beta (alpha + beta times the static spring's tension)",
            )),
            (None, _, _) => return Err(ctx.err(
                &key("ea_dynamic_alpha"),
                "the mean-load dynamic stiffness alpha + beta T1 takes both ea_dynamic_alpha and \
                 ea_dynamic_beta",
            )),
        };
    let ba_dynamic =
        match r.ba_dynamic {
            Some(_) if dynamic.is_none() => return Err(ctx.err(
                &key("ba_dynamic"),
                "the dashpot beside the dynamic spring needs a viscoelastic law (ea_dynamic, or \
                 ea_dynamic_alpha and ea_dynamic_beta)",
            )),
            Some(v) => ctx.non_negative(&key("ba_dynamic"), v)?,
            None => 0.0,
        };
    if dynamic.is_some() && r.ea_curve.is_some() {
        return Err(ctx.err(
            &key("ea_curve"),
            "a line type takes a tension-strain curve or a viscoelastic law, not both",
        ));
    }
    Ok((dynamic, ba_dynamic))
}

/// `syrope = { curve, working_curve, k1, k2, alpha, beta }` (each
/// required; docs/method.md §2.12): the original working curve's
/// [strain, tension] rows, the formula ("linear", "quadratic" or "exp",
/// MoorDyn's WCType), its k1 and k2 and the dynamic stiffness
/// alpha + beta T (N, -; MoorDyn's alphaMBL and vbeta). `ea` is not
/// given (the working curve is the static law).
fn toml_syrope(
    ctx: &Ctx,
    key: &str,
    s: &RawSyrope,
    r: &RawLineType,
) -> Result<DynamicStiffness, ScenarioError> {
    let sub = |k: &str| format!("{key}.{k}");
    if r.ea.is_some() || r.ea_curve.is_some() {
        return Err(ctx.err(
            key,
            "gives the static law (its working curves): leave out ea and ea_curve",
        ));
    }
    let rows = ctx.required(&sub("curve"), s.curve.as_ref())?;
    let mut points = Vec::with_capacity(rows.len());
    for (k, row) in rows.iter().enumerate() {
        match row.as_slice() {
            [x, y] => points.push((*x, *y)),
            _ => {
                return Err(ctx.err(
                    &sub("curve"),
                    format!(
                        "row {} has {} numbers; each is [strain, tension]",
                        k + 1,
                        row.len()
                    ),
                ))
            }
        }
    }
    let form = match ctx.required(&sub("working_curve"), s.working_curve.as_deref())? {
        "linear" => WorkingCurveForm::Linear,
        "quadratic" => WorkingCurveForm::Quadratic,
        "exp" => WorkingCurveForm::Exponential,
        other => {
            return Err(ctx.err(
                &sub("working_curve"),
                format!("is \"{other}\"; expected \"linear\", \"quadratic\" or \"exp\""),
            ))
        }
    };
    let k1 = ctx.required(&sub("k1"), s.k1)?;
    let k2 = ctx.required(&sub("k2"), s.k2)?;
    let alpha = ctx.required(&sub("alpha"), s.alpha)?;
    let beta = ctx.required(&sub("beta"), s.beta)?;
    let curves = Syrope::new(&points, form, (k1, k2), (alpha, beta), key)
        .map_err(|e| ctx.err(key, e.message))?;
    Ok(DynamicStiffness::Syrope {
        curves: std::sync::Arc::new(curves),
        tmax0: f64::NAN,
    })
}

/// `tmax0` of `[[lines]]` entry `i` (N): required for a line of a Syrope
/// type (above the original curve's first tension, at most its last),
/// refused on another.
pub(super) fn toml_tmax0(
    ctx: &Ctx,
    i: usize,
    r: &RawLine,
    t: &LineType,
) -> Result<Option<f64>, ScenarioError> {
    let key = format!("lines[{i}].tmax0");
    match (&t.ea_dynamic, r.tmax0) {
        (Some(DynamicStiffness::Syrope { curves, .. }), Some(v)) => {
            curves
                .check_tmax(v, &key)
                .map_err(|e| ctx.err(&key, e.message))?;
            Ok(Some(v))
        }
        (Some(DynamicStiffness::Syrope { .. }), None) => Err(ctx.err(
            &key,
            format!(
                "line type \"{}\" follows Syrope's working curves: give the largest mean \
                 tension the line has carried, tmax0 (N)",
                t.name
            ),
        )),
        (_, Some(_)) => Err(ctx.err(
            &key,
            format!("is Syrope's; line type \"{}\" has no Syrope law", t.name),
        )),
        (_, None) => Ok(None),
    }
}

/// Checks the viscoelastic law of line type `t` (if any) against its
/// static EA ([`Viscoelastic::check`]; a BA given as a damping ratio is
/// positive on every line): on failure the key (`ea_dynamic` or `ba`)
/// and the message.
pub(super) fn check_law(t: &LineType) -> Result<(), (&'static str, String)> {
    let Some(dynamic) = &t.ea_dynamic else {
        return Ok(());
    };
    if t.ba == 0.0 && t.ba_dynamic == 0.0 {
        return Err((
            "ba",
            "a viscoelastic line needs dashpots BA >= 0 and BA_D >= 0, not both zero".into(),
        ));
    }
    if let DynamicStiffness::Syrope { .. } = dynamic {
        return Ok(()); // the curves are checked as read, Tmax0 per line
    }
    let law = Viscoelastic {
        dynamic: dynamic.clone(),
        static_damping: t.ba.abs(),
        dynamic_damping: t.ba_dynamic,
    };
    law.check(t.ea, "").map_err(|e| {
        let key = match dynamic {
            DynamicStiffness::MeanLoad { beta, .. } if beta.is_nan() || *beta < 0.0 => {
                "ea_dynamic_beta"
            }
            DynamicStiffness::MeanLoad { .. } => "ea_dynamic_alpha",
            _ => "ea_dynamic",
        };
        (key, e.message)
    })
}

/// The law of line type `t` on a line whose dashpot beside the static
/// spring is `ba` (N s; the line's BA of a damping ratio) and whose
/// Syrope Tmax0 is `tmax0`.
pub(super) fn line_law(t: &LineType, ba: f64, tmax0: Option<f64>) -> Option<Viscoelastic> {
    let dynamic = match t.ea_dynamic.clone()? {
        DynamicStiffness::Syrope { curves, .. } => DynamicStiffness::Syrope {
            curves,
            tmax0: tmax0.unwrap_or(f64::NAN),
        },
        other => other,
    };
    Some(Viscoelastic {
        dynamic,
        static_damping: ba,
        dynamic_damping: t.ba_dynamic,
    })
}
