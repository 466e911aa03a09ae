//! `[[initial_velocity]]`: velocities at t = 0, for one node or all of
//! them (optionally with a rigid rotation), and the initial state they
//! give.

use super::context::Ctx;
use super::raw::RawInitialVelocity;
use super::{Scenario, ScenarioError};
use stancf::model::SLOT_R_X;

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

/// Every `[[initial_velocity]]` entry, in file order: `node` (required;
/// "all" allowed), `angular_velocity` and `center` (vectors; node = "all"
/// only), `velocity` (a vector; required unless `angular_velocity` is
/// given). `elements` bounds the node indices.
pub(super) fn initial_velocities(
    ctx: &Ctx,
    raw: &[RawInitialVelocity],
    elements: usize,
) -> Result<Vec<InitialVelocity>, ScenarioError> {
    let mut initial_velocity = Vec::with_capacity(raw.len());
    for (i, iv) in raw.iter().enumerate() {
        let key = format!("initial_velocity[{i}]");
        let nk = format!("{key}.node");
        let nodes = ctx.node(&nk, &ctx.required(&nk, iv.node.clone())?, elements, true)?;
        let angular_velocity = match &iv.angular_velocity {
            Some(w) => Some(ctx.vector(&format!("{key}.angular_velocity"), w)?),
            None => None,
        };
        let center = ctx.vector_or(&format!("{key}.center"), iv.center.as_deref(), [0.0; 3])?;
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
    Ok(initial_velocity)
}

/// An initial velocity given for one node must agree with a constraint on
/// that node (with node = "all", constrained coordinates keep the velocity
/// their constraint gives them): `initial_velocity[i].velocity` against
/// `[[constraints]]`.
pub(super) fn check_initial_velocities(
    ctx: &Ctx,
    initial: &[InitialVelocity],
    constraints: &[stancf::Constraint],
) -> Result<(), ScenarioError> {
    for (i, iv) in initial.iter().enumerate() {
        let NodeSet::One(node) = iv.nodes else {
            continue;
        };
        for c in constraints.iter().filter(|c| c.node == node) {
            let (name, rate) = match &c.kind {
                stancf::ConstraintKind::Clamped { .. } => ("clamped", [0.0; 3]),
                stancf::ConstraintKind::Pinned => ("pinned", [0.0; 3]),
                // Holds r_x's direction, not r.
                stancf::ConstraintKind::Parallel { .. } => continue,
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
                stancf::ConstraintKind::Attached { position, motion } => {
                    ("attached to a point", motion.state_at(position, 0.0).1)
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
                        for n in 0..model.nodes() {
                            let slopes = model.coordinate(n, SLOT_R_X, 0)..model.node_range(n).end;
                            s.v[slopes].fill(0.0);
                        }
                        model.add_rigid_rotation(&mut s, w, iv.center);
                    }
                }
            }
        }
        model.apply_constraints(&mut s);
        s
    }
}
