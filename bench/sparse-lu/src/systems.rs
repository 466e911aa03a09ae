//! The systems measured: a rope in 3 x 40 (two fixed anchors and a
//! swinging one to a free point), a chain of three lines through two
//! free points, 12 x 40 to a free point, and a single 120-element line
//! (as a system of one line and as a plain simulation).

use stancf::system::{End, Line, Point, System};

#[path = "../../../crates/stancf/tests/library/common/rope_systems.rs"]
mod rope_systems;
pub use rope_systems::{line_model, one_line, one_line_end, settings, G, SWING};

/// `anchors.len()` lines of `elements` elements from one free point of
/// 0.2 kg to the anchors (the first swinging, the others fixed). The
/// lines start at the free point, so their first nodes coincide there
/// exactly (the system checks that they do).
pub fn star(anchors: &[[f64; 3]], elements: usize) -> System {
    let hub: [f64; 3] = [0.0, 0.0, -1.0];
    let k = anchors.len();
    let lines = anchors
        .iter()
        .enumerate()
        .map(|(i, a)| Line {
            model: line_model(hub, *a, elements),
            ends: [End::Point(k), End::Point(i)],
        })
        .collect();
    let mut points: Vec<Point> = anchors
        .iter()
        .enumerate()
        .map(|(i, a)| {
            if i == 0 {
                Point::coupled(*a, SWING)
            } else {
                Point::fixed(*a)
            }
        })
        .collect();
    points.push(Point::free(hub, 0.2));
    System::new(lines, points, G).unwrap()
}

/// The 3 x 40 system of `bench/criterion/benches/systems.rs`: two fixed
/// anchors and a swinging one, to a free point.
pub fn three_to_a_point() -> System {
    rope_systems::three_to_a_point(40)
}

/// anchor - line - free point - line - free point - line - swinging anchor.
pub fn chain() -> System {
    let p: [[f64; 3]; 4] = [
        [0.0, 0.0, 0.0],
        [2.0, 0.4, -0.8],
        [4.0, -0.4, -0.8],
        [6.0, 0.0, 0.0],
    ];
    let lines = (0..3)
        .map(|i| Line {
            model: line_model(p[i], p[i + 1], 40),
            ends: [End::Point(i), End::Point(i + 1)],
        })
        .collect();
    let points = vec![
        Point::fixed(p[0]),
        Point::free(p[1], 0.2),
        Point::free(p[2], 0.2),
        Point::coupled(p[3], SWING),
    ];
    System::new(lines, points, G).unwrap()
}

/// The single 120-element line as a system: one line from a fixed point
/// to a swinging one, no free point (no border).
pub fn one_line_system() -> System {
    let a = [0.0; 3];
    let b = one_line_end();
    let lines = vec![Line {
        model: line_model(a, b, 120),
        ends: [End::Point(0), End::Point(1)],
    }];
    let points = vec![Point::fixed(a), Point::coupled(b, SWING)];
    System::new(lines, points, G).unwrap()
}

pub fn twelve_to_a_point() -> System {
    let anchors: Vec<[f64; 3]> = (0..12)
        .map(|k| {
            let a = k as f64 * std::f64::consts::TAU / 12.0;
            [2.0 * a.cos(), 2.0 * a.sin(), 0.1 * (k % 3) as f64]
        })
        .collect();
    star(&anchors, 40)
}
