//! Claims of linear wave theory and of the combined sea, checked at
//! random points (docs/method.md §12.1).

use super::*;
use crate::water::current::CurrentRow;
use crate::water::spectrum::{Jonswap, SplitMix64};
use std::f64::consts::PI;

const G: f64 = 9.80665;
const DEPTH: f64 = 40.0;
const EPS: f64 = f64::EPSILON;

/// Three waves across each other: k h = 3.3 and 1.6 (intermediate depth)
/// and 40 (the exponential form of (W3)).
fn crossing_waves() -> Vec<AiryWave> {
    vec![
        AiryWave {
            amplitude: 1.5,
            period: 7.0,
            heading_deg: 0.0,
            phase_deg: 20.0,
        },
        AiryWave {
            amplitude: 0.8,
            period: 12.0,
            heading_deg: 75.0,
            phase_deg: -130.0,
        },
        AiryWave {
            amplitude: 0.1,
            period: 2.0,
            heading_deg: -140.0,
            phase_deg: 300.0,
        },
    ]
}

fn current() -> CurrentProfile {
    CurrentProfile::new(&[
        CurrentRow {
            z: -35.0,
            velocity: [0.1, 0.0, 0.0],
        },
        CurrentRow {
            z: -20.0,
            velocity: [0.4, 0.1, 0.01],
        },
        CurrentRow {
            z: -5.0,
            velocity: [0.9, 0.3, -0.02],
        },
    ])
    .unwrap()
}

/// The waves, the current and both ramps (waves over 20 s, current 10 s).
fn full_sea() -> Sea {
    Sea::new(DEPTH, G, &crossing_waves())
        .unwrap()
        .with_wave_ramp(Ramp::new(20.0).unwrap())
        .with_current(current(), Ramp::new(10.0).unwrap())
}

/// Points in the water column, |x|, |y| < 100 m, -h < z < 0.
fn points_in_water(count: usize, seed: u64) -> Vec<[f64; 3]> {
    let mut draw = SplitMix64::new(seed);
    (0..count)
        .map(|_| {
            let x = 200.0 * draw.next_unit() - 100.0;
            let y = 200.0 * draw.next_unit() - 100.0;
            let z = -DEPTH * draw.next_unit();
            [x, y, z]
        })
        .collect()
}

/// A bound on the n-th derivative in space of the waves' velocity
/// (factor 1) or local acceleration (factor w), each space derivative a
/// factor k and |C|, |S| <= coth(k h) (W3)-(W7): sum A w^(1+m) k^n coth(k h).
fn wave_derivative_bound(sea: &Sea, space_order: i32, time_order: i32) -> f64 {
    sea.waves()
        .iter()
        .map(|w| {
            let coth = 1.0 / (w.wave_number * w.depth).tanh();
            w.amplitude * w.omega.powi(1 + time_order) * w.wave_number.powi(space_order) * coth
        })
        .sum()
}

#[test]
fn linear_waves_are_divergence_free_and_irrotational() {
    // div u = 0 and curl u = 0 hold term by term in (W6); the sums cancel
    // to round-off in the largest gradient entry.
    let sea = Sea::new(DEPTH, G, &crossing_waves()).unwrap();
    let tolerance = 16.0 * EPS * wave_derivative_bound(&sea, 1, 0);
    let mut worst: f64 = 0.0;
    for (n, p) in points_in_water(200, 3).iter().enumerate() {
        let grad = sea.kinematics(p, 0.37 * n as f64).velocity_gradient;
        let divergence = grad[0][0] + grad[1][1] + grad[2][2];
        let curl = [
            grad[2][1] - grad[1][2],
            grad[0][2] - grad[2][0],
            grad[1][0] - grad[0][1],
        ];
        assert!(
            divergence.abs() < tolerance,
            "div u = {divergence:e} at {p:?}"
        );
        for c in curl {
            assert!(c.abs() < tolerance, "curl u = {curl:?} at {p:?}");
        }
        worst = worst
            .max(divergence.abs())
            .max(curl.iter().fold(0.0, |m, c| m.max(c.abs())));
    }
    println!("div u, curl u: {worst:.1e} 1/s (bound {tolerance:.1e})");
}

#[test]
fn the_free_surface_moves_with_the_water_at_the_still_water_level() {
    // d eta/dt = u_z at z = 0 (the linear kinematic condition). Central
    // difference in t of step dt: error dt^2/6 sum A w^3 plus round-off.
    let sea = Sea::new(DEPTH, G, &crossing_waves()).unwrap();
    let dt = 1e-4;
    let amplitudes: f64 = sea.waves().iter().map(|w| w.amplitude).sum();
    let cubes: f64 = sea
        .waves()
        .iter()
        .map(|w| w.amplitude * w.omega.powi(3))
        .sum();
    let tolerance = dt * dt / 6.0 * cubes + 8.0 * EPS * amplitudes / dt;
    let mut worst: f64 = 0.0;
    for (n, p) in points_in_water(50, 5).iter().enumerate() {
        let surface = [p[0], p[1], 0.0];
        let t = 1.3 * n as f64;
        let rate = (sea.kinematics(&surface, t + dt).eta - sea.kinematics(&surface, t - dt).eta)
            / (2.0 * dt);
        let u_z = sea.kinematics(&surface, t).velocity[2];
        assert!(
            (rate - u_z).abs() < tolerance,
            "{rate} vs {u_z} ({tolerance:e})"
        );
        worst = worst.max((rate - u_z).abs());
    }
    println!("d eta/dt - u_z at z = 0: {worst:.1e} m/s (bound {tolerance:.1e})");
}

#[test]
fn the_water_does_not_cross_the_seabed() {
    // S(-h) = sinh(0) = 0 in (W4): u_z vanishes on the seabed, both forms
    // of (W3) exactly.
    let sea = Sea::new(DEPTH, G, &crossing_waves()).unwrap();
    for (n, p) in points_in_water(50, 7).iter().enumerate() {
        let bottom = [p[0], p[1], -DEPTH];
        let k = sea.kinematics(&bottom, 0.9 * n as f64);
        assert!(k.velocity[2].abs() < 4.0 * EPS * wave_derivative_bound(&sea, 0, 0));
        assert!(k.velocity[0].abs() + k.velocity[1].abs() > 0.0);
    }
}

#[test]
fn the_acceleration_is_the_time_derivative_of_the_velocity() {
    // Through both ramps (t in [0, 30] s): a = d u/dt (W12), central
    // difference of step dt. |d^3 (r u)/dt^3| <= (w + pi/T)^3 |u| per wave
    // (|r^(n)| <= (pi/T)^n / 2 (W11)); the current's is r''' U.
    let sea = full_sea();
    let dt = 1e-4;
    let truncation: f64 = sea
        .waves()
        .iter()
        .map(|w| {
            let coth = 1.0 / (w.wave_number * w.depth).tanh();
            (w.omega + PI / 20.0).powi(3) * w.amplitude * w.omega * coth
        })
        .sum::<f64>()
        + (PI / 10.0f64).powi(3);
    let size = wave_derivative_bound(&sea, 0, 0) + 1.0;
    let tolerance = dt * dt / 6.0 * truncation + 8.0 * EPS * size / dt;
    let mut worst: f64 = 0.0;
    for (n, p) in points_in_water(100, 11).iter().enumerate() {
        let t = 0.3 * n as f64 + 0.05;
        let up = sea.kinematics(p, t + dt).velocity;
        let down = sea.kinematics(p, t - dt).velocity;
        let a = sea.kinematics(p, t).acceleration;
        for i in 0..3 {
            let rate = (up[i] - down[i]) / (2.0 * dt);
            assert!(
                (rate - a[i]).abs() < tolerance,
                "t {t} i {i}: {rate} vs {}",
                a[i]
            );
            worst = worst.max((rate - a[i]).abs());
        }
    }
    println!("acceleration against d u/dt: {worst:.1e} m/s^2 (bound {tolerance:.1e})");
}

/// Central differences in x_j of the velocity and the acceleration at
/// `p`, against the gradients, to `tolerance`; the largest differences.
fn check_gradients(sea: &Sea, p: &[f64; 3], t: f64, step: f64, tolerance: [f64; 2]) -> [f64; 2] {
    let k = sea.kinematics(p, t);
    let mut worst = [0.0f64; 2];
    for j in 0..3 {
        let (mut plus, mut minus) = (*p, *p);
        plus[j] += step;
        minus[j] -= step;
        let (up, down) = (sea.kinematics(&plus, t), sea.kinematics(&minus, t));
        for i in 0..3 {
            let du = (up.velocity[i] - down.velocity[i]) / (2.0 * step);
            let da = (up.acceleration[i] - down.acceleration[i]) / (2.0 * step);
            let (gu, ga) = (k.velocity_gradient[i][j], k.acceleration_gradient[i][j]);
            assert!(
                (du - gu).abs() < tolerance[0],
                "du{i}/dx{j} at {p:?} t {t}: {du} vs {gu}"
            );
            assert!(
                (da - ga).abs() < tolerance[1],
                "da{i}/dx{j} at {p:?} t {t}: {da} vs {ga}"
            );
            worst = [worst[0].max((du - gu).abs()), worst[1].max((da - ga).abs())];
        }
    }
    worst
}

#[test]
fn the_gradients_are_the_derivatives_of_the_velocity_and_acceleration() {
    // Waves, current and ramps: a central difference of step h errs by
    // h^2/6 |f'''| <= h^2/6 sum (w + pi/T) A w k^3 coth(kh) (W6)-(W7),
    // the current's being linear between rows (exact), plus round-off
    // eps (|f| + |x| |grad f|) / h.
    let sea = full_sea();
    let step = 1e-4;
    // |x| < 150 m, the largest k is 1.01 rad/m; the current is < 1 m/s.
    let ramp_rate = PI / 20.0;
    let roundoff = |size: f64| 8.0 * EPS * size * (1.0 + 150.0 * 1.01) / step;
    let velocity_size = wave_derivative_bound(&sea, 0, 0) + 1.0;
    let acceleration_size = wave_derivative_bound(&sea, 0, 1) + ramp_rate * velocity_size;
    let tolerance = [
        step * step / 6.0 * wave_derivative_bound(&sea, 3, 0) + roundoff(velocity_size),
        step * step / 6.0
            * (wave_derivative_bound(&sea, 3, 1) + ramp_rate * wave_derivative_bound(&sea, 3, 0))
            + roundoff(acceleration_size),
    ];
    let rows = [-35.0, -20.0, -5.0];
    let mut worst = [0.0f64; 2];
    for (n, p) in points_in_water(150, 13).iter().enumerate() {
        let mut p = *p;
        if rows.iter().any(|r| (p[2] - r).abs() < 0.5) {
            p[2] += 1.0;
        }
        let errors = check_gradients(&sea, &p, 0.2 * n as f64, step, tolerance);
        worst = [worst[0].max(errors[0]), worst[1].max(errors[1])];
    }
    println!(
        "gradients by central differences: velocity {:.1e} (bound {:.1e}), acceleration {:.1e} (bound {:.1e})",
        worst[0], tolerance[0], worst[1], tolerance[1]
    );
    // In a crest (z > 0) and below the seabed the flow is that at z = 0 or
    // z = -h (W8), constant in z: the z column is zero there, as its
    // difference.
    for (n, p) in points_in_water(20, 17).iter().enumerate() {
        for z in [0.7, -DEPTH - 0.3] {
            check_gradients(&sea, &[p[0], p[1], z], 25.0 + n as f64, step, tolerance);
        }
    }
}

#[test]
fn a_point_in_a_crest_sees_the_flow_at_the_still_water_level() {
    let sea = Sea::new(DEPTH, G, &crossing_waves()).unwrap();
    let (above, at) = (
        sea.kinematics(&[3.0, -4.0, 1.2], 5.0),
        sea.kinematics(&[3.0, -4.0, 0.0], 5.0),
    );
    assert_eq!(above.velocity, at.velocity);
    assert_eq!(above.acceleration, at.acceleration);
    assert_eq!(above.eta, at.eta);
}

#[test]
fn the_ramp_starts_the_sea_from_rest_and_then_lets_it_be() {
    let ramped = full_sea();
    let unramped = Sea::new(DEPTH, G, &crossing_waves())
        .unwrap()
        .with_current(current(), Ramp::NONE);
    for p in points_in_water(20, 19) {
        let start = ramped.kinematics(&p, 0.0);
        assert_eq!(
            (start.eta, start.velocity, start.velocity_gradient),
            (0.0, [0.0; 3], [[0.0; 3]; 3])
        );
        // r(0) = r'(0) = 0: the acceleration starts from zero too (W11).
        assert_eq!(start.acceleration, [0.0; 3]);
        // After both ramps, the sea without ramps.
        for t in [20.0, 31.5] {
            assert_eq!(ramped.kinematics(&p, t), unramped.kinematics(&p, t));
        }
        // Half-way through the wave ramp, r = 1/2 exactly.
        let (half, full) = (ramped.kinematics(&p, 10.0), unramped.kinematics(&p, 10.0));
        assert!((half.eta - 0.5 * full.eta).abs() < 4.0 * EPS * full.eta.abs().max(1.0));
    }
}

#[test]
fn still_water_does_not_move() {
    let sea = Sea::still(100.0, G);
    let k = sea.kinematics(&[1.0, 2.0, -30.0], 12.0);
    assert_eq!(k, FluidKinematics::default());
}

#[test]
fn an_irregular_sea_is_a_sea_of_its_components() {
    // The JONSWAP components evaluate as any waves; a sea of them keeps
    // the identities of linear theory (spot check: divergence).
    let spectrum = Jonswap {
        hs: 3.0,
        tp: 9.0,
        gamma: 3.3,
        heading_deg: 45.0,
        seed: 5,
        components: 60,
    };
    let sea = Sea::new(DEPTH, G, &spectrum.waves().unwrap()).unwrap();
    let tolerance = 64.0 * EPS * wave_derivative_bound(&sea, 1, 0);
    for p in points_in_water(20, 23) {
        let grad = sea.kinematics(&p, 4.0).velocity_gradient;
        assert!((grad[0][0] + grad[1][1] + grad[2][2]).abs() < tolerance);
    }
}

#[test]
fn a_sea_that_cannot_be_is_refused_naming_what_is_wrong() {
    let waves = crossing_waves();
    assert_eq!(Sea::new(0.0, G, &waves).unwrap_err().key, "depth");
    assert_eq!(Sea::new(-5.0, G, &waves).unwrap_err().key, "depth");
    assert_eq!(Sea::new(DEPTH, -G, &waves).unwrap_err().key, "gravity");
    let mut bad = waves.clone();
    bad[2].period = -1.0;
    assert_eq!(Sea::new(DEPTH, G, &bad).unwrap_err().key, "waves[2].period");
    bad[2].period = 2.0;
    bad[1].heading_deg = f64::NAN;
    assert_eq!(
        Sea::new(DEPTH, G, &bad).unwrap_err().key,
        "waves[1].heading_deg"
    );
}

#[test]
fn a_sea_can_be_shared_between_threads() {
    fn shareable<T: Clone + std::fmt::Debug + Send + Sync>(sea: &T) -> T {
        sea.clone()
    }
    let sea = full_sea();
    let copy = std::thread::spawn(move || shareable(&sea).kinematics(&[1.0, 2.0, -3.0], 4.0))
        .join()
        .unwrap();
    assert_eq!(copy, full_sea().kinematics(&[1.0, 2.0, -3.0], 4.0));
}

/// The waves' dynamic pressure (W8a) is -rho dPhi/dt: its gradient is minus
/// the local acceleration, under a ramp too (W12a: the ramp's share
/// -r' Phi), and it is the gradient's integral (central differences of
/// the pressure, to 1e-7 of the acceleration's size); a steady current
/// adds none.
#[test]
fn the_dynamic_pressure_drives_the_local_acceleration() {
    let sea = Sea::new(DEPTH, G, &crossing_waves())
        .unwrap()
        .with_wave_ramp(Ramp::new(20.0).unwrap())
        .with_current(current(), Ramp::NONE);
    let mut rng = SplitMix64::new(11);
    for _ in 0..200 {
        let x = [
            100.0 * (rng.next_unit() - 0.5),
            100.0 * (rng.next_unit() - 0.5),
            -DEPTH * rng.next_unit(),
        ];
        let t = 30.0 * rng.next_unit();
        let k = sea.kinematics(&x, t);
        let size = k.acceleration.iter().fold(1.0f64, |m, a| m.max(a.abs()));
        let h = 1e-5;
        for j in 0..3 {
            assert!(
                (k.pressure_gradient[j] + k.acceleration[j]).abs() < 1e-12 * size,
                "{x:?} {t}: {:?} {:?}",
                k.pressure_gradient,
                k.acceleration
            );
            let (mut p, mut m) = (x, x);
            p[j] += h;
            m[j] -= h;
            let fd = (sea.kinematics(&p, t).pressure - sea.kinematics(&m, t).pressure) / (2.0 * h);
            assert!((fd - k.pressure_gradient[j]).abs() < 1e-7 * size, "{fd}");
        }
    }
}

/// Still water may be without gravity (MoorDyn's g = 0); waves may not
/// (their dispersion (W1) needs it): refused naming `gravity`.
#[test]
fn still_water_may_be_weightless_waves_may_not() {
    assert!(Sea::new(DEPTH, 0.0, &[]).is_ok());
    let e = Sea::new(DEPTH, 0.0, &crossing_waves()).unwrap_err();
    assert_eq!(e.key, "gravity");
    assert!(Sea::new(DEPTH, -1.0, &[]).is_err());
}

/// A current on a grid in x, z and t (W9a), started by a ramp of 10 s:
/// its acceleration is the time derivative of its velocity (W12) and its
/// gradients the derivatives in space, by central differences inside
/// the grid's cells (the field is linear along each axis there, so a
/// difference errs by the ramp's h^2/6 |r'''| |U| < 1e-10 and round-off
/// 8 eps |U| / h < 1e-11); statics sees it as it is at t = 0.
#[test]
fn a_current_on_a_grid_is_consistent_in_time_and_space() {
    use crate::water::current_grid::CurrentGrid;
    let axes = [
        vec![-20.0, 30.0],
        vec![0.0],
        vec![-DEPTH, -10.0, 0.0],
        vec![0.0, 12.0, 30.0],
    ];
    let mut velocity = Vec::new();
    for x in &axes[0] {
        for z in &axes[2] {
            for t in &axes[3] {
                velocity.push([0.4 + 0.01 * x + 0.002 * z * t, -0.2 + 0.01 * t, 0.001 * x]);
            }
        }
    }
    let grid = CurrentGrid::new(axes, velocity).unwrap();
    let sea = Sea::still(DEPTH, 9.81).with_current_grid(grid.clone(), Ramp::new(10.0).unwrap());
    let h = 1e-4;
    for (p, t) in [
        ([3.0, 1.0, -22.0], 4.0),
        ([-11.0, -5.0, -4.5], 17.5),
        ([25.0, 0.0, -1.0], 29.0),
    ] {
        let k = sea.kinematics(&p, t);
        let (up, down) = (sea.kinematics(&p, t + h), sea.kinematics(&p, t - h));
        for i in 0..3 {
            let rate = (up.velocity[i] - down.velocity[i]) / (2.0 * h);
            assert!(
                (rate - k.acceleration[i]).abs() < 1e-9,
                "t {t}: {rate} vs {k:?}"
            );
        }
        check_gradients(&sea, &p, t, h, [1e-9, 1e-9]);
        let statics = sea.steady_current(&p);
        assert_eq!(statics.velocity, grid.sample(&p, 0.0).velocity);
        assert_eq!(statics.acceleration, [0.0; 3]);
    }
}
