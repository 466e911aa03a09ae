//! Input files a careless or hostile user gives (issue 28, items 12, 13,
//! 14 and 18): devices, folders and oversized files are refused before
//! anything is read; a deck's lines are echoed at most 200 characters
//! long; a file that is neither TOML nor a deck is told what stancf
//! reads; a file that is no motion table is not quoted. Each is exit 2
//! naming the file (and the key that names it), with nothing written.

use crate::common::*;
use std::path::Path;

/// `check` and `run` of `file` exit 2 with stderr holding each of
/// `needles` and none of `absent`, at most `max_bytes` long; `run`
/// writes nothing. Returns the stderr of `check`.
fn refused(dir: &Path, file: &Path, needles: &[&str], absent: &[&str], max_bytes: usize) -> String {
    let [check, run] = refused_by_check_and_run(file, &dir.join("out"), needles, absent);
    for err in [&check, &run] {
        assert!(err.len() <= max_bytes, "{} bytes of stderr", err.len());
    }
    check
}

/// A rope whose coupled end moves along the motion table `file`, run for
/// 10 steps of 1 ms.
fn rope_moved_by(file: &str) -> String {
    format!(
        "{}[[motions]]\npoint = 2\nfile = \"{file}\"\n[analysis]\ntype = \"dynamic\"\n\
         time_step = 1e-3\nduration = 0.01\n",
        one_rope("m", "", ("coupled", [1.0, 0.0, 0.0]), (1, 1.0, 4), "")
    )
}

#[test]
fn devices_folders_and_oversized_files_are_refused_by_every_reader() {
    let d = scratch("input-files");
    refused(
        &d,
        Path::new("/dev/zero"),
        &["/dev/zero", "not a regular file (a device)"],
        &[],
        500,
    );
    refused(&d, &d, &["not a regular file (a folder)"], &[], 500);
    let big = d.join("big.toml");
    std::fs::File::create(&big)
        .unwrap()
        .set_len(64 * 1024 * 1024 + 1)
        .unwrap();
    refused(&d, &big, &["big.toml", "above the 64 MiB"], &[], 500);
    // Files a scenario refers to: a deck and a motion table.
    let deck = write_scenario(
        &d,
        "deck.toml",
        "[system]\nmoordyn = \"/dev/zero\"\n[analysis]\ntype = \"static\"\n",
    );
    refused(
        &d,
        &deck,
        &["deck.toml: system.moordyn: /dev/zero: not a regular file"],
        &[],
        500,
    );
    let motion = write_scenario(&d, "motion.toml", &rope_moved_by("/dev/zero"));
    refused(
        &d,
        &motion,
        &["motion.toml", "/dev/zero", "not a regular file"],
        &[],
        500,
    );
    std::fs::remove_dir_all(&d).unwrap();
}

#[test]
fn a_file_that_is_no_motion_table_is_not_quoted() {
    let d = scratch("passwd-motion");
    std::fs::write(
        d.join("passwd"),
        "root:x:0:0:root:/root:/bin/bash\nuser:x:1000\n",
    )
    .unwrap();
    let sc = write_scenario(&d, "bad.toml", &rope_moved_by("passwd"));
    refused(
        &d,
        &sc,
        &["passwd line 1: the first line is not a header of column names"],
        &["root"],
        1000,
    );
    std::fs::remove_dir_all(&d).unwrap();
}

#[test]
fn a_deck_with_cr_line_ends_reads_and_a_huge_line_is_echoed_cut() {
    let d = scratch("cr-deck");
    let deck = std::fs::read_to_string(repo_file("examples/midwater-bridle-moordyn.txt")).unwrap();
    // Classic Mac line ends: the deck reads as it does with \n.
    let cr = write_scenario(&d, "cr.txt", &deck.replace('\n', "\r"));
    let o = stancf(&["check", cr.to_str().unwrap()]);
    assert!(o.status.success(), "{:?}", text(&o));
    // 8 MB in one word, where an option's name goes.
    let huge = deck.replace(
        "0.0005    dtM",
        &format!("0.0005 {}", "x".repeat(8_000_000)),
    );
    let huge = write_scenario(&d, "huge.txt", &huge);
    let err = refused(&d, &huge, &["huge.txt: line", "…"], &[], 2500);
    assert!(err.len() < 2500, "{}", err.len());
    std::fs::remove_dir_all(&d).unwrap();
}

#[test]
fn a_file_neither_toml_nor_a_deck_and_a_deck_without_lines_say_so() {
    let d = scratch("neither");
    let table = write_scenario(
        &d,
        "curve.dat",
        "Strain      Tension\n(-) (N)\n0 0\n0.1 1e5\n",
    );
    refused(
        &d,
        &table,
        &["curve.dat", "not TOML", "no MoorDyn section header"],
        &[],
        2000,
    );
    let deck = std::fs::read_to_string(repo_file("examples/midwater-bridle-moordyn.txt")).unwrap();
    let (head, rest) = deck
        .split_once("-------------------------------- LINES")
        .unwrap();
    let options = &rest[rest
        .find("------------------------------- OPTIONS")
        .unwrap()..];
    write_scenario(&d, "nolines.txt", &format!("{head}{options}"));
    let sc = write_scenario(
        &d,
        "bad.toml",
        "[system]\nmoordyn = \"nolines.txt\"\n[analysis]\ntype = \"static\"\n",
    );
    refused(
        &d,
        &sc,
        &[
            "bad.toml: system.moordyn:",
            "nolines.txt: the deck defines no lines, bodies or rods",
        ],
        &[],
        2000,
    );
    // `sweep` reads a deck as a deck: its error, not TOML's.
    let o = stancf(&[
        "sweep",
        d.join("nolines.txt").to_str().unwrap(),
        "--set",
        "analysis.time_step=1,2",
    ]);
    let (_, err) = text(&o);
    assert_eq!(o.status.code(), Some(2), "{err}");
    assert!(
        err.contains("nolines.txt: the deck defines no lines"),
        "{err}"
    );
    assert!(!err.contains("system.moordyn"), "{err}");
    assert!(!err.contains("TOML parse error"), "{err}");
    std::fs::remove_dir_all(&d).unwrap();
}

/// A pipe as an input file is refused before it is opened (opening one
/// waits for a writer for ever), as the scenario and as a file it names.
#[test]
fn a_pipe_as_an_input_file_is_refused_at_once() {
    let d = scratch("fifo");
    let fifo = d.join("fifo.txt");
    let c = std::ffi::CString::new(fifo.to_str().unwrap()).unwrap();
    // SAFETY: mkfifo(3) with a valid path.
    assert_eq!(unsafe { libc::mkfifo(c.as_ptr(), 0o644) }, 0);
    let deck = write_scenario(
        &d,
        "deck.toml",
        "[system]\nmoordyn = \"fifo.txt\"\n[analysis]\ntype = \"static\"\n",
    );
    for (file, needle) in [
        (&fifo, "fifo.txt: not a regular file (a pipe)"),
        (&deck, "system.moordyn"),
    ] {
        // Before, `check` waited on the pipe for ever; the refusal comes
        // before anything is opened.
        let err = refused(
            &d,
            file,
            &[needle, "not a regular file (a pipe)"],
            &[],
            1000,
        );
        assert!(!err.is_empty());
    }
    std::fs::remove_dir_all(&d).unwrap();
}

/// `stancf plot` reads back only regular files a run wrote: a result file
/// replaced by a link to /dev/zero is refused, not read without end.
#[test]
fn plot_refuses_a_result_file_that_is_a_link_to_a_device() {
    let d = scratch("plot-link");
    let sc = write_scenario(&d, "p.toml", &pendulum("p", 1e-3, 4e-3, 1));
    let out = d.join("out");
    assert!(run_quiet(&sc, &out, &[]).status.success());
    std::fs::remove_file(out.join("nodes.csv")).unwrap();
    std::os::unix::fs::symlink("/dev/zero", out.join("nodes.csv")).unwrap();
    let o = stancf_in_bounded_memory(&["plot", out.to_str().unwrap()]);
    let (_, err) = text(&o);
    assert!(!o.status.success(), "{err}");
    assert!(err.contains("nodes.csv: a symbolic link"), "{err}");
    std::fs::remove_dir_all(&d).unwrap();
}

/// What the red-team pass of issue 28 found in the echo of input: a title
/// of megabytes is printed cut, a NUL byte of a deck shown as "?", a
/// motion table with CR line ends read as with \n, and a number too large
/// for TOML is not told "this file is not TOML".
#[test]
fn long_titles_control_characters_and_cr_tables_are_echoed_safely() {
    let d = scratch("echo");
    let long = pendulum("p", 1e-3, 4e-3, 1).replace(
        "title = \"p\"",
        &format!("title = \"{}\"", "t".repeat(100_000)),
    );
    assert!(long.contains("ttt"));
    let long = write_scenario(&d, "long.toml", &long);
    let o = stancf(&["check", long.to_str().unwrap()]);
    let (out, err) = text(&o);
    assert!(o.status.success(), "{err}");
    assert!(
        out.len() < 5000 && out.contains("ttt…"),
        "{} bytes",
        out.len()
    );
    let deck = std::fs::read_to_string(repo_file("examples/midwater-bridle-moordyn.txt"))
        .unwrap()
        .replacen("1   wire      1", "1   wire\0      1", 1);
    let deck = write_scenario(&d, "nul.txt", &deck);
    let err = refused(&d, &deck, &["wire?"], &["\0"], 2000);
    assert!(!err.is_empty());
    std::fs::write(d.join("m.csv"), "t,x,y,z\r0,1,0,0\r1,1,0,0\r").unwrap();
    let sc = write_scenario(&d, "cr.toml", &rope_moved_by("m.csv"));
    let o = stancf(&["check", sc.to_str().unwrap()]);
    assert!(o.status.success(), "{:?}", text(&o));
    let big = write_scenario(
        &d,
        "big.toml",
        "[[mesh]]\nlines = [1]\nelements = 18446744073709551615\n",
    );
    let err = refused(&d, &big, &["number too large"], &["not TOML"], 2000);
    assert!(!err.is_empty());
    std::fs::remove_dir_all(&d).unwrap();
}
