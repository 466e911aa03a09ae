//! Scenario files (TOML, docs/interface.md): parsing and validation.
//!
//! Every problem is reported as `<file>: <key>: <what is wrong>`, before
//! anything is written. Unknown keys are errors at every level.

use serde::Deserialize;
use stancf::error::Sig;
use stancf::{AxialStrain, Curvature, ElementType, Load, Material, Measures, ModelOptions};
use std::path::Path;

/// An invalid scenario: the message names the file and the key.
#[derive(Debug)]
pub struct ScenarioError(pub String);

impl std::fmt::Display for ScenarioError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.0)
    }
}

type Vector = Vec<f64>;

/// The most steps a dynamic analysis can have: 2^53, above which f64
/// cannot count them (t + dt == t).
pub const MAX_COUNTABLE_STEPS: f64 = 9_007_199_254_740_992.0;

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawScenario {
    title: Option<String>,
    cable: Option<RawCable>,
    material: Option<RawMaterial>,
    #[serde(default)]
    constraints: Vec<toml::Table>,
    #[serde(default)]
    loads: Vec<toml::Table>,
    #[serde(default)]
    initial_velocity: Vec<RawInitialVelocity>,
    analysis: Option<RawAnalysis>,
    output: Option<RawOutput>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawCable {
    length: Option<f64>,
    elements: Option<i64>,
    element: Option<String>,
    origin: Option<Vector>,
    direction: Option<Vector>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawMaterial {
    youngs_modulus: Option<f64>,
    density: Option<f64>,
    area: Option<f64>,
    second_moment: Option<f64>,
    diameter: Option<f64>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawInitialVelocity {
    node: Option<toml::Value>,
    velocity: Option<Vector>,
    angular_velocity: Option<Vector>,
    center: Option<Vector>,
}

#[derive(Deserialize, Default)]
#[serde(deny_unknown_fields)]
struct RawAnalysis {
    #[serde(rename = "type")]
    kind: Option<String>,
    time_step: Option<f64>,
    duration: Option<f64>,
    time_layers: Option<i64>,
    quadrature: Option<Vec<i64>>,
    solver: Option<String>,
    time_scheme: Option<String>,
    tolerance: Option<f64>,
    max_iterations: Option<i64>,
    load_steps: Option<i64>,
    curvature: Option<String>,
    axial_strain: Option<String>,
    constraint_method: Option<String>,
    planar_reduction: Option<bool>,
}

#[derive(Deserialize, Default)]
#[serde(deny_unknown_fields)]
struct RawOutput {
    every: Option<i64>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawGravity {
    #[serde(rename = "type")]
    _kind: String,
    acceleration: Option<Vector>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawPointForce {
    #[serde(rename = "type")]
    _kind: String,
    node: Option<toml::Value>,
    force: Option<Vector>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawAirDrag {
    #[serde(rename = "type")]
    _kind: String,
    drag_coefficient: Option<f64>,
    fluid_density: Option<f64>,
    diameter: Option<f64>,
    fluid_velocity: Option<Vector>,
    model: Option<String>,
    tangential_coefficient: Option<f64>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawEndMoment {
    #[serde(rename = "type")]
    _kind: String,
    node: Option<toml::Value>,
    moment: Option<Vector>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawClamped {
    #[serde(rename = "type")]
    _kind: String,
    node: Option<toml::Value>,
    fix_curvature: Option<bool>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawPinned {
    #[serde(rename = "type")]
    _kind: String,
    node: Option<toml::Value>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawPrescribed {
    #[serde(rename = "type")]
    _kind: String,
    node: Option<toml::Value>,
    velocity: Option<Vector>,
    amplitude: Option<Vector>,
    frequency: Option<f64>,
    phase: Option<f64>,
}

/// Which nodes an initial velocity applies to.
#[derive(Clone, Debug, PartialEq)]
pub enum NodeSet {
    One(usize),
    All,
}

/// One `[[initial_velocity]]` entry, validated.
#[derive(Clone, Debug, PartialEq)]
pub struct InitialVelocity {
    pub nodes: NodeSet,
    pub velocity: [f64; 3],
    pub angular_velocity: Option<[f64; 3]>,
    pub center: [f64; 3],
}

/// Dynamic (P2 steps in time) or static (load steps).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum AnalysisKind {
    Dynamic,
    Static,
}

/// The analysis settings.
#[derive(Clone, Debug, PartialEq)]
pub struct Analysis {
    pub kind: AnalysisKind,
    /// Dynamic only (0 for a static analysis).
    pub time_step: f64,
    pub duration: f64,
    pub time_layers: usize,
    /// Spatial Gauss points (None: the element's default).
    pub space_points: Option<stancf::SpacePoints>,
    pub time_points: usize,
    pub tolerance: f64,
    pub max_iterations: usize,
    pub solver: stancf::SolverMethod,
    pub time_scheme: stancf::TimeScheme,
    pub load_steps: usize,
    pub constraint_method: stancf::ConstraintMethod,
    /// Eliminate the out-of-plane coordinates of a planar motion.
    pub planar_reduction: bool,
}

/// A validated scenario.
#[derive(Clone, Debug)]
pub struct Scenario {
    pub title: String,
    pub cable: stancf::Cable,
    pub material: Material,
    pub diameter: f64,
    pub options: ModelOptions,
    pub loads: Vec<Load>,
    pub constraints: Vec<stancf::Constraint>,
    pub initial_velocity: Vec<InitialVelocity>,
    pub analysis: Analysis,
    pub output_every: usize,
    /// Things worth saying that do not make the scenario invalid.
    pub notes: Vec<String>,
}

/// Collects errors with the file name in front.
struct Ctx<'a> {
    file: &'a str,
}

impl Ctx<'_> {
    fn err(&self, key: &str, msg: impl std::fmt::Display) -> ScenarioError {
        ScenarioError(format!("{}: {}: {}", self.file, key, msg))
    }

    fn required<T>(&self, key: &str, v: Option<T>) -> Result<T, ScenarioError> {
        v.ok_or_else(|| self.err(key, "required key is missing"))
    }

    fn finite(&self, key: &str, v: f64) -> Result<f64, ScenarioError> {
        if v.is_finite() {
            Ok(v)
        } else {
            Err(self.err(key, format!("must be a finite number, got {v}")))
        }
    }

    fn positive(&self, key: &str, v: f64) -> Result<f64, ScenarioError> {
        let v = self.finite(key, v)?;
        if v > 0.0 {
            Ok(v)
        } else {
            Err(self.err(key, format!("must be > 0, got {v}")))
        }
    }

    fn count(&self, key: &str, v: i64, min: i64, max: i64) -> Result<usize, ScenarioError> {
        if v < min || v > max {
            if max == i64::MAX {
                return Err(self.err(key, format!("must be at least {min}, got {v}")));
            }
            return Err(self.err(key, format!("must be between {min} and {max}, got {v}")));
        }
        Ok(v as usize)
    }

    fn vector(&self, key: &str, v: &[f64]) -> Result<[f64; 3], ScenarioError> {
        if v.len() != 3 {
            return Err(self.err(
                key,
                format!(
                    "a vector needs exactly 3 components [x, y, z], got {}",
                    v.len()
                ),
            ));
        }
        for (i, c) in v.iter().enumerate() {
            if !c.is_finite() {
                return Err(self.err(key, format!("component {i} is not a finite number ({c})")));
            }
        }
        Ok([v[0], v[1], v[2]])
    }

    fn choice<'s>(
        &self,
        key: &str,
        v: Option<&'s str>,
        default: &'s str,
        allowed: &[&str],
    ) -> Result<&'s str, ScenarioError> {
        let v = v.unwrap_or(default);
        if allowed.contains(&v) {
            Ok(v)
        } else {
            let list: Vec<String> = allowed.iter().map(|a| format!("\"{a}\"")).collect();
            Err(self.err(
                key,
                format!(
                    "unknown value \"{}\" (expected {})",
                    clip(v, 60),
                    list.join(" or ")
                ),
            ))
        }
    }

    /// A node: "A", "B", an integer index 0..=elements or (`allow_all`)
    /// "all".
    fn node(
        &self,
        key: &str,
        node: &toml::Value,
        elements: usize,
        allow_all: bool,
    ) -> Result<NodeSet, ScenarioError> {
        let expected = format!(
            "a node is \"A\" (x = 0), \"B\" (x = length){} or an integer node index 0..={elements}",
            if allow_all { ", \"all\"" } else { "" }
        );
        match node {
            toml::Value::String(s) if s == "A" => Ok(NodeSet::One(0)),
            toml::Value::String(s) if s == "B" => Ok(NodeSet::One(elements)),
            toml::Value::String(s) if s == "all" && allow_all => Ok(NodeSet::All),
            toml::Value::Integer(i) if *i >= 0 && (*i as u64) <= elements as u64 => {
                Ok(NodeSet::One(*i as usize))
            }
            toml::Value::Integer(i) => Err(self.err(
                key,
                format!("node index {i} is out of range (the mesh has nodes 0..={elements})"),
            )),
            other => Err(self.err(key, format!("{expected}, got {}", describe_value(other)))),
        }
    }

    /// The types of the entries present in a `[[loads]]` or
    /// `[[constraints]]` table, checked before it is deserialized (serde's
    /// own message would name neither the key nor the expected value in
    /// words).
    fn field_types(
        &self,
        key: &str,
        table: &toml::Table,
        fields: &[(&str, Field)],
    ) -> Result<(), ScenarioError> {
        for (name, kind) in fields {
            let Some(v) = table.get(*name) else { continue };
            let k = format!("{key}.{name}");
            let number =
                |v: &toml::Value| matches!(v, toml::Value::Integer(_) | toml::Value::Float(_));
            let ok = match kind {
                Field::Number => number(v),
                Field::Text => matches!(v, toml::Value::String(_)),
                Field::Bool => matches!(v, toml::Value::Boolean(_)),
                Field::Node => true, // Ctx::node says what a node may be
                Field::Vector => {
                    if let toml::Value::Array(a) = v {
                        if let Some((i, c)) = a.iter().enumerate().find(|(_, c)| !number(c)) {
                            return Err(self.err(
                                &k,
                                format!(
                                    "component {i} must be a number, got {}",
                                    describe_value(c)
                                ),
                            ));
                        }
                        true
                    } else {
                        false
                    }
                }
            };
            if !ok {
                return Err(self.err(
                    &k,
                    format!("expected {}, got {}", kind.describe(), describe_value(v)),
                ));
            }
        }
        Ok(())
    }
}

/// What a key of a `[[loads]]` or `[[constraints]]` entry holds.
#[derive(Clone, Copy)]
enum Field {
    Number,
    Vector,
    Text,
    Bool,
    Node,
}

impl Field {
    fn describe(self) -> &'static str {
        match self {
            Field::Number => "a number",
            Field::Vector => "a vector of 3 numbers [x, y, z]",
            Field::Text => "a string",
            Field::Bool => "true or false",
            Field::Node => "a node",
        }
    }
}

/// The longest piece of the user's input echoed in a message (in
/// characters); longer pieces are cut with an ellipsis.
pub const MAX_ECHO: usize = 200;

/// `s` cut to at most `max` characters, with "..." (an ellipsis) where cut.
pub fn clip(s: &str, max: usize) -> String {
    match s.char_indices().nth(max) {
        None => s.to_string(),
        Some((end, _)) => format!("{}…", &s[..end]),
    }
}

/// A TOML value in a message: its type and (clipped) value.
fn describe_value(v: &toml::Value) -> String {
    match v {
        toml::Value::String(s) => format!("the string \"{}\"", clip(s, 60)),
        toml::Value::Integer(i) => format!("the integer {i}"),
        toml::Value::Float(x) => format!("the number {x}"),
        toml::Value::Boolean(b) => format!("{b}"),
        toml::Value::Datetime(d) => format!("the date {d}"),
        toml::Value::Array(a) => format!(
            "a list of {} item{}",
            a.len(),
            if a.len() == 1 { "" } else { "s" }
        ),
        toml::Value::Table(_) => "a table".into(),
    }
}

/// serde's words for the types of a scenario file, in the file's words;
/// pieces of input quoted in the message (between ` or ") clipped.
fn plain_words(message: &str) -> String {
    let mut m = message.trim_end().to_string();
    for (from, to) in [
        ("expected i64", "expected an integer"),
        ("expected u64", "expected an integer"),
        ("expected usize", "expected an integer"),
        ("expected f64", "expected a number"),
        ("expected a sequence", "expected a list [..]"),
        ("floating point `", "number `"),
        (
            "number too large to fit in target type",
            "number too large (at most 9223372036854775807)",
        ),
    ] {
        m = m.replace(from, to);
    }
    // Clip each quoted piece: a 5 MB key or string must not be echoed.
    let mut out = String::with_capacity(m.len().min(4 * MAX_ECHO));
    let mut rest = m.as_str();
    while let Some(open) = rest.find(['`', '"']) {
        let q = rest.as_bytes()[open] as char;
        out.push_str(&rest[..=open]);
        rest = &rest[open + 1..];
        match rest.find(q) {
            Some(close) => {
                out.push_str(&clip(&rest[..close], 60));
                out.push(q);
                rest = &rest[close + 1..];
            }
            None => {
                out.push_str(&clip(rest, 60));
                rest = "";
            }
        }
    }
    out.push_str(rest);
    clip(&out, 4 * MAX_ECHO)
}

/// A TOML syntax or type error: the line and column, the offending line
/// (a window of at most [`MAX_ECHO`] characters around the error) with a
/// caret under it, and serde's message in plain words.
fn toml_error(file: &str, text: &str, e: &toml::de::Error) -> ScenarioError {
    let message = plain_words(e.message());
    let Some(span) = e.span() else {
        return ScenarioError(format!("{file}: {message}"));
    };
    let floor = |mut i: usize| {
        i = i.min(text.len());
        while !text.is_char_boundary(i) {
            i -= 1;
        }
        i
    };
    let start = floor(span.start);
    let end = floor(span.end.max(span.start));
    let line_start = text[..start].rfind('\n').map_or(0, |i| i + 1);
    let line_end = text[start..].find('\n').map_or(text.len(), |i| start + i);
    let line_no = text[..start].matches('\n').count() + 1;
    let line = text[line_start..line_end].trim_end_matches('\r');
    let column = text[line_start..start].chars().count();
    let width = text[start..end.min(line_start + line.len()).max(start)]
        .chars()
        .count()
        .max(1);
    // The window of the line shown: MAX_ECHO characters, the error
    // starting at most a third of the way in.
    let chars = line.chars().count();
    let from = if chars <= MAX_ECHO {
        0
    } else {
        column.saturating_sub(MAX_ECHO / 3).min(chars - MAX_ECHO)
    };
    let shown: String = line.chars().skip(from).take(MAX_ECHO).collect();
    let (lead, tail) = (
        if from > 0 { "…" } else { "" },
        if from + MAX_ECHO < chars { "…" } else { "" },
    );
    let caret_at = column - from + lead.chars().count();
    let caret_width = width.min(MAX_ECHO + 1 - (column - from).min(MAX_ECHO));
    let gutter = " ".repeat(line_no.to_string().len());
    ScenarioError(format!(
        "{file}: TOML parse error at line {line_no}, column {}\n{gutter} |\n{line_no} | {lead}{shown}{tail}\n{gutter} | {}{}\n{message}",
        column + 1,
        " ".repeat(caret_at),
        "^".repeat(caret_width),
    ))
}

/// Reads and validates a scenario file.
pub fn load(path: &Path) -> Result<Scenario, ScenarioError> {
    let file = path.display().to_string();
    let text = std::fs::read_to_string(path)
        .map_err(|e| ScenarioError(format!("{file}: cannot read the file: {e}")))?;
    parse(&text, &file, path)
}

/// Parses and validates scenario text; `file` names it in messages.
pub fn parse(text: &str, file: &str, path: &Path) -> Result<Scenario, ScenarioError> {
    let ctx = Ctx { file };
    let raw: RawScenario = toml::from_str(text).map_err(|e| toml_error(file, text, &e))?;
    let title = raw.title.unwrap_or_else(|| {
        path.file_stem()
            .map(|s| s.to_string_lossy().into_owned())
            .unwrap_or_default()
    });

    let rc = ctx.required("cable", raw.cable)?;
    let length = ctx.positive("cable.length", ctx.required("cable.length", rc.length)?)?;
    let elements = ctx.count(
        "cable.elements",
        ctx.required("cable.elements", rc.elements)?,
        1,
        1_000_000,
    )?;
    let element = match ctx.choice(
        "cable.element",
        rc.element.as_deref(),
        "SAC-2",
        &["SAC-2", "SAC-3"],
    )? {
        "SAC-3" => ElementType::Sac3,
        _ => ElementType::Sac2,
    };
    let origin = match &rc.origin {
        Some(v) => ctx.vector("cable.origin", v)?,
        None => [0.0; 3],
    };
    let direction = match &rc.direction {
        Some(v) => ctx.vector("cable.direction", v)?,
        None => [1.0, 0.0, 0.0],
    };
    if direction.iter().all(|&c| c == 0.0) {
        return Err(ctx.err("cable.direction", "must not be the zero vector"));
    }
    // Only its direction counts: scaled by its largest component first, so
    // that [1e-200, 0, 0] and [1e300, 0, 0] are unit vectors too (their
    // squared lengths underflow or overflow).
    let direction = {
        let big = direction.iter().fold(0.0f64, |m, c| m.max(c.abs()));
        let d = direction.map(|c| c / big);
        let n = (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).sqrt();
        d.map(|c| c / n)
    };

    let rm = ctx.required("material", raw.material)?;
    let material = Material {
        youngs_modulus: ctx.positive(
            "material.youngs_modulus",
            ctx.required("material.youngs_modulus", rm.youngs_modulus)?,
        )?,
        density: ctx.positive(
            "material.density",
            ctx.required("material.density", rm.density)?,
        )?,
        area: ctx.positive("material.area", ctx.required("material.area", rm.area)?)?,
        second_moment: ctx.positive(
            "material.second_moment",
            ctx.required("material.second_moment", rm.second_moment)?,
        )?,
    };
    let diameter = match rm.diameter {
        Some(d) => ctx.positive("material.diameter", d)?,
        None => (4.0 * material.area / std::f64::consts::PI).sqrt(),
    };

    let mut constraints = Vec::new();
    for (i, table) in raw.constraints.iter().enumerate() {
        let key = format!("constraints[{i}]");
        let kind = type_of(&ctx, &key, table)?;
        let value = toml::Value::Table(table.clone());
        let de_err = |e: toml::de::Error| ctx.err(&key, plain_words(e.message()));
        let nk = format!("{key}.node");
        let one_node = |n: Option<toml::Value>| -> Result<usize, ScenarioError> {
            match ctx.node(&nk, &ctx.required(&nk, n)?, elements, false)? {
                NodeSet::One(n) => Ok(n),
                NodeSet::All => unreachable!("\"all\" is not accepted here"),
            }
        };
        let optional_vector = |name: &str, v: &Option<Vector>| -> Result<[f64; 3], ScenarioError> {
            match v {
                Some(v) => ctx.vector(&format!("{key}.{name}"), v),
                None => Ok([0.0; 3]),
            }
        };
        let c = match kind.as_str() {
            "clamped" => {
                ctx.field_types(&key, table, &[("node", Field::Node), ("fix_curvature", Field::Bool)])?;
                let c: RawClamped = value.try_into().map_err(de_err)?;
                stancf::Constraint {
                    node: one_node(c.node)?,
                    kind: stancf::ConstraintKind::Clamped {
                        fix_curvature: c.fix_curvature.unwrap_or(false),
                    },
                }
            }
            "pinned" => {
                let c: RawPinned = value.try_into().map_err(de_err)?;
                stancf::Constraint {
                    node: one_node(c.node)?,
                    kind: stancf::ConstraintKind::Pinned,
                }
            }
            "prescribed" => {
                ctx.field_types(&key, table, &[
                    ("velocity", Field::Vector),
                    ("amplitude", Field::Vector),
                    ("frequency", Field::Number),
                    ("phase", Field::Number),
                ])?;
                let c: RawPrescribed = value.try_into().map_err(de_err)?;
                let frequency = match c.frequency {
                    Some(f) => {
                        let f = ctx.finite(&format!("{key}.frequency"), f)?;
                        if f < 0.0 {
                            return Err(ctx.err(&format!("{key}.frequency"), format!("must be >= 0, got {f}")));
                        }
                        f
                    }
                    None => 0.0,
                };
                let phase = match c.phase {
                    Some(p) => ctx.finite(&format!("{key}.phase"), p)?,
                    None => 0.0,
                };
                stancf::Constraint {
                    node: one_node(c.node)?,
                    kind: stancf::ConstraintKind::Prescribed {
                        velocity: optional_vector("velocity", &c.velocity)?,
                        amplitude: optional_vector("amplitude", &c.amplitude)?,
                        frequency,
                        phase,
                    },
                }
            }
            other => {
                return Err(ctx.err(
                    &format!("{key}.type"),
                    format!(
                        "unknown constraint type \"{}\" (expected \"clamped\", \"pinned\" or \"prescribed\")",
                        clip(other, 60)
                    ),
                ))
            }
        };
        constraints.push(c);
    }

    let mut loads = Vec::new();
    for (i, table) in raw.loads.iter().enumerate() {
        let key = format!("loads[{i}]");
        let kind = type_of(&ctx, &key, table)?;
        let value = toml::Value::Table(table.clone());
        let de_err = |e: toml::de::Error| ctx.err(&key, plain_words(e.message()));
        match kind.as_str() {
            "gravity" => {
                ctx.field_types(&key, table, &[("acceleration", Field::Vector)])?;
                let g: RawGravity = value.try_into().map_err(de_err)?;
                let a = ctx.required(&format!("{key}.acceleration"), g.acceleration)?;
                loads.push(Load::Gravity {
                    acceleration: ctx.vector(&format!("{key}.acceleration"), &a)?,
                });
            }
            "point-force" => {
                ctx.field_types(&key, table, &[("force", Field::Vector)])?;
                let p: RawPointForce = value.try_into().map_err(de_err)?;
                let nk = format!("{key}.node");
                let node = match ctx.node(&nk, &ctx.required(&nk, p.node)?, elements, false)? {
                    NodeSet::One(n) => n,
                    NodeSet::All => unreachable!("\"all\" is not accepted here"),
                };
                let f = ctx.required(&format!("{key}.force"), p.force)?;
                loads.push(Load::PointForce {
                    node,
                    force: ctx.vector(&format!("{key}.force"), &f)?,
                });
            }
            "end-moment" => {
                ctx.field_types(&key, table, &[("moment", Field::Vector)])?;
                let p: RawEndMoment = value.try_into().map_err(de_err)?;
                let nk = format!("{key}.node");
                let node = match ctx.node(&nk, &ctx.required(&nk, p.node)?, elements, false)? {
                    NodeSet::One(n) => n,
                    NodeSet::All => unreachable!("\"all\" is not accepted here"),
                };
                let m = ctx.required(&format!("{key}.moment"), p.moment)?;
                loads.push(Load::EndMoment {
                    node,
                    moment: ctx.vector(&format!("{key}.moment"), &m)?,
                });
            }
            "air-drag" => {
                ctx.field_types(&key, table, &[
                    ("drag_coefficient", Field::Number),
                    ("fluid_density", Field::Number),
                    ("diameter", Field::Number),
                    ("fluid_velocity", Field::Vector),
                    ("model", Field::Text),
                    ("tangential_coefficient", Field::Number),
                ])?;
                let d: RawAirDrag = value.try_into().map_err(de_err)?;
                let nonneg = |name: &str, v: f64| -> Result<f64, ScenarioError> {
                    let v = ctx.finite(&format!("{key}.{name}"), v)?;
                    if v < 0.0 {
                        return Err(ctx.err(&format!("{key}.{name}"), format!("must be >= 0, got {v}")));
                    }
                    Ok(v)
                };
                let c = nonneg(
                    "drag_coefficient",
                    ctx.required(&format!("{key}.drag_coefficient"), d.drag_coefficient)?,
                )?;
                let rho = nonneg(
                    "fluid_density",
                    ctx.required(&format!("{key}.fluid_density"), d.fluid_density)?,
                )?;
                let diameter = match d.diameter {
                    Some(v) => ctx.positive(&format!("{key}.diameter"), v)?,
                    None => diameter,
                };
                let fluid_velocity = match &d.fluid_velocity {
                    Some(v) => ctx.vector(&format!("{key}.fluid_velocity"), v)?,
                    None => [0.0; 3],
                };
                let model_name = ctx.choice(&format!("{key}.model"), d.model.as_deref(), "full", &["full", "normal"])?;
                let model = match model_name {
                    "normal" => stancf::loads::DragModel::Normal {
                        tangential_coefficient: match d.tangential_coefficient {
                            Some(v) => nonneg("tangential_coefficient", v)?,
                            None => 0.0,
                        },
                    },
                    _ => {
                        if d.tangential_coefficient.is_some() {
                            return Err(ctx.err(
                                &format!("{key}.tangential_coefficient"),
                                "only the \"normal\" drag model has a tangential coefficient",
                            ));
                        }
                        stancf::loads::DragModel::Full
                    }
                };
                loads.push(Load::AirDrag(stancf::loads::AirDrag {
                    drag_coefficient: c,
                    fluid_density: rho,
                    diameter,
                    fluid_velocity,
                    model,
                }));
            }
            other => {
                return Err(ctx.err(
                    &format!("{key}.type"),
                    format!(
                        "unknown load type \"{}\" (expected \"gravity\", \"point-force\", \"end-moment\" or \"air-drag\")",
                        clip(other, 60)
                    ),
                ))
            }
        }
    }

    let mut initial_velocity = Vec::new();
    for (i, iv) in raw.initial_velocity.iter().enumerate() {
        let key = format!("initial_velocity[{i}]");
        let nk = format!("{key}.node");
        let nodes = ctx.node(&nk, &ctx.required(&nk, iv.node.clone())?, elements, true)?;
        let angular_velocity = match &iv.angular_velocity {
            Some(w) => Some(ctx.vector(&format!("{key}.angular_velocity"), w)?),
            None => None,
        };
        let center = match &iv.center {
            Some(c) => ctx.vector(&format!("{key}.center"), c)?,
            None => [0.0; 3],
        };
        if nodes != NodeSet::All {
            if angular_velocity.is_some() {
                return Err(ctx.err(
                    &format!("{key}.angular_velocity"),
                    "a rigid rotation needs node = \"all\"",
                ));
            }
            if iv.center.is_some() {
                return Err(ctx.err(
                    &format!("{key}.center"),
                    "a rotation centre needs node = \"all\"",
                ));
            }
        }
        let velocity = match (&iv.velocity, angular_velocity) {
            (Some(v), _) => ctx.vector(&format!("{key}.velocity"), v)?,
            (None, Some(_)) => [0.0; 3],
            (None, None) => {
                return Err(ctx.err(&format!("{key}.velocity"), "required key is missing"))
            }
        };
        initial_velocity.push(InitialVelocity {
            nodes,
            velocity,
            angular_velocity,
            center,
        });
    }

    let ra = raw.analysis.unwrap_or_default();
    let kind = match ctx.choice(
        "analysis.type",
        ra.kind.as_deref(),
        "dynamic",
        &["dynamic", "static"],
    )? {
        "static" => AnalysisKind::Static,
        _ => AnalysisKind::Dynamic,
    };
    let mut notes = Vec::new();
    let (time_step, duration) = match kind {
        AnalysisKind::Dynamic => {
            let time_step = ctx.positive(
                "analysis.time_step",
                ctx.required("analysis.time_step", ra.time_step)?,
            )?;
            let duration = ctx.positive(
                "analysis.duration",
                ctx.required("analysis.duration", ra.duration)?,
            )?;
            if time_step > duration {
                return Err(ctx.err(
                    "analysis.time_step",
                    format!(
                        "the step ({time_step:e} s) is longer than the duration ({duration:e} s)"
                    ),
                ));
            }
            let steps = duration / time_step;
            if steps > MAX_COUNTABLE_STEPS {
                return Err(ctx.err(
                    "analysis.duration, analysis.time_step",
                    format!(
                        "duration / time_step = {} steps cannot be counted: above 2^53 = {:.4e} \
                         the simulated time no longer advances by exactly one step \
                         (a run is refused above {:e} steps anyway, see `stancf check`)",
                        Sig(steps),
                        MAX_COUNTABLE_STEPS,
                        crate::work_bounds::MAX_STEPS as f64
                    ),
                ));
            }
            (time_step, duration)
        }
        AnalysisKind::Static => {
            for (name, v) in [("time_step", ra.time_step), ("duration", ra.duration)] {
                if v.is_some() {
                    notes.push(format!("analysis.{name} is not used by a static analysis"));
                }
            }
            if ra.planar_reduction.is_some() {
                notes.push("analysis.planar_reduction is not used by a static analysis".into());
            }
            if !raw.initial_velocity.is_empty() {
                return Err(ctx.err("initial_velocity", "a static analysis has no velocities"));
            }
            if constraints.is_empty() {
                return Err(ctx.err(
                    "constraints",
                    "a static analysis needs constraints that remove the rigid motions; there are none",
                ));
            }
            (0.0, 0.0)
        }
    };
    let time_layers = match ra.time_layers {
        Some(n) => ctx.count("analysis.time_layers", n, 1, 16)?,
        None => 1,
    };
    let qmax = stancf::quadrature::MAX_POINTS as i64;
    let qkey = "analysis.quadrature";
    let (space_points, time_points) = match ra.quadrature.as_deref() {
        None => (None, 3),
        Some([s, t]) => {
            let s = ctx.count(qkey, *s, 1, qmax)?;
            let points = stancf::SpacePoints {
                axial: s,
                bending: s,
            };
            (Some(points), ctx.count(qkey, *t, 1, qmax)?)
        }
        Some([a, b, t]) => {
            let points = stancf::SpacePoints {
                axial: ctx.count(qkey, *a, 1, qmax)?,
                bending: ctx.count(qkey, *b, 1, qmax)?,
            };
            (Some(points), ctx.count(qkey, *t, 1, qmax)?)
        }
        Some(q) => {
            return Err(ctx.err(
                qkey,
                format!(
                    "expected [space, time] or [axial, bending, time] Gauss points, got {} numbers",
                    q.len()
                ),
            ))
        }
    };
    let solver = match ctx.choice(
        "analysis.solver",
        ra.solver.as_deref(),
        "newton",
        &["newton", "broyden", "modified-newton"],
    )? {
        "broyden" => stancf::SolverMethod::Broyden,
        "modified-newton" => stancf::SolverMethod::ModifiedNewton,
        _ => stancf::SolverMethod::Newton,
    };
    let time_scheme = match ctx.choice(
        "analysis.time_scheme",
        ra.time_scheme.as_deref(),
        "p2",
        &["p2", "galerkin"],
    )? {
        "galerkin" => stancf::TimeScheme::Galerkin,
        _ => stancf::TimeScheme::P2,
    };
    if time_scheme == stancf::TimeScheme::Galerkin && time_layers > 1 {
        return Err(ctx.err(
            "analysis.time_layers",
            format!(
                "the Galerkin step takes one layer per step (got {time_layers}): joining layers \
                 by C1 interior nodes inside a Galerkin step is unstable"
            ),
        ));
    }
    let tolerance = match ra.tolerance {
        Some(t) => ctx.positive("analysis.tolerance", t)?,
        None => 1e-10,
    };
    let max_iterations = match ra.max_iterations {
        Some(n) => ctx.count("analysis.max_iterations", n, 1, 10_000)?,
        None => 50,
    };
    let load_steps = match ra.load_steps {
        Some(n) => ctx.count("analysis.load_steps", n, 1, 1_000_000)?,
        None => 20,
    };
    let curvature = match ctx.choice(
        "analysis.curvature",
        ra.curvature.as_deref(),
        "paper",
        &["paper", "exact"],
    )? {
        "exact" => Curvature::Exact,
        _ => Curvature::Paper,
    };
    let axial_strain = match ctx.choice(
        "analysis.axial_strain",
        ra.axial_strain.as_deref(),
        "green",
        &["green", "engineering"],
    )? {
        "engineering" => AxialStrain::Engineering,
        _ => AxialStrain::Green,
    };
    let constraint_method = match ctx.choice(
        "analysis.constraint_method",
        ra.constraint_method.as_deref(),
        "multiplier",
        &["multiplier", "elimination"],
    )? {
        "elimination" => stancf::ConstraintMethod::Elimination,
        _ => stancf::ConstraintMethod::Multiplier,
    };
    check_initial_velocities(&ctx, &initial_velocity, &constraints)?;
    let ro = raw.output.unwrap_or_default();
    let output_every = match ro.every {
        Some(n) => ctx.count("output.every", n, 1, i64::MAX)?,
        None => 1,
    };

    Ok(Scenario {
        title,
        cable: stancf::Cable {
            length,
            elements,
            element_type: element,
            origin,
            direction,
        },
        material,
        diameter,
        options: ModelOptions {
            measures: Measures {
                axial_strain,
                curvature,
            },
            space_points,
        },
        loads,
        constraints,
        initial_velocity,
        analysis: Analysis {
            kind,
            time_step,
            duration,
            time_layers,
            space_points,
            time_points,
            tolerance,
            max_iterations,
            solver,
            time_scheme,
            load_steps,
            constraint_method,
            planar_reduction: ra.planar_reduction.unwrap_or(true),
        },
        output_every,
        notes,
    })
}

/// The `type` of a `[[loads]]` or `[[constraints]]` entry.
fn type_of(ctx: &Ctx, key: &str, table: &toml::Table) -> Result<String, ScenarioError> {
    match table.get("type") {
        Some(toml::Value::String(s)) => Ok(s.clone()),
        Some(_) => Err(ctx.err(&format!("{key}.type"), "must be a string")),
        None => Err(ctx.err(&format!("{key}.type"), "required key is missing")),
    }
}

/// An initial velocity given for one node must agree with a constraint on
/// that node (with node = "all", constrained coordinates keep the velocity
/// their constraint gives them).
fn check_initial_velocities(
    ctx: &Ctx,
    initial: &[InitialVelocity],
    constraints: &[stancf::Constraint],
) -> Result<(), ScenarioError> {
    for (i, iv) in initial.iter().enumerate() {
        let NodeSet::One(node) = iv.nodes else {
            continue;
        };
        for c in constraints.iter().filter(|c| c.node == node) {
            let (name, rate) = match c.kind {
                stancf::ConstraintKind::Clamped { .. } => ("clamped", [0.0; 3]),
                stancf::ConstraintKind::Pinned => ("pinned", [0.0; 3]),
                stancf::ConstraintKind::Prescribed {
                    velocity,
                    amplitude,
                    frequency,
                    phase,
                } => {
                    let w = 2.0 * std::f64::consts::PI * frequency;
                    let rate = [0, 1, 2].map(|k| velocity[k] + amplitude[k] * w * phase.cos());
                    ("prescribed", rate)
                }
            };
            if (0..3).any(|k| (iv.velocity[k] - rate[k]).abs() > 1e-12 * (1.0 + rate[k].abs())) {
                return Err(ctx.err(
                    &format!("initial_velocity[{i}].velocity"),
                    format!(
                        "node {node} is {name}: its velocity at t = 0 is {rate:?}, set by the constraint, not {:?}",
                        iv.velocity
                    ),
                ));
            }
        }
    }
    Ok(())
}

impl Scenario {
    /// The library model.
    pub fn model(&self) -> Result<stancf::Model, stancf::ModelError> {
        stancf::Model::new(
            self.cable,
            self.material,
            self.options.clone(),
            self.loads.clone(),
        )?
        .with_constraints(self.constraints.clone())
    }

    /// The initial state: the straight reference shape with the initial
    /// velocities applied in file order (a later entry overrides an earlier
    /// one on the same node; a rigid rotation adds to the velocity set by
    /// the same entry).
    pub fn initial_state(&self, model: &stancf::Model) -> stancf::State {
        let mut s = model.initial_state();
        for iv in &self.initial_velocity {
            match iv.nodes {
                NodeSet::One(n) => model.set_node_velocity(&mut s, n, iv.velocity),
                NodeSet::All => {
                    for n in 0..model.nodes() {
                        model.set_node_velocity(&mut s, n, iv.velocity);
                    }
                    if let Some(w) = iv.angular_velocity {
                        // Gradients' velocities come only from the rotation.
                        let dpn = model.dofs_per_node();
                        for n in 0..model.nodes() {
                            let o = model.node_offset(n);
                            s.v[o + 3..o + dpn].fill(0.0);
                        }
                        model.add_rigid_rotation(&mut s, w, iv.center);
                    }
                }
            }
        }
        model.apply_constraints(&mut s);
        s
    }

    /// The step settings for the library.
    pub fn step_settings(&self) -> stancf::StepSettings {
        stancf::StepSettings {
            time_step: self.analysis.time_step,
            time_layers: self.analysis.time_layers,
            time_points: self.analysis.time_points,
            newton: stancf::NewtonSettings {
                tolerance: self.analysis.tolerance,
                max_iterations: self.analysis.max_iterations,
                method: self.analysis.solver,
            },
            constraint_method: self.analysis.constraint_method,
            time_scheme: self.analysis.time_scheme,
            planar_reduction: self.analysis.planar_reduction,
        }
    }
}

impl Scenario {
    /// The static solve settings for the library.
    pub fn static_settings(&self) -> stancf::StaticSettings {
        stancf::StaticSettings {
            load_steps: self.analysis.load_steps,
            tolerance: self.analysis.tolerance,
            max_iterations: self.analysis.max_iterations,
            constraint_method: self.analysis.constraint_method,
            ..stancf::StaticSettings::default()
        }
    }
}
