//! MoorDyn's coupled rods (RODS `Coupled`, docs/method.md §15.18): a rod
//! the host moves in six degrees of freedom, pushing it with its weight,
//! buoyancy, water and inertia (B36) besides its lines.

use crate::common::*;
use std::f64::consts::PI;

/// A can 2 m across and 10 m long (5 t/m, Ca 1, CaEnd 1, no drag) hanging
/// from (0, 0, -5), coupled, in 30 m of water, nothing else.
const COUPLED_ROD: &str =
    "--------------------- MoorDyn Input File ---------------------------------------
A coupled rod, a can
---------------------- ROD TYPES -----------------------------------------------
TypeName      Diam     Mass/m    Cd     Ca      CdEnd    CaEnd
(name)        (-)      (kg/m)    (-)    (-)     (-)      (-)
Can           2        5e3       0.0    1.0     0.0      1.0
---------------------- RODS ----------------------------------------------------
ID   RodType  Attachment  Xa    Ya    Za    Xb    Yb    Zb    NumSegs  RodOutputs
(#)  (name)   (#/key)     (m)   (m)   (m)   (m)   (m)   (m)   (-)      (-)
1    Can      Coupled     0     0     -5    0     0     -15   3        -
---------------------- OPTIONS -------------------------------------------------
0.01     dtM          - time step to use in mooring integration
30       WtrDpth      - water depth
------------------------- need this line ---------------------------------------
";

const G: f64 = 9.80665;
const RHO: f64 = 1025.0;

/// The can's mass and displaced mass.
fn can() -> (f64, f64) {
    (50_000.0, RHO * PI * 10.0)
}

/// `check` says the rod is coupled (6 numbers); at rest the host carries
/// its wet weight, -(m - rho V) g, with no moment about end A (it hangs
/// along its weight); lifted at a = 2 m/s^2 it pulls -((m + m_a) a +
/// (m - rho V) g) with its caps' added mass m_a = 2 rho CaEnd pi d^3 / 12
/// (B36), each interval's mean to 1e-9.
#[test]
fn a_coupled_rod_pushes_the_host_by_its_wet_weight_and_inertia() {
    let d = scratch("coupled-rod");
    let deck = write_scenario(&d, "rod.txt", COUPLED_ROD);
    let o = stancf(&["check", deck.to_str().unwrap()]);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o).1);
    let so = text(&o).0;
    assert!(
        so.contains("coupled, body 1 (moved by the host in six degrees of freedom;")
            && so.contains("mass 50000 kg; submerged;")
            && so.contains("coupled rod 1 (moved by the host in 6 degrees of freedom"),
        "{so}"
    );
    let mut c = stancf_cli::coupling::open(&deck).expect("a coupled system");
    assert_eq!(c.handle.coupled_dof(), 6);
    assert_eq!(c.coupled_body_ids, [1]);
    let (mass, displaced) = can();
    let wet = (mass - displaced) * G;
    let at = |t: f64| [0.0, 0.0, -5.0 + t * t, 0.0, 0.0, 0.0];
    let rate = |t: f64| [0.0, 0.0, 2.0 * t, 0.0, 0.0, 0.0];
    let f0 = c.handle.initialize(&at(0.0), Some(&rate(0.0))).unwrap();
    let want0 = [0.0, 0.0, -wet, 0.0, 0.0, 0.0];
    let off =
        |f: &[f64], want: &[f64; 6]| (0..6).map(|k| (f[k] - want[k]).abs()).fold(0.0, f64::max);
    assert!(off(&f0, &want0) < 1e-9 * wet, "{f0:?}");
    let added = 2.0 * RHO * PI * 8.0 / 12.0;
    let lifted = [0.0, 0.0, -((mass + added) * 2.0 + wet), 0.0, 0.0, 0.0];
    let worst = worst_interval_mean(
        &mut c.handle,
        |t| at(t).to_vec(),
        |t| rate(t).to_vec(),
        |f| off(f, &lifted),
    );
    eprintln!("a coupled rod lifted: {:.3} N to {worst:.1e}", lifted[2]);
    assert!(worst < 1e-9 * wet, "{worst:e}");
}

/// Laid level (the deck's end B 10 m along x) and spun by the host's yaw
/// about the vertical through its end A at w = 0.5 rad/s, the can pushes
/// the host outward along itself by (m + rho Ca A L) w^2 L / 2 (its
/// sections move across it, and the added mass's momentum turns with
/// them) on top of its wet weight, whose moment about end A has the arm
/// L/2 along the rod: the interval means of these turning vectors against
/// their closed forms (the host's path holds a steady spin exactly), to
/// 1e-9 of the weight's moment.
#[test]
fn a_coupled_rod_spun_level_pushes_outward_by_its_and_its_added_mass() {
    let d = scratch("coupled-rod-spin");
    let level = COUPLED_ROD.replace(
        "0     0     -5    0     0     -15   3",
        "0     0     -5    10    0     -5    3",
    );
    assert_ne!(level, COUPLED_ROD);
    let deck = write_scenario(&d, "rod.txt", &level);
    let mut c = stancf_cli::coupling::open(&deck).expect("a coupled system");
    let (mass, displaced) = can();
    let wet = (mass - displaced) * G;
    let w = 0.5;
    let x = |t: f64| [0.0, 0.0, -5.0, 0.0, 0.0, w * t];
    let xd = [0.0, 0.0, 0.0, 0.0, 0.0, w];
    c.handle.initialize(&x(0.0), Some(&xd)).unwrap();
    let axis = |t: f64| [(w * t).cos(), (w * t).sin(), 0.0];
    let across = mass + RHO * 1.0 * PI * 10.0;
    let out = across * w * w * 5.0;
    let mut worst = 0.0f64;
    for k in 1..=8 {
        let (ta, tb) = (0.25 * (k - 1) as f64, 0.25 * k as f64);
        let f = c
            .handle
            .step_to(tb, &x(tb), Some(&xd))
            .unwrap()
            .interval_mean;
        // Means over [ta, tb] of the turning closed forms, by a fine rule.
        let n = 2000;
        let mut want = [0.0; 6];
        for i in 0..n {
            let t = ta + (tb - ta) * (i as f64 + 0.5) / n as f64;
            let a = axis(t);
            let force = [out * a[0], out * a[1], -wet];
            let moment = stancf::vec3::cross(a.map(|c| 5.0 * c), [0.0, 0.0, -wet]);
            for c in 0..3 {
                want[c] += force[c] / n as f64;
                want[3 + c] += moment[c] / n as f64;
            }
        }
        let off = (0..6).map(|k| (f[k] - want[k]).abs()).fold(0.0, f64::max);
        worst = worst.max(off);
    }
    eprintln!("a coupled rod spun level: outward {out:.3} N, worst {worst:.1e}");
    assert!(worst < 1e-9 * wet * 5.0, "{worst:e}");
}

/// In TOML: a rod fixed in a coupled body (`type = "body"`) and a rod of
/// `type = "coupled"` (a coupled body of its own at its end A) both push
/// the host with their wet weight at rest: the body's 6 numbers come
/// first, the coupled rod's next (its body id after the bodies'), the
/// moment of the level rod 2 m aside of the body's reference point
/// (its middle 2 m along x), and of the coupled rod about its end A
/// (its middle 1 m along y), to 1e-9.
#[test]
fn toml_rods_on_and_as_coupled_bodies_push_the_host_by_their_wet_weight() {
    let d = scratch("coupled-rod-toml");
    let scenario = "[water]\ndepth = 30.0\n[[bodies]]\nid = 1\ntype = \"coupled\"\n\
                    position = [0.0, 0.0, -10.0]\n[[rod_types]]\nname = \"can\"\n\
                    diameter = 0.5\nmass_per_length = 100.0\nca = 1.0\n\
                    [[rods]]\nid = 1\ntype = \"body\"\nbody = 1\nrod_type = \"can\"\n\
                    end_a = [1.0, 0.0, 0.0]\nend_b = [3.0, 0.0, 0.0]\n\
                    [[rods]]\nid = 2\ntype = \"coupled\"\nrod_type = \"can\"\n\
                    end_a = [5.0, 0.0, -8.0]\nend_b = [5.0, 2.0, -8.0]\n\
                    [analysis]\ntype = \"static\"\n";
    let sc = write_scenario(&d, "rods.toml", scenario);
    let o = stancf(&["check", sc.to_str().unwrap()]);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o).1);
    assert!(
        text(&o).0.contains("coupled, body 2 (moved by the host"),
        "{}",
        text(&o).0
    );
    let mut c = stancf_cli::coupling::open(&sc).expect("a coupled system");
    assert_eq!(c.handle.coupled_dof(), 12);
    assert_eq!(c.coupled_body_ids, [1, 2]);
    let f = c
        .handle
        .initialize(
            &[
                0.0, 0.0, -10.0, 0.0, 0.0, 0.0, 5.0, 0.0, -8.0, 0.0, 0.0, 0.0,
            ],
            None,
        )
        .unwrap();
    let wet = (200.0 - RHO * PI * 0.0625 * 2.0) * 9.81;
    let want = [
        0.0,
        0.0,
        -wet,
        0.0,
        2.0 * wet,
        0.0, // the body: arm 2 m along x
        0.0,
        0.0,
        -wet,
        -wet,
        0.0,
        0.0, // the coupled rod: arm 1 m along y
    ];
    for k in 0..12 {
        assert!((f[k] - want[k]).abs() < 1e-9 * wet.abs(), "{k}: {f:?}");
    }
}
