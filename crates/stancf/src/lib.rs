//! # stancf: space-time ANCF cable elements
//!
//! A library for the dynamics of flexible cables with the space-time
//! absolute nodal coordinate formulation of Chen, Li, Lu and Lan (Machines
//! 2023, 11, 433): cable elements SAC-2 (cubic Hermite in space) and SAC-3
//! (quintic), each a tensor product with a cubic Hermite in time, so nodal
//! positions *and* velocities are unknowns; the action integrated by Gauss
//! quadrature in space and time; Hamilton's law of varying action with the
//! P2 formula, one slab per step, optionally several element layers in
//! time per step.
//!
//! The method, equation by equation with the decisions taken, is
//! docs/method.md in the repository; the modules' doc comments cite its
//! sections (§) and formulas (M1)-(M42). The modules follow the method
//! from the bottom up:
//!
//! | module | what it implements |
//! |---|---|
//! | [`shape`] | Hermite bases in space (eqs. 4, 5) and time (eq. 6) |
//! | [`quadrature`] | Gauss-Legendre rules, 1 to 10 points |
//! | [`element`] | the SAC-2/SAC-3 kernel: energy densities, slab action, gradient, exact Hessian |
//! | [`model`] | cable, material, loads, mesh and DOF numbering |
//! | [`assembly`] | the P2 equations of a step (eq. 22) with time layers |
//! | [`band`] | band LU with partial pivoting, the linear solver of one cable |
//! | [`bordered`] | bands bordered by the points' unknowns: a system's Jacobian, block elimination |
//! | [`linear`] | what the solvers need of a matrix and its factors |
//! | [`solver`] | Newton-Raphson (eq. 25, 26) |
//! | [`integrator`] | the P2 step, runs with an energy watchdog |
//! | [`observe`] | energies, momentum, stress |
//! | [`stability`] | P2's stable step for the actual mesh |
//! | [`motion`] | motions of coupled points: oscillations and interpolated tables |
//! | [`system`] | lines joined at fixed, free and coupled points, and their step |
//! | [`coupling`] | a system stepped by another code that moves its coupled points (MoorDyn's step API) |
//! | [`catenary`] | the closed-form elastic catenary of a line between two points (Irvine) |
//! | [`water`] | the sea: density, depth, currents, waves, and the loads of water on a line |
//! | [`body`] | rigid bodies: inertia, rotations over a step, a free body's Galerkin step |
//!
//! The physics never touches files, terminals or the clock; the `stancf`
//! command-line tool (crate `stancf-cli`) does.

pub mod assembly;
pub mod band;
pub mod body;
pub mod bordered;
pub mod catenary;
pub mod constraints;
pub mod coupling;
pub mod damping;
pub mod element;
pub mod error;
pub mod integrator;
pub mod linear;
pub mod loads;
pub mod model;
pub mod motion;
pub mod numbering;
pub mod observe;
pub mod quadrature;
pub mod scheme;
pub mod shape;
pub mod solver;
pub mod stability;
pub mod statics;
pub mod system;
mod threads;
pub mod vec3;
pub mod water;

pub use constraints::{Constraint, ConstraintKind, ConstraintMethod};
pub use element::{AxialStrain, Curvature, Measures};
pub use error::{FailureKind, ModelError, SolverError};
pub use integrator::{run, Simulation, StepReport, StepSettings, TimeScheme};
pub use model::{
    Cable, ElementType, GradedEnd, Grading, Load, Material, MeshSection, Model, ModelOptions,
    SpacePoints, State,
};
pub use observe::{energies, Energies};
pub use solver::{convergence_rate, Clock, NewtonSettings, SolverMethod, Timing};
pub use statics::{StaticSettings, StaticSolver};

/// The README's Rust example, compiled and run as a doc test.
#[cfg(doctest)]
#[doc = include_str!("../../../README.md")]
pub struct ReadmeDoctests;
