//! Tests of the catenary on the seabed (C14)-(C21): closure, an independent
//! RK4 integration of the equilibrium from the anchor, the friction
//! regimes, the join with the free catenary, the inextensible textbook
//! solution, the Jacobian by central differences, the errors, a sweep of
//! Newton's convergence and the OC4-DeepCwind line. Tolerances are stated
//! against round-off or the truncation error of the reference method.

use super::profile::Plane;
use super::tests::bisect;
use super::touchdown::{solve_touchdown, RestingLine, TouchdownLine, TouchdownRegime};
use super::CatenaryError;

fn line(length: f64, weight: f64, ea: f64, friction: f64) -> TouchdownLine {
    TouchdownLine {
        length,
        weight,
        ea,
        friction,
    }
}

/// A named configuration: line, fairlead offset XF and height ZF.
struct Case {
    name: &'static str,
    line: TouchdownLine,
    xf: f64,
    zf: f64,
    regime: TouchdownRegime,
}

/// W = 9.81 (113.35 - 1025 pi 0.0766^2/4) N/m: the OC4-DeepCwind chain's
/// weight in sea water (the deck examples/oc4-deepcwind-moordyn.txt: mass
/// 113.35 kg/m, diameter 0.0766 m, density 1025 kg/m^3, g = 9.81 m/s^2,
/// length 835.35 m).
fn oc4_line(friction: f64) -> TouchdownLine {
    let displaced = 1025.0 * std::f64::consts::PI * 0.0766 * 0.0766 / 4.0;
    line(835.35, 9.81 * (113.35 - displaced), 753.6e6, friction)
}

/// OC4: anchor at radius 837.6 m, depth 200 m; fairlead at radius 40.868 m,
/// z = -14 m.
const OC4_XF: f64 = 837.6 - 40.868;
const OC4_ZF: f64 = 200.0 - 14.0;

/// Lines of L = 100 m, W = 10 N/m in every regime, and the OC4 line.
fn cases() -> Vec<Case> {
    use TouchdownRegime::*;
    let case = |name, line, xf, zf, regime| Case {
        name,
        line,
        xf,
        zf,
        regime,
    };
    vec![
        case(
            "frictionless",
            line(100.0, 10.0, 1e6, 0.0),
            80.0,
            30.0,
            TautAtAnchor,
        ),
        case(
            "friction, anchor taut",
            line(100.0, 10.0, 1e6, 0.05),
            80.0,
            30.0,
            TautAtAnchor,
        ),
        case(
            "friction, anchor slack",
            line(100.0, 10.0, 1e6, 5.0),
            80.0,
            30.0,
            SlackAtAnchor,
        ),
        case(
            "soft (EA = 10 W L)",
            line(100.0, 10.0, 1e4, 0.05),
            80.0,
            30.0,
            TautAtAnchor,
        ),
        case(
            "soft and slack at the anchor",
            line(100.0, 10.0, 1e4, 5.0),
            75.0,
            30.0,
            SlackAtAnchor,
        ),
        case(
            "inextensible",
            line(100.0, 10.0, f64::INFINITY, 0.05),
            80.0,
            30.0,
            TautAtAnchor,
        ),
        case(
            "shallow (ZF = L/200)",
            line(100.0, 10.0, 1e6, 0.5),
            99.6,
            0.5,
            SlackAtAnchor,
        ),
        case(
            "shallow, frictionless",
            line(100.0, 10.0, 1e6, 0.0),
            99.6,
            0.5,
            TautAtAnchor,
        ),
        case(
            "hanging clear",
            line(100.0, 10.0, 1e6, 0.5),
            90.0,
            40.0,
            Hanging,
        ),
        case("OC4, CB = 0", oc4_line(0.0), OC4_XF, OC4_ZF, TautAtAnchor),
        case("OC4, CB = 1", oc4_line(1.0), OC4_XF, OC4_ZF, TautAtAnchor),
    ]
}

fn solve(case: &Case) -> super::touchdown::TouchdownSolution {
    solve_touchdown(&case.line, case.xf, case.zf).unwrap_or_else(|e| panic!("{}: {e}", case.name))
}

/// Closure is round-off: (C16)-(C17) are evaluated without cancellation
/// and Newton stops at 1e-13 max(L, chord) before a polishing step.
#[test]
fn profile_lands_on_the_fairlead_in_every_regime() {
    for case in cases() {
        let solution = solve(&case);
        let length = case.line.length;
        let (x, z) = solution.position(length);
        let error = (x - case.xf).hypot(z - case.zf) / length;
        let (x0, z0) = solution.position(0.0);
        eprintln!(
            "{}: {:?}, HF {:.6e}, VF {:.6e}, HA {:.6e}, LB {:.4}, s0 {:.4}, closure {error:.1e} L, \
             {} iterations",
            case.name,
            solution.regime,
            solution.hf,
            solution.vf,
            solution.ha,
            solution.resting_length,
            solution.slack_length,
            solution.iterations
        );
        assert_eq!(solution.regime, case.regime, "{}", case.name);
        assert!(error <= 1e-10, "{}", case.name);
        assert!(x0.hypot(z0) <= 1e-14 * length, "{}", case.name);
        // The resting part lies on the seabed, the rest above it.
        for k in 0..=200 {
            let s = length * k as f64 / 200.0;
            assert!(solution.position(s).1 >= 0.0, "{} at s = {s}", case.name);
        }
    }
}

/// An independent check of (C15)-(C17): integrate the equilibrium of the
/// line by RK4 from the solved anchor state. On the seabed, T' = CB W
/// where the line is taut (s > s0) and 0 where slack, x' = 1 + T/EA, z = 0;
/// from the touchdown point LB the force F = (T, 0) grows by F' = (0, W)
/// and r' = (1 + |F|/EA) F/|F|. The seabed part is polynomial and exact in
/// RK4 (steps end at s0 and LB); the suspended part takes L/20 000 steps,
/// its global error ~ (ds/rho)^4 L with the bending radius rho >= HF/W, far
/// below 1e-8 L. The tension reaching the touchdown point must be HF (the
/// friction balance), to round-off.
#[test]
fn integrating_the_equilibrium_from_the_anchor_arrives_at_the_fairlead() {
    for case in cases() {
        let solution = solve(&case);
        if solution.regime == TouchdownRegime::Hanging {
            continue; // the free catenary's own test integrates it
        }
        let TouchdownLine {
            length,
            weight,
            ea,
            friction,
        } = case.line;
        let (slack_length, resting_length) = (solution.slack_length, solution.resting_length);
        // Seabed: state (x, T); the slack part has T = 0 and x' = 1.
        let seabed_rate = |state: [f64; 2]| [1.0 + state[1] / ea, friction * weight];
        let mut seabed = [slack_length, solution.ha];
        let seabed_steps = 100;
        let ds = (resting_length - slack_length) / seabed_steps as f64;
        for _ in 0..seabed_steps {
            seabed = rk4(seabed, ds, seabed_rate);
        }
        let liftoff_error = (seabed[1] - solution.hf).abs() / solution.hf;
        // Suspended: state (x, z, F_x, F_z).
        let suspended_rate = |state: [f64; 4]| {
            let tension = state[2].hypot(state[3]);
            let stretch = (1.0 + tension / ea) / tension;
            [stretch * state[2], stretch * state[3], 0.0, weight]
        };
        let mut state = [seabed[0], 0.0, seabed[1], 0.0];
        let steps = 20_000;
        let ds = (length - resting_length) / steps as f64;
        for _ in 0..steps {
            state = rk4(state, ds, suspended_rate);
        }
        let arrival_error = (state[0] - case.xf).hypot(state[1] - case.zf) / length;
        let force_error =
            (state[2] - solution.hf).hypot(state[3] - solution.vf) / solution.fairlead_tension();
        eprintln!(
            "{}: lift-off tension error {liftoff_error:.1e}, RK4 arrival {arrival_error:.1e} L, \
             fairlead force {force_error:.1e}",
            case.name
        );
        assert!(liftoff_error <= 1e-12, "{}", case.name);
        assert!(arrival_error <= 1e-8, "{}", case.name);
        assert!(force_error <= 1e-12, "{}", case.name);
    }
}

fn rk4<const N: usize>(state: [f64; N], ds: f64, rate: impl Fn([f64; N]) -> [f64; N]) -> [f64; N] {
    let add =
        |x: [f64; N], k: [f64; N], f: f64| -> [f64; N] { std::array::from_fn(|i| x[i] + f * k[i]) };
    let k1 = rate(state);
    let k2 = rate(add(state, k1, 0.5 * ds));
    let k3 = rate(add(state, k2, 0.5 * ds));
    let k4 = rate(add(state, k3, ds));
    std::array::from_fn(|i| state[i] + ds / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]))
}

/// (C15): frictionless, the resting part carries HF to the anchor; with
/// friction the tension falls by CB W per length towards the anchor (read
/// off the profile by a difference quotient, exact for the linear T up to
/// round-off eps HF/d), to HA > 0 or to zero at s0; and since friction only
/// relieves the resting part's stretch, a line held at the same (XF, ZF)
/// must pull harder at the fairlead as CB grows.
#[test]
fn friction_drains_the_tension_along_the_resting_part() {
    let (xf, zf) = (80.0, 30.0);
    let mut previous_hf = 0.0;
    for friction in [0.0, 0.01, 0.05, 0.5, 5.0, 50.0] {
        let line = line(100.0, 10.0, 1e4, friction);
        let solution = solve_touchdown(&line, xf, zf).expect("touches down");
        let (hf, ha) = (solution.hf, solution.ha);
        let (resting_length, slack_length) = (solution.resting_length, solution.slack_length);
        eprintln!(
            "CB {friction}: {:?}, HF {hf:.9e}, HA {ha:.6e}, LB {resting_length:.6}, s0 {slack_length:.6}",
            solution.regime
        );
        assert!(
            hf > previous_hf,
            "CB {friction}: HF {hf} after {previous_hf}"
        );
        previous_hf = hf;
        if friction == 0.0 {
            assert_eq!(ha, hf);
            assert_eq!(slack_length, 0.0);
        }
        // The tension's rate along the taut part of the resting length.
        let d = 1e-3 * (resting_length - slack_length);
        let s = 0.5 * (slack_length + resting_length);
        let rate = (solution.tension(s + d) - solution.tension(s - d)) / (2.0 * d);
        let rate_error = (rate - friction * line.weight).abs();
        assert!(rate_error <= 1e-12 * hf / d, "CB {friction}: rate {rate}");
        // The anchor holds what friction does not: HF - HA = CB W (LB - s0).
        let friction_force = friction * line.weight * (resting_length - slack_length);
        assert!((hf - ha - friction_force).abs() <= 1e-13 * hf);
        if solution.regime == TouchdownRegime::SlackAtAnchor {
            assert_eq!(ha, 0.0);
            assert!(slack_length > 0.0);
            assert_eq!(solution.tension(0.5 * slack_length), 0.0);
        }
    }
}

/// As the resting length shrinks to zero the solution joins the free
/// catenary that leaves the anchor horizontally: with H* = 200 N, the free
/// catenary with V_A = 0 ends at (X*, Z*) = (C3)-(C5); fairleads at
/// X* (1 -+ 1e-10) touch down / hang clear, and both give (HF, VF) =
/// (H*, W L) to 1e-8 (the 1e-10 offset moves them by ~1e-9 relative;
/// closure is 1e-13). The closure equations also join to first order: the
/// Jacobian (C19) at (H*, W L) is the central-difference Jacobian of the
/// free catenary's end (C3)-(C5) at (H*, V_A = 0), to its truncation.
#[test]
fn vanishing_resting_length_joins_the_free_catenary() {
    for friction in [0.0, 0.3] {
        let line = line(100.0, 10.0, 1e4, friction);
        let horizontal = 200.0;
        let free_end = |h: f64, v_a: f64| {
            Plane {
                horizontal: h,
                vertical_a: v_a,
                weight: line.weight,
                compliance: 1.0 / line.ea,
            }
            .position(line.length)
        };
        let (x_star, z_star) = free_end(horizontal, 0.0);
        let full_weight = line.weight * line.length;
        for (offset, expect_hanging) in [(-1e-10, false), (1e-10, true)] {
            let solution = solve_touchdown(&line, x_star * (1.0 + offset), z_star).expect("solves");
            let hf_error = (solution.hf - horizontal).abs() / horizontal;
            let vf_error = (solution.vf - full_weight).abs() / full_weight;
            eprintln!(
                "CB {friction}, XF = X* (1 + {offset:e}): {:?}, LB {:.1e}, HF error {hf_error:.1e}, \
                 VF error {vf_error:.1e}",
                solution.regime, solution.resting_length
            );
            assert_eq!(solution.regime == TouchdownRegime::Hanging, expect_hanging);
            assert!(hf_error <= 1e-8 && vf_error <= 1e-8);
        }
        let resting = RestingLine {
            hf: horizontal,
            vf: full_weight,
            length: line.length,
            weight: line.weight,
            compliance: 1.0 / line.ea,
            friction,
        };
        let jacobian = resting.jacobian();
        let (dh, dv) = (1e-5 * horizontal, 1e-5 * full_weight);
        let column = |plus: (f64, f64), minus: (f64, f64), d: f64| {
            [
                (plus.0 - minus.0) / (2.0 * d),
                (plus.1 - minus.1) / (2.0 * d),
            ]
        };
        let by_h = column(
            free_end(horizontal + dh, 0.0),
            free_end(horizontal - dh, 0.0),
            dh,
        );
        let by_v = column(free_end(horizontal, dv), free_end(horizontal, -dv), dv);
        let error = jacobian_error(jacobian, by_h, by_v);
        eprintln!("CB {friction}: (C19) against the free catenary's Jacobian, {error:.1e}");
        assert!(error <= 1e-7);
    }
}

/// The largest entry of J - [by_h by_v], relative to J's largest entry.
fn jacobian_error(jacobian: [[f64; 2]; 2], by_h: [f64; 2], by_v: [f64; 2]) -> f64 {
    let scale = jacobian
        .iter()
        .flatten()
        .fold(0.0f64, |m, j| m.max(j.abs()));
    let mut worst: f64 = 0.0;
    for row in 0..2 {
        worst = worst.max((jacobian[row][0] - by_h[row]).abs());
        worst = worst.max((jacobian[row][1] - by_v[row]).abs());
    }
    worst / scale
}

/// The textbook inextensible catenary with touchdown: the suspended part
/// rises ZF = (T_F - H)/W with T_F^2 = H^2 + W^2 Ls^2, so
/// Ls = sqrt(ZF^2 + 2 ZF H/W), and XF = L - Ls + (H/W) asinh(W Ls/H),
/// solved for H by bisection to round-off. EA = inf must reproduce it for
/// any friction (friction only changes the stretch, and HA); finite EA
/// approaches it at the rate 1/EA.
#[test]
fn inextensible_limit_is_the_textbook_catenary_with_touchdown() {
    let (length, weight, xf, zf) = (100.0, 10.0, 80.0, 30.0);
    let suspended = |h: f64| (zf * zf + 2.0 * zf * h / weight).sqrt();
    let mismatch = |h: f64| {
        let ls = suspended(h);
        length - ls + h / weight * (weight * ls / h).asinh() - xf
    };
    // Ls = L at the largest H; X(H) - XF < 0 as H -> 0 (L - ZF < XF).
    let (low, high) = (1e-9, weight * (length * length - zf * zf) / (2.0 * zf));
    assert!(mismatch(low) < 0.0 && mismatch(high) > 0.0);
    let textbook_h = bisect(&mismatch, low, high);
    let textbook_v = weight * suspended(textbook_h);
    let relative_gap = |ea: f64, friction: f64| {
        let solution =
            solve_touchdown(&line(length, weight, ea, friction), xf, zf).expect("solves");
        let gap = ((solution.hf - textbook_h) / textbook_h)
            .abs()
            .max(((solution.vf - textbook_v) / textbook_v).abs());
        eprintln!(
            "EA {ea:e}, CB {friction}: HF {:.9e}, gap to textbook {gap:.1e}",
            solution.hf
        );
        gap
    };
    for friction in [0.0, 0.05, 5.0] {
        assert!(relative_gap(f64::INFINITY, friction) <= 1e-10);
    }
    let full_weight = weight * length;
    let (stiff, stiffer) = (
        relative_gap(1e6 * full_weight, 0.05),
        relative_gap(1e8 * full_weight, 0.05),
    );
    let ratio = stiff / stiffer;
    eprintln!("gap ratio for EA x 100: {ratio:.2}");
    assert!((90.0..=110.0).contains(&ratio));
}

/// (C19) against central differences of the closure (C18) in every
/// regime, and on the series branch (VF/HF = 5e-3). Steps 1e-5 of HF and
/// of VF's distance to 0 and W L: truncation ~ 1e-10 of the entries,
/// round-off ~ eps L/d ~ 1e-10 of them; the regimes' seam (HA = 0) is
/// kept at least a factor 2 away.
#[test]
fn jacobian_matches_central_differences_of_the_closure() {
    let resting = |ea: f64, friction: f64, hf: f64, vf: f64| RestingLine {
        hf,
        vf,
        length: 100.0,
        weight: 10.0,
        compliance: 1.0 / ea,
        friction,
    };
    let cases = [
        ("frictionless", resting(1e4, 0.0, 60.0, 350.0)),
        ("anchor taut", resting(1e4, 0.04, 60.0, 350.0)),
        ("anchor slack", resting(1e4, 5.0, 60.0, 350.0)),
        (
            "inextensible, anchor taut",
            resting(f64::INFINITY, 0.04, 60.0, 350.0),
        ),
        (
            "stiff, nearly flat (VF/HF = 5e-3)",
            resting(1e6, 0.0, 1e4, 50.0),
        ),
        ("nearly all suspended", resting(1e4, 1.0, 300.0, 990.0)),
    ];
    for (name, line) in cases {
        let ha = line.anchor_tension();
        let seam_distance = (line.hf - line.friction * line.weight * line.resting_length()).abs();
        assert!(
            line.friction == 0.0 || seam_distance >= 0.5 * line.hf,
            "{name}: near the seam"
        );
        let end = |hf: f64, vf: f64| line.with_forces(hf, vf).position(line.length);
        let dh = 1e-5 * line.hf;
        let dv = 1e-5 * line.vf.min(line.weight * line.length - line.vf);
        let difference = |plus: (f64, f64), minus: (f64, f64), d: f64| {
            [
                (plus.0 - minus.0) / (2.0 * d),
                (plus.1 - minus.1) / (2.0 * d),
            ]
        };
        let by_h = difference(end(line.hf + dh, line.vf), end(line.hf - dh, line.vf), dh);
        let by_v = difference(end(line.hf, line.vf + dv), end(line.hf, line.vf - dv), dv);
        let error = jacobian_error(line.jacobian(), by_h, by_v);
        eprintln!("{name} (HA {ha:.3e}): Jacobian error {error:.1e}");
        assert!(error <= 1e-7, "{name}");
    }
}

/// Inputs out of range are refused naming the input; a line too long to
/// lie straight on the seabed (C20), a too-short inextensible line and a
/// slack weightless one are refused with the reason.
#[test]
fn impossible_inputs_are_errors_that_say_why() {
    let good = line(100.0, 10.0, 1e4, 0.5);
    let cases: [(TouchdownLine, f64, f64, &str); 9] = [
        (good, 60.0, 30.0, "too long"),
        (
            line(100.0, 10.0, f64::INFINITY, 0.5),
            69.0,
            30.0,
            "too long",
        ),
        (line(100.0, 10.0, 1e4, -0.1), 80.0, 30.0, "friction"),
        (good, f64::NAN, 30.0, "XF"),
        (good, 80.0, 0.0, "ZF"),
        (good, 80.0, f64::INFINITY, "ZF"),
        (line(0.0, 10.0, 1e4, 0.5), 80.0, 30.0, "length"),
        (
            line(100.0, 10.0, f64::INFINITY, 0.5),
            90.0,
            50.0,
            "inextensible",
        ),
        (line(100.0, 0.0, 1e4, 0.5), 80.0, 30.0, "slack"),
    ];
    for (line, xf, zf, expected) in cases {
        let text = match solve_touchdown(&line, xf, zf) {
            Ok(solution) => panic!("{line:?} XF {xf} ZF {zf} accepted: {solution:?}"),
            Err(error) => error.to_string(),
        };
        eprintln!("{text}");
        assert!(
            text.contains(expected),
            "{text:?} does not name {expected:?}"
        );
    }
    // Just inside the bound (C20) a solution exists, with a small HF.
    let inextensible = line(100.0, 10.0, f64::INFINITY, 0.5);
    let near_bound = solve_touchdown(&inextensible, 70.0 + 1e-3, 30.0).expect("inside L_max");
    eprintln!("1e-3 m inside L_max: HF {:.3e}", near_bound.hf);
    assert!(near_bound.hf < 1e-2 * inextensible.weight * inextensible.length);
    assert!(matches!(
        solve_touchdown(&inextensible, 70.0, 30.0),
        Err(CatenaryError::NoSolution { .. })
    ));
}

/// A buoyant line (W < 0) cannot touch down: it takes the free catenary,
/// above the seabed; so does a taut weightless one (straight).
#[test]
fn buoyant_and_weightless_lines_hang_clear() {
    let buoyant = solve_touchdown(&line(100.0, -3.0, 1e4, 0.5), 80.0, 30.0).expect("hangs");
    let weightless = solve_touchdown(&line(100.0, 0.0, 1e4, 0.5), 80.0, 61.0).expect("taut");
    for solution in [&buoyant, &weightless] {
        assert_eq!(solution.regime, TouchdownRegime::Hanging);
        assert_eq!(solution.resting_length, 0.0);
        for k in 0..=100 {
            assert!(solution.position(k as f64).1 >= 0.0);
        }
    }
    assert!(buoyant.va > 0.0 && buoyant.vf < buoyant.va);
}

/// Newton from (C21) over fairlead offsets from 1e-4 L above the fold
/// bound (C20) of each line to 1 % past the chord L, heights ZF/L from 0.01
/// to 0.9, friction 0 to 10, EA from 1e2 W L to infinite: closure 1e-10 L
/// in every touching-down case.
#[test]
fn newton_converges_over_a_sweep_of_offsets_heights_and_friction() {
    let (length, weight) = (100.0, 10.0);
    let (mut count, mut touching, mut most_iterations, mut worst) = (0, 0, 0, 0.0f64);
    for ea_over_weight in [1e2, 1e4, f64::INFINITY] {
        let ea = ea_over_weight * weight * length;
        for zf_over_length in [0.01, 0.1, 0.3, 0.6, 0.9] {
            let zf = zf_over_length * length;
            let fold_xf = length - 2.0 * zf / (1.0 + (1.0 + 2.0 * weight * zf / ea).sqrt());
            let straight_xf = (length * length - zf * zf).sqrt() * 1.01;
            for i in 0..=12 {
                let t = i as f64 / 12.0;
                let xf = fold_xf + 1e-4 * length + t * (straight_xf - fold_xf);
                if ea == f64::INFINITY && xf.hypot(zf) >= length * (1.0 - 1e-9) {
                    continue; // an inextensible line cannot span its length
                }
                for friction in [0.0, 0.1, 1.0, 10.0] {
                    let line = line(length, weight, ea, friction);
                    let solution = solve_touchdown(&line, xf, zf)
                        .unwrap_or_else(|e| panic!("{line:?} XF {xf} ZF {zf}: {e}"));
                    let (x, z) = solution.position(length);
                    let error = (x - xf).hypot(z - zf) / length;
                    assert!(
                        error <= 1e-10,
                        "{line:?} XF {xf} ZF {zf}: closure {error:e}"
                    );
                    count += 1;
                    if solution.regime != TouchdownRegime::Hanging {
                        touching += 1;
                        most_iterations = most_iterations.max(solution.iterations);
                        worst = worst.max(error);
                    }
                }
            }
        }
    }
    eprintln!(
        "sweep: {count} lines, {touching} touching down, worst closure {worst:.1e} L, \
         at most {most_iterations} iterations"
    );
    assert!(touching >= 300);
}
