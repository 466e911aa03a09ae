//! MoorDyn-F's EXTERNAL LOADS of a deck on its scenario's points and
//! bodies (docs/method.md §15.21; the rows read and checked by
//! `crate::moordyn::external_loads`): a body's global force joins its
//! constant force at the reference point, its body-axes force and both
//! dampings its external loads; a point's force joins its constant force,
//! its damping its own.

use super::bodies::SystemBody;
use super::system_parts::SystemPoint;
use crate::moordyn::external_loads::{on_body, on_point, LoadAxes, LoadedObject};
use crate::moordyn::Deck;

/// Puts the deck's external loads on `bodies` and `points` (the deck's
/// bodies and points first, in deck order); the notes `check` prints.
pub(super) fn deck_external_loads(
    deck: &Deck,
    bodies: &mut [SystemBody],
    points: &mut [SystemPoint],
) -> Vec<String> {
    let loads = &deck.external_loads;
    for (i, b) in bodies.iter_mut().enumerate().take(deck.bodies.len()) {
        let (force, body_force, global, body) = on_body(loads, i + 1);
        for k in 0..3 {
            b.force[k] += force[k];
            b.body_force[k] += body_force[k];
        }
        b.damping = global;
        b.body_damping = body;
    }
    for (i, p) in points.iter_mut().enumerate().take(deck.points.len()) {
        let (force, damping) = on_point(loads, i + 1);
        for k in 0..3 {
            p.force[k] += force[k];
        }
        p.damping = damping;
    }
    loads
        .iter()
        .map(|l| {
            let on = match (l.object, l.axes) {
                (LoadedObject::Body(n), LoadAxes::Global) => {
                    format!("body {n}, at its reference point along the global axes")
                }
                (LoadedObject::Body(n), LoadAxes::Body) => {
                    format!("body {n}, at its reference point along the body's axes")
                }
                (LoadedObject::Point(n), _) if l.axes_word != "-" => format!(
                    "point {n}, along the global axes (its CSys \"{}\" is not -, which \
                     MoorDyn-F warns of; a point's loads are global)",
                    l.axes_word
                ),
                (LoadedObject::Point(n), _) => format!("point {n}, along the global axes"),
            };
            format!(
                "line {}: external load {} (MoorDyn-F's EXTERNAL LOADS) on {on}: force {:?} N, \
                 damping {:?} N s/m and {:?} N s^2/m^2 (docs/method.md §15.21)",
                l.line, l.id, l.force, l.linear, l.quadratic
            )
        })
        .collect()
}
