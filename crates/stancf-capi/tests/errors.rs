//! Errors come back as codes with a message, and the process and the
//! handle go on (docs/interface.md, "C library").

mod common;

use common::{bridle, cstring, message, repo, scratch};
use stancf_c::error::*;
use stancf_c::*;
use std::ptr::{null, null_mut};

#[test]
fn a_bad_file_is_null_with_a_message_naming_it() {
    let missing = repo("examples/no-such-file.toml");
    let s = unsafe { stancf_create(cstring(&missing).as_ptr()) };
    assert!(s.is_null());
    assert!(message().contains("no-such-file.toml"), "{}", message());

    let dir = scratch("bad-file");
    let bad = dir.join("bad.toml");
    std::fs::write(&bad, "[system]\ngravity = [0.0, 0.0]\n[[points]]\nid = 1\n").unwrap();
    let s = unsafe { stancf_create(cstring(&bad).as_ptr()) };
    assert!(s.is_null());
    assert!(message().contains("bad.toml"), "{}", message());
    // A single cable has no coupled points.
    let s = unsafe { stancf_create(cstring(&repo("examples/pendulum.toml")).as_ptr()) };
    assert!(s.is_null());
    assert!(message().contains("single cable"), "{}", message());
    assert!(unsafe { stancf_create(null()) }.is_null());
}

#[test]
fn wrong_dof_counts_null_pointers_and_bad_calls_return_codes_and_the_handle_goes_on() {
    let s = bridle();
    let mut n = 0u32;
    assert_eq!(unsafe { stancf_ncoupled_dof(s, &mut n) }, STANCF_SUCCESS);
    assert_eq!(n, 3);
    let x = [6.0, 0.0, 1.0, 0.0];
    let (mut f, mut t, mut dt) = ([0.0; 4], 0.0, 1e-3);
    // A step before stancf_init.
    let code = unsafe { stancf_step(s, x.as_ptr(), null(), f.as_mut_ptr(), &mut t, &mut dt) };
    assert_eq!(code, STANCF_INVALID_INPUT);
    assert!(message().contains("before stancf_init"), "{}", message());
    // Four values where the system has three.
    let code = unsafe { stancf_init_n(s, 4, x.as_ptr(), null()) };
    assert_eq!(code, STANCF_INVALID_VALUE);
    assert!(message().contains("expected 3 values"), "{}", message());
    let nan = [6.0, f64::NAN, 1.0];
    assert_eq!(
        unsafe { stancf_init(s, nan.as_ptr(), null()) },
        STANCF_INVALID_VALUE
    );
    assert!(message().contains("x[1]"), "{}", message());
    assert_eq!(
        unsafe { stancf_init(s, null(), null()) },
        STANCF_INVALID_INPUT
    );
    assert!(message().contains("x is NULL"), "{}", message());
    assert_eq!(
        unsafe { stancf_ncoupled_dof(null_mut(), &mut n) },
        STANCF_INVALID_INPUT
    );
    assert!(message().contains("handle is NULL"), "{}", message());

    // The handle still works.
    assert_eq!(
        unsafe { stancf_init(s, x.as_ptr(), null()) },
        STANCF_SUCCESS
    );
    let code = unsafe { stancf_step_n(s, 4, x.as_ptr(), null(), f.as_mut_ptr(), &mut t, &mut dt) };
    assert_eq!(code, STANCF_INVALID_VALUE);
    assert_eq!(t, 0.0);
    // A *t that is not the time reached.
    let mut wrong = 0.5;
    let code = unsafe { stancf_step(s, x.as_ptr(), null(), f.as_mut_ptr(), &mut wrong, &mut dt) };
    assert_eq!(code, STANCF_INVALID_INPUT);
    assert!(message().contains("not the time reached"), "{}", message());
    let code = unsafe { stancf_step(s, x.as_ptr(), null(), f.as_mut_ptr(), &mut t, &mut dt) };
    assert_eq!(code, STANCF_SUCCESS, "{}", message());
    assert_eq!(t, 1e-3);
    assert!(f[..3].iter().all(|v| v.is_finite()) && f[2] < 0.0);
    let mut p = [0.0; 3];
    assert_eq!(
        unsafe { stancf_line_node_pos(s, 5, 0, p.as_mut_ptr()) },
        STANCF_INVALID_INPUT
    );
    assert!(message().contains("no line 5"), "{}", message());
    assert_eq!(
        unsafe { stancf_line_node_pos(s, 0, 99, p.as_mut_ptr()) },
        STANCF_INVALID_INPUT
    );
    assert!(message().contains("no node 99"), "{}", message());
    assert_eq!(unsafe { stancf_close(s) }, STANCF_SUCCESS);
    assert_eq!(unsafe { stancf_close(null_mut()) }, STANCF_INVALID_INPUT);
}

/// A step whose Newton cannot converge (examples/bridle.toml at a step of
/// 1 s without halvings, its fairlead moved 4 m toward the anchors: its
/// ropes of 0.08 kg/m and EA 2e4 N swing through their whole motion in
/// one step, and Newton's residual stays at 6e6): the code says so with
/// time, step and residual, and the system stays at its last converged
/// state. (Held where it is, the fairlead's step converges: a residual at
/// its round-off floor, 2.6e-9, with the unknowns settled, is the step's
/// solution, docs/method.md §7.2.)
/// A jump of the fairlead by 1000 km is no motion at all: refused as a
/// value (issue 28, item 17), the system untouched.
#[test]
fn a_diverging_step_returns_a_numerical_error_and_keeps_the_last_step() {
    let text = std::fs::read_to_string(repo("examples/bridle.toml")).unwrap();
    assert!(text.contains("time_step = 0.00015"));
    let path = scratch("long-step").join("bridle.toml");
    std::fs::write(
        &path,
        text.replace("time_step = 0.00015", "time_step = 1.0\nstep_halvings = 0"),
    )
    .unwrap();
    let s = unsafe { stancf_create(cstring(&path).as_ptr()) };
    assert!(!s.is_null(), "{}", message());
    let x = [6.0, 0.0, 1.0];
    let (mut f, mut t, mut dt) = ([0.0; 3], 0.0, 1.0);
    assert_eq!(
        unsafe { stancf_init(s, x.as_ptr(), null()) },
        STANCF_SUCCESS
    );
    let far = [1e6; 3];
    let code = unsafe { stancf_step(s, far.as_ptr(), null(), f.as_mut_ptr(), &mut t, &mut dt) };
    assert_eq!(code, STANCF_INVALID_VALUE);
    assert!(message().contains("above the 100 m/s"), "{}", message());
    assert_eq!(t, 0.0);
    let toward = [2.0, 0.0, 1.0];
    let code = unsafe { stancf_step(s, toward.as_ptr(), null(), f.as_mut_ptr(), &mut t, &mut dt) };
    assert_eq!(code, STANCF_NUMERICAL_ERROR, "{}", message());
    let m = message();
    assert!(m.contains("t = 0 s") && m.contains("residual"), "{m}");
    assert_eq!(t, 0.0);
    let mut reached = -1.0;
    assert_eq!(unsafe { stancf_time(s, &mut reached) }, STANCF_SUCCESS);
    assert_eq!(reached, 0.0);
    let mut nodes = 0u32;
    assert_eq!(
        unsafe { stancf_line_nnodes(s, 0, &mut nodes) },
        STANCF_SUCCESS
    );
    let mut pos = vec![0.0; 3 * nodes as usize];
    assert_eq!(
        unsafe { stancf_line_positions(s, 0, pos.as_mut_ptr()) },
        STANCF_SUCCESS
    );
    assert!(pos.iter().all(|v| v.is_finite()));
    assert_eq!(unsafe { stancf_close(s) }, STANCF_SUCCESS);
}

/// The bridle deck of the examples with line 1's NumSegs set to `segs`,
/// in a scratch folder; returns its path.
fn bridle_deck_with_segments(name: &str, segs: &str) -> std::path::PathBuf {
    let text = std::fs::read_to_string(repo("examples/midwater-bridle-moordyn.txt")).unwrap();
    let row = "1   wire      1        3        46.0      20 ";
    assert!(text.contains(row));
    let deck = scratch(name).join("deck.txt");
    let text = text
        .replace(
            row,
            &format!("1   wire      1        3        46.0      {segs} "),
        )
        .replace("3   Free ", "3   Coupled ");
    std::fs::write(&deck, text).unwrap();
    deck
}

/// Item 4 of issue 28: the library applies the bounds `stancf run`
/// applies before building anything, so a deck of 1e7 segments is a
/// refusal with a message, not an abort of the host; a system beyond
/// the bound without `--allow-large` opens only with its flag.
#[test]
fn a_deck_beyond_the_bounds_is_refused_before_it_is_built_and_large_ones_open_on_request() {
    for segs in ["10000000", "18446744073709551615"] {
        let deck = bridle_deck_with_segments("huge-deck", segs);
        for flags in [0, STANCF_ALLOW_LARGE] {
            let s = unsafe { stancf_create_with(cstring(&deck).as_ptr(), flags) };
            assert!(s.is_null());
            assert!(
                message().contains("line 18: NumSegs of line 1")
                    && message().contains("above the 1000000 segments a line may have"),
                "{}",
                message()
            );
        }
    }
    let deck = bridle_deck_with_segments("large-deck", "3000");
    let s = unsafe { stancf_create(cstring(&deck).as_ptr()) };
    assert!(s.is_null());
    assert!(
        message().contains("3024 elements in all") && message().contains("--allow-large"),
        "{}",
        message()
    );
    let s = unsafe { stancf_create_with(cstring(&deck).as_ptr(), STANCF_ALLOW_LARGE) };
    assert!(!s.is_null(), "{}", message());
    let mut n = 0u32;
    assert_eq!(unsafe { stancf_line_nnodes(s, 0, &mut n) }, STANCF_SUCCESS);
    assert_eq!(n, 3001);
    assert_eq!(unsafe { stancf_close(s) }, STANCF_SUCCESS);
    let s = unsafe { stancf_create_with(cstring(&deck).as_ptr(), 6) };
    assert!(s.is_null());
    assert!(message().contains("unknown flags 0x6"), "{}", message());
}

/// A C host whose address space is limited (1.5 GB) gets NULL and a
/// message for a system its opt-in allows but its memory does not take
/// (500 024 elements, about 12.5 GB), where the allocation used to abort
/// it (issue 28, item 4).
#[test]
fn a_large_system_beyond_the_hosts_memory_is_null_not_an_abort() {
    use std::os::unix::process::CommandExt;
    let deck = bridle_deck_with_segments("memory-host", "500000");
    let dir = scratch("memory-host-c");
    let source = dir.join("open_large.c");
    std::fs::write(
        &source,
        "#include <stdio.h>\n#include \"stancf.h\"\n\
         int main(int argc, char **argv) {\n\
             (void)argc;\n\
             StancfSystem *s = stancf_create_with(argv[1], STANCF_ALLOW_LARGE);\n\
             if (s != NULL) return 1;\n\
             puts(stancf_error_message());\n\
             return 0;\n\
         }\n",
    )
    .unwrap();
    let exe = dir.join("open_large");
    common::compile(&source, &exe, "c99");
    let mut cmd = common::c_program(&exe);
    cmd.arg(&deck);
    // SAFETY: setrlimit(2) in the child before exec.
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
    let out = cmd.output().unwrap();
    let printed = String::from_utf8_lossy(&out.stdout);
    assert_eq!(
        out.status.code(),
        Some(0),
        "{printed}{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert!(printed.contains("more than the"), "{printed}");
}
