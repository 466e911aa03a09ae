//! Assembly of the equations of one time step, eq. (22), with any number
//! of element layers in time (the paper's "time direction assembly"), and
//! of a static solve (the time-invariant slab, docs/method.md §6.8).
//! The step's unknowns and rows: docs/method.md §4.3 (P2) and §5.1
//! (Galerkin); constraints: §6.3-6.4.
//!
//! A P2 step [t_a, t_b] holds L layers with time nodes t_0 = t_a, ...,
//! t_L = t_b. The unknowns are e_i, v_i at t_1 .. t_L; the rows are
//!
//! ```text
//!   dA/de_0 + M v_0 = 0                      (P2 row at the input node)
//!   dA/de_i = 0,  dA/dv_i = 0,  0 < i < L    (interior time nodes)
//!   dA/de_L - M v_L = 0                      (P2 row at the output node)
//! ```
//!
//! with A the action of all space-time elements of the step and the
//! virtual work of the nodal loads. The Galerkin step (docs/method.md
//! §5.1, (M22)) uses the same slab action with the end slopes w_a, w_b
//! as unknowns in place of the velocities and carries the momentum p:
//!
//! ```text
//!   dA/de_a + p_a = 0,   dA/dw_a = 0,   dA/dw_b = 0      (unknowns w_a, e_b, w_b)
//!   p_b = dA/de_b,       v_b = M^-1 p_b                    (after convergence)
//! ```
//!
//! A static solve has one unknown e and one row per coordinate,
//! dU/de - dW/de = 0 (A = dt (W - U) for a time-invariant slab; (M25)).
//!
//! A constrained coordinate (see [`crate::constraints`]) has prescribed
//! values at the time nodes and its rows are freed: with elimination they
//! and its unknowns leave the system (the rows' values are kept as the
//! reaction); with multipliers every freed row gets a multiplier unknown
//! and every fixed value a constraint equation.
//!
//! Unknowns and rows are numbered spatial node by spatial node, so the
//! Jacobian is a band matrix (see [`crate::band`]; docs/method.md §7.6):
//!
//! ```text
//!   unknowns of node n:  [slot 1: free coords, slot 2: ..., multipliers]
//!   rows of node n:      [slot 1: free coords, slot 2: ..., constraint eqs]
//! ```

//!
//! The files: `layout.rs` numbers the unknowns and rows ([`SlabLayout`]);
//! `system.rs` holds a step's known data, its scratch and the assembly
//! driver ([`StepProblem::assemble`]); `elements.rs` the elements'
//! contributions (element actions, on several threads for a long line's
//! residual, and static element rows); `terms.rs` the others (nodal loads,
//! momentum and constraint terms); `scaling.rs` the convergence scales ([`Scales`]);
//! `matrices.rs` the global stiffness and mass matrices.

mod elements;
mod entrained;
mod layout;
mod matrices;
mod scaling;
mod system;
mod terms;

pub use elements::PARALLEL_ELEMENTS;
pub use layout::SlabLayout;
pub use matrices::stiffness_and_mass;
pub use scaling::Scales;
pub use system::{AssemblyScratch, StepProblem, StepStart};

/// The scheme and its slot kinds live in [`crate::scheme`]; their old
/// paths here stay.
pub use crate::scheme::{Kind, Scheme};
