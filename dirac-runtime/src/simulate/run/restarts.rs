//! What the run does where a contact comes to rest or an action reset the state or changed
//! the model: the contact closed, the integration restarted from a consistent state, watched
//! and recorded from there.

use nalgebra::DefaultAllocator;

use crate::analysis::init::{Consistency, project};
use crate::error::SimError;
use crate::hybrid::events::Events;
use crate::hybrid::laws::consistent_state;
use crate::integrator::Integrator;
use crate::model::Hybrid;
use crate::model::state::State;
use crate::output::recorder::Recorder;
use crate::shape::dims::Storage;

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
    restart_in_modes(integrator, events, recorder, t, &state)
}

/// Restarts the integration at `t` after a contact closed or opened: from the consistent state
/// nearest to `state` with each law's mode chosen there again (a cone at a contact that has
/// just closed sticks or slips as the contact's slip says), watching on from there and
/// recording it.
pub(crate) fn restart_in_modes<M: Hybrid, I: Integrator<M>>(
    integrator: &mut I,
    events: &mut Events<'_, M>,
    recorder: &mut Recorder<M>,
    t: f64,
    state: &State<M>,
) -> Result<(), SimError>
where
    DefaultAllocator: Storage<M>,
{
    let consistent = consistent_state(integrator.model(), t, &state.q, &state.v, Consistency::default())?;
    restart_consistent(integrator, events, recorder, t, &consistent)
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
