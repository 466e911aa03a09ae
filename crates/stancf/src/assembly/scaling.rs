//! Scales of increments and residuals for the convergence tests
//! (docs/method.md §7.1, (M27)).

use super::layout::SlabLayout;
use super::Kind;
use crate::model::Model;

/// Scales that turn increments and residuals of a P2 step into fractions
/// of the cable length (docs/method.md §7.1, (M27)):
///
/// - an unknown e of kind r, r_x, r_xx is weighted by 1, l, l^2 (its effect
///   on the centre line inside an element), a velocity unknown also by h = dt/L;
/// - a row dA/de of coordinate c is weighted by h s_c / m_c, m_c the
///   diagonal of the mass matrix (kinetic part of the Jacobian ~ M / h),
///   a row dA/dv by s_c / m_c; a multiplier like its row, a constraint
///   equation like its unknown;
///
/// and everything is divided by the cable length.
#[derive(Clone, Debug)]
pub struct Scales {
    pub unknown: Vec<f64>,
    pub equation: Vec<f64>,
}

impl Scales {
    pub fn new(model: &Model, layout: &SlabLayout, layer_dt: f64) -> Self {
        let size = layout.size();
        let mut unknown = vec![0.0; size];
        let mut equation = vec![0.0; size];
        let mass = model.mass_diagonal();
        let len = model.cable.length;
        let dpn = layout.dpn;
        for g in 0..model.dofs() {
            let s = model.coordinate_length_scale(g / dpn, g % dpn) / len;
            let m = mass[g];
            for (slot, &(_, kind)) in layout.unknown_slots.iter().enumerate() {
                let w = match kind {
                    Kind::Position => s,
                    Kind::Velocity => s * layer_dt,
                };
                if let Some(u) = layout.unknown_at(slot, g) {
                    unknown[u] = w;
                }
                if let Some(r) = layout.constraint_row_at(slot, g) {
                    equation[r] = w;
                }
            }
            for (slot, &(_, kind)) in layout.row_slots.iter().enumerate() {
                let w = match kind {
                    Kind::Position => s * layer_dt / m,
                    Kind::Velocity => s / m,
                };
                if let Some(r) = layout.row_at(slot, g) {
                    equation[r] = w;
                }
                if let Some(u) = layout.multiplier_at(slot, g) {
                    unknown[u] = w;
                }
            }
        }
        // Direction holds: a multiplier like the r_x row it enters, an
        // equation n . r_x = 0 like an r_x unknown.
        for (h, hold) in model.constraints.directions.iter().enumerate() {
            let g = crate::model::coordinate(dpn, hold.node, crate::model::SLOT_R_X, 0);
            let (s, m) = (
                model.coordinate_length_scale(hold.node, g % dpn) / len,
                mass[g],
            );
            for k in 0..2 {
                for (slot, &(_, kind)) in layout.unknown_slots.iter().enumerate() {
                    if let Some(r) = layout.hold_row(h, slot, k) {
                        equation[r] = match kind {
                            Kind::Position => s,
                            Kind::Velocity => s * layer_dt,
                        };
                    }
                }
                for (slot, &(_, kind)) in layout.row_slots.iter().enumerate() {
                    if let Some(u) = layout.hold_multiplier(h, slot, k) {
                        unknown[u] = match kind {
                            Kind::Position => s * layer_dt / m,
                            Kind::Velocity => s / m,
                        };
                    }
                }
            }
        }
        Scales { unknown, equation }
    }

    /// max_i |w_i z_i|, NaN if any entry is not finite.
    pub fn norm(weights: &[f64], z: &[f64]) -> f64 {
        let mut m = 0.0f64;
        for (w, v) in weights.iter().zip(z.iter()) {
            let a = (w * v).abs();
            if !a.is_finite() {
                return f64::NAN;
            }
            m = m.max(a);
        }
        m
    }
}
