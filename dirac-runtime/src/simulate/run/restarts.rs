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
/// recording it. A closed contact whose force would pull there opens (the most pulling first,
/// then the state again), as a contact that has just come to rest does where the motion
/// lifts it at once (a box's corner landing while it tips away from it).
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
    let contacts = integrator.model().unilateral_names().len();
    let consistent = loop {
        let model = integrator.model();
        let closed_rows: Vec<(usize, usize)> = (0..contacts)
            .filter(|&j| model.contact_closed(j))
            .filter_map(|j| Some((j, model.contact_row(j)?)))
            .collect();
        let pulling = match consistent_state(model, t, &state.q, &state.v, Consistency::default()) {
            Ok(consistent) => {
                // Pulling beyond the round-off of the forces.
                let scale = AT_ZERO * (1.0 + consistent.lambda.amax());
                let most = closed_rows
                    .iter()
                    .map(|&(j, r)| (j, consistent.lambda[r]))
                    .filter(|&(_, force)| force < -scale)
                    .min_by(|a, b| a.1.total_cmp(&b.1));
                match most {
                    Some((j, _)) => j,
                    None => break consistent,
                }
            }
            // Friction driven by a closed contact's force puts power in: the force pulls.
            Err(SimError::FrictionPushes { row, t, power }) => {
                let names = model.constraint_names();
                match closed_rows.iter().find(|&&(_, r)| names[r] == row) {
                    Some(&(j, _)) => j,
                    None => return Err(SimError::FrictionPushes { row, t, power }),
                }
            }
            Err(error) => return Err(error),
        };
        if !close(integrator, pulling, false) {
            let contact = integrator.model().unilateral_names()[pulling].clone();
            let cause = format!("the closed contact `{contact}` would pull, and the model cannot open it");
            return Err(SimError::NotDetermined { t, cause });
        }
    };
    restart_consistent(integrator, events, recorder, t, &consistent)
}

/// The share of the largest force within which a contact force counts as zero.
const AT_ZERO: f64 = 1e-9;

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
