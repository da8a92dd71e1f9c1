//! Progress of a long run, reported while it runs. Each method's counters display as one line
//! in the method's own folder.

use std::fmt;
use std::time::Duration;

/// Where a run stands: handed to the report of
/// [`Solve::solve_with_progress`](crate::Solve::solve_with_progress).
#[derive(Clone, Copy, Debug)]
pub struct Progress<S> {
    /// The time reached.
    pub t: f64,
    /// The start time.
    pub t0: f64,
    /// The end time.
    pub t_end: f64,
    /// The integrator's counters so far (steps, rejected steps, …).
    pub stats: S,
    /// The wall-clock time since the run began.
    pub elapsed: Duration,
}

impl<S> Progress<S> {
    /// The fraction of the time span covered, in `[0, 1]`.
    pub fn fraction(&self) -> f64 {
        let span = self.t_end - self.t0;
        if span > 0.0 { ((self.t - self.t0) / span).clamp(0.0, 1.0) } else { 1.0 }
    }

    /// The wall-clock time the rest of the run may take, if it goes on at the rate so far.
    pub fn remaining(&self) -> Option<Duration> {
        let done = self.fraction();
        (done > 0.0).then(|| self.elapsed.mul_f64((1.0 - done) / done))
    }

    /// A text bar of `width` characters, `[#####     ]`.
    pub fn bar(&self, width: usize) -> String {
        let filled = (self.fraction() * width as f64).round() as usize;
        format!("[{}{}]", "#".repeat(filled.min(width)), " ".repeat(width - filled.min(width)))
    }
}

/// `t = 3.2 of 10 (32%), 412 steps (3 rejected), 0.8 s elapsed, about 1.7 s to go`.
impl<S: fmt::Display> fmt::Display for Progress<S> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "t = {:.6} of {} ({:.0}%), {}, {:.1} s elapsed",
            self.t,
            self.t_end,
            100.0 * self.fraction(),
            self.stats,
            self.elapsed.as_secs_f64()
        )?;
        match self.remaining() {
            Some(rest) if self.fraction() < 1.0 => write!(f, ", about {:.1} s to go", rest.as_secs_f64()),
            _ => Ok(()),
        }
    }
}
