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
//! (Omega = J_r(theta) theta_dot (B9), F = sum_j F_j, xi'_j = xi_j - c the
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
//!   dA/dtheta_a + Pi_a = 0,   dA/dtheta_b - J_r(theta_b)^T I_G J_r(theta_b) u_b = 0     (B11)
//!   u_a = Omega_a,   Omega_b = J_r(theta_b) u_b,   unknowns r_b, v_b, theta_b, u_b
//! ```
//! The translational rows are linear; the rotational ones are evaluated
//! on jets ([`super::jet`]), which give their exact Jacobian. The linear
//! momentum is a discrete momentum map (the cubic's variations hold the
//! translations) and is kept to round-off; the angular momentum is not
//! (a rotation of the whole path is not a cubic in the chart), and is
//! kept to the step's error, sixth order.

use super::inertia::RigidInertia;
use super::jet::{cross, dot, Jet, JetVec};
use super::pose::{self, rotate, rotate_back};
use super::rotation::{body_rate, exp_map, right_jacobian, series};
use crate::bordered::{dense_lu, dense_solve};
use crate::element::TimeSlab;
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

/// Unknowns of a step: w_a, r_b - r_a, w_b of the centre; u_a, theta_b,
/// u_b of the rotation.
const N: usize = 18;
/// Jet variables of the rotational action: theta_a, u_a, theta_b, u_b.
const NJ: usize = 12;
/// Newton iterations a step may take.
const MAX_ITERATIONS: usize = 30;

/// One rigid body moving freely under constant forces, stepped by
/// (B6)-(B7).
#[derive(Clone, Debug)]
pub struct FreeBody {
    inertia: RigidInertia,
    inertia_inverse: [[f64; 3]; 3],
    forces: BodyForces,
    slab: TimeSlab,
    time: f64,
    centre: [f64; 3],
    momentum: [f64; 3],
    rotation: [[f64; 3]; 3],
    /// Pi, the angular momentum in body axes.
    body_momentum: [f64; 3],
    scheme: TimeScheme,
    last_iterations: usize,
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
        let inertia_inverse = invert3(&inertia.inertia_at_centre)
            .ok_or_else(|| ModelError::invalid("body", "the inertia tensor is singular"))?;
        let c = rotate(rotation, inertia.centre_of_mass);
        let centre = add(position, c);
        let v_g = add(velocity, crate::vec3::cross(angular_velocity, c));
        let omega_body = rotate_back(rotation, angular_velocity);
        Ok(FreeBody {
            inertia: inertia.clone(),
            inertia_inverse,
            forces: forces.clone(),
            slab: TimeSlab::new(dt, &GaussRule::new(3)?),
            time: 0.0,
            centre,
            momentum: scale(inertia.mass, v_g),
            rotation: *rotation,
            body_momentum: mat_vec(&inertia.inertia_at_centre, omega_body),
            scheme: TimeScheme::Galerkin,
            last_iterations: 0,
        })
    }

    /// The same body stepped by `scheme` (Galerkin by default).
    pub fn with_scheme(mut self, scheme: TimeScheme) -> Self {
        self.scheme = scheme;
        self
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
    /// The angular velocity in body axes, `I_G^-1 Pi`.
    pub fn body_angular_velocity(&self) -> [f64; 3] {
        mat_vec(&self.inertia_inverse, self.body_momentum)
    }
    /// The angular velocity, global: `R Omega`.
    pub fn angular_velocity(&self) -> [f64; 3] {
        rotate(&self.rotation, self.body_angular_velocity())
    }
    /// Linear momentum `m v_G`.
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
    /// Kinetic energy `|p|^2 / 2m + 1/2 Pi . I_G^-1 Pi` and the potential
    /// of the constant forces, `-sum_j F_j . x(xi_j)`.
    pub fn energies(&self) -> (f64, f64) {
        let p = self.momentum;
        let kinetic = 0.5 * crate::vec3::dot(p, p) / self.inertia.mass
            + 0.5 * crate::vec3::dot(self.body_momentum, self.body_angular_velocity());
        let potential = -self
            .forces
            .forces
            .iter()
            .map(|(f, xi)| crate::vec3::dot(*f, self.point(*xi)))
            .sum::<f64>();
        (kinetic, potential)
    }

    /// The translational gradient dA/dy_m (M31) for y = [r_a, w_a, r_b, w_b].
    fn translation_gradient(&self, m: usize, y: &[[f64; 3]; 4]) -> [f64; 3] {
        let c = &self.slab.kinetic;
        let total = self.forces.total();
        std::array::from_fn(|i| {
            self.inertia.mass * (0..4).map(|n| c[m][n] * y[n][i]).sum::<f64>()
                + self.slab.load[m] * total[i]
        })
    }

    /// The rotational action (B5) on jets over [theta_a, u_a, theta_b, u_b]
    /// (theta_a = 0) at the slopes u_a, u_b and the end's theta_b.
    ///
    /// At a time point the density depends on theta_g and theta_dot_g
    /// alone, linear in the slots (theta_g = sum_m T_m y_m, theta_dot_g =
    /// sum_m T_m' y_m): it is evaluated on jets over those six numbers and
    /// its gradient and Hessian carried to the slots by the chain rule
    /// (four times fewer jet operations than jets over the twelve slots).
    fn rotational_action(&self, u_a: [f64; 3], theta_b: [f64; 3], u_b: [f64; 3]) -> Jet<NJ> {
        let slots = [[0.0; 3], u_a, theta_b, u_b];
        // The forces in the start's body axes, at their points from G.
        let loads: Vec<([f64; 3], [f64; 3])> = self
            .forces
            .forces
            .iter()
            .map(|(f, xi)| {
                (
                    rotate_back(&self.rotation, *f),
                    sub(*xi, self.inertia.centre_of_mass),
                )
            })
            .collect();
        let mut action = Jet::constant(0.0);
        for point in &self.slab.points {
            let (t, t_dot) = (&point.shape.t, &point.shape.t_dot);
            let at = |w: &[f64; 4], i: usize| (0..4).map(|m| w[m] * slots[m][i]).sum::<f64>();
            let theta: JetVec<6> = std::array::from_fn(|i| Jet::variable(at(t, i), i));
            let theta_dot: JetVec<6> = std::array::from_fn(|i| Jet::variable(at(t_dot, i), 3 + i));
            let density = self.rotational_density(&theta, &theta_dot, &loads);
            // d theta_g / d y_(m, i) = T_m, d theta_dot_g / d y_(m, i) = T_m'.
            let weight = |m: usize, k: usize| if k < 3 { t[m] } else { t_dot[m] };
            action.v += point.w_dt * density.v;
            for m in 0..4 {
                for i in 0..3 {
                    let row = 3 * m + i;
                    action.g[row] += point.w_dt
                        * (weight(m, i) * density.g[i] + weight(m, 3 + i) * density.g[3 + i]);
                    for n in 0..4 {
                        for j in 0..3 {
                            let mut h = 0.0;
                            for (a, wa) in [(i, weight(m, i)), (3 + i, weight(m, 3 + i))] {
                                for (b, wb) in [(j, weight(n, j)), (3 + j, weight(n, 3 + j))] {
                                    h += wa * wb * density.h[a][b];
                                }
                            }
                            action.h[row][3 * n + j] += point.w_dt * h;
                        }
                    }
                }
            }
        }
        action
    }

    /// The integrand of (B5)'s rotational part at one time point:
    /// 1/2 Omega . I_G Omega + sum_j F_j . exp([theta]) xi'_j (F_j and xi'_j
    /// in the start's body axes).
    fn rotational_density(
        &self,
        theta: &JetVec<6>,
        theta_dot: &JetVec<6>,
        loads: &[([f64; 3], [f64; 3])],
    ) -> Jet<6> {
        let i_g = &self.inertia.inertia_at_centre;
        let omega = body_rate(theta, theta_dot);
        let i_omega: JetVec<6> = std::array::from_fn(|r| {
            omega[0].scale(i_g[r][0]) + omega[1].scale(i_g[r][1]) + omega[2].scale(i_g[r][2])
        });
        let mut density = dot(&omega, &i_omega).scale(0.5);
        if !loads.is_empty() {
            let s = dot(theta, theta);
            let (f0, d0, dd0) = series(0, s.v);
            let (f1, d1, dd1) = series(1, s.v);
            let (f0, f1) = (s.compose(f0, d0, dd0), s.compose(f1, d1, dd1));
            for (f, xi) in loads {
                // F . exp([theta]) xi' (B10).
                let v: JetVec<6> = xi.map(Jet::constant);
                let t_x_v = cross(theta, &v);
                let t_x_t_x_v = cross(theta, &t_x_v);
                let turned: JetVec<6> =
                    std::array::from_fn(|i| v[i] + f0 * t_x_v[i] + f1 * t_x_t_x_v[i]);
                density = density + dot(&f.map(Jet::constant), &turned);
            }
        }
        density
    }

    /// The Galerkin rows (B6) at x = [w_a, r_b - r_a, w_b, u_a, theta_b,
    /// u_b] and their exact Jacobian (row-major, 18 x 18).
    pub fn galerkin_rows_and_jacobian(&self, x: &[f64]) -> (Vec<f64>, Vec<f64>) {
        let mut r = vec![0.0; N];
        let mut jac = vec![0.0; N * N];
        let y = [[0.0; 3], part(x, 0), part(x, 3), part(x, 6)];
        let c = &self.slab.kinetic;
        for (block, m) in [(0usize, 0usize), (1, 1), (2, 3)] {
            let g = self.translation_gradient(m, &y);
            for i in 0..3 {
                r[3 * block + i] = g[i] + if m == 0 { self.momentum[i] } else { 0.0 };
                for (col, n) in [(0usize, 1usize), (1, 2), (2, 3)] {
                    jac[(3 * block + i) * N + 3 * col + i] = self.inertia.mass * c[m][n];
                }
            }
        }
        let a = self.rotational_action(part(x, 9), part(x, 12), part(x, 15));
        // Rows: theta_a (jet 0..3), u_a (3..6), u_b (9..12); unknowns u_a,
        // theta_b, u_b (jet 3..12).
        for (block, start) in [(0usize, 0usize), (1, 3), (2, 9)] {
            for i in 0..3 {
                let row = 9 + 3 * block + i;
                let momentum = if start == 0 {
                    self.body_momentum[i]
                } else {
                    0.0
                };
                r[row] = a.g[start + i] + momentum;
                for k in 0..9 {
                    jac[row * N + 9 + k] = a.h[start + i][3 + k];
                }
            }
        }
        (r, jac)
    }

    /// The P2 rows (B11) at x = [r_b - r_a, v_b, theta_b, u_b] and their
    /// exact Jacobian (row-major, 12 x 12): the end slopes are the carried
    /// rates (u_a = Omega_a, J_r(0) = I; u_b = J_r(theta_b)^-1 Omega_b).
    pub fn p2_rows_and_jacobian(&self, x: &[f64]) -> (Vec<f64>, Vec<f64>) {
        const M: usize = 12;
        let mut r = vec![0.0; M];
        let mut jac = vec![0.0; M * M];
        let mass = self.inertia.mass;
        let v_a = scale(1.0 / mass, self.momentum);
        let y = [[0.0; 3], v_a, part(x, 0), part(x, 3)];
        let c = &self.slab.kinetic;
        for (block, m) in [(0usize, 0usize), (1, 2)] {
            let g = self.translation_gradient(m, &y);
            for i in 0..3 {
                let row = 3 * block + i;
                r[row] = g[i]
                    + if m == 0 {
                        self.momentum[i]
                    } else {
                        -mass * x[3 + i]
                    };
                jac[row * M + i] = mass * c[m][2];
                jac[row * M + 3 + i] = mass * c[m][3] - if m == 2 { mass } else { 0.0 };
            }
        }
        let omega_a = self.body_angular_velocity();
        let (theta_b, u_b) = (part(x, 6), part(x, 9));
        let a = self.rotational_action(omega_a, theta_b, u_b);
        // J_r(theta_b)^T I_G J_r(theta_b) u_b = J_r^T Pi_b, on jets (its
        // first derivatives are the row's): J_r^T v is (B9) at -theta.
        let theta: JetVec<6> = std::array::from_fn(|i| Jet::variable(theta_b[i], i));
        let rate: JetVec<6> = std::array::from_fn(|i| Jet::variable(u_b[i], 3 + i));
        let omega_b = body_rate(&theta, &rate);
        let pi_b: JetVec<6> = std::array::from_fn(|row| {
            let i_g = &self.inertia.inertia_at_centre[row];
            omega_b[0].scale(i_g[0]) + omega_b[1].scale(i_g[1]) + omega_b[2].scale(i_g[2])
        });
        let end = body_rate(&theta.map(|t| -t), &pi_b);
        for i in 0..3 {
            r[6 + i] = a.g[i] + self.body_momentum[i];
            r[9 + i] = a.g[6 + i] - end[i].v;
            for k in 0..6 {
                jac[(6 + i) * M + 6 + k] = a.h[i][6 + k];
                jac[(9 + i) * M + 6 + k] = a.h[6 + i][6 + k] - end[i].g[k];
            }
        }
        (r, jac)
    }

    /// One step of (B6)-(B7) (Galerkin) or (B11) (P2).
    pub fn step(&mut self) -> Result<(), SolverError> {
        let dt = self.slab.dt;
        let v_g = scale(1.0 / self.inertia.mass, self.momentum);
        let omega = self.body_angular_velocity();
        let guess = |position: bool, v: [f64; 3]| if position { scale(dt, v) } else { v };
        // The unknowns' order and which are positions (lengths, angles)
        // rather than rates.
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
        let rotated = match self.scheme {
            TimeScheme::Galerkin => {
                let y = [[0.0; 3], part(&x, 0), part(&x, 3), part(&x, 6)];
                self.momentum = self.translation_gradient(2, &y);
                self.centre = add(self.centre, y[2]);
                let a = self.rotational_action(part(&x, 9), part(&x, 12), part(&x, 15));
                let theta_b = part(&x, 12);
                // Pi_b solves J_r(theta_b)^T Pi_b = dA/dtheta_b.
                let jr = right_jacobian(theta_b);
                let jr_t: [[f64; 3]; 3] =
                    std::array::from_fn(|i| std::array::from_fn(|j| jr[j][i]));
                let inverse = invert3(&jr_t)
                    .ok_or_else(|| self.failure(FailureKind::SingularJacobian, 0, 0.0))?;
                self.body_momentum = mat_vec(&inverse, [a.g[6], a.g[7], a.g[8]]);
                theta_b
            }
            TimeScheme::P2 => {
                self.momentum = scale(self.inertia.mass, part(&x, 3));
                self.centre = add(self.centre, part(&x, 0));
                let theta_b = part(&x, 6);
                let omega_b = mat_vec(&right_jacobian(theta_b), part(&x, 9));
                self.body_momentum = mat_vec(&self.inertia.inertia_at_centre, omega_b);
                theta_b
            }
        };
        self.rotation =
            pose::reorthonormalized(&crate::vec3::mat3_mul(&self.rotation, &exp_map(rotated)));
        self.time += dt;
        Ok(())
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
            if change <= 1e-14 {
                return Ok(());
            }
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
            detail: "free body step (B6)".into(),
        }
    }
}

/// x[a..a + 3].
fn part(x: &[f64], a: usize) -> [f64; 3] {
    [x[a], x[a + 1], x[a + 2]]
}

fn mat_vec(a: &[[f64; 3]; 3], v: [f64; 3]) -> [f64; 3] {
    rotate(a, v)
}

/// The inverse of a 3 x 3 matrix by its adjugate (None if singular).
fn invert3(a: &[[f64; 3]; 3]) -> Option<[[f64; 3]; 3]> {
    let cof = |r: usize, c: usize| {
        let (r1, r2) = ((r + 1) % 3, (r + 2) % 3);
        let (c1, c2) = ((c + 1) % 3, (c + 2) % 3);
        a[r1][c1] * a[r2][c2] - a[r1][c2] * a[r2][c1]
    };
    let det: f64 = (0..3).map(|c| a[0][c] * cof(0, c)).sum();
    let size = a.iter().flatten().fold(0.0f64, |m, v| m.max(v.abs()));
    if !(det.abs() > 1e-300 && det.abs() > 1e-14 * size.powi(3)) {
        return None;
    }
    Some(std::array::from_fn(|i| {
        std::array::from_fn(|j| cof(j, i) / det)
    }))
}
