//! Claims of the stability analysis (docs/method.md §4).

use super::*;

/// The closed form (M20) of docs/method.md §4.5, one layer, 3 Gauss
/// points:
/// det = 1, trace = 2 (3 W^4 - 104 W^2 + 240) / (W^4 + 16 W^2 + 240).
#[test]
fn amplification_matches_the_closed_form() {
    let rule = GaussRule::new(3).unwrap();
    for &w in &[0.1, 1.0, 2.5, 3.3, 7.0, 10.0] {
        let a = p2_amplification(w, &rule, 1);
        let det = a[0][0] * a[1][1] - a[0][1] * a[1][0];
        let tr = a[0][0] + a[1][1];
        let w2 = w * w;
        let w4 = w2 * w2;
        let expect = 2.0 * (3.0 * w4 - 104.0 * w2 + 240.0) / (w4 + 16.0 * w2 + 240.0);
        assert!((det - 1.0).abs() < 1e-12, "W={w}: det {det}");
        assert!((tr - expect).abs() < 1e-12, "W={w}: trace {tr} vs {expect}");
    }
    // Spectral radius 3 at W = 10 (docs/method.md §4.5).
    let r = spectral_radius_2x2(&p2_amplification(10.0, &rule, 1));
    assert!((r - 3.0).abs() < 0.05, "{r}");
}

/// W_crit = sqrt(10) for one layer and 3 points; about pi / n per
/// layer with n layers, i.e. about pi for the whole step
/// (docs/method.md §4.5: 1.571 per layer for 2 layers, 1.048 for 3).
#[test]
fn critical_products() {
    let rule = GaussRule::new(3).unwrap();
    let w1 = p2_critical_w_dt(&rule, 1).unwrap();
    assert!((w1 - 10f64.sqrt()).abs() < 1e-9, "{w1}");
    let w2 = p2_critical_w_dt(&rule, 2).unwrap();
    assert!((w2 / 2.0 - 1.571).abs() < 1e-3, "{w2}");
    let w3 = p2_critical_w_dt(&rule, 3).unwrap();
    assert!((w3 / 3.0 - 1.048).abs() < 1e-3, "{w3}");
}

/// The suggested Galerkin step keeps w_max dt within the limit, also as
/// printed with four digits, and loses at most two units of the fourth
/// digit (rounding down, and one more at a tie with the limit).
#[test]
fn galerkin_accurate_step_is_within_the_limit() {
    // The paper's 8-element PVC mesh: 31.62 / 2.998049e4 = 1.05478e-3 s.
    assert_eq!(galerkin_accurate_step(2.998049e4), 1.054e-3);
    for k in 0..2000 {
        let w = 10f64.powf(-3.0 + 0.01 * k as f64);
        let s = galerkin_accurate_step(w);
        assert!(w * s <= GALERKIN_ACCURATE_W_DT, "{w}: {s}");
        assert!(w * s > GALERKIN_ACCURATE_W_DT * (1.0 - 2e-3), "{w}: {s}");
        let shown: f64 = format!("{s:.4e}").parse().unwrap();
        assert!(w * shown <= GALERKIN_ACCURATE_W_DT, "{w}: {shown}");
    }
}

/// x'' + x = 0, x(0) = 1, to t = 1 with steps of 1/8: the errors the
/// issue quotes (one layer 1.4e-7, two layers 5.9e-9, one layer at
/// 1/16 8.9e-9).
#[test]
fn oscillator_errors_with_layers() {
    let rule = GaussRule::new(3).unwrap();
    let err = |dt: f64, layers: usize| {
        let a = p2_amplification(dt, &rule, layers);
        let (mut x, mut v) = (1.0, 0.0);
        for _ in 0..(1.0 / dt).round() as usize {
            let nx = a[0][0] * x + a[0][1] * v;
            let nv = a[1][0] * x + a[1][1] * v;
            x = nx;
            v = nv;
        }
        (x - 1f64.cos()).abs()
    };
    let e1 = err(0.125, 1);
    let e2 = err(0.125, 2);
    let e3 = err(0.0625, 1);
    assert!((e1 / 1.4255e-7 - 1.0).abs() < 1e-3, "{e1:e}");
    assert!((e2 / 5.9405e-9 - 1.0).abs() < 1e-3, "{e2:e}");
    assert!((e3 / 8.9147e-9 - 1.0).abs() < 1e-3, "{e3:e}");
}
