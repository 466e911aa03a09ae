//! A MoorDyn deck's waves (docs/interface.md, "Water"; docs/method.md
//! §12.1): `WaveKin 7`, MoorDyn-C's summed wave components, read from
//! `wave_frequencies.txt` beside the deck and given to the sea as regular
//! Airy waves, superposed with any `[[water.waves]]` of a scenario that
//! takes the deck; `WaveKin` 2 and 3, MoorDyn's FFT grids, by
//! `super::moordyn_wave_grids`. The other modes are refused by name.
//!
//! MoorDyn (Waves/SpectrumKin.cpp) sums, for each row `w re im [beta]`
//! (rad/s, m, m, rad), the elevation
//!
//! ```text
//!   eta_i = |a| sin(w t - k (x cos beta + y sin beta) + arg a),   a = re + i im
//! ```
//!
//! with the velocity of linear theory in phase with it. stancf's wave
//! (W2) is eta = A cos theta, theta = k (x cos beta + y sin beta) - w t +
//! phi; since sin(-u) = cos(u + pi/2), the two are the same wave with
//!
//! ```text
//!   A = |a|,   T = 2 pi / w,   heading = beta,   phi = pi/2 - arg a        (W2b)
//! ```
//!
//! and the same velocity (u_h = A w C cos theta, MoorDyn's w C eta_i).
//! Where the two models differ: MoorDyn stretches the depth factors to
//! the instantaneous surface (Wheeler) and wets what lies under it;
//! stancf evaluates linear theory to the still water level and loads
//! what lies below z = 0 (§12.3). They agree under the waves (to first
//! order in the waves' height over the depth) and differ in the splash
//! zone.

pub use super::moordyn_wave_frequencies::{
    read_wave_frequencies, WaveComponent, WAVE_FREQUENCIES_FILE,
};
use super::ScenarioError;
use crate::moordyn::{Deck, SupportedOption};
use stancf::water::waves::AiryWave;
use std::f64::consts::PI;
use std::path::Path;

/// Why a deck runs statically only from the command line or a scenario
/// (None: it may run in time): its `WaveKin 1`, or MoorDyn-F's `SEASTATE
/// WaterKin`, waits for a host to set the water's kinematics at MoorDyn's
/// nodes, and a run without a host has none. The coupling API steps it.
pub(super) fn static_only(deck: &Deck, file: &str) -> Option<String> {
    let coupling = "step it through the coupling API, which takes the host's kinematics \
                    (stancf_wave_kin_set in C, Simulation.set_wave_kinematics in Python), or give \
                    the waves in a scenario that takes the deck (system.moordyn) as \
                    [[water.waves]] or [water.jonswap]";
    if let Some((name, line)) = deck.sea_from_seastate() {
        return Some(format!(
            "{file}: line {line}: option {name} is SEASTATE: the water's kinematics are those of \
             the host's SeaState module, and a run from the command line or a scenario has no \
             host, so the deck runs its static equilibrium only (in still water); {coupling}, \
             with the deck's WaterKin row removed"
        ));
    }
    let at = deck.option_at(SupportedOption::WaveKin)?;
    deck.host_sets_waves().then(|| {
        format!(
            "{file}: line {}: option {} is 1: MoorDyn's host sets the water's kinematics at its \
             nodes (MoorDyn_ExternalWaveKinSet), and a run from the command line or a scenario \
             has no host, so the deck runs its static equilibrium only; {coupling}, with \
             WaveKin 0",
            at.1, at.0
        )
    })
}

/// Every wave a deck gives, with the notes for `check`: MoorDyn-C's
/// (`WaveKin`, `super::moordyn_waves::deck_waves`) and MoorDyn-F's record
/// (`super::moordyn_waterkin_waves::waterkin_waves`, over
/// `run_length`); a deck gives one or the
/// other (`super::moordyn_waterkin` refuses both).
pub(super) fn every_deck_wave(
    deck: &Deck,
    file: &str,
    path: &Path,
    run_length: Option<f64>,
) -> Result<(Vec<AiryWave>, Vec<String>), ScenarioError> {
    let (mut waves, note) = deck_waves(deck, file, path)?;
    let mut notes: Vec<String> = note.into_iter().collect();
    let record = super::moordyn_waterkin_waves::waterkin_waves(deck, file, path, run_length)?;
    if let Some((record, note)) = record {
        waves.extend(record);
        notes.push(note);
    }
    Ok((waves, notes))
}

/// The deck's waves and a note for `check` saying where they come from,
/// from its `WaveKin`: 0 (or missing) none; 7 the components of
/// [`WAVE_FREQUENCIES_FILE`] beside the deck at `path`; any other mode
/// refused naming the option's line.
pub(super) fn deck_waves(
    deck: &Deck,
    file: &str,
    path: &Path,
) -> Result<(Vec<AiryWave>, Option<String>), ScenarioError> {
    let at = deck.option_at(SupportedOption::WaveKin);
    let Some(((name, line), mode)) = at.zip(deck.option(SupportedOption::WaveKin)) else {
        return Ok((Vec::new(), None));
    };
    let refuse = |why: &str| {
        Err(ScenarioError(format!(
            "{file}: line {line}: option {name} is {mode}: {why}; give the waves in a scenario \
             that takes this deck (system.moordyn) as [[water.waves]] or [water.jonswap]"
        )))
    };
    let dir = path.parent().unwrap_or(Path::new(""));
    match mode {
        0.0 => return Ok((Vec::new(), None)),
        7.0 => {}
        1.0 => {
            let note = format!(
                "line {line}: {name} 1: MoorDyn's host sets the water's kinematics at its nodes \
                 (MoorDyn_ExternalWaveKinSet): the coupling API takes them (stancf_wave_kin_set \
                 in C, Simulation.set_wave_kinematics in Python; still water until the host sets \
                 them, as in MoorDyn, docs/method.md §12.1 (W2f)-(W2g)); the deck's static \
                 equilibrium (a deck alone), which sees no waves in either code, runs; a dynamic \
                 run without a host is refused"
            );
            return Ok((Vec::new(), Some(note)));
        }
        2.0 | 3.0 => {
            let grid = super::moordyn_wave_grids::deck_grid_waves;
            let (waves, note) = grid(deck, mode as u8, (name, line), file, dir)?;
            return Ok((waves, Some(note)));
        }
        _ => return refuse("MoorDyn-C's wave modes are 0, 1, 2, 3 and 7"),
    }
    let at = dir.join(WAVE_FREQUENCIES_FILE);
    let read = |e: String| {
        ScenarioError(format!(
            "{file}: line {line}: option {name} 7 reads {}: {e}",
            at.display()
        ))
    };
    let components = read_wave_frequencies(&at).map_err(read)?;
    let waves = airy_waves(&components).map_err(read)?;
    let crest: f64 = waves.iter().map(|w| w.amplitude).sum();
    let note = format!(
        "line {line}: {name} 7: {} wave component(s) of {} (MoorDyn's summed components, \
         docs/method.md §12.1 (W2b)); stancf evaluates linear theory to the still water level \
         and loads what lies below z = 0 (§12.3), where MoorDyn stretches the kinematics to \
         the wave's surface (Wheeler) and wets what lies under it: the two agree under the \
         waves and differ within {} m of z = 0 (the amplitudes' sum); a static run (the deck \
         alone) does not see the waves, a coupled or dynamic run does",
        waves.len(),
        at.display(),
        stancf::error::Sig(crest)
    );
    Ok((waves, Some(note)))
}

/// The regular waves (W2b) of the components with a frequency and an
/// amplitude. A component of frequency 0 is still water (no velocity,
/// no elevation) unless its amplitude's imaginary part lifts the surface
/// by |a| sin(arg a) = im everywhere, which a sea of waves about z = 0
/// cannot hold: refused naming its line.
pub fn airy_waves(components: &[WaveComponent]) -> Result<Vec<AiryWave>, String> {
    let mut waves = Vec::new();
    for c in components {
        let [re, im] = c.amplitude;
        let amplitude = re.hypot(im);
        if c.omega == 0.0 {
            if im != 0.0 {
                return Err(format!(
                    "line {}: the component of frequency 0 lifts the still surface by {im} m \
                     (its imaginary part); stancf's surface is z = 0",
                    c.line
                ));
            }
            continue;
        }
        if amplitude == 0.0 {
            continue;
        }
        waves.push(AiryWave {
            amplitude,
            period: 2.0 * PI / c.omega,
            heading_deg: c.heading.to_degrees(),
            phase_deg: 90.0 - im.atan2(re).to_degrees(),
        });
    }
    Ok(waves)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// MoorDyn's elevation and horizontal velocity of one component at
    /// (x, y, z) and t, unstretched (SpectrumKin::getWaveKin with the
    /// surface at z = 0): the reference the conversion (W2b) must meet.
    fn moordyn_component(c: &WaveComponent, k: f64, h: f64, p: [f64; 3], t: f64) -> [f64; 3] {
        let [re, im] = c.amplitude;
        let (a, phase) = (re.hypot(im), im.atan2(re));
        let distance = c.heading.cos() * p[0] + c.heading.sin() * p[1];
        let s = a * (c.omega * t - k * distance + phase).sin();
        let cosh_over_sinh = (k * (p[2] + h)).cosh() / (k * h).sinh();
        let u = c.omega * s * cosh_over_sinh;
        [s, u * c.heading.cos(), u * c.heading.sin()]
    }

    /// Each component of MoorDyn's wavekin_7 file, turned into a wave
    /// (W2b), has MoorDyn's elevation and velocity at points and times
    /// spread over its period and a wavelength, to round-off.
    #[test]
    fn summed_components_become_the_same_airy_waves() {
        let rows = [
            (0.35, [1.0, 0.0], 0.0),
            (0.4, [0.0, 1.0], 1.57),
            (0.9, [-0.3, -0.2], -2.5),
        ];
        let (h, g) = (50.0, 9.81);
        for (omega, amplitude, heading) in rows {
            let c = WaveComponent {
                omega,
                amplitude,
                heading,
                line: 1,
            };
            let wave = airy_waves(&[c]).unwrap()[0];
            let sea = stancf::water::kinematics::Sea::new(h, g, &[wave]).unwrap();
            let k = stancf::water::waves::wave_number(omega, h, g);
            for (n, t) in [0.0, 3.1, 7.7, 12.9].into_iter().enumerate() {
                let p = [
                    -40.0 + 31.0 * n as f64,
                    13.0 - 9.0 * n as f64,
                    -7.0 - 5.0 * n as f64,
                ];
                let want = moordyn_component(&c, k, h, p, t);
                let got = sea.kinematics(&p, t);
                let have = [got.eta, got.velocity[0], got.velocity[1]];
                for i in 0..3 {
                    assert!(
                        (have[i] - want[i]).abs() < 1e-12,
                        "w {omega} at {p:?}, t {t}: {have:?} against MoorDyn's {want:?}"
                    );
                }
            }
        }
    }

    #[test]
    fn a_still_component_is_dropped_unless_it_lifts_the_surface() {
        let still = |im: f64| WaveComponent {
            omega: 0.0,
            amplitude: [0.3, im],
            heading: 0.0,
            line: 4,
        };
        assert!(airy_waves(&[still(0.0)]).unwrap().is_empty());
        let e = airy_waves(&[still(0.2)]).unwrap_err();
        assert!(e.starts_with("line 4: the component of frequency 0"), "{e}");
    }
}
