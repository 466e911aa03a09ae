//! Rigid bodies in the space-time step (docs/method.md §15): a body's
//! position and rotation are unknowns of a step like a cable's nodes,
//! moving in time along the cubic Hermite of eq. (6), with an action
//! integrated at the same time Gauss points.
//!
//! The centre of mass moves like a free point (M31). The rotation over a
//! step is a rotation vector from the step's start, R(t) = R_a
//! exp([theta(t)]) with theta a cubic, so every R(t) is a rotation, none
//! of them has singular angles however far the body turns over many
//! steps, and the Galerkin step keeps its order (§15.4).
//!
//! | module | what it holds |
//! |---|---|
//! | [`inertia`] | mass, centre of mass and inertia tensor; what no body has is refused (B2) |
//! | [`pose`] | points of a body (B1), MoorDyn's angles |
//! | [`rotation`] | the exponential (B4) and the body rate (B3) of a rotation vector |
//! | [`jet`] | numbers with their exact first and second derivatives |
//! | [`terms`] | a time point's kinetic energy (with added mass), loads and drag (B9)-(B10) |
//! | [`flow`] | the sea's velocity, acceleration and dynamic pressure at a body's point, on jets in the pose (B31) |
//! | [`rod`] | a rigid cylinder in a body: its inertia, added mass and drag (B17)-(B19) |
//! | [`waterline`] | the part of a rod under the surface: its volume and first moment (B20)-(B21) |
//! | [`wet`] | what of a rod the water wets: its sections' and caps' wet fractions and their rates (B22) |
//! | [`attach`] | a point fixed to a body over a step (B11), on jets |
//! | [`free`] | a free body's Galerkin step (B5)-(B7) and P2 step (B8) |

pub mod attach;
pub mod flow;
pub mod free;
pub mod inertia;
pub mod jet;
pub mod pose;
pub mod rod;
pub mod rotation;
pub mod terms;
mod water;
pub mod waterline;
pub mod wet;

pub use free::{BodyForces, FreeBody};
pub use inertia::RigidInertia;
pub use rod::Rod;
pub use water::{BodyExternal, BodyHostFlow, BodyWater};
