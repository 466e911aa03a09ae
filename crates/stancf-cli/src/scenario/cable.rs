//! `[cable]` (the straight reference line and its mesh) and `[material]`
//! (the section's stiffness and mass, and the diameter seen by drag).

use super::context::Ctx;
use super::raw::{RawCable, RawGrading, RawMaterial};
use super::ScenarioError;
use stancf::{ElementType, GradedEnd, Grading, Material};

/// `[cable]`: `length` (> 0, required), `elements` (1..=1000000,
/// required), `element` ("SAC-2", the default, or "SAC-3"), `origin`
/// (default [0, 0, 0]) and `direction` (default [1, 0, 0], not zero; made
/// a unit vector), `grading` (see [`grading`]; default uniform).
pub(super) fn cable(ctx: &Ctx, raw: Option<RawCable>) -> Result<stancf::Cable, ScenarioError> {
    let rc = ctx.required("cable", raw)?;
    let length = ctx.required_positive("cable.length", rc.length)?;
    let elements = ctx.count(
        "cable.elements",
        ctx.required("cable.elements", rc.elements)?,
        1,
        1_000_000,
    )?;
    let element_type = match ctx.choice(
        "cable.element",
        rc.element.as_deref(),
        "SAC-2",
        &["SAC-2", "SAC-3"],
    )? {
        "SAC-3" => ElementType::Sac3,
        _ => ElementType::Sac2,
    };
    let origin = ctx.vector_or("cable.origin", rc.origin.as_deref(), [0.0; 3])?;
    let direction = ctx.vector_or("cable.direction", rc.direction.as_deref(), [1.0, 0.0, 0.0])?;
    if direction.iter().all(|&c| c == 0.0) {
        return Err(ctx.err("cable.direction", "must not be the zero vector"));
    }
    Ok(stancf::Cable {
        length,
        elements,
        element_type,
        origin,
        direction: unit(direction),
        grading: grading(ctx, "cable", rc.grading.as_ref(), elements)?,
    })
}

/// `<owner>.grading = { toward = "A" | "B" | "both", ratio = R }`, both
/// keys required: the elements shortest at `toward`, the longest R times
/// the shortest (R >= 1, finite; docs/method.md §1.6). Missing: uniform.
/// `owner` is `cable` or `lines[i]`; the key named in an error is under it.
pub(super) fn grading(
    ctx: &Ctx,
    owner: &str,
    raw: Option<&RawGrading>,
    elements: usize,
) -> Result<Grading, ScenarioError> {
    let Some(raw) = raw else {
        return Ok(Grading::Uniform);
    };
    let key = |k: &str| format!("{owner}.grading.{k}");
    let toward = match ctx.choice(
        &key("toward"),
        Some(ctx.required(&key("toward"), raw.toward.as_deref())?),
        "",
        &["A", "B", "both"],
    )? {
        "A" => GradedEnd::A,
        "B" => GradedEnd::B,
        _ => GradedEnd::Both,
    };
    let ratio = ctx.required(&key("ratio"), raw.ratio)?;
    let g = Grading::Geometric { toward, ratio };
    g.check(elements).map_err(|e| {
        let under = e.key.strip_prefix("cable").unwrap_or(&e.key);
        ctx.err(&format!("{owner}{under}"), e.message)
    })?;
    Ok(g)
}

/// The unit vector along a non-zero `v`. Only its direction counts: scaled
/// by its largest component first, so that [1e-200, 0, 0] and
/// [1e300, 0, 0] are unit vectors too (their squared lengths underflow or
/// overflow).
fn unit(v: [f64; 3]) -> [f64; 3] {
    let big = v.iter().fold(0.0f64, |m, c| m.max(c.abs()));
    let d = v.map(|c| c / big);
    let n = (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).sqrt();
    d.map(|c| c / n)
}

/// `[material]`: `youngs_modulus`, `density`, `area` and `second_moment`
/// (each > 0, required, in that order), `axial_damping` (BA in N s, >= 0,
/// default 0; docs/method.md §2.10) and the `diameter` (> 0; default
/// sqrt(4 area / pi)), returned beside the material.
pub(super) fn material(
    ctx: &Ctx,
    raw: Option<RawMaterial>,
) -> Result<(Material, f64), ScenarioError> {
    let rm = ctx.required("material", raw)?;
    let material = Material {
        youngs_modulus: ctx.required_positive("material.youngs_modulus", rm.youngs_modulus)?,
        density: ctx.required_positive("material.density", rm.density)?,
        area: ctx.required_positive("material.area", rm.area)?,
        second_moment: ctx.required_positive("material.second_moment", rm.second_moment)?,
        axial_damping: match rm.axial_damping {
            Some(v) if v < 0.0 => {
                return Err(ctx.err(
                    "material.axial_damping",
                    format!(
                        "must be >= 0 (BA in N s), got {v}: a damping ratio (MoorDyn's negative \
                         BA) is taken by [[line_types]] ba and MoorDyn decks only"
                    ),
                ))
            }
            Some(v) => ctx.non_negative("material.axial_damping", v)?,
            None => 0.0,
        },
    };
    let diameter = match rm.diameter {
        Some(d) => ctx.positive("material.diameter", d)?,
        None => (4.0 * material.area / std::f64::consts::PI).sqrt(),
    };
    Ok((material, diameter))
}
