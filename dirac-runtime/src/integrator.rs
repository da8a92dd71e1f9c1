//! The driver every integrator shares: start, step, read the state, interpolate within the
//! last step; and, written once on top of those, `solve` and `solve_observed`, which run an
//! integration and record a [`Solution`].

use std::ops::ControlFlow;

use nalgebra::DefaultAllocator;

use crate::diagnose::{check_finite_state, violated_equation};
use crate::dims::Storage;
use crate::error::SimError;
use crate::model::{LagrangeDirac, check_parameters};
use crate::recorder::Recorder;
use crate::solution::{Sampling, Solution};
use crate::state::State;

/// An integrator of a model `M`: [`Radau`](crate::Radau) or
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

    /// The model integrated.
    fn model(&self) -> &M;

    /// Prepares to integrate from `state` at `t0` to `t_end`. The state should be consistent
    /// (see [`consistent_state`](crate::consistent_state)).
    fn start(&mut self, t0: f64, state: &State<M>, t_end: f64) -> Result<(), SimError>;

    /// Takes one step (for an adaptive method: one accepted step, retrying smaller ones as
    /// needed) and returns its size.
    fn step(&mut self) -> Result<f64, SimError>;

    /// Whether the end time has been reached.
    fn finished(&self) -> bool;

    /// The time reached.
    fn t(&self) -> f64;

    /// The state reached.
    fn state(&self) -> &State<M>;

    /// Writes the state at time `t` within the last step into `out`.
    fn interpolate(&self, t: f64, out: &mut State<M>);

    /// The work done since the last [`Integrator::start`].
    fn stats(&self) -> Self::Stats;

    /// Integrates from `state` at `t0` to `t_end`, recording samples as `sampling` says.
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
        self.solve_observed(t0, state, t_end, sampling, |_, _| ControlFlow::Continue(()))
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
        let mut recorder = Recorder::new(self.model(), sampling, t0, t_end)?;
        self.start(t0, state, t_end)?;
        recorder.record_initial(self.model(), t0, self.state());
        while !self.finished() {
            self.step()?;
            recorder.record_step(self.model(), self.t(), self.state(), |t, out| self.interpolate(t, out));
            if observer(self.t(), self.state()).is_break() {
                break;
            }
        }
        Ok(recorder.finish(self.stats()))
    }
}

/// What every integrator checks before its first step: a finite time span, finite parameters,
/// a finite state, and a state that satisfies the algebraic equations to `tolerance` (relative
/// to the size of the quantities in them).
pub(crate) fn check_start<M: LagrangeDirac>(
    model: &M,
    t0: f64,
    state: &State<M>,
    t_end: f64,
    tolerance: f64,
) -> Result<(), SimError>
where
    DefaultAllocator: Storage<M>,
{
    if !t0.is_finite() || !t_end.is_finite() || t_end <= t0 {
        return Err(SimError::InvalidTimeSpan {
            reason: format!("from {t0} to {t_end}: need finite t0 < t_end"),
        });
    }
    check_parameters(model)?;
    check_finite_state(model, t0, state)?;
    match violated_equation(model, t0, state, tolerance) {
        Some((equation, residual)) => Err(SimError::StateNotConsistent { t: t0, equation, residual }),
        None => Ok(()),
    }
}
