//! What a static solve makes of a system's free bodies (docs/method.md
//! §15.8): their constant forces at their arms from the centre of mass,
//! their points, the scales of their unknowns and rows, and the holds of
//! a body no line gives a stiffness in some direction (§15.10-§15.12).

use super::StaticBody;
use crate::system::body_terms::{BodyPoint, PinHold};
use crate::system::System;

/// The stiffness scale of a body without lines, for its rows' weights:
/// its net weight over its size (the farthest of its pin, its rods' ends
/// and its centre of mass from one another; 1 m for a point-like body).
fn own_stiffness(body: &crate::system::Body, net: [f64; 3]) -> f64 {
    let mut size = 0.0f64;
    let c = body.inertia.centre_of_mass;
    if let Some(pin) = body.pin {
        size = size.max(crate::vec3::norm(crate::vec3::sub(pin.local, c)));
    }
    if let Some(w) = &body.water {
        for r in &w.rods {
            size = size.max(r.length());
        }
    }
    let size = if size > 0.0 { size } else { 1.0 };
    crate::vec3::norm(net) / size
}

/// The free bodies of `system` as a static solve holds them: their
/// weight and buoyancy at the centre of mass, their points' arms from it,
/// and the scales of §15.8.
pub(in crate::system) fn static_bodies(system: &System) -> Vec<StaticBody> {
    system
        .free_bodies_children_first()
        .into_iter()
        .map(|b| {
            let body = &system.bodies()[b];
            let c = body.inertia.centre_of_mass;
            let (volume, density) = body
                .water
                .as_ref()
                .map_or((0.0, 0.0), |w| (w.volume, w.density));
            let g = system.gravity();
            let net = g.map(|gc| (body.inertia.mass - density * volume) * gc);
            let mut length = f64::INFINITY;
            let mut arm = 0.0f64;
            let points: Vec<BodyPoint> = system
                .points()
                .iter()
                .enumerate()
                .filter(|(_, pt)| pt.body() == Some(b))
                .map(|(p, pt)| {
                    let crate::system::PointKind::Body { local, .. } = pt.kind else {
                        unreachable!("a point on a body")
                    };
                    for (li, _) in system.attachments(p) {
                        length = length.min(system.lines()[li].model.cable.length);
                    }
                    let arm_p = crate::vec3::sub(local, c);
                    arm = arm.max(crate::vec3::norm(arm_p));
                    BodyPoint {
                        point: p,
                        arm: arm_p,
                    }
                })
                .collect();
            let length = if length.is_finite() { length } else { 1.0 };
            StaticBody {
                index: b,
                rotation: body.rotation,
                centre_of_mass: c,
                forces: std::iter::once((net, [0.0; 3]))
                    .chain(
                        body.loads
                            .iter()
                            .map(|&(f, at)| (f, crate::vec3::sub(at, c))),
                    )
                    .collect(),
                points,
                length,
                arm: if arm > 0.0 { arm } else { length },
                stiffness: 0.0,
                converged: [0.0; 6],
                pin_force: [0.0; 3],
                drag: body
                    .water
                    .as_ref()
                    .filter(|w| {
                        let current_drag = w.current != [0.0; 3]
                            && (w.drag_areas != [0.0; 3]
                                || w.rods.iter().any(|r| {
                                    r.drag_coefficient != 0.0 || r.end_drag_coefficient != 0.0
                                }));
                        // A body-fixed external force (B43) acts at rest.
                        current_drag || w.external.body_force != [0.0; 3]
                    })
                    .cloned(),
                rods_water: body.water.as_ref().filter(|w| !w.rods.is_empty()).cloned(),
                pin: body.pin.map(|pin| {
                    let hold = match system.joint_point(b) {
                        Some(p) => PinHold::Point(p),
                        // A host's motion holds it where it is at t = 0.
                        None => PinHold::Fixed(system.points()[pin.point].state_at(0.0).0),
                    };
                    (crate::vec3::sub(pin.local, c), hold)
                }),
                float_hold: crate::system::body_holds::float_hold(system, b),
                rest_hold: crate::system::body_holds::rest_hold(system, b),
                moment: body.moment,
                own_stiffness: own_stiffness(body, net),
                // A connector's spin is held by its own row (§15.20).
                spin_hold: crate::system::body_holds::spin_axis(
                    body,
                    &crate::system::body_holds::points_local(system, b),
                )
                .filter(|_| !body.connector)
                .map(|a| {
                    let weight = crate::vec3::norm(net).max(f64::MIN_POSITIVE);
                    (a, weight * length)
                }),
                yaw_hold: crate::system::body_holds::yaw_hold(system, b)
                    .filter(|_| !body.connector)
                    .map(|a| {
                        let weight = crate::vec3::norm(net).max(f64::MIN_POSITIVE);
                        (a, weight * length)
                    }),
            }
        })
        .collect()
}
