//! The `stancf` command line as a library: scenario files (parsing and
//! validation), result files, figures, ParaView output, sweeps and the
//! paper's studies. The `stancf` binary and the Python package are thin
//! layers over it, so that both read and write exactly the same files.

pub mod check;
pub mod check_system;
pub mod coupling;
pub mod echo;
pub mod figures;
pub mod figures_system;
pub mod input_file;
pub mod input_scales;
pub mod moordyn;
pub mod output;
pub mod plot;
pub mod progress;
pub mod reproduce;
pub mod result_folder;
pub mod result_layout;
pub mod results;
pub mod run;
pub mod scale_range;
pub mod scenario;
pub mod signals;
pub mod sweep;
pub mod system_geometry;
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
