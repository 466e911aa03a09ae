//! MoorDyn's CoupledPinned body (docs/method.md §15.17): its reference
//! point moved by the host, free to turn about it; 3 numbers among the
//! coupled bodies' in the coupling arrays.

use crate::common::*;

/// A deck of a CoupledPinned body at (0, 0, -5) carrying a can (2 m
/// across, 10 m long, 5 t/m, no drag, Ca and CaEnd 1) from 5 m to 15 m
/// under its reference point, nothing else (MoorDyn's
/// body_tests/pinnedBody.txt in water).
const PINNED_BODY: &str = include_str!("../fixtures/coupled-pinned-can-moordyn.txt");

/// `check` says what holds the body (3 degrees of freedom about the
/// host's point); the static run hangs the can under it and the host's
/// point carries its weight less its buoyancy, -(m - rho V) g (points.csv);
/// through the coupling API the body takes 3 numbers (MoorDyn's Step
/// reads 3 for a CoupledPinned body), `initialize` returns that pull, and
/// as the host lifts the body at a = 2 m/s^2 from rest the can, hanging
/// plumb, pulls -((m + m_a) a + (m - rho V) g), m_a = 2 rho CaEnd
/// pi d^3 / 12 its caps' added mass along it (B18), each interval's mean
/// to 1e-9 of it (B35).
#[test]
fn a_coupled_pinned_body_hangs_from_the_host_and_pulls_it() {
    let d = scratch("coupled-pinned");
    let deck = write_scenario(&d, "pinned.txt", PINNED_BODY);
    let o = stancf(&["check", deck.to_str().unwrap()]);
    let so = text(&o).0;
    assert_eq!(o.status.code(), Some(0), "{}", text(&o).1);
    assert!(
        so.contains("pinned to the host (3 degrees of freedom, turning about its reference point on point 1")
            && so.contains("less 3 per pinned body (1)"),
        "{so}"
    );
    let out = d.join("out");
    let o = run_quiet(&deck, &out, &[]);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o).1);
    let g = 9.80665;
    let (mass, displaced) = (50_000.0, 1025.0 * std::f64::consts::PI * 10.0);
    let hanging = -(mass - displaced) * g;
    let (header, rows) = read_csv(&out.join("points.csv"));
    let fz = rows[0][header.iter().position(|h| h == "fz").unwrap()];
    assert!(
        (fz - hanging).abs() < 1e-9 * hanging.abs(),
        "{fz} {hanging}"
    );
    let mut c = stancf_cli::coupling::open(&deck).expect("a coupled system");
    assert_eq!(c.coupled_body_ids, [1]);
    assert!(c.coupled_ids.is_empty(), "{:?}", c.coupled_ids);
    assert_eq!(c.handle.coupled_dof(), 3);
    let at = |t: f64| [0.0, 0.0, -5.0 + t * t];
    let rate = |t: f64| [0.0, 0.0, 2.0 * t];
    let f0 = c
        .handle
        .initialize(&at(0.0), Some(&rate(0.0)))
        .expect("equilibrium");
    assert!((f0[2] - hanging).abs() < 1e-9 * hanging.abs(), "{f0:?}");
    let added = 2.0 * 1025.0 * std::f64::consts::PI * 8.0 / 12.0;
    let lifted = -((mass + added) * 2.0 + (mass - displaced) * g);
    let worst = worst_interval_mean(
        &mut c.handle,
        |t| at(t).to_vec(),
        |t| rate(t).to_vec(),
        |f| vertical_miss(f, lifted),
    );
    eprintln!(
        "a CoupledPinned body: hangs by {hanging:.3} N, lifted pulls {lifted:.3} N to {worst:.1e}"
    );
    assert!(worst < 1e-9 * lifted.abs(), "{worst:e}");
}

/// MoorDyn's body_tests/pinnedBody.txt leaves the water out with
/// `WtrDnsty 0`: the water then has no weight, drag or inertia (the
/// seabed stays), and the pinned body's pull on the host is its whole
/// weight, -m g, to 1e-9 of it.
#[test]
fn a_deck_without_water_density_hangs_its_whole_weight_on_the_host() {
    let d = scratch("coupled-pinned-dry");
    let dry = PINNED_BODY.replace(
        "30       WtrDpth      - water depth\n",
        "30       WtrDpth      - water depth\n0.0      WtrDnsty     - no water\n",
    );
    assert_ne!(dry, PINNED_BODY);
    let deck = write_scenario(&d, "dry.txt", &dry);
    let out = d.join("out");
    let o = run_quiet(&deck, &out, &[]);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o).1);
    let (header, rows) = read_csv(&out.join("points.csv"));
    let fz = rows[0][header.iter().position(|h| h == "fz").unwrap()];
    let weight = 50_000.0 * 9.80665;
    assert!((fz + weight).abs() < 1e-9 * weight, "{fz}");
}

/// MoorDyn's rotations/nwu.txt: a coupled body with points 1 m along x,
/// y and z, no line, no gravity (`g 0`). Through the coupling API each of
/// MoorDyn's angles turns the body as its test says (the EulerXYZ of
/// docs/method.md §15.1): a roll of 90 degrees takes the port point
/// (+y) up, a pitch of 90 degrees the bow (+x) down, a yaw of 90 degrees
/// the bow to port; the points where the pose puts them, to 1e-12 m.
#[test]
fn moordyns_rotations_test_turns_the_body_as_it_says() {
    let d = scratch("nwu");
    let deck = "--------------------- MoorDyn Input File ----------------------------------------
The rotations of a coupled body, no gravity
---------------------------- BODIES ---------------------------------------------
ID  Attachment  X0  Y0  Z0  r0  p0  y0  Mass  CG*  I*  Volume  CdA*  Ca
(#) (-)         (m) (m) (m) (deg)(deg)(deg)(kg)(m) (kg-m^2)(m^3) (m^2) (-)
1   coupled     0   0   0   0   0   0   0     0    0   0       0     0
----------------------- POINTS --------------------------------------------------
Node  Type   X  Y  Z  M  V  CdA  CA
(-)   (-)   (m)(m)(m)(kg)(m^3)(m^2)(-)
1     Body1  1  0  0  0  0  0    0
2     Body1  0  1  0  0  0  0    0
3     Body1  0  0  1  0  0  0    0
-------------------------- SOLVER OPTIONS----------------------------------------
0.0      g            - No gravity
1.0      dtM          - time step
100      WtrDpth      - water depth
--------------------------- need this line -------------------------------------
";
    let file = write_scenario(&d, "nwu.txt", deck);
    let half = std::f64::consts::FRAC_PI_2;
    for (angles, point, want) in [
        ([half, 0.0, 0.0], 1, [0.0, 0.0, 1.0]),
        ([0.0, half, 0.0], 0, [0.0, 0.0, -1.0]),
        ([0.0, 0.0, half], 0, [0.0, 1.0, 0.0]),
    ] {
        let mut c = stancf_cli::coupling::open(&file).expect("a coupled system");
        let x = [0.0, 0.0, 0.0, angles[0], angles[1], angles[2]];
        let f = c.handle.initialize(&x, None).expect("initialize");
        assert!(f.iter().all(|v| *v == 0.0), "{f:?}");
        let at = c.handle.simulation().unwrap().point_state(point).0;
        for k in 0..3 {
            assert!(
                (at[k] - want[k]).abs() < 1e-12,
                "{angles:?}: {at:?} against {want:?}"
            );
        }
    }
}

/// [`PINNED_BODY`]'s can as MoorDyn's CoupledPinned rod: its end A moved
/// by the host, the rod turning freely about it, in place of the body;
/// with `and_body` the body (its can fixed in it, now 20 m aside) is kept
/// too.
fn pinned_rod_deck(and_body: bool) -> String {
    let rod = "1    Can      CoupledPinned  0     0     -5    0     0     -15   3        -";
    if and_body {
        let body = PINNED_BODY.replace(
            "1    CoupledPinned    0.00  0.00  -5.00",
            "1    CoupledPinned    20.0  0.00  -5.00",
        );
        let both = body.replace(
            "1    Can      Body1       0     0     -5    0     0     -15   3        -",
            &format!(
                "1    Can      Body1       0     0     -5    0     0     -15   3        -\n{}",
                rod.replacen("1 ", "2 ", 1)
            ),
        );
        assert_ne!(both, body);
        return both;
    }
    let start = PINNED_BODY.find("---------------------- BODIES").unwrap();
    let end = PINNED_BODY.find("---------------------- RODS").unwrap();
    let without_body = format!("{}{}", &PINNED_BODY[..start], &PINNED_BODY[end..]);
    without_body.replace(
        "1    Can      Body1       0     0     -5    0     0     -15   3        -",
        rod,
    )
}

/// A CoupledPinned rod (MoorDyn's RODS `CoupledPinned`, docs/method.md
/// §15.17) hangs from the host's point as the CoupledPinned body with the
/// same can does: `check` says so, the static pull is -(m - rho V) g, the
/// coupling arrays hold its 3 numbers (MoorDyn's Step reads 3 for a
/// pinned coupled rod), and lifted at a = 2 m/s^2 it pulls
/// -((m + m_a) a + (m - rho V) g), each interval's mean to 1e-9. With the
/// body kept, the arrays hold the body's 3 numbers, then the rod's
/// (MoorDyn's order: coupled bodies, then coupled rods), each moving its
/// own: the rod lifted pulls as alone while the held body hangs.
#[test]
fn a_coupled_pinned_rod_hangs_from_the_host_and_pulls_it() {
    let d = scratch("coupled-pinned-rod");
    let g = 9.80665;
    let (mass, displaced) = (50_000.0, 1025.0 * std::f64::consts::PI * 10.0);
    let hanging = -(mass - displaced) * g;
    let added = 2.0 * 1025.0 * std::f64::consts::PI * 8.0 / 12.0;
    let lifted = -((mass + added) * 2.0 + (mass - displaced) * g);
    let deck = write_scenario(&d, "rod.txt", &pinned_rod_deck(false));
    let o = stancf(&["check", deck.to_str().unwrap()]);
    let so = text(&o).0;
    assert_eq!(o.status.code(), Some(0), "{}", text(&o).1);
    assert!(
        so.contains("pinned at end A to point 1 (coupled, moved by the host;")
            && so.contains("less 3 per pinned body (1)"),
        "{so}"
    );
    let out = d.join("out");
    let o = run_quiet(&deck, &out, &[]);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o).1);
    let (header, rows) = read_csv(&out.join("points.csv"));
    let fz = rows[0][header.iter().position(|h| h == "fz").unwrap()];
    assert!(
        (fz - hanging).abs() < 1e-9 * hanging.abs(),
        "{fz} {hanging}"
    );
    for and_body in [false, true] {
        let deck = write_scenario(
            &d,
            &format!("rod-{and_body}.txt"),
            &pinned_rod_deck(and_body),
        );
        let mut c = stancf_cli::coupling::open(&deck).expect("a coupled system");
        let width = if and_body { 6 } else { 3 };
        assert_eq!(c.handle.coupled_dof(), width, "{and_body}");
        assert_eq!(
            c.coupled_body_ids,
            if and_body { vec![1, 2] } else { vec![1] }
        );
        // The body held at its pin (20, 0, -5); the rod's end A lifted.
        let at = |t: f64| {
            let rod = [0.0, 0.0, -5.0 + t * t];
            if and_body {
                [&[20.0, 0.0, -5.0][..], &rod[..]].concat()
            } else {
                rod.to_vec()
            }
        };
        let rate = |t: f64| {
            let rod = [0.0, 0.0, 2.0 * t];
            if and_body {
                [&[0.0; 3][..], &rod[..]].concat()
            } else {
                rod.to_vec()
            }
        };
        let f0 = c
            .handle
            .initialize(&at(0.0), Some(&rate(0.0)))
            .expect("equilibrium");
        for k in (0..width).step_by(3) {
            assert!((f0[k + 2] - hanging).abs() < 1e-9 * hanging.abs(), "{f0:?}");
        }
        let worst = worst_interval_mean(&mut c.handle, at, rate, |f| {
            let body = if and_body {
                vertical_miss(f, hanging)
            } else {
                0.0
            };
            vertical_miss(&f[width - 3..], lifted).max(body)
        });
        eprintln!(
            "a CoupledPinned rod (body too: {and_body}): lifted pulls {lifted:.3} N to {worst:.1e}"
        );
        assert!(worst < 1e-9 * lifted.abs(), "{and_body}: {worst:e}");
    }
}

/// The TOML spelling, `type = "coupled_pinned"`: the rod's end A on a
/// coupled point made there (its id after the `[[points]]`), 3 coupled
/// numbers, and at rest the host's point carries its wet weight.
#[test]
fn a_toml_coupled_pinned_rod_hangs_from_a_coupled_point() {
    let d = scratch("coupled-pinned-toml");
    let scenario = "[water]\ndepth = 30.0\n[[rod_types]]\nname = \"can\"\ndiameter = 2.0\n\
                    mass_per_length = 5000.0\nca_end = 1.0\n[[rods]]\nid = 1\n\
                    type = \"coupled_pinned\"\nrod_type = \"can\"\nend_a = [0.0, 0.0, -5.0]\n\
                    end_b = [0.0, 0.0, -15.0]\nsegments = 3\n[analysis]\ntype = \"static\"\n";
    let sc = write_scenario(&d, "rod.toml", scenario);
    let o = stancf(&["check", sc.to_str().unwrap()]);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o).1);
    assert!(
        text(&o).0.contains("(coupled, moved by the host;"),
        "{}",
        text(&o).0
    );
    let out = d.join("out");
    let o = run_quiet(&sc, &out, &[]);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o).1);
    let (header, rows) = read_csv(&out.join("points.csv"));
    let fz = rows[0][header.iter().position(|h| h == "fz").unwrap()];
    let hanging = -(50_000.0 - 1025.0 * std::f64::consts::PI * 10.0) * 9.81;
    assert!(
        (fz - hanging).abs() < 1e-9 * hanging.abs(),
        "{fz} {hanging}"
    );
    let c = stancf_cli::coupling::open(&sc).expect("a coupled system");
    assert_eq!(c.handle.coupled_dof(), 3);
}
