//! Bodies pinned to a point a host or a motion moves (docs/method.md
//! §15.17, (B34)): MoorDyn's CoupledPinned body, a rod pinned to a
//! coupled body.

use crate::common::rods::rod;
use stancf::motion::{CoupledMotion, MotionInterval};
use stancf::system::{Body, BodyKind, Pin, Point, System, SystemSimulation};
use stancf::vec3::sub;
use stancf::{StepSettings, TimeScheme};

const G: f64 = 9.81;

/// A rod 2 m long (20 kg) pinned at its end A to point 0, `degrees` from
/// the vertical, with no line: under gravity `g` (along -z), its pin
/// moving as `motion` from `top` and the rod starting with its velocity
/// there.
fn pendulum(
    top: [f64; 3],
    motion: CoupledMotion,
    velocity: [f64; 3],
    g: f64,
    degrees: f64,
) -> SystemSimulation {
    let system = pendulum_system(top, motion, velocity, g, degrees);
    let settings = StepSettings {
        time_step: 0.01,
        time_scheme: TimeScheme::Galerkin,
        ..StepSettings::default()
    };
    SystemSimulation::new(system, Vec::new(), settings).expect("simulation")
}

/// The system of [`pendulum`].
fn pendulum_system(
    top: [f64; 3],
    motion: CoupledMotion,
    velocity: [f64; 3],
    g: f64,
    degrees: f64,
) -> System {
    let (s, c) = (degrees.to_radians().sin(), degrees.to_radians().cos());
    let mut body = Body::rod(BodyKind::Free, top, rod(top, [s, 0.0, -c], 2.0, 0.0, 0.0));
    body.velocity = velocity;
    body.pin = Some(Pin {
        local: [0.0; 3],
        point: 0,
    });
    let points = vec![Point::coupled(top, motion)];
    System::with_bodies(Vec::new(), points, vec![body], [0.0, 0.0, -g]).expect("system")
}

/// A pin's path V t + a t^2 / 2 upward over `span` from the origin, as a
/// host's cubic (K2) over one interval holds it exactly.
fn accelerating(v: [f64; 3], a: f64, span: f64) -> CoupledMotion {
    let at = |t: f64| [v[0] * t, v[1] * t, 0.5 * a * t * t];
    let rate = |t: f64| [v[0], v[1], a * t];
    CoupledMotion::Interval(MotionInterval {
        t0: 0.0,
        duration: span,
        start: at(0.0),
        end: at(span),
        rates: Some((rate(0.0), rate(span))),
    })
}

/// A pendulum whose pin moves at a constant velocity V and accelerates
/// upward at a swings about it as a pendulum on a fixed pin under
/// gravity g + a (Galileo and Einstein): the pin's path V t + a t^2 / 2
/// (the host's cubic (K2) over one interval holds it exactly), the
/// rod's end B from its pin the same in both runs over 2 s, and the
/// pinned end on the moving pin: measured 7e-15 m and 8e-15 m (the two
/// runs do the same arithmetic but for the pin's path, added and taken
/// away: round-off), asserted to 1e-12 m; and the pin pulls the rod the
/// same in both (B35), to 1e-9 of its weight.
#[test]
fn a_pendulum_on_an_accelerating_pin_swings_as_under_more_gravity() {
    let (top, v, a, span) = ([0.0, 0.0, 0.0], [0.7, -0.2, 0.0], 3.0, 2.0);
    let at = |t: f64| [v[0] * t, v[1] * t, 0.5 * a * t * t];
    let moving = accelerating(v, a, span);
    let mut driven = pendulum(top, moving, v, G, 30.0);
    let mut still = pendulum(top, CoupledMotion::NONE, [0.0; 3], G + a, 30.0);
    let end_b = [
        2.0 * 30f64.to_radians().sin(),
        0.0,
        -2.0 * 30f64.to_radians().cos(),
    ];
    let (mut worst, mut slip, mut pull) = (0.0f64, 0.0f64, 0.0f64);
    while driven.time() < span - 1e-9 {
        driven.step().expect("driven step");
        still.step().expect("still step");
        let pin = at(driven.time());
        let (d, s) = (driven.free_body(0).unwrap(), still.free_body(0).unwrap());
        let relative = sub(d.point(end_b), pin);
        let reference = s.point(end_b);
        let (fd, fs) = (driven.pin_force(0).unwrap(), still.pin_force(0).unwrap());
        for c in 0..3 {
            worst = worst.max((relative[c] - reference[c]).abs());
            slip = slip.max((d.point([0.0; 3])[c] - pin[c]).abs());
            pull = pull.max((fd[c] - fs[c]).abs());
        }
    }
    eprintln!("the pins' forces differ by {pull:.1e} N of the rod's weight 196 N");
    assert!(pull < 1e-9 * 20.0 * G, "{pull:e}");
    eprintln!(
        "pendulum on an accelerating pin: off the heavier one by {worst:.1e} m, slip {slip:.1e} m"
    );
    assert!(worst < 1e-12, "{worst:e}");
    assert!(slip < 1e-12, "{slip:e}");
}

/// A rod hanging straight down from a pin that accelerates upward at a
/// stays hanging, and the pin holds it with m (g + a) (B35): the mean
/// force of every step to 1e-9 of it (the step's momentum change less
/// the weight's impulse, each exact for a constant acceleration).
#[test]
fn a_rod_hanging_from_an_accelerating_pin_is_pulled_by_its_weight_and_more() {
    let (a, span) = (3.0, 1.0);
    let moving = CoupledMotion::Interval(MotionInterval {
        t0: 0.0,
        duration: span,
        start: [0.0; 3],
        end: [0.0, 0.0, 0.5 * a * span * span],
        rates: Some(([0.0; 3], [0.0, 0.0, a * span])),
    });
    let mut sim = pendulum([0.0; 3], moving, [0.0; 3], G, 0.0);
    let want = 20.0 * (G + a);
    let mut worst = 0.0f64;
    while sim.time() < span - 1e-9 {
        sim.step().expect("step");
        let f = sim.pin_force(0).unwrap();
        worst = worst
            .max(f[0].abs())
            .max(f[1].abs())
            .max((f[2] - want).abs());
    }
    eprintln!("the pin holds the rod with {want} N to {worst:.1e} N");
    assert!(worst < 1e-9 * want, "{worst:e}");
}

/// The static solve of a rod on a pin (B35 at rest): it hangs straight
/// down from where it was 30 degrees off, and the pin holds its weight
/// m g, which the pin's point carries as its pull (the point's force
/// -m g, as points.csv writes it), to 1e-9 of the weight (the static
/// tolerance 1e-10).
#[test]
fn a_rod_at_rest_on_a_pin_is_held_by_its_weight() {
    let system = pendulum_system([0.0, 0.0, 1.0], CoupledMotion::NONE, [0.0; 3], G, 30.0);
    let statics = crate::common::seeded_equilibrium(system, 1e-10);
    let weight = 20.0 * G;
    let held = statics.pin_force(0).expect("a pinned body");
    let pulled = statics.point_force(0);
    eprintln!("a rod on a pin: held by {held:?}, its point pulled by {pulled:?}");
    for (f, want) in [(held, weight), (pulled, -weight)] {
        assert!(
            f[0].abs() < 1e-9 * weight && f[1].abs() < 1e-9 * weight,
            "{f:?}"
        );
        assert!((f[2] - want).abs() < 1e-9 * weight, "{f:?}");
    }
}

/// The pin of the accelerating pendulum does work on it, its mean force
/// times its displacement step by step (docs/method.md §15.17), and the
/// system's balance E - W holds with it: the drift over 2 s falls with
/// the step at second order at least (the mean force over a step times
/// the step's displacement is a second-order quadrature of the power)
/// and stays far below the pin's work.
#[test]
fn a_pin_moved_by_its_host_does_the_work_the_energy_balance_needs() {
    let (v, a, span) = ([0.7, -0.2, 0.0], 3.0, 2.0);
    let drift = |dt: f64| {
        let system = pendulum_system([0.0; 3], accelerating(v, a, span), v, G, 30.0);
        let settings = StepSettings {
            time_step: dt,
            time_scheme: TimeScheme::Galerkin,
            ..StepSettings::default()
        };
        let mut sim = SystemSimulation::new(system, Vec::new(), settings).expect("simulation");
        let e0 = sim.energies().mechanical();
        let mut worst = 0.0f64;
        while sim.time() < span - 1e-9 {
            sim.step().expect("step");
            worst = worst.max((sim.energies().mechanical() - sim.external_work() - e0).abs());
        }
        (worst, sim.external_work())
    };
    let (coarse, work) = drift(0.01);
    let (fine, _) = drift(0.005);
    eprintln!(
        "pin's work {work:.4e} J; balance drift {coarse:.2e} J at 10 ms, {fine:.2e} J at 5 ms \
         (ratio {:.2})",
        coarse / fine
    );
    assert!(work.abs() > 100.0, "the pin lifts the rod: {work}");
    assert!(coarse > 3.5 * fine, "{coarse:e} {fine:e}");
    assert!(fine < 1e-4 * work.abs(), "{fine:e} {work:e}");
}
