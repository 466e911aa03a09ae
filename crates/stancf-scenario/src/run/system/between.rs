//! The writing of a system run at `output.interval`'s multiples, which
//! the steps need not land on (docs/method.md §6.5a, (M23d)): after each
//! run step, every output time it crossed is written from the recorded
//! steps' cubics, and the run's last moment where the interval does not
//! land on it.

use super::rows::{dynamic_row, interval_row};
use super::writers::SystemWriters;
use crate::scenario::EndForces;
use stancf::system::SystemSimulation;
use stancf::State;

/// The next output time and the lines' interpolated states (reused).
pub(super) struct Between {
    /// The run's start.
    t0: f64,
    interval: f64,
    /// The multiple of the interval written next.
    next: u64,
    states: Vec<State>,
}

impl Between {
    /// Turns on `sim`'s step records; the start (written before the
    /// steps) is the interval's 0th multiple.
    pub(super) fn new(sim: &mut SystemSimulation, interval: f64) -> std::io::Result<Self> {
        sim.record_steps(true)
            .map_err(|e| std::io::Error::other(e.to_string()))?;
        Ok(Between {
            t0: sim.time(),
            interval,
            next: 1,
            states: Vec::new(),
        })
    }

    /// The output time of multiple k, from the run's start.
    fn time(&self, k: u64) -> f64 {
        self.t0 + k as f64 * self.interval
    }

    /// Writes the state at every output time up to `sim`'s (a time within
    /// a millionth of the interval of the step's end counts as reached),
    /// and at the run's `last` moment if no output time lands on it.
    pub(super) fn write(
        &mut self,
        sim: &SystemSimulation,
        writers: &mut SystemWriters,
        last: bool,
    ) -> std::io::Result<()> {
        let end = sim.time();
        let slack = 1e-6 * self.interval;
        let mut landed = false;
        while self.time(self.next) <= end + slack {
            let t = self.time(self.next).min(end);
            landed = (t - end).abs() <= slack;
            let row = interval_row(sim, t, &mut self.states)
                .map_err(|e| std::io::Error::other(e.to_string()))?;
            writers.write_state(&row)?;
            self.next += 1;
        }
        if last && !landed {
            writers.write_state(&dynamic_row(sim, Some(EndForces::AtTime)))?;
        }
        Ok(())
    }
}
