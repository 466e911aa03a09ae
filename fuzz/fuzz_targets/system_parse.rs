//! Fuzz target: system scenario TOML (`[system]`, `[[line_types]]`,
//! `[[points]]`, `[[lines]]`, `[water]`, `[[motions]]`, `[[mesh]]`,
//! `[analysis]`, `[output]`) -> `stancf_scenario::scenario::parse_input` on the
//! text as a `.toml` file in an empty folder (so `system.moordyn` and
//! motion files are not found), then, for a system that parses, the
//! bounds on its elements and steps (`work_bounds::admit_system`) and what
//! `stancf check` builds and reports (`check_system`). Any panic,
//! overflow (debug assertions are on), hang or out-of-memory is a
//! finding.

#![no_main]

mod common;

use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    let Ok(text) = std::str::from_utf8(data) else {
        return;
    };
    common::check_system_text(text, "fuzz.toml");
});
