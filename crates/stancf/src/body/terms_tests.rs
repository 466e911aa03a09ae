//! Checks of a body's terms at one time point (docs/method.md §15.4,
//! §15.6, §15.11, §15.15, §15.21): the drag's power, and every term's
//! derivatives against central differences.

use super::*;
use crate::water::kinematics::Sea;

/// A body of 800 kg, its centre off its reference point, in `water`.
fn test_context<'a>(rotation_a: &'a [[f64; 3]; 3], water: &'a BodyWater) -> Context<'a> {
    Context {
        mass: 800.0,
        inertia_at_centre: &[[50.0, 0.0, 0.0], [0.0, 60.0, 0.0], [0.0, 0.0, 70.0]],
        centre_of_mass: [0.3, -0.4, 0.5],
        rotation_a,
        loads: &[],
        water: Some(water),
        time: FlowTime::At(0.0),
    }
}

/// The drag's generalized forces (B10) do the drag's power, at a point
/// of the chart away from the step's start (theta != 0, so J_r^T and
/// the turned moment arm count): Q_r . v_G + Q_theta . theta_dot =
/// f . v_ref + M . Omega, the force f acting at the reference point,
/// off the centre.
#[test]
fn the_drags_generalized_forces_do_the_drags_power() {
    let rotation_a = crate::body::pose::rotation_from_moordyn_angles([15.0, -25.0, 40.0]);
    let water = BodyWater {
        density: 1025.0,
        volume: 0.7,
        added_mass_coefficients: [0.5, 0.5, 0.5],
        drag_areas: [0.8, 1.3, 2.1],
        rotational_drag_areas: [0.4, 0.6, 0.9],
        current: [0.2, -0.1, 0.05],
        rods: Vec::new(),
        gravity: 9.81,
        sea: None,
        external: external_sample(),
        host: None,
    };
    let ctx = test_context(&rotation_a, &water);
    // At theta != 0 in the chart: R = R_a exp([theta]), Omega = J_r
    // theta_dot; the power is Q_r . v_G + Q_theta . theta_dot.
    let (v_g, theta, theta_dot) = ([0.7, -0.3, 0.4], [0.3, -0.5, 0.8], [0.2, 0.5, -0.6]);
    let vars: [JetVec<NV>; 4] = [
        v_g.map(Jet::constant),
        theta.map(Jet::constant),
        theta_dot.map(Jet::constant),
        [0.0, 0.0, -10.0].map(Jet::constant),
    ];
    let (q_r, q_theta) = ctx.drag(&vars).unwrap();
    let power_q: f64 = (0..3)
        .map(|i| q_r[i].v * v_g[i] + q_theta[i].v * theta_dot[i])
        .sum();
    let turned = crate::vec3::mat3_mul(&rotation_a, &crate::body::rotation::exp_map(theta));
    let rotation = turned;
    let jr = crate::body::rotation::right_jacobian(theta);
    let omega: [f64; 3] = std::array::from_fn(|i| (0..3).map(|k| jr[i][k] * theta_dot[k]).sum());
    // The same from the forces: u = R^T (v_G - U) + c x Omega (B9).
    let rel = crate::vec3::sub(v_g, water.current);
    let c_x_w = crate::vec3::cross(ctx.centre_of_mass, omega);
    let u: [f64; 3] =
        std::array::from_fn(|i| (0..3).map(|k| rotation[k][i] * rel[k]).sum::<f64>() + c_x_w[i]);
    let speed = crate::vec3::norm(u);
    let spin = crate::vec3::norm(omega);
    let f: [f64; 3] = std::array::from_fn(|i| -0.5 * 1025.0 * water.drag_areas[i] * u[i] * speed);
    let m: [f64; 3] =
        std::array::from_fn(|i| -0.5 * 1025.0 * water.rotational_drag_areas[i] * omega[i] * spin);
    // The reference point moves at u + U (in body axes) over the ground:
    // the power against the ground is f . (u + R^T U) + M . Omega.
    let current_body: [f64; 3] =
        std::array::from_fn(|i| (0..3).map(|k| rotation[k][i] * water.current[k]).sum());
    let v_ref: [f64; 3] = std::array::from_fn(|i| u[i] + current_body[i]);
    // The external loads (B42)-(B43) at the reference point: the
    // body-fixed force, the damping along the body's axes and along
    // the global axes (on R v_ref).
    let e = &water.external;
    let along_body = e.body.force(v_ref).0;
    let global = crate::body::pose::rotate(&rotation, v_ref);
    let along_global = e.global.force(global).0;
    let external_power = crate::vec3::dot(e.body_force, v_ref)
        + crate::vec3::dot(along_body, v_ref)
        + crate::vec3::dot(along_global, global);
    let power: f64 = (0..3)
        .map(|i| f[i] * v_ref[i] + m[i] * omega[i])
        .sum::<f64>()
        + external_power;
    assert!(power < 0.0);
    assert!(
        (power_q - power).abs() < 1e-12 * power.abs(),
        "{power_q} vs {power}"
    );
}

/// The drag's generalized forces (with the momentum the water keeps,
/// (B23)) and the action's density with a rod (B18)-(B22) carry their
/// exact derivatives in the twelve variables,
/// against central differences of their values: the rod deep under
/// water, crossing the surface (its wet length and its buoyancy's
/// potential then move with the pose), and with a cap at the surface
/// (its wetness moves too).
#[test]
fn the_terms_derivatives_with_a_rod_are_exact() {
    let rod = super::super::rod::sample();
    let water = BodyWater {
        density: 1025.0,
        added_mass_coefficients: [0.5, 0.3, 0.2],
        drag_areas: [0.8, 1.3, 2.1],
        current: [0.2, -0.1, 0.05],
        rods: vec![rod.clone()],
        gravity: 9.81,
        external: external_sample(),
        ..BodyWater::default()
    };
    terms_jets_are_exact(&water, FlowTime::At(0.0));
}

/// MoorDyn-F's external loads, every part of them given.
fn external_sample() -> BodyExternal {
    BodyExternal {
        body_force: [120.0, -40.0, 75.0],
        global: crate::damping::AxisDamping {
            linear: [300.0, 150.0, 80.0],
            quadratic: [900.0, 0.0, 400.0],
        },
        body: crate::damping::AxisDamping {
            linear: [50.0, 0.0, 210.0],
            quadratic: [0.0, 700.0, 350.0],
        },
    }
}

/// The same in a sea (§15.15): two crossing waves over a sheared
/// current, the flow's velocity, acceleration and dynamic pressure
/// moving with the pose (B31)-(B33); at a time of a step and in
/// statics' steady current.
#[test]
fn the_terms_derivatives_in_waves_are_exact() {
    use crate::water::current::{CurrentProfile, CurrentRow, Ramp};
    use crate::water::waves::AiryWave;
    let waves = [(1.2, 7.0, 20.0, 0.0), (0.6, 4.5, -70.0, 50.0)].map(|(a, t, h, p)| AiryWave {
        amplitude: a,
        period: t,
        heading_deg: h,
        phase_deg: p,
    });
    let rows = [(0.0, [0.4, -0.2, 0.0]), (-30.0, [0.1, 0.1, 0.0])]
        .map(|(z, velocity)| CurrentRow { z, velocity });
    let sea = Sea::new(40.0, 9.81, &waves)
        .unwrap()
        .with_current(CurrentProfile::new(&rows).unwrap(), Ramp::NONE);
    let water = BodyWater {
        density: 1025.0,
        volume: 0.7,
        added_mass_coefficients: [0.5, 0.3, 0.2],
        drag_areas: [0.8, 1.3, 2.1],
        rods: vec![super::super::rod::sample()],
        gravity: 9.81,
        sea: Some(std::sync::Arc::new(sea)),
        ..BodyWater::default()
    };
    terms_jets_are_exact(&water, FlowTime::At(3.7));
    terms_jets_are_exact(&water, FlowTime::Steady);
}

fn terms_jets_are_exact(water: &BodyWater, time: FlowTime) {
    let rotation_a = crate::body::pose::rotation_from_moordyn_angles([15.0, -25.0, 40.0]);
    let rod = &water.rods[0];
    let mut ctx = test_context(&rotation_a, water);
    ctx.time = time;
    let theta = [0.3, -0.5, 0.8];
    let turned = crate::vec3::mat3_mul(&rotation_a, &crate::body::rotation::exp_map(theta));
    let middle = crate::vec3::sub(rod.middle(), ctx.centre_of_mass);
    let middle_z = crate::body::pose::rotate(&turned, middle)[2];
    let end_a = crate::vec3::sub(rod.end_a, ctx.centre_of_mass);
    let end_a_z = crate::body::pose::rotate(&turned, end_a)[2];
    // Deep; its middle at the surface; its cap A half a radius under.
    for centre_z in [-20.0, -middle_z, -0.075 - end_a_z] {
        let mut at = [
            0.7, -0.3, 0.4, 0.0, 0.0, 0.0, 0.2, 0.5, -0.6, 0.4, -0.2, centre_z,
        ];
        at[3..6].copy_from_slice(&theta);
        let eval = |x: &[f64; NV]| {
            let v: [JetVec<NV>; 4] = std::array::from_fn(|k| {
                std::array::from_fn(|i| Jet::variable(x[3 * k + i], 3 * k + i))
            });
            let (a, b) = ctx.drag(&v).unwrap();
            // The drag's rows as jets of second order without a
            // Hessian (they carry none: virtual work).
            let full = |q: Grad<NV>| Jet {
                v: q.v,
                g: q.g,
                h: [[0.0; NV]; NV],
            };
            [a[0], a[1], a[2], b[0], b[1], b[2]]
                .map(full)
                .into_iter()
                .chain([ctx.density(&v)])
                .collect::<Vec<_>>()
        };
        let exact = eval(&at);
        let h = 1e-6;
        let mut worst = 0.0f64;
        for j in 0..NV {
            let (mut p, mut m) = (at, at);
            p[j] += h;
            m[j] -= h;
            let (fp, fm) = (eval(&p), eval(&m));
            for r in 0..7 {
                let size = exact[r].v.abs().max(1.0);
                let fd = (fp[r].v - fm[r].v) / (2.0 * h);
                worst = worst.max((fd - exact[r].g[j]).abs() / size);
                // The drag's virtual work enters the rows by its value
                // and their Jacobian by its first derivatives; the
                // action's density by its first and second.
                if r < 6 {
                    continue;
                }
                for k in 0..NV {
                    let fd2 = (fp[r].g[k] - fm[r].g[k]) / (2.0 * h);
                    worst = worst.max((fd2 - exact[r].h[k][j]).abs() / size);
                }
            }
        }
        eprintln!("the terms' jets at centre z {centre_z:.3}: {worst:.1e}");
        assert!(worst < 1e-6, "{worst:e}");
    }
}
