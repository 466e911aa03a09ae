//! The rule a derived figure must satisfy (finite, within [`MAX_SCALE`],
//! at least its inverse for a divisor) and the one input error a figure
//! breaking it becomes: its value, what is exceeded and the scenario keys
//! it is made of, the most extreme value first. Also the names of the keys
//! and the norms the figures are made with.

use super::MAX_SCALE;
use crate::Failure;
use stancf::error::Sig;

/// What a derived figure must satisfy.
#[derive(Clone, Copy)]
pub(super) enum Rule {
    /// A finite number.
    Finite,
    /// Finite and at most `MAX_SCALE` in magnitude.
    Scale,
    /// Finite, at most `MAX_SCALE` and at least `1 / MAX_SCALE` (the
    /// solver divides by it).
    Divisor,
    /// Finite and at most this.
    Below(f64),
}

/// The derived figures of a scenario, checked one by one; a figure that
/// breaks its rule is an input error naming the keys it is made of, the
/// most extreme value first.
pub(super) struct Figures<'a> {
    pub(super) file: &'a str,
    /// Magnitude of every key's value (largest component of a vector).
    pub(super) values: Vec<(String, f64)>,
}

impl Figures<'_> {
    /// The key of a graded or sectioned mesh among the values (the
    /// grading's ratio, or the section of the shortest elements), which
    /// the shortest element length is made of too.
    pub(super) fn grading_key(&self) -> Option<&str> {
        self.values
            .iter()
            .map(|(k, _)| k.as_str())
            .find(|k| *k == key::GRADING_RATIO || k.starts_with(key::SECTIONS))
    }

    fn value(&self, key: &str) -> f64 {
        self.values
            .iter()
            .find(|(k, _)| k == key)
            .map_or(1.0, |(_, v)| *v)
    }

    /// `what = value unit`, checked against `rule`: the one place a figure
    /// out of range becomes an input error naming `keys`.
    pub(super) fn need(
        &self,
        what: &str,
        value: f64,
        unit: &str,
        keys: &[String],
        rule: Rule,
    ) -> Result<(), Failure> {
        let v = value.abs();
        let problem = match rule {
            _ if value.is_nan() => Some("is not a number".to_string()),
            _ if value.is_infinite() => Some("overflows (it is beyond 1.8e308)".to_string()),
            Rule::Finite => None,
            Rule::Scale | Rule::Divisor if v > MAX_SCALE => {
                Some(format!("is beyond {MAX_SCALE:e}{unit}"))
            }
            Rule::Divisor if v < 1.0 / MAX_SCALE => {
                Some(format!("is below {:e}{unit}", 1.0 / MAX_SCALE))
            }
            Rule::Below(limit) if v > limit => Some(format!("is beyond {limit:e}{unit}")),
            _ => None,
        };
        let Some(problem) = problem else {
            return Ok(());
        };
        let mut keys = keys.to_vec();
        if keys.iter().any(|k| k == key::ELEMENTS) {
            // On a graded or sectioned mesh the element length l (the
            // shortest) is made of the grading too.
            if let Some(grading) = self.grading_key() {
                keys.push(grading.to_string());
            }
        }
        let keys = self.culprits_first(&keys);
        let shown: Vec<String> = keys
            .iter()
            .map(|k| format!("{k} = {}", Sig(self.value(k))))
            .collect();
        Err(Failure::Input(format!(
            "{}: {}: {what} = {}{unit} {problem}: the solver computes in double precision and \
             needs the derived scales within 1e-150 to 1e150 (SI units); from {}: check these \
             values and their units",
            self.file,
            keys.join(", "),
            Sig(value),
            shown.join(", ")
        )))
    }

    /// `keys` ordered by how far their values are from 1 (|log10 v|, a
    /// non-finite value first, a zero last): the likely culprit first.
    fn culprits_first(&self, keys: &[String]) -> Vec<String> {
        let extremeness = |k: &String| {
            let v = self.value(k);
            if !v.is_finite() {
                f64::INFINITY
            } else if v > 0.0 {
                v.log10().abs()
            } else {
                -1.0 // a zero is never the culprit
            }
        };
        let mut keys = keys.to_vec();
        keys.sort_by(|a, b| extremeness(b).total_cmp(&extremeness(a)));
        keys.dedup();
        keys
    }
}

/// The Euclidean norm |v|.
pub(super) fn norm(v: &[f64]) -> f64 {
    v.iter().map(|c| c * c).sum::<f64>().sqrt()
}

/// The largest component magnitude max_i |v_i|.
pub(super) fn largest(v: &[f64]) -> f64 {
    v.iter().fold(0.0f64, |m, c| m.max(c.abs()))
}

/// The scenario keys of the cable, its material and the analysis that the
/// figures are made of.
pub(super) mod key {
    pub(in crate::input_scales) const YOUNGS_MODULUS: &str = "material.youngs_modulus";
    pub(in crate::input_scales) const DENSITY: &str = "material.density";
    pub(in crate::input_scales) const AREA: &str = "material.area";
    pub(in crate::input_scales) const SECOND_MOMENT: &str = "material.second_moment";
    pub(in crate::input_scales) const LENGTH: &str = "cable.length";
    pub(in crate::input_scales) const ELEMENTS: &str = "cable.elements";
    /// Among the values only for a graded mesh (docs/method.md §1.6).
    pub(in crate::input_scales) const GRADING_RATIO: &str = "cable.grading.ratio";
    /// Of a sectioned mesh: `cable.grading.sections[i].length` of the
    /// section with the shortest elements.
    pub(in crate::input_scales) const SECTIONS: &str = "cable.grading.sections";
    pub(in crate::input_scales) const ORIGIN: &str = "cable.origin";
    pub(in crate::input_scales) const TIME_STEP: &str = "analysis.time_step";
    pub(in crate::input_scales) const DURATION: &str = "analysis.duration";
}

/// The keys `ks`, as a figure's list of the keys it is made of.
pub(super) fn keys(ks: &[&str]) -> Vec<String> {
    ks.iter().map(|k| k.to_string()).collect()
}

/// The keys `base` followed by `more`.
pub(super) fn with(mut base: Vec<String>, more: &[String]) -> Vec<String> {
    base.extend(more.iter().cloned());
    base
}
