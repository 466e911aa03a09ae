//! Constraints on nodal coordinates (paper section 3; docs/method.md
//! §6.1-6.4).
//!
//! A constraint fixes coordinates of a node for all t: `clamped` fixes r
//! and r_x (and r_xx on request, SAC-3 only), `pinned` fixes r, and
//! `prescribed` moves r along
//!
//! ```text
//!   r(t) = r0 + u t + a sin(2 pi f t + phi)
//! ```
//!
//! In a step, a constrained coordinate's values at the time nodes after
//! t_a are known (e_j(t_i) = c_j(t_i), v_j(t_i) = c_j'(t_i)) and the rows
//! of eq. (22) it would have carried are freed: they hold the unknown
//! reaction. Two routes enforce this ([`ConstraintMethod`]): Lagrange
//! multipliers (the paper's supplementary constraints, eqs. 19 and 24,
//! after its "constraint conversion": one multiplier per freed row, one
//! constraint equation per fixed value, so no P2 row becomes singular) and
//! direct elimination of the fixed coordinates and their rows. Both give
//! the same motion to round-off.
//!
//! One constraint holds a combination of coordinates instead: `parallel`
//! keeps r_x along a direction (a line end clamped in a direction,
//! §6.10, [`DirectionHold`]), enforced by multipliers only.

mod direction;

use crate::error::ModelError;
pub use crate::motion::{
    ramp_factor, CoordinateMotion, CoupledMotion, HarmonicMotion, IntervalMotion, MotionTable,
    Oscillation,
};
use crate::numbering::{coordinate, ElementType, SLOT_R, SLOT_R_X};
pub use direction::DirectionHold;

/// What a constraint fixes (docs/method.md §6.1).
#[derive(Clone, Debug, PartialEq)]
pub enum ConstraintKind {
    /// r and r_x fixed; r_xx too when `fix_curvature` (SAC-3 only; the
    /// paper's Table 3 "with r_xx constraint" row, wrong for a bent
    /// cantilever).
    Clamped { fix_curvature: bool },
    /// r fixed.
    Pinned,
    /// r(t) = r0 + velocity t + amplitude sin(2 pi frequency t + phase),
    /// r0 the node's reference position.
    Prescribed {
        velocity: [f64; 3],
        amplitude: [f64; 3],
        frequency: f64,
        phase: f64,
    },
    /// r_x held parallel to `direction` (normalized here; a clamp in a
    /// direction, a riser hang-off, docs/method.md §6.10): the two linear
    /// equations n_1 . r_x = n_2 . r_x = 0, n_1, n_2 orthonormal to the
    /// direction, so the end may still stretch along it. r is not held (a
    /// clamp pairs it with `Pinned` or `Attached`). Multiplier route and
    /// P2 or static only.
    Parallel { direction: [f64; 3] },
    /// r held at a point of a system: fixed (an anchor) or moving with it
    /// (a coupled point, a fairlead) along `motion` from `position`
    /// ((M30) or (M39)).
    Attached {
        position: [f64; 3],
        motion: CoupledMotion,
    },
}

/// A constraint on one node.
#[derive(Clone, Debug, PartialEq)]
pub struct Constraint {
    pub node: usize,
    pub kind: ConstraintKind,
}

/// How constraints are enforced.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum ConstraintMethod {
    /// Lagrange multipliers (the paper's supplementary constraints;
    /// docs/method.md §6.3).
    #[default]
    Multiplier,
    /// Direct elimination of the constrained coordinates (docs/method.md
    /// §6.4).
    Elimination,
}

/// The motions of r of a node attached to a point (see
/// [`ConstraintKind::Attached`]).
fn attached_motions(
    key: &str,
    position: [f64; 3],
    motion: &CoupledMotion,
) -> Result<Vec<(usize, CoordinateMotion)>, ModelError> {
    let finite = |v: &[f64; 3]| v.iter().all(|x| x.is_finite());
    let o = match motion {
        CoupledMotion::Oscillation(o) => o,
        // A table is checked when built (MotionTable::new).
        CoupledMotion::Table(_) => &Oscillation::NONE,
        CoupledMotion::Interval(i) if !i.is_valid() => {
            return Err(ModelError::invalid(
                key,
                format!(
                    "the coupling interval's times, positions and velocities must be finite \
                     and its length positive, got {i:?}"
                ),
            ))
        }
        CoupledMotion::Interval(_) => &Oscillation::NONE,
    };
    if !finite(&position) || !finite(&o.amplitude) {
        return Err(ModelError::invalid(
            key,
            format!(
                "the point's position and motion amplitude must be finite, got {position:?} \
                 and {:?}",
                o.amplitude
            ),
        ));
    }
    for (name, v) in [("period", o.period), ("ramp", o.ramp)] {
        if !v.is_finite() || v < 0.0 {
            return Err(ModelError::invalid(
                format!("{key}.{name}"),
                format!("must be a finite number >= 0, got {v}"),
            ));
        }
    }
    if !o.phase.is_finite() {
        return Err(ModelError::invalid(
            format!("{key}.phase"),
            format!("must be a finite number, got {}", o.phase),
        ));
    }
    Ok((0..3)
        .map(|d| (d, motion.coordinate_motion(&position, d)))
        .collect())
}

fn conflict(key: &str, other: usize, what: &str, node: usize) -> ModelError {
    ModelError::invalid(
        key,
        format!("conflicts with constraints[{other}]: both constrain {what} of node {node}"),
    )
}

/// All constraints of a model, resolved to coordinates.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Constraints {
    /// As given.
    pub list: Vec<Constraint>,
    /// Per global coordinate: its prescribed motion, if constrained.
    pub motion: Vec<Option<CoordinateMotion>>,
    /// Nodes whose position r is constrained (their reactions are
    /// reported), ascending.
    pub position_nodes: Vec<usize>,
    /// r_x held parallel to a direction ([`ConstraintKind::Parallel`]),
    /// in the order given.
    pub directions: Vec<DirectionHold>,
    /// Per global coordinate: held because the motion stays in a plane
    /// (see [`crate::Model::reduce_to_plane`]), not by a constraint. Such a
    /// coordinate has a fixed `motion` and is always eliminated, never
    /// given a multiplier. Empty when no coordinate is held so.
    pub inactive: Vec<bool>,
    /// Every z coordinate is held by the planar reduction (the line moves
    /// in a plane z = const): its elements leave their z rows and columns
    /// unevaluated (docs/method.md §7.10).
    pub in_plane: bool,
}

impl Constraints {
    /// Resolves `list` for a mesh; `reference` holds the coordinates of the
    /// reference shape (clamped and pinned coordinates keep these values).
    pub fn new(
        list: Vec<Constraint>,
        element: ElementType,
        nodes: usize,
        reference: &[f64],
    ) -> Result<Self, ModelError> {
        let dpn = element.dofs_per_node();
        let mut motion: Vec<Option<CoordinateMotion>> = vec![None; nodes * dpn];
        let mut owner: Vec<Option<usize>> = vec![None; nodes * dpn];
        let mut position_nodes = Vec::new();
        let mut directions = Vec::new();
        for (ci, c) in list.iter().enumerate() {
            let key = format!("constraints[{ci}]");
            if c.node >= nodes {
                return Err(ModelError::invalid(
                    format!("{key}.node"),
                    format!(
                        "node {} does not exist (nodes are 0..={})",
                        c.node,
                        nodes - 1
                    ),
                ));
            }
            let o = coordinate(dpn, c.node, SLOT_R, 0);
            let coords: Vec<(usize, CoordinateMotion)> = match c.kind.clone() {
                ConstraintKind::Clamped { fix_curvature } => {
                    if fix_curvature && element != ElementType::Sac3 {
                        return Err(ModelError::invalid(
                            format!("{key}.fix_curvature"),
                            "only SAC-3 elements have an r_xx coordinate to fix",
                        ));
                    }
                    let n = if fix_curvature { 9 } else { 6 };
                    (0..n)
                        .map(|d| (d, CoordinateMotion::fixed(reference[o + d])))
                        .collect()
                }
                ConstraintKind::Pinned => (0..3)
                    .map(|d| (d, CoordinateMotion::fixed(reference[o + d])))
                    .collect(),
                ConstraintKind::Prescribed {
                    velocity,
                    amplitude,
                    frequency,
                    phase,
                } => {
                    for (name, v) in [("velocity", &velocity), ("amplitude", &amplitude)] {
                        if v.iter().any(|x| !x.is_finite()) {
                            return Err(ModelError::invalid(
                                format!("{key}.{name}"),
                                format!("must have finite components, got {v:?}"),
                            ));
                        }
                    }
                    if !frequency.is_finite() || frequency < 0.0 {
                        return Err(ModelError::invalid(
                            format!("{key}.frequency"),
                            format!("must be a finite number >= 0, got {frequency}"),
                        ));
                    }
                    if !phase.is_finite() {
                        return Err(ModelError::invalid(
                            format!("{key}.phase"),
                            format!("must be a finite number, got {phase}"),
                        ));
                    }
                    (0..3)
                        .map(|d| {
                            (
                                d,
                                CoordinateMotion::Harmonic(HarmonicMotion {
                                    base: reference[o + d],
                                    rate: velocity[d],
                                    amplitude: amplitude[d],
                                    omega: 2.0 * std::f64::consts::PI * frequency,
                                    phase,
                                    ramp: 0.0,
                                }),
                            )
                        })
                        .collect()
                }
                ConstraintKind::Attached { position, motion } => {
                    attached_motions(&key, position, &motion)?
                }
                ConstraintKind::Parallel { direction } => {
                    let hold = DirectionHold::new(&key, c.node, direction)?;
                    for d in 3..6 {
                        if let Some(other) = owner[o + d] {
                            return Err(conflict(&key, other, "r_x", c.node));
                        }
                        owner[o + d] = Some(ci);
                    }
                    directions.push(hold);
                    continue;
                }
            };
            for (d, m) in coords {
                if let Some(other) = owner[o + d] {
                    let names = ["r", "r_x", "r_xx"];
                    return Err(conflict(&key, other, names[d / 3], c.node));
                }
                owner[o + d] = Some(ci);
                motion[o + d] = Some(m);
            }
            position_nodes.push(c.node);
        }
        position_nodes.sort_unstable();
        Ok(Constraints {
            list,
            motion,
            position_nodes,
            directions,
            inactive: Vec::new(),
            in_plane: false,
        })
    }

    /// Refuses what the direction holds cannot be enforced with: the
    /// elimination route (a combination of coordinates, not a coordinate,
    /// is held). Key `analysis.constraint_method` in errors.
    pub fn check_direction_route(&self, method: ConstraintMethod) -> Result<(), ModelError> {
        let Some(h) = self.directions.first() else {
            return Ok(());
        };
        if method == ConstraintMethod::Elimination {
            return Err(ModelError::invalid(
                "analysis.constraint_method",
                format!(
                    "node {} is clamped in a direction (r_x parallel to {:?}), which holds a \
                     combination of coordinates: only the multiplier route enforces it; use \
                     constraint_method = \"multiplier\"",
                    h.node, h.direction
                ),
            ));
        }
        Ok(())
    }

    pub fn is_empty(&self) -> bool {
        self.list.is_empty()
    }

    /// The direction hold whose r_x coordinate g is (with `dpn`
    /// coordinates per node), with g's component (0, 1, 2) and the
    /// node's first r_x coordinate.
    pub fn held_direction(&self, dpn: usize, g: usize) -> Option<(&DirectionHold, usize, usize)> {
        let (node, d) = (g / dpn, g % dpn);
        if !(3..6).contains(&d) {
            return None;
        }
        let hold = self.directions.iter().find(|h| h.node == node)?;
        Some((hold, d - 3, g - (d - 3)))
    }

    /// Adds mass entry (i, j, m) of an unconstrained row i of a mass solve
    /// at the end of a Galerkin step through `add`, a held node's r_x rows
    /// turned to (M43) ([`DirectionHold::mass_row_weight`]); the holds'
    /// rate rows are added by [`Self::add_hold_rate_rows`].
    pub fn add_mass_entry(
        &self,
        dpn: usize,
        i: usize,
        j: usize,
        m: f64,
        mut add: impl FnMut(usize, usize, f64),
    ) {
        match self.held_direction(dpn, i) {
            Some((hold, c, first)) => add(first, j, hold.mass_row_weight(c) * m),
            None => add(i, j, m),
        }
    }

    /// The holds' rate rows n_k . v_rx = 0 of a mass solve (M43), through
    /// `add(row, column, value)` (coordinates).
    pub fn add_hold_rate_rows(&self, dpn: usize, mut add: impl FnMut(usize, usize, f64)) {
        for hold in &self.directions {
            let first = coordinate(dpn, hold.node, SLOT_R_X, 0);
            for (row, c, n) in hold.rate_rows() {
                add(first + row, first + c, n);
            }
        }
    }

    /// Turns the momentum `p` (per coordinate) of a mass solve's right
    /// side to (M43) at the held nodes' r_x rows.
    pub fn turn_hold_momentum(&self, dpn: usize, p: &mut [f64]) {
        for hold in &self.directions {
            let first = coordinate(dpn, hold.node, SLOT_R_X, 0);
            let rows = hold.momentum_rows([p[first], p[first + 1], p[first + 2]]);
            p[first..first + 3].copy_from_slice(&rows);
        }
    }

    /// True if the coordinate's values are prescribed: by a constraint, or
    /// because it is held by the planar reduction.
    pub fn is_constrained(&self, g: usize) -> bool {
        self.motion[g].is_some()
    }

    /// True if the coordinate is held by the planar reduction.
    pub fn is_inactive(&self, g: usize) -> bool {
        self.inactive.get(g).copied().unwrap_or(false)
    }

    /// Moves node `node`'s attachment to a point ([`ConstraintKind::Attached`])
    /// onto `motion` (a coupling code's next interval, §13.2); `dpn` is the
    /// element's coordinates per node. Refused when the node has no such
    /// constraint or when the planar reduction holds a coordinate the new
    /// motion would move.
    pub fn set_attached_motion(
        &mut self,
        node: usize,
        dpn: usize,
        motion: CoupledMotion,
    ) -> Result<(), ModelError> {
        let key = format!("node {node}");
        let Some(c) = self
            .list
            .iter_mut()
            .find(|c| c.node == node && matches!(c.kind, ConstraintKind::Attached { .. }))
        else {
            return Err(ModelError::invalid(key, "is not attached to a point"));
        };
        let ConstraintKind::Attached { position, .. } = c.kind else {
            unreachable!("matched above")
        };
        let coords = attached_motions(&key, position, &motion)?;
        let o = coordinate(dpn, node, SLOT_R, 0);
        for (d, m) in &coords {
            if self.inactive.get(o + d) == Some(&true) && !m.is_still() {
                return Err(ModelError::invalid(
                    key,
                    "the motion leaves the plane the line was reduced to (planar reduction)",
                ));
            }
        }
        c.kind = ConstraintKind::Attached { position, motion };
        for (d, m) in coords {
            self.motion[o + d] = Some(m);
        }
        Ok(())
    }

    /// True if some coordinate is held by the planar reduction.
    pub fn has_inactive(&self) -> bool {
        self.inactive.iter().any(|&b| b)
    }

    /// Holds coordinate g at `value` for all t (planar reduction). A
    /// coordinate a constraint already holds keeps its motion.
    pub fn hold_inactive(&mut self, g: usize, value: f64) {
        if self.inactive.len() < self.motion.len() {
            self.inactive.resize(self.motion.len(), false);
        }
        if self.motion[g].is_none() {
            self.motion[g] = Some(CoordinateMotion::fixed(value));
        }
        self.inactive[g] = true;
    }

    /// True if some constraint moves (prescribed motion does work).
    pub fn moves(&self) -> bool {
        self.motion.iter().flatten().any(|m| !m.is_still())
    }

    /// Whether the constraints remove the rigid motions of a static
    /// problem: some node's position must be held (translations), and a
    /// clamp or a second held position must stop the rotations.
    pub fn remove_rigid_motions(&self) -> bool {
        let clamped = self.list.iter().any(|c| {
            matches!(
                c.kind,
                ConstraintKind::Clamped { .. } | ConstraintKind::Parallel { .. }
            )
        });
        let mut nodes = self.position_nodes.clone();
        nodes.dedup();
        !nodes.is_empty() && (clamped || nodes.len() >= 2)
    }
}
