//! A host's sea (`stancf_create_in`, docs/interface.md "C library"): the
//! water depth, density and gravity a glue code gives fill what a
//! MoorDyn deck leaves out, as OpenFAST gives MoorDyn-F its WtrDepth,
//! rhoW and g; the deck's own values win; bad values are refused.

mod common;

use common::*;
use stancf_c::error::STANCF_SUCCESS;
use stancf_c::*;
use std::path::{Path, PathBuf};
use std::ptr::null_mut;

/// examples/oc4-deepcwind-moordyn.txt without the option rows in `drop`
/// (its anchors at z = -200 m, the deck's WtrDpth 200, WtrDnsty 1025,
/// g 9.81).
fn oc4_without(name: &str, drop: &[&str]) -> PathBuf {
    let text = std::fs::read_to_string(repo("examples/oc4-deepcwind-moordyn.txt")).unwrap();
    let kept: String = text
        .lines()
        .filter(|l| !drop.iter().any(|d| l.split_whitespace().nth(1) == Some(d)))
        .map(|l| format!("{l}\n"))
        .collect();
    let deck = scratch(name).join("deck.txt");
    std::fs::write(&deck, kept).unwrap();
    deck
}

/// The fairlead forces of the static equilibrium with the coupled points
/// where the deck puts them; `host` None opens with `stancf_create`.
fn fairlead_forces(deck: &Path, host: Option<[f64; 3]>) -> Vec<f64> {
    let c = cstring(deck);
    let s = unsafe {
        match host {
            None => stancf_create(c.as_ptr()),
            Some([h, rho, g]) => stancf_create_in(c.as_ptr(), 0, h, rho, g),
        }
    };
    assert!(!s.is_null(), "{}", message());
    let mut n = 0u32;
    assert_eq!(unsafe { stancf_ncoupled_dof(s, &mut n) }, STANCF_SUCCESS);
    let mut x = vec![0.0; n as usize];
    let mut f = vec![0.0; n as usize];
    unsafe {
        assert_eq!(stancf_coupled_positions(s, x.as_mut_ptr()), STANCF_SUCCESS);
        assert_eq!(
            stancf_init(s, x.as_ptr(), null_mut()),
            STANCF_SUCCESS,
            "{}",
            message()
        );
        assert_eq!(stancf_init_force(s, f.as_mut_ptr()), STANCF_SUCCESS);
        assert_eq!(stancf_close(s), STANCF_SUCCESS);
    }
    f
}

fn relative_change(a: &[f64], b: &[f64]) -> f64 {
    let size = a.iter().map(|v| v.abs()).fold(0.0, f64::max);
    a.iter()
        .zip(b)
        .map(|(p, q)| (p - q).abs())
        .fold(0.0, f64::max)
        / size
}

/// Without WtrDpth, WtrDnsty and g the deck is MoorDyn's defaults' (the
/// deepest point's depth, 200 m; 1025 kg/m^3; 9.80665 m/s^2) unless the
/// host gives them: the host's 200 m, 1025 kg/m^3 and 9.80665 m/s^2 are
/// those inputs (the same forces to the bit), a 210 m sea lowers the bed
/// under the anchors and a denser sea lightens the chains (their wet
/// weight (m - rho A) g falls), which the fairleads feel.
#[test]
fn a_hosts_sea_fills_what_the_deck_leaves_out() {
    let deck = oc4_without("host-sea", &["WtrDpth", "WtrDnsty", "g"]);
    let defaults = fairlead_forces(&deck, None);
    let same = fairlead_forces(&deck, Some([200.0, 1025.0, 9.80665]));
    assert_eq!(defaults, same);
    let only_depth = fairlead_forces(&deck, Some([200.0, 0.0, 0.0]));
    assert_eq!(defaults, only_depth);
    let deeper = fairlead_forces(&deck, Some([210.0, 0.0, 0.0]));
    assert!(relative_change(&deeper, &defaults) > 1e-3);
    let denser = fairlead_forces(&deck, Some([0.0, 1100.0, 0.0]));
    // The vertical force of each fairlead (every third number from the
    // third) falls with the chains' wet weight.
    for i in (2..defaults.len()).step_by(3) {
        assert!(
            denser[i].abs() < defaults[i].abs(),
            "{} against {}",
            denser[i],
            defaults[i]
        );
    }
}

/// The deck's WtrDpth, WtrDnsty and g win over the host's.
#[test]
fn the_decks_own_sea_wins_over_the_hosts() {
    let deck = repo("examples/oc4-deepcwind-moordyn.txt");
    let own = fairlead_forces(&deck, None);
    let hosted = fairlead_forces(&deck, Some([210.0, 1100.0, 9.7]));
    assert_eq!(own, hosted);
}

#[test]
fn a_hosts_value_that_is_not_positive_and_finite_is_refused_naming_it() {
    let deck = oc4_without("host-bad", &["WtrDpth"]);
    for (host, words) in [
        ([-3.0, 0.0, 0.0], "the host's water depth is -3 m"),
        ([0.0, f64::NAN, 0.0], "the host's water density is NaN"),
        ([0.0, 0.0, f64::INFINITY], "the host's gravity is inf"),
    ] {
        let s = unsafe { stancf_create_in(cstring(&deck).as_ptr(), 0, host[0], host[1], host[2]) };
        assert!(s.is_null());
        assert!(message().contains(words), "{words}: {}", message());
    }
}

/// A deck whose host sets the waves at MoorDyn's nodes (`WaveKin 1`,
/// Lowe and Langley's jumper in MoorDyn's tests) opens, asks for them at
/// its 69 nodes, 2 points and MoorDyn's ground body, and stands in still
/// water until the host sets them, as in MoorDyn: from its equilibrium the
/// top's pull stays the static one to 1e-9 over 10 of the deck's steps.
#[test]
fn a_deck_waiting_for_a_hosts_wave_kinematics_stands_in_still_water_until_it_sets_them() {
    let deck = repo("crates/stancf-cli/tests/fixtures/lowe-langley-2006-jumper-moordyn.txt");
    let s = unsafe { stancf_create(cstring(&deck).as_ptr()) };
    assert!(!s.is_null(), "{}", message());
    let top = [0.0, 0.0, -5.0];
    let mut start = [0.0; 3];
    let mut n = 0u32;
    unsafe {
        assert_eq!(
            stancf_init(s, top.as_ptr(), [0.0; 3].as_ptr()),
            STANCF_SUCCESS
        );
        assert_eq!(stancf_init_force(s, start.as_mut_ptr()), STANCF_SUCCESS);
        assert_eq!(stancf_wave_kin_init(s, &mut n), STANCF_SUCCESS);
    }
    assert_eq!(n, 69 + 2 + 1);
    let mut t = 0.0;
    let mut f = Vec::new();
    for _ in 0..10 {
        f = step_held(s, &top, &mut t, 1e-3);
    }
    let norm = |v: &[f64]| v.iter().map(|c| c * c).sum::<f64>().sqrt();
    let moved = (norm(&f) - norm(&start)).abs();
    assert!(moved < 1e-9 * norm(&start), "{f:?} against {start:?}");
    assert_eq!(unsafe { stancf_close(s) }, STANCF_SUCCESS);
}

/// A FAST.Farm farm-level deck (OpenFAST r-test's MD_Shared) opened with
/// the host's turbine positions (`stancf_create_farm`): two platforms of
/// 6 coupled degrees of freedom each, at the positions given; no
/// positions for its Turbine<n> points, or NULL ones, refused.
#[test]
fn a_host_places_a_farm_decks_turbines() {
    let deck = scratch("capi_farm").join("SharedMooring2.dat");
    std::fs::copy(
        repo("crates/stancf-cli/tests/fixtures/fast-farm-shared-mooring.dat"),
        &deck,
    )
    .unwrap();
    let c = cstring(&deck);
    let positions = [0.0, 0.0, 0.0, 1600.0, 0.0, 0.0];
    let s = unsafe { stancf_create_farm(c.as_ptr(), 0, 2, positions.as_ptr()) };
    assert!(!s.is_null(), "{}", message());
    let mut n = 0u32;
    let mut x = [0.0; 12];
    unsafe {
        assert_eq!(stancf_ncoupled_dof(s, &mut n), STANCF_SUCCESS);
        assert_eq!(n, 12);
        assert_eq!(stancf_coupled_positions(s, x.as_mut_ptr()), STANCF_SUCCESS);
        assert_eq!(stancf_close(s), STANCF_SUCCESS);
    }
    assert_eq!((x[0], x[6]), (0.0, 1600.0));
    let none = unsafe { stancf_create_in(c.as_ptr(), 0, 0.0, 0.0, 0.0) };
    assert!(none.is_null());
    assert!(
        message().contains("point 1 is on turbine 1"),
        "{}",
        message()
    );
    let null = unsafe { stancf_create_farm(c.as_ptr(), 0, 2, std::ptr::null()) };
    assert!(null.is_null());
    assert!(
        message().contains("2 turbines given with no positions"),
        "{}",
        message()
    );
}
