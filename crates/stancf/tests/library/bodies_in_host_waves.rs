//! Bodies and rods in a sea whose waves a host sets (MoorDyn's
//! `WaveKin 1`, docs/method.md §12.1, (W2h)): the host's flow at a body's
//! reference point and at its rods' nodes against the sea's own current,
//! and a body as dense as the water following the host's acceleration.

use crate::common::lumped_bodies::{neutral_lumped_body, G, RHO};
use stancf::body::{BodyHostFlow, FreeBody, Rod};
use stancf::water::current::{CurrentProfile, Ramp};
use stancf::water::host_flow::NodeFlow;
use stancf::water::kinematics::Sea;
use stancf::TimeScheme;

/// A body of MoorDyn's lumped water as dense as the water
/// ([`neutral_lumped_body`], its drag areas times `drag`) with a rod fixed
/// in it across x (1 m, 0.2 m across, Cd 1.2 and CdEnd 0.6 times `drag`,
/// as dense as the water), 10 m down in `sea`, stepped by `scheme` at
/// 0.1 s.
fn neutral_body(sea: Sea, scheme: TimeScheme, drag: f64) -> FreeBody {
    let rod = Rod {
        end_a: [-0.5, 0.0, 0.0],
        end_b: [0.5, 0.0, 0.0],
        diameter: 0.2,
        mass_per_length: RHO * std::f64::consts::PI * 0.01,
        drag_coefficient: 1.2 * drag,
        added_mass_coefficient: 1.0,
        end_drag_coefficient: 0.6 * drag,
        end_added_mass_coefficient: 0.5,
        segments: 4,
    };
    neutral_lumped_body(sea, vec![rod], drag, scheme, 0.1)
}

fn host_sea() -> Sea {
    Sea::still(200.0, G).with_host_waves().unwrap()
}

/// The host's uniform flow: (u, a) at the reference point and at the
/// rod's five nodes.
fn uniform(u: [f64; 3], a: [f64; 3]) -> BodyHostFlow {
    BodyHostFlow {
        reference: (u, a),
        rods: vec![NodeFlow {
            velocity: vec![u; 5],
            acceleration: vec![a; 5],
        }],
    }
}

/// A host that sets the same uniform velocity U at the body and at its
/// rod's nodes drags them as the sea's own uniform current U does, to
/// the bit, in both schemes: (W2h) adds U to still water where the
/// current puts U, and the same numbers reach the same terms (the
/// lumped body's drag at its reference point, the rod's along it and on
/// its caps).
#[test]
fn a_hosts_uniform_flow_drags_a_body_and_its_rod_as_the_same_current_does() {
    let u = [0.6, -0.4, 0.1];
    for scheme in [TimeScheme::Galerkin, TimeScheme::P2] {
        let current = CurrentProfile::uniform(u).unwrap();
        let own_sea = Sea::still(200.0, G).with_current(current, Ramp::NONE);
        let mut own = neutral_body(own_sea, scheme, 1.0);
        let mut hosted = neutral_body(host_sea(), scheme, 1.0);
        hosted.set_host_flow(uniform(u, [0.0; 3])).unwrap();
        for _ in 0..20 {
            own.step().unwrap();
            hosted.step().unwrap();
        }
        assert_eq!(own.position(), hosted.position(), "{scheme:?}");
        assert_eq!(own.rotation(), hosted.rotation(), "{scheme:?}");
        let moved = hosted.position()[0];
        eprintln!("{scheme:?}: the body {moved:.3e} m downstream");
        assert!(moved > 0.0, "{scheme:?}: moved {moved} m along the flow");
    }
}

/// A body as dense as the water, without drag, in water that a host
/// accelerates uniformly at a (its velocity a t, set at each step's
/// middle), follows it: its weight and buoyancy cancel, and its mass and
/// added mass, (1 + Ca_i) rho V along body axis i for the lumped volume
/// and (1 + Ca) rho A per length across the rod, are driven by the same
/// factors times a (B32), so r(t) = r_0 + a t^2 / 2, which both schemes'
/// cubics hold exactly. Along y and along z, across the rod (its caps'
/// inertia along it would need the dynamic pressure, which a host does
/// not give, as in MoorDyn; and at once along both, the lumped volume's
/// Ca differing between them, its added mass's kinetic energy in the
/// body's velocity would turn it, Munk's moment). Measured to round-off of
/// the distance (4e-15 at most), asserted to 1e-12.
#[test]
fn a_body_as_dense_as_the_water_follows_a_hosts_uniform_acceleration() {
    for a in [[0.0, 0.3, 0.0], [0.0, 0.0, -0.2]] {
        for scheme in [TimeScheme::Galerkin, TimeScheme::P2] {
            let mut body = neutral_body(host_sea(), scheme, 0.0);
            let start = body.position();
            let mut worst = 0.0f64;
            while body.time() < 5.0 - 1e-9 {
                let t_mid = body.time() + 0.05;
                body.set_host_flow(uniform(a.map(|c| c * t_mid), a))
                    .unwrap();
                body.step().unwrap();
                let t = body.time();
                let distance = 0.5 * t * t * stancf::vec3::norm(a);
                for i in 0..3 {
                    let expected = start[i] + 0.5 * a[i] * t * t;
                    worst = worst.max((body.position()[i] - expected).abs() / distance);
                }
            }
            eprintln!("{scheme:?}, a = {a:?}: off r_0 + a t^2 / 2 by {worst:.2e} of the distance");
            assert!(worst < 1e-12, "{scheme:?}, a = {a:?}: {worst:e}");
        }
    }
}
