//! MoorDyn's per-body output files, `<deck>_Body<n>.out` (docs/interface.md,
//! "Results of a system"): MoorDyn-C opens one for every body of a deck
//! and writes, as its `Body::Output` does, `Time`, the reference point
//! `x y z` (m) and MoorDyn's `roll pitch yaw` (degrees) at each output
//! time, tab-separated (a tab and a space after each value but the last),
//! the numbers in C++'s default stream format (six significant digits,
//! `%g`), a units row `(s) (m) ... (deg)` unless `WriteUnits 0`.

use super::bodies::BodyRow;
use crate::output::{AtomicFile, Dest};
use std::io::Write;

/// One body's file.
pub(super) struct BodyOut {
    file: AtomicFile,
    /// The system body it writes.
    pub(super) body: usize,
    at_rest: bool,
}

impl BodyOut {
    /// Creates `name` for the system's body `body`, with its header (and
    /// units) rows.
    pub(super) fn create(
        dest: &Dest,
        name: &str,
        body: usize,
        units: bool,
        at_rest: bool,
    ) -> std::io::Result<Self> {
        let mut file = dest.create(name)?;
        let w = file.writer();
        writeln!(w, "Time\t x\ty\tz\troll\tpitch\tyaw")?;
        if units {
            writeln!(w, "(s)\t (m)\t(m)\t(m)\t(deg)\t(deg)\t(deg)")?;
        }
        Ok(BodyOut {
            file,
            body,
            at_rest,
        })
    }

    /// The row of time `t` (0 for a static run's equilibrium, MoorDyn's
    /// row after its initial conditions).
    pub(super) fn write_row(&mut self, t: f64, row: &BodyRow) -> std::io::Result<()> {
        let t = if self.at_rest { 0.0 } else { t };
        let p = row.motion.position;
        let a = row.angles;
        let w = self.file.writer();
        write!(w, "{}\t ", cpp_default(t))?;
        for v in p {
            write!(w, "{}\t ", cpp_default(v))?;
        }
        writeln!(
            w,
            "{}\t {}\t {}",
            cpp_default(a[0]),
            cpp_default(a[1]),
            cpp_default(a[2])
        )
    }

    pub(super) fn commit(self) -> std::io::Result<()> {
        self.file.commit()
    }
}

/// `v` as C++'s default stream format writes it (`%g` with precision 6):
/// six significant digits, trailing zeros and a bare point dropped,
/// scientific (`1.5e-05`, the exponent of two digits at least) where the
/// exponent is below -4 or at least 6.
pub fn cpp_default(v: f64) -> String {
    if v == 0.0 {
        return if v.is_sign_negative() { "-0" } else { "0" }.to_string();
    }
    // Rounded to six significant digits first: its exponent decides.
    let s = format!("{v:.5e}");
    let (mantissa, exponent) = s.split_once('e').expect("{:e} writes an exponent");
    let e: i32 = exponent.parse().expect("an integer exponent");
    let trim = |m: &str| -> String {
        if m.contains('.') {
            m.trim_end_matches('0').trim_end_matches('.').to_string()
        } else {
            m.to_string()
        }
    };
    if !(-4..6).contains(&e) {
        let sign = if e < 0 { '-' } else { '+' };
        format!("{}e{sign}{:02}", trim(mantissa), e.abs())
    } else {
        let decimals = (5 - e) as usize;
        trim(&format!("{v:.decimals$}"))
    }
}

#[cfg(test)]
mod tests {
    use super::cpp_default;

    /// What `std::cout << v` prints for these values.
    #[test]
    fn numbers_are_written_as_cpp_writes_them_by_default() {
        for (v, want) in [
            (0.0, "0"),
            (1.0, "1"),
            (-50.0, "-50"),
            (0.1, "0.1"),
            (123456.7, "123457"),
            (1234567.0, "1.23457e+06"),
            (999999.5, "1e+06"),
            (0.0001, "0.0001"),
            (0.00001234, "1.234e-05"),
            (-1.23456789, "-1.23457"),
            (2.5e-300, "2.5e-300"),
            (99.99996, "100"),
        ] {
            assert_eq!(cpp_default(v), want, "{v}");
        }
    }
}
