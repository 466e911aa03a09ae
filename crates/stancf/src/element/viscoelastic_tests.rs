use super::*;

const EA: f64 = 1.424e8;

fn constant() -> Viscoelastic {
    Viscoelastic {
        dynamic: DynamicStiffness::Constant(1.9e8),
        static_damping: 4e7,
        dynamic_damping: 2e6,
    }
}

fn mean_load() -> Viscoelastic {
    Viscoelastic {
        dynamic: DynamicStiffness::MeanLoad {
            alpha: 1.586e8,
            beta: 0.4,
        },
        static_damping: 4e9,
        dynamic_damping: 11e6,
    }
}

#[test]
fn the_mean_load_stiffness_is_alpha_plus_beta_times_the_static_springs_tension() {
    let v = mean_load();
    for eps1 in [0.0, 1e-3, 0.05, 0.4] {
        let s = v.springs(EA, eps1);
        let (alpha, beta) = (1.586e8, 0.4);
        let rule = alpha + beta * s.k1 * eps1;
        assert!(
            (s.k2 - rule).abs() <= 1e-12 * s.k2,
            "k2 {} rule {rule}",
            s.k2
        );
        // Series: 1/k1 + 1/k2 = 1/EA.
        assert!((1.0 / s.k1 + 1.0 / s.k2 - 1.0 / EA).abs() <= 1e-12 / EA);
        if eps1 == 0.0 {
            continue; // k2 has a kink at zero (alpha below)
        }
        // Derivatives against central differences.
        let h = 1e-7;
        let (p, m) = (v.springs(EA, eps1 + h), v.springs(EA, eps1 - h));
        let fd2 = (p.k2 - m.k2) / (2.0 * h);
        let fd1 = (p.k1 - m.k1) / (2.0 * h);
        assert!(
            (fd2 - s.dk2).abs() <= 1e-6 * s.dk2.abs().max(1.0),
            "dk2 {} fd {fd2}",
            s.dk2
        );
        assert!(
            (fd1 - s.dk1).abs() <= 1e-6 * s.dk1.abs().max(1.0),
            "dk1 {} fd {fd1}",
            s.dk1
        );
    }
    // Below zero the stiffness is alpha, continuous at zero when alpha > EA.
    assert_eq!(v.springs(EA, -0.01).k2, 1.586e8);
    assert!((v.springs(EA, 0.0).k2 - 1.586e8).abs() <= 1e-6);
}

#[test]
fn at_rest_a_viscoelastic_line_carries_the_static_ea_times_its_strain() {
    for v in [constant(), mean_load()] {
        for eps in [-0.01, 0.0, 0.002, 0.08, 1.0] {
            let eps1 = v.rest_state(EA, eps, 0.0);
            let f = v.force(EA, eps1, 0.0, eps, 0.0, false);
            assert!(
                f.rate.abs() <= 1e-12 * (eps.abs() + 1e-300),
                "rate {}",
                f.rate
            );
            let n = EA * eps;
            assert!(
                (f.force - n).abs() <= 1e-9 * n.abs().max(1.0),
                "N {} vs {n}",
                f.force
            );
        }
    }
}

#[test]
fn the_force_and_rate_derivatives_are_their_finite_differences() {
    for v in [constant(), mean_load()] {
        let x = [0.03, 0.05, 0.2];
        let f = v.force(EA, x[0], 0.0, x[1], x[2], false);
        for k in 0..3 {
            let h = 1e-7;
            let mut p = x;
            let mut m = x;
            p[k] += h;
            m[k] -= h;
            let fp = v.force(EA, p[0], 0.0, p[1], p[2], false);
            let fm = v.force(EA, m[0], 0.0, m[1], m[2], false);
            let d_rate = (fp.rate - fm.rate) / (2.0 * h);
            let d_force = (fp.force - fm.force) / (2.0 * h);
            let scale_rate = f.rate_d.iter().map(|c| c.abs()).fold(0.0, f64::max);
            let scale_force = f.force_d.iter().map(|c| c.abs()).fold(0.0, f64::max);
            assert!(
                (d_rate - f.rate_d[k]).abs() <= 1e-6 * scale_rate,
                "rate_d[{k}]"
            );
            assert!(
                (d_force - f.force_d[k]).abs() <= 1e-6 * scale_force,
                "force_d[{k}]"
            );
        }
    }
}

/// Nodes: `points` Gauss points on [0, 1] and the end.
fn nodes(points: usize) -> Vec<f64> {
    let mut t: Vec<f64> = crate::quadrature::GaussRule::shared(points)
        .iter()
        .map(|(x, _)| x)
        .collect();
    t.push(1.0);
    t
}

/// eps1 at t = 1 s under eps = a sin(w t) from eps1(0) = 0, by `steps`
/// collocation steps, and exactly (the linear (V2) with constant k2).
fn sine_drive(points: usize, steps: usize) -> (f64, f64) {
    let v = constant();
    let (a, w) = (0.01, 7.0);
    let s = v.springs(EA, 0.0);
    let (k, c) = (s.k1 + s.k2, v.static_damping + v.dynamic_damping);
    let dt = 1.0 / steps as f64;
    let taus = nodes(points);
    let col = Collocation::new(&taus, dt);
    let mut eps1 = 0.0;
    for step in 0..steps {
        let t0 = step as f64 * dt;
        let eps: Vec<f64> = taus
            .iter()
            .map(|tau| a * (w * (t0 + tau * dt)).sin())
            .collect();
        let rate: Vec<f64> = taus
            .iter()
            .map(|tau| a * w * (w * (t0 + tau * dt)).cos())
            .collect();
        let slack = vec![false; taus.len()];
        eps1 = v
            .collocate(EA, &col, (eps1, 0.0), &eps, &rate, &slack)
            .state[taus.len() - 1];
    }
    // Exact: the particular solution a Im(H e^{iwt}), H = (k2 + i w c2) /
    // (k + i w c), and the homogeneous one decaying at k / c.
    let (hr, hi) = {
        let (nr, ni) = (s.k2, w * v.dynamic_damping);
        let (dr, di) = (k, w * c);
        let d = dr * dr + di * di;
        ((nr * dr + ni * di) / d, (ni * dr - nr * di) / d)
    };
    let particular = |t: f64| a * (hr * (w * t).sin() + hi * (w * t).cos());
    let exact = particular(1.0) + (0.0 - particular(0.0)) * (-k / c * 1.0).exp();
    (eps1, exact)
}

#[test]
fn the_collocation_converges_at_order_twice_its_gauss_points() {
    // In the asymptotic range: k dt / c below 0.6 (at coarser steps the
    // error of this stiff drive changes sign).
    for (points, steps) in [(2, 64), (3, 32)] {
        let (e1, exact) = sine_drive(points, steps);
        let (e2, _) = sine_drive(points, 2 * steps);
        let (err1, err2) = ((e1 - exact).abs(), (e2 - exact).abs());
        let order = (err1 / err2).log2();
        assert!(
            (order - 2.0 * points as f64).abs() < 0.2,
            "{points} points: errors {err1:e} {err2:e}, order {order}"
        );
    }
}

#[test]
fn a_dashpot_far_faster_than_the_step_leaves_no_oscillation() {
    // c / k = 1e-9 s against dt = 0.1 s: from a state far from rest the
    // end of one step is at rest under the held strain (L-stability).
    let v = Viscoelastic {
        static_damping: 0.1,
        dynamic_damping: 0.0,
        ..constant()
    };
    let taus = nodes(3);
    let col = Collocation::new(&taus, 0.1);
    let eps = vec![0.02; taus.len()];
    let zero = vec![0.0; taus.len()];
    let out = v.collocate(EA, &col, (0.5, 0.0), &eps, &zero, &vec![false; taus.len()]);
    let rest = v.rest_state(EA, 0.02, 0.0);
    let end = out.state[taus.len() - 1];
    assert!((end - rest).abs() <= 1e-6 * rest, "end {end} rest {rest}");
}

#[test]
fn the_collocated_forces_derivatives_are_their_finite_differences() {
    for v in [constant(), mean_load()] {
        let taus = nodes(3);
        let n = taus.len();
        let col = Collocation::new(&taus, 0.05);
        let eps: Vec<f64> = taus.iter().map(|t| 0.03 + 0.01 * t).collect();
        let rate: Vec<f64> = taus.iter().map(|t| 0.2 - 0.1 * t).collect();
        let slack = vec![false; n];
        let out = v.collocate(EA, &col, (0.02, 0.0), &eps, &rate, &slack);
        for h in 0..n {
            for (which, base) in [(0, &eps), (1, &rate)] {
                let step = 1e-7;
                let (mut p, mut m) = (base.clone(), base.clone());
                p[h] += step;
                m[h] -= step;
                let (fp, fm) = if which == 0 {
                    (
                        v.collocate(EA, &col, (0.02, 0.0), &p, &rate, &slack),
                        v.collocate(EA, &col, (0.02, 0.0), &m, &rate, &slack),
                    )
                } else {
                    (
                        v.collocate(EA, &col, (0.02, 0.0), &eps, &p, &slack),
                        v.collocate(EA, &col, (0.02, 0.0), &eps, &m, &slack),
                    )
                };
                for g in 0..n {
                    let fd = (fp.force[g] - fm.force[g]) / (2.0 * step);
                    let exact = if which == 0 {
                        out.d_eps[g][h]
                    } else {
                        out.d_rate[g][h]
                    };
                    let scale = out.d_eps[g]
                        .iter()
                        .chain(out.d_rate[g].iter())
                        .map(|c| c.abs())
                        .fold(0.0, f64::max);
                    assert!(
                        (fd - exact).abs() <= 1e-6 * scale,
                        "dN_{g}/d({which})_{h}: {exact:e} fd {fd:e}"
                    );
                }
            }
        }
    }
}

#[test]
fn a_dynamic_stiffness_not_above_the_static_ea_is_refused_by_name() {
    let bad = Viscoelastic {
        dynamic: DynamicStiffness::Constant(1e8),
        ..constant()
    };
    let e = bad
        .check(EA, "line_types[0].ea_dynamic")
        .unwrap_err()
        .to_string();
    assert!(
        e.contains("line_types[0].ea_dynamic") && e.contains("static EA"),
        "{e}"
    );
    let undamped = Viscoelastic {
        static_damping: 0.0,
        dynamic_damping: 0.0,
        ..constant()
    };
    assert!(undamped.check(EA, "k").is_err());
    assert!(constant().check(EA, "k").is_ok() && mean_load().check(EA, "k").is_ok());
}

#[test]
fn the_collocation_integrates_polynomials_of_its_degree_on_every_time_rule() {
    // int_0^tau_i s^k ds = tau_i^(k+1) / (k + 1) for k < n: the rows of
    // dt A applied to the nodes' s^k, up to the largest rule (10 points).
    for points in 1..=crate::quadrature::MAX_POINTS {
        let taus = nodes(points);
        let dt = 0.3;
        let col = Collocation::new(&taus, dt);
        for k in 0..taus.len() {
            for (i, &ti) in taus.iter().enumerate() {
                let sum: f64 = (0..taus.len())
                    .map(|j| col.dt_a[i][j] * (taus[j] * dt).powi(k as i32))
                    .sum();
                let exact = (ti * dt).powi(k as i32 + 1) / (k as f64 + 1.0);
                assert!(
                    (sum - exact).abs() <= 1e-11 * dt,
                    "{points} points, s^{k} at node {i}: {sum} vs {exact}"
                );
            }
        }
    }
}

fn syrope_law() -> Viscoelastic {
    let owc = [
        (2.06897e-3, 1.71768e5),
        (1.24138e-2, 8.66556e5),
        (3.10345e-2, 1.89540e6),
        (6.0e-2, 4.38601e6),
    ];
    let curves = super::super::syrope::Syrope::new(
        &owc,
        super::super::syrope::WorkingCurveForm::Exponential,
        (0.2, 1.5),
        (1.53e8, 23.12),
        "k",
    )
    .unwrap();
    Viscoelastic {
        dynamic: DynamicStiffness::Syrope {
            curves: std::sync::Arc::new(curves),
            tmax0: 1.302e6,
        },
        static_damping: 5e6,
        dynamic_damping: 1e5,
    }
}

#[test]
fn syropes_force_and_rate_derivatives_are_their_finite_differences() {
    // A state inside a segment of the working curve and one on the
    // original curve (beyond Tmax), away from the tables' points.
    let v = syrope_law();
    let tmax = 1.302e6;
    for x in [[0.0105, 0.0112, 0.01], [0.0262, 0.0301, -0.02]] {
        let f = v.force(EA, x[0], tmax, x[1], x[2], false);
        for k in 0..3 {
            let h = 1e-9;
            let (mut p, mut m) = (x, x);
            p[k] += h;
            m[k] -= h;
            let fp = v.force(EA, p[0], tmax, p[1], p[2], false);
            let fm = v.force(EA, m[0], tmax, m[1], m[2], false);
            let d_rate = (fp.rate - fm.rate) / (2.0 * h);
            let d_force = (fp.force - fm.force) / (2.0 * h);
            let sr = f.rate_d.iter().map(|c| c.abs()).fold(0.0, f64::max);
            let sf = f.force_d.iter().map(|c| c.abs()).fold(0.0, f64::max);
            assert!(
                (d_rate - f.rate_d[k]).abs() <= 1e-6 * sr,
                "rate_d[{k}] at {x:?}"
            );
            assert!(
                (d_force - f.force_d[k]).abs() <= 1e-6 * sf,
                "force_d[{k}] at {x:?}"
            );
        }
        // At rest under its strain the rate vanishes and the tension is
        // the curve's.
        let z = v.rest_state(EA, x[1], tmax);
        let rest = v.force(
            EA,
            z,
            tmax.max(v.history_after(tmax, &[z])),
            x[1],
            0.0,
            false,
        );
        assert!(rest.rate.abs() < 1e-9, "{}", rest.rate);
    }
}
