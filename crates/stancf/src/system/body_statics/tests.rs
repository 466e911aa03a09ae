//! The static rows' Jacobian with free bodies, clamps and connectors
//! against central differences (docs/method.md §15.8, §15.19-§15.20).

use crate::body::RigidInertia;
use crate::linear::Jacobian;
use crate::statics::StaticEquations;
use crate::system::{Body, BodyKind, End, Line, Point, System, SystemStatics};
use crate::{Cable, ElementType, Load, Material, Model, ModelOptions, StaticSettings};

/// The static rows' Jacobian with a free body (its own forces' moment,
/// its points' rows carried to it, their constraints, the current's
/// drag on it and on its rod) against central differences, away from
/// the equilibrium and with the body turned.
#[test]
fn the_static_jacobian_with_a_free_body_is_the_derivative_of_its_rows() {
    let g = [0.0, 0.0, -9.81];
    let rotation = crate::body::pose::rotation_from_moordyn_angles([10.0, -20.0, 30.0]);
    let mut body = Body::new(
        BodyKind::Free,
        [0.0, 0.0, -10.0],
        rotation,
        RigidInertia::principal(400.0, [0.1, 0.0, -1.0], [50.0, 60.0, 70.0]),
    );
    body.loads.push(([30.0, -20.0, 500.0], [0.5, 0.5, 0.2]));
    // A current's drag with different areas on the body's axes.
    body.water = Some(crate::body::BodyWater {
        density: 1025.0,
        volume: 0.05,
        drag_areas: [1.0, 2.0, 0.5],
        current: [0.8, -0.3, 0.1],
        rods: Vec::new(),
        ..crate::body::BodyWater::default()
    });
    // And a rod's drag across it and on its caps (B19).
    body.rods.push(crate::body::rod::sample());
    let (lines, points) = two_lines_to(&body, |k, local| [0.5 * k as f64, 2.0 * local[1], 0.0]);
    let system = System::with_bodies(lines, points, vec![body], g).unwrap();
    let (worst, size) = static_jacobian_error(system);
    eprintln!("static Jacobian against differences: {worst:.1e} of {size:.1e}");
    assert!(worst < 1e-6 * size, "{worst:e} of {size:e}");
}

/// The same with both lines clamped at the body along their chords
/// (docs/method.md §15.19) and a connector (§15.20) joining a third
/// line to a fourth: the holds' rows, their multipliers in the lines'
/// and the bodies' rows, the connector's held spin; every unknown
/// moved off the seed (the multipliers not zero).
#[test]
fn the_static_jacobian_with_clamps_at_bodies_is_the_derivative_of_its_rows() {
    let g = [0.0, 0.0, -9.81];
    let rotation = crate::body::pose::rotation_from_moordyn_angles([10.0, -20.0, 30.0]);
    let body = Body::new(
        BodyKind::Free,
        [0.0, 0.0, -10.0],
        rotation,
        RigidInertia::principal(400.0, [0.1, 0.0, -1.0], [50.0, 60.0, 70.0]),
    );
    let (lines, mut points) = two_lines_to(&body, |k, local| [0.5 * k as f64, 2.0 * local[1], 0.0]);
    let mut lines: Vec<Line> = lines
        .into_iter()
        .map(|l| {
            let chord = l.model.cable.direction;
            l.clamped(1, chord).unwrap()
        })
        .collect();
    // A connector at (5, 0, -5) joining a line from a fixed point to a
    // line to another, both clamped along x + z.
    let joint = [5.0, 0.0, -5.0];
    let axis = [1.0, 0.0, 0.2];
    for (k, (a, b)) in [([0.0, 0.0, -6.0], joint), (joint, [10.0, 0.0, -3.5])]
        .into_iter()
        .enumerate()
    {
        let material = Material {
            youngs_modulus: 1e9,
            density: 2000.0,
            area: 1e-3,
            second_moment: 1e-7,
            axial_damping: 0.0,
        };
        let cable = Cable::straight(
            crate::vec3::norm(crate::vec3::sub(b, a)),
            4,
            ElementType::Sac2,
        )
        .with_origin(a)
        .with_direction(crate::vec3::sub(b, a));
        let loads = vec![Load::Gravity { acceleration: g }];
        let model = Model::new(cable, material, ModelOptions::default(), loads).unwrap();
        let ends = if k == 0 {
            [End::Point(4), End::Point(5)]
        } else {
            [End::Point(5), End::Point(6)]
        };
        lines.push(Line { model, ends }.clamped(1 - k, axis).unwrap());
    }
    points.push(Point::fixed([0.0, 0.0, -6.0]));
    points.push(Point::on_body(1, [0.0; 3]));
    points.push(Point::fixed([10.0, 0.0, -3.5]));
    let bodies = vec![body, Body::connector(joint, axis)];
    let system = System::with_bodies(lines, points, bodies, g).unwrap();
    let (worst, size) = static_jacobian_error(system);
    eprintln!("static Jacobian with clamps against differences: {worst:.1e} of {size:.1e}");
    assert!(worst < 1e-6 * size, "{worst:e} of {size:e}");
}

/// Two lines (10.5 m, 6 SAC-2, EA 1e6 N, 2 kg/m, under gravity) from
/// fixed points at `anchor(k, local)` to body 0's points `local`,
/// [0, -1, 0] and [0, 1, 0.3]: the lines and points 0-3 (anchor,
/// body point, anchor, body point).
pub(in crate::system) fn two_lines_to(
    body: &Body,
    anchor: impl Fn(usize, [f64; 3]) -> [f64; 3],
) -> (Vec<Line>, Vec<Point>) {
    let g = [0.0, 0.0, -9.81];
    let mut points = Vec::new();
    let mut lines = Vec::new();
    for (k, local) in [[0.0, -1.0, 0.0], [0.0, 1.0, 0.3]].into_iter().enumerate() {
        let anchor = anchor(k, local);
        let end = body.point(local);
        points.push(Point::fixed(anchor));
        points.push(Point::on_body(0, local));
        let material = Material {
            youngs_modulus: 1e9,
            density: 2000.0,
            area: 1e-3,
            second_moment: 1e-9,
            axial_damping: 0.0,
        };
        let cable = Cable::straight(10.5, 6, ElementType::Sac2)
            .with_origin(anchor)
            .with_direction(crate::vec3::sub(end, anchor));
        let loads = vec![Load::Gravity { acceleration: g }];
        let model = Model::new(cable, material, ModelOptions::default(), loads).unwrap();
        lines.push(Line {
            model,
            ends: [End::Point(2 * k), End::Point(2 * k + 1)],
        });
    }
    (lines, points)
}

/// The largest difference between the static rows' Jacobian of
/// `system` and their central differences (steps 1e-6), and the
/// largest entry, away from the seed: every free body turned and moved
/// a little.
pub(in crate::system) fn static_jacobian_error(system: System) -> (f64, f64) {
    let seeds = crate::system::catenary_states(&system);
    let mut statics = SystemStatics::new(system, seeds, StaticSettings::default()).unwrap();
    let eq = &mut statics.equations;
    eq.homotopy = 0.0;
    let mut x = statics.newton.x.clone();
    for b in 0..eq.layout.body_base.len() {
        for k in 0..6 {
            if let Some(i) = eq.layout.body_unknown(b, 0, k) {
                x[i] += 0.05 * (k as f64 + 1.0) / (b as f64 + 1.0);
            }
        }
    }
    // The multipliers (and everything else) a little off the seed.
    let scale = x.iter().fold(0.0f64, |m, v| m.max(v.abs()));
    for (i, v) in x.iter_mut().enumerate() {
        *v += 1e-4 * scale * (i as f64).sin();
    }
    let n = x.len();
    let mut jac = crate::bordered::BorderedMatrix::new(&eq.layout.shapes, eq.layout.border);
    let mut r = vec![0.0; n];
    eq.evaluate(&x, &mut r, Some(&mut jac));
    let h = 1e-6;
    let mut worst = 0.0f64;
    let mut size = 0.0f64;
    for c in 0..n {
        let (mut xp, mut xm) = (x.clone(), x.clone());
        xp[c] += h;
        xm[c] -= h;
        let (mut rp, mut rm) = (vec![0.0; n], vec![0.0; n]);
        eq.evaluate(&xp, &mut rp, None);
        eq.evaluate(&xm, &mut rm, None);
        for i in 0..n {
            let fd = (rp[i] - rm[i]) / (2.0 * h);
            let a = jac.get(i, c);
            size = size.max(a.abs());
            worst = worst.max((fd - a).abs());
        }
    }
    (worst, size)
}
