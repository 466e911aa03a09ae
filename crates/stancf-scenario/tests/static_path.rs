//! The static paths of decks found by the random decks of the property
//! tests (issue 28): one that cannot reach its equilibrium ends, one that
//! stalled on the static Newton's weights reaches it.

use std::path::Path;

/// Found by the random decks of the property tests (issue 28): a chain
/// from an anchor on the seabed to a 2000 kg clump and on to a fairlead.
/// Its static path stalled at load factor 0.99986, its increments cut
/// below the precision of the load factor, where one no longer moves it
/// and so "converged"; that reset the cuts, the next increment doubled,
/// failed and was cut back to it, for ever (`stancf run` never ended).
/// Such an increment is a failure now (statics/newton.rs); and the stall
/// itself was the static Newton weighing the multipliers' increments (the
/// end forces) by their constraint rows' position weight, so that they
/// grew by at most 0.2 L newtons an iteration (docs/method.md §6.9).
const CHAIN_AND_CLUMP: &str = "\
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

/// Found by the random systems of the property tests: a free point of
/// drag area 3.8e18 m^2 between three lines in a current, whose static
/// path cannot pass a load factor near 0.005.
const ABSURD_DRAG: &str = "[[line_types]]\nname = \"buoyant\"\ndiameter = 0.45\n\
    mass_per_length = 120.0\nea = 5.0e8\nei = 2.0e4\ncd = 1.2\n\
    [[points]]\nid = 1\ntype = \"fixed\"\nposition = [-75.0, -37.5, -150.0]\n\
    [[points]]\nid = 2\ntype = \"fixed\"\nposition = [-75.0, 37.5, -150.0]\n\
    [[points]]\nid = 3\ntype = \"free\"\nposition = [-37.5, 0.0, -75.0]\nmass = 100.0\n\
    cda = 3762470146307697448\n\
    [[points]]\nid = 4\ntype = \"coupled\"\nposition = [0.0, 0.0, 0.0]\n\
    [[lines]]\nid = 1\ntype = \"buoyant\"\nlength = 119.413\nelements = 3\na = 1\nb = 3\n\
    [[lines]]\nid = 2\ntype = \"buoyant\"\nlength = 119.413\nelements = 1\na = 2\nb = 3\n\
    [[lines]]\nid = 3\ntype = \"buoyant\"\nlength = 109.008\nelements = 4\na = 3\nb = 4\n\
    [water]\ndepth = 150.0\n\
    [water.current]\nprofile = [[-150.0, 0.1, 0.0, 0.0], [0.0, 0.5, 0.0, 0.0]]\n\
    [analysis]\ntype = \"static\"\n";

/// The static solve of `text` (named `name`), its increments counted
/// and stopped after 10 000 (far more than any path takes to end).
fn solve(text: &str, name: &str) -> (Result<(), String>, usize, stancf::system::SystemStatics) {
    let path = Path::new(name);
    let sc = match stancf_scenario::scenario::parse_input(text, name, path) {
        Ok(stancf_scenario::scenario::Input::System(sc)) => sc,
        other => panic!("{name} reads as a system: {other:?}"),
    };
    let mut statics = stancf_scenario::check_system::prepare(path, &sc)
        .expect("the system builds")
        .statics
        .expect("a static analysis");
    let mut increments = 0;
    let result = statics.solve(|_, _| {
        increments += 1;
        if increments > 10_000 {
            std::ops::ControlFlow::Break(())
        } else {
            std::ops::ControlFlow::Continue(())
        }
    });
    (
        result.map(|_| ()).map_err(|e| e.to_string()),
        increments,
        statics,
    )
}

/// The chain and clump reach their equilibrium: the clump's lines hold
/// its weight, 2000 kg x 9.80665 m/s^2 (it displaces no water), to the
/// solve's tolerance.
#[test]
fn a_chain_and_clump_whose_path_stalled_reaches_its_equilibrium() {
    let (result, increments, statics) = solve(CHAIN_AND_CLUMP, "stalling.txt");
    result.expect("the equilibrium is reached");
    assert!(increments <= 10_000);
    let f = statics.point_force(2);
    let weight = 2000.0 * 9.80665;
    assert!(
        f[0].abs() < 1e-6 * weight && (f[2] - weight).abs() < 1e-6 * weight,
        "{f:?}"
    );
}

/// A path that cannot pass a load factor ends with an error naming it:
/// its increments are cut until the halvings run out, or, creeping, it
/// takes the most increments it may.
#[test]
fn a_static_path_that_cannot_pass_a_load_factor_ends_naming_it() {
    let (result, increments, _) = solve(ABSURD_DRAG, "drag.toml");
    let m = result.expect_err("the path stalls");
    assert!(increments <= 10_000, "{increments} increments: {m}");
    assert!(m.contains("load factor 0.00"), "{m}");
    assert!(m.contains("halvings") || m.contains("stalled"), "{m}");
}
