//! The checks every part of a scenario uses: a required key, a finite or
//! positive number, a count in a range, a vector of 3, one of a few
//! words, a node, the types of a `[[loads]]` or `[[constraints]]` entry.
//! Each reports `<file>: <key>: <what is wrong>`.

use super::messages::{clip, describe_value, plain_words};
use super::{NodeSet, ScenarioError};
use serde::de::DeserializeOwned;

/// Collects errors with the file name in front.
pub(super) struct Ctx<'a> {
    pub(super) file: &'a str,
}

impl Ctx<'_> {
    pub(super) fn err(&self, key: &str, msg: impl std::fmt::Display) -> ScenarioError {
        ScenarioError(format!("{}: {}: {}", self.file, key, msg))
    }

    pub(super) fn required<T>(&self, key: &str, v: Option<T>) -> Result<T, ScenarioError> {
        v.ok_or_else(|| self.err(key, "required key is missing"))
    }

    pub(super) fn finite(&self, key: &str, v: f64) -> Result<f64, ScenarioError> {
        if v.is_finite() {
            Ok(v)
        } else {
            Err(self.err(key, format!("must be a finite number, got {v}")))
        }
    }

    pub(super) fn positive(&self, key: &str, v: f64) -> Result<f64, ScenarioError> {
        let v = self.finite(key, v)?;
        if v > 0.0 {
            Ok(v)
        } else {
            Err(self.err(key, format!("must be > 0, got {v}")))
        }
    }

    pub(super) fn count(
        &self,
        key: &str,
        v: i64,
        min: i64,
        max: i64,
    ) -> Result<usize, ScenarioError> {
        if v < min || v > max {
            if max == i64::MAX {
                return Err(self.err(key, format!("must be at least {min}, got {v}")));
            }
            return Err(self.err(key, format!("must be between {min} and {max}, got {v}")));
        }
        Ok(v as usize)
    }

    pub(super) fn vector(&self, key: &str, v: &[f64]) -> Result<[f64; 3], ScenarioError> {
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

    pub(super) fn choice<'s>(
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

    /// A required key that must be a finite number > 0.
    pub(super) fn required_positive(
        &self,
        key: &str,
        v: Option<f64>,
    ) -> Result<f64, ScenarioError> {
        self.positive(key, self.required(key, v)?)
    }

    /// A finite number >= 0.
    pub(super) fn non_negative(&self, key: &str, v: f64) -> Result<f64, ScenarioError> {
        let v = self.finite(key, v)?;
        if v < 0.0 {
            return Err(self.err(key, format!("must be >= 0, got {v}")));
        }
        Ok(v)
    }

    /// An optional vector: checked by [`Ctx::vector`] if given, else
    /// `default`.
    pub(super) fn vector_or(
        &self,
        key: &str,
        v: Option<&[f64]>,
        default: [f64; 3],
    ) -> Result<[f64; 3], ScenarioError> {
        match v {
            Some(v) => self.vector(key, v),
            None => Ok(default),
        }
    }

    /// The required `node` of a `[[loads]]` or `[[constraints]]` entry:
    /// one node ("A", "B" or an index, not "all").
    pub(super) fn one_node(
        &self,
        key: &str,
        node: Option<toml::Value>,
        elements: usize,
    ) -> Result<usize, ScenarioError> {
        match self.node(key, &self.required(key, node)?, elements, false)? {
            NodeSet::One(n) => Ok(n),
            NodeSet::All => unreachable!("\"all\" is not accepted here"),
        }
    }

    /// The `type` of a `[[loads]]` or `[[constraints]]` entry: a string,
    /// required.
    pub(super) fn type_of(&self, key: &str, table: &toml::Table) -> Result<String, ScenarioError> {
        match table.get("type") {
            Some(toml::Value::String(s)) => Ok(s.clone()),
            Some(_) => Err(self.err(&format!("{key}.type"), "must be a string")),
            None => Err(self.err(&format!("{key}.type"), "required key is missing")),
        }
    }

    /// A `[[loads]]` or `[[constraints]]` entry deserialized into its
    /// `Raw*` type once its `type` is known; serde's message (an unknown
    /// key, say) in plain words under the entry's key.
    pub(super) fn entry<T: DeserializeOwned>(
        &self,
        key: &str,
        table: &toml::Table,
    ) -> Result<T, ScenarioError> {
        toml::Value::Table(table.clone())
            .try_into()
            .map_err(|e: toml::de::Error| self.err(key, plain_words(e.message())))
    }

    /// A node: "A", "B", an integer index 0..=elements or (`allow_all`)
    /// "all".
    pub(super) fn node(
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
    pub(super) fn field_types(
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
pub(super) enum Field {
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
