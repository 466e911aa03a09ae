//! include/stancf.h is the library's contract: it declares every
//! exported function with its arguments, and a C99 program (and a C++
//! one) calling every function compiles against it without a warning and
//! runs against the library.

mod common;

use common::{compile, repo, scratch};
use std::collections::BTreeMap;

/// name -> number of arguments of each `stancf_` prototype in the header.
fn header_prototypes() -> BTreeMap<String, usize> {
    let text = std::fs::read_to_string(repo("crates/stancf-capi/include/stancf.h")).unwrap();
    // Prototypes end with ");" and may span lines; comments hold no "(".
    let code: String = text
        .lines()
        .filter(|l| !l.trim_start().starts_with("/*") && !l.trim_start().starts_with('*'))
        .collect::<Vec<_>>()
        .join(" ");
    prototypes(&code, "stancf_")
}

/// name -> number of arguments of each `extern "C" fn stancf_` in the
/// crate's sources.
fn exported_functions() -> BTreeMap<String, usize> {
    let mut all = BTreeMap::new();
    for file in ["lib.rs", "lines.rs", "bodies.rs", "waves.rs"] {
        let text = std::fs::read_to_string(repo("crates/stancf-capi/src").join(file)).unwrap();
        let code = text
            .split("extern \"C\" fn ")
            .skip(1)
            .map(|rest| format!("stancf_{}", rest.trim_start_matches("stancf_")));
        for item in code {
            all.extend(prototypes(&item, "stancf_").into_iter().take(1));
        }
    }
    all
}

/// The functions named `prefix...(` in `code` and their argument counts
/// (`void` or nothing: 0).
fn prototypes(code: &str, prefix: &str) -> BTreeMap<String, usize> {
    let mut out = BTreeMap::new();
    let mut rest = code;
    while let Some(i) = rest.find(prefix) {
        let after = &rest[i..];
        let name_end = after
            .find(|c: char| !(c.is_ascii_alphanumeric() || c == '_'))
            .unwrap_or(after.len());
        let name = &after[..name_end];
        let tail = after[name_end..].trim_start();
        if let Some(args) = tail.strip_prefix('(') {
            let close = args.find(')').unwrap();
            let inner = args[..close].trim();
            let count = if inner.is_empty() || inner == "void" {
                0
            } else {
                // (rustfmt leaves a comma after the last of many.)
                inner.split(',').filter(|a| !a.trim().is_empty()).count()
            };
            out.insert(name.to_string(), count);
            rest = &args[close..];
        } else {
            rest = &after[name_end..];
        }
    }
    out
}

#[test]
fn the_header_declares_every_export_with_its_arguments() {
    let header = header_prototypes();
    let exports = exported_functions();
    assert!(exports.len() >= 25, "{exports:?}");
    assert_eq!(header, exports);
}

const EVERY_CALL: &str = r#"
#include <math.h>
#include <stdio.h>
#include <string.h>
#include "stancf.h"

/* Calls every function of the header once; exits 0 if all answered as
   the contract says. */
int main(int argc, char **argv) {
    (void)argc;
    if (stancf_create("no/such/file.toml") != NULL) return 10;
    if (strstr(stancf_error_message(), "file.toml") == NULL) return 11;
    StancfSystem *s = stancf_create(argv[1]);
    if (s == NULL) { fprintf(stderr, "%s\n", stancf_error_message()); return 12; }
    StancfSystem *large = stancf_create_with(argv[1], STANCF_ALLOW_LARGE);
    if (large == NULL || stancf_close(large)) return 35;
    if (stancf_create_with(argv[1], 2u) != NULL) return 36;
    unsigned int n = 0, lines = 0, nodes = 0, points = 0;
    int64_t id = 0, ids[1];
    double x[3], xd[3] = {0.0, 0.0, 0.0}, f[3], t = 0.0, dt = 0.01, v3[3], v;
    if (stancf_ncoupled_dof(s, &n) || n != 3) return 13;
    if (stancf_coupled_ids(s, ids) || ids[0] != 2) return 14;
    /* The bridle has no coupled body. */
    unsigned int nb = 1;
    if (stancf_coupled_body_count(s, &nb) || nb != 0 || stancf_coupled_body_ids(s, ids)) return 38;
    if (stancf_coupled_positions(s, x) || x[0] != 6.0) return 15;
    if (stancf_init_force(s, f) != STANCF_INVALID_INPUT) return 40;
    if (stancf_init(s, x, xd) || stancf_init_n(s, 3, x, NULL)) return 16;
    /* The bridle's fairlead carries its lines' pull at rest. */
    if (stancf_init_force(s, f) || !(f[0] != 0.0 || f[2] != 0.0)) return 41;
    if (stancf_set_max_interval_steps(s, 1000)) return 31;
    if (stancf_set_max_interval_steps(s, 0) != STANCF_INVALID_VALUE) return 32;
    x[0] += 0.01;
    if (stancf_step(s, x, xd, f, &t, &dt) || t != 0.01) return 17;
    if (stancf_step_n(s, 3, x, NULL, f, &t, &dt) || t != 0.02) return 18;
    if (stancf_step_n(s, 2, x, NULL, f, &t, &dt) != STANCF_INVALID_VALUE) return 19;
    /* The time reached: the internal steps' sum, t to round-off. */
    if (stancf_interval_mean_force(s, f) || stancf_time(s, &v) || fabs(v - t) > 1e-12) return 20;
    /* Equal steps of the bridle's 0.15 ms over 10 ms: 67. */
    if (stancf_last_steps(s, &nodes) || nodes != 67) return 60;
    StancfState *state = stancf_save(s);
    if (state == NULL || stancf_restore(s, state) || stancf_free_state(state)) return 21;
    if (stancf_free_state(state) != STANCF_INVALID_INPUT) return 33;
    if (stancf_nlines(s, &lines) || lines != 2 || stancf_line_id(s, 1, &id) || id != 2) return 22;
    if (stancf_line_nnodes(s, 0, &nodes) || nodes != 17) return 23;
    if (stancf_line_node_pos(s, 0, 0, v3) || stancf_line_node_vel(s, 0, 0, v3)) return 24;
    if (stancf_line_node_ten(s, 0, 0, &v) || stancf_line_node_curv(s, 0, 0, &v)) return 25;
    double pos[3 * 17], ten[17];
    if (stancf_line_positions(s, 0, pos) || stancf_line_tensions(s, 0, ten)) return 26;
    if (stancf_npoints(s, &points) || points != 3 || stancf_point_id(s, 2, &id) || id != 3) return 27;
    if (stancf_point_state(s, 2, v3, NULL, f)) return 28;
    /* The bridle has no body: its id 1 is refused. */
    double k[36];
    if (stancf_body_stiffness(s, 1, k) != STANCF_INVALID_INPUT) return 37;
    /* Its anchor 1 is fixed, its fairlead 2 coupled: a 3 x 3 of the lines'. */
    if (stancf_point_stiffness(s, 1, k) != STANCF_INVALID_INPUT) return 38;
    if (stancf_point_stiffness(s, 2, k) != STANCF_SUCCESS || !(k[0] > 0.0)) return 39;
    /* The bridle's waves are not a host's: nothing to set. */
    if (stancf_wave_kin_init(s, &n) != STANCF_INVALID_INPUT) return 42;
    if (stancf_wave_kin_n(s, &n) != STANCF_INVALID_INPUT) return 43;
    if (stancf_wave_kin_coordinates(s, k) != STANCF_INVALID_INPUT) return 44;
    if (stancf_wave_kin_set(s, k, k, 0.0) != STANCF_INVALID_INPUT) return 45;
    if (stancf_close(s) != STANCF_SUCCESS) return 29;
    if (stancf_close(NULL) != STANCF_INVALID_INPUT) return 30;
    /* A closed handle is refused, not read. */
    if (stancf_close(s) != STANCF_INVALID_INPUT || stancf_time(s, &v) != STANCF_INVALID_INPUT)
        return 34;
    return 0;
}
"#;

#[test]
fn a_c99_program_calling_every_function_compiles_and_runs_against_the_library() {
    let dir = scratch("every-call");
    let source = dir.join("every_call.c");
    std::fs::write(&source, EVERY_CALL).unwrap();
    let exe = dir.join("every_call");
    compile(&source, &exe, "c99");
    let run = common::c_program(&exe)
        .arg(repo("examples/bridle.toml"))
        .output()
        .unwrap();
    assert_eq!(
        run.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&run.stderr)
    );
}

#[test]
fn the_header_compiles_as_cpp() {
    let dir = scratch("cpp");
    let source = dir.join("include.cpp");
    std::fs::write(
        &source,
        "#include \"stancf.h\"\nint main() { return stancf_error_message() == nullptr; }\n",
    )
    .unwrap();
    let cxx = std::env::var("CXX").unwrap_or_else(|_| "c++".into());
    let out = std::process::Command::new(cxx)
        .args(["-fsyntax-only", "-Wall", "-Werror", "-I"])
        .arg(repo("crates/stancf-capi/include"))
        .arg(&source)
        .output()
        .expect("the system C++ compiler runs");
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
}
