//! Currents that vary in space and time, given on a rectilinear grid
//! (docs/method.md §12.1, (W9a)-(W9b)): MoorDyn's dynamic current
//! profile (x, y fixed) and its 4-D current grid.
//!
//! The grid has axes x_i, y_j, z_k, t_l, each strictly increasing with
//! at least one value, and a velocity at every node. Between nodes the
//! current is multilinear; beyond an axis's ends it holds the end value
//! (a one-value axis is constant along it):
//!
//! ```text
//!   U(x, y, z, t) = sum over the 16 corners of the cell
//!                   w_x w_y w_z w_t U_corner,
//!   w = 1 - f or f,  f = (c - c_i) / (c_(i+1) - c_i) in [0, 1]      (W9a)
//! ```
//!
//! Its derivatives are those of the interpolant: along an axis, w is
//! replaced by dw/dc = -+1 / (c_(i+1) - c_i) inside the axis's range and
//! by 0 outside it, so that
//!
//! ```text
//!   dU/dx_j,  a = dU/dt,  da/dx_j = d2U / dt dx_j                   (W9b)
//! ```
//!
//! are piecewise constant in the cell (the mixed derivative included):
//! the exact derivatives of the field the loads see, with kinks at the
//! grid's planes. At a node the cell above it is used.

use super::grid_axis::{check_axis, AxisCell};
use crate::error::ModelError;

/// A current on a rectilinear grid in x, y, z and t (W9a).
#[derive(Clone, Debug, PartialEq)]
pub struct CurrentGrid {
    /// x, y, z (m) and t (s), each strictly increasing, at least one.
    axes: [Vec<f64>; 4],
    /// The velocity (m/s) at node (i, j, k, l), at index
    /// ((i n_y + j) n_z + k) n_t + l.
    velocity: Vec<[f64; 3]>,
}

/// The current and its derivatives at a point and time (W9b).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct CurrentSample {
    pub velocity: [f64; 3],
    /// `[i][j] = dU_i / dx_j`.
    pub velocity_gradient: [[f64; 3]; 3],
    /// dU/dt at the fixed point.
    pub acceleration: [f64; 3],
    /// `[i][j] = d2U_i / dt dx_j`.
    pub acceleration_gradient: [[f64; 3]; 3],
}

const AXIS_NAMES: [&str; 4] = ["x", "y", "z", "t"];

impl CurrentGrid {
    /// A grid from its axes (x, y, z in m, t in s) and the velocities at
    /// its nodes, node (i, j, k, l) at index ((i n_y + j) n_z + k) n_t + l.
    /// Refused, naming the key: an empty axis, an axis not strictly
    /// increasing (`axes.z[3]`), a value that is not finite
    /// (`velocity[12]`), a count of velocities other than the nodes'.
    pub fn new(axes: [Vec<f64>; 4], velocity: Vec<[f64; 3]>) -> Result<Self, ModelError> {
        for (axis, name) in axes.iter().zip(AXIS_NAMES) {
            check_axis(axis, &format!("axes.{name}"))?;
        }
        let nodes: usize = axes.iter().map(Vec::len).product();
        if velocity.len() != nodes {
            return Err(ModelError::invalid(
                "velocity",
                format!("{} velocities for the grid's {nodes} nodes", velocity.len()),
            ));
        }
        if let Some(i) = velocity
            .iter()
            .position(|v| v.iter().any(|c| !c.is_finite()))
        {
            return Err(ModelError::invalid(
                format!("velocity[{i}]"),
                "must be finite",
            ));
        }
        Ok(CurrentGrid { axes, velocity })
    }

    /// The axes x, y, z, t.
    pub fn axes(&self) -> &[Vec<f64>; 4] {
        &self.axes
    }

    /// The velocities at the nodes, in the order of [`CurrentGrid::new`].
    pub fn velocities(&self) -> &[[f64; 3]] {
        &self.velocity
    }

    fn index(&self, node: [usize; 4]) -> usize {
        let [_, ny, nz, nt] = [0, 1, 2, 3].map(|a| self.axes[a].len());
        ((node[0] * ny + node[1]) * nz + node[2]) * nt + node[3]
    }

    /// The current and its derivatives (W9a)-(W9b) at `position` and
    /// time `t`.
    pub fn sample(&self, position: &[f64; 3], t: f64) -> CurrentSample {
        let at = [position[0], position[1], position[2], t];
        let cells: [AxisCell; 4] = std::array::from_fn(|a| AxisCell::locate(&self.axes[a], at[a]));
        let mut out = CurrentSample::default();
        for corner in 0..16 {
            let side: [usize; 4] = std::array::from_fn(|a| (corner >> a) & 1);
            let node: [usize; 4] = std::array::from_fn(|a| cells[a].nodes[side[a]]);
            let w: [f64; 4] = std::array::from_fn(|a| cells[a].weights[side[a]]);
            let s: [f64; 4] = std::array::from_fn(|a| cells[a].slopes[side[a]]);
            // The far side of a held axis weighs nothing in any product.
            if (0..4).any(|a| w[a] == 0.0 && s[a] == 0.0) {
                continue;
            }
            let u = self.velocity[self.index(node)];
            // The product of the weights with axis `d` (and `e`) replaced
            // by its slope.
            let product = |d: Option<usize>, e: Option<usize>| -> f64 {
                (0..4)
                    .map(|a| {
                        if Some(a) == d || Some(a) == e {
                            s[a]
                        } else {
                            w[a]
                        }
                    })
                    .product()
            };
            let value = product(None, None);
            let rate = product(Some(3), None);
            for i in 0..3 {
                out.velocity[i] += value * u[i];
                out.acceleration[i] += rate * u[i];
                for j in 0..3 {
                    out.velocity_gradient[i][j] += product(Some(j), None) * u[i];
                    out.acceleration_gradient[i][j] += product(Some(j), Some(3)) * u[i];
                }
            }
        }
        out
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A field linear in each of x, y, z, t with every cross term (a
    /// multilinear field) on an uneven grid is reproduced exactly by
    /// (W9a) inside the grid, and its derivatives (W9b) are the field's.
    fn field(p: [f64; 4]) -> [f64; 3] {
        let [x, y, z, t] = p;
        [
            0.3 + 0.01 * x - 0.02 * y + 0.005 * z * t + 0.001 * x * y * z * t,
            -0.1 + 0.03 * t + 0.002 * x * z,
            0.02 * y * t - 0.004 * z,
        ]
    }

    fn grid() -> CurrentGrid {
        let axes = [
            vec![-10.0, 0.0, 25.0],
            vec![-3.0, 4.0],
            vec![-50.0, -20.0, -5.0, 0.0],
            vec![0.0, 10.0, 40.0],
        ];
        let mut velocity = Vec::new();
        for &x in &axes[0] {
            for &y in &axes[1] {
                for &z in &axes[2] {
                    for &t in &axes[3] {
                        velocity.push(field([x, y, z, t]));
                    }
                }
            }
        }
        CurrentGrid::new(axes, velocity).unwrap()
    }

    #[test]
    fn a_multilinear_field_is_reproduced_with_its_derivatives() {
        let g = grid();
        for p in [
            [-4.0, 1.0, -33.0, 7.0],
            [12.0, -2.5, -3.0, 31.0],
            [0.0, 4.0 - 1e-9, -20.0, 10.0],
        ] {
            let s = g.sample(&[p[0], p[1], p[2]], p[3]);
            let want = field(p);
            let h = 1e-4;
            for i in 0..3 {
                assert!((s.velocity[i] - want[i]).abs() < 1e-13, "{p:?}: {s:?}");
                // Central differences of a field that is linear along each
                // axis inside a cell: exact but for round-off.
                let along = |d: usize, q: [f64; 4]| {
                    let (mut a, mut b) = (q, q);
                    a[d] += h;
                    b[d] -= h;
                    (field(a)[i] - field(b)[i]) / (2.0 * h)
                };
                let rate = along(3, p);
                assert!((s.acceleration[i] - rate).abs() < 1e-9, "{p:?}: {s:?}");
                for j in 0..3 {
                    let g = along(j, p);
                    assert!((s.velocity_gradient[i][j] - g).abs() < 1e-9, "{p:?} {i}{j}");
                    let (mut a, mut b) = (p, p);
                    a[3] += h;
                    b[3] -= h;
                    let mixed = (along(j, a) - along(j, b)) / (2.0 * h);
                    assert!(
                        (s.acceleration_gradient[i][j] - mixed).abs() < 1e-7,
                        "{p:?} {i}{j}: {} against {mixed}",
                        s.acceleration_gradient[i][j]
                    );
                }
            }
        }
    }

    /// Beyond an axis's ends the current holds its end value and does
    /// not change along that axis.
    #[test]
    fn beyond_the_grid_the_current_holds_its_edge() {
        let g = grid();
        let s = g.sample(&[40.0, 1.0, -60.0], 100.0);
        let want = field([25.0, 1.0, -50.0, 40.0]);
        for i in 0..3 {
            assert!((s.velocity[i] - want[i]).abs() < 1e-13);
            assert_eq!(s.acceleration[i], 0.0);
            assert_eq!(s.velocity_gradient[i][0], 0.0);
            assert_eq!(s.velocity_gradient[i][2], 0.0);
        }
    }

    #[test]
    fn a_grid_out_of_order_or_short_of_velocities_is_refused_naming_the_key() {
        let e = CurrentGrid::new(
            [vec![0.0], vec![0.0], vec![-1.0, -2.0], vec![0.0]],
            vec![[0.0; 3]; 2],
        )
        .unwrap_err();
        assert_eq!(e.key, "axes.z[1]");
        let e = CurrentGrid::new(
            [vec![0.0], vec![0.0], vec![-2.0, -1.0], vec![0.0, 1.0]],
            vec![[0.0; 3]; 3],
        )
        .unwrap_err();
        assert_eq!(e.key, "velocity");
        let e = CurrentGrid::new([vec![], vec![0.0], vec![0.0], vec![0.0]], vec![]).unwrap_err();
        assert_eq!(e.key, "axes.x");
    }
}
