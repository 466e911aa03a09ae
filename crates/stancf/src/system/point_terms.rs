//! A free point's own share of its rows (docs/method.md §11.2): the slab
//! action of a point mass m under a constant force F (its weight m g and
//! any given force),
//!
//! ```text
//!   A_p = sum_g w_g dt ( m/2 |r_dot(t_g)|^2 + F . r(t_g) ),   r(t) = sum_m phi_m(t) y_m
//!   dA_p/dy_m = m sum_n C_mn y_n + b_m F,       d2A_p/dy_m dy_n = m C_mn I
//! ```
//!
//! with C and b the slab's kinetic and load weights (§3.1), plus the
//! momentum terms of the P2 rows, + m v_a on row e_0 and - m v_L on row
//! e_L (§4.3) (the Galerkin step: + p_a on row e_0 and no e_L row, the
//! end momentum [`PointTerms::end_momentum`] taking its place, §11.10);
//! in statics the row is - F. The lines attached at the point
//! add their own shares to the same rows (their end's coordinates are
//! the point's), so the rows state the point's balance of momentum.
//!
//! In water (docs/method.md §12.6) m includes the added mass and F the
//! buoyancy; the drag and the fluid's inertia f(r, r_dot, t) (W34) add
//! their virtual work at the slab's time points,
//!
//! ```text
//!   dA_p/dy_m += sum_g w_g dt phi_m f(r_g, r_dot_g, t_g)
//!   d2A_p/dy_m dy_n += sum_g w_g dt phi_m (phi_n df/dr + phidot_n df/dr_dot)
//! ```
//!
//! and in statics - f of the steady current at rest. A free point's
//! damping (B42) adds its force f(r_dot) the same way (zero at rest),
//! and so does the seabed's push on it (W42p), f(r, r_dot).

use super::point_bed::{add_force, steady_point_force, PointBed};
use crate::assembly::{Kind, SlabLayout};
use crate::damping::AxisDamping;
use crate::element::TimeSlab;
use crate::linear::AddEntries;
use crate::water::{PointForce, PointInWater};

/// The values of one free point at the time nodes of a step:
/// `e[i]`, `v[i]` at time node i (P2 and statics; the Galerkin step's
/// slopes in `v`).
#[derive(Clone, Debug, Default)]
pub struct PointNodes {
    pub e: Vec<[f64; 3]>,
    pub v: Vec<[f64; 3]>,
}

/// A free point's data for its terms: mass, load (already scaled by the
/// load factor), global indices of its unknowns (and rows) per slot.
pub struct PointTerms<'a> {
    /// The point's inertia: its mass and added mass.
    pub mass: f64,
    pub load: [f64; 3],
    /// The water's drag and inertia on the point, if in water.
    pub water: Option<&'a PointInWater>,
    /// The point's damping (B42), zero if none.
    pub damping: &'a AxisDamping,
    /// The seabed's push on the point (W42p), if a line attached there
    /// has a seabed.
    pub bed: Option<&'a PointBed>,
    /// The step's start time.
    pub time: f64,
    /// Global index of (slot, component): `index[3 slot + c]`.
    pub index: &'a [usize],
    pub layout: &'a SlabLayout,
    pub slab: &'a TimeSlab,
}

impl<'a> PointTerms<'a> {
    /// The terms of free point p of `system` in the step from `time`:
    /// its inertia, load and water (docs/method.md §11.2, §12.6).
    pub fn of(
        system: &'a super::Topology,
        p: usize,
        time: f64,
        index: &'a [usize],
        layout: &'a SlabLayout,
        slab: &'a TimeSlab,
    ) -> Self {
        PointTerms {
            mass: system.point_inertia(p),
            load: system.point_load(p),
            water: system.points()[p].water.as_ref(),
            damping: &system.points()[p].damping,
            bed: system.point_bed(p),
            time,
            index,
            layout,
            slab,
        }
    }

    /// Fills the time-node values from the unknowns `x` and the start
    /// (e_a, v_a).
    pub fn expand(&self, x: &[f64], e_a: [f64; 3], v_a: [f64; 3], nodes: &mut PointNodes) {
        let layout = self.layout;
        let count = layout.time_nodes();
        nodes.e.resize(count, [0.0; 3]);
        nodes.v.resize(count, [0.0; 3]);
        let known_start = layout.scheme.has_known_start();
        for i in 0..count {
            let (e0, v0) = if i == 0 && known_start {
                (e_a, v_a)
            } else {
                ([0.0; 3], [0.0; 3])
            };
            let se = layout.unknown_slot(i, Kind::Position);
            let sv = layout.unknown_slot(i, Kind::Velocity);
            for c in 0..3 {
                nodes.e[i][c] = se.map_or(e0[c], |s| x[self.index[3 * s + c]]);
                nodes.v[i][c] = sv.map_or(v0[c], |s| x[self.index[3 * s + c]]);
            }
        }
    }

    /// The Galerkin step's end momentum of the point, its share of
    /// p_b = dA/de_b (docs/method.md §5.1, §11.10): the gradient entry of
    /// the slot (1, e) that the step has no row for,
    /// `m sum_n C_(e_b) n y_n + b_(e_b) F`.
    pub fn end_momentum(&self, nodes: &PointNodes) -> [f64; 3] {
        let y = [nodes.e[0], nodes.v[0], nodes.e[1], nodes.v[1]];
        let mut p: [f64; 3] = std::array::from_fn(|c| {
            let mut p = self.slab.load[2] * self.load[c];
            for (b, yb) in y.iter().enumerate() {
                p += self.mass * self.slab.kinetic[2][b] * yb[c];
            }
            p
        });
        if self.has_own_forces() {
            for (tp, f) in self.own_forces(0, &y) {
                for c in 0..3 {
                    p[c] += tp.w_dt * tp.shape.t[2] * f.force[c];
                }
            }
        }
        p
    }

    /// The work of the water's drag and inertia (W34) and of the damping
    /// (B42) on the point over the step, and that of the bed's push
    /// (W42p): sum_layers sum_g w_g dt f_g . r_dot_g, from the expanded
    /// time-node values `nodes` (0 in air undamped off the bed), the same
    /// quadrature as their virtual work in the rows.
    pub fn own_work(&self, nodes: &PointNodes) -> (f64, f64) {
        let (mut water, mut bed) = (0.0, 0.0);
        if !self.has_own_forces() {
            return (water, bed);
        }
        for j in 0..self.layout.layers() {
            let y = [nodes.e[j], nodes.v[j], nodes.e[j + 1], nodes.v[j + 1]];
            let start = self.time + j as f64 * self.slab.dt;
            for tp in &self.slab.points {
                let (r, rdot) = motion_at(tp, &y);
                let power = |f: &PointForce| tp.w_dt * crate::vec3::dot(f.force, rdot);
                water += power(&self.water_force(&r, &rdot, start + tp.offset));
                if let Some(b) = self.bed {
                    bed += power(&b.force(&r, &rdot));
                }
            }
        }
        (water, bed)
    }

    /// Whether the point has forces of its motion: water, damping or the
    /// bed's push.
    pub fn has_own_forces(&self) -> bool {
        self.water.is_some() || !self.damping.is_zero() || self.bed.is_some()
    }

    /// The water's force (W34), the damping (B42) and the bed's push
    /// (W42p) at the time points of layer j, whose slot values are `y` =
    /// [e_j, v_j, e_j+1, v_j+1].
    fn own_forces<'s>(
        &'s self,
        j: usize,
        y: &'s [[f64; 3]; 4],
    ) -> impl Iterator<Item = (&'s crate::element::TimePoint, PointForce)> + 's {
        let start = self.time + j as f64 * self.slab.dt;
        self.slab.points.iter().map(move |tp| {
            let (r, rdot) = motion_at(tp, y);
            let mut f = self.water_force(&r, &rdot, start + tp.offset);
            if let Some(bed) = self.bed {
                add_force(&mut f, &bed.force(&r, &rdot));
            }
            (tp, f)
        })
    }

    /// The water's force (W34) and the damping (B42) on the point at r
    /// moving at r_dot at time t.
    fn water_force(&self, r: &[f64; 3], rdot: &[f64; 3], t: f64) -> PointForce {
        let mut f = self
            .water
            .map_or_else(PointForce::default, |w| w.force(r, rdot, t));
        if !self.damping.is_zero() {
            let (force, slope) = self.damping.force(*rdot);
            for c in 0..3 {
                f.force[c] += force[c];
                f.d_rdot[c][c] += slope[c];
            }
        }
        f
    }

    /// Adds the point's share to the rows and, if given, the Jacobian.
    pub fn add<J: AddEntries>(
        &self,
        nodes: &PointNodes,
        momentum_a: [f64; 3],
        residual: &mut [f64],
        mut jacobian: Option<&mut J>,
    ) {
        let layout = self.layout;
        if layout.scheme.is_static() {
            self.add_static(nodes, residual, jacobian);
            return;
        }
        let m = self.mass;
        for j in 0..layout.layers() {
            let slots = [
                (j, Kind::Position),
                (j, Kind::Velocity),
                (j + 1, Kind::Position),
                (j + 1, Kind::Velocity),
            ];
            let y = slots.map(|(i, kind)| match kind {
                Kind::Position => nodes.e[i],
                Kind::Velocity => nodes.v[i],
            });
            for (a, &(i, kind)) in slots.iter().enumerate() {
                let Some(rs) = layout.row_slot(i, kind) else {
                    continue;
                };
                for c in 0..3 {
                    let mut g = self.slab.load[a] * self.load[c];
                    for b in 0..4 {
                        g += m * self.slab.kinetic[a][b] * y[b][c];
                    }
                    residual[self.index[3 * rs + c]] += g;
                }
                if self.has_own_forces() {
                    self.add_water(j, (a, rs), &slots, &y, residual, jacobian.as_deref_mut());
                }
                let Some(jac) = jacobian.as_deref_mut() else {
                    continue;
                };
                for (b, &(i2, kind2)) in slots.iter().enumerate() {
                    let Some(cs) = layout.unknown_slot(i2, kind2) else {
                        continue;
                    };
                    let k = m * self.slab.kinetic[a][b];
                    if k != 0.0 {
                        for c in 0..3 {
                            jac.add(self.index[3 * rs + c], self.index[3 * cs + c], k);
                        }
                    }
                }
            }
        }
        let last = layout.layers();
        if let Some(s) = layout.row_slot(0, Kind::Position) {
            for c in 0..3 {
                residual[self.index[3 * s + c]] += momentum_a[c];
            }
        }
        if let (Some(rs), Some(cs)) = (
            layout.row_slot(last, Kind::Position),
            layout.unknown_slot(last, Kind::Velocity),
        ) {
            for c in 0..3 {
                residual[self.index[3 * rs + c]] -= m * nodes.v[last][c];
                if let Some(jac) = jacobian.as_deref_mut() {
                    jac.add(self.index[3 * rs + c], self.index[3 * cs + c], -m);
                }
            }
        }
    }

    /// The static rows: - F, and - f of the steady current at rest in
    /// water and of the bed's push (W42p), with its derivative.
    fn add_static<J: AddEntries>(
        &self,
        nodes: &PointNodes,
        residual: &mut [f64],
        jacobian: Option<&mut J>,
    ) {
        let Some(s) = self.layout.row_slot(0, Kind::Position) else {
            return;
        };
        for c in 0..3 {
            residual[self.index[3 * s + c]] -= self.load[c];
        }
        let Some(u) = self.layout.unknown_slot(0, Kind::Position) else {
            return;
        };
        if self.water.is_none() && self.bed.is_none() {
            return;
        }
        let f = steady_point_force(self.water, self.bed, &nodes.e[0]);
        for c in 0..3 {
            residual[self.index[3 * s + c]] -= f.force[c];
        }
        if let Some(jac) = jacobian {
            for c in 0..3 {
                for d in 0..3 {
                    jac.add(self.index[3 * s + c], self.index[3 * u + d], -f.d_r[c][d]);
                }
            }
        }
    }

    /// The water's virtual work on row slot `rs` (slot a of layer j's
    /// four) and its derivatives in the layer's unknowns.
    #[allow(clippy::too_many_arguments)]
    fn add_water<J: AddEntries>(
        &self,
        j: usize,
        (a, rs): (usize, usize),
        slots: &[(usize, Kind); 4],
        y: &[[f64; 3]; 4],
        residual: &mut [f64],
        mut jacobian: Option<&mut J>,
    ) {
        for (tp, f) in self.own_forces(j, y) {
            let wa = tp.w_dt * tp.shape.t[a];
            for c in 0..3 {
                residual[self.index[3 * rs + c]] += wa * f.force[c];
            }
            let Some(jac) = jacobian.as_deref_mut() else {
                continue;
            };
            for (b, &(i2, kind2)) in slots.iter().enumerate() {
                let Some(cs) = self.layout.unknown_slot(i2, kind2) else {
                    continue;
                };
                let (pb, pdb) = (tp.shape.t[b], tp.shape.t_dot[b]);
                for c in 0..3 {
                    for d in 0..3 {
                        let v = wa * (pb * f.d_r[c][d] + pdb * f.d_rdot[c][d]);
                        jac.add(self.index[3 * rs + c], self.index[3 * cs + d], v);
                    }
                }
            }
        }
    }
}

/// The point's position and velocity at time point `tp` of a layer whose
/// slot values are `y` = [e_j, v_j, e_j+1, v_j+1].
fn motion_at(tp: &crate::element::TimePoint, y: &[[f64; 3]; 4]) -> ([f64; 3], [f64; 3]) {
    let mut r = [0.0; 3];
    let mut rdot = [0.0; 3];
    for (m, ym) in y.iter().enumerate() {
        for c in 0..3 {
            r[c] += tp.shape.t[m] * ym[c];
            rdot[c] += tp.shape.t_dot[m] * ym[c];
        }
    }
    (r, rdot)
}
