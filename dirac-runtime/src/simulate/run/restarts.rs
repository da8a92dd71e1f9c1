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
///
/// The contacts' modes are settled first, as the complementarity of the contacts at rest on
/// their surfaces asks at acceleration level: a closed contact whose force would pull opens,
/// and an open one that touches without normal speed (`φ_j` and `φ̇_j` at round-off) closes
/// where its acceleration `φ̈_j` would press it in (a foot that a knee's stop would lift
/// stays down where the leg's fall presses it instead). One contact changes at a time, the
/// lowest-numbered of those in the wrong mode, then the state again (Murty's principal
/// pivoting, which settles in finitely many changes where the contacts' response is a
/// P-matrix: independent frictionless contacts). Where the changes come back to modes met
/// before, the run ends in [`SimError::NotDetermined`] naming the contacts that changed: a
/// slipping contact under Coulomb friction can have no consistent mode at all (Painlevé's
/// paradox: closed its force would pull, open it would be pressed in).
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
    // The modes met so far, each with the number of changes made before it.
    let (mut changed, mut met): (Vec<usize>, Vec<(Vec<bool>, usize)>) = (Vec::new(), Vec::new());
    let consistent = loop {
        let model = integrator.model();
        let modes: Vec<bool> = (0..contacts).map(|j| model.contact_closed(j)).collect();
        if let Some(&(_, since)) = met.iter().find(|(m, _)| *m == modes) {
            return Err(SimError::NotDetermined { t, cause: unsettled(model, &changed[since..]) });
        }
        met.push((modes, changed.len()));
        let closed_rows: Vec<(usize, usize)> = (0..contacts)
            .filter(|&j| model.contact_closed(j))
            .filter_map(|j| Some((j, model.contact_row(j)?)))
            .collect();
        let wrong = match consistent_state(model, t, &state.q, &state.v, Consistency::default()) {
            Ok(consistent) => {
                // Pulling beyond the round-off of the forces.
                let scale = AT_ZERO * (1.0 + consistent.lambda.amax());
                let pulling =
                    closed_rows.iter().filter(|&&(_, r)| consistent.lambda[r] < -scale).map(|&(j, _)| j);
                let pressed = pressed_in(model, t, &consistent)?
                    .into_iter()
                    .filter(|&j| model.contact_row(j).is_some());
                match pulling.chain(pressed).min() {
                    Some(j) => j,
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
        let closing = !integrator.model().contact_closed(wrong);
        if !close(integrator, wrong, closing) {
            let contact = integrator.model().unilateral_names()[wrong].clone();
            let cause = format!("the closed contact `{contact}` would pull, and the model cannot open it");
            return Err(SimError::NotDetermined { t, cause });
        }
        if closing && let Some(contacts) = events.contacts.as_mut() {
            contacts.rested(wrong);
        }
        changed.push(wrong);
    };
    restart_consistent(integrator, events, recorder, t, &consistent)
}

/// Why contacts whose modes came back after the changes `cycle` have no consistent mode.
fn unsettled<M: Hybrid>(model: &M, cycle: &[usize]) -> String
where
    DefaultAllocator: Storage<M>,
{
    let names = model.unilateral_names();
    let mut contacts: Vec<&str> = cycle.iter().map(|&j| names[j].as_str()).collect();
    contacts.sort_unstable();
    contacts.dedup();
    match contacts.as_slice() {
        [one] => format!(
            "the contact `{one}` has no consistent mode: closed, its force would pull; open, it would be pressed \
             in. With friction where it slips this is Painlevé's paradox of rigid contact under Coulomb's law (a \
             smaller coefficient of friction, or a compliant contact, has a motion)"
        ),
        many => format!(
            "the contacts `{}` have no consistent modes: each choice of which rest has one that would pull or one \
             pressed in (with friction where they slip, Painlevé's paradox of rigid contact under Coulomb's law)",
            many.join("`, `")
        ),
    }
}

/// The open contacts that touch their surfaces at `state` without normal speed (`φ_j` and
/// `φ̇_j` at round-off) and whose acceleration `φ̈_j` would press them in, beyond its
/// round-off: a contact whose force and acceleration are both about zero stays as it is, so
/// that the two tests cannot flip it back and forth. The rates are
/// differences of `φ` along the motion, `q(t + s) ≈ q + s v + s²/2 v̇` with `v̇` from the
/// equations of motion, measured only where some open contact touches.
fn pressed_in<M: Hybrid>(model: &M, t: f64, state: &State<M>) -> Result<Vec<usize>, SimError>
where
    DefaultAllocator: Storage<M>,
{
    let k = model.unilateral_names().len();
    let size = state.q.iter().fold(1.0f64, |s, x| s.max(x.abs()));
    let speed = state.v.amax();
    let h = TOUCH_STEP * size / (speed + size);
    let gaps = |s: f64, accel: Option<&nalgebra::DVector<f64>>| {
        let mut q = state.q.clone();
        for (i, x) in q.iter_mut().enumerate() {
            *x += s * state.v[i] + accel.map_or(0.0, |a| 0.5 * s * s * a[i]);
        }
        let mut out = vec![0.0; k];
        model.unilateral(t + s, &q, &mut out);
        out
    };
    let now = gaps(0.0, None);
    let (before, after) = (gaps(-h, None), gaps(h, None));
    let touching: Vec<usize> = (0..k)
        .filter(|&j| !model.contact_closed(j))
        .filter(|&j| {
            now[j].abs() <= TOUCHES * size
                && ((after[j] - before[j]) / (2.0 * h)).abs() <= RESTS * (1.0 + speed)
        })
        .collect();
    if touching.is_empty() {
        return Ok(touching);
    }
    let accel = crate::hybrid::impact::accelerations(model, t, &state.q, &state.v)?;
    let (before, after) = (gaps(-h, Some(&accel)), gaps(h, Some(&accel)));
    let pressing = PRESSES * (1.0 + accel.amax());
    Ok(touching
        .into_iter()
        .filter(|&j| (after[j] - 2.0 * now[j] + before[j]) / (h * h) < -pressing)
        .collect())
}

/// The step of the differences that measure an open contact's rates, relative to the size of
/// the positions over that of the positions and velocities.
const TOUCH_STEP: f64 = 1e-4;
/// An open contact whose gap is within this share of the positions' size touches.
const TOUCHES: f64 = 1e-10;
/// A touching contact whose normal speed is within this share of the velocities' size rests.
const RESTS: f64 = 1e-6;
/// A resting open contact whose normal acceleration is below minus this share of the
/// accelerations' size is pressed in.
const PRESSES: f64 = 1e-6;

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
