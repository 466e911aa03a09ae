//! A MoorDyn deck's FFT wave grids (docs/interface.md, "Water";
//! docs/method.md §12.1 (W2c)-(W2e)): `WaveKin 2` (the components of
//! `wave_frequencies.txt` on an even frequency grid) and `WaveKin 3` (the
//! elevation record of `wave_elevation.txt`), each turned into the
//! regular Airy waves whose sum MoorDyn-C's grid samples.
//!
//! MoorDyn (Waves/WaveGrid.cpp) builds for either a spectrum zeta_k at
//! frequencies w_k = k dw, k = 0 .. N/2, inverse-transforms it at every
//! node of `water_grid.txt` into N samples every 2 pi / (N dw) s and
//! interpolates them linearly in space and time. At the samples its
//! elevation is the series (W2d) of `stancf::water::record`, its
//! velocities and accelerations those of linear theory term by term; the
//! series is what the grid samples, so stancf sums its terms at the
//! space-time Gauss points and needs no grid. What the grid cannot say as
//! waves, its mean (a still level) and its Nyquist term (a sign that
//! alternates at the samples), is refused or noted below.

use super::ScenarioError;
use crate::moordyn::{Deck, SupportedOption};
use stancf::error::Sig;
use stancf::water::record::record_series;
use stancf::water::waves::AiryWave;
use std::f64::consts::PI;
use std::path::Path;

/// The file MoorDyn-C reads the elevation record of `WaveKin 3` from.
pub const WAVE_ELEVATION_FILE: &str = "wave_elevation.txt";

/// MoorDyn's `dtWave` when a deck gives none (WaveOptions.hpp).
const DEFAULT_WAVE_TIME_STEP: f64 = 0.25;

/// MoorDyn cuts the elevation record's spectrum above 0.5 Hz "to avoid
/// FFT noise getting amplified when moving to other points in the wave
/// field" (WaveGrid.cpp, `constructWaveGridElevationData`).
const RECORD_HIGHEST_OMEGA: f64 = 0.5 * 2.0 * PI;

/// The most samples of a resampled record (a day at 8.64 ms).
const MOST_RECORD_SAMPLES: f64 = 1e7;

/// The most work the transform of a record may take, samples times waves
/// kept (W2c): 2e9 multiply-adds, a few seconds; a three-hour record at
/// 4 Hz is 43 200 x 5 400 = 2.3e8.
const MOST_TRANSFORM_WORK: f64 = 2e9;

/// The most frequencies of MoorDyn's even grid a `wave_frequencies.txt`
/// may make (MoorDyn's FFT of a million samples per grid node).
const MOST_GRID_FREQUENCIES: f64 = 1e6;

/// The waves of `WaveKin 2`: the rows of `wave_frequencies.txt` (read by
/// `super::moordyn_wave_frequencies::read_wave_frequencies`) on MoorDyn's even
/// grid (W2e): dw the smallest spacing of the rows, the frequencies k dw
/// for k = 0 .. floor(w_last / dw), each complex amplitude and heading
/// interpolated linearly between the rows about it
/// (`DiscreteWaveSpectrum::interpEvenlySpaced`; a grid frequency within
/// round-off of a row is that row's). MoorDyn scales them by
/// N/2 = nw - 1 before its inverse transform of length N = 2 (nw - 1)
/// and divides by N after it, so a grid term 0 < k < N/2 is the wave
/// Re(a_k e^(i (w_k t - k_k x . e))): A = |a_k|, phi = -arg a_k (W2d).
/// Its first row must be w = 0 (as MoorDyn asks); the still term's
/// elevation Re(a_0) / 2 and the Nyquist term (k = nw - 1) are refused
/// if not zero, naming the row that gives them. Returns the waves and dw.
pub fn fft_grid_waves(
    rows: &[super::moordyn_wave_frequencies::WaveComponent],
) -> Result<(Vec<AiryWave>, f64), String> {
    if rows[0].omega != 0.0 {
        return Err(format!(
            "line {}: the first frequency is {} rad/s; MoorDyn's FFT grid starts at 0",
            rows[0].line, rows[0].omega
        ));
    }
    let dw = rows
        .windows(2)
        .map(|p| p[1].omega - p[0].omega)
        .fold(f64::INFINITY, f64::min);
    if dw <= 0.0 {
        let at = rows.windows(2).find(|p| p[1].omega <= p[0].omega).unwrap();
        return Err(format!(
            "line {}: the frequency {} rad/s does not rise above the row before; MoorDyn's \
             FFT grid asks for ascending frequencies",
            at[1].line, at[1].omega
        ));
    }
    let last = rows.last().expect("2 rows at least").omega;
    let count = (last / dw).floor() + 1.0;
    if count > MOST_GRID_FREQUENCIES {
        return Err(format!(
            "MoorDyn's grid of these rows has {count:.0} frequencies (dw = {dw} rad/s, the \
             smallest spacing of the rows, up to {last} rad/s), beyond the \
             {MOST_GRID_FREQUENCIES:e} stancf sums; space the rows more evenly"
        ));
    }
    let count = count as usize;
    // k dw lands on a row given in decimals only to round-off (0.05 k
    // against k times the smallest spacing, 0.04999999999999999): such a
    // grid frequency takes the row's amplitude, where MoorDyn's
    // interpolation leaks ~1e-15 of it into the neighbours.
    let on_a_row = 16.0 * f64::EPSILON * last;
    let mut waves = Vec::new();
    let mut upper = 1;
    for k in 0..count {
        let omega = k as f64 * dw;
        while upper < rows.len() - 1 && omega > rows[upper].omega + on_a_row {
            upper += 1;
        }
        let (a, b) = (&rows[upper - 1], &rows[upper]);
        let f = match ((omega - a.omega).abs(), (omega - b.omega).abs()) {
            (d, _) if d <= on_a_row => 0.0,
            (_, d) if d <= on_a_row => 1.0,
            _ => ((omega - a.omega) / (b.omega - a.omega)).clamp(0.0, 1.0),
        };
        let lerp = |p: f64, q: f64| p + f * (q - p);
        let re = lerp(a.amplitude[0], b.amplitude[0]);
        let im = lerp(a.amplitude[1], b.amplitude[1]);
        let from = if f == 0.0 { a.line } else { b.line };
        if k == 0 && re != 0.0 {
            return Err(format!(
                "line {from}: the row of frequency 0 lifts MoorDyn's surface by re / 2 = {} m; \
                 stancf's still surface is z = 0",
                re / 2.0
            ));
        }
        if k + 1 == count && count > 1 && re.hypot(im) != 0.0 {
            return Err(format!(
                "line {from}: {omega} rad/s is the Nyquist frequency of MoorDyn's FFT grid \
                 (its last, (N/2) dw with dw = {dw} rad/s), where the inverse transform \
                 alternates a sign at its samples and makes no wave; give it no amplitude \
                 (a last row of zero amplitude above the waves)"
            ));
        }
        let amplitude = re.hypot(im);
        if k == 0 || k + 1 == count || amplitude == 0.0 {
            continue;
        }
        waves.push(AiryWave {
            amplitude,
            period: 2.0 * PI / omega,
            heading_deg: lerp(a.heading, b.heading).to_degrees(),
            phase_deg: -im.atan2(re).to_degrees(),
        });
    }
    Ok((waves, dw))
}

/// `WaveKin 3` as MoorDyn reads it: the record of `wave_elevation.txt`
/// (rows `t eta`, more columns ignored, times rising) resampled every
/// `dt` (`dtWave`) by linear interpolation, holding the first value
/// before the record and the last after it (`moordyn::interp`), over N =
/// floor(t_last / dt) + 1 samples less one if odd; its series (W2d) up
/// to 0.5 Hz, heading +x. MoorDyn keeps the Nyquist term when its
/// frequency pi / dt is within 0.5 Hz (dt >= 1 s).
pub fn record_waves(text: &str, dt: f64) -> Result<RecordWaves, String> {
    let shape = "\"t eta\" (s, m)";
    let rows = super::moordyn_water::table_rows(text, 0, 2..=usize::MAX, shape)?;
    if rows.len() < 2 {
        return Err(format!("{} row(s); a record needs 2 at least", rows.len()));
    }
    if let Some(p) = rows.windows(2).find(|p| p[1].1[0] <= p[0].1[0]) {
        return Err(format!(
            "line {}: the time {} s does not rise above the row before",
            p[1].0, p[1].1[0]
        ));
    }
    let t_last = rows.last().expect("2 rows").1[0];
    // Bounded before anything the record's size is allocated: N samples,
    // and the terms up to 0.5 Hz, k <= N dt / 2.
    let count = (t_last / dt).floor().max(0.0) + 1.0;
    let kept = (count * dt / 2.0).min(count / 2.0);
    if count > MOST_RECORD_SAMPLES || count * kept > MOST_TRANSFORM_WORK {
        return Err(format!(
            "the record of {t_last} s every dtWave = {dt} s is {count:.0} samples with {kept:.0} \
             waves up to 0.5 Hz, beyond the {MOST_RECORD_SAMPLES:e} samples and \
             {MOST_TRANSFORM_WORK:e} samples x waves stancf transforms; give a larger dtWave or a \
             shorter record"
        ));
    }
    let mut n = count as usize;
    n -= n % 2;
    if n < 2 {
        return Err(format!(
            "the record ends at {t_last} s, within one dtWave ({dt} s) of its start: \
             MoorDyn's grid needs two samples"
        ));
    }
    let samples: Vec<f64> = (0..n)
        .map(|i| {
            let t = i as f64 * dt;
            let j = rows.partition_point(|r| r.1[0] < t);
            match j {
                0 => rows[0].1[1],
                j if j == rows.len() => rows[j - 1].1[1],
                j => {
                    let ((t0, e0), (t1, e1)) = (
                        (rows[j - 1].1[0], rows[j - 1].1[1]),
                        (rows[j].1[0], rows[j].1[1]),
                    );
                    e0 + (t - t0) / (t1 - t0) * (e1 - e0)
                }
            }
        })
        .collect();
    let series = record_series(&samples, dt, 0.0, RECORD_HIGHEST_OMEGA);
    let nyquist_kept = PI / dt <= RECORD_HIGHEST_OMEGA;
    let largest = samples.iter().fold(0.0_f64, |m, e| m.max(e.abs()));
    Ok(RecordWaves {
        waves: series.waves,
        samples: n,
        mean: series.mean,
        dropped_nyquist: if nyquist_kept { series.nyquist } else { 0.0 },
        largest,
    })
}

/// The waves of an elevation record and what of it is not a wave.
#[derive(Clone, Debug, PartialEq)]
pub struct RecordWaves {
    pub waves: Vec<AiryWave>,
    /// N, the samples of one period of the series.
    pub samples: usize,
    /// The samples' mean (m): MoorDyn's grid lifts its surface by it.
    pub mean: f64,
    /// The Nyquist term's amplitude (m) MoorDyn keeps and stancf drops.
    pub dropped_nyquist: f64,
    /// The largest |eta| of the samples (m).
    pub largest: f64,
}

/// The deck's `WaveKin 2` or `3` waves and the note for `check`; `at` is
/// the option's name and line, `dir` the deck's folder.
pub(super) fn deck_grid_waves(
    deck: &Deck,
    mode: u8,
    (name, line): (&str, usize),
    file: &str,
    dir: &Path,
) -> Result<(Vec<AiryWave>, String), ScenarioError> {
    let source = if mode == 2 {
        super::moordyn_wave_frequencies::WAVE_FREQUENCIES_FILE
    } else {
        WAVE_ELEVATION_FILE
    };
    let at = dir.join(source);
    let read = |e: String| {
        ScenarioError(format!(
            "{file}: line {line}: option {name} {mode} reads {}: {e}",
            at.display()
        ))
    };
    let (waves, how) = if mode == 2 {
        let rows = super::moordyn_wave_frequencies::read_wave_frequencies(&at).map_err(read)?;
        let (waves, dw) = fft_grid_waves(&rows).map_err(read)?;
        let how = format!(
            "MoorDyn's even grid of {} rad/s, the rows' amplitudes interpolated onto it",
            Sig(dw)
        );
        (waves, how)
    } else {
        let dt = deck
            .option(SupportedOption::WaveTimeStep)
            .map_or(DEFAULT_WAVE_TIME_STEP, |v| {
                SupportedOption::WaveTimeStep.as_moordyn_reads(v)
            });
        let text = crate::input_file::read_text(&at).map_err(read)?;
        let r = record_waves(&text, dt).map_err(read)?;
        let mut how = format!(
            "its series (W2d) of {} samples every dtWave = {} s up to 0.5 Hz, repeating every \
             {} s as MoorDyn's grid does",
            r.samples,
            Sig(dt),
            Sig(r.samples as f64 * dt)
        );
        if r.mean.abs() > 1e-12 * r.largest {
            how += &format!(
                "; the samples' mean, {} m, lifts MoorDyn's surface and not stancf's (z = 0)",
                Sig(r.mean)
            );
        }
        if r.dropped_nyquist != 0.0 {
            how += &format!(
                "; its Nyquist term of {} m, a sign alternating at the samples in MoorDyn's grid, \
                 is no wave and is left out",
                Sig(r.dropped_nyquist)
            );
        }
        (r.waves, how)
    };
    let crest: f64 = waves.iter().map(|w| w.amplitude).sum();
    let note = format!(
        "line {line}: {name} {mode}: {} wave component(s) from {} ({how}; docs/method.md \
         §12.1 (W2c)-(W2e)); MoorDyn samples them on water_grid.txt and interpolates linearly \
         in space and time, stancf sums them where the lines are; stancf evaluates linear \
         theory to the still water level and loads what lies below z = 0 (§12.3), where \
         MoorDyn stretches the kinematics to the wave's surface (Wheeler) and wets what lies \
         under it: the two agree under the waves and differ within {} m of z = 0 (the \
         amplitudes' sum); a static run (the deck alone) does not see the waves, a coupled or \
         dynamic run does",
        waves.len(),
        at.display(),
        Sig(crest)
    );
    Ok((waves, note))
}

#[cfg(test)]
#[path = "moordyn_wave_grids_tests.rs"]
mod tests;
