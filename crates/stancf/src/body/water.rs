//! A body's water and what acts with it at its reference point
//! (docs/method.md §15.6, §15.11, §15.15, §15.21): MoorDyn's Volume, Ca
//! and CdA, the density, a uniform current or the sea, the body's rods,
//! and MoorDyn-F's external force and damping. Validated here; the terms
//! they give at a time point are `terms.rs`'.

use crate::water::kinematics::Sea;

/// A body's water: MoorDyn's Volume, Ca and CdA (body axes; the rotational
/// drag area multiplies Omega |Omega|, as MoorDyn's does), with the
/// water's density and a uniform steady current, and the body's rods,
/// whose buoyancy, added mass and drag the water adds over their parts
/// under the surface z = 0 (B18)-(B21; their mass is in the body's
/// inertia: [`crate::system::Body`] puts it there). `gravity` is g, along
/// -z: the rods' buoyancy is rho g times their wet volume.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct BodyWater {
    pub density: f64,
    pub volume: f64,
    pub added_mass_coefficients: [f64; 3],
    pub drag_areas: [f64; 3],
    pub rotational_drag_areas: [f64; 3],
    pub current: [f64; 3],
    pub rods: Vec<super::Rod>,
    pub gravity: f64,
    /// The sea whose waves and current act on the body where they are
    /// (§15.15): its velocity in the drag, its acceleration in the fluid's
    /// inertia, its dynamic pressure on the rods' caps. With a sea the
    /// uniform `current` above must be zero (the sea carries the current).
    pub sea: Option<std::sync::Arc<Sea>>,
    /// MoorDyn-F's EXTERNAL LOADS on the body at its reference point: a
    /// force fixed in the body's axes and damping along the global and the
    /// body's axes (docs/method.md §15.21, (B42)-(B43)). Carried with the
    /// water's loads, being virtual work at the same point; a body in air
    /// that has them takes a water of density 0.
    pub external: BodyExternal,
}

/// A force and damping at a body's reference point (MoorDyn-F's EXTERNAL
/// LOADS; a force in global axes is one of the body's constant loads).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct BodyExternal {
    /// A force fixed in the body's axes (N), following the body as it
    /// turns.
    pub body_force: [f64; 3],
    /// Damping of the reference point's velocity along the global axes.
    pub global: crate::damping::AxisDamping,
    /// Damping of the reference point's velocity along the body's axes.
    pub body: crate::damping::AxisDamping,
}

impl BodyExternal {
    /// Whether there is nothing.
    pub fn is_zero(&self) -> bool {
        self.body_force == [0.0; 3] && self.global.is_zero() && self.body.is_zero()
    }
}

impl BodyWater {
    /// Refuses a density, volume or coefficient that is negative or not
    /// finite, naming it.
    pub fn validate(&self, key: &str) -> Result<(), crate::error::ModelError> {
        let named = [
            ("density", vec![self.density]),
            ("volume", vec![self.volume]),
            (
                "added_mass_coefficients",
                self.added_mass_coefficients.to_vec(),
            ),
            ("drag_areas", self.drag_areas.to_vec()),
            ("rotational_drag_areas", self.rotational_drag_areas.to_vec()),
            ("gravity", vec![self.gravity]),
        ];
        for (name, values) in named {
            if values.iter().any(|v| !(v.is_finite() && *v >= 0.0)) {
                return Err(crate::error::ModelError::invalid(
                    format!("{key}.{name}"),
                    format!("{values:?}: must be finite and not negative"),
                ));
            }
        }
        for (k, rod) in self.rods.iter().enumerate() {
            rod.validate(&format!("{key}.rods[{k}]"))?;
        }
        if self.external.body_force.iter().any(|f| !f.is_finite()) {
            return Err(crate::error::ModelError::invalid(
                format!("{key}.body_force"),
                "must be finite",
            ));
        }
        self.external.global.check(&format!("{key}.global"))?;
        self.external.body.check(&format!("{key}.body"))?;
        if self.current.iter().any(|v| !v.is_finite()) {
            return Err(crate::error::ModelError::invalid(
                format!("{key}.current"),
                "must be finite",
            ));
        }
        if self.sea.is_some() && self.current != [0.0; 3] {
            return Err(crate::error::ModelError::invalid(
                format!("{key}.current"),
                "must be zero with a sea: the sea's current acts on the body",
            ));
        }
        Ok(())
    }
}
