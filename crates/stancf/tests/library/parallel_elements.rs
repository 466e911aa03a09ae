//! The residual of a long line is evaluated on several threads
//! (docs/method.md §7.8): each element into its own derivatives, added to
//! the rows in the element order, so the result is the serial one to the
//! bit whatever the number of threads.

use stancf::assembly::PARALLEL_ELEMENTS;
use stancf::loads::{AirDrag, DragModel};
use stancf::{
    Cable, Constraint, ConstraintKind, ElementType, Load, Material, Model, ModelOptions,
    Simulation, SolverMethod, TimeScheme,
};

/// A long rope pinned at one end, released horizontal under gravity in a
/// wind (drag's terms on the threads too), stepped `steps` times on a
/// pool of `threads`; its final positions and velocities.
fn hanging_rope(threads: usize, scheme: TimeScheme, method: SolverMethod) -> Vec<f64> {
    let elements = PARALLEL_ELEMENTS + 44;
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(threads)
        .build()
        .expect("a thread pool");
    pool.install(|| {
        let model = Model::new(
            Cable::straight(30.0, elements, ElementType::Sac2),
            Material::chen2023_gutta_percha(),
            ModelOptions::default(),
            vec![
                Load::Gravity {
                    acceleration: [0.0, -9.81, 0.0],
                },
                Load::AirDrag(AirDrag {
                    drag_coefficient: 1.2,
                    fluid_density: 1.225,
                    diameter: 3.7e-3,
                    fluid_velocity: [0.0, 0.0, 2.0],
                    model: DragModel::Full,
                }),
            ],
        )
        .unwrap()
        .with_constraints(vec![Constraint {
            node: 0,
            kind: ConstraintKind::Pinned,
        }])
        .unwrap();
        let state = model.initial_state();
        let mut settings = crate::common::step_settings(2e-3, scheme, 1e-10);
        settings.newton.method = method;
        let mut sim = Simulation::new(model, state, settings).unwrap();
        for _ in 0..4 {
            sim.step().unwrap();
        }
        let s = sim.state();
        s.e.iter().chain(s.v.iter()).copied().collect()
    })
}

#[test]
fn a_long_lines_residual_on_two_threads_is_the_serial_one_to_the_bit() {
    for scheme in [TimeScheme::P2, TimeScheme::Galerkin] {
        for method in [SolverMethod::ModifiedNewton, SolverMethod::Newton] {
            let serial = hanging_rope(1, scheme, method);
            let parallel = hanging_rope(2, scheme, method);
            let moved = serial.iter().any(|&v| v != 0.0);
            assert!(moved, "{scheme:?} {method:?}: nothing moved");
            let differing = serial
                .iter()
                .zip(&parallel)
                .filter(|(a, b)| a.to_bits() != b.to_bits())
                .count();
            assert_eq!(
                differing, 0,
                "{scheme:?} {method:?}: {differing} values differ"
            );
        }
    }
}
