//! A rigid body's inertia as the natural coordinates see it
//! (docs/method.md §15.2).
//!
//! With x(xi) = S(xi) q (B1), the kinetic energy of the body is
//!
//! ```text
//!   T = 1/2 int |x_dot|^2 dm = 1/2 q_dot^T (Q (x) I_3) q_dot,
//!   Q = int [1; xi] [1; xi]^T dm = [ m      m c^T ]
//!                                  [ m c    J     ],                         (B2)
//!   J = int xi xi^T dm = J_G + m c c^T,   J_G = 1/2 tr(I_G) 1 - I_G          (B3)
//! ```
//!
//! (c the centre of mass and I_G the inertia tensor at it, both in body
//! axes). Q is constant: the rotational kinetic energy 1/2 w . I w, with
//! its gyroscopic terms, comes out of a quadratic form in q_dot. Q is
//! positive definite exactly when m > 0 and J_G is, i.e. when the principal
//! moments satisfy the triangle inequalities I_1 <= I_2 + I_3 (and
//! cyclically), which every mass distribution does; a body without mass or
//! with moments that no mass distribution has is refused.

use crate::error::ModelError;

/// Mass, centre of mass (body axes, from the reference point) and inertia
/// tensor at the centre of mass (body axes).
#[derive(Clone, Debug, PartialEq)]
pub struct RigidInertia {
    pub mass: f64,
    pub centre_of_mass: [f64; 3],
    pub inertia_at_centre: [[f64; 3]; 3],
}

impl RigidInertia {
    /// A body with principal axes along its body axes (MoorDyn's BODIES
    /// rows: one or three moments).
    pub fn principal(mass: f64, centre_of_mass: [f64; 3], moments: [f64; 3]) -> Self {
        let mut inertia_at_centre = [[0.0; 3]; 3];
        for i in 0..3 {
            inertia_at_centre[i][i] = moments[i];
        }
        RigidInertia {
            mass,
            centre_of_mass,
            inertia_at_centre,
        }
    }

    /// (B3): the second moment of the mass about the centre, J_G.
    pub fn second_moment_at_centre(&self) -> [[f64; 3]; 3] {
        let i = &self.inertia_at_centre;
        let half_trace = 0.5 * (i[0][0] + i[1][1] + i[2][2]);
        let mut j = [[0.0; 3]; 3];
        for r in 0..3 {
            for c in 0..3 {
                j[r][c] = if r == c { half_trace } else { 0.0 } - i[r][c];
            }
        }
        j
    }

    /// (B2): the 4 x 4 generalized mass Q; the body's mass matrix is
    /// Q (x) I_3 over q = [r, a_1, a_2, a_3].
    pub fn generalized_mass(&self) -> [[f64; 4]; 4] {
        let m = self.mass;
        let c = self.centre_of_mass;
        let jg = self.second_moment_at_centre();
        let mut q = [[0.0; 4]; 4];
        q[0][0] = m;
        for i in 0..3 {
            q[0][i + 1] = m * c[i];
            q[i + 1][0] = m * c[i];
            for k in 0..3 {
                q[i + 1][k + 1] = jg[i][k] + m * c[i] * c[k];
            }
        }
        q
    }

    /// Refuses what is not a rigid body's inertia: a mass that is not
    /// positive and finite, a tensor that is not symmetric, or one whose
    /// J_G (B3) is not positive definite (moments breaking the triangle
    /// inequality, or a body of zero extent in some direction).
    pub fn validate(&self, key: &str) -> Result<(), ModelError> {
        let finite = self.mass.is_finite()
            && self.centre_of_mass.iter().all(|v| v.is_finite())
            && self
                .inertia_at_centre
                .iter()
                .flatten()
                .all(|v| v.is_finite());
        if !finite {
            return Err(ModelError::invalid(
                key,
                "mass, centre and inertia must be finite",
            ));
        }
        if self.mass <= 0.0 {
            return Err(ModelError::invalid(
                key,
                format!("mass {} kg: a free body needs a positive mass", self.mass),
            ));
        }
        let i = &self.inertia_at_centre;
        for r in 0..3 {
            for c in 0..r {
                if (i[r][c] - i[c][r]).abs() > 1e-12 * (i[r][c].abs() + i[c][r].abs()) {
                    return Err(ModelError::invalid(
                        key,
                        "the inertia tensor is not symmetric",
                    ));
                }
            }
        }
        let j = self.second_moment_at_centre();
        let minors = [
            j[0][0],
            j[0][0] * j[1][1] - j[0][1] * j[1][0],
            determinant(&j),
        ];
        let scale = (i[0][0].abs() + i[1][1].abs() + i[2][2].abs()).max(f64::MIN_POSITIVE);
        if minors[0] <= 0.0 || minors[1] <= 0.0 || minors[2] <= 1e-12 * scale.powi(3) {
            return Err(ModelError::invalid(
                key,
                format!(
                    "moments of inertia {:?} kg m^2 at the centre of mass are not those of a \
                     body with extent in all three directions (each principal moment must be \
                     less than the sum of the other two)",
                    [i[0][0], i[1][1], i[2][2]]
                ),
            ));
        }
        Ok(())
    }
}

fn determinant(a: &[[f64; 3]; 3]) -> f64 {
    a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1])
        - a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0])
        + a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0])
}

#[cfg(test)]
mod tests {
    use super::*;

    /// (B2) reproduces 1/2 m |v_G|^2 + 1/2 w . I_G w for a rigid motion
    /// x_dot = v + w x (x - r) of a body with an offset centre.
    #[test]
    fn the_generalized_mass_gives_the_rigid_bodys_kinetic_energy() {
        let body = RigidInertia {
            mass: 3.0,
            centre_of_mass: [0.2, -0.5, 0.7],
            inertia_at_centre: [[2.0, 0.1, -0.2], [0.1, 1.5, 0.3], [-0.2, 0.3, 1.8]],
        };
        let q = body.generalized_mass();
        // Identity orientation: a_i = e_i, a_i_dot = w x e_i.
        let v = [0.3, -1.1, 0.4];
        let w = [0.7, 0.2, -1.3];
        let mut qdot = [[0.0; 3]; 4];
        qdot[0] = v;
        for i in 0..3 {
            let mut e = [0.0; 3];
            e[i] = 1.0;
            qdot[i + 1] = crate::vec3::cross(w, e);
        }
        let mut t = 0.0;
        for a in 0..4 {
            for b in 0..4 {
                t += 0.5 * q[a][b] * crate::vec3::dot(qdot[a], qdot[b]);
            }
        }
        let v_g = crate::vec3::add(v, crate::vec3::cross(w, body.centre_of_mass));
        let iw: Vec<f64> = (0..3)
            .map(|r| (0..3).map(|c| body.inertia_at_centre[r][c] * w[c]).sum())
            .collect();
        let expected = 0.5 * body.mass * crate::vec3::dot(v_g, v_g)
            + 0.5 * (0..3).map(|k| w[k] * iw[k]).sum::<f64>();
        assert!((t - expected).abs() < 1e-13 * expected, "{t} vs {expected}");
    }

    #[test]
    fn moments_no_body_has_are_refused() {
        let ok = RigidInertia::principal(2.0, [0.0; 3], [1.0, 1.0, 1.9]);
        assert!(ok.validate("bodies[0]").is_ok());
        let rod_like = RigidInertia::principal(2.0, [0.0; 3], [1.0, 1.0, 2.0]);
        assert!(
            rod_like.validate("bodies[0]").is_err(),
            "a flat disc has no thickness"
        );
        let bad = RigidInertia::principal(2.0, [0.0; 3], [1.0, 1.0, 3.0]);
        let e = bad.validate("bodies[0]").unwrap_err();
        assert!(e.to_string().contains("less than the sum"), "{e}");
        assert!(RigidInertia::principal(0.0, [0.0; 3], [1.0; 3])
            .validate("b")
            .is_err());
    }
}
