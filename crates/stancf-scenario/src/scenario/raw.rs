//! The scenario file as serde reads it: every key optional (the
//! validation says which are required, naming the key), unknown keys
//! refused at every level (`deny_unknown_fields`).
//!
//! `[[constraints]]` and `[[loads]]` entries are read as plain tables
//! first and deserialized into their `Raw*` type once their `type` is
//! known (see [`super::context::Ctx::entry`]).

use serde::Deserialize;

/// A vector as written in the file, `[x, y, z]` (its length is checked by
/// [`super::context::Ctx::vector`]).
pub(super) type Vector = Vec<f64>;

/// The whole file: `title`, `[cable]`, `[material]`, `[[constraints]]`,
/// `[[loads]]`, `[[initial_velocity]]`, `[analysis]`, `[output]`.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct RawScenario {
    pub(super) title: Option<String>,
    pub(super) cable: Option<RawCable>,
    pub(super) material: Option<RawMaterial>,
    #[serde(default)]
    pub(super) constraints: Vec<toml::Table>,
    #[serde(default)]
    pub(super) loads: Vec<toml::Table>,
    #[serde(default)]
    pub(super) initial_velocity: Vec<RawInitialVelocity>,
    pub(super) analysis: Option<RawAnalysis>,
    pub(super) output: Option<RawOutput>,
    /// A system of lines (docs/interface.md, "Systems").
    pub(super) system: Option<RawSystem>,
    #[serde(default)]
    pub(super) line_types: Vec<RawLineType>,
    #[serde(default)]
    pub(super) points: Vec<RawPoint>,
    /// Rigid bodies (docs/interface.md, "Rigid bodies").
    #[serde(default)]
    pub(super) bodies: Vec<RawBody>,
    /// Rod types and rods (docs/interface.md, "Rods").
    #[serde(default)]
    pub(super) rod_types: Vec<RawRodType>,
    #[serde(default)]
    pub(super) rods: Vec<RawRod>,
    #[serde(default)]
    pub(super) lines: Vec<RawLine>,
    #[serde(default)]
    pub(super) motions: Vec<RawMotion>,
    /// The meshes of a MoorDyn deck's lines (docs/interface.md, "MoorDyn
    /// decks").
    #[serde(default)]
    pub(super) mesh: Vec<RawMesh>,
    /// The water a system's lines are in (docs/interface.md, "Water").
    pub(super) water: Option<RawWater>,
    /// A FAST.Farm deck's turbines (docs/interface.md, "MoorDyn decks").
    pub(super) farm: Option<RawFarm>,
    /// Values of the MoorDyn deck of `system.moordyn` set by name
    /// (`scenario/deck_values.rs`).
    pub(super) deck: Option<toml::Table>,
    /// Line failures (docs/interface.md, "Line failures").
    #[serde(default)]
    pub(super) failures: Vec<RawFailure>,
}

impl RawScenario {
    /// Whether the file describes a system of lines.
    pub(super) fn is_system(&self) -> bool {
        self.system.is_some()
            || !self.line_types.is_empty()
            || !self.points.is_empty()
            || !self.bodies.is_empty()
            || !self.rod_types.is_empty()
            || !self.rods.is_empty()
            || !self.lines.is_empty()
            || !self.motions.is_empty()
            || !self.mesh.is_empty()
            || self.farm.is_some()
            || !self.failures.is_empty()
    }
}

/// One `[[mesh]]` entry: the mesh of some of a MoorDyn deck's lines.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct RawMesh {
    pub(super) lines: Option<Vec<i64>>,
    pub(super) elements: Option<i64>,
    pub(super) grading: Option<RawGrading>,
}

/// `[system]`.
#[derive(Deserialize, Default)]
#[serde(deny_unknown_fields)]
pub(super) struct RawSystem {
    pub(super) gravity: Option<Vector>,
    pub(super) moordyn: Option<String>,
    /// With `moordyn`: the minimum breaking load of deck line types, by
    /// name (N).
    pub(super) mbl: Option<toml::Table>,
}

/// `[water]`.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct RawWater {
    pub(super) density: Option<f64>,
    pub(super) depth: Option<f64>,
    pub(super) wave_ramp: Option<f64>,
    pub(super) host_waves: Option<bool>,
    pub(super) seabed: Option<RawSeabed>,
    pub(super) current: Option<RawCurrent>,
    #[serde(default)]
    pub(super) waves: Vec<RawWave>,
    pub(super) jonswap: Option<RawJonswap>,
}

/// `[water.seabed]`.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct RawSeabed {
    pub(super) stiffness: Option<f64>,
    pub(super) damping: Option<f64>,
    pub(super) friction_axial: Option<f64>,
    pub(super) friction_transverse: Option<f64>,
    pub(super) slip_velocity: Option<f64>,
    pub(super) slope: Option<Vec<f64>>,
    pub(super) file: Option<String>,
    pub(super) static_friction: Option<String>,
}

/// `[water.current]`.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct RawCurrent {
    pub(super) profile: Option<Vec<Vec<f64>>>,
    pub(super) velocity: Option<Vector>,
    pub(super) ramp: Option<f64>,
}

/// One `[[water.waves]]` entry.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct RawWave {
    pub(super) amplitude: Option<f64>,
    pub(super) period: Option<f64>,
    pub(super) heading: Option<f64>,
    pub(super) phase: Option<f64>,
}

/// `[water.jonswap]`.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct RawJonswap {
    pub(super) hs: Option<f64>,
    pub(super) tp: Option<f64>,
    pub(super) gamma: Option<f64>,
    pub(super) heading: Option<f64>,
    pub(super) seed: Option<i64>,
    pub(super) components: Option<i64>,
}

/// One `[[line_types]]` entry.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct RawLineType {
    pub(super) name: Option<String>,
    pub(super) diameter: Option<f64>,
    pub(super) mass_per_length: Option<f64>,
    pub(super) ea: Option<f64>,
    pub(super) ea_curve: Option<Vec<Vec<f64>>>,
    pub(super) ea_dynamic: Option<f64>,
    pub(super) ea_dynamic_alpha: Option<f64>,
    pub(super) ea_dynamic_beta: Option<f64>,
    pub(super) ba_dynamic: Option<f64>,
    pub(super) syrope: Option<RawSyrope>,
    pub(super) ei: Option<f64>,
    pub(super) ba: Option<f64>,
    pub(super) cd: Option<f64>,
    pub(super) ca: Option<f64>,
    pub(super) cdax: Option<f64>,
    pub(super) caax: Option<f64>,
    pub(super) compression: Option<bool>,
    pub(super) viv: Option<RawViv>,
    pub(super) mbl: Option<f64>,
}

/// `viv = { cl = ..., df = 0.08, cf = 0.18, averaging_time = ... }` of a
/// line type (docs/method.md §12.7).
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct RawViv {
    pub(super) cl: Option<f64>,
    pub(super) df: Option<f64>,
    pub(super) cf: Option<f64>,
    pub(super) averaging_time: Option<f64>,
}

/// `syrope = { curve = [[strain, tension], ...], working_curve = "linear",
/// k1 = ..., k2 = ..., alpha = ..., beta = ... }` of a line type
/// (docs/method.md §2.12).
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct RawSyrope {
    pub(super) curve: Option<Vec<Vec<f64>>>,
    pub(super) working_curve: Option<String>,
    pub(super) k1: Option<f64>,
    pub(super) k2: Option<f64>,
    pub(super) alpha: Option<f64>,
    pub(super) beta: Option<f64>,
}

/// One `[[points]]` entry.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct RawPoint {
    pub(super) id: Option<i64>,
    #[serde(rename = "type")]
    pub(super) kind: Option<String>,
    pub(super) position: Option<Vector>,
    pub(super) mass: Option<f64>,
    pub(super) force: Option<Vector>,
    pub(super) volume: Option<f64>,
    pub(super) cda: Option<f64>,
    pub(super) ca: Option<f64>,
    pub(super) damping_linear: Option<Vector>,
    pub(super) damping_quadratic: Option<Vector>,
    /// The id of the body a point of type "body" is on.
    pub(super) body: Option<i64>,
    /// The id of the rod a point of type "rod" is at, and which end
    /// ("A" or "B").
    pub(super) rod: Option<i64>,
    pub(super) end: Option<String>,
}

/// One `[[rod_types]]` entry.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct RawRodType {
    pub(super) name: Option<String>,
    pub(super) diameter: Option<f64>,
    pub(super) mass_per_length: Option<f64>,
    pub(super) cd: Option<f64>,
    pub(super) ca: Option<f64>,
    pub(super) cd_end: Option<f64>,
    pub(super) ca_end: Option<f64>,
}

/// One `[[rods]]` entry.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct RawRod {
    pub(super) id: Option<i64>,
    #[serde(rename = "type")]
    pub(super) kind: Option<String>,
    /// The id of the body a rod of type "body" is fixed in.
    pub(super) body: Option<i64>,
    pub(super) rod_type: Option<String>,
    pub(super) end_a: Option<Vector>,
    pub(super) end_b: Option<Vector>,
    pub(super) segments: Option<i64>,
}

/// One `[[bodies]]` entry.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct RawBody {
    pub(super) id: Option<i64>,
    #[serde(rename = "type")]
    pub(super) kind: Option<String>,
    pub(super) position: Option<Vector>,
    pub(super) angles: Option<Vector>,
    pub(super) mass: Option<f64>,
    pub(super) centre_of_mass: Option<Vector>,
    pub(super) inertia: Option<Vector>,
    pub(super) volume: Option<f64>,
    pub(super) cda: Option<Vector>,
    pub(super) rotational_cda: Option<Vector>,
    pub(super) ca: Option<Vector>,
    pub(super) velocity: Option<Vector>,
    pub(super) angular_velocity: Option<Vector>,
    pub(super) force: Option<Vector>,
    pub(super) moment: Option<Vector>,
    pub(super) body_force: Option<Vector>,
    pub(super) damping_linear: Option<Vector>,
    pub(super) damping_quadratic: Option<Vector>,
    pub(super) body_damping_linear: Option<Vector>,
    pub(super) body_damping_quadratic: Option<Vector>,
}

impl RawBody {
    /// Whether each key only a free body takes is given, in the order
    /// mass, centre_of_mass, inertia, volume, cda, rotational_cda, ca,
    /// velocity, angular_velocity, force, moment, body_force,
    /// damping_linear, damping_quadratic, body_damping_linear,
    /// body_damping_quadratic.
    pub(super) fn free_keys(&self) -> [bool; 16] {
        [
            self.mass.is_some(),
            self.centre_of_mass.is_some(),
            self.inertia.is_some(),
            self.volume.is_some(),
            self.cda.is_some(),
            self.rotational_cda.is_some(),
            self.ca.is_some(),
            self.velocity.is_some(),
            self.angular_velocity.is_some(),
            self.force.is_some(),
            self.moment.is_some(),
            self.body_force.is_some(),
            self.damping_linear.is_some(),
            self.damping_quadratic.is_some(),
            self.body_damping_linear.is_some(),
            self.body_damping_quadratic.is_some(),
        ]
    }
}

/// One `[[lines]]` entry.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct RawLine {
    pub(super) id: Option<i64>,
    #[serde(rename = "type")]
    pub(super) line_type: Option<String>,
    pub(super) length: Option<f64>,
    pub(super) elements: Option<i64>,
    pub(super) element: Option<String>,
    pub(super) a: Option<i64>,
    pub(super) b: Option<i64>,
    pub(super) clamp_a: Option<Vector>,
    pub(super) clamp_b: Option<Vector>,
    pub(super) grading: Option<RawGrading>,
    pub(super) tmax0: Option<f64>,
}

/// `grading = { toward = "B", ratio = 4.0 }` or `grading = { sections =
/// [{ length = 300.0, elements = 30 }, ...] }` of `[cable]`, a `[[lines]]`
/// entry or a `[[mesh]]` entry.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct RawGrading {
    pub(super) toward: Option<String>,
    pub(super) ratio: Option<f64>,
    pub(super) sections: Option<Vec<RawSection>>,
}

/// One `{ length, elements }` of `grading.sections`.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct RawSection {
    pub(super) length: Option<f64>,
    pub(super) elements: Option<i64>,
}

/// One `[[motions]]` entry.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct RawMotion {
    pub(super) point: Option<i64>,
    pub(super) amplitude: Option<Vector>,
    pub(super) period: Option<f64>,
    pub(super) phase: Option<f64>,
    pub(super) ramp: Option<f64>,
    pub(super) file: Option<String>,
}

/// `[cable]`.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct RawCable {
    pub(super) length: Option<f64>,
    pub(super) elements: Option<i64>,
    pub(super) element: Option<String>,
    pub(super) origin: Option<Vector>,
    pub(super) direction: Option<Vector>,
    pub(super) grading: Option<RawGrading>,
}

/// `[material]`.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct RawMaterial {
    pub(super) youngs_modulus: Option<f64>,
    pub(super) density: Option<f64>,
    pub(super) area: Option<f64>,
    pub(super) second_moment: Option<f64>,
    pub(super) diameter: Option<f64>,
    pub(super) axial_damping: Option<f64>,
}

/// One `[[initial_velocity]]` entry.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct RawInitialVelocity {
    pub(super) node: Option<toml::Value>,
    pub(super) velocity: Option<Vector>,
    pub(super) angular_velocity: Option<Vector>,
    pub(super) center: Option<Vector>,
}

/// `[analysis]`.
#[derive(Deserialize, Default)]
#[serde(deny_unknown_fields)]
pub(super) struct RawAnalysis {
    #[serde(rename = "type")]
    pub(super) kind: Option<String>,
    pub(super) time_step: Option<f64>,
    pub(super) duration: Option<f64>,
    pub(super) time_layers: Option<i64>,
    pub(super) quadrature: Option<Vec<i64>>,
    pub(super) solver: Option<String>,
    pub(super) time_scheme: Option<String>,
    pub(super) tolerance: Option<f64>,
    pub(super) max_iterations: Option<i64>,
    pub(super) load_steps: Option<i64>,
    pub(super) curvature: Option<String>,
    pub(super) axial_strain: Option<String>,
    pub(super) constraint_method: Option<String>,
    pub(super) planar_reduction: Option<bool>,
    pub(super) step_halvings: Option<i64>,
    pub(super) force_tolerance: Option<f64>,
    pub(super) initial: Option<String>,
}

/// `[output]`.
#[derive(Deserialize, Default)]
#[serde(deny_unknown_fields)]
pub(super) struct RawOutput {
    pub(super) every: Option<i64>,
    pub(super) files: Option<Vec<String>>,
    pub(super) end_forces: Option<String>,
    pub(super) statistics_after: Option<f64>,
    pub(super) interval: Option<f64>,
}

/// A `[[loads]]` entry of type `"gravity"`.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct RawGravity {
    #[serde(rename = "type")]
    _kind: String,
    pub(super) acceleration: Option<Vector>,
}

/// A `[[loads]]` entry of type `"point-force"`.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct RawPointForce {
    #[serde(rename = "type")]
    _kind: String,
    pub(super) node: Option<toml::Value>,
    pub(super) force: Option<Vector>,
}

/// A `[[loads]]` entry of type `"air-drag"`.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct RawAirDrag {
    #[serde(rename = "type")]
    _kind: String,
    pub(super) drag_coefficient: Option<f64>,
    pub(super) fluid_density: Option<f64>,
    pub(super) diameter: Option<f64>,
    pub(super) fluid_velocity: Option<Vector>,
    pub(super) model: Option<String>,
    pub(super) tangential_coefficient: Option<f64>,
}

/// A `[[loads]]` entry of type `"end-moment"`.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct RawEndMoment {
    #[serde(rename = "type")]
    _kind: String,
    pub(super) node: Option<toml::Value>,
    pub(super) moment: Option<Vector>,
}

/// A `[[constraints]]` entry of type `"clamped"`.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct RawClamped {
    #[serde(rename = "type")]
    _kind: String,
    pub(super) node: Option<toml::Value>,
    pub(super) fix_curvature: Option<bool>,
}

/// A `[[constraints]]` entry of type `"pinned"`.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct RawPinned {
    #[serde(rename = "type")]
    _kind: String,
    pub(super) node: Option<toml::Value>,
}

/// A `[[constraints]]` entry of type `"prescribed"`.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct RawPrescribed {
    #[serde(rename = "type")]
    _kind: String,
    pub(super) node: Option<toml::Value>,
    pub(super) velocity: Option<Vector>,
    pub(super) amplitude: Option<Vector>,
    pub(super) frequency: Option<f64>,
    pub(super) phase: Option<f64>,
}

/// `[farm]` of a scenario that takes a FAST.Farm deck (`super::farm`).
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct RawFarm {
    pub(super) turbines: Option<Vec<Vec<f64>>>,
    pub(super) fast_farm: Option<String>,
}

/// One `[[failures]]` entry.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct RawFailure {
    pub(super) id: Option<i64>,
    pub(super) point: Option<i64>,
    pub(super) lines: Option<Vec<i64>>,
    pub(super) time: Option<f64>,
    pub(super) tension: Option<f64>,
}
