//! A free rigid body's Galerkin step (docs/method.md §15.4).
//!
//! Over a step the natural coordinates move along the cubic of eq. (6),
//! `q(t) = T1 q_a + T2 w_a + T3 q_b + T4 w_b`, with end slopes w internal
//! to the step as in the cables' Galerkin step (M22). The body's action
//! (M13) with the constant mass Q (x) I_3 of (B2) and the generalized
//! force f of constant forces F_j at body points xi_j,
//!
//! ```text
//!   A = sum_g w_g dt [ 1/2 q_dot_g^T M q_dot_g + f . q_g ],   f_k = sum_j s_k(xi_j) F_j     (B4)
//!   dA/dy_m = sum_n C_mn M y_n + b_m f,      d2A/dy_m dy_n = C_mn M
//! ```
//!
//! and the conditions (B5) held at the step's ends with multipliers
//! (the RATTLE form of a constrained variational integrator):
//!
//! ```text
//!   dA/dq_a + p_a + G(q_a)^T lambda = 0,   dA/dw_a = 0,   dA/dw_b = 0,   g(q_b) = 0    (B6)
//!   p_b = dA/dq_b + G(q_b)^T mu,   G(q_b) M^-1 p_b = 0,   v_b = M^-1 p_b                (B7)
//! ```
//!
//! (B6) are 42 equations in w_a, q_b, w_b (12 each) and lambda (6),
//! solved by Newton with the exact Jacobian (linear but for g); (B7) is a
//! 6 x 6 projection of the end momentum onto the rates that keep the
//! columns orthonormal. The action and the conditions are invariant under
//! rotations and translations, so the discrete momentum maps hold: the
//! angular momentum of a body without torque and the linear momentum of
//! one without force are kept to round-off.

use super::inertia::RigidInertia;
use super::natural::{self, column, Natural};
use super::orthonormality;
use crate::bordered::{dense_lu, dense_solve};
use crate::element::TimeSlab;
use crate::error::{FailureKind, ModelError, SolverError};
use crate::quadrature::GaussRule;
use crate::vec3::{add, cross, scale};

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

    /// The generalized force f of (B4).
    pub fn generalized(&self) -> Natural {
        let mut f = [0.0; 12];
        for (force, xi) in &self.forces {
            let s = natural::point_weights(*xi);
            for k in 0..4 {
                for i in 0..3 {
                    f[3 * k + i] += s[k] * force[i];
                }
            }
        }
        f
    }
}

/// Unknowns of a step: w_a, q_b, w_b and the six multipliers.
const N: usize = 42;
/// Newton iterations a step may take.
const MAX_ITERATIONS: usize = 30;

/// One rigid body moving freely under constant forces, stepped by (B6)-(B7).
#[derive(Clone, Debug)]
pub struct FreeBody {
    mass: [[f64; 4]; 4],
    mass_inverse: [[f64; 4]; 4],
    force: Natural,
    slab: TimeSlab,
    time: f64,
    q: Natural,
    v: Natural,
    p: Natural,
    last_iterations: usize,
}

/// (Q (x) I_3) y.
fn times(q4: &[[f64; 4]; 4], y: &Natural) -> Natural {
    let mut out = [0.0; 12];
    for k in 0..4 {
        for l in 0..4 {
            for i in 0..3 {
                out[3 * k + i] += q4[k][l] * y[3 * l + i];
            }
        }
    }
    out
}

impl FreeBody {
    /// A body at `position` with `rotation` (body axes to global), its
    /// reference point moving at `velocity` and turning at
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
        let mass = inertia.generalized_mass();
        let mass_inverse = invert4(&mass)
            .ok_or_else(|| ModelError::invalid("body", "the generalized mass (B2) is singular"))?;
        let q = natural::from_pose(position, rotation);
        let off = orthonormality::conditions(&q)
            .iter()
            .fold(0.0f64, |m, g| m.max(g.abs()));
        if off > 1e-12 {
            return Err(ModelError::invalid(
                "body.rotation",
                format!("not a rotation: its columns are off orthonormal by {off:e}"),
            ));
        }
        let v = natural::rates_from(velocity, angular_velocity, &q);
        let p = times(&mass, &v);
        Ok(FreeBody {
            mass,
            mass_inverse,
            force: forces.generalized(),
            slab: TimeSlab::new(dt, &GaussRule::new(3)?),
            time: 0.0,
            q,
            v,
            p,
            last_iterations: 0,
        })
    }

    pub fn time(&self) -> f64 {
        self.time
    }
    pub fn coordinates(&self) -> &Natural {
        &self.q
    }
    pub fn rates(&self) -> &Natural {
        &self.v
    }
    /// Newton iterations of the last step.
    pub fn last_iterations(&self) -> usize {
        self.last_iterations
    }
    /// The rotation matrix (body axes to global).
    pub fn rotation(&self) -> [[f64; 3]; 3] {
        natural::rotation(&self.q)
    }
    /// The angular velocity, global (B8).
    pub fn angular_velocity(&self) -> [f64; 3] {
        natural::angular_velocity(&self.q, &self.v)
    }

    /// Kinetic energy 1/2 v^T M v and the potential -f . q of the
    /// constant forces.
    pub fn energies(&self) -> (f64, f64) {
        let mv = times(&self.mass, &self.v);
        let kinetic = 0.5 * (0..12).map(|i| self.v[i] * mv[i]).sum::<f64>();
        let potential = -(0..12).map(|i| self.force[i] * self.q[i]).sum::<f64>();
        (kinetic, potential)
    }

    /// Linear momentum `sum_l Q_0l v_l` (m times the centre's velocity).
    pub fn linear_momentum(&self) -> [f64; 3] {
        let mut p = [0.0; 3];
        for l in 0..4 {
            p = add(p, scale(self.mass[0][l], column(&self.v, l)));
        }
        p
    }

    /// Angular momentum about the global origin,
    /// `sum_kl Q_kl q_k x v_l` (the integral of x x x_dot dm over (B1)).
    pub fn angular_momentum(&self) -> [f64; 3] {
        let mut h = [0.0; 3];
        for k in 0..4 {
            for l in 0..4 {
                let c = cross(column(&self.q, k), column(&self.v, l));
                h = add(h, scale(self.mass[k][l], c));
            }
        }
        h
    }

    /// dA/dy_m of (B4) for the slab's values y = [q_a, w_a, q_b, w_b].
    fn action_gradient(&self, m: usize, y: &[Natural; 4]) -> Natural {
        let c = &self.slab.kinetic;
        let mut mixed = [0.0; 12];
        for n in 0..4 {
            for i in 0..12 {
                mixed[i] += c[m][n] * y[n][i];
            }
        }
        let mut g = times(&self.mass, &mixed);
        for i in 0..12 {
            g[i] += self.slab.load[m] * self.force[i];
        }
        g
    }

    /// The rows (B6) at the unknowns x = [w_a, q_b, w_b, lambda].
    pub fn residual(&self, x: &[f64; N]) -> [f64; N] {
        let y = self.slab_values(x);
        let ga = orthonormality::jacobian(&self.q);
        let mut r = [0.0; N];
        let row_a = self.action_gradient(0, &y);
        for i in 0..12 {
            let constraint: f64 = (0..6).map(|j| ga[j][i] * x[36 + j]).sum();
            r[i] = row_a[i] + self.p[i] + constraint;
        }
        r[12..24].copy_from_slice(&self.action_gradient(1, &y));
        r[24..36].copy_from_slice(&self.action_gradient(3, &y));
        r[36..42].copy_from_slice(&orthonormality::conditions(&y[2]));
        r
    }

    /// The exact Jacobian of (B6), row-major 42 x 42.
    pub fn jacobian(&self, x: &[f64; N]) -> Vec<f64> {
        let y = self.slab_values(x);
        let c = &self.slab.kinetic;
        let mut jac = vec![0.0; N * N];
        // Kinetic blocks C_mn M for rows m = q_a, w_a, w_b and unknowns
        // n = w_a, q_b, w_b.
        for (row_block, m) in [(0usize, 0usize), (1, 1), (2, 3)] {
            for (col_block, n) in [(0usize, 1usize), (1, 2), (2, 3)] {
                for k in 0..4 {
                    for l in 0..4 {
                        let v = c[m][n] * self.mass[k][l];
                        for i in 0..3 {
                            jac[(12 * row_block + 3 * k + i) * N + 12 * col_block + 3 * l + i] = v;
                        }
                    }
                }
            }
        }
        let ga = orthonormality::jacobian(&self.q);
        let gb = orthonormality::jacobian(&y[2]);
        for j in 0..6 {
            for i in 0..12 {
                jac[i * N + 36 + j] = ga[j][i];
                jac[(36 + j) * N + 12 + i] = gb[j][i];
            }
        }
        jac
    }

    fn slab_values(&self, x: &[f64; N]) -> [Natural; 4] {
        let part = |a: usize| -> Natural { std::array::from_fn(|i| x[a + i]) };
        [self.q, part(0), part(12), part(24)]
    }

    /// One step of (B6)-(B7).
    pub fn step(&mut self) -> Result<(), SolverError> {
        let dt = self.slab.dt;
        let mut x = [0.0; N];
        for i in 0..12 {
            x[i] = self.v[i];
            x[12 + i] = self.q[i] + dt * self.v[i];
            x[24 + i] = self.v[i];
        }
        let mut pivots = [0usize; N];
        let scale_q = 1.0 + self.q.iter().fold(0.0f64, |m, v| m.max(v.abs()));
        let mut converged = false;
        let mut last_change = f64::INFINITY;
        for k in 1..=MAX_ITERATIONS {
            let mut delta = self.residual(&x);
            if delta.iter().any(|v| !v.is_finite()) {
                return Err(self.failure(FailureKind::NonFinite, k, f64::NAN));
            }
            let mut jac = self.jacobian(&x);
            if dense_lu(&mut jac, N, &mut pivots).is_err() {
                return Err(self.failure(FailureKind::SingularJacobian, k, f64::NAN));
            }
            dense_solve(&jac, N, &pivots, &mut delta);
            // The motion's change: positions and dt times the slopes.
            let mut change = 0.0f64;
            for i in 0..36 {
                x[i] -= delta[i];
                let size = if (12..24).contains(&i) {
                    delta[i]
                } else {
                    dt * delta[i]
                };
                change = change.max(size.abs());
            }
            for j in 36..N {
                x[j] -= delta[j];
            }
            last_change = change;
            self.last_iterations = k;
            if change <= 1e-14 * scale_q {
                converged = true;
                break;
            }
        }
        if !converged {
            return Err(self.failure(FailureKind::NotConverged, MAX_ITERATIONS, last_change));
        }
        let y = self.slab_values(&x);
        let end = self.action_gradient(2, &y);
        self.p = self.project_momentum(&y[2], &end);
        self.v = times(&self.mass_inverse, &self.p);
        self.q = y[2];
        self.time += dt;
        Ok(())
    }

    /// (B7): p_b = p~ + G^T mu with G M^-1 p_b = 0.
    fn project_momentum(&self, q_b: &Natural, p: &Natural) -> Natural {
        let g = orthonormality::jacobian(q_b);
        let m_inv_p = times(&self.mass_inverse, p);
        let m_inv_gt: Vec<Natural> = (0..6).map(|j| times(&self.mass_inverse, &g[j])).collect();
        let mut s = [0.0; 36];
        let mut mu = [0.0; 6];
        for a in 0..6 {
            mu[a] = -(0..12).map(|i| g[a][i] * m_inv_p[i]).sum::<f64>();
            for b in 0..6 {
                s[6 * a + b] = (0..12).map(|i| g[a][i] * m_inv_gt[b][i]).sum();
            }
        }
        let mut pivots = [0usize; 6];
        if dense_lu(&mut s, 6, &mut pivots).is_err() {
            return *p;
        }
        dense_solve(&s, 6, &pivots, &mut mu);
        let mut out = *p;
        for j in 0..6 {
            for i in 0..12 {
                out[i] += g[j][i] * mu[j];
            }
        }
        out
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

/// The inverse of a 4 x 4 matrix by Gauss-Jordan with partial pivoting
/// (None if singular).
fn invert4(a: &[[f64; 4]; 4]) -> Option<[[f64; 4]; 4]> {
    let mut lu: Vec<f64> = a.iter().flatten().copied().collect();
    let mut pivots = [0usize; 4];
    dense_lu(&mut lu, 4, &mut pivots).ok()?;
    let mut inv = [[0.0; 4]; 4];
    for c in 0..4 {
        let mut e = [0.0; 4];
        e[c] = 1.0;
        dense_solve(&lu, 4, &pivots, &mut e);
        for r in 0..4 {
            inv[r][c] = e[r];
        }
    }
    Some(inv)
}
