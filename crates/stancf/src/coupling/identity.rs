//! The identity of a coupled system (docs/method.md §13.4): what a saved
//! state carries so that it is restored only into a system whose states
//! it can stand for.

use crate::error::ModelError;
use crate::integrator::StepSettings;
use crate::system::System;
use std::fmt::{self, Write};

/// The part of an [`Identity`] the builders of a handle do not change:
/// the system and its step settings, hashed once (the `Debug` text of a
/// system of 2000 elements is about 8 MB: some 50 ms).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) struct SystemDigest {
    lines: usize,
    points: usize,
    /// [`Fnv1a`] of the system's and the step settings' `Debug` text.
    hash: u64,
}

impl SystemDigest {
    /// The digest of `system` stepped with `steps`: a 64-bit FNV-1a hash
    /// over the `Debug` text of the system (every line's model: node
    /// count, element type, DOFs per node, material, loads, water, seabed
    /// and constraints; every point: its kind, motion, position, mass and
    /// load; gravity) and of the step settings, streamed into the hash
    /// without building the text. `Debug` prints every field and floats to
    /// the bit (Rust prints the shortest text that reads back to the same
    /// float), so two handles built from the same scenario text get the
    /// same value and a field added to a model later is covered without
    /// being listed here; the system holds no map, pointer or clock whose
    /// text could differ between two builds of it.
    pub(super) fn of(system: &System, steps: &StepSettings) -> Self {
        let mut hash = Fnv1a(0xcbf2_9ce4_8422_2325);
        // Fnv1a's `write_str` cannot fail.
        let _ = write!(hash, "{system:?}|{steps:?}");
        SystemDigest {
            lines: system.lines().len(),
            points: system.points().len(),
            hash: hash.0,
        }
    }
}

/// What makes the states of two handles interchangeable: the counts a
/// message can name and a fingerprint of everything else.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) struct Identity {
    lines: usize,
    points: usize,
    /// The [`SystemDigest`]'s hash continued over the coupled points'
    /// order and the step halvings.
    fingerprint: u64,
}

impl Identity {
    /// The identity of a handle of the digested system with these
    /// coupled points' order and step halvings.
    pub(super) fn of(digest: &SystemDigest, coupled: &[usize], step_halvings: u32) -> Self {
        let mut hash = Fnv1a(digest.hash);
        let _ = write!(hash, "|{coupled:?}|{step_halvings}");
        Identity {
            lines: digest.lines,
            points: digest.points,
            fingerprint: hash.0,
        }
    }

    /// Refuses a state of `saved`'s identity in a handle of this one,
    /// naming both systems' counts.
    pub(super) fn admit(&self, saved: &Identity) -> Result<(), ModelError> {
        if saved == self {
            return Ok(());
        }
        let same_counts = (saved.lines, saved.points) == (self.lines, self.points);
        Err(ModelError::invalid(
            "state",
            format!(
                "a state saved from another system ({}) cannot be restored into this one \
                 ({}{}); restore states saved from this handle, or from one opened from the \
                 same scenario",
                counts(saved.lines, saved.points),
                counts(self.lines, self.points),
                if same_counts {
                    ": as many lines and points, but other lines, points, coupled order or \
                     step settings"
                } else {
                    ""
                }
            ),
        ))
    }
}

/// "N lines, M points" (singular for one).
fn counts(lines: usize, points: usize) -> String {
    let plural = |n: usize, what: &str| format!("{n} {what}{}", if n == 1 { "" } else { "s" });
    format!("{}, {}", plural(lines, "line"), plural(points, "point"))
}

/// The FNV-1a hash (64 bits) of the text written into it.
struct Fnv1a(u64);

impl Write for Fnv1a {
    fn write_str(&mut self, s: &str) -> fmt::Result {
        for &b in s.as_bytes() {
            self.0 = (self.0 ^ u64::from(b)).wrapping_mul(0x0000_0100_0000_01b3);
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::Fnv1a;
    use std::fmt::Write;

    #[test]
    fn fnv1a_gives_the_published_values() {
        // The reference values of the FNV test suite (isthe.com/chongo).
        for (text, want) in [
            ("", 0xcbf2_9ce4_8422_2325u64),
            ("a", 0xaf63_dc4c_8601_ec8c),
            ("foobar", 0x8594_4171_f739_67e8),
        ] {
            let mut h = Fnv1a(0xcbf2_9ce4_8422_2325);
            h.write_str(text).unwrap();
            assert_eq!(h.0, want, "{text:?}");
        }
    }
}
