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

use super::inertia::RigidInertia;
use super::jet::{Jet, JetVec};
use super::pose::{self, rotate, rotate_back};
use super::rotation::{exp_map, right_jacobian};
use super::terms::{BodyWater, Context, NV};
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
}

/// The slab's rows over the 24 slots and their derivatives (row-major).
struct SlabRows {
    rows: [f64; SLOTS],
    jacobian: Vec<f64>,
}

/// d(variable k at a time point)/d(slot block m): which slot and weight.
fn variable_slot(k: usize, m: usize, point: &TimePoint) -> (usize, f64) {
    let (t, t_dot) = (point.shape.t[m], point.shape.t_dot[m]);
    match k {
        0..=2 => (3 * m + k, t_dot),
        3..=5 => (12 + 3 * m + k - 3, t),
        _ => (12 + 3 * m + k - 6, t_dot),
    }
}

/// The nine variables of [`super::terms`] at values v, as jets.
fn variables(v: [[f64; 3]; 3]) -> [JetVec<NV>; 3] {
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
        inertia.validate("body")?;
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
        };
        body.momenta_from_rates();
        Ok(body)
    }

    /// The same body stepped by `scheme` (Galerkin by default).
    pub fn with_scheme(mut self, scheme: TimeScheme) -> Self {
        self.scheme = scheme;
        self
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
    /// the constant forces, `-sum_j F_j . x(xi_j)`.
    pub fn energies(&self) -> (f64, f64) {
        let kinetic = self
            .context(&[])
            .kinetic(&variables([self.velocity, [0.0; 3], self.body_rate]))
            .v;
        let potential = -self
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
        }
    }

    /// The constant forces in the start's body axes, at their points from
    /// the centre of mass.
    fn loads(&self) -> Vec<([f64; 3], [f64; 3])> {
        self.forces
            .forces
            .iter()
            .map(|(f, xi)| {
                (
                    rotate_back(&self.rotation, *f),
                    sub(*xi, self.inertia.centre_of_mass),
                )
            })
            .collect()
    }

    /// p and Pi from v_G and Omega (the kinetic energy's gradient in the
    /// rates at theta = 0, where theta_dot = Omega).
    fn momenta_from_rates(&mut self) {
        let t = self
            .context(&[])
            .kinetic(&variables([self.velocity, [0.0; 3], self.body_rate]));
        self.momentum = [t.g[0], t.g[1], t.g[2]];
        self.body_momentum = [t.g[6], t.g[7], t.g[8]];
    }

    /// v_G and Omega from p and Pi: the kinetic energy is quadratic in
    /// the rates, `[p; Pi] = g0 + H [v_G; Omega]` (g0 from the current).
    fn rates_from_momenta(&mut self) -> Result<(), SolverError> {
        let t = self.context(&[]).kinetic(&variables([[0.0; 3]; 3]));
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

    /// (B5) and (B10) over the slab: the action's gradient plus the drag's
    /// virtual work, per slot, and their derivatives. `slots` holds the
    /// eight blocks (the centre's from r_a).
    fn slab_rows(&self, slots: &[[f64; 3]; 8]) -> SlabRows {
        let loads = self.loads();
        let ctx = self.context(&loads);
        let mut out = SlabRows {
            rows: [0.0; SLOTS],
            jacobian: vec![0.0; SLOTS * SLOTS],
        };
        let total = self.forces.total();
        for m in 0..4 {
            for i in 0..3 {
                out.rows[3 * m + i] += self.slab.load[m] * total[i];
            }
        }
        for point in &self.slab.points {
            let at = |w: &[f64; 4], first: usize| -> [f64; 3] {
                std::array::from_fn(|i| (0..4).map(|m| w[m] * slots[first + m][i]).sum())
            };
            let (t, t_dot) = (&point.shape.t, &point.shape.t_dot);
            let v = variables([at(t_dot, 0), at(t, 4), at(t_dot, 4)]);
            let density = ctx.density(&v);
            let wdt = point.w_dt;
            for m in 0..4 {
                for k in 0..NV {
                    let (s, wk) = variable_slot(k, m, point);
                    out.rows[s] += wdt * wk * density.g[k];
                    for n in 0..4 {
                        for l in 0..NV {
                            let (s2, wl) = variable_slot(l, n, point);
                            out.jacobian[s * SLOTS + s2] += wdt * wk * wl * density.h[k][l];
                        }
                    }
                }
            }
            if let Some((on_centre, on_theta)) = ctx.drag(&v) {
                for m in 0..4 {
                    for (first, q) in [(0usize, &on_centre), (12, &on_theta)] {
                        for i in 0..3 {
                            let s = first + 3 * m + i;
                            out.rows[s] += wdt * t[m] * q[i].v;
                            for n in 0..4 {
                                for l in 0..NV {
                                    let (s2, wl) = variable_slot(l, n, point);
                                    out.jacobian[s * SLOTS + s2] += wdt * t[m] * wl * q[i].g[l];
                                }
                            }
                        }
                    }
                }
            }
        }
        out
    }

    /// The slot blocks of a step from its unknowns x.
    fn slots(&self, x: &[f64]) -> [[f64; 3]; 8] {
        let mut slots = [[0.0; 3]; 8];
        match self.scheme {
            TimeScheme::Galerkin => {
                for (k, &b) in GALERKIN_UNKNOWNS.iter().enumerate() {
                    slots[b] = part(x, 3 * k);
                }
            }
            TimeScheme::P2 => {
                slots[1] = self.velocity;
                slots[5] = self.body_rate;
                for (k, &b) in P2_UNKNOWNS.iter().enumerate() {
                    slots[b] = part(x, 3 * k);
                }
            }
        }
        slots
    }

    /// The Galerkin rows (B6) at x = [w_a, r_b - r_a, w_b, u_a, theta_b,
    /// u_b] and their exact Jacobian (row-major, 18 x 18).
    pub fn galerkin_rows_and_jacobian(&self, x: &[f64]) -> (Vec<f64>, Vec<f64>) {
        let slab = self.slab_rows(&self.slots(x));
        let (mut r, jac) = pick(&slab, &GALERKIN_ROWS, &GALERKIN_UNKNOWNS);
        for i in 0..3 {
            r[i] += self.momentum[i];
            r[9 + i] += self.body_momentum[i];
        }
        (r, jac)
    }

    /// The P2 rows (B8) at x = [r_b - r_a, v_b, theta_b, u_b] and their
    /// exact Jacobian (row-major, 12 x 12): the end slopes are the carried
    /// rates (u_a = Omega_a, J_r(0) = I; u_b = J_r(theta_b)^-1 Omega_b),
    /// the end momenta the kinetic energy's gradient in the end's rates.
    pub fn p2_rows_and_jacobian(&self, x: &[f64]) -> (Vec<f64>, Vec<f64>) {
        const M: usize = 12;
        let slab = self.slab_rows(&self.slots(x));
        let (mut r, mut jac) = pick(&slab, &P2_ROWS, &P2_UNKNOWNS);
        let end = self
            .context(&[])
            .kinetic(&variables([part(x, 3), part(x, 6), part(x, 9)]));
        for i in 0..3 {
            r[i] += self.momentum[i];
            r[6 + i] += self.body_momentum[i];
            // -dT/dv_G and -dT/dtheta_dot at the end; their derivatives in
            // v_b (x 3..6), theta_b (6..9), u_b (9..12).
            r[3 + i] -= end.g[i];
            r[9 + i] -= end.g[6 + i];
            for k in 0..NV {
                jac[(3 + i) * M + 3 + k] -= end.h[i][k];
                jac[(9 + i) * M + 3 + k] -= end.h[6 + i][k];
            }
        }
        (r, jac)
    }

    /// One step of (B6)-(B7) (Galerkin) or (B8) (P2).
    pub fn step(&mut self) -> Result<(), SolverError> {
        let dt = self.slab.dt;
        let (v_g, omega) = (self.velocity, self.body_rate);
        let guess = |position: bool, v: [f64; 3]| if position { scale(dt, v) } else { v };
        // The unknowns' blocks: whether a position (else a rate) and
        // whether the rotation's (else the centre's).
        let layout: &[(bool, bool)] = match self.scheme {
            TimeScheme::Galerkin => &[
                (false, false),
                (true, false),
                (false, false),
                (false, true),
                (true, true),
                (false, true),
            ],
            TimeScheme::P2 => &[(true, false), (false, false), (true, true), (false, true)],
        };
        let mut x: Vec<f64> = layout
            .iter()
            .flat_map(|&(position, turning)| guess(position, if turning { omega } else { v_g }))
            .collect();
        self.newton(&mut x, layout)?;
        let slots = self.slots(&x);
        let theta_b = slots[6];
        match self.scheme {
            TimeScheme::Galerkin => {
                let (p, dtheta) = self.galerkin_end_gradient(&x);
                // Pi_b solves J_r(theta_b)^T Pi_b = dA/dtheta_b.
                let pi = solve_transposed(&right_jacobian(theta_b), dtheta)
                    .ok_or_else(|| self.failure(FailureKind::SingularJacobian, 0, f64::NAN))?;
                self.advance(&x)?;
                self.momentum = p;
                self.body_momentum = pi;
                self.rates_from_momenta()?;
            }
            TimeScheme::P2 => {
                self.advance(&x)?;
                self.velocity = slots[3];
                self.body_rate = rotate(&right_jacobian(theta_b), slots[7]);
                self.momenta_from_rates();
            }
        }
        Ok(())
    }

    /// Moves the body to the end of the step whose unknowns are x (the
    /// centre by r_b - r_a, the rotation to R_a exp([theta_b]), brought
    /// back to orthonormal) and its clock on; the rates are the caller's
    /// to set. The chart (B3)-(B4) holds a step's turn below pi (J_r is
    /// singular at 2 pi): a longer turn is refused as a step too long for
    /// the body's rotation.
    pub fn advance(&mut self, x: &[f64]) -> Result<(), SolverError> {
        let slots = self.slots(x);
        let theta_b = slots[6];
        let turn = crate::vec3::norm(theta_b);
        if turn > std::f64::consts::PI {
            let mut e = self.failure(FailureKind::NotConverged, self.last_iterations, f64::NAN);
            e.detail = format!(
                "{}: the body turns by {turn:.3} rad in one step, more than pi; take a shorter step",
                e.detail
            );
            return Err(e);
        }
        self.centre = add(self.centre, slots[2]);
        self.rotation =
            pose::reorthonormalized(&crate::vec3::mat3_mul(&self.rotation, &exp_map(theta_b)));
        self.time += self.slab.dt;
        Ok(())
    }

    /// The Galerkin step's end gradients at its unknowns x: dA/dr_b (the
    /// end momentum p_b of (B7)) and dA/dtheta_b (= J_r(theta_b)^T Pi_b).
    pub fn galerkin_end_gradient(&self, x: &[f64]) -> ([f64; 3], [f64; 3]) {
        let slab = self.slab_rows(&self.slots(x));
        (part(&slab.rows, 6), part(&slab.rows, 18))
    }

    /// The first guess of a Galerkin step's unknowns [w_a, r_b - r_a, w_b,
    /// u_a, theta_b, u_b]: at the carried rates.
    pub fn galerkin_guess(&self) -> [f64; 18] {
        let dt = self.slab.dt;
        let (v, w) = (self.velocity, self.body_rate);
        let blocks = [v, scale(dt, v), v, w, scale(dt, w), w];
        std::array::from_fn(|i| blocks[i / 3][i % 3])
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
        let t = self.context(&[]).kinetic(&variables([[0.0; 3]; 3]));
        let index = [0, 1, 2, 6, 7, 8];
        (
            index.map(|k| t.g[k]),
            index.map(|a| index.map(|b| t.h[a][b])),
        )
    }

    /// The centre of mass r_G.
    pub fn centre(&self) -> [f64; 3] {
        self.centre
    }

    /// The body's mass, centre of mass and inertia.
    pub fn inertia(&self) -> &RigidInertia {
        &self.inertia
    }

    /// Steps of `dt` from now on (a halved step).
    pub fn set_time_step(&mut self, dt: f64) {
        let rule = GaussRule::new(3).expect("three Gauss points");
        self.slab = TimeSlab::new(dt, &rule);
    }

    /// Newton on the scheme's rows from x; `layout` says which blocks of
    /// three are positions (else rates, whose change counts times dt) and
    /// which are the rotation's (else the centre's, whose change counts
    /// relative to the centre's size).
    fn newton(&mut self, x: &mut [f64], layout: &[(bool, bool)]) -> Result<(), SolverError> {
        let n = x.len();
        let dt = self.slab.dt;
        let scale_r = 1.0 + self.centre.iter().fold(0.0f64, |m, v| m.max(v.abs()));
        let mut pivots = vec![0usize; n];
        let mut change = f64::INFINITY;
        let mut previous = f64::INFINITY;
        for k in 1..=MAX_ITERATIONS {
            let (mut delta, mut jac) = match self.scheme {
                TimeScheme::Galerkin => self.galerkin_rows_and_jacobian(x),
                TimeScheme::P2 => self.p2_rows_and_jacobian(x),
            };
            if delta.iter().any(|v| !v.is_finite()) {
                return Err(self.failure(FailureKind::NonFinite, k, f64::NAN));
            }
            if dense_lu(&mut jac, n, &mut pivots).is_err() {
                return Err(self.failure(FailureKind::SingularJacobian, k, f64::NAN));
            }
            dense_solve(&jac, n, &pivots, &mut delta);
            change = 0.0;
            for i in 0..n {
                x[i] -= delta[i];
                let (position, turning) = layout[i / 3];
                let size = if position { delta[i] } else { dt * delta[i] };
                let unit = if turning { 1.0 } else { scale_r };
                change = change.max(size.abs() / unit);
            }
            self.last_iterations = k;
            // Converged: the change at round-off, or below 1e-10 and no
            // longer halving (the round-off floor of a body whose
            // couplings amplify the rows' round-off).
            if change <= 1e-14 || (change <= 1e-10 && change > 0.5 * previous) {
                return Ok(());
            }
            previous = change;
        }
        Err(self.failure(FailureKind::NotConverged, MAX_ITERATIONS, change))
    }

    fn failure(&self, kind: FailureKind, iterations: usize, residual: f64) -> SolverError {
        SolverError {
            kind,
            time: self.time,
            step: (self.time / self.slab.dt).round() as usize + 1,
            residual,
            iterations,
            detail: match self.scheme {
                TimeScheme::Galerkin => "free body's Galerkin step (B6)".into(),
                TimeScheme::P2 => "free body's P2 step (B8)".into(),
            },
        }
    }
}

/// The rows of the slot blocks `rows` and their derivatives in the slot
/// blocks `unknowns`.
fn pick(slab: &SlabRows, rows: &[usize], unknowns: &[usize]) -> (Vec<f64>, Vec<f64>) {
    let n = 3 * rows.len();
    let mut r = vec![0.0; n];
    let mut jac = vec![0.0; n * n];
    for (a, &ra) in rows.iter().enumerate() {
        for i in 0..3 {
            r[3 * a + i] = slab.rows[3 * ra + i];
            for (b, &ub) in unknowns.iter().enumerate() {
                for j in 0..3 {
                    jac[(3 * a + i) * n + 3 * b + j] =
                        slab.jacobian[(3 * ra + i) * SLOTS + 3 * ub + j];
                }
            }
        }
    }
    (r, jac)
}

/// x[a..a + 3].
fn part(x: &[f64], a: usize) -> [f64; 3] {
    [x[a], x[a + 1], x[a + 2]]
}

/// y with A^T y = b (None if A is singular).
pub(crate) fn solve_transposed(a: &[[f64; 3]; 3], b: [f64; 3]) -> Option<[f64; 3]> {
    let mut m: Vec<f64> = (0..9).map(|k| a[k % 3][k / 3]).collect();
    let mut pivots = [0usize; 3];
    dense_lu(&mut m, 3, &mut pivots).ok()?;
    let mut y = b;
    dense_solve(&m, 3, &pivots, &mut y);
    Some(y)
}
