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
}

/// `[output]`.
#[derive(Deserialize, Default)]
#[serde(deny_unknown_fields)]
pub(super) struct RawOutput {
    pub(super) every: Option<i64>,
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
