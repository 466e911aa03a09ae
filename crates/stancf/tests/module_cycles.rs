//! The core's module tree has no import cycle among sibling modules
//! (issue 29): `scripts/module-cycles.py` finds none in `crates/stancf/src`.
//! An edge A -> B is any reference from a file under A to B (`crate::B`,
//! `super::B`, a `use` of B's items); a module and its parent or children
//! do not count.

use std::path::Path;
use std::process::Command;

#[test]
fn the_core_has_no_import_cycle_among_sibling_modules() {
    let crate_dir = Path::new(env!("CARGO_MANIFEST_DIR"));
    let script = crate_dir.join("../../scripts/module-cycles.py");
    let out = Command::new("python3")
        .arg(&script)
        .arg(crate_dir.join("src"))
        .output()
        .expect("python3 runs scripts/module-cycles.py");
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(out.status.success(), "cycles in the core:\n{text}");
    assert!(text.contains("no cycles"), "{text}");
}
