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
use super::water::{BodyExternal, BodyHostFlow, BodyWater};
use super::waterline::Submerged;
use super::wet::WetPart;
use crate::water::host_flow::FlowAt;

/// Variables at a time point: v_G (0..3), theta (3..6), theta_dot
/// (6..9), r_G (9..12).
pub const NV: usize = 12;

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
    // The product rule to first order, term by term: d/dq_j of
    // (dx/dq_k) q_k_dot is (d2x/dq_k dq_j) q_k_dot + (dx/dq_k) dq_k_dot/dq_j.
    let mut rate = Jet::constant(0.0);
    for i in 0..3 {
        for (k, speed) in [(3 + i, &v[2][i]), (9 + i, &v[0][i])] {
            rate.v += x.g[k] * speed.v;
            for j in 0..NV {
                rate.g[j] += x.h[k][j] * speed.v + x.g[k] * speed.g[j];
            }
        }
    }
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
    /// Omega and u of (B9) (body axes): the reference point's velocity
    /// through the uniform current.
    fn rates<const H: usize>(&self, v: &[JetVec<NV, H>; 4]) -> (JetVec<NV, H>, JetVec<NV, H>) {
        self.reference_velocity(v, self.water.map_or([0.0; 3], |w| w.current))
    }

    /// Omega and the reference point's velocity relative to a uniform
    /// flow `current`, u = R^T (v_G - U) + c x Omega (body axes).
    fn reference_velocity<const H: usize>(
        &self,
        v: &[JetVec<NV, H>; 4],
        current: [f64; 3],
    ) -> (JetVec<NV, H>, JetVec<NV, H>) {
        let [v_g, theta, theta_dot, _] = v;
        let omega = body_rate(theta, theta_dot);
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
        let theta = &v[1];
        let u_ref = self.reference_velocity(v, [0.0; 3]).1;
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
    /// With `host`, the host's flow there (global) added (W2g), (W2h):
    /// it does not depend on the pose. None without a sea.
    fn flow<const H: usize>(
        &self,
        v: &[JetVec<NV, H>; 4],
        rotation: &Rotation<H>,
        xi: &JetVec<NV, H>,
        host: Option<FlowAt>,
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
        let mut global = flow_at(sea, &x, self.time);
        if let Some((u, a)) = host {
            for i in 0..3 {
                global.velocity[i] = global.velocity[i] + Jet::constant(u[i]);
                global.acceleration[i] = global.acceleration[i] + Jet::constant(a[i]);
            }
        }
        Some(global.turned(back))
    }

    /// The host's flow at the body (W2h), in a step (statics see none of
    /// it, as MoorDyn's).
    fn host_flow(&self) -> Option<&BodyHostFlow> {
        match self.time {
            FlowTime::At(_) => self.water?.host.as_ref(),
            FlowTime::Steady => None,
        }
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
            (rod, wet, under)
        })
    }

    /// A rod's wet part with the rates of its pose-dependent numbers
    /// along the motion of `v` (what its added mass and drag take).
    fn moving(wet: WetPart<NV>, v: &[JetVec<NV>; 4]) -> WetPart<NV> {
        wet.with_rates(|x| rate_along(x, v))
    }

    /// The buoyancy's potential of the body's rods, -rho g sum I (B20):
    /// zero in air.
    pub fn buoyancy_potential(&self, v: &[JetVec<NV>; 4]) -> Jet<NV> {
        let rods: Vec<_> = self.rods_in_water(v).collect();
        self.buoyancy_of(&rods)
    }

    /// [`Self::buoyancy_potential`] of the rods in water as
    /// [`Self::rods_in_water`] found them.
    fn buoyancy_of(&self, rods: &[(&Rod, WetPart<NV>, Submerged<NV>)]) -> Jet<NV> {
        let Some(w) = self.water else {
            return Jet::constant(0.0);
        };
        let mut u = Jet::constant(0.0);
        for (_, _, under) in rods {
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
        let rods: Vec<_> = self.rods_in_water(v).collect();
        self.kinetic_of(v, rods)
    }

    /// [`Self::kinetic`] with the rods in water as
    /// [`Self::rods_in_water`] found them.
    fn kinetic_of(
        &self,
        v: &[JetVec<NV>; 4],
        rods: Vec<(&Rod, WetPart<NV>, Submerged<NV>)>,
    ) -> Jet<NV> {
        let (omega, u) = self.rates(v);
        let mut t = dot(&v[0], &v[0]).scale(0.5 * self.mass)
            + dot(&omega, &times(self.inertia_at_centre, &omega)).scale(0.5);
        if let Some(w) = self.water {
            let a: [f64; 3] =
                std::array::from_fn(|i| w.density * w.volume * w.added_mass_coefficients[i]);
            for i in 0..3 {
                t = t + (u[i] * u[i]).scale(0.5 * a[i]);
            }
            for (rod, wet, _) in rods {
                let wet = Self::moving(wet, v);
                t = t + rod.added_mass_energy(&wet, &u, &omega, w.density);
            }
        }
        t
    }

    /// The integrand of (B5) without the centre's linear load term:
    /// T + sum_j F_j . exp([theta]) xi'_j - U_b (B20).
    pub fn density(&self, v: &[JetVec<NV>; 4]) -> Jet<NV> {
        // The rods' wet parts once, for both terms.
        let rods: Vec<_> = self.rods_in_water(v).collect();
        let buoyancy = self.buoyancy_of(&rods);
        let mut density = self.kinetic_of(v, rods) - buoyancy;
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
        let host = self.host_flow();
        let flow = |xi: &JetVec<NV, 0>, at: Option<FlowAt>| {
            rotation.as_ref().and_then(|r| self.flow(v, r, xi, at))
        };
        let at_reference = flow(&constant([0.0; 3]), host.map(|h| h.reference));
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
        for (k, (rod, wet, _)) in self.rods_in_water(pose).enumerate() {
            let wet = Self::moving(wet, pose);
            let wet = wet.first_order();
            let on_rod =
                |xi: &JetVec<NV, 0>| flow(xi, host.map(|h| h.on_rod(k, rod, xi.map(|c| c.v))));
            let (force, moment) =
                rod.drag(&wet, &u, &omega, w.density, self.centre_of_mass, &on_rod);
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
#[path = "terms_tests.rs"]
mod tests;
