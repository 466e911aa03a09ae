//! The lines' part of a system's static equations (docs/method.md §11.6):
//! their rows gathered into the system's, their multipliers' weights in
//! the static Newton's increment norm (§6.9), and the forces their ends
//! exert on their points at a converged increment.

use super::layout::add_lines_rows;
use super::simulation::EndForce;
use super::statics::SystemEquations;
use super::AttachedEnd;
use crate::bordered::BorderedMatrix;
use crate::model::{coordinate, SLOT_R};

impl SystemEquations {
    /// Each line's multipliers and the rows of the coordinates they hold,
    /// in the system's numbering (the increment norm's weights, §6.9).
    pub(super) fn multiplier_rows(&self) -> Vec<(usize, [usize; 3])> {
        let mut rows = Vec::new();
        for (line, map) in self.lines.iter().zip(&self.layout.maps) {
            let global = line.multiplier_rows().into_iter();
            rows.extend(global.map(|(m, r)| (map.global[m], r.map(|r| map.global[r]))));
        }
        rows
    }

    /// Each line's rows at x into `residual` and their Jacobians into
    /// `jacobian` (both cleared first).
    pub(super) fn line_rows(
        &mut self,
        x: &[f64],
        residual: &mut [f64],
        jacobian: Option<&mut BorderedMatrix>,
    ) {
        add_lines_rows(
            &mut self.lines,
            &self.layout.maps,
            (&mut self.x_local, &mut self.residual_local),
            x,
            residual,
            jacobian,
            |line, xl, rl, view| line.assemble_into(xl, rl, view),
        );
    }
}

impl SystemEquations {
    /// The forces of the line ends on their points: at a free point
    /// minus the line's rows there (the rows are dU/de - f, the force the
    /// point exerts on the line; the residual of `converged`); at a fixed
    /// or coupled point minus the line's reaction.
    pub(super) fn collect_end_forces(&mut self) {
        for (i, line) in self.lines.iter().enumerate() {
            let dpn = line.model.dofs_per_node();
            self.end_forces[i] = [EndForce::default(); 2];
            for AttachedEnd {
                end: k,
                point: p,
                node,
            } in self.system.attached_ends(i, &line.model)
            {
                let force = if self.system.points()[p].is_unknown() {
                    std::array::from_fn(|c| {
                        let g = coordinate(dpn, node, SLOT_R, c);
                        let u = line.layout.row_at(0, g).expect("a free end's row");
                        -self.residual_local[i][u]
                    })
                } else {
                    let r = line
                        .reactions
                        .iter()
                        .find(|(n, _)| *n == node)
                        .map_or([0.0; 3], |(_, f)| *f);
                    r.map(|f| -f)
                };
                self.end_forces[i][k] = EndForce { force };
            }
        }
    }
}
