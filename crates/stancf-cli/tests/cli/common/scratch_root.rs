//! Where the tests' scratch folders go, shared by the CLI's and the C
//! library's tests (the C tests include this file by its path).

use std::path::{Path, PathBuf};

/// Cargo's folder for integration tests' files (inside target/), from
/// which, the first time in a process, the folders named
/// `<prefix><pid>-...` of earlier runs whose process has ended are
/// removed (a run leaves some 500 behind; in the system's temp folder
/// they used to pile up by the tens of thousands). Name a folder
/// `<prefix><this process's id>-...` for it to be removed so.
pub fn scratch_root(prefix: &str) -> PathBuf {
    static CLEANED: std::sync::Once = std::sync::Once::new();
    let root = PathBuf::from(env!("CARGO_TARGET_TMPDIR"));
    CLEANED.call_once(|| remove_ended_runs(&root, prefix));
    root
}

/// Removes the folders in `root` named `<prefix><pid>-...` whose process
/// has ended (where the system says which have: /proc).
fn remove_ended_runs(root: &Path, prefix: &str) {
    if !Path::new("/proc/self").exists() {
        return;
    }
    let Ok(entries) = std::fs::read_dir(root) else {
        return;
    };
    for entry in entries.flatten() {
        let name = entry.file_name().to_string_lossy().into_owned();
        let Some(pid) = name
            .strip_prefix(prefix)
            .and_then(|rest| rest.split('-').next())
        else {
            continue;
        };
        let ended = pid
            .parse::<u32>()
            .is_ok_and(|p| p != std::process::id() && !Path::new(&format!("/proc/{p}")).exists());
        if ended {
            let _ = std::fs::remove_dir_all(entry.path());
        }
    }
}
