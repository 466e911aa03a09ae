//! Result files (docs/interface.md) written so that a crash leaves either
//! the old file or the complete new one: each file is streamed into
//! `<name>.partial` next to its final path and renamed over it only when
//! complete (a rename within a directory is atomic on POSIX systems).

pub use crate::result_folder::ResultFolder;
use std::fs::File;
use std::io::{self, BufWriter, Write};
use std::path::{Path, PathBuf};

/// A file that appears under its final name only on [`AtomicFile::commit`].
pub struct AtomicFile {
    path: PathBuf,
    partial: PathBuf,
    writer: BufWriter<File>,
}

impl AtomicFile {
    pub fn create(dir: &Path, name: &str) -> io::Result<Self> {
        let path = dir.join(name);
        let partial = dir.join(format!("{name}.partial"));
        let file = File::create(&partial)?;
        Ok(AtomicFile {
            path,
            partial,
            writer: BufWriter::with_capacity(1 << 16, file),
        })
    }

    pub fn writer(&mut self) -> &mut BufWriter<File> {
        &mut self.writer
    }

    /// Flushes, syncs and renames the file into place.
    pub fn commit(self) -> io::Result<()> {
        let file = self.writer.into_inner().map_err(|e| e.into_error())?;
        file.sync_all()?;
        drop(file);
        std::fs::rename(&self.partial, &self.path)
    }
}

/// Writes `contents` to `dir/name` atomically.
pub fn write_atomic(dir: &Path, name: &str, contents: &[u8]) -> io::Result<()> {
    let mut f = AtomicFile::create(dir, name)?;
    f.writer().write_all(contents)?;
    f.commit()
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
