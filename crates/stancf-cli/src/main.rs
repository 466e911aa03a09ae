//! `stancf`: run space-time ANCF cable simulations from scenario files.
//!
//! Exit codes (docs/interface.md): 0 success, 2 invalid input, 3 the solver
//! failed (results up to the last converged step are kept), 1 anything else.

use clap::{Parser, Subcommand};
use stancf_cli::{check, reproduce, run, signals, sweep, Failure};
use std::path::PathBuf;
use std::process::ExitCode;

#[derive(Parser)]
#[command(
    name = "stancf",
    version,
    about = "Flexible cables with space-time ANCF elements (SAC-2, SAC-3) and the P2 variational step"
)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand)]
enum Command {
    /// Run one scenario and write its results.
    Run {
        /// Scenario file (TOML).
        scenario: PathBuf,
        /// Output folder (default: out/<scenario file stem>/).
        #[arg(long)]
        out: Option<PathBuf>,
        /// Also draw the figures (PNG and SVG) next to the results.
        #[arg(long)]
        plot: bool,
        /// Also write ParaView files: vtk/cable_<k>.vtp per written step
        /// and the collection cable.pvd.
        #[arg(long)]
        vtk: bool,
        /// No progress bar and no summary on standard output.
        #[arg(long, short)]
        quiet: bool,
        /// Run even when the step count or the size of the result files
        /// exceeds the bounds that otherwise refuse a run (see `check`).
        #[arg(long)]
        allow_large: bool,
        /// The water depth (m) of a MoorDyn deck without WtrDpth, as a
        /// coupling code gives it (the deck's WtrDpth wins).
        #[arg(long, value_name = "METRES")]
        water_depth: Option<f64>,
    },
    /// Run a scenario over a grid of key values: `--set key=v1,v2` (dotted
    /// keys, list entries by index: `loads.1.drag_coefficient`), one folder
    /// per run and DIR/sweep.csv with the summary figures of all.
    Sweep {
        /// Scenario files (TOML) or MoorDyn decks; several make one more
        /// axis, `scenario` (intact and damaged variants).
        #[arg(required = true)]
        scenario: Vec<PathBuf>,
        /// key=v1,v2,... (repeat for a grid).
        #[arg(long = "set")]
        sets: Vec<String>,
        /// Runs at a time (default: the number of cores).
        #[arg(long)]
        jobs: Option<usize>,
        /// Output folder (default: out/<scenario file stem>-sweep/).
        #[arg(long)]
        out: Option<PathBuf>,
    },
    /// Draw the figures (PNG and SVG) of results already in DIR.
    Plot {
        /// A folder written by `stancf run`.
        dir: PathBuf,
    },
    /// Validate a scenario and print derived figures (DOFs, wave speed,
    /// Courant number, stable step); runs nothing.
    Check {
        /// Scenario file (TOML) or MoorDyn v2 deck.
        scenario: PathBuf,
        /// Check a system beyond the element and step bounds, as `run
        /// --allow-large` would run it.
        #[arg(long)]
        allow_large: bool,
        /// The water depth (m) of a MoorDyn deck without WtrDpth, as `run
        /// --water-depth`.
        #[arg(long, value_name = "METRES")]
        water_depth: Option<f64>,
    },
    /// Reproduce one of the paper's studies (or `all`): tables as CSV and
    /// Markdown in DIR/<study>/.
    Reproduce {
        /// circle-bending | all
        study: String,
        /// Output folder (default: out/reproduce).
        #[arg(long)]
        out: Option<PathBuf>,
    },
}

/// `--water-depth` as the host's sea.
fn host_depth(water_depth: Option<f64>) -> run::HostEnvironment {
    run::HostEnvironment {
        water_depth,
        ..run::HostEnvironment::NONE
    }
}

fn main() -> ExitCode {
    let cli = match Cli::try_parse() {
        Ok(c) => c,
        Err(e) => {
            let code = if e.use_stderr() { 2 } else { 0 };
            let _ = e.print();
            return ExitCode::from(code);
        }
    };
    if matches!(cli.command, Command::Run { .. } | Command::Sweep { .. }) {
        signals::install();
    }
    let result = match cli.command {
        Command::Run {
            scenario,
            out,
            plot,
            vtk,
            quiet,
            allow_large,
            water_depth,
        } => run::run(
            &scenario,
            run::RunOptions {
                out,
                plot: plot
                    .then(|| run::Figures(std::sync::Arc::new(stancf_cli::figures::plot_results))),
                vtk,
                quiet,
                allow_large,
                cancel: Some(signals::cancel()),
                shown_as: None,
                collect: None,
                host: host_depth(water_depth),
            },
        ),
        Command::Plot { dir } => stancf_cli::figures::plot(&dir),
        Command::Sweep {
            scenario,
            sets,
            jobs,
            out,
        } => sweep::sweep(&scenario, &sets, jobs, out),
        Command::Check {
            scenario,
            allow_large,
            water_depth,
        } => check::check_in(&scenario, allow_large, &host_depth(water_depth)),
        Command::Reproduce { study, out } => reproduce::reproduce(
            &study,
            &out.unwrap_or_else(|| PathBuf::from("out").join("reproduce")),
        ),
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(Failure::Input(m)) => {
            eprintln!("error: {m}");
            ExitCode::from(2)
        }
        Err(Failure::Solver(m)) => {
            eprintln!("error: {m}");
            ExitCode::from(3)
        }
        Err(Failure::Other(m)) => {
            eprintln!("error: {m}");
            ExitCode::from(1)
        }
        Err(Failure::Interrupted(m)) => {
            eprintln!("error: {m}");
            ExitCode::from(signals::exit_code())
        }
    }
}
