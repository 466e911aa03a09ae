//! A deck whose `TmaxIC` is 0 starts through the C library as MoorDyn
//! starts without initial conditions (docs/method.md §13.7): its lines in
//! their closed-form shapes between the coupled points where the host
//! puts them, no static solve; `stancf_init` gives the forces of those
//! shapes, and there is no equilibrium to take a stiffness at.

mod common;

use common::*;
use stancf_c::error::{STANCF_INVALID_INPUT, STANCF_SUCCESS};
use stancf_c::*;
use std::path::{Path, PathBuf};

/// examples/oc4-deepcwind-moordyn.txt with its TmaxIC set to `tmax`.
fn oc4_with_tmax_ic(name: &str, tmax: &str) -> PathBuf {
    let text = std::fs::read_to_string(repo("examples/oc4-deepcwind-moordyn.txt")).unwrap();
    let text = text.replacen("60.0      TmaxIC", &format!("{tmax}      TmaxIC"), 1);
    let deck = scratch(name).join("oc4.txt");
    std::fs::write(&deck, text).unwrap();
    deck
}

/// The forces `stancf_init` gives with the fairleads where the deck puts
/// them, and the handle.
fn init_forces(deck: &Path) -> (*mut StancfSystem, Vec<f64>) {
    let s = unsafe { stancf_create(cstring(deck).as_ptr()) };
    assert!(!s.is_null(), "{}", message());
    let mut x = vec![0.0; 9];
    let mut f = vec![0.0; 9];
    unsafe {
        assert_eq!(stancf_coupled_positions(s, x.as_mut_ptr()), STANCF_SUCCESS);
        assert_eq!(
            stancf_init(s, x.as_ptr(), std::ptr::null()),
            STANCF_SUCCESS,
            "{}",
            message()
        );
        assert_eq!(stancf_init_force(s, f.as_mut_ptr()), STANCF_SUCCESS);
    }
    (s, f)
}

/// The OC4 chains with TmaxIC 0 start as the closed form of a chain
/// resting on its bed (docs/method.md (C14)-(C21)), whose fairlead forces
/// are within 1e-3 of the static equilibrium's the deck gets otherwise
/// (the closed form's rigid bed against the soft one and 42 m elements:
/// 2.8e-4 of H and 1.8e-4 of V_F measured, `systems::the_oc4_chains_rest_on_the_seabed_as_elastic_catenaries`),
/// but are not that equilibrium's (no static solve ran); the system steps
/// from there, and asking its mooring stiffness is refused.
#[test]
fn a_deck_with_tmaxic_0_starts_from_its_chains_closed_forms() {
    let (start, from_shapes) = init_forces(&oc4_with_tmax_ic("tmax0", "0"));
    let (solved, at_equilibrium) = init_forces(&oc4_with_tmax_ic("tmax60", "60.0"));
    for k in 0..3 {
        let a = &from_shapes[3 * k..3 * k + 3];
        let b = &at_equilibrium[3 * k..3 * k + 3];
        let size = b.iter().map(|c| c * c).sum::<f64>().sqrt();
        let apart = (0..3).map(|i| (a[i] - b[i]).abs()).fold(0.0, f64::max);
        eprintln!(
            "fairlead {k}: {a:?} against the equilibrium's {b:?}: {:.2e}",
            apart / size
        );
        assert!(apart < 1e-3 * size, "fairlead {k}: {a:?} against {b:?}");
        assert!(
            apart > 1e-9 * size,
            "fairlead {k}: the equilibrium's forces"
        );
    }
    let x: Vec<f64> = {
        let mut x = vec![0.0; 9];
        unsafe { stancf_coupled_positions(start, x.as_mut_ptr()) };
        x
    };
    let mut t = 0.0;
    for _ in 0..5 {
        step_held(start, &x, &mut t, 1e-3);
    }
    let mut k = [0.0; 9];
    assert_eq!(
        unsafe { stancf_point_stiffness(start, 4, k.as_mut_ptr()) },
        STANCF_INVALID_INPUT
    );
    assert!(message().contains("TmaxIC 0"), "{}", message());
    assert_eq!(
        unsafe { stancf_point_stiffness(solved, 4, k.as_mut_ptr()) },
        STANCF_SUCCESS
    );
    unsafe {
        assert_eq!(stancf_close(start), STANCF_SUCCESS);
        assert_eq!(stancf_close(solved), STANCF_SUCCESS);
    }
}
