//! The second paths of a system's static solve (docs/method.md §11.6,
//! §12.2): a line without compression that the path leaves shortened is
//! solved again with its own law (M32c), and with `pulled` seabed
//! friction every anchored line is pulled along its bed from the
//! equilibrium as laid (W49). What the bed holds at the end.

use super::static_friction::{self, StaticFriction};
use super::statics::{SystemStatics, KEPT_SHORTENING};
use crate::error::{SolverError, STATIC_SOLVE};
use crate::statics::StaticIncrement;
use std::ops::ControlFlow;

impl SystemStatics {
    /// The second stage of [`StaticFriction::Pulled`], once the first (as
    /// laid) has converged: the path from its equilibrium with each
    /// anchored line's friction targets where its unstretched resting
    /// part lay (W49) and the friction on. None when there is nothing to
    /// pull: another policy, the second stage done, or no line anchored
    /// on a bed with friction.
    pub(super) fn pull(&self) -> Result<Option<SystemStatics>, SolverError> {
        if self.friction != StaticFriction::Pulled || self.pulling {
            return Ok(None);
        }
        let system = &self.equations.system;
        let states = self.line_states();
        let targets: Vec<Option<Vec<f64>>> = system
            .lines()
            .iter()
            .zip(&states)
            .map(|(line, state)| {
                static_friction::has_friction(&line.model)
                    .then(|| static_friction::pulled_targets(&line.model, &state.e))
                    .flatten()
            })
            .collect();
        if targets.iter().all(Option::is_none) {
            return Ok(None);
        }
        let targets = targets
            .into_iter()
            .zip(&states)
            .map(|(t, s)| t.unwrap_or_else(|| s.e.clone()))
            .collect();
        let (settings, own_law) = (self.settings.clone(), self.own_law.clone());
        let stage =
            Self::build(system.clone(), states, settings, own_law, Some(targets)).map_err(|e| {
                SolverError {
                    kind: crate::error::FailureKind::PathStalled,
                    time: 1.0,
                    step: 0,
                    residual: f64::NAN,
                    iterations: 0,
                    detail: format!(
                        "{}: the pull along the bed from the equilibrium as laid: {e}",
                        crate::error::STATIC_SOLVE
                    ),
                }
            })?;
        Ok(Some(stage))
    }

    /// What the seabed exerts on line i's nodes at the last converged
    /// increment: the consistent nodal forces of the contact with its
    /// static friction against the slide from the friction's targets
    /// (W48; [`crate::observe::static_seabed_nodal_forces`]).
    pub fn seabed_nodal_forces(&self, line: usize) -> Vec<[f64; 3]> {
        let l = &self.equations.lines[line];
        crate::observe::static_seabed_nodal_forces(&l.model, &l.state, l.friction_targets())
    }

    /// What the seabed's friction holds in this solve.
    pub fn seabed_friction(&self) -> StaticFriction {
        self.friction
    }

    /// At the end of the path (M32): the lines without compression it
    /// shortens by more than [`KEPT_SHORTENING`] carry compression there,
    /// which their law (M4a) does not. The path is then followed again
    /// from the same seeds with those lines' own law (docs/method.md
    /// §11.6, (M32c)), and its end replaces this one if it is reached and
    /// isolated: its Jacobian regular (a line slack at zero tension along
    /// its whole length has no stiffness against shortening, and its
    /// equilibria under (M4a) are a continuum, of which the first path's
    /// end is one). False if the observer stopped the second path (this
    /// end is kept).
    pub(super) fn release<F>(&mut self, observer: &mut F) -> bool
    where
        F: FnMut(&SystemStatics, &StaticIncrement) -> ControlFlow<()>,
    {
        if !std::mem::take(&mut self.check_compression) {
            return true;
        }
        let own_law = self.shortened_without_compression();
        if !own_law.iter().any(|&o| o) {
            return true;
        }
        match self.own_law_path(own_law, observer) {
            OwnLawPath::Stopped => false,
            OwnLawPath::Done(second) => {
                *self = *second;
                true
            }
            OwnLawPath::Failed | OwnLawPath::Singular => true,
        }
    }

    /// Where the path fails and a line without compression is solved
    /// with its compressive stiffness kept: the path again from the same
    /// seeds with every such line's own law (M4a) (docs/method.md §11.6,
    /// (M32c)), kept if it reaches the end and its equilibrium is
    /// isolated. Measured: MoorDyn's MHK_RM1_Floating deck (six slack
    /// chains of 152 and 160 m to fairlead 40 m up and 118 to 128 m away,
    /// 30 elements each) stalls at load factor 0.41 with the compression
    /// kept and reaches its equilibrium this way. Ok(true): `self` is that
    /// path, at its end; Ok(false): the observer stopped it; Err(()):
    /// there is no such path, or it failed too.
    pub(super) fn own_law_after_failure<F>(&mut self, observer: &mut F) -> Result<bool, ()>
    where
        F: FnMut(&SystemStatics, &StaticIncrement) -> ControlFlow<()>,
    {
        if self.own_law.iter().any(|&o| o) {
            return Err(());
        }
        let own_law: Vec<bool> = self
            .equations
            .system
            .lines()
            .iter()
            .map(|l| !l.model.carries_compression())
            .collect();
        if !own_law.iter().any(|&o| o) {
            return Err(());
        }
        match self.own_law_path(own_law, observer) {
            OwnLawPath::Stopped => Ok(false),
            OwnLawPath::Done(second) => {
                *self = *second;
                Ok(true)
            }
            OwnLawPath::Failed | OwnLawPath::Singular => Err(()),
        }
    }

    /// Where every load path failed with `error`: the equilibrium at the
    /// full load by pseudo-transient continuation from this path's seeds
    /// (docs/method.md §6.9, (M26b)), which the observer sees as one
    /// increment. Ok(true): `self` is that solve, converged; Ok(false):
    /// the observer stopped it; Err: the path's error, followed by where
    /// the continuation stopped.
    pub(super) fn relax_after_failure<F>(
        &mut self,
        error: SolverError,
        observer: &mut F,
    ) -> Result<bool, SolverError>
    where
        F: FnMut(&SystemStatics, &StaticIncrement) -> ControlFlow<()>,
    {
        if self.relaxed {
            return Err(error);
        }
        let (system, seeds) = (self.equations.system.clone(), self.seeds.clone());
        let (settings, targets) = (self.settings.clone(), self.targets.clone());
        let own_law = self.own_law.clone();
        let Ok(mut relaxed) = Self::build(system, seeds, settings, own_law, targets) else {
            return Err(error);
        };
        relaxed.relaxed = true;
        relaxed.pulling = self.pulling;
        match relaxed.newton.relax(&mut relaxed.equations) {
            Ok(increment) => {
                let go_on = observer(&relaxed, &increment).is_continue();
                *self = relaxed;
                Ok(go_on && self.release_by_flow(observer))
            }
            Err(stopped) => {
                let then = stopped.detail.trim_start_matches(STATIC_SOLVE);
                Err(SolverError {
                    detail: format!("{}; then{}", error.detail, then.trim_start_matches(':')),
                    ..error
                })
            }
        }
    }

    /// Which lines are without compression and left shortened by more
    /// than [`KEPT_SHORTENING`] at the last converged increment (their
    /// compressive stiffness kept): those to solve again with their own
    /// law (M4a), (M32c).
    fn shortened_without_compression(&self) -> Vec<bool> {
        let eq = &self.equations;
        (0..eq.lines.len())
            .map(|i| {
                let own = &eq.system.lines()[i].model;
                !own.carries_compression()
                    && crate::observe::largest_shortening(own, &eq.lines[i].state) > KEPT_SHORTENING
            })
            .collect()
    }

    /// At the flow's end (M26b): the lines without compression that it
    /// leaves shortened by more than [`KEPT_SHORTENING`] are given their
    /// own law (M4a) and the flow is followed on from this equilibrium
    /// (the system at it, the lines' states its seeds), as the path is
    /// followed again in (M32c); its end replaces this one if it is
    /// reached and isolated. False if the observer stopped it.
    fn release_by_flow<F>(&mut self, observer: &mut F) -> bool
    where
        F: FnMut(&SystemStatics, &StaticIncrement) -> ControlFlow<()>,
    {
        let own_law = self.shortened_without_compression();
        if !own_law.iter().any(|&o| o) {
            return true;
        }
        let (settings, targets) = (self.settings.clone(), self.targets.clone());
        let system = self.system_at_equilibrium();
        let Ok(mut released) = Self::build(system, self.line_states(), settings, own_law, targets)
        else {
            return true;
        };
        released.relaxed = true;
        released.pulling = self.pulling;
        let Ok(increment) = released.newton.relax(&mut released.equations) else {
            return true;
        };
        if !released.newton.regular_at(&mut released.equations) {
            return true;
        }
        let go_on = observer(&released, &increment).is_continue();
        *self = released;
        go_on
    }

    /// Whether this equilibrium was reached by pseudo-transient
    /// continuation (docs/method.md §6.9, (M26b)): every load path from
    /// the seeds failed, or the path's end was unstable at a body
    /// (M26c).
    pub fn relaxed(&self) -> bool {
        self.relaxed
    }

    /// The path from this one's seeds with the lines marked in `own_law`
    /// solved with their own law (M4a), followed to its end (the observer
    /// sees its increments), and whether its end is an isolated
    /// equilibrium: its Jacobian regular (a line slack at zero tension
    /// along its whole length has no stiffness against shortening, and
    /// its equilibria under (M4a) are a continuum).
    fn own_law_path<F>(&self, own_law: Vec<bool>, observer: &mut F) -> OwnLawPath
    where
        F: FnMut(&SystemStatics, &StaticIncrement) -> ControlFlow<()>,
    {
        let (system, seeds) = (self.equations.system.clone(), self.seeds.clone());
        let (settings, targets) = (self.settings.clone(), self.targets.clone());
        let Ok(mut second) = Self::build(system, seeds, settings, own_law, targets) else {
            return OwnLawPath::Failed;
        };
        loop {
            match second.newton.advance(&mut second.equations) {
                Ok(Some(inc)) => {
                    if observer(&second, &inc).is_break() {
                        return OwnLawPath::Stopped;
                    }
                }
                Ok(None) => break,
                Err(_) => return OwnLawPath::Failed,
            }
        }
        if second.newton.regular_at(&mut second.equations) {
            OwnLawPath::Done(Box::new(second))
        } else {
            OwnLawPath::Singular
        }
    }
}

/// How a path with lines solved with their own law (M4a) ended.
enum OwnLawPath {
    /// The observer stopped it.
    Stopped,
    /// It failed, or could not be built.
    Failed,
    /// It ended at an equilibrium that is not isolated.
    Singular,
    /// It ended at an isolated equilibrium.
    Done(Box<SystemStatics>),
}
