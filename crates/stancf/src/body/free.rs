//! A free rigid body's Galerkin step (docs/method.md §15.3-§15.4).
//!
//! The centre of mass r_G moves along the cubic of eq. (6), like a free
//! point (M31); the rotation is R(t) = R_a exp([theta(t)]) with theta the
//! cubic `T2 u_a + T3 theta_b + T4 u_b` (theta_a = 0: the step's start is
//! the chart's origin), so R(t) is a rotation at every t. The action at
//! the time Gauss points,
//!
//! ```text
//!   A = sum_g w_g dt [ m/2 |r_G_dot|^2 + F . r_G
//!                      + 1/2 Omega . I_G Omega + sum_j F_j . R_a exp([theta]) xi'_j ]   (B5)
//! ```
//!
//! (Omega = J_r(theta) theta_dot (B3), F = sum_j F_j, xi'_j = xi_j - c the
//! force's point from the centre of mass), gives the rows of the Galerkin
//! step (M22) in the chart:
//!
//! ```text
//!   dA/dr_a + p_a = 0,      dA/dw_a = 0,  dA/dw_b = 0
//!   dA/dtheta_a + Pi_a = 0, dA/du_a = 0,  dA/du_b = 0                              (B6)
//!   p_b = dA/dr_b,   Pi_b = J_r(theta_b)^-T dA/dtheta_b,   R_b = R_a exp([theta_b]) (B7)
//! ```
//!
//! (Pi the angular momentum in body axes: Hamilton's law's end terms are
//! Pi . eta with eta the virtual rotation in body axes, eta = J_r dtheta).
//! The P2 step (eq. 22) keeps the position variations and ties the end
//! slopes to the carried rates:
//!
//! ```text
//!   dA/dr_a + p_a = 0,        dA/dr_b - m v_b = 0
//!   dA/dtheta_a + Pi_a = 0,   dA/dtheta_b - J_r(theta_b)^T I_G J_r(theta_b) u_b = 0     (B8)
//!   u_a = Omega_a,   Omega_b = J_r(theta_b) u_b,   unknowns r_b, v_b, theta_b, u_b
//! ```
//! In water the body's added mass joins T and its drag adds its virtual
//! work ([`super::terms`], (B9)-(B10)). The integrand at a time point
//! is a function of v_G, theta and theta_dot, evaluated on jets
//! ([`super::jet`]) and carried to the slots by the chain rule: the rows'
//! exact Jacobian. The linear
//! momentum is a discrete momentum map (the cubic's variations hold the
//! translations) and is kept to round-off; the angular momentum is not
//! (a rotation of the whole path is not a cubic in the chart), and is
//! kept to the step's error, sixth order.

mod step;

pub(crate) use step::solve_transposed;

use super::inertia::RigidInertia;
use super::jet::{Jet, JetVec};
use super::pose::{self, rotate, rotate_back};
use super::rotation::{exp_map, right_jacobian};
use super::terms::{Context, NV};
use super::water::BodyWater;
use crate::bordered::{dense_lu, dense_solve};
use crate::element::{TimePoint, TimeSlab};
use crate::error::{FailureKind, ModelError, SolverError};
use crate::quadrature::GaussRule;
use crate::scheme::TimeScheme;
use crate::vec3::{add, scale, sub};

/// Constant forces on a body, each at a body-fixed point (body axes, from
/// the reference point): weight and buoyancy at the centre of mass
/// (MoorDyn's convention), a given force.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct BodyForces {
    pub forces: Vec<([f64; 3], [f64; 3])>,
}

impl BodyForces {
    /// Weight `m g` and buoyancy `-rho V g` at the centre of mass.
    pub fn weight_and_buoyancy(
        inertia: &RigidInertia,
        volume: f64,
        density: f64,
        g: [f64; 3],
    ) -> Self {
        let net = scale(inertia.mass - density * volume, g);
        BodyForces {
            forces: vec![(net, inertia.centre_of_mass)],
        }
    }

    fn total(&self) -> [f64; 3] {
        self.forces.iter().fold([0.0; 3], |s, (f, _)| add(s, *f))
    }
}

/// Slots of the slab: the centre's four (from r_a: r_a, w_a, r_b, w_b) and
/// the rotation's four (theta_a = 0, u_a, theta_b, u_b), 3 numbers each.
const SLOTS: usize = 24;
/// Newton iterations a step may take.
const MAX_ITERATIONS: usize = 30;
/// The slot blocks (of three) of the Galerkin step's unknowns and rows.
const GALERKIN_UNKNOWNS: [usize; 6] = [1, 2, 3, 5, 6, 7];
const GALERKIN_ROWS: [usize; 6] = [0, 1, 3, 4, 5, 7];
/// P2's unknowns and rows (its slopes at the start are the carried rates).
const P2_UNKNOWNS: [usize; 4] = [2, 3, 6, 7];
const P2_ROWS: [usize; 4] = [0, 2, 4, 6];

/// One rigid body moving freely under constant forces and, in water, its
/// drag and added mass, stepped by (B6)-(B7) or (B8).
#[derive(Clone, Debug)]
pub struct FreeBody {
    inertia: RigidInertia,
    forces: BodyForces,
    water: Option<BodyWater>,
    slab: TimeSlab,
    time: f64,
    centre: [f64; 3],
    rotation: [[f64; 3]; 3],
    /// p = dT/dv_G (global) and Pi = dT/dOmega (body axes).
    momentum: [f64; 3],
    body_momentum: [f64; 3],
    /// v_G and Omega, kept with the momenta.
    velocity: [f64; 3],
    body_rate: [f64; 3],
    scheme: TimeScheme,
    last_iterations: usize,
    /// The constant forces in the step's start axes at their arms from
    /// the centre of mass ([`FreeBody::refresh_loads`]).
    start_loads: Vec<([f64; 3], [f64; 3])>,
    /// The work of the water's drag so far (B10).
    water_work: f64,
    /// The impulse of the body's own loads on its centre over the last
    /// step (`own_impulse_over`), kept where asked for (a pinned body's,
    /// whose pin's force it gives, §15.17): None otherwise.
    own_impulse: Option<[f64; 3]>,
    /// A constant moment on the body (global) and its work so far (B27).
    moment: [f64; 3],
    moment_work: f64,
}

/// The slab's rows over the 24 slots and their derivatives (row-major).
struct SlabRows {
    rows: [f64; SLOTS],
    jacobian: [f64; SLOTS * SLOTS],
}

/// d(variable k at a time point)/d(slot block m): which slot and weight.
fn variable_slot(k: usize, m: usize, point: &TimePoint) -> (usize, f64) {
    let (t, t_dot) = (point.shape.t[m], point.shape.t_dot[m]);
    match k {
        0..=2 => (3 * m + k, t_dot),
        3..=5 => (12 + 3 * m + k - 3, t),
        6..=8 => (12 + 3 * m + k - 6, t_dot),
        _ => (3 * m + k - 9, t),
    }
}

/// The twelve variables of [`super::terms`] at values v (v_G, theta,
/// theta_dot, r_G), as jets.
fn variables(v: [[f64; 3]; 4]) -> [JetVec<NV>; 4] {
    std::array::from_fn(|b| std::array::from_fn(|i| Jet::variable(v[b][i], 3 * b + i)))
}

impl FreeBody {
    /// A body whose reference point is at `position` with `rotation`
    /// (body axes to global), moving at `velocity` and turning at
    /// `angular_velocity` (global), stepped with steps of `dt`.
    pub fn new(
        inertia: &RigidInertia,
        forces: &BodyForces,
        position: [f64; 3],
        rotation: &[[f64; 3]; 3],
        velocity: [f64; 3],
        angular_velocity: [f64; 3],
        dt: f64,
    ) -> Result<Self, ModelError> {
        // A connector (docs/method.md §15.20) has no inertia at all.
        if inertia.mass != 0.0 || inertia.inertia_at_centre != [[0.0; 3]; 3] {
            inertia.validate("body")?;
        }
        if !(dt > 0.0 && dt.is_finite()) {
            return Err(ModelError::invalid(
                "time_step",
                "must be positive and finite",
            ));
        }
        let c = rotate(rotation, inertia.centre_of_mass);
        let mut body = FreeBody {
            inertia: inertia.clone(),
            forces: forces.clone(),
            water: None,
            slab: TimeSlab::new(dt, &GaussRule::new(3)?),
            time: 0.0,
            centre: add(position, c),
            rotation: *rotation,
            momentum: [0.0; 3],
            body_momentum: [0.0; 3],
            velocity: add(velocity, crate::vec3::cross(angular_velocity, c)),
            body_rate: rotate_back(rotation, angular_velocity),
            scheme: TimeScheme::Galerkin,
            last_iterations: 0,
            start_loads: Vec::with_capacity(forces.forces.len()),
            water_work: 0.0,
            own_impulse: None,
            moment: [0.0; 3],
            moment_work: 0.0,
        };
        body.refresh_loads();
        body.momenta_from_rates();
        Ok(body)
    }

    /// The same body stepped by `scheme` (Galerkin by default).
    pub fn with_scheme(mut self, scheme: TimeScheme) -> Self {
        self.scheme = scheme;
        self
    }

    /// The same body under a constant moment `moment` (global, N m) beside
    /// its forces (B27): a load that turns with nothing, whose work is
    /// external.
    pub fn with_moment(mut self, moment: [f64; 3]) -> Self {
        self.moment = moment;
        self
    }

    /// The work done on the body by its constant moment so far (B27).
    pub fn moment_work(&self) -> f64 {
        self.moment_work
    }

    /// The same body in water: its drag and added mass (B9)-(B10).
    /// Refuses a density, volume or coefficient that is negative or not
    /// finite.
    pub fn with_water(mut self, water: BodyWater) -> Result<Self, ModelError> {
        water.validate("body.water")?;
        self.water = Some(water);
        self.momenta_from_rates();
        Ok(self)
    }

    /// Sets the water's flow a host gives at the body (docs/method.md
    /// (W2h)) for the steps from now on; nothing in air. Refused: not one
    /// node flow per rod of the body's water, each at the rod's N + 1
    /// nodes.
    pub fn set_host_flow(&mut self, host: super::BodyHostFlow) -> Result<(), ModelError> {
        if let Some(w) = self.water.as_mut() {
            host.check(&w.rods, "host_flow")?;
            w.host = Some(host);
        }
        Ok(())
    }

    pub fn time(&self) -> f64 {
        self.time
    }
    /// Newton iterations of the last step.
    pub fn last_iterations(&self) -> usize {
        self.last_iterations
    }
    /// The rotation matrix (body axes to global).
    pub fn rotation(&self) -> [[f64; 3]; 3] {
        self.rotation
    }
    /// The reference point, `r_G - R c`.
    pub fn position(&self) -> [f64; 3] {
        sub(
            self.centre,
            rotate(&self.rotation, self.inertia.centre_of_mass),
        )
    }
    /// The global position of the body point `xi` (B1).
    pub fn point(&self, xi: [f64; 3]) -> [f64; 3] {
        pose::point(self.position(), &self.rotation, xi)
    }
    /// The centre of mass's velocity.
    pub fn centre_velocity(&self) -> [f64; 3] {
        self.velocity
    }
    /// The angular velocity in body axes, Omega.
    pub fn body_angular_velocity(&self) -> [f64; 3] {
        self.body_rate
    }
    /// The angular velocity, global: `R Omega`.
    pub fn angular_velocity(&self) -> [f64; 3] {
        rotate(&self.rotation, self.body_rate)
    }
    /// Linear momentum `dT/dv_G` (with the added mass's, in water).
    pub fn linear_momentum(&self) -> [f64; 3] {
        self.momentum
    }
    /// Angular momentum about the global origin, `r_G x p + R Pi`.
    pub fn angular_momentum(&self) -> [f64; 3] {
        add(
            crate::vec3::cross(self.centre, self.momentum),
            rotate(&self.rotation, self.body_momentum),
        )
    }
    /// Kinetic energy (B9) (with the added mass's) and the potential of
    /// the constant forces and of the rods' buoyancy,
    /// `-sum_j F_j . x(xi_j) - rho g sum I` (B20).
    pub fn energies(&self) -> (f64, f64) {
        let ctx = self.context(&[]);
        let now = variables([self.velocity, [0.0; 3], self.body_rate, self.centre]);
        let kinetic = ctx.kinetic(&now).v;
        let potential = ctx.buoyancy_potential(&now).v
            - self
                .forces
                .forces
                .iter()
                .map(|(f, xi)| crate::vec3::dot(*f, self.point(*xi)))
                .sum::<f64>();
        (kinetic, potential)
    }

    fn context<'a>(&'a self, loads: &'a [([f64; 3], [f64; 3])]) -> Context<'a> {
        Context {
            mass: self.inertia.mass,
            inertia_at_centre: &self.inertia.inertia_at_centre,
            centre_of_mass: self.inertia.centre_of_mass,
            rotation_a: &self.rotation,
            loads,
            water: self.water.as_ref(),
            time: super::flow::FlowTime::At(self.time),
        }
    }

    /// Sets the body's clock (the time its sea's flow is taken at; a
    /// system starting at t sets its bodies' to it).
    pub fn set_time(&mut self, t: f64) {
        self.time = t;
    }

    /// The variables at the current pose, at rest.
    fn at_rest(&self) -> [JetVec<NV>; 4] {
        variables([[0.0; 3], [0.0; 3], [0.0; 3], self.centre])
    }

    /// The constant forces in the start's body axes, at their points from
    /// the centre of mass: kept for the step (the same number each time,
    /// so no allocation after the first).
    fn refresh_loads(&mut self) {
        self.start_loads.clear();
        for (f, xi) in &self.forces.forces {
            self.start_loads.push((
                rotate_back(&self.rotation, *f),
                sub(*xi, self.inertia.centre_of_mass),
            ));
        }
    }

    /// p and Pi from v_G and Omega (the kinetic energy's gradient in the
    /// rates at theta = 0, where theta_dot = Omega).
    fn momenta_from_rates(&mut self) {
        let t = self.context(&[]).kinetic(&variables([
            self.velocity,
            [0.0; 3],
            self.body_rate,
            self.centre,
        ]));
        self.momentum = [t.g[0], t.g[1], t.g[2]];
        self.body_momentum = [t.g[6], t.g[7], t.g[8]];
    }

    /// v_G and Omega from p and Pi: the kinetic energy is quadratic in
    /// the rates, `[p; Pi] = g0 + H [v_G; Omega]` (g0 from the current).
    fn rates_from_momenta(&mut self) -> Result<(), SolverError> {
        let t = self.context(&[]).kinetic(&self.at_rest());
        let rate_index = [0, 1, 2, 6, 7, 8];
        let mut h = [0.0; 36];
        let mut rhs = [0.0; 6];
        for (a, &ka) in rate_index.iter().enumerate() {
            let target = if a < 3 {
                self.momentum[a]
            } else {
                self.body_momentum[a - 3]
            };
            rhs[a] = target - t.g[ka];
            for (b, &kb) in rate_index.iter().enumerate() {
                h[6 * a + b] = t.h[ka][kb];
            }
        }
        let mut pivots = [0usize; 6];
        if dense_lu(&mut h, 6, &mut pivots).is_err() {
            return Err(self.failure(FailureKind::SingularJacobian, 0, f64::NAN));
        }
        dense_solve(&h, 6, &pivots, &mut rhs);
        self.velocity = [rhs[0], rhs[1], rhs[2]];
        self.body_rate = [rhs[3], rhs[4], rhs[5]];
        Ok(())
    }

    /// Sets the rates v_G and Omega (body axes) and the momenta they
    /// carry (a system's step solves them with its lines', §15.7).
    pub fn set_rates(&mut self, velocity: [f64; 3], body_rate: [f64; 3]) {
        self.velocity = velocity;
        self.body_rate = body_rate;
        self.momenta_from_rates();
    }

    /// The kinetic energy's gradient at zero rates and its Hessian in the
    /// rates [v_G; Omega] at the current pose: [p; Pi] = g0 + H [v_G; Omega].
    pub fn rate_hessian(&self) -> ([f64; 6], [[f64; 6]; 6]) {
        let t = self.context(&[]).kinetic(&self.at_rest());
        let index = [0, 1, 2, 6, 7, 8];
        (
            index.map(|k| t.g[k]),
            index.map(|a| index.map(|b| t.h[a][b])),
        )
    }

    /// The work done on the body by the water's drag so far (B10): the
    /// drag's power Q_r . v_G + Q_theta . theta_dot at the slab's time
    /// points, with their weights, step by step.
    /// The same body keeping the impulse of its own loads over each step
    /// ([`Self::own_impulse`]; an extra pass over the step's time points,
    /// so only where it is needed).
    pub fn with_own_impulse(mut self) -> Self {
        self.own_impulse = Some([0.0; 3]);
        self
    }

    /// The impulse of the body's own loads (weight, buoyancy, constant
    /// forces, the water's) on its centre over the last step, global;
    /// None unless kept ([`Self::with_own_impulse`]).
    pub fn own_impulse(&self) -> Option<[f64; 3]> {
        self.own_impulse
    }

    pub fn water_work(&self) -> f64 {
        self.water_work
    }

    /// The centre of mass r_G.
    pub fn centre(&self) -> [f64; 3] {
        self.centre
    }

    /// The body's mass, centre of mass and inertia.
    pub fn water(&self) -> Option<&BodyWater> {
        self.water.as_ref()
    }
    pub fn inertia(&self) -> &RigidInertia {
        &self.inertia
    }

    /// Steps of `dt` from now on (a halved step).
    pub fn set_time_step(&mut self, dt: f64) {
        let rule = GaussRule::new(3).expect("three Gauss points");
        self.slab = TimeSlab::new(dt, &rule);
    }
}
