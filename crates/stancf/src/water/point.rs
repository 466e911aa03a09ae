//! A free point of a system in water (docs/method.md §12.6, (W33)-(W35)):
//! MoorDyn's POINTS columns Volume, CdA and Ca. As MoorDyn's points, a
//! point is taken to be wholly submerged wherever it is.
//!
//! With the point's displaced volume V, the relative velocity
//! v = u - r_dot and the water's local acceleration a_f at the point:
//!
//! ```text
//!   f_B = -rho_w V g                               buoyancy          (W33)
//!   f_D = 1/2 rho_w CdA |v| v,   f_I = rho_w V (1 + Ca) a_f          (W34)
//!   m_a = Ca rho_w V                               added mass        (W35)
//! ```
//!
//! The added mass is isotropic and constant, so it joins the point's mass
//! (its kinetic energy 1/2 m_a |r_dot|^2 is the entrained water's, and the
//! step stays Hamilton's law); f_D and f_I enter the point's rows at the
//! slab's time points like the lines' loads, with the derivatives
//!
//! ```text
//!   df/dr_dot = -Q,   df/dr = Q grad u + rho_w V (1 + Ca) grad a_f,
//!   Q = 1/2 rho_w CdA (|v| I + v v^T / |v|)
//! ```

use super::host_flow::FlowAt;
use super::hydro::{with_host_flow, Water};
use super::kinematics::FluidKinematics;
use crate::error::ModelError;
use std::sync::Arc;

/// The water's force on a point and its derivatives (rows: components).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct PointForce {
    pub force: [f64; 3],
    pub d_r: [[f64; 3]; 3],
    pub d_rdot: [[f64; 3]; 3],
}

/// A free point in water.
#[derive(Clone, Debug, PartialEq)]
pub struct PointInWater {
    pub water: Arc<Water>,
    /// Displaced volume V (m^3).
    pub volume: f64,
    /// Drag area CdA (m^2): the drag coefficient times the frontal area.
    pub drag_area: f64,
    /// Added-mass coefficient Ca on the volume.
    pub ca: f64,
    /// The flow a host has set at the point, when the sea's waves are the
    /// host's ([`super::Sea::host_waves`], (W2g)); None otherwise.
    pub host: Option<FlowAt>,
}

impl PointInWater {
    /// Checked: a volume, drag area and coefficient >= 0 and a density >=
    /// 0, all finite; `key` names the point in the message.
    pub fn check(&self, key: &str) -> Result<(), ModelError> {
        for (name, v) in [
            ("volume", self.volume),
            ("drag_area", self.drag_area),
            ("ca", self.ca),
            ("density", self.water.density),
        ] {
            if !(v.is_finite() && v >= 0.0) {
                return Err(ModelError::invalid(
                    format!("{key}.{name}"),
                    format!("must be a finite number >= 0, got {v}"),
                ));
            }
        }
        Ok(())
    }

    /// The added mass Ca rho_w V (W35).
    pub fn added_mass(&self) -> f64 {
        self.ca * self.water.density * self.volume
    }

    /// The buoyancy -rho_w V g under gravity `gravity` (W33).
    pub fn buoyancy(&self, gravity: &[f64; 3]) -> [f64; 3] {
        gravity.map(|g| -self.water.density * self.volume * g)
    }

    /// Drag and the fluid's inertia (W34) at `r` moving at `rdot` at time
    /// `t`, with their derivatives.
    pub fn force(&self, r: &[f64; 3], rdot: &[f64; 3], t: f64) -> PointForce {
        let flow = with_host_flow(self.water.sea.kinematics(r, t), self.host);
        self.force_in(&flow, rdot)
    }

    /// The force at rest in the steady current (statics, as the lines'
    /// §12.4: the current at full strength, no waves).
    pub fn static_force(&self, r: &[f64; 3]) -> PointForce {
        self.force_in(&self.water.sea.steady_current(r), &[0.0; 3])
    }

    fn force_in(&self, flow: &FluidKinematics, rdot: &[f64; 3]) -> PointForce {
        let rho = self.water.density;
        let v: [f64; 3] = std::array::from_fn(|i| flow.velocity[i] - rdot[i]);
        // q(k, v) = k |v| v and Q = dq/dv: the air drag's law with the
        // sign of a force along v.
        let (drag, q) = crate::loads::quadratic_drag(-0.5 * rho * self.drag_area, &v);
        let c = rho * self.volume * (1.0 + self.ca);
        let mut out = PointForce::default();
        for i in 0..3 {
            out.force[i] = drag[i] + c * flow.acceleration[i];
            for j in 0..3 {
                out.d_rdot[i][j] = -q[i][j];
                out.d_r[i][j] = (0..3)
                    .map(|l| q[i][l] * flow.velocity_gradient[l][j])
                    .sum::<f64>()
                    + c * flow.acceleration_gradient[i][j];
            }
        }
        out
    }
}

/// The largest differences between a point force's derivatives d_r and
/// d_rdot at (r, r_dot) and central differences of its force with step
/// h (a check of the exact derivatives, shared by the point forces'
/// tests).
#[cfg(test)]
pub(crate) fn derivative_errors(
    force: impl Fn(&[f64; 3], &[f64; 3]) -> PointForce,
    r: &[f64; 3],
    rdot: &[f64; 3],
    h: f64,
) -> (f64, f64) {
    let f = force(r, rdot);
    let (mut by_r, mut by_rdot) = (0.0f64, 0.0f64);
    for j in 0..3 {
        let (mut rp, mut rm, mut vp, mut vm) = (*r, *r, *rdot, *rdot);
        rp[j] += h;
        rm[j] -= h;
        vp[j] += h;
        vm[j] -= h;
        let (fr_p, fr_m) = (force(&rp, rdot).force, force(&rm, rdot).force);
        let (fv_p, fv_m) = (force(r, &vp).force, force(r, &vm).force);
        for i in 0..3 {
            let dr = (fr_p[i] - fr_m[i]) / (2.0 * h);
            let dv = (fv_p[i] - fv_m[i]) / (2.0 * h);
            by_r = by_r.max((dr - f.d_r[i][j]).abs());
            by_rdot = by_rdot.max((dv - f.d_rdot[i][j]).abs());
        }
    }
    (by_r, by_rdot)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::water::current::{CurrentProfile, CurrentRow, Ramp};
    use crate::water::kinematics::Sea;
    use crate::water::waves::AiryWave;

    fn buoy() -> PointInWater {
        let wave = AiryWave {
            amplitude: 1.0,
            period: 7.0,
            heading_deg: 25.0,
            phase_deg: 60.0,
        };
        let current = CurrentProfile::new(&[
            CurrentRow {
                z: -40.0,
                velocity: [0.1, 0.0, 0.0],
            },
            CurrentRow {
                z: 0.0,
                velocity: [0.8, 0.3, 0.0],
            },
        ])
        .unwrap();
        let sea = Sea::new(40.0, 9.81, &[wave])
            .unwrap()
            .with_current(current, Ramp::new(3.0).unwrap());
        PointInWater {
            water: Arc::new(Water {
                density: 1025.0,
                sea,
            }),
            volume: 0.4,
            drag_area: 0.6,
            ca: 0.8,
            host: None,
        }
    }

    #[test]
    fn a_point_s_water_force_derivatives_match_finite_differences() {
        let p = buoy();
        let (r, rdot, t) = ([3.0, -2.0, -6.0], [0.2, -0.5, 0.1], 2.0);
        let f = p.force(&r, &rdot, t);
        let scale = f.force.iter().map(|c| c.abs()).fold(1.0, f64::max);
        let (dr, dv) = super::derivative_errors(|r, v| p.force(r, v, t), &r, &rdot, 1e-6);
        assert!(dr < 1e-6 * scale, "d f / d r off by {dr}");
        assert!(dv < 1e-6 * scale, "d f / d rdot off by {dv}");
    }

    #[test]
    fn a_point_at_rest_in_a_current_feels_half_rho_cda_u_squared() {
        let mut p = buoy();
        p.water = Arc::new(Water {
            density: 1025.0,
            sea: Sea::still(40.0, 9.81).with_current(
                CurrentProfile::uniform([0.5, 0.0, 0.0]).unwrap(),
                Ramp::NONE,
            ),
        });
        let f = p.static_force(&[0.0, 0.0, -10.0]);
        let expected = 0.5 * 1025.0 * 0.6 * 0.25;
        assert!((f.force[0] - expected).abs() < 1e-12 * expected);
        assert_eq!(p.added_mass(), 0.8 * 1025.0 * 0.4);
        assert_eq!(p.buoyancy(&[0.0, 0.0, -9.81])[2], 1025.0 * 0.4 * 9.81);
    }
}
