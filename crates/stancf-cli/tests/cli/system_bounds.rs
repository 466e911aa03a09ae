//! A system's work is bounded before anything of it is built (issue 28,
//! items 2 and 3): `check` applies the bounds `run` applies, so that it
//! never passes what `run` refuses, and a deck's element counts are
//! summed without wrapping around. Each refusal is exit 2 naming the
//! deck line (or the scenario key) and what to do, in bounded memory.

use crate::common::*;
use std::path::{Path, PathBuf};

/// The bridle deck of the examples with line 1's NumSegs set to `segs`.
fn bridle_with_segments(dir: &Path, segs: &str) -> PathBuf {
    let text = std::fs::read_to_string(repo_file("examples/midwater-bridle-moordyn.txt")).unwrap();
    let row = "1   wire      1        3        46.0      20 ";
    assert!(text.contains(row));
    let deck = dir.join(format!("deck-{}.txt", segs.len()));
    std::fs::write(
        &deck,
        text.replace(
            row,
            &format!("1   wire      1        3        46.0      {segs} "),
        ),
    )
    .unwrap();
    deck
}

/// `check` and `run` both refuse with exit 2 and the same message, which
/// holds `needles`, in bounded memory; `run` writes nothing.
fn both_refuse(dir: &Path, file: &Path, needles: &[&str]) -> String {
    let [check, run] = refused_by_check_and_run(file, &dir.join("out"), needles, &[]);
    assert_eq!(check, run);
    check
}

#[test]
fn numsegs_past_any_integer_is_refused_by_its_deck_line_not_a_panic() {
    let d = scratch("numsegs-huge");
    for segs in [
        "18446744073709551615",
        "18446744073709551616",
        "10000000",
        "1000001",
    ] {
        let deck = bridle_with_segments(&d, segs);
        both_refuse(
            &d,
            &deck,
            &[
                "line 18: NumSegs of line 1",
                segs,
                "above the 1000000 segments a line may have",
            ],
        );
    }
    std::fs::remove_dir_all(&d).unwrap();
}

#[test]
fn check_refuses_a_system_beyond_the_element_bound_as_run_does_and_allows_it_on_request() {
    let d = scratch("numsegs-large");
    let deck = bridle_with_segments(&d, "1000000");
    both_refuse(
        &d,
        &deck,
        &[
            "line 18: NumSegs",
            "1000024 elements in all",
            "above the 2000",
            "--allow-large",
        ],
    );
    // With --allow-large the hard bound still holds, before building.
    let o = stancf_in_bounded_memory(&["check", deck.to_str().unwrap(), "--allow-large"]);
    let (_, err) = text(&o);
    assert_eq!(o.status.code(), Some(2), "{err}");
    assert!(err.contains("above the 1000000 a system may have"), "{err}");
    // A system between the two bounds is checked when allowed.
    let deck = bridle_with_segments(&d, "2000");
    both_refuse(&d, &deck, &["2024 elements in all"]);
    let o = stancf(&["check", deck.to_str().unwrap(), "--allow-large"]);
    let (out, err) = text(&o);
    assert!(o.status.success(), "{err}");
    assert!(out.contains("2024 elements in all"), "{out}");
    std::fs::remove_dir_all(&d).unwrap();
}

#[test]
fn a_mesh_of_a_deck_beyond_the_bound_is_refused_naming_its_entry() {
    let d = scratch("mesh-large");
    std::fs::copy(
        repo_file("examples/midwater-bridle-moordyn.txt"),
        d.join("deck.txt"),
    )
    .unwrap();
    let sc = write_scenario(
        &d,
        "bad.toml",
        "[system]\nmoordyn = \"deck.txt\"\n[[mesh]]\nlines = [2]\nelements = 1000000\n[analysis]\ntype = \"static\"\n",
    );
    both_refuse(
        &d,
        &sc,
        &["bad.toml: mesh[0].elements", "1000020 elements in all"],
    );
    std::fs::remove_dir_all(&d).unwrap();
}

#[test]
fn a_deck_of_hundreds_of_thousands_of_lines_is_refused_in_bounded_memory() {
    let d = scratch("many-lines");
    let text = std::fs::read_to_string(repo_file("examples/midwater-bridle-moordyn.txt")).unwrap();
    let (head, rest) = text
        .split_once("-------------------------------- LINES")
        .unwrap();
    let options = &rest[rest
        .find("------------------------------- OPTIONS")
        .unwrap()..];
    let mut deck = format!(
        "{head}--- LINES ---\nID LineType AttachA AttachB UnstrLen NumSegs Outputs\n\
         (#) (name) (#) (#) (m) (-) (-)\n"
    );
    let n = 300_000;
    for i in 1..=n {
        deck.push_str(&format!("{i} wire 1 3 46.0 20 -\n"));
    }
    deck.push_str(options);
    let file = write_scenario(&d, "many.txt", &deck);
    both_refuse(&d, &file, &["6000000 elements in all", "above the 2000"]);
    std::fs::remove_dir_all(&d).unwrap();
}

#[test]
fn check_reports_the_elements_and_steps_against_the_bounds() {
    let d = scratch("work-report");
    let deck = d.join("deck.txt");
    std::fs::copy(repo_file("examples/midwater-bridle-moordyn.txt"), &deck).unwrap();
    let o = stancf(&["check", deck.to_str().unwrap()]);
    let (out, err) = text(&o);
    assert!(o.status.success(), "{err}");
    assert!(
        out.contains("44 elements in all (a run takes 2000 without --allow-large)"),
        "{out}"
    );
    let sc = write_scenario(
        &d,
        "dyn.toml",
        &format!(
            "{}[analysis]\ntype = \"dynamic\"\ntime_step = 1e-3\nduration = 2.0\n",
            one_rope("r", "", ("fixed", [1.0, 0.0, 0.0]), (1, 1.0, 4), "")
        ),
    );
    let o = stancf(&["check", sc.to_str().unwrap()]);
    let (out, err) = text(&o);
    assert!(o.status.success(), "{err}");
    assert!(
        out.contains("4 elements in all") && out.contains("; 2000 steps (a run takes 1e8"),
        "{out}"
    );
    std::fs::remove_dir_all(&d).unwrap();
}

/// A large system allowed by `--allow-large` is still refused when it
/// would take more memory than the process may (an allocation that fails
/// aborts the process): 500 024 elements, about 12.5 GB, under a limit
/// of 1.5 GB.
#[test]
fn an_allowed_large_system_beyond_the_memory_the_process_may_take_is_refused() {
    let d = scratch("memory-bound");
    let deck = bridle_with_segments(&d, "500000");
    let o = stancf_in_bounded_memory(&["check", deck.to_str().unwrap(), "--allow-large"]);
    let (_, err) = text(&o);
    assert_eq!(o.status.code(), Some(2), "{err}");
    assert!(
        err.contains("line 18: NumSegs") && err.contains("more than the"),
        "{err}"
    );
    std::fs::remove_dir_all(&d).unwrap();
}
