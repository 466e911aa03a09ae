//! Running `stancf check` and `stancf run` on one scenario in its own
//! temp folder, each process killed after a time limit, and checking what
//! they leave: exit code 0, 2 or 3 and no panic, nothing written by `check`
//! nor by a `run` that exits 2, and on exit 0 or 3 a summary.json that
//! parses, no `.partial` file and CSV files of finite numbers. A case is
//! a scenario file or a MoorDyn deck and the files beside it that it
//! refers to ([`Case`]). Also the proptest runner (fixed seed and case
//! count) that feeds a generator's cases through these checks.

use crate::common::{scratch, BIN};
use proptest::strategy::Strategy;
use proptest::test_runner::{Config, RngAlgorithm, RngSeed, TestCaseError, TestError, TestRunner};
use std::collections::BTreeMap;
use std::io::Read;
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::Mutex;
use std::time::{Duration, Instant};

/// A process still running after this is killed and the case fails
/// (`STANCF_PROPTEST_TIME_LIMIT_S` overrides it): it catches a run that
/// would not end. The longest legitimate case of the fixed seed is a
/// mutated RodHanging deck (a 450 m rope from the surface piled on the
/// bed) whose static solve fails from both of its seeds, the catenary
/// network's and the deck's positions (docs/method.md §11.6): 22 to 25 s
/// on this 2-core machine, alone.
fn time_limit() -> Duration {
    let s = std::env::var("STANCF_PROPTEST_TIME_LIMIT_S")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(60);
    Duration::from_secs(s)
}

struct Outcome {
    /// None: killed by a signal or by the time limit.
    code: Option<i32>,
    timed_out: bool,
    stdout: String,
    stderr: String,
}

impl Outcome {
    fn describe(&self) -> String {
        let code = match (self.code, self.timed_out) {
            (_, true) => format!("killed after the time limit of {:?}", time_limit()),
            (Some(c), _) => format!("exit {c}"),
            (None, _) => "killed by a signal".to_string(),
        };
        format!(
            "{code}\n--- stdout ---\n{}\n--- stderr ---\n{}",
            clip(&self.stdout),
            clip(&self.stderr)
        )
    }
}

fn clip(s: &str) -> String {
    const MAX: usize = 2000;
    if s.len() <= MAX {
        return s.to_string();
    }
    let mut end = MAX;
    while !s.is_char_boundary(end) {
        end -= 1;
    }
    format!("{}... ({} bytes in all)", &s[..end], s.len())
}

/// Runs `stancf args` in `dir`, killing it after `time_limit()`.
fn stancf(dir: &Path, args: &[&std::ffi::OsStr]) -> Outcome {
    let mut child = Command::new(BIN)
        .args(args)
        .current_dir(dir)
        .env_remove("RUST_BACKTRACE")
        .stdin(Stdio::null())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("start stancf");
    let drain = |mut r: Box<dyn Read + Send>| {
        std::thread::spawn(move || {
            let mut v = Vec::new();
            let _ = r.read_to_end(&mut v);
            String::from_utf8_lossy(&v).into_owned()
        })
    };
    let out = drain(Box::new(child.stdout.take().unwrap()));
    let err = drain(Box::new(child.stderr.take().unwrap()));
    let start = Instant::now();
    let limit = time_limit();
    let mut timed_out = false;
    let status = loop {
        if let Some(s) = child.try_wait().expect("wait for stancf") {
            break s;
        }
        if start.elapsed() > limit {
            timed_out = true;
            let _ = child.kill();
            break child.wait().expect("wait for stancf");
        }
        std::thread::sleep(Duration::from_millis(2));
    };
    Outcome {
        code: if timed_out { None } else { status.code() },
        timed_out,
        stdout: out.join().unwrap_or_default(),
        stderr: err.join().unwrap_or_default(),
    }
}

/// Every file under `dir` (relative path -> contents); empty if absent.
fn snapshot(dir: &Path) -> BTreeMap<PathBuf, Vec<u8>> {
    fn walk(root: &Path, d: &Path, into: &mut BTreeMap<PathBuf, Vec<u8>>) {
        let Ok(entries) = std::fs::read_dir(d) else {
            return;
        };
        for e in entries.flatten() {
            let p = e.path();
            let rel = p.strip_prefix(root).unwrap().to_path_buf();
            if p.is_dir() {
                into.insert(rel.join(""), Vec::new());
                walk(root, &p, into);
            } else {
                into.insert(rel, std::fs::read(&p).unwrap_or_default());
            }
        }
    }
    let mut m = BTreeMap::new();
    walk(dir, dir, &mut m);
    m
}

fn files_under(dir: &Path) -> Vec<PathBuf> {
    snapshot(dir)
        .into_keys()
        .filter(|p| !p.as_os_str().to_string_lossy().ends_with('/'))
        .map(|p| dir.join(p))
        .collect()
}

/// A "NaN" or "inf" word in the text (what a non-finite f64 prints as).
fn non_finite_word(text: &str) -> Option<String> {
    text.split(|c: char| !c.is_ascii_alphanumeric())
        .find(|w| {
            let w = w.to_ascii_lowercase();
            w == "nan" || w == "inf" || w == "infinity"
        })
        .map(|w| w.to_string())
}

/// A CSV result file: a header, then rows of as many fields, each a finite
/// number or empty; the word columns are tensions.csv's `end`, A or B, and
/// stiffness.csv's `row`, the force or moment of the row (fx ... mz).
fn check_csv(path: &Path) -> Result<(), String> {
    let text = std::fs::read_to_string(path).map_err(|e| format!("unreadable: {e}"))?;
    let mut lines = text.lines();
    let header = lines.next().ok_or("empty file (no header)")?;
    let columns = header.split(',').count();
    for (i, line) in lines.enumerate() {
        let fields: Vec<&str> = line.split(',').collect();
        if fields.len() != columns {
            return Err(format!(
                "line {}: {} fields under a header of {columns}: {}",
                i + 2,
                fields.len(),
                clip(line)
            ));
        }
        for (f, name) in fields.iter().zip(header.split(',')) {
            let f = f.trim();
            let word = (name == "end" && (f == "A" || f == "B"))
                || (name == "row" && ["fx", "fy", "fz", "mx", "my", "mz"].contains(&f));
            if f.is_empty() || word {
                continue;
            }
            match f.parse::<f64>() {
                Ok(v) if v.is_finite() => {}
                _ => {
                    return Err(format!(
                        "line {}: {name} = {f:?} is not a finite number",
                        i + 2
                    ))
                }
            }
        }
    }
    Ok(())
}

/// The result folder of a run that exited 0 or 3.
fn check_results(out: &Path) -> Result<(), String> {
    if !out.join("summary.json").is_file() {
        return Err(format!("{}: no summary.json", out.display()));
    }
    for f in files_under(out) {
        let name = f.display().to_string();
        if name.ends_with(".partial") {
            return Err(format!("{name}: a .partial file is left behind"));
        }
        if name.ends_with(".csv") {
            check_csv(&f).map_err(|e| format!("{name}: {e}"))?;
        } else if name.ends_with(".json") {
            let text = std::fs::read_to_string(&f).map_err(|e| format!("{name}: {e}"))?;
            // serde_json refuses NaN and Infinity tokens.
            serde_json::from_str::<serde_json::Value>(&text)
                .map_err(|e| format!("{name}: not valid JSON ({e})"))?;
        }
    }
    Ok(())
}

/// Exit codes seen, for the report and to make sure a generator reaches
/// the solver in a fair share of its cases.
#[derive(Default, Debug)]
pub struct Tally {
    pub check: BTreeMap<i32, usize>,
    pub run: BTreeMap<i32, usize>,
}

/// One input of `check` and `run`: the file they are given (`name`,
/// `text`) and the files beside it that it may refer to (a deck a
/// scenario takes as `system.moordyn`, a motion table, a deck's
/// `current_profile.txt`).
#[derive(Clone, Debug)]
pub struct Case {
    pub name: String,
    pub text: String,
    pub beside: Vec<(String, String)>,
}

impl Case {
    /// A scenario file alone, `case.toml`.
    pub fn toml(text: String) -> Case {
        Case {
            name: "case.toml".into(),
            text,
            beside: Vec::new(),
        }
    }
}

/// The file's text, then each file beside it under a line naming it.
impl std::fmt::Display for Case {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.text)?;
        for (name, text) in &self.beside {
            write!(f, "\n=== beside it, {name} ===\n{text}")?;
        }
        Ok(())
    }
}

static CASE: AtomicUsize = AtomicUsize::new(0);

/// Runs `check` and `run` on one scenario text and asserts the properties.
pub fn exercise(tag: &str, text: &str, tally: &Mutex<Tally>) -> Result<(), String> {
    exercise_case(tag, &Case::toml(text.to_string()), tally)
}

/// Runs `check` and `run` on one case (its files written into a folder of
/// its own) and asserts the properties.
pub fn exercise_case(tag: &str, case: &Case, tally: &Mutex<Tally>) -> Result<(), String> {
    let n = CASE.fetch_add(1, Ordering::Relaxed);
    if let Some(dump) = std::env::var_os("STANCF_PROPTEST_DUMP") {
        // Seeds for the fuzzers (fuzz/README.md): the case's own file.
        let dump = Path::new(&dump).join(tag);
        std::fs::create_dir_all(&dump).unwrap();
        std::fs::write(dump.join(format!("{n}-{}", case.name)), &case.text).unwrap();
    }
    let dir = scratch(&format!("properties-{tag}-{n}"));
    let scenario = dir.join(&case.name);
    std::fs::write(&scenario, &case.text).unwrap();
    for (name, text) in &case.beside {
        std::fs::write(dir.join(name), text).unwrap();
    }
    let result = exercise_in(&dir, &scenario, tally);
    match result {
        Ok(()) => {
            let _ = std::fs::remove_dir_all(&dir);
            Ok(())
        }
        Err(e) => {
            // Keep the scenario, not gigabytes of a run that did not stop.
            let out = dir.join("out");
            let size: u64 = files_under(&out)
                .iter()
                .filter_map(|f| f.metadata().ok())
                .map(|m| m.len())
                .sum();
            if size > 10_000_000 {
                let _ = std::fs::remove_dir_all(&out);
            }
            if std::env::var_os("STANCF_PROPTEST_KEEP_GOING").is_some() {
                eprintln!(
                    "FAILURE {}: {}",
                    dir.display(),
                    e.lines().next().unwrap_or("")
                );
                return Ok(());
            }
            Err(format!("{e}\n(case folder kept: {})", dir.display()))
        }
    }
}

fn exercise_in(dir: &Path, scenario: &Path, tally: &Mutex<Tally>) -> Result<(), String> {
    let sane = |what: &str, o: &Outcome| -> Result<i32, String> {
        if o.stderr.contains("panicked") || o.code == Some(101) {
            return Err(format!("`{what}` panicked: {}", o.describe()));
        }
        match o.code {
            Some(c @ (0 | 2 | 3)) => Ok(c),
            _ => Err(format!(
                "`{what}` must exit 0, 2 or 3, got {}",
                o.describe()
            )),
        }
    };

    // check: validates, prints, writes nothing.
    let before = snapshot(dir);
    let o = stancf(dir, &["check".as_ref(), scenario.as_os_str()]);
    let check = sane("check", &o)?;
    if snapshot(dir) != before {
        return Err(format!("`check` wrote into its folder: {}", o.describe()));
    }
    if check == 0 {
        // The title is the user's text; every other line is a figure.
        let figures: String = o
            .stdout
            .lines()
            .filter(|l| !l.starts_with("title"))
            .collect::<Vec<_>>()
            .join("\n");
        if let Some(w) = non_finite_word(&figures) {
            return Err(format!(
                "`check` exit 0 prints a non-finite figure ({w}) instead of refusing the input: {}",
                o.describe()
            ));
        }
    }

    // run: a few steps into its own folder.
    let out = dir.join("out");
    let o = stancf(
        dir,
        &[
            "run".as_ref(),
            scenario.as_os_str(),
            "--out".as_ref(),
            out.as_os_str(),
            "--quiet".as_ref(),
        ],
    );
    let run = sane("run", &o)?;
    if std::env::var_os("STANCF_PROPTEST_VERBOSE").is_some() {
        eprintln!(
            "--- case {} (check {check}, run {run}) ---\n{}\n>>> {}",
            dir.display(),
            std::fs::read_to_string(scenario).unwrap_or_default(),
            o.stderr.lines().last().unwrap_or("")
        );
    }
    {
        let mut t = tally.lock().unwrap();
        *t.check.entry(check).or_default() += 1;
        *t.run.entry(run).or_default() += 1;
    }
    if check == 2 && run != 2 {
        return Err(format!(
            "`check` refused the scenario (exit 2) but `run` did not: {}",
            o.describe()
        ));
    }
    match run {
        2 => {
            let after = snapshot(dir);
            if after != before {
                let new: Vec<String> = after
                    .keys()
                    .filter(|k| before.get(*k) != after.get(*k))
                    .map(|k| k.display().to_string())
                    .collect();
                return Err(format!(
                    "`run` exit 2 (invalid input) but wrote {new:?}: {}",
                    o.describe()
                ));
            }
        }
        _ => check_results(&out).map_err(|e| format!("`run` exit {run}: {e}: {}", o.describe()))?,
    }
    Ok(())
}

fn config(cases: u32) -> Config {
    let cases = std::env::var("STANCF_PROPTEST_CASES")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(cases);
    Config {
        cases,
        failure_persistence: None,
        rng_algorithm: RngAlgorithm::ChaCha,
        rng_seed: RngSeed::Fixed(
            std::env::var("STANCF_PROPTEST_SEED")
                .ok()
                .and_then(|s| s.parse().ok())
                .unwrap_or(0x5354_414e_4346_0011),
        ),
        max_shrink_iters: 64,
        max_shrink_time: 60_000,
        ..Config::default()
    }
}

/// Runs `cases` scenarios from `strategy` through `exercise`; on a failure
/// panics with the (shrunk) scenario text.
pub fn property(tag: &str, strategy: impl Strategy<Value = String>, cases: u32) -> (Tally, usize) {
    property_cases(tag, strategy.prop_map(Case::toml), cases)
}

/// Runs `cases` cases from `strategy` through `exercise_case`; on a
/// failure panics with the (shrunk) case, its files beside it included.
pub fn property_cases(
    tag: &str,
    strategy: impl Strategy<Value = Case>,
    cases: u32,
) -> (Tally, usize) {
    let tally = Mutex::new(Tally::default());
    let config = config(cases);
    let cases = config.cases as usize;
    let mut runner = TestRunner::new(config);
    let start = Instant::now();
    let result = runner.run(&strategy, |case| {
        exercise_case(tag, &case, &tally).map_err(TestCaseError::fail)
    });
    let tally = tally.into_inner().unwrap();
    eprintln!(
        "{tag}: {:.1} s; check exits {:?}, run exits {:?}",
        start.elapsed().as_secs_f64(),
        tally.check,
        tally.run
    );
    match result {
        Ok(()) => (tally, cases),
        Err(TestError::Fail(reason, text)) => {
            panic!("{reason}\n=== scenario (minimal failing case) ===\n{text}\n=== end ===")
        }
        Err(TestError::Abort(reason)) => panic!("aborted: {reason}"),
    }
}
