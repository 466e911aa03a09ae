//! MoorDyn's order of the places a host that sets the waves is asked at
//! (`WaveKin 1`; docs/method.md §12.1, (W2h)), for the system a scenario
//! builds ([`stancf::system::HostOrder`]): its rods in the order given
//! (a deck's RODS), each where the system holds it (in its body's water,
//! fixed, on a fixed body where it is, or a point for a rod of zero
//! length); its points but those it
//! adds at rods' ends or for a rod of zero length; its bodies but the
//! rods' own bodies and the connectors of rods of zero length.

use super::rod_parts::RodHolder;
use super::system_parts::SystemScenario;
use stancf::system::{HostOrder, HostRod};

/// The host's order of `sc`'s system (module doc).
pub(super) fn host_order(sc: &SystemScenario) -> HostOrder {
    let mut in_body = vec![0usize; sc.bodies.len()];
    let rods = sc
        .rods
        .iter()
        .map(|r| match (r.holder, &r.rod) {
            (RodHolder::Fixed, rod) => HostRod::Fixed {
                ends: r.ends,
                segments: rod.as_ref().map_or(0, |rod| rod.segments),
            },
            (RodHolder::Point { point, .. }, _) => HostRod::AtPoint(point),
            // A rod of zero length on a body: MoorDyn's one node, at the
            // point there, or on the body where it is if no line makes
            // one (where it is, on a fixed body).
            (_, None) => match (r.points[0].or(r.points[1]), r.body()) {
                (Some(p), _) => HostRod::AtPoint(p),
                (None, Some(body)) if sc.bodies[body].kind != super::BodyType::Fixed => {
                    HostRod::OnBody {
                        body,
                        local: r.local[0],
                    }
                }
                (None, _) => HostRod::Fixed {
                    ends: r.ends,
                    segments: 0,
                },
            },
            // On a fixed body (which has no water of its own): where it is.
            (RodHolder::Body { body }, Some(rod))
                if sc.bodies[body].kind == super::BodyType::Fixed =>
            {
                HostRod::Fixed {
                    ends: r.ends,
                    segments: rod.segments,
                }
            }
            (_, Some(_)) => {
                let body = r.body().expect("a rod on a body or its own body");
                // The body's water holds its rods as rods_of_body lists
                // them: those with a length, in the scenario's order.
                let k = in_body[body];
                in_body[body] += 1;
                HostRod::InBody { body, rod: k }
            }
        })
        .collect();
    let rod_points: Vec<usize> = sc
        .rods
        .iter()
        .flat_map(|r| r.points.iter().flatten().copied())
        .collect();
    // Neither the points at rods' ends nor those a CoupledPinned body's
    // pin makes for its host are MoorDyn's.
    let pins: Vec<usize> = sc.bodies.iter().filter_map(|b| b.host_pin).collect();
    let points = (0..sc.points.len())
        .filter(|p| !rod_points.contains(p) && !pins.contains(p))
        .collect();
    let rod_bodies: Vec<usize> = sc.rods.iter().filter_map(|r| r.own_body()).collect();
    let bodies = (0..sc.bodies.len())
        .filter(|b| !rod_bodies.contains(b) && sc.bodies[*b].connector_axis.is_none())
        .collect();
    HostOrder {
        rods,
        points,
        bodies,
    }
}
