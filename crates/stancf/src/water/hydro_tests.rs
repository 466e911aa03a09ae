//! The water's force on a line (W18)-(W23): its values against the
//! formulas' limits and its derivatives against central differences.

use super::*;
use crate::water::current::{CurrentProfile, CurrentRow, Ramp};
use crate::water::waves::AiryWave;

const G: [f64; 3] = [0.0, 0.0, -9.81];

fn water(sea: Sea) -> Arc<Water> {
    Arc::new(Water {
        density: 1025.0,
        sea,
    })
}

fn morison() -> Morison {
    Morison {
        diameter: 0.3,
        cd_normal: 1.2,
        cd_axial: 0.4,
        ca_normal: 1.0,
        ca_axial: 0.5,
    }
}

/// Two crossing waves, ramped, over a sheared current, ramped.
fn rough_sea() -> Sea {
    let waves = [
        AiryWave {
            amplitude: 0.8,
            period: 6.0,
            heading_deg: 20.0,
            phase_deg: 40.0,
        },
        AiryWave {
            amplitude: 0.3,
            period: 3.5,
            heading_deg: -70.0,
            phase_deg: 0.0,
        },
    ];
    let current = CurrentProfile::new(&[
        CurrentRow {
            z: -30.0,
            velocity: [0.1, 0.05, 0.0],
        },
        CurrentRow {
            z: 0.0,
            velocity: [0.6, -0.2, 0.01],
        },
    ])
    .unwrap();
    Sea::new(30.0, 9.81, &waves)
        .unwrap()
        .with_wave_ramp(Ramp::new(8.0).unwrap())
        .with_current(current, Ramp::new(5.0).unwrap())
}

#[test]
fn a_submerged_line_is_buoyed_by_the_weight_of_the_water_it_displaces() {
    let line = LineInWater::new(water(Sea::still(50.0, 9.81)), morison());
    let f = line.force(&[1.0, 2.0, -10.0], &[1.0, 0.0, 0.0], &[0.0; 3], 3.0, &G);
    let expected = 1025.0 * morison().area() * 9.81;
    assert_eq!(f.force[0], 0.0);
    assert!((f.force[2] - expected).abs() < 1e-12 * expected);
    // Dry above the surface band.
    let dry = line.force(&[0.0, 0.0, 0.2], &[1.0, 0.0, 0.0], &[1.0; 3], 0.0, &G);
    assert_eq!(dry, ForceAtPoint::default());
}

#[test]
fn normal_and_axial_drag_follow_moordyn_conventions() {
    // Still water, a line along x moving at (2, 3, 0): axial speed 2, normal 3.
    let line = LineInWater::new(water(Sea::still(50.0, 9.81)), morison());
    let no_gravity = [0.0; 3];
    let f = line.force(
        &[0.0, 0.0, -5.0],
        &[1.0, 0.0, 0.0],
        &[2.0, 3.0, 0.0],
        0.0,
        &no_gravity,
    );
    let m = morison();
    let normal = -0.5 * 1025.0 * m.cd_normal * m.diameter * 3.0 * 3.0;
    let axial = -0.5 * 1025.0 * m.cd_axial * std::f64::consts::PI * m.diameter * 2.0 * 2.0;
    assert!((f.force[1] - normal).abs() < 1e-12 * normal.abs());
    assert!((f.force[0] - axial).abs() < 1e-12 * axial.abs());
}

/// Central differences of the force in r, r_x and r_dot against its
/// derivatives: the error of a step h is O(h^2 f''') plus the drag's kink
/// at zero relative speed, avoided here.
fn check_derivatives(line: &LineInWater, r: [f64; 3], rx: [f64; 3], rdot: [f64; 3], t: f64) {
    let f = line.force(&r, &rx, &rdot, t, &G);
    let scale = f.force.iter().map(|c| c.abs()).fold(1.0, f64::max);
    let h = 1e-6;
    for j in 0..3 {
        for (which, exact) in [("r", f.d_r), ("r_x", f.d_rx), ("r_dot", f.d_rdot)] {
            let shifted = |sign: f64| {
                let (mut a, mut b, mut c) = (r, rx, rdot);
                match which {
                    "r" => a[j] += sign * h,
                    "r_x" => b[j] += sign * h,
                    _ => c[j] += sign * h,
                }
                line.force(&a, &b, &c, t, &G).force
            };
            let (plus, minus) = (shifted(1.0), shifted(-1.0));
            for i in 0..3 {
                let fd = (plus[i] - minus[i]) / (2.0 * h);
                assert!(
                    (fd - exact[i][j]).abs() < 1e-6 * scale,
                    "d f_{i} / d {which}_{j} at z {}: exact {} fd {fd}",
                    r[2],
                    exact[i][j]
                );
            }
        }
    }
}

#[test]
fn the_force_derivatives_match_finite_differences_in_waves_and_current() {
    let line = LineInWater::new(water(rough_sea()), morison());
    let rx = [0.8, -0.3, 0.55];
    let rdot = [0.3, -0.4, 0.2];
    // Deep, in the surface band (partly submerged), and mid-ramp.
    for (r, t) in [
        ([3.0, -1.0, -7.0], 9.0),
        ([3.0, -1.0, -0.05], 9.0),
        ([-2.0, 4.0, 0.08], 2.5),
        ([1.0, 1.0, -20.0], 4.0),
    ] {
        check_derivatives(&line, r, rx, rdot, t);
    }
}

#[test]
fn the_static_force_is_buoyancy_and_the_steady_current_at_full_strength() {
    let line = LineInWater::new(water(rough_sea()), morison());
    let r = [0.0, 0.0, -15.0];
    let rx = [0.0, 0.0, 1.0];
    // The current ramps over 5 s and the waves over 8 s: at t = 100 the
    // waves are whole; take them out to compare.
    let current_only = Sea::still(30.0, 9.81).with_current(
        rough_sea().current().unwrap().clone(),
        Ramp::new(5.0).unwrap(),
    );
    let dynamic = LineInWater::new(water(current_only), morison());
    let a = line.static_force(&r, &rx, &G);
    let b = dynamic.force(&r, &rx, &[0.0; 3], 100.0, &G);
    for i in 0..3 {
        assert!((a.force[i] - b.force[i]).abs() < 1e-12 * b.force[2].abs());
    }
}
