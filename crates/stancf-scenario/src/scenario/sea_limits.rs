//! What no sea has: waves steeper than the breaking limit or higher than
//! the depth lets them be (issue 28, item 17). They are warned of, once,
//! by `check` and `run`: Airy's kinematics are defined at any height, but
//! a result of them describes no sea.

use super::SystemScenario;

/// The limit steepness H/L of a progressive wave (Michell 1893: 0.142,
/// about 1/7), beyond which it breaks.
pub const BREAKING_STEEPNESS: f64 = 1.0 / 7.0;

/// The limit height over depth of a wave in shallow water (McCowan 1894:
/// H/h = 0.78), beyond which it breaks.
pub const BREAKING_DEPTH_RATIO: f64 = 0.78;

/// Warnings of the waves a linear (Airy) wave cannot be (issue 28, item
/// 17): a regular wave, or a JONSWAP sea by its Hs and Tp, steeper than
/// [`BREAKING_STEEPNESS`] (its length L = 2 pi / k from the dispersion
/// relation (W1) at the water's depth) or higher than
/// [`BREAKING_DEPTH_RATIO`] times the depth. They run (Airy's kinematics
/// are defined at any height), but no sea has them.
pub(super) fn breaking_wave_notes(sc: &SystemScenario) -> Vec<String> {
    use stancf::error::Sig;
    let Some(w) = &sc.water else {
        return Vec::new();
    };
    let g = sc.gravity.iter().map(|c| c * c).sum::<f64>().sqrt();
    let mut waves: Vec<(String, f64, f64)> = w
        .waves
        .iter()
        .enumerate()
        .map(|(i, a)| (format!("water.waves[{i}]"), 2.0 * a.amplitude, a.period))
        .collect();
    if let Some(j) = &w.jonswap {
        waves.push(("water.jonswap (hs, tp)".into(), j.hs, j.tp));
    }
    let mut notes = Vec::new();
    for (key, height, period) in waves {
        if height == 0.0 || g.is_nan() || g <= 0.0 {
            continue;
        }
        let k = stancf::water::waves::wave_number(2.0 * std::f64::consts::PI / period, w.depth, g);
        let length = 2.0 * std::f64::consts::PI / k;
        if height / length > BREAKING_STEEPNESS {
            notes.push(format!(
                "{key}: a wave {} m high and {} m long (period {} s in {} m of water) is \
                 steeper than a wave can be (H/L = {:.3} > 1/7, the breaking limit); its \
                 kinematics are linear theory's, which no sea has",
                Sig(height),
                Sig(length),
                Sig(period),
                Sig(w.depth),
                height / length
            ));
        }
        if height > BREAKING_DEPTH_RATIO * w.depth {
            notes.push(format!(
                "{key}: a wave {} m high in {} m of water is higher than a wave there can be \
                 (H/h = {:.2} > 0.78, where waves break on the depth)",
                Sig(height),
                Sig(w.depth),
                height / w.depth
            ));
        }
    }
    notes
}

/// A note that a static analysis does not see the waves of its water
/// (statics see buoyancy and the steady current, docs/method.md §12.4).
pub(super) fn static_waves_note(sc: &SystemScenario) -> Option<String> {
    let w = sc.water.as_ref()?;
    let waves = !w.waves.is_empty() || w.jonswap.is_some();
    (waves && sc.analysis.kind == super::AnalysisKind::Static).then(|| {
        "water: a static analysis sees the water's buoyancy and steady current; its waves \
         act in a dynamic one only"
            .to_string()
    })
}
