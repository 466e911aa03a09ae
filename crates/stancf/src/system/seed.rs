//! Start shapes of a system's lines (docs/method.md §11.6): straight
//! between the end points, or the elastic catenary through them, the
//! seed of a static solve.

use super::{End, System};
use crate::catenary::touchdown::{
    max_resting_length, solve_touchdown, TouchdownLine, TouchdownRegime, TouchdownSolution,
};
use crate::catenary::{Catenary, CatenaryLine, LineEnd};
use crate::model::{coordinate, Model, State, SLOT_R, SLOT_R_X, SLOT_R_XX};
use crate::vec3::norm;

/// A straight state of `model` from a to b, at rest at t = 0:
/// r_j = a + (b - a) x_j / L, r_x = (b - a) / L, r_xx = 0 (stretched or
/// compressed to the chord).
pub fn straight_between(model: &Model, a: [f64; 3], b: [f64; 3]) -> State {
    let len = model.cable.length;
    let rx: [f64; 3] = std::array::from_fn(|k| (b[k] - a[k]) / len);
    shaped(model, |x| {
        (std::array::from_fn(|k| a[k] + rx[k] * x), rx, [0.0; 3])
    })
}

/// The state at rest whose node j has (r, r_x, r_xx) = `shape(x_j)`.
pub fn shaped(model: &Model, shape: impl Fn(f64) -> ([f64; 3], [f64; 3], [f64; 3])) -> State {
    let dpn = model.dofs_per_node();
    let vectors = model.element_type().vectors_per_node();
    let mut e = vec![0.0; model.dofs()];
    for j in 0..model.nodes() {
        let (r, rx, rxx) = shape(model.node_coordinate(j));
        for (slot, v) in [(SLOT_R, r), (SLOT_R_X, rx), (SLOT_R_XX, rxx)] {
            if slot < vectors {
                for k in 0..3 {
                    e[coordinate(dpn, j, slot, k)] = v[k];
                }
            }
        }
    }
    State {
        t: 0.0,
        v: vec![0.0; e.len()],
        e,
        internal: Vec::new(),
    }
}

/// Where line `line`'s ends start: at their points (at t = 0); a loose
/// end hangs the line's length from the other along gravity (along -z
/// without gravity).
pub fn end_positions(system: &System, line: usize) -> ([f64; 3], [f64; 3]) {
    let at_rest: Vec<[f64; 3]> = system.points().iter().map(|p| p.state_at(0.0).0).collect();
    end_positions_at(system, line, &at_rest)
}

/// [`end_positions`] with point p at `positions[p]`.
pub fn end_positions_at(
    system: &System,
    line: usize,
    positions: &[[f64; 3]],
) -> ([f64; 3], [f64; 3]) {
    let l = &system.lines()[line];
    let at = |e: End| match e {
        End::Point(p) => Some(positions[p]),
        End::Loose => None,
    };
    let g = system.gravity();
    let gn = norm(g);
    let down = if gn > 0.0 {
        g.map(|c| c / gn)
    } else {
        [0.0, 0.0, -1.0]
    };
    let length = l.model.cable.length;
    let hang = |from: [f64; 3]| -> [f64; 3] { std::array::from_fn(|k| from[k] + length * down[k]) };
    match (at(l.ends[0]), at(l.ends[1])) {
        (Some(a), Some(b)) => (a, b),
        (Some(a), None) => (a, hang(a)),
        (None, Some(b)) => (hang(b), b),
        (None, None) => (l.model.cable.origin, hang(l.model.cable.origin)),
    }
}

/// The strain of a slack line's taut state in [`taut_states`]: just
/// above zero, where a line without compression has its full axial
/// stiffness, and far enough above the round-off of a unit tangent's
/// length (1e-16) that it cannot read as slack.
const JUST_TAUT: f64 = 1e-9;

/// Every line straight along its chord from its end A, stretched as the
/// chord stretches it, or just taut ([`JUST_TAUT`]) where the chord is
/// shorter than the line (along -z for a chord of zero length): where
/// its axial modes, a line's highest, are as stiff as they get short of
/// a stretch. A slack line's straight start between its ends is
/// compressed, and a line without compression has no axial stiffness
/// there: its highest frequency would be its bending's, which its motion
/// leaves as soon as it pulls taut. A line of a nonlinear axial law
/// (docs/method.md §2.2a) is stretched into the middle of its stiffest
/// segment. The states the P2 step's stability is judged on
/// ([`super::stable_step`]).
pub fn taut_states(system: &System) -> Vec<State> {
    (0..system.lines().len())
        .map(|i| {
            let model = &system.lines()[i].model;
            let (a, b) = end_positions(system, i);
            let chord: [f64; 3] = std::array::from_fn(|k| b[k] - a[k]);
            let span = norm(chord);
            let length = model.cable.length;
            let (direction, stretch) = if span > 0.0 {
                (
                    chord.map(|c| c / span),
                    (span / length).max(1.0 + JUST_TAUT),
                )
            } else {
                ([0.0, 0.0, -1.0], 1.0 + JUST_TAUT)
            };
            // A nonlinear axial law (M4b) is judged where it is stiffest.
            let stretch = model
                .axial_curve()
                .map_or(stretch, |c| 1.0 + c.stiffest_strain());
            let end: [f64; 3] = std::array::from_fn(|k| a[k] + direction[k] * stretch * length);
            straight_between(model, a, end)
        })
        .collect()
}

/// Every line straight between its end points ([`straight_between`],
/// [`end_positions`]), with the constrained coordinates at their
/// prescribed values and rates: the reference start of a system.
pub fn straight_states(system: &System) -> Vec<State> {
    (0..system.lines().len())
        .map(|i| {
            let model = &system.lines()[i].model;
            let (a, b) = end_positions(system, i);
            let mut s = straight_between(model, a, b);
            model.apply_constraints(&mut s);
            s
        })
        .collect()
}

/// Every line as its seed shape through its end points where the
/// scenario puts them (docs/method.md §11.6): the elastic catenary of its
/// weight per length (rho A |g|) and EA ([`crate::catenary`]; node j
/// takes r, r_x and r_xx of the catenary at its material coordinate).
/// Where no catenary exists (a slack weightless line, a slack vertical
/// one), the line starts straight between its ends. A line whose
/// catenary would pass through its flat seabed, anchored on the bed,
/// starts as the closed form resting on the bed instead (§11.12): the
/// catenary would start it metres inside the bed, where the contact's
/// forces (and static friction's stiffness) are far from the solution's.
/// The seed of a static solve is [`super::static_seed_states`].
pub fn catenary_states(system: &System) -> Vec<State> {
    let at_rest: Vec<[f64; 3]> = system.points().iter().map(|p| p.state_at(0.0).0).collect();
    catenary_states_at(system, &at_rest)
}

/// [`catenary_states`] with point p at `positions[p]`.
pub fn catenary_states_at(system: &System, positions: &[[f64; 3]]) -> Vec<State> {
    (0..system.lines().len())
        .map(|i| {
            let model = &system.lines()[i].model;
            let (a, b) = end_positions_at(system, i, positions);
            let mut s = seed_shape(system, i, a, b).state(model, a, b);
            // The end nodes exactly at their ends: the closed form's far
            // end carries its round-off (1e-14 m), and a dynamic start
            // from these states asks the ends of the lines at a point to
            // coincide.
            let dpn = model.dofs_per_node();
            for (node, at) in [(0, a), (model.nodes() - 1, b)] {
                for k in 0..3 {
                    s.e[coordinate(dpn, node, SLOT_R, k)] = at[k];
                }
            }
            model.apply_constraints(&mut s);
            s
        })
        .collect()
}

/// The seed shape of one line between end positions a and b.
pub(super) enum SeedShape {
    Catenary(Catenary),
    Resting(Resting),
    /// A slack vertical line folded under its lower end (M32d): the
    /// state straight between its ends, the folded line's end forces.
    Folded(Folded),
    /// No catenary (a slack weightless line, or a slack vertical one
    /// whose fold would reach into its bed): straight, and no force on
    /// its ends.
    Straight,
}

/// A slack line whose ends are one above the other, hanging as the
/// limit of its catenary as the span goes to zero (docs/method.md
/// §11.6, (M32d)): the line falls from each end to a fold below the
/// lower one, the upper side's unstretched length s_u and the lower
/// side's s_l with
///
/// ```text
///   s_u + s_l = L,   (s_u - s_l) (1 + w L / (2 EA)) = |rise|,
///   f_upper = w s_u g^,   f_lower = w s_l g^                          (M32d)
/// ```
///
/// (each side stretched by its own weight, w s^2 / (2 EA); g^ the
/// direction of gravity). At s_l = 0 it is the taut vertical line whose
/// lower end is at zero tension, so the end forces are continuous as the
/// line goes from taut to slack. A free point or body that hangs below
/// its anchor passes this way in the catenary network: from above the
/// anchor it falls, the fold pulling it down, past the anchor, until the
/// line is taut under it.
pub(super) struct Folded {
    /// The force on end A and on end B.
    forces: [[f64; 3]; 2],
}

/// (M32d) for a line between a and b, if it is vertical and slack, has
/// weight, and its fold stays above its bed.
fn folded_vertical(
    model: &Model,
    line: CatenaryLine,
    a: [f64; 3],
    b: [f64; 3],
    gravity: [f64; 3],
) -> Option<Folded> {
    let g = norm(gravity);
    if g == 0.0 || line.weight <= 0.0 || line.ea.is_nan() || line.ea <= 0.0 {
        return None;
    }
    let down = gravity.map(|c| c / g);
    let chord: [f64; 3] = std::array::from_fn(|k| b[k] - a[k]);
    let drop_ab = crate::vec3::dot(chord, down);
    let across: [f64; 3] = std::array::from_fn(|k| chord[k] - drop_ab * down[k]);
    if norm(across) > 1e-12 * norm(chord).max(line.length) {
        return None;
    }
    let w = line.weight;
    let (upper_side, lower_side) = fold_sides(line, drop_ab.abs())?;
    // End B below end A when the chord from A to B points down.
    let (lower, upper_end) = if drop_ab > 0.0 { (b, 0) } else { (a, 1) };
    if let Some(bed) = model.seabed.as_ref() {
        let bottom: [f64; 3] = std::array::from_fn(|k| {
            lower[k] + down[k] * lower_side * (1.0 + w * lower_side / (2.0 * line.ea))
        });
        if bed.seabed.penetration(&bottom) > 0.0 {
            return None;
        }
    }
    let mut forces = [[0.0; 3]; 2];
    forces[upper_end] = down.map(|c| w * upper_side * c);
    forces[1 - upper_end] = down.map(|c| w * lower_side * c);
    Some(Folded { forces })
}

/// The unstretched lengths (s_u, s_l) of (M32d)'s upper and lower sides
/// of a vertical line whose ends are `drop` apart; None where it is taut
/// (s_l would be negative: |rise| >= L (1 + w L / (2 EA))).
fn fold_sides(line: CatenaryLine, drop: f64) -> Option<(f64, f64)> {
    let length = line.length;
    let difference = drop / (1.0 + line.weight * length / (2.0 * line.ea));
    if difference >= length {
        return None;
    }
    let lower_side = 0.5 * (length - difference);
    Some((length - lower_side, lower_side))
}

/// Line `line`'s seed shape from `a` to `b` (see [`catenary_states`]).
pub(super) fn seed_shape(system: &System, line: usize, a: [f64; 3], b: [f64; 3]) -> SeedShape {
    seed_shape_capped(system, line, a, b, f64::INFINITY)
}

/// [`seed_shape`] with the line's EA taken at most `ea_cap` (the
/// softened catenary network, docs/method.md §11.6).
pub(super) fn seed_shape_capped(
    system: &System,
    line: usize,
    a: [f64; 3],
    b: [f64; 3],
    ea_cap: f64,
) -> SeedShape {
    let model = &system.lines()[line].model;
    let section = model.material.section();
    let cat_line = CatenaryLine {
        length: model.cable.length,
        weight: section.rho_a * norm(model.gravity),
        ea: section.ea.min(ea_cap),
    };
    let direction = if norm(model.gravity) > 0.0 {
        model.gravity
    } else {
        system.gravity()
    };
    match Catenary::between(cat_line, a, b, direction) {
        Ok(c) if norm(direction) > 0.0 => {
            let through_bed = model.seabed.as_ref().is_some_and(|bed| {
                (0..model.nodes()).any(|j| {
                    bed.seabed
                        .penetration(&c.position(model.node_coordinate(j)))
                        > 0.0
                })
            });
            match through_bed
                .then(|| resting_shape(model, cat_line, a, b))
                .flatten()
            {
                Some(rest) => SeedShape::Resting(rest),
                None => SeedShape::Catenary(c),
            }
        }
        _ => folded_vertical(model, cat_line, a, b, direction)
            .map_or(SeedShape::Straight, SeedShape::Folded),
    }
}

impl SeedShape {
    /// The line's state at rest in this shape (from `a` to `b`).
    fn state(&self, model: &Model, a: [f64; 3], b: [f64; 3]) -> State {
        match self {
            SeedShape::Catenary(c) => shaped(model, |x| {
                (c.position(x), c.derivative(x), c.second_derivative(x))
            }),
            SeedShape::Resting(rest) => shaped(model, |x| rest.at(x)),
            SeedShape::Folded(_) | SeedShape::Straight => straight_between(model, a, b),
        }
    }

    /// The force the line exerts on the point at its end `end` (0: A,
    /// 1: B): the catenary's (C12); resting on the bed, the fairlead's
    /// (HF, VF) pulling the upper end down and towards the anchor, the
    /// anchor's HA pulling the lower end towards the fairlead.
    pub(super) fn end_force(&self, end: usize) -> [f64; 3] {
        match self {
            SeedShape::Catenary(c) => c.end_force(if end == 0 { LineEnd::A } else { LineEnd::B }),
            SeedShape::Resting(rest) => {
                let [hx, hy] = rest.horizontal;
                let sol = &rest.solution;
                // End A is the lower end unless the line was reversed.
                if (end == 0) != rest.reversed {
                    [sol.ha * hx, sol.ha * hy, sol.va]
                } else {
                    [-sol.hf * hx, -sol.hf * hy, -sol.vf]
                }
            }
            SeedShape::Folded(fold) => fold.forces[end],
            SeedShape::Straight => [0.0; 3],
        }
    }
}

/// The closed form of a line resting on its flat seabed (docs/method.md
/// §11.12, (C14)-(C21), frictionless) from its lower end, on the bed,
/// to its upper end, in the vertical plane through both: r(x), r_x and
/// r_xx at material coordinate x from end A (derivatives by central
/// differences over 1e-4 of the length: a seed). None where it does not
/// apply: a bed that is not flat, gravity not along its normal, the
/// lower end off the bed (by more than 1e-6 of the length), ends one
/// above the other, or no resting solution (the line too long, (C20)).
fn resting_shape(model: &Model, line: CatenaryLine, a: [f64; 3], b: [f64; 3]) -> Option<Resting> {
    let AnchoredOnBed {
        low,
        high,
        reversed,
        span,
    } = anchored_on_bed(model, a, b)?;
    let length = model.cable.length;
    let resting = TouchdownLine {
        length,
        weight: line.weight,
        ea: line.ea,
        friction: 0.0,
    };
    let solution = solve_touchdown(&resting, span, high[2] - low[2]).ok()?;
    if solution.regime == TouchdownRegime::Hanging {
        return None;
    }
    let horizontal = [(high[0] - low[0]) / span, (high[1] - low[1]) / span];
    Some(Resting {
        solution,
        low,
        horizontal,
        reversed,
        length,
    })
}

/// A line from its lower end on its flat bed to its upper end.
struct AnchoredOnBed {
    low: [f64; 3],
    high: [f64; 3],
    /// Whether end B is the lower one.
    reversed: bool,
    /// The horizontal distance between the ends.
    span: f64,
}

/// The ends a, b of a line of `model` as [`resting_shape`] takes them;
/// None where it does not apply (see there).
fn anchored_on_bed(model: &Model, a: [f64; 3], b: [f64; 3]) -> Option<AnchoredOnBed> {
    let bed = &model.seabed.as_ref()?.seabed;
    let g = norm(model.gravity);
    let down: [f64; 3] = model.gravity.map(|c| c / g);
    let bed_height = bed.horizontal_height()?;
    if down != [0.0, 0.0, -1.0] {
        return None;
    }
    let length = model.cable.length;
    let (low, high, reversed) = if a[2] <= b[2] {
        (a, b, false)
    } else {
        (b, a, true)
    };
    if (low[2] - bed_height).abs() > 1e-6 * length {
        return None;
    }
    let span = ((high[0] - low[0]).powi(2) + (high[1] - low[1]).powi(2)).sqrt();
    if span <= 1e-9 * length {
        return None;
    }
    Some(AnchoredOnBed {
        low,
        high,
        reversed,
        span,
    })
}

/// A line anchored on its flat bed that is longer than its path to the
/// fairlead can hold (C20).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct OverlongLine {
    /// The line's index.
    pub line: usize,
    /// Its unstretched length (m).
    pub length: f64,
    /// L_max = XF + V0/W of (C20) (m).
    pub max_length: f64,
}

impl std::fmt::Display for OverlongLine {
    /// Why the line has no unique equilibrium (its subject is the line).
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(
            f,
            "its {} m are at least the {} m that can hang from its fairlead and lie straight \
             along the bed to its anchor (L_max = XF + V0/W, docs/method.md (C20)); the rest \
             would lie slack on the bed in a shape no static solve determines, so the line has \
             no unique equilibrium",
            crate::error::Sig(self.length),
            crate::error::Sig(self.max_length)
        )
    }
}

/// The lines of `system` between fixed or coupled points, anchored on its
/// flat bed, whose length reaches L_max (C20) between the points where
/// they are at t = 0: each would hang vertically from its fairlead and
/// lie along the bed with length to spare, which lies slack on the bed in
/// a shape no static solve determines (docs/method.md §11.12). A line to
/// a free point is not judged here: the point moves until it hangs.
/// Weights are the lines' weight per length under their models' gravity:
/// pass the seed system (wet weights, §11.6).
pub fn overlong_lines(system: &System) -> Vec<OverlongLine> {
    (0..system.lines().len())
        .filter(|&i| {
            system.lines()[i].ends.iter().all(|e| match *e {
                End::Point(p) => !system.points()[p].is_free(),
                End::Loose => false,
            })
        })
        .filter_map(|i| overlong_line(system, i))
        .collect()
}

/// Line `i` of `system`, if it is anchored on its flat bed and its length
/// reaches L_max (C20) between its ends where they are now, whatever
/// holds them: MoorDyn's catenary start refuses such a line and lays it
/// straight (MoorDyn's `Catenary`, "line length too large").
pub(super) fn overlong_line(system: &System, i: usize) -> Option<OverlongLine> {
    let model = &system.lines()[i].model;
    let (a, b) = end_positions(system, i);
    let ends = anchored_on_bed(model, a, b)?;
    let section = model.material.section();
    let weight = section.rho_a * norm(model.gravity);
    let zf = ends.high[2] - ends.low[2];
    if weight <= 0.0 || zf <= 0.0 {
        return None;
    }
    let max_length = max_resting_length(weight, section.ea, ends.span, zf);
    (model.cable.length >= max_length).then_some(OverlongLine {
        line: i,
        length: model.cable.length,
        max_length,
    })
}

/// A line resting on the bed, as [`resting_shape`] solves it.
pub(super) struct Resting {
    solution: TouchdownSolution,
    low: [f64; 3],
    horizontal: [f64; 2],
    reversed: bool,
    length: f64,
}

impl Resting {
    /// r at arc length s from the lower end.
    fn point(&self, s: f64) -> [f64; 3] {
        let (x, z) = self.solution.position(s.clamp(0.0, self.length));
        [
            self.low[0] + x * self.horizontal[0],
            self.low[1] + x * self.horizontal[1],
            self.low[2] + z,
        ]
    }

    /// (r, r_x, r_xx) at material coordinate x from end A.
    fn at(&self, x: f64) -> ([f64; 3], [f64; 3], [f64; 3]) {
        let (s, sign) = if self.reversed {
            (self.length - x, -1.0)
        } else {
            (x, 1.0)
        };
        let h = 1e-4 * self.length;
        // Central differences inside, shifted one step in at the ends.
        let c = s.clamp(h, self.length - h);
        let (m, o, p) = (self.point(c - h), self.point(c), self.point(c + h));
        let r = self.point(s);
        let rx = std::array::from_fn(|k| sign * (p[k] - m[k]) / (2.0 * h));
        let rxx = std::array::from_fn(|k| (p[k] - 2.0 * o[k] + m[k]) / (h * h));
        (r, rx, rxx)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// (M32d)'s sides meet the taut vertical catenary (§11.1) where the
    /// line goes slack: just below the drop L (1 + w L / (2 EA)) the
    /// lower side's length, and so its end's pull w s_l, goes to zero,
    /// and the upper end's pull to w L, as the taut line's end forces
    /// just above it; and the sides always add up to L.
    #[test]
    fn a_folded_vertical_lines_end_forces_meet_the_taut_lines() {
        let line = CatenaryLine {
            length: 4.5,
            weight: 19.127,
            ea: 500.0,
        };
        let taut_from = line.length * (1.0 + line.weight * line.length / (2.0 * line.ea));
        let (upper, lower) = fold_sides(line, taut_from * (1.0 - 1e-9)).unwrap();
        assert!((upper + lower - line.length).abs() < 1e-14);
        let taut = Catenary::between(
            line,
            [0.0; 3],
            [0.0, 0.0, -taut_from * (1.0 + 1e-9)],
            [0.0, 0.0, -1.0],
        )
        .unwrap();
        let (top, bottom) = (taut.end_force(LineEnd::A), taut.end_force(LineEnd::B));
        let scale = line.weight * line.length;
        assert!(
            (line.weight * upper - top[2].abs()).abs() < 1e-6 * scale,
            "{upper} {top:?}"
        );
        assert!(
            (line.weight * lower - bottom[2].abs()).abs() < 1e-6 * scale,
            "{lower} {bottom:?}"
        );
        assert!(fold_sides(line, taut_from * (1.0 + 1e-9)).is_none());
        let (upper, lower) = fold_sides(line, 0.0).unwrap();
        assert_eq!(upper, lower);
    }
}
