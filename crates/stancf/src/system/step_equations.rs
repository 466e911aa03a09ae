//! The equations of a system's step as Newton sees them
//! (docs/method.md §11.2-11.3): every line's slab rows gathered into the
//! bordered numbering and the free points' own rows, with the
//! convergence scales of the system's unknowns and rows (§7.1).

use super::body_clamps::{add_step_clamp, hold_spin};
use super::body_terms::StepBody;
use super::layout::{add_lines_rows, SystemLayout};
use super::point_terms::{PointNodes, PointTerms};
use super::{AttachedEnd, Topology};
use crate::bordered::BorderedMatrix;
use crate::element::TimeSlab;
use crate::integrator::Simulation;
use crate::model::{coordinate, SLOT_R, SLOT_R_X};
use crate::solver::NonlinearSystem;

/// Position, velocity and predictor history of a point.
#[derive(Clone, Debug, Default)]
pub(super) struct PointMotion {
    pub(super) e: [f64; 3],
    pub(super) v: [f64; 3],
    pub(super) previous: ([f64; 3], [f64; 3]),
    pub(super) acceleration: [f64; 3],
}

/// The convergence scales of the system's unknowns and rows: each line's
/// (docs/method.md §7.1) at its own indices; at a free point's, the
/// smallest of the attached lines' for unknowns, and for rows the
/// lines' weights combined as the point's total mass demands (a row
/// weight is inverse to the mass on the coordinate: 1/w = sum 1/w_i,
/// scaled by the lines' end mass over that plus the point's).
///
/// A point on a free body: its rows are its constraints (B13), weighted
/// like its unknowns. A free body: its centre like a point of the
/// shortest attached line's length L, its rotation by the arm rho of its
/// farthest point (a turn dtheta moves it rho dtheta); its rows like a
/// line's, with its mass m and its moment I + m rho^2 about the centre.
pub(super) fn system_scales(
    system: &Topology,
    lines: &[Simulation],
    layout: &SystemLayout,
    bodies: &[StepBody],
    dt: f64,
) -> (Vec<f64>, Vec<f64>) {
    let n = layout.size;
    let border_start = layout.border_start();
    let mut unknown = vec![f64::INFINITY; n];
    let mut inverse_equation = vec![0.0; n];
    let mut equation = vec![0.0; n];
    let mut end_mass = vec![0.0; layout.border];
    for (i, line) in lines.iter().enumerate() {
        let scales = line.scales();
        let map = &layout.maps[i];
        let mass = line.model().mass_diagonal();
        for (u, &g) in map.global.iter().enumerate() {
            unknown[g] = unknown[g].min(scales.unknown[u]);
            if g < border_start {
                equation[g] = scales.equation[u];
            } else if scales.equation[u] > 0.0 {
                inverse_equation[g] += 1.0 / scales.equation[u];
            }
        }
        for AttachedEnd { point, node, .. } in system.attached_ends(i, line.model()) {
            let Some(base) = layout.point_base[point] else {
                continue;
            };
            let o = coordinate(line.model().dofs_per_node(), node, SLOT_R, 0);
            for k in 0..3 * layout.slots {
                end_mass[base + k] += mass[o + k % 3];
            }
        }
    }
    for p in 0..system.points().len() {
        let Some(base) = layout.point_base[p] else {
            continue;
        };
        for k in 0..3 * layout.slots {
            let g = border_start + base + k;
            let lines_mass = end_mass[base + k];
            let share = lines_mass / (lines_mass + system.point_inertia(p));
            equation[g] = share / inverse_equation[g];
        }
    }
    for body in bodies {
        body_scales(
            system,
            lines,
            layout,
            body,
            dt,
            (&mut unknown, &mut equation),
        );
    }
    for u in unknown.iter_mut() {
        if !u.is_finite() {
            *u = 0.0;
        }
    }
    (unknown, equation)
}

/// The scales of a free body's unknowns and rows and of its points' rows
/// (see [`system_scales`]).
fn body_scales(
    system: &Topology,
    lines: &[Simulation],
    layout: &SystemLayout,
    body: &StepBody,
    dt: f64,
    (unknown, equation): (&mut [f64], &mut [f64]),
) {
    let mut length = f64::INFINITY;
    let mut arm = 0.0f64;
    for bp in &body.points {
        arm = arm.max(crate::vec3::norm(bp.arm));
        for (li, _) in system.attachments(bp.point) {
            length = length.min(lines[li].model().cable.length);
        }
    }
    let length = if length.is_finite() { length } else { 1.0 };
    let arm = if arm > 0.0 { arm } else { length };
    let inertia = body.body.inertia();
    // A connector (§15.20) has no mass: its rows are its lines' ends'.
    let mass = if inertia.mass > 0.0 {
        inertia.mass
    } else {
        lines_end_mass(system, lines, body)
    };
    let moment = inertia.inertia_at_centre[0][0]
        + inertia.inertia_at_centre[1][1]
        + inertia.inertia_at_centre[2][2]
        + mass * arm * arm;
    // Unknown slots (0,w), (1,e), (1,w); row slots (0,e), (0,w), (1,w).
    let rate = [true, false, true];
    let row_is_rate = [false, true, true];
    for slot in 0..3 {
        for k in 0..6 {
            let (reach, inert) = if k < 3 { (1.0, mass) } else { (arm, moment) };
            let u = reach / length * if rate[slot] { dt } else { 1.0 };
            let e = reach / (length * inert) * if row_is_rate[slot] { 1.0 } else { dt };
            let g = layout.body_unknown(body.index, slot, k).expect("free body");
            unknown[g] = u;
            equation[g] = e;
        }
    }
    // The points' rows are their constraints (B13), positions like their
    // unknowns; a point no line holds (a joint's, §15.14) moves like the
    // centre.
    for bp in &body.points {
        for slot in 0..3 {
            for c in 0..3 {
                let g = layout.point_unknown(bp.point, slot, c).expect("border");
                let centre = layout.body_unknown(body.index, slot, c).expect("free body");
                if !unknown[g].is_finite() {
                    unknown[g] = unknown[centre];
                }
                equation[g] = unknown[g];
            }
        }
    }
}

/// The mass of the line ends at body `body`'s points (one coordinate's
/// diagonal entry per end).
fn lines_end_mass(system: &Topology, lines: &[Simulation], body: &StepBody) -> f64 {
    let mut mass = 0.0;
    for bp in &body.points {
        for (li, end) in system.attachments(bp.point) {
            let model = lines[li].model();
            let node = super::end_node(model, end);
            mass += model.mass_diagonal()[coordinate(model.dofs_per_node(), node, SLOT_R, 0)];
        }
    }
    mass
}

/// The step of a system as Newton sees it.
pub(super) struct StepOfSystem<'a> {
    pub(super) topology: &'a Topology,
    pub(super) lines: &'a mut [Simulation],
    pub(super) layout: &'a SystemLayout,
    pub(super) slab: &'a TimeSlab,
    pub(super) points: &'a [PointMotion],
    pub(super) bodies: &'a [StepBody],
    pub(super) point_index: &'a [Vec<usize>],
    pub(super) point_nodes: &'a mut [PointNodes],
    pub(super) x_local: &'a mut [Vec<f64>],
    pub(super) residual_local: &'a mut [Vec<f64>],
    pub(super) unknown_scale: &'a [f64],
    pub(super) equation_scale: &'a [f64],
    /// The step's start time (the water's kinematics depend on it).
    pub(super) time: f64,
}

impl NonlinearSystem<BorderedMatrix> for StepOfSystem<'_> {
    fn evaluate(
        &mut self,
        x: &[f64],
        residual: &mut [f64],
        mut jacobian: Option<&mut BorderedMatrix>,
    ) {
        add_lines_rows(
            self.lines,
            &self.layout.maps,
            (self.x_local, self.residual_local),
            x,
            residual,
            jacobian.as_deref_mut(),
            |line, xl, rl, view| line.assemble_line(xl, rl, view),
        );
        let layout = &self.layout.time;
        for (p, idx) in self.point_index.iter().enumerate() {
            if idx.is_empty() {
                continue;
            }
            let m = &self.points[p];
            let terms = PointTerms::of(self.topology, p, self.time, idx, layout, self.slab);
            terms.expand(x, m.e, m.v, &mut self.point_nodes[p]);
            let momentum = m.v.map(|v| terms.mass * v);
            terms.add(
                &self.point_nodes[p],
                momentum,
                residual,
                jacobian.as_deref_mut(),
            );
        }
        for body in self.bodies {
            body.add(self.layout, x, residual, jacobian.as_deref_mut());
            body.add_pin(self.layout, x, residual, jacobian.as_deref_mut());
        }
        for clamp in self.topology.body_clamps() {
            let body = self.bodies.iter().find(|b| b.index == clamp.body);
            let body = body.expect("a clamp's body is free");
            let line = &self.lines[clamp.line];
            let dpn = line.model().dofs_per_node();
            let g0 = coordinate(dpn, clamp.node, SLOT_R_X, 0);
            let e = &line.state().e;
            let xb = body.unknowns(self.layout, x);
            add_step_clamp(
                clamp,
                self.layout,
                dpn,
                [e[g0], e[g0 + 1], e[g0 + 2]],
                &body.body.rotation(),
                &xb,
                x,
                residual,
                jacobian.as_deref_mut(),
            );
        }
        for body in self.bodies {
            if self.topology.bodies()[body.index].connector {
                let rows: [usize; 3] = std::array::from_fn(|s| {
                    self.layout
                        .body_unknown(body.index, s, 5)
                        .expect("free body")
                });
                hold_spin(&rows, x, residual, jacobian.as_deref_mut());
            }
        }
    }

    fn residual_norm(&self, r: &[f64]) -> f64 {
        crate::assembly::Scales::norm(self.equation_scale, r)
    }

    fn increment_norm(&self, dx: &[f64]) -> f64 {
        crate::assembly::Scales::norm(self.unknown_scale, dx)
    }
}
