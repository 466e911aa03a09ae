//! Helpers shared by the command-line tests: scratch folders, running the
//! binary, small scenarios, and readers that fail on any malformed or
//! non-finite number.
#![allow(dead_code)]

mod bodies;
mod rods;
mod scratch_root;
mod sweep_tables;
// The properties binary shares this module and uses none of them.
#[allow(unused_imports)]
pub use bodies::*;
#[allow(unused_imports)]
pub use rods::*;
#[allow(unused_imports)]
pub use sweep_tables::*;

use scratch_root::scratch_root;
use std::path::{Path, PathBuf};
use std::process::{Command, Output};
use std::sync::atomic::{AtomicUsize, Ordering};

pub const BIN: &str = env!("CARGO_BIN_EXE_stancf");

/// A scratch folder of its own for each call (the process and a count of
/// calls in the name: the tests of one binary share the process), emptied
/// first, in [`scratch_root`] (the folders of ended runs removed).
pub fn scratch(name: &str) -> PathBuf {
    static CALLS: AtomicUsize = AtomicUsize::new(0);
    let call = CALLS.fetch_add(1, Ordering::Relaxed);
    let d =
        scratch_root("stancf-t-").join(format!("stancf-t-{}-{call}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

pub fn repo_file(rel: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../..")
        .join(rel)
}

/// A copy of the test fixture `fixture` (a file of
/// crates/stancf-cli/tests/fixtures) in `dir` under `name`: its path.
pub fn copy_fixture(dir: &Path, fixture: &str, name: &str) -> PathBuf {
    let to = dir.join(name);
    let from = repo_file(&format!("crates/stancf-cli/tests/fixtures/{fixture}"));
    std::fs::copy(&from, &to).unwrap_or_else(|e| panic!("{from:?}: {e}"));
    to
}

/// Runs `stancf` with `args` to completion.
pub fn stancf(args: &[&str]) -> Output {
    Command::new(BIN).args(args).output().expect("run stancf")
}

/// Standard output and standard error as text.
pub fn text(o: &Output) -> (String, String) {
    (
        String::from_utf8_lossy(&o.stdout).into_owned(),
        String::from_utf8_lossy(&o.stderr).into_owned(),
    )
}

pub fn write_scenario(dir: &Path, name: &str, contents: &str) -> PathBuf {
    let p = dir.join(name);
    std::fs::write(&p, contents).unwrap();
    p
}

/// The paper's transverse impact (example 2: a free 4 m PVC cable, 8
/// SAC-2, struck at both ends), shortened to 40 steps written every 4th.
pub const IMPACT: &str = r#"
title = "test"
[cable]
length = 4.0
elements = 8
element = "SAC-2"
origin = [-2.0, 0.0, 0.0]
direction = [1.0, 0.0, 0.0]
[material]
youngs_modulus = 3.4e9
density = 1380.0
area = 3.0e-6
second_moment = 1.25e-13
[[loads]]
type = "gravity"
acceleration = [0.0, -9.81, 0.0]
[[initial_velocity]]
node = "A"
velocity = [0.0, 10.0, 0.0]
[[initial_velocity]]
node = 8
velocity = [0.0, -10.0, 0.0]
[analysis]
type = "dynamic"
time_step = 5.0e-5
duration = 2.0e-3
quadrature = [3, 3]
[output]
every = 4
"#;

/// The rope line type of the system tests: 10 mm, 0.08 kg/m, EA 2e4 N
/// (a TOML `[[line_types]]` entry named "rope"), with `extra_keys` (TOML
/// lines such as `ba = 20.0`, or "") added to it.
pub fn rope_type(extra_keys: &str) -> String {
    format!(
        "[[line_types]]\nname = \"rope\"\ndiameter = 0.01\nmass_per_length = 0.08\n\
         ea = 2.0e4\n{extra_keys}\n"
    )
}

/// A MoorDyn deck of one rope (10 mm, 0.08 kg/m, EA 2e4 N, EI 0, no
/// damping or hydrodynamic coefficients) of 1 m in 4 segments, from
/// fixed point 1 at (0, 0, -1) to coupled point 2 at (1, 0, -1), in
/// water 50 m deep, dtM 1e-4; `outputs` (channel names, one per line, or
/// "") in its OUTPUTS. Displacing 0.0805 kg/m, the rope is neutrally
/// buoyant to 0.6 %.
pub fn rope_deck(outputs: &str) -> String {
    format!(
        "--- MoorDyn v2 input file ---\nA rope 1 m under the surface\n\
         --- LINE TYPES ---\n\
         TypeName Diam Mass/m EA BA/-zeta EI Cd Ca CdAx CaAx\n\
         (name) (m) (kg/m) (N) (N-s/-) (N-m^2) (-) (-) (-) (-)\n\
         rope 0.01 0.08 2.0e4 0 0 0 0 0 0\n\
         --- POINTS ---\n\
         ID Attachment X Y Z Mass Volume CdA Ca\n\
         (#) (-) (m) (m) (m) (kg) (m^3) (m^2) (-)\n\
         1 Fixed 0.0 0.0 -1.0 0 0 0 0\n\
         2 Coupled 1.0 0.0 -1.0 0 0 0 0\n\
         --- LINES ---\n\
         ID LineType AttachA AttachB UnstrLen NumSegs Outputs\n\
         (#) (name) (#) (#) (m) (-) (-)\n\
         1 rope 1 2 1.0 4 -\n\
         --- OPTIONS ---\n\
         1.0e-4 dtM\n9.81 g\n50 WtrDpth\n\
         --- OUTPUTS ---\n{outputs}END\n--- need this line ---\n"
    )
}

/// A `[[points]]` entry: `id`, `kind` ("fixed", "coupled", "free") and
/// `position`.
pub fn toml_point(id: u32, kind: &str, position: [f64; 3]) -> String {
    format!("[[points]]\nid = {id}\ntype = \"{kind}\"\nposition = {position:?}\n")
}

/// A system of one rope line (type [`rope_type`] with `type_keys`) from
/// fixed point 1 at the origin to point 2 (`kind` at `b`): line `id`,
/// `length` m in `elements` elements, with `line_keys` (TOML lines, or
/// "") added to its `[[lines]]` entry. The caller appends the other
/// sections (`[[motions]]`, `[analysis]`, `[output]`).
pub fn one_rope(
    title: &str,
    type_keys: &str,
    (kind, b): (&str, [f64; 3]),
    (id, length, elements): (u32, f64, usize),
    line_keys: &str,
) -> String {
    format!(
        "title = \"{title}\"\n{}{}{}[[lines]]\nid = {id}\ntype = \"rope\"\n\
         length = {length:?}\nelements = {elements}\na = 1\nb = 2\n{line_keys}\n",
        rope_type(type_keys),
        toml_point(1, "fixed", [0.0; 3]),
        toml_point(2, kind, b),
    )
}

/// A bridle: two ropes (type [`rope_type`] with `type_keys`), 4 m from
/// point 1, fixed at the origin, and 5 m from point 2 (of type `point2`,
/// at [6, 0, 1]), meet at free point 3 with a clump weight of `mass` kg;
/// `line2_keys` (TOML lines, or "") are added to line 2 and `rest` (the
/// `[[motions]]`, `[analysis]` and `[output]` sections) appended.
pub fn bridle_system(
    mass: f64,
    (point2, type_keys, line2_keys): (&str, &str, &str),
    rest: &str,
) -> String {
    format!(
        r#"title = "bridle"
{}{}{}[[points]]
id = 3
type = "free"
position = [2.5, 0.0, -2.5]
mass = {mass}
[[lines]]
id = 1
type = "rope"
length = 4.0
elements = 8
a = 1
b = 3
[[lines]]
id = 2
type = "rope"
length = 5.0
elements = 10
a = 2
b = 3
{line2_keys}
{rest}
"#,
        rope_type(type_keys),
        toml_point(1, "fixed", [0.0; 3]),
        toml_point(2, point2, [6.0, 0.0, 1.0]),
    )
}

/// The paper's free pendulum (4 SAC-2, pinned at A, gravity) with the
/// given title, step and duration: cheap, smooth, and with reactions.
pub fn pendulum(title: &str, time_step: f64, duration: f64, every: usize) -> String {
    format!(
        r#"title = "{title}"
[cable]
length = 0.5
elements = 4
element = "SAC-2"
[material]
youngs_modulus = 0.91e6
density = 1202.0
area = 1.075e-5
second_moment = 9.15e-12
[[constraints]]
type = "pinned"
node = "A"
[[loads]]
type = "gravity"
acceleration = [0.0, -9.81, 0.0]
[analysis]
type = "dynamic"
time_step = {time_step:e}
duration = {duration:e}
[output]
every = {every}
"#
    )
}

/// Parses a CSV file of numbers: its header and rows; fails on a ragged
/// row or any empty, non-numeric or non-finite field.
pub fn read_csv(path: &Path) -> (Vec<String>, Vec<Vec<f64>>) {
    parse_csv(path, false)
}

/// [`read_csv`] for files with optional figures left blank (solver.csv's
/// convergence rate), read as 0.
pub fn read_csv_with_blanks(path: &Path) -> (Vec<String>, Vec<Vec<f64>>) {
    parse_csv(path, true)
}

fn parse_csv(path: &Path, blanks: bool) -> (Vec<String>, Vec<Vec<f64>>) {
    let s = std::fs::read_to_string(path).unwrap_or_else(|e| panic!("{path:?}: {e}"));
    let mut lines = s.lines();
    let header: Vec<String> = lines
        .next()
        .unwrap_or_else(|| panic!("{path:?}: empty"))
        .split(',')
        .map(String::from)
        .collect();
    let rows: Vec<Vec<f64>> = lines
        .map(|l| {
            l.split(',')
                .map(|f| {
                    if blanks && f.is_empty() {
                        return 0.0;
                    }
                    let v: f64 = f
                        .parse()
                        .unwrap_or_else(|_| panic!("{path:?}: bad field {f:?}"));
                    assert!(v.is_finite(), "{path:?}: non-finite {f}");
                    v
                })
                .collect()
        })
        .collect();
    for r in &rows {
        assert_eq!(r.len(), header.len(), "{path:?}: ragged row");
    }
    (header, rows)
}

/// The rows of a CSV file whose `end` column (tensions.csv) is A or B,
/// read as 0 and 1.
pub fn read_tensions(path: &Path) -> Vec<Vec<f64>> {
    let s = std::fs::read_to_string(path).unwrap();
    let mut lines = s.lines();
    assert_eq!(lines.next(), Some("t,line,end,fx,fy,fz,tension"));
    lines
        .map(|l| {
            l.split(',')
                .map(|f| match f {
                    "A" => 0.0,
                    "B" => 1.0,
                    _ => f.parse::<f64>().unwrap(),
                })
                .collect()
        })
        .collect()
}

pub fn read_json(path: &Path) -> serde_json::Value {
    let s = std::fs::read_to_string(path).unwrap_or_else(|e| panic!("{path:?}: {e}"));
    serde_json::from_str(&s).unwrap_or_else(|e| panic!("{path:?}: {e}"))
}

/// The names in a folder, sorted.
pub fn names(dir: &Path) -> Vec<String> {
    let mut v: Vec<String> = std::fs::read_dir(dir)
        .unwrap_or_else(|e| panic!("{dir:?}: {e}"))
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    v.sort();
    v
}

/// `stancf run <scenario> --out <out>` (progress and summary printed).
pub fn run_to(scenario: &Path, out: &Path) -> Output {
    Command::new(BIN)
        .arg("run")
        .arg(scenario)
        .arg("--out")
        .arg(out)
        .output()
        .expect("run stancf")
}

/// `stancf run --quiet <scenario> --out <out>`, with `extra` arguments.
pub fn run_quiet(scenario: &Path, out: &Path, extra: &[&str]) -> Output {
    Command::new(BIN)
        .args(["run", "--quiet"])
        .arg(scenario)
        .arg("--out")
        .arg(out)
        .args(extra)
        .output()
        .expect("run stancf")
}

/// Runs `stancf run` on a scenario and checks the exit code 2, that the
/// message names the file and `needles`, and that no output is written.
pub fn expect_input_error(name: &str, scenario: &str, needles: &[&str]) {
    expect_input_error_beside(name, scenario, &[], needles);
}

/// [`expect_input_error`] with `files` (name, contents) written beside
/// the scenario (files it refers to).
pub fn expect_input_error_beside(
    name: &str,
    scenario: &str,
    files: &[(&str, &str)],
    needles: &[&str],
) {
    let mut needles = needles.to_vec();
    needles.push("bad.toml");
    expect_refusal_beside(name, scenario, files, &needles);
}

/// Runs `stancf run` and `stancf check` on the scenario `bad.toml`
/// with `files` (name, contents) beside it, and checks the exit code 2,
/// that the message names `needles` (a file the scenario refers to may be
/// the one named), and that no output is written.
pub fn expect_refusal_beside(name: &str, scenario: &str, files: &[(&str, &str)], needles: &[&str]) {
    let d = scratch(name);
    for (file, contents) in files {
        std::fs::write(d.join(file), contents).unwrap();
    }
    let sc = write_scenario(&d, "bad.toml", scenario);
    refused_by_check_and_run(&sc, &d.join("never"), needles, &[]);
}

/// `stancf <args>` with its address space limited to 1.5 GB: a command
/// that tried to build a system of millions of elements, or to read a
/// file without end, would abort instead of taking the machine.
pub fn stancf_in_bounded_memory(args: &[&str]) -> Output {
    use std::os::unix::process::CommandExt;
    let mut cmd = Command::new(BIN);
    cmd.args(args);
    // SAFETY: setrlimit(2) in the child before exec, async-signal-safe.
    unsafe {
        cmd.pre_exec(|| {
            let limit = libc::rlimit {
                rlim_cur: 1_500_000_000,
                rlim_max: 1_500_000_000,
            };
            libc::setrlimit(libc::RLIMIT_AS, &limit);
            Ok(())
        });
    }
    cmd.output().expect("run stancf")
}

/// `stancf check <file>` and `stancf run <file> --out <out>`, each in
/// bounded memory, both exit 2 with standard error holding each of
/// `needles` and none of `absent`, and `run` creates no `out`; their
/// standard errors, check's first.
pub fn refused_by_check_and_run(
    file: &Path,
    out: &Path,
    needles: &[&str],
    absent: &[&str],
) -> [String; 2] {
    let file_arg = file.to_str().unwrap();
    let out_arg = out.to_str().unwrap();
    let runs = [
        vec!["check", file_arg],
        vec!["run", file_arg, "--out", out_arg],
    ];
    let errors = runs.map(|args| {
        let o = stancf_in_bounded_memory(&args);
        let (_, err) = text(&o);
        assert_eq!(o.status.code(), Some(2), "{args:?}: {err}");
        for n in needles {
            assert!(err.contains(n), "{args:?}: no {n:?} in {err}");
        }
        for a in absent {
            assert!(!err.contains(a), "{args:?}: {a:?} in {err}");
        }
        err
    });
    assert!(!out.exists(), "{file:?}: an output folder was created");
    errors
}

/// The first sample of every element in stress.csv rows at one time
/// (columns t, s, axial_stress, curvature, element): its s, x_k.
pub fn element_starts(rows: &[Vec<f64>], t: f64) -> Vec<f64> {
    let mut starts = Vec::new();
    for r in rows.iter().filter(|r| r[0] == t) {
        let k = r[4] as usize;
        if starts.len() == k {
            starts.push(r[1]);
        }
    }
    starts
}

/// A PNG file: signature, IHDR size, and a size a real figure has.
pub fn check_png(path: &Path) {
    let b = std::fs::read(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    assert_eq!(&b[..8], b"\x89PNG\r\n\x1a\n", "{}", path.display());
    assert_eq!(&b[12..16], b"IHDR", "{}", path.display());
    let w = u32::from_be_bytes(b[16..20].try_into().unwrap());
    let h = u32::from_be_bytes(b[20..24].try_into().unwrap());
    assert!(
        (600..=2000).contains(&w) && (400..=1500).contains(&h),
        "{w} x {h}"
    );
    assert!(
        b.len() > 10_000 && b.len() < 5_000_000,
        "{}: {} bytes",
        path.display(),
        b.len()
    );
}

/// The values of a `<DataArray ... Name="name" ...>` of a VTK XML file.
pub fn vtk_array(xml: &str, name: &str) -> Vec<f64> {
    let tag = format!("Name=\"{name}\"");
    let start = xml.find(&tag).unwrap_or_else(|| panic!("no array {name}"));
    let open = start + xml[start..].find('>').unwrap() + 1;
    let close = open + xml[open..].find("</DataArray>").unwrap();
    xml[open..close]
        .split_whitespace()
        .map(|v| v.parse::<f64>().unwrap())
        .collect()
}

/// MoorDyn's WD0050_Chain test deck (410 m of chain from an anchor on the
/// bed at x = 400 m to a fairlead at the surface over x = 0, 50 m of
/// water, FrictionCoefficient 0.5), as its tests/Mooring/WD0050_Chain.txt
/// gives it but
/// for `dtM` in place of `cfl` and without its `fileIC`.
pub const WD0050_CHAIN: &str =
    "--------------------- MoorDyn Input File ------------------------------------
MoorDyn input file of the mooring system for FD validation cases
----------------------- LINE TYPES ------------------------------------------
TypeName   Diam    Mass/m     EA         BA/-zeta    EI         Cd     Ca     CdAx    CaAx
(name)     (m)     (kg/m)     (N)        (N-s/-)     (N-m^2)    (-)    (-)    (-)     (-)
chain      0.252   390        1.674e9    -1.0        0          1.37   1.0    0.64    0.0
---------------------- POINT PROPERTIES --------------------------------
ID    Type      X       Y       Z       Mass   Volume  CdA    Ca
(#)   (-)       (m)     (m)     (m)     (kg)   (m^3)   (m^2)  (-)
1     Fixed     400    0.0     -50.0    0      0       0      0
2     Vessel    0.0     0.0     0.0     0      0       0      0
---------------------- LINES ----------------------------------------
ID   LineType   AttachA  AttachB  UnstrLen  NumSegs  LineOutputs
(#)   (name)     (#)      (#)       (m)       (-)     (-)
1     chain      1        2         410       41      -
---------------------- OPTIONS -----------------------------------------
0.001                dtM                  time step
1.0e5                kBot                 bottom stiffness (Pa/m)
1.0e4                cBot                 bottom damping (Pa-s/m)
1025.0               WtrDnsty             water density (kg/m^3)
50                   WtrDpth              water depth (m)
0.5                  FrictionCoefficient  general bottom friction coefficient, as a start (-)
------------------------- need this line -------------------------------------- 
";
