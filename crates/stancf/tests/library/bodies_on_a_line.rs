//! A free body whose mass lies on a line through its centre (docs/method.md
//! (B2a)): MoorDyn's orbitalBody, two point masses on a body of no mass of
//! its own. Its spin about the line moves none of its mass; the inertia
//! about the line is completed, and the line turns as the dumbbell does.

use stancf::body::RigidInertia;
use stancf::system::{Body, BodyKind, Point, System, SystemSimulation};
use stancf::{ModelError, StepSettings, TimeScheme};

const IDENTITY: [[f64; 3]; 3] = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
/// orbitalBody's body 1: its reference point, and its centre and point
/// masses 10 m from it (body axes), the masses 2 m either side of the
/// centre along z.
const REFERENCE: [f64; 3] = [0.0, 10.0, 20.0];
const CENTRE: [f64; 3] = [0.0, -10.0, 0.0];
const POINT_MASS: f64 = 20.0;

/// The body with its two point masses and `extra` points, turning at
/// `spin` (global) about its centre, which is at rest.
fn dumbbell(spin: [f64; 3], extra: Vec<Point>) -> Result<System, ModelError> {
    let mut body = Body::new(
        BodyKind::Free,
        REFERENCE,
        IDENTITY,
        RigidInertia::principal(0.0, CENTRE, [0.0; 3]),
    );
    // v_ref = -spin x c: the centre at rest.
    let c = CENTRE;
    body.velocity = [
        -(spin[1] * c[2] - spin[2] * c[1]),
        -(spin[2] * c[0] - spin[0] * c[2]),
        -(spin[0] * c[1] - spin[1] * c[0]),
    ];
    body.angular_velocity = spin;
    let mut points: Vec<Point> = [-2.0, 2.0]
        .map(|z| Point {
            mass: POINT_MASS,
            ..Point::on_body(0, [CENTRE[0], CENTRE[1], z])
        })
        .to_vec();
    points.extend(extra);
    System::with_bodies(vec![], points, vec![body], [0.0; 3])
}

/// MoorDyn's test of orbitalBody (tests/bodies.cpp, "Excentric body"):
/// spun at 0.2 rad/s about x, across its line (z), with its centre at
/// rest, the reference point orbits the centre at 10 m, at the angle
/// 0.2 t. Nothing acts on the body, so it turns at a constant rate about
/// a fixed axis, which the step's cubic rotation vector holds exactly:
/// what is left is the Newton tolerance (1e-13) and round-off over 40
/// steps, far inside the 1e-9 asserted (MoorDyn's test asserts 1e-6).
#[test]
fn a_dumbbell_spun_across_its_line_orbits_its_centre_at_its_rate() {
    let omega = 0.2;
    let system = dumbbell([omega, 0.0, 0.0], vec![]).expect("a body of point masses on a line");
    let mut settings = StepSettings {
        time_step: 0.25,
        time_scheme: TimeScheme::Galerkin,
        ..StepSettings::default()
    };
    settings.newton.tolerance = 1e-13;
    let mut sim = SystemSimulation::new(system, vec![], settings).expect("simulation");
    let centre = [
        REFERENCE[0] + CENTRE[0],
        REFERENCE[1] + CENTRE[1],
        REFERENCE[2],
    ];
    for _ in 0..40 {
        sim.step().expect("step");
        let t = sim.time();
        let body = sim.free_body(0).expect("free body");
        let r = body.position();
        let q = [0.0, 1.0, 2.0].map(|k: f64| (r[k as usize] - centre[k as usize]) / 10.0);
        let radius = (q[0] * q[0] + q[1] * q[1] + q[2] * q[2]).sqrt();
        assert!((radius - 1.0).abs() <= 1e-9, "t = {t}: radius {radius}");
        let angle = q[2].atan2(q[1]);
        assert!(
            (angle - omega * t).abs() <= 1e-9 * omega * t,
            "t = {t}: angle {angle}, expected {}",
            omega * t
        );
        // No spin about the line (the body's z axis) ever starts.
        let w = body.angular_velocity();
        let axis = body.rotation().map(|row| row[2]);
        let spin = w[0] * axis[0] + w[1] * axis[1] + w[2] * axis[2];
        assert!(spin.abs() <= 1e-12 * omega, "t = {t}: spin {spin}");
    }
}

/// Something acting off the line would turn the body about it with no
/// inertia to resist: refused by name, as is a start spinning about it.
#[test]
fn a_force_off_the_line_of_a_bodys_mass_or_a_spin_about_it_is_refused() {
    let pushed = Point {
        force: [0.0, 0.0, 1.0],
        ..Point::on_body(0, [1.0, -10.0, 0.0])
    };
    let e = dumbbell([0.0; 3], vec![pushed]).unwrap_err().to_string();
    assert!(e.contains("off the line"), "{e}");
    let e = dumbbell([0.0, 0.0, 0.2], vec![]).unwrap_err().to_string();
    assert!(e.contains("spinning about the line"), "{e}");
    // A point without mass or force on the line changes nothing.
    let quiet = Point::on_body(0, [0.0, -10.0, 5.0]);
    assert!(dumbbell([0.2, 0.0, 0.0], vec![quiet]).is_ok());
}

/// A body whose mass is at its centre alone (moments of inertia 0, OpenFAST's
/// md_BdyExtLdDmpg) is a point mass: its inertia is completed on every
/// axis (B2a), and pushed at its centre it accelerates as a point,
/// r = r0 + F t^2 / (2 m), which the step's cubic holds exactly, without
/// turning.
#[test]
fn a_point_mass_body_pushed_at_its_centre_moves_as_a_point() {
    let (m, force) = (5.0, [3.0, -2.0, 1.0]);
    let mut body = Body::new(
        BodyKind::Free,
        REFERENCE,
        IDENTITY,
        RigidInertia::principal(m, [0.0; 3], [0.0; 3]),
    );
    body.loads.push((force, [0.0; 3]));
    let system = System::with_bodies(vec![], vec![], vec![body], [0.0; 3]).expect("a point mass");
    let mut settings = StepSettings {
        time_step: 0.1,
        time_scheme: TimeScheme::Galerkin,
        ..StepSettings::default()
    };
    settings.newton.tolerance = 1e-13;
    let mut sim = SystemSimulation::new(system, vec![], settings).expect("simulation");
    for _ in 0..20 {
        sim.step().expect("step");
    }
    let t = sim.time();
    let body = sim.free_body(0).expect("free body");
    let r = body.position();
    for c in 0..3 {
        let want = REFERENCE[c] + force[c] * t * t / (2.0 * m);
        assert!((r[c] - want).abs() <= 1e-10, "{c}: {} against {want}", r[c]);
    }
    assert_eq!(body.angular_velocity(), [0.0; 3]);
    // Pushed off its centre it would turn with nothing to resist: refused.
    let mut off = Body::new(
        BodyKind::Free,
        REFERENCE,
        IDENTITY,
        RigidInertia::principal(m, [0.0; 3], [0.0; 3]),
    );
    off.loads.push((force, [0.0, 0.0, 1.0]));
    let e = System::with_bodies(vec![], vec![], vec![off], [0.0; 3]).unwrap_err();
    assert!(e.to_string().contains("no inertia about any line"), "{e}");
}
