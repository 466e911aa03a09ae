//! The water a system's rigid bodies are in (docs/interface.md, "Rigid
//! bodies"): a body's volume, drag and added mass in air, refused naming
//! the body's value. In water a body sees every flow the lines see
//! (docs/method.md §15.15).

use super::system_parts::SystemScenario;
use super::ScenarioError;

/// Refuses a free body's water values in air (no `[water]`): its
/// volume, drag areas and added mass act in water only, and are refused
/// naming the key rather than left unused.
pub(super) fn refuse_water_in_air(file: &str, sc: &SystemScenario) -> Result<(), ScenarioError> {
    if sc.water.is_some() {
        return Ok(());
    }
    for (i, b) in sc.bodies.iter().enumerate() {
        let given = [
            ("volume", b.volume != 0.0),
            ("cda", b.drag_areas != [0.0; 3]),
            ("rotational_cda", b.rotational_drag_areas != [0.0; 3]),
            ("ca", b.ca != [0.0; 3]),
        ];
        if let Some((key, _)) = given.iter().find(|(_, g)| *g) {
            return Err(ScenarioError(format!(
                "{file}: {}: acts in water, which this scenario does not have ([water]); \
                 a body in air has no buoyancy, drag or added mass: leave it out or give [water]",
                sc.names.body(i, key, key)
            )));
        }
    }
    Ok(())
}
