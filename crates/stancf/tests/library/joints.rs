//! Joints (docs/method.md §15.14, (B28)-(B30)): a body pinned at one of
//! its points to a point of another free body (MoorDyn's `Body<n>Pinned`
//! rod on a free body). Two rods hanging from one another are a double
//! compound pendulum; a rod pinned under a moored buoy leans in a current.

use crate::common::rods::{rod, rope};
use crate::common::{
    assert_energy_balance_falls_at_fourth_order, galerkin_energy_drift, hanging_line,
    lean_in_a_current, period_from_crossings, seeded_equilibrium, started_with_bodies,
    straight_line,
};
use stancf::body::{BodyWater, RigidInertia};
use stancf::system::{Body, BodyKind, End, Line, Pin, Point, System, SystemSimulation};
use stancf::vec3::{cross, norm, normalized, scale, sub};
use stancf::{Material, State, StepSettings, TimeScheme};

const G: f64 = 9.81;
const RHO: f64 = 1025.0;

/// One rod of a [`double_pendulum`]: its length, its axis (unit) and its
/// angular velocity at t = 0.
#[derive(Clone, Copy)]
struct Link {
    length: f64,
    axis: [f64; 3],
    spin: [f64; 3],
}

/// Rod 0 (body 0) pinned at its end A to a fixed point at `top` (point 0);
/// rod 1 (body 1) pinned at its end A to rod 0's end B (point 1, on body
/// 0), its end A moving with it. `water`: both rods in it with drag and
/// added mass 1 (and light ropes from anchors to the joint's point and to
/// rod 1's end B, points 2-4); else in air with one line between two
/// anchors aside on neither rod (a system needs a line).
fn double_pendulum(
    top: [f64; 3],
    links: [Link; 2],
    water: Option<BodyWater>,
) -> (System, Vec<State>) {
    let c = if water.is_some() { 1.0 } else { 0.0 };
    let joint = std::array::from_fn(|i| top[i] + links[0].length * links[0].axis[i]);
    let end_b = std::array::from_fn(|i| joint[i] + links[1].length * links[1].axis[i]);
    let mut bodies = Vec::new();
    for (k, (a, link)) in [(top, links[0]), (joint, links[1])].into_iter().enumerate() {
        let mut body = Body::rod(BodyKind::Free, a, rod(a, link.axis, link.length, c, c));
        body.angular_velocity = link.spin;
        body.water = water.clone();
        body.pin = Some(Pin {
            local: [0.0; 3],
            point: k,
        });
        bodies.push(body);
    }
    bodies[1].velocity = cross(links[0].spin, sub(joint, top));
    let mut points = vec![
        Point::fixed(top),
        Point::on_body(0, sub(joint, top)),
        Point::on_body(1, sub(end_b, joint)),
    ];
    let lines = if water.is_some() {
        let anchors = [[1.5, 1.0, top[2] - 1.0], [0.5, -1.0, top[2] - 3.0]];
        points.extend(anchors.map(Point::fixed));
        vec![
            Line {
                model: rope(anchors[0], joint),
                ends: [End::Point(3), End::Point(1)],
            },
            Line {
                model: rope(anchors[1], end_b),
                ends: [End::Point(4), End::Point(2)],
            },
        ]
    } else {
        let aside = [10.0, 0.0, top[2]];
        points.extend([aside, [10.0, 0.0, top[2] - 1.0]].map(Point::fixed));
        let (line, _) = hanging_line(aside);
        vec![Line {
            ends: [End::Point(3), End::Point(4)],
            ..line
        }]
    };
    let system = System::with_bodies(lines, points, bodies, [0.0, 0.0, -G]).expect("system");
    let states = started_with_bodies(&system);
    (system, states)
}

/// The buoys' mooring lines: 1 kg/m, EA 1e7 N, light against the lift
/// they hold.
fn mooring_rope() -> Material {
    Material {
        youngs_modulus: 1e10,
        density: 1000.0,
        area: 1e-3,
        second_moment: 1e-12,
        axial_damping: 0.0,
    }
}

/// The angle from the downward vertical, in the x-z plane, of the rod
/// from `a` to `b`.
fn swing(a: [f64; 3], b: [f64; 3]) -> f64 {
    (b[0] - a[0]).atan2(a[2] - b[2])
}

/// Two solid rods (0.1 m across, 10 kg/m; 2 m and 1.5 m) hanging from
/// one another, released at rest in one of their normal modes at 0.002
/// rad, swing at its frequency: the linearized double compound pendulum,
/// det(K - w^2 M) = 0 with
///
/// ```text
///   M = [I_0 + m_1 l_0^2,  m_1 l_0 l_1/2;  m_1 l_0 l_1/2,  I_1 + m_1 l_1^2/4]
///   K = diag((m_0/2 + m_1) g l_0,  m_1 g l_1/2)
/// ```
///
/// (I_0 = m_0 (l_0^2/3 + d^2/16) about rod 0's pin, I_1 = m_1 (l_1^2/12 +
/// d^2/16) about rod 1's centre). The period from three zero crossings
/// of rod 0's angle to 1e-5 of it: the amplitude's shift is of the order
/// of the coupling's cos(theta_1 - theta_0) - 1, (0.0027)^2/2 = 3.5e-6 in
/// the fast mode (measured: 6.0e-5 at 0.01 rad, 2.4e-6 at 0.002, falling
/// as the amplitude squared), the crossings' linear interpolation at 200
/// steps a period below 1e-6; the joint keeps rod 1's end A on rod 0's
/// end B to 1e-12 m.
#[test]
fn a_double_pendulum_of_two_rods_swings_at_its_normal_modes() {
    let (l0, l1, d) = (2.0, 1.5, 0.1);
    let (m0, m1) = (10.0 * l0, 10.0 * l1);
    let i0 = m0 * (l0 * l0 / 3.0 + d * d / 16.0);
    let i1 = m1 * (l1 * l1 / 12.0 + d * d / 16.0);
    let mass = [
        [i0 + m1 * l0 * l0, m1 * l0 * l1 / 2.0],
        [0.0, i1 + m1 * l1 * l1 / 4.0],
    ];
    let (m11, m12, m22) = (mass[0][0], mass[0][1], mass[1][1]);
    let (k11, k22) = ((m0 / 2.0 + m1) * G * l0, m1 * G * l1 / 2.0);
    // (m11 m22 - m12^2) w^4 - (k11 m22 + k22 m11) w^2 + k11 k22 = 0.
    let (a, b, c) = (m11 * m22 - m12 * m12, k11 * m22 + k22 * m11, k11 * k22);
    let root = (b * b - 4.0 * a * c).sqrt();
    for w2 in [(b - root) / (2.0 * a), (b + root) / (2.0 * a)] {
        let want = 2.0 * std::f64::consts::PI / w2.sqrt();
        // The mode: (k11 - w^2 m11) theta0 = w^2 m12 theta1.
        let ratio = (k11 - w2 * m11) / (w2 * m12);
        let theta = scale(0.002 / ratio.abs().max(1.0), [1.0, ratio, 0.0]);
        let links = [(l0, theta[0]), (l1, theta[1])].map(|(length, t)| Link {
            length,
            axis: [t.sin(), 0.0, -t.cos()],
            spin: [0.0; 3],
        });
        let top = [0.0, 0.0, 5.0];
        let (system, states) = double_pendulum(top, links, None);
        let dt = want / 200.0;
        let settings = StepSettings {
            time_step: dt,
            time_scheme: TimeScheme::Galerkin,
            ..StepSettings::default()
        };
        let mut sim = SystemSimulation::new(system, states, settings).expect("simulation");
        let angle = |sim: &SystemSimulation| {
            let rod0 = sim.free_body(0).unwrap();
            swing(rod0.point([0.0; 3]), rod0.point(scale(l0, links[0].axis)))
        };
        let mut gap = 0.0f64;
        let period = period_from_crossings(&mut sim, dt, angle, |sim| {
            let joint = sim.free_body(0).unwrap().point(scale(l0, links[0].axis));
            gap = gap.max(norm(sub(sim.free_body(1).unwrap().point([0.0; 3]), joint)));
        });
        eprintln!(
            "double pendulum, mode theta1/theta0 = {ratio:.4}: period {period:.6} s against \
             {want:.6} s ({:.1e}); the joint opened {gap:.1e} m",
            (period - want).abs() / want
        );
        assert!((period - want).abs() < 1e-5 * want, "{period} {want}");
        assert!(gap < 1e-12, "{gap:e}");
    }
}

/// Two rods 5 m under water hanging from one another, swinging wide and
/// spinning, with drag and added mass and light ropes at the joint and
/// at the lower rod's end: their energy less the water's work is kept to
/// the step's error at fourth order (the joint does no work: its forces
/// on the two rods are equal and opposite at one point).
#[test]
fn a_double_pendulum_in_water_keeps_its_energy_less_the_waters_work() {
    assert_energy_balance_falls_at_fourth_order(
        |dt| {
            let links = [
                Link {
                    length: 2.0,
                    axis: normalized([0.6, 0.0, -0.8]),
                    spin: [0.4, 1.5, 0.8],
                },
                Link {
                    length: 1.5,
                    axis: normalized([-0.3, 0.5, -0.8]),
                    spin: [-1.0, 0.5, 0.7],
                },
            ];
            let water = BodyWater {
                density: RHO,
                ..BodyWater::default()
            };
            let (system, states) = double_pendulum([0.0, 0.0, -5.0], links, Some(water));
            galerkin_energy_drift(system, states, dt)
        },
        1e-3,
    );
}

/// The step's Jacobian of two rods hanging from one another in a
/// current, turning, with ropes at the joint and the lower rod's end:
/// the derivative of its rows (the child's centre rows carried to the
/// joint's point and on to the parent, the joint's constraint against
/// the point's unknowns), by central differences.
#[test]
fn the_steps_jacobian_with_a_joint_is_the_derivative_of_its_rows() {
    let links = [
        Link {
            length: 1.2,
            axis: normalized([0.8, 0.6, -0.6]),
            spin: [0.5, 1.0, -0.7],
        },
        Link {
            length: 0.9,
            axis: normalized([-0.2, 0.7, -0.5]),
            spin: [0.3, -0.8, 0.4],
        },
    ];
    let water = BodyWater {
        density: RHO,
        current: [0.3, -0.2, 0.05],
        ..BodyWater::default()
    };
    let (system, states) = double_pendulum([0.2, -0.1, -3.0], links, Some(water));
    let err = crate::common::galerkin_jacobian_error(system, states, 0.01);
    eprintln!("step Jacobian with a joint: rel. error {err:.1e}");
    assert!(err < 1e-7, "{err:e}");
}

/// A heavy rod (4 m, 0.3 m across, 200 kg/m) pinned under a buoy (500 kg,
/// 2 m^3) that a line holds from an anchor below and aside, in a current
/// of 0.5 m/s: the rod leans until its net weight's moment about the
/// joint balances its drag's, w L sin(a) = 1/2 rho Cd d L U^2 cos^2(a)
/// (the same balance as a rod at a fixed pin: the joint's point is at
/// rest), and the line holds the buoy and the rod together: its pull is
/// -(lift - w L) z - D (cos a, 0, sin a), D = 1/2 rho Cd d L U^2 cos^2(a)
/// the rod's drag, normal to it. To the static tolerance: the angle to
/// 1e-8 rad, the pull to 1e-8 of the lift (the rows are converged to
/// 1e-10 of the lines' stiffness times their length), the rod's end A
/// on the buoy's point to 1e-10 m.
#[test]
fn a_heavy_rod_pinned_under_a_moored_buoy_leans_in_a_current() {
    let (l, d, u, cd) = (4.0, 0.3, 0.5, 1.2);
    let current = [u, 0.0, 0.0];
    let water = BodyWater {
        density: RHO,
        current,
        ..BodyWater::default()
    };
    let centre = [0.0, 0.0, -10.0];
    let joint_local = [0.0, 0.0, -0.5];
    let joint = [0.0, 0.0, -10.5];
    let identity = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
    let mut buoy = Body::new(
        BodyKind::Free,
        centre,
        identity,
        RigidInertia::principal(500.0, [0.0; 3], [100.0; 3]),
    );
    buoy.water = Some(BodyWater {
        volume: 2.0,
        ..water.clone()
    });
    let mut r = rod(joint, [0.0, 0.0, -1.0], l, cd, 1.0);
    r.diameter = d;
    r.mass_per_length = 200.0;
    r.end_drag_coefficient = 0.0;
    let weight = (200.0 * l - RHO * r.volume()) * G;
    let mut hung = Body::rod(BodyKind::Free, joint, r);
    hung.water = Some(water);
    hung.pin = Some(Pin {
        local: [0.0; 3],
        point: 0,
    });
    let anchor = [-8.0, 0.0, -40.0];
    let rope = mooring_rope();
    let line = Line {
        model: straight_line(anchor, joint, 31.0, 10, rope),
        ends: [End::Point(1), End::Point(0)],
    };
    let points = vec![Point::on_body(0, joint_local), Point::fixed(anchor)];
    let system =
        System::with_bodies(vec![line], points, vec![buoy, hung], [0.0, 0.0, -G]).expect("system");
    let statics = seeded_equilibrium(system, 1e-10);
    let lift = (RHO * 2.0 - 500.0) * G;
    let drag_scale = 0.5 * RHO * cd * d * l * u * u;
    let want = lean_in_a_current(weight, drag_scale);
    let (buoy_at, buoy_rotation) = statics.body_pose(0).unwrap();
    let (rod_at, rod_rotation) = statics.body_pose(1).unwrap();
    let axis = stancf::body::pose::rotate(&rod_rotation, [0.0, 0.0, -1.0]);
    let lean = axis[0].atan2(-axis[2]);
    let on_buoy = stancf::body::pose::point(buoy_at, &buoy_rotation, joint_local);
    let gap = norm(sub(rod_at, on_buoy));
    let drag = drag_scale * want.cos().powi(2);
    let expected = [
        -drag * want.cos(),
        0.0,
        -(lift - weight) - drag * want.sin(),
    ];
    let pull = statics.end_forces(0)[1].force;
    let off = norm(sub(pull, expected));
    eprintln!(
        "rod under a buoy: lean {lean:.10} rad against {want:.10} ({:.1e}); the line pulls \
         {pull:?} N ({off:.1e} off); the joint opened {gap:.1e} m",
        (lean - want).abs()
    );
    assert!((lean - want).abs() < 1e-8, "{lean} {want}");
    assert!(off < 1e-8 * lift, "{off:e}");
    assert!(gap < 1e-10, "{gap:e}");
}

/// A buoy (500 kg, 2 m^3) held by three lines that meet at one of its
/// points, 1 m under its centre, with a heavy rod (4 m, 0.3 m across,
/// 200 kg/m) hung at a joint 1 m aside of its centre, in still water:
/// the rod hangs plumb, and the buoy tilts until the lines' point, its
/// lift L and the rod's net weight W balance in moment, tan(b) = W / (L -
/// W) about the axis across the offset. The whole turns freely about
/// the vertical through the lines' point (gravity and still water are
/// the same at every heading; the static solve's hold picks the heading
/// as given, docs/method.md §15.14): roll and heading stay zero to
/// 1e-14 rad, round-off of the rotation (without the hold, the singular
/// solves let them wander: 7e-13 and 1.4e-12 measured), the buoy in the
/// plane of its offset to 1e-12 m; the tilt to 1e-9 rad and the rod's
/// axis to the vertical to 1e-9 rad (the static tolerance).
#[test]
fn a_buoy_on_lines_at_one_point_tilts_under_its_jointed_rod_and_keeps_its_heading() {
    let (l, d) = (4.0, 0.3);
    let identity = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
    let mut buoy = Body::new(
        BodyKind::Free,
        [0.0, 0.0, -10.0],
        identity,
        RigidInertia::principal(500.0, [0.0; 3], [100.0; 3]),
    );
    let still = BodyWater {
        density: RHO,
        ..BodyWater::default()
    };
    buoy.water = Some(BodyWater {
        volume: 2.0,
        ..still.clone()
    });
    let (joint_local, lines_local) = ([1.0, 0.0, 0.0], [0.0, 0.0, -1.0]);
    let joint = buoy.point(joint_local);
    let mut r = rod(joint, [0.0, 0.0, -1.0], l, 1.0, 1.0);
    r.diameter = d;
    r.mass_per_length = 200.0;
    let weight = (200.0 * l - RHO * r.volume()) * G;
    let mut hung = Body::rod(BodyKind::Free, joint, r);
    hung.water = Some(still);
    hung.pin = Some(Pin {
        local: [0.0; 3],
        point: 0,
    });
    let rope = mooring_rope();
    let top = buoy.point(lines_local);
    let mut points = vec![
        Point::on_body(0, joint_local),
        Point::on_body(0, lines_local),
    ];
    let mut lines = Vec::new();
    for k in 0..3 {
        let angle = 2.0 * std::f64::consts::PI * k as f64 / 3.0;
        let anchor = [20.0 * angle.cos(), 20.0 * angle.sin(), -40.0];
        points.push(Point::fixed(anchor));
        lines.push(Line {
            model: straight_line(anchor, top, 36.0, 10, rope),
            ends: [End::Point(2 + k), End::Point(1)],
        });
    }
    let system =
        System::with_bodies(lines, points, vec![buoy, hung], [0.0, 0.0, -G]).expect("system");
    let statics = seeded_equilibrium(system, 1e-10);
    let lift = (RHO * 2.0 - 500.0) * G;
    let want = (weight / (lift - weight)).atan();
    let (at, rotation) = statics.body_pose(0).unwrap();
    let (_, rod_rotation) = statics.body_pose(1).unwrap();
    let axis = [rotation[0][2], rotation[1][2], rotation[2][2]];
    let tilt = axis[0].atan2(axis[2]).abs();
    let roll = axis[1].abs();
    let heading = rotation[1][0].abs();
    let hang = stancf::body::pose::rotate(&rod_rotation, [0.0, 0.0, -1.0]);
    let plumb = hang[0].hypot(hang[1]);
    eprintln!(
        "buoy on one point: tilt {tilt:.10} rad against {want:.10} ({:.1e}); roll {roll:.1e}, \
         heading {heading:.1e}, y {:.1e}; the rod {plumb:.1e} rad off plumb",
        (tilt - want).abs(),
        at[1]
    );
    assert!((tilt - want).abs() < 1e-9, "{tilt} {want}");
    assert!(roll < 1e-14 && heading < 1e-14, "{roll:e} {heading:e}");
    assert!(at[1].abs() < 1e-12, "{}", at[1]);
    assert!(plumb < 1e-9, "{plumb:e}");
}
