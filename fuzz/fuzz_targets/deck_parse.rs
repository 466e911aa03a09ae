//! Fuzz target: MoorDyn v2 deck text -> `stancf_scenario::moordyn::parse`, and
//! for a deck that reads, what `stancf check` does with it short of
//! printing: the system scenario (`scenario::parse_input` on the text as
//! a `.txt` file in an empty folder), the bounds on its elements
//! (`work_bounds::admit_system`), the system, its static solver and the
//! check report (`check_system`). Any panic, overflow (debug assertions
//! are on), hang or out-of-memory is a finding.

#![no_main]

mod common;

use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    let Ok(text) = std::str::from_utf8(data) else {
        return;
    };
    if stancf_scenario::moordyn::parse(text).is_err() {
        return;
    }
    common::check_system_text(text, "fuzz.txt");
});
