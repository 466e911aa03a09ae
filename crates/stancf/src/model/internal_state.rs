//! The internal state of a line (docs/method.md §2.11-§2.12, §12.7): a
//! viscoelastic line carries the strain eps1 of its static spring at
//! every point of the axial rule of every element (a Syrope line also its
//! largest mean tension and the work done on its law), a line with VIV
//! the shedding phase phi and the mean squares A^2, B^2 there;
//! [`State::internal`], element after element, in each the viscoelastic
//! values of every axial point, then the VIV's. This file gives a model
//! its law and the state's layout, its rest value and the energy it
//! stores.

use super::{coordinate, gather, Mesh, Model, State, SLOT_R};
use crate::element::{Viscoelastic, Viv};
use crate::error::ModelError;

impl Model {
    /// The model whose lines follow the viscoelastic law `law` (static
    /// stiffness: the material's EA; docs/method.md §2.11). Refused on a
    /// line with a tension-strain curve or a Kelvin-Voigt BA (the law has
    /// its own dashpots), or a law that [`Viscoelastic::check`] refuses.
    ///
    /// A Syrope law (docs/method.md §2.12) brings its static law, the
    /// working curve of its Tmax0 and the original curve beyond
    /// ([`crate::element::Syrope::static_curve`]), as the line's
    /// tension-strain curve (engineering strain).
    pub fn with_viscoelastic(mut self, law: Viscoelastic) -> Result<Self, ModelError> {
        let ea = self.material.youngs_modulus * self.material.area;
        law.check(ea, "viscoelastic")?;
        if let crate::element::DynamicStiffness::Syrope { curves, tmax0 } = &law.dynamic {
            if self.has_axial_damping() {
                return Err(ModelError::invalid(
                    "viscoelastic",
                    "a Syrope line's damping is its law's two dashpots; the material's axial \
                     damping must be 0",
                ));
            }
            let points = curves.static_curve(*tmax0);
            let curve = crate::element::AxialCurve::new(&points, "syrope")?;
            self = self.with_axial_curve(std::sync::Arc::new(curve))?;
            return Ok(self.with_law(&law));
        }
        if self.axial_curve().is_some() {
            return Err(ModelError::invalid(
                "viscoelastic",
                "a line takes a tension-strain curve or a viscoelastic law, not both (MoorDyn's \
                 viscoelastic model uses a constant static EA)",
            ));
        }
        if self.has_axial_damping() {
            return Err(ModelError::invalid(
                "viscoelastic",
                "a viscoelastic line's damping is its law's two dashpots (BA beside the static \
                 spring, BA_D beside the dynamic one); the material's axial damping must be 0",
            ));
        }
        Ok(self.with_law(&law))
    }

    /// Every element of the model with the law `law`.
    fn with_law(mut self, law: &Viscoelastic) -> Self {
        match &mut self.mesh {
            Mesh::Sac2(els) => els
                .iter_mut()
                .for_each(|e| e.section.visco = Some(law.clone())),
            Mesh::Sac3(els) => els
                .iter_mut()
                .for_each(|e| e.section.visco = Some(law.clone())),
        }
        self
    }

    /// The line's viscoelastic law, if it has one.
    pub fn viscoelastic(&self) -> Option<&Viscoelastic> {
        crate::with_elements!(&self.mesh, els => els.first().and_then(|e| e.section.visco.as_ref()))
    }

    /// The model whose lines carry MoorDyn's VIV lift `viv`
    /// (docs/method.md §12.7), acting where the line is in water.
    /// Refused on a model without water (the lift acts in water only).
    pub fn with_viv(mut self, viv: Viv) -> Result<Self, ModelError> {
        viv.check("viv")?;
        if self.water.is_none() {
            return Err(ModelError::invalid(
                "viv",
                "the VIV lift acts in water: give the line a Load::Water",
            ));
        }
        match &mut self.mesh {
            Mesh::Sac2(els) => els
                .iter_mut()
                .for_each(|e| e.section.viv = Some(viv.clone())),
            Mesh::Sac3(els) => els
                .iter_mut()
                .for_each(|e| e.section.viv = Some(viv.clone())),
        }
        Ok(self)
    }

    /// The line's VIV law, if it has one.
    pub fn viv(&self) -> Option<&Viv> {
        crate::with_elements!(&self.mesh, els => els.first().and_then(|e| e.section.viv.as_ref()))
    }

    /// Whether a state of this model carries an internal state (a
    /// viscoelastic law's strains, a VIV's phases).
    pub fn has_internal_state(&self) -> bool {
        self.internal_values_per_point() > 0
    }

    /// The internal state's values per point of the axial rule: the
    /// viscoelastic law's, then the VIV's (phi, A^2, B^2).
    fn internal_values_per_point(&self) -> usize {
        crate::with_elements!(&self.mesh, els => els.first().map_or(0, |e| e.internal_values_per_point()))
    }

    /// The internal state's length: its values at every point of every
    /// element's axial rule (0 without a viscoelastic law or VIV).
    pub fn internal_state_len(&self) -> usize {
        let per = self.internal_values_per_point();
        crate::with_elements!(&self.mesh, els => els.iter().map(|e| e.axial_rule_points() * per).sum())
    }

    /// The internal state at rest at positions `e`: every axial point's
    /// eps1 where the law's rate vanishes, so the line carries EA eps,
    /// and the VIV's phases spread over 0..2 pi along the line with no
    /// mean squares (empty without either).
    pub fn rest_internal_state(&self, e: &[f64]) -> Vec<f64> {
        let dpn = self.dofs_per_node();
        let length = self.cable.length;
        crate::with_elements!(&self.mesh, els => {
            let mut x0 = 0.0;
            els.iter()
                .enumerate()
                .flat_map(|(k, el)| {
                    let rest = el.rest_internal(&gather(e, coordinate(dpn, k, SLOT_R, 0)), x0, length);
                    x0 += el.length;
                    rest
                })
                .collect()
        })
    }

    /// Element k's share of an internal state.
    pub fn element_internal<'a>(&self, internal: &'a [f64], k: usize) -> &'a [f64] {
        if internal.is_empty() {
            return internal;
        }
        let per = crate::with_elements!(&self.mesh, els => els[0].axial_rule_points())
            * self.internal_values_per_point();
        &internal[k * per..(k + 1) * per]
    }

    /// The energy stored in the springs of a viscoelastic line in `state`
    /// (docs/method.md §2.11, (V1)): sum over the axial points of
    /// 1/2 k1 eps1^2 + 1/2 k2 (eps - eps1)^2; 0 without a law.
    pub fn visco_stored_energy(&self, state: &State) -> f64 {
        if !self.has_internal_state() || state.internal.is_empty() {
            return 0.0;
        }
        let dpn = self.dofs_per_node();
        crate::with_elements!(&self.mesh, els => els
            .iter()
            .enumerate()
            .map(|(k, el)| {
                let q = gather(&state.e, coordinate(dpn, k, SLOT_R, 0));
                let (visco, _) = el.split_internal(self.element_internal(&state.internal, k));
                el.visco_stored_energy(&q, visco)
            })
            .sum())
    }

    /// Checks that `internal` fits the model: empty, or one value per
    /// axial point.
    pub(crate) fn check_internal_state(&self, internal: &[f64]) -> Result<(), ModelError> {
        let want = self.internal_state_len();
        if internal.is_empty() || internal.len() == want {
            return Ok(());
        }
        Err(ModelError::invalid(
            "state.internal",
            format!(
                "the internal state has {} values; this line has {want} (its values at each point of \
                 each element's axial rule{})",
                internal.len(),
                if want == 0 {
                    ", and no viscoelastic law or VIV"
                } else {
                    ""
                }
            ),
        ))
    }
}
