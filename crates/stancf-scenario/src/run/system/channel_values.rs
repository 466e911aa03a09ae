//! The values of a deck's MoorDyn output channels (docs/interface.md,
//! "Results of a system": channels.csv and `<deck>.out`) at a written
//! row.

use super::bodies::BodyRow;
use super::rods::{rod_value, RodFrame};
use super::rows::SystemRow;
use crate::moordyn::{Axis, BodyQuantity, Channel, LineEnd, LineQuantity, PointQuantity};
use stancf::model::SLOT_R;

/// The value of a MoorDyn output channel at a row (ids are 1-based, as
/// the deck's): line end tensions (0 before the first step of a run from
/// the straight shape, where no end force is known yet), point and line
/// node positions and velocities, bodies' and rods' (`rods`) values.
pub(super) fn channel_value(c: &Channel, row: &SystemRow, rods: &[RodFrame]) -> f64 {
    let axis = |a: Axis| match a {
        Axis::X => 0,
        Axis::Y => 1,
        Axis::Z => 2,
    };
    let end_tension =
        |line: usize, end: usize| row.ends[line - 1][end].map_or(0.0, |f| f.tension());
    match *c {
        Channel::FairleadTension { line } => end_tension(line, 1),
        Channel::AnchorTension { line } => end_tension(line, 0),
        Channel::LineEndTension { line, end } => {
            end_tension(line, if end == LineEnd::A { 0 } else { 1 })
        }
        Channel::LineNode {
            line,
            node,
            quantity,
        } => {
            let (model, state) = row.lines[line - 1];
            let o = model.coordinate(node, SLOT_R, 0);
            let last = model.nodes() - 1;
            match quantity {
                LineQuantity::Position(a) => state.e[o + axis(a)],
                LineQuantity::Velocity(a) => state.v[o + axis(a)],
                // MoorDyn's: the end's force at an end node, the line's
                // tension at an inner one.
                LineQuantity::Tension if node == 0 => end_tension(line, 0),
                LineQuantity::Tension if node == last => end_tension(line, 1),
                LineQuantity::Tension => stancf::observe::node_axial_force(model, state, node),
                LineQuantity::Force(_) => f64::NAN,
            }
        }
        Channel::Point { point, quantity } => {
            let (x, v, _) = row.points[point - 1];
            let net = row.point_net[point - 1];
            match quantity {
                PointQuantity::Position(a) => x[axis(a)],
                PointQuantity::Velocity(a) => v[axis(a)],
                PointQuantity::Force(a) => net[axis(a)],
                PointQuantity::Tension => net.iter().map(|f| f * f).sum::<f64>().sqrt(),
                PointQuantity::Acceleration(_) => f64::NAN,
            }
        }
        Channel::Body { body, quantity } => body_value(&row.bodies[body - 1], quantity),
        Channel::Rod { rod, quantity } => rod_value(&rods[rod - 1], quantity, row),
        // Its column is left empty (not computed).
        Channel::Unrecognized => f64::NAN,
    }
}

/// The value of a body channel (MoorDyn's units: rotations in degrees and
/// degrees per second; forces MoorDyn's net force, see
/// [`super::bodies`]); accelerations are refused on reading (NaN here).
fn body_value(b: &BodyRow, q: BodyQuantity) -> f64 {
    let axis = |a: Axis| match a {
        Axis::X => 0,
        Axis::Y => 1,
        Axis::Z => 2,
    };
    let m = &b.motion;
    match q {
        BodyQuantity::Position(a) => m.position[axis(a)],
        BodyQuantity::Rotation(a) => b.angles[axis(a)],
        BodyQuantity::Velocity(a) => m.velocity[axis(a)],
        BodyQuantity::AngularVelocity(a) => m.angular_velocity[axis(a)].to_degrees(),
        BodyQuantity::Force(a) => b.net_force[axis(a)],
        BodyQuantity::Moment(a) => b.net_moment[axis(a)],
        BodyQuantity::Tension => stancf::vec3::norm(b.net_force),
        BodyQuantity::Acceleration(_) | BodyQuantity::AngularAcceleration(_) => f64::NAN,
    }
}
