//! Input sources read by time: a table of samples held or interpolated.

use crate::error::SimError;

/// How a [`Table`] is read between its samples.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Hold {
    /// The last sample's value until the next sample (zero-order hold). Its jumps are met by
    /// ending the steps there: [`Drive::stop_at`](crate::integrator::Drive::stop_at) with
    /// [`Table::times`].
    Zero,
    /// The straight line between the two samples around `t`.
    Linear,
}

/// A table of samples `(t_k, u_k)` of an input, read at any time without allocating: before the
/// first sample its value, after the last the last value.
///
/// ```
/// use dirac_runtime::integrator::sources::{Hold, Table};
///
/// let ramp = Table::new(vec![0.0, 1.0, 3.0], vec![0.0, 2.0, 2.0], Hold::Linear)?;
/// assert_eq!(ramp.at(0.5), 1.0);
/// assert_eq!(ramp.at(2.0), 2.0);
/// let held = Table::new(vec![0.0, 1.0], vec![5.0, -5.0], Hold::Zero)?;
/// assert_eq!(held.at(0.999), 5.0);
/// assert_eq!(held.at(1.0), -5.0);
/// # Ok::<(), dirac_runtime::SimError>(())
/// ```
#[derive(Clone, Debug)]
pub struct Table {
    times: Vec<f64>,
    values: Vec<f64>,
    hold: Hold,
}

impl Table {
    /// A table of `values` at `times`: as many of each, at least one, every number finite and
    /// the times strictly increasing.
    pub fn new(times: Vec<f64>, values: Vec<f64>, hold: Hold) -> Result<Self, SimError> {
        let invalid = |reason: String| Err(SimError::InvalidOption { what: "table", reason });
        if times.is_empty() || times.len() != values.len() {
            return invalid(format!(
                "{} times and {} values: need as many of each, at least one",
                times.len(),
                values.len()
            ));
        }
        if let Some(k) = times.iter().zip(&values).position(|(t, u)| !t.is_finite() || !u.is_finite()) {
            return invalid(format!(
                "sample {k} is ({}, {}): every time and value must be finite",
                times[k], values[k]
            ));
        }
        if let Some(k) = times.windows(2).position(|w| w[1] <= w[0]) {
            return invalid(format!("time {} follows {}: times must increase", times[k + 1], times[k]));
        }
        Ok(Table { times, values, hold })
    }

    /// The input at time `t`.
    pub fn at(&self, t: f64) -> f64 {
        // The number of samples at or before t.
        let k = self.times.partition_point(|&s| s <= t);
        match (k, self.hold) {
            (0, _) => self.values[0],
            (k, _) if k == self.times.len() => self.values[k - 1],
            (k, Hold::Zero) => self.values[k - 1],
            (k, Hold::Linear) => {
                let (t0, t1) = (self.times[k - 1], self.times[k]);
                let (u0, u1) = (self.values[k - 1], self.values[k]);
                u0 + (u1 - u0) * (t - t0) / (t1 - t0)
            }
        }
    }

    /// The sample times, where a zero-order hold jumps and a linear interpolation bends: the
    /// stops to give [`Drive::stop_at`](crate::integrator::Drive::stop_at).
    pub fn times(&self) -> &[f64] {
        &self.times
    }
}
