//! The momentum and kinetic energy of a line with the water it entrains
//! (docs/method.md §12.5, (W30)-(W31)): p = M v + dT_a/dv, a function of
//! the configuration as well as of the rates, and the configuration's
//! mass matrix M + M_a(e).

use super::{coordinate, gather, Model, SLOT_R};
use crate::water::AddedMass;

impl Model {
    /// The line's added mass, if it is in water with a nonzero coefficient.
    pub fn added_mass(&self) -> Option<AddedMass> {
        self.water.as_ref().and_then(AddedMass::of)
    }

    /// The momentum p = M v + dT_a/dv at coordinates `e` and rates `v`
    /// (W30); M v without added mass.
    pub fn momentum(&self, e: &[f64], v: &[f64], p: &mut [f64]) {
        self.mass_times(v, p);
        let Some(am) = self.added_mass() else {
            return;
        };
        let dpn = self.dofs_per_node();
        crate::with_elements!(&self.mesh, els => {
            for (k, el) in els.iter().enumerate() {
                let o = coordinate(dpn, k, SLOT_R, 0);
                let mut pk = [0.0; _];
                el.entrained_momentum(&am, (&gather(e, o), &gather(v, o)), &mut pk, None);
                for (d, pd) in pk.iter().enumerate() {
                    p[o + d] += pd;
                }
            }
        });
    }

    /// T_a of the whole line at coordinates `e` and rates `v` (W28); zero
    /// without added mass.
    pub fn entrained_energy(&self, e: &[f64], v: &[f64]) -> f64 {
        let Some(am) = self.added_mass() else {
            return 0.0;
        };
        let dpn = self.dofs_per_node();
        crate::with_elements!(&self.mesh, els => {
            let mut energy = 0.0;
            for (k, el) in els.iter().enumerate() {
                let o = coordinate(dpn, k, SLOT_R, 0);
                let (mut dq, mut dv) = ([0.0; _], [0.0; _]);
                let pair = (&gather(e, o), &gather(v, o));
                energy += el.entrained_energy(&am, pair, &mut dq, &mut dv, None);
            }
            energy
        })
    }

    /// Calls `add(a, b, value)` with the entries of the added mass matrix
    /// M_a(e) (W31), element by element (entries repeat where elements
    /// share a node); nothing without added mass.
    pub fn for_entrained_mass(&self, e: &[f64], mut add: impl FnMut(usize, usize, f64)) {
        let Some(am) = self.added_mass() else {
            return;
        };
        let dpn = self.dofs_per_node();
        crate::with_elements!(&self.mesh, els => {
            let mut block = [[0.0; _]; _];
            for (k, el) in els.iter().enumerate() {
                let o = coordinate(dpn, k, SLOT_R, 0);
                el.entrained_mass(&am, &gather(e, o), &mut block);
                for (a, row) in block.iter().enumerate() {
                    for (b, &val) in row.iter().enumerate() {
                        add(o + a, o + b, val);
                    }
                }
            }
        });
    }

    /// Calls `add(a, b, dp_a/de_b, dp_a/dv_b)` with the derivatives of
    /// the entrained momentum dT_a/dv at (e, v) (the X and V of (W28)),
    /// element by element; nothing without added mass.
    pub fn for_entrained_momentum_derivatives(
        &self,
        e: &[f64],
        v: &[f64],
        mut add: impl FnMut(usize, usize, f64, f64),
    ) {
        let Some(am) = self.added_mass() else {
            return;
        };
        let dpn = self.dofs_per_node();
        crate::with_elements!(&self.mesh, els => {
            let (mut de, mut dv) = ([[0.0; _]; _], [[0.0; _]; _]);
            for (k, el) in els.iter().enumerate() {
                let o = coordinate(dpn, k, SLOT_R, 0);
                let mut p = [0.0; _];
                let pair = (&gather(e, o), &gather(v, o));
                el.entrained_momentum(&am, pair, &mut p, Some((&mut de, &mut dv)));
                for a in 0..de.len() {
                    for b in 0..de.len() {
                        add(o + a, o + b, de[a][b], dv[a][b]);
                    }
                }
            }
        });
    }
}
