//! Helpers shared by the integration tests.
#![allow(dead_code)]

pub mod lumped_bodies;
pub mod rods;
pub mod rope_systems;
pub mod step_checks;
pub mod water_lines;

use stancf::element::{CableElement, Measures, Section, SpaceRules, TimeSlab};
use stancf::quadrature::GaussRule;
use stancf::shape::{cubic_hermite, quintic_hermite};
use stancf::{AxialStrain, Curvature, Material, NewtonSettings, StepSettings, TimeScheme};

/// Deterministic pseudo-random numbers in [-1, 1) (xorshift64).
pub struct Rng(pub u64);

impl Rng {
    pub fn next(&mut self) -> f64 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        (self.0 >> 11) as f64 / (1u64 << 52) as f64 - 1.0
    }
}

/// Relative difference |a - b| / max(|b|, floor) of two vectors (2-norm).
pub fn rel_diff(a: &[f64], b: &[f64]) -> f64 {
    let num: f64 = a
        .iter()
        .zip(b)
        .map(|(x, y)| (x - y).powi(2))
        .sum::<f64>()
        .sqrt();
    let den: f64 = b.iter().map(|y| y * y).sum::<f64>().sqrt();
    num / den.max(1e-300)
}

pub const ALL_MEASURES: [Measures; 4] = [
    Measures {
        axial_strain: AxialStrain::Green,
        curvature: Curvature::Paper,
    },
    Measures {
        axial_strain: AxialStrain::Green,
        curvature: Curvature::Exact,
    },
    Measures {
        axial_strain: AxialStrain::Engineering,
        curvature: Curvature::Paper,
    },
    Measures {
        axial_strain: AxialStrain::Engineering,
        curvature: Curvature::Exact,
    },
];

pub fn section() -> Section {
    Section {
        ea: 3.0,
        ei: 0.2,
        rho_a: 1.3,
        ba: 0.0,
        tension_only: false,
        curve: None,
        visco: None,
        viv: None,
    }
}

pub fn rules(axial: usize, bending: usize) -> SpaceRules {
    SpaceRules {
        axial: GaussRule::new(axial).unwrap(),
        bending: GaussRule::new(bending).unwrap(),
    }
}

pub fn sac2(l: f64, m: Measures, r: &SpaceRules) -> CableElement<4, 12> {
    CableElement::new(cubic_hermite, l, section(), m, r)
}

pub fn sac3(l: f64, m: Measures, r: &SpaceRules) -> CableElement<6, 18> {
    CableElement::new(quintic_hermite, l, section(), m, r)
}

pub fn slab(dt: f64, points: usize) -> TimeSlab {
    TimeSlab::new(dt, &GaussRule::new(points).unwrap())
}

/// Random slab unknowns near a bent, stretched, moving element: the
/// straight reference plus perturbations of size `amp`, velocities of
/// order 1.
pub fn random_slab_state<const NS: usize, const ND: usize>(
    rng: &mut Rng,
    l: f64,
    amp: f64,
) -> [[f64; ND]; 4] {
    let vpn = NS / 2;
    let mut y = [[0.0; ND]; 4];
    for t in [0, 2] {
        for a in 0..NS {
            let node = a / vpn;
            let kind = a % vpn;
            for i in 0..3 {
                let base = match (kind, i) {
                    (0, 0) => node as f64 * l,
                    (1, 0) => 1.0,
                    _ => 0.0,
                };
                y[t][3 * a + i] = base + amp * rng.next();
            }
        }
    }
    for t in [1, 3] {
        for d in 0..ND {
            y[t][d] = rng.next();
        }
    }
    y
}

/// Eigenvalues of the symmetric matrix `a` (dense, n x n), ascending, by
/// the cyclic Jacobi method (rotations until the off-diagonal part is
/// below 1e-16 of the whole): slow, simple and independent of the
/// library's eigenvalue code.
pub fn symmetric_eigenvalues(mut a: Vec<Vec<f64>>) -> Vec<f64> {
    let n = a.len();
    let total: f64 = a.iter().flatten().map(|v| v * v).sum();
    for _sweep in 0..100 {
        let off: f64 = (0..n)
            .flat_map(|i| (0..n).filter(move |&j| j != i).map(move |j| (i, j)))
            .map(|(i, j)| a[i][j] * a[i][j])
            .sum();
        if off <= 1e-32 * total {
            break;
        }
        for p in 0..n {
            for q in p + 1..n {
                if a[p][q] == 0.0 {
                    continue;
                }
                let theta = (a[q][q] - a[p][p]) / (2.0 * a[p][q]);
                let t = theta.signum() / (theta.abs() + (theta * theta + 1.0).sqrt());
                let t = if theta == 0.0 { 1.0 } else { t };
                let c = 1.0 / (t * t + 1.0).sqrt();
                let s = t * c;
                for k in 0..n {
                    let (akp, akq) = (a[k][p], a[k][q]);
                    a[k][p] = c * akp - s * akq;
                    a[k][q] = s * akp + c * akq;
                }
                for k in 0..n {
                    let (apk, aqk) = (a[p][k], a[q][k]);
                    a[p][k] = c * apk - s * aqk;
                    a[q][k] = s * apk + c * aqk;
                }
            }
        }
    }
    let mut ev: Vec<f64> = (0..n).map(|i| a[i][i]).collect();
    ev.sort_by(f64::total_cmp);
    ev
}

/// Largest lambda of K x = lambda M x (K symmetric, M symmetric positive
/// definite, dense): Cholesky M = L L^T, then the eigenvalues of
/// L^-1 K L^-T by [`symmetric_eigenvalues`].
pub fn generalized_max_eigenvalue(k: &[Vec<f64>], m: &[Vec<f64>]) -> f64 {
    let n = k.len();
    let mut l = vec![vec![0.0; n]; n];
    for i in 0..n {
        for j in 0..=i {
            let s = m[i][j] - (0..j).map(|p| l[i][p] * l[j][p]).sum::<f64>();
            l[i][j] = if i == j { s.sqrt() } else { s / l[j][j] };
        }
    }
    // C = L^-1 K L^-T: solve L Y = K, then L C^T = Y^T.
    let lower_solve = |b: &[f64]| {
        let mut x = vec![0.0; n];
        for i in 0..n {
            x[i] = (b[i] - (0..i).map(|p| l[i][p] * x[p]).sum::<f64>()) / l[i][i];
        }
        x
    };
    let y: Vec<Vec<f64>> = (0..n)
        .map(|j| lower_solve(&(0..n).map(|i| k[i][j]).collect::<Vec<_>>()))
        .collect(); // y[j] = column j of L^-1 K
    let c: Vec<Vec<f64>> = (0..n)
        .map(|i| lower_solve(&(0..n).map(|j| y[j][i]).collect::<Vec<_>>()))
        .collect(); // c[i] = column i of L^-1 (L^-1 K)^T = row i of C
    let c: Vec<Vec<f64>> = (0..n)
        .map(|i| (0..n).map(|j| 0.5 * (c[i][j] + c[j][i])).collect())
        .collect();
    *symmetric_eigenvalues(c).last().expect("n > 0")
}

/// A light rope: 2 mm^2 at 1 MPa (EA 2 N: 1 % strain under its own weight
/// over a metre, wave speed 32 m/s), 2 g/m, bending stiffness 1e-6 of its
/// axial one over a metre squared, no damping.
pub fn light_rope() -> Material {
    Material {
        youngs_modulus: 1e6,
        density: 1000.0,
        area: 2e-6,
        second_moment: 2e-12,
        axial_damping: 0.0,
    }
}

/// A step of `dt` in `scheme` with Newton to `tolerance` in at most 50
/// iterations (the rest as [`StepSettings::default`]).
pub fn step_settings(dt: f64, scheme: TimeScheme, tolerance: f64) -> StepSettings {
    StepSettings {
        time_step: dt,
        time_scheme: scheme,
        newton: NewtonSettings {
            tolerance,
            max_iterations: 50,
            ..NewtonSettings::default()
        },
        ..StepSettings::default()
    }
}

/// The relative difference (as [`rel_diff`]) between the next step's
/// Jacobian of `sim` at its predicted unknowns and central differences
/// of its rows with step h.
pub fn step_jacobian_error(sim: &mut stancf::system::SystemSimulation, h: f64) -> f64 {
    use stancf::linear::Jacobian;
    let (jac, x) = sim.next_step_jacobian();
    let n = x.len();
    let mut analytic = Vec::with_capacity(n * n);
    let mut fd = Vec::with_capacity(n * n);
    for c in 0..n {
        let (mut xp, mut xm) = (x.clone(), x.clone());
        xp[c] += h;
        xm[c] -= h;
        let (rp, rm) = (sim.next_step_residual(&xp), sim.next_step_residual(&xm));
        for r in 0..n {
            fd.push((rp[r] - rm[r]) / (2.0 * h));
            analytic.push(jac.get(r, c));
        }
    }
    rel_diff(&analytic, &fd)
}

/// A system with a free body stepped by the Galerkin scheme for 1 s at
/// `dt`: the largest drift of its energy less the external work from its
/// start, and the energy the water took (-water work).
pub fn galerkin_energy_drift(
    system: stancf::system::System,
    states: Vec<stancf::State>,
    dt: f64,
) -> (f64, f64) {
    let settings = StepSettings {
        time_step: dt,
        time_scheme: TimeScheme::Galerkin,
        ..StepSettings::default()
    };
    let mut sim = stancf::system::SystemSimulation::new(system, states, settings).unwrap();
    let e0 = sim.energies().mechanical();
    let mut drift = 0.0f64;
    for _ in 0..(1.0 / dt).round() as usize {
        sim.step().expect("step");
        drift = drift.max((sim.energies().mechanical() - sim.external_work() - e0).abs());
    }
    (drift, -sim.water_work())
}

/// The energy balance of [`galerkin_energy_drift`] at dt 0.02 and 0.01 s
/// (`run(dt)`) holds to the step's error at fourth order: asserts that
/// the water took more than `least_lost`, a drift ratio above 8 and a
/// drift at 0.01 s below 1e-4 of what the water took.
pub fn assert_energy_balance_falls_at_fourth_order(
    run: impl Fn(f64) -> (f64, f64),
    least_lost: f64,
) {
    let (coarse, lost) = run(0.02);
    let (fine, _) = run(0.01);
    eprintln!(
        "energy less the water's work: drift {coarse:.1e} and {fine:.1e} J (ratio {:.1}); \
         the water took {lost:.3} J",
        coarse / fine
    );
    assert!(lost > least_lost, "the drag does work: {lost}");
    assert!(
        coarse > 8.0 * fine && fine < 1e-4 * lost,
        "{coarse:e} {fine:e}"
    );
}

/// `body` (body 0) holding two light ropes at its points `local` (points
/// 0 and 1): rope 0 from a fixed point at [0.1, 0.4, z] (point 2), rope 1
/// from a loose end at [-0.4, 0.4, z], both straight, starting to move
/// with the body (`System::start_lines_with_bodies`); in gravity 9.81.
pub fn two_ropes_on_a_body(
    body: stancf::system::Body,
    local: [[f64; 3]; 2],
    z: f64,
) -> (stancf::system::System, Vec<stancf::State>) {
    use stancf::system::{End, Line, Point, System};
    use stancf::vec3::{norm, scale, sub};
    let lines: Vec<Line> = (0..2)
        .map(|k| {
            let (start, end) = ([0.1 - 0.5 * k as f64, 0.4, z], body.point(local[k]));
            let chord = norm(sub(end, start));
            let cable = stancf::Cable::straight(chord, 4, stancf::ElementType::Sac2)
                .with_direction(scale(1.0 / chord, sub(end, start)))
                .with_origin(start);
            let model =
                stancf::Model::new(cable, light_rope(), Default::default(), vec![]).expect("model");
            let first = if k == 0 { End::Point(2) } else { End::Loose };
            Line {
                model,
                ends: [first, End::Point(k)],
            }
        })
        .collect();
    let points = vec![
        Point::on_body(0, local[0]),
        Point::on_body(0, local[1]),
        Point::fixed([0.1, 0.4, z]),
    ];
    let system = System::with_bodies(lines, points, vec![body], [0.0, 0.0, -9.81]).expect("system");
    let states = started_with_bodies(&system);
    (system, states)
}

/// The lines' states of `system` at their models' initial states, their
/// ends moved with the bodies they are on
/// (`System::start_lines_with_bodies`).
pub fn started_with_bodies(system: &stancf::system::System) -> Vec<stancf::State> {
    let mut states: Vec<stancf::State> = system
        .lines()
        .iter()
        .map(|l| l.model.initial_state())
        .collect();
    system.start_lines_with_bodies(&mut states);
    states
}

/// The period of `angle(sim)` over three periods from its zero crossings
/// (each placed linearly between the steps around it), stepping `sim`
/// with steps of `dt`; `watch(sim)` is called after every step (a
/// quantity to track alongside).
pub fn period_from_crossings(
    sim: &mut stancf::system::SystemSimulation,
    dt: f64,
    angle: impl Fn(&stancf::system::SystemSimulation) -> f64,
    mut watch: impl FnMut(&stancf::system::SystemSimulation),
) -> f64 {
    let (mut before, mut crossings) = (angle(sim), Vec::new());
    while crossings.len() < 7 {
        let t = sim.time();
        sim.step().expect("step");
        let now = angle(sim);
        if before * now < 0.0 {
            crossings.push(t + dt * before / (before - now));
        }
        before = now;
        watch(sim);
    }
    (crossings[6] - crossings[0]) / 3.0
}

/// A 1 m [`light_rope`] (2 g) hanging from `top` in gravity 9.81, its end A
/// on point 0, its end B loose, and its state at rest.
pub fn hanging_line(top: [f64; 3]) -> (stancf::system::Line, stancf::State) {
    use stancf::system::{End, Line};
    let cable = stancf::Cable::straight(1.0, 4, stancf::ElementType::Sac2)
        .with_origin(top)
        .with_direction([0.0, 0.0, -1.0]);
    let model = stancf::Model::new(
        cable,
        light_rope(),
        Default::default(),
        vec![stancf::Load::Gravity {
            acceleration: [0.0, 0.0, -9.81],
        }],
    )
    .expect("model");
    let state = model.initial_state();
    (
        Line {
            model,
            ends: [End::Point(0), End::Loose],
        },
        state,
    )
}

/// `system`'s static equilibrium from the seeded path
/// ([`stancf::system::SystemStatics::seeded`]) to `tolerance`.
pub fn seeded_equilibrium(
    system: stancf::system::System,
    tolerance: f64,
) -> stancf::system::SystemStatics {
    let settings = stancf::StaticSettings {
        tolerance,
        ..stancf::StaticSettings::default()
    };
    let mut statics =
        stancf::system::SystemStatics::seeded(system.clone(), &system, settings).expect("statics");
    assert!(statics
        .solve(|_, _| std::ops::ControlFlow::Continue(()))
        .expect("solve"));
    statics
}

/// The lean a of a buoyant rod held at its foot in a current, where its
/// lift's moment balances its drag's: lift sin(a) = drag cos^2(a)
/// (lift (rho V - m) g, drag 1/2 rho Cd d L U^2), by Newton from 0.
pub fn lean_in_a_current(lift: f64, drag: f64) -> f64 {
    let mut a = 0.0f64;
    for _ in 0..50 {
        let balance = lift * a.sin() - drag * a.cos().powi(2);
        let slope = lift * a.cos() + 2.0 * drag * a.cos() * a.sin();
        a -= balance / slope;
    }
    a
}

/// `body` (body 0) on no line, in a system whose only line (which a system
/// needs) is a [`hanging_line`] between two anchors at `aside` and 1 m
/// below it (points 0 and 1); in gravity 9.81. With the line's state.
pub fn body_on_no_line(
    body: stancf::system::Body,
    aside: [f64; 3],
) -> (stancf::system::System, stancf::State) {
    use stancf::system::{End, Line, Point, System};
    let (line, state) = hanging_line(aside);
    let line = Line {
        ends: [End::Point(0), End::Point(1)],
        ..line
    };
    let below = [aside[0], aside[1], aside[2] - 1.0];
    let points = vec![Point::fixed(aside), Point::fixed(below)];
    let system =
        System::with_bodies(vec![line], points, vec![body], [0.0, 0.0, -9.81]).expect("system");
    (system, state)
}

/// [`step_jacobian_error`] of the first Galerkin step of `dt` of `system`
/// from `states`, with differences of 1e-6.
pub fn galerkin_jacobian_error(
    system: stancf::system::System,
    states: Vec<stancf::State>,
    dt: f64,
) -> f64 {
    let settings = StepSettings {
        time_step: dt,
        time_scheme: TimeScheme::Galerkin,
        ..StepSettings::default()
    };
    let mut sim = stancf::system::SystemSimulation::new(system, states, settings).unwrap();
    step_jacobian_error(&mut sim, 1e-6)
}

/// A line of `material` and `length` laid straight from `start` towards
/// `end` in `elements` SAC-2 elements, under gravity 9.81.
pub fn straight_line(
    start: [f64; 3],
    end: [f64; 3],
    length: f64,
    elements: usize,
    material: stancf::Material,
) -> stancf::Model {
    let chord = stancf::vec3::sub(end, start);
    let cable = stancf::Cable::straight(length, elements, stancf::ElementType::Sac2)
        .with_origin(start)
        .with_direction(stancf::vec3::normalized(chord));
    stancf::Model::new(
        cable,
        material,
        Default::default(),
        vec![stancf::Load::Gravity {
            acceleration: [0.0, 0.0, -9.81],
        }],
    )
    .expect("model")
}

/// A system tumbling in empty space for 0.4 s at dt 8, 4 and 2 ms:
/// `start(dt)` makes its simulation, `momenta(sim)` the whole's linear
/// and angular momentum. Asserts that the linear momentum is kept to
/// 1e-12 at each step; returns the drifts of the angular momentum and of
/// the energy at each step, and their orders from 8 to 4 ms.
pub fn tumbling_drifts(
    start: impl Fn(f64) -> stancf::system::SystemSimulation,
    momenta: impl Fn(&stancf::system::SystemSimulation) -> ([f64; 3], [f64; 3]),
) -> (Vec<(f64, f64)>, f64, f64) {
    let largest =
        |a: [f64; 3], b: [f64; 3]| (0..3).map(|c| (a[c] - b[c]).abs()).fold(0.0, f64::max);
    let mut drifts = Vec::new();
    for (dt, steps) in [(8e-3, 50), (4e-3, 100), (2e-3, 200)] {
        let mut sim = start(dt);
        let ((p0, l0), e0) = (momenta(&sim), sim.energies().mechanical());
        for _ in 0..steps {
            sim.step().expect("step");
        }
        let ((p1, l1), e1) = (momenta(&sim), sim.energies().mechanical());
        let (dp, dl, de) = (largest(p1, p0), largest(l1, l0), (e1 - e0).abs());
        eprintln!(
            "dt {dt:e}: momentum {dp:.1e}, angular momentum {dl:.1e}, energy {de:.1e} of \
             {e0:.3e} J"
        );
        assert!(dp < 1e-12, "linear momentum drifts by {dp:e}");
        drifts.push((dl, de));
    }
    let order_l = (drifts[0].0 / drifts[1].0).log2();
    let order_e = (drifts[0].1 / drifts[1].1).log2();
    eprintln!("orders from dt 8e-3 to 4e-3: angular momentum {order_l:.2}, energy {order_e:.2}");
    (drifts, order_l, order_e)
}

/// A free body at [0.3, 0.1, -1] turned by MoorDyn's angles (20, -35, 50)
/// degrees, moving at [0.2, -0.1, 0.3] m/s and turning at [0.5, 1, -0.7]
/// rad/s, of `inertia`: the step Jacobians' test body.
pub fn turned_moving_body(inertia: stancf::body::RigidInertia) -> stancf::system::Body {
    let rotation = stancf::body::pose::rotation_from_moordyn_angles([20.0, -35.0, 50.0]);
    let kind = stancf::system::BodyKind::Free;
    let mut body = stancf::system::Body::new(kind, [0.3, 0.1, -1.0], rotation, inertia);
    body.velocity = [0.2, -0.1, 0.3];
    body.angular_velocity = [0.5, 1.0, -0.7];
    body
}

/// `model`'s reference state turning rigidly at `spin` about the origin
/// and drifting at `drift`.
pub fn spun_and_drifting(model: &stancf::Model, spin: [f64; 3], drift: [f64; 3]) -> stancf::State {
    let mut state = model.initial_state();
    model.add_rigid_rotation(&mut state, spin, [0.0; 3]);
    for node in 0..model.nodes() {
        let o = model.coordinate(node, 0, 0);
        for c in 0..3 {
            state.v[o + c] += drift[c];
        }
    }
    state
}

/// The constraints of the step Jacobian checks with `constrained`: node 0
/// clamped, node 2 driven (a drift and a sine); none otherwise.
pub fn clamped_and_driven(constrained: bool) -> Vec<stancf::Constraint> {
    use stancf::{Constraint, ConstraintKind};
    if !constrained {
        return vec![];
    }
    vec![
        Constraint {
            node: 0,
            kind: ConstraintKind::Clamped {
                fix_curvature: false,
            },
        },
        Constraint {
            node: 2,
            kind: ConstraintKind::Prescribed {
                velocity: [0.1, 0.0, -0.2],
                amplitude: [0.0, 0.02, 0.01],
                frequency: 3.0,
                phase: 0.4,
            },
        },
    ]
}

/// Model options with the engineering strain (MoorDyn's), the rest the
/// defaults.
pub fn engineering_options() -> stancf::ModelOptions {
    stancf::ModelOptions {
        measures: Measures {
            axial_strain: AxialStrain::Engineering,
            ..Measures::default()
        },
        ..stancf::ModelOptions::default()
    }
}

/// The slab rows' Jacobian (every block of [`CableElement::slab_hessian_block`])
/// against central differences (h = 1e-6) of the rows under `loads`, from
/// the internal state `history`: the relative error.
pub fn slab_jacobian_error<const NS: usize, const ND: usize>(
    el: &CableElement<NS, ND>,
    slab: &TimeSlab,
    y: &[[f64; ND]; 4],
    loads: &stancf::element::SlabLoads,
    history: &[f64],
) -> f64 {
    use stancf::element::SlabDerivatives;
    const H: f64 = 1e-6;
    let mut d = SlabDerivatives::<ND>::default();
    el.slab_derivatives_from(slab, y, loads, history, true, &mut d);
    let (mut dp, mut dm) = (
        SlabDerivatives::<ND>::default(),
        SlabDerivatives::<ND>::default(),
    );
    let (mut exact, mut fd) = (Vec::new(), Vec::new());
    let mut block = [[0.0; ND]; ND];
    let mut columns = vec![vec![[0.0; ND]; 4]; 4 * ND];
    for n in 0..4 {
        for b in 0..ND {
            let (mut yp, mut ym) = (*y, *y);
            yp[n][b] += H;
            ym[n][b] -= H;
            el.slab_derivatives_from(slab, &yp, loads, history, false, &mut dp);
            el.slab_derivatives_from(slab, &ym, loads, history, false, &mut dm);
            for m in 0..4 {
                for a in 0..ND {
                    columns[n * ND + b][m][a] = (dp.grad[m][a] - dm.grad[m][a]) / (2.0 * H);
                }
            }
        }
    }
    for m in 0..4 {
        for n in 0..4 {
            el.slab_hessian_block(slab, &d, m, n, &mut block);
            for a in 0..ND {
                for b in 0..ND {
                    exact.push(block[a][b]);
                    fd.push(columns[n * ND + b][m][a]);
                }
            }
        }
    }
    rel_diff(&exact, &fd)
}

/// The mechanical energy of a system whose one free point p carries a
/// constant load: its lines' energies, the point's kinetic energy
/// (its inertia, with any added mass) and the load's potential.
pub fn line_and_point_energy(sim: &stancf::system::SystemSimulation, p: usize) -> f64 {
    let system = sim.topology();
    let (load, inertia) = (system.point_load(p), system.point_inertia(p));
    let lines: f64 = sim.lines().iter().map(|l| l.energies().mechanical()).sum();
    let (x, v) = sim.point_state(p);
    let kinetic = 0.5 * inertia * v.iter().map(|c| c * c).sum::<f64>();
    lines + kinetic - (0..3).map(|k| load[k] * x[k]).sum::<f64>()
}
