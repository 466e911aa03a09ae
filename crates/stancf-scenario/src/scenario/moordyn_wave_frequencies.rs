//! MoorDyn-C's `wave_frequencies.txt` (docs/interface.md, "Water"): the
//! wave components its `WaveKin` 2 and 7 read, rows `w re im [beta]`.

use std::f64::consts::PI;
use std::path::Path;

/// The file MoorDyn-C reads its wave components from (`WaveKin` 2 and 7),
/// in the deck's folder.
pub const WAVE_FREQUENCIES_FILE: &str = "wave_frequencies.txt";

/// One row of [`WAVE_FREQUENCIES_FILE`]: angular frequency (rad/s), the
/// complex amplitude (m) and the heading (rad), and its line.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct WaveComponent {
    pub omega: f64,
    pub amplitude: [f64; 2],
    pub heading: f64,
    pub line: usize,
}

/// MoorDyn-C's `wave_frequencies.txt`: rows `w re im [beta]` (blank lines
/// skipped), at least 2, w not negative and finite, |beta| <= 2 pi, as
/// MoorDyn's `spectrumFromFile` reads them. Errors name the line.
pub fn read_wave_frequencies(path: &Path) -> Result<Vec<WaveComponent>, String> {
    let text = crate::input_file::read_text(path)?;
    let mut rows = Vec::new();
    let shape = "\"w re im [beta]\" (rad/s, m, m, rad)";
    for (at, mut v) in super::moordyn_water::table_rows(&text, 0, 3..=4, shape)? {
        v.resize(4, 0.0);
        if v[0] < 0.0 {
            return Err(format!(
                "line {at}: the frequency {} rad/s is negative",
                v[0]
            ));
        }
        if v[3].abs() > 2.0 * PI {
            return Err(format!(
                "line {at}: the direction {} is beyond 2 pi; it is in radians",
                v[3]
            ));
        }
        rows.push(WaveComponent {
            omega: v[0],
            amplitude: [v[1], v[2]],
            heading: v[3],
            line: at,
        });
    }
    if rows.len() < 2 {
        return Err(format!(
            "{} row(s); MoorDyn asks for 2 at least",
            rows.len()
        ));
    }
    Ok(rows)
}
