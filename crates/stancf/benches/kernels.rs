//! Benchmarks: the element kernel (slab residual plus the tangent blocks a
//! one-layer P2 step uses) and one whole P2 step for 8, 64 and 512
//! elements. Report ratios measured in one run (the machine is shared).
//!
//! cargo bench -p stancf --bench kernels

use criterion::{black_box, criterion_group, criterion_main, BenchmarkId, Criterion};
use stancf::element::{CableElement, SlabDerivatives, SlabLoads, SpaceRules, TimeSlab};
use stancf::quadrature::GaussRule;
use stancf::shape::{cubic_hermite, quintic_hermite};
use stancf::{
    stability, Cable, ElementType, Material, Measures, Model, ModelOptions, Simulation,
    StepSettings,
};

fn pvc() -> Material {
    Material::chen2023_pvc()
}

/// A bent, stretched, moving element state.
fn slab_state<const NS: usize, const ND: usize>(l: f64) -> [[f64; ND]; 4] {
    let vpn = NS / 2;
    let mut y = [[0.0; ND]; 4];
    for t in [0, 2] {
        for a in 0..NS {
            let node = (a / vpn) as f64;
            let kind = a % vpn;
            let phase = 0.1 * (t as f64 + 1.0);
            y[t][3 * a] = if kind == 0 {
                node * l
            } else if kind == 1 {
                1.001
            } else {
                0.02
            };
            y[t][3 * a + 1] = if kind == 0 {
                0.01 * phase
            } else {
                0.05 * phase
            };
            y[t][3 * a + 2] = 0.003 * node;
        }
    }
    for t in [1, 3] {
        for d in 0..ND {
            y[t][d] = 0.1 * (d as f64 + 1.0).sin();
        }
    }
    y
}

fn element_kernel<const NS: usize, const ND: usize>(
    c: &mut Criterion,
    name: &str,
    el: &CableElement<NS, ND>,
    slab: &TimeSlab,
) {
    let y = slab_state::<NS, ND>(el.length);
    let g = [0.0, -9.81, 0.0];
    let mut d = SlabDerivatives::<ND>::default();
    let mut block = [[0.0; ND]; ND];
    c.bench_function(name, |b| {
        b.iter(|| {
            el.slab_derivatives(slab, black_box(&y), &SlabLoads::gravity(g), true, &mut d);
            // The four blocks of a one-layer P2 step: rows e_a, e_b; columns e_b, v_b.
            for m in [0, 2] {
                for n in [2, 3] {
                    el.slab_hessian_block(slab, &d, m, n, &mut block);
                    black_box(&block);
                }
            }
        })
    });
}

fn kernels(c: &mut Criterion) {
    let section = pvc().section();
    let slab = TimeSlab::new(5e-5, &GaussRule::new(3).unwrap());
    let r3 = SpaceRules {
        axial: GaussRule::new(3).unwrap(),
        bending: GaussRule::new(3).unwrap(),
    };
    let r5 = SpaceRules {
        axial: GaussRule::new(5).unwrap(),
        bending: GaussRule::new(5).unwrap(),
    };
    let sac2 = CableElement::<4, 12>::new(cubic_hermite, 0.5, section, Measures::default(), &r3);
    let sac3 = CableElement::<6, 18>::new(quintic_hermite, 0.5, section, Measures::default(), &r5);
    element_kernel(c, "element SAC-2 3x3 residual+tangent", &sac2, &slab);
    element_kernel(c, "element SAC-3 5x3 residual+tangent", &sac3, &slab);
}

/// One P2 step of the transverse impact (example 2) on n SAC-2 elements,
/// at 0.3 times the mesh's stable step.
fn whole_step(c: &mut Criterion) {
    let mut group = c.benchmark_group("P2 step SAC-2");
    for &n in &[8usize, 64, 512] {
        let model = Model::new(
            Cable::straight(4.0, n, ElementType::Sac2).with_origin([-2.0, 0.0, 0.0]),
            pvc(),
            ModelOptions::default(),
            vec![],
        )
        .unwrap();
        let mut s = model.initial_state();
        model.set_node_velocity(&mut s, 0, [0.0, 10.0, 0.0]);
        model.set_node_velocity(&mut s, n, [0.0, -10.0, 0.0]);
        let dt =
            0.3 * stability::stable_step(&model, &s.e, &GaussRule::new(3).unwrap(), 1).unwrap();
        let settings = StepSettings {
            time_step: dt,
            ..StepSettings::default()
        };
        let mut sim = Simulation::new(model, s, settings).unwrap();
        // Past the start-up, into the regular motion.
        for _ in 0..20 {
            sim.step().unwrap();
        }
        group.bench_with_input(BenchmarkId::from_parameter(n), &n, |b, _| {
            b.iter(|| black_box(sim.step().unwrap()))
        });
    }
    group.finish();
}

criterion_group! {
    name = benches;
    config = Criterion::default().sample_size(30).measurement_time(std::time::Duration::from_secs(3));
    targets = kernels, whole_step
}
criterion_main!(benches);
