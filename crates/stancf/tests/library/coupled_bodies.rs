//! Coupled bodies (docs/method.md §13.6): a host moves a platform by its
//! six numbers, and gets back the force and the moment of its lines
//! about the platform's reference point.

use crate::common::rope_systems::{line_model, settings};
use stancf::body::pose::{point, rotate, rotation_from_moordyn_angles};
use stancf::body::RigidInertia;
use stancf::coupling::CoupledSystem;
use stancf::system::{Body, BodyKind, End, Line, Point, System};
use stancf::vec3::{add, cross, sub};
use stancf::StaticSettings;

const G: [f64; 3] = [0.0, 0.0, -9.81];

/// The fairleads in the platform's axes and the anchors below them.
fn fairleads() -> [([f64; 3], [f64; 3]); 3] {
    std::array::from_fn(|k| {
        let a = 2.0 * std::f64::consts::PI * k as f64 / 3.0;
        (
            [1.5 * a.cos(), 1.5 * a.sin(), -0.5],
            [4.0 * a.cos(), 4.0 * a.sin(), -3.0],
        )
    })
}

/// Three rope lines from anchors to the fairleads, on a coupled
/// platform at the origin (`on_body`) or at three coupled points.
fn moored(on_body: bool) -> System {
    let mut lines = Vec::new();
    let mut points = Vec::new();
    for (k, (local, anchor)) in fairleads().iter().enumerate() {
        points.push(if on_body {
            Point::on_body(0, *local)
        } else {
            Point::coupled(*local, stancf::motion::CoupledMotion::NONE)
        });
        points.push(Point::fixed(*anchor));
        lines.push(Line {
            model: line_model(*anchor, *local, 4),
            ends: [End::Point(2 * k + 1), End::Point(2 * k)],
        });
    }
    let identity = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
    let bodies = if on_body {
        vec![Body::new(
            BodyKind::Coupled,
            [0.0; 3],
            identity,
            RigidInertia::principal(1.0, [0.0; 3], [1.0; 3]),
        )]
    } else {
        vec![]
    };
    System::with_bodies(lines, points, bodies, G).expect("system")
}

fn handle(system: System) -> CoupledSystem {
    CoupledSystem::new(
        system.clone(),
        system,
        StaticSettings::default(),
        settings(),
    )
    .expect("handle")
}

/// The platform's pose and velocity at t (MoorDyn's angles in radians,
/// the angular velocity global).
fn platform(t: f64) -> ([f64; 6], [f64; 6]) {
    let x = [
        0.02 * t,
        -0.01 * t,
        0.005 * t,
        0.03 * t,
        -0.02 * t,
        0.04 * t,
    ];
    // The angles turn slowly: w is given as the host gives it.
    let xd = [0.02, -0.01, 0.005, 0.03, -0.02, 0.04];
    (x, xd)
}

/// The three fairleads' positions and velocities for the platform at x,
/// xd: r + R xi and v + w x R xi.
fn fairlead_arrays(x: &[f64; 6], xd: &[f64; 6]) -> (Vec<f64>, Vec<f64>) {
    let rotation = rotation_from_moordyn_angles([x[3], x[4], x[5]].map(f64::to_degrees));
    let (r, v, w) = (
        [x[0], x[1], x[2]],
        [xd[0], xd[1], xd[2]],
        [xd[3], xd[4], xd[5]],
    );
    let mut p = Vec::new();
    let mut pd = Vec::new();
    for (local, _) in fairleads() {
        p.extend(point(r, &rotation, local));
        pd.extend(add(v, cross(w, rotate(&rotation, local))));
    }
    (p, pd)
}

/// The platform moved by its six numbers and the same platform's three
/// fairleads moved as coupled points along the same motion give the same
/// lines: the platform's force is the fairleads' sum and its moment their
/// moments about the reference point, after the static start and over
/// three intervals of two steps, to round-off (1e-12 of the force).
#[test]
fn a_coupled_platform_takes_its_fairleads_force_and_moment() {
    let mut body = handle(moored(true));
    let mut points = handle(moored(false));
    assert_eq!((body.coupled_dof(), points.coupled_dof()), (6, 9));
    assert_eq!(body.initial_positions(), vec![0.0; 6]);
    let (x0, xd0) = platform(0.0);
    let (p0, pd0) = fairlead_arrays(&x0, &xd0);
    let fb = body.initialize(&x0, Some(&xd0)).expect("initialize body");
    let fp = points
        .initialize(&p0, Some(&pd0))
        .expect("initialize points");
    let check = |fb: &[f64], fp: &[f64], x: &[f64; 6], p: &[f64]| {
        let mut force = [0.0; 3];
        let mut moment = [0.0; 3];
        for k in 0..3 {
            let f = [fp[3 * k], fp[3 * k + 1], fp[3 * k + 2]];
            let arm = sub([p[3 * k], p[3 * k + 1], p[3 * k + 2]], [x[0], x[1], x[2]]);
            force = add(force, f);
            moment = add(moment, cross(arm, f));
        }
        let size = force.iter().map(|v| v.abs()).fold(0.0, f64::max);
        for c in 0..3 {
            assert!((fb[c] - force[c]).abs() < 1e-12 * size, "{fb:?} {force:?}");
            assert!(
                (fb[3 + c] - moment[c]).abs() < 1e-12 * size,
                "{fb:?} {moment:?}"
            );
        }
        size
    };
    let size = check(&fb, &fp, &x0, &p0);
    assert!(size > 1e-3, "the lines pull: {size}");
    for k in 1..=3 {
        let t = 2e-4 * k as f64;
        let (x, xd) = platform(t);
        let (p, pd) = fairlead_arrays(&x, &xd);
        let fb = body.step_to(t, &x, Some(&xd)).expect("body step");
        let fp = points.step_to(t, &p, Some(&pd)).expect("points step");
        check(&fb.last_step, &fp.last_step, &x, &p);
        assert_eq!(fb.steps, 2);
    }
}

/// MoorDyn's convention through the arrays: a roll of +0.1 rad lifts the
/// +y side (the fairlead at 120 degrees, y > 0, rises by 1.5 sin 120 deg
/// sin 0.1 and comes in), a pitch puts +x down, a yaw turns +x toward +y
/// (docs/method.md §15.1).
#[test]
fn a_coupled_platform_turns_as_moordyns_angles_say() {
    for (angles, point_index, check) in [
        ([0.1, 0.0, 0.0], 2usize, [None, None, Some(1.0)]),
        ([0.0, 0.1, 0.0], 0, [None, None, Some(-1.0)]),
        ([0.0, 0.0, 0.1], 0, [None, Some(1.0), None]),
    ] {
        let mut body = handle(moored(true));
        let x = [0.0, 0.0, 0.0, angles[0], angles[1], angles[2]];
        body.initialize(&x, None).expect("initialize");
        let sim = body.simulation().expect("running");
        let (local, _) = fairleads()[point_index / 2];
        let at = sim.point_state(point_index).0;
        let moved = sub(at, local);
        for c in 0..3 {
            if let Some(sign) = check[c] {
                assert!(
                    sign * moved[c] > 0.01,
                    "{angles:?}: point moved by {moved:?}"
                );
            }
        }
        let expect = point(
            [0.0; 3],
            &rotation_from_moordyn_angles(angles.map(f64::to_degrees)),
            local,
        );
        for c in 0..3 {
            assert!((at[c] - expect[c]).abs() < 1e-14);
        }
    }
}

/// A coupled system with a free platform (hanging on its three ropes, a
/// fourth rope from it to a coupled point) gives the platform's mooring
/// stiffness (B16) at the equilibrium its initialization finds: the
/// matrix of the static solve of the same system (the library's, whose
/// derivatives are checked against differences in body_statics.rs), to
/// round-off; None before initialization and for a body index that is
/// not a free body.
#[test]
fn a_coupled_system_gives_its_free_platforms_mooring_stiffness() {
    let (system, host) = hanging_platform([0.0; 3]);
    let mut coupled = galerkin_handle(system.clone());
    assert!(coupled.body_stiffness(0).is_none());
    coupled.initialize(&host, None).expect("initialize");
    let from_handle = coupled.body_stiffness(0).expect("a free body's stiffness");
    assert!(coupled.body_stiffness(1).is_none());
    let mut statics =
        stancf::system::SystemStatics::seeded(system.clone(), &system, StaticSettings::default())
            .expect("statics");
    assert!(statics
        .solve(|_, _| std::ops::ControlFlow::Continue(()))
        .expect("solve"));
    let direct = statics.body_stiffness(0).expect("stiffness");
    let size = direct.iter().flatten().fold(0.0f64, |m, v| m.max(v.abs()));
    let worst = (0..36)
        .map(|k| (from_handle[k / 6][k % 6] - direct[k / 6][k % 6]).abs())
        .fold(0.0f64, f64::max);
    eprintln!("stiffness from the handle against the static solve's: {worst:.1e} of {size:.1e}");
    assert!(size > 0.0 && worst <= 1e-12 * size, "{worst:e} of {size:e}");
    // Heave: pulling the platform down stretches its ropes.
    assert!(from_handle[2][2] > 0.0);
}

/// The free platform of [`hanging_platform`] given a start velocity
/// initializes (its lines start moving with it, linear in their length
/// from their anchors at rest: `System::start_lines_with_bodies`; the
/// core refused the lines at rest before) and steps.
#[test]
fn a_free_platform_that_starts_moving_starts_its_lines_with_it() {
    let (system, host) = hanging_platform([0.05, -0.02, 0.0]);
    let mut coupled = galerkin_handle(system);
    coupled.initialize(&host, None).expect("initialize");
    let body = coupled
        .simulation()
        .expect("running")
        .free_body(0)
        .expect("free body");
    assert!((body.centre_velocity()[0] - 0.05).abs() < 1e-12);
    coupled.step_to(0.01, &host, None).expect("step");
}

fn galerkin_handle(system: System) -> CoupledSystem {
    let mut steps = settings();
    steps.time_scheme = stancf::TimeScheme::Galerkin;
    CoupledSystem::new(system.clone(), system, StaticSettings::default(), steps).expect("handle")
}

/// A free platform of 0.5 kg hanging on ropes from the anchors of
/// [`fairleads`], a fourth rope from it up to a coupled point at `host`
/// (returned), moving at `velocity` at t = 0.
fn hanging_platform(velocity: [f64; 3]) -> (System, [f64; 3]) {
    let mut lines = Vec::new();
    let mut points = Vec::new();
    for (k, (local, anchor)) in fairleads().iter().enumerate() {
        points.push(Point::on_body(0, *local));
        points.push(Point::fixed(*anchor));
        lines.push(Line {
            model: line_model(*anchor, *local, 4),
            ends: [End::Point(2 * k + 1), End::Point(2 * k)],
        });
    }
    let host = [0.0, 0.0, 2.0];
    points.push(Point::coupled(host, stancf::motion::CoupledMotion::NONE));
    points.push(Point::on_body(0, [0.0, 0.0, 0.5]));
    lines.push(Line {
        model: line_model([0.0, 0.0, 0.5], host, 4),
        ends: [End::Point(7), End::Point(6)],
    });
    let identity = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
    let mut body = Body::new(
        BodyKind::Free,
        [0.0; 3],
        identity,
        RigidInertia::principal(0.5, [0.0, 0.0, -0.2], [0.02, 0.02, 0.03]),
    );
    body.velocity = velocity;
    (
        System::with_bodies(lines, points, vec![body], G).expect("system"),
        host,
    )
}

/// Right after initialization, before any step, the handle reads the
/// static equilibrium's forces: a coupled point's force is the one
/// `initialize` returned, to round-off (it read zero before the first
/// step).
#[test]
fn before_the_first_step_a_coupled_point_reads_the_equilibriums_force() {
    let (system, host) = hanging_platform([0.0; 3]);
    let mut coupled = galerkin_handle(system);
    let returned = coupled.initialize(&host, None).expect("initialize");
    let read = coupled.point(6).expect("a point").force;
    let size = returned.iter().fold(0.0f64, |m, v| m.max(v.abs()));
    for c in 0..3 {
        assert!(
            (read[c] - returned[c]).abs() <= 1e-12 * size,
            "{read:?} against {returned:?}"
        );
    }
    assert!(size > 0.0);
}

/// Two coupled platforms, each on one rope to an anchor below it: put in
/// the arrays in the other order (`with_body_order`, as a scenario orders
/// them by id), their 6 numbers and their 6 forces swap places and are
/// otherwise the same, bit for bit; an order that is not a permutation
/// of the coupled bodies is refused.
#[test]
fn coupled_bodies_take_the_order_they_are_given_in_the_arrays() {
    let identity = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
    let build = || {
        let mut lines = Vec::new();
        let mut points = Vec::new();
        let mut bodies = Vec::new();
        for (k, x) in [0.0f64, 6.0].into_iter().enumerate() {
            let anchor = [x + 2.0, 0.0, -3.0];
            let fairlead = [x, 0.0, -0.5];
            points.push(Point::on_body(k, [0.0, 0.0, -0.5]));
            points.push(Point::fixed(anchor));
            lines.push(Line {
                model: line_model(anchor, fairlead, 4),
                ends: [End::Point(2 * k + 1), End::Point(2 * k)],
            });
            bodies.push(Body::new(
                BodyKind::Coupled,
                [x, 0.0, 0.0],
                identity,
                RigidInertia::principal(1.0, [0.0; 3], [1.0; 3]),
            ));
        }
        handle(System::with_bodies(lines, points, bodies, G).expect("system"))
    };
    let mut natural = build();
    let mut swapped = build().with_body_order(vec![1, 0]).expect("a permutation");
    assert_eq!(swapped.coupled_bodies(), vec![1, 0]);
    let x = natural.initial_positions();
    let y = swapped.initial_positions();
    assert_eq!((&x[0..6], &x[6..12]), (&y[6..12], &y[0..6]));
    let f = natural.initialize(&x, None).expect("initialize");
    let g = swapped.initialize(&y, None).expect("initialize");
    assert_eq!((&f[0..6], &f[6..12]), (&g[6..12], &g[0..6]));
    assert!(build().with_body_order(vec![1, 1]).is_err());
    assert!(build().with_body_order(vec![0]).is_err());
}
