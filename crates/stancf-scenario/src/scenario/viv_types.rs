//! A line type's VIV lift (docs/method.md §12.7): the TOML table `viv =
//! { cl, df, cf, averaging_time }` of `[[line_types]]` (a deck's `Cl dF
//! cF` columns are read in `moordyn/sections.rs`), its refusal in air,
//! and the note on the steps it is validated at.

use super::context::Ctx;
use super::raw::RawViv;
use super::system_parts::SystemScenario;
use super::ScenarioError;
use stancf::element::Viv;
use stancf::error::Sig;

/// `viv` of a line type at `key`: `cl` (> 0, required), `df` and `cf`
/// (MoorDyn's defaults 0.08 and 0.18), `averaging_time` (s, > 0,
/// required: MoorDyn's is 500 of its steps).
pub(super) fn toml_viv(
    ctx: &Ctx,
    key: &str,
    raw: Option<&RawViv>,
) -> Result<Option<Viv>, ScenarioError> {
    let Some(r) = raw else {
        return Ok(None);
    };
    let sub = |k: &str| format!("{key}.{k}");
    let law = Viv {
        lift: ctx.required_positive(&sub("cl"), r.cl)?,
        range: match r.df {
            Some(v) => ctx.non_negative(&sub("df"), v)?,
            None => crate::moordyn::VivColumns::RANGE,
        },
        centre: match r.cf {
            Some(v) => ctx.required_positive(&sub("cf"), Some(v))?,
            None => crate::moordyn::VivColumns::CENTRE,
        },
        averaging_time: match r.averaging_time {
            Some(v) => ctx.required_positive(&sub("averaging_time"), Some(v))?,
            None => {
                return Err(ctx.err(
                    &sub("averaging_time"),
                    "is required: the time (s) over which the running RMS of the line's \
                     cross-flow velocity and acceleration are taken (MoorDyn takes 500 of its \
                     steps: 0.05 s at dtM = 1e-4 s)",
                ))
            }
        },
    };
    law.check("").map_err(|e| ctx.err(&sub("df"), e.message))?;
    Ok(Some(law))
}

/// Refuses a line with VIV in air: the lift acts in water.
pub(super) fn refuse_viv_in_air(file: &str, sc: &SystemScenario) -> Result<(), ScenarioError> {
    if sc.water.is_some() {
        return Ok(());
    }
    match sc.line_types.iter().position(|t| t.viv.is_some()) {
        Some(i) => Err(ScenarioError(format!(
            "{file}: line_types[{i}].viv: the VIV lift acts in water, which this scenario does \
             not have ([water]): leave it out or give [water]"
        ))),
        None => Ok(()),
    }
}

/// `check`'s words on line type `t`'s VIV (empty without).
pub fn viv_words(t: &super::system_parts::LineType) -> String {
    let Some(v) = &t.viv else {
        return String::new();
    };
    format!(
        "; VIV lift Cl {}, shedding at f d / |v_n| = cF {} +- dF {}, running RMS over {} s \
         (MoorDyn's model, docs/method.md §12.7; in dynamics only)",
        Sig(v.lift),
        Sig(v.centre),
        Sig(v.range),
        Sig(v.averaging_time)
    )
}

/// The steps per shedding period d / (cF U) at which stancf's VIV is
/// validated: Thorsen's riser (MoorDyn's viv.txt) with the Galerkin step
/// at dt = 0.02 s, 33 steps per period, is within 0.25 % of the
/// frequency, 2 % of the cross-flow swing and 5 % of the tension's swing
/// at dt = 2.5 ms (docs/method.md §12.7).
pub const VALIDATED_STEPS_PER_SHEDDING: f64 = 30.0;

/// The notes on a dynamic run with VIV outside what it is validated for
/// (docs/method.md §12.7): the P2 step, a step longer than 1/30 of the
/// shedding period d / (cF U) in the fastest steady current U (the
/// profile's fastest row), or no steady current.
pub(super) fn viv_notes(sc: &SystemScenario) -> Vec<String> {
    if sc.analysis.kind != super::AnalysisKind::Dynamic {
        return Vec::new();
    }
    let used = |i: usize| sc.lines.iter().any(|l| l.line_type == i);
    let Some(water) = &sc.water else {
        return Vec::new();
    };
    let speed = fastest_current(water);
    let mut notes = Vec::new();
    for (i, t) in sc.line_types.iter().enumerate() {
        let Some(v) = t.viv.as_ref().filter(|_| used(i)) else {
            continue;
        };
        if sc.analysis.time_scheme == stancf::TimeScheme::P2 {
            notes.push(format!(
                "line type \"{}\": VIV (docs/method.md §12.7) is validated with the Galerkin \
                 step, not with P2 (analysis.time_scheme = \"galerkin\")",
                t.name
            ));
        }
        let Some(speed) = speed.filter(|u| *u > 0.0) else {
            notes.push(format!(
                "line type \"{}\": VIV (docs/method.md §12.7) is validated in a steady current; \
                 this water has {}, and the lift follows its flow unvalidated",
                t.name,
                if water.current.is_some() {
                    "one that varies in time"
                } else {
                    "none"
                }
            ));
            continue;
        };
        let period = t.diameter / (v.centre * speed);
        let dt = sc.analysis.time_step;
        if dt * VALIDATED_STEPS_PER_SHEDDING > period {
            notes.push(format!(
                "line type \"{}\": the step {} s is {} of the VIV shedding period d / (cF U) = \
                 {} s (U = {} m/s, the fastest steady current); VIV is validated at steps up to \
                 1/{} of it (docs/method.md §12.7)",
                t.name,
                Sig(dt),
                Sig(dt / period),
                Sig(period),
                Sig(speed),
                VALIDATED_STEPS_PER_SHEDDING
            ));
        }
    }
    notes
}

/// The fastest speed (m/s) of a steady current profile, its largest
/// row (the profile is linear between rows and constant beyond them);
/// None without a steady current (none, or one on a grid in time).
fn fastest_current(water: &super::Water) -> Option<f64> {
    match &water.current.as_ref()?.field {
        super::CurrentField::Profile(rows) => Some(
            rows.iter()
                .map(|r| r.velocity.iter().map(|u| u * u).sum::<f64>().sqrt())
                .fold(0.0, f64::max),
        ),
        super::CurrentField::Grid(_) => None,
    }
}
