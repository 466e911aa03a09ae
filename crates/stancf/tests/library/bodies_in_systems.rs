//! Free rigid bodies holding lines (docs/method.md §15.7): a body's
//! points move with it (B11), the lines' rows at them load it through the
//! chain rule (B12)-(B13), and the step's end rates come from the system's
//! mass matrix with the body's rates in it (B14).

use crate::common::light_rope;
use stancf::body::RigidInertia;
use stancf::observe::{angular_momentum as angular_momentum_of_line, momentum};
use stancf::system::{Body, BodyKind, End, Line, Point, System, SystemSimulation};
use stancf::{Cable, ElementType, Model, ModelOptions, StepSettings, TimeScheme};

const BODY_MASS: f64 = 0.2;
const SPIN: f64 = 3.0;

/// Three 1 m lines at 120 degrees in the x-y plane, line k from the
/// point `arms[k]` on `on` (ends A) out along its direction, ends B
/// loose; the lines turn at `spin` about the origin and drift at `drift`.
fn star(
    arms: [[f64; 3]; 3],
    spin: [f64; 3],
    drift: [f64; 3],
    on: impl Fn([f64; 3]) -> Point,
) -> (Vec<Line>, Vec<Point>, Vec<stancf::State>) {
    let (mut lines, mut points, mut states) = (Vec::new(), Vec::new(), Vec::new());
    for (k, &start) in arms.iter().enumerate() {
        let angle = 2.0 * std::f64::consts::PI * k as f64 / 3.0;
        let d = [angle.cos(), angle.sin(), 0.0];
        let cable = Cable::straight(1.0, 8, ElementType::Sac2)
            .with_direction(d)
            .with_origin(start);
        let model =
            Model::new(cable, light_rope(), ModelOptions::default(), vec![]).expect("model");
        states.push(crate::common::spun_and_drifting(&model, spin, drift));
        points.push(on(start));
        lines.push(Line {
            model,
            ends: [End::Point(k), End::Loose],
        });
    }
    (lines, points, states)
}

/// A free body of 0.2 kg at the origin with `moments` about its centre
/// `centre`, moving as the star's lines do.
fn star_body(moments: [f64; 3], centre: [f64; 3], spin: [f64; 3], drift: [f64; 3]) -> Body {
    let mut body = Body::new(
        BodyKind::Free,
        [0.0; 3],
        [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]],
        RigidInertia::principal(BODY_MASS, centre, moments),
    );
    body.velocity = drift;
    body.angular_velocity = spin;
    body
}

fn galerkin(dt: f64) -> StepSettings {
    let mut settings = StepSettings {
        time_step: dt,
        time_scheme: TimeScheme::Galerkin,
        ..StepSettings::default()
    };
    settings.newton.tolerance = 1e-13;
    settings
}

/// Linear momentum of the lines and the body.
fn linear_momentum(sim: &SystemSimulation) -> [f64; 3] {
    let mut p = sim.free_body(0).expect("free body").linear_momentum();
    for line in sim.lines() {
        let (_, pl, _) = momentum(line.model(), line.state());
        for c in 0..3 {
            p[c] += pl[c];
        }
    }
    p
}

/// Lines held at a body's centre of mass put no moment on it, so the body
/// moves as a point of its mass would: the star of lines on a body whose
/// three points are its centre follows the star on a free point of
/// 0.2 kg to round-off over 300 steps (Newton to 1e-13), though the
/// body's step solves six more unknowns and its points' rows are its
/// constraints (B13) while the point's are its balance.
#[test]
fn lines_held_at_a_bodys_centre_move_it_as_a_point_of_its_mass() {
    let drift = [0.5, -0.2, 0.1];
    let spin = [0.0, 0.0, SPIN];
    let (lines, _, states) = star([[0.0; 3]; 3], spin, drift, |_| {
        Point::free([0.0; 3], BODY_MASS)
    });
    let lines: Vec<Line> = lines
        .into_iter()
        .map(|l| Line {
            model: l.model,
            ends: [End::Point(0), End::Loose],
        })
        .collect();
    let point = System::new(
        lines.clone(),
        vec![Point::free([0.0; 3], BODY_MASS)],
        [0.0; 3],
    )
    .expect("point system");
    let body = System::with_bodies(
        lines,
        vec![Point::on_body(0, [0.0; 3])],
        vec![star_body([0.02, 0.03, 0.04], [0.0; 3], spin, drift)],
        [0.0; 3],
    )
    .expect("body system");
    let mut body_sim = SystemSimulation::new(body, states.clone(), galerkin(1e-3)).unwrap();
    let mut point_sim = SystemSimulation::new(point, states, galerkin(1e-3)).unwrap();
    let mut worst = 0.0f64;
    for _ in 0..300 {
        body_sim.step().expect("body step");
        point_sim.step().expect("point step");
        let (xb, vb) = body_sim.point_state(0);
        let (xp, vp) = point_sim.point_state(0);
        for c in 0..3 {
            worst = worst
                .max((xb[c] - xp[c]).abs())
                .max(1e-3 * (vb[c] - vp[c]).abs());
        }
    }
    let centre = body_sim.free_body(0).unwrap().centre();
    let (xp, _) = point_sim.point_state(0);
    eprintln!(
        "body against point: largest difference {worst:.1e} m; centre {centre:?}, point {xp:?}"
    );
    assert!(worst < 1e-12, "{worst:e}");
    for c in 0..3 {
        assert!((centre[c] - xp[c]).abs() < 1e-12);
    }
}

/// Angular momentum about the origin of the lines and the body.
fn angular_momentum(sim: &SystemSimulation) -> [f64; 3] {
    let mut l = sim.free_body(0).expect("free body").angular_momentum();
    for line in sim.lines() {
        let ll = angular_momentum_of_line(line.model(), line.state());
        for c in 0..3 {
            l[c] += ll[c];
        }
    }
    l
}

/// The star of lines on a body, held at three body points at different
/// distances and heights, the centre of mass off the reference point,
/// spinning about a tilted axis and drifting in empty space: the body
/// tumbles and the lines whip. The whole keeps its linear momentum to
/// round-off (the cubic's variations hold the translations, for the
/// body as for the lines; Newton to 1e-13), and its angular momentum
/// and energy to the step's error, which falls with the step.
#[test]
fn a_spinning_star_of_lines_on_a_body_keeps_its_momenta_and_energy() {
    let drift = [0.5, -0.2, 0.1];
    let start = |dt: f64| {
        let spin = [1.0, -0.5, SPIN];
        let arms = [[0.1, 0.0, 0.05], [-0.075, 0.13, -0.03], [-0.1, -0.17, 0.0]];
        let (lines, points, states) = star(arms, spin, drift, |x| Point::on_body(0, x));
        let body = star_body([0.002, 0.003, 0.004], [0.0, 0.02, 0.01], spin, drift);
        let system = System::with_bodies(lines, points, vec![body], [0.0; 3]).expect("system");
        SystemSimulation::new(system, states, galerkin(dt)).unwrap()
    };
    let momenta = |sim: &SystemSimulation| (linear_momentum(sim), angular_momentum(sim));
    let (errors, order_l, order_e) = crate::common::tumbling_drifts(start, momenta);
    // Measured: orders 4.0 and 3.9 (angular momentum), 4.6 and 3.7
    // (energy); the end of the last pair is near round-off. The point's
    // path is matched to the body's at the step's ends, position and
    // slope (B13), and between them the line end follows their cubic
    // (docs/method.md §15.7): fourth order, as P2.
    for (dl, de) in &errors {
        assert!(*dl < 1e-12 && *de < 1e-10, "{dl:e} {de:e}");
    }
    assert!(order_l > 3.5 && order_e > 3.5, "{order_l} {order_e}");
}

/// The step's Jacobian with a free body is the derivative of its rows
/// (the body's own, the lines' carried to it by (B12), the points'
/// constraints (B13)), by central differences: a body turned at the
/// start, its centre off its reference point, in water (drag, rotational
/// drag, added mass), hanging in gravity from a fixed anchor by one line
/// and holding a second, slack one, moving.
#[test]
fn a_systems_jacobian_with_a_free_body_is_the_derivative_of_its_rows() {
    let mut body = crate::common::turned_moving_body(RigidInertia::principal(
        2.0,
        [0.05, -0.1, 0.2],
        [0.02, 0.03, 0.04],
    ));
    {
        body.water = Some(stancf::body::BodyWater {
            density: 1025.0,
            volume: 0.004,
            added_mass_coefficients: [1.0, 0.8, 0.5],
            drag_areas: [0.05, 0.08, 0.03],
            rotational_drag_areas: [0.01, 0.01, 0.01],
            current: [0.0; 3],
            rods: Vec::new(),
            gravity: 0.0,
            sea: None,
            external: Default::default(),
            host: None,
        });
    }
    let (system, states) =
        crate::common::two_ropes_on_a_body(body, [[0.2, 0.1, 0.3], [-0.1, 0.25, 0.0]], 0.0);
    let mut sim = SystemSimulation::new(system, states, galerkin(0.01)).unwrap();
    let err = crate::common::step_jacobian_error(&mut sim, 1e-6);
    eprintln!("step Jacobian with a free body: rel. error {err:.1e}");
    assert!(err < 1e-7, "{err:e}");
}

/// A light, stiff line (EA 1e5 N, 1 g/m, EI 1e-5 N m^2) hanging from the
/// origin at `phi` from the vertical, `l` long under `tension`: its
/// reference is unstretched and its state stretched to l.
fn pendulum_line(l: f64, phi: f64, tension: f64) -> (Model, stancf::State) {
    let line = stancf::Material {
        youngs_modulus: 1e9,
        density: 10.0,
        area: 1e-4,
        second_moment: 1e-14,
        axial_damping: 0.0,
    };
    let stretch = 1.0 + tension / (line.youngs_modulus * line.area);
    let cable = Cable::straight(l / stretch, 4, ElementType::Sac2).with_direction([
        phi.sin(),
        0.0,
        -phi.cos(),
    ]);
    let model = Model::new(cable, line, ModelOptions::default(), vec![]).expect("model");
    let mut state = model.initial_state();
    for node in 0..model.nodes() {
        for slot in 0..2 {
            let o = model.coordinate(node, slot, 0);
            for c in 0..3 {
                state.e[o + c] *= stretch;
            }
        }
    }
    (model, state)
}

/// A body of 10 kg (moment 0.5 kg m^2 about its centre) hanging by a
/// point 0.5 m above its centre from a 1 m line to a fixed anchor: for
/// small swings a double pendulum whose line is a rigid massless rod,
///
/// ```text
///   [ M L^2   M L d       ] [phi1'']   [ M g L   0     ] [phi1]
///   [ M L d   M d^2 + I_G ] [phi2''] + [ 0       M g d ] [phi2] = 0
/// ```
///
/// (phi1 the line's angle, phi2 the body's; periods 2.49 s and 0.51 s).
/// Released at rest from (0.001, -0.0015) rad, the centre's sideways
/// motion L phi1 + d phi2 is the sum of the two modes' cosines. The line
/// (EA 1e5 N, 1 g/m) starts stretched to 1 m by the body's weight, so the
/// rod's model holds to about 1e-4 (the line's mass against the body's,
/// its stretch's change with the swing); over 6 s, 74 radians of the
/// fast mode, that is a phase of 7e-3 at most. Measured: 1.7e-3 of the
/// modes' amplitude, the same at half the amplitude (so not the swing's
/// nonlinearity, which at 0.01 rad gave 1.5e-2), at half the step (so
/// not the step's error) and with EA ten times larger.
#[test]
fn a_body_hanging_from_a_line_swings_as_a_double_pendulum() {
    let (m, inertia, l, d, g) = (10.0, 0.5, 1.0, 0.5, 9.81);
    let (phi1, phi2) = (0.001f64, -0.0015f64);
    let top = [l * phi1.sin(), 0.0, -l * phi1.cos()];
    let centre = [top[0] + d * phi2.sin(), 0.0, top[2] - d * phi2.cos()];
    // Unstretched so that the body's weight stretches it to l.
    let (model, state) = pendulum_line(l, phi1, m * g);
    // Body axes: the point is 0.5 m up the body's z axis, turned by phi2
    // about y (R_y(-phi2) takes +z to (-sin phi2, 0, cos phi2)).
    let body = Body::new(
        BodyKind::Free,
        centre,
        stancf::body::pose::rotation_from_moordyn_angles([0.0, -phi2.to_degrees(), 0.0]),
        RigidInertia::principal(m, [0.0; 3], [inertia; 3]),
    );
    let system = System::with_bodies(
        vec![Line {
            model,
            ends: [End::Point(0), End::Point(1)],
        }],
        vec![Point::fixed([0.0; 3]), Point::on_body(0, [0.0, 0.0, d])],
        vec![body],
        [0.0, 0.0, -g],
    )
    .expect("system");
    let settings = StepSettings {
        time_step: 0.005,
        time_scheme: TimeScheme::Galerkin,
        ..StepSettings::default()
    };
    let mut sim = SystemSimulation::new(system, vec![state], settings).unwrap();
    // The modes: det(K - w^2 M) = 0, a quadratic in w^2.
    let (m11, m12, m22) = (m * l * l, m * l * d, m * d * d + inertia);
    let (k11, k22) = (m * g * l, m * g * d);
    let a = m11 * m22 - m12 * m12;
    let b = -(k11 * m22 + k22 * m11);
    let c = k11 * k22;
    let root = (b * b - 4.0 * a * c).sqrt();
    let w2 = [(-b - root) / (2.0 * a), (-b + root) / (2.0 * a)];
    // Mode shapes (1, r_i): (k11 - w^2 m11) - w^2 m12 r = 0.
    let r = w2.map(|w| (k11 - w * m11) / (w * m12));
    // q0 = c1 (1, r1) + c2 (1, r2).
    let c2 = (phi2 - r[0] * phi1) / (r[1] - r[0]);
    let c1 = phi1 - c2;
    let sideways = |t: f64| {
        let q1 = c1 * (w2[0].sqrt() * t).cos() + c2 * (w2[1].sqrt() * t).cos();
        let q2 = c1 * r[0] * (w2[0].sqrt() * t).cos() + c2 * r[1] * (w2[1].sqrt() * t).cos();
        l * q1 + d * q2
    };
    let amplitude = (c1 * (l + d * r[0])).abs() + (c2 * (l + d * r[1])).abs();
    let mut worst = 0.0f64;
    for _ in 0..1200 {
        sim.step().expect("step");
        let x = sim.free_body(0).unwrap().centre()[0];
        worst = worst.max((x - sideways(sim.time())).abs());
    }
    eprintln!(
        "periods {:.3} s and {:.3} s; largest difference from the modes {worst:.2e} m \
         ({:.1e} of the modes' sideways amplitude {amplitude:.1e} m)",
        2.0 * std::f64::consts::PI / w2[0].sqrt(),
        2.0 * std::f64::consts::PI / w2[1].sqrt(),
        worst / amplitude
    );
    assert!(worst < 5e-3 * amplitude, "{worst:e}");
}

/// A body in water swinging on its line, its drag (translational and
/// rotational) and added mass on: its energy (the water's added mass in
/// the kinetic) less the work of the water on it is kept to the step's
/// error, at fourth order (the drag's work is its power at the slab's
/// time points, the same quadrature as its virtual work in the rows,
/// docs/method.md §15.6): measured drifts printed, asserted a ratio above
/// 8 from dt 0.02 to 0.01 s and a drift below 1e-4 of the energy the
/// water took. The line starts stretched by the body's weight less its
/// buoyancy (see docs/method.md §15.7 for a line started far from that).
#[test]
fn a_swinging_body_in_water_loses_what_its_drag_takes() {
    let run = |dt: f64| {
        let (m, l, g, volume) = (10.0, 1.0, 9.81, 0.004);
        let phi = 0.3f64;
        let net = (m - 1025.0 * volume) * g;
        let (model, state) = pendulum_line(l, phi, net * phi.cos());
        let top = [l * phi.sin(), 0.0, -l * phi.cos()];
        let mut body = Body::new(
            BodyKind::Free,
            [top[0], 0.0, top[2] - 0.5],
            stancf::body::pose::rotation_from_moordyn_angles([0.0; 3]),
            RigidInertia::principal(m, [0.0; 3], [0.5; 3]),
        );
        body.water = Some(stancf::body::BodyWater {
            density: 1025.0,
            volume,
            added_mass_coefficients: [1.0, 0.8, 0.5],
            drag_areas: [0.05, 0.08, 0.03],
            rotational_drag_areas: [0.01, 0.01, 0.01],
            current: [0.0; 3],
            rods: Vec::new(),
            gravity: 0.0,
            sea: None,
            external: Default::default(),
            host: None,
        });
        let system = System::with_bodies(
            vec![Line {
                model,
                ends: [End::Point(0), End::Point(1)],
            }],
            vec![Point::fixed([0.0; 3]), Point::on_body(0, [0.0, 0.0, 0.5])],
            vec![body],
            [0.0, 0.0, -g],
        )
        .expect("system");
        crate::common::galerkin_energy_drift(system, vec![state], dt)
    };
    crate::common::assert_energy_balance_falls_at_fourth_order(run, 0.01);
}

/// The star on a body lets go of line 0 at its body point at 0.2 s (a
/// failure, docs/method.md §11.16): the line flies off from a new free
/// point of no mass, and over 0.4 s the whole keeps its linear momentum to
/// round-off and its energy to the step's error. The released end snaps
/// (its centrifugal tension gone at once), a motion of high frequency
/// that the step must resolve: measured, the energy drifts 3.4e-8, 1.1e-8,
/// 1.4e-9, 3.8e-12 and 9.4e-14 J (of 6e-2 J) at dt 4, 2, 1, 0.5 and
/// 0.25 ms, at high order once the snap is resolved (ratio 40 over the
/// last halving, order 5.3); without the release the same star drifts
/// 4e-12 J at 8 ms.
#[test]
fn a_spinning_star_on_a_body_that_lets_go_of_a_line_keeps_its_momentum_and_energy() {
    let drift = [0.5, -0.2, 0.1];
    let mut drifts = Vec::new();
    for dt in [5e-4, 2.5e-4] {
        let spin = [1.0, -0.5, SPIN];
        let arms = [[0.1, 0.0, 0.05], [-0.075, 0.13, -0.03], [-0.1, -0.17, 0.0]];
        let (lines, points, states) = star(arms, spin, drift, |x| Point::on_body(0, x));
        let body = star_body([0.002, 0.003, 0.004], [0.0, 0.02, 0.01], spin, drift);
        let system = System::with_bodies(lines, points, vec![body], [0.0; 3]).expect("system");
        let mut sim = SystemSimulation::new(system, states, galerkin(dt)).unwrap();
        sim.set_failures(vec![stancf::system::LineFailure {
            point: 0,
            lines: vec![0],
            time: Some(0.2),
            tension: None,
        }])
        .expect("failure");
        let (p0, e0) = (linear_momentum(&sim), sim.energies().mechanical());
        let (mut dp, mut de) = (0.0f64, 0.0f64);
        for _ in 0..(0.4 / dt).round() as usize {
            sim.step().expect("step");
            let p = linear_momentum(&sim);
            for c in 0..3 {
                dp = dp.max((p[c] - p0[c]).abs());
            }
            de = de.max((sim.energies().mechanical() - e0).abs());
        }
        eprintln!("dt {dt:e}: momentum {dp:.1e}, energy {de:.1e} of {e0:.3e} J");
        assert_eq!(sim.releases().len(), 1);
        assert!(dp < 1e-12, "{dp:e}");
        drifts.push(de);
    }
    assert!(drifts[0] > 16.0 * drifts[1], "{drifts:?}");
    assert!(drifts[1] < 1e-10, "{drifts:?}");
}
