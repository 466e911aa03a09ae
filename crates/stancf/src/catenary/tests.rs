//! Tests of the elastic catenary: closure, equilibrium, derivatives, an
//! independent integration of the equilibrium equations, the inextensible
//! classic catenary, the closed-form special cases, the errors and a sweep
//! of Newton's convergence. Tolerances are stated against round-off (about
//! 1e-16 per operation on quantities of size L) or against the truncation
//! error of the reference method.

use super::*;

/// Gravity along a direction not parallel to any axis and not of unit
/// length, and the unit vectors (e_x horizontal, e_z = -g_hat up) of a
/// vertical plane in that frame.
struct TiltedFrame {
    gravity: [f64; 3],
    horizontal: [f64; 3],
    up: [f64; 3],
    origin: [f64; 3],
}

fn tilted_frame() -> TiltedFrame {
    let gravity = [0.9, -1.3, -2.4];
    let up = scale(-1.0 / norm(gravity), gravity);
    let trial = [0.2, 0.7, -0.1];
    let horizontal = sub(trial, scale(dot(trial, up), up));
    TiltedFrame {
        gravity,
        horizontal: scale(1.0 / norm(horizontal), horizontal),
        up,
        origin: [1.5, -2.0, 0.7],
    }
}

impl TiltedFrame {
    fn point(&self, span: f64, rise: f64) -> [f64; 3] {
        std::array::from_fn(|i| self.origin[i] + span * self.horizontal[i] + rise * self.up[i])
    }

    fn catenary(&self, line: CatenaryLine, span: f64, rise: f64) -> Catenary {
        Catenary::between(line, self.origin, self.point(span, rise), self.gravity)
            .unwrap_or_else(|e| panic!("{line:?} span {span} rise {rise}: {e}"))
    }
}

fn distance(a: [f64; 3], b: [f64; 3]) -> f64 {
    norm(sub(a, b))
}

/// A named configuration: line, span, rise.
struct Case {
    name: &'static str,
    line: CatenaryLine,
    span: f64,
    rise: f64,
}

/// Taut, slack, near-vertical (slack and taut), buoyant and nearly
/// inextensible lines of L = 10 m, w = 3 N/m.
fn cases() -> Vec<Case> {
    let line = |weight, ea| CatenaryLine {
        length: 10.0,
        weight,
        ea,
    };
    let taut_rise = (10.05f64 * 10.05 - 64.0).sqrt();
    vec![
        Case {
            name: "taut (chord = 1.005 L)",
            line: line(3.0, 1e5),
            span: 8.0,
            rise: taut_rise,
        },
        Case {
            name: "slack",
            line: line(3.0, 1e4),
            span: 6.0,
            rise: 2.0,
        },
        Case {
            name: "near-vertical slack (h = 1e-4 L)",
            line: line(3.0, 1e4),
            span: 1e-3,
            rise: 8.0,
        },
        Case {
            name: "near-vertical taut (h = 1e-4 L)",
            line: line(3.0, 1e4),
            span: 1e-3,
            rise: -10.05,
        },
        Case {
            name: "buoyant (w < 0)",
            line: line(-3.0, 1e4),
            span: 6.0,
            rise: -2.0,
        },
        Case {
            name: "nearly inextensible (EA = 1e12 w L)",
            line: line(3.0, 1e12 * 30.0),
            span: 6.0,
            rise: 3.0,
        },
    ]
}

/// Closure is round-off: (C3)-(C5) are evaluated without cancellation and
/// Newton stops at 1e-13 max(L, c) before a polishing step; 1e-10 L leaves
/// three orders for the frame's rotation.
#[test]
fn solved_curve_closes_at_both_ends_in_a_tilted_frame() {
    let frame = tilted_frame();
    for case in cases() {
        let catenary = frame.catenary(case.line, case.span, case.rise);
        let length = case.line.length;
        let b = frame.point(case.span, case.rise);
        let error_a = distance(catenary.position(0.0), frame.origin) / length;
        let error_b = distance(catenary.position(length), b) / length;
        eprintln!(
            "{}: closure A {error_a:.1e}, B {error_b:.1e} (x L), {} iterations, H = {:.6e}",
            case.name,
            catenary.iterations(),
            catenary.horizontal_tension()
        );
        assert!(error_a <= 1e-10 && error_b <= 1e-10, "{}", case.name);
    }
}

/// (C12): the points carry the line's weight, F_A + F_B = w L g_hat, to
/// round-off of the largest force.
#[test]
fn end_forces_carry_the_weight_of_the_line() {
    let frame = tilted_frame();
    let g_hat = scale(-1.0, frame.up);
    for case in cases() {
        let catenary = frame.catenary(case.line, case.span, case.rise);
        let weight = case.line.weight * case.line.length;
        let force_a = catenary.end_force(LineEnd::A);
        let force_b = catenary.end_force(LineEnd::B);
        let imbalance: [f64; 3] =
            std::array::from_fn(|i| force_a[i] + force_b[i] - weight * g_hat[i]);
        let force_scale = norm(force_a).max(norm(force_b)).max(weight.abs());
        let error = norm(imbalance) / force_scale;
        eprintln!("{}: force imbalance {error:.1e}", case.name);
        assert!(error <= 1e-14, "{}", case.name);
        // The end forces are the end tensions.
        let tension_a = catenary.tension(0.0);
        let tension_b = catenary.tension(case.line.length);
        assert!((norm(force_a) - tension_a).abs() <= 1e-14 * force_scale);
        assert!((norm(force_b) - tension_b).abs() <= 1e-14 * force_scale);
    }
}

/// (C2): an element stretches by 1 + T/EA; both sides are formulas of
/// (H, V(s)), so they agree to round-off.
#[test]
fn tangent_length_is_one_plus_strain() {
    let frame = tilted_frame();
    for case in cases() {
        let catenary = frame.catenary(case.line, case.span, case.rise);
        let mut worst: f64 = 0.0;
        for k in 0..=100 {
            let s = case.line.length * k as f64 / 100.0;
            let stretch = 1.0 + catenary.tension(s) / case.line.ea;
            worst = worst.max((norm(catenary.derivative(s)) - stretch).abs());
        }
        eprintln!("{}: | |r'| - (1 + T/EA) | <= {worst:.1e}", case.name);
        assert!(worst <= 1e-14, "{}", case.name);
    }
}

/// Central differences with step d = min(1e-4 L, 1e-3 T(s)/|w|): T/|w| is
/// the arc length over which the curvature w H/T^2 changes (the distance
/// to the vertex V = 0 plus the vertex radius H/|w|; 4e-5 m at the bottom
/// of the near-vertical slack line), so the truncation d^2 |r'''|/6 and
/// d^2 |r''''|/12 are ~ 1e-6 of |r'| and |r''|; round-off adds eps R/d and
/// eps R/d^2, R ~ 13 m the size of the coordinates. The bounds are these
/// with a factor of 10.
#[test]
fn derivatives_match_central_differences_of_position() {
    let frame = tilted_frame();
    for case in cases() {
        let catenary = frame.catenary(case.line, case.span, case.rise);
        let length = case.line.length;
        let coordinate_size = norm(frame.origin) + length;
        let (mut first_worst, mut second_worst): (f64, f64) = (0.0, 0.0);
        for k in 1..200 {
            let s = length * k as f64 / 200.0;
            let (first, second) = (catenary.derivative(s), catenary.second_derivative(s));
            let variation_length = catenary.tension(s) / case.line.weight.abs();
            let d = f64::min(1e-4 * length, 1e-3 * variation_length);
            let (before, at, after) = (
                catenary.position(s - d),
                catenary.position(s),
                catenary.position(s + d),
            );
            let first_difference: [f64; 3] =
                std::array::from_fn(|i| (after[i] - before[i]) / (2.0 * d));
            let second_difference: [f64; 3] =
                std::array::from_fn(|i| (after[i] - 2.0 * at[i] + before[i]) / (d * d));
            let round_off = 10.0 * f64::EPSILON * coordinate_size;
            let first_allowed = 1e-5 * norm(first) + round_off / d;
            let second_allowed = 1e-5 * norm(second) + round_off / (d * d);
            first_worst = first_worst.max(distance(first_difference, first) / first_allowed);
            second_worst = second_worst.max(distance(second_difference, second) / second_allowed);
        }
        eprintln!(
            "{}: finite-difference error / bound: r' {first_worst:.2}, r'' {second_worst:.2}",
            case.name
        );
        assert!(first_worst <= 1.0 && second_worst <= 1.0, "{}", case.name);
    }
}

/// An independent check of (C1)-(C5): integrate the equilibrium of the
/// elastic line, dF/ds = -w g_hat (F = T t the internal force) and
/// dr/ds = (1 + |F|/EA) F/|F|, by RK4 from A with the solved end force,
/// and arrive at B. The step is L/20 000, or 1/200 of the local
/// bending radius T^2/(|w| H) where that is smaller (the bottom of the
/// near-vertical slack line); RK4's global error, ~ (ds/rho)^4 times the
/// length, is then far below 1e-8 L.
#[test]
fn integrating_the_equilibrium_equations_from_a_arrives_at_b() {
    let frame = tilted_frame();
    let g_hat = scale(-1.0, frame.up);
    for case in cases() {
        let catenary = frame.catenary(case.line, case.span, case.rise);
        let CatenaryLine { length, weight, ea } = case.line;
        let rate = |state: [f64; 6]| -> [f64; 6] {
            let force = [state[3], state[4], state[5]];
            let tension = norm(force);
            let stretch = (1.0 + tension / ea) / tension;
            [
                stretch * force[0],
                stretch * force[1],
                stretch * force[2],
                -weight * g_hat[0],
                -weight * g_hat[1],
                -weight * g_hat[2],
            ]
        };
        let add = |x: [f64; 6], k: [f64; 6], f: f64| -> [f64; 6] {
            std::array::from_fn(|i| x[i] + f * k[i])
        };
        let force_a = catenary.end_force(LineEnd::A);
        let mut state = [
            frame.origin[0],
            frame.origin[1],
            frame.origin[2],
            force_a[0],
            force_a[1],
            force_a[2],
        ];
        let (mut s, mut steps) = (0.0, 0);
        while s < length {
            let force = [state[3], state[4], state[5]];
            let tension = norm(force);
            let horizontal = norm(sub(force, scale(dot(force, g_hat), g_hat)));
            let radius = tension * tension / (weight.abs() * horizontal);
            let ds = (length / 20_000.0).min(0.005 * radius).min(length - s);
            let k1 = rate(state);
            let k2 = rate(add(state, k1, 0.5 * ds));
            let k3 = rate(add(state, k2, 0.5 * ds));
            let k4 = rate(add(state, k3, ds));
            state = std::array::from_fn(|i| {
                state[i] + ds / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i])
            });
            s += ds;
            steps += 1;
        }
        let arrival = [state[0], state[1], state[2]];
        let error = distance(arrival, frame.point(case.span, case.rise)) / length;
        eprintln!(
            "{}: RK4 arrival error {error:.1e} (x L) in {steps} steps",
            case.name
        );
        assert!(error <= 1e-8, "{}", case.name);
    }
}

/// EA = inf, symmetric span: the classic catenary z = a cosh(x/a) (origin
/// at the vertex) with a from L = 2 a sinh(h/(2a)), solved by bisection to
/// round-off; H = w a and sag a (cosh(h/(2a)) - 1). Both are exact, so the
/// agreement is round-off (1e-10 allows for the conditioning of a).
#[test]
fn inextensible_symmetric_span_is_the_classic_catenary() {
    let (length, weight, span) = (10.0, 2.5, 7.0);
    let frame = tilted_frame();
    let line = CatenaryLine {
        length,
        weight,
        ea: f64::INFINITY,
    };
    let catenary = frame.catenary(line, span, 0.0);
    // L - 2 a sinh(h/(2a)) increases with a (from -inf to L - h > 0).
    let mismatch = |a: f64| length - 2.0 * a * (span / (2.0 * a)).sinh();
    let a = bisect(&mismatch, 0.1, 1e3);
    let h_error = (catenary.horizontal_tension() - weight * a).abs() / (weight * a);
    let expected_sag = a * ((span / (2.0 * a)).cosh() - 1.0);
    let sag_error = (catenary.sag() - expected_sag).abs() / length;
    let mut shape_error: f64 = 0.0;
    for k in 0..=40 {
        let s = length * k as f64 / 40.0;
        // Arc length from the vertex, s - L/2, gives x = a asinh((s - L/2)/a).
        let x = a * ((s - 0.5 * length) / a).asinh();
        let z = a * (x / a).cosh() - a * (span / (2.0 * a)).cosh();
        let expected = frame.point(x + 0.5 * span, z);
        shape_error = shape_error.max(distance(catenary.position(s), expected) / length);
    }
    eprintln!("classic catenary: H {h_error:.1e}, sag {sag_error:.1e}, shape {shape_error:.1e}");
    assert!(h_error <= 1e-10 && sag_error <= 1e-10 && shape_error <= 1e-10);
}

/// (C10): a weightless taut line is the straight chord with the tension
/// EA (c/L - 1): exactly so for a chord (3, 0, 4) of L = 4 under gravity
/// along -z (c = 5 and c/L - 1 = 1/4 are exact), to round-off in the
/// tilted frame (where c carries the frame's rounding).
#[test]
fn weightless_taut_line_is_straight_with_elastic_tension() {
    let line = CatenaryLine {
        length: 4.0,
        weight: 0.0,
        ea: 2.0e6,
    };
    let exact = Catenary::between(line, [0.0; 3], [3.0, 0.0, 4.0], [0.0, 0.0, -1.0])
        .expect("a taut weightless line");
    assert_eq!(exact.tension(1.3), line.ea * (5.0 / line.length - 1.0));
    assert_eq!(exact.horizontal_tension(), 0.6 * exact.tension(0.0));
    let frame = tilted_frame();
    for (span, rise) in [(3.0, 2.9), (0.0, -4.2), (4.5, 0.0)] {
        let catenary = frame.catenary(line, span, rise);
        let chord = f64::hypot(span, rise);
        let expected = line.ea * (chord / line.length - 1.0);
        assert!((catenary.tension(1.3) - expected).abs() <= 1e-14 * line.ea);
        assert_eq!(catenary.sag(), 0.0);
        let b = frame.point(span, rise);
        let midpoint = catenary.position(0.5 * line.length);
        let chord_midpoint: [f64; 3] = std::array::from_fn(|i| 0.5 * (frame.origin[i] + b[i]));
        assert!(distance(midpoint, chord_midpoint) <= 1e-14 * chord);
        assert!(distance(catenary.position(line.length), b) <= 1e-14 * chord);
    }
}

/// (C11): a taut vertical line, its closed form and its continuity with
/// the near-vertical catenary (h = 1e-7 L changes positions by O(h)).
#[test]
fn vertical_line_is_the_closed_form_and_the_limit_of_small_spans() {
    let frame = tilted_frame();
    let line = CatenaryLine {
        length: 10.0,
        weight: 3.0,
        ea: 1e4,
    };
    for rise in [10.2, -10.2] {
        let vertical = frame.catenary(line, 0.0, rise);
        // The top carries the weight and the elastic pull.
        let top_tension =
            line.ea * (rise.abs() - line.length) / line.length + 0.5 * line.weight * line.length;
        let top = if rise > 0.0 { line.length } else { 0.0 };
        assert!((vertical.tension(top) - top_tension).abs() <= 1e-12 * top_tension);
        let b = frame.point(0.0, rise);
        assert!(distance(vertical.position(line.length), b) <= 1e-13 * line.length);
        let near = frame.catenary(line, 1e-6, rise);
        let mut gap: f64 = 0.0;
        for k in 0..=20 {
            let s = line.length * k as f64 / 20.0;
            gap = gap.max(distance(near.position(s), vertical.position(s)));
        }
        eprintln!("vertical rise {rise}: gap to h = 1e-6 m catenary {gap:.1e} m");
        assert!(gap <= 2e-6);
    }
}

/// w < 0 is the mirror of w > 0 about the horizontal through A: same H,
/// opposite V_A, mirrored points, opposite sag.
#[test]
fn buoyant_line_mirrors_the_hanging_line() {
    let frame = tilted_frame();
    let line = CatenaryLine {
        length: 10.0,
        weight: 3.0,
        ea: 1e4,
    };
    let buoyant_line = CatenaryLine {
        weight: -3.0,
        ..line
    };
    let hanging = frame.catenary(line, 6.0, 2.0);
    let buoyant = frame.catenary(buoyant_line, 6.0, -2.0);
    let h = hanging.horizontal_tension();
    assert!((buoyant.horizontal_tension() - h).abs() <= 1e-13 * h);
    assert!((buoyant.sag() + hanging.sag()).abs() <= 1e-13 * line.length);
    assert!(hanging.sag() > 0.0);
    for k in 0..=10 {
        let s = line.length * k as f64 / 10.0;
        let up = sub(hanging.position(s), frame.origin);
        let down = sub(buoyant.position(s), frame.origin);
        let (x_up, z_up) = (dot(up, frame.horizontal), dot(up, frame.up));
        let (x_down, z_down) = (dot(down, frame.horizontal), dot(down, frame.up));
        assert!((x_up - x_down).abs() <= 1e-13 * line.length);
        assert!((z_up + z_down).abs() <= 1e-13 * line.length);
    }
}

/// A line, its ends, the gravity direction, and a word the refusal names.
type RefusedCase = (CatenaryLine, [f64; 3], [f64; 3], [f64; 3], &'static str);

/// Invalid inputs are refused with the input named; configurations
/// without a (unique) shape are refused with the reason.
#[test]
fn invalid_inputs_and_impossible_configurations_are_errors() {
    let good = CatenaryLine {
        length: 10.0,
        weight: 3.0,
        ea: 1e4,
    };
    let down = [0.0, 0.0, -1.0];
    let a = [0.0; 3];
    let b = [6.0, 0.0, 2.0];
    let message = |line: CatenaryLine, a, b, g| match Catenary::between(line, a, b, g) {
        Ok(_) => panic!("{line:?} {a:?} {b:?} {g:?} accepted"),
        Err(e) => e.to_string(),
    };
    let cases: [RefusedCase; 11] = [
        (
            CatenaryLine {
                length: 0.0,
                ..good
            },
            a,
            b,
            down,
            "length",
        ),
        (
            CatenaryLine {
                length: f64::NAN,
                ..good
            },
            a,
            b,
            down,
            "length",
        ),
        (
            CatenaryLine {
                weight: f64::INFINITY,
                ..good
            },
            a,
            b,
            down,
            "weight",
        ),
        (CatenaryLine { ea: 0.0, ..good }, a, b, down, "EA"),
        (
            CatenaryLine {
                ea: f64::NAN,
                ..good
            },
            a,
            b,
            down,
            "EA",
        ),
        (good, [f64::NAN, 0.0, 0.0], b, down, "end A"),
        (good, a, [0.0, f64::INFINITY, 0.0], down, "end B"),
        (good, a, b, [0.0; 3], "gravity"),
        (good, a, [0.0, 0.0, 5.0], down, "fold"),
        (
            CatenaryLine {
                weight: 0.0,
                ..good
            },
            a,
            b,
            down,
            "slack",
        ),
        (
            CatenaryLine {
                ea: f64::INFINITY,
                ..good
            },
            a,
            [6.0, 0.0, 8.5],
            down,
            "inextensible",
        ),
    ];
    for (line, a, b, g, expected) in cases {
        let text = message(line, a, b, g);
        eprintln!("{text}");
        assert!(
            text.contains(expected),
            "{text:?} does not name {expected:?}"
        );
    }
    // Exactly as long as the chord: weightless with finite EA is straight
    // and unstressed; inextensible, the tension is indeterminate.
    let exact = CatenaryLine {
        length: 5.0,
        weight: 0.0,
        ea: 1e4,
    };
    let b = [3.0, 0.0, 4.0];
    let unstressed = Catenary::between(exact, a, b, down).expect("straight");
    assert_eq!(unstressed.tension(0.0), 0.0);
    let rigid = CatenaryLine {
        ea: f64::INFINITY,
        ..exact
    };
    assert!(message(rigid, a, b, down).contains("indeterminate"));
}

/// Newton from (C9) converges for L/c from 0.9 (taut, 11 % strain) to 5
/// (very slack) and rise/span from -3 to 3, with weight positive and
/// negative and EA from 1e2 to 1e10 times the weight w L: closure at 1e-10 L.
#[test]
fn newton_converges_over_a_sweep_of_slack_and_rise() {
    let frame = tilted_frame();
    let (mut worst, mut most_iterations, mut count) = (0.0f64, 0, 0);
    for i in 0..10 {
        let length_over_chord = 0.9 + (5.0 - 0.9) * i as f64 / 9.0;
        for j in 0..10 {
            let rise_over_span = -3.0 + 6.0 * j as f64 / 9.0;
            for (weight, ea_over_weight) in [(3.0, 1e2), (-3.0, 1e4), (3.0, 1e10)] {
                let length = 10.0;
                let chord = length / length_over_chord;
                if ea_over_weight > 1e8 && chord > length * (1.0 - 1e-9) {
                    continue; // no inextensible-like line spans more than itself
                }
                let span = chord / rise_over_span.hypot(1.0);
                let rise = rise_over_span * span;
                let line = CatenaryLine {
                    length,
                    weight,
                    ea: ea_over_weight * weight.abs() * length,
                };
                let catenary = frame.catenary(line, span, rise);
                let error = distance(catenary.position(length), frame.point(span, rise)) / length;
                assert!(
                    error <= 1e-10,
                    "L/c {length_over_chord}, v/h {rise_over_span}"
                );
                worst = worst.max(error);
                most_iterations = most_iterations.max(catenary.iterations());
                count += 1;
            }
        }
    }
    eprintln!(
        "sweep: {count} lines, worst closure {worst:.1e} L, at most {most_iterations} iterations"
    );
    assert!(count >= 200);
}

/// The root of an increasing `f` with f(low) < 0 < f(high), by 200
/// bisections (to the last bit of the bracket): an independent solve for
/// the textbook catenaries the tests compare with.
pub(super) fn bisect(f: &dyn Fn(f64) -> f64, mut low: f64, mut high: f64) -> f64 {
    for _ in 0..200 {
        let mid = 0.5 * (low + high);
        if f(mid) < 0.0 {
            low = mid;
        } else {
            high = mid;
        }
    }
    0.5 * (low + high)
}
