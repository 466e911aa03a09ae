//! What a body's slab action and the water's virtual work are at one
//! time point (docs/method.md §15.4, §15.6, §15.11), as functions of the
//! twelve numbers the slab gives there: the centre's velocity v_G
//! (global), the rotation vector theta and its rate theta_dot (the step's
//! chart, R = R_a exp([theta])) and the centre r_G (where the body's rods
//! meet the surface). Evaluated on jets, they carry their exact
//! derivatives to the step's rows.
//!
//! ```text
//!   T = m/2 |v_G|^2 + 1/2 Omega . I_G Omega + 1/2 u . A u,            (B5), (B9)
//!   u = R^T (v_ref - U) = R^T (v_G - U) + c x Omega,   A = rho V diag(Ca)
//!   f = 1/2 rho diag(CdA) u_r |u_r|,   u_r = -u,    M = -1/2 rho diag(CdA_r) Omega |Omega|   (B10)
//!   Q_r = R f,   Q_theta = J_r(theta)^T (f x c + M)
//! ```
//!
//! (body axes but for Q_r; U the current; f the drag at the reference
//! point and M the rotational drag; Q the generalized forces on r_G and on
//! theta: the virtual rotation in body axes is eta = J_r dtheta, and the
//! reference point moves by dr_G + R (c x eta)).

use super::flow::{flow_at, Flow, FlowTime};
use super::jet::{cross, dot, norm, Grad, Jet, JetVec};
use super::rod::Rod;
use super::rotation::{body_rate, times, turn};
use super::waterline::Submerged;
use super::wet::WetPart;
use crate::water::kinematics::Sea;

/// Variables at a time point: v_G (0..3), theta (3..6), theta_dot
/// (6..9), r_G (9..12).
pub const NV: usize = 12;

/// A body's water: MoorDyn's Volume, Ca and CdA (body axes; the rotational
/// drag area multiplies Omega |Omega|, as MoorDyn's does), with the
/// water's density and a uniform steady current, and the body's rods,
/// whose buoyancy, added mass and drag the water adds over their parts
/// under the surface z = 0 (B18)-(B21; their mass is in the body's
/// inertia: [`crate::system::Body`] puts it there). `gravity` is g, along
/// -z: the rods' buoyancy is rho g times their wet volume.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct BodyWater {
    pub density: f64,
    pub volume: f64,
    pub added_mass_coefficients: [f64; 3],
    pub drag_areas: [f64; 3],
    pub rotational_drag_areas: [f64; 3],
    pub current: [f64; 3],
    pub rods: Vec<super::Rod>,
    pub gravity: f64,
    /// The sea whose waves and current act on the body where they are
    /// (§15.15): its velocity in the drag, its acceleration in the fluid's
    /// inertia, its dynamic pressure on the rods' caps. With a sea the
    /// uniform `current` above must be zero (the sea carries the current).
    pub sea: Option<std::sync::Arc<Sea>>,
    /// MoorDyn-F's EXTERNAL LOADS on the body at its reference point: a
    /// force fixed in the body's axes and damping along the global and the
    /// body's axes (docs/method.md §15.21, (B42)-(B43)). Carried with the
    /// water's loads, being virtual work at the same point; a body in air
    /// that has them takes a water of density 0.
    pub external: BodyExternal,
}

/// A force and damping at a body's reference point (MoorDyn-F's EXTERNAL
/// LOADS; a force in global axes is one of the body's constant loads).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct BodyExternal {
    /// A force fixed in the body's axes (N), following the body as it
    /// turns.
    pub body_force: [f64; 3],
    /// Damping of the reference point's velocity along the global axes.
    pub global: crate::damping::AxisDamping,
    /// Damping of the reference point's velocity along the body's axes.
    pub body: crate::damping::AxisDamping,
}

impl BodyExternal {
    /// Whether there is nothing.
    pub fn is_zero(&self) -> bool {
        self.body_force == [0.0; 3] && self.global.is_zero() && self.body.is_zero()
    }
}

impl BodyWater {
    /// Refuses a density, volume or coefficient that is negative or not
    /// finite, naming it.
    pub fn validate(&self, key: &str) -> Result<(), crate::error::ModelError> {
        let named = [
            ("density", vec![self.density]),
            ("volume", vec![self.volume]),
            (
                "added_mass_coefficients",
                self.added_mass_coefficients.to_vec(),
            ),
            ("drag_areas", self.drag_areas.to_vec()),
            ("rotational_drag_areas", self.rotational_drag_areas.to_vec()),
            ("gravity", vec![self.gravity]),
        ];
        for (name, values) in named {
            if values.iter().any(|v| !(v.is_finite() && *v >= 0.0)) {
                return Err(crate::error::ModelError::invalid(
                    format!("{key}.{name}"),
                    format!("{values:?}: must be finite and not negative"),
                ));
            }
        }
        for (k, rod) in self.rods.iter().enumerate() {
            rod.validate(&format!("{key}.rods[{k}]"))?;
        }
        if self.external.body_force.iter().any(|f| !f.is_finite()) {
            return Err(crate::error::ModelError::invalid(
                format!("{key}.body_force"),
                "must be finite",
            ));
        }
        self.external.global.check(&format!("{key}.global"))?;
        self.external.body.check(&format!("{key}.body"))?;
        if self.current.iter().any(|v| !v.is_finite()) {
            return Err(crate::error::ModelError::invalid(
                format!("{key}.current"),
                "must be finite",
            ));
        }
        if self.sea.is_some() && self.current != [0.0; 3] {
            return Err(crate::error::ModelError::invalid(
                format!("{key}.current"),
                "must be zero with a sea: the sea's current acts on the body",
            ));
        }
        Ok(())
    }
}

/// (B42) on jets: |v_i| v_i is v_i^2 times the sign of v_i, whose
/// derivative 2 |v_i| is exact on both sides of zero.
fn damping_on_jets<const H: usize>(
    d: &crate::damping::AxisDamping,
    v: &JetVec<NV, H>,
) -> JetVec<NV, H> {
    std::array::from_fn(|i| {
        let sign = if v[i].v < 0.0 { -1.0 } else { 1.0 };
        let quadratic = (v[i] * v[i]).scale(sign * d.quadratic[i]);
        -(v[i].scale(d.linear[i]) + quadratic)
    })
}

/// A rotation matrix on jets, `[row][column]`.
type Rotation<const H: usize> = [[Jet<NV, H>; 3]; 3];

/// What the terms need of the body and the step.
pub struct Context<'a> {
    pub mass: f64,
    pub inertia_at_centre: &'a [[f64; 3]; 3],
    pub centre_of_mass: [f64; 3],
    /// R_a, the rotation at the step's start.
    pub rotation_a: &'a [[f64; 3]; 3],
    /// Constant forces and their points from the centre of mass, both in
    /// the start's body axes.
    pub loads: &'a [([f64; 3], [f64; 3])],
    pub water: Option<&'a BodyWater>,
    /// When the sea's flow is taken (a time of the step, or statics').
    pub time: FlowTime,
}

/// dx/dt of a function x of the pose (theta, r_G) along the motion
/// (theta_dot, v_G) of `v`: sum_k (dx/dq_k) q_k_dot, with its value and
/// first derivatives (its second would need x's third derivatives; the
/// water's virtual work, where it enters, takes none).
fn rate_along(x: &Jet<NV>, v: &[JetVec<NV>; 4]) -> Jet<NV> {
    let mut rate = Jet::constant(0.0);
    for i in 0..3 {
        for (k, speed) in [(3 + i, v[2][i]), (9 + i, v[0][i])] {
            let mut slope = Jet::constant(x.g[k]);
            slope.g = x.h[k];
            rate = rate + slope * speed;
        }
    }
    rate.h = [[0.0; NV]; NV];
    rate
}

/// A constant moment `moment` (global) on a body as generalized forces on
/// theta (B27): its virtual work M . (R eta), eta = J_r(theta) dtheta the
/// virtual rotation in body axes and R = R_a exp([theta]), is
/// Q_theta . dtheta with Q_theta = J_r^T R^T M (J_r^T is (B3) at -theta).
pub fn moment_on_theta<const N: usize>(
    rotation_a: &[[f64; 3]; 3],
    moment: [f64; 3],
    theta: &JetVec<N>,
) -> JetVec<N> {
    let start_axes = super::pose::rotate_back(rotation_a, moment).map(Jet::constant);
    let body_axes = turn(theta, &start_axes, -1.0);
    let minus_theta = theta.map(|t| -t);
    body_rate(&minus_theta, &body_axes)
}

fn constant<const H: usize>(v: [f64; 3]) -> JetVec<NV, H> {
    v.map(Jet::constant)
}

impl Context<'_> {
    /// Omega and u of (B9) (body axes).
    fn rates<const H: usize>(&self, v: &[JetVec<NV, H>; 4]) -> (JetVec<NV, H>, JetVec<NV, H>) {
        let [v_g, theta, theta_dot, _] = v;
        let omega = body_rate(theta, theta_dot);
        let current = self.water.map_or([0.0; 3], |w| w.current);
        let relative: JetVec<NV, H> = std::array::from_fn(|i| v_g[i] - Jet::constant(current[i]));
        let start_axes = times(&crate::vec3::mat3_transpose(self.rotation_a), &relative);
        let body_axes = turn(theta, &start_axes, -1.0);
        let c_x_omega = cross(&constant(self.centre_of_mass), &omega);
        let u = std::array::from_fn(|i| body_axes[i] + c_x_omega[i]);
        (omega, u)
    }

    /// MoorDyn-F's external force and damping at the reference point
    /// (B42)-(B43), in body axes: the body-fixed force F_L, the damping
    /// of the reference point's velocity u_ref = R^T v_G + c x Omega along
    /// the body's axes, and along the global axes on R u_ref, turned back
    /// by R^T (R = R_a exp([theta]), so R^T x = exp(-[theta]) R_a^T x).
    fn external_force<const H: usize>(
        &self,
        v: &[JetVec<NV, H>; 4],
        external: &BodyExternal,
    ) -> JetVec<NV, H> {
        let mut f: JetVec<NV, H> = constant(external.body_force);
        if external.global.is_zero() && external.body.is_zero() {
            return f;
        }
        let [v_g, theta, theta_dot, _] = v;
        let omega = body_rate(theta, theta_dot);
        let start_axes = times(&crate::vec3::mat3_transpose(self.rotation_a), v_g);
        let body_axes = turn(theta, &start_axes, -1.0);
        let c_x_omega = cross(&constant(self.centre_of_mass), &omega);
        let u_ref: JetVec<NV, H> = std::array::from_fn(|i| body_axes[i] + c_x_omega[i]);
        let along_body = damping_on_jets(&external.body, &u_ref);
        let global = times(self.rotation_a, &turn(theta, &u_ref, 1.0));
        let along_global = damping_on_jets(&external.global, &global);
        let back = turn(
            theta,
            &times(&crate::vec3::mat3_transpose(self.rotation_a), &along_global),
            -1.0,
        );
        for i in 0..3 {
            f[i] = f[i] + along_body[i] + back[i];
        }
        f
    }

    /// The sea's flow (B31) at the body's point `xi` (body axes, from the
    /// reference point) at the pose (r_G, theta) of `v`, in body axes:
    /// x = r_G + R (xi - c), turned back by R^T = exp(-[theta]) R_a^T.
    /// None without a sea.
    fn flow<const H: usize>(
        &self,
        v: &[JetVec<NV, H>; 4],
        rotation: &Rotation<H>,
        xi: &JetVec<NV, H>,
    ) -> Option<Flow<NV, H>> {
        let sea = self.water?.sea.as_deref()?;
        let arm: JetVec<NV, H> =
            std::array::from_fn(|i| xi[i] - Jet::constant(self.centre_of_mass[i]));
        let x: JetVec<NV, H> = std::array::from_fn(|i| {
            v[3][i] + rotation[i][0] * arm[0] + rotation[i][1] * arm[1] + rotation[i][2] * arm[2]
        });
        let back = |g: &JetVec<NV, H>| -> JetVec<NV, H> {
            std::array::from_fn(|i| {
                rotation[0][i] * g[0] + rotation[1][i] * g[1] + rotation[2][i] * g[2]
            })
        };
        Some(flow_at(sea, &x, self.time).turned(back))
    }

    /// R = R_a exp([theta]) on jets, its columns exp([theta]) e_k turned
    /// by R_a; only with a sea, whose flow it carries to body axes.
    fn rotation<const H: usize>(&self, v: &[JetVec<NV, H>; 4]) -> Option<Rotation<H>> {
        self.water?.sea.as_ref()?;
        let columns: [JetVec<NV, H>; 3] = std::array::from_fn(|k| {
            let mut e = constant([0.0; 3]);
            e[k] = Jet::constant(1.0);
            times(self.rotation_a, &turn(&v[1], &e, 1.0))
        });
        Some(std::array::from_fn(|i| {
            std::array::from_fn(|k| columns[k][i])
        }))
    }

    /// Each rod of the body's water with its wet part and its part under
    /// the surface (B20) at the pose (r_G, theta) of `v`: end A's height
    /// z_A = e_z . (r_G + R_a exp([theta]) (xi_A - c)) and the axis's
    /// vertical component e_z . R_a exp([theta]) q.
    fn rods_in_water<'b>(
        &'b self,
        v: &'b [JetVec<NV>; 4],
    ) -> impl Iterator<Item = (&'b Rod, WetPart<NV>, Submerged<NV>)> + 'b {
        let rods = self.water.map_or(&[][..], |w| &w.rods[..]);
        let up = self.rotation_a[2];
        let height = move |x: [f64; 3]| {
            let turned = turn(&v[1], &constant(x), 1.0);
            turned[0].scale(up[0]) + turned[1].scale(up[1]) + turned[2].scale(up[2])
        };
        rods.iter().map(move |rod| {
            let arm = crate::vec3::sub(rod.end_a, self.centre_of_mass);
            let z_a = v[3][2] + height(arm);
            let (wet, under) = rod.wet_part(z_a, height(rod.axis()));
            (rod, wet.with_rates(|x| rate_along(x, v)), under)
        })
    }

    /// The buoyancy's potential of the body's rods, -rho g sum I (B20):
    /// zero in air.
    pub fn buoyancy_potential(&self, v: &[JetVec<NV>; 4]) -> Jet<NV> {
        let Some(w) = self.water else {
            return Jet::constant(0.0);
        };
        let mut u = Jet::constant(0.0);
        for (_, _, under) in self.rods_in_water(v) {
            u = u + under.first_moment.scale(-w.density * w.gravity);
        }
        u
    }

    /// The rods' buoyancy (B20) on the body at rest with its centre at
    /// `centre` and the rotation R_a: the force -dU_b/dr_G and the moment
    /// about the centre, R_a (-dU_b/dtheta) (global; at theta = 0 a
    /// virtual rotation in body axes is dtheta).
    pub fn buoyancy_at(&self, centre: [f64; 3]) -> ([f64; 3], [f64; 3]) {
        let mut v = [[Jet::constant(0.0); 3]; 4];
        for i in 0..3 {
            v[1][i] = Jet::variable(0.0, 3 + i);
            v[3][i] = Jet::variable(centre[i], 9 + i);
        }
        let u = self.buoyancy_potential(&v);
        let force = std::array::from_fn(|i| -u.g[9 + i]);
        let moment = std::array::from_fn(|i| -u.g[3 + i]);
        (force, super::pose::rotate(self.rotation_a, moment))
    }

    /// The kinetic energy T of (B9).
    pub fn kinetic(&self, v: &[JetVec<NV>; 4]) -> Jet<NV> {
        let (omega, u) = self.rates(v);
        let mut t = dot(&v[0], &v[0]).scale(0.5 * self.mass)
            + dot(&omega, &times(self.inertia_at_centre, &omega)).scale(0.5);
        if let Some(w) = self.water {
            let a: [f64; 3] =
                std::array::from_fn(|i| w.density * w.volume * w.added_mass_coefficients[i]);
            for i in 0..3 {
                t = t + (u[i] * u[i]).scale(0.5 * a[i]);
            }
            for (rod, wet, _) in self.rods_in_water(v) {
                t = t + rod.added_mass_energy(&wet, &u, &omega, w.density);
            }
        }
        t
    }

    /// The integrand of (B5) without the centre's linear load term:
    /// T + sum_j F_j . exp([theta]) xi'_j - U_b (B20).
    pub fn density(&self, v: &[JetVec<NV>; 4]) -> Jet<NV> {
        let mut density = self.kinetic(v) - self.buoyancy_potential(v);
        for (f, xi) in self.loads {
            let turned = turn(&v[1], &constant(*xi), 1.0);
            density = density + dot(&constant(*f), &turned);
        }
        density
    }

    /// The drag's generalized forces (B10), (B19): on r_G (global) and on
    /// theta, from the drag's resultant f and its moment about the centre
    /// of mass M_G (body axes): Q_r = R f, Q_theta = J_r^T M_G. In a sea
    /// (§15.15) they hold the water's loads where it moves: the drag on
    /// the velocity through the moving water, the fluid's inertia (B32)
    /// and the dynamic pressure on the rods' caps (B33). Virtual work,
    /// whose rows take its value and first derivatives alone: evaluated
    /// on jets of first order.
    pub fn drag(&self, pose: &[JetVec<NV>; 4]) -> Option<([Grad<NV>; 3], [Grad<NV>; 3])> {
        let w = self.water?;
        let v: &[JetVec<NV, 0>; 4] = &pose.map(|x| x.map(Jet::first_order));
        let (omega, u) = self.rates(v);
        let half_rho = 0.5 * w.density;
        let external = self.external_force(v, &w.external);
        // In a sea, the reference point's velocity through the water and
        // the fluid's inertia there, rho V (1 + Ca) a_f (B32).
        let rotation = self.rotation(v);
        let flow = |xi: &JetVec<NV, 0>| rotation.as_ref().and_then(|r| self.flow(v, r, xi));
        let at_reference = flow(&constant([0.0; 3]));
        let relative: JetVec<NV, 0> = match &at_reference {
            Some(flow) => std::array::from_fn(|i| u[i] - flow.velocity[i]),
            None => u,
        };
        let speed = norm(&relative);
        let mut f: JetVec<NV, 0> =
            std::array::from_fn(|i| (relative[i] * speed).scale(-half_rho * w.drag_areas[i]));
        if let Some(flow) = &at_reference {
            for i in 0..3 {
                let inertia = w.density * w.volume * (1.0 + w.added_mass_coefficients[i]);
                f[i] = f[i] + flow.acceleration[i].scale(inertia);
            }
        }
        for i in 0..3 {
            f[i] = f[i] + external[i];
        }
        let spin = norm(&omega);
        // The reference point is at -c from the centre: (-c) x f = f x c.
        let f_x_c = cross(&f, &constant(self.centre_of_mass));
        let mut on_eta: JetVec<NV, 0> = std::array::from_fn(|i| {
            f_x_c[i] + (omega[i] * spin).scale(-half_rho * w.rotational_drag_areas[i])
        });
        for (rod, wet, _) in self.rods_in_water(pose) {
            let wet = wet.first_order();
            let (force, moment) = rod.drag(&wet, &u, &omega, w.density, self.centre_of_mass, &flow);
            for i in 0..3 {
                f[i] = f[i] + force[i];
                on_eta[i] = on_eta[i] + moment[i];
            }
        }
        // J_r^T q is (B3) at -theta.
        let minus_theta = v[1].map(|t| -t);
        let on_theta = body_rate(&minus_theta, &on_eta);
        let start_axes = turn(&v[1], &f, 1.0);
        let on_centre = times(self.rotation_a, &start_axes);
        Some((on_centre, on_theta))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

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
        let omega: [f64; 3] =
            std::array::from_fn(|i| (0..3).map(|k| jr[i][k] * theta_dot[k]).sum());
        // The same from the forces: u = R^T (v_G - U) + c x Omega (B9).
        let rel = crate::vec3::sub(v_g, water.current);
        let c_x_w = crate::vec3::cross(ctx.centre_of_mass, omega);
        let u: [f64; 3] = std::array::from_fn(|i| {
            (0..3).map(|k| rotation[k][i] * rel[k]).sum::<f64>() + c_x_w[i]
        });
        let speed = crate::vec3::norm(u);
        let spin = crate::vec3::norm(omega);
        let f: [f64; 3] =
            std::array::from_fn(|i| -0.5 * 1025.0 * water.drag_areas[i] * u[i] * speed);
        let m: [f64; 3] = std::array::from_fn(|i| {
            -0.5 * 1025.0 * water.rotational_drag_areas[i] * omega[i] * spin
        });
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
}
