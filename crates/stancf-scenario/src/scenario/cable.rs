//! `[cable]` (the straight reference line and its mesh) and `[material]`
//! (the section's stiffness and mass, and the diameter seen by drag).

use super::context::Ctx;
use super::raw::{RawCable, RawGrading, RawMaterial, RawSection};
use super::ScenarioError;
use stancf::{ElementType, GradedEnd, Grading, Material, MeshSection};

/// `[cable]`: `length` (> 0, required), `elements` (1..=1000000,
/// required unless the grading has sections), `element` ("SAC-2", the
/// default, or "SAC-3"), `origin` (default [0, 0, 0]) and `direction`
/// (default [1, 0, 0], not zero; made a unit vector), `grading` (see
/// [`mesh`]; default uniform).
pub(super) fn cable(ctx: &Ctx, raw: Option<RawCable>) -> Result<stancf::Cable, ScenarioError> {
    let rc = ctx.required("cable", raw)?;
    let length = ctx.required_positive("cable.length", rc.length)?;
    let (elements, grading) = mesh(ctx, "cable", length, rc.elements, rc.grading.as_ref())?;
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
        grading,
    })
}

/// The largest element count of a line (`elements` and the sum of
/// `grading.sections`' elements): the core's.
const MAX_ELEMENTS: i64 = stancf::model::MAX_ELEMENTS as i64;

/// `<owner>.elements` and `<owner>.grading` of a line of `length`: the
/// element count and the mesh (docs/method.md §1.6).
///
/// - `grading = { toward = "A" | "B" | "both", ratio = R }`, both keys
///   required: the elements shortest at `toward`, the longest R times the
///   shortest (R >= 1, finite; (M38)); `elements` required.
/// - `grading = { sections = [{ length, elements }, ...] }` from end A,
///   each in equal elements of its own length ((M38a)); the lengths add
///   up to the line's, `elements` may be left out (it is their sum; given,
///   it must be).
/// - no grading: uniform, `elements` required.
///
/// `owner` is `cable`, `lines[i]` or `mesh[i]`; the key named in an error
/// is under it.
pub(super) fn mesh(
    ctx: &Ctx,
    owner: &str,
    length: f64,
    raw_elements: Option<i64>,
    raw: Option<&RawGrading>,
) -> Result<(usize, Grading), ScenarioError> {
    let elements_key = format!("{owner}.elements");
    if let Some(
        g @ RawGrading {
            sections: Some(sections),
            ..
        },
    ) = raw
    {
        for (present, k) in [(g.toward.is_some(), "toward"), (g.ratio.is_some(), "ratio")] {
            if present {
                return Err(ctx.err(
                    &format!("{owner}.grading.{k}"),
                    "a grading is either geometric (toward, ratio) or in sections, not both",
                ));
            }
        }
        let sections = self::sections(ctx, owner, sections)?;
        let count: usize = sections.iter().map(|s| s.elements).sum();
        if count as i64 > MAX_ELEMENTS {
            return Err(ctx.err(
                &format!("{owner}.grading.sections"),
                format!("the sections' elements add up to {count}, more than {MAX_ELEMENTS}"),
            ));
        }
        if let Some(n) = raw_elements {
            if n != count as i64 {
                return Err(ctx.err(
                    &elements_key,
                    format!(
                        "is {n}, the sections of {owner}.grading have {count} elements (leave \
                         elements out to take their sum)"
                    ),
                ));
            }
        }
        let grading = Grading::Sections(sections);
        check(ctx, owner, &grading, length, count)?;
        return Ok((count, grading));
    }
    let elements = ctx.count(
        &elements_key,
        ctx.required(&elements_key, raw_elements)?,
        1,
        MAX_ELEMENTS,
    )?;
    Ok((elements, grading(ctx, owner, raw, length, elements)?))
}

/// `<owner>.grading.sections`: each `{ length, elements }` with both keys
/// required (their values checked by [`stancf::Grading::check`]).
fn sections(ctx: &Ctx, owner: &str, raw: &[RawSection]) -> Result<Vec<MeshSection>, ScenarioError> {
    let mut out = Vec::with_capacity(raw.len());
    for (i, r) in raw.iter().enumerate() {
        let key = |k: &str| format!("{owner}.grading.sections[{i}].{k}");
        let length = ctx.required_positive(&key("length"), r.length)?;
        let elements = ctx.count(
            &key("elements"),
            ctx.required(&key("elements"), r.elements)?,
            1,
            MAX_ELEMENTS,
        )?;
        out.push(MeshSection { length, elements });
    }
    Ok(out)
}

/// [`stancf::Grading::check`], its error's key put under `owner`.
fn check(
    ctx: &Ctx,
    owner: &str,
    grading: &Grading,
    length: f64,
    elements: usize,
) -> Result<(), ScenarioError> {
    grading.check(length, elements).map_err(|e| {
        let under = e.key.strip_prefix("cable").unwrap_or(&e.key);
        ctx.err(&format!("{owner}{under}"), e.message)
    })
}

/// A geometric `<owner>.grading` (see [`mesh`]); missing: uniform.
fn grading(
    ctx: &Ctx,
    owner: &str,
    raw: Option<&RawGrading>,
    length: f64,
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
    check(ctx, owner, &g, length, elements)?;
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
