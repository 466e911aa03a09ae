//! What seabed friction holds at a static equilibrium of a MoorDyn deck
//! (docs/method.md §12.2, issue 35): MoorDyn's WD0050_Chain test deck
//! (410 m of chain from an anchor on the bed at x = 400 m to a fairlead at
//! the surface over x = 0, 50 m of water, FrictionCoefficient 0.5), its
//! `cfl` replaced by a `dtM`.

use crate::common::*;
use std::f64::consts::PI;
use std::path::Path;

/// The chain's wet weight per length (N/m).
fn wet_weight() -> f64 {
    (390.0 - 1025.0 * PI / 4.0 * 0.252 * 0.252) * 9.80665
}

/// What a static run of `scenario` gives: the horizontal forces of the
/// line on its anchor (end A) and fairlead (end B), the vertical force at
/// the fairlead, and the bed's friction towards the anchor (+x): the sum
/// of node_loads.csv's seabed_fx.
struct Equilibrium {
    anchor_h: f64,
    fairlead_h: f64,
    fairlead_v: f64,
    friction: f64,
}

fn equilibrium(scenario: &Path, out: &Path) -> Equilibrium {
    let o = run_quiet(scenario, out, &[]);
    assert!(o.status.success(), "{}", text(&o).1);
    let t = read_tensions(&out.join("tensions.csv"));
    // Rows t, line, end (0 = A, 1 = B), fx, fy, fz, tension.
    let (a, b) = (&t[0], &t[1]);
    let (header, rows) = read_csv(&out.join("lines/1/node_loads.csv"));
    let fx = header.iter().position(|h| h == "seabed_fx").unwrap();
    Equilibrium {
        anchor_h: a[3].abs(),
        fairlead_h: b[3].abs(),
        fairlead_v: -b[5],
        friction: rows.iter().map(|r| r[fx]).sum(),
    }
}

/// As laid (a deck's default, MoorDyn's equilibrium): friction holds
/// nothing, the anchor's horizontal force is the fairlead's (to the
/// solve's tolerance 1e-10 of the scaled rows; written with 16 digits),
/// and node_loads.csv shows no friction. Before, the solve held the
/// chain 42.5 kN towards its fairlead (anchor 881.6 kN, fairlead 839.1
/// kN); MoorDyn 2.7 ends at 839.3 kN at both ends.
#[test]
fn moordyn_wd0050_chain_laid_on_its_bed_is_held_by_no_friction() {
    let dir = scratch("wd0050_as_laid");
    let deck = write_scenario(&dir, "WD0050_Chain.txt", WD0050_CHAIN);
    let eq = equilibrium(&deck, &dir.join("out"));
    assert!(
        (eq.anchor_h - eq.fairlead_h).abs() < 1e-8 * eq.fairlead_h,
        "anchor {} N, fairlead {} N",
        eq.anchor_h,
        eq.fairlead_h
    );
    assert!(
        eq.friction.abs() < 1e-8 * eq.fairlead_h,
        "friction {}",
        eq.friction
    );
    let o = stancf(&["check", deck.to_str().unwrap()]);
    assert!(
        text(&o).0.contains("static_friction = \"as_laid\""),
        "{}",
        text(&o).0
    );
}

/// Pulled out along the bed (`[water.seabed] static_friction =
/// "pulled"`): friction holds the chain towards its anchor, so the
/// anchor's horizontal force is below the fairlead's by at most mu w L_B
/// (L_B = L - V_F / w, the resting length of the closed form), and the
/// line balances: H_F - H_A is the bed's friction that node_loads.csv
/// shows (to 1e-8 of H_F: the solve's tolerance).
#[test]
fn moordyn_wd0050_chain_pulled_out_along_its_bed_is_held_towards_its_anchor() {
    let dir = scratch("wd0050_pulled");
    write_scenario(&dir, "WD0050_Chain.txt", WD0050_CHAIN);
    let scenario = write_scenario(
        &dir,
        "pulled.toml",
        "[system]\nmoordyn = \"WD0050_Chain.txt\"\n\n[water.seabed]\n\
         static_friction = \"pulled\"\n\n[analysis]\ntype = \"static\"\n",
    );
    let eq = equilibrium(&scenario, &dir.join("out"));
    let w = wet_weight();
    let resting = 410.0 - eq.fairlead_v / w;
    let held = eq.fairlead_h - eq.anchor_h;
    assert!(
        held > 0.0 && held <= 0.5 * w * resting * (1.0 + 1e-3),
        "H_F - H_A = {held} N outside (0, mu w L_B = {}]",
        0.5 * w * resting
    );
    // Friction is mobilized over all but the anchor's first metres: the
    // pull is most of mu w L_B.
    assert!(held > 0.9 * 0.5 * w * resting, "only {held} N held");
    assert!(
        (held - eq.friction).abs() < 1e-8 * eq.fairlead_h,
        "H_F - H_A {held} N, bed friction {} N",
        eq.friction
    );
}

/// A policy the scenario does not know is refused naming its key.
#[test]
fn an_unknown_static_friction_policy_is_refused() {
    expect_input_error_beside(
        "static_friction_unknown",
        "[system]\nmoordyn = \"WD0050_Chain.txt\"\n\n[water.seabed]\n\
         static_friction = \"sticky\"\n\n[analysis]\ntype = \"static\"\n",
        &[("WD0050_Chain.txt", WD0050_CHAIN)],
        &[
            "water.seabed.static_friction",
            "sticky",
            "as_laid",
            "pulled",
        ],
    );
}
