//! The regular waves of a sampled elevation record: its discrete Fourier
//! series (docs/method.md §12.1, (W2c)-(W2d)).
//!
//! N elevations eta_n sampled every dt at the origin (x = y = 0) over one
//! period N dt have the discrete Fourier transform
//!
//! ```text
//!   X_k = sum_{n=0}^{N-1} eta_n e^(-2 pi i k n / N),   k = 0 .. N-1      (W2c)
//! ```
//!
//! and, eta being real (X_{N-k} = conj X_k), the samples are exactly
//!
//! ```text
//!   eta_n = X_0 / N + sum_{0<k<N/2} (2 |X_k| / N) cos(w_k t_n + arg X_k)
//!           + [N even] (X_{N/2} / N) (-1)^n,     w_k = 2 pi k / (N dt)  (W2d)
//! ```
//!
//! Each term 0 < k < N/2 is a wave (W2) of heading beta passing the
//! origin: at x = y = 0 (W2) is A cos(-w t + phi) = A cos(w t - phi), so
//! A = 2 |X_k| / N, T = 2 pi / w_k and phi = -arg X_k. The mean X_0 / N
//! (a still level) and the term at the Nyquist frequency (an alternation
//! of sign at the samples, which no single wave of linear theory makes)
//! are returned apart: what to do with them is the caller's.

use super::waves::AiryWave;
use std::f64::consts::PI;

/// A record's series (W2d): its waves, its mean and the amplitude of its
/// Nyquist term (0 for an odd number of samples).
#[derive(Clone, Debug, PartialEq)]
pub struct RecordSeries {
    pub waves: Vec<AiryWave>,
    pub mean: f64,
    pub nyquist: f64,
}

/// The series (W2d) of `elevation` sampled every `dt` (s), its waves
/// heading `heading_deg`, keeping the terms 0 < k < N/2 with w_k <=
/// `highest_omega` (rad/s). The transform (W2c) is summed directly for
/// those k only, with the twiddle factors of the exact angles
/// 2 pi (k n mod N) / N: N K operations for K terms kept, a second for a
/// three-hour record at 4 Hz and 0.5 Hz. Its round-off is that of a sum
/// of N terms, |dX_k| <= (N + 2) eps sum |eta_n| <= (N + 2) eps N
/// max |eta|, so an amplitude 2 |X_k| / N at or below
/// [`round_off_amplitude`] cannot be told from zero and is left out (a
/// sampled sine keeps its one wave, not N/2 - 1 of 1e-16 m).
pub fn record_series(
    elevation: &[f64],
    dt: f64,
    heading_deg: f64,
    highest_omega: f64,
) -> RecordSeries {
    let n = elevation.len();
    if n == 0 {
        return RecordSeries {
            waves: Vec::new(),
            mean: 0.0,
            nyquist: 0.0,
        };
    }
    let twiddles: Vec<(f64, f64)> = (0..n)
        .map(|j| (2.0 * PI * j as f64 / n as f64).sin_cos())
        .map(|(s, c)| (c, -s))
        .collect();
    let transform = |k: usize| {
        elevation
            .iter()
            .enumerate()
            .fold((0.0, 0.0), |(re, im), (m, eta)| {
                let (c, s) = twiddles[(k * m) % n];
                (re + eta * c, im + eta * s)
            })
    };
    let mean = elevation.iter().sum::<f64>() / n as f64;
    let nyquist = if n.is_multiple_of(2) {
        elevation
            .iter()
            .enumerate()
            .map(|(m, eta)| if m % 2 == 0 { *eta } else { -eta })
            .sum::<f64>()
            / n as f64
    } else {
        0.0
    };
    let period = n as f64 * dt;
    let floor = round_off_amplitude(elevation);
    let mut waves = Vec::new();
    for k in 1..n.div_ceil(2) {
        let omega = 2.0 * PI * k as f64 / period;
        if omega > highest_omega {
            break;
        }
        let (re, im) = transform(k);
        let amplitude = 2.0 * re.hypot(im) / n as f64;
        if amplitude <= floor {
            continue;
        }
        waves.push(AiryWave {
            amplitude,
            period: period / k as f64,
            heading_deg,
            phase_deg: -im.atan2(re).to_degrees(),
        });
    }
    RecordSeries {
        waves,
        mean,
        nyquist,
    }
}

/// The bound 2 (N + 2) eps max |eta| on the round-off of a term's
/// amplitude in the series of the N samples `elevation` (W2c).
pub fn round_off_amplitude(elevation: &[f64]) -> f64 {
    let largest = elevation.iter().fold(0.0_f64, |m, e| m.max(e.abs()));
    2.0 * (elevation.len() + 2) as f64 * f64::EPSILON * largest
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::water::kinematics::Sea;

    /// A record of three waves and a still level, band-limited below the
    /// Nyquist frequency: the series' waves are the three, and the sea of
    /// them, with the mean and the Nyquist term, passes through every
    /// sample (W2d) to round-off.
    #[test]
    fn the_series_of_a_record_passes_through_its_samples() {
        let (n, dt) = (64, 0.5);
        let period = n as f64 * dt;
        let terms = [(1, 0.8, 0.3), (3, 0.25, -2.0), (7, 0.05, 1.1)];
        let (level, alternation) = (0.12, 0.01);
        let eta: Vec<f64> = (0..n)
            .map(|m| {
                let t = m as f64 * dt;
                let waves: f64 = terms
                    .iter()
                    .map(|&(k, a, p)| a * (2.0 * PI * k as f64 * t / period + p).cos())
                    .sum();
                level
                    + waves
                    + if m % 2 == 0 {
                        alternation
                    } else {
                        -alternation
                    }
            })
            .collect();
        let s = record_series(&eta, dt, 30.0, f64::INFINITY);
        assert!((s.mean - level).abs() < 1e-15, "{}", s.mean);
        assert!((s.nyquist - alternation).abs() < 1e-15, "{}", s.nyquist);
        assert_eq!(s.waves.len(), 3, "{:?}", s.waves);
        for (w, &(k, a, p)) in s.waves.iter().zip(&terms) {
            assert!((w.amplitude - a).abs() < 1e-14, "{w:?}");
            assert!((w.period - period / k as f64).abs() < 1e-12, "{w:?}");
            assert!((w.phase_deg + p.to_degrees()).abs() < 1e-11, "{w:?}");
            assert_eq!(w.heading_deg, 30.0);
        }
        let sea = Sea::new(200.0, 9.81, &s.waves).unwrap();
        for (m, want) in eta.iter().enumerate() {
            let t = m as f64 * dt;
            let nyquist = if m % 2 == 0 { s.nyquist } else { -s.nyquist };
            let have = sea.kinematics(&[0.0, 0.0, -5.0], t).eta + s.mean + nyquist;
            assert!(
                (have - want).abs() < 1e-14,
                "sample {m}: {have} against {want}"
            );
        }
    }

    /// Terms above the highest frequency are left out, and an odd record
    /// has no Nyquist term.
    #[test]
    fn terms_above_the_highest_frequency_are_left_out() {
        let (n, dt) = (21, 1.0);
        let eta: Vec<f64> = (0..n)
            .map(|m| {
                let t = m as f64 * dt;
                (2.0 * PI * t / 21.0).cos() + 0.5 * (2.0 * PI * 8.0 * t / 21.0).sin()
            })
            .collect();
        let highest = 2.0 * PI * 5.0 / 21.0;
        let s = record_series(&eta, dt, 0.0, highest);
        assert_eq!(s.nyquist, 0.0);
        assert!(s.waves.iter().all(|w| 2.0 * PI / w.period <= highest));
        let largest = s.waves.iter().map(|w| w.amplitude).fold(0.0, f64::max);
        assert!((largest - 1.0).abs() < 1e-14, "{:?}", s.waves);
        assert_eq!(s.waves.len(), 1, "{:?}", s.waves);
    }
}
