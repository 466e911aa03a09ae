//! The `stancf` command line as a library: the scenario library
//! (`stancf_scenario`, re-exported here) with what only the command line
//! has: figures (PNG and SVG), `stancf plot` and the paper's studies.

pub use stancf_scenario::*;

pub mod figure_data;
pub mod figures;
pub mod figures_bodies;
pub mod figures_energy;
pub mod figures_system;
pub mod plot;
pub mod reproduce;
