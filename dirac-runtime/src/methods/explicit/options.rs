//! The explicit integrator's options and counters.

use crate::error::SimError;
use crate::integrator::check_step_options;

/// Tolerances and limits of an [`Explicit`](crate::methods::explicit::Explicit) integration.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ExplicitOptions {
    /// Relative tolerance of the local error of positions and velocities (default `1e-6`).
    pub rtol: f64,
    /// Absolute tolerance (default `1e-8`).
    pub atol: f64,
    /// The first step size; by default chosen from the derivatives at the start, as
    /// Hairer's DOPRI5 does.
    pub initial_step: Option<f64>,
    /// The largest step size (default: unbounded).
    pub max_step: f64,
    /// The most steps, accepted and rejected, before giving up (default `1_000_000`).
    pub max_steps: usize,
    /// Steps of exactly this size (the last one shorter, to end at the end time), without
    /// error control, where set (default: adaptive steps).
    pub fixed_step: Option<f64>,
    /// Whether to stop with [`SimError::Unstable`] when the model turns out stiff: when
    /// stability, not accuracy, has held fifteen adaptive steps in a row (default `true`).
    /// An explicit method then crawls at its stability limit where Radau would take large
    /// steps.
    pub stiffness_test: bool,
}

impl Default for ExplicitOptions {
    fn default() -> Self {
        ExplicitOptions {
            rtol: 1e-6,
            atol: 1e-8,
            initial_step: None,
            max_step: f64::INFINITY,
            max_steps: 1_000_000,
            fixed_step: None,
            stiffness_test: true,
        }
    }
}

impl ExplicitOptions {
    /// The default options with relative and absolute tolerances `rtol` and `atol`.
    pub fn tolerances(rtol: f64, atol: f64) -> ExplicitOptions {
        ExplicitOptions { rtol, atol, ..ExplicitOptions::default() }
    }

    /// The default options with steps of size `h` and no error control.
    pub fn fixed(h: f64) -> ExplicitOptions {
        ExplicitOptions { fixed_step: Some(h), ..ExplicitOptions::default() }
    }

    /// Checks every option, naming the first one out of its range.
    pub fn validate(&self) -> Result<(), SimError> {
        check_step_options(self.rtol, self.atol, self.max_step, self.initial_step)?;
        if let Some(h) = self.fixed_step
            && (h.is_nan() || h <= 0.0 || h.is_infinite())
        {
            return Err(SimError::InvalidOption {
                what: "fixed_step",
                reason: format!("{h} is not positive and finite"),
            });
        }
        Ok(())
    }
}

/// Counters of the work an [`Explicit`](crate::methods::explicit::Explicit) integration did.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct ExplicitStats {
    /// Accepted steps.
    pub steps: usize,
    /// Rejected step attempts (error too large, non-finite or undetermined stages).
    pub rejected: usize,
    /// Evaluations of the accelerations and multipliers, one saddle-point solve each.
    pub evaluations: usize,
    /// Factorisations of the saddle-point system `[L_vv −Aᵀ; A 0]`.
    pub factorizations: usize,
}

/// `412 steps (3 rejected), 2500 evaluations, 2500 factorisations`.
impl std::fmt::Display for ExplicitStats {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(
            f,
            "{} steps ({} rejected), {} evaluations, {} factorisations",
            self.steps, self.rejected, self.evaluations, self.factorizations
        )
    }
}
