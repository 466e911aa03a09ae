//! No heap allocation inside the Newton loop: after the first step (which
//! sizes the scratch buffers), stepping allocates nothing. Counted with a
//! global allocator wrapper; this test binary holds nothing else, so no
//! other thread allocates while it counts.

use std::alloc::{GlobalAlloc, Layout, System};
use std::sync::atomic::{AtomicUsize, Ordering};

struct Counting;

static ALLOCATIONS: AtomicUsize = AtomicUsize::new(0);

unsafe impl GlobalAlloc for Counting {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        ALLOCATIONS.fetch_add(1, Ordering::SeqCst);
        unsafe { System.alloc(layout) }
    }
    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        unsafe { System.dealloc(ptr, layout) }
    }
    unsafe fn realloc(&self, ptr: *mut u8, layout: Layout, new_size: usize) -> *mut u8 {
        ALLOCATIONS.fetch_add(1, Ordering::SeqCst);
        unsafe { System.realloc(ptr, layout, new_size) }
    }
}

#[global_allocator]
static GLOBAL: Counting = Counting;

use stancf::{
    Cable, Constraint, ConstraintKind, ConstraintMethod, ElementType, Load, Material, Model,
    ModelOptions, Simulation, StepSettings,
};

#[test]
fn stepping_allocates_nothing() {
    let material = Material::chen2023_pvc();
    for (kind, layers, constrained, method) in [
        (ElementType::Sac2, 1, false, ConstraintMethod::Multiplier),
        (ElementType::Sac3, 2, false, ConstraintMethod::Multiplier),
        (ElementType::Sac2, 1, true, ConstraintMethod::Multiplier),
        (ElementType::Sac3, 2, true, ConstraintMethod::Elimination),
    ] {
        let constraints = if constrained {
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
