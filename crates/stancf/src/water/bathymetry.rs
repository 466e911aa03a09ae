//! A seabed of varying depth (docs/method.md §12.2, (W40a)-(W40c)):
//! MoorDyn's 3-D seafloor, the height z = h(x, y) of the bed given at the
//! nodes of a rectilinear grid, bilinear in each cell and held at its edge
//! value beyond the grid, as MoorDyn's `Seafloor::getDepthAt`
//! interpolates it:
//!
//! ```text
//!   h(x, y) = sum over the cell's 4 corners w_x w_y h_corner          (W40a)
//! ```
//!
//! with the weights of [`super::grid_axis::AxisCell`]. Its slopes h_x,
//! h_y are piecewise linear and its twist h_xy piecewise constant (the
//! bilinear's only second derivative); beyond the grid the held
//! direction's slope and the twist are 0.
//!
//! The contact of (W40)-(W46) is on the bed's local tangent plane: at a
//! point r = (x, y, z) of a line, the plane that touches the surface
//! above it, with upward normal and penetration
//!
//! ```text
//!   N = (-h_x, -h_y, 1),  m = |N|,  n = N / m,
//!   g = (h(x, y) - z) / m                                              (W40b)
//! ```
//!
//! (the depth below the surface times the cosine of its slope: the
//! distance to that plane). On a plane bed, g and n are (W40)'s exactly.
//! Their derivatives in r, for the contact's Jacobian, with
//! dN/dx = (0, -h_xy, 0), dN/dy = (-h_xy, 0, 0), dN/dz = 0:
//!
//! ```text
//!   dm/dr = n^T dN/dr = -h_xy (n_y, n_x, 0),
//!   dn/dr = (I - n n^T) dN/dr / m,
//!   dg/dr = -n - (g / m) dm/dr                                         (W40c)
//! ```
//!
//! (dg/dr = -n on a plane, where h_xy = 0).

use super::grid_axis::{check_axis, AxisCell};
use crate::error::ModelError;

/// A seabed's height on a rectilinear grid (W40a).
#[derive(Clone, Debug, PartialEq)]
pub struct Bathymetry {
    /// x and y (m), each strictly increasing, at least one value.
    axes: [Vec<f64>; 2],
    /// The bed's height z (m, up; the still surface z = 0) at node (i, j),
    /// at index i n_y + j.
    heights: Vec<f64>,
}

/// The bed's height and its derivatives above a point (W40a).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct BedHeight {
    /// h (m).
    pub height: f64,
    /// (h_x, h_y).
    pub slope: [f64; 2],
    /// h_xy (1/m).
    pub twist: f64,
}

/// The local contact geometry at a point (W40b)-(W40c): penetration g
/// (> 0 in the bed), the upward unit normal n and their derivatives in
/// the point's position.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct BedPoint {
    pub penetration: f64,
    pub normal: [f64; 3],
    /// dg/dr.
    pub d_penetration: [f64; 3],
    /// `[i][j] = dn_i / dr_j` (zero on a plane).
    pub d_normal: [[f64; 3]; 3],
}

impl Bathymetry {
    /// A bed from its axes x, y (m) and the heights z (m) at its nodes,
    /// node (i, j) at index i n_y + j. Refused, naming the key: an empty
    /// axis or one not strictly increasing (`axes.y[3]`), a height that is
    /// not finite (`heights[12]`), a count of heights other than the
    /// nodes'.
    pub fn new(axes: [Vec<f64>; 2], heights: Vec<f64>) -> Result<Self, ModelError> {
        for (axis, name) in axes.iter().zip(["x", "y"]) {
            check_axis(axis, &format!("axes.{name}"))?;
        }
        let nodes = axes[0].len() * axes[1].len();
        if heights.len() != nodes {
            return Err(ModelError::invalid(
                "heights",
                format!("{} heights for the grid's {nodes} nodes", heights.len()),
            ));
        }
        if let Some(i) = heights.iter().position(|h| !h.is_finite()) {
            return Err(ModelError::invalid(
                format!("heights[{i}]"),
                "must be finite",
            ));
        }
        Ok(Bathymetry { axes, heights })
    }

    /// The axes x, y.
    pub fn axes(&self) -> &[Vec<f64>; 2] {
        &self.axes
    }

    /// The heights at the nodes, in the order of [`Bathymetry::new`].
    pub fn heights(&self) -> &[f64] {
        &self.heights
    }

    /// The mean of the nodes' heights: MoorDyn's "average depth", which
    /// becomes its water depth (with the sign turned) when a deck gives a
    /// seafloor file.
    pub fn mean_height(&self) -> f64 {
        self.heights.iter().sum::<f64>() / self.heights.len() as f64
    }

    /// The lowest and the highest node.
    pub fn height_range(&self) -> (f64, f64) {
        self.heights
            .iter()
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), h| {
                (lo.min(*h), hi.max(*h))
            })
    }

    /// The height and its derivatives above (x, y) (W40a).
    pub fn height(&self, x: f64, y: f64) -> BedHeight {
        let cx = AxisCell::locate(&self.axes[0], x);
        let cy = AxisCell::locate(&self.axes[1], y);
        let ny = self.axes[1].len();
        let mut out = BedHeight::default();
        for a in 0..2 {
            for b in 0..2 {
                let h = self.heights[cx.nodes[a] * ny + cy.nodes[b]];
                out.height += cx.weights[a] * cy.weights[b] * h;
                out.slope[0] += cx.slopes[a] * cy.weights[b] * h;
                out.slope[1] += cx.weights[a] * cy.slopes[b] * h;
                out.twist += cx.slopes[a] * cy.slopes[b] * h;
            }
        }
        out
    }

    /// The contact geometry (W40b)-(W40c) at r.
    pub fn contact_point(&self, r: &[f64; 3]) -> BedPoint {
        let BedHeight {
            height,
            slope: [hx, hy],
            twist,
        } = self.height(r[0], r[1]);
        let big_n = [-hx, -hy, 1.0];
        let m = (hx * hx + hy * hy + 1.0).sqrt();
        let n = big_n.map(|c| c / m);
        let g = (height - r[2]) / m;
        // dN/dr: columns x, y, z.
        let dn_big = [[0.0, -twist, 0.0], [-twist, 0.0, 0.0], [0.0; 3]];
        let dm = [-twist * n[1], -twist * n[0], 0.0];
        let d_normal = std::array::from_fn(|i| {
            std::array::from_fn(|j| {
                let projected: f64 = (0..3)
                    .map(|k| (f64::from(u8::from(i == k)) - n[i] * n[k]) * dn_big[k][j])
                    .sum();
                projected / m
            })
        });
        let d_penetration = std::array::from_fn(|j| -n[j] - g / m * dm[j]);
        BedPoint {
            penetration: g,
            normal: n,
            d_penetration,
            d_normal,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A 3 x 4 grid of uneven spacing with a twist in every cell.
    fn bed() -> Bathymetry {
        let xs = vec![-10.0, 0.0, 25.0];
        let ys = vec![-5.0, 0.0, 3.0, 10.0];
        let heights = (0..12)
            .map(|k| {
                let (i, j) = (k / 4, k % 4);
                -50.0 + 0.1 * xs[i] - 0.05 * ys[j] + 0.002 * xs[i] * ys[j] + [0.0, 0.3][k % 2]
            })
            .collect();
        Bathymetry::new([xs, ys], heights).unwrap()
    }

    #[test]
    fn the_surface_passes_through_its_nodes_and_holds_its_edges() {
        let b = bed();
        for (i, x) in b.axes()[0].iter().enumerate() {
            for (j, y) in b.axes()[1].iter().enumerate() {
                assert_eq!(b.height(*x, *y).height, b.heights()[i * 4 + j]);
            }
        }
        // Beyond x's end: the edge's value, no slope along x, no twist.
        let inside = b.height(25.0, 1.0);
        let beyond = b.height(40.0, 1.0);
        assert_eq!(beyond.height, inside.height);
        assert_eq!((beyond.slope[0], beyond.twist), (0.0, 0.0));
    }

    /// A plane given on a grid is the plane: height to round-off, the
    /// slope exactly its gradient up to round-off, no twist.
    #[test]
    fn a_plane_on_a_grid_is_the_plane() {
        let xs = vec![-20.0, -5.0, 10.0, 40.0];
        let ys = vec![-3.0, 4.0];
        let plane = |x: f64, y: f64| -30.0 + 0.125 * x - 0.25 * y;
        let heights = xs
            .iter()
            .flat_map(|x| ys.iter().map(move |y| plane(*x, *y)))
            .collect();
        let b = Bathymetry::new([xs, ys], heights).unwrap();
        for (x, y) in [(-12.3, 0.7), (7.0, -2.9), (33.3, 3.9)] {
            let h = b.height(x, y);
            assert!((h.height - plane(x, y)).abs() <= 1e-13 * 30.0);
            assert!((h.slope[0] - 0.125).abs() <= 1e-15 && (h.slope[1] + 0.25).abs() <= 1e-15);
            assert!(h.twist.abs() <= 1e-16);
        }
    }

    /// (W40c) against central differences of (W40b) inside cells, where
    /// the surface is smooth: h = 1e-6 m puts round-off (eps 50 / h =
    /// 1e-8) and truncation (h^2 times the third derivatives, O(1e-12))
    /// below 1e-7.
    #[test]
    fn the_contact_geometry_derivatives_match_finite_differences() {
        let b = bed();
        for r in [[-4.1, -2.2, -52.0], [12.5, 6.3, -47.9], [3.3, 1.1, -51.0]] {
            let p = b.contact_point(&r);
            let h = 1e-6;
            for j in 0..3 {
                let (mut plus, mut minus) = (r, r);
                plus[j] += h;
                minus[j] -= h;
                let (pp, pm) = (b.contact_point(&plus), b.contact_point(&minus));
                let dg = (pp.penetration - pm.penetration) / (2.0 * h);
                assert!((dg - p.d_penetration[j]).abs() <= 1e-7, "dg/dr{j}");
                for i in 0..3 {
                    let dn = (pp.normal[i] - pm.normal[i]) / (2.0 * h);
                    assert!((dn - p.d_normal[i][j]).abs() <= 1e-7, "dn{i}/dr{j}");
                }
            }
            let n = p.normal;
            assert!(((n[0] * n[0] + n[1] * n[1] + n[2] * n[2]).sqrt() - 1.0).abs() < 1e-15);
        }
    }

    #[test]
    fn a_bad_grid_is_refused_by_name() {
        let key = |r: Result<Bathymetry, ModelError>| r.unwrap_err().key;
        assert_eq!(
            key(Bathymetry::new([vec![0.0, 0.0], vec![1.0]], vec![0.0; 2])),
            "axes.x[1]"
        );
        assert_eq!(
            key(Bathymetry::new([vec![0.0], vec![1.0]], vec![0.0; 2])),
            "heights"
        );
        assert_eq!(
            key(Bathymetry::new(
                [vec![0.0, 1.0], vec![1.0]],
                vec![0.0, f64::NAN]
            )),
            "heights[1]"
        );
    }
}
