//! Whether this process may hand work to rayon's threads (docs/method.md
//! §7.8, §11.14).
//!
//! A process forked from one whose rayon pool has started (Python's
//! `ProcessPoolExecutor` forks on Linux; so does `multiprocessing`)
//! inherits the pool's bookkeeping but not its threads: a parallel
//! iterator there waits forever for workers that do not exist. So the
//! first time the library considers the threads it keeps the process's
//! id, and a process whose id differs (a fork made after that) does the
//! work on its own thread. The results are the same either way: which
//! thread solves a line or evaluates an element changes nothing.

use std::sync::OnceLock;

/// The id of the process that first considered rayon's threads.
static POOL_PROCESS: OnceLock<u32> = OnceLock::new();

/// False in a process forked after this library first considered
/// rayon's threads (whose pool the fork cannot use); true otherwise.
/// Call it before any call into rayon.
pub(crate) fn usable() -> bool {
    let me = std::process::id();
    *POOL_PROCESS.get_or_init(|| me) == me
}
