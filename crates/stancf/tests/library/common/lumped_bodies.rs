//! A body of MoorDyn's lumped water as dense as the water, shared by the
//! tests of bodies in waves and in a host's flow.

use stancf::body::{BodyForces, BodyWater, FreeBody, RigidInertia, Rod};
use stancf::water::kinematics::Sea;
use stancf::TimeScheme;
use std::sync::Arc;

pub const RHO: f64 = 1025.0;
pub const G: f64 = 9.80665;
const IDENTITY: [[f64; 3]; 3] = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];

/// A body of MoorDyn's lumped water (0.5 m^3; Ca 0.5, 0.7 and 0.9 and
/// CdA 0.8, 1.0 and 1.2 m^2 times `drag` along its axes) with `rods`
/// fixed in it, all as dense as the water (the rods' own density is
/// theirs to set), 10 m down in `sea`, at rest, stepped by `scheme` with
/// steps of `dt`.
pub fn neutral_lumped_body(
    sea: Sea,
    rods: Vec<Rod>,
    drag: f64,
    scheme: TimeScheme,
    dt: f64,
) -> FreeBody {
    let lumped = RigidInertia::principal(RHO * 0.5, [0.0; 3], [40.0; 3]);
    let inertia = rods
        .iter()
        .fold(lumped, |body, rod| body.with_part(&rod.inertia()));
    let forces = BodyForces::weight_and_buoyancy(&inertia, 0.5, RHO, [0.0, 0.0, -G]);
    let water = BodyWater {
        density: RHO,
        volume: 0.5,
        added_mass_coefficients: [0.5, 0.7, 0.9],
        drag_areas: [0.8 * drag, 1.0 * drag, 1.2 * drag],
        rods,
        gravity: G,
        sea: Some(Arc::new(sea)),
        ..BodyWater::default()
    };
    FreeBody::new(
        &inertia,
        &forces,
        [0.0, 0.0, -10.0],
        &IDENTITY,
        [0.0; 3],
        [0.0; 3],
        dt,
    )
    .unwrap()
    .with_scheme(scheme)
    .with_water(water)
    .unwrap()
}
