//! Radau's options and statistics, and the tolerances as its error estimate uses them.

use nalgebra::DefaultAllocator;

use crate::error::SimError;
use crate::integrator::check_step_options;
use crate::model::LagrangeDirac;
use crate::model::state::State;
use crate::shape::dims::{Sizes, Storage, VecY};
use crate::shape::layout::Layout;

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
/// events, [`Integrator::interpolate`](crate::integrator::Integrator::interpolate)).
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
///
/// The absolute tolerance is a floor for components near zero, in the model's units; it never
/// exceeds the relative tolerance times the largest magnitude its kind of quantity (positions,
/// velocities, momenta, multipliers) has reached in the run. So a run of picofarads and
/// nanoseconds, whose charges are 1e-12 and fluxes 1e-9, is held to the same relative accuracy
/// as the same circuit in farads and seconds, where the default `atol` of 1e-8 changes nothing:
/// the results do not depend on the units. Tolerances set per component
/// ([`Radau::set_absolute_tolerances`](crate::methods::radau::Radau::set_absolute_tolerances))
/// are the user's own and are kept as they are.
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
    /// Whether the absolute tolerances were set per component, and are kept as they are.
    per_component: bool,
    /// The largest magnitude of the positions, velocities, momenta and multipliers reached in
    /// the run: the caps of their absolute tolerances.
    peaks: [f64; 4],
    /// The run's span: the time against which a step's size is measured where the multipliers'
    /// weights grow by `span / h` (Hairer's `1/h` for index-2 variables, in the run's own unit
    /// of time rather than in seconds).
    time_scale: f64,
    /// `rtol · atol` as given: a magnitude below it is below anything the tolerances resolve
    /// (the round-off a solve leaves in a quantity at rest), and sets no peak.
    negligible: f64,
    /// Whether a step of the run was accepted.
    accepted: bool,
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
        Tolerances {
            rtol,
            atol: atol_y,
            sizes,
            fnewt,
            per_component: false,
            peaks: [0.0; 4],
            time_scale: 1.0,
            negligible: options.rtol * options.atol,
            accepted: false,
        }
    }

    /// Forgets the peaks: a new run starts, over `span`.
    pub fn begin_run(&mut self, span: f64) {
        self.peaks = [0.0; 4];
        self.accepted = false;
        self.time_scale = span;
    }

    /// Takes in the state `y` reached (the start, or an accepted step's end): the peaks grow
    /// to its magnitudes.
    pub fn observe(&mut self, y: &VecY<M>) {
        self.peaks = self.peaks_with(y, None);
        self.accepted = true;
    }

    /// The peaks with those of `y`, and of `y + z` if given (a step's candidate end).
    fn peaks_with(&self, y: &VecY<M>, z: Option<&VecY<M>>) -> [f64; 4] {
        let l = Layout::new(self.sizes.typed::<M>());
        let mut peaks = self.peaks;
        for (k, range) in [(0, l.q..l.v), (1, l.v..l.p), (2, l.p..l.lambda), (3, l.lambda..l.len)] {
            for i in range {
                let end = z.map_or(0.0, |z| (y[i] + z[i]).abs());
                let reached = y[i].abs().max(end);
                if reached > self.negligible {
                    peaks[k] = peaks[k].max(reached);
                }
            }
        }
        peaks
    }

    /// [`Self::weights`] for judging a step from `y` whose candidate end is `y + z`: the
    /// absolute tolerances capped by the peaks the step would reach (the first step from a
    /// state at rest has no peaks of its own yet).
    /// After the run's first step, a kind of quantity still at rest (the fluxes of a circuit
    /// whose held source voltage jumps from zero) keeps the absolute tolerance as given until a
    /// step has moved it: the error estimate of a step from an inconsistent start is of the size
    /// of its first motion, which its own end would make the scale.
    pub fn weights_judging(&mut self, (y, z): (&VecY<M>, &VecY<M>), h: f64, out: &mut VecY<M>) {
        let kept = self.peaks;
        let reached = self.peaks_with(y, Some(z));
        for (peak, (was, now)) in self.peaks.iter_mut().zip(kept.iter().zip(reached)) {
            if !self.accepted || *was > 0.0 {
                *peak = now;
            }
        }
        self.weights(y, h, out);
        self.peaks = kept;
    }

    /// The absolute tolerance of slot `i` (of group `group`): capped by `rtol` times the
    /// group's peak, unless set per component or the group has not moved yet.
    #[inline]
    fn absolute(&self, i: usize, group: usize) -> f64 {
        let (atol, peak) = (self.atol[i], self.peaks[group]);
        if self.per_component || peak == 0.0 { atol } else { atol.min(self.rtol * peak) }
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
        self.per_component = true;
        Ok(())
    }

    /// The error weight of a position (`i < nq`) or velocity (`nq + i`) of value `y`, for the
    /// first step's choice.
    pub fn motion_scale(&self, i: usize, y: f64) -> f64 {
        let l = Layout::new(self.sizes.typed::<M>());
        let (slot, group) = if i < self.sizes.nq { (l.q + i, 0) } else { (l.v + i - self.sizes.nq, 1) };
        self.absolute(slot, group) + self.rtol * y.abs()
    }

    /// The error weight of momentum `i` of value `p`: the accuracy to which the Newton
    /// iteration solves its Legendre map `p = ∂L/∂v`.
    pub fn momentum_weight(&self, i: usize, p: f64) -> f64 {
        let slot = Layout::new(self.sizes.typed::<M>()).p + i;
        self.absolute(slot, 2) + self.rtol * p.abs()
    }

    /// The error weights at state `y` for a step `h`: `atol + rtol |y|` (the absolute
    /// tolerance capped as the type's documentation says), times `span / h` for the
    /// multipliers, index-2 variables whose error estimate is one order worse.
    pub fn weights(&self, y: &VecY<M>, h: f64, out: &mut VecY<M>) {
        let l = Layout::new(self.sizes.typed::<M>());
        let index_two = self.time_scale / h;
        for (i, s) in out.iter_mut().enumerate() {
            let group = usize::from(i >= l.v) + usize::from(i >= l.p) + usize::from(i >= l.lambda);
            *s = self.absolute(i, group) + self.rtol * y[i].abs();
            if i >= l.lambda {
                *s *= index_two;
            }
        }
    }

    /// The error weights of a sensitivity `s` for a step `h`: as [`Self::weights`], with the
    /// absolute tolerances as given (a sensitivity's magnitude is not its state's).
    pub fn sensitivity_weights(&self, s: &VecY<M>, h: f64, out: &mut VecY<M>) {
        let lambda = Layout::new(self.sizes.typed::<M>()).lambda;
        let index_two = self.time_scale / h;
        for (i, w) in out.iter_mut().enumerate() {
            *w = self.atol[i] + self.rtol * s[i].abs();
            if i >= lambda {
                *w *= index_two;
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

/// `412 steps (3 rejected), 1300 residual evaluations, 20 Jacobians, 35 factorisations, 1250 Newton iterations`.
impl std::fmt::Display for RadauStats {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(
            f,
            "{} steps ({} rejected), {} residual evaluations, {} Jacobians, {} factorisations, {} Newton iterations",
            self.steps,
            self.rejected,
            self.residual_evaluations,
            self.jacobian_evaluations,
            self.factorizations,
            self.newton_iterations
        )?;
        if self.sensitivity_iterations > 0 {
            write!(f, ", {} sensitivity iterations", self.sensitivity_iterations)?;
        }
        Ok(())
    }
}
