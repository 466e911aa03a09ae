//! What seabed friction holds at a system's static equilibrium
//! (docs/method.md §12.2, (W48)-(W49)).
//!
//! Static friction is indeterminate: a chain resting on a bed with
//! coefficient mu may carry any axial friction up to mu w per metre of its
//! resting length L_B, in either direction, so the anchor's horizontal
//! force can be anything in [H_F - mu w L_B, H_F + mu w L_B] (clipped at
//! zero) for one fairlead force H_F. Which one a line carries depends on
//! how it got there. stancf's static friction (W48) resists the slide of
//! each point from a reference position, the friction's *target*; the
//! policy says where the targets are:
//!
//! - [`StaticFriction::AsLaid`]: the lines were laid in their equilibrium
//!   and nothing has dragged them since; friction holds nothing. The
//!   equilibrium is the frictionless one, which is also an equilibrium of
//!   the dynamic equations at rest (their friction acts on the sliding
//!   velocity, (W43)-(W44)), and it is where MoorDyn's dynamic
//!   relaxation ends (its friction is a saturated damping of the nodes'
//!   velocities). The default of a scenario.
//! - [`StaticFriction::Pulled`]: every line anchored on the bed was laid
//!   unstretched and pulled out towards its fairlead to its tension, so
//!   friction holds it back towards the anchor wherever it has slid: the
//!   closed form of quasi-static mooring codes with CB (docs/method.md
//!   §11.12, (C14)-(C21); MAP++, MoorPy). Solved in two stages: as laid,
//!   then with the targets put back where the unstretched resting part
//!   lay (W49) and the friction on.
//! - [`StaticFriction::FromSeed`]: the targets are the seeds given to
//!   [`super::SystemStatics::new`], for a caller who knows how the lines
//!   were laid.
//!
//! Measured on MoorDyn's WD0050_Chain deck (mu = 0.5, 243 m on the bed):
//! the targets at the seed on the bed's surface, as before these
//! policies, put the anchor's horizontal force 42.5 kN *above* the
//! fairlead's: the line settles 0.13 m into the soft bed while its anchor
//! stays at the surface, the dip draws the first nodes 0.2-0.4 mm
//! towards the anchor, and friction, mobilized over u_s = 0.25 mm,
//! resisted that, a slide no real line makes. As laid, the two agree
//! (MoorDyn 2.7: 839.3 and 839.3 kN); pulled, the anchor's is below the
//! fairlead's by the friction of the resting part.

pub use crate::statics::StaticFriction;

use super::System;
use crate::model::State;
use crate::model::{coordinate, Model, SLOT_R, SLOT_R_X};
use crate::statics::{CableStatics, StaticSettings};
use crate::vec3::{dot, norm};

/// `model` without seabed friction (the static copy of a line laid as in
/// its equilibrium): the contact's normal force stays.
pub(super) fn without_friction(mut model: Model) -> Model {
    if let Some(contact) = model.seabed.as_mut() {
        contact.seabed.friction_axial = 0.0;
        contact.seabed.friction_transverse = 0.0;
    }
    model
}

/// Whether `model` has a seabed with friction.
pub(super) fn has_friction(model: &Model) -> bool {
    model
        .seabed
        .as_ref()
        .is_some_and(|c| c.seabed.has_friction())
}

/// The friction targets of a line pulled out along the bed (W49): from
/// the coordinates `e` of its equilibrium as laid, every node moved back
/// towards the anchor by the stretch of the resting part between the
/// anchor and it,
///
/// ```text
///   r_0(x) = r(x) - t(x) int_0^x chi(s) eps(s) ds,
///   r_0,x(x) = r_x(x) - chi(x) eps(x) t(x),
/// ```
///
/// with eps = |r_x| - 1 the engineering strain, chi = 1 where the line
/// lies on the bed (the contact pushes on it, or it is the anchor's node)
/// and t the unit direction along the bed away from the anchor (P_n r_x /
/// |P_n r_x|, reversed when the anchor is end B). The hanging part's
/// targets move by the whole resting stretch, so the seed of the pull is
/// continuous at touchdown. The anchor is the end whose node is on the
/// bed (penetration within 1e-6 of the length of the surface or in it)
/// while the other end is off it; a line with both ends on the bed or
/// neither has no anchor to pull from: None.
pub(super) fn pulled_targets(model: &Model, e: &[f64]) -> Option<Vec<f64>> {
    let contact = model.seabed.as_ref()?;
    let bed = &contact.seabed;
    let dpn = model.dofs_per_node();
    let nodes = model.nodes();
    let position =
        |j: usize| -> [f64; 3] { std::array::from_fn(|c| e[coordinate(dpn, j, SLOT_R, c)]) };
    let tangent =
        |j: usize| -> [f64; 3] { std::array::from_fn(|c| e[coordinate(dpn, j, SLOT_R_X, c)]) };
    let slack = 1e-6 * model.cable.length;
    let on_bed = |j: usize| bed.penetration(&position(j)) >= -slack;
    let anchor = match (on_bed(0), on_bed(nodes - 1)) {
        (true, false) => 0,
        (false, true) => nodes - 1,
        _ => return None,
    };
    // Nodes in order from the anchor, and the sign that turns r_x into
    // the direction away from it.
    let order: Vec<usize> = if anchor == 0 {
        (0..nodes).collect()
    } else {
        (0..nodes).rev().collect()
    };
    let away = if anchor == 0 { 1.0 } else { -1.0 };
    let along_bed = |j: usize| -> Option<[f64; 3]> {
        let n = bed.normal_at(&position(j));
        let rx = tangent(j);
        let rn = dot(n, rx);
        let p: [f64; 3] = std::array::from_fn(|c| away * (rx[c] - rn * n[c]));
        let len = norm(p);
        (len > 0.0).then(|| p.map(|c| c / len))
    };
    let strain = |j: usize| norm(tangent(j)) - 1.0;
    let mut targets = e.to_vec();
    let mut shift = [0.0; 3];
    let mut resting = true;
    let mut last_direction = along_bed(anchor)?;
    for w in 0..nodes {
        let j = order[w];
        if resting && w > 0 {
            let i = order[w - 1];
            if on_bed(j) {
                // The trapezoid of chi eps t over the element i..j.
                let dx = (model.node_coordinate(j) - model.node_coordinate(i)).abs();
                let tj = along_bed(j).unwrap_or(last_direction);
                let (ei, ej) = (strain(i), strain(j));
                for c in 0..3 {
                    shift[c] += 0.5 * dx * (ei * last_direction[c] + ej * tj[c]);
                }
                last_direction = tj;
            } else {
                resting = false;
            }
        }
        for c in 0..3 {
            targets[coordinate(dpn, j, SLOT_R, c)] -= shift[c];
        }
        if resting {
            let eps = strain(j);
            for c in 0..3 {
                targets[coordinate(dpn, j, SLOT_R_X, c)] -= away * eps * last_direction[c];
            }
        }
    }
    Some(targets)
}

/// Each line's static equations from its seed (docs/method.md §11.6): a
/// line without compression with its compressive stiffness kept (§2.2,
/// (M4a)), or, marked in `own_law`, with its own law (M32c); the
/// seabed's friction off while the lines are solved as laid (the whole
/// solve of [`StaticFriction::AsLaid`], the first stage of
/// [`StaticFriction::Pulled`]), and its targets at `targets` in the
/// pull (W49).
pub(super) fn line_statics(
    system: &System,
    seeds: &[State],
    own_law: &[bool],
    targets: Option<&[Vec<f64>]>,
    settings: &StaticSettings,
) -> Vec<CableStatics> {
    let frictionless = match settings.seabed_friction {
        StaticFriction::AsLaid => true,
        StaticFriction::Pulled => targets.is_none(),
        StaticFriction::FromSeed => false,
    };
    system
        .lines()
        .iter()
        .zip(seeds)
        .zip(own_law)
        .enumerate()
        .map(|(i, ((line, seed), &own))| {
            // At exactly zero tension a line without compression has no
            // axial stiffness without it, and where it is nowhere
            // shortened the equilibrium is the same; where it is, the
            // line is solved again with its own law (M32c).
            let mut model = if own {
                line.model.clone()
            } else {
                line.model.clone().with_compression()
            };
            if frictionless {
                model = without_friction(model);
            }
            let mut line = CableStatics::new(model, settings.constraint_method, seed.e.clone());
            line.take_strain_defects();
            if let Some(t) = targets {
                line.set_friction_targets(&t[i]);
            }
            line
        })
        .collect()
}
