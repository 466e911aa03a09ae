//! Where a coordinate falls on one axis of a rectilinear grid: the
//! shared cell search of the current grid (W9a) and the bathymetry
//! (W40a). Between nodes the weights are 1 - f and f, f = (c - c_i) /
//! (c_(i+1) - c_i), with slopes -+1 / (c_(i+1) - c_i); beyond the axis's
//! ends (and on an axis of one value) the end node weighs 1 with slope 0,
//! the field held at its edge. At a node the cell above it is used.

use crate::error::ModelError;

/// An axis of a grid: at least one value, each finite, strictly
/// increasing; refused naming `key[i]` (`axes.z[3]`).
pub(crate) fn check_axis(axis: &[f64], key: &str) -> Result<(), ModelError> {
    if axis.is_empty() {
        return Err(ModelError::invalid(key, "an axis needs at least one value"));
    }
    for (i, v) in axis.iter().enumerate() {
        if !v.is_finite() {
            return Err(ModelError::invalid(format!("{key}[{i}]"), "must be finite"));
        }
        if i > 0 && *v <= axis[i - 1] {
            return Err(ModelError::invalid(
                format!("{key}[{i}]"),
                format!(
                    "the axis must be strictly increasing: {v} after {}",
                    axis[i - 1]
                ),
            ));
        }
    }
    Ok(())
}

/// Where a coordinate falls along one axis: the two nodes of its cell,
/// the weights of each and their derivatives along the axis.
#[derive(Clone, Copy, Debug)]
pub(crate) struct AxisCell {
    pub(crate) nodes: [usize; 2],
    pub(crate) weights: [f64; 2],
    pub(crate) slopes: [f64; 2],
}

impl AxisCell {
    pub(crate) fn locate(axis: &[f64], c: f64) -> AxisCell {
        let n = axis.len();
        let held = |i: usize| AxisCell {
            nodes: [i, i],
            weights: [1.0, 0.0],
            slopes: [0.0, 0.0],
        };
        if n == 1 || c <= axis[0] {
            return held(0);
        }
        if c >= axis[n - 1] {
            return held(n - 1);
        }
        // axis[i] <= c < axis[i + 1]: the cell above a node.
        let i = axis.partition_point(|&a| a <= c) - 1;
        let span = axis[i + 1] - axis[i];
        let f = (c - axis[i]) / span;
        AxisCell {
            nodes: [i, i + 1],
            weights: [1.0 - f, f],
            slopes: [-1.0 / span, 1.0 / span],
        }
    }
}
