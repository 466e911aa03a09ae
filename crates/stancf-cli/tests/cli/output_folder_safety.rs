//! A run never deletes what it did not write (issue 28, items 1 and 15):
//! it replaces its output folder only when the folder holds a result set
//! of stancf's and nothing else, and only when it can delete the old set
//! afterwards. Anything else is exit 2 naming the folder and the foreign
//! entry, with the folder untouched.

use crate::common::*;
use std::path::Path;

/// The bridle deck of the examples, copied into `dir`.
fn bridle_deck(dir: &Path) -> std::path::PathBuf {
    let deck = dir.join("deck.txt");
    std::fs::copy(repo_file("examples/midwater-bridle-moordyn.txt"), &deck).unwrap();
    deck
}

/// A user's project folder: a stray `summary.json`, a thesis and sources.
fn users_project(dir: &Path) -> std::path::PathBuf {
    let proj = dir.join("proj");
    std::fs::create_dir_all(proj.join("src")).unwrap();
    // A summary.json as stancf writes it (copied from a run, say): the
    // folder's other entries still make it a user's.
    std::fs::write(
        proj.join("summary.json"),
        r#"{"title": "copied", "analysis": "static"}"#,
    )
    .unwrap();
    std::fs::write(proj.join("thesis.tex"), "precious").unwrap();
    std::fs::write(proj.join("src/main.c"), "int main;").unwrap();
    proj
}

fn assert_project_intact(proj: &Path) {
    assert_eq!(names(proj), ["src", "summary.json", "thesis.tex"]);
    assert_eq!(
        std::fs::read_to_string(proj.join("thesis.tex")).unwrap(),
        "precious"
    );
    assert_eq!(names(&proj.join("src")), ["main.c"]);
}

#[test]
fn a_users_folder_holding_a_summary_json_is_not_replaced_directly_or_through_a_link() {
    let d = scratch("users-folder");
    let deck = bridle_deck(&d);
    let proj = users_project(&d);
    std::os::unix::fs::symlink(&proj, d.join("link")).unwrap();
    for out in [proj.clone(), d.join("link")] {
        let o = run_quiet(&deck, &out, &[]);
        let (_, err) = text(&o);
        assert_eq!(o.status.code(), Some(2), "{err}");
        // The first foreign entry is named (the order of a folder's
        // entries is the file system's: either of the two).
        assert!(
            err.contains("thesis.tex") || err.contains("src"),
            "no foreign entry named: {err}"
        );
        assert!(err.contains("does not write"), "{err}");
        assert_project_intact(&proj);
    }
    // Nothing was left beside it either.
    assert_eq!(names(&d), ["deck.txt", "link", "proj"]);
    std::fs::remove_dir_all(&d).unwrap();
}

#[test]
fn a_result_set_with_one_foreign_file_deep_inside_is_not_replaced() {
    let d = scratch("deep-foreign");
    let deck = bridle_deck(&d);
    let out = d.join("case");
    assert!(run_quiet(&deck, &out, &["--plot", "--vtk"])
        .status
        .success());
    // Every file of a full system set with figures and ParaView files is
    // one stancf replaces.
    let o = run_quiet(&deck, &out, &["--plot", "--vtk"]);
    assert!(o.status.success(), "{:?}", text(&o));
    let note = out.join("lines/1/notes.txt");
    std::fs::write(&note, "mine").unwrap();
    let o = run_quiet(&deck, &out, &[]);
    let (_, err) = text(&o);
    assert_eq!(o.status.code(), Some(2), "{err}");
    assert!(err.contains("lines/1/notes.txt"), "{err}");
    assert_eq!(std::fs::read_to_string(&note).unwrap(), "mine");
    assert!(out.join("vtk").is_dir() && out.join("energy.png").is_file());
    std::fs::remove_dir_all(&d).unwrap();
}

#[test]
fn a_sweep_folder_is_replaced_by_the_next_sweep_and_a_users_file_in_it_stops_it() {
    let d = scratch("sweep-layout");
    let sc = write_scenario(&d, "p.toml", &pendulum("p", 1e-3, 4e-3, 1));
    let out = d.join("sw");
    let args = |o: &Path| {
        vec![
            "sweep".to_string(),
            sc.display().to_string(),
            "--set".into(),
            "analysis.time_step=1e-3,2e-3".into(),
            "--out".into(),
            o.display().to_string(),
        ]
    };
    let run = |o: &Path| {
        let a = args(o);
        stancf(&a.iter().map(String::as_str).collect::<Vec<_>>())
    };
    assert!(run(&out).status.success());
    let o = run(&out);
    assert!(o.status.success(), "{:?}", text(&o));
    std::fs::write(out.join("run_0001/plot.py"), "mine").unwrap();
    let o = run(&out);
    assert_eq!(o.status.code(), Some(2), "{:?}", text(&o));
    assert!(text(&o).1.contains("run_0001/plot.py"), "{:?}", text(&o));
    assert!(out.join("run_0001/plot.py").is_file());
    std::fs::remove_dir_all(&d).unwrap();
}

#[test]
fn a_read_only_result_folder_is_refused_and_left_as_it_was() {
    use std::os::unix::fs::PermissionsExt;
    let d = scratch("read-only");
    let deck = bridle_deck(&d);
    let out = d.join("case");
    assert!(run_quiet(&deck, &out, &[]).status.success());
    let before = names(&out);
    let lines = out.join("lines");
    for locked in [&out, &lines] {
        std::fs::set_permissions(locked, std::fs::Permissions::from_mode(0o555)).unwrap();
        let o = run_quiet(&deck, &out, &[]);
        let (_, err) = text(&o);
        std::fs::set_permissions(locked, std::fs::Permissions::from_mode(0o755)).unwrap();
        assert_eq!(o.status.code(), Some(2), "{err}");
        assert!(
            err.contains("read-only") && err.contains(&locked.display().to_string()),
            "{err}"
        );
        assert_eq!(names(&out), before);
        // No staging folder or parked set is left beside it.
        assert_eq!(names(&d), ["case", "deck.txt"]);
    }
    std::fs::remove_dir_all(&d).unwrap();
}

#[test]
fn a_dangling_output_link_is_an_input_error_naming_where_it_points() {
    let d = scratch("dangling");
    let deck = bridle_deck(&d);
    let link = d.join("out");
    std::os::unix::fs::symlink(d.join("gone"), &link).unwrap();
    let o = run_quiet(&deck, &link, &[]);
    let (_, err) = text(&o);
    assert_eq!(o.status.code(), Some(2), "{err}");
    assert!(
        err.contains("does not exist") && err.contains("gone"),
        "{err}"
    );
    assert!(!d.join("gone").exists());
    std::fs::remove_dir_all(&d).unwrap();
}
