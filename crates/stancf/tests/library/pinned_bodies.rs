//! Bodies pinned at a point to a fixed point (docs/method.md §15.12,
//! (B24)-(B26)): MoorDyn's pinned rods, turning freely about their end A.

use crate::common::rods::{rod, rope};
use crate::common::{
    assert_energy_balance_falls_at_fourth_order, galerkin_energy_drift, period_from_crossings,
    started_with_bodies,
};
use stancf::body::BodyWater;
use stancf::system::{Body, BodyKind, End, Line, Pin, Point, System, SystemSimulation};
use stancf::vec3::{norm, scale, sub};
use stancf::{Cable, ElementType, Material, Model, StepSettings, TimeScheme};

const G: f64 = 9.81;
const RHO: f64 = 1025.0;

/// `body` (body 0) pinned at its reference point to a fixed point there
/// (point 1), holding a light rope at its point `local` from a fixed
/// point at `anchor` (point 2), the lines starting to move with it.
fn pinned(mut body: Body, local: [f64; 3], anchor: [f64; 3]) -> (System, Vec<stancf::State>) {
    let at = body.position;
    body.pin = Some(Pin {
        local: [0.0; 3],
        point: 1,
    });
    let line = Line {
        model: rope(anchor, body.point(local)),
        ends: [End::Point(2), End::Point(0)],
    };
    let points = vec![
        Point::on_body(0, local),
        Point::fixed(at),
        Point::fixed(anchor),
    ];
    let system =
        System::with_bodies(vec![line], points, vec![body], [0.0, 0.0, -G]).expect("system");
    let states = started_with_bodies(&system);
    (system, states)
}

/// A rod 2 m long hanging from a pin at its end A, released 0.01 rad
/// from the vertical in air, swings as the physical pendulum:
/// T = 2 pi sqrt(I_A / (m g L/2)) (1 + theta0^2/16 + 11 theta0^4/3072),
/// I_A = m (L^2/3 + d^2/16) the solid cylinder's about its end; the
/// rope it holds is slack and weighs nothing (2 g of the rod's 20 kg pull
/// on it through its 1 % stretch at most, 1e-4 of the period). The
/// period from three zero crossings of its angle (linearly between
/// steps: the angle is straight there to (omega dt)^2 / 6 of a step,
/// 1e-5 s) to 1e-4 of it; the pinned end stays at the pin to 1e-12 m.
#[test]
fn a_pinned_rod_swings_as_a_physical_pendulum() {
    let (l, d, theta0) = (2.0, 0.1, 0.01f64);
    let axis = [theta0.sin(), 0.0, -theta0.cos()];
    let top = [0.0, 0.0, 5.0];
    let body = Body::rod(BodyKind::Free, top, rod(top, axis, l, 0.0, 0.0));
    let (system, states) = pinned(body, [0.0; 3], [0.0, 0.5, 5.0]);
    let m = 10.0 * l;
    let inertia = m * (l * l / 3.0 + d * d / 16.0);
    let t0 = 2.0 * std::f64::consts::PI * (inertia / (m * G * l / 2.0)).sqrt();
    let want = t0 * (1.0 + theta0.powi(2) / 16.0 + 11.0 * theta0.powi(4) / 3072.0);
    let dt = t0 / 200.0;
    let settings = StepSettings {
        time_step: dt,
        time_scheme: TimeScheme::Galerkin,
        ..StepSettings::default()
    };
    let mut sim = SystemSimulation::new(system, states, settings).expect("simulation");
    let angle = |sim: &SystemSimulation| {
        let body = sim.free_body(0).unwrap();
        let b = body.point([l * axis[0], 0.0, l * axis[2]]);
        let a = body.point([0.0; 3]);
        (b[0] - a[0]).atan2(a[2] - b[2])
    };
    let mut drift = 0.0f64;
    let period = period_from_crossings(&mut sim, dt, angle, |sim| {
        drift = drift.max(norm(sub(sim.free_body(0).unwrap().point([0.0; 3]), top)));
    });
    eprintln!(
        "pinned rod: period {period:.6} s against {want:.6} s ({:.1e}); the pin moved {drift:.1e} m",
        (period - want).abs() / want
    );
    assert!((period - want).abs() < 1e-4 * want, "{period} {want}");
    assert!(drift < 1e-12, "{drift:e}");
}

/// A rod pinned at its end A 5 m under water, swinging wide and turning
/// about its axis with its drag and added mass (in still water: in a
/// current the added mass's kinetic energy of the relative flow is not
/// conserved, pinned or not): its energy less the water's work is kept to
/// the step's error at fourth order (the pin does no work).
#[test]
fn a_pinned_rod_in_water_keeps_its_energy_less_the_waters_work() {
    assert_energy_balance_falls_at_fourth_order(
        |dt| {
            let a = [0.0, 0.0, -5.0];
            let axis = [0.6, 0.0, -0.8];
            let mut body = Body::rod(BodyKind::Free, a, rod(a, axis, 1.5, 1.0, 1.0));
            body.water = Some(BodyWater {
                density: RHO,
                ..BodyWater::default()
            });
            body.angular_velocity = [0.4, 1.5, 0.8];
            let (system, states) = pinned(body, [0.75 * 0.6, 0.0, -0.75 * 0.8], [1.0, 1.0, -6.0]);
            galerkin_energy_drift(system, states, dt)
        },
        1e-3,
    );
}

/// The step's Jacobian with a pinned rod of every coefficient, turning
/// in a current and holding a rope: the derivative of its rows
/// ((B25)'s carried rows and (B24)'s constraints), by central
/// differences.
#[test]
fn the_steps_jacobian_with_a_pinned_rod_is_the_derivative_of_its_rows() {
    let a = [0.2, -0.1, -3.0];
    let axis = stancf::vec3::normalized([0.8, 0.6, 0.6]);
    let mut body = Body::rod(BodyKind::Free, a, rod(a, axis, 1.2, 1.2, 1.0));
    body.water = Some(BodyWater {
        density: RHO,
        current: [0.3, -0.2, 0.05],
        ..BodyWater::default()
    });
    body.angular_velocity = [0.5, 1.0, -0.7];
    let (system, states) = pinned(body, scale(0.8, axis), [1.5, 0.5, -2.0]);
    let err = crate::common::galerkin_jacobian_error(system, states, 0.01);
    eprintln!("step Jacobian with a pinned rod: rel. error {err:.1e}");
    assert!(err < 1e-7, "{err:e}");
}

/// A buoyant rod pinned at its foot in a current leans until its lift's
/// moment about the pin balances its drag's: (rho V - m) g sin(a) =
/// 1/2 rho Cd d L U^2 cos^2(a) (the drag across it, 1/2 rho Cd d (U
/// cos a)^2 per length, has the moment L^2/2 of it; the lift acts at L/2),
/// to the static tolerance (1e-10 rad).
#[test]
fn a_buoyant_rod_pinned_at_its_foot_leans_in_a_current() {
    let (l, d, u) = (4.0, 0.3, 0.5);
    let a = [0.0, 0.0, -18.0];
    let mut r = rod(a, [0.0, 0.0, 1.0], l, 1.2, 1.0);
    r.diameter = d;
    r.end_drag_coefficient = 0.0;
    let lift = (RHO * r.volume() - 10.0 * l) * G;
    let mut body = Body::rod(BodyKind::Free, a, r);
    body.water = Some(BodyWater {
        density: RHO,
        current: [u, 0.0, 0.0],
        ..BodyWater::default()
    });
    let material = Material {
        youngs_modulus: 1e9,
        density: 1000.0,
        area: 1e-4,
        second_moment: 1e-12,
        axial_damping: 0.0,
    };
    // No line on the rod (the pin holds it); a system needs a line: one
    // between two anchors aside.
    let cable = Cable::straight(3.0, 4, ElementType::Sac2)
        .with_origin([10.0, 0.0, -10.0])
        .with_direction([0.0, 0.0, 1.0]);
    let model = Model::new(cable, material, Default::default(), vec![]).expect("model");
    body.pin = Some(Pin {
        local: [0.0; 3],
        point: 0,
    });
    let points = vec![
        Point::fixed(a),
        Point::fixed([10.0, 0.0, -10.0]),
        Point::fixed([10.0, 0.0, -7.0]),
    ];
    let line = Line {
        model,
        ends: [End::Point(1), End::Point(2)],
    };
    let system =
        System::with_bodies(vec![line], points, vec![body], [0.0, 0.0, -G]).expect("system");
    let mut statics = crate::common::seeded_equilibrium(system, 1e-10);
    let (reference, rotation) = statics.body_pose(0).expect("a free body");
    let q = [rotation[0][2], rotation[1][2], rotation[2][2]];
    let alpha = q[0].atan2(q[2]);
    let drag = 0.5 * RHO * 1.2 * d * l * u * u;
    let want = crate::common::lean_in_a_current(lift, drag);
    eprintln!("pinned lean {alpha:.10} rad, balance {want:.10} rad; the foot at {reference:?}");
    assert!((alpha - want).abs() < 1e-8, "{alpha} against {want}");
    assert!(
        norm(sub(reference, a)) < 1e-10,
        "the pin holds: {reference:?}"
    );
    assert!(
        statics.body_stiffness(0).is_none(),
        "a pinned body has no 6 x 6"
    );
}

/// A rod 2 m long (20 kg) hanging from a pin at its top end in air, under
/// a constant moment M = 30 N m about the pin's horizontal axis (B27):
/// - at rest it hangs at the angle where its weight's moment balances M,
///   m g (L/2) sin(phi) = M (0.1538 rad), to the static tolerance;
/// - released hanging straight down it swings about that angle, the
///   moment's work is M times the angle turned (a rotation about a fixed
///   axis: Q_theta = M, the power M phi_dot, quadratic in time, which the
///   Gauss points integrate exactly) to round-off, and its energy less
///   that work is kept to the step's error at fourth order (dt = T/100
///   and T/200).
#[test]
fn a_hanging_rod_under_a_constant_moment_turns_to_its_balance() {
    let (l, moment) = (2.0, 30.0);
    let top = [0.0, 0.0, 5.0];
    let m = 10.0 * l;
    let want = (moment / (m * G * l / 2.0)).asin();
    let build = || {
        let mut body = Body::rod(BodyKind::Free, top, rod(top, [0.0, 0.0, -1.0], l, 0.0, 0.0));
        body.moment = [0.0, moment, 0.0];
        // The rope holds the body at its pin, where the body turns in place.
        pinned(body, [0.0; 3], [0.0, 0.0, 6.0])
    };
    let (system, _) = build();
    let statics = crate::common::seeded_equilibrium(system, 1e-10);
    let (_, rotation) = statics.body_pose(0).expect("a free body");
    // The turn about y: R = R_y(phi), r_02 = sin(phi), r_22 = cos(phi)
    // (the rod, along body -z, swings towards -x).
    let phi = rotation[0][2].atan2(rotation[2][2]);
    eprintln!("under the moment: {phi:.10} rad, balance {want:.10} rad");
    assert!((phi - want).abs() < 1e-8, "{phi} against {want}");

    let inertia = m * (l * l / 3.0 + 0.01 / 16.0);
    let period = 2.0 * std::f64::consts::PI * (inertia / (m * G * l / 2.0)).sqrt();
    let run = |steps: usize| {
        let (system, states) = build();
        let settings = StepSettings {
            time_step: period / steps as f64,
            time_scheme: TimeScheme::Galerkin,
            ..StepSettings::default()
        };
        let mut sim = SystemSimulation::new(system, states, settings).expect("simulation");
        let e0 = sim.energies().mechanical();
        let (mut drift, mut worst, mut most) = (0.0f64, 0.0f64, 0.0f64);
        for _ in 0..steps {
            sim.step().expect("step");
            let body = sim.free_body(0).unwrap();
            let r = body.rotation();
            let turned = r[0][2].atan2(r[2][2]);
            worst = worst.max((body.moment_work() - moment * turned).abs());
            most = most.max(body.moment_work().abs());
            drift = drift.max((sim.energies().mechanical() - sim.external_work() - e0).abs());
        }
        (drift, worst, most)
    };
    let (coarse, _, _) = run(100);
    let (fine, worst, most) = run(200);
    eprintln!(
        "moment's work up to {most:.3} J, against M phi {worst:.1e}; energy less work \
         {coarse:.1e} and {fine:.1e} J (ratio {:.1})",
        coarse / fine
    );
    assert!(worst < 1e-9 * moment, "{worst:e}");
    assert!(
        coarse > 8.0 * fine && fine < 1e-6 * most,
        "{coarse:e} {fine:e}"
    );
}
