//! The `OUTPUTS` section: channel names as `MoorDyn2.cpp` reads them
//! (`ReadInFile`, the `OUTPUT` section, with `str::decomposeString`),
//! case-insensitive.

use super::layout::Section;
use super::{DeckBody, DeckError, DeckLine, DeckPoint, DeckRod, Output};

/// A component of a vector, in the global frame.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Axis {
    X,
    Y,
    Z,
}

/// An end of a line.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum LineEnd {
    /// End A, node 0 (`AttachA`).
    A,
    /// End B, node `NumSegs` (`AttachB`).
    B,
}

/// What MoorDyn outputs at a line node (`Line::GetLineOutput`).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum LineQuantity {
    /// `PX` `PY` `PZ` (m).
    Position(Axis),
    /// `VX` `VY` `VZ` (m/s).
    Velocity(Axis),
    /// `FX` `FY` `FZ`: net force on the node (N).
    Force(Axis),
    /// `T` or `TEN` (N): at an end node the magnitude of the net force on
    /// it, at an inner node the mean tension of its two segments.
    Tension,
}

/// What MoorDyn outputs at a point (`Point::GetPointOutput`).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum PointQuantity {
    /// `PX` `PY` `PZ` (m).
    Position(Axis),
    /// `VX` `VY` `VZ` (m/s).
    Velocity(Axis),
    /// `AX` `AY` `AZ` (m/s²).
    Acceleration(Axis),
    /// `FX` `FY` `FZ`: net force on the point (N).
    Force(Axis),
    /// `T` or `TEN`: magnitude of the net force (N).
    Tension,
}

/// What MoorDyn outputs of a body (`Body::GetBodyOutput`): of its
/// reference point and its rotation, about the reference point, global.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum BodyQuantity {
    /// `PX` `PY` `PZ` (m): the reference point.
    Position(Axis),
    /// `RX` `RY` `RZ` (deg): roll, pitch and yaw, MoorDyn's angles.
    Rotation(Axis),
    /// `VX` `VY` `VZ` (m/s): the reference point's velocity.
    Velocity(Axis),
    /// `RVX` `RVY` `RVZ` (deg/s): the angular velocity, global.
    AngularVelocity(Axis),
    /// `AX` `AY` `AZ` (m/s^2).
    Acceleration(Axis),
    /// `RAX` `RAY` `RAZ` (deg/s^2).
    AngularAcceleration(Axis),
    /// `FX` `FY` `FZ` (N): the net force on the body.
    Force(Axis),
    /// `MX` `MY` `MZ` (N m): the net moment about the reference point.
    Moment(Axis),
    /// `T` or `TEN` (N): the magnitude of the net force.
    Tension,
}

/// What MoorDyn outputs of a rod as a whole (`Rod::GetRodOutput`, its
/// channels without a node): of its end A (its reference point) and its
/// axis, global. MoorDyn has no rotation about a rod's axis: no `RZ`,
/// `RVZ` or `RAZ`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum RodQuantity {
    /// `PX` `PY` `PZ` (m): end A.
    Position(Axis),
    /// `RX` `RY` (deg): MoorDyn's "roll" -phi sin(beta) and "pitch"
    /// phi cos(beta) of the axis (phi its angle from the vertical, beta
    /// its heading); only `X` and `Y`.
    Rotation(Axis),
    /// `VX` `VY` `VZ` (m/s): end A's velocity.
    Velocity(Axis),
    /// `RVX` `RVY` (deg/s): the angular velocity, global; only `X`, `Y`.
    AngularVelocity(Axis),
    /// `AX` `AY` `AZ` (m/s^2).
    Acceleration(Axis),
    /// `RAX` `RAY` (deg/s^2).
    AngularAcceleration(Axis),
    /// `FX` `FY` `FZ` (N): the net force on the rod.
    Force(Axis),
    /// `MX` `MY` `MZ` (N m): the net moment about end A.
    Moment(Axis),
    /// `TA`/`TENA`, `TB`/`TENB` (N): the magnitude of the net force of
    /// the lines attached at that end.
    EndTension(LineEnd),
    /// `SUB`: the fraction of the rod under the water surface.
    Submerged,
    /// `N<k>P<x>`, `NAP<x>`, `NBP<x>` (m): node k of the rod's NumSegs
    /// segments, at A + (k / N) (B - A) on the rigid rod.
    NodePosition(usize, Axis),
    /// `N<k>V<x>` (m/s): its velocity, v_A + w x (x_k - x_A).
    NodeVelocity(usize, Axis),
    /// Any other node quantity (its tension, forces, acceleration): not
    /// computed, its column left empty.
    NodeOther(usize),
}

/// An output channel.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Channel {
    /// `FairTen<n>`: tension at end B (the fairlead, node `NumSegs`) of
    /// line n; the same as `L<n>NB T`.
    FairleadTension { line: usize },
    /// `AnchTen<n>`: tension at end A (the anchor, node 0) of line n.
    AnchorTension { line: usize },
    /// `L<n>N<k><q>` or `Line<n>N<k><q>`; `NA` is node 0 and `NB` node
    /// `NumSegs`; without a node, node 0 (MoorDyn's reference point of a
    /// line is end A).
    LineNode {
        line: usize,
        node: usize,
        quantity: LineQuantity,
    },
    /// `L<n>TA`/`L<n>TenA` and `L<n>TB`/`L<n>TenB`: the magnitude of the
    /// net force on an end node of line n (N).
    LineEndTension { line: usize, end: LineEnd },
    /// `P<n><q>`, `Point<n><q>` or the older `Con<n><q>`.
    Point {
        point: usize,
        quantity: PointQuantity,
    },
    /// `B<n><q>` or `Body<n><q>`.
    Body { body: usize, quantity: BodyQuantity },
    /// `R<n><q>` or `Rod<n><q>`: the rod as a whole, or one of its nodes
    /// (`R<n>N<k><q>`, `NA`, `NB`).
    Rod { rod: usize, quantity: RodQuantity },
    /// A name MoorDyn does not know as a channel (an object letter or a
    /// quantity it has not): MoorDyn warns and skips it, stancf notes it
    /// and leaves its column empty ([`super::Output::unrecognized`] says
    /// why).
    Unrecognized,
}

/// Why a name is not a channel of the deck.
enum NotAChannel {
    /// It names a line, point, body, rod or node the deck does not
    /// define: MoorDyn refuses the deck.
    Missing(String),
    /// MoorDyn does not know it: it warns and skips it.
    Unknown(String),
    /// It is not a word of letters and digits: it could not head a column
    /// of channels.csv.
    Malformed(String),
}

impl From<String> for NotAChannel {
    fn from(m: String) -> Self {
        NotAChannel::Unknown(m)
    }
}

impl From<&str> for NotAChannel {
    fn from(m: &str) -> Self {
        NotAChannel::Unknown(m.to_string())
    }
}

/// A channel name before the lines and points are known.
pub(crate) struct RawOutput<'a> {
    line: usize,
    name: &'a str,
}

/// The channel names: every word of every row, up to a row starting with
/// `END` (MoorDyn-F stops there; MoorDyn-C skips the word with a
/// warning); nothing may follow `END` in the section.
pub(crate) fn words<'a>(s: &Section<'a>) -> Result<Vec<RawOutput<'a>>, DeckError> {
    let mut out = Vec::new();
    let mut end: Option<usize> = None;
    for row in &s.rows {
        if let Some(at) = end {
            return Err(DeckError::at(
                row.line,
                format!("\"{}\" follows END (line {at}) in OUTPUTS", row.words[0]),
            ));
        }
        for (i, w) in row.words.iter().enumerate() {
            if w.eq_ignore_ascii_case("END") {
                if i > 0 || row.words.len() > 1 {
                    return Err(DeckError::at(
                        row.line,
                        "END must stand alone on its line in OUTPUTS",
                    ));
                }
                end = Some(row.line);
            } else {
                out.push(RawOutput {
                    line: row.line,
                    name: w,
                });
            }
        }
    }
    Ok(out)
}

/// The channels, checked against the deck's lines, points, bodies and
/// rods.
pub(crate) fn resolve(
    raw: Vec<RawOutput>,
    lines: &[DeckLine],
    points: &[DeckPoint],
    (bodies, rods): (&[DeckBody], &[DeckRod]),
) -> Result<Vec<Output>, DeckError> {
    let counts = Counts {
        bodies: bodies.len(),
        rods,
    };
    raw.into_iter()
        .map(|r| {
            let (channel, unrecognized) = match channel(r.name, lines, points, counts) {
                Ok(c) => (c, None),
                Err(NotAChannel::Unknown(why)) => (Channel::Unrecognized, Some(why)),
                Err(NotAChannel::Missing(why) | NotAChannel::Malformed(why)) => {
                    return Err(DeckError::at(
                        r.line,
                        format!("output channel \"{}\": {why}", r.name),
                    ))
                }
            };
            Ok(Output {
                line: r.line,
                name: r.name.to_string(),
                channel,
                unrecognized,
            })
        })
        .collect()
}

/// A name cut into its leading letters, the digits after them and the
/// rest (`FairTen12` → `FAIRTEN`, `12`, ``).
fn head(upper: &str) -> (&str, &str, &str) {
    let a = upper
        .find(|c: char| !c.is_ascii_alphabetic())
        .unwrap_or(upper.len());
    let b = upper[a..]
        .find(|c: char| !c.is_ascii_digit())
        .map_or(upper.len(), |i| a + i);
    (&upper[..a], &upper[a..b], &upper[b..])
}

/// How many bodies and rods the deck defines.
#[derive(Clone, Copy)]
struct Counts<'a> {
    bodies: usize,
    rods: &'a [DeckRod],
}

fn channel(
    name: &str,
    lines: &[DeckLine],
    points: &[DeckPoint],
    Counts { bodies, rods }: Counts,
) -> Result<Channel, NotAChannel> {
    if !name.chars().all(|c| c.is_ascii_alphanumeric()) {
        return Err(NotAChannel::Malformed(
            "a channel name is made of letters and digits".into(),
        ));
    }
    let upper = name.to_ascii_uppercase();
    let (kind, id, rest) = head(&upper);
    let known =
        "known: FairTen<n>, AnchTen<n>, L<n>N<k><q> (Line...), P<n><q> (Point..., Con...), \
                 B<n><q> (Body...), R<n><q> (Rod...)";
    if id.is_empty() {
        return Err(format!("no object number; {known}").into());
    }
    let id: usize = id
        .parse()
        .map_err(|_| NotAChannel::Missing("the object number is too large".into()))?;
    match kind {
        "FAIRTEN" | "ANCHTEN" => {
            if !rest.is_empty() {
                return Err(format!("unexpected \"{rest}\" after the line number").into());
            }
            line_of(id, lines)?;
            Ok(if kind == "FAIRTEN" {
                Channel::FairleadTension { line: id }
            } else {
                Channel::AnchorTension { line: id }
            })
        }
        "L" | "LINE" => line_channel(id, rest, line_of(id, lines)?),
        "P" | "POINT" | "CON" => {
            if id == 0 || id > points.len() {
                return Err(NotAChannel::Missing(format!(
                    "there is no point {id} ({} points)",
                    points.len()
                )));
            }
            let quantity = point_quantity(rest)?;
            Ok(Channel::Point {
                point: id,
                quantity,
            })
        }
        "R" | "ROD" => {
            if id == 0 || id > rods.len() {
                return Err(NotAChannel::Missing(format!(
                    "there is no rod {id} ({} rods)",
                    rods.len()
                )));
            }
            Ok(Channel::Rod {
                rod: id,
                quantity: rod_quantity(rest, rods[id - 1].segments)?,
            })
        }
        "B" | "BODY" => {
            if id == 0 || id > bodies {
                return Err(NotAChannel::Missing(format!(
                    "there is no body {id} ({bodies} bodies)"
                )));
            }
            Ok(Channel::Body {
                body: id,
                quantity: body_quantity(rest)?,
            })
        }
        _ => Err(format!("unknown channel; {known}").into()),
    }
}

fn line_of(id: usize, lines: &[DeckLine]) -> Result<&DeckLine, NotAChannel> {
    id.checked_sub(1).and_then(|i| lines.get(i)).ok_or_else(|| {
        NotAChannel::Missing(format!("there is no line {id} ({} lines)", lines.len()))
    })
}

/// The part after `L<n>`: `N<k><q>`, `NA<q>`, `NB<q>`, `<q>`, `TA`, `TB`.
fn line_channel(id: usize, rest: &str, line: &DeckLine) -> Result<Channel, NotAChannel> {
    if let Some(end) = end_tension(rest) {
        return Ok(Channel::LineEndTension { line: id, end });
    }
    let (node, q) = if let Some(after) = rest.strip_prefix('N') {
        let digits = after
            .find(|c: char| !c.is_ascii_digit())
            .unwrap_or(after.len());
        if digits > 0 {
            let k: usize = after[..digits]
                .parse()
                .map_err(|_| NotAChannel::Missing("node number too large".into()))?;
            (k, &after[digits..])
        } else if let Some(q) = after.strip_prefix('A') {
            (0, q)
        } else if let Some(q) = after.strip_prefix('B') {
            (line.segments, q)
        } else {
            return Err("after N comes a node number, A or B".into());
        }
    } else {
        (0, rest)
    };
    if node > line.segments {
        return Err(NotAChannel::Missing(format!(
            "line {id} has nodes 0 to {} ({} segments)",
            line.segments, line.segments
        )));
    }
    if end_tension(q).is_some() {
        return Err("TA and TB (end tensions) take no node".into());
    }
    let quantity = match quantity(q)? {
        Q::P(a) => LineQuantity::Position(a),
        Q::V(a) => LineQuantity::Velocity(a),
        Q::F(a) => LineQuantity::Force(a),
        Q::T => LineQuantity::Tension,
        Q::A(_) | Q::Other => {
            return Err(format!(
                "MoorDyn outputs no \"{q}\" at line nodes (only PX PY PZ VX VY VZ FX FY FZ T)"
            )
            .into())
        }
    };
    Ok(Channel::LineNode {
        line: id,
        node,
        quantity,
    })
}

fn end_tension(q: &str) -> Option<LineEnd> {
    match q {
        "TA" | "TENA" => Some(LineEnd::A),
        "TB" | "TENB" => Some(LineEnd::B),
        _ => None,
    }
}

fn point_quantity(q: &str) -> Result<PointQuantity, String> {
    Ok(match quantity(q)? {
        Q::P(a) => PointQuantity::Position(a),
        Q::V(a) => PointQuantity::Velocity(a),
        Q::A(a) => PointQuantity::Acceleration(a),
        Q::F(a) => PointQuantity::Force(a),
        Q::T => PointQuantity::Tension,
        Q::Other => {
            return Err(format!(
                "MoorDyn outputs no \"{q}\" at points (only PX PY PZ VX VY VZ AX AY AZ FX FY FZ T)"
            ))
        }
    })
}

fn body_quantity(q: &str) -> Result<BodyQuantity, String> {
    let b = q.as_bytes();
    let axis = |c: Option<&u8>| match c {
        Some(b'X') => Some(Axis::X),
        Some(b'Y') => Some(Axis::Y),
        Some(b'Z') => Some(Axis::Z),
        _ => None,
    };
    let last = axis(b.last());
    Ok(match (&q[..q.len().saturating_sub(1)], last) {
        ("P", Some(a)) => BodyQuantity::Position(a),
        ("R", Some(a)) => BodyQuantity::Rotation(a),
        ("V", Some(a)) => BodyQuantity::Velocity(a),
        ("RV", Some(a)) => BodyQuantity::AngularVelocity(a),
        ("A", Some(a)) => BodyQuantity::Acceleration(a),
        ("RA", Some(a)) => BodyQuantity::AngularAcceleration(a),
        ("F", Some(a)) => BodyQuantity::Force(a),
        ("M", Some(a)) => BodyQuantity::Moment(a),
        _ if q == "T" || q == "TEN" => BodyQuantity::Tension,
        _ if q.is_empty() => return Err("no quantity (e.g. PX, RY, FZ)".into()),
        _ => {
            return Err(format!(
                "MoorDyn outputs no \"{q}\" of a body (only PX PY PZ RX RY RZ VX VY VZ RVX RVY \
                 RVZ AX AY AZ RAX RAY RAZ FX FY FZ MX MY MZ T)"
            ))
        }
    })
}

/// The part after `R<n>`: a quantity of the rod as a whole, or of one of
/// its `segments + 1` nodes (`N<k>`, `NA` node 0, `NB` the last: no
/// quantity starts with N). Refused: what MoorDyn has no value for, a
/// rotation about the rod's axis (`RZ`, `RVZ`, `RAZ`, none in
/// `Rod::GetRodOutput`), `T` (MoorDyn writes 0); a node past the last.
fn rod_quantity(q: &str, segments: usize) -> Result<RodQuantity, NotAChannel> {
    if let Some(after) = q.strip_prefix('N') {
        let digits = after
            .find(|c: char| !c.is_ascii_digit())
            .unwrap_or(after.len());
        let (node, rest) = if digits > 0 {
            let k: usize = after[..digits]
                .parse()
                .map_err(|_| NotAChannel::Missing("node number too large".into()))?;
            (k, &after[digits..])
        } else if let Some(rest) = after.strip_prefix('A') {
            (0, rest)
        } else if let Some(rest) = after.strip_prefix('B') {
            (segments, rest)
        } else {
            return Err("after N comes a node number, A or B".into());
        };
        if node > segments {
            return Err(NotAChannel::Missing(format!(
                "the rod has nodes 0 to {segments} ({segments} segments)"
            )));
        }
        return Ok(match quantity(rest)? {
            Q::P(a) => RodQuantity::NodePosition(node, a),
            Q::V(a) => RodQuantity::NodeVelocity(node, a),
            _ => RodQuantity::NodeOther(node),
        });
    }
    if let Some(end) = end_tension(q) {
        return Ok(RodQuantity::EndTension(end));
    }
    if q == "SUB" {
        return Ok(RodQuantity::Submerged);
    }
    let only = "only PX PY PZ RX RY VX VY VZ RVX RVY AX AY AZ RAX RAY FX FY FZ MX MY MZ TENA \
                TENB SUB";
    if matches!(q, "RZ" | "RVZ" | "RAZ") {
        return Err(format!(
            "MoorDyn has no \"{q}\" of a rod (no rotation about its axis; {only})"
        )
        .into());
    }
    let quantity = match body_quantity(q) {
        Ok(BodyQuantity::Position(a)) => RodQuantity::Position(a),
        Ok(BodyQuantity::Rotation(a)) => RodQuantity::Rotation(a),
        Ok(BodyQuantity::Velocity(a)) => RodQuantity::Velocity(a),
        Ok(BodyQuantity::AngularVelocity(a)) => RodQuantity::AngularVelocity(a),
        Ok(BodyQuantity::Acceleration(a)) => RodQuantity::Acceleration(a),
        Ok(BodyQuantity::AngularAcceleration(a)) => RodQuantity::AngularAcceleration(a),
        Ok(BodyQuantity::Force(a)) => RodQuantity::Force(a),
        Ok(BodyQuantity::Moment(a)) => RodQuantity::Moment(a),
        Ok(BodyQuantity::Tension) => {
            return Err(format!(
                "MoorDyn writes 0 for \"{q}\" of a rod (TENA and TENB are its ends' line \
                 forces; {only})"
            )
            .into())
        }
        Err(_) if q.is_empty() => return Err("no quantity (e.g. PX, RY, TENA, SUB)".into()),
        Err(_) => return Err(format!("MoorDyn outputs no \"{q}\" of a rod ({only})").into()),
    };
    Ok(quantity)
}

/// The quantity suffixes of `MoorDyn2.cpp`, those of no line or point
/// (rotations, moments, `SUB`) as `Other`.
enum Q {
    P(Axis),
    V(Axis),
    A(Axis),
    F(Axis),
    T,
    Other,
}

fn quantity(q: &str) -> Result<Q, String> {
    let axis = |c: u8| match c {
        b'X' => Some(Axis::X),
        b'Y' => Some(Axis::Y),
        b'Z' => Some(Axis::Z),
        _ => None,
    };
    let b = q.as_bytes();
    let q2 = if b.len() == 2 { axis(b[1]) } else { None };
    Ok(match (b.first(), q2) {
        (Some(b'P'), Some(a)) => Q::P(a),
        (Some(b'V'), Some(a)) => Q::V(a),
        (Some(b'A'), Some(a)) => Q::A(a),
        (Some(b'F'), Some(a)) => Q::F(a),
        _ if q == "T" || q == "TEN" => Q::T,
        _ if matches!(
            q,
            "RX" | "RY"
                | "RZ"
                | "RVX"
                | "RVY"
                | "RVZ"
                | "RAX"
                | "RAY"
                | "RAZ"
                | "MX"
                | "MY"
                | "MZ"
                | "SUB"
        ) =>
        {
            Q::Other
        }
        _ if q.is_empty() => return Err("no quantity (e.g. PX, VZ, FX, T)".into()),
        _ => return Err(format!("unknown quantity \"{q}\"")),
    })
}
