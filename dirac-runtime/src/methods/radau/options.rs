//! Radau's options and statistics, and the tolerances as its error estimate uses them.

use nalgebra::DefaultAllocator;

use crate::error::SimError;
use crate::model::LagrangeDirac;
use crate::model::state::State;
use crate::shape::dims::{Sizes, Storage, VecY};
use crate::shape::layout::Layout;
use crate::simulate::integrator::check_step_options;

/// Tolerances and limits of a Radau integration.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RadauOptions {
    /// Relative tolerance (default `1e-6`).
    pub rtol: f64,
    /// Absolute tolerance (default `1e-8`).
    pub atol: f64,
    /// The first step size. By default it is chosen from the start's positions, velocities
    /// and accelerations, as DOPRI5's `HINIT` chooses it, for the tolerances and the order of
    /// Radau's error estimate; `1e-6` of the time span where the start's accelerations are not
    /// determined.
    pub initial_step: Option<f64>,
    /// The largest step size (default: unbounded).
    pub max_step: f64,
    /// The most steps, accepted and rejected, before giving up (default `1_000_000`).
    pub max_steps: usize,
    /// Newton iterations per step attempt (default 7).
    pub max_newton_iterations: usize,
    /// Whether to project the state onto the constraints after every accepted step, and every
    /// sample between steps (default `false`). Radau integrates the equations in their index-2 form, where holonomic
    /// constraints enter through their velocities `A(q, t) v + b(q, t) = 0`: the positions then drift from
    /// `φ(q, t) = 0` by the accumulated local errors, slowly but without bound. With projection
    /// the positions are moved back onto `φ(q, t) = 0` and the velocities onto `A v + b = 0`, each
    /// by the smallest correction, and the momenta follow from the Legendre map.
    pub projection: bool,
    /// How the error estimate's components are combined (default [`ErrorNorm::Rms`]).
    pub error_norm: ErrorNorm,
    /// What values between steps are taken from (default [`DenseOutput::Corrected`]).
    pub dense_output: DenseOutput,
    /// Whether Newton's iteration goes on past the tolerance to round-off each step (default
    /// `false`). The run is then a function of each step's start and size alone, so that a
    /// step can be solved again with the same result: what an adjoint sweep over checkpoints
    /// ([`Radau::record_within`](crate::methods::radau::Radau::record_within)) needs, and turns
    /// on. Costs a few Newton iterations a step.
    pub exact_stages: bool,
}

/// How Radau samples its solution between steps (`Sampling::Every`, `Sampling::Times`,
/// events, [`Integrator::interpolate`](crate::Integrator::interpolate)).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum DenseOutput {
    /// The collocation polynomial corrected by the step's ends, the velocities from the
    /// Legendre map and the constraints: values between steps as accurate as the steps' ends
    /// (`O(h⁵)`), the velocities on the constraints.
    #[default]
    Corrected,
    /// The collocation polynomial of RADAU5 alone: `O(h⁴)` inside a step while its end is
    /// `O(h⁶)`, so that at tight tolerances values between steps are tens to hundreds of times
    /// less accurate than at the steps' ends. Slightly cheaper to evaluate.
    Collocation,
}

/// How Radau combines the scaled error of every component into the one number it keeps
/// below 1.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum ErrorNorm {
    /// The root mean square, as in Hairer and Wanner's RADAU5: smooth, and the usual choice.
    /// In a large model where only a few components move (a wave on a long line), the mean
    /// dilutes their error by the square root of the share that moves.
    #[default]
    Rms,
    /// The largest component: every component is held to the tolerance, whatever the size of
    /// the model. Costs more steps where the error is spread evenly.
    Max,
}

impl Default for RadauOptions {
    fn default() -> Self {
        RadauOptions {
            rtol: 1e-6,
            atol: 1e-8,
            initial_step: None,
            max_step: f64::INFINITY,
            max_steps: 1_000_000,
            max_newton_iterations: 7,
            projection: false,
            error_norm: ErrorNorm::Rms,
            dense_output: DenseOutput::Corrected,
            exact_stages: false,
        }
    }
}

impl RadauOptions {
    /// The default options with relative and absolute tolerances `rtol` and `atol`.
    pub fn tolerances(rtol: f64, atol: f64) -> RadauOptions {
        RadauOptions { rtol, atol, ..RadauOptions::default() }
    }

    /// Checks every option, naming the first one out of its range: what [`Radau::new`]
    /// checks, for code that holds options before it builds the integrator.
    ///
    /// [`Radau::new`]: crate::methods::radau::Radau::new
    pub fn validate(&self) -> Result<(), SimError> {
        check_step_options(self.rtol, self.atol, self.max_step, self.initial_step)?;
        if self.max_newton_iterations < 2 {
            return Err(SimError::InvalidOption {
                what: "max_newton_iterations",
                reason: "at least 2".into(),
            });
        }
        Ok(())
    }
}

/// Counters of the work a Radau integration did.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct RadauStats {
    /// Accepted steps.
    pub steps: usize,
    /// Rejected step attempts (error too large, Newton failure, singular matrix).
    pub rejected: usize,
    /// Evaluations of the residual `f(t, y)`.
    pub residual_evaluations: usize,
    /// Evaluations of the Jacobian blocks.
    pub jacobian_evaluations: usize,
    /// LU factorisations (each a real and a complex one).
    pub factorizations: usize,
    /// Newton iterations.
    pub newton_iterations: usize,
    /// Linear iterations of the forward sensitivities' stage systems, over all sensitivities.
    pub sensitivity_iterations: usize,
    /// Step attempts whose sensitivities were solved with the three stages' coupled system,
    /// factored once for all of them (small nonlinear models; each sensitivity then counts one
    /// linear iteration).
    pub coupled_sensitivity_steps: usize,
}

/// The tolerances as the error estimate and the Newton iteration use them: Hairer's
/// transformation, under which an `rtol` of 1e-6 asks the estimator for about 1e-5 locally,
/// so that the achieved global error follows the requested one.
pub(crate) struct Tolerances<M: LagrangeDirac>
where
    DefaultAllocator: Storage<M>,
{
    rtol: f64,
    atol: VecY<M>,
    /// The model's sizes: the multipliers' weights scale with `1/h` (index 2).
    sizes: Sizes,
    /// The Newton iteration's stopping tolerance.
    pub fnewt: f64,
}

impl<M: LagrangeDirac> Tolerances<M>
where
    DefaultAllocator: Storage<M>,
{
    pub fn new(options: &RadauOptions, sizes: Sizes) -> Self {
        let rtol = 0.1 * options.rtol.powf(2.0 / 3.0);
        let atol = rtol * options.atol / options.rtol;
        let fnewt = (10.0 * f64::EPSILON / rtol).max(0.03f64.min(rtol.sqrt()));
        let mut atol_y = sizes.zeros_y::<M>();
        atol_y.fill(atol);
        Tolerances { rtol, atol: atol_y, sizes, fnewt }
    }

    /// A Newton increment of round-off size in the weighted norm: `ε |y|` over
    /// `rtol |y|`.
    pub fn round_off(&self) -> f64 {
        f64::EPSILON / self.rtol
    }

    /// Replaces the absolute tolerances by one per component of the state.
    pub fn set_absolute(&mut self, options: &RadauOptions, atol: &State<M>) -> Result<(), SimError> {
        if let Some(&value) = atol.components().find(|a| a.is_nan() || **a <= 0.0 || a.is_infinite()) {
            return Err(SimError::InvalidTolerance { what: "atol", value });
        }
        let factor = 0.1 * options.rtol.powf(2.0 / 3.0) / options.rtol;
        for (slot, a) in self.atol.iter_mut().zip(atol.components()) {
            *slot = a * factor;
        }
        Ok(())
    }

    /// The error weight of a position (`i < nq`) or velocity (`nq + i`) of value `y`, for the
    /// first step's choice.
    pub fn motion_scale(&self, i: usize, y: f64) -> f64 {
        let l = Layout::new(self.sizes.typed::<M>());
        let slot = if i < self.sizes.nq { l.q + i } else { l.v + i - self.sizes.nq };
        self.atol[slot] + self.rtol * y.abs()
    }

    /// The error weights at state `y` for a step `h`: `atol + rtol |y|`, divided by `h` for
    /// the multipliers, index-2 variables whose error estimate is one order worse.
    pub fn weights(&self, y: &VecY<M>, h: f64, out: &mut VecY<M>) {
        let lambda = Layout::new(self.sizes.typed::<M>()).lambda;
        for (i, s) in out.iter_mut().enumerate() {
            *s = self.atol[i] + self.rtol * y[i].abs();
            if i >= lambda {
                *s /= h;
            }
        }
    }
}

/// The weighted root-mean-square norm `√(Σ (x_i / w_i)² / len)`.
#[inline]
pub(crate) fn norm<M: LagrangeDirac>(x: &VecY<M>, weights: &VecY<M>, kind: ErrorNorm) -> f64
where
    DefaultAllocator: Storage<M>,
{
    let scaled = x.iter().zip(weights.iter()).map(|(a, s)| a / s);
    match kind {
        ErrorNorm::Rms => (scaled.map(|e| e * e).sum::<f64>() / x.len() as f64).sqrt(),
        ErrorNorm::Max => scaled.fold(0.0, |m, e| if e.abs() > m || e.is_nan() { e.abs() } else { m }),
    }
}
