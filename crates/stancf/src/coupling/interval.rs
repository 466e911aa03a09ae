//! A coupling interval (docs/method.md §13.3): the coupled points and
//! bodies moved along the host's motion (K1)-(K2), the interval split
//! into equal steps, the lines' forces and the held bodies' own push
//! (§15.18) averaged over it.

use super::bodies::ArrayLayout;
use super::{
    held_loads, not_initialized, triple, CoupledForces, CoupledSystem, CouplingError, Running,
};
use crate::error::{FailureKind, SolverError};
use crate::motion::{CoupledMotion, MotionInterval};
use crate::system::{Stepper, SystemSimulation};

impl CoupledSystem {
    /// Advances to `t_next` with the coupled points moving from where the
    /// last call put them to `x` (3 per point): along the cubic (K2) with
    /// the velocities given or, without them, estimated from the host's
    /// positions (K2a) (along the line (K1) in the first interval of a
    /// start without velocities). The interval is split into the fewest
    /// equal steps no longer than the scenario's (§13.3), or, with a
    /// tolerance ([`Self::with_force_tolerance`]), crossed in the steps it
    /// chooses (M23c); an interval of more steps of the scenario's length
    /// than [`Self::max_interval_steps`] is refused before anything moves. On a
    /// solver failure the state stays at the last converged step, with
    /// the coupled points on this interval's motion, so a later call
    /// continues from there.
    pub fn step_to(
        &mut self,
        t_next: f64,
        x: &[f64],
        xd: Option<&[f64]>,
    ) -> Result<CoupledForces, CouplingError> {
        self.step_to_with(t_next, x, xd, &mut || false)
    }

    /// [`Self::step_to`], asking `stop` between two internal steps (after
    /// each but the last): when it says true, the call ends with
    /// [`CouplingError::Interrupted`] and the state is left as after a
    /// solver failure (at the last converged step, at least one step after
    /// the time reached and before `t_next`, the coupled points on this
    /// interval's motion), so a later call continues from there.
    pub fn step_to_with(
        &mut self,
        t_next: f64,
        x: &[f64],
        xd: Option<&[f64]>,
        stop: &mut dyn FnMut() -> bool,
    ) -> Result<CoupledForces, CouplingError> {
        let (steps, h) = self.interval(t_next, x, xd)?;
        let rates = self.call_rates(t_next, x, xd);
        let xd = rates.as_deref();
        let coupled = self.coupled.clone();
        let layout = self.layout.clone();
        let n = coupled.len();
        let end = layout.positions(x, n);
        let end_rate = xd.map(|v| layout.velocities(x, v, n));
        let running = self.running.as_mut().ok_or_else(not_initialized)?;
        let t0 = running.sim.time();
        let span = steps as f64 * h;
        let references = running.move_on(
            (&coupled, &layout),
            (t0, span),
            (&end, end_rate.as_deref()),
            (x, xd),
        )?;
        // The coupled bodies' own parts on the host's motion (§15.18).
        let held_end: Vec<_> = (0..layout.bodies.len())
            .map(|b| layout.held_end(x, xd, b))
            .collect();
        let paths = running.held_paths(&layout, &held_end, (t0, span));
        // The lines' forces on the coupling arrays, the mean over the
        // last step of `h` (with the held bodies' own push over it).
        let loads = |sim: &SystemSimulation, h: f64| {
            let mut out = layout.forces(
                |k| sim.point_force(coupled[k]),
                |k| sim.point_state(coupled[k]).0,
                |b| references[b].state(sim.time()).0,
            );
            let topology = sim.topology();
            for (k, path) in paths.iter().enumerate() {
                if let Some(path) = path {
                    let body = &topology.bodies()[layout.bodies[k].body];
                    let t_a = sim.time() - h;
                    let push = held_loads::mean_push(body, topology.gravity(), path, t_a, h);
                    layout.add_push(&mut out, k, &push);
                }
            }
            out
        };
        let mut impulse = vec![0.0; x.len()];
        let mut last_step = Vec::new();
        let mut taken = 0;
        let mut book = |f: Vec<f64>, h: f64| {
            for (i, v) in f.iter().enumerate() {
                impulse[i] += v * h;
            }
            last_step = f;
            taken += 1;
        };
        let stepped = match self.control {
            None => fixed_steps(
                &mut running.sim,
                &mut running.watch,
                (steps, h),
                stop,
                &mut |sim| book(loads(sim, h), h),
            ),
            Some(control) => {
                let big = self.steps.time_step;
                let next = running.next_step.unwrap_or(big);
                let mut stepper = Stepper::resume(control, big, next, running.watch.clone());
                let result = controlled_steps(
                    &mut running.sim,
                    &mut stepper,
                    (t0 + span, self.max_interval_steps),
                    stop,
                    &mut |sim, h| (loads(sim, h), h),
                    &mut |kept| {
                        for (f, h) in kept {
                            book(f, h);
                        }
                    },
                );
                // The simulation keeps the last half step's length: set
                // back to h, its factors would be dropped for nothing.
                let (next, watch) = stepper.into_parts();
                running.next_step = Some(next);
                running.watch = watch;
                result
            }
        };
        if let Err(e) = stepped {
            running.stop_on_motion(&coupled, &references);
            running.stop_held(&paths);
            return Err(e);
        }
        running.position = end;
        running.velocity = end_rate;
        running.held = held_end;
        running.reference = (0..layout.bodies.len())
            .map(|b| layout.reference(x, b))
            .collect();
        running.reference_rate = xd.map(|v| {
            (0..layout.bodies.len())
                .map(|b| layout.reference(v, b))
                .collect()
        });
        Ok(CoupledForces {
            last_step,
            interval_mean: impulse.iter().map(|i| i / span).collect(),
            steps: taken,
        })
    }
}

/// The interval's `steps` equal steps of `h`, `book` called after each;
/// `stop` asked after each but the last.
fn fixed_steps(
    sim: &mut SystemSimulation,
    watch: &mut crate::integrator::EnergyWatch,
    (steps, h): (usize, f64),
    stop: &mut dyn FnMut() -> bool,
    book: &mut dyn FnMut(&SystemSimulation),
) -> Result<(), CouplingError> {
    sim.set_time_step(h);
    for taken in 1..=steps {
        let halvings = sim.step_halvings();
        crate::system::watched_step(sim, watch, halvings)?;
        book(sim);
        if taken < steps && stop() {
            return Err(CouplingError::Interrupted { time: sim.time() });
        }
    }
    Ok(())
}

/// Steps chosen by the tolerance (docs/method.md (M23c)) to `end`, each
/// kept step taken as two halves: `half` gives what a half step leaves
/// for the interval, `book` takes a kept step's two; `stop` asked after
/// each kept step but the last. More than `most` half steps fail the
/// call (the bound on one call's internal steps, §13.3).
fn controlled_steps<T>(
    sim: &mut SystemSimulation,
    stepper: &mut Stepper,
    (end, most): (f64, usize),
    stop: &mut dyn FnMut() -> bool,
    half: &mut dyn FnMut(&SystemSimulation, f64) -> T,
    book: &mut dyn FnMut([T; 2]),
) -> Result<(), CouplingError> {
    let mut taken = 0;
    loop {
        let kept = stepper.advance(sim, end, half)?;
        book(kept.halves);
        taken += 2;
        if stepper.reached(sim, end) {
            return Ok(());
        }
        if taken >= most {
            return Err(CouplingError::Solver(SolverError {
                kind: FailureKind::NotConverged,
                time: sim.time(),
                step: kept.report.step,
                residual: kept.report.newton.residual,
                iterations: kept.report.newton.iterations,
                detail: format!(
                    "the force tolerance took {taken} internal steps, the most one call may \
                     take (max_interval_steps), and {:.6e} s of the interval are left; \
                     loosen the tolerance, couple more often or raise the bound",
                    end - sim.time()
                ),
            }));
        }
        if stop() {
            return Err(CouplingError::Interrupted { time: sim.time() });
        }
    }
}

impl Running {
    /// The coupled bodies' paths from their last poses to `held_end` over
    /// `(t0, span)`, for those whose own parts carry loads (§15.18).
    fn held_paths(
        &self,
        layout: &ArrayLayout,
        held_end: &[Option<held_loads::HeldEnd>],
        (t0, span): (f64, f64),
    ) -> Vec<Option<held_loads::HeldPath>> {
        (0..layout.bodies.len())
            .map(|k| {
                let body = &self.sim.topology().bodies()[layout.bodies[k].body];
                match (&self.held[k], &held_end[k]) {
                    (Some(a), Some(b)) if held_loads::carries_loads(body) => {
                        Some(held_loads::HeldPath::new(t0, span, a, b))
                    }
                    _ => None,
                }
            })
            .collect()
    }

    /// Puts the coupled points on the interval's motion from where the
    /// last call left them to `end` (with the rates `end_rate`, where
    /// both calls gave them) over `(t0, span)`, (K2); the coupled bodies'
    /// reference points on the same motion (the moments' arms), returned.
    fn move_on(
        &mut self,
        (coupled, layout): (&[usize], &ArrayLayout),
        (t0, span): (f64, f64),
        (end, end_rate): (&[f64], Option<&[f64]>),
        (x, xd): (&[f64], Option<&[f64]>),
    ) -> Result<Vec<MotionInterval>, CouplingError> {
        let rates = match (&self.velocity, end_rate) {
            (Some(v0), Some(v1)) => Some((v0.as_slice(), v1)),
            _ => None,
        };
        for (k, &p) in coupled.iter().enumerate() {
            let interval = MotionInterval {
                t0,
                duration: span,
                start: triple(&self.position, k),
                end: triple(end, k),
                rates: rates.map(|(a, b)| (triple(a, k), triple(b, k))),
            };
            self.sim
                .set_point_motion(p, CoupledMotion::Interval(interval))?;
        }
        Ok((0..layout.bodies.len())
            .map(|b| MotionInterval {
                t0,
                duration: span,
                start: self.reference[b],
                end: layout.reference(x, b),
                rates: match (&self.reference_rate, xd) {
                    (Some(r0), Some(v)) => Some((r0[b], layout.reference(v, b))),
                    _ => None,
                },
            })
            .collect())
    }

    /// After a failed or stopped step: the held bodies' poses (and rates,
    /// where the last call had them) where their paths have them at the
    /// time reached.
    fn stop_held(&mut self, paths: &[Option<held_loads::HeldPath>]) {
        let t = self.sim.time();
        for (end, path) in self.held.iter_mut().zip(paths) {
            if let (Some(end), Some(path)) = (end.as_mut(), path) {
                let m = path.at(t);
                end.position = m.position;
                end.rotation = m.rotation;
                end.rates = end.rates.map(|_| (m.velocity, m.angular_velocity));
            }
        }
    }

    /// After a failed or stopped step: the coupled points' last positions and
    /// velocities become where their interval's motion has them at the
    /// time reached, so the next interval starts from there.
    fn stop_on_motion(&mut self, coupled: &[usize], references: &[MotionInterval]) {
        let t = self.sim.time();
        let mut velocity = vec![0.0; self.position.len()];
        for (k, &p) in coupled.iter().enumerate() {
            let (r, v) = self.sim.topology().points()[p].state_at(t);
            self.position[3 * k..3 * k + 3].copy_from_slice(&r);
            velocity[3 * k..3 * k + 3].copy_from_slice(&v);
        }
        self.velocity = self.velocity.is_some().then_some(velocity);
        let states: Vec<_> = references.iter().map(|m| m.state(t)).collect();
        self.reference = states.iter().map(|s| s.0).collect();
        if self.reference_rate.is_some() {
            self.reference_rate = Some(states.iter().map(|s| s.1).collect());
        }
    }
}
