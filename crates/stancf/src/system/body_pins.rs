//! The checks of a system's pinned bodies (docs/method.md §15.12,
//! §15.14): a pin where its body puts its point and moving as it moves,
//! and joints that form a tree, not a loop.

use super::{Body, BodyKind, Point, PointKind};
use crate::error::ModelError;

/// Refuses joints that close a loop (body a pinned to a point of b, ...,
/// pinned to a point of a): a loop of rigid bodies is not a tree of
/// joints, which is what §15.14 builds. Key `bodies[i].pin`.
pub(super) fn check_joint_loops(bodies: &[Body], points: &[Point]) -> Result<(), ModelError> {
    let parent = |b: usize| {
        let pin = bodies[b].pin?;
        points[pin.point].body()
    };
    for start in 0..bodies.len() {
        let mut b = start;
        for _ in 0..bodies.len() {
            match parent(b) {
                Some(next) if next == start => {
                    return Err(ModelError::invalid(
                        format!("bodies[{start}].pin"),
                        "the joints close a loop (the body hangs, through pins, from a point of                          itself): a loop of bodies is not built, only a tree of joints",
                    ))
                }
                Some(next) => b = next,
                None => break,
            }
        }
    }
    Ok(())
}

/// Checks body `index`'s pin: a free body's point held at a fixed point,
/// a free point or another free body's point (a joint, §15.14), where
/// the body puts that point at t = 0 and moving as it moves
/// (`velocities`, every point's at t = 0; to 1e-9 of the point's
/// distance from the origin, or of 1 m). A fixed body's pin holds
/// nothing and goes; a coupled body's, a pin to a coupled point, are
/// refused (not built).
pub(super) fn check_pin(
    index: usize,
    body: &mut Body,
    points: &[Point],
    velocities: &[[f64; 3]],
) -> Result<(), ModelError> {
    let Some(pin) = body.pin else {
        return Ok(());
    };
    match body.kind {
        BodyKind::Fixed => {
            body.pin = None;
            return Ok(());
        }
        BodyKind::Coupled => {
            return Err(ModelError::invalid(
                "",
                "a coupled body pinned (MoorDyn's CoupledPinned) is not built yet",
            ))
        }
        BodyKind::Free => {}
    }
    let Some(point) = points.get(pin.point) else {
        return Err(ModelError::invalid(
            "point",
            format!("{} names no point", pin.point),
        ));
    };
    match point.kind {
        PointKind::Fixed | PointKind::Free => {}
        PointKind::Body { body: on, .. } if on != index => {}
        PointKind::Body { .. } => {
            return Err(ModelError::invalid(
                "point",
                format!(
                    "point {} is on the body itself: a pin holds nothing",
                    pin.point
                ),
            ))
        }
        // A host's motion moves it (§15.17).
        PointKind::Coupled(_) => {}
    }
    let at = body.point(pin.local);
    let off = crate::vec3::norm(crate::vec3::sub(at, point.position));
    if off.is_nan() || off > 1e-9 * (1.0 + crate::vec3::norm(point.position)) {
        return Err(ModelError::invalid(
            "local",
            format!(
                "the body puts its pinned point at {at:?}, {off:.3e} m from point {} at {:?}: \
                 a pin starts where it holds",
                pin.point, point.position
            ),
        ));
    }
    let held = velocities[pin.point];
    let slip = crate::vec3::norm(crate::vec3::sub(body.point_velocity(pin.local), held));
    let scale = 1.0 + crate::vec3::norm(body.velocity) + crate::vec3::norm(held);
    if slip.is_nan() || slip > 1e-12 * scale {
        return Err(ModelError::invalid(
            "local",
            format!(
                "its pinned point moves at {slip:.3e} m/s from point {} at t = 0: a pin moves \
                 it with the point",
                pin.point
            ),
        ));
    }
    Ok(())
}
