//! Lines in still water with added mass only (no drag), shared by the
//! added-mass tests (docs/method.md §12.5). Included with `#[path]`.
#![allow(dead_code)]

use stancf::water::{kinematics::Sea, LineInWater, Morison, Water};
use stancf::Load;
use std::sync::Arc;

/// Sea water, rho_w = 1025 kg/m^3.
pub const RHO_W: f64 = 1025.0;

/// Still water of the given depth (m), g = 9.81.
pub fn still_water(depth: f64) -> Arc<Water> {
    Arc::new(Water {
        density: RHO_W,
        sea: Sea::still(depth, 9.81),
    })
}

/// A line of hydrodynamic diameter `d` with added-mass coefficients Can,
/// Cat and no drag.
pub fn added_mass_only(d: f64, can: f64, cat: f64) -> Morison {
    Morison {
        diameter: d,
        cd_normal: 0.0,
        cd_axial: 0.0,
        ca_normal: can,
        ca_axial: cat,
    }
}

/// The load of still water of `depth` on a line of diameter `d` with
/// added mass (Can, Cat) and no drag.
pub fn in_still_water(depth: f64, d: f64, can: f64, cat: f64) -> Load {
    Load::Water(LineInWater::new(
        still_water(depth),
        added_mass_only(d, can, cat),
    ))
}

/// rho_w A of a line of diameter `d`: the displaced water per length.
pub fn displaced(d: f64) -> f64 {
    RHO_W * 0.25 * std::f64::consts::PI * d * d
}
