//! Fuzz target: scenario text -> `stancf_scenario::scenario::parse`, and for a
//! scenario that parses, what `stancf check` does with it short of
//! printing: the model, the initial state, the highest frequency and the
//! step count, and the simulation (dynamic) or static solver it would
//! build. No file is read or written. Any panic, overflow (debug
//! assertions are on), hang or out-of-memory is a finding.

#![no_main]

use libfuzzer_sys::fuzz_target;
use std::path::Path;

/// Larger meshes are valid (up to 1e6 elements) but only slow the fuzzer
/// down: their model is not built.
const MAX_ELEMENTS: usize = 2_000;

fuzz_target!(|data: &[u8]| {
    let Ok(text) = std::str::from_utf8(data) else {
        return;
    };
    let Ok(sc) = stancf_scenario::scenario::parse(text, "fuzz.toml", Path::new("fuzz.toml")) else {
        return;
    };
    if sc.cable.elements > MAX_ELEMENTS {
        return;
    }
    let Ok(model) = sc.model() else {
        return;
    };
    let state = sc.initial_state(&model);
    match sc.analysis.kind {
        stancf_scenario::scenario::AnalysisKind::Dynamic => {
            let _ = stancf::stability::highest_frequency(&model, &state.e);
            let _ = stancf::integrator::step_count(sc.analysis.duration, sc.analysis.time_step);
            if let Ok(sim) = stancf::Simulation::new(model, state, sc.step_settings()) {
                let _ = (sim.unknowns_per_step(), sim.is_planar());
            }
        }
        stancf_scenario::scenario::AnalysisKind::Static => {
            let _ = stancf::StaticSolver::new(model, sc.static_settings());
        }
    }
});
