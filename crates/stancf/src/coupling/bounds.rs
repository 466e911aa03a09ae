//! What a coupling code may give a [`CoupledSystem`] (docs/method.md
//! §13.3): arrays of `coupled_dof` finite values, positions within
//! [`MAX_COUPLED_COORDINATE`] of the origin, velocities and mean speeds
//! over an interval up to [`MAX_COUPLED_SPEED`], a next time after the
//! time reached, and intervals of at most the handle's bound on internal
//! steps ([`MAX_INTERVAL_STEPS`] unless set). Each is checked before
//! anything moves.

use super::{not_initialized, triple, CoupledSystem, CouplingError};
use crate::error::{ModelError, Sig};
use crate::integrator::step_count;

/// The most internal steps one coupling call takes unless the handle is
/// told otherwise ([`CoupledSystem::set_max_interval_steps`]). A coupling
/// interval is typically 0.01 to 1 s and a line's time step 1e-4 to
/// 1e-2 s, so an interval takes a few thousand steps at most; 100 000 is
/// 10 times the longest of these (a 10 s interval at 1e-4 s), and at
/// the 0.1 to 10 ms a step of a mooring system takes, seconds to
/// minutes of work. An interval asking for more is a mistake of units or
/// of the time step (dt 1e6 s, a deck's dtM 1e-7 s) that would otherwise
/// hold the host's call for hours with no way to stop it from C.
pub const MAX_INTERVAL_STEPS: usize = 100_000;

/// The farthest a coupled point may be from the origin (m), in any
/// coordinate: ten thousand kilometres, beyond any mooring's frame.
pub const MAX_COUPLED_COORDINATE: f64 = 1e7;

/// The fastest a coupled point may move over a coupling interval, and
/// the largest velocity a coupling code may give one (m/s): a
/// fairlead of a floating platform in a storm moves a few m/s, a towed
/// body or a cable robot's winch tens; 100 m/s is no mooring's motion.
pub const MAX_COUPLED_SPEED: f64 = 100.0;

/// The steps of a coupling interval of `length` (§13.3): the fewest equal
/// steps no longer than `dt` (with 1e-9 of slack, so an interval of a
/// whole number of steps takes exactly `dt`, to the bit, as a run does).
pub fn interval_steps(length: f64, dt: f64) -> (usize, f64) {
    let n = step_count(length, dt);
    let h = length / n as f64;
    (n, if (h - dt).abs() <= 1e-9 * dt { dt } else { h })
}

impl CoupledSystem {
    /// The steps of the interval from the time reached to `t_next` and
    /// their length, the arguments of a [`Self::step_to`] checked; nothing
    /// is changed.
    pub(super) fn interval(
        &self,
        t_next: f64,
        x: &[f64],
        xd: Option<&[f64]>,
    ) -> Result<(usize, f64), CouplingError> {
        self.check_values("x", x)?;
        if let Some(v) = xd {
            self.check_values("xd", v)?;
        }
        let dt = self.steps.time_step;
        let t0 = self
            .running
            .as_ref()
            .ok_or_else(not_initialized)?
            .sim
            .time();
        let length = t_next - t0;
        if !t_next.is_finite() || length <= 0.0 {
            return Err(ModelError::invalid(
                "t",
                format!(
                    "the next time {} s must come after the time reached, {} s",
                    Sig(t_next),
                    Sig(t0)
                ),
            )
            .into());
        }
        if length <= 1e-9 * dt {
            return Err(ModelError::invalid(
                "t",
                format!(
                    "an interval of {} s from {} s is shorter than 1e-9 of the time step, {} \
                     s: too short to step (a time in another unit?)",
                    Sig(length),
                    Sig(t0),
                    Sig(dt)
                ),
            )
            .into());
        }
        self.check_speeds(x, length)?;
        let (steps, h) = interval_steps(length, dt);
        if steps > self.max_interval_steps {
            return Err(ModelError::invalid(
                "t",
                format!(
                    "the interval of {} s from {} s to {} s takes {steps} steps of at most \
                     the time step, {} s: more than the {} one call may take; step in \
                     shorter intervals, or raise the bound (Rust \
                     CoupledSystem::set_max_interval_steps, C stancf_set_max_interval_steps, \
                     Python Simulation.max_interval_steps)",
                    Sig(length),
                    Sig(t0),
                    Sig(t_next),
                    Sig(dt),
                    self.max_interval_steps
                ),
            )
            .into());
        }
        Ok((steps, h))
    }

    /// The coupled points' mean speeds over an interval of `length` to
    /// `x`, each at most [`MAX_COUPLED_SPEED`]: a point moved faster was
    /// given a wrong position (another unit, another frame, a swapped
    /// array), not a motion.
    pub(super) fn check_speeds(&self, x: &[f64], length: f64) -> Result<(), ModelError> {
        let Some(running) = self.running.as_ref() else {
            return Ok(());
        };
        let to_all = self.layout.positions(x, self.coupled.len());
        for (k, &p) in self.coupled.iter().enumerate() {
            let from = triple(&running.position, k);
            let to = triple(&to_all, k);
            let jump =
                ((to[0] - from[0]).powi(2) + (to[1] - from[1]).powi(2) + (to[2] - from[2]).powi(2))
                    .sqrt();
            let speed = jump / length;
            if speed > MAX_COUPLED_SPEED {
                let (start, count) = self.layout.array_range(k);
                return Err(ModelError::invalid(
                    format!("x[{}..{}]", start, start + count),
                    format!(
                        "coupled point {k} (point index {p}) would move {} m in {} s, a mean \
                         speed of {} m/s, above the {MAX_COUPLED_SPEED} m/s a coupled point \
                         may move (a wrong position: another unit or frame?); the system is \
                         untouched",
                        Sig(jump),
                        Sig(length),
                        Sig(speed)
                    ),
                ));
            }
        }
        Ok(())
    }

    /// Why an array of `got` values is not a coupling array. MoorDyn-C
    /// 2.7's `NCoupledDOF` counts 6 per CoupledPinned body, but its `Init`,
    /// `Step` and `GetForces` read and write 3 per such body, in this order,
    /// and leave the last 3 per body of an array of that length unread (a
    /// host that laid out 6 per body, as the count suggests, would give
    /// MoorDyn a point's coordinates from the body's angles). An array of
    /// MoorDyn's count is refused by name: which layout the host meant is
    /// not for stancf to guess.
    fn length_message(&self, got: usize) -> String {
        let n = self.coupled_dof();
        let pinned = self
            .layout
            .bodies
            .iter()
            .filter(|b| b.pin.is_some())
            .count();
        let layout = "coupled_dof: 6 per coupled body, 3 per body pinned to the host \
                      (CoupledPinned), 3 per coupled point";
        if pinned > 0 && got == n + 3 * pinned {
            return format!(
                "expected {n} values ({layout}), got {got}: MoorDyn-C's NCoupledDOF counts 6 \
                 per CoupledPinned body ({got} here) but its Init, Step and GetForces read 3 \
                 per such body, these {n} in this order, and leave the last {} unread; give \
                 the {n} values",
                3 * pinned
            );
        }
        format!("expected {n} values ({layout}), got {got}")
    }

    /// A coupling array: `coupled_dof` finite values; positions (`x`)
    /// within [`MAX_COUPLED_COORDINATE`] of the origin, velocities (`xd`)
    /// of speeds up to [`MAX_COUPLED_SPEED`].
    pub(super) fn check_values(&self, key: &str, values: &[f64]) -> Result<(), ModelError> {
        if values.len() != self.coupled_dof() {
            return Err(ModelError::invalid(key, self.length_message(values.len())));
        }
        if let Some(i) = values.iter().position(|v| !v.is_finite()) {
            return Err(ModelError::invalid(
                format!("{key}[{i}]"),
                format!("must be finite, got {}", values[i]),
            ));
        }
        if key == "xd" {
            // Velocities: each point's speed within the bound.
            for k in 0..values.len() / 3 {
                let speed = values[3 * k..3 * k + 3]
                    .iter()
                    .map(|v| v * v)
                    .sum::<f64>()
                    .sqrt();
                if speed > MAX_COUPLED_SPEED {
                    return Err(ModelError::invalid(
                        format!("xd[{}..{}]", 3 * k, 3 * k + 3),
                        format!(
                            "coupled point {k} is given a speed of {} m/s, above the \
                             {MAX_COUPLED_SPEED} m/s a coupled point may move (a wrong \
                             velocity: another unit or frame?); the system is untouched",
                            Sig(speed)
                        ),
                    ));
                }
            }
        } else if let Some(i) = values.iter().position(|v| v.abs() > MAX_COUPLED_COORDINATE) {
            return Err(ModelError::invalid(
                format!("{key}[{i}]"),
                format!(
                    "{} m is farther from the origin than the {MAX_COUPLED_COORDINATE:e} m a \
                     coupled point may be (a wrong position: another unit or frame?); the \
                     system is untouched",
                    Sig(values[i])
                ),
            ));
        }
        Ok(())
    }
}
