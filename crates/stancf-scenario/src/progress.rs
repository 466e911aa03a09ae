//! A progress bar on standard error for long runs: steps done, simulated
//! time, Newton iterations per step and the time left. It appears only
//! after the run has taken a second, only when standard error is a
//! terminal (never in a pipe or a log file) and not with `--quiet`; it
//! redraws at most ten times a second and erases itself at the end.

use std::io::{IsTerminal, Write};
use std::time::{Duration, Instant};

pub struct Progress {
    enabled: bool,
    start: Instant,
    last_draw: Option<Instant>,
    total_steps: usize,
    drawn: bool,
}

/// How long a run must take before the bar shows.
const DELAY: Duration = Duration::from_secs(1);
const PERIOD: Duration = Duration::from_millis(100);
const WIDTH: usize = 30;

impl Progress {
    /// A bar for `total_steps` steps, shown if `wanted` and standard
    /// error is a terminal.
    pub fn new(total_steps: usize, wanted: bool) -> Self {
        Progress {
            enabled: wanted && std::io::stderr().is_terminal(),
            start: Instant::now(),
            last_draw: None,
            total_steps: total_steps.max(1),
            drawn: false,
        }
    }

    /// After step `step` (1-based) at time `t` with `iterations` Newton
    /// iterations so far.
    pub fn update(&mut self, step: usize, t: f64, iterations: usize) {
        if !self.enabled {
            return;
        }
        let now = Instant::now();
        let elapsed = now - self.start;
        if elapsed < DELAY || self.last_draw.is_some_and(|l| now - l < PERIOD) {
            return;
        }
        self.last_draw = Some(now);
        let line = render(step, self.total_steps, t, iterations, elapsed.as_secs_f64());
        let mut err = std::io::stderr().lock();
        let _ = write!(err, "\r{line}\x1b[K");
        let _ = err.flush();
        self.drawn = true;
    }

    /// Erases the bar.
    pub fn finish(&mut self) {
        if self.drawn {
            let mut err = std::io::stderr().lock();
            let _ = write!(err, "\r\x1b[K");
            let _ = err.flush();
            self.drawn = false;
        }
    }
}

impl Drop for Progress {
    fn drop(&mut self) {
        self.finish();
    }
}

/// The bar's text, e.g.
/// `[#########.....................]  31 % step 11160/36000  t = 0.558 s  2.00 it/step  0:04 left`.
pub fn render(step: usize, total: usize, t: f64, iterations: usize, elapsed: f64) -> String {
    let frac = (step as f64 / total.max(1) as f64).clamp(0.0, 1.0);
    let filled = (frac * WIDTH as f64).round() as usize;
    let bar: String = "#".repeat(filled) + &".".repeat(WIDTH - filled);
    let per_step = iterations as f64 / step.max(1) as f64;
    let left = if step > 0 {
        elapsed * (total.saturating_sub(step)) as f64 / step as f64
    } else {
        0.0
    };
    let secs = left.round() as u64;
    format!(
        "[{bar}] {:3.0} % step {step}/{total}  t = {t:.4e} s  {per_step:.2} it/step  {}:{:02} left",
        100.0 * frac,
        secs / 60,
        secs % 60
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_bar_says_how_far_and_how_long() {
        let s = render(9000, 36000, 0.45, 18000, 2.0);
        assert!(s.starts_with("[########......................]"), "{s}");
        assert!(s.contains(" 25 % step 9000/36000"), "{s}");
        assert!(s.contains("t = 4.5000e-1 s"), "{s}");
        assert!(s.contains("2.00 it/step"), "{s}");
        assert!(s.contains("0:06 left"), "{s}");
    }

    #[test]
    fn no_bar_when_not_wanted() {
        let mut p = Progress::new(10, false);
        p.start -= Duration::from_secs(5);
        p.update(5, 0.1, 10);
        assert!(!p.drawn);
    }
}
