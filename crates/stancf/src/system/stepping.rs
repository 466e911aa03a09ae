//! One step of a system (docs/method.md §11.3): the lines begin their
//! step, the prediction of every unknown is gathered, the slab equations
//! of all lines and free points are solved together (or each line apart,
//! §11.14), and the lines, the end forces (§6.5, (M23)) and the points
//! take the converged step.

use super::body_terms::PinHold;
use super::clamp_moments::clamp_turn;
use super::end_forces::{force_at_end, force_cubic, position_row_sum, row_moments};
use super::layout::add_line_rows;
use super::point_terms::PointTerms;
use super::simulation::{step_problem, SystemSimulation};
use super::step_equations::StepOfSystem;
use super::{AttachedEnd, End, EndForce};
use crate::assembly::Kind;
use crate::bordered::BorderedMatrix;
use crate::error::SolverError;
use crate::integrator::StepReport;
use crate::model::{coordinate, SLOT_R};
use crate::solver::{solve, NewtonReport};

impl SystemSimulation {
    /// One step of the step length, not halved.
    pub(super) fn step_once(&mut self) -> Result<StepReport, SolverError> {
        let dt = self.settings.time_step;
        self.move_pins(dt);
        for line in &mut self.lines {
            line.begin_step();
        }
        let report = if self.topology.has_free_points() || self.topology.has_free_bodies() {
            self.gather_prediction();
            let report = self.solve_step(dt)?;
            self.check_body_turns()?;
            for (i, line) in self.lines.iter_mut().enumerate() {
                let map = &self.layout.maps[i];
                let xl = line.unknowns();
                map.gather(&self.x, xl);
            }
            report
        } else {
            let report =
                super::apart::solve_lines_apart(&mut self.lines, dt, self.apart_iterations)?;
            self.apart_iterations = report.iterations;
            report
        };
        self.finish_lines(report)?;
        self.add_point_water_work();
        self.collect_end_forces(dt);
        self.collect_pin_forces(dt);
        if self.settings.time_scheme.carries_momentum() {
            let (mean, at_end) = (&self.end_forces, &self.end_forces_at_end);
            self.forces_at_time.set_at_end(mean, at_end, dt);
        } else {
            self.forces_at_time.update(&self.end_forces, dt);
        }
        self.advance_points(dt);
        self.keep_step_record(self.t, dt);
        self.steps += 1;
        self.t += dt;
        Ok(StepReport {
            step: self.steps,
            t: self.t,
            newton: report,
        })
    }

    /// The slot values over the step from t of the pins on a host's
    /// motion (B34): the point's velocity at the start, its position and
    /// velocity at the end.
    fn move_pins(&mut self, dt: f64) {
        for body in &mut self.bodies {
            let Some(pin) = body.pin.as_mut() else {
                continue;
            };
            pin.momentum_a = body.body.linear_momentum();
            if let PinHold::Moving(p) = pin.hold {
                let point = &self.topology.points()[p];
                let (from, start) = point.state_at(self.t);
                let (end, end_velocity) = point.state_at(self.t + dt);
                pin.held = [start, end, end_velocity];
                pin.moved = crate::vec3::sub(end, from);
            }
        }
    }

    /// Each pin's mean force on its body over the step (B35): what of the
    /// body's momentum change p_b - p_a its own loads' impulse and its
    /// lines' (their mean forces at its points) do not give.
    fn collect_pin_forces(&mut self, dt: f64) {
        for k in 0..self.bodies.len() {
            let Some(pin) = self.bodies[k].pin else {
                continue;
            };
            let body = &self.bodies[k];
            let mut impulse = crate::vec3::sub(body.body.linear_momentum(), pin.momentum_a);
            let own = body.body.own_impulse().expect("a pinned body keeps it");
            impulse = crate::vec3::sub(impulse, own);
            for bp in &body.points {
                let f = self.point_force(bp.point);
                impulse = crate::vec3::sub(impulse, f.map(|c| c * dt));
            }
            if let Some(pin) = self.bodies[k].pin.as_mut() {
                pin.force = impulse.map(|c| c / dt);
                pin.work += crate::vec3::dot(pin.force, pin.moved);
            }
        }
    }

    /// Adds the step's work of the water (W34), the damping (B42) and
    /// the bed (W42p) on the free points.
    pub(super) fn add_point_water_work(&mut self) {
        let layout = &self.layout.time;
        for (p, idx) in self.point_index.iter().enumerate() {
            if idx.is_empty() {
                continue;
            }
            let m = &self.points[p];
            let terms = PointTerms::of(&self.topology, p, self.t, idx, layout, &self.slab);
            if !terms.has_own_forces() {
                continue;
            }
            terms.expand(&self.x, m.e, m.v, &mut self.point_nodes[p]);
            let (water, bed) = terms.own_work(&self.point_nodes[p]);
            self.point_water_work += water;
            self.point_bed_work += bed;
        }
    }

    /// Completes every line's step. The Galerkin step of a system with
    /// free points takes the end rates from the system's mass matrix
    /// (docs/method.md §11.10), the others from each line's own.
    pub(super) fn finish_lines(&mut self, report: NewtonReport) -> Result<(), SolverError> {
        self.clamp_step_ends();
        let Some(mass) = &mut self.mass else {
            for line in &mut self.lines {
                line.finish_step(report);
            }
            return Ok(());
        };
        for line in &mut self.lines {
            line.expand_step();
        }
        let layout = &self.layout.time;
        for (p, idx) in self.point_index.iter().enumerate() {
            if idx.is_empty() {
                continue;
            }
            let m = &self.points[p];
            let terms = PointTerms::of(&self.topology, p, self.t, idx, layout, &self.slab);
            terms.expand(&self.x, m.e, m.v, &mut self.point_nodes[p]);
            self.point_momentum[p] = terms.end_momentum(&self.point_nodes[p]);
        }
        // The bodies' end momenta (B14) from the lines' rows at their
        // points, then the bodies move to the step's end.
        // (only the lines with an end on a body's point are assembled again)
        if !self.bodies.is_empty() {
            self.body_rows.fill(0.0);
            for (i, line) in self.lines.iter_mut().enumerate() {
                let on_body = self.topology.line_ends()[i].iter().any(
                    |e| matches!(e, End::Point(p) if self.topology.points()[*p].body().is_some()),
                );
                if on_body {
                    add_line_rows(
                        &self.layout.maps[i],
                        i,
                        &self.x,
                        (&mut self.x_local[i][..], &mut self.residual_local[i][..]),
                        &mut self.body_rows,
                        None,
                        |xl, rl, view| line.assemble_line(xl, rl, view),
                    );
                }
            }
        }
        for k in 0..self.bodies.len() {
            let clamps = self.topology.body_clamps();
            let clamp_turn = clamp_turn(clamps, &self.clamp_ends, self.bodies[k].index);
            let body = &mut self.bodies[k];
            let xb = body.unknowns(&self.layout, &self.x);
            let (layout, rows) = (&self.layout, &self.body_rows);
            let end_rows = |p: usize| -> [f64; 3] {
                std::array::from_fn(|c| rows[layout.point_unknown(p, 2, c).expect("border")])
            };
            let (momentum, centre_row) = body
                .end_momentum(&xb, end_rows, clamp_turn)
                .ok_or_else(|| singular(self.t, self.steps, "a body's J_r(theta_b) is singular"))?;
            self.body_momentum[k] = momentum;
            // A joint's child (before its parent): its centre's end row
            // joins its point's (B29).
            if let Some(PinHold::Point(p)) = body.pin.map(|pin| pin.hold) {
                for (c, v) in centre_row.iter().enumerate() {
                    self.body_rows[self.layout.point_unknown(p, 2, c).expect("border")] += v;
                }
            }
            body.body.advance(&xb)?;
        }
        // The clamps' frames turned with their bodies to the step's end.
        for clamp in self.topology.body_clamps() {
            let body = self.bodies.iter().find(|b| b.index == clamp.body);
            let rotation = body.expect("a clamp's body is free").body.rotation();
            self.lines[clamp.line].set_direction_hold(clamp.hold, clamp.local.turned(&rotation));
        }
        mass.set_end_rates(
            &self.topology,
            &mut self.lines,
            &self.point_momentum,
            &mut self.bodies,
            &self.body_momentum,
            &self.clamp_ends,
        )
        .map_err(|_| {
            singular(
                self.t,
                self.steps,
                "the system's mass matrix is singular (a free body without mass or inertia?)",
            )
        })?;
        self.collect_clamp_moments(self.settings.time_step);
        for line in &mut self.lines {
            line.close_step(report);
        }
        Ok(())
    }

    /// Refuses a step in which a free body turns by more than pi: its
    /// chart (B3)-(B4) would near its singularity (docs/method.md §15.4).
    fn check_body_turns(&self) -> Result<(), SolverError> {
        for body in &self.bodies {
            let xb = body.unknowns(&self.layout, &self.x);
            let turn = crate::vec3::norm([xb[12], xb[13], xb[14]]);
            if turn > std::f64::consts::PI {
                let mut e = singular(self.t, self.steps, "");
                e.kind = crate::error::FailureKind::NotConverged;
                e.detail = format!(
                    "body {} turns by {turn:.3} rad in one step, more than pi; take a shorter \
                     step",
                    body.index
                );
                return Err(e);
            }
        }
        Ok(())
    }

    /// The lines' predicted unknowns, and the free points' (docs/method.md
    /// §4.8, §11.3): a line end's position coordinates at a free point are
    /// the point's unknowns, so the line's prediction (its last step's
    /// cubic extrapolated) is the point's too. A point no line end is at
    /// takes the Taylor expansion with its last step's acceleration.
    pub(super) fn gather_prediction(&mut self) {
        for (i, line) in self.lines.iter_mut().enumerate() {
            let map = &self.layout.maps[i];
            let xl = line.unknowns();
            map.scatter(xl, &mut self.x);
        }
        let layout = &self.layout.time;
        let h = self.slab.dt;
        for (p, idx) in self.point_index.iter().enumerate() {
            if idx.is_empty() || self.topology.attachments(p).next().is_some() {
                continue;
            }
            let m = &self.points[p];
            for (s, &(i, kind)) in layout.unknown_slots.iter().enumerate() {
                let tau = h * i as f64;
                for c in 0..3 {
                    let (e, v, a) = (m.e[c], m.v[c], m.acceleration[c]);
                    self.x[idx[3 * s + c]] = match kind {
                        Kind::Position => e + tau * v + 0.5 * tau * tau * a,
                        Kind::Velocity => v + tau * a,
                    };
                }
            }
        }
        // A free body at its carried rates, its points where it puts them
        // (B13).
        for body in &self.bodies {
            let xb = body.body.galerkin_guess();
            body.set_unknowns(&self.layout, &xb, &mut self.x);
            for bp in &body.points {
                let slots = body.point_slots(&body.maps(bp.arm, &xb), &xb);
                for (s, values) in slots.iter().enumerate() {
                    for (c, &v) in values.iter().enumerate() {
                        let g = self.layout.point_unknown(bp.point, s, c).expect("border");
                        self.x[g] = v;
                    }
                }
            }
        }
    }

    pub(super) fn solve_step(&mut self, dt: f64) -> Result<NewtonReport, SolverError> {
        let mut problem = step_problem!(self);
        solve(
            &mut problem,
            &mut self.x,
            &self.settings.newton,
            &mut self.workspace,
            None,
        )
        .map_err(|f| SolverError {
            kind: f.kind,
            time: self.t,
            step: self.steps + 1,
            residual: f.report.residual,
            iterations: f.report.iterations,
            detail: format!("time step {dt:e} s"),
        })
    }

    /// The forces of the line ends on their points over the step: at a
    /// free point the line's share of the point's position rows, summed
    /// over the step's position rows and divided by dt (the negative of
    /// the impulse the point gives the line, docs/method.md §11.4); at a
    /// fixed or coupled point minus the line's reaction (§6.5). With the
    /// Galerkin step, also the forces at the step's end from the same
    /// rows' four moments (M23b), into `end_forces_at_end`.
    pub(super) fn collect_end_forces(&mut self, dt: f64) {
        let galerkin = self.settings.time_scheme.carries_momentum();
        for (i, line) in self.lines.iter_mut().enumerate() {
            let ends = self.topology.line_ends()[i];
            let free_end = ends
                .iter()
                .any(|e| matches!(e, End::Point(p) if self.topology.points()[*p].is_unknown()));
            if free_end {
                // The line's rows at the converged unknowns.
                let map = &self.layout.maps[i];
                let xl = &mut self.x_local[i];
                map.gather(&self.x, xl);
                line.assemble_line::<BorderedMatrix>(xl, &mut self.residual_local[i], None);
            }
            let layout = &self.layout.lines[i];
            self.end_forces[i] = [EndForce::default(); 2];
            self.end_forces_at_end[i] = [EndForce::default(); 2];
            self.force_cubics[i] = [None; 2];
            for AttachedEnd {
                end: k,
                point: p,
                node,
            } in self.topology.attached_ends(i, line.model())
            {
                let (force, moments) = if self.topology.points()[p].is_unknown() {
                    let rows = position_row_sum(layout, node, &self.residual_local[i]);
                    let dpn = line.model().dofs_per_node();
                    let end_term: [f64; 3] = std::array::from_fn(|c| {
                        line.galerkin_end_term(coordinate(dpn, node, SLOT_R, c))
                    });
                    let force = std::array::from_fn(|c| (rows[c] + end_term[c]) / dt);
                    let moments = galerkin.then(|| {
                        let mut moments = row_moments(layout, node, &self.residual_local[i]);
                        moments[2] = end_term;
                        moments
                    });
                    (force, moments)
                } else {
                    let r = line
                        .reactions()
                        .iter()
                        .find(|(n, _)| *n == node)
                        .map_or([0.0; 3], |(_, f)| *f);
                    let moments = line
                        .reaction_moments(node)
                        .map(|m| m.map(|mj| mj.map(|v| -v)));
                    (r.map(|f| -f), moments)
                };
                self.end_forces[i][k] = EndForce { force };
                self.end_forces_at_end[i][k] = EndForce {
                    force: moments.map_or(force, |m| force_at_end(&m, dt)),
                };
                self.force_cubics[i][k] = moments.map(|m| force_cubic(&m, dt));
            }
        }
    }

    /// Moves the points to the end of the step: free points to their
    /// converged unknowns, fixed and coupled ones along their motion.
    pub(super) fn advance_points(&mut self, dt: f64) {
        let layout = &self.layout.time;
        let last = layout.layers();
        let t_end = self.t + dt;
        for (p, point) in self.topology.points().iter().enumerate() {
            let m = &mut self.points[p];
            m.previous = (m.e, m.v);
            let galerkin_rate = self.mass.as_ref().and_then(|mass| mass.point_rate(p));
            let (e, v) = if self.point_index[p].is_empty() {
                point.state_at(t_end)
            } else if let Some(v) = galerkin_rate {
                let idx = &self.point_index[p];
                let se = layout.unknown_slot(last, Kind::Position).expect("e_L");
                (std::array::from_fn(|c| self.x[idx[3 * se + c]]), v)
            } else {
                let idx = &self.point_index[p];
                let se = layout.unknown_slot(last, Kind::Position).expect("e_L");
                let sv = layout.unknown_slot(last, Kind::Velocity).expect("v_L");
                (
                    std::array::from_fn(|c| self.x[idx[3 * se + c]]),
                    std::array::from_fn(|c| self.x[idx[3 * sv + c]]),
                )
            };
            for c in 0..3 {
                m.acceleration[c] = (v[c] - m.v[c]) / dt;
            }
            m.e = e;
            m.v = v;
        }
    }
}

/// A singular-matrix failure of the step from t (after `steps` steps).
fn singular(t: f64, steps: usize, detail: &str) -> SolverError {
    SolverError {
        kind: crate::error::FailureKind::SingularJacobian,
        time: t,
        step: steps + 1,
        residual: f64::NAN,
        iterations: 0,
        detail: detail.into(),
    }
}
