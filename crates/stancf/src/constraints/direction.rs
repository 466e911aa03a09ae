//! A line end clamped in a direction: r_x held parallel to a unit d by
//! n_1 . r_x = n_2 . r_x = 0 (docs/method.md §6.10, (M41)-(M42)).

use crate::error::ModelError;
use crate::vec3::{cross, dot, normalized, scale, sub};

/// r_x of `node` held parallel to `direction` by n . r_x = 0 for both
/// `normals` (docs/method.md §6.10, (M41)).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DirectionHold {
    pub node: usize,
    /// Unit direction d.
    pub direction: [f64; 3],
    /// n_1, n_2: with d, an orthonormal right-handed frame (d x n_1 = n_2).
    pub normals: [[f64; 3]; 2],
    /// Whether the frame turns with a free body the end is clamped to
    /// (docs/method.md §15.19): its equations and reactions then involve
    /// the body's unknowns and are the system's to assemble; the line's
    /// own assembly leaves them out (its layout keeps their multipliers
    /// and rows), and the frame here is the body's at the step's start.
    pub turning: bool,
}

impl DirectionHold {
    /// The hold of node's r_x along `direction` (finite, not zero; key
    /// `key` in errors).
    pub fn new(key: &str, node: usize, direction: [f64; 3]) -> Result<Self, ModelError> {
        let norm = direction.iter().map(|c| c * c).sum::<f64>().sqrt();
        if !norm.is_finite() || norm == 0.0 || direction.iter().any(|c| !c.is_finite()) {
            return Err(ModelError::invalid(
                format!("{key}.direction"),
                format!("must be a finite vector that is not zero, got {direction:?}"),
            ));
        }
        let d = direction.map(|c| c / norm);
        // The axis least aligned with d, made normal to it.
        let k = (0..3)
            .min_by(|&a, &b| d[a].abs().total_cmp(&d[b].abs()))
            .expect("3 axes");
        let mut e = [0.0; 3];
        e[k] = 1.0;
        let n1 = normalized(sub(e, scale(dot(d, e), d)));
        let n2 = cross(d, n1);
        Ok(DirectionHold {
            node,
            direction: d,
            normals: [n1, n2],
            turning: false,
        })
    }

    /// The same hold in the frame turned by `rotation`: d and n_k become
    /// R d and R n_k (a body's turn, from the frame at its given pose).
    pub fn turned(&self, rotation: &[[f64; 3]; 3]) -> Self {
        let turn = |v: [f64; 3]| crate::body::pose::rotate(rotation, v);
        DirectionHold {
            direction: turn(self.direction),
            normals: self.normals.map(turn),
            ..*self
        }
    }

    /// The generalized force Q = sum_k lambda_k n_k on r_x turned into
    /// the moment r_x x Q it exerts (from (M7): a moment M normal to r_x
    /// acts on r_x as Q = M x r_x / |r_x|^2, so M = r_x x Q).
    pub fn moment(r_x: [f64; 3], q: [f64; 3]) -> [f64; 3] {
        cross(r_x, q)
    }

    /// The rows of the held node's r_x in a mass solve M v = p at the end
    /// of a Galerkin step (docs/method.md §6.10, (M43)): the first is
    /// d . (M v - p) = 0, the other two the hold's rates n_k . v = 0 (the
    /// hold's impulse at t_b, a multiplier times n_k, takes the normal
    /// part of M v - p). A mass entry m of row r_x component `c` goes to
    /// the first row, weighted d_c ([`Self::mass_row_weight`]); these are
    /// the rows' constraint entries: (row 1 + k, component c, n_k c).
    pub fn rate_rows(&self) -> impl Iterator<Item = (usize, usize, f64)> + '_ {
        (0..2).flat_map(move |k| (0..3).map(move |c| (1 + k, c, self.normals[k][c])))
    }

    /// The weight d_c of a mass entry of r_x component c in the node's
    /// first r_x row (the others are [`Self::rate_rows`]).
    pub fn mass_row_weight(&self, c: usize) -> f64 {
        self.direction[c]
    }

    /// The right side of the three r_x rows from the momentum p_rx:
    /// (d . p_rx, 0, 0).
    pub fn momentum_rows(&self, p_rx: [f64; 3]) -> [f64; 3] {
        [dot(self.direction, p_rx), 0.0, 0.0]
    }
}
