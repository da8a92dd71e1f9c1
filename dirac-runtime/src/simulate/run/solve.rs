//! [`Solve::run`] and its one-line shorthands, for every integrator.

use std::ops::ControlFlow;

use nalgebra::DefaultAllocator;

use super::Run;
use super::cycle::{Hooks, drive};
use crate::error::SimError;
use crate::hybrid::event::Event;
use crate::hybrid::events::{EventContext, Events};
use crate::integrator::Integrator;
use crate::model::state::State;
use crate::model::{Hybrid, LagrangeDirac};
use crate::output::progress::Progress;
use crate::output::solution::{Sampling, Solution};
use crate::shape::dims::Storage;

/// Running an integration: [`Solve::run`] and its shorthands, implemented for every
/// [`Integrator`] (and in the facade's prelude).
pub trait Solve<M: LagrangeDirac>: Integrator<M> + Sized
where
    DefaultAllocator: Storage<M>,
{
    /// Begins a run from `state` at `t0` to `t_end`, whose options (samples, events, a
    /// sampled-data controller, an observer, a progress report) compose with each other and
    /// with the model's contacts, laws and switching surfaces, which every run watches; ended
    /// by [`Run::solve`]. [`Run`] has an example.
    fn run<'r>(&'r mut self, t0: f64, state: &'r State<M>, t_end: f64) -> Run<'r, M, Self> {
        Run::new(self, t0, state, t_end)
    }

    /// Runs from `t0` to `t_end` under a sampled-data controller: every `period`, from `t0` on,
    /// `controller(t_k, state, model)` reads the state and sets the model's inputs (or
    /// parameters), which are held until the next sample. The integration stops at each sample
    /// instant and restarts there, so no step straddles a change. Needs an integrator built on
    /// `&mut model`. The guide's section "Inputs and controllers" has an example. A shorthand
    /// of `run(..).sampling(..).every(period, controller).solve()` ([`Run::every`]).
    fn solve_sampled(
        &mut self,
        t0: f64,
        state: &State<M>,
        t_end: f64,
        period: f64,
        sampling: &Sampling,
        controller: impl FnMut(f64, &State<M>, &mut M),
    ) -> Result<Solution<M, Self::Stats>, SimError>
    where
        M: Hybrid,
    {
        self.run(t0, state, t_end).sampling(sampling.clone()).every(period, controller).solve()
    }

    /// Integrates from `state` at `t0` to `t_end`, recording samples as `sampling` says, with
    /// the model's unilateral constraints, laws and switching surfaces watched: its impacts and
    /// switches are in the solution. A shorthand of `run(..).sampling(..).solve()`
    /// ([`Solve::run`]).
    fn solve(
        &mut self,
        t0: f64,
        state: &State<M>,
        t_end: f64,
        sampling: &Sampling,
    ) -> Result<Solution<M, Self::Stats>, SimError>
    where
        M: Hybrid,
    {
        self.run(t0, state, t_end).sampling(sampling.clone()).solve()
    }

    /// [`Solve::solve`] with a report of the progress: `report` is called with the time
    /// reached, the integrator's counters and the wall-clock time, at most once per `interval`
    /// of wall-clock time (every step for a zero interval) and once at the end. `Progress`
    /// displays as one line; [`Progress::bar`] draws a text bar. The guide's section "Step by
    /// step, and observers" has a runnable example. A shorthand of
    /// `run(..).sampling(..).progress(interval, report).solve()` ([`Run::progress`]).
    fn solve_with_progress(
        &mut self,
        t0: f64,
        state: &State<M>,
        t_end: f64,
        sampling: &Sampling,
        interval: std::time::Duration,
        report: impl FnMut(&Progress<Self::Stats>),
    ) -> Result<Solution<M, Self::Stats>, SimError>
    where
        M: Hybrid,
    {
        self.run(t0, state, t_end).sampling(sampling.clone()).progress(interval, report).solve()
    }

    /// [`Solve::solve`] with an observer called after every step with the time and the
    /// state reached (read by name: `state.q(Model::X)`); returning `ControlFlow::Break(())`
    /// stops the integration there. A shorthand of `run(..).sampling(..).observe(observer).solve()`
    /// ([`Run::observe`]).
    fn solve_observed(
        &mut self,
        t0: f64,
        state: &State<M>,
        t_end: f64,
        sampling: &Sampling,
        observer: impl FnMut(f64, &State<M>) -> ControlFlow<()>,
    ) -> Result<Solution<M, Self::Stats>, SimError>
    where
        M: Hybrid,
    {
        self.run(t0, state, t_end).sampling(sampling.clone()).observe(observer).solve()
    }

    /// [`Solve::solve`] with events: after each step, the crossings of the `events`'
    /// functions within it are located on the dense output and handed to `action` in time
    /// order, with an [`EventContext`] to read the state at the event, reset it
    /// ([`EventContext::state_mut`]) or change the model ([`EventContext::model_mut`]). The
    /// model's unilateral constraints are watched too unless `events` asked for the
    /// [`free_motion`](Events::free_motion), and its laws always.
    ///
    /// - An action that changes nothing costs no restart: the search goes on within the step.
    /// - After a reset or a change, the integration restarts at the event from the consistent
    ///   state nearest to the one the action left ([`consistent_state`](crate::consistent_state)).
    /// - `ControlFlow::Break(())` ends the solution at the event (the integrator itself stays
    ///   at the end of the step that held it; [`Integrator::restart_at`] moves it back).
    ///
    /// The solution records every event ([`Solution::events`]) and, unless it samples at
    /// chosen times, the state at each event, twice when the action reset it (before, then
    /// after). The [`Events`] type has an example. A shorthand of
    /// `run(t0, state, t_end).sampling(..).events(..).on_event(action).solve()`
    /// ([`Solve::run`]), which `events` is borrowed by, not moved into.
    fn solve_with_events(
        &mut self,
        t0: f64,
        state: &State<M>,
        t_end: f64,
        sampling: &Sampling,
        events: &mut Events<'_, M>,
        mut action: impl FnMut(&Event, &mut EventContext<'_, M, Self>) -> ControlFlow<()>,
    ) -> Result<Solution<M, Self::Stats>, SimError>
    where
        M: Hybrid,
    {
        events.watch_model(self.model(), false)?;
        let recorder = drive(self, (t0, state, t_end), sampling, events, Hooks::acting(&mut action))?;
        recorder.finish_from(self)
    }
}

impl<M: LagrangeDirac, I: Integrator<M>> Solve<M> for I where DefaultAllocator: Storage<M> {}
