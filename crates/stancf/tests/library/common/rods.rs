//! Rods and ropes of the tests of pinned bodies and joints.

use super::light_rope;
use stancf::body::Rod;
use stancf::vec3::{norm, scale, sub};
use stancf::{Cable, ElementType, Model};

/// A rod of `length` and 0.1 m across, 10 kg/m, from `a` along `axis`
/// (unit), drag and added mass `cd`, `ca` (and on its caps).
pub fn rod(a: [f64; 3], axis: [f64; 3], length: f64, cd: f64, ca: f64) -> Rod {
    Rod {
        end_a: a,
        end_b: std::array::from_fn(|c| a[c] + length * axis[c]),
        diameter: 0.1,
        mass_per_length: 10.0,
        drag_coefficient: cd,
        added_mass_coefficient: ca,
        end_drag_coefficient: cd,
        end_added_mass_coefficient: ca,
        segments: 4,
    }
}

/// A straight light rope (4 elements, no weight) from `start` to `end`.
pub fn rope(start: [f64; 3], end: [f64; 3]) -> Model {
    let chord = norm(sub(end, start));
    let cable = Cable::straight(chord, 4, ElementType::Sac2)
        .with_direction(scale(1.0 / chord, sub(end, start)))
        .with_origin(start);
    Model::new(cable, light_rope(), Default::default(), vec![]).expect("model")
}
