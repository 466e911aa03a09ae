//! Static equilibrium of a system (docs/method.md §11.6): every line's
//! static rows (M25) and the free points' rows, the point's load against
//! the forces of its lines,
//!
//! ```text
//!   R(x) = [ dU_i/de_i - f_i            (each line i, its constraints)
//!            sum_i R_i|end at p - F_p ] (each free point p, F_p = m g + F)
//! ```
//!
//! solved by the static driver (§6.9) on the bordered Jacobian. The path
//! starts at a seed x0 (each line's elastic catenary through its end
//! points, [`super::seed_states`]) and follows the Newton homotopy
//!
//! ```text
//!   H(x; t) = R(x) - (1 - t) R(x0) = 0,     t: 0 -> 1       (M32)
//! ```
//!
//! x0 solves H(.; 0) exactly, and H(.; 1) = R: the full loads are on from
//! the start, and the increments take the seed's residual away. Unlike
//! ramping the loads from zero, no increment meets a slack line without
//! load (whose shape nothing determines).
//!
//! The part of the seed's residual that its elements' interpolation
//! makes, the axial strain between the nodes off the catenary's (large
//! where EA is far above the tension and the elements are coarse), is
//! taken away as an initial axial force of the elements, -(1 - t) EA
//! times the defect at every point of the axial rule (M32b): it turns
//! with the line, where as a dead load it buckled a buoyant section on
//! the path (docs/method.md §11.6).
//!
//! A line without compression is solved with its compressive stiffness
//! kept (at zero tension its own law has none). Where the path's end
//! shortens it, that end carries compression the line does not have (a
//! coarse chain's touchdown element locks: MHK_RM1 line 1 on 30
//! elements, 3.5 % on the fairlead's pull), and the path is followed
//! again from the seed with its own law (M32c), whose end, if reached
//! and isolated, is the equilibrium.

use super::body_clamps::{add_static_clamp, hold_spin};
use super::body_statics::{static_bodies, StaticBody};
use super::layout::SystemLayout;
use super::simulation::EndForce;
use super::static_friction::{line_statics, StaticFriction};
use super::System;
use crate::bordered::{BorderedLu, BorderedMatrix};
use crate::error::{ModelError, SolverError};
use crate::linear::{AddEntries, Jacobian};
use crate::model::State;
use crate::statics::{
    CableStatics, StaticEquations, StaticIncrement, StaticNewton, StaticSettings,
};
use std::ops::ControlFlow;

/// A static solve of a system.
pub struct SystemStatics {
    pub(super) equations: SystemEquations,
    pub(super) newton: StaticNewton<BorderedLu>,
    pub(super) settings: StaticSettings,
    /// Seeds to start over from if the path fails (see
    /// [`SystemStatics::seeded`]).
    pub(super) fallback: Option<(Vec<State>, System)>,
    /// What the seabed's friction holds (docs/method.md §12.2).
    pub(super) friction: StaticFriction,
    /// Whether this path is the second stage of [`StaticFriction::Pulled`]
    /// (the pull from the equilibrium as laid).
    pub(super) pulling: bool,
    /// The friction's targets of this path (W49), None: the seeds.
    pub(super) targets: Option<Vec<Vec<f64>>>,
    /// The seeds this path started from (a second path, without the
    /// compression kept, starts from them again: (M32c)).
    pub(super) seeds: Vec<State>,
    /// Whether line i, a line without compression, is solved with its
    /// own law (M4a) (the second path of (M32c)) instead of with its
    /// compressive stiffness kept.
    pub(super) own_law: Vec<bool>,
    /// Whether the path's end is still to be checked for lines to solve
    /// again without their compression (M32c).
    pub(super) check_compression: bool,
    /// Whether this solve's equilibrium is the pseudo-transient
    /// continuation's (M26b): from the seeds at the full load where the
    /// load paths failed, or from an end unstable at a body (M26c).
    pub(super) relaxed: bool,
}

/// The shortening above which the path's end of a line without
/// compression, solved with its compressive stiffness kept, is solved
/// again with its own law (docs/method.md §11.6, (M32c)): about the
/// strain that the static tolerance leaves (1e-10 of the line's length
/// over elements of a tenth to a hundredth of it).
pub(super) const KEPT_SHORTENING: f64 = 1e-9;

/// The equations of a system's equilibrium on the homotopy path (M32).
pub(super) struct SystemEquations {
    pub(super) system: System,
    pub(super) lines: Vec<CableStatics>,
    pub(super) layout: SystemLayout,
    pub(super) x_local: Vec<Vec<f64>>,
    pub(super) residual_local: Vec<Vec<f64>>,
    /// R(x0): the seed's residual.
    pub(super) offset: Vec<f64>,
    /// 1 - t.
    pub(super) homotopy: f64,
    /// Global indices of free point p's x, y, z (empty for the others).
    pub(super) point_index: Vec<Vec<usize>>,
    /// Positions of the points at the last converged increment.
    pub(super) point_position: Vec<[f64; 3]>,
    pub(super) end_forces: Vec<[EndForce; 2]>,
    /// The free bodies (docs/method.md §15.8).
    pub(super) bodies: Vec<StaticBody>,
}

impl SystemStatics {
    /// The static solve of `system` from the lines' seed states (one per
    /// line, e.g. [`super::seed_states`]); the free points start where
    /// their lines' seeds put the ends (which must agree). What seabed
    /// friction holds is `settings.seabed_friction` (with
    /// [`StaticFriction::FromSeed`], the slide from these seeds).
    pub fn new(
        system: System,
        seeds: Vec<State>,
        settings: StaticSettings,
    ) -> Result<Self, ModelError> {
        let own_law = vec![false; system.lines().len()];
        Self::build(system, seeds, settings, own_law, None)
    }

    /// [`SystemStatics::new`] with the lines without compression marked
    /// in `own_law` solved with their own law (M4a), the others with
    /// their compressive stiffness kept (docs/method.md §2.2, §11.6), and
    /// for the second stage of [`StaticFriction::Pulled`] the lines'
    /// friction `targets` (W49).
    pub(super) fn build(
        system: System,
        seeds: Vec<State>,
        settings: StaticSettings,
        own_law: Vec<bool>,
        targets: Option<Vec<Vec<f64>>>,
    ) -> Result<Self, ModelError> {
        settings.validate()?;
        super::body_holds::check_held(&system)?;
        let friction = settings.seabed_friction;
        if seeds.len() != system.lines().len() {
            return Err(ModelError::invalid(
                "initial_state",
                format!(
                    "expected {} line seeds, got {}",
                    system.lines().len(),
                    seeds.len()
                ),
            ));
        }
        system.check_held()?;
        let method = settings.constraint_method;
        for (i, line) in system.lines().iter().enumerate() {
            line.model
                .constraints
                .check_direction_route(method)
                .map_err(|e| ModelError::invalid(e.key, format!("line {i}: {}", e.message)))?;
        }
        let lines = line_statics(&system, &seeds, &own_law, targets.as_deref(), &settings);
        let models: Vec<_> = lines.iter().map(|l| &l.model).collect();
        let layout = SystemLayout::new(&system, &models, crate::assembly::Scheme::Static, method);
        let n = layout.size;
        let mut x = vec![f64::NAN; n];
        let mut unknown_weight = vec![f64::INFINITY; n];
        for (i, line) in lines.iter().enumerate() {
            let map = &layout.maps[i];
            let (xl, wl) = (line.unknowns_of_state(), line.unknown_weights());
            for (u, &g) in map.global.iter().enumerate() {
                if !x[g].is_nan() && (x[g] - xl[u]).abs() > 1e-9 * line.model.cable.length {
                    return Err(ModelError::invalid(
                        format!("lines[{i}]"),
                        "its seed does not start at the position of its free point",
                    ));
                }
                x[g] = xl[u];
                unknown_weight[g] = unknown_weight[g].min(wl[u]);
            }
        }
        let bodies = static_bodies(&system);
        for body in &bodies {
            // A point on the body that no line holds: where the body puts
            // it, weighted like the body's centre.
            for bp in &body.points {
                let at = system.points()[bp.point].position;
                for c in 0..3 {
                    let g = layout.point_unknown(bp.point, 0, c).expect("border");
                    if x[g].is_nan() {
                        x[g] = at[c];
                        unknown_weight[g] = 1.0 / body.length;
                    }
                }
            }
            let b = &system.bodies()[body.index];
            let centre = b.point(b.inertia.centre_of_mass);
            let weights = body.unknown_weights();
            for k in 0..6 {
                let g = layout.body_unknown(body.index, 0, k).expect("a free body");
                x[g] = if k < 3 { centre[k] } else { 0.0 };
                unknown_weight[g] = weights[k];
            }
        }
        let point_index = (0..system.points().len())
            .map(|p| {
                (0..3)
                    .filter_map(|c| layout.point_unknown(p, 0, c))
                    .collect()
            })
            .collect();
        let point_position = system.points().iter().map(|p| p.state_at(0.0).0).collect();
        let mut equations = SystemEquations {
            x_local: layout.lines.iter().map(|l| vec![0.0; l.size()]).collect(),
            residual_local: layout.lines.iter().map(|l| vec![0.0; l.size()]).collect(),
            offset: vec![0.0; n],
            homotopy: 0.0,
            end_forces: vec![[EndForce::default(); 2]; system.lines().len()],
            point_index,
            point_position,
            bodies,
            system,
            lines,
            layout,
        };
        let mut r0 = vec![0.0; n];
        equations.evaluate(&x, &mut r0, None);
        equations.offset = r0;
        equations.homotopy = 1.0;
        equations.converged(&x);
        let lu = BorderedLu::new(&equations.layout.shapes, equations.layout.border);
        let jacobian = BorderedMatrix::new(&equations.layout.shapes, equations.layout.border);
        let mut newton = StaticNewton::new(x, unknown_weight, lu, jacobian, settings.clone());
        newton.set_weight_rows(&equations.multiplier_rows());
        let check_compression = !own_law.iter().any(|&o| o);
        Ok(SystemStatics {
            equations,
            newton,
            settings,
            fallback: None,
            pulling: friction == StaticFriction::Pulled && targets.is_some(),
            friction,
            targets,
            seeds,
            own_law,
            check_compression,
            relaxed: false,
        })
    }

    /// The static solve of `system` from the seed of §11.6: the lines'
    /// catenaries of `seed_system` (the system itself in air, its lines
    /// under their wet weight in water) with the free points at the
    /// catenary network's equilibrium (M32a, [`super::static_seed_states`]);
    /// if that path fails, [`SystemStatics::solve`] starts over once from
    /// the free points where the scenario puts them
    /// ([`super::catenary_states`]). Measured: the network's start takes
    /// the bridle to its equilibrium from fairlead positions where the
    /// scenario's start stalls or ends on a rope folded in compression;
    /// the lazy-wave example's path from it turns back at t = 0.286 and
    /// the scenario's start reaches the equilibrium.
    /// What the seabed's friction holds is `settings.seabed_friction`,
    /// [`StaticFriction::FromSeed`] taken as [`StaticFriction::AsLaid`]:
    /// these seeds are not where a line was laid. A line anchored on the
    /// bed longer than its path can hold ([`super::overlong_lines`],
    /// (C20)) is refused.
    pub fn seeded(
        system: System,
        seed_system: &System,
        mut settings: StaticSettings,
    ) -> Result<Self, ModelError> {
        let given_system = system.clone();
        let mut system = system;
        // The free bodies start where the network balances them too.
        let poses = super::balanced_bodies(seed_system);
        for b in seed_system.free_bodies().collect::<Vec<_>>() {
            let (position, rotation) = poses[b];
            if b < system.bodies().len() {
                system.set_body_pose(b, position, rotation);
            }
        }
        if settings.seabed_friction == StaticFriction::FromSeed {
            settings.seabed_friction = StaticFriction::AsLaid;
        }
        // A line longer than its path can hold has no unique equilibrium
        // (C20): refused before the path stalls at load factor 0.
        if let Some(l) = super::overlong_lines(seed_system).first() {
            return Err(ModelError::invalid(
                format!("lines[{}]", l.line),
                l.to_string(),
            ));
        }
        let balanced = super::static_seed_states(seed_system);
        let given = super::catenary_states(seed_system);
        let own_law = vec![false; system.lines().len()];
        let mut statics = Self::build(system, balanced.clone(), settings, own_law, None)?;
        if given != balanced {
            statics.fallback = Some((given, given_system));
        }
        Ok(statics)
    }

    pub fn system(&self) -> &System {
        &self.equations.system
    }

    /// Line i's state at the last converged increment (at rest; t holds
    /// the path parameter).
    pub fn line_state(&self, line: usize) -> &State {
        &self.equations.lines[line].state
    }

    /// Every line's state at the last converged increment, at t = 0:
    /// the start of a dynamic run from this equilibrium.
    pub fn line_states(&self) -> Vec<State> {
        self.equations
            .lines
            .iter()
            .map(|l| State {
                t: 0.0,
                ..l.state.clone()
            })
            .collect()
    }

    /// Position of point p at the last converged increment.
    pub fn point_position(&self, p: usize) -> [f64; 3] {
        self.equations.point_position[p]
    }

    /// The force each end of line i exerts on its point (zero at a loose
    /// end). Only at the end of the path (t = 1) are these the forces of
    /// the equilibrium; before, they include the seed's share (M32).
    pub fn end_forces(&self, line: usize) -> [EndForce; 2] {
        self.equations.end_forces[line]
    }

    /// The net force the attached lines (and the bodies pinned there)
    /// exert on point p.
    pub fn point_force(&self, p: usize) -> [f64; 3] {
        let mut f = [0.0; 3];
        for (li, end) in self.equations.system.attachments(p) {
            for c in 0..3 {
                f[c] += self.equations.end_forces[li][end].force[c];
            }
        }
        // The bodies pinned there pull it as their pins hold them.
        for (b, body) in self.equations.system.bodies().iter().enumerate() {
            if body.pin.is_some_and(|pin| pin.point == p) {
                let held = self.pin_force(b).unwrap_or([0.0; 3]);
                for c in 0..3 {
                    f[c] -= held[c];
                }
            }
        }
        f
    }

    /// Unknowns of the static system.
    pub fn unknowns(&self) -> usize {
        self.equations.layout.size
    }

    /// Whether line i, a line without compression, was solved with its
    /// own law (M4a) (docs/method.md §11.6, (M32c)): its equilibrium is
    /// then shortened only where it is slack, carrying no compression.
    pub fn released(&self, line: usize) -> bool {
        self.own_law[line]
    }

    /// Follows the path (M32) in `load_steps` increments, calling
    /// `observer` after each converged one (see
    /// [`crate::StaticSolver::solve`]). A solve built by
    /// [`SystemStatics::seeded`] whose path fails starts over once from
    /// its fallback seed (the observer sees both paths' increments); the
    /// error is the last path's. A path whose end shortens a line without
    /// compression is followed again from its seed with such lines' own
    /// law (M32c), whose end, if it is reached and isolated, is the
    /// equilibrium (the observer sees its increments too).
    pub fn solve<F>(&mut self, mut observer: F) -> Result<bool, SolverError>
    where
        F: FnMut(&SystemStatics, &StaticIncrement) -> ControlFlow<()>,
    {
        loop {
            match self.newton.advance(&mut self.equations) {
                Ok(Some(inc)) => {
                    if observer(self, &inc).is_break() {
                        return Ok(false);
                    }
                }
                Ok(None) => {
                    if !self.release(&mut observer) {
                        return Ok(false);
                    }
                    match self.pull()? {
                        Some(stage) => *self = stage,
                        None => return self.leave_unstable(&mut observer),
                    }
                }
                Err(e) => {
                    let Some((seeds, system)) = self.fallback.take() else {
                        match self.own_law_after_failure(&mut observer) {
                            Ok(true) => continue,
                            Ok(false) => return Ok(false),
                            Err(()) => match self.relax_after_failure(e, &mut observer) {
                                Ok(true) => continue,
                                Ok(false) => return Ok(false),
                                Err(e) => return Err(e),
                            },
                        }
                    };
                    // The system was accepted with the first seeds; the
                    // fallback has the same lines, so this cannot fail.
                    let settings = self.settings.clone();
                    let own_law = vec![false; system.lines().len()];
                    let Ok(restart) = Self::build(system, seeds, settings, own_law, None) else {
                        return Err(e);
                    };
                    *self = restart;
                }
            }
        }
    }
}

impl StaticEquations for SystemEquations {
    type Matrix = BorderedMatrix;

    fn evaluate(
        &mut self,
        x: &[f64],
        residual: &mut [f64],
        mut jacobian: Option<&mut BorderedMatrix>,
    ) {
        self.line_rows(x, residual, jacobian.as_deref_mut());
        for (p, idx) in self.point_index.iter().enumerate() {
            if idx.is_empty() {
                continue;
            }
            let load = self.system.point_load(p);
            for c in 0..3 {
                residual[idx[c]] -= load[c];
            }
            // In water: the steady current's drag at rest (§12.6); on the
            // bed: its push (W42p).
            let (water, bed) = (&self.system.points()[p].water, self.system.point_bed(p));
            if water.is_none() && bed.is_none() {
                continue;
            }
            let r = [x[idx[0]], x[idx[1]], x[idx[2]]];
            let f = super::point_bed::steady_point_force(water.as_ref(), bed, &r);
            for c in 0..3 {
                residual[idx[c]] -= f.force[c];
                if let Some(jac) = jacobian.as_deref_mut() {
                    for d in 0..3 {
                        jac.add(idx[c], idx[d], -f.d_r[c][d]);
                    }
                }
            }
        }
        for body in &mut self.bodies {
            body.add(&self.layout, x, residual, jacobian.as_deref_mut());
        }
        for clamp in self.system.body_clamps() {
            let body = self.bodies.iter().find(|b| b.index == clamp.body);
            let rotation = body.expect("a clamp's body is free").rotation;
            let dpn = self.system.lines()[clamp.line].model.dofs_per_node();
            let jacobian = jacobian.as_deref_mut();
            add_static_clamp(clamp, &self.layout, dpn, &rotation, x, residual, jacobian);
        }
        for body in &self.bodies {
            if self.system.bodies()[body.index].connector {
                let row = self
                    .layout
                    .body_unknown(body.index, 0, 5)
                    .expect("free body");
                hold_spin(&[row], x, residual, jacobian.as_deref_mut());
            }
        }
        for (r, r0) in residual.iter_mut().zip(&self.offset) {
            *r -= self.homotopy * r0;
        }
    }

    /// Each line's weights (§6.9) at its own rows; a free point's rows
    /// take the smallest weight of the lines attached there.
    fn row_weights(&mut self, jacobian: &BorderedMatrix, weights: &mut [f64]) {
        let n = self.layout.size;
        let kmax = (0..n).map(|i| jacobian.get(i, i).abs()).fold(0.0, f64::max);
        weights.fill(f64::INFINITY);
        for (i, line) in self.lines.iter().enumerate() {
            let map = &self.layout.maps[i];
            let wl = &mut self.residual_local[i];
            line.row_weights(|r| jacobian.get(map.global[r], map.global[r]), kmax, wl);
            for (u, &g) in map.global.iter().enumerate() {
                weights[g] = weights[g].min(wl[u]);
            }
        }
        for body in &self.bodies {
            // Its points' rows are their constraints: weighted as positions.
            for bp in &body.points {
                for c in 0..3 {
                    let g = self.layout.point_unknown(bp.point, 0, c).expect("border");
                    weights[g] = weights[g].min(1.0 / body.length);
                }
            }
            let w = body.row_weights();
            for (k, &wk) in w.iter().enumerate() {
                weights[self
                    .layout
                    .body_unknown(body.index, 0, k)
                    .expect("free body")] = wk;
            }
        }
    }

    fn set_load_factor(&mut self, t: f64) {
        self.homotopy = 1.0 - t;
        for line in &mut self.lines {
            line.scale_initial_axial_forces(1.0 - t);
        }
    }

    fn legs(&self) -> usize {
        1
    }

    fn converged(&mut self, x: &[f64]) {
        if self.bodies.iter().any(|b| b.pin.is_some()) {
            // The pins' forces at the solution (the bodies' rows hold
            // them), before the lines' converged rows are taken below.
            let mut scratch = vec![0.0; x.len()];
            self.evaluate(x, &mut scratch, None);
        }
        for (i, line) in self.lines.iter_mut().enumerate() {
            let map = &self.layout.maps[i];
            let xl = &mut self.x_local[i];
            map.gather(x, xl);
            line.converged(xl, &mut self.residual_local[i]);
        }
        for (p, point) in self.system.points().iter().enumerate() {
            let idx = &self.point_index[p];
            self.point_position[p] = if idx.is_empty() {
                point.state_at(0.0).0
            } else {
                [x[idx[0]], x[idx[1]], x[idx[2]]]
            };
        }
        for body in &mut self.bodies {
            body.converged = body.unknowns(&self.layout, x);
        }
        self.collect_end_forces();
    }
}
