//! The line failures of a run (docs/method.md §11.16): what is given
//! ([`LineFailure`]), what happened ([`Release`], [`Dropped`]) and what a
//! simulation keeps of them ([`Failures`]); the releases themselves are
//! `release.rs`.

/// A failure of the attachment of `lines` at `point`: due at `time` (s)
/// or when the tension at one of those line ends reaches `tension` (N),
/// whichever comes first; at least one of the two is given.
#[derive(Clone, Debug, PartialEq)]
pub struct LineFailure {
    pub point: usize,
    pub lines: Vec<usize>,
    pub time: Option<f64>,
    pub tension: Option<f64>,
}

/// What set a failure off.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Trigger {
    /// Its time came.
    Time,
    /// The end of `line` pulled on the point with `tension` (N) at the
    /// end of the step, at or above the threshold.
    Tension { line: usize, tension: f64 },
}

/// A failure that happened: at the end of step `step` (time `time`),
/// the ends of `lines` left `point` for the new free point `new_point`.
#[derive(Clone, Debug, PartialEq)]
pub struct Release {
    /// The failure's index in the list given to
    /// [`SystemSimulation::set_failures`].
    pub failure: usize,
    pub time: f64,
    pub step: usize,
    pub point: usize,
    pub lines: Vec<usize>,
    pub new_point: usize,
    pub trigger: Trigger,
}

/// A failure that will not happen: its lines were all released by
/// failures before it, or releasing them would leave a free point with
/// no line (MoorDyn-F ignores such a failure too).
#[derive(Clone, Debug, PartialEq)]
pub struct Dropped {
    pub failure: usize,
    pub time: f64,
    pub why: String,
}

/// The failures still to come (with their index in the given list), the
/// releases so far and the failures dropped.
#[derive(Clone, Debug, Default)]
pub(super) struct Failures {
    pub(super) pending: Vec<(usize, LineFailure)>,
    pub(super) releases: Vec<Release>,
    pub(super) dropped: Vec<Dropped>,
}
