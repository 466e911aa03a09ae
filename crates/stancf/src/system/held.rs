//! The loads of a body whose motion is given: what it pushes its holder
//! with, its inverse dynamics (docs/method.md §15.18, (B36)). A coupled
//! body's rods (MoorDyn's coupled rod is one) are carried by the host,
//! which feels their weight, buoyancy and water and what it takes to
//! accelerate them with their added mass.
//!
//! In the chart centred at the instant (theta = 0, R_a = R(t)), with
//! q = (r_G, theta), q_dot = (v_G, theta_dot = Omega) and the action's
//! density D = T - U_b of the body's terms (B9), (B20), Lagrange's
//! equations give the generalized force the holder applies:
//!
//! ```text
//!   Q_h = d/dt dD/dq_dot - dD/dq - F_c - Q_w,
//!   d/dt dD/dq_dot = (d2D/dq_dot dq) q_dot + (d2D/dq_dot dq_dot) q_ddot          (B36)
//! ```
//!
//! with F_c the constant forces (the weight less the lumped volume's
//! buoyancy at the centre of mass, the forces at points, a constant
//! moment), Q_w the water's
//! virtual work (B10), (B19), (B32), and q_ddot = (a_G, Omega_dot): at
//! theta = 0 the chart's theta_ddot is Omega_dot (theta_dot =
//! J_r(theta)^-1 Omega, J_r^-1 = I + [theta]/2 + ..., adds Omega x Omega /
//! 2 = 0). At theta = 0, J_r = I, so Q_h's theta part is the holder's
//! moment about the centre in body axes. The body pushes its holder with
//! -Q_h: the force -Q_h,r (global) and the moment -R Q_h,theta about
//! the centre, here moved to the reference point.

use super::bodies::Body;
use crate::body::flow::FlowTime;
use crate::body::jet::{Jet, JetVec};
use crate::body::pose::{rotate, rotate_back};
use crate::body::terms::{Context, NV};
use crate::vec3::{add, cross, scale, sub};

/// A body's motion at an instant: its reference point's position,
/// velocity and acceleration, its rotation (body axes to global), its
/// angular velocity and angular acceleration (global).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct HeldMotion {
    pub position: [f64; 3],
    pub velocity: [f64; 3],
    pub acceleration: [f64; 3],
    pub rotation: [[f64; 3]; 3],
    pub angular_velocity: [f64; 3],
    pub angular_acceleration: [f64; 3],
}

impl HeldMotion {
    /// At rest at `position` turned by `rotation`.
    pub fn at_rest(position: [f64; 3], rotation: [[f64; 3]; 3]) -> Self {
        HeldMotion {
            position,
            velocity: [0.0; 3],
            acceleration: [0.0; 3],
            rotation,
            angular_velocity: [0.0; 3],
            angular_acceleration: [0.0; 3],
        }
    }
}

/// What `body` (its inertia with its rods folded in, its water, its
/// constant loads) pushes the holder that moves it as `m` with, under
/// `gravity` at `time` (B36): the force (global) and its moment about the
/// reference point.
pub fn held_push(
    body: &Body,
    gravity: [f64; 3],
    m: &HeldMotion,
    time: FlowTime,
) -> ([f64; 3], [f64; 3]) {
    let inertia = &body.inertia;
    let c = inertia.centre_of_mass;
    let arm = rotate(&m.rotation, c);
    let w = m.angular_velocity;
    let (v_g, a_g) = (
        add(m.velocity, cross(w, arm)),
        add(
            add(m.acceleration, cross(m.angular_acceleration, arm)),
            cross(w, cross(w, arm)),
        ),
    );
    let omega = rotate_back(&m.rotation, w);
    let omega_dot = rotate_back(&m.rotation, m.angular_acceleration);
    let ctx = Context {
        mass: inertia.mass,
        inertia_at_centre: &inertia.inertia_at_centre,
        centre_of_mass: c,
        rotation_a: &m.rotation,
        loads: &[],
        water: body.water.as_ref(),
        time,
    };
    let centre = add(m.position, arm);
    let v: [JetVec<NV>; 4] = std::array::from_fn(|k| {
        std::array::from_fn(|i| {
            let value = [v_g[i], 0.0, omega[i], centre[i]][k];
            Jet::variable(value, 3 * k + i)
        })
    });
    let density = ctx.density(&v);
    // q_dot and q_ddot by variable: v_G, theta, theta_dot, r_G.
    let rate = |j: usize| [a_g, omega, omega_dot, v_g][j / 3][j % 3];
    let d_dt = |k: usize| (0..NV).map(|j| density.h[k][j] * rate(j)).sum::<f64>();
    let water = ctx.drag(&v);
    let water_r = water.as_ref().map_or([0.0; 3], |(r, _)| r.map(|q| q.v));
    let water_theta = water.as_ref().map_or([0.0; 3], |(_, t)| t.map(|q| q.v));
    // The constant forces: the weight less the lumped volume's buoyancy at
    // the centre, the loads at their points; their moment about the
    // centre (body axes).
    let (density_w, volume) = body
        .water
        .as_ref()
        .map_or((0.0, 0.0), |w| (w.density, w.volume));
    let weight = scale(inertia.mass - density_w * volume, gravity);
    let mut constant = weight;
    let mut constant_moment = [0.0; 3];
    for (f, xi) in &body.loads {
        constant = add(constant, *f);
        let lever = rotate(&m.rotation, sub(*xi, c));
        constant_moment = add(constant_moment, cross(lever, *f));
    }
    // A constant moment on the body (global, B27).
    let constant_moment = rotate_back(&m.rotation, add(constant_moment, body.moment));
    let held_r: [f64; 3] =
        std::array::from_fn(|i| d_dt(i) - density.g[9 + i] - constant[i] - water_r[i]);
    let held_theta: [f64; 3] = std::array::from_fn(|i| {
        d_dt(6 + i) - density.g[3 + i] - constant_moment[i] - water_theta[i]
    });
    let force = held_r.map(|q| -q);
    let about_centre = rotate(&m.rotation, held_theta.map(|q| -q));
    (force, add(about_centre, cross(arm, force)))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::body::inertia::RigidInertia;
    use crate::body::pose::rotation_from_moordyn_angles;
    use crate::system::BodyKind;

    fn body(inertia: RigidInertia) -> Body {
        let turned = rotation_from_moordyn_angles([0.0; 3]);
        Body::new(BodyKind::Coupled, [0.0; 3], turned, inertia)
    }

    /// In air a held body pushes with its weight less its momentum's
    /// rate: F = m g - m a_G, and about its centre M_G = -R (I Omega_dot
    /// plus Omega x I Omega) (Euler's equations), moved to the reference
    /// point; an asymmetric body off its reference point, turned, spinning
    /// and accelerating, against the closed forms to 1e-12.
    #[test]
    fn a_held_body_in_air_pushes_by_newtons_and_eulers_laws() {
        let i = [[3.0, 0.4, -0.2], [0.4, 5.0, 0.3], [-0.2, 0.3, 7.0]];
        let inertia = RigidInertia {
            mass: 12.0,
            centre_of_mass: [0.3, -0.7, 1.1],
            inertia_at_centre: i,
        };
        let b = body(inertia.clone());
        let g = [0.0, 0.0, -9.81];
        let m = HeldMotion {
            position: [1.0, 2.0, -3.0],
            velocity: [0.4, -0.2, 0.9],
            acceleration: [1.3, 0.5, -2.0],
            rotation: rotation_from_moordyn_angles([20.0, -35.0, 60.0]),
            angular_velocity: [0.7, -1.1, 0.4],
            angular_acceleration: [-0.5, 0.8, 1.9],
        };
        let (f, moment) = held_push(&b, g, &m, FlowTime::Steady);
        let arm = rotate(&m.rotation, inertia.centre_of_mass);
        let w = m.angular_velocity;
        let a_g = add(
            add(m.acceleration, cross(m.angular_acceleration, arm)),
            cross(w, cross(w, arm)),
        );
        let want_f: [f64; 3] = std::array::from_fn(|k| 12.0 * (g[k] - a_g[k]));
        let omega = rotate_back(&m.rotation, w);
        let omega_dot = rotate_back(&m.rotation, m.angular_acceleration);
        let times = |v: [f64; 3]| -> [f64; 3] {
            std::array::from_fn(|r| (0..3).map(|k| i[r][k] * v[k]).sum())
        };
        let euler = add(times(omega_dot), cross(omega, times(omega)));
        let want_m = add(rotate(&m.rotation, scale(-1.0, euler)), cross(arm, want_f));
        for k in 0..3 {
            assert!((f[k] - want_f[k]).abs() < 1e-12 * 200.0, "{f:?} {want_f:?}");
            assert!(
                (moment[k] - want_m[k]).abs() < 1e-12 * 200.0,
                "{moment:?} {want_m:?}"
            );
        }
    }

    /// A rod 4 m long, 0.5 m across, level along x from the reference
    /// point, 10 m down, in still water (rho 1025), Ca 0.8, CaEnd 0.6, no
    /// drag: its holder's body of no mass of its own, the rod folded in.
    fn held_rod(cd: f64) -> (Body, crate::body::Rod) {
        let rod = crate::body::Rod {
            end_a: [0.0; 3],
            end_b: [4.0, 0.0, 0.0],
            diameter: 0.5,
            mass_per_length: 150.0,
            drag_coefficient: cd,
            added_mass_coefficient: 0.8,
            end_drag_coefficient: 0.0,
            end_added_mass_coefficient: 0.6,
            segments: 4,
        };
        let mut b = body(rod.inertia());
        b.water = Some(crate::body::BodyWater {
            density: 1025.0,
            rods: vec![rod.clone()],
            gravity: 9.81,
            ..Default::default()
        });
        (b, rod)
    }

    /// A held rod under water pushes its holder with its weight less its
    /// buoyancy at its middle, less its mass and added mass times its
    /// acceleration: across it rho Ca A L (B18), along it the caps' 2 rho
    /// CaEnd pi d^3 / 12; turning about a vertical axis through its end A
    /// at a constant rate w, outward by (m + rho Ca A L) w^2 L/2: its
    /// sections move across it, and the added mass's momentum turns with
    /// the rod as the rod's own does (Kirchhoff's -w x P); with
    /// drag, at a steady speed v across it, 1/2 rho Cd d L v^2 against the
    /// motion. Each to 1e-10 of the weight.
    #[test]
    fn a_held_rod_in_water_pushes_by_its_wet_weight_inertia_and_drag() {
        let (b, rod) = held_rod(0.0);
        let g = [0.0, 0.0, -9.81];
        let (rho, l, d) = (1025.0, 4.0, 0.5);
        let area = std::f64::consts::PI * d * d / 4.0;
        let (mass, displaced) = (150.0 * l, rho * area * l);
        let at = |a: [f64; 3], w: [f64; 3]| HeldMotion {
            acceleration: a,
            angular_velocity: w,
            ..HeldMotion::at_rest([0.0, 0.0, -10.0], rotation_from_moordyn_angles([0.0; 3]))
        };
        let wet = (mass - displaced) * 9.81;
        let close = |got: [f64; 3], want: [f64; 3], what: &str| {
            for k in 0..3 {
                assert!(
                    (got[k] - want[k]).abs() < 1e-10 * wet.abs(),
                    "{what}: {got:?} {want:?}"
                );
            }
        };
        let (f, m) = held_push(&b, g, &at([0.0; 3], [0.0; 3]), FlowTime::Steady);
        close(f, [0.0, 0.0, -wet], "at rest");
        // The wet weight at the middle, 2 m along x: its moment about A.
        close(m, [0.0, 2.0 * wet, 0.0], "at rest, moment");
        let across = mass + rho * 0.8 * area * l;
        let (f, _) = held_push(&b, g, &at([0.0, 2.0, 0.0], [0.0; 3]), FlowTime::Steady);
        close(f, [0.0, -2.0 * across, -wet], "across");
        let along = mass + 2.0 * rho * 0.6 * std::f64::consts::PI * d.powi(3) / 12.0;
        let (f, _) = held_push(&b, g, &at([2.0, 0.0, 0.0], [0.0; 3]), FlowTime::Steady);
        close(f, [-2.0 * along, 0.0, -wet], "along");
        let (f, _) = held_push(&b, g, &at([0.0; 3], [0.0, 0.0, 0.5]), FlowTime::Steady);
        // The sections' velocity across the rod carries the added mass's
        // momentum too, which turns with the rod: (m + m_a) w^2 L/2.
        close(f, [across * 0.25 * l / 2.0, 0.0, -wet], "spinning");
        let (b, _) = held_rod(1.1);
        let steady = HeldMotion {
            velocity: [0.0, 1.5, 0.0],
            ..at([0.0; 3], [0.0; 3])
        };
        let (f, _) = held_push(&b, g, &steady, FlowTime::Steady);
        close(f, [0.0, -0.5 * rho * 1.1 * d * l * 2.25, -wet], "drag");
        let _ = rod;
    }
}
