//! Irregular long-crested seas from the JONSWAP spectrum
//! (docs/method.md §12.1, (W14)-(W16)).
//!
//! A sea state (Hs, Tp, gamma, heading) becomes a sum of regular Airy
//! waves at equally spaced frequencies over [0.5 wp, 4 wp], of amplitudes
//! sqrt(2 S(w) dw) and random phases drawn by SplitMix64 from a seed, so
//! a seed gives the same sea on every machine.

use super::waves::AiryWave;
use crate::error::ModelError;
use std::f64::consts::PI;

/// The components span [LOWEST_FREQUENCY wp, HIGHEST_FREQUENCY wp] (W15).
/// Below, the spectrum holds e^(-20) = 2e-9 of the variance (exactly, for
/// gamma = 1); above, 1 - e^(-5/4 / 4^4) = 0.49 % for gamma = 1 and less
/// for peakier spectra (0.32 % at gamma = 3.3).
pub const LOWEST_FREQUENCY: f64 = 0.5;
pub const HIGHEST_FREQUENCY: f64 = 4.0;

/// The JONSWAP spectral density S(w) (m^2 s) in the form of DNV-RP-C205
/// (2010) §3.5.5 with wp = 2 pi / Tp:
///
/// ```text
/// S_PM(w) = (5/16) Hs^2 wp^4 w^-5 exp(-(5/4) (w / wp)^-4)
/// S(w) = (1 - 0.287 ln gamma) S_PM(w)
///        gamma^exp(-(w - wp)^2 / (2 sigma^2 wp^2))                  (W14)
/// sigma = 0.07 for w <= wp, 0.09 for w > wp
/// ```
///
/// S_PM (Pierson-Moskowitz, gamma = 1) integrates to Hs^2/16 exactly:
/// S_PM = (Hs^2/16) d/dw exp(-(5/4)(wp/w)^4). The factor 1 - 0.287 ln gamma
/// is DNV's approximate normalization: the variance is Hs^2/16 to
/// 0.25 % for 1 <= gamma <= 5 and 1.8 % low at gamma = 7 (measured by
/// the tests). Both factors of the peak enhancement are stationary at
/// wp, so S' (wp) = 0 for any gamma.
pub fn jonswap_spectral_density(omega: f64, hs: f64, tp: f64, gamma: f64) -> f64 {
    if omega <= 0.0 {
        return 0.0;
    }
    let wp = 2.0 * PI / tp;
    let ratio = omega / wp;
    let pierson_moskowitz =
        5.0 / 16.0 * hs * hs * wp.powi(4) * omega.powi(-5) * (-1.25 * ratio.powi(-4)).exp();
    let sigma = if omega <= wp { 0.07 } else { 0.09 };
    let peak_exponent = (-0.5 * ((omega - wp) / (sigma * wp)).powi(2)).exp();
    (1.0 - 0.287 * gamma.ln()) * pierson_moskowitz * gamma.powf(peak_exponent)
}

/// A long-crested irregular sea: significant wave height `hs` (m), peak
/// period `tp` (s), peak enhancement `gamma` (1 <= gamma <= 7; 1 is
/// Pierson-Moskowitz), heading in degrees from +x, the seed of the random
/// phases and the number of components.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Jonswap {
    pub hs: f64,
    pub tp: f64,
    pub gamma: f64,
    pub heading_deg: f64,
    pub seed: u64,
    pub components: usize,
}

impl Jonswap {
    /// The sea as regular waves (W15)-(W16): N components at the midpoints
    /// w_i = w_lo + (i + 1/2) dw, dw = (w_hi - w_lo)/N, of [w_lo, w_hi] =
    /// [0.5 wp, 4 wp], with
    ///
    /// ```text
    /// A_i = sqrt(2 S(w_i) dw),  T_i = 2 pi / w_i,
    /// phi_i = 360 deg * u_i                                         (W15)
    /// ```
    ///
    /// u_i the i-th draw of [`SplitMix64`] seeded with `seed`, mapped to
    /// [0, 1) by its top 53 bits (W16). The variance sum A_i^2/2 is the
    /// midpoint rule for the integral of S over [w_lo, w_hi]; the sea
    /// repeats after 2 pi / dw = N Tp / 3.5.
    ///
    /// Refused, naming the field: hs < 0, tp <= 0, gamma outside [1, 7],
    /// no components, a value that is not finite.
    pub fn waves(&self) -> Result<Vec<AiryWave>, ModelError> {
        self.validate()?;
        let wp = 2.0 * PI / self.tp;
        let (lowest, highest) = (LOWEST_FREQUENCY * wp, HIGHEST_FREQUENCY * wp);
        let step = (highest - lowest) / self.components as f64;
        let mut phases = SplitMix64::new(self.seed);
        Ok((0..self.components)
            .map(|i| {
                let omega = lowest + (i as f64 + 0.5) * step;
                let density = jonswap_spectral_density(omega, self.hs, self.tp, self.gamma);
                AiryWave {
                    amplitude: (2.0 * density * step).sqrt(),
                    period: 2.0 * PI / omega,
                    heading_deg: self.heading_deg,
                    phase_deg: 360.0 * phases.next_unit(),
                }
            })
            .collect())
    }

    fn validate(&self) -> Result<(), ModelError> {
        for (name, value) in [
            ("hs", self.hs),
            ("tp", self.tp),
            ("gamma", self.gamma),
            ("heading_deg", self.heading_deg),
        ] {
            if !value.is_finite() {
                return Err(ModelError::invalid(
                    name,
                    format!("must be finite, got {value}"),
                ));
            }
        }
        if self.hs < 0.0 {
            return Err(ModelError::invalid(
                "hs",
                format!("must be >= 0 m, got {}", self.hs),
            ));
        }
        if self.tp <= 0.0 {
            return Err(ModelError::invalid(
                "tp",
                format!("must be > 0 s, got {}", self.tp),
            ));
        }
        if !(1.0..=7.0).contains(&self.gamma) {
            return Err(ModelError::invalid(
                "gamma",
                format!(
                    "must be within [1, 7], where DNV's normalization 1 - 0.287 ln gamma holds, got {}",
                    self.gamma
                ),
            ));
        }
        if self.components == 0 {
            return Err(ModelError::invalid(
                "components",
                "a sea needs at least one component",
            ));
        }
        Ok(())
    }
}

/// SplitMix64 (Steele, Lea, Flood 2014; Vigna's reference constants): a
/// 64-bit state advanced by the golden-ratio increment and mixed:
///
/// ```text
/// s <- s + 0x9E3779B97F4A7C15
/// z <- (s ^ (s >> 30)) * 0xBF58476D1CE4E5B9
/// z <- (z ^ (z >> 27)) * 0x94D049BB133111EB
/// x = z ^ (z >> 31)                                                (W16)
/// ```
///
/// with wrapping products; a draw in [0, 1) is (x >> 11) 2^-53.
#[derive(Clone, Debug)]
pub struct SplitMix64 {
    state: u64,
}

impl SplitMix64 {
    pub fn new(seed: u64) -> Self {
        SplitMix64 { state: seed }
    }

    pub fn next_u64(&mut self) -> u64 {
        self.state = self.state.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.state;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }

    /// A draw in [0, 1) with 53 random bits.
    pub fn next_unit(&mut self) -> f64 {
        (self.next_u64() >> 11) as f64 * (1.0 / (1u64 << 53) as f64)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn sea_state(gamma: f64, seed: u64) -> Jonswap {
        Jonswap {
            hs: 4.0,
            tp: 10.0,
            gamma,
            heading_deg: 30.0,
            seed,
            components: 400,
        }
    }

    fn variance_of(waves: &[AiryWave]) -> f64 {
        waves.iter().map(|w| 0.5 * w.amplitude * w.amplitude).sum()
    }

    /// The midpoint rule's error bound (b - a) dw^2 max|S''| / 24, with
    /// max|S''| from second differences on a grid of wp/2000 (twice it, for
    /// the grid missing the true maximum).
    fn midpoint_bound(sea: &Jonswap) -> f64 {
        let wp = 2.0 * PI / sea.tp;
        let (a, b) = (LOWEST_FREQUENCY * wp, HIGHEST_FREQUENCY * wp);
        let h = wp / 2000.0;
        let s = |w: f64| jonswap_spectral_density(w, sea.hs, sea.tp, sea.gamma);
        let mut curvature: f64 = 0.0;
        let mut w = a;
        while w <= b {
            curvature = curvature.max(((s(w + h) - 2.0 * s(w) + s(w - h)) / (h * h)).abs());
            w += h;
        }
        let dw = (b - a) / sea.components as f64;
        2.0 * (b - a) * dw * dw * curvature / 24.0
    }

    /// Composite Simpson's rule with n (even) intervals.
    fn simpson(f: impl Fn(f64) -> f64, a: f64, b: f64, n: usize) -> f64 {
        let h = (b - a) / n as f64;
        let inner: f64 = (1..n)
            .map(|i| if i % 2 == 1 { 4.0 } else { 2.0 } * f(a + i as f64 * h))
            .sum();
        (f(a) + f(b) + inner) * h / 3.0
    }

    #[test]
    fn splitmix64_draws_the_reference_sequence() {
        // Published outputs of the reference implementation.
        assert_eq!(SplitMix64::new(0).next_u64(), 0xE220_A839_7B1D_CDAF);
        let mut generator = SplitMix64::new(1_234_567);
        let draws: Vec<u64> = (0..3).map(|_| generator.next_u64()).collect();
        assert_eq!(
            draws,
            [
                6_457_827_717_110_365_317,
                3_203_168_211_198_807_973,
                9_817_491_932_198_370_423
            ]
        );
    }

    #[test]
    fn a_pierson_moskowitz_sea_holds_the_variance_of_its_frequency_range() {
        // gamma = 1: the integral of S over [a, b] is (Hs^2/16)
        // (e^(-(5/4)(wp/b)^4) - e^(-(5/4)(wp/a)^4)) exactly (W14), 99.51 %
        // of Hs^2/16 for [0.5 wp, 4 wp]; the components' sum is its
        // midpoint rule.
        // 4000 components make the midpoint rule's rigorous (loose) bound
        // small beside the truncation.
        let sea = Jonswap {
            components: 4000,
            ..sea_state(1.0, 7)
        };
        let full = sea.hs * sea.hs / 16.0;
        let truncated = |ratio: f64| (-1.25 / ratio.powi(4)).exp();
        let expected = full * (truncated(HIGHEST_FREQUENCY) - truncated(LOWEST_FREQUENCY));
        let variance = variance_of(&sea.waves().unwrap());
        let bound = midpoint_bound(&sea);
        // The bound is a quarter of the truncation, so the test tells a
        // truncated sum from a whole one.
        assert!(bound < 0.25 * (full - expected), "bound {bound:e}");
        println!("midpoint error {:e}, bound {bound:e}", variance - expected);
        assert!(
            (variance - expected).abs() < bound,
            "{variance} vs {expected} (bound {bound:e})"
        );
        assert!(
            (1.0 - variance / full - 0.004_871).abs() < 1e-4,
            "lost {}",
            1.0 - variance / full
        );
    }

    #[test]
    fn a_jonswap_sea_holds_hs_squared_over_16_less_its_truncation() {
        // gamma = 3.3: the components' sum is the midpoint rule for the
        // integral over [a, b], computed independently by Simpson's rule;
        // with the tails (Simpson down to 0.2 wp and up to 100 wp, and the
        // closed-form Pierson-Moskowitz tail beyond, gamma^~0 = 1 there)
        // the whole integral is Hs^2/16 to DNV's normalization, 0.25 %.
        let sea = Jonswap {
            components: 4000,
            ..sea_state(3.3, 11)
        };
        let wp = 2.0 * PI / sea.tp;
        let s = |w: f64| jonswap_spectral_density(w, sea.hs, sea.tp, sea.gamma);
        let (a, b) = (LOWEST_FREQUENCY * wp, HIGHEST_FREQUENCY * wp);
        let in_range = simpson(s, a, wp, 20_000) + simpson(s, wp, b, 60_000);
        let full = sea.hs * sea.hs / 16.0;
        let far_tail =
            (1.0 - 0.287 * sea.gamma.ln()) * full * (1.0 - (-1.25 / 100f64.powi(4)).exp());
        let total = simpson(s, 0.2 * wp, a, 2_000)
            + in_range
            + simpson(s, b, 100.0 * wp, 200_000)
            + far_tail;
        assert!(
            (total / full - 1.0).abs() < 2.5e-3,
            "total / (Hs^2/16) = {}",
            total / full
        );
        // The truncation above 4 wp is 0.32 % of the total.
        let lost = 1.0 - in_range / total;
        assert!((lost - 0.0032).abs() < 1e-4, "lost {lost}");

        let variance = variance_of(&sea.waves().unwrap());
        let bound = midpoint_bound(&sea);
        assert!(bound < 0.25 * (total - in_range), "bound {bound:e}");
        println!("midpoint error {:e}, bound {bound:e}", variance - in_range);
        assert!(
            (variance - in_range).abs() < bound,
            "{variance} vs {in_range} (bound {bound:e})"
        );
    }

    #[test]
    fn the_spectrum_peaks_at_the_peak_frequency() {
        // A golden-section search on [0.5 wp, 2 wp] (unimodal) locates the
        // maximum to ~sqrt(eps) relative; DNV's form puts it at wp.
        for gamma in [1.0, 3.3, 7.0] {
            let tp = 8.0;
            let wp = 2.0 * PI / tp;
            let s = |w: f64| jonswap_spectral_density(w, 3.0, tp, gamma);
            let (mut lo, mut hi) = (0.5 * wp, 2.0 * wp);
            let ratio = (5f64.sqrt() - 1.0) / 2.0;
            while hi - lo > 1e-9 * wp {
                let (left, right) = (hi - ratio * (hi - lo), lo + ratio * (hi - lo));
                if s(left) < s(right) {
                    lo = left;
                } else {
                    hi = right;
                }
            }
            let found = 0.5 * (lo + hi);
            assert!(
                ((found - wp) / wp).abs() < 1e-6,
                "gamma {gamma}: peak at {} wp",
                found / wp
            );
        }
    }

    #[test]
    fn a_seed_gives_the_same_sea_and_another_seed_another() {
        let first = sea_state(3.3, 42).waves().unwrap();
        assert_eq!(first, sea_state(3.3, 42).waves().unwrap());
        let other = sea_state(3.3, 43).waves().unwrap();
        // Same amplitudes and periods, phases all different.
        for (a, b) in first.iter().zip(&other) {
            assert_eq!((a.amplitude, a.period), (b.amplitude, b.period));
            assert_ne!(a.phase_deg, b.phase_deg);
        }
        // Phases spread over [0, 360): 400 uniform draws have mean 180 deg
        // to within 5 standard errors (104 / sqrt(400) = 5.2 deg each).
        let mean = first.iter().map(|w| w.phase_deg).sum::<f64>() / first.len() as f64;
        assert!((mean - 180.0).abs() < 26.0, "mean phase {mean}");
        assert!(first.iter().all(|w| (0.0..360.0).contains(&w.phase_deg)));
    }

    #[test]
    fn an_impossible_sea_state_is_refused_naming_the_field() {
        let key = |sea: Jonswap| sea.waves().unwrap_err().key;
        assert_eq!(
            key(Jonswap {
                tp: 0.0,
                ..sea_state(3.3, 1)
            }),
            "tp"
        );
        assert_eq!(
            key(Jonswap {
                hs: -1.0,
                ..sea_state(3.3, 1)
            }),
            "hs"
        );
        assert_eq!(
            key(Jonswap {
                gamma: 0.5,
                ..sea_state(3.3, 1)
            }),
            "gamma"
        );
        assert_eq!(
            key(Jonswap {
                components: 0,
                ..sea_state(3.3, 1)
            }),
            "components"
        );
    }
}
