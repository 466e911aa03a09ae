//! A line type's viscoelastic law (docs/method.md §2.11): the TOML keys
//! `ea_dynamic`, or `ea_dynamic_alpha` with `ea_dynamic_beta`, and
//! `ba_dynamic` of `[[line_types]]` (a deck's `EA|EA_D`, `EA|alphaMBL|vbeta`
//! and `BA|BA_D`, read in `moordyn/visco_columns.rs`), and the check of the
//! law a line type gives, with the key to name.

use super::context::Ctx;
use super::raw::RawLineType;
use super::system_parts::LineType;
use super::ScenarioError;
use stancf::element::{DynamicStiffness, Viscoelastic};

/// The dynamic stiffness and BA_D of `[[line_types]]` entry `i`.
pub(super) fn toml_dynamic(
    ctx: &Ctx,
    i: usize,
    r: &RawLineType,
) -> Result<(Option<DynamicStiffness>, f64), ScenarioError> {
    let key = |k: &str| format!("line_types[{i}].{k}");
    let dynamic =
        match (r.ea_dynamic, r.ea_dynamic_alpha, r.ea_dynamic_beta) {
            (None, None, None) => None,
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

/// Checks the viscoelastic law of line type `t` (if any) against its
/// static EA ([`Viscoelastic::check`]; a BA given as a damping ratio is
/// positive on every line): on failure the key (`ea_dynamic` or `ba`)
/// and the message.
pub(super) fn check_law(t: &LineType) -> Result<(), (&'static str, String)> {
    let Some(dynamic) = t.ea_dynamic else {
        return Ok(());
    };
    let law = Viscoelastic {
        dynamic,
        static_damping: t.ba.abs(),
        dynamic_damping: t.ba_dynamic,
    };
    law.check(t.ea, "").map_err(|e| {
        let key = match dynamic {
            _ if t.ba == 0.0 && t.ba_dynamic == 0.0 => "ba",
            DynamicStiffness::Constant(_) => "ea_dynamic",
            DynamicStiffness::MeanLoad { beta, .. } if !(beta >= 0.0) => "ea_dynamic_beta",
            DynamicStiffness::MeanLoad { .. } => "ea_dynamic_alpha",
        };
        (key, e.message)
    })
}

/// The law of line type `t` on a line whose dashpot beside the static
/// spring is `ba` (N s; the line's BA of a damping ratio).
pub(super) fn line_law(t: &LineType, ba: f64) -> Option<Viscoelastic> {
    t.ea_dynamic.map(|dynamic| Viscoelastic {
        dynamic,
        static_damping: ba,
        dynamic_damping: t.ba_dynamic,
    })
}
