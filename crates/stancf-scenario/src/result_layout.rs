//! The layout of a result set: every name a run or a sweep writes into its
//! output folder (docs/interface.md, "Result files", "Systems of lines").
//!
//! A run replaces its output folder whole ([`crate::result_folder`]), so
//! it may only replace a folder that holds nothing but a result set: a
//! folder that holds one foreign entry (a user's file, a subfolder of
//! theirs, a symbolic link, a device) is never replaced. A folder is a
//! result set when
//! - it holds a run's `summary.json` (a JSON object with stancf's
//!   `title` and `analysis`) or a sweep's `sweep.csv` (its header
//!   starting `run,`), and
//! - each of its entries, followed down, is a regular file or folder
//!   named as stancf names them: [`RUN_FILES`], the figures
//!   ([`FIGURES`] as `.png` and `.svg`), `vtk/cable_<k>.vtp` (k of 6 to 9
//!   digits), `lines/<id>/` with [`LINE_FILES`], the `.out` files the
//!   folder's `summary.json` names as its `moordyn_out` (MoorDyn's output
//!   files, named after the deck) and, in a sweep's folder (one
//!   with `sweep.csv`), its `extremes.csv` and `run_<k>/` (k of 4 or 5
//!   digits) holding a run's set.

use std::io;
use std::path::{Path, PathBuf};

/// The files a single cable's or a system's run writes at the top of its
/// folder (each at most once; which ones depends on the run).
pub const RUN_FILES: [&str; 15] = [
    "summary.json",
    "scenario.toml",
    "history.csv",
    "nodes.csv",
    "stress.csv",
    "reactions.csv",
    "solver.csv",
    "convergence.csv",
    "points.csv",
    "tensions.csv",
    "channels.csv",
    "node_loads.csv",
    "bodies.csv",
    "stiffness.csv",
    "cable.pvd",
];

/// The figures `--plot` draws (each as `<name>.png` and `<name>.svg`).
pub const FIGURES: [&str; 6] = [
    "shapes",
    "energy",
    "stress_map",
    "convergence",
    "tensions",
    "curvature",
];

/// The files of a system's line, in `lines/<id>/`.
pub const LINE_FILES: [&str; 3] = ["nodes.csv", "stress.csv", "node_loads.csv"];

/// At most this many entries are looked at (a sweep of 10 000 runs with
/// 100 lines each is far below): a folder with more is not taken for a
/// result set.
const MAX_ENTRIES: usize = 10_000_000;

/// What a folder holds, as a result set or not.
#[derive(Debug, PartialEq, Eq)]
pub enum Contents {
    /// Nothing at all.
    Empty,
    /// A result set of stancf's, and nothing else.
    ResultSet,
    /// Something stancf did not write: the first foreign entry found (its
    /// path) and what makes it foreign.
    Foreign(PathBuf, String),
}

/// What the folder `dir` holds (see the module documentation).
pub fn contents(dir: &Path) -> io::Result<Contents> {
    let mut entries = std::fs::read_dir(dir)?;
    let Some(first) = entries.next() else {
        return Ok(Contents::Empty);
    };
    let sweep = is_sweep_table(&dir.join("sweep.csv"));
    if !(sweep || is_run_summary(&dir.join("summary.json"))) {
        return Ok(Contents::Foreign(
            first?.path(),
            "and neither a summary.json of stancf's (title, analysis) nor a sweep.csv of its: \
             not a result set of stancf's"
                .to_string(),
        ));
    }
    let top = if sweep { Level::Sweep } else { Level::Top };
    let mut seen = 0;
    Ok(match foreign_in(dir, top, &mut seen)? {
        Some((path, why)) => Contents::Foreign(path, why),
        None => Contents::ResultSet,
    })
}

/// Where in a result set a folder sits.
#[derive(Clone, Copy, PartialEq, Eq)]
enum Level {
    /// A run's output folder.
    Top,
    /// A sweep's output folder.
    Sweep,
    /// A sweep's `run_<k>/`.
    SweepRun,
    /// `vtk/`.
    Vtk,
    /// `lines/`.
    Lines,
    /// `lines/<id>/`.
    Line,
}

/// The first entry of `dir` (at `level`) that stancf does not write, and
/// why; None when every entry, followed down, is one of its.
fn foreign_in(dir: &Path, level: Level, seen: &mut usize) -> io::Result<Option<(PathBuf, String)>> {
    let moordyn_out = match level {
        Level::Top | Level::Sweep | Level::SweepRun => moordyn_out_of(&dir.join("summary.json")),
        _ => Vec::new(),
    };
    for entry in std::fs::read_dir(dir)? {
        let entry = entry?;
        *seen += 1;
        let path = entry.path();
        if *seen > MAX_ENTRIES {
            return Ok(Some((path, format!("more than {MAX_ENTRIES} entries"))));
        }
        let kind = entry.file_type()?;
        let name = entry.file_name();
        let Some(name) = name.to_str() else {
            return Ok(Some((path, "a name stancf never writes".into())));
        };
        if kind.is_symlink() {
            return Ok(Some((path, "a symbolic link".into())));
        }
        if kind.is_file() {
            if !is_result_file(level, name) && !moordyn_out.iter().any(|n| n == name) {
                return Ok(Some((path, "a file stancf does not write".into())));
            }
            continue;
        }
        if !kind.is_dir() {
            return Ok(Some((path, "neither a file nor a folder".into())));
        }
        let Some(inner) = folder_level(level, name) else {
            return Ok(Some((path, "a folder stancf does not write".into())));
        };
        if let Some(found) = foreign_in(&path, inner, seen)? {
            return Ok(Some(found));
        }
    }
    Ok(None)
}

/// Whether stancf writes a file `name` in a folder at `level`.
fn is_result_file(level: Level, name: &str) -> bool {
    match level {
        Level::Top | Level::SweepRun => RUN_FILES.contains(&name) || is_figure(name),
        // A sweep's own files; a run's beside its runs' folders when the
        // sweep's folder was a run's before.
        Level::Sweep => {
            ["sweep.csv", "extremes.csv"].contains(&name)
                || RUN_FILES.contains(&name)
                || is_figure(name)
        }
        Level::Vtk => name
            .strip_prefix("cable_")
            .and_then(|r| r.strip_suffix(".vtp"))
            .is_some_and(|k| digits_between(k, 6, 9)),
        Level::Lines => false,
        Level::Line => LINE_FILES.contains(&name),
    }
}

/// `<figure>.png` or `<figure>.svg`.
fn is_figure(name: &str) -> bool {
    let stem = name
        .strip_suffix(".png")
        .or_else(|| name.strip_suffix(".svg"));
    stem.is_some_and(|s| FIGURES.contains(&s))
}

/// The level of a subfolder `name` of a folder at `level`, if stancf
/// writes one of that name there.
fn folder_level(level: Level, name: &str) -> Option<Level> {
    match (level, name) {
        (Level::Top | Level::Sweep | Level::SweepRun, "vtk") => Some(Level::Vtk),
        (Level::Top | Level::Sweep | Level::SweepRun, "lines") => Some(Level::Lines),
        (Level::Sweep, _)
            if name
                .strip_prefix("run_")
                .is_some_and(|k| digits_between(k, 4, 5)) =>
        {
            Some(Level::SweepRun)
        }
        (Level::Lines, _) if is_line_id(name) => Some(Level::Line),
        _ => None,
    }
}

/// A line's id as a folder name: an integer, perhaps negative.
fn is_line_id(name: &str) -> bool {
    all_digits(name.strip_prefix('-').unwrap_or(name))
}

/// `s` is `min` to `max` decimal digits.
fn digits_between(s: &str, min: usize, max: usize) -> bool {
    (min..=max).contains(&s.len()) && all_digits(s)
}

/// A run's `summary.json`: a JSON object (of at most 64 MiB) with a
/// string `title` and an `analysis`, as every run of stancf's writes.
fn is_run_summary(path: &Path) -> bool {
    let Ok(text) = crate::input_file::read_text(path) else {
        return false;
    };
    serde_json::from_str::<serde_json::Value>(&text)
        .is_ok_and(|v| v.get("title").is_some_and(|t| t.is_string()) && v.get("analysis").is_some())
}

/// The `.out` files a run's `summary.json` names (`moordyn_out`, a list
/// of MoorDyn's files): plain file names ending `.out`, not hidden.
fn moordyn_out_of(summary: &Path) -> Vec<String> {
    let Some(value) = is_regular_file(summary)
        .then(|| crate::input_file::read_text(summary).ok())
        .flatten()
        .and_then(|text| serde_json::from_str::<serde_json::Value>(&text).ok())
    else {
        return Vec::new();
    };
    let names = value.get("moordyn_out").and_then(|v| v.as_array());
    names
        .into_iter()
        .flatten()
        .filter_map(|n| n.as_str())
        .filter(|n| !n.contains(['/', '\\']) && !n.starts_with('.') && n.ends_with(".out"))
        .map(str::to_string)
        .collect()
}

/// A sweep's `sweep.csv`: a regular file whose header starts `run,`.
fn is_sweep_table(path: &Path) -> bool {
    use std::io::Read;
    if !is_regular_file(path) {
        return false;
    }
    let mut head = [0u8; 4];
    std::fs::File::open(path)
        .and_then(|mut f| f.read_exact(&mut head))
        .is_ok_and(|()| &head == b"run,")
}

fn all_digits(s: &str) -> bool {
    !s.is_empty() && s.bytes().all(|b| b.is_ascii_digit())
}

fn is_regular_file(path: &Path) -> bool {
    std::fs::symlink_metadata(path).is_ok_and(|m| m.file_type().is_file())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn scratch(name: &str) -> PathBuf {
        let d = std::env::temp_dir().join(format!("stancf-layout-{}-{name}", std::process::id()));
        let _ = std::fs::remove_dir_all(&d);
        std::fs::create_dir_all(&d).unwrap();
        d
    }

    /// The least summary.json a run of stancf's writes.
    const SUMMARY: &str = r#"{"title": "t", "analysis": "static"}"#;

    fn touch(dir: &Path, rel: &str) {
        let p = dir.join(rel);
        std::fs::create_dir_all(p.parent().unwrap()).unwrap();
        std::fs::write(p, "x").unwrap();
    }

    /// The `<deck>.out` a run's summary names is its; another `.out`, or
    /// one a summary names with a path, is foreign.
    #[test]
    fn the_out_file_a_summary_names_is_a_runs_and_no_other() {
        let d = scratch("moordyn-out");
        let named =
            r#"{"title": "t", "analysis": "static", "moordyn_out": ["oc4.out", "oc4_Line1.out"]}"#;
        std::fs::write(d.join("summary.json"), named).unwrap();
        touch(&d, "oc4.out");
        touch(&d, "oc4_Line1.out");
        assert_eq!(contents(&d).unwrap(), Contents::ResultSet);
        touch(&d, "other.out");
        assert!(
            matches!(contents(&d).unwrap(), Contents::Foreign(p, _) if p.ends_with("other.out"))
        );
        std::fs::remove_file(d.join("other.out")).unwrap();
        std::fs::remove_file(d.join("oc4_Line1.out")).unwrap();
        let escaping = r#"{"title": "t", "analysis": "static", "moordyn_out": ["../oc4.out"]}"#;
        std::fs::write(d.join("summary.json"), escaping).unwrap();
        assert!(matches!(contents(&d).unwrap(), Contents::Foreign(p, _) if p.ends_with("oc4.out")));
    }

    #[test]
    fn a_full_system_set_and_a_sweep_of_them_are_result_sets() {
        let d = scratch("sets");
        for f in RUN_FILES {
            touch(&d, f);
        }
        std::fs::write(d.join("summary.json"), SUMMARY).unwrap();
        for f in ["energy.png", "energy.svg", "vtk/cable_000012.vtp"] {
            touch(&d, f);
        }
        for f in LINE_FILES {
            touch(&d, &format!("lines/-3/{f}"));
            touch(&d, &format!("lines/17/{f}"));
        }
        assert_eq!(contents(&d).unwrap(), Contents::ResultSet);
        let sweep = scratch("sweep");
        std::fs::write(sweep.join("sweep.csv"), "run,status\n").unwrap();
        touch(&sweep, "run_0000/summary.json");
        touch(&sweep, "run_0001/lines/1/nodes.csv");
        touch(&sweep, "run_0001/vtk/cable_000000.vtp");
        assert_eq!(contents(&sweep).unwrap(), Contents::ResultSet);
        std::fs::remove_dir_all(&d).unwrap();
        std::fs::remove_dir_all(&sweep).unwrap();
    }

    #[test]
    fn one_foreign_entry_anywhere_makes_a_folder_foreign_and_is_named() {
        for (rel, why) in [
            ("thesis.tex", "a file stancf does not write"),
            ("src/main.rs", "a folder stancf does not write"),
            ("lines/1/notes.txt", "a file stancf does not write"),
            ("lines/a/nodes.csv", "a folder stancf does not write"),
            ("vtk/cable.vtp", "a file stancf does not write"),
            ("run_0001/sweep.csv", "a file stancf does not write"),
            (
                "run_0001/run_0002/summary.json",
                "a folder stancf does not write",
            ),
            ("energy.jpg", "a file stancf does not write"),
            (
                "vtk/cable_0000000000000.vtp",
                "a file stancf does not write",
            ),
            ("run_0001/summary.json", "a folder stancf does not write"),
        ] {
            let d = scratch("foreign");
            // A sweep's folder for the runs' folders, a run's for the rest.
            if rel.starts_with("run_0001/") && rel != "run_0001/summary.json" {
                std::fs::write(d.join("sweep.csv"), "run,status\n").unwrap();
            } else {
                std::fs::write(d.join("summary.json"), SUMMARY).unwrap();
            }
            touch(&d, rel);
            match contents(&d).unwrap() {
                Contents::Foreign(p, w) => {
                    let first = rel.split('/').collect::<Vec<_>>();
                    assert!(p.starts_with(d.join(first[0])), "{rel}: {p:?}");
                    assert_eq!(w, why, "{rel}");
                }
                other => panic!("{rel}: {other:?}"),
            }
            std::fs::remove_dir_all(&d).unwrap();
        }
    }

    #[test]
    fn a_symbolic_link_a_missing_marker_or_a_users_marker_is_foreign() {
        let d = scratch("link");
        std::fs::write(d.join("summary.json"), SUMMARY).unwrap();
        std::os::unix::fs::symlink("/", d.join("nodes.csv")).unwrap();
        assert!(matches!(contents(&d).unwrap(), Contents::Foreign(p, w)
            if p == d.join("nodes.csv") && w == "a symbolic link"));
        std::fs::remove_dir_all(&d).unwrap();
        let d = scratch("marker");
        touch(&d, "history.csv");
        assert!(matches!(contents(&d).unwrap(), Contents::Foreign(p, w)
            if p == d.join("history.csv") && w.contains("neither a summary.json of stancf's")));
        std::fs::remove_dir_all(&d).unwrap();
        // A user's own summary.json or sweep.csv is no marker.
        for (name, text) in [
            ("summary.json", "my summary"),
            ("summary.json", "{}"),
            ("sweep.csv", "user sweep data"),
        ] {
            let d = scratch("user-marker");
            std::fs::write(d.join(name), text).unwrap();
            assert!(
                matches!(contents(&d).unwrap(), Contents::Foreign(..)),
                "{name}: {text}"
            );
            std::fs::remove_dir_all(&d).unwrap();
        }
        let d = scratch("empty");
        assert_eq!(contents(&d).unwrap(), Contents::Empty);
        std::fs::remove_dir_all(&d).unwrap();
    }
}
