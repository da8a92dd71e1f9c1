//! One run of an integrator, with whatever it is asked to do besides stepping: samples,
//! events and their actions, a sampled-data controller, an observer, a progress report. The
//! model's contacts, laws and switching surfaces are always watched, whatever else the run
//! does, so that every combination means what each part means alone.
//!
//! [`Solve::run`](crate::Solve::run) begins one; [`Run::solve`](crate::Run::solve)
//! runs it to a [`Solution`](crate::Solution). `solve`,
//! `solve_sampled`, `solve_observed`, `solve_with_progress` and `solve_with_events` are
//! one-line shorthands of it.

use std::marker::PhantomData;
use std::ops::ControlFlow;
use std::time::{Duration, Instant};

use nalgebra::DefaultAllocator;

use crate::error::SimError;
use crate::hybrid::event::Event;
use crate::hybrid::events::{EventContext, Events};
use crate::integrator::{Drive, Integrator};
use crate::model::state::State;
use crate::model::{Hybrid, LagrangeDirac, Parameters};
use crate::output::progress::Progress;
use crate::output::solution::{Sampling, Solution};
use crate::shape::dims::Storage;
use crate::simulate::sensitive::{Carrier, Sensitive};
use crate::simulate::sensitivity::Sensitivities;

pub(crate) mod cycle;
mod restarts;
mod solve;
pub(crate) mod tangent;

pub use self::solve::Solve;

use self::cycle::{ActionRef, Hooks, drive};
pub(crate) use self::tangent::TangentRef;

/// What a [`Run`] was asked that feeds back into the model as it runs, which decides what it
/// can carry besides the state: the third parameter of its type.
pub mod feedback {
    /// Nothing feeds back into the model: the run can carry forward sensitivities
    /// ([`Run::sensitivities`](super::Run::sensitivities)) or record its steps for an adjoint
    /// (`Run::record`, with Radau).
    #[derive(Debug)]
    pub struct Open;

    /// A sampled controller, an event action or a drive changes the model as it runs: their
    /// derivatives are not carried, so neither sensitivities nor a recording are offered.
    #[derive(Debug)]
    pub struct FedBack;

    /// The run carries forward sensitivities: nothing that feeds back into the model is
    /// offered.
    #[derive(Debug)]
    pub struct WithSensitivities;

    /// The states in which a controller, an action or a drive may still be added.
    pub trait MayFeedBack: private::Sealed {}
    impl MayFeedBack for Open {}
    impl MayFeedBack for FedBack {}

    /// The states that solve without sensitivities.
    pub trait Plain: private::Sealed {}
    impl Plain for Open {}
    impl Plain for FedBack {}

    mod private {
        pub trait Sealed {}
        impl Sealed for super::Open {}
        impl Sealed for super::FedBack {}
    }
}

use self::feedback::{FedBack, MayFeedBack, Open, Plain, WithSensitivities};

/// An event's action: what it does with the event, the state and the model there.
type Action<'r, M, I> = Box<dyn FnMut(&Event, &mut EventContext<'_, M, I>) -> ControlFlow<()> + 'r>;

/// A sampled-data controller: `controller(t_k, state, model)` sets the model's inputs.
type Controller<'r, M> = Box<dyn FnMut(f64, &State<M>, &mut M) + 'r>;

/// An observer of the state after each step, which may stop the run.
type Observer<'r, M> = Box<dyn FnMut(f64, &State<M>) -> ControlFlow<()> + 'r>;

/// A report of the run's progress.
type Report<'r, S> = Box<dyn FnMut(&Progress<S>) + 'r>;

/// One run of integrator `I` over model `M`, built by [`Solve::run`] and its options, and
/// run by [`Run::solve`] (or, with Radau, recorded for an adjoint by `Run::record`). Every
/// option composes with every other, and with the model's own contacts, laws and switching
/// surfaces, which every run watches. What is asked for is tracked in the type's third
/// parameter ([`feedback`]): a run whose controller, event action or drive feeds back into
/// the model offers no sensitivities and no recording, and one with sensitivities offers none
/// of those, refused when it compiles.
///
/// The facade's guide (`dirac::guide`, "One run: controllers, events and contacts together") has
/// a runnable example: a block on a spring, with a wall, under a controller at 100 Hz.
pub struct Run<'r, M: LagrangeDirac, I: Integrator<M>, F = Open>
where
    DefaultAllocator: Storage<M>,
{
    pub(crate) integrator: &'r mut I,
    pub(crate) t0: f64,
    pub(crate) start: &'r State<M>,
    pub(crate) t_end: f64,
    sampling: Sampling,
    events: Events<'r, M>,
    action: Option<Action<'r, M, I>>,
    controller: Option<(f64, Controller<'r, M>)>,
    observer: Option<Observer<'r, M>>,
    progress: Option<(Duration, Report<'r, I::Stats>)>,
    wrt: Option<&'r Sensitivities<M>>,
    /// Why the run cannot go: a drive the integrator refused.
    refused: Option<SimError>,
    feedback: PhantomData<F>,
}

impl<'r, M: LagrangeDirac, I: Integrator<M>> Run<'r, M, I>
where
    DefaultAllocator: Storage<M>,
{
    /// A run of `integrator` from `start` at `t0` to `t_end` that records every step and does
    /// nothing else ([`Solve::run`](crate::Solve::run)).
    pub(crate) fn new(integrator: &'r mut I, t0: f64, start: &'r State<M>, t_end: f64) -> Self {
        Run {
            integrator,
            t0,
            start,
            t_end,
            sampling: Sampling::Steps,
            events: Events::new(),
            action: None,
            controller: None,
            observer: None,
            progress: None,
            wrt: None,
            refused: None,
            feedback: PhantomData,
        }
    }
}

impl<'r, M: LagrangeDirac, I: Integrator<M>, F> Run<'r, M, I, F>
where
    DefaultAllocator: Storage<M>,
{
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

    /// The same run in feedback state `G`.
    fn now<G>(self) -> Run<'r, M, I, G> {
        let Run {
            integrator,
            t0,
            start,
            t_end,
            sampling,
            events,
            action,
            controller,
            observer,
            progress,
            wrt,
            refused,
            ..
        } = self;
        Run {
            integrator,
            t0,
            start,
            t_end,
            sampling,
            events,
            action,
            controller,
            observer,
            progress,
            wrt,
            refused,
            feedback: PhantomData,
        }
    }

    /// Runs the loop with `tangent` carried (if any), the observer and the progress report
    /// called after each step; the samples recorded.
    pub(crate) fn go(
        self,
        tangent: Option<TangentRef<'_, M, I>>,
    ) -> Result<(crate::output::recorder::Recorder<M>, &'r mut I), SimError>
    where
        M: Hybrid,
    {
        let Run {
            integrator,
            t0,
            start,
            t_end,
            sampling,
            mut events,
            action,
            controller,
            observer,
            progress,
            refused,
            ..
        } = self;
        if let Some(error) = refused {
            return Err(error);
        }
        // A run without events of its own watches the model's switching surfaces too, so that
        // no step reaches across a kink; one with events watches what they ask for.
        let surfaces = events.names().is_empty();
        events.watch_model(integrator.model(), surfaces)?;
        let mut tangent = tangent;
        if let Some(tangent) = &mut tangent {
            tangent.prepare(integrator);
        }
        let mut action = action;
        let mut no_action = |_: &Event, _: &mut EventContext<'_, M, I>| ControlFlow::Continue(());
        let action: ActionRef<'_, M, I> = match &mut action {
            Some(action) => action,
            None => &mut no_action,
        };
        let began = Instant::now();
        let mut watch = Watch { began, last: began, t0, t_end, observer, progress };
        let watching = watch.observer.is_some() || watch.progress.is_some();
        let mut after_step = |integrator: &I| watch.after_step(integrator);
        let mut controller = controller;
        let hooks = Hooks {
            action,
            every: controller.as_mut().map(|(period, controller)| (*period, &mut **controller as _)),
            after_step: if watching { Some(&mut after_step) } else { None },
            tangent: tangent.as_deref_mut().map(|tangent| -> TangentRef<'_, M, I> { tangent }),
        };
        let recorder = drive(integrator, (t0, start, t_end), &sampling, &mut events, hooks);
        if let Some(tangent) = &mut tangent {
            tangent.restore(integrator);
        }
        watch.finish(integrator);
        Ok((recorder?, integrator))
    }
}

/// The observer and the progress report of a run, called after each step.
struct Watch<'r, M: LagrangeDirac, S>
where
    DefaultAllocator: Storage<M>,
{
    began: Instant,
    /// When the last report was made.
    last: Instant,
    t0: f64,
    t_end: f64,
    observer: Option<Observer<'r, M>>,
    progress: Option<(Duration, Report<'r, S>)>,
}

impl<M: LagrangeDirac, S> Watch<'_, M, S>
where
    DefaultAllocator: Storage<M>,
{
    /// Reports the progress, if an interval passed since the last report, and calls the
    /// observer.
    fn after_step<I: Integrator<M, Stats = S>>(&mut self, integrator: &I) -> ControlFlow<()> {
        if let Some((interval, report)) = &mut self.progress {
            let now = Instant::now();
            if now.duration_since(self.last) >= *interval && !integrator.finished() {
                self.last = now;
                let elapsed = now - self.began;
                report(&Progress {
                    t: integrator.t(),
                    t0: self.t0,
                    t_end: self.t_end,
                    stats: integrator.stats(),
                    elapsed,
                });
            }
        }
        match &mut self.observer {
            Some(observer) => observer(integrator.t(), integrator.state()),
            None => ControlFlow::Continue(()),
        }
    }

    /// The last report, at the end.
    fn finish<I: Integrator<M, Stats = S>>(&mut self, integrator: &I) {
        if let Some((_, report)) = &mut self.progress {
            report(&Progress {
                t: integrator.t(),
                t0: self.t0,
                t_end: self.t_end,
                stats: integrator.stats(),
                elapsed: self.began.elapsed(),
            });
        }
    }
}
impl<'r, M: LagrangeDirac, I: Integrator<M>, F: MayFeedBack> Run<'r, M, I, F>
where
    DefaultAllocator: Storage<M>,
{
    /// Hands each event, the model's contacts' and laws' included, to `action`, in time order,
    /// with an [`EventContext`] to read the state there, reset it or change the model, as
    /// [`Solve::solve_with_events`] describes.
    pub fn on_event(
        mut self,
        action: impl FnMut(&Event, &mut EventContext<'_, M, I>) -> ControlFlow<()> + 'r,
    ) -> Run<'r, M, I, FedBack> {
        self.action = Some(Box::new(action));
        self.now()
    }

    /// Runs under a sampled-data controller: every `period` from the start,
    /// `controller(t_k, state, model)` reads the state and sets the model's inputs (or
    /// parameters), held until the next sample. No step straddles a sample. An input that
    /// moves a constraint (a voltage source's voltage, a prescribed position) moves the state
    /// as an impulse through the constraints would, to the consistent state nearest in the
    /// kinetic-energy norm; a law whose mode the new inputs change (a push past static
    /// friction) switches there. Needs an integrator built on `&mut model`.
    pub fn every(
        mut self,
        period: f64,
        controller: impl FnMut(f64, &State<M>, &mut M) + 'r,
    ) -> Run<'r, M, I, FedBack> {
        self.controller = Some((period, Box::new(controller)));
        self.now()
    }

    /// Sets the model's inputs with `drive(t, state, model)` before every evaluation of the
    /// model, within the steps (a source, a table, a continuous feedback), and ends a step at
    /// each of `stops`, where those inputs jump or bend: [`Drive::drive`] and
    /// [`Drive::stop_at`] on the integrator, which keeps them after the run. Needs an
    /// integrator built on `&mut model`; where the integrator refuses, the run's `solve` says
    /// why.
    pub fn drive<'m>(
        mut self,
        drive: &'m mut dyn FnMut(f64, &State<M>, &mut M),
        stops: &[f64],
    ) -> Run<'r, M, I, FedBack>
    where
        I: Drive<'m, M>,
    {
        if let Err(error) = self.integrator.drive(drive).and_then(|()| self.integrator.stop_at(stops)) {
            self.refused = Some(error);
        }
        self.now()
    }
}

impl<M: Hybrid, I: Integrator<M>, F: Plain> Run<'_, M, I, F>
where
    DefaultAllocator: Storage<M>,
{
    /// Runs the integration and records its [`Solution`]: the samples, every event (the
    /// model's contacts and laws among them), every impact.
    pub fn solve(self) -> Result<Solution<M, I::Stats>, SimError> {
        let (recorder, integrator) = self.go(None)?;
        recorder.finish_from(integrator)
    }
}

impl<'r, M: Parameters, I: Sensitive<M>> Run<'r, M, I, Open>
where
    DefaultAllocator: Storage<M>,
{
    /// Carries the forward sensitivities of the solution with respect to `wrt`'s parameters and
    /// initial values, recorded at the same samples as the state ([`Solution::sensitivity`]),
    /// through impacts, switching surfaces and law switches (each crossing's jump carried).
    /// Only a method that carries them ([`Sensitive`]: Radau) offers it, and only on a run
    /// whose model nothing feeds back into: a controller, an event action or a drive before or
    /// after it does not compile. Samples, events of the run's own (recorded, moving nothing),
    /// an observer and a progress report compose with it.
    pub fn sensitivities(mut self, wrt: &'r Sensitivities<M>) -> Run<'r, M, I, WithSensitivities> {
        self.wrt = Some(wrt);
        self.now()
    }
}

impl<M: Parameters + Hybrid, I: Sensitive<M>> Run<'_, M, I, WithSensitivities>
where
    DefaultAllocator: Storage<M>,
{
    /// Runs the integration with the sensitivities and records both: the state as
    /// [`Run::solve`] does and each sensitivity at the same samples, read by quantity and name
    /// ([`Solution::sensitivity`]).
    pub fn solve(self) -> Result<Solution<M, I::Stats>, SimError> {
        let wrt = self.wrt.expect("a run with sensitivities holds what they are taken with respect to");
        self.integrator.carry_sensitivities(wrt)?;
        let mut carrier = Carrier::new(&*self.integrator)?;
        let (recorder, integrator) = self.go(Some(&mut carrier))?;
        carrier.finish(integrator, recorder)
    }
}
