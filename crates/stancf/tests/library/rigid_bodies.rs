//! A rigid body in the space-time step (docs/method.md §15): natural
//! coordinates, the orthonormality conditions at the step's ends, the
//! Galerkin step (B6)-(B7), against Euler's equations in closed form and
//! the conservation laws.

use stancf::body::natural::{self, rotation_from_moordyn_angles};
use stancf::body::{BodyForces, FreeBody, RigidInertia};
use stancf::vec3::{norm, sub};

/// A symmetric top (I_1 = I_2 = 2, I_3 = 1 kg m^2 at its centre, 3 kg)
/// spinning at w = (1, 0, 2) rad/s in its own axes, tilted, no forces.
fn symmetric_top(dt: f64) -> FreeBody {
    let inertia = RigidInertia::principal(3.0, [0.0; 3], [2.0, 2.0, 1.0]);
    let rotation = rotation_from_moordyn_angles([20.0, -35.0, 50.0]);
    let w_body = [1.0, 0.0, 2.0];
    let w: [f64; 3] = std::array::from_fn(|i| (0..3).map(|k| rotation[i][k] * w_body[k]).sum());
    FreeBody::new(
        &inertia,
        &BodyForces::default(),
        [1.0, -2.0, 0.5],
        &rotation,
        [0.3, 0.0, -0.1],
        w,
        dt,
    )
    .expect("body")
}

/// The angular velocity in the body's axes, R^T w.
fn body_axes_rate(b: &FreeBody) -> [f64; 3] {
    let r = b.rotation();
    let w = b.angular_velocity();
    std::array::from_fn(|k| (0..3).map(|i| r[i][k] * w[i]).sum())
}

/// Euler's equations for I_1 = I_2 = 2, I_3 = 1, w_3 = 2: w_1' = w_2,
/// w_2' = -w_1, so w = (cos t, -sin t, 2) in the body's axes.
fn euler_closed_form(t: f64) -> [f64; 3] {
    [t.cos(), -t.sin(), 2.0]
}

/// The step's Jacobian is the derivative of its rows (B6), checked by
/// central differences at an iterate away from the solution.
#[test]
fn a_free_bodys_step_jacobian_is_the_derivative_of_its_rows() {
    let inertia = RigidInertia {
        mass: 2.5,
        centre_of_mass: [0.3, -0.2, 0.6],
        inertia_at_centre: [[2.0, 0.1, 0.0], [0.1, 1.6, -0.2], [0.0, -0.2, 1.2]],
    };
    let forces = BodyForces::weight_and_buoyancy(&inertia, 0.001, 1025.0, [0.0, 0.0, -9.81]);
    let b = FreeBody::new(
        &inertia,
        &forces,
        [0.0; 3],
        &rotation_from_moordyn_angles([5.0, 10.0, 15.0]),
        [0.1, 0.2, 0.3],
        [0.5, -0.4, 0.9],
        0.05,
    )
    .unwrap();
    let x: [f64; 42] = std::array::from_fn(|i| ((i * 13 + 5) % 17) as f64 * 0.07 - 0.5);
    let jac = b.jacobian(&x);
    let h = 1e-6;
    let mut worst = 0.0f64;
    for c in 0..42 {
        let (mut up, mut down) = (x, x);
        up[c] += h;
        down[c] -= h;
        let (ru, rd) = (b.residual(&up), b.residual(&down));
        for r in 0..42 {
            let fd = (ru[r] - rd[r]) / (2.0 * h);
            worst = worst.max((fd - jac[r * 42 + c]).abs() / (1.0 + fd.abs()));
        }
    }
    // The rows are at most quadratic in x: central differences are exact
    // but for round-off, ~eps |r| / h = 1e-10.
    assert!(worst < 1e-8, "largest difference {worst:e}");
}

/// Over 6 s (about one precession of the spin axis in the body, whose
/// rate is (I_3 - I_1)/I_1 w_3 = -1 rad/s) the rate in the body's axes
/// follows Euler's closed form at second order in the step (measured
/// 1.4e-1, 3.2e-2, 7.9e-3 at 0.2, 0.1, 0.05 s: orders 2.11, 2.03; the
/// conditions hold at the step's ends only, and the cubic's chords of the
/// turning columns are short by (w dt)^2 / 8, docs/method.md §15.4;
/// asserted above 1.8). The angular momentum about the origin and the
/// linear momentum are kept to round-off (the discrete momentum maps of a
/// rotation- and translation-invariant step: measured 4e-14 and 1e-13),
/// the columns stay orthonormal to round-off (3e-16), and so does the
/// kinetic energy (1.5e-14; asserted 1e-12).
#[test]
fn a_torque_free_symmetric_top_precesses_as_eulers_equations_say() {
    let duration = 6.0;
    let mut errors = Vec::new();
    for dt in [0.2, 0.1, 0.05] {
        let mut b = symmetric_top(dt);
        let h0 = b.angular_momentum();
        let p0 = b.linear_momentum();
        let (e0, _) = b.energies();
        let steps = (duration / dt).round() as usize;
        let mut worst_h = 0.0f64;
        let mut worst_g = 0.0f64;
        let mut worst_e = 0.0f64;
        let mut worst_p = 0.0f64;
        for _ in 0..steps {
            b.step().expect("step");
            worst_h = worst_h.max(norm(sub(b.angular_momentum(), h0)) / norm(h0));
            worst_p = worst_p.max(norm(sub(b.linear_momentum(), p0)) / norm(p0));
            let g = stancf::body::orthonormality::conditions(b.coordinates());
            worst_g = worst_g.max(g.iter().fold(0.0f64, |m, v| m.max(v.abs())));
            worst_e = worst_e.max((b.energies().0 - e0).abs() / e0);
        }
        let w = body_axes_rate(&b);
        let exact = euler_closed_form(b.time());
        let err = norm(sub(w, exact)) / norm(exact);
        eprintln!(
            "dt {dt}: rate error {err:.3e}, |dH|/|H| {worst_h:.1e}, |dP|/|P| {worst_p:.1e}, \
             |g| {worst_g:.1e}, |dE|/E {worst_e:.2e}, iterations {}",
            b.last_iterations()
        );
        assert!(worst_h < 1e-12, "angular momentum {worst_h:e}");
        assert!(worst_p < 1e-12, "linear momentum {worst_p:e}");
        assert!(worst_g < 1e-13, "orthonormality {worst_g:e}");
        errors.push((err, worst_e));
    }
    for w in errors.windows(2) {
        let order = (w[0].0 / w[1].0).log2();
        eprintln!("order of the rate's error: {order:.2}");
        assert!(order > 1.8, "{errors:?}");
    }
    for (_, energy) in &errors {
        assert!(*energy < 1e-12, "energy {energy:e}");
    }
}

/// Weight and buoyancy at an offset centre of mass: the linear momentum
/// grows by the net force times t, to round-off, while the body spins.
#[test]
fn a_sinking_spinning_body_gains_momentum_at_its_net_weight() {
    let inertia = RigidInertia::principal(1200.0, [0.2, 0.0, -0.5], [400.0, 500.0, 300.0]);
    let g = [0.0, 0.0, -9.80665];
    let forces = BodyForces::weight_and_buoyancy(&inertia, 0.8, 1025.0, g);
    let net = (1200.0 - 1025.0 * 0.8) * -9.80665;
    let mut b = FreeBody::new(
        &inertia,
        &forces,
        [0.0, 0.0, -10.0],
        &rotation_from_moordyn_angles([0.0, 30.0, 0.0]),
        [0.0; 3],
        [0.0, 0.0, 1.5],
        0.01,
    )
    .unwrap();
    let p0 = b.linear_momentum();
    for _ in 0..200 {
        b.step().unwrap();
    }
    let p = b.linear_momentum();
    let t = b.time();
    for i in 0..3 {
        let expected = p0[i] + if i == 2 { net * t } else { 0.0 };
        assert!(
            (p[i] - expected).abs() < 1e-12 * norm(p),
            "momentum {i}: {} vs {expected}",
            p[i]
        );
    }
    // The centre of mass moves as a particle under the net weight,
    // r_G(t) = r_G0 + v_G0 t + 1/2 a t^2 (v_G0 = p0 / m): the step keeps
    // the momentum exactly, and the centre's path to the scheme's error.
    let c0 = natural::point(
        &natural::from_pose(
            [0.0, 0.0, -10.0],
            &rotation_from_moordyn_angles([0.0, 30.0, 0.0]),
        ),
        inertia.centre_of_mass,
    );
    let c = natural::point(b.coordinates(), inertia.centre_of_mass);
    let a = net / 1200.0;
    let expected: [f64; 3] = std::array::from_fn(|i| {
        c0[i] + p0[i] / 1200.0 * t + if i == 2 { 0.5 * a * t * t } else { 0.0 }
    });
    let off = norm(sub(c, expected));
    eprintln!("centre of mass off its particle path by {off:e} m after {t} s");
    assert!(off < 1e-6, "{off}");
}
