//! What `stancf check` does with a system scenario short of printing,
//! shared by the `deck_parse` and `system_parse` targets: the scenario
//! (`scenario::parse_input`), the element and step bounds a run applies
//! before building anything (`work_bounds::admit_system`), then the
//! system, its static solver and its simulation as `run` builds them
//! (`check_system::prepare`) and the report `check` would print
//! (`check_system::check_system`, which returns it as text).

use stancf_scenario::scenario::{parse_input, Input};
use std::path::PathBuf;
use std::sync::OnceLock;

/// A file named `name` in an empty folder (`stancf-fuzz-empty` in the
/// system's temp folder, made once and never written into): what a
/// scenario refers to beside it (`Currents 1`'s `current_profile.txt`,
/// `system.moordyn`, a motion `file`) is not there, so the scenario is
/// refused without any file being read or written.
pub fn lonely_path(name: &str) -> PathBuf {
    static DIR: OnceLock<PathBuf> = OnceLock::new();
    let dir = DIR.get_or_init(|| {
        let d = std::env::temp_dir().join("stancf-fuzz-empty");
        std::fs::create_dir_all(&d).expect("create the fuzzer's empty folder");
        d
    });
    dir.join(name)
}

/// Parses `text` as the file `name` and, for a system, checks it as
/// `stancf check` does (without `--allow-large`). A single cable is left
/// to the `scenario_parse` target.
pub fn check_system_text(text: &str, name: &str) {
    let path = lonely_path(name);
    let file = path.display().to_string();
    let Ok(Input::System(sc)) = parse_input(text, &file, &path) else {
        return;
    };
    if stancf_scenario::work_bounds::admit_system(&file, &sc, false).is_err() {
        return;
    }
    let _ = stancf_scenario::check_system::check_system(&path, &sc);
}
