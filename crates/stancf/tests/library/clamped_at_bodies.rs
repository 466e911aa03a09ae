//! Line ends clamped in a direction at a free body (docs/method.md
//! §15.19): the clamp's frame turns with the body, its equations (B37)
//! and reactions (B38) involve the body's rotation, its impulse at the
//! step's end reaches the body's rates (B40). A cantilever holding a body
//! bends and turns it as Euler-Bernoulli says; a body tumbling with
//! clamped lines keeps the momenta and energy of the whole; the step's
//! Jacobian is the derivative of its rows.

use stancf::body::RigidInertia;
use stancf::observe::{angular_momentum as angular_momentum_of_line, momentum};
use stancf::system::{Body, BodyKind, End, Line, Point, System, SystemSimulation};
use stancf::vec3::{norm, scale, sub};
use stancf::{Cable, ElementType, Material, Model, ModelOptions, StepSettings};
use stancf::{State, TimeScheme};

const IDENTITY: [[f64; 3]; 3] = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];

/// The paper's PVC cable (EI = 4.25e-4 N m^2, EA = 1.02e4 N).
fn pvc() -> Material {
    Material::chen2023_pvc()
}

/// A light, limp line: EA 2 N, EI 1e-4 N m^2, 2 g/m (its first
/// cantilever frequency 0.8 rad/s: it whips about its clamp).
fn whippy() -> Material {
    Material {
        youngs_modulus: 1e6,
        density: 1000.0,
        area: 2e-6,
        second_moment: 1e-10,
        axial_damping: 0.0,
    }
}

/// A straight line of `elements` SAC-2 from `a` to `b` (unstretched).
fn straight(a: [f64; 3], b: [f64; 3], elements: usize, material: Material) -> Model {
    let chord = norm(sub(b, a));
    let cable = Cable::straight(chord, elements, ElementType::Sac2)
        .with_direction(scale(1.0 / chord, sub(b, a)))
        .with_origin(a);
    Model::new(cable, material, ModelOptions::default(), vec![]).expect("model")
}

fn galerkin(dt: f64) -> StepSettings {
    crate::common::step_settings(dt, TimeScheme::Galerkin, 1e-13)
}

/// A 1 m PVC cantilever of 10 SAC-2 along x, clamped at the origin, its
/// end B clamped along x at a free body's reference point; the body
/// carries a force P (-z) at `arm` beyond the end along the beam, in no
/// gravity. In linear theory the end takes P and the moment P arm, so it
/// deflects and turns by
///
/// ```text
///   delta = P L^3 / 3 EI + P arm L^2 / 2 EI,   phi = P L^2 / 2 EI + P arm L / EI
/// ```
///
/// and the body with it (its x axis along the end's tangent). At alpha =
/// P L^2 / EI = 1e-3 the elastica's correction is of order alpha^2
/// (0.12 alpha^2 measured for a clamped cantilever, docs/method.md §6.10)
/// and the stretch P / EA 4e-11; the elements are exact in linear
/// theory. So both agree to 1e-5 of themselves.
#[test]
fn a_cantilever_holding_a_body_bends_and_turns_it_as_euler_bernoulli_says() {
    let ei = pvc().youngs_modulus * pvc().second_moment;
    let (length, arm) = (1.0, 0.5);
    let load = 1e-3 * ei / (length * length);
    let mut body = Body::new(
        BodyKind::Free,
        [length, 0.0, 0.0],
        IDENTITY,
        RigidInertia::principal(0.05, [0.2, 0.0, 0.0], [1e-3, 2e-3, 2e-3]),
    );
    body.loads.push(([0.0, 0.0, -load], [arm, 0.0, 0.0]));
    let line = Line {
        model: straight([0.0; 3], [length, 0.0, 0.0], 10, pvc()),
        ends: [End::Point(0), End::Point(1)],
    };
    let line = line.clamped(0, [1.0, 0.0, 0.0]).unwrap();
    let line = line.clamped(1, [1.0, 0.0, 0.0]).unwrap();
    let points = vec![Point::fixed([0.0; 3]), Point::on_body(0, [0.0; 3])];
    let system = System::with_bodies(vec![line], points, vec![body], [0.0; 3]).expect("system");
    let statics = crate::common::seeded_equilibrium(system, 1e-13);
    let (position, rotation) = statics.body_pose(0).expect("free body");
    let delta = load * length.powi(3) / (3.0 * ei) + load * arm * length.powi(2) / (2.0 * ei);
    let phi = load * length.powi(2) / (2.0 * ei) + load * arm * length / ei;
    let turn = (-rotation[2][0]).atan2(rotation[0][0]);
    eprintln!(
        "end at {position:?}, deflection {:.9e} (linear {delta:.9e}), turn {turn:.9e} \
         (linear {phi:.9e})",
        -position[2]
    );
    assert!((-position[2] - delta).abs() < 1e-5 * delta);
    assert!((turn - phi).abs() < 1e-5 * phi);
    // The body turned about y alone, and the line's end tangent is its x axis.
    assert!(rotation[1][0].abs() < 1e-12 && rotation[0][1].abs() < 1e-12);
    // The clamp's moment on the body balances the load's about the end.
    let arm = stancf::body::pose::rotate(&rotation, [arm, 0.0, 0.0]);
    let expected = stancf::vec3::cross(arm, [0.0, 0.0, load]);
    let moment = statics.clamp_moment(0);
    eprintln!("clamp moment on the body {moment:?}, the load's balance {expected:?}");
    for c in 0..3 {
        assert!((moment[c] - expected[c]).abs() < 1e-9 * norm(expected));
    }
}

/// The mooring stiffness (B16) of a body held by a straight, unloaded
/// beam clamped at both ends (at a fixed point and at the body's
/// reference point): the end stiffness of Euler-Bernoulli's clamped
/// beam, EA/L along it and, across it,
///
/// ```text
///   [F_z; M_y] = -EI/L^3 [ 12   6L   ] [dz   ]      [F_y; M_z] = -EI/L^3 [ 12   -6L  ] [dy   ]
///                        [ 6L   4L^2 ] [dphi_y],                        [ -6L  4L^2 ] [dphi_z]
/// ```
///
/// (a turn about y tilts the end's tangent down, one about z sideways),
/// nothing about the beam's axis (a cable has no torsion). Cubic
/// Hermite elements are exact for it, so K agrees to round-off: each
/// entry to 1e-9 of its block's largest (EA 100 N, EI 1 N m^2, 1 m).
/// The clamp's reactions are the moment's whole source here: the
/// points' pull alone gives no bending stiffness.
#[test]
fn a_body_held_by_a_clamped_beam_has_its_end_stiffness() {
    let (ea, ei, l) = (100.0, 1.0, 1.0);
    let body = Body::new(
        BodyKind::Free,
        [l, 0.0, 0.0],
        IDENTITY,
        RigidInertia::principal(1.0, [0.2, 0.1, -0.1], [1e-2, 2e-2, 2e-2]),
    );
    let line = Line {
        model: straight([0.0; 3], [l, 0.0, 0.0], 4, stocky()),
        ends: [End::Point(0), End::Point(1)],
    };
    let line = line.clamped(0, [1.0, 0.0, 0.0]).unwrap();
    let line = line.clamped(1, [1.0, 0.0, 0.0]).unwrap();
    let points = vec![Point::fixed([0.0; 3]), Point::on_body(0, [0.0; 3])];
    let system = System::with_bodies(vec![line], points, vec![body], [0.0; 3]).expect("system");
    let mut statics = crate::common::seeded_equilibrium(system, 1e-13);
    let k = statics
        .body_stiffness(0)
        .expect("a clamped body's stiffness");
    let (b, s) = (ei / l.powi(3), 6.0 * ei / l.powi(2));
    let mut want = [[0.0; 6]; 6];
    want[0][0] = ea / l;
    (want[1][1], want[1][5], want[5][1], want[5][5]) = (12.0 * b, -s, -s, 4.0 * ei / l);
    (want[2][2], want[2][4], want[4][2], want[4][4]) = (12.0 * b, s, s, 4.0 * ei / l);
    let scale = |i: usize, j: usize| if i == 0 || j == 0 { ea / l } else { 12.0 * b };
    let mut worst = 0.0f64;
    for i in 0..6 {
        eprintln!("{:?}", k[i].map(|v| (v * 1e6).round() / 1e6));
        for j in 0..6 {
            worst = worst.max((k[i][j] - want[i][j]).abs() / scale(i, j));
        }
    }
    eprintln!("against the clamped beam's end stiffness: {worst:.1e}");
    assert!(worst < 1e-9, "{worst:e}");
}

/// A stocky line (EA 100 N, EI 1 N m^2): its bending and stretching
/// stiffnesses of one size over a metre.
fn stocky() -> Material {
    Material {
        youngs_modulus: 1e6,
        density: 1000.0,
        area: 1e-4,
        second_moment: 1e-6,
        axial_damping: 0.0,
    }
}

/// A body at (1, 0, 0) held by two stocky 1 m beams clamped at both ends,
/// one along x from the origin, one along y from (1, -1, 0) (each one's
/// bending holds the other's twist), loaded by `load` at `arm` from its
/// reference point and by `extra`, a force and a moment at the reference
/// point; no gravity.
fn cross_braced(load: [f64; 3], arm: [f64; 3], extra: [f64; 6]) -> System {
    let mut body = Body::new(
        BodyKind::Free,
        [1.0, 0.0, 0.0],
        IDENTITY,
        RigidInertia::principal(1.0, [0.2, 0.1, -0.1], [1e-2, 2e-2, 2e-2]),
    );
    body.loads.push((load, arm));
    body.loads.push(([extra[0], extra[1], extra[2]], [0.0; 3]));
    body.moment = [extra[3], extra[4], extra[5]];
    let beam = |from: [f64; 3], a: usize, along: [f64; 3]| {
        let line = Line {
            model: straight(from, [1.0, 0.0, 0.0], 8, stocky()),
            ends: [End::Point(a), End::Point(2)],
        };
        line.clamped(0, along).unwrap().clamped(1, along).unwrap()
    };
    let lines = vec![
        beam([0.0; 3], 0, [1.0, 0.0, 0.0]),
        beam([1.0, -1.0, 0.0], 1, [0.0, 1.0, 0.0]),
    ];
    let points = vec![
        Point::fixed([0.0; 3]),
        Point::fixed([1.0, -1.0, 0.0]),
        Point::on_body(0, [0.0; 3]),
    ];
    System::with_bodies(lines, points, vec![body], [0.0; 3]).expect("system")
}

/// The mooring stiffness (B16) of a loaded body two clamped beams hold,
/// against differences of its equilibrium under small extra loads: the
/// pose moves by dz with (K + K_own) dz = dL, K_own = -[P x][a x] in
/// the turn (the load P at the arm a turning with the body), so K is
/// (dz/dL)^-1 - K_own. At P L^2/EI = 0.3 the clamps' multipliers and the
/// lines' moment are far from zero, so (B16)'s chart and pull terms
/// count. Central differences over extra loads of h = 1e-3 and 5e-4
/// (N, N m) fall as h^2; their Richardson extrapolation removes that,
/// and what is left is the static tolerance (1e-13 of the rows) over h:
/// asserted 1e-7 of the matrix's size.
#[test]
fn a_loaded_clamped_bodys_stiffness_is_the_derivative_of_its_equilibrium() {
    let (load, arm) = ([0.1, 0.05, -0.3], [0.5, 0.2, 0.0]);
    let solve =
        |extra: [f64; 6]| crate::common::seeded_equilibrium(cross_braced(load, arm, extra), 1e-13);
    let mut base = solve([0.0; 6]);
    let k = base.body_stiffness(0).expect("stiffness");
    let (position, rotation) = base.body_pose(0).unwrap();
    let compliance = |h: f64| {
        let mut c = [[0.0; 6]; 6];
        for j in 0..6 {
            let pose = |sign: f64| {
                let mut extra = [0.0; 6];
                extra[j] = sign * h;
                let (at, turned) = solve(extra).body_pose(0).unwrap();
                let turn = stancf::body::rotation::log_map(&stancf::vec3::mat3_mul(
                    &turned,
                    &stancf::vec3::mat3_transpose(&rotation),
                ));
                [
                    at[0] - position[0],
                    at[1] - position[1],
                    at[2] - position[2],
                    turn[0],
                    turn[1],
                    turn[2],
                ]
            };
            let (up, down) = (pose(1.0), pose(-1.0));
            for i in 0..6 {
                c[i][j] = (up[i] - down[i]) / (2.0 * h);
            }
        }
        c
    };
    let (coarse, fine) = (compliance(1e-3), compliance(5e-4));
    let extrapolated: Vec<f64> = (0..36)
        .map(|n| (4.0 * fine[n / 6][n % 6] - coarse[n / 6][n % 6]) / 3.0)
        .collect();
    let total = inverse(&extrapolated, 6);
    // K_own = -[P x][a x] in the turn, a the arm turned with the body.
    let a = stancf::body::pose::rotate(&rotation, arm);
    let own = stancf::vec3::mat3_mul(&hat(load), &hat(a));
    let size = k.iter().flatten().map(|v| v * v).sum::<f64>().sqrt();
    let mut worst = 0.0f64;
    for i in 0..6 {
        eprintln!("{:?}", k[i].map(|v| (v * 1e4).round() / 1e4));
        for j in 0..6 {
            let own_ij = if i >= 3 && j >= 3 {
                -own[i - 3][j - 3]
            } else {
                0.0
            };
            worst = worst.max((k[i][j] - (total[6 * i + j] - own_ij)).abs());
        }
    }
    eprintln!(
        "against the differences of the equilibrium: {:.1e} of {size:.3e}",
        worst / size
    );
    assert!(worst < 1e-7 * size, "{:e}", worst / size);
}

/// The inverse of the n x n matrix `a` (row-major), by LU.
fn inverse(a: &[f64], n: usize) -> Vec<f64> {
    let mut lu = stancf::band::BandLu::new(n, n - 1, n - 1);
    for i in 0..n {
        for j in 0..n {
            lu.matrix_mut().add(i, j, a[n * i + j]);
        }
    }
    lu.factorize().expect("regular");
    let mut inv = vec![0.0; n * n];
    for j in 0..n {
        let mut e = vec![0.0; n];
        e[j] = 1.0;
        lu.solve(&mut e);
        for i in 0..n {
            inv[n * i + j] = e[i];
        }
    }
    inv
}

/// [a x], the cross-product matrix.
fn hat(a: [f64; 3]) -> [[f64; 3]; 3] {
    [[0.0, -a[2], a[1]], [a[2], 0.0, -a[0]], [-a[1], a[0], 0.0]]
}

/// Three 1 m limp lines ([`whippy`]) of 8 SAC-2 leaving a body at its
/// points `arms` at 120 degrees about z, 11 degrees above the x-y plane
/// (ends A clamped there along them, ends B loose), the whole spinning at
/// `spin` about the origin (the body's reference point) and drifting at
/// `drift`.
fn clamped_star(spin: [f64; 3], drift: [f64; 3]) -> (System, Vec<State>) {
    let arms = [[0.1, 0.0, 0.05], [-0.075, 0.13, -0.03], [-0.1, -0.17, 0.0]];
    let (mut lines, mut points, mut states) = (Vec::new(), Vec::new(), Vec::new());
    for (k, &start) in arms.iter().enumerate() {
        let angle = 2.0 * std::f64::consts::PI * k as f64 / 3.0;
        let d = [angle.cos(), angle.sin(), 0.2];
        let d = scale(1.0 / norm(d), d);
        let model = straight(start, stancf::vec3::add(start, d), 8, whippy());
        states.push(crate::common::spun_and_drifting(&model, spin, drift));
        points.push(Point::on_body(0, start));
        let line = Line {
            model,
            ends: [End::Point(k), End::Loose],
        };
        lines.push(line.clamped(0, d).unwrap());
    }
    let mut body = Body::new(
        BodyKind::Free,
        [0.0; 3],
        IDENTITY,
        RigidInertia::principal(0.02, [0.0, 0.02, 0.01], [2e-4, 3e-4, 4e-4]),
    );
    body.velocity = drift;
    body.angular_velocity = spin;
    let system = System::with_bodies(lines, points, vec![body], [0.0; 3]).expect("system");
    (system, states)
}

/// Linear and angular momentum (about the origin) of the lines and the
/// body.
fn momenta(sim: &SystemSimulation) -> ([f64; 3], [f64; 3]) {
    let body = sim.free_body(0).expect("free body");
    let (mut p, mut l) = (body.linear_momentum(), body.angular_momentum());
    for line in sim.lines() {
        let (_, pl, _) = momentum(line.model(), line.state());
        let ll = angular_momentum_of_line(line.model(), line.state());
        for c in 0..3 {
            p[c] += pl[c];
            l[c] += ll[c];
        }
    }
    (p, l)
}

/// The clamped star tumbling and drifting in empty space: the clamps'
/// reactions are the gradient of one function invariant under rigid
/// motions (B38), so the whole keeps its linear momentum to round-off,
/// and its angular momentum and energy to the step's error, which falls
/// at fourth order at least, as for lines held at a body's points
/// (docs/method.md §15.7: the point's path between the step's ends is not
/// a cubic). Measured: angular momentum 6.2e-13, 3.8e-14, 2.4e-15 kg
/// m^2/s (orders 4.0, 4.0), energy 1.3e-7, 3.0e-10, 1.9e-12 J (8.7, 7.3)
/// at dt 8, 4, 2 ms over 0.4 s, the lines whipping about their clamps.
#[test]
fn a_body_tumbling_with_clamped_lines_keeps_its_momenta_and_energy() {
    let (spin, drift) = ([1.0, -0.5, 3.0], [0.5, -0.2, 0.1]);
    let start = |dt: f64| {
        let (system, states) = clamped_star(spin, drift);
        SystemSimulation::new(system, states, galerkin(dt)).unwrap()
    };
    let (_, order_l, order_e) = crate::common::tumbling_drifts(start, momenta);
    assert!(order_l > 3.5 && order_e > 3.5, "{order_l} {order_e}");
}

/// The step's Jacobian with lines clamped at a free body is the
/// derivative of its rows, by central differences: a body turned at the
/// start, its centre off its reference point, spinning and falling, one
/// line from a fixed clamp to a clamp at the body, one clamped at the
/// body with its other end loose; after two steps, so that the clamps'
/// multipliers are not zero.
#[test]
fn a_systems_jacobian_with_lines_clamped_at_a_body_is_the_derivative_of_its_rows() {
    let body = crate::common::turned_moving_body(RigidInertia::principal(
        0.05,
        [0.05, -0.1, 0.2],
        [2e-3, 3e-3, 4e-3],
    ));
    let local = [[0.2, 0.1, 0.3], [-0.1, 0.25, 0.0]];
    let anchor = [0.1, 0.4, 0.0];
    let first = body.point(local[0]);
    let second = body.point(local[1]);
    let out = stancf::vec3::add(second, [0.3, 0.5, -0.4]);
    let lines = vec![
        Line {
            model: straight(anchor, first, 4, pvc()),
            ends: [End::Point(2), End::Point(0)],
        }
        .clamped(0, sub(first, anchor))
        .unwrap()
        .clamped(1, sub(first, anchor))
        .unwrap(),
        Line {
            model: straight(second, out, 4, pvc()),
            ends: [End::Point(1), End::Loose],
        }
        .clamped(0, sub(out, second))
        .unwrap(),
    ];
    let points = vec![
        Point::on_body(0, local[0]),
        Point::on_body(0, local[1]),
        Point::fixed(anchor),
    ];
    let system = System::with_bodies(lines, points, vec![body], [0.0, 0.0, -9.81]).expect("system");
    let mut states: Vec<State> = system
        .lines()
        .iter()
        .map(|l| l.model.initial_state())
        .collect();
    system.start_lines_with_bodies(&mut states);
    let mut sim = SystemSimulation::new(system, states, galerkin(0.01)).unwrap();
    sim.step().expect("step");
    sim.step().expect("step");
    let err = crate::common::step_jacobian_error(&mut sim, 1e-6);
    eprintln!("step Jacobian with clamps at a free body: rel. error {err:.1e}");
    assert!(err < 1e-7, "{err:e}");
}

/// A 1 m PVC cantilever along x clamped at the origin, made of two 0.5 m
/// lines (5 SAC-2 each) joined by a connector at x = 0.5 m (MoorDyn's
/// free rod of zero length, both lines clamped to it along x,
/// docs/method.md §15.20), its tip a free point carrying P (-z), in no
/// gravity. The connector turns to balance the two lines' moments, so the
/// pair bends as one beam: the tip deflects by P L^3 / 3 EI and the
/// connector turns with the beam's slope there, P (L a - a^2/2) / EI at
/// a = 0.5 m. At alpha = P L^2 / EI = 1e-3 both hold to 1e-5, as for the
/// cantilever holding a body above.
#[test]
fn two_lines_joined_by_a_connector_bend_as_one_cantilever() {
    let ei = pvc().youngs_modulus * pvc().second_moment;
    let load = 1e-3 * ei;
    let x = [1.0, 0.0, 0.0];
    let lines = vec![
        Line {
            model: straight([0.0; 3], [0.5, 0.0, 0.0], 5, pvc()),
            ends: [End::Point(0), End::Point(1)],
        }
        .clamped(0, x)
        .unwrap()
        .clamped(1, x)
        .unwrap(),
        Line {
            model: straight([0.5, 0.0, 0.0], [1.0, 0.0, 0.0], 5, pvc()),
            ends: [End::Point(1), End::Point(2)],
        }
        .clamped(0, x)
        .unwrap(),
    ];
    let mut tip = Point::free([1.0, 0.0, 0.0], 0.0);
    tip.force = [0.0, 0.0, -load];
    let points = vec![Point::fixed([0.0; 3]), Point::on_body(0, [0.0; 3]), tip];
    let connector = Body::connector([0.5, 0.0, 0.0], x);
    let system = System::with_bodies(lines, points, vec![connector], [0.0; 3]).expect("system");
    let statics = crate::common::seeded_equilibrium(system, 1e-13);
    let tip = statics.point_position(2);
    let (_, rotation) = statics.body_pose(0).expect("connector");
    // The connector's z axis is the beam's tangent there.
    let turn = (-rotation[2][2]).atan2(rotation[0][2]);
    let delta = load / (3.0 * ei);
    let slope = load * (0.5 - 0.125) / ei;
    eprintln!(
        "tip deflection {:.9e} (linear {delta:.9e}), connector turn {turn:.9e} (linear \
         {slope:.9e})",
        -tip[2]
    );
    assert!((-tip[2] - delta).abs() < 1e-5 * delta);
    assert!((turn - slope).abs() < 1e-5 * slope);
}

/// Euler-Bernoulli's first cantilever mode, beta_1 L = 1.8751: its
/// deflection and slope at x (L = 1).
fn first_mode(x: f64) -> (f64, f64) {
    let b: f64 = 1.875_104_068_711_961;
    let s = (b.cosh() + b.cos()) / (b.sinh() + b.sin());
    let bx = b * x;
    let w = bx.cosh() - bx.cos() - s * (bx.sinh() - bx.sin());
    let slope = b * (bx.sinh() + bx.sin() - s * (bx.cosh() - bx.cos()));
    (w, slope)
}

/// The two-line cantilever of
/// [`two_lines_joined_by_a_connector_bend_as_one_cantilever`] (tip loose,
/// no load) released at rest in its first mode, the tip 1 mm off the
/// axis, stepped by the Galerkin step at 200 steps a period: the
/// connector has neither mass nor inertia, and turning to balance the
/// lines' moments at every step it lets the pair swing as one beam, at
/// omega_1 = (beta_1 L)^2 sqrt(EI / (rho A L^4)). As for the one-line
/// cantilever (clamped_ends.rs), the period from the first two zero
/// crossings is within 2e-5 of 2 pi / omega_1 (the elements' error on the
/// mode O((h/L)^4), the step's phase error, the crossings'
/// interpolation and the 1 mm amplitude's nonlinearity each below 1e-6),
/// and the swing keeps its amplitude to 1e-4.
#[test]
fn two_lines_joined_by_a_connector_swing_as_one_cantilever() {
    let m = pvc();
    let (ei, mass) = (m.youngs_modulus * m.second_moment, m.density * m.area);
    let beta = 1.875_104_068_711_961f64;
    let omega = beta * beta * (ei / mass).sqrt();
    let period = 2.0 * std::f64::consts::PI / omega;
    let amplitude = 1e-3;
    let tip = first_mode(1.0).0;
    // The mode's shape on a line from x0 to x0 + 0.5 of 5 SAC-2.
    let shaped = |x0: f64| {
        let model = straight([x0, 0.0, 0.0], [x0 + 0.5, 0.0, 0.0], 5, pvc());
        let mut state = model.initial_state();
        for k in 0..=5 {
            let (w, slope) = first_mode(x0 + 0.1 * k as f64);
            let (e, t) = (model.coordinate(k, 0, 0), model.coordinate(k, 1, 0));
            state.e[e + 2] = amplitude * w / tip;
            state.e[t + 2] = amplitude * slope / tip;
        }
        (model, state)
    };
    let ((first, s1), (second, s2)) = (shaped(0.0), shaped(0.5));
    let (w, slope) = first_mode(0.5);
    let axis = [1.0, 0.0, amplitude * slope / tip];
    let joint = [0.5, 0.0, amplitude * w / tip];
    let lines = vec![
        Line {
            model: first,
            ends: [End::Point(0), End::Point(1)],
        }
        .clamped(0, [1.0, 0.0, 0.0])
        .unwrap()
        .clamped(1, axis)
        .unwrap(),
        Line {
            model: second,
            ends: [End::Point(1), End::Loose],
        }
        .clamped(0, axis)
        .unwrap(),
    ];
    let points = vec![Point::fixed([0.0; 3]), Point::on_body(0, [0.0; 3])];
    let connector = Body::connector(joint, axis);
    let system = System::with_bodies(lines, points, vec![connector], [0.0; 3]).expect("system");
    // Newton to its default tolerance, 1e-10, as the one-line cantilever.
    let settings = StepSettings {
        time_step: period / 200.0,
        time_scheme: TimeScheme::Galerkin,
        ..StepSettings::default()
    };
    let mut sim = SystemSimulation::new(system, vec![s1, s2], settings).unwrap();
    let deflection = |sim: &SystemSimulation| {
        let line = &sim.lines()[1];
        line.state().e[line.model().coordinate(5, 0, 2)]
    };
    let mut path = vec![(0.0, deflection(&sim))];
    for _ in 0..210 {
        sim.step().expect("step");
        path.push((sim.time(), deflection(&sim)));
    }
    let crossings: Vec<f64> = path
        .windows(2)
        .filter(|w| w[0].1 * w[1].1 < 0.0)
        .map(|w| w[0].0 - w[0].1 * (w[1].0 - w[0].0) / (w[1].1 - w[0].1))
        .collect();
    assert!(crossings.len() >= 2, "{crossings:?}");
    let measured = 2.0 * (crossings[1] - crossings[0]);
    let error = measured / period - 1.0;
    let peak = path.iter().map(|p| p.1.abs()).fold(0.0, f64::max);
    eprintln!("period {measured:.9} s against {period:.9} s ({error:.2e}); peak {peak:.6e} m");
    assert!(error.abs() < 2e-5, "{error:e}");
    assert!((peak / amplitude - 1.0).abs() < 1e-4, "{peak:e}");
}
