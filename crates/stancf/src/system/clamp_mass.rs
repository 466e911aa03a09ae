//! A line end clamped at a free body in the mass solve at a step's end
//! (docs/method.md §15.19, (B40)): the hold's rate n_k(b) . v_rx + c_k .
//! Omega = 0 in the turned r_x rows (M43), and its impulse, eliminated,
//! carried to the body's Omega rows.

use super::body_clamps::BodyClamp;
use super::layout::SystemLayout;
use crate::constraints::DirectionHold;
use crate::linear::AddEntries;
use crate::model::{coordinate, SLOT_R_X};
use crate::vec3::dot;

/// A mass entry (line, coordinates, value) of a row of r_x held by a
/// clamp at a free body, before (M43) turns the row.
pub(super) struct HeldEntry {
    pub line: usize,
    pub row: usize,
    pub column: usize,
    pub mass: f64,
}

/// A clamp at a free body in the mass solve at a step's end (B40): the
/// global indices of its r_x rows and of the body's Omega, the frame at
/// the end (world n_k, d) and the hold's rate arms c_k = n_k' x R_b^T r_x.
pub(super) struct ClampMass<'a> {
    clamp: &'a BodyClamp,
    layout: &'a SystemLayout,
    first: usize,
    omega: [usize; 3],
    arms: [[f64; 3]; 2],
    frame: DirectionHold,
}

impl<'a> ClampMass<'a> {
    /// The clamp at the step's end: the lines expanded (their end r_x),
    /// the bodies moved (their end rotation), the line's hold turned.
    pub fn of(
        clamp: &'a BodyClamp,
        layout: &'a SystemLayout,
        lines: &[crate::integrator::Simulation],
        bodies: &[super::body_terms::StepBody],
    ) -> Self {
        let line = &lines[clamp.line];
        let first = coordinate(line.model().dofs_per_node(), clamp.node, SLOT_R_X, 0);
        let body = bodies
            .iter()
            .find(|b| b.index == clamp.body)
            .expect("a clamp's body is free");
        let e = line.end_coordinates();
        let r_x = crate::body::pose::rotate_back(
            &body.body.rotation(),
            [e[first], e[first + 1], e[first + 2]],
        );
        ClampMass {
            clamp,
            layout,
            first,
            omega: std::array::from_fn(|j| {
                layout.body_unknown(clamp.body, 0, 3 + j).expect("free")
            }),
            arms: clamp.local.normals.map(|n| crate::vec3::cross(n, r_x)),
            frame: line.model().constraints.directions[clamp.hold],
        }
    }

    fn global(&self, g: usize) -> usize {
        let numbering = &self.layout.lines[self.clamp.line];
        self.layout.maps[self.clamp.line].global[numbering.unknown_at(0, g).expect("free")]
    }

    /// The hold's rates' Omega columns (n_k . v + c_k . Omega = 0 in the
    /// turned rows 1 + k), and the r_x rows' mass entries `held` carried
    /// to the body's Omega rows by - sum_k c_k n_k^T (B40).
    pub fn add_rows(&self, m: &mut crate::bordered::BorderedMatrix, held: &[HeldEntry]) {
        for k in 0..2 {
            let row = self.global(self.first + 1 + k);
            for j in 0..3 {
                m.add(row, self.omega[j], self.arms[k][j]);
            }
        }
        let own = |e: &&HeldEntry| {
            e.line == self.clamp.line && (self.first..self.first + 3).contains(&e.row)
        };
        for e in held.iter().filter(own) {
            let (c, column) = (e.row - self.first, self.global(e.column));
            for j in 0..3 {
                let w: f64 = (0..2)
                    .map(|k| self.arms[k][j] * self.frame.normals[k][c])
                    .sum();
                m.add(self.omega[j], column, -w * e.mass);
            }
        }
    }

    /// The right side: the line's r_x momentum `p` (its own, before
    /// (M43), with the clamp's share `extra` of (B39)) carried to the
    /// body's Omega rows by - sum_k c_k n_k . p, and `extra`'s part along
    /// d in the turned row d . (M v - p) = 0.
    pub fn add_momentum(&self, rates: &mut [f64], p: [f64; 3], extra: [f64; 3]) {
        rates[self.global(self.first)] += dot(self.frame.direction, extra);
        for j in 0..3 {
            let w: f64 = (0..2)
                .map(|k| self.arms[k][j] * dot(self.frame.normals[k], p))
                .sum();
            rates[self.omega[j]] -= w;
        }
    }
}
