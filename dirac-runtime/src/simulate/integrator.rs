//! The driver every integrator shares: start, step, read the state, interpolate within the
//! last step; and, written once on top of those, `solve` and `solve_observed`, which run an
//! integration and record a [`Solution`](crate::Solution).

use std::ops::ControlFlow;

use nalgebra::DefaultAllocator;

use crate::error::{Capability, SimError};
use crate::model::keys::Input;
use crate::model::state::State;
use crate::model::{InputsOutputs, LagrangeDirac, Parameters};
use crate::shape::dims::Storage;
use crate::shape::layout::Layout;
use crate::simulate::laws;
use crate::simulate::progress::Progress;
use crate::simulate::recorder::Recorder;
use crate::simulate::sensitivity::Sensitivities;
use crate::simulate::solution::{Sampling, Solution};

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

    /// Whether the method carries forward sensitivities ([`Integrator::carry_sensitivities`]).
    const SENSITIVITIES: bool = false;

    /// The model integrated.
    fn model(&self) -> &M;

    /// Prepares to integrate from `state` at `t0` to `t_end`. The state should be consistent
    /// (see [`consistent_state`](crate::analysis::init::consistent_state)).
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

    /// Runs from `t0` to `t_end` under a sampled-data controller: every `period`, from `t0` on,
    /// `controller(t_k, state, model)` reads the state and sets the model's inputs (or
    /// parameters), which are held until the next sample. The integration stops at each sample
    /// instant and restarts there, so no step straddles a change. Needs an integrator built on
    /// `&mut model`. The guide's section "Inputs and controllers" has an example.
    fn solve_sampled(
        &mut self,
        t0: f64,
        state: &State<M>,
        t_end: f64,
        period: f64,
        sampling: &Sampling,
        mut controller: impl FnMut(f64, &State<M>, &mut M),
    ) -> Result<Solution<M, Self::Stats>, SimError>
    where
        Self: Sized,
    {
        check_period(t0, t_end, period)?;
        refuse_unwatched(self.model())?;
        let mut recorder = Recorder::new(self.model(), sampling, t0, t_end)?;
        let mut held = state.clone();
        let sample = |k: usize| (t0 + k as f64 * period).min(t_end);
        controller(t0, &held, self.model_mut().ok_or(SimError::SharedModel { t: t0 })?);
        self.start(t0, state, sample(1))?;
        recorder.record_initial(self.model(), t0, self.state());
        let mut k = 1;
        while self.t() < t_end {
            while !self.finished() {
                self.step()?;
                recorder.record_step(self.model(), self.t(), self.state(), |t, out| self.interpolate(t, out));
            }
            if self.t() >= t_end {
                break;
            }
            let t = self.t();
            held.clone_from(self.state());
            controller(t, &held, self.model_mut().ok_or(SimError::SharedModel { t })?);
            k += 1;
            self.restart_until(sample(k))?;
        }
        recorder.finish_from(self)
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

    /// Asks the integrator to carry the forward sensitivities of its solution with respect to
    /// `wrt`'s parameters and initial values from its next start. [`Radau`](crate::Radau)
    /// carries them (the staggered direct method); a method that does not refuses with
    /// [`SimError::Unsupported`].
    fn carry_sensitivities(&mut self, wrt: &Sensitivities<M>) -> Result<(), SimError>
    where
        M: Parameters,
    {
        let _ = wrt;
        Err(no_sensitivities::<M, Self>())
    }

    /// The names of the sensitivities carried, in order: what they are taken with respect to
    /// (none unless asked for).
    fn sensitivity_names(&self) -> &[String] {
        &[]
    }

    /// Writes sensitivity `j` at the time reached, `∂(q, v, p, λ)/∂θ_j`, into `out`; `false`
    /// (leaving `out` alone) if there is no sensitivity `j`.
    fn sensitivity(&self, j: usize, out: &mut State<M>) -> bool {
        let _ = (j, out);
        false
    }

    /// Writes sensitivity `j` at time `t` within the last step into `out`; `false` if there is
    /// no sensitivity `j`.
    fn interpolate_sensitivity(&self, j: usize, t: f64, out: &mut State<M>) -> bool {
        let _ = (j, t, out);
        false
    }

    /// The parameter sensitivity `j` is taken with respect to (its index), or `None` for an
    /// initial value's (or no sensitivity `j`).
    fn sensitivity_parameter(&self, j: usize) -> Option<usize> {
        let _ = j;
        None
    }

    /// Restarts the integration at `t` from `state` (consistent) with the sensitivities
    /// `sensitivities` (one per sensitivity carried), after a jump whose derivative the caller
    /// carried them across (an impact). A method that does not carry sensitivities refuses.
    fn restart_with_sensitivities(
        &mut self,
        t: f64,
        state: &State<M>,
        sensitivities: &[State<M>],
    ) -> Result<(), SimError> {
        let _ = (t, state, sensitivities);
        Err(no_sensitivities::<M, Self>())
    }

    /// Completes sensitivity `j` at the start of the integration, in `out`, with what the first
    /// step taught: the multipliers' sensitivities, which a method may not carry at the start
    /// (Radau extrapolates them from its first step's stages). Does nothing by default.
    fn complete_initial_sensitivity(&self, j: usize, out: &mut State<M>) {
        let _ = (j, out);
    }

    /// Integrates from `state` at `t0` to `t_end` with the sensitivities asked for
    /// ([`Integrator::carry_sensitivities`]), recording the state as [`Integrator::solve`] does
    /// and every sensitivity at the same samples: read them from the solution by quantity and
    /// name ([`Solution::sensitivity`]). A model with unilateral constraints has its contacts
    /// watched, as [`Integrator::solve`] does, and each sensitivity carried across each impact
    /// by the impact's saltation matrix ([`saltation`](crate::impact::saltation)); one with
    /// switching surfaces (`abs`, `signum`, conditionals) has them located, and each
    /// sensitivity carried across each crossing by `(f⁻ − f⁺) ∂t*/∂θ`, the jump of the rate
    /// times the crossing's shift; one with laws (friction, diodes, ideal switches) has them
    /// switched, and each sensitivity carried across each switch the same way, with the rates
    /// of the old mode and the new. A method that does not carry sensitivities refuses with
    /// [`SimError::Unsupported`].
    fn solve_with_sensitivities(
        &mut self,
        t0: f64,
        state: &State<M>,
        t_end: f64,
        sampling: &Sampling,
    ) -> Result<Solution<M, Self::Stats>, SimError>
    where
        Self: Sized,
    {
        record_with_sensitivities(self, t0, state, t_end, sampling)
    }

    /// Integrates from `state` at `t0` to `t_end`, recording samples as `sampling` says. A model
    /// that declares unilateral constraints (`unilateral(...)`) is integrated with them watched,
    /// as [`SolveWithEvents::solve_with_events`](crate::SolveWithEvents::solve_with_events)
    /// with [`Events::contacts`](crate::Events::contacts) does: its impacts are in the solution.
    fn solve(
        &mut self,
        t0: f64,
        state: &State<M>,
        t_end: f64,
        sampling: &Sampling,
    ) -> Result<Solution<M, Self::Stats>, SimError>
    where
        Self: Sized,
    {
        // A model with unilateral constraints is solved with them watched, one with switching
        // surfaces with them located.
        if (!self.model().unilateral_names().is_empty()
            || self.model().has_switches()
            || laws::has_laws(self.model()))
            && let Some(solution) = M::__solve_with_contacts(self, t0, state, t_end, sampling)
        {
            return solution;
        }
        self.solve_observed(t0, state, t_end, sampling, |_, _| ControlFlow::Continue(()))
    }

    /// [`Integrator::solve_observed`] with a report of the progress: `report` is called with
    /// the time reached, the integrator's counters and the wall-clock time, at most once per
    /// `interval` of wall-clock time (every step for a zero interval) and once at the end.
    /// `Progress` displays as one line; [`Progress::bar`] draws a text bar. The guide's section
    /// "Step by step, and observers" has a runnable example.
    fn solve_with_progress(
        &mut self,
        t0: f64,
        state: &State<M>,
        t_end: f64,
        sampling: &Sampling,
        interval: std::time::Duration,
        mut report: impl FnMut(&Progress<Self::Stats>),
    ) -> Result<Solution<M, Self::Stats>, SimError>
    where
        Self: Sized,
    {
        let began = std::time::Instant::now();
        let mut last = began;
        let solution = observed(self, t0, state, t_end, sampling, |integrator| {
            let now = std::time::Instant::now();
            if now.duration_since(last) >= interval && !integrator.finished() {
                last = now;
                report(&Progress {
                    t: integrator.t(),
                    t0,
                    t_end,
                    stats: integrator.stats(),
                    elapsed: now - began,
                });
            }
            ControlFlow::Continue(())
        });
        report(&Progress { t: self.t(), t0, t_end, stats: self.stats(), elapsed: began.elapsed() });
        solution
    }

    /// [`Integrator::solve`] with an observer called after every step with the time and the
    /// state reached (read by name: `state.q(Model::X)`); returning `ControlFlow::Break(())`
    /// stops the integration there.
    fn solve_observed(
        &mut self,
        t0: f64,
        state: &State<M>,
        t_end: f64,
        sampling: &Sampling,
        mut observer: impl FnMut(f64, &State<M>) -> ControlFlow<()>,
    ) -> Result<Solution<M, Self::Stats>, SimError>
    where
        Self: Sized,
    {
        observed(self, t0, state, t_end, sampling, |integrator| observer(integrator.t(), integrator.state()))
    }
}

/// The loop of [`Integrator::solve_observed`] and [`Integrator::solve_with_progress`]: records
/// every step's samples and calls `after_step` with the integrator, stopping where it breaks.
fn observed<M: LagrangeDirac, I: Integrator<M>>(
    integrator: &mut I,
    t0: f64,
    state: &State<M>,
    t_end: f64,
    sampling: &Sampling,
    mut after_step: impl FnMut(&I) -> ControlFlow<()>,
) -> Result<Solution<M, I::Stats>, SimError>
where
    DefaultAllocator: Storage<M>,
{
    refuse_unwatched(integrator.model())?;
    let mut recorder = Recorder::new(integrator.model(), sampling, t0, t_end)?;
    integrator.start(t0, state, t_end)?;
    recorder.record_initial(integrator.model(), t0, integrator.state());
    while !integrator.finished() {
        integrator.step()?;
        recorder.record_step(integrator.model(), integrator.t(), integrator.state(), |t, out| {
            integrator.interpolate(t, out)
        });
        if after_step(integrator).is_break() {
            break;
        }
    }
    recorder.finish_from(integrator)
}

/// The most sample intervals [`Integrator::solve_sampled`] takes on: a period this short
/// against the span is a mistake, not a controller.
const MAX_SAMPLES: f64 = 1e9;

/// A sampling period that is positive, finite, resolvable at the span's times and not absurdly
/// short for the span.
fn check_period(t0: f64, t_end: f64, period: f64) -> Result<(), SimError> {
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
/// inputs between steps ([`Integrator::set_input`], [`Integrator::solve_sampled`]). The
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
    /// inputs jump or bend (a table's samples: [`Table::times`](crate::sources::Table::times)),
    /// known in advance, so located exactly, and no step straddles one. A drive reads the
    /// inputs at a stop's time from the left for the step that ends there and from the right
    /// after it. Set it before `start`; by default the method refuses.
    fn stop_at(&mut self, times: &[f64]) -> Result<(), SimError> {
        let _ = times;
        Err(SimError::Unsupported { method: Self::NAME, capability: Capability::Drive })
    }
}

/// The refusal of a method that does not carry sensitivities.
fn no_sensitivities<M: LagrangeDirac, I: Integrator<M> + ?Sized>() -> SimError
where
    DefaultAllocator: Storage<M>,
{
    SimError::Unsupported { method: I::NAME, capability: Capability::Sensitivities }
}

/// The model's switching surfaces, each as `` `name`: g = 0 ``.
fn surfaces<M: LagrangeDirac>(model: &M) -> Vec<String>
where
    DefaultAllocator: Storage<M>,
{
    model
        .event_declarations()
        .into_iter()
        .filter(|&(_, d)| crate::model::names::is_switch(d))
        .map(|(name, _)| format!("`{name}`: {} = 0", model.surface(&name).unwrap_or("?")))
        .collect()
}

/// [`Integrator::solve_with_sensitivities`]: the samples of the state, and at each the
/// sensitivities, recorded sample by sample (each sample's values side by side, contiguous
/// writes) and turned into one column per value at the end.
fn record_with_sensitivities<M: LagrangeDirac, I: Integrator<M>>(
    integrator: &mut I,
    t0: f64,
    state: &State<M>,
    t_end: f64,
    sampling: &Sampling,
) -> Result<Solution<M, I::Stats>, SimError>
where
    DefaultAllocator: Storage<M>,
{
    if !I::SENSITIVITIES {
        return Err(no_sensitivities::<M, I>());
    }
    let count = integrator.sensitivity_names().len();
    if count == 0 {
        return Err(SimError::InvalidOption {
            what: "sensitivities",
            reason: "none were asked for: build the integrator with `with_sensitivities`".into(),
        });
    }
    let model = integrator.model();
    if !model.unilateral_names().is_empty() || model.has_switches() || laws::has_laws(model) {
        return M::__solve_with_sensitivities_through_events(integrator, t0, state, t_end, sampling)
            .unwrap_or_else(|| {
                let model = integrator.model();
                let what = match model.unilateral_names().first() {
                    Some(contact) => format!("the contact `{contact}`'s impacts"),
                    None if model.has_switches() => {
                        format!("its switching surfaces ({})", surfaces(model).join(", "))
                    }
                    None => format!("its laws' switches ({})", laws::law_names(model).join(", ")),
                };
                Err(SimError::InvalidOption {
                    what: "sensitivities",
                    reason: format!(
                        "this model (a network, assembled while the program runs) does not carry \
                         sensitivities across {what}: take differences of solutions"
                    ),
                })
            });
    }
    let mut recorder = Recorder::new(integrator.model(), sampling, t0, t_end)?;
    let mut rows = SensitivityRows::new(integrator, &mut recorder)?;
    integrator.start(t0, state, t_end)?;
    recorder.record_initial(integrator.model(), t0, integrator.state());
    rows.push_initial(integrator, &recorder);
    while !integrator.finished() {
        let before = recorder.len();
        integrator.step()?;
        rows.complete(integrator);
        recorder.record_step(integrator.model(), integrator.t(), integrator.state(), |t, out| {
            integrator.interpolate(t, out)
        });
        rows.push_within(integrator, &recorder, before);
    }
    rows.finish(integrator, recorder)
}

/// The sensitivities recorded sample by sample beside a [`Recorder`]'s samples (each sample's
/// values side by side, contiguous writes), turned into one column per value at the end.
pub(crate) struct SensitivityRows<M: LagrangeDirac>
where
    DefaultAllocator: Storage<M>,
{
    rows: Vec<f64>,
    /// Values a sample: every sensitivity's state.
    series: usize,
    len: usize,
    buffer: State<M>,
    /// The samples whose multipliers' sensitivities the next step completes: the start's, and
    /// those just after a restart.
    incomplete: Vec<usize>,
}

impl<M: LagrangeDirac> SensitivityRows<M>
where
    DefaultAllocator: Storage<M>,
{
    /// Room for `integrator`'s sensitivities at `recorder`'s samples.
    pub fn new<I: Integrator<M>>(integrator: &I, recorder: &mut Recorder<M>) -> Result<Self, SimError> {
        let sizes = integrator.model().sizes();
        let len = Layout::new(sizes).len;
        let series = integrator.sensitivity_names().len() * len;
        let rows = recorder.extra_series(series)?;
        Ok(SensitivityRows { rows, series, len, buffer: State::with_sizes(sizes), incomplete: Vec::new() })
    }

    /// The sensitivities at the start, if it is sampled, to be completed by the first step.
    pub fn push_initial<I: Integrator<M>>(&mut self, integrator: &I, recorder: &Recorder<M>) {
        if recorder.len() > 0 {
            for j in 0..integrator.sensitivity_names().len() {
                integrator.sensitivity(j, &mut self.buffer);
                self.rows.extend(self.buffer.components());
            }
            self.incomplete.push(0);
        }
    }

    /// The sensitivities at the samples from `before` on, each within the last step.
    pub fn push_within<I: Integrator<M>>(&mut self, integrator: &I, recorder: &Recorder<M>, before: usize) {
        for k in before..recorder.len() {
            let ts = recorder.time(k);
            for j in 0..integrator.sensitivity_names().len() {
                if ts >= integrator.t() {
                    integrator.sensitivity(j, &mut self.buffer);
                } else {
                    integrator.interpolate_sensitivity(j, ts, &mut self.buffer);
                }
                self.rows.extend(self.buffer.components());
            }
        }
    }

    /// `sensitivities` at the samples from `before` on, taken where the integration restarts
    /// with them: their multipliers' parts are completed by the next step.
    pub fn push_restart(&mut self, sensitivities: &[State<M>], recorder: &Recorder<M>, before: usize) {
        for k in before..recorder.len() {
            for s in sensitivities {
                self.rows.extend(s.components());
            }
            self.incomplete.push(k);
        }
    }

    /// Completes the multipliers' sensitivities of the samples at the start of the step just
    /// taken from that step (see [`Integrator::complete_initial_sensitivity`]).
    pub fn complete<I: Integrator<M>>(&mut self, integrator: &I) {
        let (series, len) = (self.series, self.len);
        for k in self.incomplete.drain(..) {
            for j in 0..integrator.sensitivity_names().len() {
                let row = &mut self.rows[k * series + j * len..k * series + (j + 1) * len];
                for (x, &v) in self.buffer.components_mut().zip(row.iter()) {
                    *x = v;
                }
                integrator.complete_initial_sensitivity(j, &mut self.buffer);
                for (x, &v) in row.iter_mut().zip(self.buffer.components()) {
                    *x = v;
                }
            }
        }
    }

    /// The solution, with a column per sensitivity value.
    pub fn finish<I: Integrator<M>>(
        self,
        integrator: &mut I,
        recorder: Recorder<M>,
    ) -> Result<Solution<M, I::Stats>, SimError> {
        let (rows, series, samples) = (self.rows, self.series, recorder.len());
        let columns = (0..series).map(|i| (0..samples).map(|k| rows[k * series + i]).collect()).collect();
        let names = integrator.sensitivity_names().to_vec();
        let solution = recorder.finish_from(integrator)?;
        Ok(solution.with_sensitivities(names, columns))
    }
}

/// A typed error if `model` declares laws (`friction`, `diode`) or unilateral constraints
/// that the solve would not watch: the laws would hold one mode throughout, the motion would
/// pass through the constraints.
fn refuse_unwatched<M: LagrangeDirac>(model: &M) -> Result<(), SimError>
where
    DefaultAllocator: Storage<M>,
{
    if laws::has_laws(model) {
        let laws: Vec<String> = laws::law_names(model).iter().map(|n| format!("`{n}`")).collect();
        return Err(SimError::InvalidOption {
            what: "laws",
            reason: format!(
                "the model's friction laws or diodes ({}) switch their modes at events, which this solve \
                 would not watch: they would hold one mode throughout. Solve with `solve`, or with \
                 `solve_with_events` and `Events::new().switches()`",
                laws.join(", ")
            ),
        });
    }
    refuse_unwatched_contacts(model)
}

/// A solve that would not watch the model's unilateral constraints: an error naming them.
pub(crate) fn refuse_unwatched_contacts<M: LagrangeDirac>(model: &M) -> Result<(), SimError>
where
    DefaultAllocator: Storage<M>,
{
    let names = model.unilateral_names();
    if names.is_empty() {
        return Ok(());
    }
    let list = names.iter().map(|n| format!("`{n}`")).collect::<Vec<_>>().join(", ");
    Err(SimError::InvalidOption {
        what: "contacts",
        reason: format!(
            "the model declares the unilateral constraint(s) {list}, which this solve would not watch: \
             its motion would pass through them. Solve with `solve` (which watches them), or with \
             `solve_with_events(t0, &state, t_end, &sampling, &mut Events::new().contacts(&model), |_, _| \
             ControlFlow::Continue(()))`, or, for the motion without them, with \
             `Events::new().free_motion()`"
        ),
    })
}
