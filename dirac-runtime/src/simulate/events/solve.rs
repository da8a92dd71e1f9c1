//! A whole integration with events: each crossing handed to the user's action in time order,
//! impacts applied at contacts, and a restart from a consistent state where the action
//! reset the state or changed the model.

use std::ops::ControlFlow;

use nalgebra::DefaultAllocator;

use super::Events;
use crate::analysis::diagnose::{CheckRoom, check_constraints_kept};
use crate::analysis::init::{Consistency, project};
use crate::error::SimError;
use crate::model::state::State;
use crate::model::{Hybrid, LagrangeDirac};
use crate::shape::dims::Storage;
use crate::simulate::integrator::{Integrator, refuse_unwatched_contacts};
use crate::simulate::laws;
use crate::simulate::recorder::Recorder;
use crate::simulate::restart::constraint_violation;
use crate::simulate::restart::restart_at_nearest;
use crate::simulate::solution::{Event, Impact, Sampling, Solution};

/// What an event's action may do: read the event's time and state, reset the state, change
/// the model (if the integrator holds it exclusively).
pub struct EventContext<'a, M: LagrangeDirac, I>
where
    DefaultAllocator: Storage<M>,
{
    t: f64,
    state: &'a mut State<M>,
    integrator: &'a mut I,
    reset: bool,
    /// How far the state was from the constraints before the model was first handed out.
    before: Option<f64>,
    /// The impulse of the event's contact, when the event is an impact.
    impulse: Option<f64>,
    /// Whether the action asked for the state or the model to change.
    touched: bool,
}

impl<'a, M: LagrangeDirac, I: Integrator<M>> EventContext<'a, M, I>
where
    DefaultAllocator: Storage<M>,
{
    pub(crate) fn new(t: f64, state: &'a mut State<M>, integrator: &'a mut I) -> Self {
        EventContext { t, state, integrator, reset: false, before: None, impulse: None, touched: false }
    }

    /// The impulse `Λ ≥ 0` the impact law gave the event's contact, when the event is a
    /// unilateral constraint's ([`Events::contacts`]); the state is then the one after it.
    pub fn impulse(&self) -> Option<f64> {
        self.impulse
    }

    /// The event's time.
    pub fn t(&self) -> f64 {
        self.t
    }

    /// The state at the event.
    pub fn state(&self) -> &State<M> {
        self.state
    }

    /// The state at the event, to reset: the integration restarts from the consistent state
    /// nearest to the positions and velocities left here (see
    /// [`consistent_state`](crate::consistent_state): momenta and multipliers are computed,
    /// not read).
    pub fn state_mut(&mut self) -> &mut State<M> {
        self.reset = true;
        self.touched = true;
        self.state
    }

    /// The model.
    pub fn model(&self) -> &M {
        self.integrator.model()
    }

    /// The integrator's statistics so far: steps taken, rejected, evaluations.
    pub fn stats(&self) -> I::Stats {
        self.integrator.stats()
    }

    /// The model, to change (its inputs, its parameters): the integration restarts at the
    /// event. A change that moves a constraint off the state is refused with
    /// [`SimError::ConstraintMoved`] unless the state is reset too.
    pub fn model_mut(&mut self) -> Result<&mut M, SimError> {
        self.touched = true;
        if self.before.is_none() {
            self.before = Some(constraint_violation(self.integrator.model(), self.t, self.state));
        }
        let t = self.t;
        self.integrator.model_mut().ok_or(SimError::SharedModel { t })
    }

    /// Whether the action reset the state or changed the model.
    pub(crate) fn changes(&self) -> (bool, Option<f64>) {
        (self.reset, self.before)
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
    /// ([`EventContext::state_mut`]) or change the model ([`EventContext::model_mut`]).
    ///
    /// - An action that changes nothing costs no restart: the search goes on within the step.
    /// - After a reset or a change, the integration restarts at the event from the consistent
    ///   state nearest to the one the action left ([`consistent_state`](crate::consistent_state)).
    /// - `ControlFlow::Break(())` ends the solution at the event (the integrator itself stays
    ///   at the end of the step that held it; [`Integrator::restart_at`] moves it back).
    ///
    /// The solution records every event ([`Solution::events`](crate::simulate::solution::Solution::events)) and, unless it samples at
    /// chosen times, the state at each event, twice when the action reset it (before, then
    /// after). The [`Events`] type has an example.
    fn solve_with_events(
        &mut self,
        t0: f64,
        state: &State<M>,
        t_end: f64,
        sampling: &Sampling,
        events: &mut Events<'_, M>,
        mut action: impl FnMut(&Event, &mut EventContext<'_, M, Self>) -> ControlFlow<()>,
    ) -> Result<Solution<M, Self::Stats>, SimError> {
        if events.contacts.is_none() && !events.free_motion {
            refuse_unwatched_contacts(self.model())?;
        }
        let mut recorder = Recorder::new(self.model(), sampling, t0, t_end)?;
        recorder.name_events(events.names());
        if let Some(contacts) = &events.contacts {
            recorder.name_contacts(&contacts.names);
        }
        // Each law starts in the mode the state puts it in (the start made consistent there, if
        // the state held another).
        if laws::has_laws(self.model()) && !events.watches_laws(self.model()) {
            return Err(unwatched_laws(self.model()));
        }
        let chosen = laws::start_in_modes(self.model(), t0, state)?;
        let state = chosen.as_ref().unwrap_or(state);
        self.start(t0, state, t_end)?;
        events.begin(self.model(), t0, self.state())?;
        recorder.record_initial(self.model(), t0, self.state());
        let mut after = state.clone();
        // A timed switch at zero at the start (a pulse's first edge at `t0`): the run goes on
        // from the first time after it, on its other side, from the consistent state nearest.
        if let Some(t) = events.start_across(self)? {
            after.clone_from(self.state());
            if self.start(t, &after, t_end).is_err() {
                after = project(self.model(), t, &after.q, &after.v, Consistency::default())?;
                self.start(t, &after, t_end)?;
            }
            events.resume(self.model(), t, &after)?;
        }
        let mut reopened = Vec::new();
        while !self.finished() {
            events.bound_step(self)?;
            if let Err(error) = self.step() {
                // A step that fails where impacts accumulate fails because of them: the contact
                // comes to rest where the integrator stands, if it can.
                let Some(j) = (match (&error, &events.contacts) {
                    (SimError::StepSizeTooSmall { t, .. }, Some(contacts)) => contacts.zeno(*t),
                    _ => None,
                }) else {
                    return Err(sliding(self, events, error));
                };
                rest_where_it_stands(self, events, &mut recorder, j)?;
                continue;
            }
            let mut restarted = false;
            loop {
                let event = match events.locate(self) {
                    Ok(Some(event)) => event,
                    Ok(None) => break,
                    // A contact pressed in without an impact rests from the step's end, if it can.
                    Err(SimError::ContactCloses { contact, t_limit: None, .. })
                        if events
                            .contact_index(&contact)
                            .is_some_and(|j| self.model().contact_row(j).is_some()) =>
                    {
                        let j = events.contact_index(&contact).expect("just found");
                        rest_where_it_stands(self, events, &mut recorder, j)?;
                        restarted = true;
                        break;
                    }
                    Err(error) => return Err(error),
                };
                let t = event.t;
                recorder.record_step(self.model(), t, events.state(), |ts, out| self.interpolate(ts, out));
                recorder.record_event(self.model(), event, events.state());
                after.clone_from(events.state());
                let mut impulse = None;
                let mut switched = false;
                reopened.clear();
                if let Some(contact) = events.contact_of[event.index] {
                    let impacts = events.impact(self.model(), event.index, t, &mut after)?;
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
                        // Left at rest: the contact closes, if it can, and the restart
                        // projects the state onto it (a plastic impact).
                        if !close(self, j, true) {
                            let contacts =
                                events.contacts.as_ref().expect("contact events come with their contacts");
                            return Err(contacts.closes(j, t));
                        }
                        events.contacts.as_mut().expect("contact events come with their contacts").rested(j);
                        reopened.retain(|&c| c != j);
                        switched = true;
                    }
                }
                if let Some(j) = events.release_of[event.index] {
                    switched |= close(self, j, false);
                }
                // A law switches its mode: the state is made consistent in the new one.
                let law = events.switch_law(self.model(), event.index, t, &mut after)?;
                // Consistent already, unless an impact or a contact changed it too.
                let consistent = law && !switched && reopened.is_empty();
                switched |= law;
                let mut context = EventContext::new(t, &mut after, self);
                context.impulse = impulse;
                context.reset = !reopened.is_empty() || switched;
                let flow = action(&event, &mut context);
                let (reset, before) = context.changes();
                let context_touched = context.touched;
                if flow.is_break() {
                    return recorder.finish_from(self);
                }
                if !(reset || before.is_some()) && events.switch_of[event.index] {
                    // A switching surface: the step that reached across it is cut there, and the
                    // integration goes on from the state at the crossing, on the other side.
                    // The interpolated state is the step's, on the constraints as its steps are;
                    // where the integrator's own check refuses it, from the consistent state
                    // nearest to it.
                    restart_at_nearest(self, t, &mut after)?;
                    events.resume(self.model(), t, &after)?;
                    restarted = true;
                    break;
                }
                if reset || before.is_some() {
                    if let (false, Some(before)) = (reset, before) {
                        check_constraints_kept(
                            self.model(),
                            t,
                            &after,
                            before,
                            &mut CheckRoom::new(self.model()),
                        )?;
                    }
                    if consistent && !context_touched {
                        restart_consistent(self, events, &mut recorder, t, &after)?;
                    } else {
                        restart_from(self, events, &mut recorder, t, &after)?;
                    }
                    events.reopen(&reopened);
                    restarted = true;
                    break;
                }
            }
            if !restarted {
                recorder.record_step(self.model(), self.t(), self.state(), |t, out| self.interpolate(t, out));
            }
        }
        recorder.finish_from(self)
    }
}

impl<M: Hybrid, I: Integrator<M>> SolveWithEvents<M> for I where DefaultAllocator: Storage<M> {}

/// A step that failed where the state sits on a switching surface failed because the motion
/// slides along it: `error` named as that, with the surface; any other failure as it is.
fn sliding<M: Hybrid, I: Integrator<M>>(
    integrator: &mut I,
    events: &mut Events<'_, M>,
    error: SimError,
) -> SimError
where
    DefaultAllocator: Storage<M>,
{
    if !matches!(
        error,
        SimError::StepSizeTooSmall { .. } | SimError::NewtonDiverged { .. } | SimError::SingularMatrix { .. }
    ) {
        return error;
    }
    let t = integrator.t();
    match events.sliding_surface(integrator.model(), t, integrator.state()) {
        Ok(Some(k)) => {
            let surface = events.names()[k].clone();
            let condition = integrator.model().surface(&surface).unwrap_or("?").to_string();
            SimError::Sliding { surface, condition, t, cause: error.to_string() }
        }
        _ => error,
    }
}

/// The error for a solve with events that would leave the model's laws unswitched.
fn unwatched_laws<M: Hybrid>(model: &M) -> SimError
where
    DefaultAllocator: Storage<M>,
{
    let names: Vec<String> = laws::law_names(model).iter().map(|n| format!("`{n}`")).collect();
    SimError::InvalidOption {
        what: "events",
        reason: format!(
            "the model's friction laws or diodes ({}) switch their modes at events this solve would not \
             watch, so they would hold one mode throughout: add them with `Events::new().switches()` (or \
             `.declared()`; `switches_in(&model)` or `declared_in(&model)` for a network, whose parts \
             declare them), or solve with `solve`, which watches them",
            names.join(", ")
        ),
    }
}

/// Closes (or opens) contact `j` of the integrator's model, if the model can rest it (a
/// companion made by `with_contacts`) and the integrator holds it exclusively.
fn close<M: Hybrid, I: Integrator<M>>(integrator: &mut I, j: usize, closed: bool) -> bool
where
    DefaultAllocator: Storage<M>,
{
    integrator.model().contact_row(j).is_some()
        && integrator.model_mut().is_some_and(|model| model.set_contact_closed(j, closed))
}

/// Contact `j` comes to rest where the integrator stands (the end of its last step): closed,
/// the state projected onto it, the integration restarted there. An error naming the contact
/// if the model cannot rest it.
fn rest_where_it_stands<M: Hybrid, I: Integrator<M>>(
    integrator: &mut I,
    events: &mut Events<'_, M>,
    recorder: &mut Recorder<M>,
    j: usize,
) -> Result<(), SimError>
where
    DefaultAllocator: Storage<M>,
{
    let t = integrator.t();
    let contacts = events.contacts.as_mut().expect("contacts are watched");
    if !close(integrator, j, true) {
        return Err(contacts.closes(j, contacts.last_impact(j).min(t)));
    }
    contacts.rested(j);
    let state = integrator.state().clone();
    restart_from(integrator, events, recorder, t, &state)
}

/// Restarts the integration at `t` from the consistent state nearest to `state`, watching on
/// from there and recording it.
fn restart_from<M: Hybrid, I: Integrator<M>>(
    integrator: &mut I,
    events: &mut Events<'_, M>,
    recorder: &mut Recorder<M>,
    t: f64,
    state: &State<M>,
) -> Result<(), SimError>
where
    DefaultAllocator: Storage<M>,
{
    let consistent = project(integrator.model(), t, &state.q, &state.v, Consistency::default())?;
    restart_consistent(integrator, events, recorder, t, &consistent)
}

/// Restarts the integration at `t` from `state`, consistent already, watching on from there
/// and recording it.
fn restart_consistent<M: Hybrid, I: Integrator<M>>(
    integrator: &mut I,
    events: &mut Events<'_, M>,
    recorder: &mut Recorder<M>,
    t: f64,
    state: &State<M>,
) -> Result<(), SimError>
where
    DefaultAllocator: Storage<M>,
{
    integrator.restart_at(t, state)?;
    events.resume(integrator.model(), t, state)?;
    recorder.record_reset(integrator.model(), t, state);
    Ok(())
}
