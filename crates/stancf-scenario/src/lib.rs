//! stancf's scenario library: scenario files and MoorDyn decks read and
//! validated (with the bounds on a run's work and the plausibility of its
//! scales), result files written as one transaction and read back, runs
//! and sweeps of scenarios, and coupled systems opened for a host. The
//! `stancf` command line, the Python package and the C library are shells
//! over it and the core (`stancf`); it draws no figures and parses no
//! command line.

pub mod check;
pub mod check_bodies;
pub mod check_system;
pub mod coupling;
pub mod echo;
pub mod input_file;
pub mod input_scales;
pub mod moordyn;
pub mod output;
pub mod progress;
pub mod result_folder;
pub mod result_layout;
pub mod results;
pub mod run;
pub mod scale_range;
pub mod scenario;
pub mod signals;
pub mod sweep;
pub mod system_geometry;
mod system_start;
pub mod vtk;
pub mod work_bounds;

/// How a command ended.
#[derive(Debug)]
pub enum Failure {
    /// Invalid input (exit 2).
    Input(String),
    /// The solver failed (exit 3).
    Solver(String),
    /// Anything else, e.g. a file that cannot be written (exit 1).
    Other(String),
    /// Stopped on request (Ctrl-C in Python; exit 130); the results up to
    /// the last step are kept.
    Interrupted(String),
}

impl std::fmt::Display for Failure {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Failure::Input(m)
            | Failure::Solver(m)
            | Failure::Other(m)
            | Failure::Interrupted(m) => f.write_str(m),
        }
    }
}

impl std::error::Error for Failure {}
