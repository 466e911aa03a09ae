//! Helpers of the C library's tests: files of the repository, C strings,
//! the built library and the system C compiler.
#![allow(dead_code)]

use stancf_c::error::STANCF_SUCCESS;
use stancf_c::*;
use std::ffi::{CStr, CString};
use std::path::{Path, PathBuf};
use std::process::Command;

#[path = "../../../stancf-cli/tests/cli/common/scratch_root.rs"]
mod scratch_root;
use scratch_root::scratch_root;

/// A file of the repository.
pub fn repo(path: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../..")
        .join(path)
}

pub fn cstring(path: &Path) -> CString {
    CString::new(path.to_str().unwrap()).unwrap()
}

/// This thread's last error message.
pub fn message() -> String {
    unsafe { CStr::from_ptr(stancf_error_message()) }
        .to_str()
        .unwrap()
        .to_string()
}

/// examples/bridle.toml opened: one coupled point (id 2 at (6, 0, 1)).
pub fn bridle() -> *mut StancfSystem {
    let s = unsafe { stancf_create(cstring(&repo("examples/bridle.toml")).as_ptr()) };
    assert!(!s.is_null(), "{}", message());
    s
}

/// Where the fairlead of the bridle swings: 0.2 m along x over 1 s,
/// a little along y and z.
pub fn swing(t: f64) -> ([f64; 3], [f64; 3]) {
    let w = 2.0 * std::f64::consts::PI;
    let a = [0.2, 0.1, 0.05];
    (
        [
            6.0 + a[0] * (w * t).sin(),
            a[1] * (w * t).sin(),
            1.0 + a[2] * (w * t).sin(),
        ],
        [
            a[0] * w * (w * t).cos(),
            a[1] * w * (w * t).cos(),
            a[2] * w * (w * t).cos(),
        ],
    )
}

/// The folder of the built `libstancf_c.so`: beside the test executable
/// (target/<profile>/deps) or one up (target/<profile>).
pub fn library_dir() -> PathBuf {
    let exe = std::env::current_exe().unwrap();
    let deps = exe.parent().unwrap().to_path_buf();
    for dir in [deps.clone(), deps.parent().unwrap().to_path_buf()] {
        if dir.join("libstancf_c.so").exists() {
            return dir;
        }
    }
    panic!(
        "libstancf_c.so is neither in {} nor one folder up",
        deps.display()
    );
}

/// Compiles C `source` against the header and the library into `exe`
/// with the system C compiler (`cc`, or `$CC`), warnings as errors.
pub fn compile(source: &Path, exe: &Path, standard: &str) {
    let lib = library_dir();
    let cc = std::env::var("CC").unwrap_or_else(|_| "cc".into());
    let out = Command::new(cc)
        .args([
            "-O1",
            "-Wall",
            "-Wextra",
            "-Werror",
            &format!("-std={standard}"),
        ])
        .arg("-I")
        .arg(repo("crates/stancf-capi/include"))
        .arg(source)
        .arg("-L")
        .arg(&lib)
        .arg("-lstancf_c")
        .arg(format!("-Wl,-rpath,{}", lib.display()))
        .arg("-lm")
        .arg("-o")
        .arg(exe)
        .output()
        .expect("the system C compiler runs");
    assert!(
        out.status.success(),
        "{} does not compile: {}",
        source.display(),
        String::from_utf8_lossy(&out.stderr)
    );
}

/// A command running the compiled C program `exe` against the library of
/// [`library_dir`]: its folder first on `LD_LIBRARY_PATH`, which the
/// loader searches before the program's run path (cargo puts
/// `target/release` there, where an older `libstancf_c.so` of `cargo
/// build` may lie).
pub fn c_program(exe: &Path) -> Command {
    let lib = library_dir();
    let path = match std::env::var_os("LD_LIBRARY_PATH") {
        Some(old) => {
            let mut p = lib.into_os_string();
            p.push(":");
            p.push(old);
            p
        }
        None => lib.into_os_string(),
    };
    let mut cmd = Command::new(exe);
    cmd.env("LD_LIBRARY_PATH", path);
    cmd
}

/// A fresh folder for a test's files, in [`scratch_root`] (the folders
/// of ended runs removed).
pub fn scratch(name: &str) -> PathBuf {
    let dir =
        scratch_root("stancf-capi-").join(format!("stancf-capi-{}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// The node positions of line `line` of `s` (3 per node), through
/// `stancf_line_nnodes` and `stancf_line_positions`.
pub fn line_positions(s: *mut StancfSystem, line: u32) -> Vec<f64> {
    let mut n = 0u32;
    assert_eq!(
        unsafe { stancf_line_nnodes(s, line, &mut n) },
        STANCF_SUCCESS
    );
    let mut pos = vec![0.0; 3 * n as usize];
    assert_eq!(
        unsafe { stancf_line_positions(s, line, pos.as_mut_ptr()) },
        STANCF_SUCCESS
    );
    pos
}

/// One `stancf_step` of `s` over `dt` from `*t` with the coupled points
/// held at `x` (at rest): the force it returns; `*t` the time reached.
pub fn step_held(s: *mut StancfSystem, x: &[f64], t: &mut f64, dt: f64) -> Vec<f64> {
    let mut f = vec![0.0; x.len()];
    let mut h = dt;
    let rest = vec![0.0; x.len()];
    let code = unsafe { stancf_step(s, x.as_ptr(), rest.as_ptr(), f.as_mut_ptr(), t, &mut h) };
    assert_eq!(code, STANCF_SUCCESS, "{}", message());
    f
}
