use super::*;
use crate::scenario::moordyn_wave_frequencies::WaveComponent;
use stancf::water::kinematics::Sea;
use stancf::water::waves::wave_number;

/// A file's rows `(w, re, im, beta)`.
fn rows(r: &[(f64, f64, f64, f64)]) -> Vec<WaveComponent> {
    r.iter()
        .enumerate()
        .map(|(i, &(omega, re, im, heading))| WaveComponent {
            omega,
            amplitude: [re, im],
            heading,
            line: i + 1,
        })
        .collect()
}

/// MoorDyn's grid (WaveGrid.cpp, `fillWaveGrid`) at (x, y, z) and sample
/// n, written out as its inverse transform: zeta_k = nw_1 a_k e^(-i k_k
/// l_k) for the N/2 + 1 = nw grid frequencies, the velocity's transforms
/// w zeta C cos(beta), w zeta C sin(beta), i w zeta S, and kiss_fftri's
/// real inverse over the Hermitian spectrum (the real parts of the first
/// and last bins, the others twice) divided by N. The reference the
/// waves (W2d) must meet at the samples: eta, u_x, u_y, u_z.
fn moordyn_grid_sample(grid: &[(f64, [f64; 2], f64)], p: [f64; 3], n: usize, h: f64) -> [f64; 4] {
    let nw = grid.len();
    let big_n = 2 * (nw - 1);
    let mut out = [0.0; 4];
    for (k, &(w, a, beta)) in grid.iter().enumerate() {
        let kk = wave_number(w, h, 9.81);
        let l = beta.cos() * p[0] + beta.sin() * p[1];
        // zeta = (nw - 1) a e^(-i kk l)
        let (c, s) = ((kk * l).cos(), -(kk * l).sin());
        let scale = (nw - 1) as f64;
        let zeta = [scale * (a[0] * c - a[1] * s), scale * (a[0] * s + a[1] * c)];
        let (cf, sf) = if kk == 0.0 {
            (0.0, 1.0)
        } else {
            (
                (kk * (p[2] + h)).cosh() / (kk * h).sinh(),
                (kk * (p[2] + h)).sinh() / (kk * h).sinh(),
            )
        };
        let spectra = [
            zeta,
            [w * zeta[0] * cf * beta.cos(), w * zeta[1] * cf * beta.cos()],
            [w * zeta[0] * cf * beta.sin(), w * zeta[1] * cf * beta.sin()],
            [-w * zeta[1] * sf, w * zeta[0] * sf],
        ];
        let angle = 2.0 * PI * (k * n) as f64 / big_n as f64;
        for (o, x) in out.iter_mut().zip(spectra) {
            let re_part = x[0] * angle.cos() - x[1] * angle.sin();
            *o += if k == 0 || k == nw - 1 {
                x[0] * angle.cos()
            } else {
                2.0 * re_part
            } / big_n as f64;
        }
    }
    out
}

/// The tests' wavekin_2 file on its even grid (0 to 0.6 rad/s by 0.05,
/// then 6 rad/s), with headings given to two rows: its waves have
/// MoorDyn's grid's elevation and velocity at every sample of a period,
/// at points along the line and across it, to round-off.
#[test]
fn moordyns_fft_grid_samples_the_waves_of_its_spectrum() {
    let mut r = vec![(0.0, 0.0, 0.0, 0.0)];
    for k in 1..=12 {
        let (re, im) = match k {
            4 => (0.5, 0.0),
            5 => (0.2, 0.0),
            8 => (0.0, 1.0),
            9 => (0.0, 0.5),
            _ => (0.0, 0.0),
        };
        let beta = if k == 5 {
            0.7
        } else if k == 9 {
            -2.0
        } else {
            0.0
        };
        r.push((0.05 * k as f64, re, im, beta));
    }
    r.push((6.0, 0.0, 0.0, 0.0));
    let (waves, dw) = fft_grid_waves(&rows(&r)).unwrap();
    assert!((dw - 0.05).abs() < 1e-15, "{dw}");
    assert_eq!(waves.len(), 4, "{waves:?}");
    // MoorDyn's grid: the file's rows, then zeros up to 6 rad/s.
    let nw = (6.0_f64 / dw).floor() as usize + 1;
    let grid: Vec<(f64, [f64; 2], f64)> = (0..nw)
        .map(|k| {
            let row = r.get(k).filter(|_| k <= 12).copied();
            let (re, im, beta) = row.map_or((0.0, 0.0, 0.0), |x| (x.1, x.2, x.3));
            (k as f64 * dw, [re, im], beta)
        })
        .collect();
    let h = 50.0;
    let sea = Sea::new(h, 9.81, &waves).unwrap();
    let big_n = 2 * (nw - 1);
    let dt = 2.0 * PI / (big_n as f64 * dw);
    let largest = [1.7, 0.6, 0.6, 0.6];
    for p in [
        [-400.0, 0.0, -49.0],
        [-130.0, 25.0, -20.0],
        [0.0, -3.0, -2.0],
    ] {
        for n in (0..big_n).step_by(7) {
            let want = moordyn_grid_sample(&grid, p, n, h);
            let got = sea.kinematics(&p, n as f64 * dt);
            let have = [got.eta, got.velocity[0], got.velocity[1], got.velocity[2]];
            for i in 0..4 {
                assert!(
                    (have[i] - want[i]).abs() < 1e-12 * largest[i],
                    "{i} at {p:?}, sample {n}: {have:?} against MoorDyn's {want:?}"
                );
            }
        }
    }
}

/// Rows between the grid's frequencies are interpolated linearly, the
/// amplitude's parts and the heading alike, as MoorDyn's
/// `interpEvenlySpaced` does.
#[test]
fn uneven_rows_are_interpolated_onto_the_even_grid() {
    let r = rows(&[
        (0.0, 0.0, 0.0, 0.0),
        (0.1, 1.0, 0.0, 0.0),
        (0.3, 0.0, 2.0, 1.0),
        (0.4, 0.0, 0.0, 0.0),
    ]);
    let (waves, dw) = fft_grid_waves(&r).unwrap();
    assert!((dw - 0.1).abs() < 1e-15);
    let middle = waves
        .iter()
        .find(|w| (w.period - 2.0 * PI / 0.2).abs() < 1e-9)
        .unwrap();
    assert!(
        (middle.amplitude - 0.5_f64.hypot(1.0)).abs() < 1e-12,
        "{middle:?}"
    );
    assert!(
        (middle.heading_deg - 0.5_f64.to_degrees()).abs() < 1e-9,
        "{middle:?}"
    );
    assert!((middle.phase_deg + 2.0_f64.atan2(1.0).to_degrees()).abs() < 1e-9);
    assert_eq!(waves.len(), 3, "{waves:?}");
}

#[test]
fn what_moordyns_grid_cannot_make_a_wave_of_is_refused_naming_the_row() {
    for (r, needles) in [
        (
            vec![(0.1, 0.0, 0.0, 0.0), (0.2, 1.0, 0.0, 0.0)],
            vec!["line 1", "starts at 0"],
        ),
        (
            vec![
                (0.0, 0.0, 0.0, 0.0),
                (0.2, 1.0, 0.0, 0.0),
                (0.2, 1.0, 0.0, 0.0),
            ],
            vec!["line 3", "ascending"],
        ),
        (
            vec![
                (0.0, 0.4, 0.0, 0.0),
                (0.2, 1.0, 0.0, 0.0),
                (0.4, 0.0, 0.0, 0.0),
            ],
            vec!["line 1", "0.2 m", "z = 0"],
        ),
        (
            vec![
                (0.0, 0.0, 0.0, 0.0),
                (0.2, 1.0, 0.0, 0.0),
                (0.4, 0.0, 0.1, 0.0),
            ],
            vec!["line 3", "Nyquist", "no amplitude"],
        ),
        (
            vec![
                (0.0, 0.0, 0.0, 0.0),
                (1e-9, 1.0, 0.0, 0.0),
                (2.0, 0.0, 0.0, 0.0),
            ],
            vec!["frequencies", "space the rows more evenly"],
        ),
    ] {
        let e = fft_grid_waves(&rows(&r)).unwrap_err();
        for n in needles {
            assert!(e.contains(n), "{n}: {e}");
        }
    }
}

/// The tests' wavekin_2 record (eta = sin(2 pi t / 15) every 0.15 s to
/// 15 s) at MoorDyn's dtWave 0.15 read as a float: 100 samples (101
/// less one, the count being odd), one wave of amplitude 1 and period
/// N dtWave = 15.0000006 s; the series passes through every resampled
/// sample (W2d), and the resampled samples lie on the sine to the
/// interpolation's error over the float's 6e-9 s shift per sample (at
/// most 6e-7 s by the 100th, 3e-7 m on a slope of 0.42 m/s).
#[test]
fn an_elevation_record_becomes_the_series_moordyns_grid_samples() {
    let text: String = (0..=100)
        .map(|i| {
            let t = 0.15 * i as f64;
            format!("{t} {}\n", (2.0 * PI * t / 15.0).sin())
        })
        .collect();
    let dt = SupportedOption::WaveTimeStep.as_moordyn_reads(0.15);
    assert!(dt > 0.15 && dt - 0.15 < 1e-8, "{dt}");
    let r = record_waves(&text, dt).unwrap();
    assert_eq!(r.samples, 100);
    assert!(r.mean.abs() < 1e-15, "{}", r.mean);
    assert_eq!(r.dropped_nyquist, 0.0);
    // The float's shift makes the resampled record not quite periodic:
    // MoorDyn's grid holds six more terms of < 1e-7 m, and so does the
    // series.
    let big: Vec<_> = r.waves.iter().filter(|w| w.amplitude > 1e-7).collect();
    assert_eq!(big.len(), 1, "{:?}", r.waves);
    let period = 100.0 * dt;
    assert!((big[0].period - period).abs() < 1e-12, "{:?}", big[0]);
    assert!((big[0].amplitude - 1.0).abs() < 1e-6, "{:?}", big[0]);
    assert!((big[0].phase_deg - 90.0).abs() < 1e-4, "{:?}", big[0]);
    let sea = Sea::new(50.0, 9.81, &r.waves).unwrap();
    for n in 0..100 {
        let t = n as f64 * dt;
        let have = sea.kinematics(&[0.0, 0.0, -10.0], t).eta;
        let want = (2.0 * PI * t / 15.0).sin();
        assert!(
            (have - want).abs() < 1e-6,
            "sample {n}: {have} against {want}"
        );
    }
}

#[test]
fn a_record_moordyn_cannot_grid_is_refused_naming_its_line() {
    for (text, needles) in [
        ("0 0\n0.5 0.1\n0.5 0.2\n", vec!["line 3", "does not rise"]),
        ("0 0\n0.1 0.1\n", vec!["two samples"]),
        ("0 0\n1 x\n", vec!["line 2", "\"x\""]),
        ("0\n", vec!["line 1", "at least 2"]),
        ("0 0\n1e12 0.1\n", vec!["samples", "larger dtWave"]),
        ("0 0\n1 0.1\n", vec!["samples", "larger dtWave"]),
    ] {
        let dt = if text.starts_with("0 0\n1 ") {
            1e-8
        } else {
            0.25
        };
        let e = record_waves(text, dt).unwrap_err();
        for n in needles {
            assert!(e.contains(n), "{n}: {e}");
        }
    }
}
