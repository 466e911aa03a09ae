//! A sea whose waves a host sets at the nodes (MoorDyn's `WaveKin 1`,
//! docs/method.md §12.1, (W2f)-(W2g)): a tether with drag and added mass
//! up to a buoy with a drag area, the host's flow against the sea's own
//! current, the step's Jacobian against finite differences, the points
//! the host is asked at in MoorDyn's order, and the refusals.

use stancf::system::{
    catenary_states, End, Line, LineFailure, Point, System, SystemSimulation, SystemStatics,
};
use stancf::water::current::{CurrentProfile, Ramp};
use stancf::water::kinematics::Sea;
use stancf::water::waves::AiryWave;
use stancf::water::{LineInWater, Morison, PointInWater, Water};
use stancf::{
    Cable, ElementType, Load, Material, Model, ModelOptions, StaticSettings, StepSettings,
    TimeScheme,
};
use std::ops::ControlFlow;
use std::sync::Arc;

const RHO_W: f64 = 1025.0;
const G: f64 = 9.81;
const DEPTH: f64 = 50.0;
const TETHER: f64 = 12.0;
const ELEMENTS: usize = 6;

/// A 12 m tether of 6 elements leaning from an anchor at (0, 0, -50) to
/// a buoy (100 kg, 1 m^3, CdA 0.8 m^2, Ca 1): the tether with normal and
/// axial drag and added mass, so that the host's flow reaches every term
/// of the line's water (W19)-(W20) and the point's (W34).
fn buoy_system(sea: Sea, top: Option<[f64; 3]>) -> System {
    let water = Arc::new(Water {
        density: RHO_W,
        sea,
    });
    let d = 0.08;
    let area = 0.25 * std::f64::consts::PI * d * d;
    let ea = 2e6;
    let material = Material {
        youngs_modulus: ea / area,
        density: 2.0 * RHO_W,
        area,
        second_moment: 10.0 / (ea / area),
        axial_damping: 0.0,
    };
    let morison = Morison {
        diameter: d,
        cd_normal: 1.2,
        cd_axial: 0.2,
        ca_normal: 1.0,
        ca_axial: 0.5,
    };
    let direction = [0.3, 0.1, 1.0];
    let n = (direction.iter().map(|c| c * c).sum::<f64>()).sqrt();
    let direction = direction.map(|c| c / n);
    let cable = Cable::straight(TETHER, ELEMENTS, ElementType::Sac2)
        .with_origin([0.0, 0.0, -DEPTH])
        .with_direction(direction);
    let loads = vec![
        Load::Gravity {
            acceleration: [0.0, 0.0, -G],
        },
        Load::Water(LineInWater::new(water.clone(), morison)),
    ];
    let model = Model::new(cable, material, ModelOptions::default(), loads).unwrap();
    let top = top.unwrap_or([
        direction[0] * TETHER,
        direction[1] * TETHER,
        direction[2] * TETHER - DEPTH,
    ]);
    let mut buoy = Point::free(top, 100.0);
    buoy.water = Some(PointInWater {
        water,
        volume: 1.0,
        drag_area: 0.8,
        ca: 1.0,
        host: None,
    });
    System::new(
        vec![Line {
            model,
            ends: [End::Point(0), End::Point(1)],
        }],
        vec![Point::fixed([0.0, 0.0, -DEPTH]), buoy],
        [0.0, 0.0, -G],
    )
    .unwrap()
}

/// The system in `sea`, started at rest at its equilibrium in still
/// water (the host's flow is not in statics; nor is it before the host
/// sets it).
fn simulation(sea: Sea, scheme: TimeScheme) -> SystemSimulation {
    // P2 within its stable step (the tether's axial waves cross a 2 m
    // element in 4.5 ms), the Galerkin step at any.
    let time_step = match scheme {
        TimeScheme::P2 => 0.002,
        _ => 0.05,
    };
    let still = buoy_system(host_sea(), None);
    let seeds = catenary_states(&still);
    let mut statics = SystemStatics::new(still, seeds, StaticSettings::default()).unwrap();
    statics.solve(|_, _| ControlFlow::Continue(())).unwrap();
    let system = buoy_system(sea, Some(statics.point_position(1)));
    let states = statics.line_states();
    let settings = StepSettings {
        time_step,
        time_scheme: scheme,
        ..StepSettings::default()
    };
    SystemSimulation::new(system, states, settings).unwrap()
}

fn host_sea() -> Sea {
    Sea::still(DEPTH, G).with_host_waves().unwrap()
}

/// A host that sets the same uniform flow U at every point moves the
/// tether and the buoy as the sea's own uniform current U does, to the
/// bit, in both schemes: (W2g) adds U to still water where the current
/// puts U (its ramp's rate and gradient zero), and the same numbers reach
/// the same terms.
#[test]
fn a_hosts_uniform_flow_moves_a_tether_and_its_buoy_as_the_same_current_does() {
    let u = [0.7, -0.3, 0.05];
    for scheme in [TimeScheme::Galerkin, TimeScheme::P2] {
        let current = CurrentProfile::uniform(u).unwrap();
        let mut own = simulation(
            Sea::still(DEPTH, G).with_current(current, Ramp::NONE),
            scheme,
        );
        let mut hosted = simulation(host_sea(), scheme);
        // Still water until the host sets its flow, as in MoorDyn.
        let mut unset = simulation(host_sea(), scheme);
        let count = hosted.host_flow_points().len();
        hosted
            .set_host_flow(&vec![u; count], &vec![[0.0; 3]; count])
            .unwrap();
        for _ in 0..20 {
            own.step().unwrap();
            hosted.step().unwrap();
            unset.step().unwrap();
        }
        assert_eq!(
            own.lines()[0].state().e,
            hosted.lines()[0].state().e,
            "{scheme:?}"
        );
        assert_eq!(own.point_state(1), hosted.point_state(1), "{scheme:?}");
        // The flow moved them: the buoy is downstream of where it is in
        // still water.
        let moved = hosted.point_state(1).0[0] - unset.point_state(1).0[0];
        eprintln!("{scheme:?}: the buoy {moved:.3e} m downstream of its still-water place");
        assert!(
            moved > 0.0,
            "{scheme:?}: the buoy moved {moved} m along the flow"
        );
    }
}

/// The step's Jacobian with a host's flow that differs from node to node
/// and carries accelerations (interpolated along each element, (W2f))
/// against central differences of the step's residual, both schemes: to
/// 1e-6, as the buoy's in waves (`points_in_water`): the host's values do
/// not depend on where the nodes are, so the flow's gradients are the
/// sea's (none here) and the Jacobian stays exact.
#[test]
fn the_step_jacobian_in_a_hosts_flow_matches_finite_differences() {
    for scheme in [TimeScheme::P2, TimeScheme::Galerkin] {
        let mut sim = simulation(host_sea(), scheme);
        let points = sim.host_flow_points();
        let velocity: Vec<[f64; 3]> = points
            .iter()
            .enumerate()
            .map(|(k, _)| [0.4 + 0.1 * k as f64, -0.2, 0.05 * (k as f64).sin()])
            .collect();
        let acceleration: Vec<[f64; 3]> = (0..points.len())
            .map(|k| [0.3 * (k as f64).cos(), 0.1, -0.2])
            .collect();
        sim.set_host_flow(&velocity, &acceleration).unwrap();
        let err = crate::common::step_jacobian_error(&mut sim, 1e-5);
        eprintln!("{scheme:?}: step Jacobian rel. error {err:.1e}");
        assert!(err < 1e-6, "{scheme:?}: {err:e}");
    }
}

/// The host is asked where MoorDyn asks it: every node of every line,
/// then every point, then MoorDyn's ground body at the origin; the
/// positions are the nodes' and points' now.
#[test]
fn the_host_is_asked_at_the_nodes_then_the_points_then_the_ground() {
    let sim = simulation(host_sea(), TimeScheme::Galerkin);
    let points = sim.host_flow_points();
    assert_eq!(points.len(), (ELEMENTS + 1) + 2 + 1);
    let line = &sim.lines()[0];
    let e = &line.state().e;
    let dpn = line.model().dofs_per_node();
    for k in 0..=ELEMENTS {
        assert_eq!(points[k], [e[k * dpn], e[k * dpn + 1], e[k * dpn + 2]]);
    }
    assert_eq!(points[ELEMENTS + 1], sim.point_state(0).0);
    assert_eq!(points[ELEMENTS + 2], sim.point_state(1).0);
    assert_eq!(points[ELEMENTS + 3], [0.0; 3]);
}

/// Refused, naming what is wrong: a count other than the points', a value
/// that is not finite, a flow set where the sea's waves are its own, and
/// a sea with waves of its own that a host would set.
#[test]
fn a_hosts_flow_is_refused_where_it_cannot_be_taken() {
    let mut sim = simulation(host_sea(), TimeScheme::Galerkin);
    let n = sim.host_flow_points().len();
    let e = sim
        .set_host_flow(&vec![[0.0; 3]; n - 1], &vec![[0.0; 3]; n])
        .unwrap_err();
    assert!(
        e.to_string().contains(&format!("{} points given", n - 1)),
        "{e}"
    );
    let mut bad = vec![[0.0; 3]; n];
    bad[3][1] = f64::NAN;
    let e = sim.set_host_flow(&vec![[0.0; 3]; n], &bad).unwrap_err();
    assert!(e.to_string().contains("acceleration[3]"), "{e}");
    let mut own = simulation(Sea::still(DEPTH, G), TimeScheme::Galerkin);
    assert!(own.host_flow_points().is_empty());
    let e = own.set_host_flow(&[], &[]).unwrap_err();
    assert!(e.to_string().contains("not a host's"), "{e}");
    let wave = AiryWave {
        amplitude: 1.0,
        period: 8.0,
        heading_deg: 0.0,
        phase_deg: 0.0,
    };
    let e = Sea::new(DEPTH, G, &[wave])
        .unwrap()
        .with_host_waves()
        .unwrap_err();
    assert!(e.to_string().contains("no waves of its own"), "{e}");
}

/// A line failure's release adds a free point (docs/method.md §11.16),
/// which MoorDyn does not add to the points its host is asked at (its
/// count is fixed at init): the tether let go of its anchor at 0.1 s, the
/// host is asked at the same points as before, and its arrays of that
/// count are taken.
#[test]
fn a_line_failures_new_point_is_not_asked_for_the_hosts_waves() {
    let mut sim = simulation(host_sea(), TimeScheme::Galerkin);
    let before = sim.host_flow_points().len();
    sim.set_failures(vec![LineFailure {
        point: 0,
        lines: vec![0],
        time: Some(0.1),
        tension: None,
    }])
    .unwrap();
    for _ in 0..4 {
        sim.step().unwrap();
    }
    assert_eq!(sim.releases().len(), 1);
    assert_eq!(sim.topology().points().len(), 3);
    assert_eq!(sim.host_flow_points().len(), before);
    let u = vec![[0.3, 0.0, 0.0]; before];
    sim.set_host_flow(&u, &vec![[0.0; 3]; before]).unwrap();
    sim.step().unwrap();
}
