//! MoorDyn's main output file, `<deck>.out` (docs/interface.md, "Results
//! of a system"): where a deck asks for OUTPUTS, the channels stancf
//! computes written as MoorDyn's `WriteOutputs` writes them, so that the
//! post-processing users have for MoorDyn (MHKiT's `read_moordyn`,
//! MoorDyn's own scripts) reads stancf's results unchanged: a header row
//! `Time` and the channels' names as the deck writes them, a units row
//! (`(s)` and MoorDyn's units, unless the deck says `WriteUnits 0`), then
//! a row per written time, the time right-aligned in 10 characters with 4
//! decimals and every value in 20 in C++'s `scientific` with 7 digits
//! after the point (`1.2345670e+05`), whitespace between. A channel MoorDyn
//! skips (a name it does not know) has no column, as in MoorDyn's file; a
//! channel MoorDyn knows and stancf does not compute has none either (a
//! number it could not be), which `check`'s note on it says.

use crate::output::{AtomicFile, Dest};
use crate::scenario::OutputChannel;
use std::io::Write;

/// The widths of MoorDyn's columns (`setw(10)` for the time, `WIDTH` for
/// the channels) and its `PRECISION`.
pub(super) const TIME_WIDTH: usize = 10;
pub(super) const WIDTH: usize = 20;
const PRECISION: usize = 7;

/// A row's time as MoorDyn writes it: `fixed`, 4 decimals, in 10.
pub(super) fn write_time(w: &mut impl Write, t: f64) -> std::io::Result<()> {
    write!(w, "{t:>TIME_WIDTH$.4}")
}

/// A value as MoorDyn writes it: `scientific`, `PRECISION` digits, in
/// `WIDTH`.
pub(super) fn write_value(w: &mut impl Write, v: f64) -> std::io::Result<()> {
    write!(w, "{:>WIDTH$}", cpp_scientific(v, PRECISION))
}

/// The open file and the channels (their indices among the deck's) it
/// has columns for.
pub(super) struct MoorDynOut {
    file: AtomicFile,
    columns: Vec<usize>,
    /// A static run's equilibrium is MoorDyn's row of t = 0 (what its
    /// `Init` writes after the initial conditions), not stancf's load
    /// factor 1.
    at_rest: bool,
}

impl MoorDynOut {
    /// Creates `name` in `dest` with its header (and units) rows.
    pub(super) fn create(
        dest: &Dest,
        name: &str,
        channels: &[OutputChannel],
        units: bool,
        at_rest: bool,
    ) -> std::io::Result<Self> {
        let columns: Vec<usize> = channels
            .iter()
            .enumerate()
            .filter(|(_, c)| c.computed && c.channel.moordyn_units().is_some())
            .map(|(i, _)| i)
            .collect();
        let mut file = dest.create(name)?;
        let w = file.writer();
        write!(w, "{:>TIME_WIDTH$}", "Time")?;
        for &i in &columns {
            write!(w, "{:>WIDTH$}", channels[i].name)?;
        }
        writeln!(w)?;
        if units {
            write!(w, "{:>TIME_WIDTH$}", "(s)")?;
            for &i in &columns {
                let unit = channels[i].channel.moordyn_units().expect("kept above");
                write!(w, "{unit:>WIDTH$}")?;
            }
            writeln!(w)?;
        }
        Ok(MoorDynOut {
            file,
            columns,
            at_rest,
        })
    }

    /// The row of time `t` from the values of all the deck's channels
    /// (None where stancf does not compute one).
    pub(super) fn write_row(&mut self, t: f64, values: &[Option<f64>]) -> std::io::Result<()> {
        let t = if self.at_rest { 0.0 } else { t };
        let w = self.file.writer();
        write_time(w, t)?;
        for &i in &self.columns {
            write_value(w, values[i].expect("a column's channel is computed"))?;
        }
        writeln!(w)
    }

    pub(super) fn commit(self) -> std::io::Result<()> {
        self.file.commit()
    }
}

/// `v` as C++'s `std::scientific` with `precision` digits after the
/// point: `d.ddddddde+XX`, the exponent signed and of two digits at least
/// (Rust's `{:e}` writes `d.dddddde5`).
pub fn cpp_scientific(v: f64, precision: usize) -> String {
    let s = format!("{v:.precision$e}");
    let (mantissa, exponent) = s.split_once('e').expect("{:e} writes an exponent");
    let e: i32 = exponent.parse().expect("an integer exponent");
    let sign = if e < 0 { '-' } else { '+' };
    format!("{mantissa}e{sign}{:02}", e.abs())
}

#[cfg(test)]
mod tests {
    use super::cpp_scientific;

    /// What C++'s `std::cout << std::scientific << std::setprecision(7)`
    /// prints for these values.
    #[test]
    fn numbers_are_written_as_cpp_writes_them_in_scientific() {
        for (v, want) in [
            (123456.789, "1.2345679e+05"),
            (-0.000123, "-1.2300000e-04"),
            (0.0, "0.0000000e+00"),
            (-0.0, "-0.0000000e+00"),
            (1.5e-300, "1.5000000e-300"),
            (9.99999999e9, "1.0000000e+10"),
        ] {
            assert_eq!(cpp_scientific(v, 7), want);
        }
    }
}
