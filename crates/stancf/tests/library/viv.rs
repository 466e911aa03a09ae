//! MoorDyn's VIV lift on a line (docs/method.md §12.7, (V20)-(V26)): the
//! slab rows' exact Jacobian, with the shedding phase collocated over the
//! slab, against central differences (element and assembled steps, both
//! schemes); and the phase of a line held still in a current against the
//! closed form of its synchronisation equation.

use crate::common::step_checks::{check_elements_schemes_and_routes, clamped_start};
use crate::common::*;
use stancf::assembly::Scheme;
use stancf::element::{
    CableElement, DynamicStiffness, Measures, Section, SlabDerivatives, SlabLoads, TimeSlab,
    Viscoelastic, Viv,
};
use stancf::shape::{cubic_hermite, quintic_hermite};
use stancf::water::current::{CurrentProfile, CurrentRow, Ramp};
use stancf::water::kinematics::Sea;
use stancf::water::waves::AiryWave;
use stancf::water::{LineInWater, Morison, Water};
use stancf::{AxialStrain, Cable, Curvature, Load, Material, Model, ModelOptions};
use std::sync::Arc;

const RHO_W: f64 = 1025.0;

fn law() -> Viv {
    Viv {
        lift: 0.7,
        centre: 0.18,
        range: 0.08,
        averaging_time: 0.05,
    }
}

fn morison(d: f64) -> Morison {
    Morison {
        diameter: d,
        cd_normal: 1.2,
        cd_axial: 0.08,
        ca_normal: 1.0,
        ca_axial: 0.0,
    }
}

/// A line of diameter `d` and 1500 kg/m^3 over the displaced area.
fn heavy_line(d: f64) -> Material {
    let area = morison(d).area();
    Material {
        youngs_modulus: 2e5,
        density: 1500.0,
        area,
        second_moment: 1e-4 * area * d * d,
        axial_damping: 0.0,
    }
}

/// A wave and a sheared current: the flow's gradient enters the lift.
fn sheared_sea() -> Sea {
    let wave = AiryWave {
        amplitude: 0.3,
        period: 2.5,
        heading_deg: 20.0,
        phase_deg: 30.0,
    };
    let current = CurrentProfile::new(&[
        CurrentRow {
            z: -5.0,
            velocity: [0.4, 0.1, 0.0],
        },
        CurrentRow {
            z: 0.0,
            velocity: [0.9, -0.3, 0.0],
        },
    ])
    .unwrap();
    Sea::new(5.0, 9.81, &[wave])
        .unwrap()
        .with_wave_ramp(Ramp::new(1.0).unwrap())
        .with_current(current, Ramp::new(1.0).unwrap())
}

fn in_water(sea: Sea, d: f64) -> LineInWater {
    LineInWater::new(
        Arc::new(Water {
            density: RHO_W,
            sea,
        }),
        morison(d),
    )
}

/// The slab rows' Jacobian against central differences of the rows, from
/// the internal state `history`: central differences with h = 1e-6 on
/// rows of size 1e2 leave ~1e-9 relative; the phase's collocation is
/// solved to 1e-14.
fn check_jacobian<const NS: usize, const ND: usize>(
    el: &CableElement<NS, ND>,
    slab: &TimeSlab,
    y: &[[f64; ND]; 4],
    (water, history): (&LineInWater, &[f64]),
    label: &str,
) {
    let loads = SlabLoads {
        water: Some(water),
        time: 0.3,
        ..SlabLoads::gravity([0.0, 0.0, -9.81])
    };
    let mut d = SlabDerivatives::<ND>::default();
    el.slab_derivatives_from(slab, y, &loads, history, false, &mut d);
    assert!(d.viv.active, "{label}: the lift acts");
    let e = slab_jacobian_error(el, slab, y, &loads, history);
    assert!(e < 1e-6, "{label}: Jacobian rel. error {e:e}");
}

/// An element 2 m down, moved by random slab unknowns about it.
fn submerged<const ND: usize>(
    mut y: [[f64; ND]; 4],
    depth: f64,
    per_node: usize,
) -> [[f64; ND]; 4] {
    for m in [0, 2] {
        for node in 0..2 {
            y[m][node * per_node + 2] -= depth;
        }
    }
    y
}

#[test]
fn a_viv_slabs_jacobian_is_the_finite_differences_of_its_rows() {
    let mut rng = Rng(0x7715_0000_0000_0031);
    let visco = Viscoelastic {
        dynamic: DynamicStiffness::Constant(7.0),
        static_damping: 0.4,
        dynamic_damping: 0.05,
    };
    let m = Measures {
        axial_strain: AxialStrain::Engineering,
        curvature: Curvature::Exact,
    };
    let r = rules(4, 3);
    let d = 0.1;
    for with_visco in [false, true] {
        let sec = Section {
            viv: Some(law()),
            visco: with_visco.then(|| visco.clone()),
            ..section()
        };
        let el2 = CableElement::new(cubic_hermite, 0.45, sec.clone(), m, &r);
        let el3 = CableElement::new(quintic_hermite, 0.45, sec, m, &r);
        // Deep (the lift alone) and across the surface (its s(z)).
        for (depth, sea) in [(2.0, sheared_sea()), (0.0, sheared_sea())] {
            let water = in_water(sea, d);
            for points in [2, 3] {
                let s = slab(0.02, points);
                let visco_start: Vec<f64> = if with_visco {
                    vec![0.02, -0.01, 0.05, 0.03]
                } else {
                    vec![]
                };
                for squares in [(0.0, 0.0), (0.04, 0.9)] {
                    let y2 = submerged(random_slab_state::<4, 12>(&mut rng, 0.45, 0.2), depth, 6);
                    let mut history = visco_start.clone();
                    for k in 0..4 {
                        history.extend([0.4 + 1.3 * k as f64, squares.0, squares.1]);
                    }
                    let label = format!(
                        "visco {with_visco} depth {depth} {points} points {squares:?} SAC-2"
                    );
                    check_jacobian(&el2, &s, &y2, (&water, &history), &label);
                    let y3 = submerged(random_slab_state::<6, 18>(&mut rng, 0.45, 0.2), depth, 9);
                    check_jacobian(
                        &el3,
                        &s,
                        &y3,
                        (&water, &history),
                        &label.replace("SAC-2", "SAC-3"),
                    );
                }
            }
        }
    }
}

/// Assembled steps of a line with VIV in waves and a current, P2 and the
/// Galerkin step, SAC-2 and SAC-3, free and clamped by both constraint
/// routes: the step Jacobian against central differences.
#[test]
fn a_viv_lines_step_jacobian_is_the_finite_differences_of_its_rows() {
    let mut rng = Rng(0x7715_0000_0000_0032);
    let model = |kind, constrained| {
        let d = 0.1;
        let cable = Cable::straight(1.2, 3, kind)
            .with_origin([0.1, -0.2, -2.0])
            .with_direction([1.0, 0.5, -0.25]);
        let water = in_water(sheared_sea(), d);
        let material = heavy_line(d);
        let loads = vec![
            Load::Gravity {
                acceleration: [0.0, 0.0, -9.81],
            },
            Load::Water(water),
        ];
        Model::new(cable, material, ModelOptions::default(), loads)
            .unwrap()
            .with_viv(law())
            .unwrap()
            .with_constraints(clamped_start(constrained))
            .unwrap()
    };
    let schemes = [Scheme::P2 { layers: 1 }, Scheme::Galerkin];
    let worst = check_elements_schemes_and_routes(&model, &schemes, &mut rng, "viv", 1e-7);
    eprintln!("step Jacobians with VIV: worst rel. error {worst:.1e}");
}

/// An upright SAC-2 element 0.5 m long, 10 m down (its coordinates).
const UPRIGHT: [f64; 12] = [
    0.0, 0.0, -10.0, 0.0, 0.0, 1.0, 0.0, 0.0, -9.5, 0.0, 0.0, 1.0,
];

/// Water of a uniform current `u` along x, 50 m deep, and a 0.5 m element
/// of diameter `d` with the VIV law (three axial and three time points).
fn upright_in_a_current(u: f64, d: f64) -> (LineInWater, CableElement<4, 12>) {
    let current = CurrentProfile::uniform([u, 0.0, 0.0]).unwrap();
    let sea = Sea::still(50.0, 9.81).with_current(current, Ramp::new(0.0).unwrap());
    let sec = Section {
        viv: Some(law()),
        ..section()
    };
    let el = CableElement::new(cubic_hermite, 0.5, sec, Measures::default(), &rules(3, 3));
    (in_water(sea, d), el)
}

/// An upright line held still in a uniform current U: its cross-flow velocity
/// and acceleration are zero, psi = 0, and (V22) is Adler's equation
/// phi' = a - b sin(phi), a = 2 pi cF U / d, b = 2 pi dF U / d, whose
/// solution is tan(phi / 2) = (b + w tan(w (t + C) / 2)) / a,
/// w = sqrt(a^2 - b^2). The collocation over slabs of two Gauss points
/// is of order 4: the phase after 2 s errs by 1.2e-5 rad at dt = 0.02 s,
/// and halving the step divides it by 16.
#[test]
fn a_held_lines_shedding_phase_follows_adlers_equation_at_the_collocations_order() {
    let (u, d) = (0.6, 0.05);
    let (water, el) = upright_in_a_current(u, d);
    // Still: its velocity and acceleration are exactly zero across the
    // flow (psi is the angle of a scale-free pair, so a round-off motion
    // would set it anywhere; a line never rests exactly in a flow that
    // moves it).
    let mut y = [[0.0; 12]; 4];
    for m in [0, 2] {
        y[m] = UPRIGHT;
    }
    let loads = SlabLoads {
        water: Some(&water),
        ..SlabLoads::gravity([0.0, 0.0, 0.0])
    };
    let (a, b) = (
        std::f64::consts::TAU * law().centre * u / d,
        std::f64::consts::TAU * law().range * u / d,
    );
    let w = (a * a - b * b).sqrt();
    let phi0 = 0.7;
    let c = 2.0 / w * ((a * (phi0 / 2.0f64).tan() - b) / w).atan();
    let exact = |t: f64| 2.0 * ((b + w * (w * (t + c) / 2.0).tan()) / a).atan();
    let error = |dt: f64| -> f64 {
        let s = slab(dt, 2);
        let mut history: Vec<f64> = (0..3).flat_map(|_| [phi0, 0.0, 0.0]).collect();
        let steps = (2.0 / dt).round() as usize;
        let mut d = SlabDerivatives::<12>::default();
        for _ in 0..steps {
            el.slab_derivatives_from(&s, &y, &loads, &history, false, &mut d);
            history.clone_from(&d.viv.end);
        }
        let (got, want) = (history[0], exact(steps as f64 * dt));
        // The difference wrapped to (-pi, pi].
        let d = got - want;
        d.sin().atan2(d.cos()).abs()
    };
    let (coarse, fine) = (error(0.02), error(0.01));
    let order = (coarse / fine).log2();
    eprintln!("phase error {coarse:.2e} -> {fine:.2e} rad, order {order:.2}");
    assert!(coarse < 1e-4, "phase error {coarse:e} rad");
    assert!((order - 4.0).abs() < 0.3, "order {order}");
}

/// The lift acts in water: a line without `Load::Water` is refused VIV,
/// naming it.
#[test]
fn a_line_in_air_is_refused_the_viv_lift() {
    let material = heavy_line(0.1);
    let gravity = vec![Load::Gravity {
        acceleration: [0.0, 0.0, -9.81],
    }];
    let cable = Cable::straight(1.2, 3, stancf::ElementType::Sac2);
    let e = Model::new(cable, material, ModelOptions::default(), gravity)
        .unwrap()
        .with_viv(law())
        .unwrap_err();
    assert!(e.to_string().contains("acts in water"), "{e}");
}

/// MoorDyn's `V` output: the consistent nodal forces of the lift (V23).
/// An upright element, 0.5 m long, held still in a uniform current u
/// along x with every point's phase phi: the lift per length is
/// f = 1/2 rho_w d Cl u^2 cos(phi) along t x v_n = z x x = y, uniform, so
/// its generalized force is f l / 2 on each end's position and
/// +-f l^2 / 12 on its slopes (the cubic's integrals, exact under the
/// 3-point rule), to round-off.
#[test]
fn a_held_lines_viv_nodal_forces_are_the_uniform_lifts_integrals() {
    let (u, d, phi, l) = (0.6, 0.05, 0.7, 0.5);
    let (water, el) = upright_in_a_current(u, d);
    let state: Vec<f64> = (0..3).flat_map(|_| [phi, 0.0, 0.0]).collect();
    let fq = el.viv_generalized_force((&UPRIGHT, &[0.0; 12]), &state, 3.0, &water);
    let f = 0.5 * RHO_W * d * law().lift * u * u * phi.cos();
    let want = [
        0.0,
        f * l / 2.0,
        0.0,
        0.0,
        f * l * l / 12.0,
        0.0,
        0.0,
        f * l / 2.0,
        0.0,
        0.0,
        -f * l * l / 12.0,
        0.0,
    ];
    for (k, (got, want)) in fq.iter().zip(want).enumerate() {
        assert!((got - want).abs() <= 1e-13 * f, "{k}: {got} against {want}");
    }
}
