//! What every integrator does: start, step, read the state, interpolate within the last step,
//! restart after a change of its model; how it holds its model, the drive that sets the
//! model's inputs within its steps, and the checks of its starts and restarts. A whole run on
//! top of these steps is [`Solve::run`](crate::Solve::run)'s.

use nalgebra::DefaultAllocator;

pub(crate) mod drive;
/// How an integrator holds its model: shared, or exclusive to change it while it runs.
pub mod held;
pub(crate) mod restart;
/// Input sources read by time: tables held or interpolated.
pub mod sources;

use crate::error::{Capability, SimError};
use crate::model::keys::Input;
use crate::model::state::State;
use crate::model::{InputsOutputs, LagrangeDirac};
use crate::shape::dims::Storage;

/// An integrator of a model `M`: [`Explicit`](crate::Explicit), [`Radau`](crate::Radau) or
/// [`Variational`](crate::Variational).
///
/// The required methods take one step at a time; the provided ones run a whole integration.
/// The facade's guide (`dirac::guide`, "Step by step") has a runnable example of both.
pub trait Integrator<M: LagrangeDirac>
where
    DefaultAllocator: Storage<M>,
{
    /// The integrator's own counters of the work it did.
    type Stats: Copy + core::fmt::Debug;

    /// The method's name, for messages: `Radau`, `Explicit` or `Variational`.
    const NAME: &'static str;

    /// The model integrated.
    fn model(&self) -> &M;

    /// Prepares to integrate from `state` at `t0` to `t_end`. The state should be consistent
    /// (see [`consistent_state`](crate::consistent_state)).
    fn start(&mut self, t0: f64, state: &State<M>, t_end: f64) -> Result<(), SimError>;

    /// The model to change between steps, if the integrator holds it exclusively (it was built
    /// on `&mut model`). Restart after the change ([`Integrator::restart_until`]): the restart
    /// refuses a change that moved a constraint off the state
    /// ([`SimError::ConstraintMoved`]).
    fn model_mut(&mut self) -> Option<&mut M>;

    /// Starts again from the current time and state, towards `t_end`, after the model changed:
    /// the step-size history and the extrapolated stages are dropped, the step size and the
    /// counters kept (Radau keeps its last Jacobian as the simplified Newton iteration's
    /// matrix until the iteration's convergence asks for a new one). Positions, velocities
    /// and momenta carry over, so a change must keep `p = ∂L/∂v` (inputs in forces or in the
    /// potential do; one in the mass matrix is refused with [`SimError::MomentumChanged`]).
    /// Does nothing once `t_end` is reached.
    fn restart_until(&mut self, t_end: f64) -> Result<(), SimError>;

    /// [`Integrator::restart_until`] the current end time.
    fn restart(&mut self) -> Result<(), SimError> {
        self.restart_until(self.end())
    }

    /// The end time the integration is heading for.
    fn end(&self) -> f64;

    /// Changes the model between steps (its inputs, its parameters) and restarts. The guide's
    /// section "Inputs and controllers" shows it at work.
    fn update(&mut self, change: impl FnOnce(&mut M)) -> Result<(), SimError>
    where
        Self: Sized,
    {
        let t = self.t();
        change(self.model_mut().ok_or(SimError::SharedModel { t })?);
        self.restart()
    }

    /// Sets an input between steps and restarts.
    fn set_input(&mut self, key: Input<M>, value: f64) -> Result<(), SimError>
    where
        Self: Sized,
        M: InputsOutputs,
    {
        self.update(|m| m.set_input(key, value))
    }

    /// Takes one step (for an adaptive method: one accepted step, retrying smaller ones as
    /// needed) and returns its size.
    fn step(&mut self) -> Result<f64, SimError>;

    /// Moves back to time `t` within the last step (or its end), to `state`, and restarts there
    /// towards the end time, as [`Integrator::restart_until`] does: what an event whose action
    /// reset the state or changed the model needs. The state must be consistent at `t`.
    fn restart_at(&mut self, t: f64, state: &State<M>) -> Result<(), SimError>;

    /// Sets the model's inputs for time `t` and `state` where something sets them within the
    /// steps (a Radau drive), so that a function of the inputs read at a time within the last
    /// step (an event function) sees them as the step did. Does nothing otherwise.
    fn set_inputs_at(&mut self, t: f64, state: &State<M>) {
        let _ = (t, state);
    }

    /// Whether something sets the model's inputs within the steps (a drive): then a solution's
    /// inputs and outputs at a sample are read after [`Integrator::set_inputs_at`] its time.
    fn driven(&self) -> bool {
        false
    }

    /// Replaces the multipliers of `state`, the state at `t` within the last step, by those the
    /// equations of motion give at its positions and velocities, where the method's own are
    /// less accurate between steps (Radau's collocation polynomial holds index-2 multipliers to
    /// its stage order only): what a release (a law's force through zero, a resting contact's)
    /// is located on. Leaves them as they are by default, and where that system is singular.
    #[doc(hidden)]
    fn exact_multipliers(&self, t: f64, state: &mut State<M>) {
        let _ = (t, state);
    }

    /// Where the next step would end as the integrator stands (its proposed step, within its
    /// stretch): how far a timed switch is looked for before the step. The end time by
    /// default.
    #[doc(hidden)]
    fn next_step_end(&self) -> f64 {
        self.end()
    }

    /// Ends the next steps at `t` (`None`: no such bound), reading the model there from the
    /// left, so that a timed switch crossed at `t` (a step source's edge) reaches no stage of
    /// the step that ends at it. Returns whether the method honours it (a fixed-step method
    /// does not: its steps straddle the switch, which the events then locate).
    #[doc(hidden)]
    fn end_step_at(&mut self, t: Option<f64>) -> bool {
        let _ = t;
        false
    }

    /// Whether the end time has been reached.
    fn finished(&self) -> bool;

    /// The time reached.
    fn t(&self) -> f64;

    /// The state reached.
    fn state(&self) -> &State<M>;

    /// Writes the state at time `t` within the last step into `out`.
    fn interpolate(&self, t: f64, out: &mut State<M>);

    /// Writes the positions and velocities at time `t` within the last step into `out`, its
    /// momenta and multipliers written too or left as they are: what a function of the motion
    /// alone reads, such as a switching surface sampled within a step. The dense output by
    /// default; a method whose momenta and multipliers cost an evaluation of the model skips it.
    fn interpolate_motion(&self, t: f64, out: &mut State<M>) {
        self.interpolate(t, out);
    }

    /// Writes the state at time `t` within the last step into `out` as the method itself would
    /// reach it, which is where events are located: the dense output by default (Radau's is
    /// its collocation polynomial); the variational integrator takes a step of its own to `t`
    /// from the step's start, so that an impact time is solved on the discrete flow.
    fn state_at(&self, t: f64, out: &mut State<M>) -> Result<(), SimError> {
        self.interpolate(t, out);
        Ok(())
    }

    /// The work done since the last [`Integrator::start`].
    fn stats(&self) -> Self::Stats;
}

/// The most sample intervals `solve_sampled` takes on: a period this short
/// against the span is a mistake, not a controller.
const MAX_SAMPLES: f64 = 1e9;

/// A sampling period that is positive, finite, resolvable at the span's times and not absurdly
/// short for the span.
pub(crate) fn check_period(t0: f64, t_end: f64, period: f64) -> Result<(), SimError> {
    if !(t0.is_finite() && t_end.is_finite() && t_end > t0) {
        return Err(SimError::InvalidTimeSpan {
            reason: format!("from {t0} to {t_end}: need finite t0 < t_end"),
        });
    }
    let invalid = |reason: String| Err(SimError::InvalidOption { what: "period", reason });
    if !(period > 0.0 && period.is_finite()) {
        return invalid(format!("{period} is not positive and finite"));
    }
    let magnitude = t0.abs().max(t_end.abs());
    if period <= 16.0 * f64::EPSILON * magnitude {
        return invalid(format!("{period:e} is below the resolution of t at {magnitude:e}"));
    }
    let samples = (t_end - t0) / period;
    if samples > MAX_SAMPLES {
        return invalid(format!(
            "{period:e} makes {samples:e} samples from {t0} to {t_end}, more than {MAX_SAMPLES:e}"
        ));
    }
    Ok(())
}

/// `x^y` to single precision, all a step-size factor or a convergence heuristic needs, at half
/// the cost of the double one (two powers a step are a tenth of a small model's step).
pub(crate) fn rough_power(x: f64, y: f64) -> f64 {
    f64::from((x as f32).powf(y as f32))
}

/// The options every adaptive integrator checks: positive, finite tolerances, a relative one
/// in `[10 ε, 1)`, a positive largest step and a positive, finite first step if one is given.
pub(crate) fn check_step_options(
    rtol: f64,
    atol: f64,
    max_step: f64,
    initial_step: Option<f64>,
) -> Result<(), SimError> {
    for (what, value) in [("rtol", rtol), ("atol", atol)] {
        if value.is_nan() || value <= 0.0 || value.is_infinite() {
            return Err(SimError::InvalidTolerance { what, value });
        }
    }
    // Above 1 a relative tolerance controls nothing; below 10 ε it asks for more than double
    // precision holds.
    if !(10.0 * f64::EPSILON..1.0).contains(&rtol) {
        return Err(SimError::InvalidOption {
            what: "rtol",
            reason: format!(
                "{rtol:e} is outside [2.2e-15, 1): a relative error of 100% or more controls nothing, \
                 and below 10 machine epsilons no step can meet it"
            ),
        });
    }
    if max_step.is_nan() || max_step <= 0.0 {
        return Err(SimError::InvalidOption {
            what: "max_step",
            reason: format!("{max_step} is not positive"),
        });
    }
    if let Some(h) = initial_step
        && (h.is_nan() || h <= 0.0 || h.is_infinite())
    {
        return Err(SimError::InvalidOption { what: "initial_step", reason: format!("{h} is not positive") });
    }
    Ok(())
}

/// An integrator that sets the model's inputs from time and state before every evaluation of
/// the model, within its steps: a source such as `u0 sin(ω t)`, a table read with linear
/// interpolation or held, a continuous feedback; and that ends its steps at the times where
/// those inputs jump or bend ([`Drive::stop_at`]), restarting there. Every method offers it
/// (Radau also with the feedback's Jacobian: `Radau::drive_feedback`). Every method also sets
/// inputs between steps ([`Integrator::set_input`], [`Solve::solve_sampled`](crate::Solve::solve_sampled)). The
/// facade's guide (`dirac::guide`, "Inputs and controllers") drives a model from a table in
/// each method.
pub trait Drive<'m, M: LagrangeDirac>: Integrator<M>
where
    DefaultAllocator: Storage<M>,
{
    /// Sets the model's inputs with `drive(t, state, model)` before every evaluation of the
    /// model from now on. Needs an integrator built on `&mut model`; set it before `start`. By
    /// default the method refuses.
    fn drive(&mut self, drive: &'m mut dyn FnMut(f64, &State<M>, &mut M)) -> Result<(), SimError> {
        let _ = drive;
        Err(SimError::Unsupported { method: Self::NAME, capability: Capability::Drive })
    }

    /// Ends a step at each of `times` and restarts there, from now on: the instants where the
    /// inputs jump or bend (a table's samples: [`Table::times`](crate::integrator::sources::Table::times)),
    /// known in advance, so located exactly, and no step straddles one. A drive reads the
    /// inputs at a stop's time from the left for the step that ends there and from the right
    /// after it. Set it before `start`; by default the method refuses.
    fn stop_at(&mut self, times: &[f64]) -> Result<(), SimError> {
        let _ = times;
        Err(SimError::Unsupported { method: Self::NAME, capability: Capability::Drive })
    }
}
