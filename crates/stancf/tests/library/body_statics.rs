//! The static equilibrium of free bodies held by lines (docs/method.md
//! §15.8): the body's weight and buoyancy against its lines' forces and
//! moments, the lines being catenaries between their anchors and the
//! body's points.

use stancf::body::{BodyWater, RigidInertia};
use stancf::catenary::{Catenary, CatenaryLine, LineEnd};
use stancf::system::{Body, BodyKind, End, Line, Point, System, SystemSimulation, SystemStatics};
use stancf::{
    AxialStrain, Cable, ElementType, Load, Material, Model, ModelOptions, StaticSettings,
    StepSettings, TimeScheme,
};

const G: [f64; 3] = [0.0, 0.0, -9.81];
const RHO: f64 = 1025.0;
/// The lines: 2 kg/m, EA 1e7 N, EI 1e-7 w L^3 of the longest (the
/// EI = 0 rule of docs/method.md §11.7).
const MASS_PER_LENGTH: f64 = 2.0;
const EA: f64 = 1e7;

fn chain(a: [f64; 3], b: [f64; 3], length: f64) -> Model {
    line_model(a, b, length, vec![Load::Gravity { acceleration: G }])
}

/// The lines' model from `a` towards `b`, of `length`, under `loads`.
fn line_model(a: [f64; 3], b: [f64; 3], length: f64, loads: Vec<Load>) -> Model {
    let w = MASS_PER_LENGTH * 9.81;
    let area = 1e-3;
    let material = Material {
        youngs_modulus: EA / area,
        density: MASS_PER_LENGTH / area,
        area,
        second_moment: 1e-7 * w * 64.0f64.powi(3) / (EA / area),
        axial_damping: 0.0,
    };
    let d: [f64; 3] = std::array::from_fn(|i| b[i] - a[i]);
    let cable = Cable::straight(length, 40, ElementType::Sac2)
        .with_origin(a)
        .with_direction(d);
    // The engineering strain, Irvine's (and MoorDyn's): T = EA (lam - 1).
    let mut options = ModelOptions::default();
    options.measures.axial_strain = AxialStrain::Engineering;
    Model::new(cable, material, options, loads).expect("model")
}

fn norm(v: [f64; 3]) -> f64 {
    v.iter().map(|x| x * x).sum::<f64>().sqrt()
}

/// A buoy of 500 kg and 2 m^3 (net lift 15.2 kN) near 10 m depth, held
/// taut by three lines of 60, 62 and 64 m from anchors 50 m out at 50 m
/// depth to three points on its underside 1 m from its axis, its centre
/// of mass 0.3 m below its reference point: the uneven lines pull it
/// sideways and tilt it.
fn moored_buoy() -> System {
    let rotation = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
    buoy_at(BodyKind::Free, [0.0, 0.0, -10.0], rotation)
}

/// The buoy of [`moored_buoy`], `kind`, at `position` turned by `rotation`.
fn buoy_at(kind: BodyKind, position: [f64; 3], rotation: [[f64; 3]; 3]) -> System {
    buoy_in(kind, position, rotation, BodyWater::default())
}

/// The buoy with `water`'s drag areas and current.
fn buoy_in(
    kind: BodyKind,
    position: [f64; 3],
    rotation: [[f64; 3]; 3],
    water: BodyWater,
) -> System {
    let mut body = Body::new(
        kind,
        position,
        rotation,
        RigidInertia::principal(500.0, [0.0, 0.0, -0.3], [300.0, 300.0, 200.0]),
    );
    body.water = Some(BodyWater {
        density: RHO,
        volume: 2.0,
        ..water
    });
    let mut lines = Vec::new();
    let mut points = Vec::new();
    for k in 0..3 {
        let angle = 2.0 * std::f64::consts::PI * k as f64 / 3.0;
        let (c, s) = (angle.cos(), angle.sin());
        let local = [c, s, -0.5];
        let anchor = [50.0 * c, 50.0 * s, -50.0];
        let top = body.point(local);
        points.push(Point::on_body(0, local));
        points.push(Point::fixed(anchor));
        lines.push(Line {
            model: chain(anchor, top, 60.0 + 2.0 * k as f64),
            ends: [End::Point(2 * k + 1), End::Point(2 * k)],
        });
    }
    System::with_bodies(lines, points, vec![body], G).expect("system")
}

/// At the equilibrium every line's pull on the buoy is the elastic
/// catenary's (Irvine's closed form between the line's anchor and the
/// buoy's point, crate::catenary) to 1e-5, the elements' and the EI = 0
/// rule's accuracy (as for a line alone, system_statics.rs); and the
/// buoy is balanced: the lines' forces against its net lift and their
/// moments about its centre of mass, to 1e-9 of the lift (the static
/// tolerance, 1e-12, on the lines' rows).
#[test]
fn a_buoy_held_by_three_lines_balances_their_catenaries() {
    let statics = solved(moored_buoy());
    let (position, rotation) = statics.body_pose(0).expect("a free body");
    let centre = stancf::body::pose::point(position, &rotation, [0.0, 0.0, -0.3]);
    let lift = (RHO * 2.0 - 500.0) * 9.81;
    let mut force = [0.0, 0.0, lift];
    let mut moment = [0.0; 3];
    let mut worst = 0.0f64;
    for k in 0..3 {
        let [anchor_end, body_end] = statics.end_forces(k);
        let top = statics.point_position(2 * k);
        let anchor = statics.point_position(2 * k + 1);
        let exact = Catenary::between(
            CatenaryLine {
                length: 60.0 + 2.0 * k as f64,
                weight: MASS_PER_LENGTH * 9.81,
                ea: EA,
            },
            anchor,
            top,
            G,
        )
        .expect("catenary");
        for (got, end) in [(anchor_end.force, LineEnd::A), (body_end.force, LineEnd::B)] {
            let want = exact.end_force(end);
            let err = norm(std::array::from_fn(|c| got[c] - want[c])) / norm(want);
            eprintln!("line {k} end {end:?}: {got:?} against {want:?}: {err:.1e}");
            worst = worst.max(err);
        }
        let arm: [f64; 3] = std::array::from_fn(|c| top[c] - centre[c]);
        let m = stancf::vec3::cross(arm, body_end.force);
        for c in 0..3 {
            force[c] += body_end.force[c];
            moment[c] += m[c];
        }
    }
    let angles = stancf::body::pose::moordyn_angles(&rotation);
    eprintln!(
        "buoy at {position:?}, roll pitch yaw {angles:?} deg; unbalanced force {:.1e} N, \
         moment {:.1e} N m (lift {lift:.0} N)",
        norm(force),
        norm(moment)
    );
    assert!(worst < 1e-5, "{worst:e}");
    assert!(
        position[0].abs() > 0.1 && angles[0].abs() + angles[1].abs() > 0.1,
        "the uneven lines move and tilt the buoy"
    );
    assert!(norm(force) < 1e-9 * lift, "{force:?}");
    assert!(norm(moment) < 1e-9 * lift, "{moment:?}");
}

/// A dynamic run from the buoy's equilibrium (the system with the buoy
/// where the static solve left it, the lines in their static shapes,
/// at rest) stays there: over 2 s its centre moves less than 1e-6 m, the
/// equilibrium's residual (1e-12 of the lines' scale) and the time
/// discretization's share of the static shape (the slab's action at rest
/// is the static potential, exactly) being far below that.
#[test]
fn a_moored_buoy_started_at_its_equilibrium_stays_put() {
    let statics = solved(moored_buoy());
    let at_rest = statics.system_at_equilibrium();
    let (position, _) = statics.body_pose(0).unwrap();
    let steps = StepSettings {
        time_step: 0.02,
        time_scheme: TimeScheme::Galerkin,
        ..StepSettings::default()
    };
    let mut sim = SystemSimulation::new(at_rest, statics.line_states(), steps).expect("simulation");
    let start = sim.free_body(0).unwrap().position();
    for k in 0..3 {
        assert!((start[k] - position[k]).abs() < 1e-12);
    }
    let mut moved = 0.0f64;
    for _ in 0..100 {
        sim.step().expect("step");
        let now = sim.free_body(0).unwrap().position();
        moved = moved.max(norm(std::array::from_fn(|c| now[c] - start[c])));
    }
    eprintln!("the buoy moved at most {moved:.1e} m in 2 s");
    assert!(moved < 1e-6, "{moved:e}");
}

fn solved(system: System) -> SystemStatics {
    let seeds = stancf::system::catenary_states(&system);
    let settings = StaticSettings {
        tolerance: 1e-12,
        ..StaticSettings::default()
    };
    let mut statics = SystemStatics::new(system, seeds, settings).expect("statics");
    assert!(statics
        .solve(|_, _| std::ops::ControlFlow::Continue(()))
        .expect("solve"));
    statics
}

/// The lines' force and moment about `reference` on the buoy's three
/// points (points 0, 2, 4).
fn mooring_load(statics: &SystemStatics, reference: [f64; 3]) -> [f64; 6] {
    let mut load = [0.0; 6];
    for k in 0..3 {
        let p = 2 * k;
        let f = statics.point_force(p);
        let arm: [f64; 3] = std::array::from_fn(|c| statics.point_position(p)[c] - reference[c]);
        let m = stancf::vec3::cross(arm, f);
        for c in 0..3 {
            load[c] += f[c];
            load[3 + c] += m[c];
        }
    }
    load
}

/// The buoy's mooring stiffness (B16), from the condensed tangent at its
/// equilibrium, against differences of the lines' static force and
/// moment with the buoy held (a fixed body) at poses h from the
/// equilibrium, along and about global axes through its reference point.
/// Central differences fall to the matrix as h^2 (measured 3.3e-5,
/// 8.3e-6, 2.1e-6, 5.2e-7 of its size at h = 2, 1, 0.5, 0.25 mm or mrad);
/// their Richardson extrapolation from h = 1 and 0.5 removes that term
/// and agrees to 1e-7 of the matrix's size (the static tolerance's force
/// error, ~1e-4 N, over 2 h is 5e-7 of it at h = 0.5 mm, and the
/// extrapolation weighs it by 5/3).
#[test]
fn a_moored_buoys_stiffness_matrix_is_the_derivative_of_its_mooring_load() {
    let mut statics = solved(moored_buoy());
    let (position, rotation) = statics.body_pose(0).expect("free body");
    let k = statics.body_stiffness(0).expect("stiffness");
    let differences = |h: f64| {
        let mut fd = [[0.0; 6]; 6];
        for j in 0..6 {
            let load = |sign: f64| {
                let mut at = position;
                let mut turned = rotation;
                if j < 3 {
                    at[j] += sign * h;
                } else {
                    let mut phi = [0.0; 3];
                    phi[j - 3] = sign * h;
                    turned =
                        stancf::vec3::mat3_mul(&stancf::body::rotation::exp_map(phi), &rotation);
                }
                mooring_load(&solved(buoy_at(BodyKind::Fixed, at, turned)), at)
            };
            let (up, down) = (load(1.0), load(-1.0));
            for i in 0..6 {
                fd[i][j] = -(up[i] - down[i]) / (2.0 * h);
            }
        }
        fd
    };
    let (coarse, fine) = (differences(1e-3), differences(5e-4));
    let size = k.iter().flatten().map(|v| v * v).sum::<f64>().sqrt();
    let mut worst = 0.0f64;
    for i in 0..6 {
        eprintln!("{:?}", k[i].map(|v| (v * 10.0).round() / 10.0));
        for j in 0..6 {
            let extrapolated = (4.0 * fine[i][j] - coarse[i][j]) / 3.0;
            worst = worst.max((k[i][j] - extrapolated).abs());
        }
    }
    eprintln!(
        "stiffness against extrapolated differences: {:.1e} of {size:.3e}",
        worst / size
    );
    assert!(worst < 1e-7 * size, "{:e}", worst / size);
}

/// The mooring stiffness is the lines': the buoy made a coupled body (a
/// host holds it) at the free buoy's equilibrium pose has the same 6 x 6
/// as the free buoy there, which the test above checks against
/// differences; here through the coupled points made free
/// (`SystemStatics::coupled_body_stiffness`): both condense the same
/// Jacobian at the same equilibrium (the coupled one solved anew to
/// 1e-12), so they agree to the solves' round-off (measured 2.6e-12 of
/// the matrix's size; asserted 1e-9).
#[test]
fn a_coupled_buoys_stiffness_is_the_free_buoys_at_the_same_pose() {
    let mut free = solved(moored_buoy());
    let (position, rotation) = free.body_pose(0).expect("free body");
    let want = free.body_stiffness(0).expect("free stiffness");
    let mut coupled = solved(buoy_at(BodyKind::Coupled, position, rotation));
    let got = coupled.body_stiffness(0).expect("coupled stiffness");
    let size = want.iter().flatten().map(|v| v * v).sum::<f64>().sqrt();
    let worst = (0..36)
        .map(|k| (want[k / 6][k % 6] - got[k / 6][k % 6]).abs())
        .fold(0.0, f64::max);
    eprintln!(
        "coupled against free stiffness: {:.1e} of {size:.3e}",
        worst / size
    );

    assert!(worst < 1e-9 * size, "{:e}", worst / size);
    assert!(
        coupled.coupled_point_stiffness(1).is_none(),
        "an anchor is not coupled"
    );
}

/// A coupled point holding one straight line, weightless, stretched to
/// l = 1.01 L0 from an anchor: its stiffness is the elastic string's,
/// K = EA / L0 e e^T + T / l (1 - e e^T) (T = EA (l - L0) / L0 the
/// tension, e along the line), exact for the straight line the elements
/// represent; to round-off (1e-9 of EA / L0).
#[test]
fn a_coupled_points_stiffness_is_a_stretched_strings() {
    let (l0, stretch) = (20.0, 1.01);
    let e = [0.6, 0.0, 0.8];
    let top: [f64; 3] = std::array::from_fn(|c| stretch * l0 * e[c]);
    let points = vec![
        Point::fixed([0.0; 3]),
        Point::coupled(top, stancf::motion::CoupledMotion::NONE),
    ];
    let line = Line {
        model: line_model([0.0; 3], top, l0, Vec::new()),
        ends: [End::Point(0), End::Point(1)],
    };
    let system = System::new(vec![line], points, [0.0; 3]).expect("system");
    let statics = solved(system);
    let k = statics.coupled_point_stiffness(1).expect("stiffness");
    let tension = EA * (stretch - 1.0);
    let mut worst = 0.0f64;
    for i in 0..3 {
        for j in 0..3 {
            let delta = if i == j { 1.0 } else { 0.0 };
            let want = EA / l0 * e[i] * e[j] + tension / (stretch * l0) * (delta - e[i] * e[j]);
            worst = worst.max((k[i][j] - want).abs());
        }
    }
    eprintln!(
        "stretched string's stiffness: {worst:.1e} of {:.3e} N/m",
        EA / l0
    );
    assert!(worst < 1e-9 * EA / l0, "{worst:e}");
    assert!(statics.coupled_point_stiffness(0).is_none());
}

/// A body hanging by two lines from points 1 m either side of its
/// reference point along its y axis, its own centre of mass 1 m below
/// that point and a point of 1/4 of its mass 1 m out along its x axis (a
/// point on the body with a mass: the body's, at the point): at rest the
/// common centre of mass hangs below the axis through the two points, so
/// the body pitches by atan(m / M) = atan(1/4), its +x side down (a
/// positive pitch, MoorDyn's convention), to the static tolerance. The
/// lines (10 m) reach the body's points 10 m below unstretched: from
/// their catenaries, which carry none of the body's weight, the path's
/// first Newton step has no pendulum stiffness to turn the body against;
/// [`SystemStatics::seeded`] starts from the catenary network with the
/// body balanced on it (M32a), and the path is short (docs/method.md
/// §15.8).
#[test]
fn a_bodys_heavy_point_tilts_it_until_their_centre_hangs_below_the_line() {
    let (big, small) = (400.0, 100.0);
    let identity = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
    let body = Body::new(
        BodyKind::Free,
        [0.0, 0.0, -10.0],
        identity,
        RigidInertia::principal(big, [0.0, 0.0, -1.0], [50.0, 50.0, 50.0]),
    );
    let mut heavy = Point::on_body(0, [1.0, 0.0, 0.0]);
    heavy.mass = small;
    let points = vec![
        Point::fixed([0.0, -1.0, 0.0]),
        Point::on_body(0, [0.0, -1.0, 0.0]),
        Point::fixed([0.0, 1.0, 0.0]),
        Point::on_body(0, [0.0, 1.0, 0.0]),
        heavy,
    ];
    let lines = (0..2)
        .map(|k| {
            let y = [-1.0, 1.0][k];
            Line {
                model: chain([0.0, y, 0.0], [0.0, y, -10.0], 10.0),
                ends: [End::Point(2 * k), End::Point(2 * k + 1)],
            }
        })
        .collect();
    let system = System::with_bodies(lines, points, vec![body], G).expect("system");
    let settings = StaticSettings {
        tolerance: 1e-12,
        ..StaticSettings::default()
    };
    let mut statics = SystemStatics::seeded(system.clone(), &system, settings).expect("statics");
    assert!(statics
        .solve(|_, _| std::ops::ControlFlow::Continue(()))
        .expect("solve"));
    let (position, rotation) = statics.body_pose(0).expect("free body");
    let angles = stancf::body::pose::moordyn_angles(&rotation);
    let expected = (small / big).atan().to_degrees();
    eprintln!(
        "pitch {:.9} deg (expected {expected:.9}), at {position:?}",
        angles[1]
    );
    assert!((angles[1] - expected).abs() < 1e-7, "{angles:?}");
    assert!(angles[0].abs() < 1e-9 && angles[2].abs() < 1e-9);
    // The lines hold both masses and their own weight.
    let pull = statics.end_forces(0)[0].force[2] + statics.end_forces(1)[0].force[2];
    let weight = (big + small + 2.0 * MASS_PER_LENGTH * 10.0) * 9.81;
    assert!((-pull - weight).abs() < 1e-6 * weight, "{pull} {weight}");
}

/// In a steady current of 0.5 m/s along x and 0.2 m/s along y the buoy
/// (drag area 2 m^2 on each of its axes, so its drag does not turn with
/// it: D = 1/2 rho CdA |U| U) moves down-current until its lines hold its
/// drag with its net lift: their pull on it is -(D + lift) to 1e-9 of the
/// lift (the static tolerance on the lines' rows).
#[test]
fn a_buoy_in_a_current_is_held_against_its_drag_and_lift() {
    let current = [0.5, 0.2, 0.0];
    let water = BodyWater {
        drag_areas: [2.0; 3],
        current,
        ..BodyWater::default()
    };
    let identity = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
    let still = solved(moored_buoy());
    let statics = solved(buoy_in(BodyKind::Free, [0.0, 0.0, -10.0], identity, water));
    let speed = norm(current);
    let drag = current.map(|u| 0.5 * RHO * 2.0 * speed * u);
    let lift = (RHO * 2.0 - 500.0) * 9.81;
    let mut pull = [0.0; 3];
    for k in 0..3 {
        let f = statics.end_forces(k)[1].force;
        for c in 0..3 {
            pull[c] += f[c];
        }
    }
    let expected = [-drag[0], -drag[1], -lift];
    let err = norm(std::array::from_fn(|c| pull[c] - expected[c]));
    let (moved, _) = statics.body_pose(0).unwrap();
    let (before, _) = still.body_pose(0).unwrap();
    eprintln!(
        "drag {drag:?} N; the lines pull {pull:?} N ({err:.1e} off); the buoy moved by {:?} m",
        std::array::from_fn::<f64, 3, _>(|c| moved[c] - before[c])
    );
    assert!(moved[0] > before[0] && moved[1] > before[1], "down-current");
    assert!(err < 1e-9 * lift, "{err:e}");
}

/// A free body that no line holds (none, or a point of its own with no
/// line at it) has no static equilibrium: the static solve refuses it,
/// naming the body, before any iteration.
#[test]
fn a_free_body_no_line_holds_is_refused_by_the_static_solve() {
    for with_point in [false, true] {
        let identity = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
        let body = Body::new(
            BodyKind::Free,
            [5.0, 0.0, -10.0],
            identity,
            RigidInertia::principal(100.0, [0.0; 3], [10.0; 3]),
        );
        let mut points = vec![
            Point::fixed([0.0, 0.0, -50.0]),
            Point::fixed([40.0, 0.0, -10.0]),
        ];
        if with_point {
            points.push(Point::on_body(0, [0.0, 0.0, 1.0]));
        }
        let line = Line {
            model: chain([0.0, 0.0, -50.0], [40.0, 0.0, -10.0], 60.0),
            ends: [End::Point(0), End::Point(1)],
        };
        let system = System::with_bodies(vec![line], points, vec![body], G).expect("system");
        let refused = SystemStatics::seeded(system.clone(), &system, StaticSettings::default())
            .err()
            .expect("refused");
        assert_eq!(refused.key, "bodies[0]", "{refused}");
        assert!(refused.message.contains("no line holds it"), "{refused}");
    }
}
