//! A rigid body's inertia (docs/method.md §15.2): mass, centre of mass
//! and inertia tensor at the centre of mass, in body axes.
//!
//! The kinetic energy is `T = 1/2 m |v_G|^2 + 1/2 Omega . I_G Omega`
//! (Omega the angular velocity in body axes). Only what a mass
//! distribution can have is accepted: m > 0, I_G symmetric and each
//! principal moment less than the sum of the other two (the triangle
//! inequalities): `J_G = 1/2 tr(I_G) 1 - I_G = int xi xi^T dm` must be
//! positive definite (B2).

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

    /// The body with a point mass m added at `at` (body axes, from the
    /// reference point): [`Self::with_part`] with a part of no size.
    pub fn with_point_mass(&self, m: f64, at: [f64; 3]) -> RigidInertia {
        self.with_part(&RigidInertia {
            mass: m,
            centre_of_mass: at,
            inertia_at_centre: [[0.0; 3]; 3],
        })
    }

    /// The body with a rigid part joined to it (a rod, a point mass): the
    /// masses add, the centre moves to their barycentre and each part's
    /// inertia is carried to it (the parallel axis theorem,
    /// I + m (|d|^2 1 - d d^T)).
    pub fn with_part(&self, part: &RigidInertia) -> RigidInertia {
        let total = self.mass + part.mass;
        if total <= 0.0 {
            return self.clone();
        }
        let centre: [f64; 3] = std::array::from_fn(|i| {
            (self.mass * self.centre_of_mass[i] + part.mass * part.centre_of_mass[i]) / total
        });
        let shift = |mass: f64, from: [f64; 3]| -> [[f64; 3]; 3] {
            let d: [f64; 3] = std::array::from_fn(|i| from[i] - centre[i]);
            let dd = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
            std::array::from_fn(|i| {
                std::array::from_fn(|j| mass * (if i == j { dd } else { 0.0 } - d[i] * d[j]))
            })
        };
        let a = shift(self.mass, self.centre_of_mass);
        let b = shift(part.mass, part.centre_of_mass);
        RigidInertia {
            mass: total,
            centre_of_mass: centre,
            inertia_at_centre: std::array::from_fn(|i| {
                std::array::from_fn(|j| {
                    self.inertia_at_centre[i][j] + part.inertia_at_centre[i][j] + a[i][j] + b[i][j]
                })
            }),
        }
    }

    /// (B2): the second moment of the mass about the centre,
    /// `J_G = int xi xi^T dm = 1/2 tr(I_G) 1 - I_G`.
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

    /// Refuses what is not a rigid body's inertia: a mass that is not
    /// positive and finite, a tensor that is not symmetric, or one whose
    /// J_G (B2) is not positive definite (moments breaking the triangle
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
        // Tolerances relative to the tensor's size (its trace): a tensor
        // built as R D R^T has off-diagonal pairs that differ by round-off
        // of the whole tensor, not of themselves.
        let scale = (i[0][0].abs() + i[1][1].abs() + i[2][2].abs()).max(f64::MIN_POSITIVE);
        for r in 0..3 {
            for c in 0..r {
                if (i[r][c] - i[c][r]).abs() > 1e-12 * scale {
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
        // Sylvester's criterion, each leading minor against the trace to
        // its power (a minor is a product of that many eigenvalues).
        let tolerance = [1e-12 * scale, 1e-12 * scale.powi(2), 1e-12 * scale.powi(3)];
        if (0..3).any(|k| minors[k] <= tolerance[k]) {
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

    #[test]
    fn moments_no_body_has_are_refused() {
        let ok = RigidInertia::principal(2.0, [0.0; 3], [1.0, 1.0, 1.9]);
        assert!(ok.validate("bodies[0]").is_ok());
        let flat_disc = RigidInertia::principal(2.0, [0.0; 3], [1.0, 1.0, 2.0]);
        assert!(
            flat_disc.validate("bodies[0]").is_err(),
            "a flat disc has no thickness"
        );
        // A principal tensor turned, R D R^T: symmetric to round-off only.
        let r = crate::body::pose::rotation_from_moordyn_angles([33.0, -71.0, 12.5]);
        let d = [1.3, 1.7, 2.1];
        let turned: [[f64; 3]; 3] = std::array::from_fn(|a| {
            std::array::from_fn(|b| (0..3).map(|k| r[a][k] * d[k] * r[b][k]).sum())
        });
        let body = RigidInertia {
            mass: 2.0,
            centre_of_mass: [0.0; 3],
            inertia_at_centre: turned,
        };
        assert!(body.validate("bodies[0]").is_ok());
        let bad = RigidInertia::principal(2.0, [0.0; 3], [1.0, 1.0, 3.0]);
        let e = bad.validate("bodies[0]").unwrap_err();
        assert!(e.to_string().contains("less than the sum"), "{e}");
        assert!(RigidInertia::principal(0.0, [0.0; 3], [1.0; 3])
            .validate("b")
            .is_err());
    }

    /// Two bodies' inertia about their common centre is each one's about
    /// its own plus the reduced mass times the squared distance across
    /// the line between them: M m / (M + m) d^2 (and nothing along it).
    #[test]
    fn a_point_mass_joins_by_the_parallel_axis_theorem() {
        let body = RigidInertia::principal(3.0, [0.0, 0.0, -1.0], [2.0, 3.0, 4.0]);
        let joined = body.with_point_mass(1.0, [2.0, 0.0, -1.0]);
        let reduced = 3.0 * 1.0 / 4.0;
        assert_eq!(joined.mass, 4.0);
        assert!((joined.centre_of_mass[0] - 0.5).abs() < 1e-15);
        assert!((joined.centre_of_mass[2] + 1.0).abs() < 1e-15);
        let i = joined.inertia_at_centre;
        assert!((i[0][0] - 2.0).abs() < 1e-14);
        assert!((i[1][1] - (3.0 + reduced * 4.0)).abs() < 1e-14);
        assert!((i[2][2] - (4.0 + reduced * 4.0)).abs() < 1e-14);
        for (r, c) in [(0, 1), (0, 2), (1, 2)] {
            assert!(i[r][c].abs() < 1e-15 && i[c][r].abs() < 1e-15);
        }
    }
}
