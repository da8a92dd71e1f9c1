//! What crossing an event does beyond the events themselves: the context an action sees, a
//! contact brought to rest, a restart from a consistent state where an action reset the state
//! or changed the model, and the errors naming what slid or went unwatched.

use nalgebra::DefaultAllocator;

use super::Events;
use crate::analysis::init::{Consistency, project};
use crate::error::SimError;
use crate::model::state::State;
use crate::model::{Hybrid, LagrangeDirac};
use crate::shape::dims::Storage;
use crate::simulate::integrator::Integrator;
use crate::simulate::laws;
use crate::simulate::recorder::Recorder;
use crate::simulate::restart::constraint_violation;

/// What an event's action may do: read the event's time and state, reset the state, change
/// the model (if the integrator holds it exclusively).
pub struct EventContext<'a, M: LagrangeDirac, I>
where
    DefaultAllocator: Storage<M>,
{
    t: f64,
    state: &'a mut State<M>,
    integrator: &'a mut I,
    pub(crate) reset: bool,
    /// How far the state was from the constraints before the model was first handed out.
    before: Option<f64>,
    /// The impulse of the event's contact, when the event is an impact.
    pub(crate) impulse: Option<f64>,
    /// Whether the action asked for the state or the model to change.
    pub(crate) touched: bool,
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

/// A step that failed where the state sits on a switching surface failed because the motion
/// slides along it: `error` named as that, with the surface; any other failure as it is.
pub(crate) fn sliding<M: Hybrid, I: Integrator<M>>(
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
pub(crate) fn unwatched_laws<M: Hybrid>(model: &M) -> SimError
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
pub(crate) fn close<M: Hybrid, I: Integrator<M>>(integrator: &mut I, j: usize, closed: bool) -> bool
where
    DefaultAllocator: Storage<M>,
{
    integrator.model().contact_row(j).is_some()
        && integrator.model_mut().is_some_and(|model| model.set_contact_closed(j, closed))
}

/// Contact `j` comes to rest where the integrator stands (the end of its last step): closed,
/// the state projected onto it, the integration restarted there. An error naming the contact
/// if the model cannot rest it.
pub(crate) fn rest_where_it_stands<M: Hybrid, I: Integrator<M>>(
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
pub(crate) fn restart_from<M: Hybrid, I: Integrator<M>>(
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
pub(crate) fn restart_consistent<M: Hybrid, I: Integrator<M>>(
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
