//! No heap allocation inside the Newton loop: after the first step (which
//! sizes the scratch buffers), stepping allocates nothing. Counted with a
//! global allocator wrapper that counts only the allocations of the
//! thread that asked for counting: the test runner's own thread
//! allocates when it reports on tests, at times that depend on the
//! machine's load, and must not be counted.

use std::alloc::{GlobalAlloc, Layout, System};
use std::cell::Cell;
use std::sync::atomic::{AtomicUsize, Ordering};

struct Counting;

static ALLOCATIONS: AtomicUsize = AtomicUsize::new(0);

thread_local! {
    /// Whether this thread's allocations are counted (a const
    /// thread-local: reading it allocates nothing).
    static COUNTED: Cell<bool> = const { Cell::new(false) };
}

/// Counts an allocation if this thread asked for counting.
fn count() {
    if COUNTED.with(Cell::get) {
        ALLOCATIONS.fetch_add(1, Ordering::SeqCst);
    }
}

unsafe impl GlobalAlloc for Counting {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        count();
        unsafe { System.alloc(layout) }
    }
    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        unsafe { System.dealloc(ptr, layout) }
    }
    unsafe fn realloc(&self, ptr: *mut u8, layout: Layout, new_size: usize) -> *mut u8 {
        count();
        unsafe { System.realloc(ptr, layout, new_size) }
    }
}

#[global_allocator]
static GLOBAL: Counting = Counting;

use stancf::{
    Cable, Constraint, ConstraintKind, ConstraintMethod, ElementType, Load, Material, Model,
    ModelOptions, Simulation, StepSettings,
};

/// One test, counting this thread's allocations only.
#[test]
fn stepping_a_cable_or_a_system_allocates_nothing() {
    COUNTED.with(|c| c.set(true));
    stepping_a_cable_allocates_nothing();
    stepping_a_system_with_a_free_point_allocates_nothing();
    stepping_a_system_with_a_free_body_allocates_nothing();
    stepping_lines_apart_allocates_nothing();
}

fn stepping_a_cable_allocates_nothing() {
    for (kind, layers, constrained, method, held, damped) in [
        (
            ElementType::Sac2,
            1,
            false,
            ConstraintMethod::Multiplier,
            false,
            false,
        ),
        (
            ElementType::Sac3,
            2,
            false,
            ConstraintMethod::Multiplier,
            false,
            false,
        ),
        (
            ElementType::Sac2,
            1,
            true,
            ConstraintMethod::Multiplier,
            false,
            false,
        ),
        (
            ElementType::Sac3,
            2,
            true,
            ConstraintMethod::Elimination,
            false,
            false,
        ),
        (
            ElementType::Sac3,
            2,
            true,
            ConstraintMethod::Multiplier,
            true,
            false,
        ),
        (
            ElementType::Sac2,
            1,
            true,
            ConstraintMethod::Elimination,
            false,
            true,
        ),
    ] {
        // The last case with axial damping (docs/method.md §2.10).
        let material = Material::chen2023_pvc().with_axial_damping(if damped { 1e-3 } else { 0.0 });
        let mut constraints = if constrained {
            vec![
                Constraint {
                    node: 0,
                    kind: ConstraintKind::Clamped {
                        fix_curvature: false,
                    },
                },
                Constraint {
                    node: 4,
                    kind: ConstraintKind::Prescribed {
                        velocity: [0.0, 0.1, 0.0],
                        amplitude: [0.01, 0.0, 0.0],
                        frequency: 3.0,
                        phase: 0.0,
                    },
                },
            ]
        } else {
            vec![]
        };
        if held {
            // r_x of node 6 held along an oblique direction (§6.10).
            constraints.push(Constraint {
                node: 6,
                kind: ConstraintKind::Parallel {
                    direction: [1.0, 0.2, -0.1],
                },
            });
        }
        let model = Model::new(
            Cable::straight(4.0, 8, kind),
            material,
            ModelOptions::default(),
            vec![
                Load::Gravity {
                    acceleration: [0.0, -9.81, 0.0],
                },
                Load::PointForce {
                    node: 8,
                    force: [0.0, 0.0, 0.1],
                },
                Load::EndMoment {
                    node: 8,
                    moment: [0.0, 0.0, 1e-4],
                },
            ],
        )
        .unwrap()
        .with_constraints(constraints)
        .unwrap();
        let mut s = model.initial_state();
        model.set_node_velocity(&mut s, 0, [0.0, 10.0, 0.0]);
        let settings = StepSettings {
            time_step: 2e-5,
            time_layers: layers,
            constraint_method: method,
            ..StepSettings::default()
        };
        let mut sim = Simulation::new(model, s, settings).unwrap();
        sim.step().unwrap();
        let before = ALLOCATIONS.load(Ordering::SeqCst);
        let mut iterations = 0;
        for _ in 0..50 {
            iterations += sim.step().unwrap().newton.iterations;
            std::hint::black_box(sim.energies());
            std::hint::black_box(sim.reactions());
        }
        let after = ALLOCATIONS.load(Ordering::SeqCst);
        assert!(iterations >= 50, "the steps did iterate");
        assert_eq!(
            after - before,
            0,
            "{kind:?}: {} allocations in 50 steps",
            after - before
        );
    }
}

/// Three lines from two fixed points and a moving coupled one meet at a
/// free point carrying a mass: after the first step, stepping the system
/// (the bordered factorization, the point rows, the end forces)
/// allocates nothing, with either constraint route, all three solvers
/// and both time schemes (the Galerkin step's system mass solve too), and
/// with the coupled point moved by an oscillation or by a table (the
/// spline evaluated at every time node).
fn stepping_a_system_with_a_free_point_allocates_nothing() {
    use crate::common::rope_systems::{settings, three_to_a_point, three_to_a_point_on_a_table};
    use stancf::system::{straight_states, SystemSimulation};
    use stancf::SolverMethod;
    use stancf::TimeScheme::{Galerkin, P2};
    for (method, solver, scheme, table) in [
        (
            ConstraintMethod::Multiplier,
            SolverMethod::Newton,
            P2,
            false,
        ),
        (
            ConstraintMethod::Elimination,
            SolverMethod::Newton,
            P2,
            false,
        ),
        (
            ConstraintMethod::Multiplier,
            SolverMethod::Broyden,
            P2,
            false,
        ),
        (
            ConstraintMethod::Elimination,
            SolverMethod::ModifiedNewton,
            P2,
            false,
        ),
        (
            ConstraintMethod::Multiplier,
            SolverMethod::Newton,
            Galerkin,
            false,
        ),
        (
            ConstraintMethod::Elimination,
            SolverMethod::Broyden,
            Galerkin,
            false,
        ),
        (ConstraintMethod::Multiplier, SolverMethod::Newton, P2, true),
        (
            ConstraintMethod::Elimination,
            SolverMethod::Newton,
            Galerkin,
            true,
        ),
    ] {
        let system = if table {
            three_to_a_point_on_a_table(10)
        } else {
            three_to_a_point(10)
        };
        let start = straight_states(&system);
        let mut settings = StepSettings {
            constraint_method: method,
            time_scheme: scheme,
            ..settings()
        };
        settings.newton.method = solver;
        let mut sim = SystemSimulation::new(system, start, settings).unwrap();
        let allocations = allocations_in_50_steps(&mut sim, |sim| {
            std::hint::black_box(sim.point_force(3));
        });
        assert_eq!(
            allocations, 0,
            "{method:?} {solver:?} {scheme:?} (table: {table}): {allocations} allocations in 50 steps"
        );
    }
}

/// A free body holding three lines (docs/method.md §15.7): the three
/// lines of [`crate::common::rope_systems::three_to_a_point`] held at
/// three points of a free body instead of at the free point, stepped by
/// the Galerkin scheme (the body's rows, its points' constraints, the
/// system's mass matrix refactorized with the body's rates at every
/// step's end): after the first step nothing is allocated.
fn stepping_a_system_with_a_free_body_allocates_nothing() {
    use crate::common::rope_systems::{line_model, settings};
    use stancf::body::RigidInertia;
    use stancf::system::SystemSimulation;
    use stancf::system::{straight_states, Body, BodyKind, End, Line, Point, System};
    let anchors: [[f64; 3]; 3] = [[2.0, 0.0, 0.0], [-1.0, 1.7, 0.0], [-1.0, -1.7, 0.5]];
    let identity = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
    let body = Body::new(
        BodyKind::Free,
        [0.0, 0.0, -1.0],
        identity,
        RigidInertia::principal(0.2, [0.0, 0.0, -0.05], [1e-3, 1e-3, 1.5e-3]),
    );
    let mut points = Vec::new();
    let mut lines = Vec::new();
    for (k, a) in anchors.iter().enumerate() {
        let local = a.map(|c| 0.05 * c);
        points.push(Point::fixed(*a));
        points.push(Point::on_body(0, local));
        lines.push(Line {
            model: line_model(*a, body.point(local), 10),
            ends: [End::Point(2 * k), End::Point(2 * k + 1)],
        });
    }
    let system = System::with_bodies(lines, points, vec![body], [0.0, 0.0, -9.81]).unwrap();
    let start = straight_states(&system);
    let settings = StepSettings {
        time_scheme: stancf::TimeScheme::Galerkin,
        ..settings()
    };
    let mut sim = SystemSimulation::new(system, start, settings).unwrap();
    let allocations = allocations_in_50_steps(&mut sim, |sim| {
        std::hint::black_box(sim.free_body(0).map(|b| b.position()));
    });
    assert_eq!(allocations, 0, "{allocations} allocations in 50 steps");
}

/// The allocations of this thread in 50 steps of `sim` after its first
/// (which sizes the buffers), reading its end forces and what `read`
/// reads after each; the steps must have iterated.
fn allocations_in_50_steps(
    sim: &mut stancf::system::SystemSimulation,
    read: impl Fn(&stancf::system::SystemSimulation),
) -> usize {
    sim.step().unwrap();
    let before = ALLOCATIONS.load(Ordering::SeqCst);
    let mut iterations = 0;
    for _ in 0..50 {
        iterations += sim.step().unwrap().newton.iterations;
        std::hint::black_box(sim.end_forces(0));
        read(sim);
    }
    let after = ALLOCATIONS.load(Ordering::SeqCst);
    assert!(iterations >= 50, "the steps did iterate");
    after - before
}

/// A system without free points (docs/method.md §11.14): 2 and 3 lines of
/// 10 elements (at 2 Newton iterations a step, a step's work under
/// `PARALLEL_LINES_WORK`: solved one after the other), each from a fixed
/// anchor to a swinging fairlead; after the first step, stepping
/// allocates nothing, with Newton and modified Newton (each line's own
/// kept factors). Above that work the lines go to rayon's threads, whose
/// job queue allocates a block now and then (once in 50 steps of 4 lines
/// of 15 elements, measured): rayon's, not the step's.
fn stepping_lines_apart_allocates_nothing() {
    use crate::common::rope_systems::{independent_ropes, settings};
    use stancf::system::{straight_states, SystemSimulation};
    use stancf::SolverMethod;
    for (lines, solver) in [
        (2, SolverMethod::Newton),
        (2, SolverMethod::ModifiedNewton),
        (3, SolverMethod::Newton),
        (3, SolverMethod::ModifiedNewton),
    ] {
        let all: Vec<usize> = (0..lines).collect();
        let system = independent_ropes(&all, lines, 10);
        let start = straight_states(&system);
        let mut settings = settings();
        settings.newton.method = solver;
        let mut sim = SystemSimulation::new(system, start, settings).unwrap();
        let allocations = allocations_in_50_steps(&mut sim, |_| {});
        assert_eq!(
            allocations, 0,
            "{lines} lines of 10 ({solver:?}): {allocations} allocations in 50 steps"
        );
    }
}
