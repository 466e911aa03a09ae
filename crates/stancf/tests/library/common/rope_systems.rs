//! A rope system shared by the allocation test, the `systems` benchmark
//! and `bench/sparse-lu`: three lines from two fixed anchors and a
//! swinging one to a free point of 0.2 kg, and the single 120-element
//! line of the same rope it is measured against. Included with
//! `#[path]` (benches and the standalone crate cannot use `tests/common`
//! as a module otherwise).
#![allow(dead_code)]

use stancf::constraints::{MotionTable, Oscillation};
use stancf::motion::CoupledMotion;
use stancf::system::{End, Line, Point, System};
use stancf::{
    Cable, Constraint, ConstraintKind, ElementType, Load, Material, Model, ModelOptions,
    Simulation, StepSettings,
};

pub const G: [f64; 3] = [0.0, 0.0, -9.81];

/// The swinging anchor's motion: 5 cm along x at 2 Hz, no ramp.
pub const SWING: Oscillation = Oscillation {
    amplitude: [0.05, 0.0, 0.0],
    period: 0.5,
    phase: 0.0,
    ramp: 0.0,
};

/// 10 mm^2 at 10 MPa (EA 100 N), 10 g/m.
pub fn rope() -> Material {
    Material {
        youngs_modulus: 1e7,
        density: 1000.0,
        area: 1e-5,
        second_moment: 1e-12,
        axial_damping: 0.0,
    }
}

/// P2 steps of 0.1 ms.
pub fn settings() -> StepSettings {
    StepSettings {
        time_step: 1e-4,
        ..StepSettings::default()
    }
}

/// A straight rope line of `elements` SAC-2 from a to b, under gravity.
pub fn line_model(a: [f64; 3], b: [f64; 3], elements: usize) -> Model {
    let d = [b[0] - a[0], b[1] - a[1], b[2] - a[2]];
    let length = (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).sqrt();
    Model::new(
        Cable::straight(length, elements, ElementType::Sac2)
            .with_origin(a)
            .with_direction(d),
        rope(),
        ModelOptions::default(),
        vec![Load::Gravity { acceleration: G }],
    )
    .unwrap()
}

/// Three lines of `elements` elements from two fixed anchors and a
/// swinging one (points 0-2) to a free point of 0.2 kg (point 3).
pub fn three_to_a_point(elements: usize) -> System {
    three_to_a_point_moving(elements, SWING.into())
}

/// [`three_to_a_point`] with the swinging anchor moved by a table of
/// [`SWING`] sampled every 5 ms over 1 s (201 rows).
pub fn three_to_a_point_on_a_table(elements: usize) -> System {
    let anchor = [-1.0, -1.7, 0.5];
    let swing = CoupledMotion::from(SWING);
    let times: Vec<f64> = (0..=200).map(|i| i as f64 * 5e-3).collect();
    let positions = times
        .iter()
        .map(|&t| swing.state_at(&anchor, t).0)
        .collect();
    let table = MotionTable::new(times, positions).unwrap();
    three_to_a_point_moving(elements, table.into())
}

fn three_to_a_point_moving(elements: usize, swing: CoupledMotion) -> System {
    let hub: [f64; 3] = [0.0, 0.0, -1.0];
    let anchors: [[f64; 3]; 3] = [[2.0, 0.0, 0.0], [-1.0, 1.7, 0.0], [-1.0, -1.7, 0.5]];
    let lines = anchors
        .iter()
        .enumerate()
        .map(|(i, a)| Line {
            model: line_model(*a, hub, elements),
            ends: [End::Point(i), End::Point(3)],
        })
        .collect();
    let points = vec![
        Point::fixed(anchors[0]),
        Point::fixed(anchors[1]),
        Point::coupled(anchors[2], swing),
        Point::free(hub, 0.2),
    ];
    System::new(lines, points, G).unwrap()
}

/// Where the single line's end B is: 6 m along (1, 0.5, -0.3), out of
/// every coordinate plane like the system's lines. A line in the x-z
/// plane swinging along x keeps y decoupled: a third of its Jacobian's
/// coupling entries are exact zeros, which the assembly and the band LU
/// skip, and it would be cheaper per unknown than any line of a system
/// in three dimensions (1.52x against it, 1.28x against this one, in
/// instructions per step).
pub fn one_line_end() -> [f64; 3] {
    let n = (1.0f64 + 0.25 + 0.09).sqrt();
    [6.0 / n, 3.0 / n, -1.8 / n]
}

/// One 120-element line of the same rope, pinned at the origin and
/// swinging at [`one_line_end`].
pub fn one_line(planar_reduction: bool) -> Simulation {
    let m = line_model([0.0; 3], one_line_end(), 120)
        .with_constraints(vec![
            Constraint {
                node: 0,
                kind: ConstraintKind::Pinned,
            },
            Constraint {
                node: 120,
                kind: ConstraintKind::Prescribed {
                    velocity: [0.0; 3],
                    amplitude: SWING.amplitude,
                    frequency: 1.0 / SWING.period,
                    phase: 0.0,
                },
            },
        ])
        .unwrap();
    let s = m.initial_state();
    Simulation::new(
        m,
        s,
        StepSettings {
            planar_reduction,
            ..settings()
        },
    )
    .unwrap()
}

/// Independent ropes (no free point: docs/method.md §11.14): of `of`
/// ropes of `elements` elements, each from a fixed anchor on a circle of
/// radius 1.2 m, 1 m down, to a fairlead swinging by [`SWING`] on a
/// circle of 0.1 m, those numbered in `which` (each keeps its direction:
/// no two alike).
pub fn independent_ropes(which: &[usize], of: usize, elements: usize) -> System {
    let mut points = Vec::new();
    let mut lines = Vec::new();
    for (j, &k) in which.iter().enumerate() {
        let angle = 0.3 + 2.0 * std::f64::consts::PI * k as f64 / of as f64;
        let (s, c) = angle.sin_cos();
        let (anchor, fairlead) = ([1.2 * c, 1.2 * s, -1.0], [0.1 * c, 0.1 * s, 0.0]);
        points.extend([Point::fixed(anchor), Point::coupled(fairlead, SWING)]);
        lines.push(Line {
            model: line_model(anchor, fairlead, elements),
            ends: [End::Point(2 * j), End::Point(2 * j + 1)],
        });
    }
    System::new(lines, points, G).unwrap()
}

/// [`three_to_a_point`] of 4 elements per line, straight and at rest, in
/// Galerkin steps of `dt`, Newton to 1e-12.
pub fn galerkin_three_to_a_point(dt: f64) -> stancf::system::SystemSimulation {
    three_to_a_point_stepped(dt, stancf::TimeScheme::Galerkin)
}

/// [`galerkin_three_to_a_point`] in steps of `scheme`.
pub fn three_to_a_point_stepped(
    dt: f64,
    scheme: stancf::TimeScheme,
) -> stancf::system::SystemSimulation {
    let system = three_to_a_point(4);
    let states = system
        .lines()
        .iter()
        .map(|l| l.model.initial_state())
        .collect();
    let settings = StepSettings {
        time_step: dt,
        time_scheme: scheme,
        newton: stancf::NewtonSettings {
            tolerance: 1e-12,
            ..stancf::NewtonSettings::default()
        },
        ..StepSettings::default()
    };
    stancf::system::SystemSimulation::new(system, states, settings).expect("system")
}
