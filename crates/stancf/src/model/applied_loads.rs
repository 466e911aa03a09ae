//! The loads on the cable (docs/method.md §2.5-§2.8): gravity, point
//! forces, end moments and air drag; their validation, and the views of
//! them the assembly uses.

use super::validate::{check_positive, check_vector};
use super::Model;
use crate::error::ModelError;

/// A load on the cable.
#[derive(Clone, Debug, PartialEq)]
pub enum Load {
    /// Distributed weight rho A g, eq. (13).
    Gravity { acceleration: [f64; 3] },
    /// Constant force on the position of a node, eq. (14).
    PointForce { node: usize, force: [f64; 3] },
    /// Moment vector M n (N m) on the tangent r_x of a node, eqs. (15)-(16):
    /// work M theta, theta the rotation of r_x about n (see [`crate::loads`]).
    EndMoment { node: usize, moment: [f64; 3] },
    /// Air drag along the whole cable, eq. (17) (see [`crate::loads::AirDrag`]).
    AirDrag(crate::loads::AirDrag),
    /// Contact with a seabed, with friction (docs/method.md §12.2; see
    /// [`crate::water::SeabedContact`]). At most one per cable.
    Seabed(crate::water::SeabedContact),
    /// The water the cable is in: buoyancy, Morison drag, the fluid's
    /// inertia and the added mass (docs/method.md §12.3-12.5; see
    /// [`crate::water::LineInWater`]). At most one per cable.
    Water(crate::water::LineInWater),
}

/// Checks `loads` on a cable of `elements` elements and returns the sum of
/// the gravity loads and the drag loads.
pub(super) fn gravity_and_drag(
    loads: &[Load],
    elements: usize,
) -> Result<([f64; 3], Vec<crate::loads::AirDrag>), ModelError> {
    let mut gravity = [0.0; 3];
    let mut drag = Vec::new();
    for (i, load) in loads.iter().enumerate() {
        match load {
            Load::AirDrag(d) => {
                let k = format!("loads[{i}]");
                let nonneg = |name: &str, v: f64| -> Result<(), ModelError> {
                    if v.is_finite() && v >= 0.0 {
                        Ok(())
                    } else {
                        Err(ModelError::invalid(
                            format!("{k}.{name}"),
                            format!("must be a finite number >= 0, got {v}"),
                        ))
                    }
                };
                nonneg("drag_coefficient", d.drag_coefficient)?;
                nonneg("fluid_density", d.fluid_density)?;
                check_positive(&format!("{k}.diameter"), d.diameter)?;
                check_vector(&format!("{k}.fluid_velocity"), &d.fluid_velocity)?;
                if let crate::loads::DragModel::Normal {
                    tangential_coefficient,
                } = d.model
                {
                    nonneg("tangential_coefficient", tangential_coefficient)?;
                }
                drag.push(*d);
            }
            Load::Gravity { acceleration } => {
                check_vector(&format!("loads[{i}].acceleration"), acceleration)?;
                for c in 0..3 {
                    gravity[c] += acceleration[c];
                }
            }
            Load::Seabed(_) | Load::Water(_) => {}
            Load::PointForce { node, force: v } | Load::EndMoment { node, moment: v } => {
                let name = match load {
                    Load::PointForce { .. } => "force",
                    _ => "moment",
                };
                check_vector(&format!("loads[{i}].{name}"), v)?;
                if *node > elements {
                    return Err(ModelError::invalid(
                        format!("loads[{i}].node"),
                        format!("node {node} does not exist (nodes are 0..={elements})"),
                    ));
                }
            }
        }
    }
    Ok((gravity, drag))
}

/// The one seabed among `loads`, checked: a unit normal, finite point,
/// kBot > 0, cBot, friction coefficients >= 0, slip velocity > 0.
pub(super) fn seabed(loads: &[Load]) -> Result<Option<crate::water::SeabedContact>, ModelError> {
    let mut found = None;
    for (i, load) in loads.iter().enumerate() {
        let Load::Seabed(c) = load else { continue };
        let k = format!("loads[{i}]");
        if found.is_some() {
            return Err(ModelError::invalid(
                k,
                "a second seabed (a cable touches one)",
            ));
        }
        let bed = &c.seabed;
        // A grid was checked when it was built (`Bathymetry::new`).
        if let crate::water::BedSurface::Plane { point, normal } = &bed.surface {
            check_vector(&format!("{k}.point"), point)?;
            check_vector(&format!("{k}.normal"), normal)?;
            let norm = crate::vec3::dot(*normal, *normal).sqrt();
            if (norm - 1.0).abs() > 1e-12 {
                return Err(ModelError::invalid(
                    format!("{k}.normal"),
                    format!("must be a unit vector, has length {norm}"),
                ));
            }
        }
        check_positive(&format!("{k}.diameter"), c.diameter)?;
        check_positive(&format!("{k}.stiffness"), bed.stiffness)?;
        check_positive(&format!("{k}.slip_velocity"), bed.slip_velocity)?;
        for (name, v) in [
            ("damping", bed.damping),
            ("friction_axial", bed.friction_axial),
            ("friction_transverse", bed.friction_transverse),
        ] {
            if !(v.is_finite() && v >= 0.0) {
                return Err(ModelError::invalid(
                    format!("{k}.{name}"),
                    format!("must be a finite number >= 0, got {v}"),
                ));
            }
        }
        found = Some(c.clone());
    }
    Ok(found)
}

/// The one water load among `loads`, checked: a density >= 0, a
/// diameter > 0 and coefficients >= 0, all finite.
pub(super) fn water(loads: &[Load]) -> Result<Option<crate::water::LineInWater>, ModelError> {
    let mut found = None;
    for (i, load) in loads.iter().enumerate() {
        let Load::Water(w) = load else { continue };
        let k = format!("loads[{i}]");
        if found.is_some() {
            return Err(ModelError::invalid(
                k,
                "a second water load (a cable is in one water)",
            ));
        }
        check_positive(&format!("{k}.diameter"), w.morison.diameter)?;
        let m = &w.morison;
        for (name, v) in [
            ("density", w.water.density),
            ("cd_normal", m.cd_normal),
            ("cd_axial", m.cd_axial),
            ("ca_normal", m.ca_normal),
            ("ca_axial", m.ca_axial),
        ] {
            if !(v.is_finite() && v >= 0.0) {
                return Err(ModelError::invalid(
                    format!("{k}.{name}"),
                    format!("must be a finite number >= 0, got {v}"),
                ));
            }
        }
        found = Some(w.clone());
    }
    Ok(found)
}

impl Model {
    /// End moments: (node, moment vector).
    pub fn end_moments(&self) -> impl Iterator<Item = (usize, [f64; 3])> + '_ {
        self.loads.iter().filter_map(|l| match l {
            Load::EndMoment { node, moment } => Some((*node, *moment)),
            _ => None,
        })
    }

    /// Point forces acting on node j (summed).
    pub fn point_forces(&self) -> impl Iterator<Item = (usize, [f64; 3])> + '_ {
        self.loads.iter().filter_map(|l| match l {
            Load::PointForce { node, force } => Some((*node, *force)),
            _ => None,
        })
    }
}
