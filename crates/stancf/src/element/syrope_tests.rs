use super::*;

/// MoorDyn's test rope (tests/Mooring/syrope/owc.dat as MoorDyn reads it,
/// its first row skipped with the headers): a few of its points.
fn rope(form: WorkingCurveForm, k1: f64, k2: f64) -> Syrope {
    let owc = [
        (2.06897e-3, 1.71768e5),
        (6.20690e-3, 4.78788e5),
        (1.24138e-2, 8.66556e5),
        (2.06897e-2, 1.32880e6),
        (3.10345e-2, 1.89540e6),
        (4.13793e-2, 2.56220e6),
        (6.00000e-2, 4.38601e6),
    ];
    Syrope::new(&owc, form, (k1, k2), (1.53e8, 23.12), "syrope").unwrap()
}

#[test]
fn a_working_curve_runs_from_its_least_strain_to_the_original_curve_at_tmax() {
    for (form, k1, k2) in [
        (WorkingCurveForm::Linear, 1.25e8, 0.0),
        (WorkingCurveForm::Quadratic, 0.25, 1.0),
        (WorkingCurveForm::Exponential, 0.2, 1.5),
    ] {
        let r = rope(form, k1, k2);
        let tmax = 1.302e6;
        let (x, y, z) = r.working_curve(tmax);
        let n = x.len() - 1;
        let eps_max = r.strain_at(tmax);
        assert!((x[n] - eps_max).abs() < 1e-15 && (y[n] - tmax).abs() < 1e-9 * tmax);
        assert_eq!(y[0], 0.0);
        let eps_min = match form {
            WorkingCurveForm::Linear => eps_max - tmax / k1,
            _ => 2.06897e-3 + k1 * (eps_max - 2.06897e-3),
        };
        assert!((x[0] - eps_min).abs() < 1e-15, "{form:?}");
        // (V7) at every point, and the slope of the linear form is k1.
        for i in 0..=n {
            let zi = x[i] - (1.0 + 23.12 * y[i] / 1.53e8).ln() / 23.12;
            assert!((z[i] - zi).abs() < 1e-15);
        }
        if form == WorkingCurveForm::Linear {
            assert!(((y[n] - y[0]) / (x[n] - x[0]) - k1).abs() < 1e-6 * k1);
        }
    }
}

#[test]
fn the_spring_follows_the_working_curve_below_tmax_and_the_original_curve_beyond() {
    let r = rope(WorkingCurveForm::Exponential, 0.2, 1.5);
    let tmax = 1.302e6;
    r.check_tmax(tmax, "tmax").unwrap();
    let (x, y, _) = r.working_curve(tmax);
    // Below: the WC's tension at rest; beyond eps_max: the OWC's.
    for eps in [x[3], 0.5 * (x[10] + x[11]), x[28]] {
        let t = r.tension_at_rest(eps, tmax);
        let z = r.slow_strain_at_rest(t, tmax);
        let s = r.spring(z, tmax);
        assert!((s.tension - t).abs() < 1e-9 * tmax, "{} vs {t}", s.tension);
        assert!(
            (s.strain_at_rest - eps).abs() < 1e-12,
            "{} vs {eps}",
            s.strain_at_rest
        );
        assert!(t < tmax && t >= 0.0 && t <= y[29]);
    }
    for eps in [0.025, 0.05] {
        let t = r.tension_at_rest(eps, tmax);
        let owc_t = super::interpolate(&r.x, &r.y, eps).0;
        assert!((t - owc_t).abs() < 1e-9 * t && t > tmax);
        let s = r.spring(r.slow_strain_at_rest(t, tmax), tmax);
        assert!((s.tension - t).abs() < 1e-9 * t);
    }
    // Continuous where the two meet: the OWC's slow strain at Tmax.
    let z_top = super::interpolate(&r.y, &r.z, tmax).0;
    let (below, above) = (r.spring(z_top - 1e-12, tmax), r.spring(z_top + 1e-12, tmax));
    assert!(
        (below.tension - above.tension).abs() < 1e-3,
        "{} {}",
        below.tension,
        above.tension
    );
}

#[test]
fn a_rope_whose_slow_strain_outruns_its_total_strain_is_refused() {
    // A static stiffness above the dynamic one: z falls along the curve.
    let steep = [(0.0, 0.0), (0.001, 1.0e6)];
    let e = Syrope::new(
        &steep,
        WorkingCurveForm::Linear,
        (1e8, 0.0),
        (1.53e8, 23.12),
        "k",
    )
    .unwrap_err()
    .to_string();
    assert!(e.contains("slow strains") && e.contains("k"), "{e}");
    let r = rope(WorkingCurveForm::Linear, 1.25e8, 0.0);
    assert!(r
        .check_tmax(1e9, "t")
        .unwrap_err()
        .to_string()
        .contains("at most"));
    assert!(r.check_tmax(1.302e6, "t").is_ok());
    // The quadratic form on this part of the curve rises at its top
    // faster than the dynamic stiffness: refused.
    let q = rope(WorkingCurveForm::Quadratic, 0.25, 1.0);
    assert!(q
        .check_tmax(1.302e6, "t")
        .unwrap_err()
        .to_string()
        .contains("do not rise"));
}
