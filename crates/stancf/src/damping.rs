//! Damping along fixed axes, MoorDyn-F's EXTERNAL LOADS (docs/method.md
//! §15.21, (B42)): on a free point along the global axes, on a free body
//! at its reference point along the global or the body's axes, a linear
//! and a quadratic coefficient per axis,
//!
//! ```text
//!   f_i = -b1_i v_i - b2_i |v_i| v_i,   df_i/dv_i = -(b1_i + 2 b2_i |v_i|)   (B42)
//! ```
//!
//! (no sum over i: each axis on its own velocity component). It is
//! virtual work at the slab's time points, as the water's drag; at rest it
//! is zero, so statics never sees it.

use crate::error::ModelError;

/// Linear (N s/m) and quadratic (N s^2/m^2) damping coefficients along
/// three axes.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct AxisDamping {
    pub linear: [f64; 3],
    pub quadratic: [f64; 3],
}

impl AxisDamping {
    /// Whether every coefficient is zero.
    pub fn is_zero(&self) -> bool {
        self.linear == [0.0; 3] && self.quadratic == [0.0; 3]
    }

    /// Refuses a coefficient that is negative or not finite (a negative
    /// one would feed energy in), naming `key`.
    pub fn check(&self, key: &str) -> Result<(), ModelError> {
        for (name, values) in [("linear", self.linear), ("quadratic", self.quadratic)] {
            if values.iter().any(|b| !(b.is_finite() && *b >= 0.0)) {
                return Err(ModelError::invalid(
                    format!("{key}.damping_{name}"),
                    format!("{values:?}: must be finite and not negative"),
                ));
            }
        }
        Ok(())
    }

    /// (B42) at the velocity `v` along the axes: the force and its
    /// diagonal derivative df_i/dv_i.
    pub fn force(&self, v: [f64; 3]) -> ([f64; 3], [f64; 3]) {
        let force =
            std::array::from_fn(|i| -self.linear[i] * v[i] - self.quadratic[i] * v[i].abs() * v[i]);
        let slope = std::array::from_fn(|i| -self.linear[i] - 2.0 * self.quadratic[i] * v[i].abs());
        (force, slope)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// (B42)'s derivative against central differences on both sides of
    /// zero.
    #[test]
    fn axis_damping_derivatives_are_exact() {
        let d = AxisDamping {
            linear: [3.0, 0.0, 1.5],
            quadratic: [2.0, 5.0, 0.0],
        };
        for v in [[0.7, -1.3, 0.2], [-0.4, 0.9, -2.0]] {
            let slope = d.force(v).1;
            for i in 0..3 {
                let h = 1e-6;
                let mut vp = v;
                let mut vm = v;
                vp[i] += h;
                vm[i] -= h;
                let fd = (d.force(vp).0[i] - d.force(vm).0[i]) / (2.0 * h);
                assert!(
                    (fd - slope[i]).abs() < 1e-8 * (1.0 + slope[i].abs()),
                    "{fd} {}",
                    slope[i]
                );
            }
        }
    }
}
