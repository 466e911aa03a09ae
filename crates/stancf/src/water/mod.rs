//! Lines in water (docs/method.md §12): the sea a line sees (density,
//! depth, currents, waves) and the loads it puts on the line at the
//! slab's space-time Gauss points.
//!
//! z is up, the still water surface is z = 0 and the seabed z = -depth.
pub mod added_mass;
pub mod bathymetry;
pub mod current;
pub mod current_grid;
mod grid_axis;
pub mod host_flow;
pub mod hydro;
pub mod kinematics;
pub mod point;
pub mod record;
pub mod seabed;
pub mod spectrum;
pub mod submerged;
pub mod waves;

pub use added_mass::{AddedMass, EntrainedAtPoint, EntrainedFirst};
pub use bathymetry::Bathymetry;
pub use host_flow::{ElementFlow, NodeFlow};
pub use hydro::{LineInWater, Morison, Water};
pub use point::{PointForce, PointInWater};
pub use seabed::{BedSurface, ForceAtPoint, Seabed, SeabedContact};
pub use submerged::SubmergedFraction;
