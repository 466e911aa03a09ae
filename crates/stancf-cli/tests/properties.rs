//! Property-based tests of the command line (issue 11): random scenario
//! files from a grammar of the real keys, and mutations of the shipped
//! examples, are fed to `stancf check` and to a few steps of `stancf run`.
//! Whatever the input:
//!
//! - no panic (no "panicked" on standard error, exit code not 101);
//! - the exit code is 0, 2 or 3 (never 1, nor a signal, nor a hang);
//! - `check` writes nothing, and on exit 0 prints no NaN or inf;
//! - what `check` refuses (exit 2), `run` refuses too;
//! - `run` on exit 2 writes nothing at all (the case folder is unchanged);
//! - `run` on exit 0 or 3 leaves a summary.json that parses (so holds no
//!   NaN or Infinity), no `.partial` file, and CSV files whose every field
//!   is a finite number (or empty) with as many fields as the header.
//!
//! Deterministic and bounded: a fixed RNG seed and case count, no failure
//! persistence file, scenarios of at most a few elements and a few steps
//! (the step count of a valid scenario is clamped; only absurd ones such
//! as 1e-300 s steps are left for the CLI to refuse), every process in its
//! own folder under the system's temp folder and killed after
//! 30 s (a failure, not a hang). A failing case is shrunk and
//! printed whole; its folder is kept.
//!
//! For exploring (not for CI): `STANCF_PROPTEST_CASES=n` runs `n` cases per
//! generator, `STANCF_PROPTEST_SEED=n` another seed,
//! `STANCF_PROPTEST_TIME_LIMIT_S=n` another time limit,
//! `STANCF_PROPTEST_KEEP_GOING=1` prints each failing case's folder and
//! goes on, and `STANCF_PROPTEST_VERBOSE=1` prints every case.

use proptest::prelude::*;
use proptest::sample::select;
use proptest::test_runner::{Config, RngAlgorithm, RngSeed, TestCaseError, TestError, TestRunner};
use std::collections::BTreeMap;
use std::io::Read;
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::Mutex;
use std::time::{Duration, Instant};

const BIN: &str = env!("CARGO_BIN_EXE_stancf");

/// A process still running after this is killed and the case fails
/// (`STANCF_PROPTEST_TIME_LIMIT_S` overrides it).
fn time_limit() -> Duration {
    let s = std::env::var("STANCF_PROPTEST_TIME_LIMIT_S")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(30);
    Duration::from_secs(s)
}

/// Cases per generator (each runs `check` and `run`).
const CASES: u32 = 1000;

/// Valid step counts above this are clamped to a few steps; a scenario
/// asking for more steps than `ABSURD_STEPS` is left as it is: the CLI must
/// refuse it (exit 2), not run it for ever.
const MAX_STEPS: f64 = 16.0;
const ABSURD_STEPS: f64 = 1e10;

// ---------------------------------------------------------------------
// Running the binary

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
/// number or empty.
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
            if f.is_empty() {
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
struct Tally {
    check: BTreeMap<i32, usize>,
    run: BTreeMap<i32, usize>,
}

static CASE: AtomicUsize = AtomicUsize::new(0);

/// Runs `check` and `run` on one scenario text and asserts the properties.
fn exercise(tag: &str, text: &str, tally: &Mutex<Tally>) -> Result<(), String> {
    let n = CASE.fetch_add(1, Ordering::Relaxed);
    let dir = std::env::temp_dir().join(format!(
        "stancf-properties-{}-{tag}-{n}",
        std::process::id()
    ));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    let scenario = dir.join("case.toml");
    std::fs::write(&scenario, text).unwrap();
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
fn property(tag: &str, strategy: impl Strategy<Value = String>, cases: u32) -> (Tally, usize) {
    let tally = Mutex::new(Tally::default());
    let config = config(cases);
    let cases = config.cases as usize;
    let mut runner = TestRunner::new(config);
    let start = Instant::now();
    let result = runner.run(&strategy, |text| {
        exercise(tag, &text, &tally).map_err(TestCaseError::fail)
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

// ---------------------------------------------------------------------
// Bounding the work of a scenario

fn number(v: &toml::Value) -> Option<f64> {
    match v {
        toml::Value::Float(f) => Some(*f),
        toml::Value::Integer(i) => Some(*i as f64),
        _ => None,
    }
}

/// Keeps a valid scenario small: a valid step count above `MAX_STEPS` (but
/// not absurd), more than 64 elements or 20 load steps are brought down.
/// Text that is not TOML, or needs no change, is returned as it is.
fn bound_work(text: String) -> String {
    let Ok(mut doc) = toml::from_str::<toml::Table>(&text) else {
        return text;
    };
    let mut changed = false;
    if let Some(toml::Value::Table(a)) = doc.get_mut("analysis") {
        let dt = a.get("time_step").and_then(number);
        let t = a.get("duration").and_then(number);
        if let (Some(dt), Some(t)) = (dt, t) {
            if dt > 0.0 && t > 0.0 && dt.is_finite() && t.is_finite() {
                let steps = t / dt;
                if steps > MAX_STEPS && steps < ABSURD_STEPS {
                    a.insert("duration".into(), toml::Value::Float(dt * 8.0));
                    changed = true;
                }
            }
        }
        if let Some(toml::Value::Integer(n)) = a.get("load_steps") {
            if (21..=1_000_000).contains(n) {
                a.insert("load_steps".into(), toml::Value::Integer(5));
                changed = true;
            }
        }
    }
    if let Some(toml::Value::Table(c)) = doc.get_mut("cable") {
        if let Some(toml::Value::Integer(n)) = c.get("elements") {
            if (65..=1_000_000).contains(n) {
                c.insert("elements".into(), toml::Value::Integer(8));
                changed = true;
            }
        }
    }
    if changed {
        toml::to_string(&doc).unwrap_or(text)
    } else {
        text
    }
}

// ---------------------------------------------------------------------
// (a) Random scenarios from a grammar of the real keys

/// Values of every kind that a key should not get, or only at its limits.
const WEIRD: &[&str] = &[
    "0",
    "-1",
    "0.0",
    "-0.0",
    "1",
    "2.5",
    "-2.5",
    "1e-300",
    "-1e-300",
    "1e300",
    "-1e300",
    "5e-324",
    "1.7976931348623157e308",
    "inf",
    "-inf",
    "nan",
    "9223372036854775807",
    "-9223372036854775808",
    "4294967296",
    "1000001",
    "17",
    "11",
    "\"\"",
    "\"A\"",
    "\"B\"",
    "\"all\"",
    "\"1e-3\"",
    "\"SAC-4\"",
    "\"dynamic\"",
    "\"gravity\"",
    "\"clamped\"",
    "\"a,b\\\"c\\nd\"",
    "true",
    "false",
    "[]",
    "[0]",
    "[0, 0]",
    "[0, 0, 0]",
    "[1, 2, 3, 4]",
    "[\"x\", 0, 0]",
    "[nan, 0, 0]",
    "[0, inf, 0]",
    "[1e300, 1e300, 1e300]",
    "[1e-300, 0, 0]",
    "[0, 0, -1e300]",
    "[[1, 2, 3]]",
    "[1, \"2\", 3]",
    "{}",
    "{ x = 1 }",
    "1979-05-27T07:32:00Z",
    "07:32:00",
    "0x10",
    "0o7",
    "0b1",
    "[2, 3]",
    "[10, 10, 10]",
    "[0, 11]",
    "[3, 0]",
    "[3, 3, 3, 3]",
    "[-1, 3]",
];

fn weird() -> BoxedStrategy<String> {
    select(WEIRD).prop_map(String::from).boxed()
}

fn f64_literal(v: f64) -> String {
    if v.is_nan() {
        "nan".into()
    } else if v.is_infinite() {
        if v > 0.0 {
            "inf".into()
        } else {
            "-inf".into()
        }
    } else {
        format!("{v:e}")
    }
}

/// Any number, from the whole range of i64 and f64.
fn wide_number() -> BoxedStrategy<String> {
    prop_oneof![
        any::<i64>().prop_map(|i| i.to_string()),
        any::<f64>().prop_map(f64_literal),
        (-330i32..330).prop_map(|e| format!("1e{e}")),
        (-330i32..330).prop_map(|e| format!("-1e{e}")),
    ]
    .boxed()
}

fn pick(values: &'static [&'static str]) -> BoxedStrategy<String> {
    select(values).prop_map(String::from).boxed()
}

fn sane_vector(components: &'static [&'static str]) -> BoxedStrategy<String> {
    prop::array::uniform3(select(components))
        .prop_map(|[a, b, c]| format!("[{a}, {b}, {c}]"))
        .boxed()
}

const SMALL: &[&str] = &[
    "0.0", "0.0", "0.0", "1.0", "-1.0", "0.5", "-9.81", "10.0", "-10.0", "2",
];

/// How values are drawn at a given level of chaos `p` (the chance that a
/// key is missing or gets a value from `WEIRD` or `wide_number`).
#[derive(Clone, Copy, Debug)]
struct Gen {
    p: f64,
}

type Kv = (String, Option<String>);

impl Gen {
    fn weights(self) -> (u32, u32) {
        let bad = (self.p * 10_000.0).round().max(1.0) as u32;
        (10_000 - bad.min(9_000), bad)
    }

    /// A key that a valid scenario has (or that has a default).
    fn key(self, key: &str, sane: BoxedStrategy<String>) -> BoxedStrategy<Kv> {
        let (good, bad) = self.weights();
        let key = key.to_string();
        prop_oneof![
            good => sane.prop_map(Some),
            bad.div_ceil(3) => Just(None),
            bad.div_ceil(3) => weird().prop_map(Some),
            bad.div_ceil(3) => wide_number().prop_map(Some),
        ]
        .prop_map(move |v| (key.clone(), v))
        .boxed()
    }

    /// An optional key: present in about `present` of the cases.
    fn optional(self, key: &str, present: f64, sane: BoxedStrategy<String>) -> BoxedStrategy<Kv> {
        let key_s = key.to_string();
        let w = (present * 100.0).round() as u32;
        prop_oneof![
            100 - w => Just((key_s, None)),
            w.max(1) => self.key(key, sane),
        ]
        .boxed()
    }

    /// Now and then an unknown key (a typo).
    fn stray(self) -> BoxedStrategy<Vec<Kv>> {
        let (good, bad) = self.weights();
        prop_oneof![
            good => Just(Vec::new()),
            bad => (select(&["lenght", "Type", "node ", "velocity_", "elements2", "x"][..]), weird())
                .prop_map(|(k, v)| vec![(format!("{k:?}"), Some(v))]),
        ]
        .boxed()
    }
}

fn render_table(header: &str, keys: &[Kv], out: &mut String) {
    out.push_str(header);
    out.push('\n');
    for (k, v) in keys {
        if let Some(v) = v {
            out.push_str(&format!("{k} = {v}\n"));
        }
    }
    out.push('\n');
}

fn node(with_all: bool) -> BoxedStrategy<String> {
    if with_all {
        pick(&["\"A\"", "\"B\"", "0", "1", "2", "\"all\"", "\"all\""])
    } else {
        pick(&[
            "\"A\"", "\"B\"", "\"A\"", "\"B\"", "\"A\"", "\"B\"", "0", "1", "2",
        ])
    }
}

fn constraint(g: Gen) -> BoxedStrategy<Vec<Kv>> {
    let (good, bad) = g.weights();
    let kind = prop_oneof![
        good => pick(&["\"clamped\"", "\"pinned\"", "\"prescribed\""]),
        bad => weird(),
    ];
    (
        kind,
        g.key("node", node(false)),
        g.optional("fix_curvature", 0.1, pick(&["true", "false"])),
        g.optional("velocity", 0.3, sane_vector(SMALL)),
        g.optional("amplitude", 0.3, sane_vector(&["0.0", "0.01", "-0.02"])),
        g.optional("frequency", 0.3, pick(&["0.0", "2.0", "50.0"])),
        g.optional("phase", 0.2, pick(&["0.0", "1.5707963267948966"])),
        g.stray(),
    )
        .prop_map(|(kind, n, fc, v, a, f, ph, stray)| {
            let mut kv = vec![("type".to_string(), Some(kind.clone())), n];
            match kind.as_str() {
                "\"clamped\"" => kv.push(fc),
                "\"prescribed\"" => kv.extend([v, a, f, ph]),
                "\"pinned\"" => {}
                _ => kv.extend([fc, v]),
            }
            kv.extend(stray);
            kv
        })
        .boxed()
}

fn load(g: Gen) -> BoxedStrategy<Vec<Kv>> {
    let (good, bad) = g.weights();
    let kind = prop_oneof![
        good => pick(&["\"gravity\"", "\"point-force\"", "\"end-moment\"", "\"air-drag\""]),
        bad => weird(),
    ];
    (
        kind,
        g.key("acceleration", sane_vector(&["0.0", "0.0", "-9.81", "1.0"])),
        g.key("node", node(false)),
        g.key("force", sane_vector(&["0.0", "-1.0", "0.5", "100.0"])),
        g.key("moment", sane_vector(&["0.0", "0.0", "1e-4", "-4.25e-4"])),
        (
            g.key("drag_coefficient", pick(&["1.5", "0.0", "1.2"])),
            g.key("fluid_density", pick(&["1.225", "0.0", "1000.0"])),
            g.optional("diameter", 0.3, pick(&["3.7e-3", "1e-2"])),
            g.optional("fluid_velocity", 0.3, sane_vector(&["0.0", "1.0", "-5.0"])),
            g.optional("model", 0.4, pick(&["\"full\"", "\"normal\""])),
            g.optional("tangential_coefficient", 0.2, pick(&["0.0", "0.1"])),
        ),
        g.stray(),
    )
        .prop_map(|(kind, acc, n, f, m, (c, rho, d, u, model, ct), stray)| {
            let mut kv = vec![("type".to_string(), Some(kind.clone()))];
            match kind.as_str() {
                "\"gravity\"" => kv.push(acc),
                "\"point-force\"" => kv.extend([n, f]),
                "\"end-moment\"" => kv.extend([n, m]),
                "\"air-drag\"" => kv.extend([c, rho, d, u, model, ct]),
                _ => kv.extend([acc, n]),
            }
            kv.extend(stray);
            kv
        })
        .boxed()
}

fn initial_velocity(g: Gen) -> BoxedStrategy<Vec<Kv>> {
    (
        g.key("node", node(true)),
        g.optional("velocity", 0.9, sane_vector(SMALL)),
        g.optional(
            "angular_velocity",
            0.3,
            sane_vector(&["0.0", "0.0", "1.0", "-3.0"]),
        ),
        g.optional("center", 0.2, sane_vector(&["0.0", "0.5", "-2.0"])),
        g.stray(),
        prop::bool::weighted(g.p),
    )
        .prop_map(|(n, v, w, c, stray, wild)| {
            // A rotation only with node = "all", unless chaos says otherwise.
            let all = n.1.as_deref() == Some("\"all\"");
            let mut kv = if all || wild {
                vec![n, v, w, c]
            } else {
                vec![n, v]
            };
            kv.extend(stray);
            kv
        })
        .boxed()
}

fn analysis(g: Gen) -> BoxedStrategy<Vec<Kv>> {
    // A valid duration is a few steps; time_step and duration may still
    // each be replaced by anything.
    let steps = (select(&[1e-5, 5e-5, 1e-4, 1e-3, 1e-2][..]), 1u32..=10);
    (
        g.optional(
            "type",
            0.7,
            pick(&["\"dynamic\"", "\"dynamic\"", "\"dynamic\"", "\"static\""]),
        ),
        steps.prop_flat_map(move |(dt, k)| {
            (
                g.key("time_step", Just(f64_literal(dt)).boxed()),
                g.key("duration", Just(f64_literal(dt * k as f64)).boxed()),
            )
        }),
        (
            g.optional("time_layers", 0.2, pick(&["1", "2", "3"])),
            g.optional(
                "quadrature",
                0.3,
                pick(&[
                    "[3, 3]",
                    "[5, 3]",
                    "[2, 2]",
                    "[1, 1]",
                    "[5, 4, 3]",
                    "[10, 10]",
                    "[3, 10, 1]",
                ]),
            ),
            g.optional(
                "solver",
                0.3,
                pick(&["\"newton\"", "\"broyden\"", "\"modified-newton\""]),
            ),
            g.optional("time_scheme", 0.3, pick(&["\"p2\"", "\"galerkin\""])),
            g.optional("tolerance", 0.3, pick(&["1e-10", "1e-8", "1e-6", "1e-14"])),
            g.optional("max_iterations", 0.3, pick(&["50", "1", "3", "200"])),
            g.optional("load_steps", 0.3, pick(&["1", "2", "5"])),
        ),
        (
            g.optional("curvature", 0.2, pick(&["\"paper\"", "\"exact\""])),
            g.optional("axial_strain", 0.2, pick(&["\"green\"", "\"engineering\""])),
            g.optional(
                "constraint_method",
                0.3,
                pick(&["\"multiplier\"", "\"elimination\""]),
            ),
            g.optional("planar_reduction", 0.3, pick(&["true", "false"])),
        ),
        g.stray(),
    )
        .prop_map(
            |(kind, (dt, t), (l, q, s, ts, tol, it, ls), (c, ax, cm, pr), stray)| {
                let mut kv = vec![kind, dt, t, l, q, s, ts, tol, it, ls, c, ax, cm, pr];
                kv.extend(stray);
                kv
            },
        )
        .boxed()
}

/// Whether a section is there: in about `present` of the cases with no
/// chaos, less often with more.
fn section(g: Gen, present: f64) -> BoxedStrategy<bool> {
    let present = (present * (1.0 - g.p)).clamp(0.0, 1.0);
    prop::bool::weighted(present).boxed()
}

fn scenario_with(g: Gen) -> BoxedStrategy<String> {
    let title = g.optional(
        "title",
        0.5,
        select(
            &[
                "plain",
                "with, a comma",
                "quote \" and \\ backslash",
                "é ü 中",
                "",
                "line\nbreak",
            ][..],
        )
        .prop_map(|s| toml::Value::String(s.to_string()).to_string())
        .boxed(),
    );
    let cable = (
        g.key("length", pick(&["0.5", "1.0", "4.0", "2"])),
        g.key("elements", pick(&["1", "2", "3", "4"])),
        g.optional("element", 0.6, pick(&["\"SAC-2\"", "\"SAC-3\""])),
        g.optional("origin", 0.4, sane_vector(&["0.0", "-2.0", "1.5"])),
        g.optional(
            "direction",
            0.4,
            pick(&[
                "[1.0, 0.0, 0.0]",
                "[0.0, 1.0, 0.0]",
                "[0.0, 0.0, 1.0]",
                "[1.0, 1.0, 0.0]",
                "[0.6, 0.0, 0.8]",
            ]),
        ),
        g.stray(),
    )
        .prop_map(|(a, b, c, d, e, stray)| {
            let mut kv = vec![a, b, c, d, e];
            kv.extend(stray);
            kv
        });
    let material = (
        g.key("youngs_modulus", pick(&["3.4e9", "0.91e6", "2.1e11"])),
        g.key("density", pick(&["1380.0", "1202.0", "7850"])),
        g.key("area", pick(&["3.0e-6", "1.075e-5", "1e-4"])),
        g.key("second_moment", pick(&["1.25e-13", "9.15e-12", "1e-9"])),
        g.optional("diameter", 0.3, pick(&["1.95e-3", "3.7e-3"])),
        g.stray(),
    )
        .prop_map(|(a, b, c, d, e, stray)| {
            let mut kv = vec![a, b, c, d, e];
            kv.extend(stray);
            kv
        });
    (
        title,
        (section(g, 0.98), cable),
        (section(g, 0.98), material),
        prop::collection::vec(constraint(g), 0..=2),
        prop::collection::vec(load(g), 0..=3),
        prop::collection::vec(initial_velocity(g), 0..=2),
        (section(g, 0.95), analysis(g)),
        (
            section(g, 0.5),
            g.key("every", pick(&["1", "2", "3", "100"])),
            g.stray(),
        ),
        g.stray(),
    )
        .prop_map(
            move |(
                title,
                (has_cable, cable),
                (has_mat, mat),
                cons,
                loads,
                ivs,
                (has_an, an),
                (has_out, every, ostray),
                top,
            )| {
                let mut s = String::new();
                for (k, v) in [title].iter().chain(&top) {
                    if let Some(v) = v {
                        s.push_str(&format!("{k} = {v}\n"));
                    }
                }
                s.push('\n');
                if has_cable {
                    render_table("[cable]", &cable, &mut s);
                }
                if has_mat {
                    render_table("[material]", &mat, &mut s);
                }
                for c in &cons {
                    render_table("[[constraints]]", c, &mut s);
                }
                for l in &loads {
                    render_table("[[loads]]", l, &mut s);
                }
                for iv in &ivs {
                    render_table("[[initial_velocity]]", iv, &mut s);
                }
                if has_an {
                    render_table("[analysis]", &an, &mut s);
                }
                if has_out {
                    let mut kv = vec![every];
                    kv.extend(ostray);
                    render_table("[output]", &kv, &mut s);
                }
                s
            },
        )
        .prop_map(bound_work)
        .boxed()
}

/// Random scenarios at a random level of chaos: a third of them with every
/// key sane (these reach the solver), the others with some keys missing or
/// given extreme or wrongly typed values.
fn random_scenario() -> BoxedStrategy<String> {
    select(&[0.0, 0.0, 0.0, 0.0, 0.01, 0.03, 0.1, 0.3][..])
        .prop_flat_map(|p| scenario_with(Gen { p }))
        .boxed()
}

// ---------------------------------------------------------------------
// (b) Mutations of the shipped examples

fn examples_dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples")
}

/// The shipped examples, each shortened to a few steps (`duration` set to
/// 4 time steps), with their comments kept.
fn shortened_examples() -> Vec<(String, String)> {
    let mut names: Vec<PathBuf> = std::fs::read_dir(examples_dir())
        .expect("examples/")
        .flatten()
        .map(|e| e.path())
        .filter(|p| p.extension().is_some_and(|e| e == "toml"))
        .collect();
    names.sort();
    assert!(!names.is_empty(), "no examples/*.toml");
    names
        .into_iter()
        .map(|p| {
            let text = std::fs::read_to_string(&p).unwrap();
            let value = |key: &str| -> Option<f64> {
                text.lines()
                    .find(|l| l.trim_start().starts_with(key))
                    .and_then(|l| l.split('=').nth(1))
                    .and_then(|v| v.split('#').next())
                    .and_then(|v| v.trim().parse().ok())
            };
            let short = match value("time_step") {
                Some(dt) => text
                    .lines()
                    .map(|l| {
                        if l.trim_start().starts_with("duration") {
                            format!("duration = {:e}   # shortened to 4 steps", 4.0 * dt)
                        } else {
                            l.to_string()
                        }
                    })
                    .collect::<Vec<_>>()
                    .join("\n"),
                None => text,
            };
            (p.file_name().unwrap().to_string_lossy().into_owned(), short)
        })
        .collect()
}

/// A position in a sequence of any length (taken modulo the length).
#[derive(Clone, Copy, Debug)]
struct Ix(usize);

impl Ix {
    fn index(self, len: usize) -> usize {
        self.0 % len
    }
}

impl Arbitrary for Ix {
    type Parameters = ();
    type Strategy = proptest::strategy::Map<std::ops::Range<usize>, fn(usize) -> Ix>;
    fn arbitrary_with(_: ()) -> Self::Strategy {
        (0..1usize << 20).prop_map(Ix)
    }
}

#[derive(Clone, Debug)]
enum Mutation {
    DeleteLine(Ix),
    DuplicateLine(Ix),
    SwapLines(Ix, Ix),
    FlipChar(Ix, char),
    ScaleNumber(Ix, i32),
    NegateNumber(Ix),
    Truncate(Ix),
    InsertLine(Ix, String),
    ReplaceValue(Ix, String),
}

const INSERTS: &[&str] = &[
    "bogus = 1",
    "[extra]",
    "[cable]",
    "[analysis]",
    "[[loads]]",
    "[[constraints]]",
    "[[initial_velocity]]",
    "type = \"gravity\"",
    "type = \"static\"",
    "type = \"clamped\"",
    "node = \"all\"",
    "node = 2.5",
    "node = -1",
    "node = 99",
    "elements = 1000001",
    "time_layers = 17",
    "time_layers = 2",
    "duration = 1e30",
    "time_step = 1e-300",
    "every = 0",
    "title = \"x,y\"",
    "velocity = [1e300, 0, 0]",
    "angular_velocity = [0, 0, 1e200]",
    "fix_curvature = true",
    "element = \"SAC-3\"",
    "time_scheme = \"galerkin\"",
    "solver = \"broyden\"",
    "solver = \"modified-newton\"",
    "constraint_method = \"elimination\"",
    "planar_reduction = false",
    "quadrature = [1, 1]",
    "quadrature = [2, 3, 1]",
    "max_iterations = 1",
    "tolerance = 1e-300",
    "tolerance = 1e300",
    "area = 1e300",
    "second_moment = 1e-300",
    "length = 1e300",
    "density = 1e-300",
    "youngs_modulus = 1e300",
    "[[constraints]]\ntype = \"clamped\"\nnode = \"B\"",
    "[[constraints]]\ntype = \"prescribed\"\nnode = \"B\"\namplitude = [0, 0.01, 0]\nfrequency = 1e300",
    "[[loads]]\ntype = \"end-moment\"\nnode = \"B\"\nmoment = [1e300, 0, 0]",
    "[[loads]]\ntype = \"point-force\"\nnode = \"B\"\nforce = [0, -1e300, 0]",
    "[[loads]]\ntype = \"air-drag\"\ndrag_coefficient = 1e300\nfluid_density = 1.2",
    "[[initial_velocity]]\nnode = \"all\"\nangular_velocity = [0, 0, 1]",
    "[[initial_velocity]]\nnode = \"B\"\nvelocity = [0, 1e200, 0]",
    "\u{0}",
    "\u{feff}title = \"bom\"",
    "a = \"unterminated",
    "[",
    "=",
    "'''",
];

const FLIPS: &[char] = &[
    '"', '\'', '[', ']', '{', '}', '=', '#', '\n', '.', ',', '-', '+', 'e', 'E', '0', '1', '9',
    ' ', '\t', '\\', '_', 'x', 'A', 'é', '\u{0}', '\u{7f}', '\u{2028}',
];

fn mutation() -> impl Strategy<Value = Mutation> {
    let value = prop_oneof![weird(), wide_number()];
    prop_oneof![
        1 => any::<Ix>().prop_map(Mutation::DeleteLine),
        1 => any::<Ix>().prop_map(Mutation::DuplicateLine),
        1 => (any::<Ix>(), any::<Ix>()).prop_map(|(a, b)| Mutation::SwapLines(a, b)),
        1 => (any::<Ix>(), select(FLIPS)).prop_map(|(i, c)| Mutation::FlipChar(i, c)),
        3 => (any::<Ix>(), select(&[-300, -20, -10, -5, -3, -2, -1, 1, 2, 3, 5, 10, 20, 300][..]))
            .prop_map(|(i, k)| Mutation::ScaleNumber(i, k)),
        1 => any::<Ix>().prop_map(Mutation::NegateNumber),
        1 => any::<Ix>().prop_map(Mutation::Truncate),
        2 => (any::<Ix>(), select(INSERTS)).prop_map(|(i, l)| Mutation::InsertLine(i, l.to_string())),
        2 => (any::<Ix>(), value).prop_map(|(i, v)| Mutation::ReplaceValue(i, v)),
    ]
}

/// The numbers of a text: byte ranges of tokens such as `4`, `-2.0`,
/// `1.25e-13` that follow a space, `[`, `,`, `=` or a line start.
fn number_spans(text: &str) -> Vec<(usize, usize)> {
    let b = text.as_bytes();
    let mut spans = Vec::new();
    let mut i = 0;
    while i < b.len() {
        let starts = (b[i].is_ascii_digit() || b[i] == b'-' || b[i] == b'+')
            && (i == 0 || matches!(b[i - 1], b' ' | b'[' | b',' | b'=' | b'\n' | b'\t'));
        if starts {
            let mut j = i + 1;
            while j < b.len() && (b[j].is_ascii_digit() || b"._eE+-".contains(&b[j])) {
                j += 1;
            }
            if text[i..j].replace('_', "").parse::<f64>().is_ok() {
                spans.push((i, j));
            }
            i = j;
        } else {
            i += 1;
        }
    }
    spans
}

fn apply(text: &str, m: &Mutation) -> String {
    let mut lines: Vec<String> = text.lines().map(String::from).collect();
    let join = |lines: Vec<String>| lines.join("\n") + "\n";
    match m {
        Mutation::DeleteLine(i) if !lines.is_empty() => {
            lines.remove(i.index(lines.len()));
            join(lines)
        }
        Mutation::DuplicateLine(i) if !lines.is_empty() => {
            let k = i.index(lines.len());
            let l = lines[k].clone();
            lines.insert(k, l);
            join(lines)
        }
        Mutation::SwapLines(a, b) if !lines.is_empty() => {
            let (a, b) = (a.index(lines.len()), b.index(lines.len()));
            lines.swap(a, b);
            join(lines)
        }
        Mutation::InsertLine(i, l) => {
            let k = i.index(lines.len() + 1);
            lines.insert(k, l.clone());
            join(lines)
        }
        Mutation::ReplaceValue(i, v) => {
            let with_value: Vec<usize> = (0..lines.len())
                .filter(|&k| lines[k].contains('=') && !lines[k].trim_start().starts_with('#'))
                .collect();
            if with_value.is_empty() {
                return text.to_string();
            }
            let k = with_value[i.index(with_value.len())];
            let key = lines[k].split('=').next().unwrap().to_string();
            lines[k] = format!("{key}= {v}");
            join(lines)
        }
        Mutation::FlipChar(i, c) => {
            let mut chars: Vec<char> = text.chars().collect();
            if chars.is_empty() {
                return c.to_string();
            }
            let k = i.index(chars.len());
            chars[k] = *c;
            chars.into_iter().collect()
        }
        Mutation::Truncate(i) => text
            .chars()
            .take(i.index(text.chars().count() + 1))
            .collect(),
        Mutation::ScaleNumber(i, k) => {
            let spans = number_spans(text);
            if spans.is_empty() {
                return text.to_string();
            }
            let (a, b) = spans[i.index(spans.len())];
            let tok = &text[a..b];
            let integer = !tok.contains(['.', 'e', 'E']);
            let new = if integer && *k > 0 {
                // Stays an integer: may overflow i64 (an error TOML must report).
                format!("{tok}{}", "0".repeat(*k as usize))
            } else {
                let v: f64 = tok.replace('_', "").parse().unwrap();
                f64_literal(v * 10f64.powi(*k))
            };
            format!("{}{new}{}", &text[..a], &text[b..])
        }
        Mutation::NegateNumber(i) => {
            let spans = number_spans(text);
            if spans.is_empty() {
                return text.to_string();
            }
            let (a, b) = spans[i.index(spans.len())];
            let tok = &text[a..b];
            let new = match tok.strip_prefix('-') {
                Some(rest) => rest.to_string(),
                None => format!("-{}", tok.trim_start_matches('+')),
            };
            format!("{}{new}{}", &text[..a], &text[b..])
        }
        _ => text.to_string(),
    }
}

fn mutated_example() -> BoxedStrategy<String> {
    let examples = shortened_examples();
    let texts: Vec<String> = examples.into_iter().map(|(_, t)| t).collect();
    (select(texts), prop::collection::vec(mutation(), 1..=2))
        .prop_map(|(text, ms)| bound_work(ms.iter().fold(text, |t, m| apply(&t, m))))
        .boxed()
}

// ---------------------------------------------------------------------
// The properties

#[test]
fn shipped_examples_shortened_pass_check_and_run_with_clean_results() {
    let tally = Mutex::new(Tally::default());
    for (name, text) in shortened_examples() {
        if let Err(e) = exercise("example", &text, &tally) {
            panic!("{name} (shortened): {e}\n=== scenario ===\n{text}\n=== end ===");
        }
    }
    let tally = tally.into_inner().unwrap();
    let n = shortened_examples().len();
    assert_eq!(
        tally.check.get(&0),
        Some(&n),
        "check exits: {:?}",
        tally.check
    );
    assert_eq!(tally.run.get(&0), Some(&n), "run exits: {:?}", tally.run);
}

/// Minimal scenarios of what the generators found on the way (issue 11):
/// they must keep the properties.
const FINDINGS: &[(&str, &str)] = &[
    (
        "youngs_modulus 5e-324: check printed w_max NaN with no warning",
        "[cable]\nlength = 1.0\nelements = 2\n[material]\nyoungs_modulus = 5e-324\n\
         density = 1380.0\narea = 3.0e-6\nsecond_moment = 1.25e-13\n\
         [analysis]\ntime_step = 1e-5\nduration = 2e-5\n",
    ),
    (
        "length 2.8e18: check printed w_max NaN with no warning",
        "[cable]\nlength = 2805586978562170655\nelements = 2\n[material]\n\
         youngs_modulus = 3.4e9\ndensity = 1380.0\narea = 3.0e-6\nsecond_moment = 1.25e-13\n\
         [analysis]\ntime_step = 1e-5\nduration = 2e-5\n",
    ),
    (
        "static, length 1e-248: exit 1, non-finite result at t = 0",
        "[cable]\nlength = 1e-248\nelements = 2\n[material]\nyoungs_modulus = 3.4e9\n\
         density = 1380.0\narea = 3.0e-6\nsecond_moment = 1.25e-13\n\
         [[constraints]]\ntype = \"clamped\"\nnode = \"A\"\n\
         [[loads]]\ntype = \"end-moment\"\nnode = \"B\"\nmoment = [0.0, 0.0, 2.67e-3]\n\
         [analysis]\ntype = \"static\"\nload_steps = 2\n",
    ),
    (
        "initial velocity 1e301: exit 1, non-finite result at t = 0",
        "[cable]\nlength = 1.0\nelements = 2\n[material]\nyoungs_modulus = 3.4e9\n\
         density = 1380.0\narea = 3.0e-6\nsecond_moment = 1.25e-13\n\
         [[initial_velocity]]\nnode = \"A\"\nvelocity = [0.0, 1e301, 0.0]\n\
         [analysis]\ntime_step = 1e-5\nduration = 2e-5\n",
    ),
    (
        "prescribed frequency 1e300: exit 1, non-finite result at t = 0",
        "[cable]\nlength = 1.0\nelements = 2\n[material]\nyoungs_modulus = 3.4e9\n\
         density = 1380.0\narea = 3.0e-6\nsecond_moment = 1.25e-13\n\
         [[constraints]]\ntype = \"prescribed\"\nnode = \"B\"\n\
         amplitude = [0, 0.01, 0]\nfrequency = 1e300\n\
         [analysis]\ntime_step = 1e-5\nduration = 2e-5\n",
    ),
    (
        "static, length 1e300 and force 1e300: exit 1, non-finite result at t = 0",
        "[cable]\nlength = 1e300\nelements = 2\n[material]\nyoungs_modulus = 3.4e9\n\
         density = 1380.0\narea = 3.0e-6\nsecond_moment = 1.25e-13\n\
         [[constraints]]\ntype = \"clamped\"\nnode = \"A\"\n\
         [[loads]]\ntype = \"point-force\"\nnode = \"B\"\nforce = [0, -1e300, 0]\n\
         [analysis]\ntype = \"static\"\nload_steps = 2\n",
    ),
    (
        "4e10 steps: ran until killed",
        "[cable]\nlength = 1.0\nelements = 2\n[material]\nyoungs_modulus = 3.4e9\n\
         density = 1380.0\narea = 3.0e-6\nsecond_moment = 1.25e-13\n\
         [analysis]\ntime_step = 5e-5\nduration = 2e6\n",
    ),
];

#[test]
fn findings_of_the_generators_never_panic_and_exit_0_2_or_3() {
    let tally = Mutex::new(Tally::default());
    for (what, text) in FINDINGS {
        if let Err(e) = exercise("finding", text, &tally) {
            panic!("{what}: {e}\n=== scenario ===\n{text}\n=== end ===");
        }
    }
}

/// Found by the random generator (seed 1): a one-step Galerkin run with
/// 2-point rules and gravity out of the plane never ends: Newton's residual
/// is below the tolerance but the confirming chord step's increment is not,
/// and the chord steps repeat without counting against max_iterations
/// (crates/stancf/src/solver.rs, `newton`); they now count against the
/// iteration limit.
#[test]
fn a_newton_step_that_cannot_confirm_its_convergence_ends() {
    let text = "[cable]\nlength = 2\nelements = 2\n[material]\nyoungs_modulus = 0.91e6\n\
                density = 1202.0\narea = 1e-4\nsecond_moment = 9.15e-12\n\
                [[loads]]\ntype = \"gravity\"\nacceleration = [0.0, 0.0, 1.0]\n\
                [analysis]\ntime_step = 1e-3\nduration = 1e-3\n\
                time_scheme = \"galerkin\"\nquadrature = [2, 2]\n";
    let tally = Mutex::new(Tally::default());
    if let Err(e) = exercise("chord", text, &tally) {
        panic!("{e}\n=== scenario ===\n{text}\n=== end ===");
    }
}

#[test]
fn random_scenarios_never_panic_and_exit_0_2_or_3() {
    let (tally, cases) = property("random", random_scenario(), CASES);
    let solved: usize = [0, 3].iter().filter_map(|c| tally.run.get(c)).sum();
    assert!(
        solved * 8 >= cases,
        "fewer than an eighth of the random scenarios reached the solver: {tally:?}"
    );
}

#[test]
fn mutated_examples_never_panic_and_exit_0_2_or_3() {
    let (tally, cases) = property("mutated", mutated_example(), CASES);
    let solved: usize = [0, 3].iter().filter_map(|c| tally.run.get(c)).sum();
    assert!(
        solved * 8 >= cases,
        "fewer than an eighth of the mutated examples reached the solver: {tally:?}"
    );
}

#[test]
fn mutations_change_the_text_they_aim_at() {
    // The mutation operators themselves (no process is run).
    let t = "a = 8\nb = [-2.0, 1.25e-13]\nc = \"SAC-2\"\n";
    assert_eq!(number_spans(t).len(), 3, "{:?}", number_spans(t));
    let first = Ix(0);
    assert_eq!(
        apply(t, &Mutation::ScaleNumber(first, 2)),
        t.replace("= 8", "= 800")
    );
    assert_eq!(
        apply(t, &Mutation::NegateNumber(first)),
        t.replace("= 8", "= -8")
    );
    assert_eq!(
        apply(t, &Mutation::DeleteLine(first)),
        "b = [-2.0, 1.25e-13]\nc = \"SAC-2\"\n"
    );
    let long = "[analysis]\ntime_step = 1e-5\nduration = 1.0\n".to_string();
    let bounded: toml::Table = toml::from_str(&bound_work(long)).unwrap();
    assert_eq!(bounded["analysis"]["duration"].as_float(), Some(8e-5));
    let absurd = "[analysis]\ntime_step = 1e-300\nduration = 1.0\n".to_string();
    assert_eq!(bound_work(absurd.clone()), absurd);
}
