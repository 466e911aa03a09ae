//! A body's water and what acts with it at its reference point
//! (docs/method.md §15.6, §15.11, §15.15, §15.21): MoorDyn's Volume, Ca
//! and CdA, the density, a uniform current or the sea, the body's rods,
//! and MoorDyn-F's external force and damping. Validated here; the terms
//! they give at a time point are `terms.rs`'.

use super::rod::Rod;
use crate::water::host_flow::{FlowAt, NodeFlow};
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
    /// The water's velocity and local acceleration a host sets at the
    /// body (MoorDyn's `WaveKin 1`, docs/method.md §12.1, (W2h)): at its
    /// reference point and at each of its rods' nodes. Some only in a sea
    /// whose waves a host sets (still until it sets them).
    pub host: Option<BodyHostFlow>,
}

/// The host's flow at a body (W2h): at its reference point (MoorDyn asks
/// at a body's position), and at the N + 1 nodes of each of its rods
/// (`rods[k]` for the water's rod k; MoorDyn's rod of N segments has its
/// nodes evenly along it, node 0 at end A).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct BodyHostFlow {
    pub reference: FlowAt,
    pub rods: Vec<NodeFlow>,
}

impl BodyHostFlow {
    /// Still water at the reference point and at the nodes of `rods`.
    pub fn still(rods: &[Rod]) -> Self {
        BodyHostFlow {
            reference: ([0.0; 3], [0.0; 3]),
            rods: rods
                .iter()
                .map(|r| NodeFlow::still(r.segments + 1))
                .collect(),
        }
    }

    /// Refuses a flow that is not one node flow per rod of `rods`, each
    /// with the rod's N + 1 velocities and accelerations, or a value that
    /// is not finite, naming `key`.
    pub fn check(&self, rods: &[Rod], key: &str) -> Result<(), crate::error::ModelError> {
        let shaped = self.rods.len() == rods.len()
            && self.rods.iter().zip(rods).all(|(f, r)| {
                f.velocity.len() == r.segments + 1 && f.acceleration.len() == r.segments + 1
            });
        if !shaped {
            return Err(crate::error::ModelError::invalid(
                key,
                format!(
                    "the flow at {} rods given, the body has {}: one per rod, at its N + 1 nodes",
                    self.rods.len(),
                    rods.len()
                ),
            ));
        }
        let values = self
            .rods
            .iter()
            .flat_map(|f| f.velocity.iter().chain(&f.acceleration));
        let reference = [&self.reference.0, &self.reference.1];
        if reference
            .into_iter()
            .chain(values)
            .flatten()
            .any(|c| !c.is_finite())
        {
            return Err(crate::error::ModelError::invalid(key, "must be finite"));
        }
        Ok(())
    }

    /// (W2h): the flow at the point `xi` (body axes) of rod k: its
    /// nodes' values interpolated linearly along the rod (W2f), at the
    /// point's place s = (xi - A) . q along it (clamped to the rod).
    pub fn on_rod(&self, k: usize, rod: &Rod, xi: [f64; 3]) -> FlowAt {
        let nodes = &self.rods[k];
        let segments = nodes.velocity.len() - 1;
        if segments == 0 {
            return (nodes.velocity[0], nodes.acceleration[0]);
        }
        let along = crate::vec3::dot(crate::vec3::sub(xi, rod.end_a), rod.axis()) / rod.length();
        let place = (along.clamp(0.0, 1.0) * segments as f64).min(segments as f64);
        let element = (place.floor() as usize).min(segments - 1);
        nodes.element(element).at(place - element as f64)
    }
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
        if let Some(host) = &self.host {
            host.check(&self.rods, &format!("{key}.host"))?;
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

#[cfg(test)]
mod tests {
    use super::*;

    /// (W2h): a rod's host flow is its nodes' values at the nodes, linear
    /// between them along the rod, and its end nodes' beyond its ends (a
    /// cap's centre).
    #[test]
    fn a_rods_host_flow_is_its_nodes_values_linear_between_them() {
        let rod = Rod {
            end_a: [1.0, 0.0, -2.0],
            end_b: [1.0, 0.0, 4.0],
            diameter: 0.5,
            mass_per_length: 10.0,
            drag_coefficient: 1.0,
            added_mass_coefficient: 1.0,
            end_drag_coefficient: 0.5,
            end_added_mass_coefficient: 0.5,
            segments: 3,
        };
        let value = |s: f64| [s, 2.0 * s * s, -1.0];
        let mut host = BodyHostFlow::still(std::slice::from_ref(&rod));
        for j in 0..4 {
            host.rods[0].velocity[j] = value(j as f64);
            host.rods[0].acceleration[j] = value(10.0 + j as f64);
        }
        let at = |z: f64| host.on_rod(0, &rod, [1.0, 0.3, z]);
        // At the nodes (z = -2, 0, 2, 4).
        for j in 0..4 {
            let (u, a) = at(-2.0 + 2.0 * j as f64);
            assert_eq!(u, value(j as f64));
            assert_eq!(a, value(10.0 + j as f64));
        }
        // A quarter of the way from node 1 to node 2.
        let (u, _) = at(0.5);
        assert!((u[1] - (0.75 * 2.0 + 0.25 * 8.0)).abs() < 1e-14, "{u:?}");
        // Beyond the ends: the end nodes'.
        assert_eq!(at(-3.0).0, value(0.0));
        assert_eq!(at(5.0).0, value(3.0));
    }
}
