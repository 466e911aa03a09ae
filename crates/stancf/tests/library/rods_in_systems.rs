//! Rods (docs/method.md §15.10): rigid cylinders whose mass joins a
//! body's (B17) and whose water acts along them (B18)-(B19), a free rod
//! being a body of its own.

use stancf::body::{BodyWater, Rod};
use stancf::system::{Body, BodyKind, End, Line, Point, System, SystemSimulation};
use stancf::{Cable, ElementType, Material, Model, ModelOptions, StepSettings, TimeScheme};

const RHO: f64 = 1025.0;
const G: f64 = 9.81;

/// Still water of density RHO for a body, `current` through it.
fn water(current: [f64; 3]) -> BodyWater {
    BodyWater {
        density: RHO,
        current,
        ..BodyWater::default()
    }
}

/// MoorDyn's `floatRod` of tests/Mooring/rod_tests/AddedMass.txt: 0.5 m
/// across, 100 kg/m, Ca 1, no drag; `cap` its CaEnd.
fn float_rod(a: [f64; 3], b: [f64; 3], cap: f64) -> Rod {
    Rod {
        end_a: a,
        end_b: b,
        diameter: 0.5,
        mass_per_length: 100.0,
        drag_coefficient: 0.0,
        added_mass_coefficient: 1.0,
        end_drag_coefficient: 0.0,
        end_added_mass_coefficient: cap,
        segments: 4,
    }
}

/// MoorDyn's added-mass test for rods (tests/Mooring/rod_tests/
/// AddedMass.txt: "it takes ~2.3 seconds to get to z = -1"), held by a
/// 2 g line hanging from a point on its axis: released at rest 10 m
/// down, the buoyant rod rises at a = (rho V - m - m_l) g / (m + m_a +
/// m_l), with the added mass m_a = rho V Ca across the rod (lying along
/// y) and 2 rho CaEnd pi d^3/12 along it (standing along z), the line
/// translating with it. The line's stretch as it follows changes its
/// pull by at most its weight, m_l g (0.02 N against a lift of 2 kN):
/// a difference in a of at most m_l (g + a) / (m + m_a), 5e-5 m/s^2,
/// hence 3e-5 m at 1 s. The rise over 1 s is 1.65 m and 1.56 m; without
/// the added mass it would be about three times as far.
#[test]
fn a_free_rod_rises_at_moordyns_added_mass_rate() {
    let cases = [
        ("across", [0.0, -1.0, -10.0], [0.0, 1.0, -10.0], 1.0),
        ("along", [0.0, 0.0, -11.0], [0.0, 0.0, -9.0], 0.8),
    ];
    for (name, a, b, cap) in cases {
        let rod = float_rod(a, b, cap);
        let (length, volume) = (rod.length(), rod.volume());
        let m = 100.0 * length;
        let added = if name == "across" {
            RHO * volume
        } else {
            2.0 * RHO * cap * std::f64::consts::PI * 0.5f64.powi(3) / 12.0
        };
        // The line hangs from the rod's middle across, from its end A
        // along: a point on its axis.
        let local = if name == "across" {
            [0.0, 1.0, 0.0]
        } else {
            [0.0; 3]
        };
        let top: [f64; 3] = std::array::from_fn(|c| a[c] + local[c]);
        let (line, state) = crate::common::hanging_line(top);
        let m_line = 2e-3;
        let mut body = Body::rod(BodyKind::Free, a, rod);
        body.water = Some(water([0.0; 3]));
        let system = System::with_bodies(
            vec![line],
            vec![Point::on_body(0, local)],
            vec![body],
            [0.0, 0.0, -G],
        )
        .expect("system");
        let settings = StepSettings {
            time_step: 0.01,
            time_scheme: TimeScheme::Galerkin,
            ..StepSettings::default()
        };
        let mut sim = SystemSimulation::new(system, vec![state], settings).unwrap();
        let z0 = sim.free_body(0).unwrap().centre()[2];
        for _ in 0..100 {
            sim.step().expect("step");
        }
        let rise = sim.free_body(0).unwrap().centre()[2] - z0;
        let accel = (RHO * volume - m - m_line) * G / (m + added + m_line);
        let want = 0.5 * accel * sim.time() * sim.time();
        eprintln!(
            "{name}: rise {rise:.6} m in {:.2} s, expected {want:.6} m",
            sim.time()
        );
        assert!((rise - want).abs() < 5e-5, "{name}: {rise} against {want}");
    }
}

/// A system of a rod alone, no line and no point (MoorDyn's
/// rod_tests/AddedMass.txt as written): released 10 m down, lying along
/// y, it rises at a = (rho V - m) g / (m + rho V Ca), which the Galerkin
/// step integrates exactly: 1.648 m in 1 s, to 1e-9 m (it once stood
/// still: a system without free points solved its lines apart and left
/// its bodies out; and a system once needed a line).
#[test]
fn a_rod_alone_rises_at_moordyns_added_mass_rate() {
    let (a, b) = ([0.0, -1.0, -10.0], [0.0, 1.0, -10.0]);
    let rod = float_rod(a, b, 1.0);
    let (m, volume) = (100.0 * rod.length(), rod.volume());
    let mut body = Body::rod(BodyKind::Free, a, rod);
    body.water = Some(water([0.0; 3]));
    let system =
        System::with_bodies(Vec::new(), Vec::new(), vec![body], [0.0, 0.0, -G]).expect("system");
    let settings = StepSettings {
        time_step: 0.01,
        time_scheme: TimeScheme::Galerkin,
        ..StepSettings::default()
    };
    let mut sim = SystemSimulation::new(system, Vec::new(), settings).unwrap();
    let z0 = sim.free_body(0).unwrap().centre()[2];
    for _ in 0..100 {
        sim.step().expect("step");
    }
    let rise = sim.free_body(0).unwrap().centre()[2] - z0;
    let want = 0.5 * (RHO * volume - m) * G / (m + RHO * volume) * sim.time().powi(2);
    eprintln!("a rod alone rises {rise:.9} m, closed form {want:.9} m");
    assert!((rise - want).abs() < 1e-9, "{rise} against {want}");
}

/// The same rod's static equilibrium, from 10 m down: it floats lying on
/// the surface with its sections' wet fraction its density's ratio to
/// the water's, phi = w / (rho A) = 0.4969 (Archimedes): its axis at z =
/// -a x with Phi(x) = phi (B22), 1.2 mm above the surface, to 1e-9 m
/// (the static tolerance 1e-10 of the rod's scale). Deep, it has no
/// stiffness in heave: the network starts it at the height where its
/// buoyancy carries it (bisection, `body_holds::floating_height`).
#[test]
fn a_rod_alone_floats_at_its_draft() {
    let (a, b) = ([0.0, -1.0, -10.0], [0.0, 1.0, -10.0]);
    let rod = float_rod(a, b, 1.0);
    let fraction = 100.0 / (RHO * rod.area());
    let mut body = Body::rod(BodyKind::Free, a, rod);
    body.water = Some(water([0.0; 3]));
    let system =
        System::with_bodies(Vec::new(), Vec::new(), vec![body], [0.0, 0.0, -G]).expect("system");
    let statics = crate::common::seeded_equilibrium(system, 1e-10);
    let (reference, rotation) = statics.body_pose(0).expect("a free body");
    // Phi(x) = 1/2 + (x sqrt(1 - x^2) + asin x) / pi rises with x.
    let phi = |x: f64| 0.5 + (x * (1.0 - x * x).sqrt() + x.asin()) / std::f64::consts::PI;
    let (mut low, mut high) = (-1.0, 1.0);
    for _ in 0..200 {
        let mid = 0.5 * (low + high);
        if phi(mid) < fraction {
            low = mid;
        } else {
            high = mid;
        }
    }
    let z = -0.25 * 0.5 * (low + high);
    eprintln!(
        "a rod alone floats with its axis at {:.12} m, Archimedes {z:.12} m",
        reference[2]
    );
    assert!(
        (reference[2] - z).abs() < 1e-9,
        "{} against {z}",
        reference[2]
    );
    assert!((rotation[2][2] - 1.0).abs() < 1e-12 && reference[1] == -1.0);
}

/// A rod of every coefficient, turned, moving and spinning in a current,
/// held at its end B by a line from an anchor and holding a slack line
/// at a point off its axis: the step's Jacobian with the rod's added
/// mass (B18) and drag (B19) is the derivative of its rows, by central
/// differences.
#[test]
fn a_systems_jacobian_with_a_free_rod_is_the_derivative_of_its_rows() {
    let (a, b) = ([0.2, -0.1, -3.0], [1.0, 0.5, -2.4]);
    let rod = Rod {
        end_a: a,
        end_b: b,
        diameter: 0.2,
        mass_per_length: 15.0,
        drag_coefficient: 1.2,
        added_mass_coefficient: 1.0,
        end_drag_coefficient: 0.7,
        end_added_mass_coefficient: 0.6,
        segments: 3,
    };
    let mut body = Body::rod(BodyKind::Free, a, rod);
    body.water = Some(water([0.3, -0.2, 0.05]));
    body.velocity = [0.2, -0.1, 0.3];
    body.angular_velocity = [0.5, 1.0, -0.7];
    let (system, states) =
        crate::common::two_ropes_on_a_body(body, [[0.8, 0.6, 0.6], [0.3, 0.25, 0.1]], -1.0);
    let err = crate::common::galerkin_jacobian_error(system, states, 0.01);
    eprintln!("step Jacobian with a free rod: rel. error {err:.1e}");
    assert!(err < 1e-7, "{err:e}");
}

/// A rod swinging in still water from a line at its end A, out of the
/// line's plane, its drag and added mass across and at its caps on: its
/// energy (the water's added mass in the kinetic) less the work of the
/// water on it is kept to the step's error, falling at fourth order (the
/// rod's drag's work is its power at the slab's time points, the
/// quadrature of its virtual work, as a body's, docs/method.md §15.6):
/// asserted a ratio above 8 from dt 0.02 to 0.01 s and a drift below
/// 1e-4 of the energy the water took.
#[test]
fn a_swinging_rod_in_water_loses_what_its_drag_takes() {
    let run = |dt: f64| {
        let (phi, tilt) = (0.4f64, 0.3f64);
        let top = [0.0, 0.0, -5.0];
        let a = [phi.sin(), 0.0, top[2] - phi.cos()];
        let b = [a[0] + 2.0 * tilt.sin(), 0.3, a[2] - 2.0 * tilt.cos()];
        let rod = Rod {
            end_a: a,
            end_b: b,
            diameter: 0.1,
            mass_per_length: 20.0,
            drag_coefficient: 1.2,
            added_mass_coefficient: 1.0,
            end_drag_coefficient: 0.7,
            end_added_mass_coefficient: 0.6,
            segments: 4,
        };
        let net = (20.0 - RHO * rod.area()) * rod.length() * G;
        let mut body = Body::rod(BodyKind::Free, a, rod);
        body.water = Some(water([0.0; 3]));
        // A line of 0.1 kg/m and EA 1e4 N, stretched to 1 m by about the
        // rod's net weight (positions from the top and slopes scaled), so
        // that it stays taut as the rod swings; the rod bounces on it at
        // about 16 rad/s, which the steps resolve.
        let line = Material {
            youngs_modulus: 1e8,
            density: 1000.0,
            area: 1e-4,
            second_moment: 1e-12,
            axial_damping: 0.0,
        };
        let stretch = 1.0 + net / 1e4;
        let cable = Cable::straight(1.0 / stretch, 4, ElementType::Sac2)
            .with_origin(top)
            .with_direction([phi.sin(), 0.0, -phi.cos()]);
        let model = Model::new(cable, line, ModelOptions::default(), vec![]).expect("model");
        let mut state = model.initial_state();
        for node in 0..model.nodes() {
            for slot in 0..2 {
                let o = model.coordinate(node, slot, 0);
                for c in 0..3 {
                    let from = if slot == 0 { top[c] } else { 0.0 };
                    state.e[o + c] = from + (state.e[o + c] - from) * stretch;
                }
            }
        }
        let system = System::with_bodies(
            vec![Line {
                model,
                ends: [End::Point(0), End::Point(1)],
            }],
            vec![Point::fixed(top), Point::on_body(0, [0.0; 3])],
            vec![body],
            [0.0, 0.0, -G],
        )
        .expect("system");
        crate::common::galerkin_energy_drift(system, vec![state], dt)
    };
    crate::common::assert_energy_balance_falls_at_fourth_order(run, 0.1);
}

/// A buoyant rod (4 m, 0.3 m across, 20 kg/m) held at its end A by three
/// taut lines from anchors around and below it, in a steady current U
/// along x: it leans until its net lift's moment about A balances its
/// drag's. The current across the rod is U cos(alpha), so the drag per
/// length is uniform, 1/2 rho Cd d U^2 cos^2(alpha), across the rod, at
/// its middle, and
///
/// ```text
///   (rho V - m) g sin(alpha) = 1/2 rho Cd d L U^2 cos^2(alpha)
/// ```
///
/// whatever the lines do (they pull at A, where a line's end is pinned).
/// The rod's spin about its own axis has no stiffness; the static solve
/// holds it (docs/method.md §15.10). The solve meets the balance to its
/// tolerance: 1e-8 rad.
#[test]
fn a_tethered_rod_leans_in_a_current_until_its_lift_balances_its_drag() {
    let (l, d, w, cd, u) = (4.0, 0.3, 20.0, 1.2, 0.5);
    let a = [0.0, 0.0, -18.0];
    let rod = Rod {
        end_a: a,
        end_b: [0.0, 0.0, -18.0 + l],
        diameter: d,
        mass_per_length: w,
        drag_coefficient: cd,
        added_mass_coefficient: 1.0,
        end_drag_coefficient: 0.0,
        end_added_mass_coefficient: 0.5,
        segments: 4,
    };
    let lift = (RHO * rod.volume() - w * l) * G;
    let mut body = Body::rod(BodyKind::Free, a, rod);
    body.water = Some(water([u, 0.0, 0.0]));
    // Three lines of EA 1e7 N from anchors 2 m out and 2 m down.
    let material = Material {
        youngs_modulus: 1e11,
        density: 1000.0,
        area: 1e-4,
        second_moment: 1e-10,
        axial_damping: 0.0,
    };
    let mut lines = Vec::new();
    let mut points = vec![Point::on_body(0, [0.0; 3])];
    for k in 0..3 {
        let angle = 2.0 * std::f64::consts::PI * k as f64 / 3.0;
        let anchor = [2.0 * angle.cos(), 2.0 * angle.sin(), a[2] - 2.0];
        let length = stancf::vec3::norm(stancf::vec3::sub(a, anchor));
        let model = crate::common::straight_line(anchor, a, length, 8, material);
        points.push(Point::fixed(anchor));
        lines.push(Line {
            model,
            ends: [End::Point(k + 1), End::Point(0)],
        });
    }
    let system = System::with_bodies(lines, points, vec![body], [0.0, 0.0, -G]).expect("system");
    let statics = crate::common::seeded_equilibrium(system, 1e-10);
    let (_, rotation) = statics.body_pose(0).expect("a free body");
    // The rod's axis: body z (its body axes are the global ones at t = 0).
    let axis = [rotation[0][2], rotation[1][2], rotation[2][2]];
    let alpha = axis[0].atan2(axis[2]);
    let drag = 0.5 * RHO * cd * d * l * u * u;
    let want = crate::common::lean_in_a_current(lift, drag);
    eprintln!(
        "lean {alpha:.10} rad, balance {want:.10} rad; sideways {:.1e}",
        axis[1]
    );
    assert!((alpha - want).abs() < 1e-8, "{alpha} against {want}");
    assert!(axis[1].abs() < 1e-10);
}
