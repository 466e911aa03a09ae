//! Bodies pinned to a point a host or a motion moves (docs/method.md
//! §15.17, (B34)): MoorDyn's CoupledPinned body, a rod pinned to a
//! coupled body.

use crate::common::rods::rod;
use stancf::motion::{CoupledMotion, MotionInterval};
use stancf::system::{Body, BodyKind, Pin, Point, System, SystemSimulation};
use stancf::vec3::sub;
use stancf::{StepSettings, TimeScheme};

const G: f64 = 9.81;

/// A rod 2 m long pinned at its end A to point 0, 30 degrees from the
/// vertical, with no line: under gravity `g` (along -z), its pin moving as
/// `motion` from `top` and the rod starting with its velocity there.
fn pendulum(top: [f64; 3], motion: CoupledMotion, velocity: [f64; 3], g: f64) -> SystemSimulation {
    let (s, c) = (30f64.to_radians().sin(), 30f64.to_radians().cos());
    let mut body = Body::rod(BodyKind::Free, top, rod(top, [s, 0.0, -c], 2.0, 0.0, 0.0));
    body.velocity = velocity;
    body.pin = Some(Pin {
        local: [0.0; 3],
        point: 0,
    });
    let points = vec![Point::coupled(top, motion)];
    let system =
        System::with_bodies(Vec::new(), points, vec![body], [0.0, 0.0, -g]).expect("system");
    let settings = StepSettings {
        time_step: 0.01,
        time_scheme: TimeScheme::Galerkin,
        ..StepSettings::default()
    };
    SystemSimulation::new(system, Vec::new(), settings).expect("simulation")
}

/// A pendulum whose pin moves at a constant velocity V and accelerates
/// upward at a swings about it as a pendulum on a fixed pin under
/// gravity g + a (Galileo and Einstein): the pin's path V t + a t^2 / 2
/// (the host's cubic (K2) over one interval holds it exactly), the
/// rod's end B from its pin the same in both runs over 2 s, and the
/// pinned end on the moving pin: measured 7e-15 m and 8e-15 m (the two
/// runs do the same arithmetic but for the pin's path, added and taken
/// away: round-off), asserted to 1e-12 m.
#[test]
fn a_pendulum_on_an_accelerating_pin_swings_as_under_more_gravity() {
    let (top, v, a, span) = ([0.0, 0.0, 0.0], [0.7, -0.2, 0.0], 3.0, 2.0);
    let at = |t: f64| [v[0] * t, v[1] * t, 0.5 * a * t * t];
    let rate = |t: f64| [v[0], v[1], a * t];
    let moving = CoupledMotion::Interval(MotionInterval {
        t0: 0.0,
        duration: span,
        start: at(0.0),
        end: at(span),
        rates: Some((rate(0.0), rate(span))),
    });
    let mut driven = pendulum(top, moving, v, G);
    let mut still = pendulum(top, CoupledMotion::NONE, [0.0; 3], G + a);
    let end_b = [
        2.0 * 30f64.to_radians().sin(),
        0.0,
        -2.0 * 30f64.to_radians().cos(),
    ];
    let (mut worst, mut slip) = (0.0f64, 0.0f64);
    while driven.time() < span - 1e-9 {
        driven.step().expect("driven step");
        still.step().expect("still step");
        let pin = at(driven.time());
        let (d, s) = (driven.free_body(0).unwrap(), still.free_body(0).unwrap());
        let relative = sub(d.point(end_b), pin);
        let reference = s.point(end_b);
        for c in 0..3 {
            worst = worst.max((relative[c] - reference[c]).abs());
            slip = slip.max((d.point([0.0; 3])[c] - pin[c]).abs());
        }
    }
    eprintln!(
        "pendulum on an accelerating pin: off the heavier one by {worst:.1e} m, slip {slip:.1e} m"
    );
    assert!(worst < 1e-12, "{worst:e}");
    assert!(slip < 1e-12, "{slip:e}");
}
