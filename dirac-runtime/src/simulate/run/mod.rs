//! One run of an integrator, with whatever it is asked to do besides stepping: samples,
//! events and their actions, a sampled-data controller, an observer, a progress report. The
//! model's contacts, laws and switching surfaces are always watched, whatever else the run
//! does, so that every combination means what each part means alone.
//!
//! [`Integrator::run`](crate::Integrator::run) begins one; [`Run::solve`](crate::Run::solve)
//! runs it to a [`Solution`](crate::Solution). `solve`,
//! `solve_sampled`, `solve_observed`, `solve_with_progress` and `solve_with_events` are
//! one-line shorthands of it.

use std::ops::ControlFlow;
use std::time::{Duration, Instant};

use nalgebra::DefaultAllocator;

use crate::error::SimError;
use crate::model::state::State;
use crate::model::{Hybrid, LagrangeDirac, Parameters};
use crate::shape::dims::Storage;
use crate::simulate::events::{EventContext, Events};
use crate::simulate::integrator::Integrator;
use crate::simulate::progress::Progress;
use crate::simulate::sensitive::Sensitive;
use crate::simulate::sensitivity::Sensitivities;
use crate::simulate::solution::{Event, Sampling, Solution};

mod cycle;

use self::cycle::{ActionRef, Hooks, drive};

/// An event's action: what it does with the event, the state and the model there.
type Action<'r, M, I> = Box<dyn FnMut(&Event, &mut EventContext<'_, M, I>) -> ControlFlow<()> + 'r>;

/// A sampled-data controller: `controller(t_k, state, model)` sets the model's inputs.
type Controller<'r, M> = Box<dyn FnMut(f64, &State<M>, &mut M) + 'r>;

/// An observer of the state after each step, which may stop the run.
type Observer<'r, M> = Box<dyn FnMut(f64, &State<M>) -> ControlFlow<()> + 'r>;

/// A report of the run's progress.
type Report<'r, S> = Box<dyn FnMut(&Progress<S>) + 'r>;

/// One run of integrator `I` over model `M`, built by [`Integrator::run`] and its options, and
/// run by [`Run::solve`]. Every option composes with every other, and with the model's own
/// contacts, laws and switching surfaces, which every run watches.
///
/// The facade's guide (`dirac::guide`, "One run: controllers, events and contacts together") has
/// a runnable example: a block on a spring, with a wall, under a controller at 100 Hz.
pub struct Run<'r, M: LagrangeDirac, I: Integrator<M>>
where
    DefaultAllocator: Storage<M>,
{
    integrator: &'r mut I,
    t0: f64,
    start: &'r State<M>,
    t_end: f64,
    sampling: Sampling,
    events: Events<'r, M>,
    action: Option<Action<'r, M, I>>,
    every: Option<(f64, Controller<'r, M>)>,
    observer: Option<Observer<'r, M>>,
    progress: Option<(Duration, Report<'r, I::Stats>)>,
}

impl<'r, M: LagrangeDirac, I: Integrator<M>> Run<'r, M, I>
where
    DefaultAllocator: Storage<M>,
{
    /// A run of `integrator` from `start` at `t0` to `t_end` that records every step and does
    /// nothing else ([`Integrator::run`]).
    pub(crate) fn new(integrator: &'r mut I, t0: f64, start: &'r State<M>, t_end: f64) -> Self {
        Run {
            integrator,
            t0,
            start,
            t_end,
            sampling: Sampling::Steps,
            events: Events::new(),
            action: None,
            every: None,
            observer: None,
            progress: None,
        }
    }

    /// Records samples as `sampling` says (every step by default).
    pub fn sampling(mut self, sampling: Sampling) -> Self {
        self.sampling = sampling;
        self
    }

    /// Watches `events` besides the model's contacts, laws and switching surfaces (which every
    /// run watches: `Events::free_motion()` leaves the contacts out), each crossing recorded
    /// in the solution and handed to the action of [`Run::on_event`], if any.
    pub fn events(mut self, events: Events<'r, M>) -> Self {
        self.events = events;
        self
    }

    /// Hands each event, the model's contacts' and laws' included, to `action`, in time order,
    /// with an [`EventContext`] to read the state there, reset it or change the model, as
    /// [`SolveWithEvents::solve_with_events`] describes.
    pub fn on_event(
        mut self,
        action: impl FnMut(&Event, &mut EventContext<'_, M, I>) -> ControlFlow<()> + 'r,
    ) -> Self {
        self.action = Some(Box::new(action));
        self
    }

    /// Runs under a sampled-data controller: every `period` from the start,
    /// `controller(t_k, state, model)` reads the state and sets the model's inputs (or
    /// parameters), held until the next sample. No step straddles a sample. An input that
    /// moves a constraint (a voltage source's voltage, a prescribed position) moves the state
    /// as an impulse through the constraints would, to the consistent state nearest in the
    /// kinetic-energy norm; a law whose mode the new inputs change (a push past static
    /// friction) switches there. Needs an integrator built on `&mut model`.
    pub fn every(mut self, period: f64, controller: impl FnMut(f64, &State<M>, &mut M) + 'r) -> Self {
        self.every = Some((period, Box::new(controller)));
        self
    }

    /// Calls `observer` after every step with the time and the state reached (read by name:
    /// `state.q(Model::X)`); `ControlFlow::Break(())` ends the run there.
    pub fn observe(mut self, observer: impl FnMut(f64, &State<M>) -> ControlFlow<()> + 'r) -> Self {
        self.observer = Some(Box::new(observer));
        self
    }

    /// Reports the progress: `report` is called with the time reached, the integrator's
    /// counters and the wall-clock time, at most once per `interval` of wall-clock time (every
    /// step for a zero interval) and once at the end. `Progress` displays as one line;
    /// [`Progress::bar`] draws a text bar.
    pub fn progress(mut self, interval: Duration, report: impl FnMut(&Progress<I::Stats>) + 'r) -> Self {
        self.progress = Some((interval, Box::new(report)));
        self
    }

    /// Runs the integration and records its [`Solution`]: the samples, every event (the
    /// model's contacts and laws among them), every impact.
    pub fn solve(self) -> Result<Solution<M, I::Stats>, SimError>
    where
        M: Hybrid,
    {
        let Run { integrator, t0, start, t_end, sampling, events, action, every, observer, progress } = self;
        // A run without events of its own watches the model's switching surfaces too, so that
        // no step reaches across a kink; one with events watches what they ask for.
        let surfaces = events.names().is_empty();
        let mut events = events.watch_model(integrator.model(), surfaces)?;
        let mut action = action;
        let mut no_action = |_: &Event, _: &mut EventContext<'_, M, I>| ControlFlow::Continue(());
        let action: ActionRef<'_, M, I> = match &mut action {
            Some(action) => action,
            None => &mut no_action,
        };
        let began = Instant::now();
        let mut last = began;
        let mut observer = observer;
        let mut progress = progress;
        let watching = observer.is_some() || progress.is_some();
        let mut after_step = |integrator: &I| {
            if let Some((interval, report)) = &mut progress {
                let now = Instant::now();
                if now.duration_since(last) >= *interval && !integrator.finished() {
                    last = now;
                    report(&Progress {
                        t: integrator.t(),
                        t0,
                        t_end,
                        stats: integrator.stats(),
                        elapsed: now - began,
                    });
                }
            }
            match &mut observer {
                Some(observer) => observer(integrator.t(), integrator.state()),
                None => ControlFlow::Continue(()),
            }
        };
        let mut every = every;
        let hooks = Hooks {
            action,
            every: every.as_mut().map(|(period, controller)| (*period, &mut **controller as _)),
            after_step: if watching { Some(&mut after_step) } else { None },
        };
        let solution = drive(integrator, (t0, start, t_end), &sampling, &mut events, hooks);
        if let Some((_, report)) = &mut progress {
            report(&Progress {
                t: integrator.t(),
                t0,
                t_end,
                stats: integrator.stats(),
                elapsed: began.elapsed(),
            });
        }
        solution
    }
}

impl<'r, M: Parameters, I: Sensitive<M>> Run<'r, M, I>
where
    DefaultAllocator: Storage<M>,
{
    /// Carries the forward sensitivities of the solution with respect to `wrt`'s parameters and
    /// initial values, recorded at the same samples as the state ([`Solution::sensitivity`]),
    /// through impacts, switching surfaces and law switches (each crossing's jump carried).
    /// Only a method that carries them ([`Sensitive`]: Radau) offers it. The run that results
    /// takes samples and a progress report; a controller, an observer that stops the run or an
    /// event action that resets the state are not offered with sensitivities, whose jumps
    /// through them are not derived.
    pub fn sensitivities(self, wrt: &'r Sensitivities<M>) -> SensitiveRun<'r, M, I> {
        SensitiveRun {
            integrator: self.integrator,
            t0: self.t0,
            start: self.start,
            t_end: self.t_end,
            sampling: self.sampling,
            wrt,
        }
    }
}

/// A [`Run`] that carries forward sensitivities ([`Run::sensitivities`]).
pub struct SensitiveRun<'r, M: LagrangeDirac, I: Integrator<M>>
where
    DefaultAllocator: Storage<M>,
{
    integrator: &'r mut I,
    t0: f64,
    start: &'r State<M>,
    t_end: f64,
    sampling: Sampling,
    wrt: &'r Sensitivities<M>,
}

impl<M: Parameters + Hybrid, I: Sensitive<M>> SensitiveRun<'_, M, I>
where
    DefaultAllocator: Storage<M>,
{
    /// Records samples as `sampling` says.
    pub fn sampling(mut self, sampling: Sampling) -> Self {
        self.sampling = sampling;
        self
    }

    /// Runs the integration with the sensitivities and records both.
    pub fn solve(self) -> Result<Solution<M, I::Stats>, SimError> {
        self.integrator.carry_sensitivities(self.wrt)?;
        self.integrator.solve_with_sensitivities(self.t0, self.start, self.t_end, &self.sampling)
    }
}

/// Running an integration with events: implemented for every [`Integrator`] (and in the
/// facade's prelude).
pub trait SolveWithEvents<M: Hybrid>: Integrator<M> + Sized
where
    DefaultAllocator: Storage<M>,
{
    /// [`Integrator::solve`] with events: after each step, the crossings of the `events`'
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
    /// ([`Integrator::run`]), which `events` is borrowed by, not moved into.
    fn solve_with_events(
        &mut self,
        t0: f64,
        state: &State<M>,
        t_end: f64,
        sampling: &Sampling,
        events: &mut Events<'_, M>,
        mut action: impl FnMut(&Event, &mut EventContext<'_, M, Self>) -> ControlFlow<()>,
    ) -> Result<Solution<M, Self::Stats>, SimError> {
        *events = std::mem::take(events).watch_model(self.model(), false)?;
        let hooks = Hooks { action: &mut action, every: None, after_step: None };
        drive(self, (t0, state, t_end), sampling, events, hooks)
    }
}

impl<M: Hybrid, I: Integrator<M>> SolveWithEvents<M> for I where DefaultAllocator: Storage<M> {}
