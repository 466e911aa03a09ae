//! Rods crossing the water surface (docs/method.md §15.11): the buoyancy
//! of the part under z = 0 as a potential of the pose (B20)-(B21), with
//! its waterplane's stiffness, and the added mass and drag of the wet
//! part, checked against a floating spar's closed forms.

use crate::common::{assert_energy_balance_falls_at_fourth_order, galerkin_energy_drift};
use stancf::body::{BodyWater, RigidInertia, Rod};
use stancf::system::{Body, BodyKind, End, Line, Point, System, SystemSimulation, SystemStatics};
use stancf::vec3::{add, cross, norm, scale, sub};
use stancf::{Material, StaticSettings, StepSettings, TimeScheme};

const RHO: f64 = 1025.0;
const G: f64 = 9.81;
const IDENTITY: [[f64; 3]; 3] = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];

/// A spar: a rod 20 m long and 2 m across (500 kg/m, Ca 1, CaEnd 1, Cd
/// `cd`) standing on its end A, the body's reference point, with 40 t of
/// ballast 1 m above it: 50 t in all, floating upright at a draft of
/// 15.53 m, its centre of mass 4.98 m under its centre of buoyancy
/// (stable: GM = I_wp / V + z_B - z_G = 4.99 m); every length times
/// `size` (and every mass times its cube).
fn spar(bottom: [f64; 3], cd: f64, size: f64) -> Body {
    let ballast = RigidInertia::principal(40_000.0 * size.powi(3), [0.0, 0.0, size], [0.0; 3]);
    let mut body = Body::new(BodyKind::Free, bottom, IDENTITY, ballast);
    body.rods.push(Rod {
        end_a: [0.0; 3],
        end_b: [0.0, 0.0, 20.0 * size],
        diameter: 2.0 * size,
        mass_per_length: 500.0 * size * size,
        drag_coefficient: cd,
        added_mass_coefficient: 1.0,
        end_drag_coefficient: 0.0,
        end_added_mass_coefficient: 1.0,
        segments: 6,
    });
    body.water = Some(BodyWater {
        density: RHO,
        ..BodyWater::default()
    });
    body
}

const SPAR_MASS: f64 = 50_000.0;
const SPAR_AREA: f64 = std::f64::consts::PI;

/// The spar with a light line hanging from its bottom.
fn spar_system(body: Body) -> (System, Vec<stancf::State>) {
    let (line, state) = crate::common::hanging_line(body.position);
    let system = System::with_bodies(
        vec![line],
        vec![Point::on_body(0, [0.0; 3])],
        vec![body],
        [0.0, 0.0, -G],
    )
    .expect("system");
    let mut states = vec![state];
    system.start_lines_with_bodies(&mut states);
    (system, states)
}

/// A spar released 1 m above its floating draft heaves as the linear
/// oscillator z(t) = z_eq + Z cos(omega t): its waterplane's stiffness
/// rho g A (B21) against its mass, the bottom cap's added mass rho CaEnd
/// pi d^3 / 12 and the line's 2 g (which, hanging, moves with it); the
/// wet length changes, the side's added mass does not act in heave. The
/// line's own stretch changes its pull by at most its weight (2e-2 N
/// against a stiffness of 32 kN/m): under 1e-6 m. The step's error at
/// omega dt = 0.04 is far below; the bound 1e-5 m (of an amplitude of 1
/// m) is the line's, tenfold.
#[test]
fn a_spar_heaves_at_its_waterplanes_closed_form_frequency() {
    let m_line = 2e-3;
    let draft = (SPAR_MASS + m_line) / (RHO * SPAR_AREA);
    let lift = 1.0;
    let (system, states) = spar_system(spar([0.0, 0.0, -draft + lift], 0.0, 1.0));
    let settings = StepSettings {
        time_step: 0.05,
        time_scheme: TimeScheme::Galerkin,
        ..StepSettings::default()
    };
    let mut sim = SystemSimulation::new(system, states, settings).expect("simulation");
    let added = RHO * std::f64::consts::PI * 8.0 / 12.0;
    let omega = (RHO * G * SPAR_AREA / (SPAR_MASS + added + m_line)).sqrt();
    let z_eq = -draft + 1.0 * 40_000.0 / SPAR_MASS + 10.0 * 10_000.0 / SPAR_MASS;
    let mut worst = 0.0f64;
    // Two periods (8.1 s each).
    while sim.time() < 16.2 {
        sim.step().expect("step");
        let z = sim.free_body(0).unwrap().centre()[2];
        let want = z_eq + lift * (omega * sim.time()).cos();
        worst = worst.max((z - want).abs());
    }
    eprintln!(
        "heave against the closed form (period {:.4} s): {worst:.1e} m",
        2.0 * std::f64::consts::PI / omega
    );
    assert!(worst < 1e-5, "{worst:e}");
}

/// A spar tilted 0.005 rad about its centre of mass and released pitches
/// at the closed-form period of a free floating body, its surge free: the
/// linear equations (M + A) [x; theta]'' + diag(0, C) [x; theta] = 0 about
/// the centre of mass G give omega^2 = C / (I_G + A_55 - A_15^2 / (m +
/// A_11)), with the hydrostatic C = rho g V GM (GM = I_wp / V + z_B -
/// z_G, the naval architect's), I_G the ballast's and the hull's (a solid
/// cylinder: m (d^2/16 + L^2/12) about its middle), and the wet side's
/// added mass a = rho Ca pi d^2 / 4 per length: A_11 = a D, A_15 = a int
/// (z - z_G) dz, A_55 = a int (z - z_G)^2 dz over the draft D (the caps'
/// added mass acts along the axis, not in surge or pitch). The period
/// from three zero crossings to 1e-4 of it: the amplitude's shift is of
/// order theta0^2 = 2.5e-5, the hanging line's 2 g below 1e-6, the step
/// (T/50, Galerkin of order 6) far below.
#[test]
fn a_spar_pitches_at_its_metacentric_closed_form_period() {
    let m_line = 2e-3;
    let m = SPAR_MASS;
    let draft = (m + m_line) / (RHO * SPAR_AREA);
    let z_g = (40_000.0 * 1.0 + 10_000.0 * 10.0) / m;
    let i_g = 40_000.0 * (1.0 - z_g).powi(2)
        + 10_000.0 * (4.0 / 16.0 + 400.0 / 12.0)
        + 10_000.0 * (10.0 - z_g).powi(2);
    let volume = m / RHO;
    let metacentre = (std::f64::consts::PI / 4.0) / volume + draft / 2.0 - z_g;
    let c55 = RHO * G * volume * metacentre;
    let a = RHO * SPAR_AREA;
    let a11 = a * draft;
    let a15 = a * ((draft - z_g).powi(2) - z_g * z_g) / 2.0;
    let a55 = a * ((draft - z_g).powi(3) + z_g.powi(3)) / 3.0;
    let omega = (c55 / (i_g + a55 - a15 * a15 / (m + a11))).sqrt();
    let want = 2.0 * std::f64::consts::PI / omega;
    let theta0 = 0.005f64;
    let (s, c) = theta0.sin_cos();
    let rotation = [[c, 0.0, s], [0.0, 1.0, 0.0], [-s, 0.0, c]];
    let centre = [0.0, 0.0, -draft + z_g];
    let bottom = sub(
        centre,
        stancf::body::pose::rotate(&rotation, [0.0, 0.0, z_g]),
    );
    let mut body = spar(bottom, 0.0, 1.0);
    body.rotation = rotation;
    let (system, states) = spar_system(body);
    let dt = want / 50.0;
    let settings = StepSettings {
        time_step: dt,
        time_scheme: TimeScheme::Galerkin,
        ..StepSettings::default()
    };
    let mut sim = SystemSimulation::new(system, states, settings).expect("simulation");
    let pitch = |sim: &SystemSimulation| {
        let body = sim.free_body(0).unwrap();
        let axis = sub(body.point([0.0, 0.0, 20.0]), body.point([0.0; 3]));
        axis[0].atan2(axis[2])
    };
    let period = crate::common::period_from_crossings(&mut sim, dt, pitch, |_| {});
    eprintln!(
        "spar pitch: period {period:.6} s against {want:.6} s ({:.1e}); GM {metacentre:.4} m",
        (period - want).abs() / want
    );
    assert!((period - want).abs() < 1e-4 * want, "{period} {want}");
}

/// A spar a twentieth of the size (1 m long, heaving at 1.8 s) heaving,
/// pitching and drifting in still water with a drag across its wet
/// part: its energy less the drag's work is kept to the step's error at
/// fourth order, its wet length, its waterplane moment and the added
/// mass of its wet side all moving with its pose (the Lagrangian of (B5)
/// with the potential -rho g I of (B20) and the added mass over the wet
/// length h = V_w / A).
#[test]
fn a_rocking_spar_keeps_its_energy_less_the_drags_work() {
    let size = 0.05;
    let draft = SPAR_MASS * size / (RHO * SPAR_AREA);
    assert_energy_balance_falls_at_fourth_order(
        |dt| {
            let mut body = spar([0.0, 0.0, -draft + 0.05], 0.8, size);
            body.velocity = [0.1, -0.05, 0.2];
            body.angular_velocity = [0.6, 0.4, 0.2];
            let (system, states) = spar_system(body);
            galerkin_energy_drift(system, states, dt)
        },
        1e-3,
    );
}

/// A spar moored by two catenaries from opposite sides, one at its
/// bottom and one 8 m up, in static equilibrium (their pulls' couple
/// heels it): the buoyancy rho g V_w of its tilted wet part (no cap cut:
/// V_w = A h_c, h_c the axis's wet length) carries its weight and the
/// lines' pull, and the buoyancy acting at the wet part's centroid
/// balances the lines' moment about the centre of mass; the centroid of
/// a cylinder cut obliquely at tilt alpha lies h_c / 2 + a^2
/// tan^2(alpha) / (8 h_c) up the axis and a^2 tan(alpha) / (4 h_c)
/// across it towards the deeper side (the classical geometry, not the
/// potential's formula). Both to 1e-8 of the buoyancy (and its radius),
/// above the static solve's tolerance of 1e-10.
#[test]
fn a_moored_spar_floats_where_archimedes_puts_it() {
    let draft = SPAR_MASS / (RHO * SPAR_AREA);
    let bottom = [0.0, 0.0, -draft];
    let material = Material {
        youngs_modulus: 2e11,
        density: 7850.0,
        area: 3e-3,
        second_moment: 1e-9,
        axial_damping: 0.0,
    };
    let fairleads = [[0.0, 0.0, 0.0], [0.0, 0.0, 8.0]];
    let anchors = [[150.0, 0.0, -80.0], [-150.0, 10.0, -80.0]];
    let mut lines = Vec::new();
    let mut points = Vec::new();
    for k in 0..2 {
        let end = add(bottom, fairleads[k]);
        let length = 1.02 * norm(sub(end, anchors[k]));
        let model = crate::common::straight_line(anchors[k], end, length, 20, material);
        points.push(Point::on_body(0, fairleads[k]));
        points.push(Point::fixed(anchors[k]));
        lines.push(Line {
            model,
            ends: [End::Point(2 * k + 1), End::Point(2 * k)],
        });
    }
    let system = System::with_bodies(lines, points, vec![spar(bottom, 0.0, 1.0)], [0.0, 0.0, -G])
        .expect("system");
    let statics = crate::common::seeded_equilibrium(system, 1e-10);
    let (reference, rotation) = statics.body_pose(0).expect("a free body");
    let q = [rotation[0][2], rotation[1][2], rotation[2][2]];
    let (c, s) = (q[2], (1.0 - q[2] * q[2]).sqrt());
    assert!(s > 1e-3, "the lines heel the spar: {s}");
    let wet = -reference[2] / c;
    let a = 1.0;
    let volume = SPAR_AREA * wet;
    let tan = s / c;
    let up = scale(1.0 / s, sub([0.0, 0.0, 1.0], scale(c, q)));
    let centroid = add(
        reference,
        add(
            scale(wet / 2.0 + a * a * tan * tan / (8.0 * wet), q),
            scale(-a * a * tan / (4.0 * wet), up),
        ),
    );
    let centre = stancf::body::pose::point(reference, &rotation, [0.0, 0.0, 2.8]);
    let buoyancy = [0.0, 0.0, RHO * G * volume];
    let weight = [0.0, 0.0, -SPAR_MASS * G];
    let mut force = add(buoyancy, weight);
    let mut moment = cross(sub(centroid, centre), buoyancy);
    for (k, local) in fairleads.iter().enumerate() {
        let pull = statics.point_force(2 * k);
        let at = stancf::body::pose::point(reference, &rotation, *local);
        force = add(force, pull);
        moment = add(moment, cross(sub(at, centre), pull));
    }
    let scale_f = RHO * G * volume;
    eprintln!(
        "tilt {:.6} rad, wet length {wet:.6} m; force {:.1e} N, moment {:.1e} N m of {scale_f:.3e} N",
        s.atan2(c),
        norm(force),
        norm(moment)
    );
    assert!(norm(force) < 1e-8 * scale_f, "{force:?}");
    assert!(norm(moment) < 1e-8 * scale_f * a, "{moment:?}");
}

/// The spar on no line (beside a line between two anchors, which a
/// system needs) has a static equilibrium of its own: started 2 m high
/// and heeled by 0.1 rad, the static solve stands it upright at the
/// draft where its buoyancy carries its weight, m = rho A h, its centre
/// over where it was (still water's loads do not move it sideways or turn
/// it about the vertical: the solve holds those, docs/method.md §15.11),
/// to the static tolerance.
#[test]
fn a_spar_on_no_line_floats_upright_at_its_draft() {
    let draft = SPAR_MASS / (RHO * SPAR_AREA);
    let heel = stancf::body::rotation::exp_map([0.1, 0.0, 0.0]);
    let mut body = spar([0.0, 0.0, -draft + 2.0], 0.0, 1.0);
    body.rotation = heel;
    let start = body.point([0.0, 0.0, 2.8]);
    let (system, _) = crate::common::body_on_no_line(body, [30.0, 0.0, -1.0]);
    let statics = crate::common::seeded_equilibrium(system, 1e-10);
    let (reference, rotation) = statics.body_pose(0).expect("a free body");
    let centre = stancf::body::pose::point(reference, &rotation, [0.0, 0.0, 2.8]);
    let tilt = (rotation[0][2].powi(2) + rotation[1][2].powi(2)).sqrt();
    eprintln!(
        "floating spar: bottom at {:.9} m (draft {draft:.9}), tilt {tilt:.1e}, centre moved {:.1e} m",
        reference[2],
        ((centre[0] - start[0]).powi(2) + (centre[1] - start[1]).powi(2)).sqrt()
    );
    assert!(
        (reference[2] + draft).abs() < 1e-9 * draft,
        "{}",
        reference[2]
    );
    assert!(tilt < 1e-9, "{tilt:e}");
    assert!((centre[0] - start[0]).abs() < 1e-9 && (centre[1] - start[1]).abs() < 1e-9);
}

/// A spar on no line that its rods' whole buoyancy cannot carry (ballast
/// doubled: 90 t against 64 t of displacement) sinks: the static solve
/// refuses it, naming the body and both forces (it has no equilibrium; a
/// body has no seabed contact).
#[test]
fn a_spar_on_no_line_too_heavy_to_float_is_refused_by_the_static_solve() {
    let mut body = spar([0.0, 0.0, -15.0], 0.0, 1.0);
    body.inertia = body.inertia.with_point_mass(40_000.0, [0.0, 0.0, 1.0]);
    let (system, _) = crate::common::body_on_no_line(body, [30.0, 0.0, -1.0]);
    let err = SystemStatics::seeded(system.clone(), &system, StaticSettings::default())
        .err()
        .expect("refused");
    assert_eq!(err.key, "bodies[0]");
    assert!(err.message.contains("sinks"), "{}", err.message);
}

/// The spar on no line started 1 m above the water and heeled by 2.5
/// rad, nearly upside down: the load path from there ends on the spar
/// floating upside down (its ballast 4.5 m above the water, an
/// equilibrium: its buoyancy on the line of its weight), where its pitch
/// stiffness is rho g V GM < 0. The solve finds the condensed Hessian's
/// negative eigenvalue, moves the spar along its eigenvector and follows
/// the flow (docs/method.md §6.9, (M26b), (M26c)) to the stable
/// equilibrium: upright at Archimedes' draft m = rho A h, to the static
/// tolerance.
#[test]
fn a_spar_started_upside_down_floats_upright_at_its_draft() {
    let draft = SPAR_MASS / (RHO * SPAR_AREA);
    let mut body = spar([0.0, 0.0, 1.0], 0.0, 1.0);
    body.rotation = stancf::body::rotation::exp_map([2.5, 0.0, 0.0]);
    let (system, _) = crate::common::body_on_no_line(body, [30.0, 0.0, -1.0]);
    let mut statics = crate::common::seeded_equilibrium(system, 1e-10);
    let (reference, rotation) = statics.body_pose(0).expect("a free body");
    let tilt = (rotation[0][2].powi(2) + rotation[1][2].powi(2)).sqrt();
    eprintln!(
        "spar started upside down: bottom at {:.9} m (draft {draft:.9}), axis z {:.3}, tilt \
         {tilt:.1e}, left by the flow: {}",
        reference[2],
        rotation[2][2],
        statics.relaxed()
    );
    assert!(statics.relaxed());
    assert!(rotation[2][2] > 0.0, "upside down: {rotation:?}");
    assert!(tilt < 1e-9, "{tilt:e}");
    assert!(
        (reference[2] + draft).abs() < 1e-9 * draft,
        "{}",
        reference[2]
    );
    assert!(statics.body_downhill(0).is_none());
}
