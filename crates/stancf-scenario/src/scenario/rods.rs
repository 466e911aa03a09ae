//! Rods of a system (docs/interface.md, "Rods"; docs/method.md §15.10):
//! a deck's ROD TYPES and RODS, or `[[rod_types]]` and `[[rods]]`
//! (`rod_toml.rs`). A rod is a rigid cylinder held four ways:
//!
//! - free: a body of its own (six degrees of freedom), its reference
//!   point at end A, its axes the global ones at t = 0, its mass and
//!   water the rod's ([`stancf::system::Body::rod`]);
//! - pinned (`Pinned`, `Body<n>Pinned` on a fixed body n): a free rod's
//!   body whose end A is held at a fixed point there (the body's
//!   [`stancf::system::Pin`], docs/method.md §15.12), turning freely
//!   about it; a line at end A ends at that fixed point;
//! - on a body: fixed in it, its mass and water joining the body's;
//! - fixed: held where it is, its ends fixed points.
//!
//! A deck's free rod of zero length (`NumSegs` = 0, MoorDyn's 3-DOF
//! point carrying only its lines, docs/moordyn-bodies-rods.md §1.3) is a
//! free point of no mass, volume or drag.
//!
//! Lines attach at a rod's end through a point there: a point on the
//! rod's body at the end's body coordinates, or a fixed point for a
//! fixed rod (a deck's line ends at `R<n>A`, `R<n>B` get such a point,
//! numbered after the deck's points; a TOML scenario writes them as
//! `[[points]]` of type "rod"). Points are pinned: MoorDyn clamps a
//! line's end to the rod's axis, which for a line without bending
//! stiffness is the same. A deck's line with bending stiffness at a
//! fixed rod's end is clamped along the rod's axis (its cantilever); at
//! the end of a rod that moves it is refused.

use super::bodies::{BodyType, SystemBody};
use super::rod_parts::{free_rod_body, next_body_id, rod_of, RodHolder, RodTypeValues, SystemRod};
use super::system_parts::{PointType, SystemPoint, SystemScenario};
use super::ScenarioError;
use crate::moordyn::{Deck, DeckRod, LineAttachment, RodAttachment, RodEnd};
use stancf::body::Rod;
use stancf::vec3::{norm, sub};

/// The kind of the point at end `k` (0 for A, 1 for B) of `rod` (its
/// holder and ends placed): on the rod's body at the end's body
/// coordinates, a fixed point at a fixed rod's end or a pinned rod's end
/// A (its pin), the rod's free point for one of zero length.
pub(super) fn end_kind(rod: &SystemRod, k: usize) -> PointType {
    let local = rod.local[k];
    match rod.holder {
        RodHolder::Fixed => PointType::Fixed,
        RodHolder::Pinned {
            host: Some((body, local)),
            ..
        } if k == 0 => PointType::Body { body, local },
        RodHolder::Pinned { coupled: true, .. } if k == 0 => PointType::Coupled,
        RodHolder::Pinned { .. } if k == 0 => PointType::Fixed,
        RodHolder::Point {
            connector: Some(body),
            ..
        } => PointType::Body {
            body,
            local: [0.0; 3],
        },
        RodHolder::Point { .. } => PointType::Free,
        RodHolder::Free { body }
        | RodHolder::Pinned { body, .. }
        | RodHolder::Body { body }
        | RodHolder::Coupled { body } => PointType::Body { body, local },
    }
}

/// The point at end `k` of `rod` ([`end_kind`]), where the rod's ends
/// put it at t = 0; `id` its id.
pub(super) fn end_point(rod: &SystemRod, k: usize, id: i64) -> SystemPoint {
    SystemPoint::made(id, end_kind(rod, k), rod.ends[k])
}

/// The deck's rods and the points their line ends need: the bodies of
/// free rods pushed onto `bodies` (ids after the deck's), the points
/// onto `points` (which holds the deck's, ids 1 to n: ids n + 1...), and the point (index) at each
/// line's ends. Refused naming the deck's line: a rod of a length
/// MoorDyn gives none with segments (or none with length), a line with
/// bending stiffness at a rod end, a zero-length free rod no line is
/// attached to.
pub(super) fn deck_rods(
    deck: &Deck,
    file: &str,
    bodies: &mut Vec<SystemBody>,
    points: &mut Vec<SystemPoint>,
) -> Result<(Vec<SystemRod>, Vec<DeckLineEnds>), ScenarioError> {
    let at = |line: usize, msg: String| ScenarioError(format!("{file}: line {line}: {msg}"));
    let mut rods = Vec::with_capacity(deck.rods.len());
    for r in &deck.rods {
        let rod = deck_rod(deck, r, bodies, points).map_err(|m| at(r.line, m))?;
        rods.push(rod);
    }
    let mut ends = Vec::with_capacity(deck.lines.len());
    let mut pending = Vec::new();
    for l in &deck.lines {
        let mut pair = [0; 2];
        let mut clamps = [None; 2];
        for (k, a) in [l.end_a, l.end_b].into_iter().enumerate() {
            pair[k] = match a {
                LineAttachment::Point(p) => p - 1,
                LineAttachment::Rod(n, end) => {
                    let ei = deck.line_type_of(l).ei;
                    if let (
                        true,
                        RodHolder::Point {
                            connector: Some(_), ..
                        },
                    ) = (ei > 0.0, rods[n - 1].holder)
                    {
                        // Clamped along the connector's axis, once all
                        // the lines' ends are known.
                        pending.push((ends.len(), k, n - 1, end));
                    } else if ei > 0.0 {
                        // MoorDyn's cantilever: the line leaves the rod
                        // along its axis (§1.5 of the note), a clamp that
                        // turns with the rod (docs/method.md §15.19).
                        let axis = clamp_axis(&rods[n - 1], bodies).map_err(|why| {
                            at(
                                l.line,
                                format!(
                                    "{} of line {} is end {} of rod {n}, and its line type has \
                                     bending stiffness EI = {} N m^2, so MoorDyn clamps it to \
                                     the rod's axis: {why}",
                                    ["AttachA", "AttachB"][k],
                                    l.id,
                                    end.letter(),
                                    ei
                                ),
                            )
                        })?;
                        clamps[k] = Some(axis);
                    }
                    rod_end_point(&mut rods[n - 1], end, points)
                }
            };
        }
        ends.push(DeckLineEnds {
            points: pair,
            clamps,
        });
    }
    connector_axes(deck, &rods, &pending, bodies, points, &mut ends);
    for (r, rod) in deck.rods.iter().zip(&rods) {
        let attached = deck.lines.iter().any(|l| {
            [l.end_a, l.end_b]
                .iter()
                .any(|a| matches!(a, LineAttachment::Rod(n, _) if *n == r.id))
        });
        if matches!(rod.holder, RodHolder::Point { .. }) && !attached {
            return Err(at(
                r.line,
                format!(
                    "rod {} is free with NumSegs 0, a point of no mass that carries only the \
                     lines attached to it, and no line is attached to it (R{}A, R{}B)",
                    r.id, r.id, r.id
                ),
            ));
        }
    }
    Ok((rods, ends))
}

/// The axes of the connectors (zero-length free rods with lines of
/// bending stiffness, docs/method.md §15.20) and the clamps of those
/// lines along them. `pending` holds (line, line end, rod, rod end) of
/// each such line end. MoorDyn turns a zero-length rod to balance its
/// lines' bending moments: its axis q is the unit vector of the sum of
/// the lines' end tangents weighted by EI over their length, each taken
/// in the rod's sense (a line arriving at end A or leaving end B runs
/// along q, one leaving end A or arriving at end B against it). Here the
/// lines start straight between their end points, and that sum is the
/// connector's axis at t = 0 (its first pose; the static solve turns
/// it).
fn connector_axes(
    deck: &Deck,
    rods: &[SystemRod],
    pending: &[(usize, usize, usize, RodEnd)],
    bodies: &mut [SystemBody],
    points: &[SystemPoint],
    ends: &mut [DeckLineEnds],
) {
    let mut sums = vec![[0.0; 3]; bodies.len()];
    for &(li, k, rod, end) in pending {
        let RodHolder::Point {
            point,
            connector: Some(b),
        } = rods[rod].holder
        else {
            continue;
        };
        let (joint, far) = (
            points[point].position,
            points[ends[li].points[1 - k]].position,
        );
        let chord = if k == 0 {
            sub(far, joint)
        } else {
            sub(joint, far)
        };
        let along = (k == 1) == (end == RodEnd::A);
        let l = &deck.lines[li];
        let weight = deck.line_type_of(l).ei / l.unstretched_length;
        let w = if along { weight } else { -weight } / norm(chord).max(f64::MIN_POSITIVE);
        sums[b] = stancf::vec3::add(sums[b], chord.map(|c| w * c));
    }
    for (b, sum) in sums.iter().enumerate() {
        if bodies[b].connector_axis.is_some() && norm(*sum) > 0.0 {
            let axis = sum.map(|c| c / norm(*sum));
            bodies[b].connector_axis = Some(axis);
            // Its frame's angles, as check and the results show them.
            let frame = stancf::system::Body::connector(bodies[b].position, axis).rotation;
            bodies[b].angles = stancf::body::pose::moordyn_angles(&frame);
        }
    }
    for &(li, k, rod, _) in pending {
        if let RodHolder::Point {
            connector: Some(b), ..
        } = rods[rod].holder
        {
            ends[li].clamps[k] = bodies[b].connector_axis;
        }
    }
}

/// A deck line's end points (indices) and the directions its ends are
/// clamped in (a line with bending stiffness at a fixed rod's end).
pub(super) struct DeckLineEnds {
    pub points: [usize; 2],
    pub clamps: [Option<[f64; 3]>; 2],
}

impl DeckLineEnds {
    /// Whether an end is clamped (only multipliers hold it, docs/method.md
    /// §6.10).
    pub fn clamped(&self) -> bool {
        self.clamps.iter().any(Option::is_some)
    }
}

/// The axis (global, at t = 0) of a rod with a length, where a line with
/// bending stiffness is clamped; why not for any other: a rod of zero
/// length (MoorDyn turns it to balance its lines' bending moments, a
/// joint that keeps their slopes, not built yet) or a rod the host turns
/// (a coupled rod, a rod fixed in a coupled body: a clamp on the host's
/// rotation is not built yet).
fn clamp_axis(rod: &SystemRod, bodies: &[SystemBody]) -> Result<[f64; 3], String> {
    if rod.rod.is_none() {
        return Err(
            "a line with bending stiffness at a rod of zero length (MoorDyn turns the \
                    rod to balance the bending moments of its lines, a joint that keeps their \
                    slopes) is not built yet"
                .into(),
        );
    }
    let turned_by_host = match rod.holder {
        RodHolder::Coupled { .. } => true,
        RodHolder::Body { body } => bodies[body].kind == BodyType::Coupled,
        _ => false,
    };
    if turned_by_host {
        return Err(
            "a clamp that turns with a rod the host moves (a coupled rod, or a rod \
                    fixed in a coupled body) is not built yet (at a fixed or free rod it is \
                    built)"
                .into(),
        );
    }
    let axis = sub(rod.ends[1], rod.ends[0]);
    Ok(axis.map(|c| c / norm(axis)))
}

/// One RODS row as a rod (a free rod's body or a zero-length rod's point
/// pushed); the message of its refusal.
fn deck_rod(
    deck: &Deck,
    r: &DeckRod,
    bodies: &mut Vec<SystemBody>,
    points: &mut Vec<SystemPoint>,
) -> Result<SystemRod, String> {
    let t = RodTypeValues::of_deck(deck.rod_type_of(r));
    let zero = r.segments == 0;
    let (holder, rod, ends) = match r.attachment {
        RodAttachment::Fixed => (RodHolder::Fixed, [r.end_a, r.end_b], [r.end_a, r.end_b]),
        RodAttachment::Free if zero => {
            // With a line of bending stiffness, a connector (its axis set
            // once the lines are, [`connector_axes`]).
            let bent = deck.lines.iter().any(|l| {
                [l.end_a, l.end_b]
                    .iter()
                    .any(|a| matches!(a, LineAttachment::Rod(n, _) if *n == r.id))
                    && deck.line_type_of(l).ei > 0.0
            });
            let connector = bent.then(|| {
                bodies.push(SystemBody {
                    connector_axis: Some([0.0, 0.0, 1.0]),
                    ..free_rod_body(next_body_id(bodies), r.end_a)
                });
                bodies.len() - 1
            });
            let holder = RodHolder::Point {
                point: points.len(),
                connector,
            };
            (holder, [r.end_a; 2], [r.end_a; 2])
        }
        RodAttachment::Free => {
            let body = bodies.len();
            bodies.push(free_rod_body(next_body_id(bodies), r.end_a));
            let local = [[0.0; 3], sub(r.end_b, r.end_a)];
            (RodHolder::Free { body }, local, [r.end_a, r.end_b])
        }
        RodAttachment::Coupled => {
            let body = bodies.len();
            bodies.push(SystemBody {
                kind: BodyType::Coupled,
                ..free_rod_body(next_body_id(bodies), r.end_a)
            });
            let local = [[0.0; 3], sub(r.end_b, r.end_a)];
            (RodHolder::Coupled { body }, local, [r.end_a, r.end_b])
        }
        RodAttachment::Body(n) => {
            let b = &bodies[n - 1];
            let ends = [b.point(r.end_a), b.point(r.end_b)];
            (RodHolder::Body { body: n - 1 }, [r.end_a, r.end_b], ends)
        }
        RodAttachment::Pinned | RodAttachment::BodyPinned(_) | RodAttachment::CoupledPinned => {
            let (ends, host) = pinned_ends(r, bodies)?;
            let body = bodies.len();
            bodies.push(free_rod_body(next_body_id(bodies), ends[0]));
            let local = [[0.0; 3], sub(ends[1], ends[0])];
            let coupled = r.attachment == RodAttachment::CoupledPinned;
            (
                RodHolder::Pinned {
                    body,
                    host,
                    coupled,
                },
                local,
                ends,
            )
        }
    };
    let built = (!zero).then(|| rod_of(&t, rod[0], rod[1], r.segments));
    if let Some(built) = &built {
        built
            .validate(&format!("rod {}", r.id))
            .map_err(|e| format!("{}: {}", e.key, e.message))?;
    } else if r.attachment != RodAttachment::Free && r.end_a != r.end_b {
        // A fixed or body rod of zero length is where its end A is; its
        // end B would be ignored.
        return Err(format!(
            "rod {} has NumSegs 0 (a rod of zero length) but its ends differ: give it \
             segments, or end B = end A",
            r.id
        ));
    }
    let mut out = SystemRod {
        id: r.id as i64,
        holder,
        type_name: deck.rod_type_of(r).name.clone(),
        type_index: r.type_index,
        rod: built,
        ends,
        local: rod,
        points: [None; 2],
    };
    match holder {
        RodHolder::Point { .. } => {
            let id = points.len() as i64 + 1;
            points.push(end_point(&out, 0, id));
            out.points = [Some(points.len() - 1); 2];
        }
        // The pin's fixed point, whether or not a line attaches there.
        RodHolder::Pinned { .. } => {
            rod_end_point(&mut out, RodEnd::A, points);
        }
        _ => {}
    }
    Ok(out)
}

/// A pinned rod's global ends and its joint's host ([`pinned_ends`]).
type PinnedEnds = ([[f64; 3]; 2], Option<(usize, [f64; 3])>);

/// The global ends of a pinned rod: as written for `Pinned`, where its
/// body's pose puts them for `Body<n>Pinned`; and for a free body n, the
/// joint's host (or for a coupled body n, the host whose motion moves the
/// pin): body n (its index) at end A's coordinates in it. Refused: a rod
/// of zero length (nothing to turn).
fn pinned_ends(r: &DeckRod, bodies: &[SystemBody]) -> Result<PinnedEnds, String> {
    if r.segments == 0 {
        return Err(format!(
            "rod {} is pinned with NumSegs 0, a rod of zero length, which has nothing to turn \
             about its pin: give it segments, or make it Fixed",
            r.id
        ));
    }
    match r.attachment {
        RodAttachment::BodyPinned(n) => {
            let b = &bodies[n - 1];
            // On a free body a joint (§15.14); on a coupled body a pin on
            // its host's motion (§15.17), at a point of the body.
            let host = match b.kind {
                BodyType::Fixed => None,
                BodyType::Free | BodyType::Coupled => Some((n - 1, r.end_a)),
            };
            Ok(([b.point(r.end_a), b.point(r.end_b)], host))
        }
        _ => Ok(([r.end_a, r.end_b], None)),
    }
}

/// The point (index) at end `end` of `rod`, pushed onto `points` (after
/// the deck's, its id one more than their count) the first time an end
/// asks for it.
fn rod_end_point(rod: &mut SystemRod, end: RodEnd, points: &mut Vec<SystemPoint>) -> usize {
    let k = match end {
        RodEnd::A => 0,
        RodEnd::B => 1,
    };
    if let Some(p) = rod.points[k] {
        return p;
    }
    let id = points.len() as i64 + 1;
    points.push(end_point(rod, k, id));
    rod.points[k] = Some(points.len() - 1);
    points.len() - 1
}

/// Notes for the deck's rods that ask MoorDyn for a file of their own
/// (RodOutputs with one of `pvUDctsd`), which stancf does not write.
pub(super) fn rod_file_notes(deck: &Deck) -> Vec<String> {
    deck.rods
        .iter()
        .filter(|r| r.wants_rod_file())
        .map(|r| {
            let unwritten: String = r.outputs.chars().filter(|c| !"pv".contains(*c)).collect();
            format!(
                "line {}: rod {}'s RodOutputs \"{}\": its file of MoorDyn's holds the node \
                 positions and velocities (p, v) it asks for{}",
                r.line,
                r.id,
                crate::echo::clip(&r.outputs, 40),
                if unwritten.is_empty() {
                    String::new()
                } else {
                    format!(
                        "; \"{}\" (forces, water, seabed) not computed for a rod, no columns",
                        crate::echo::clip(&unwritten, 40)
                    )
                }
            )
        })
        .collect()
}

/// The rods of body `b` as the library takes them (body axes from its
/// reference point).
pub(super) fn rods_of_body(sc: &SystemScenario, b: usize) -> Vec<Rod> {
    sc.rods
        .iter()
        .filter(|r| r.body() == Some(b))
        .filter_map(|r| r.rod.clone())
        .collect()
}

/// The pin of body `b` if it is a pinned rod: its end A (the body's
/// reference point) held at the fixed point there.
pub(super) fn pin_of_body(sc: &SystemScenario, b: usize) -> Option<stancf::system::Pin> {
    sc.rods
        .iter()
        .find(|r| r.own_body() == Some(b))
        .and_then(SystemRod::pin_point)
        .map(|point| stancf::system::Pin {
            local: [0.0; 3],
            point,
        })
}

/// The host of body `b` if it is a rod pinned to a free body (a joint):
/// the host's index and the pin's place in its axes.
pub(super) fn joint_host(sc: &SystemScenario, b: usize) -> Option<(usize, [f64; 3])> {
    sc.rods.iter().find_map(|r| match r.holder {
        RodHolder::Pinned { body, host, .. } if body == b => host,
        _ => None,
    })
}

/// A core error about a free rod's body (`bodies[i]...`) or a rod of a
/// body (`bodies[i].rods[j]...`) named by the rod (`rods[k]`, or its
/// deck line); any other error as it is.
pub(super) fn rod_error(sc: &SystemScenario, e: stancf::ModelError) -> stancf::ModelError {
    let Some(rest) = e.key.strip_prefix("bodies[") else {
        return e;
    };
    let Some((b, rest)) = rest.split_once(']') else {
        return e;
    };
    let Ok(b) = b.parse::<usize>() else { return e };
    let on_body = |r: &&SystemRod| r.body() == Some(b) && r.rod.is_some();
    let found = match rest.strip_prefix(".rods[").and_then(|r| r.split_once(']')) {
        Some((j, tail)) => j
            .parse::<usize>()
            .ok()
            .and_then(|j| sc.rods.iter().filter(on_body).nth(j))
            .map(|r| (r, tail)),
        None => sc
            .rods
            .iter()
            .find(|r| r.own_body() == Some(b))
            .map(|r| (r, rest)),
    };
    let Some((rod, tail)) = found else { return e };
    let k = sc
        .rods
        .iter()
        .position(|r| std::ptr::eq(r, rod))
        .unwrap_or(0);
    stancf::ModelError {
        key: format!("{}{tail}", sc.names.rod_place(k)),
        message: e.message,
    }
}
