//! Currents as depth profiles, and the ramp that starts a sea
//! (docs/method.md §12.1, (W9)-(W11)).
//!
//! A profile is a table of rows (z_i, U_i), z_i strictly increasing
//! after sorting; the current is linear between rows and constant beyond
//! the first and the last (W9); its vertical derivative is piecewise
//! constant, taken from the row's upper side at a row (W10).

use crate::error::ModelError;
use std::f64::consts::PI;

/// One row of a current profile: the current velocity (m/s) at height z
/// (m, z up, still water level z = 0).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CurrentRow {
    pub z: f64,
    pub velocity: [f64; 3],
}

/// A current that depends on z only, from a table of rows (W9).
#[derive(Clone, Debug, PartialEq)]
pub struct CurrentProfile {
    /// Rows by strictly increasing z; at least one.
    rows: Vec<CurrentRow>,
}

impl CurrentProfile {
    /// A profile from rows by strictly increasing or strictly decreasing z
    /// (a surface-down table is reversed). Refused: no rows, a value that
    /// is not finite, z not strictly monotone (naming the first row out of
    /// order, `rows[3].z`).
    pub fn new(rows: &[CurrentRow]) -> Result<Self, ModelError> {
        if rows.is_empty() {
            return Err(ModelError::invalid(
                "rows",
                "a current profile needs at least one row",
            ));
        }
        for (i, row) in rows.iter().enumerate() {
            if !row.z.is_finite() {
                return Err(ModelError::invalid(
                    format!("rows[{i}].z"),
                    "must be finite",
                ));
            }
            if row.velocity.iter().any(|v| !v.is_finite()) {
                return Err(ModelError::invalid(
                    format!("rows[{i}].velocity"),
                    "must be finite",
                ));
            }
        }
        let decreasing = rows.len() > 1 && rows[1].z < rows[0].z;
        for i in 1..rows.len() {
            let in_order = if decreasing {
                rows[i].z < rows[i - 1].z
            } else {
                rows[i].z > rows[i - 1].z
            };
            if !in_order {
                let direction = if decreasing {
                    "decreasing"
                } else {
                    "increasing"
                };
                return Err(ModelError::invalid(
                    format!("rows[{i}].z"),
                    format!(
                        "rows must be by strictly {direction} z as the first two are: {} after {}",
                        rows[i].z,
                        rows[i - 1].z
                    ),
                ));
            }
        }
        let mut rows = rows.to_vec();
        if decreasing {
            rows.reverse();
        }
        Ok(CurrentProfile { rows })
    }

    /// A current the same at every depth.
    pub fn uniform(velocity: [f64; 3]) -> Result<Self, ModelError> {
        CurrentProfile::new(&[CurrentRow { z: 0.0, velocity }])
    }

    /// The rows by increasing z.
    pub fn rows(&self) -> &[CurrentRow] {
        &self.rows
    }

    /// The current U(z) and its derivative dU/dz at height z:
    ///
    /// ```text
    /// U(z) = U_i + (z - z_i) (U_{i+1} - U_i) / (z_{i+1} - z_i)
    ///        for z_i <= z < z_{i+1}                                   (W9)
    /// U(z) = U_0 for z < z_0,  U(z) = U_last for z >= z_last
    ///
    /// dU/dz = (U_{i+1} - U_i) / (z_{i+1} - z_i) on [z_i, z_{i+1}),
    ///         0 below z_0 and from z_last up                          (W10)
    /// ```
    ///
    /// At a row z = z_i, where U has a kink, dU/dz is the derivative on
    /// the segment above the row (the right-hand derivative in z); the
    /// half-open segments make (W9) and (W10) agree on that choice.
    pub fn velocity_and_derivative(&self, z: f64) -> ([f64; 3], [f64; 3]) {
        let rows = &self.rows;
        let first = rows[0];
        let last = rows[rows.len() - 1];
        if z < first.z {
            return (first.velocity, [0.0; 3]);
        }
        if z >= last.z {
            return (last.velocity, [0.0; 3]);
        }
        // The row below z: the last row with z_i <= z (first.z <= z < last.z,
        // so 1 <= count < rows.len()).
        let below = rows.partition_point(|row| row.z <= z) - 1;
        let (lower, upper) = (rows[below], rows[below + 1]);
        let height = upper.z - lower.z;
        let fraction = (z - lower.z) / height;
        let mut velocity = [0.0; 3];
        let mut derivative = [0.0; 3];
        for c in 0..3 {
            let rise = upper.velocity[c] - lower.velocity[c];
            velocity[c] = lower.velocity[c] + fraction * rise;
            derivative[c] = rise / height;
        }
        (velocity, derivative)
    }
}

/// A smooth start in time: the factor
///
/// ```text
/// r(t) = 0 for t <= 0,  (1 - cos(pi t / T)) / 2 for 0 < t < T,  1 after
/// r'(t) = (pi / (2 T)) sin(pi t / T) for 0 < t < T,  0 otherwise  (W11)
/// ```
///
/// continuous with its first derivative at t = 0 and t = T. A duration of
/// zero is no ramp (r = 1 always).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Ramp {
    duration: f64,
}

impl Ramp {
    /// No ramp: r = 1 at every t.
    pub const NONE: Ramp = Ramp { duration: 0.0 };

    /// A ramp over `duration` seconds (>= 0, finite; 0 is none).
    pub fn new(duration: f64) -> Result<Self, ModelError> {
        if !(duration.is_finite() && duration >= 0.0) {
            return Err(ModelError::invalid(
                "ramp",
                format!("the ramp duration must be finite and >= 0 s, got {duration}"),
            ));
        }
        Ok(Ramp { duration })
    }

    pub fn duration(&self) -> f64 {
        self.duration
    }

    /// r(t) and r'(t) of (W11).
    pub fn factor_and_rate(&self, t: f64) -> (f64, f64) {
        let duration = self.duration;
        if duration == 0.0 || t >= duration {
            (1.0, 0.0)
        } else if t <= 0.0 {
            (0.0, 0.0)
        } else {
            let (sin, cos) = (PI * t / duration).sin_cos();
            (0.5 * (1.0 - cos), 0.5 * PI / duration * sin)
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn row(z: f64, velocity: [f64; 3]) -> CurrentRow {
        CurrentRow { z, velocity }
    }

    fn surface_down_profile() -> CurrentProfile {
        CurrentProfile::new(&[
            row(0.0, [1.0, 0.5, 0.0]),
            row(-10.0, [0.6, 0.25, 0.02]),
            row(-40.0, [0.2, -0.1, 0.0]),
        ])
        .unwrap()
    }

    #[test]
    fn a_profile_is_linear_between_rows() {
        let profile = surface_down_profile();
        // Rows are reproduced exactly; a quarter of the way from -40 to -10
        // is a quarter of the way between their currents.
        assert_eq!(profile.velocity_and_derivative(-10.0).0, [0.6, 0.25, 0.02]);
        let (u, dudz) = profile.velocity_and_derivative(-32.5);
        let expected = [0.2 + 0.25 * 0.4, -0.1 + 0.25 * 0.35, 0.25 * 0.02];
        let slope = [0.4 / 30.0, 0.35 / 30.0, 0.02 / 30.0];
        for c in 0..3 {
            assert!((u[c] - expected[c]).abs() < 4.0 * f64::EPSILON, "{u:?}");
            assert!((dudz[c] - slope[c]).abs() < 4.0 * f64::EPSILON * slope[c].abs().max(1.0));
        }
    }

    #[test]
    fn a_profile_is_constant_beyond_its_ends() {
        let profile = surface_down_profile();
        assert_eq!(
            profile.velocity_and_derivative(3.0),
            ([1.0, 0.5, 0.0], [0.0; 3])
        );
        assert_eq!(
            profile.velocity_and_derivative(-400.0),
            ([0.2, -0.1, 0.0], [0.0; 3])
        );
        assert_eq!(
            profile.velocity_and_derivative(0.0),
            ([1.0, 0.5, 0.0], [0.0; 3])
        );
    }

    #[test]
    fn the_profile_derivative_is_its_finite_difference() {
        // Linear segments: a central difference inside a segment is exact
        // up to round-off eps |U| / step.
        let profile = surface_down_profile();
        let step = 1e-4;
        for z in [-39.0, -25.0, -10.5, -9.5, -0.2] {
            let (_, dudz) = profile.velocity_and_derivative(z);
            let (up, _) = profile.velocity_and_derivative(z + step);
            let (down, _) = profile.velocity_and_derivative(z - step);
            for c in 0..3 {
                let difference = (up[c] - down[c]) / (2.0 * step);
                assert!((difference - dudz[c]).abs() < 1e-11, "z {z} c {c}");
            }
        }
        // At a row, the derivative of the segment above, as documented (W10):
        // the one-sided difference upwards.
        let (at_row, dudz) = profile.velocity_and_derivative(-10.0);
        let (up, _) = profile.velocity_and_derivative(-10.0 + step);
        for c in 0..3 {
            assert!(((up[c] - at_row[c]) / step - dudz[c]).abs() < 1e-11);
        }
    }

    #[test]
    fn increasing_and_decreasing_tables_give_the_same_current() {
        let decreasing = surface_down_profile();
        let mut rows = decreasing.rows().to_vec();
        rows.sort_by(|a, b| a.z.total_cmp(&b.z));
        let increasing = CurrentProfile::new(&rows).unwrap();
        assert_eq!(increasing, decreasing);
    }

    #[test]
    fn an_unsorted_profile_is_refused_naming_the_row() {
        let err = CurrentProfile::new(&[
            row(0.0, [1.0; 3]),
            row(-10.0, [1.0; 3]),
            row(-5.0, [1.0; 3]),
        ])
        .unwrap_err();
        assert_eq!(err.key, "rows[2].z");
        let err = CurrentProfile::new(&[row(-1.0, [1.0; 3]), row(-1.0, [1.0; 3])]).unwrap_err();
        assert_eq!(err.key, "rows[1].z");
        assert_eq!(CurrentProfile::new(&[]).unwrap_err().key, "rows");
        let err = CurrentProfile::new(&[row(0.0, [f64::NAN, 0.0, 0.0])]).unwrap_err();
        assert_eq!(err.key, "rows[0].velocity");
    }

    #[test]
    fn the_ramp_rate_is_the_derivative_of_the_ramp() {
        // r''' <= (pi/T)^3 / 2, so the central difference errs by at most
        // step^2 (pi/T)^3 / 12, plus round-off eps / step.
        let ramp = Ramp::new(8.0).unwrap();
        let step = 1e-4;
        let bound = step * step * (PI / 8.0f64).powi(3) / 12.0 + 4.0 * f64::EPSILON / step;
        for t in [0.3, 2.0, 4.0, 6.5, 7.9] {
            let (_, rate) = ramp.factor_and_rate(t);
            let difference = (ramp.factor_and_rate(t + step).0 - ramp.factor_and_rate(t - step).0)
                / (2.0 * step);
            assert!((difference - rate).abs() < bound, "t {t}");
        }
        assert_eq!(ramp.factor_and_rate(0.0), (0.0, 0.0));
        assert_eq!(ramp.factor_and_rate(8.0), (1.0, 0.0));
        assert_eq!(Ramp::NONE.factor_and_rate(0.0), (1.0, 0.0));
        assert_eq!(Ramp::new(-1.0).unwrap_err().key, "ramp");
    }
}
