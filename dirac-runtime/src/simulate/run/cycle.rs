//! The one loop of every run: steps, samples, events located and crossed (impacts, law
//! switches, switching surfaces, actions), a controller's samples and what is called after each
//! step.

use std::ops::ControlFlow;

use nalgebra::DefaultAllocator;

use super::restarts::{close, rest_where_it_stands, restart_consistent, restart_from, restart_in_modes};
use super::tangent::{Tangent, TangentRef};
use crate::analysis::diagnose::{CheckRoom, check_constraints_kept};
use crate::analysis::init::{Consistency, project};
use crate::error::SimError;
use crate::hybrid::event::{Event, Impact};
use crate::hybrid::events::context::sliding;
use crate::hybrid::events::{EventContext, Events};
use crate::hybrid::laws;
use crate::hybrid::laws::consistent_state;
use crate::integrator::restart::restart_at_nearest;
use crate::integrator::{Integrator, check_period};
use crate::model::state::State;
use crate::model::{Hybrid, LagrangeDirac};
use crate::output::recorder::Recorder;
use crate::output::solution::Sampling;
use crate::shape::dims::Storage;

/// An event's action, borrowed for the run's loop.
pub(crate) type ActionRef<'h, M, I> =
    &'h mut dyn FnMut(&Event, &mut EventContext<'_, M, I>) -> ControlFlow<()>;

/// A sampled-data controller, borrowed for the run's loop.
type ControllerRef<'h, M> = &'h mut dyn FnMut(f64, &State<M>, &mut M);

/// What a run calls after every step, borrowed for its loop.
type AfterStep<'h, I> = &'h mut dyn FnMut(&I) -> ControlFlow<()>;

/// What a run does besides stepping and watching events.
pub(crate) struct Hooks<'h, M: LagrangeDirac, I>
where
    DefaultAllocator: Storage<M>,
{
    /// The action at each event.
    pub action: ActionRef<'h, M, I>,
    /// A sampled-data controller and its period.
    pub every: Option<(f64, ControllerRef<'h, M>)>,
    /// Called after every step; a break ends the run.
    pub after_step: Option<AfterStep<'h, I>>,
    /// Carried beside the state and through its jumps.
    pub tangent: Option<TangentRef<'h, M, I>>,
}

impl<'h, M: LagrangeDirac, I> Hooks<'h, M, I>
where
    DefaultAllocator: Storage<M>,
{
    /// Only `action` at each event.
    pub fn acting(action: ActionRef<'h, M, I>) -> Self {
        Hooks { action, every: None, after_step: None, tangent: None }
    }
}

/// The one loop of every run: steps, the samples recorded, the events located and crossed
/// (impacts, law switches, switching surfaces, the user's actions), the controller's samples,
/// the observer after each step, the tangent carried. Returns the samples recorded, for the
/// caller to finish into a solution.
pub(crate) fn drive<M: Hybrid, I: Integrator<M>>(
    integrator: &mut I,
    (t0, state, t_end): (f64, &State<M>, f64),
    sampling: &Sampling,
    events: &mut Events<'_, M>,
    hooks: Hooks<'_, M, I>,
) -> Result<Recorder<M>, SimError>
where
    DefaultAllocator: Storage<M>,
{
    let Hooks { action, mut every, mut after_step, mut tangent } = hooks;
    if let Some((period, _)) = &every {
        check_period(t0, t_end, *period)?;
    }
    let mut recorder = Recorder::new(integrator.model(), sampling, t0, t_end)?;
    recorder.name_events(events.names());
    if let Some(contacts) = &events.contacts {
        recorder.name_contacts(&contacts.names);
    }
    // The controller's first sample sets the inputs the start holds.
    let sample = |k: usize, period: f64| (t0 + k as f64 * period).min(t_end);
    let mut stop = t_end;
    if let Some((period, controller)) = &mut every {
        controller(t0, state, integrator.model_mut().ok_or(SimError::SharedModel { t: t0 })?);
        stop = sample(1, *period);
    }
    let mut after = begin(integrator, events, &mut recorder, (t0, state, stop))?;
    if let Some(tangent) = &mut tangent {
        tangent.started(integrator, &recorder, &after)?;
    }
    let mut reopened = Vec::new();
    let mut k = 1;
    loop {
        let mut stretch = Stretch {
            events,
            recorder: &mut recorder,
            after: &mut after,
            reopened: &mut reopened,
            tangent: tangent.as_deref_mut(),
        };
        if stretch.run(integrator, action, &mut after_step)?.is_break() {
            return Ok(recorder);
        }
        let Some((period, controller)) = &mut every else { break };
        let t = integrator.t();
        if t >= t_end {
            break;
        }
        after.clone_from(integrator.state());
        controller(t, &after, integrator.model_mut().ok_or(SimError::SharedModel { t })?);
        k += 1;
        resample(integrator, events, &mut recorder, sample(k, *period))?;
    }
    Ok(recorder)
}

/// What the steps of a run between two of the controller's samples work on.
struct Stretch<'a, 'e, 't, M: LagrangeDirac, I>
where
    DefaultAllocator: Storage<M>,
{
    events: &'a mut Events<'e, M>,
    recorder: &'a mut Recorder<M>,
    /// The state after the last event crossed.
    after: &'a mut State<M>,
    /// The contacts the last impact reopened.
    reopened: &'a mut Vec<usize>,
    /// Carried beside the state, if the run carries anything.
    tangent: Option<&'a mut (dyn Tangent<M, I> + 't)>,
}

impl<M: Hybrid, I: Integrator<M>> Stretch<'_, '_, '_, M, I>
where
    DefaultAllocator: Storage<M>,
{
    /// Steps until the integrator reaches its end (the next sample, or the run's end), the
    /// events watched and the samples recorded; a break where an action or the after-step hook
    /// ended the run.
    fn run(
        &mut self,
        integrator: &mut I,
        action: ActionRef<'_, M, I>,
        after_step: &mut Option<AfterStep<'_, I>>,
    ) -> Result<ControlFlow<()>, SimError> {
        let watching = !self.events.names().is_empty();
        while !integrator.finished() {
            let restarted = if watching {
                match self.step_with_events(integrator, action)? {
                    Stepped::Ended => return Ok(ControlFlow::Break(())),
                    Stepped::Restarted => true,
                    Stepped::On => false,
                }
            } else {
                self.step(integrator)?;
                false
            };
            if !restarted {
                let before = self.recorder.len();
                self.recorder.record_step(
                    integrator.model(),
                    integrator.t(),
                    integrator.state(),
                    |t, out| integrator.interpolate(t, out),
                );
                if let Some(tangent) = &mut self.tangent {
                    tangent.sampled(integrator, self.recorder, before);
                }
            }
            if let Some(after_step) = after_step
                && after_step(integrator).is_break()
            {
                return Ok(ControlFlow::Break(()));
            }
        }
        Ok(ControlFlow::Continue(()))
    }

    /// One step, the tangent told before and after it.
    fn step(&mut self, integrator: &mut I) -> Result<(), SimError> {
        if let Some(tangent) = &mut self.tangent {
            tangent.before_step(integrator);
        }
        let h = integrator.step()?;
        if let Some(tangent) = &mut self.tangent {
            tangent.after_step(integrator, h);
        }
        Ok(())
    }
}

/// Starts `integrator` from `state` at `t0` towards `stop`, each law in the mode the state puts
/// it in, the events watched from there and the start recorded; returns the state started from.
fn begin<M: Hybrid, I: Integrator<M>>(
    integrator: &mut I,
    events: &mut Events<'_, M>,
    recorder: &mut Recorder<M>,
    (t0, state, stop): (f64, &State<M>, f64),
) -> Result<State<M>, SimError>
where
    DefaultAllocator: Storage<M>,
{
    // Each law starts in the mode the state puts it in (the start made consistent there, if
    // the state held another).
    let chosen = laws::start_in_modes(integrator.model(), t0, state)?;
    let state = chosen.as_ref().unwrap_or(state);
    integrator.start(t0, state, stop)?;
    events.begin(integrator.model(), t0, integrator.state())?;
    recorder.record_initial(integrator.model(), t0, integrator.state());
    let mut after = state.clone();
    // A timed switch at zero at the start (a pulse's first edge at `t0`): the run goes on
    // from the first time after it, on its other side, from the consistent state nearest.
    if let Some(t) = events.start_across(integrator)? {
        after.clone_from(integrator.state());
        if integrator.start(t, &after, stop).is_err() {
            after = project(integrator.model(), t, &after.q, &after.v, Consistency::default())?;
            integrator.start(t, &after, stop)?;
        }
        events.resume(integrator.model(), t, &after)?;
    }
    Ok(after)
}

/// Goes on from a controller's sample towards `next`, the model changed by the controller:
/// where it moved a constraint, the state jumps to the consistent state nearest in the
/// kinetic-energy norm (the impulse through the constraints); where it changed a law's mode,
/// the state is made consistent in the new one; the events watch on from there.
fn resample<M: Hybrid, I: Integrator<M>>(
    integrator: &mut I,
    events: &mut Events<'_, M>,
    recorder: &mut Recorder<M>,
    next: f64,
) -> Result<(), SimError>
where
    DefaultAllocator: Storage<M>,
{
    let t = integrator.t();
    match integrator.restart_until(next) {
        Err(SimError::ConstraintMoved { .. }) => {
            let state = integrator.state();
            let jumped = consistent_state(integrator.model(), t, &state.q, &state.v, Consistency::default())?;
            // The change was checked: on towards `next`, then from the state after the impulse.
            integrator.restart_until(next)?;
            integrator.restart_at(t, &jumped)?;
            recorder.record_reset(integrator.model(), t, &jumped);
        }
        other => other?,
    }
    if let Some(chosen) = laws::start_in_modes(integrator.model(), t, integrator.state())? {
        integrator.restart_at(t, &chosen)?;
        recorder.record_reset(integrator.model(), t, &chosen);
    }
    events.resume(integrator.model(), t, integrator.state())
}

/// How a step with events ended.
enum Stepped {
    /// The step stands; the run goes on from its end.
    On,
    /// The run restarted within the step or at its end (a reset, a switch, an impact, a rest),
    /// its samples recorded up to there.
    Restarted,
    /// An action ended the run.
    Ended,
}

impl<M: Hybrid, I: Integrator<M>> Stretch<'_, '_, '_, M, I>
where
    DefaultAllocator: Storage<M>,
{
    /// One step with the events watched: the step taken (or a Zeno sequence of impacts brought
    /// to rest), then each crossing within it located and crossed in time order (impacts, law
    /// switches, switching surfaces, the action), restarting where one of them changes the
    /// state or the model.
    fn step_with_events(
        &mut self,
        integrator: &mut I,
        action: ActionRef<'_, M, I>,
    ) -> Result<Stepped, SimError> {
        self.events.bound_step(integrator)?;
        // A contact that comes to rest switches the constraints, whose jump a tangent does not
        // carry: a run that carries one ends there.
        let rests = self.tangent.is_none();
        if let Err(error) = self.step(integrator) {
            // A step that fails where impacts accumulate fails because of them: the contact
            // comes to rest where the integrator stands, if it can.
            let Some(j) = (match (&error, &self.events.contacts) {
                (SimError::StepSizeTooSmall { t, .. }, Some(contacts)) if rests => contacts.zeno(*t),
                _ => None,
            }) else {
                return Err(sliding(integrator, self.events, error));
            };
            rest_where_it_stands(integrator, self.events, self.recorder, j)?;
            return Ok(Stepped::Restarted);
        }
        loop {
            let event = match self.events.locate(integrator) {
                Ok(Some(event)) => event,
                Ok(None) => return Ok(Stepped::On),
                // A contact pressed in without an impact rests from the step's end, if it can.
                Err(SimError::ContactCloses { contact, t_limit: None, .. })
                    if rests
                        && self
                            .events
                            .contact_index(&contact)
                            .is_some_and(|j| integrator.model().contact_row(j).is_some()) =>
                {
                    let j = self.events.contact_index(&contact).expect("just found");
                    rest_where_it_stands(integrator, self.events, self.recorder, j)?;
                    return Ok(Stepped::Restarted);
                }
                Err(error) => return Err(error),
            };
            let crossed = match self.tangent.is_some() {
                true => self.cross_carried(integrator, event)?,
                false => self.cross(integrator, action, event)?,
            };
            if let Some(stepped) = crossed {
                return Ok(stepped);
            }
        }
    }

    /// Crosses `event`, located within the last step: records it, applies its impacts, its
    /// contact's rest or release and its law's switch, hands it to the action, and restarts
    /// where any of them changed the state or the model (`Some`); `None` where the search goes
    /// on within the step.
    fn cross(
        &mut self,
        integrator: &mut I,
        action: ActionRef<'_, M, I>,
        event: Event,
    ) -> Result<Option<Stepped>, SimError> {
        let Stretch { events, recorder, after, reopened, .. } = self;
        let t = event.t;
        recorder
            .record_step(integrator.model(), t, events.state(), |ts, out| integrator.interpolate(ts, out));
        recorder.record_event(integrator.model(), event, events.state());
        after.clone_from(events.state());
        let (impulse, mut switched) = strike(integrator, events, recorder, after, reopened, &event)?;
        let contact_switched = switched;
        // A law switches its mode: the state is made consistent in the new one. Where that leaves
        // a contact's force pulling, so that the friction it drives would push, the contacts'
        // modes are settled again (the contact opens).
        let (law, pulled) = match events.switch_law(integrator.model(), event.index, t, after) {
            Ok(law) => (law, false),
            Err(SimError::FrictionPushes { row, .. }) if pulls_at_contact(integrator.model(), &row) => {
                (true, true)
            }
            Err(error) => return Err(error),
        };
        let contact_switched = contact_switched || pulled;
        // Consistent already, unless an impact or a contact changed it too.
        let consistent = law && !switched && !pulled && reopened.is_empty();
        switched |= law;
        let mut context = EventContext::new(t, after, integrator);
        context.impulse = impulse;
        context.reset = !reopened.is_empty() || switched;
        let flow = action(&event, &mut context);
        let (reset, before) = context.changes();
        let touched = context.touched;
        if flow.is_break() {
            return Ok(Some(Stepped::Ended));
        }
        if !(reset || before.is_some()) && events.switch_of[event.index] {
            // A switching surface: the step that reached across it is cut there, and the
            // integration goes on from the state at the crossing, on the other side. The
            // interpolated state is the step's, on the constraints as its steps are; where the
            // integrator's own check refuses it, from the consistent state nearest to it.
            restart_at_nearest(integrator, t, after)?;
            events.resume(integrator.model(), t, after)?;
            return Ok(Some(Stepped::Restarted));
        }
        if !(reset || before.is_some()) {
            return Ok(None);
        }
        if let (false, Some(before)) = (reset, before) {
            check_constraints_kept(
                integrator.model(),
                t,
                after,
                before,
                &mut CheckRoom::new(integrator.model()),
            )?;
        }
        if consistent && !touched {
            restart_consistent(integrator, events, recorder, t, after)?;
        } else if contact_switched && !touched {
            restart_in_modes(integrator, events, recorder, t, after)?;
        } else {
            restart_from(integrator, events, recorder, t, after)?;
        }
        events.reopen(reopened);
        Ok(Some(Stepped::Restarted))
    }

    /// Crosses `event` in a run that carries a tangent: records it and the tangent there, and
    /// crosses its impact, law switch or switching surface with its derivative
    /// ([`Events::cross`]), the tangent carried across the jump and the integration restarted
    /// after it (`Some`); `None` for an event of the run's own, which changes nothing.
    fn cross_carried(&mut self, integrator: &mut I, event: Event) -> Result<Option<Stepped>, SimError> {
        let Stretch { events, recorder, tangent, .. } = self;
        let tangent = tangent.as_deref_mut().expect("a run that carries a tangent");
        let t = event.t;
        let before = recorder.len();
        recorder
            .record_step(integrator.model(), t, events.state(), |ts, out| integrator.interpolate(ts, out));
        recorder.record_event(integrator.model(), event, events.state());
        tangent.sampled(integrator, recorder, before);
        if !events.jumps_at(event.index) {
            return Ok(None);
        }
        let crossed = tangent.cross(integrator.model(), events, &event)?;
        for &(j, impulse) in &crossed.impulses {
            recorder.record_impact(Impact { contact: j, t, impulse });
        }
        let Some(mut jump) = crossed.jump else { return Ok(None) };
        let reopened = std::mem::take(&mut jump.reopened);
        let after = tangent.jump(integrator, t, jump)?;
        events.resume(integrator.model(), t, &after)?;
        events.reopen(&reopened);
        if !crossed.impulses.is_empty() || crossed.switched {
            // An impact's state after it is a sample of its own, as a law's switch's is; a
            // switching surface's is the crossing's, just recorded.
            let before = recorder.len();
            recorder.record_reset(integrator.model(), t, &after);
            tangent.restarted(recorder, before);
        }
        Ok(Some(Stepped::Restarted))
    }
}

/// Whether `row` is the row of a closed contact of `model` that can open: a friction that
/// such a contact's pulling force would make push is settled by opening it.
fn pulls_at_contact<M: Hybrid>(model: &M, row: &str) -> bool
where
    DefaultAllocator: Storage<M>,
{
    let names = model.constraint_names();
    (0..model.unilateral_names().len())
        .filter(|&j| model.contact_closed(j))
        .filter_map(|j| model.contact_row(j))
        .any(|r| names[r] == row)
}

/// What `event` does to the contacts, when it is one's (an impact, with every contact closed
/// there too; a contact left at rest closed) or a resting contact's release: `after` changed
/// by the impact law, the impulses recorded, the contacts the impact reopened in `reopened`.
/// Returns the event's own contact's impulse and whether a contact closed or opened.
fn strike<M: Hybrid, I: Integrator<M>>(
    integrator: &mut I,
    events: &mut Events<'_, M>,
    recorder: &mut Recorder<M>,
    after: &mut State<M>,
    reopened: &mut Vec<usize>,
    event: &Event,
) -> Result<(Option<f64>, bool), SimError>
where
    DefaultAllocator: Storage<M>,
{
    let t = event.t;
    let (mut impulse, mut switched) = (None, false);
    reopened.clear();
    if let Some(contact) = events.contact_of[event.index] {
        let impacts = events.impact(integrator.model(), event.index, t, after)?;
        for &(j, lambda) in &impacts.impulses {
            recorder.record_impact(Impact { contact: j, t, impulse: lambda });
            if lambda > 0.0 {
                reopened.push(j);
            }
            if j == contact {
                impulse = Some(lambda);
            }
        }
        if let Some(j) = impacts.resting {
            // Left at rest: the contact closes, if it can, and the restart projects the state
            // onto it (a plastic impact).
            if !close(integrator, j, true) {
                let contacts = events.contacts.as_ref().expect("contact events come with their contacts");
                return Err(contacts.closes(j, t));
            }
            events.contacts.as_mut().expect("contact events come with their contacts").rested(j);
            reopened.retain(|&c| c != j);
            switched = true;
        }
    }
    if let Some(j) = events.release_of[event.index] {
        switched |= close(integrator, j, false);
    }
    Ok((impulse, switched))
}
