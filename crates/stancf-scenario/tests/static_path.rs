//! The static path of a deck that cannot reach its equilibrium ends
//! (issue 28): found by the random decks of the property tests.

use std::path::Path;

/// Found by the random decks of the property tests (issue 28): a chain
/// from an anchor on the seabed to a 2000 kg clump and on to a fairlead,
/// whose static path cannot pass load factor 0.99986. Its increments were
/// cut below the precision of the load factor, where one no longer moves
/// it and so "converged"; that reset the cuts, the next increment doubled,
/// failed and was cut back to it, for ever (`stancf run` never ended).
/// Such an increment is a failure now (statics/newton.rs).
const STALLING_DECK: &str = "\
--- LINE TYPES ---
TypeName Diam Mass/m EA BA/-zeta EI Cd Ca CdAx CaAx
(name) (m) (kg/m) (N) (N-s/-) (N-m^2) (-) (-) (-) (-)
chain 0.1 20.0 1.0e8 0 0 0 0 0 0
--- POINTS ---
ID Attachment X Y Z Mass Volume CdA Ca
(#) (-) (m) (m) (m) (kg) (m^3) (m^2) (-)
1 Fixed -25.0 0.0 -50.0 0 0 0 0
2 Coupled 0.0 0.0 -5.0 0 0 0 0
3 Free -12.5 0.0 -32.5 2000 0 0 0
--- LINES ---
ID LineType AttachA AttachB UnstrLen NumSegs Outputs
(#) (name) (#) (#) (m) (-) (-)
1 chain 1 3 27.958 1 -
2 chain 3 2 39.27 2 -
--- OPTIONS ---
50.0 WtrDpth
";

#[test]
fn a_static_path_that_stalls_fails_once_its_cuts_reach_the_load_factors_precision() {
    let path = Path::new("stalling.txt");
    let sc = match stancf_scenario::scenario::parse_input(STALLING_DECK, "stalling.txt", path) {
        Ok(stancf_scenario::scenario::Input::System(sc)) => sc,
        other => panic!("the deck reads as a system: {other:?}"),
    };
    let mut statics = stancf_scenario::check_system::prepare(path, &sc)
        .expect("the deck's system builds")
        .statics
        .expect("a deck alone is a static analysis");
    // Far more increments than the path takes to stall; before the fix
    // the solve went on past any number of them.
    let mut increments = 0;
    let result = statics.solve(|_, _| {
        increments += 1;
        if increments > 10_000 {
            std::ops::ControlFlow::Break(())
        } else {
            std::ops::ControlFlow::Continue(())
        }
    });
    let e = result.expect_err("the path stalls at load factor 0.99986");
    let m = e.to_string();
    assert!(increments <= 10_000, "{increments} increments: {m}");
    // Ends there: its increments below the load factor's precision fail
    // and are cut until the halvings run out, or the path, creeping,
    // takes the most increments it may.
    assert!(m.contains("load factor 0.9998"), "{m}");
    assert!(m.contains("halvings") || m.contains("stalled"), "{m}");
}
