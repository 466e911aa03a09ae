//! The rows a system run writes: its state after a step or at its static
//! equilibrium as one [`SystemRow`] (lines, points, bodies, end forces,
//! energies and works), from a simulation or a static solve.

use super::bodies::{at_rest, body_rows, stepped, BodyRow};
use crate::scenario::EndForces;
use stancf::body::flow::FlowTime;
use stancf::system::{EndForce, SystemSimulation, SystemStatics, Topology};
use stancf::water::PointInWater;
use stancf::{Model, State};

/// One written moment of a system.
pub(super) struct SystemRow<'a> {
    pub t: f64,
    /// Each line's model and state.
    pub lines: Vec<(&'a Model, &'a State)>,
    /// Each point's position, velocity and the net force of its lines.
    pub points: Vec<([f64; 3], [f64; 3], [f64; 3])>,
    /// Each point's net force as MoorDyn's `Fnet` (its lines', its
    /// weight, buoyancy and given force, and the water's drag and the
    /// fluid's inertia on it; not its own inertia nor its added mass's).
    pub point_net: Vec<[f64; 3]>,
    /// Each body's pose, velocities and loads.
    pub bodies: Vec<BodyRow>,
    /// Each line's end forces (A, B; None for a loose end).
    pub ends: Vec<[Option<EndForce>; 2]>,
    /// Kinetic, strain and gravity energies of lines and points.
    pub energies: [f64; 3],
    pub iterations: usize,
    pub residual: f64,
    /// Work of the lines' axial damping so far (written with
    /// `with_damping`).
    pub damping_work: f64,
    /// Work of the water and the seabed on lines and points so far
    /// (written with `with_water`).
    pub water_work: f64,
    pub seabed_work: f64,
    /// Each line's seabed nodal forces where the row knows them (a static
    /// equilibrium, whose friction resists the slide from its targets,
    /// (W48)); None: those of the contact at the state's velocities.
    pub seabed: Option<Vec<Vec<[f64; 3]>>>,
}

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
    let bodies = body_rows(
        system,
        |b| match sim.free_body(b) {
            Some(free) => stepped(free),
            None => at_rest(&system.bodies()[b]),
        },
        &points,
        |b| sim.clamp_moment(b),
        FlowTime::At(sim.time()),
    );
    SystemRow {
        t: sim.time(),
        point_net,
        bodies,
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

/// The state of a system simulation at time `t` inside the steps it has
/// recorded since its run step began (docs/method.md §6.5a, (M23d)): the
/// lines' states (written into `states`, one per line, which the row
/// borrows), the points', the end forces at t. Its energies are not
/// computed (zero: the row is written by `SystemWriters::write_state`,
/// which writes none; history.csv keeps the steps' own).
pub(super) fn interval_row<'a>(
    sim: &'a SystemSimulation,
    t: f64,
    states: &'a mut Vec<State>,
) -> Result<SystemRow<'a>, stancf::ModelError> {
    let system = sim.topology();
    states.resize_with(sim.lines().len(), || State {
        t,
        e: Vec::new(),
        v: Vec::new(),
        internal: Vec::new(),
    });
    for (i, state) in states.iter_mut().enumerate() {
        sim.line_state_within(i, t, state)?;
    }
    let lines = sim
        .lines()
        .iter()
        .zip(states.iter())
        .map(|(l, s)| (l.model(), s))
        .collect();
    let points = (0..system.points().len())
        .map(|p| {
            let (x, v) = sim.point_state_within(p, t)?;
            Ok((x, v, sim.point_force_within(p, t)?))
        })
        .collect::<Result<Vec<_>, stancf::ModelError>>()?;
    let forces = (0..sim.lines().len())
        .map(|i| sim.end_forces_within(i, t))
        .collect::<Result<Vec<_>, _>>()?;
    let ends = ends_of(system, |i| forces[i], true);
    let point_net = net_point_forces(system, &points, |w, x, v| w.force(x, v, t).force);
    let bodies = body_rows(
        system,
        |b| at_rest(&system.bodies()[b]),
        &points,
        |b| sim.clamp_moment(b),
        FlowTime::At(t),
    );
    Ok(SystemRow {
        t,
        point_net,
        bodies,
        lines,
        points,
        ends,
        energies: [0.0; 3],
        iterations: 0,
        residual: 0.0,
        damping_work: 0.0,
        water_work: 0.0,
        seabed_work: 0.0,
        seabed: None,
    })
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
    // The free bodies' potential is in the core's static energies, as in a
    // simulation's: a dynamic run's history.csv starts where its steps go on.
    let en = [e.kinetic, e.strain, e.gravity];
    let point_net = net_point_forces(system, &points, |w, x, _| w.static_force(x).force);
    let bodies = body_rows(
        system,
        |b| {
            let mut m = at_rest(&system.bodies()[b]);
            if let Some((position, rotation)) = st.body_pose(b) {
                (m.position, m.rotation) = (position, rotation);
            }
            m
        },
        &points,
        |b| st.clamp_moment(b),
        FlowTime::Steady,
    );
    SystemRow {
        t,
        point_net,
        bodies,
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

/// The static row `row` as the start of a dynamic run `sim`: where a body
/// is given a starting velocity, the velocities the run starts with (the
/// body's, its points', zero elsewhere) and its kinetic energy (its, its
/// lines').
pub(super) fn with_start_rates(row: &mut SystemRow, sim: &SystemSimulation) {
    let pushed = sim.topology().bodies().iter().any(|b| {
        b.kind == stancf::system::BodyKind::Free
            && (b.velocity != [0.0; 3] || b.angular_velocity != [0.0; 3])
    });
    if !pushed {
        return;
    }
    for (p, point) in row.points.iter_mut().enumerate() {
        point.1 = sim.point_state(p).1;
    }
    for (b, body) in row.bodies.iter_mut().enumerate() {
        if let Some(free) = sim.free_body(b) {
            let start = stepped(free);
            body.motion.velocity = start.velocity;
            body.motion.angular_velocity = start.angular_velocity;
        }
    }
    row.energies[0] = sim.energies().kinetic;
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
