//! Validation of the model data: finite, positive figures and finite
//! vectors, with the key of the offending entry (docs/method.md §1.1).

use super::{Cable, Material};
use crate::error::ModelError;

pub(super) fn check_positive(key: &str, value: f64) -> Result<(), ModelError> {
    if !value.is_finite() {
        return Err(ModelError::invalid(
            key,
            format!("must be a finite number, got {value}"),
        ));
    }
    if value <= 0.0 {
        return Err(ModelError::invalid(
            key,
            format!("must be > 0, got {value}"),
        ));
    }
    Ok(())
}

pub(super) fn check_vector(key: &str, v: &[f64; 3]) -> Result<(), ModelError> {
    if v.iter().any(|x| !x.is_finite()) {
        return Err(ModelError::invalid(
            key,
            format!("must have finite components, got {v:?}"),
        ));
    }
    Ok(())
}

/// Checks the cable and returns it with its direction normalized.
pub(super) fn cable(cable: Cable) -> Result<Cable, ModelError> {
    check_positive("cable.length", cable.length)?;
    if cable.elements == 0 {
        return Err(ModelError::invalid(
            "cable.elements",
            "must be at least 1, got 0",
        ));
    }
    if cable.elements > super::MAX_ELEMENTS {
        return Err(ModelError::invalid(
            "cable.elements",
            format!(
                "{} is above the {} elements a cable or line may have",
                cable.elements,
                super::MAX_ELEMENTS
            ),
        ));
    }
    cable.grading.check(cable.length, cable.elements)?;
    check_vector("cable.origin", &cable.origin)?;
    check_vector("cable.direction", &cable.direction)?;
    let norm = crate::vec3::dot(cable.direction, cable.direction).sqrt();
    if norm == 0.0 {
        return Err(ModelError::invalid(
            "cable.direction",
            "must not be the zero vector",
        ));
    }
    let mut cable = cable;
    cable.direction = cable.direction.map(|c| c / norm);
    Ok(cable)
}

/// Checks that every material figure is finite and positive (the axial
/// damping finite and >= 0).
pub(super) fn material(material: &Material) -> Result<(), ModelError> {
    check_positive("material.youngs_modulus", material.youngs_modulus)?;
    check_positive("material.density", material.density)?;
    check_positive("material.area", material.area)?;
    check_positive("material.second_moment", material.second_moment)?;
    let ba = material.axial_damping;
    if !ba.is_finite() || ba < 0.0 {
        return Err(ModelError::invalid(
            "material.axial_damping",
            format!("must be a finite number >= 0 (N s), got {ba}"),
        ));
    }
    Ok(())
}
