//! Mesh grading (docs/method.md §1.6, (M38), (M38a)): where the nodes of
//! a cable sit along its material coordinate. A uniform mesh has elements
//! of length `L / n`; a graded one grows its elements geometrically away
//! from the end (or ends) where it is finest, such as a fairlead; a
//! sectioned one divides the line into consecutive sections, each in
//! equal elements of its own length, such as a fine touchdown zone between
//! a coarse grounded part and a coarse suspended one.
//! [`Grading::node_coordinates`] is the one place the node positions x_j
//! are computed; the model, the reference shape, the seeds and every
//! output take them from there.

use crate::error::ModelError;

/// The end (or ends) a graded mesh is finest at.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum GradedEnd {
    /// End A (node 0, x = 0).
    A,
    /// End B (the last node, x = L).
    B,
    /// Both ends: the elements grow toward the middle.
    Both,
}

impl GradedEnd {
    /// "A", "B" or "both" (as the scenario file writes it).
    pub fn name(self) -> &'static str {
        match self {
            GradedEnd::A => "A",
            GradedEnd::B => "B",
            GradedEnd::Both => "both",
        }
    }
}

/// One section of a sectioned mesh (M38a): `length` of unstretched line
/// in `elements` equal elements.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MeshSection {
    pub length: f64,
    pub elements: usize,
}

/// The relative tolerance on the sum of a sectioned mesh's lengths
/// against the line's length: the sum of a few decimal numbers a user
/// wrote carries round-off of a few ulps, a mistake is many orders larger.
const SECTION_LENGTH_TOLERANCE: f64 = 1e-9;

/// How the elements of a cable divide its length (docs/method.md §1.6).
#[derive(Clone, Debug, Default, PartialEq)]
pub enum Grading {
    /// Every element `L / n` long; node j at `j (L / n)`.
    #[default]
    Uniform,
    /// A geometric progression of element lengths, shortest at `toward`,
    /// with `ratio` = longest / shortest (>= 1; 1 is the uniform mesh,
    /// bit for bit). Toward one end, consecutive elements grow by
    /// `ratio^(1 / (n - 1))`; toward both, by `ratio^(1 / m)` from each
    /// end to the middle, `m = floor((n - 1) / 2)` (M38).
    Geometric { toward: GradedEnd, ratio: f64 },
    /// Consecutive sections from end A, each in equal elements of its own
    /// length (M38a); their lengths add up to the cable's, their elements
    /// to its element count.
    Sections(Vec<MeshSection>),
}

impl Grading {
    /// Whether the mesh is uniform: [`Grading::Uniform`], or a geometric
    /// grading of ratio 1.
    pub fn is_uniform(&self) -> bool {
        match self {
            Grading::Uniform => true,
            Grading::Geometric { ratio, .. } => *ratio == 1.0,
            Grading::Sections(_) => false,
        }
    }

    /// The relative length w_k of element k of n (the shortest 1, the
    /// longest `ratio`): `ratio^(p_k / m)` with p_k the element's
    /// distance in elements from the fine end (the nearer one, toward
    /// both) and m the largest p_k (M38). Exact at the ends of the
    /// progression: `ratio^0 = 1`, `ratio^1 = ratio`.
    fn weight(&self, k: usize, n: usize) -> f64 {
        let Grading::Geometric { toward, ratio } = *self else {
            return 1.0;
        };
        let (p, m) = match toward {
            GradedEnd::A => (k, n - 1),
            GradedEnd::B => (n - 1 - k, n - 1),
            GradedEnd::Both => (k.min(n - 1 - k), (n - 1) / 2),
        };
        if m == 0 {
            return 1.0;
        }
        ratio.powf(p as f64 / m as f64)
    }

    /// The material coordinates x_0 .. x_n of the nodes of a cable of
    /// `length` L in `elements` n elements (M38):
    ///
    /// ```text
    ///   uniform:  x_j = j (L / n)
    ///   graded:   x_j = L (S_j / S_n),   S_j = w_0 + ... + w_(j-1)
    ///   sections: x_j = L (X_j / X_n),   X_j = (L_0 + ... + L_(s-1))
    ///                                          + i (L_s / n_s)   (M38a)
    /// ```
    ///
    /// (node j the i-th of section s). The graded and sectioned x_n are L
    /// exactly (S_n / S_n = 1), and x_j is monotone (rounding is). The
    /// uniform form is the one of earlier versions, kept so that uniform
    /// meshes give the same numbers to the bit.
    pub fn node_coordinates(&self, length: f64, elements: usize) -> Vec<f64> {
        if let Grading::Sections(sections) = self {
            return section_node_coordinates(sections, length);
        }
        if self.is_uniform() {
            let l = length / elements as f64;
            return (0..=elements).map(|j| j as f64 * l).collect();
        }
        let mut sums = Vec::with_capacity(elements + 1);
        let mut s = 0.0;
        sums.push(s);
        for k in 0..elements {
            s += self.weight(k, elements);
            sums.push(s);
        }
        sums.iter().map(|&sj| length * (sj / s)).collect()
    }

    /// The reference length of every element: `L / n` for a uniform mesh
    /// (as in earlier versions), `x_(k+1) - x_k` of
    /// [`Self::node_coordinates`] for a graded one, so that the elements
    /// span the nodes exactly.
    pub fn element_lengths(&self, length: f64, elements: usize) -> Vec<f64> {
        if self.is_uniform() {
            return vec![length / elements as f64; elements];
        }
        self.node_coordinates(length, elements)
            .windows(2)
            .map(|x| x[1] - x[0])
            .collect()
    }

    /// Checks the ratio (finite, >= 1) and that `elements` can take the
    /// grading: a ratio above 1 needs two elements toward one end, three
    /// toward both; or that the sections are each of a finite positive
    /// length and at least one element, with lengths adding up to
    /// `length` (to 1e-9 of it) and elements to `elements`. The error's key
    /// is `cable.grading.ratio`, `cable.grading` or
    /// `cable.grading.sections`.
    pub fn check(&self, length: f64, elements: usize) -> Result<(), ModelError> {
        if let Grading::Sections(sections) = self {
            return check_sections(sections, length, elements);
        }
        let Grading::Geometric { toward, ratio } = *self else {
            return Ok(());
        };
        if !ratio.is_finite() || ratio < 1.0 {
            return Err(ModelError::invalid(
                "cable.grading.ratio",
                format!(
                    "must be a finite number >= 1 (the longest element over the shortest), \
                     got {ratio}"
                ),
            ));
        }
        let needed = match toward {
            GradedEnd::A | GradedEnd::B => 2,
            GradedEnd::Both => 3,
        };
        if ratio > 1.0 && elements < needed {
            return Err(ModelError::invalid(
                "cable.grading",
                format!(
                    "a grading of ratio {ratio} toward {} needs at least {needed} elements, \
                     got {elements}",
                    toward.name()
                ),
            ));
        }
        Ok(())
    }
}

/// The node coordinates of a sectioned mesh (M38a), from end A; the last
/// is `length` exactly.
fn section_node_coordinates(sections: &[MeshSection], length: f64) -> Vec<f64> {
    let total: f64 = sections.iter().map(|s| s.length).sum();
    let mut x = Vec::with_capacity(sections.iter().map(|s| s.elements).sum::<usize>() + 1);
    x.push(0.0);
    let mut start = 0.0;
    for s in sections {
        let l = s.length / s.elements as f64;
        for i in 1..=s.elements {
            x.push(length * ((start + i as f64 * l) / total));
        }
        start += s.length;
    }
    if let Some(last) = x.last_mut() {
        *last = length;
    }
    x
}

/// The checks of [`Grading::check`] for a sectioned mesh.
fn check_sections(
    sections: &[MeshSection],
    length: f64,
    elements: usize,
) -> Result<(), ModelError> {
    const KEY: &str = "cable.grading.sections";
    if sections.is_empty() {
        return Err(ModelError::invalid(KEY, "needs at least one section"));
    }
    for (i, s) in sections.iter().enumerate() {
        if !(s.length.is_finite() && s.length > 0.0) {
            return Err(ModelError::invalid(
                format!("{KEY}[{i}].length"),
                format!("must be a finite number > 0, got {}", s.length),
            ));
        }
        if s.elements == 0 {
            return Err(ModelError::invalid(
                format!("{KEY}[{i}].elements"),
                "must be at least 1",
            ));
        }
    }
    let total: f64 = sections.iter().map(|s| s.length).sum();
    if (total - length).abs() > SECTION_LENGTH_TOLERANCE * length {
        return Err(ModelError::invalid(
            KEY,
            format!("the sections' lengths add up to {total}, the line is {length} long"),
        ));
    }
    let count: usize = sections.iter().map(|s| s.elements).sum();
    if count != elements {
        return Err(ModelError::invalid(
            KEY,
            format!("the sections' elements add up to {count}, the line has {elements}"),
        ));
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Toward A with ratio 8 over 4 elements: lengths proportional to
    /// 1, 2, 4, 8 (q = 8^(1/3) = 2), i.e. L/15 times those.
    #[test]
    fn a_geometric_progression_toward_a_doubles_each_element() {
        let g = Grading::Geometric {
            toward: GradedEnd::A,
            ratio: 8.0,
        };
        let x = g.node_coordinates(15.0, 4);
        let want = [0.0, 1.0, 3.0, 7.0, 15.0];
        for (a, b) in x.iter().zip(want) {
            assert!((a - b).abs() <= 4.0 * f64::EPSILON * 15.0, "{x:?}");
        }
        assert_eq!(x[4], 15.0);
    }

    /// Toward both ends the lengths are symmetric, shortest at the ends
    /// and `ratio` times longer in the middle, for odd and even counts.
    #[test]
    fn grading_toward_both_ends_is_symmetric() {
        for n in [3, 4, 7, 10] {
            let g = Grading::Geometric {
                toward: GradedEnd::Both,
                ratio: 3.0,
            };
            let l = g.element_lengths(2.0, n);
            for k in 0..n {
                assert!((l[k] - l[n - 1 - k]).abs() <= 1e-15, "{n}: {l:?}");
            }
            let (lo, hi) = (l[0], l[(n - 1) / 2]);
            assert!((hi / lo - 3.0).abs() <= 1e-14, "{n}: {l:?}");
        }
    }

    /// Ratios below 1, non-finite ones and gradings that too few elements
    /// cannot take are refused, naming the key.
    #[test]
    fn bad_gradings_are_refused_by_key() {
        let g = |toward, ratio| Grading::Geometric { toward, ratio };
        for r in [0.5, f64::NAN, f64::INFINITY, -2.0] {
            let e = g(GradedEnd::B, r).check(10.0, 8).unwrap_err();
            assert_eq!(e.key, "cable.grading.ratio", "{e}");
        }
        assert_eq!(
            g(GradedEnd::A, 2.0).check(10.0, 1).unwrap_err().key,
            "cable.grading"
        );
        assert_eq!(
            g(GradedEnd::Both, 2.0).check(10.0, 2).unwrap_err().key,
            "cable.grading"
        );
        assert!(g(GradedEnd::Both, 1.0).check(10.0, 1).is_ok());
        assert!(g(GradedEnd::Both, 2.0).check(10.0, 3).is_ok());
    }

    /// Sections of 30 m in 3 elements and 70 m in 2: nodes at 0, 10, 20,
    /// 30, 65, 100; the last at the length exactly, even where the
    /// sections' sum carries round-off (0.1 + 0.2 != 0.3).
    #[test]
    fn sections_divide_each_part_of_the_line_equally() {
        let s = |length, elements| MeshSection { length, elements };
        let g = Grading::Sections(vec![s(30.0, 3), s(70.0, 2)]);
        let x = g.node_coordinates(100.0, 5);
        let want = [0.0, 10.0, 20.0, 30.0, 65.0, 100.0];
        for (a, b) in x.iter().zip(want) {
            assert!((a - b).abs() <= 4.0 * f64::EPSILON * 100.0, "{x:?}");
        }
        let l = g.element_lengths(100.0, 5);
        assert!(
            (l[0] - 10.0).abs() < 1e-12 && (l[4] - 35.0).abs() < 1e-12,
            "{l:?}"
        );
        let odd = Grading::Sections(vec![s(0.1, 1), s(0.2, 4)]);
        assert!(odd.check(0.3, 5).is_ok());
        assert_eq!(odd.node_coordinates(0.3, 5)[5], 0.3);
    }

    /// Sections whose lengths or elements do not add up, empty ones, and
    /// a zero or non-finite length are refused, naming the key.
    #[test]
    fn bad_sections_are_refused_by_key() {
        let s = |length, elements| MeshSection { length, elements };
        let key = |g: Grading, l, n| g.check(l, n).unwrap_err().key;
        let two = || Grading::Sections(vec![s(30.0, 3), s(70.0, 2)]);
        assert_eq!(key(two(), 100.1, 5), "cable.grading.sections");
        assert_eq!(key(two(), 100.0, 6), "cable.grading.sections");
        assert_eq!(
            key(Grading::Sections(vec![]), 1.0, 1),
            "cable.grading.sections"
        );
        assert_eq!(
            key(Grading::Sections(vec![s(f64::NAN, 1)]), 1.0, 1),
            "cable.grading.sections[0].length"
        );
        assert_eq!(
            key(Grading::Sections(vec![s(1.0, 1), s(0.0, 1)]), 1.0, 2),
            "cable.grading.sections[1].length"
        );
        assert_eq!(
            key(Grading::Sections(vec![s(1.0, 0)]), 1.0, 0),
            "cable.grading.sections[0].elements"
        );
        assert!(two().check(100.0, 5).is_ok());
    }
}
