//! The bounds on a run's work: at most [`MAX_STEPS`] steps and about
//! [`MAX_RESULT_BYTES`] of result files, estimated from the steps,
//! `output.every` and the mesh before anything runs; `run` refuses a run
//! beyond them unless given `--allow-large`, and `check` warns.

use crate::moordyn::SupportedOption;
use crate::scenario::{AnalysisKind, Scenario, SystemScenario, MAX_STEPS};
use crate::Failure;
use stancf::error::Sig;
use stancf::integrator::step_count;
use std::path::Path;

/// A run is refused when its result files would exceed this many bytes
/// (estimated from the steps, `output.every` and the mesh) unless
/// `--allow-large` is given (`check` warns).
pub const MAX_RESULT_BYTES: f64 = 4e9;

/// A system of more elements than this (all lines together) is refused
/// unless `--allow-large` is given: its static solve alone takes about
/// 10 ms per element when lines rest on the seabed (the OC4 deck with one
/// line of 2000 segments: 22 s).
pub const MAX_SYSTEM_ELEMENTS: usize = 2000;

/// The most elements a system may have even with `--allow-large` (and
/// a library opening one with its opt-in for large systems): one line of
/// the most a line may have ([`stancf::model::MAX_ELEMENTS`], about 25 GB
/// to build and solve, [`BYTES_PER_SYSTEM_ELEMENT`]); below it, the
/// memory the process may take bounds it too.
pub const HARD_MAX_SYSTEM_ELEMENTS: usize = stancf::model::MAX_ELEMENTS;

/// Bytes a system's element takes to build and solve, statics and
/// dynamics: 8.6 kB measured by `check` (its model, its static solve's and
/// its simulation's matrices) on a line of 1e5 elements, 19 kB by a
/// coupled system's static solve at 1e5 elements (1.93 GB); with a margin.
pub const BYTES_PER_SYSTEM_ELEMENT: f64 = 25e3;

/// The memory this process may still take (bytes): the machine's
/// available memory (`MemAvailable` of /proc/meminfo) and what the
/// process's address-space limit leaves (`RLIMIT_AS` less its `VmSize`),
/// whichever is less; None where neither is known.
pub fn memory_available() -> Option<f64> {
    let field = |text: &str, key: &str| -> Option<f64> {
        let line = text.lines().find(|l| l.starts_with(key))?;
        let kb: f64 = line[key.len()..]
            .trim()
            .trim_end_matches("kB")
            .trim()
            .parse()
            .ok()?;
        Some(kb * 1024.0)
    };
    let machine = std::fs::read_to_string("/proc/meminfo")
        .ok()
        .and_then(|t| field(&t, "MemAvailable:"));
    let mut limit = libc::rlimit {
        rlim_cur: 0,
        rlim_max: 0,
    };
    // SAFETY: getrlimit(2) writes the struct it is given.
    let limited = unsafe { libc::getrlimit(libc::RLIMIT_AS, &mut limit) } == 0
        && limit.rlim_cur != libc::RLIM_INFINITY;
    let process = if limited {
        let used = std::fs::read_to_string("/proc/self/status")
            .ok()
            .and_then(|t| field(&t, "VmSize:"))
            .unwrap_or(0.0);
        Some((limit.rlim_cur as f64 - used).max(0.0))
    } else {
        None
    };
    match (machine, process) {
        (Some(a), Some(b)) => Some(a.min(b)),
        (a, b) => a.or(b),
    }
}

/// The work of a system, counted from its scenario before anything of it
/// is built: its elements (all lines; the sum saturates, it never wraps)
/// and, for a dynamic analysis, its steps.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SystemWork {
    pub elements: usize,
    /// The line with the most elements (its index).
    pub largest_line: usize,
    /// Steps of a dynamic analysis (0 for a static one).
    pub steps: f64,
}

/// The work of the system of `sc` (see [`SystemWork`]).
pub fn system_work(sc: &SystemScenario) -> SystemWork {
    let elements = sc
        .lines
        .iter()
        .fold(0usize, |n, l| n.saturating_add(l.elements));
    let largest_line = (0..sc.lines.len())
        .max_by_key(|&i| sc.lines[i].elements)
        .unwrap_or(0);
    let steps = match sc.analysis.kind {
        AnalysisKind::Dynamic => step_count(sc.analysis.duration, sc.analysis.time_step) as f64,
        AnalysisKind::Static => 0.0,
    };
    SystemWork {
        elements,
        largest_line,
        steps,
    }
}

/// Why a system is refused, or None within the bounds: its elements above
/// [`MAX_SYSTEM_ELEMENTS`] (unless `allow_large`) or
/// [`HARD_MAX_SYSTEM_ELEMENTS`], its steps above [`MAX_STEPS`] (unless
/// `allow_large`). The message starts with the keys (the scenario's, or the
/// deck's lines) and says what to do.
pub fn system_problem(sc: &SystemScenario, allow_large: bool) -> Option<String> {
    elements_problem(sc, allow_large).or_else(|| steps_problem(sc, allow_large))
}

/// The part of [`system_problem`] on elements: the bounds, and the
/// memory the system would take against what this process may take (an
/// allocation that fails aborts the process, a C library's host with it).
fn elements_problem(sc: &SystemScenario, allow_large: bool) -> Option<String> {
    let work = system_work(sc);
    if let Some(l) = sc.lines.get(work.largest_line) {
        let limit = if allow_large {
            HARD_MAX_SYSTEM_ELEMENTS
        } else {
            MAX_SYSTEM_ELEMENTS
        };
        if work.elements > limit {
            let key = sc.names.line(work.largest_line, "elements", "NumSegs");
            let what = format!(
                "{key}: the lines have {} elements in all (the most, {}, in line {})",
                work.elements, l.elements, l.id
            );
            return Some(if allow_large {
                format!(
                    "{what}, above the {HARD_MAX_SYSTEM_ELEMENTS} a system may have (about 25 GB \
                     to build and solve); mesh the lines more coarsely"
                )
            } else {
                format!(
                    "{what}, above the {MAX_SYSTEM_ELEMENTS} a system takes without \
                     --allow-large (its static solve alone takes about 10 ms an element); mesh \
                     the lines more coarsely or pass --allow-large"
                )
            });
        }
    }
    let needed = work.elements as f64 * BYTES_PER_SYSTEM_ELEMENT;
    if let Some(free) = memory_available().filter(|&free| needed > free) {
        let key = sc.names.line(work.largest_line, "elements", "NumSegs");
        return Some(format!(
            "{key}: the lines have {} elements in all, which take about {} to build and \
             solve, more than the {} this process may still take; mesh the lines more \
             coarsely",
            work.elements,
            bytes_text(needed),
            bytes_text(free)
        ));
    }
    None
}

/// The part of [`system_problem`] on steps.
fn steps_problem(sc: &SystemScenario, allow_large: bool) -> Option<String> {
    let work = system_work(sc);
    if !allow_large && work.steps > MAX_STEPS as f64 {
        let step = sc
            .names
            .option("analysis.time_step", SupportedOption::TimeStep);
        return Some(format!(
            "analysis.duration, {step}: {} steps, above the {:e} a run takes without \
             --allow-large; take a longer step or a shorter run, or pass --allow-large",
            Sig(work.steps),
            MAX_STEPS as f64
        ));
    }
    // The moments `output.interval` writes, bounded as the steps are.
    let moments = sc
        .output_interval
        .map_or(0.0, |interval| sc.analysis.duration / interval);
    if !allow_large && moments > MAX_STEPS as f64 {
        return Some(format!(
            "analysis.duration, output.interval: {} moments written, above the {:e} a run \
             writes without --allow-large; take a longer interval or a shorter run, or pass \
             --allow-large",
            Sig(moments),
            MAX_STEPS as f64
        ));
    }
    None
}

/// [`system_problem`] as an input error naming `file`: `check`, `run` and
/// the coupling library apply it before building anything of a system.
pub fn admit_system(file: &str, sc: &SystemScenario, allow_large: bool) -> Result<(), Failure> {
    match system_problem(sc, allow_large) {
        None => Ok(()),
        Some(m) => Err(Failure::Input(format!("{file}: {m}"))),
    }
}

/// The bound on elements of [`admit_system`] alone: a coupled system's
/// steps are bounded per coupling call, by its handle.
pub fn admit_elements(file: &str, sc: &SystemScenario, allow_large: bool) -> Result<(), Failure> {
    match elements_problem(sc, allow_large) {
        None => Ok(()),
        Some(m) => Err(Failure::Input(format!("{file}: {m}"))),
    }
}

/// How much a run would do and write.
pub(crate) struct Size {
    /// Steps (dynamic) or load steps (static).
    pub(crate) steps: f64,
    /// Rows written (one per written step).
    pub(crate) written: f64,
    /// Estimated bytes of the result files.
    pub(crate) bytes: f64,
}

/// Bytes per step of solver.csv and convergence.csv (dynamic runs), and
/// per written row of history.csv, per node of nodes.csv, per sample of
/// stress.csv, per constrained node of reactions.csv and per element of a
/// `--vtk` file: measured on the examples, rounded up.
const BYTES_PER_STEP: f64 = 250.0;
const BYTES_PER_HISTORY_ROW: f64 = 150.0;
const BYTES_PER_NODE_ROW: f64 = 120.0;
const BYTES_PER_STRESS_ROW: f64 = 75.0;
const BYTES_PER_REACTION_ROW: f64 = 95.0;
const BYTES_PER_VTK_ELEMENT: f64 = 2700.0;

/// The size of a run of `sc` (with `--vtk` when `vtk`).
pub(crate) fn size(sc: &Scenario, vtk: bool) -> Size {
    let a = &sc.analysis;
    let (steps, per_step) = match a.kind {
        AnalysisKind::Dynamic => (step_count(a.duration, a.time_step) as f64, BYTES_PER_STEP),
        AnalysisKind::Static => (a.load_steps as f64, 0.0),
    };
    // Every k-th step, the first row at t = 0 and the last step (a static
    // run writes every load step).
    let written = match a.kind {
        AnalysisKind::Dynamic => (steps / sc.output_every as f64).floor() + 2.0,
        AnalysisKind::Static => steps + 1.0,
    };
    let elements = sc.cable.elements as f64;
    let row = BYTES_PER_HISTORY_ROW
        + BYTES_PER_NODE_ROW * (elements + 1.0)
        + BYTES_PER_STRESS_ROW * 5.0 * elements
        + BYTES_PER_REACTION_ROW * sc.constraints.len() as f64
        + if vtk {
            BYTES_PER_VTK_ELEMENT * elements
        } else {
            0.0
        };
    Size {
        steps,
        written,
        bytes: steps * per_step + written * row,
    }
}

/// Bytes in words: "3.2 GB", "850 MB", "12 kB".
pub(crate) fn bytes_text(b: f64) -> String {
    let units = [(1e12, "TB"), (1e9, "GB"), (1e6, "MB"), (1e3, "kB")];
    for (scale, unit) in units {
        if b >= scale {
            return format!("{} {unit}", Sig((b / scale * 10.0).round() / 10.0));
        }
    }
    format!("{} bytes", b.round())
}

/// Why a run of this size is refused without `--allow-large`: the keys
/// that set its size and what is exceeded; `None` within the bounds.
pub(crate) fn size_problem(sc: &Scenario, size: &Size) -> Option<(String, String)> {
    let dynamic = sc.analysis.kind == AnalysisKind::Dynamic;
    let steps_key = if dynamic {
        "analysis.duration, analysis.time_step"
    } else {
        "analysis.load_steps"
    };
    let mut keys = Vec::new();
    let mut what = Vec::new();
    if size.steps > MAX_STEPS as f64 {
        keys.push(steps_key.to_string());
        what.push(format!(
            "{} steps (the bound is {:e})",
            Sig(size.steps),
            MAX_STEPS as f64
        ));
    }
    if size.bytes > MAX_RESULT_BYTES {
        if keys.is_empty() {
            keys.push(steps_key.to_string());
        }
        keys.push("output.every, cable.elements".to_string());
        what.push(format!(
            "about {} of result files ({} written steps; the bound is {})",
            bytes_text(size.bytes),
            Sig(size.written),
            bytes_text(MAX_RESULT_BYTES)
        ));
    }
    (!what.is_empty()).then(|| (keys.join(", "), what.join(" and ")))
}

/// `run`'s bound on work: a run above [`MAX_STEPS`] steps or
/// [`MAX_RESULT_BYTES`] of result files (with ParaView's files if `vtk`)
/// is an input error naming the keys and `--allow-large`, unless
/// `allow_large`. Called before anything is written.
pub(crate) fn admit(
    path: &Path,
    sc: &Scenario,
    vtk: bool,
    allow_large: bool,
) -> Result<(), Failure> {
    if allow_large {
        return Ok(());
    }
    let size = size(sc, vtk);
    match size_problem(sc, &size) {
        None => Ok(()),
        Some((keys, what)) => Err(Failure::Input(format!(
            "{}: {keys}: this run would take {what}; shorten the run, write fewer steps \
             (a larger output.every) or pass --allow-large to run it anyway",
            path.display()
        ))),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scenario;

    fn scenario(body: &str) -> Scenario {
        let text = format!(
            "[cable]\nlength = 4.0\nelements = 8\n[material]\nyoungs_modulus = 3.4e9\n\
             density = 1380.0\narea = 3.0e-6\nsecond_moment = 1.25e-13\n{body}"
        );
        scenario::parse(&text, "t.toml", Path::new("t.toml")).expect("valid")
    }

    #[test]
    fn the_size_estimate_counts_every_written_step_and_the_per_step_files() {
        let sc = scenario("[analysis]\ntime_step = 1e-3\nduration = 1.0\n[output]\nevery = 10\n");
        let s = size(&sc, false);
        assert_eq!(s.steps, 1000.0);
        assert_eq!(s.written, 102.0);
        let row = 150.0 + 120.0 * 9.0 + 75.0 * 5.0 * 8.0;
        assert_eq!(s.bytes, 1000.0 * 250.0 + 102.0 * row);
        assert!(size(&sc, true).bytes > s.bytes);
        assert!(size_problem(&sc, &s).is_none());
    }

    #[test]
    fn a_run_above_the_bounds_is_refused_unless_allowed() {
        let sc = scenario("[analysis]\ntime_step = 1e-6\nduration = 200.0\n");
        let refused = admit(Path::new("t.toml"), &sc, false, false);
        match refused {
            Err(Failure::Input(m)) => {
                assert!(
                    m.starts_with("t.toml: analysis.duration, analysis.time_step"),
                    "{m}"
                );
                assert!(
                    m.contains("2e8 steps") && m.contains("--allow-large"),
                    "{m}"
                );
            }
            other => panic!("{other:?}"),
        }
        assert!(admit(Path::new("t.toml"), &sc, false, true).is_ok());
    }

    #[test]
    fn bytes_read_in_words() {
        assert_eq!(bytes_text(4e9), "4 GB");
        assert_eq!(bytes_text(26_400.0), "26.4 kB");
        assert_eq!(bytes_text(5.04e13), "50.4 TB");
        assert_eq!(bytes_text(512.0), "512 bytes");
    }
}
