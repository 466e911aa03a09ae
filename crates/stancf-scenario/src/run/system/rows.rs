//! The rows a system run writes: its state after a step or at its static
//! equilibrium as one [`SystemRow`] (lines, points, end forces, energies
//! and works), from a simulation or a static solve.

use super::writers::SystemRow;
use crate::scenario::EndForces;
use stancf::system::{EndForce, SystemSimulation, SystemStatics, Topology};
use stancf::water::PointInWater;

/// The end forces of line i of the last step: its means or their
/// estimates at its end (docs/method.md §6.5, (M23), (M23a)).
pub(super) fn step_end_forces(sim: &SystemSimulation, kind: EndForces, i: usize) -> [EndForce; 2] {
    match kind {
        EndForces::StepMean => sim.end_forces(i),
        EndForces::AtTime => sim.end_forces_at_time(i),
    }
}

/// The row of a system simulation's current state (`forces`: the end
/// forces of the last step, of that kind; none before the first).
pub(super) fn dynamic_row(sim: &SystemSimulation, forces: Option<EndForces>) -> SystemRow<'_> {
    let system = sim.topology();
    let lines = sim.lines().iter().map(|l| (l.model(), l.state())).collect();
    let points: Vec<_> = (0..system.points().len())
        .map(|p| {
            let (x, v) = sim.point_state(p);
            let f = forces.map_or([0.0; 3], |kind| match kind {
                EndForces::StepMean => sim.point_force(p),
                EndForces::AtTime => sim.point_force_at_time(p),
            });
            (x, v, f)
        })
        .collect();
    let kind = forces.unwrap_or_default();
    let ends = ends_of(system, |i| step_end_forces(sim, kind, i), forces.is_some());
    let e = sim.energies();
    let en = [e.kinetic, e.strain, e.gravity];
    let point_net = net_point_forces(system, &points, |w, x, v| w.force(x, v, sim.time()).force);
    SystemRow {
        t: sim.time(),
        point_net,
        lines,
        points,
        ends,
        energies: en,
        iterations: 0,
        residual: 0.0,
        damping_work: sim.damping_work(),
        water_work: sim.water_work(),
        seabed_work: sim.seabed_work(),
        seabed: None,
    }
}

/// The row of a static solve's equilibrium, at time `t`.
pub(super) fn static_row(st: &SystemStatics, t: f64) -> SystemRow<'_> {
    let system = st.system();
    let lines = system
        .lines()
        .iter()
        .enumerate()
        .map(|(i, l)| (&l.model, st.line_state(i)))
        .collect();
    let points: Vec<_> = (0..system.points().len())
        .map(|p| (st.point_position(p), [0.0; 3], st.point_force(p)))
        .collect();
    let ends = ends_of(system, |i| st.end_forces(i), true);
    let e = st.energies();
    let en = [e.kinetic, e.strain, e.gravity];
    let point_net = net_point_forces(system, &points, |w, x, _| w.static_force(x).force);
    SystemRow {
        t,
        point_net,
        lines,
        points,
        ends,
        energies: en,
        iterations: 0,
        residual: 0.0,
        damping_work: 0.0,
        water_work: 0.0,
        seabed_work: 0.0,
        seabed: Some(
            (0..system.lines().len())
                .map(|i| st.seabed_nodal_forces(i))
                .collect(),
        ),
    }
}

/// Each point's net force as MoorDyn's `Fnet`: the force of its lines
/// (`points`' third member), its own load (weight, buoyancy, given force)
/// and, in water, `water(w, x, v)`, the water's force on it at its
/// position and velocity. At a free point in equilibrium it is zero to
/// the solve's tolerance; in motion its mass and added mass times its
/// acceleration.
fn net_point_forces(
    topology: &Topology,
    points: &[([f64; 3], [f64; 3], [f64; 3])],
    water: impl Fn(&PointInWater, &[f64; 3], &[f64; 3]) -> [f64; 3],
) -> Vec<[f64; 3]> {
    points
        .iter()
        .enumerate()
        .map(|(p, (x, v, lines))| {
            let own = topology.point_load(p);
            let in_water = topology.points()[p].water.as_ref();
            let w = in_water.map_or([0.0; 3], |w| water(w, x, v));
            std::array::from_fn(|k| lines[k] + own[k] + w[k])
        })
        .collect()
}

/// The end forces of every line, None at loose ends (and everywhere
/// without `forces`).
fn ends_of(
    system: &Topology,
    forces_of: impl Fn(usize) -> [EndForce; 2],
    forces: bool,
) -> Vec<[Option<EndForce>; 2]> {
    system
        .line_ends()
        .iter()
        .enumerate()
        .map(|(i, ends)| {
            let f = forces_of(i);
            std::array::from_fn(|k| {
                (forces && ends[k] != stancf::system::End::Loose).then_some(f[k])
            })
        })
        .collect()
}
