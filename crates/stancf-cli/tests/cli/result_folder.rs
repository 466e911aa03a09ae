//! A result folder is one transaction (issue 11): whatever happens to a run
//! (a second run into the same folder, `kill -9` at any moment, Ctrl-C,
//! SIGTERM, a full disk), its output folder holds one complete set of
//! results, the old or the new, and nothing of an earlier run.

use crate::common::*;
use std::path::{Path, PathBuf};
use std::process::{Child, Command, Stdio};
use std::time::{Duration, Instant};

/// The files of a complete dynamic set of a constrained run (no --vtk).
const DYNAMIC_SET: [&str; 8] = [
    "convergence.csv",
    "history.csv",
    "nodes.csv",
    "reactions.csv",
    "scenario.toml",
    "solver.csv",
    "stress.csv",
    "summary.json",
];

/// Files whose bytes a rerun reproduces (solver.csv and summary.json hold
/// wall times).
const EXACT_FILES: [&str; 6] = [
    "convergence.csv",
    "history.csv",
    "nodes.csv",
    "reactions.csv",
    "scenario.toml",
    "stress.csv",
];

fn spawn_run(scenario: &Path, out: &Path) -> Child {
    Command::new(BIN)
        .args(["run", "--quiet"])
        .arg(scenario)
        .arg("--out")
        .arg(out)
        .stdout(Stdio::null())
        .stderr(Stdio::piped())
        .spawn()
        .expect("spawn stancf")
}

fn signal(child: &Child, sig: i32) {
    // SAFETY: kill(2) on our own child's pid.
    let rc = unsafe { libc::kill(child.id() as libc::pid_t, sig) };
    assert_eq!(rc, 0, "kill failed");
}

/// Waits (up to a minute) until `ready` holds.
fn wait_for(what: &str, ready: impl Fn() -> bool) {
    let start = Instant::now();
    while !ready() {
        assert!(
            start.elapsed() < Duration::from_secs(60),
            "timed out waiting for {what}"
        );
        std::thread::sleep(Duration::from_millis(5));
    }
}

/// The staging folder of a run into `target`, once it holds a history
/// file with at least `bytes` bytes (the run is stepping).
fn staging_with_history(target: &Path, bytes: u64) -> Option<PathBuf> {
    let parent = target.parent().unwrap();
    let prefix = format!(".{}.stancf-", target.file_name()?.to_string_lossy());
    std::fs::read_dir(parent).ok()?.flatten().find_map(|e| {
        let name = e.file_name().to_string_lossy().into_owned();
        let partial = e.path().join("history.csv.partial");
        (name.starts_with(&prefix) && std::fs::metadata(&partial).is_ok_and(|m| m.len() >= bytes))
            .then(|| e.path())
    })
}

/// Runs `scenario` into `target`, sends SIGINT once it is stepping (its
/// history holds 4 kB) and checks exit code 130; its standard error.
fn interrupted_mid_run(scenario: &Path, target: &Path) -> String {
    let child = spawn_run(scenario, target);
    wait_for("the run to step", || {
        staging_with_history(target, 4096).is_some()
    });
    signal(&child, libc::SIGINT);
    let out = child.wait_with_output().unwrap();
    let err = String::from_utf8_lossy(&out.stderr).into_owned();
    assert_eq!(out.status.code(), Some(130), "{err}");
    err
}

/// Asserts that `dir` holds a valid set: every CSV file parses with finite
/// numbers, the last history row is the summary's time, the final nodes
/// are the summary's, and the history has one row per written step.
fn assert_valid_set(dir: &Path) -> serde_json::Value {
    let summary = read_json(&dir.join("summary.json"));
    let (_, history) = read_csv(&dir.join("history.csv"));
    let (_, nodes) = read_csv(&dir.join("nodes.csv"));
    read_csv(&dir.join("stress.csv"));
    read_csv_with_blanks(&dir.join("solver.csv"));
    let t_last = history.last().unwrap()[0];
    assert_eq!(t_last, summary["time"].as_f64().unwrap(), "{dir:?}");
    let final_nodes: Vec<&Vec<f64>> = nodes.iter().filter(|r| r[0] == t_last).collect();
    let expected = summary["nodes_final"].as_array().unwrap();
    assert_eq!(final_nodes.len(), expected.len());
    for (row, node) in final_nodes.iter().zip(expected) {
        for c in 0..3 {
            assert_eq!(row[2 + c], node[c].as_f64().unwrap(), "{dir:?}");
        }
    }
    summary
}

/// Asserts that `target` is exactly one of the complete reference sets
/// (same files, same bytes where a rerun reproduces them); its index.
fn assert_one_complete_set(target: &Path, references: &[PathBuf]) -> usize {
    assert_eq!(names(target), DYNAMIC_SET, "{target:?}");
    let title = read_json(&target.join("summary.json"))["title"].clone();
    let k = references
        .iter()
        .position(|r| read_json(&r.join("summary.json"))["title"] == title)
        .unwrap_or_else(|| panic!("{target:?}: a set of neither reference ({title})"));
    for f in EXACT_FILES {
        assert!(
            std::fs::read(target.join(f)).unwrap() == std::fs::read(references[k].join(f)).unwrap(),
            "{target:?}/{f} differs from the complete set {:?}",
            references[k]
        );
    }
    k
}

#[test]
fn kill_9_at_any_moment_leaves_the_old_or_the_new_complete_set() {
    let d = scratch("kill9");
    let a = write_scenario(&d, "a.toml", &pendulum("set A", 1e-4, 0.15, 1));
    let b = write_scenario(&d, "b.toml", &pendulum("set B", 1e-4, 0.1, 1));
    let references = [d.join("ref-a"), d.join("ref-b")];
    let start = Instant::now();
    for (sc, r) in [&a, &b].iter().zip(&references) {
        let o = run_quiet(sc, r, &[]);
        assert!(o.status.success(), "{:?}", text(&o));
    }
    // The span the kills are spread over: a little more than one run.
    let span = start.elapsed().as_secs_f64() * 0.5 * 1.3;
    let root = d.join("k");
    let target = root.join("case");
    let o = run_quiet(&a, &target, &[]);
    assert!(o.status.success());
    // A fixed pseudo-random sequence of moments (the claim holds at every
    // moment, so which ones the machine's speed makes them is immaterial).
    let mut seed: u64 = 0x2545_f491_4f6c_dd1d;
    let mut seen = [0usize; 2];
    for i in 0..50 {
        seed ^= seed << 13;
        seed ^= seed >> 7;
        seed ^= seed << 17;
        let moment = (seed % 10_000) as f64 / 10_000.0 * span;
        let mut child = spawn_run(if i % 2 == 0 { &b } else { &a }, &target);
        std::thread::sleep(Duration::from_secs_f64(moment));
        signal(&child, libc::SIGKILL);
        let _ = child.wait();
        seen[assert_one_complete_set(&target, &references)] += 1;
    }
    // What killed runs left beside the target goes with the next run.
    let o = run_quiet(&a, &target, &[]);
    assert!(o.status.success(), "{:?}", text(&o));
    assert_eq!(names(&root), ["case"]);
    assert_eq!(assert_one_complete_set(&target, &references), 0);
    eprintln!(
        "after the 50 kills the folder held set A {} times, set B {}",
        seen[0], seen[1]
    );
    std::fs::remove_dir_all(&d).unwrap();
}

#[test]
fn a_second_run_into_a_folder_in_use_is_refused_and_the_first_keeps_its_results() {
    let d = scratch("concurrent");
    // A million steps, long enough to be running for as long as the test
    // needs it (and within the bounds on work); it is ended by SIGTERM,
    // which must leave its results valid.
    let long = write_scenario(&d, "long.toml", &pendulum("first", 1e-4, 1e2, 10));
    let short = write_scenario(&d, "short.toml", &pendulum("second", 1e-4, 0.01, 1));
    let target = d.join("case");
    let mut first = spawn_run(&long, &target);
    wait_for("the first run to step", || {
        staging_with_history(&target, 4096).is_some()
    });
    let o = run_to(&short, &target);
    let (_, err) = text(&o);
    assert_eq!(o.status.code(), Some(2), "{err}");
    assert!(err.contains(target.to_str().unwrap()), "{err}");
    assert!(err.contains("another stancf run"), "{err}");
    signal(&first, libc::SIGTERM);
    let status = first.wait().unwrap();
    assert_eq!(status.code(), Some(143));
    let summary = assert_valid_set(&target);
    assert_eq!(summary["title"], "first");
    assert_eq!(summary["interrupted"], true);
    assert_eq!(names(&target), DYNAMIC_SET);
    assert_eq!(names(&d), ["case", "long.toml", "short.toml"]);
    std::fs::remove_dir_all(&d).unwrap();
}

#[test]
fn ctrl_c_mid_run_writes_a_valid_partial_set_marked_interrupted() {
    let d = scratch("sigint");
    let long = write_scenario(&d, "long.toml", &pendulum("long", 1e-4, 1e2, 7));
    let target = d.join("case");
    // An older complete set, replaced by the interrupted run's.
    let old = write_scenario(&d, "old.toml", &pendulum("old", 1e-4, 0.01, 1));
    let o = run_to(&old, &target);
    assert!(o.status.success());
    let err = interrupted_mid_run(&long, &target);
    assert!(err.contains("interrupted"), "{err}");
    let summary = assert_valid_set(&target);
    assert_eq!(summary["title"], "long");
    assert_eq!(summary["interrupted"], true);
    assert_eq!(summary["converged"], true);
    let t = summary["time"].as_f64().unwrap();
    assert!(t > 0.0 && t < 1e2, "{t}");
    // Every converged step is kept: the last row is the last step even
    // where output.every = 7 skips it.
    let steps = summary["steps"].as_u64().unwrap();
    assert!(
        (t - steps as f64 * 1e-4).abs() < 1e-9,
        "{t} vs {steps} steps"
    );
    std::fs::remove_dir_all(&d).unwrap();
}

/// A system's summary says it was interrupted, as a single cable's does
/// (docs/interface.md, "Result folders, interruptions and exit codes").
#[test]
fn ctrl_c_mid_system_run_marks_its_summary_interrupted() {
    let d = scratch("sigint-system");
    let long = format!(
        "{}[analysis]\ntype = \"dynamic\"\ntime_step = 1e-4\nduration = 100.0\n\
         [output]\nevery = 7\n",
        one_rope("long", "", ("fixed", [4.0, 0.0, 0.0]), (1, 4.0, 12), "")
    );
    let long = write_scenario(&d, "long.toml", &long);
    let target = d.join("case");
    interrupted_mid_run(&long, &target);
    let summary = read_json(&target.join("summary.json"));
    assert_eq!(summary["interrupted"], true, "{summary}");
    assert_eq!(summary["error"], "interrupted");
    let t = summary["t_final"].as_f64().unwrap();
    assert!(t > 0.0 && t < 1e2, "{t}");
    std::fs::remove_dir_all(&d).unwrap();
}

/// A file a user puts into the output folder while a run writes is kept
/// (issue 28): the folder is checked again before it is swapped out, and
/// the new results go beside it under a name of their own.
#[test]
fn a_file_added_to_the_output_folder_during_a_run_is_kept() {
    let d = scratch("added-during");
    let target = d.join("case");
    let old = write_scenario(&d, "old.toml", &pendulum("old", 1e-4, 0.01, 1));
    assert!(run_to(&old, &target).status.success());
    let long = write_scenario(&d, "long.toml", &pendulum("long", 1e-4, 0.4, 7));
    let child = spawn_run(&long, &target);
    wait_for("the run to step", || {
        staging_with_history(&target, 4096).is_some()
    });
    std::fs::write(target.join("notes.txt"), "mine").unwrap();
    let out = child.wait_with_output().unwrap();
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(1), "{err}");
    assert!(
        err.contains("notes.txt") && err.contains("new-results"),
        "{err}"
    );
    assert_eq!(
        std::fs::read_to_string(target.join("notes.txt")).unwrap(),
        "mine"
    );
    // The old set is as it was, the new one whole beside it.
    assert_eq!(read_json(&target.join("summary.json"))["title"], "old");
    let kept = names(&d)
        .into_iter()
        .find(|n| n.starts_with("case.new-results-"))
        .unwrap_or_else(|| panic!("no new results beside: {:?}", names(&d)));
    assert_eq!(
        read_json(&d.join(kept).join("summary.json"))["title"],
        "long"
    );
    std::fs::remove_dir_all(&d).unwrap();
}

#[test]
fn a_new_run_leaves_nothing_of_an_older_one_in_its_folder() {
    let d = scratch("stale");
    let target = d.join("case");
    let out = target.to_str().unwrap();
    let pinned = write_scenario(&d, "pinned.toml", &pendulum("pinned", 1e-4, 0.01, 1));
    let o = stancf(&[
        "run",
        "--quiet",
        "--vtk",
        pinned.to_str().unwrap(),
        "--out",
        out,
    ]);
    assert!(o.status.success(), "{:?}", text(&o));
    assert!(target.join("reactions.csv").exists() && target.join("vtk").is_dir());
    // The same cable without its pin: no reactions, no ParaView files.
    let free = pendulum("free", 1e-4, 0.01, 1)
        .replace("[[constraints]]\ntype = \"pinned\"\nnode = \"A\"\n", "");
    let free = write_scenario(&d, "free.toml", &free);
    let o = stancf(&["run", "--quiet", free.to_str().unwrap(), "--out", out]);
    assert!(o.status.success(), "{:?}", text(&o));
    let expected: Vec<&str> = DYNAMIC_SET
        .iter()
        .copied()
        .filter(|f| *f != "reactions.csv")
        .collect();
    assert_eq!(names(&target), expected);
    // A static run with its figures over a dynamic one: no solver files and
    // no convergence figure drawn from a stale convergence.csv.
    let o = stancf(&[
        "run",
        "--quiet",
        "--plot",
        repo_file("examples/circle-bending.toml").to_str().unwrap(),
        "--out",
        out,
    ]);
    assert!(o.status.success(), "{:?}", text(&o));
    let listing = names(&target);
    assert!(listing.iter().any(|n| n == "shapes.png"), "{listing:?}");
    for stale in ["solver.csv", "convergence.csv", "convergence.png"] {
        assert!(
            !listing.iter().any(|n| n == stale),
            "{stale} in {listing:?}"
        );
    }
    assert_eq!(names(&d), ["case", "free.toml", "pinned.toml"]);
    std::fs::remove_dir_all(&d).unwrap();
}

#[test]
fn the_default_output_folder_is_always_a_folder_of_its_own_under_out() {
    let d = scratch("default-out");
    let sc = pendulum("x", 1e-4, 1e-3, 1);
    for (file, folder) in [
        ("..toml", "run"),
        (".hidden.toml", "hidden"),
        ("a b;c.toml", "a_b_c"),
    ] {
        write_scenario(&d, file, &sc);
        let o = Command::new(BIN)
            .current_dir(&d)
            .args(["run", "--quiet", &format!("./{file}")])
            .output()
            .unwrap();
        assert!(o.status.success(), "{file}: {:?}", text(&o));
        assert!(
            d.join("out").join(folder).join("summary.json").is_file(),
            "{file}"
        );
    }
    assert_eq!(names(&d), ["..toml", ".hidden.toml", "a b;c.toml", "out"]);
    assert_eq!(names(&d.join("out")), ["a_b_c", "hidden", "run"]);
    std::fs::remove_dir_all(&d).unwrap();
}

#[test]
fn an_output_folder_of_a_users_files_or_a_dot_is_refused_untouched() {
    let d = scratch("user-folder");
    let sc = write_scenario(&d, "p.toml", &pendulum("x", 1e-4, 1e-3, 1));
    let mine = d.join("mine");
    std::fs::create_dir(&mine).unwrap();
    std::fs::write(mine.join("notes.txt"), "precious").unwrap();
    for out in [mine.to_str().unwrap(), ".", ".."] {
        let o = Command::new(BIN)
            .current_dir(&d)
            .args(["run", sc.to_str().unwrap(), "--out", out])
            .output()
            .unwrap();
        let (_, err) = text(&o);
        assert_eq!(o.status.code(), Some(2), "{out}: {err}");
        assert!(err.contains(out), "{err}");
    }
    assert_eq!(
        std::fs::read_to_string(mine.join("notes.txt")).unwrap(),
        "precious"
    );
    assert_eq!(names(&d), ["mine", "p.toml"]);
    assert_eq!(names(&mine), ["notes.txt"]);
    std::fs::remove_dir_all(&d).unwrap();
}

#[test]
fn a_full_disk_leaves_the_old_set_and_frees_what_it_wrote() {
    use std::os::unix::process::CommandExt;
    let d = scratch("disk-full");
    let target = d.join("case");
    let out = target.to_str().unwrap();
    let old = write_scenario(&d, "old.toml", &pendulum("old", 1e-4, 0.01, 1));
    let o = stancf(&["run", "--quiet", old.to_str().unwrap(), "--out", out]);
    assert!(o.status.success());
    let before: Vec<(String, Vec<u8>)> = names(&target)
        .into_iter()
        .map(|n| (n.clone(), std::fs::read(target.join(&n)).unwrap()))
        .collect();
    // nodes.csv of this run passes 64 KiB: the file-size limit makes the
    // write fail as a full disk does (EFBIG instead of ENOSPC).
    let big = write_scenario(&d, "big.toml", &pendulum("big", 1e-4, 0.2, 1));
    let mut cmd = Command::new(BIN);
    cmd.args(["run", "--quiet", big.to_str().unwrap(), "--out", out]);
    // SAFETY: only async-signal-safe calls between fork and exec.
    unsafe {
        cmd.pre_exec(|| {
            libc::signal(libc::SIGXFSZ, libc::SIG_IGN);
            let limit = libc::rlimit {
                rlim_cur: 64 * 1024,
                rlim_max: 64 * 1024,
            };
            libc::setrlimit(libc::RLIMIT_FSIZE, &limit);
            Ok(())
        });
    }
    let o = cmd.output().unwrap();
    let (_, err) = text(&o);
    assert_eq!(o.status.code(), Some(1), "{err}");
    assert!(
        err.contains("cannot write results") && err.contains(out),
        "{err}"
    );
    let after: Vec<(String, Vec<u8>)> = names(&target)
        .into_iter()
        .map(|n| (n.clone(), std::fs::read(target.join(&n)).unwrap()))
        .collect();
    assert!(before == after, "the old set changed");
    assert_eq!(names(&d), ["big.toml", "case", "old.toml"]);
    std::fs::remove_dir_all(&d).unwrap();
}
