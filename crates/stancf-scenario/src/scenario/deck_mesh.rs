//! `[[mesh]]`: the meshes a scenario gives a MoorDyn deck's lines in place
//! of the deck's uniform NumSegs (docs/interface.md, "Systems of lines").

use super::context::Ctx;
use super::raw::RawMesh;
use super::system_parts::{OutputChannel, SystemScenario};
use super::ScenarioError;

/// `[[mesh]]` of a MoorDyn deck: `lines` (deck line ids, required, each
/// line in one entry at most) take `elements` (default: the deck's
/// NumSegs, unless the grading has sections) and `grading` (see
/// [`super::cable::mesh`]) in place of the deck's uniform NumSegs. An
/// entry with neither changes nothing and is refused. The deck's output
/// channels of a remeshed line's end B (node NumSegs) move to its new
/// last node; a channel of an interior node is refused (that node is not
/// on the new mesh), and so is a line type's damping ratio (BA < 0, MoorDyn's
/// per-segment definition) on a mesh that is not uniform.
pub(super) fn deck_meshes(
    ctx: &Ctx,
    raw: &[RawMesh],
    sc: &mut SystemScenario,
) -> Result<(), ScenarioError> {
    let mut meshed: Vec<i64> = Vec::new();
    for (i, m) in raw.iter().enumerate() {
        let owner = format!("mesh[{i}]");
        let ids = ctx.required(&format!("{owner}.lines"), m.lines.as_ref())?;
        if ids.is_empty() {
            return Err(ctx.err(&format!("{owner}.lines"), "names no line"));
        }
        if m.elements.is_none() && m.grading.is_none() {
            return Err(ctx.err(
                &owner,
                "gives neither elements nor grading: it would leave the deck's mesh as it is",
            ));
        }
        let sectioned = m.grading.as_ref().is_some_and(|g| g.sections.is_some());
        for &id in ids {
            let key = format!("{owner}.lines");
            let Some(position) = sc.lines.iter().position(|l| l.id == id) else {
                let known: Vec<String> = sc.lines.iter().map(|l| l.id.to_string()).collect();
                return Err(ctx.err(
                    &key,
                    format!(
                        "the deck has no line {id} (its lines: {})",
                        known.join(", ")
                    ),
                ));
            };
            if meshed.contains(&id) {
                return Err(ctx.err(&key, format!("line {id} is meshed twice")));
            }
            meshed.push(id);
            let line = &mut sc.lines[position];
            let elements = m.elements.or((!sectioned).then_some(line.elements as i64));
            let (n, grading) =
                super::cable::mesh(ctx, &owner, line.length, elements, m.grading.as_ref())?;
            let ba = sc.line_types[line.line_type].ba;
            if ba < 0.0 && !grading.is_uniform() {
                return Err(ctx.err(
                    &format!("{owner}.grading"),
                    format!(
                        "line {id}'s type {} gives its axial damping as a damping ratio \
                         (BA = {ba}), which MoorDyn defines on segments of one length: give BA \
                         in N s in the deck, or mesh the line uniformly (elements alone)",
                        sc.line_types[line.line_type].name
                    ),
                ));
            }
            let old = line.elements;
            line.elements = n;
            line.grading = grading;
            sc.names.remeshed(position, i);
            remesh_channels(ctx, &owner, (position + 1, id), old, n, &mut sc.channels)?;
        }
    }
    Ok(())
}

/// The deck's channels of a line (its number in the deck, as channels
/// name lines, and its id) after its `old` segments became `new`
/// elements: end B's node follows the end, node 0 stays; an interior
/// node is refused under `owner.lines`.
fn remesh_channels(
    ctx: &Ctx,
    owner: &str,
    (number, id): (usize, i64),
    old: usize,
    new: usize,
    channels: &mut [OutputChannel],
) -> Result<(), ScenarioError> {
    for c in channels.iter_mut() {
        let crate::moordyn::Channel::LineNode { line, node, .. } = &mut c.channel else {
            continue;
        };
        if *line != number || *node == 0 {
            continue;
        }
        if *node != old {
            return Err(ctx.err(
                &format!("{owner}.lines"),
                format!(
                    "the deck's output channel {} names node {node} of line {id}'s {old} \
                     segments, which its new mesh does not have (end nodes A and B are kept)",
                    c.name
                ),
            ));
        }
        *node = new;
    }
    Ok(())
}
