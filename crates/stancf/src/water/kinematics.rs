//! The flow of the sea at a point: waves, current and their ramps
//! combined (docs/method.md §12.1, (W12)-(W13)).
//!
//! A [`Sea`] holds the depth, gravity, the regular waves (given one by
//! one or drawn from a JONSWAP spectrum, [`super::spectrum`]) with their
//! wave numbers solved once, an optional current profile, and a ramp for
//! each. [`Sea::kinematics`] evaluates them at a point and a time without
//! allocating: it runs at every Gauss point of every step.

use super::current::{CurrentProfile, Ramp};
use super::current_grid::CurrentGrid;
use super::waves::{AiryWave, SolvedWave, WaveFlow};
use crate::error::ModelError;

/// The water's motion at a point and time (z up, still water level z = 0).
///
/// `acceleration` is the local acceleration du/dt at the fixed point (the
/// convective part (u . grad) u follows from `velocity_gradient`);
/// gradients are `[i][j] = d(.)_i / d x_j`.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct FluidKinematics {
    /// Elevation of the free surface above (x, y) (m).
    pub eta: f64,
    pub velocity: [f64; 3],
    pub acceleration: [f64; 3],
    pub velocity_gradient: [[f64; 3]; 3],
    pub acceleration_gradient: [[f64; 3]; 3],
    /// The waves' dynamic pressure over the water's density (m^2/s^2)
    /// and its gradient (W8a); a current adds none (a current's ramp
    /// accelerates the water without a pressure here: its acceleration
    /// acts through Morison's inertia, not on a rod's caps).
    pub pressure: f64,
    pub pressure_gradient: [f64; 3],
}

/// The sea a line sees: flat seabed at z = -depth, gravity, waves,
/// current. Build it with [`Sea::new`] or [`Sea::still`], then add a
/// current and ramps.
#[derive(Clone, Debug, PartialEq)]
pub struct Sea {
    depth: f64,
    gravity: f64,
    waves: Vec<SolvedWave>,
    wave_ramp: Ramp,
    current: Option<CurrentProfile>,
    /// A current on a grid in space and time (W9a), the alternative to
    /// `current`: a sea has one current or none.
    current_grid: Option<CurrentGrid>,
    current_ramp: Ramp,
    /// The waves are a host's, set at the nodes while it steps the system
    /// (MoorDyn's `WaveKin 1`, (W2f)-(W2g), [`super::host_flow`]).
    host_waves: bool,
}

impl Sea {
    /// A sea of depth `depth` (m, positive) under gravity `gravity`
    /// (m/s^2, a positive magnitude; 0 allowed without waves) with the
    /// regular waves `waves` superposed, no current and no ramp. Refused,
    /// naming the quantity (`depth`, `gravity`, `waves[3].period`, ...): a
    /// depth not positive and finite, a gravity not so with waves, a wave
    /// with a period <= 0, an amplitude < 0, or a value that is not
    /// finite.
    pub fn new(depth: f64, gravity: f64, waves: &[AiryWave]) -> Result<Sea, ModelError> {
        if !(depth.is_finite() && depth > 0.0) {
            return Err(ModelError::invalid(
                "depth",
                format!("must be > 0 m and finite, got {depth}"),
            ));
        }
        // Waves need gravity (their dispersion, (W1)); still water or a
        // current may be without (MoorDyn's g = 0).
        let weightless = gravity == 0.0 && waves.is_empty();
        if !(weightless || (gravity.is_finite() && gravity > 0.0)) {
            return Err(ModelError::invalid(
                "gravity",
                format!("must be a positive magnitude (m/s^2) with waves, got {gravity}"),
            ));
        }
        let waves = waves
            .iter()
            .enumerate()
            .map(|(i, wave)| SolvedWave::new(wave, depth, gravity, &format!("waves[{i}]")))
            .collect::<Result<Vec<_>, _>>()?;
        Ok(Sea {
            depth,
            gravity,
            waves,
            wave_ramp: Ramp::NONE,
            current: None,
            current_grid: None,
            current_ramp: Ramp::NONE,
            host_waves: false,
        })
    }

    /// Still water of depth `depth` under gravity `gravity`: no waves, no
    /// current. Panics if depth or gravity is not positive and finite.
    pub fn still(depth: f64, gravity: f64) -> Sea {
        Sea::new(depth, gravity, &[]).expect("still water needs depth > 0 and gravity > 0")
    }

    /// The same sea with the waves started by `ramp` (W12).
    pub fn with_wave_ramp(mut self, ramp: Ramp) -> Sea {
        self.wave_ramp = ramp;
        self
    }

    /// The same sea with a current, started by `ramp` (W12); replaces any
    /// current it had.
    pub fn with_current(mut self, current: CurrentProfile, ramp: Ramp) -> Sea {
        self.current = Some(current);
        self.current_grid = None;
        self.current_ramp = ramp;
        self
    }

    /// The same sea with a current that varies in space and time (W9a),
    /// started by `ramp` (W12); replaces any current it had.
    pub fn with_current_grid(mut self, current: CurrentGrid, ramp: Ramp) -> Sea {
        self.current_grid = Some(current);
        self.current = None;
        self.current_ramp = ramp;
        self
    }

    /// The same sea with its waves left to a host, which sets the water's
    /// velocity and acceleration at the system's nodes while it steps it
    /// (MoorDyn's `WaveKin 1`; docs/method.md §12.1, (W2f)-(W2g)). Refused
    /// for a sea with waves of its own (`waves`).
    pub fn with_host_waves(mut self) -> Result<Sea, ModelError> {
        if !self.waves.is_empty() {
            return Err(ModelError::invalid(
                "waves",
                "a sea whose waves a host sets has no waves of its own".to_string(),
            ));
        }
        self.host_waves = true;
        Ok(self)
    }

    /// Whether a host sets the waves ([`Self::with_host_waves`]).
    pub fn host_waves(&self) -> bool {
        self.host_waves
    }

    pub fn current_grid(&self) -> Option<&CurrentGrid> {
        self.current_grid.as_ref()
    }

    pub fn depth(&self) -> f64 {
        self.depth
    }

    pub fn gravity(&self) -> f64 {
        self.gravity
    }

    /// The waves with their solved wave numbers.
    pub fn waves(&self) -> &[SolvedWave] {
        &self.waves
    }

    pub fn current(&self) -> Option<&CurrentProfile> {
        self.current.as_ref()
    }

    /// The flow at `position` and time t: the waves' flows (W4)-(W8)
    /// summed and ramped by r_w (W12), plus the current (W9)-(W10) ramped
    /// by r_c:
    ///
    /// ```text
    /// u = r_w sum_i u_i + r_c U(z),  eta = r_w sum_i eta_i           (W13)
    /// ```
    ///
    /// A ramp r(t) (W11) multiplies a velocity field u(x, t) into r u, so
    /// the local acceleration stays the time derivative of the velocity:
    ///
    /// ```text
    /// u_r = r u,  a_r = d(r u)/dt = r a + r' u,  eta_r = r eta
    /// grad u_r = r grad u,  grad a_r = r grad a + r' grad u         (W12)
    /// ```
    ///
    /// The ramped waves' dynamic pressure is -rho d(r Phi)/dt, so that
    /// -grad p_r / rho stays the ramped local acceleration a_r:
    ///
    /// ```text
    /// p_r / rho = r p_d / rho - r' Phi,  grad p_r / rho = r grad p_d / rho - r' u   (W12a)
    /// ```
    ///
    /// A current U(z) is steady, so it contributes r_c U to the velocity,
    /// r_c' U to the acceleration and (r_c dU/dz, r_c' dU/dz) to the z
    /// column of the gradients.
    pub fn kinematics(&self, position: &[f64; 3], t: f64) -> FluidKinematics {
        if self.waves.is_empty() && self.current.is_none() && self.current_grid.is_none() {
            // Still water: every term below is zero.
            return FluidKinematics::default();
        }
        let mut flow = WaveFlow::default();
        for wave in &self.waves {
            wave.add_flow(position, t, &mut flow);
        }
        let (r, r_rate) = self.wave_ramp.factor_and_rate(t);
        let mut out = FluidKinematics {
            eta: r * flow.eta,
            pressure: r * flow.pressure - r_rate * flow.potential,
            pressure_gradient: std::array::from_fn(|i| {
                r * flow.pressure_gradient[i] - r_rate * flow.velocity[i]
            }),
            ..FluidKinematics::default()
        };
        for i in 0..3 {
            out.velocity[i] = r * flow.velocity[i];
            out.acceleration[i] = r * flow.acceleration[i] + r_rate * flow.velocity[i];
            for j in 0..3 {
                out.velocity_gradient[i][j] = r * flow.velocity_gradient[i][j];
                out.acceleration_gradient[i][j] =
                    r * flow.acceleration_gradient[i][j] + r_rate * flow.velocity_gradient[i][j];
            }
        }
        if let Some(current) = &self.current {
            let (rc, rc_rate) = self.current_ramp.factor_and_rate(t);
            let (u, dudz) = current.velocity_and_derivative(position[2]);
            for i in 0..3 {
                out.velocity[i] += rc * u[i];
                out.acceleration[i] += rc_rate * u[i];
                out.velocity_gradient[i][2] += rc * dudz[i];
                out.acceleration_gradient[i][2] += rc_rate * dudz[i];
            }
        }
        if let Some(grid) = &self.current_grid {
            let (rc, rc_rate) = self.current_ramp.factor_and_rate(t);
            let c = grid.sample(position, t);
            for i in 0..3 {
                out.velocity[i] += rc * c.velocity[i];
                out.acceleration[i] += rc * c.acceleration[i] + rc_rate * c.velocity[i];
                for j in 0..3 {
                    out.velocity_gradient[i][j] += rc * c.velocity_gradient[i][j];
                    out.acceleration_gradient[i][j] +=
                        rc * c.acceleration_gradient[i][j] + rc_rate * c.velocity_gradient[i][j];
                }
            }
        }
        out
    }

    /// The steady current at `position` at full strength (its ramp
    /// ignored) and nothing else: the flow of statics (docs/method.md
    /// §12.4); a current on a grid in time as it is at t = 0, without
    /// its acceleration. Still water without a current.
    pub fn steady_current(&self, position: &[f64; 3]) -> FluidKinematics {
        let mut out = FluidKinematics::default();
        if let Some(current) = &self.current {
            let (u, dudz) = current.velocity_and_derivative(position[2]);
            for i in 0..3 {
                out.velocity[i] = u[i];
                out.velocity_gradient[i][2] = dudz[i];
            }
        }
        if let Some(grid) = &self.current_grid {
            let c = grid.sample(position, 0.0);
            out.velocity = c.velocity;
            out.velocity_gradient = c.velocity_gradient;
        }
        out
    }
}

#[cfg(test)]
#[path = "kinematics_tests.rs"]
mod tests;
