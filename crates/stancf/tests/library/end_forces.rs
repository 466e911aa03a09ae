//! The end forces of a system's lines at the end of a step
//! (docs/method.md §6.5): the step means of (M23) are the forces at the
//! steps' middles, off the forces at their ends by dt/2 times the rate;
//! the Galerkin step's estimate from its own four moments (M23b) is
//! fourth order, P2's through the last two means (M23a) second order.

use crate::common::rope_systems::three_to_a_point_stepped;
use stancf::TimeScheme;

/// The forces of the lines on the swinging anchor (point 2, a coupled
/// point: the lines' reactions) and on the free point (point 3: the
/// lines' shares of its rows) of the rope system of `rope_systems` (4
/// elements per line, steps of `dt`, Newton to 1e-12) at t = 0.1 s: the
/// step means and the estimates at t.
fn forces_at(dt: f64, scheme: TimeScheme) -> [([f64; 3], [f64; 3]); 2] {
    let mut sim = three_to_a_point_stepped(dt, scheme);
    let steps = (0.1 / dt).round() as usize;
    for _ in 0..steps {
        sim.step().expect("step");
    }
    assert!((sim.time() - 0.1).abs() < 1e-12);
    let at_free_point = |f: [stancf::system::EndForce; 2]| f[1].force;
    [
        (sim.point_force(2), sim.point_force_at_time(2)),
        (
            at_free_point(sim.end_forces(0)),
            at_free_point(sim.end_forces_at_time(0)),
        ),
    ]
}

fn distance(a: [f64; 3], b: [f64; 3]) -> f64 {
    (0..3).map(|c| (a[c] - b[c]).powi(2)).sum::<f64>().sqrt()
}

/// The errors (mean, estimate at t) at each point for each step of `dts`
/// against the estimate at t of steps of `reference`, and the orders
/// between successive steps.
fn orders(dts: &[f64], reference: f64, scheme: TimeScheme) -> Vec<[(f64, f64); 2]> {
    let truth = forces_at(reference, scheme);
    let mut errors = Vec::new();
    for &dt in dts {
        let got = forces_at(dt, scheme);
        let e: [(f64, f64); 2] = std::array::from_fn(|k| {
            (
                distance(got[k].0, truth[k].1),
                distance(got[k].1, truth[k].1),
            )
        });
        eprintln!("{scheme:?} dt {dt:e}: coupled point: mean off by {:.3e} N, at t by {:.3e} N; line 1 at the free point: {:.3e} N, {:.3e} N",
            e[0].0, e[0].1, e[1].0, e[1].1);
        for (mean, at_time) in e {
            assert!(at_time < mean, "dt {dt}: {e:?}");
        }
        errors.push(e);
    }
    errors
        .windows(2)
        .map(|w| {
            std::array::from_fn(|k| {
                let (a, b) = (w[0][k], w[1][k]);
                ((a.0 / b.0).log2(), (a.1 / b.1).log2())
            })
        })
        .collect()
}

/// Galerkin (M23b), against steps 8 times shorter than the shortest:
/// at the coupled point (the lines' reactions) the estimate's error falls
/// by 16 with each halving of the step, orders 4.16, 4.10 and 4.3 from
/// 2 ms to 0.25 ms (1.7e-4 N at 2 ms, 2.5e-8 N at 0.25 ms, near Newton's
/// 1e-12; the mean 5.7e-3 and 9.4e-4 N). At the free point (a line's
/// share of the point's rows, whose motion is the step's own cubic, not a
/// prescribed one) orders 3.51, 2.54 and 2.56 (2.2e-5 N at 2 ms, 5.6e-8 N
/// at 0.25 ms; the mean 1.6e-2 and 2.0e-3 N): better than P2's (M23a) at
/// every step, at least its order. The means' order is 0.77 to 0.99 (below
/// 1 while the axial waves, 100 m/s over 0.55 m elements, are not
/// resolved). Bounds: above 3.5 at the coupled point and 2.2 at the free
/// point (at least (M23a)'s second order), below 1.3 for the mean; the
/// estimate closer than the mean at every step (measured 34 to 38 000
/// times closer).
#[test]
fn the_galerkin_steps_end_force_at_t_is_fourth_order_in_the_step() {
    for (k, [coupled, free]) in orders(&[2e-3, 1e-3, 5e-4, 2.5e-4], 3.125e-5, TimeScheme::Galerkin)
        .into_iter()
        .enumerate()
    {
        eprintln!("halving {k}: orders, coupled point {coupled:.2?}, free point {free:.2?}");
        for ((mean, at_time), least) in [(coupled, 3.5), (free, 2.2)] {
            assert!(mean < 1.3, "step mean order {mean}");
            assert!(at_time > least, "estimate order {at_time}");
        }
    }
}

/// P2 (M23a), against steps 4 times shorter than the shortest (its own
/// error ~1/16 of the shortest's at second order, so an order measured
/// against it is off by at most log2((1 + 1/64) / (1 - 1/16)) = 0.12):
/// the step means' error halves with the step (order 1) and the
/// estimate's quarters (order 2). P2's stable step here is about 1.8 ms
/// (§4.6). Bounds: order above 1.7 for the estimate, below 1.3 for the
/// mean.
#[test]
fn the_p2_steps_end_force_at_t_is_second_order_in_the_step() {
    for (k, [coupled, free]) in orders(&[2.5e-4, 1.25e-4, 6.25e-5], 1.5625e-5, TimeScheme::P2)
        .into_iter()
        .enumerate()
    {
        eprintln!("halving {k}: orders, coupled point {coupled:.2?}, free point {free:.2?}");
        for (mean, at_time) in [coupled, free] {
            assert!(mean < 1.3, "step mean order {mean}");
            assert!(at_time > 1.7, "estimate order {at_time}");
        }
    }
}
