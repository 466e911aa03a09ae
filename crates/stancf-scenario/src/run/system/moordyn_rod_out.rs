//! MoorDyn's per-rod output files, `<deck>_Rod<n>.out` (docs/interface.md,
//! "Results of a system"): for a rod whose `RodOutputs` hold one of the
//! letters MoorDyn opens a file for (`pvUDctsd`), the node quantities of
//! the rigid rod stancf has, written as MoorDyn's `Rod::Output` writes
//! them: `Time`, then `p` `Node<i>px py pz` (m) and `v` `Node<i>vx vy vz`
//! (m/s) for its NumSegs + 1 nodes (one for a rod of zero length), a units
//! row unless `WriteUnits 0`, the widths and numbers of the main file
//! (`super::moordyn_out`). MoorDyn's force flags (`f W B X Y A a P b`) get
//! no columns, which `check` notes.

use super::moordyn_out::{write_time, write_value, TIME_WIDTH, WIDTH};
use crate::output::{AtomicFile, Dest};
use std::io::Write;

/// The flags written, in MoorDyn's order, with their column suffixes and
/// unit.
const WRITTEN: [(char, [&str; 3], &str); 2] = [
    ('p', ["px", "py", "pz"], "(m)"),
    ('v', ["vx", "vy", "vz"], "(m/s)"),
];

/// One rod's file.
pub(super) struct RodOut {
    file: AtomicFile,
    /// The system rod it writes.
    pub(super) rod: usize,
    /// Positions, velocities written.
    flags: [bool; 2],
    at_rest: bool,
}

impl RodOut {
    /// Creates `name` for rod `rod` of `nodes` nodes whose `RodOutputs`
    /// are `flags`, with its header (and units) rows.
    pub(super) fn create(
        dest: &Dest,
        name: &str,
        (rod, nodes): (usize, usize),
        flags: &str,
        units: bool,
        at_rest: bool,
    ) -> std::io::Result<Self> {
        let written = WRITTEN.map(|(f, ..)| flags.contains(f));
        let mut file = dest.create(name)?;
        let w = file.writer();
        write!(w, "{:>TIME_WIDTH$}", "Time")?;
        for ((_, suffixes, _), on) in WRITTEN.iter().zip(written) {
            if on {
                for i in 0..nodes {
                    for s in suffixes {
                        write!(w, "{:>WIDTH$}", format!("Node{i}{s}"))?;
                    }
                }
            }
        }
        writeln!(w)?;
        if units {
            write!(w, "{:>TIME_WIDTH$}", "(s)")?;
            for ((_, _, unit), on) in WRITTEN.iter().zip(written) {
                if on {
                    for _ in 0..3 * nodes {
                        write!(w, "{unit:>WIDTH$}")?;
                    }
                }
            }
            writeln!(w)?;
        }
        Ok(RodOut {
            file,
            rod,
            flags: written,
            at_rest,
        })
    }

    /// The row of time `t` from the rod's nodes (position, velocity).
    pub(super) fn write_row(
        &mut self,
        t: f64,
        nodes: &[([f64; 3], [f64; 3])],
    ) -> std::io::Result<()> {
        let t = if self.at_rest { 0.0 } else { t };
        let w = self.file.writer();
        write_time(w, t)?;
        for (k, on) in self.flags.iter().enumerate() {
            if *on {
                for node in nodes {
                    let v = if k == 0 { node.0 } else { node.1 };
                    for c in v {
                        write_value(w, c)?;
                    }
                }
            }
        }
        writeln!(w)
    }

    pub(super) fn commit(self) -> std::io::Result<()> {
        self.file.commit()
    }
}
