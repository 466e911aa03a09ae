//! Where a line may be clamped in a direction (docs/method.md §6.10,
//! §15.19-§15.20): the clamps at free bodies' points found and framed in
//! the bodies' axes, the connectors checked, and the clamped r_x's start
//! rates made the turning frame's.

use super::body_clamps::BodyClamp;
use super::{Body, BodyKind, End, Line, Point};
use crate::error::ModelError;
use crate::model::{coordinate, SLOT_R_X};
use crate::vec3::{dot, scale};

/// Checks line `li`'s direction holds and returns those at a free body's
/// point, marked turning ([`DirectionHold::turning`]) with their frames in
/// the body's axes. A hold must be at a line end attached to a fixed or
/// coupled point (its frame fixed in space, §6.10) or to a free body's
/// point (§15.19); at a coupled body's point (a frame the host turns) it
/// is refused, as at a free point or a loose end (nothing to clamp to).
pub(super) fn line_clamps(
    li: usize,
    line: &mut Line,
    points: &[Point],
    bodies: &[Body],
    body_points: &[Vec<(usize, [f64; 3])>],
) -> Result<Vec<BodyClamp>, ModelError> {
    let last = super::end_node(&line.model, 1);
    let mut clamps = Vec::new();
    let key = || format!("lines[{li}]");
    for (h, hold) in line.model.constraints.directions.iter_mut().enumerate() {
        let end = match hold.node {
            0 => 0,
            n if n == last => 1,
            n => {
                return Err(ModelError::invalid(
                    key(),
                    format!("node {n} is clamped in a direction; only a line end may be"),
                ))
            }
        };
        let name = ["A", "B"][end];
        let End::Point(p) = line.ends[end] else {
            return Err(ModelError::invalid(
                key(),
                format!("end {name} is clamped in a direction but attached to nothing"),
            ));
        };
        if let Some(b) = points[p].body() {
            let back = crate::vec3::mat3_transpose(&bodies[b].rotation);
            hold.turning = true;
            clamps.push(BodyClamp {
                line: li,
                hold: h,
                node: hold.node,
                body: b,
                local: hold.turned(&back),
            });
            continue;
        }
        let host = (0..bodies.len()).find(|&b| {
            bodies[b].kind == BodyKind::Coupled && body_points[b].iter().any(|&(q, _)| q == p)
        });
        if let Some(b) = host {
            return Err(ModelError::invalid(
                key(),
                format!(
                    "end {name} is clamped in a direction at a point of coupled body {b}: a \
                     clamp that turns with a body the host moves is not built yet (at a fixed \
                     or free body it is)"
                ),
            ));
        }
        if points[p].is_unknown() {
            return Err(ModelError::invalid(
                key(),
                format!(
                    "end {name} is clamped in a direction but attached to a free point (a free \
                     point has no rotation to clamp to; a body's point has)"
                ),
            ));
        }
    }
    Ok(clamps)
}

/// The start states' r_x rates at the clamps made those of the turning
/// frame: r_x = s d(t) gives r_x' = (d . r_x') d + omega x r_x (omega the
/// body's angular velocity, global), so the hold's rate C_k' is zero at
/// the start (the step's first rows assume it, (B37)). `models` hold the
/// frames at the bodies' poses, `spins` are the bodies' angular
/// velocities; r_x is turned onto d first (length and sense kept).
pub(super) fn start_rates(
    clamps: &[BodyClamp],
    models: &[crate::model::Model],
    spins: &[[f64; 3]],
    states: &mut [crate::model::State],
) {
    for clamp in clamps {
        let model = &models[clamp.line];
        let hold = &model.constraints.directions[clamp.hold];
        let o = coordinate(model.dofs_per_node(), clamp.node, SLOT_R_X, 0);
        let state = &mut states[clamp.line];
        let d = hold.direction;
        let r_x = [state.e[o], state.e[o + 1], state.e[o + 2]];
        // r_x turned onto d, length and sense kept (as §6.10's start).
        let r_x = scale(crate::vec3::norm(r_x) * dot(d, r_x).signum(), d);
        let along = dot(d, [state.v[o], state.v[o + 1], state.v[o + 2]]);
        let turn = crate::vec3::cross(spins[clamp.body], r_x);
        for c in 0..3 {
            state.e[o + c] = r_x[c];
            state.v[o + c] = along * d[c] + turn[c];
        }
    }
}

/// Refuses a connector (docs/method.md §15.20) with a point off its
/// reference point, no line clamped to it, or a clamp not along its z
/// axis. Key `bodies[b]`.
pub(super) fn check_connectors(
    bodies: &[Body],
    body_points: &[Vec<(usize, [f64; 3])>],
    clamps: &[BodyClamp],
) -> Result<(), ModelError> {
    for b in (0..bodies.len()).filter(|&b| bodies[b].connector) {
        let key = format!("bodies[{b}]");
        if body_points[b].iter().any(|(_, local)| *local != [0.0; 3]) {
            return Err(ModelError::invalid(
                key,
                "a connector's points are at its reference point",
            ));
        }
        let mut on = clamps.iter().filter(|c| c.body == b).peekable();
        if on.peek().is_none() {
            return Err(ModelError::invalid(
                key,
                "is a connector and no line is clamped to it (a free point joins lines without \
                 bending stiffness)",
            ));
        }
        if on.any(|c| (1.0 - c.local.direction[2].abs()) > 1e-9) {
            return Err(ModelError::invalid(
                key,
                "a connector's lines are clamped along its z axis",
            ));
        }
    }
    Ok(())
}
