//! MoorDyn-F's waves from an elevation record (its WaterKin file's
//! `WaveKinMod 1`, the "old method"; docs/method.md §12.1 (W2i)): the
//! record of the file `WaveKinFile` names, resampled every `dtWave` over
//! the run, its series (W2d) summed where the lines are, heading
//! `WaveDir`.
//!
//! MoorDyn-F (`setupWaterKin` in MoorDyn_Misc.f90) reads the record's rows
//! `t eta` after any header lines (a line whose first word is not a
//! number), the first time exactly 0; samples it at t_i = i dtWave for
//! i = 0 .. ceil(TMax / dtWave) - 1 (TMax the run's length its host
//! passes), each linearly between the first two rows with t_(j+1) > t_i
//! and 0 where there is none (after the record, and at its last time);
//! pads the samples with zeros to an even number and then to 2
//! PSF(N / 2), the next size whose prime factors are at most 23; and
//! inverse-transforms the terms 0 < k < N/2 (its mean and its Nyquist
//! term dropped, no cut-off) into kinematics on its grid, each term a
//! wave of linear theory toward WaveDir (degrees from +x toward +y)
//! through the origin. stancf takes the same samples and the same
//! terms, as waves (W2d) of heading WaveDir; its frequencies are the
//! transform's, w_k = 2 pi k / (N dtWave) (MoorDyn-F takes 2 pi k / TMax,
//! which differs where N dtWave is not TMax: noted).
//! `WaveKinMod 2` (the hybrid method) takes its spectrum from OpenFAST's
//! SeaState, without which MoorDyn-F stops: refused by name.

use super::ScenarioError;
use crate::moordyn::{Deck, SupportedOption};
use stancf::error::Sig;
use stancf::water::record::record_series;
use stancf::water::waves::AiryWave;
use std::path::Path;

/// The largest prime factor of MoorDyn-F's transform sizes: the 9th
/// prime (`PSF(n, 9)` in NWTC_Num.f90).
const LARGEST_FACTOR: usize = 23;

/// The most samples stancf transforms (a day every 8.64 ms).
const MOST_SAMPLES: f64 = 1e7;

/// The most work of the transform, samples times terms (2e9
/// multiply-adds: seconds).
const MOST_WORK: f64 = 2e9;

/// What lines 4 to 13 of a WaterKin file say of the waves: `WaveKinMod`
/// 1's record file, `dtWave` and `WaveDir` (degrees).
#[derive(Clone, Debug, PartialEq)]
pub(super) struct RecordWaves {
    pub file: String,
    pub dt: f64,
    pub heading_deg: f64,
}

/// The waves part of a WaterKin file's `lines`: None for `WaveKinMod` 0,
/// the record's settings for 1; 2 and others refused naming the line.
/// The grid's type lines (8, 10, 12) must be 0, 1 or 2, as MoorDyn-F
/// asks; stancf sums the series where the lines are and needs no grid.
pub(super) fn read_wave_settings(lines: &[&str]) -> Result<Option<RecordWaves>, String> {
    let word = |i: usize| -> Result<&str, String> {
        let line = lines.get(i).ok_or_else(|| {
            format!(
                "the file ends at line {}, before line {}",
                lines.len(),
                i + 1
            )
        })?;
        Ok(line.split_whitespace().next().unwrap_or(""))
    };
    let number = |i: usize, what: &str| -> Result<f64, String> {
        let w = word(i)?;
        w.parse::<f64>()
            .ok()
            .filter(|v| v.is_finite())
            .ok_or_else(|| format!("line {}: {what} is \"{w}\", not a number", i + 1))
    };
    let mode = number(3, "WaveKinMod")?;
    match mode {
        0.0 => return Ok(None),
        1.0 => {}
        2.0 => {
            return Err(
                "line 4: WaveKinMod 2: the hybrid method takes its waves from OpenFAST's \
                 SeaState module, without which MoorDyn-F stops (\"Hybrid method requires \
                 SeaState\"), and stancf has none; give the waves as an elevation record \
                 (WaveKinMod 1), as [[water.waves]] or [water.jonswap] in a scenario that takes \
                 the deck, or WaterKin SEASTATE for a coupling host's kinematics"
                    .into(),
            )
        }
        m => {
            return Err(format!(
                "line 4: WaveKinMod is {m}; MoorDyn-F's are 0, 1 and 2"
            ))
        }
    }
    for (i, axis) in [(7, "X"), (9, "Y"), (11, "Z")] {
        let t = number(i, &format!("the {axis} grid's type"))?;
        if ![0.0, 1.0, 2.0].contains(&t) {
            return Err(format!(
                "line {}: the {axis} grid's type is {t}; MoorDyn-F's are 0 (not used), 1 (a \
                 list) and 2 (first, last, count)",
                i + 1
            ));
        }
    }
    let file = quoted_or_first_word(lines.get(4).copied().unwrap_or(""));
    if file.is_empty() {
        return Err("line 5: WaveKinMod 1 needs a WaveKinFile (MoorDyn-F stops without)".into());
    }
    let dt = number(5, "dtWave")?;
    if dt <= 0.0 {
        return Err(format!("line 6: dtWave is {dt}; it must be positive"));
    }
    let heading_deg = number(6, "WaveDir")?;
    Ok(Some(RecordWaves {
        file,
        dt,
        heading_deg,
    }))
}

/// A list-directed string as Fortran reads it: the text between a
/// leading pair of double or single quotes (spaces kept), else the first
/// word.
fn quoted_or_first_word(line: &str) -> String {
    let line = line.trim_start();
    for q in ['"', '\''] {
        if let Some(rest) = line.strip_prefix(q) {
            if let Some(end) = rest.find(q) {
                return rest[..end].to_string();
            }
        }
    }
    line.split_whitespace().next().unwrap_or("").to_string()
}

/// The elevation samples MoorDyn-F takes from the record `text` every
/// `dt` over `run_length` (s; without one, over the record: up to its
/// last time), padded to its transform's size (see the module), and the
/// record's last time. Errors name the line.
pub(super) fn record_samples(
    text: &str,
    dt: f64,
    run_length: Option<f64>,
) -> Result<(Vec<f64>, f64), String> {
    let rows = record_rows(text)?;
    let t_last = rows.last().expect("a row at least").1;
    let span = run_length.unwrap_or(t_last);
    let count = (span / dt).ceil().max(1.0);
    if count > MOST_SAMPLES || count * count / 2.0 > MOST_WORK {
        return Err(format!(
            "{} s every dtWave = {dt} s is {count:.0} samples, beyond the {MOST_SAMPLES:e} \
             samples and {MOST_WORK:e} samples x waves stancf transforms; give a larger dtWave",
            Sig(span)
        ));
    }
    let mut samples: Vec<f64> = (0..count as usize)
        .map(|i| {
            let t = i as f64 * dt;
            // The first pair of rows with t_(j+1) > t (j + 1 >= 1: the
            // first time is 0 <= t); none: still water.
            let next = rows.partition_point(|r| r.1 <= t);
            match rows.get(next) {
                Some(&(_, t1, e1)) => {
                    let (_, t0, e0) = rows[next - 1];
                    e0 + (t - t0) / (t1 - t0) * (e1 - e0)
                }
                None => 0.0,
            }
        })
        .collect();
    let even = samples.len().div_ceil(2) * 2;
    let size = 2 * small_factors_at_least(even / 2);
    samples.resize(size, 0.0);
    Ok((samples, t_last))
}

/// The record's rows (line, t, eta) after its header lines (those whose
/// first word is not a number, before the first row), blank lines
/// skipped; words split at blanks and commas, columns after the second
/// ignored. The first time must be 0 and the times rise (one row is a
/// still sea: MoorDyn-F finds no pair of rows about any sample).
fn record_rows(text: &str) -> Result<Vec<(usize, f64, f64)>, String> {
    let mut rows = Vec::new();
    for (i, line) in text.lines().enumerate() {
        let words: Vec<&str> = line
            .split(|c: char| c.is_whitespace() || c == ',')
            .filter(|w| !w.is_empty())
            .collect();
        let Some(first) = words.first() else { continue };
        let Ok(t) = first.parse::<f64>() else {
            if rows.is_empty() {
                continue; // a header line
            }
            return Err(format!(
                "line {}: \"{}\" is not a row \"t eta\" (s, m) after the record's first row",
                i + 1,
                line.trim()
            ));
        };
        let eta = words.get(1).and_then(|w| w.parse::<f64>().ok());
        match eta {
            Some(eta) if t.is_finite() && eta.is_finite() => rows.push((i + 1, t, eta)),
            _ => {
                return Err(format!(
                    "line {}: a row \"t eta\" (s, m) of two numbers",
                    i + 1
                ))
            }
        }
    }
    match rows.first() {
        None => return Err("no row \"t eta\" (s, m)".into()),
        Some(&(line, t, _)) if t != 0.0 => {
            return Err(format!(
                "line {line}: the record starts at {t} s; MoorDyn-F asks for its first time at 0"
            ))
        }
        _ => {}
    }
    if let Some(p) = rows.windows(2).find(|p| p[1].1 <= p[0].1) {
        return Err(format!(
            "line {}: the time {} s does not rise above the row before",
            p[1].0, p[1].1
        ));
    }
    Ok(rows)
}

/// The smallest whole number at least `n` whose prime factors are at
/// most [`LARGEST_FACTOR`] (MoorDyn-F's FFT sizes, `PSF`).
fn small_factors_at_least(n: usize) -> usize {
    let smooth = |mut m: usize| {
        for p in [2, 3, 5, 7, 11, 13, 17, 19, LARGEST_FACTOR] {
            while m.is_multiple_of(p) {
                m /= p;
            }
        }
        m == 1
    };
    (n.max(1)..).find(|&m| smooth(m)).expect("2^k is smooth")
}

/// The deck's `WaterKin` file's waves and the note for `check` (None
/// without the option, for `SEASTATE` or for `WaveKinMod` 0), the record
/// resampled over `run_length` (s). Refused naming the option's line and
/// the file's line.
pub(super) fn waterkin_waves(
    deck: &Deck,
    file: &str,
    path: &Path,
    run_length: Option<f64>,
) -> Result<Option<(Vec<AiryWave>, String)>, ScenarioError> {
    let Some((named, name, line)) = deck.option_text(SupportedOption::WaterKinFile) else {
        return Ok(None);
    };
    if deck.sea_from_seastate().is_some() {
        return Ok(None);
    }
    let refuse = |e: String| ScenarioError(format!("{file}: line {line}: option {name}: {e}"));
    let dir = path.parent().unwrap_or(Path::new(""));
    let at = dir.join(named);
    let text =
        crate::input_file::read_text(&at).map_err(|e| refuse(format!("{}: {e}", at.display())))?;
    let lines: Vec<&str> = text.lines().collect();
    let settings =
        read_wave_settings(&lines).map_err(|e| refuse(format!("{}: {e}", at.display())))?;
    let Some(s) = settings else { return Ok(None) };
    // MoorDyn-F opens WaveKinFile from the deck's folder too.
    let record = dir.join(&s.file);
    let read = |e: String| {
        refuse(format!(
            "{}: WaveKinFile {}: {e}",
            at.display(),
            record.display()
        ))
    };
    let record_text = crate::input_file::read_text(&record).map_err(read)?;
    let (samples, t_last) = record_samples(&record_text, s.dt, run_length).map_err(read)?;
    let series = record_series(&samples, s.dt, s.heading_deg, f64::INFINITY);
    let period = samples.len() as f64 * s.dt;
    let over = match run_length {
        Some(t) => format!("over the run's {} s", Sig(t)),
        None => format!(
            "over the record's {} s (no run length: a coupled run repeats it every {} s, where \
             MoorDyn-F's sea is still after the record)",
            Sig(t_last),
            Sig(period)
        ),
    };
    let mut note = format!(
        "OPTIONS: {name} (line {line}): WaveKinMod 1, {} wave component(s) heading {} deg from \
         the record {} (from the deck's folder, as MoorDyn-F opens it), resampled every dtWave \
         = {} s {over}, still after its last time {} s, {} samples (zeros to MoorDyn-F's \
         transform size), its mean and Nyquist term dropped as MoorDyn-F drops them \
         (docs/method.md §12.1 (W2i)); MoorDyn-F interpolates them on its grid and stretches \
         them to the surface (Wheeler), stancf sums them where the lines are, to z = 0",
        series.waves.len(),
        Sig(s.heading_deg),
        record.display(),
        Sig(s.dt),
        Sig(t_last),
        samples.len(),
    );
    let with_waves = !series.waves.is_empty();
    if let Some(t) = run_length.filter(|t| with_waves && (period - t).abs() > 1e-9 * t) {
        note += &format!(
            "; MoorDyn-F takes the frequencies 2 pi k / TMax (TMax {} s) where its transform's \
             are 2 pi k / (N dtWave), N dtWave = {} s: its waves away from the origin and its \
             velocities are those of frequencies {} times the record's; stancf's are the \
             transform's",
            Sig(t),
            Sig(period),
            Sig(period / t)
        );
    }
    Ok(Some((series.waves, note)))
}

#[cfg(test)]
#[path = "moordyn_waterkin_waves_tests.rs"]
mod tests;
