//! Rigid bodies in the space-time step (docs/method.md §15): a body's
//! position and rotation are unknowns of a step like a cable's nodes,
//! moving along the same cubic Hermite in time (eq. 6), with an action
//! integrated at the same time Gauss points.
//!
//! A body is described by *natural coordinates* (§15.1): the position r
//! of its reference point and the three columns a_1, a_2, a_3 of its
//! rotation matrix, twelve numbers
//!
//! ```text
//!   q = [r, a_1, a_2, a_3],      x(xi) = r + xi_1 a_1 + xi_2 a_2 + xi_3 a_3 = S(xi) q     (B1)
//! ```
//!
//! so a body-fixed point is *linear* in q, the kinetic energy has a
//! constant mass matrix (B2), gravity and buoyancy are linear (B4), and a
//! rotation of any size is represented without singular angles. The
//! columns' six orthonormality conditions (B5) are constraints of the
//! step, enforced at its end with multipliers (B6)-(B7).
//!
//! | module | what it holds |
//! |---|---|
//! | [`inertia`] | mass, centre of mass and inertia tensor, the generalized mass (B2)-(B3) |
//! | [`natural`] | natural coordinates from a pose and back, rates, angular velocity (B1), (B8); MoorDyn's angles |
//! | [`orthonormality`] | the six conditions (B5) and their Jacobian |
//! | [`free`] | a free body's Galerkin step (B6)-(B7): its rows, Jacobian and momentum projection |

pub mod free;
pub mod inertia;
pub mod natural;
pub mod orthonormality;

pub use free::{BodyForces, FreeBody};
pub use inertia::RigidInertia;
