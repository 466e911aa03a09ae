//! The units MoorDyn writes under each output channel in its `.out` file
//! (`UnitList` of MoorDyn2.cpp).

use super::{BodyQuantity, Channel, LineQuantity, PointQuantity, RodQuantity};

impl Channel {
    /// The units MoorDyn writes under the channel in its `.out` file
    /// (`UnitList` of MoorDyn2.cpp: "m", "deg", "m/s", "deg/s", "m/s^2",
    /// "deg/s^2", "N", "N*m", "(frac)"); None for a name MoorDyn skips
    /// and for a rod node's quantity stancf does not compute.
    pub fn moordyn_units(&self) -> Option<&'static str> {
        Some(match *self {
            Channel::FairleadTension { .. }
            | Channel::AnchorTension { .. }
            | Channel::LineEndTension { .. } => "N",
            Channel::LineNode { quantity, .. } => match quantity {
                LineQuantity::Position(_) => "m",
                LineQuantity::Velocity(_) => "m/s",
                LineQuantity::Force(_) | LineQuantity::Tension => "N",
            },
            Channel::Point { quantity, .. } => match quantity {
                PointQuantity::Position(_) => "m",
                PointQuantity::Velocity(_) => "m/s",
                PointQuantity::Acceleration(_) => "m/s^2",
                PointQuantity::Force(_) | PointQuantity::Tension => "N",
            },
            Channel::Body { quantity, .. } => match quantity {
                BodyQuantity::Position(_) => "m",
                BodyQuantity::Rotation(_) => "deg",
                BodyQuantity::Velocity(_) => "m/s",
                BodyQuantity::AngularVelocity(_) => "deg/s",
                BodyQuantity::Acceleration(_) => "m/s^2",
                BodyQuantity::AngularAcceleration(_) => "deg/s^2",
                BodyQuantity::Force(_) | BodyQuantity::Tension => "N",
                BodyQuantity::Moment(_) => "N*m",
            },
            Channel::Rod { quantity, .. } => match quantity {
                RodQuantity::Position(_) | RodQuantity::NodePosition(..) => "m",
                RodQuantity::Rotation(_) => "deg",
                RodQuantity::Velocity(_) | RodQuantity::NodeVelocity(..) => "m/s",
                RodQuantity::AngularVelocity(_) => "deg/s",
                RodQuantity::Acceleration(_) => "m/s^2",
                RodQuantity::AngularAcceleration(_) => "deg/s^2",
                RodQuantity::Force(_) | RodQuantity::EndTension(_) => "N",
                RodQuantity::Moment(_) => "N*m",
                RodQuantity::Submerged => "(frac)",
                RodQuantity::NodeOther(_) => return None,
            },
            Channel::Unrecognized => return None,
        })
    }
}
