//! Benchmarks: the element kernel (slab residual plus the tangent blocks a
//! one-layer P2 step uses), in air and in water (a current, the added
//! mass, a wave, the bed: the water's cost beside the elastic kernel's,
//! issue 33), and one whole P2 step for 8, 64 and 512 elements. Report
//! ratios measured in one run (the machine is shared).
//!
//! cargo bench --manifest-path bench/criterion/Cargo.toml --bench kernels

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
    element_kernel_in(
        c,
        name,
        el,
        slab,
        &SlabLoads::gravity([0.0, -9.81, 0.0]),
        [0.0; 3],
    );
}

/// [`element_kernel`] under `loads`, the element's state moved by `shift`.
fn element_kernel_in<const NS: usize, const ND: usize>(
    c: &mut Criterion,
    name: &str,
    el: &CableElement<NS, ND>,
    slab: &TimeSlab,
    loads: &SlabLoads,
    shift: [f64; 3],
) {
    let mut y = slab_state::<NS, ND>(el.length);
    for t in [0, 2] {
        for a in (0..NS).step_by(NS / 2) {
            for i in 0..3 {
                y[t][3 * a + i] += shift[i];
            }
        }
    }
    let mut d = SlabDerivatives::<ND>::default();
    let mut block = [[0.0; ND]; ND];
    c.bench_function(name, |b| {
        b.iter(|| {
            el.slab_derivatives(slab, black_box(&y), loads, true, &mut d);
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

/// Floating-point operations of one call of the kernel as benchmarked
/// (`slab_derivatives` with the tangent, then `blocks` Hessian blocks),
/// counted from its loops (FMA = 2):
///
/// per time point: q and qdot (2 x 4 ND FMA), M qdot (3 NS^2 FMA),
/// per axial point: r_x, r_xx (2 x 3 NS FMA), density (~30), gradient
/// (3 NS x 3), Hessian (NS (NS+1)/2 pairs x (2 + 9 x 2));
/// per bending point: r_x, r_xx (2 x 3 NS FMA), density (~250), gradient
/// (3 NS x 5), Hessian (pairs x (8 + 9 x 4 x 2)); time spread of the
/// gradient (4 ND x 5); per block: time points x ND^2 FMA + 4 NS^2.
fn kernel_flops(ns: usize, axial: usize, bending: usize, time: usize, blocks: usize) -> f64 {
    let nd = 3 * ns;
    let pairs = ns * (ns + 1) / 2;
    let per_axial = 12 * ns + 30 + 9 * ns + pairs * 20;
    let per_bending = 12 * ns + 250 + 15 * ns + pairs * 80;
    let per_time = 16 * nd + 6 * ns * ns + axial * per_axial + bending * per_bending + 20 * nd;
    let per_block = 2 * time * nd * nd + 4 * ns * ns;
    (time * per_time + blocks * per_block) as f64
}

/// One core's peak: 8 independent chains of 4-wide fused multiply-adds
/// (AVX2 + FMA; Zen 4 runs AVX-512 at the same rate), when the CPU has
/// them, else 2-wide SSE2 multiplies and adds.
fn peak(c: &mut Criterion) {
    const N: usize = 1 << 16;
    #[cfg(target_arch = "x86_64")]
    {
        if is_x86_feature_detected!("avx2") && is_x86_feature_detected!("fma") {
            #[target_feature(enable = "avx2,fma")]
            unsafe fn fma_chains(x: f64) -> f64 {
                use std::arch::x86_64::*;
                let a = _mm256_set1_pd(1.0 - 1e-9);
                let b = _mm256_set1_pd(1e-9);
                let mut acc = [_mm256_set1_pd(x); 8];
                for _ in 0..N {
                    for v in acc.iter_mut() {
                        *v = _mm256_fmadd_pd(*v, a, b);
                    }
                }
                let mut s = [0.0; 4];
                let mut t = acc[0];
                for v in &acc[1..] {
                    t = _mm256_add_pd(t, *v);
                }
                _mm256_storeu_pd(s.as_mut_ptr(), t);
                s.iter().sum()
            }
            let flops = (N * 8 * 4 * 2) as f64;
            c.bench_function(&format!("peak: AVX2 FMA, {flops:e} flops"), |bch| {
                bch.iter(|| unsafe { fma_chains(black_box(1.0)) })
            });
        }
    }
}

fn kernels(c: &mut Criterion) {
    for (name, ns, a, b, t) in [("SAC-2 3x3", 4, 3, 3, 3), ("SAC-3 5x3", 6, 5, 5, 3)] {
        eprintln!(
            "flops per kernel call, {name}: {:.0}",
            kernel_flops(ns, a, b, t, 4)
        );
    }
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
    let sac2 = CableElement::<4, 12>::new(
        cubic_hermite,
        0.5,
        section.clone(),
        Measures::default(),
        &r3,
    );
    let sac3 = CableElement::<6, 18>::new(quintic_hermite, 0.5, section, Measures::default(), &r5);
    element_kernel(c, "element SAC-2 3x3 residual+tangent", &sac2, &slab);
    element_kernel(c, "element SAC-3 5x3 residual+tangent", &sac3, &slab);
    water_kernels(c, &sac2, &slab);
}

/// The SAC-2 kernel in water (issue 33: the water's cost beside the
/// elastic kernel's in air): 20 m down in a sheared current with Morison
/// drag, the fluid's inertia and buoyancy (no added mass), then with the
/// entrained water's added mass, then in a wave over the current, then
/// resting on the bed with its contact and friction.
fn water_kernels(c: &mut Criterion, el: &CableElement<4, 12>, slab: &TimeSlab) {
    use stancf::water::current::{CurrentProfile, CurrentRow, Ramp};
    use stancf::water::kinematics::Sea;
    use stancf::water::waves::AiryWave;
    use stancf::water::{LineInWater, Morison, Seabed, SeabedContact, Water};
    use std::sync::Arc;
    let current = CurrentProfile::new(&[
        CurrentRow {
            z: -50.0,
            velocity: [0.2, 0.0, 0.0],
        },
        CurrentRow {
            z: 0.0,
            velocity: [0.8, 0.1, 0.0],
        },
    ])
    .unwrap();
    let calm = Sea::still(50.0, 9.81).with_current(current.clone(), Ramp::new(0.0).unwrap());
    let wave = AiryWave {
        amplitude: 1.0,
        period: 8.0,
        heading_deg: 20.0,
        phase_deg: 0.0,
    };
    let rough = Sea::new(50.0, 9.81, &[wave])
        .unwrap()
        .with_current(current, Ramp::new(0.0).unwrap());
    let morison = |ca: f64| Morison {
        diameter: 0.05,
        cd_normal: 1.2,
        cd_axial: 0.1,
        ca_normal: ca,
        ca_axial: 0.0,
    };
    let water = |sea: &Sea, ca: f64| {
        LineInWater::new(
            Arc::new(Water {
                density: 1025.0,
                sea: sea.clone(),
            }),
            morison(ca),
        )
    };
    let g = [0.0, 0.0, -9.81];
    let (plain, added, waves) = (water(&calm, 0.0), water(&calm, 1.0), water(&rough, 1.0));
    let air = SlabLoads::gravity(g);
    element_kernel_in(
        c,
        "element SAC-2 3x3 in air (z up)",
        el,
        slab,
        &air,
        [0.0; 3],
    );
    let deep = [0.0, 0.0, -20.0];
    let cases: [(&str, &LineInWater); 3] = [
        ("element SAC-2 3x3 in a current", &plain),
        ("element SAC-2 3x3 in a current, added mass", &added),
        (
            "element SAC-2 3x3 in a wave and a current, added mass",
            &waves,
        ),
    ];
    for (name, w) in cases {
        let loads = SlabLoads {
            water: Some(w),
            ..SlabLoads::gravity(g)
        };
        element_kernel_in(c, name, el, slab, &loads, deep);
    }
    let bed = SeabedContact {
        seabed: Seabed::flat(20.0, 3e6, 3e5).with_friction(0.5, 0.5, 1e-3),
        diameter: 0.05,
    };
    let loads = SlabLoads {
        water: Some(&added),
        seabed: Some(&bed),
        ..SlabLoads::gravity(g)
    };
    element_kernel_in(
        c,
        "element SAC-2 3x3 on the bed in a current, added mass",
        el,
        slab,
        &loads,
        deep,
    );
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
    targets = peak, kernels, whole_step
}
criterion_main!(benches);
