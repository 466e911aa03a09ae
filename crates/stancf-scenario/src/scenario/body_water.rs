//! The water a system's rigid bodies are in (docs/interface.md, "Rigid
//! bodies"): a body's volume, drag and added mass in air, and the water
//! this version does not build for a body, refused naming the body's
//! value and the water's key.

use super::bodies::uniform_current;
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

/// Refuses a body's water this version does not build, naming the body's
/// value and the water's key: drag (or added mass, which sees the water's
/// velocity too) in a current that is not uniform, or that a ramp
/// starts; drag in waves (in a dynamic analysis: a static one sees no
/// waves). A steady uniform current is the body's (its drag in the
/// static solve too, docs/method.md §15.8).
pub(super) fn check_body_water(file: &str, sc: &SystemScenario) -> Result<(), ScenarioError> {
    let Some(w) = &sc.water else { return Ok(()) };
    let refuse = |i: usize, column: (&str, &str), water_key: String, why: &str| {
        Err(ScenarioError(format!(
            "{file}: {}, {water_key}: body {} {why}",
            sc.names.body(i, column.0, column.1),
            sc.bodies[i].id
        )))
    };
    let current_key = || {
        sc.names
            .option("water.current", crate::moordyn::SupportedOption::Currents)
    };
    let dynamic = sc.analysis.kind == super::AnalysisKind::Dynamic;
    for (i, b) in sc.bodies.iter().enumerate().filter(|(_, b)| b.is_free()) {
        let sees_current = b.has_drag() || b.ca != [0.0; 3];
        // The value that makes the body see the water, as written.
        let drag = if b.drag_areas != [0.0; 3] {
            ("cda", "CdA")
        } else {
            ("rotational_cda", "CdA")
        };
        let seeing = if b.has_drag() { drag } else { ("ca", "Ca") };
        if let Some(c) = &w.current {
            if sees_current && uniform_current(w).is_none() {
                return refuse(
                    i,
                    seeing,
                    current_key(),
                    "has drag or added mass in a current that varies with depth: a body's \
                     drag in waves or a sheared current is not built (a uniform current is)",
                );
            }
            if sees_current && c.ramp > 0.0 {
                return refuse(
                    i,
                    seeing,
                    "water.current.ramp".into(),
                    "has drag or added mass in a current started by a ramp: a body sees a \
                     steady current only in this version",
                );
            }
        }
        let waves = !w.waves.is_empty() || w.jonswap.is_some();
        if waves && dynamic && b.has_drag() {
            let key = if w.waves.is_empty() {
                "water.jonswap"
            } else {
                "water.waves"
            };
            return refuse(
                i,
                drag,
                key.into(),
                "has drag in waves: a body's drag in waves or a sheared current is not built",
            );
        }
    }
    Ok(())
}
