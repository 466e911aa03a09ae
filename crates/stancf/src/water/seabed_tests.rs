//! Checks of the seabed contact (W40)-(W48) and its bathymetry (W40b)-(W46a).

use super::*;
use std::sync::Arc;

/// The plane of a plane bed: its point and unit normal.
fn plane_of(c: &SeabedContact) -> ([f64; 3], [f64; 3]) {
    match &c.seabed.surface {
        BedSurface::Plane { point, normal } => (*point, *normal),
        BedSurface::Grid(_) => panic!("a plane bed"),
    }
}

fn bed() -> SeabedContact {
    SeabedContact {
        seabed: Seabed::plane([0.3, 0.0, -50.0], [0.1, -0.2, 1.0], 3e6, 3e5)
            .with_friction(0.6, 1.0, 0.05),
        diameter: 0.08,
    }
}

/// Central differences of `force` in argument `which` (r, r_x, r_dot)
/// against the analytic derivative, to 1e-6 of the largest derivative
/// (step h: round-off eps |f| / h and truncation h^2 f''' are both
/// below 1e-9 of it for these magnitudes; P is quadratic in the ramp).
fn check(c: &SeabedContact, args: [[f64; 3]; 3], which: usize, h: f64) {
    let f0 = c.force(&args[0], &args[1], &args[2]);
    let analytic = [f0.d_r, f0.d_rx, f0.d_rdot][which];
    let scale = [f0.d_r, f0.d_rx, f0.d_rdot]
        .iter()
        .flatten()
        .flatten()
        .fold(0.0f64, |m, x| m.max(x.abs()));
    for j in 0..3 {
        let (mut plus, mut minus) = (args, args);
        plus[which][j] += h;
        minus[which][j] -= h;
        let fp = c.force(&plus[0], &plus[1], &plus[2]).force;
        let fm = c.force(&minus[0], &minus[1], &minus[2]).force;
        for i in 0..3 {
            let fd = (fp[i] - fm[i]) / (2.0 * h);
            assert!(
                (fd - analytic[i][j]).abs() <= 1e-6 * scale + 1e-9,
                "arg {which} d f{i}/d x{j}: fd {fd} analytic {}",
                analytic[i][j]
            );
        }
    }
}

/// [`check`] of all three arguments at r, `below` in the bed, with the
/// line's tangent and velocity of these checks; the step 1e-8 within the
/// ramp (P is quadratic there), 1e-6 beyond.
fn check_at_depth(c: &SeabedContact, r: [f64; 3], below: f64) {
    assert!((c.seabed.penetration(&r) - below).abs() < 1e-12);
    let h = if below.abs() < c.ramp_width() {
        1e-8
    } else {
        1e-6
    };
    for which in 0..3 {
        check(c, [r, [0.8, 0.5, -0.1], [0.03, -0.02, -0.01]], which, h);
    }
}

#[test]
fn the_contact_force_derivatives_match_finite_differences() {
    let c = bed();
    let (point, n) = plane_of(&c);
    // Deep in the bed, in the ramp, and clear of it.
    for below in [0.01, 0.3 * c.ramp_width(), -0.01] {
        let along = [0.4, 0.9, 0.0];
        let along_n = dot(along, n);
        let r: [f64; 3] =
            std::array::from_fn(|i| point[i] + along[i] - along_n * n[i] - below * n[i]);
        check_at_depth(&c, r, below);
    }
}

/// A residual's contact force (no derivatives) is the full one's to
/// the bit, with friction along and across the line, in and past the
/// ramp, sliding slower and faster than the slip velocity; its
/// derivatives are zero.
#[test]
fn the_force_without_derivatives_is_the_full_forces_to_the_bit() {
    let c = bed();
    let (point, n) = plane_of(&c);
    for below in [0.01, 0.3 * c.ramp_width(), -0.01] {
        for v in [[0.03, -0.02, -0.01], [2.0, 1.5, -0.3], [-1e-4, 3e-4, 0.0]] {
            let r: [f64; 3] = std::array::from_fn(|i| point[i] - below * n[i]);
            let rx = [0.8, 0.5, -0.1];
            let full = c.force(&r, &rx, &v);
            let lean = c.force_at(&r, &rx, &v, false);
            assert_eq!(lean.force, full.force, "below {below}, v {v:?}");
            assert_eq!((lean.d_r, lean.d_rx, lean.d_rdot), Default::default());
        }
    }
}

#[test]
fn a_line_resting_in_the_bed_feels_its_weight_back_without_friction_at_rest() {
    let c = SeabedContact {
        seabed: Seabed::flat(100.0, 3e6, 3e5).with_friction(0.5, 1.0, 1e-3),
        diameter: 0.1,
    };
    let g = 2e-3;
    let f = c.force(&[5.0, 2.0, -100.0 - g], &[1.0, 0.0, 0.0], &[0.0; 3]);
    let expected = 3e6 * 0.1 * (g - 0.5 * c.ramp_width());
    // The penetration 100 + g - 100 is exact to eps 100 / g = 1e-11.
    assert!((f.force[2] - expected).abs() <= 1e-10 * expected);
    assert_eq!((f.force[0], f.force[1]), (0.0, 0.0));
}

#[test]
fn sliding_friction_is_coulombs_well_above_the_slip_velocity() {
    let c = SeabedContact {
        seabed: Seabed::flat(100.0, 3e6, 0.0).with_friction(0.5, 1.0, 1e-3),
        diameter: 0.1,
    };
    let r = [0.0, 0.0, -100.01];
    let ne = 3e6 * 0.1 * (0.01 - 0.5 * c.ramp_width());
    // Axial (along x) and transverse (along y) sliding at 1 m/s.
    let fa = c.force(&r, &[2.0, 0.0, 0.3], &[1.0, 0.0, 0.0]).force;
    let ft = c.force(&r, &[2.0, 0.0, 0.3], &[0.0, -1.0, 0.0]).force;
    let coulomb = |mu: f64| mu * ne / (1.0f64 + 1e-6).sqrt();
    assert!((fa[0] + coulomb(0.5)).abs() <= 1e-12 * ne);
    assert!((ft[1] - coulomb(1.0)).abs() <= 1e-12 * ne);
}

/// Static friction (W48): the slide r - r_0 stands where the velocity
/// was, so the derivative in r of the force with r_0 held is the
/// velocity-free derivative plus the sliding's; against central
/// differences as above, in the bed and in the ramp.
#[test]
fn the_static_contact_force_derivatives_match_finite_differences() {
    let c = bed();
    let (point, n) = plane_of(&c);
    let rx = [0.8, 0.5, -0.1];
    for below in [0.01, 0.3 * c.ramp_width()] {
        let along = [0.4, 0.9, 0.0];
        let along_n = dot(along, n);
        let r: [f64; 3] =
            std::array::from_fn(|i| point[i] + along[i] - along_n * n[i] - below * n[i]);
        // Slid by a few u_s (where phi bends) from r_0.
        let r0: [f64; 3] = std::array::from_fn(|i| r[i] - [2.0, -1.0, 0.5][i] * c.static_slip());
        let force = |r: &[f64; 3], rx: &[f64; 3]| {
            c.static_force(r, rx, &std::array::from_fn(|i| r[i] - r0[i]))
        };
        let f0 = force(&r, &rx);
        assert_eq!(f0.d_rdot, [[0.0; 3]; 3]);
        let scale = [f0.d_r, f0.d_rx]
            .iter()
            .flatten()
            .flatten()
            .fold(0.0f64, |m, x| m.max(x.abs()));
        // h = 1e-7: round-off eps |r| / h stays below 1e-7 at |r| ~ 50 m
        // and truncation (h / u_s)^2 below 1e-5 across the slide's
        // regularization (u_s = 8e-5 m).
        let h = 1e-7;
        for j in 0..3 {
            for (which, analytic) in [(0, f0.d_r), (1, f0.d_rx)] {
                let (mut rp, mut rm, mut xp, mut xm) = (r, r, rx, rx);
                if which == 0 {
                    rp[j] += h;
                    rm[j] -= h;
                } else {
                    xp[j] += h;
                    xm[j] -= h;
                }
                let (fp, fm) = (force(&rp, &xp).force, force(&rm, &xm).force);
                for i in 0..3 {
                    let fd = (fp[i] - fm[i]) / (2.0 * h);
                    assert!(
                        (fd - analytic[i][j]).abs() <= 1e-6 * scale,
                        "arg {which} d f{i}/d x{j}: fd {fd} analytic {}",
                        analytic[i][j]
                    );
                }
            }
        }
        // Slid far: Coulomb's friction against the slide, no damping.
        let far = c.static_force(&r, &[1.0, 0.0, 0.0], &[1.0, 0.0, 0.0]);
        assert!(far.force[0] < 0.0);
    }
}

/// A bed of uneven cells, each twisted (h_xy != 0), with friction.
fn twisted_bed() -> SeabedContact {
    let xs = vec![-10.0, 0.0, 25.0];
    let ys = vec![-5.0, 0.0, 3.0, 10.0];
    let heights = (0..12)
        .map(|k| {
            let (x, y) = (xs[k / 4], ys[k % 4]);
            -50.0 + 0.1 * x - 0.05 * y + 0.004 * x * y + [0.0, 0.4][k % 2]
        })
        .collect();
    let grid = Bathymetry::new([xs, ys], heights).unwrap();
    SeabedContact {
        seabed: Seabed::on_grid(Arc::new(grid), 3e6, 3e5).with_friction(0.6, 1.0, 0.05),
        diameter: 0.08,
    }
}

/// The point `below` under the bathymetry's surface at (x, y): the
/// penetration (W40b) is `below` there.
fn under_grid(c: &SeabedContact, x: f64, y: f64, below: f64) -> [f64; 3] {
    let BedSurface::Grid(grid) = &c.seabed.surface else {
        panic!("a grid bed")
    };
    let h = grid.height(x, y);
    let m = (1.0 + h.slope[0].powi(2) + h.slope[1].powi(2)).sqrt();
    [x, y, h.height - below * m]
}

/// (W45)-(W46a) on a twisted bathymetry, where the normal and friction's
/// directions turn with the position: central differences as on the
/// plane, inside cells (the surface is smooth there), in the bed, in the
/// ramp and clear of it.
#[test]
fn the_contact_force_derivatives_on_a_bathymetry_match_finite_differences() {
    let c = twisted_bed();
    for (x, y) in [(-4.1, -2.2), (12.5, 6.3), (3.3, 1.1)] {
        for below in [0.01, 0.3 * c.ramp_width(), -0.01] {
            check_at_depth(&c, under_grid(&c, x, y, below), below);
        }
    }
}

/// Static friction (W48) on the twisted bathymetry: the derivative in r
/// with the targets held, against central differences (h as in the
/// plane's static check).
#[test]
fn the_static_contact_force_derivatives_on_a_bathymetry_match_finite_differences() {
    let c = twisted_bed();
    let rx = [0.8, 0.5, -0.1];
    let r = under_grid(&c, 4.4, 1.7, 0.01);
    let r0: [f64; 3] = std::array::from_fn(|i| r[i] - [2.0, -1.0, 0.5][i] * c.static_slip());
    let force = |r: &[f64; 3]| c.static_force(r, &rx, &std::array::from_fn(|i| r[i] - r0[i]));
    let f0 = force(&r);
    let scale = f0.d_r.iter().flatten().fold(0.0f64, |m, x| m.max(x.abs()));
    let h = 1e-7;
    for j in 0..3 {
        let (mut rp, mut rm) = (r, r);
        rp[j] += h;
        rm[j] -= h;
        let (fp, fm) = (force(&rp).force, force(&rm).force);
        for i in 0..3 {
            let fd = (fp[i] - fm[i]) / (2.0 * h);
            assert!(
                (fd - f0.d_r[i][j]).abs() <= 1e-6 * scale,
                "d f{i}/d r{j}: fd {fd} analytic {}",
                f0.d_r[i][j]
            );
        }
    }
}

/// A plane given as a bathymetry grid is that plane: the same contact
/// force and derivatives as the tilted plane bed, to round-off (the
/// bilinear reproduces a plane; its normal comes from the slopes instead
/// of being given).
#[test]
fn a_plane_bathymetry_pushes_as_the_tilted_plane() {
    let (sx, sy) = (0.125, -0.25);
    let xs = vec![-40.0, -10.0, 5.0, 60.0];
    let ys = vec![-8.0, 0.0, 8.0];
    let heights = xs
        .iter()
        .flat_map(|x| ys.iter().map(move |y| -30.0 + sx * x + sy * y))
        .collect();
    let grid = Bathymetry::new([xs, ys], heights).unwrap();
    let with = |seabed: Seabed| SeabedContact {
        seabed: seabed.with_friction(0.6, 1.0, 0.05),
        diameter: 0.08,
    };
    let on_grid = with(Seabed::on_grid(Arc::new(grid), 3e6, 3e5));
    let plane = with(Seabed::plane([0.0, 0.0, -30.0], [-sx, -sy, 1.0], 3e6, 3e5));
    for (x, y) in [(-20.5, -3.3), (7.7, 5.1)] {
        for below in [0.01, 0.3 * plane.ramp_width()] {
            let r = under_grid(&on_grid, x, y, below);
            let args = (&r, &[0.8, 0.5, -0.1], &[0.03, -0.02, -0.01]);
            let (a, b) = (
                on_grid.force(args.0, args.1, args.2),
                plane.force(args.0, args.1, args.2),
            );
            let scale = b.force.iter().fold(0.0f64, |m, f| m.max(f.abs()));
            for i in 0..3 {
                assert!((a.force[i] - b.force[i]).abs() <= 1e-9 * scale);
                for j in 0..3 {
                    for (p, q) in [(a.d_r, b.d_r), (a.d_rx, b.d_rx), (a.d_rdot, b.d_rdot)] {
                        assert!((p[i][j] - q[i][j]).abs() <= 1e-9 * scale / 1e-3);
                    }
                }
            }
        }
    }
}
