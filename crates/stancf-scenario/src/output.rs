//! Result files (docs/interface.md) written so that a crash leaves either
//! the old file or the complete new one: each file is streamed into
//! `<name>.partial` next to its final path and renamed over it only when
//! complete (a rename within a directory is atomic on POSIX systems).

pub use crate::result_folder::ResultFolder;
use std::collections::BTreeMap;
use std::fs::File;
use std::io::{self, BufWriter, Write};
use std::path::{Path, PathBuf};
use std::sync::{Arc, Mutex};

/// A file that appears under its final name only on [`AtomicFile::commit`].
pub struct AtomicFile {
    path: PathBuf,
    partial: PathBuf,
    writer: Sink,
    /// Where the copy goes on commit, under the file's name in the run's
    /// folder.
    collect: Option<(Collector, String)>,
}

/// The bytes of a result file on their way to disk and, when its run
/// collects its results (see [`Collector`]), into a copy in memory: the
/// same bytes, formatted once.
pub struct Sink {
    file: BufWriter<File>,
    copy: Option<Vec<u8>>,
}

impl Write for Sink {
    fn write(&mut self, buf: &[u8]) -> io::Result<usize> {
        self.file.write_all(buf)?;
        if let Some(copy) = &mut self.copy {
            copy.extend_from_slice(buf);
        }
        Ok(buf.len())
    }

    fn flush(&mut self) -> io::Result<()> {
        self.file.flush()
    }
}

impl AtomicFile {
    pub fn create(dir: &Path, name: &str) -> io::Result<Self> {
        Self::create_in(Dest { dir, collect: None }, name)
    }

    /// A file of `dest` (its copy kept when `dest` collects).
    pub fn create_in(dest: Dest, name: &str) -> io::Result<Self> {
        let path = dest.dir.join(name);
        let partial = dest.dir.join(format!("{name}.partial"));
        let file = File::create(&partial)?;
        Ok(AtomicFile {
            path,
            partial,
            writer: Sink {
                file: BufWriter::with_capacity(1 << 16, file),
                copy: dest.collect.map(|_| Vec::new()),
            },
            collect: dest.collect.map(|c| (c.clone(), name.to_string())),
        })
    }

    pub fn writer(&mut self) -> &mut Sink {
        &mut self.writer
    }

    /// Flushes, syncs and renames the file into place (and hands its
    /// copy to the collector).
    pub fn commit(self) -> io::Result<()> {
        let file = self.writer.file.into_inner().map_err(|e| e.into_error())?;
        file.sync_all()?;
        drop(file);
        std::fs::rename(&self.partial, &self.path)?;
        if let (Some((collector, name)), Some(copy)) = (self.collect, self.writer.copy) {
            collector.keep(name, copy);
        }
        Ok(())
    }
}

/// Writes `contents` to `dir/name` atomically.
pub fn write_atomic(dir: &Path, name: &str, contents: &[u8]) -> io::Result<()> {
    Dest { dir, collect: None }.write(name, contents)
}

/// The result files of a run kept in memory as they are written (`stancf.run`
/// in Python takes its results from here: `RunOptions::collect`): the
/// files' names in the run's folder (`lines/1/nodes.csv`) and their bytes,
/// for the files committed so far (a run that stops early commits the
/// rows up to its last converged step).
#[derive(Clone, Debug, Default)]
pub struct Collector(Arc<Mutex<BTreeMap<String, Vec<u8>>>>);

impl Collector {
    fn keep(&self, name: String, bytes: Vec<u8>) {
        self.0.lock().expect("not poisoned").insert(name, bytes);
    }

    /// The files collected so far (the collector is left empty).
    pub fn take(&self) -> BTreeMap<String, Vec<u8>> {
        std::mem::take(&mut *self.0.lock().expect("not poisoned"))
    }
}

/// Where a run writes: its folder, and the collector that keeps a copy of
/// each file when the run collects its results.
#[derive(Clone, Copy)]
pub struct Dest<'a> {
    pub dir: &'a Path,
    pub collect: Option<&'a Collector>,
}

impl Dest<'_> {
    /// A file of this destination ([`AtomicFile::create_in`]).
    pub fn create(&self, name: &str) -> io::Result<AtomicFile> {
        AtomicFile::create_in(*self, name)
    }

    /// Writes `contents` to the file `name` atomically.
    pub fn write(&self, name: &str, contents: &[u8]) -> io::Result<()> {
        let mut f = self.create(name)?;
        f.writer().write_all(contents)?;
        f.commit()
    }
}

/// A number for a CSV file: the shortest text that reads back to the same
/// f64, in exponent form outside [1e-4, 1e15) so no field gets long.
/// Callers never pass a non-finite value (they are checked first).
#[derive(Clone, Copy)]
pub struct Num(pub f64);

impl std::fmt::Display for Num {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let x = self.0;
        debug_assert!(x.is_finite(), "non-finite value written");
        let a = x.abs();
        if x == 0.0 {
            f.write_str("0")
        } else if (1e-4..1e15).contains(&a) {
            write!(f, "{x}")
        } else {
            write!(f, "{x:e}")
        }
    }
}

/// The times of a dynamic run's rows written as the decimal numbers they
/// are: the time of step k is t0 + k dt in decimals, `14.7`, not the
/// accumulated `14.700000000000074` (issue 29). A time is rounded to the
/// most decimals of the shortest decimal forms of the times the user
/// wrote (the step, the start, the duration: a shortened last step lands
/// on the duration), which keeps every time of the run and takes off the
/// round-off of adding the steps (far below the last decimal kept). Every
/// result file of single cables and systems writes its times through
/// [`TimeGrid::time`]; a static run's load factors are written as they are
/// ([`TimeGrid::default`]).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct TimeGrid {
    /// 10^decimals; None: times are written as they are.
    scale: Option<f64>,
}

/// The most decimals a [`TimeGrid`] rounds to: 10^22 is the largest power
/// of ten an f64 holds exactly.
const MAX_TIME_DECIMALS: usize = 22;

impl TimeGrid {
    /// The grid of the times `given` (the step, the start, the duration,
    /// as the user wrote them).
    pub fn of(given: &[f64]) -> Self {
        let decimals = given.iter().map(|&x| decimals(x)).max().unwrap_or(0);
        TimeGrid {
            scale: (decimals <= MAX_TIME_DECIMALS).then(|| 10f64.powi(decimals as i32)),
        }
    }

    /// `t` rounded to the grid's decimals: the f64 nearest to the decimal
    /// number (a whole number over an exact power of ten, divided once);
    /// `t` itself where the grid keeps every digit of it.
    pub fn time(&self, t: f64) -> f64 {
        match self.scale {
            Some(p) if (t * p).abs() < 2f64.powi(52) => (t * p).round() / p,
            _ => t,
        }
    }
}

/// The decimals of the shortest decimal form of `x` (0 for a whole or
/// non-finite number).
fn decimals(x: f64) -> usize {
    if !x.is_finite() {
        return 0;
    }
    let text = format!("{}", x.abs());
    text.split_once('.').map_or(0, |(_, d)| d.len())
}

/// A JSON number, or null when not finite (JSON has no NaN or infinity).
pub fn json_num(x: f64) -> serde_json::Value {
    if x.is_finite() {
        serde_json::json!(x)
    } else {
        serde_json::Value::Null
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numbers_round_trip() {
        for &x in &[
            0.0,
            1.0,
            -2.5,
            1e-5,
            3.4e9,
            1.25e-13,
            1e300,
            -7.123456789012345e-3,
            1e15,
        ] {
            let s = Num(x).to_string();
            assert_eq!(s.parse::<f64>().unwrap(), x, "{s}");
            assert!(s.len() <= 24, "{s}");
        }
    }

    #[test]
    fn a_time_of_k_steps_is_written_as_the_decimal_product_of_k_and_the_step() {
        let grid = TimeGrid::of(&[0.1, 0.0, 14.7]);
        let mut t = 0.0;
        for k in 1..=147 {
            t += 0.1;
            let written = Num(grid.time(t)).to_string();
            assert_eq!(written, format!("{}", k as f64 / 10.0));
        }
        assert_eq!(Num(grid.time(t)).to_string(), "14.7");
        // The shortened last step of 0.0003 s steps over 0.001 s.
        let grid = TimeGrid::of(&[0.0003, 0.0, 0.001]);
        assert_eq!(
            Num(grid.time(0.0009000000000000001 + 1e-4)).to_string(),
            "0.001"
        );
        // Without a grid, and beyond the decimals an f64 holds, times stay.
        assert_eq!(TimeGrid::default().time(0.1 + 0.2), 0.1 + 0.2);
        assert_eq!(TimeGrid::of(&[1e-30]).time(0.1 + 0.2), 0.1 + 0.2);
    }

    #[test]
    fn commit_replaces_and_partial_never_shows_under_the_final_name() {
        let dir = std::env::temp_dir().join(format!("stancf-atomic-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        write_atomic(&dir, "a.csv", b"old\n").unwrap();
        let mut f = AtomicFile::create(&dir, "a.csv").unwrap();
        f.writer().write_all(b"new\n").unwrap();
        f.writer().flush().unwrap();
        // Not committed yet: the old file is intact.
        assert_eq!(std::fs::read_to_string(dir.join("a.csv")).unwrap(), "old\n");
        f.commit().unwrap();
        assert_eq!(std::fs::read_to_string(dir.join("a.csv")).unwrap(), "new\n");
        assert!(!dir.join("a.csv.partial").exists());
        std::fs::remove_dir_all(&dir).unwrap();
    }
}
