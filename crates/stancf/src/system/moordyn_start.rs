//! MoorDyn's start when it generates no initial conditions (a deck's
//! `TmaxIC 0`; docs/method.md §13.7): every line in its seed shape
//! between its ends where the scenario puts them, at rest, and the forces
//! those shapes put on their ends, which the run's t = 0 row and a
//! coupling code's init are given (where MoorDyn 2.7 gives zero until its
//! first step, docs/method.md §13.7).

use super::seed::{catenary_states, end_positions, overlong_line, seed_shape, straight_states};
use super::{EndForce, OverlongLine, System};
use crate::model::State;

/// MoorDyn's start when it generates no initial conditions (a deck's
/// TmaxIC 0; docs/method.md §13.7): each line of `system` in its seed
/// shape of `seed` (the same lines with their wet weights,
/// [`catenary_states`]); a line longer than its catenary can hold (C20)
/// straight between its ends, as MoorDyn lays it, shortened and slack
/// where it carries no compression (M4a). Every line is judged where its
/// ends are, a line to a free point too, as MoorDyn judges each line
/// before anything moves (OpenFAST's md_case2: a chain to a free point
/// exactly as long as its "L", L = XF + ZF, starts straight). A line that
/// carries compression would start pushing its ends apart: the first
/// such line is the error.
pub fn moordyn_start_states(system: &System, seed: &System) -> Result<Vec<State>, OverlongLine> {
    let mut states = catenary_states(seed);
    let straight = straight_states(system);
    for l in (0..seed.lines().len()).filter_map(|i| overlong_line(seed, i)) {
        if system.lines()[l.line].model.carries_compression() {
            return Err(l);
        }
        states[l.line] = straight[l.line].clone();
    }
    Ok(states)
}

/// The forces the lines of [`moordyn_start_states`] put on their ends:
/// each seed shape's, the elastic catenary's (C12), the closed form's
/// resting on the bed ((C14)-(C21), fairlead and anchor) or the folded
/// vertical line's (M32d), of the lines' wet weights in `seed`; none from
/// a line laid straight and slack (overlong, (C20)), as MoorDyn's
/// straight line carries no compression.
pub fn moordyn_start_forces(seed: &System) -> Vec<[EndForce; 2]> {
    (0..seed.lines().len())
        .map(|i| {
            if overlong_line(seed, i).is_some() {
                return [EndForce::default(); 2];
            }
            let (a, b) = end_positions(seed, i);
            let shape = seed_shape(seed, i, a, b);
            [0, 1].map(|end| EndForce {
                force: shape.end_force(end),
            })
        })
        .collect()
}
