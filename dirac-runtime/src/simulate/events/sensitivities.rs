//! Forward sensitivities through impacts: the solve of a model with unilateral constraints
//! that carries each sensitivity across each impact by the impact's saltation matrix
//! ([`saltation`]), the impact's time moving with the parameters and the initial values.

use nalgebra::{DMatrix, DVector, DefaultAllocator};

use super::Events;
use crate::analysis::init::{Consistency, project};
use crate::error::SimError;
use crate::model::blocks::ResidualBlocks;
use crate::model::state::State;
use crate::model::{Hybrid, LagrangeDirac, Parameters};
use crate::shape::dims::Storage;
use crate::simulate::impact::{Saltation, saltation};
use crate::simulate::law_jump::law_jump;
use crate::simulate::laws;
use crate::simulate::recorder::Recorder;
use crate::simulate::restart::restart_nearest_with;
use crate::simulate::sensitive::{Sensitive, SensitivityRows};
use crate::simulate::solution::{Event, Impact, Sampling, Solution};
use crate::simulate::surface::surface_jump;

/// [`Sensitive::solve_with_sensitivities`] of a model with unilateral constraints, switching
/// surfaces or laws: the integration watches the contacts, locates the surfaces and switches
/// the laws as [`Integrator::solve`](crate::Integrator::solve) does. At each law's switch every sensitivity jumps as at a
/// surface, with the rates of the old mode and the new (see the `law_jump` module). At each crossing of a
/// surface every sensitivity's velocities jump by `(v̇⁻ − v̇⁺) ∂t*/∂x s` plus, for a parameter,
/// `(v̇⁻ − v̇⁺) ∂t*/∂θ` (the jump of the rate times the crossing's shift; see the
/// `surface` module), and at each impact every sensitivity `s = ∂(q, v)/∂θ` just
/// before it becomes `S s + c_θ` just after it (`S` the saltation matrix, `c_θ` its column for
/// the parameter `θ`, zero for an initial value), the momenta's part following the Legendre
/// map, `s_p = L_vq s_q + L_vv s_v + ∂(∂L/∂v)/∂θ`. The multipliers' part restarts at zero and is
/// completed, at the impact's sample after it, from the next step, as at the start.
///
/// A contact that comes to rest ends the integration in [`SimError::ContactCloses`], as
/// without sensitivities (resting contacts would switch the model's constraints, whose
/// sensitivities' jump is not carried).
pub fn solve_with_sensitivities_through_events<M: Hybrid + Parameters, I: Sensitive<M>>(
    integrator: &mut I,
    t0: f64,
    state: &State<M>,
    t_end: f64,
    sampling: &Sampling,
) -> Result<Solution<M, I::Stats>, SimError>
where
    DefaultAllocator: Storage<M>,
{
    let count = integrator.sensitivity_names().len();
    let model = integrator.model();
    let names = model.unilateral_names();
    if let Some(j) = (0..names.len()).find(|&j| model.contact_row(j).is_some()) {
        return Err(SimError::InvalidOption {
            what: "sensitivities",
            reason: format!(
                "the contact `{}` can rest (a companion made by `with_contacts`): resting switches the \
                 model's constraints, and that switch's sensitivities are not carried; carry them on the \
                 model itself, whose impacts are",
                names[j]
            ),
        });
    }
    let sizes = integrator.model().sizes();
    let n = sizes.nq;
    let mut recorder = Recorder::new(integrator.model(), sampling, t0, t_end)?;
    let model = integrator.model();
    let events = if names.is_empty() { Events::new() } else { Events::new().contacts(model) };
    let switches = model.has_switches() || laws::has_laws(model);
    let mut events = if switches { events.switches_in(model) } else { events };
    // Each law starts in the mode the state puts it in, as in a solve.
    let chosen = laws::start_in_modes(model, t0, state)?;
    let state = chosen.as_ref().unwrap_or(state);
    if let Some(contacts) = &events.contacts {
        recorder.name_contacts(&contacts.names);
    }
    recorder.name_events(events.names());
    let mut rows = SensitivityRows::new(integrator, &mut recorder)?;
    let mut buffer = State::<M>::with_sizes(sizes);
    integrator.start(t0, state, t_end)?;
    events.begin(integrator.model(), t0, integrator.state())?;
    recorder.record_initial(integrator.model(), t0, integrator.state());
    rows.push_initial(integrator, &recorder);
    let mut restarted = vec![State::<M>::with_sizes(sizes); count];
    while !integrator.finished() {
        events.bound_step(integrator)?;
        integrator.step()?;
        rows.complete(integrator);
        let mut jumped = false;
        while let Some(event) = events.locate(integrator)? {
            let t = event.t;
            let before = recorder.len();
            recorder.record_step(integrator.model(), t, events.state(), |ts, out| {
                integrator.interpolate(ts, out)
            });
            recorder.record_event(integrator.model(), event, events.state());
            rows.push_within(integrator, &recorder, before);
            let crossed = events.cross(integrator.model(), &event, "sensitivities")?;
            for &(j, impulse) in &crossed.impulses {
                recorder.record_impact(Impact { contact: j, t, impulse });
            }
            let Some(mut jump) = crossed.jump else { continue };
            carry(integrator, &jump, t, &mut restarted, &mut buffer, n);
            // From the consistent state nearest to the crossing where the restart refuses it,
            // as a solve does, the sensitivities' momenta following it.
            restart_nearest_with(integrator, t, &mut jump.after, |integrator, t, after, projected| {
                if projected {
                    momenta(integrator, t, after, &mut restarted);
                }
                integrator.restart_with_sensitivities(t, after, &restarted)
            })?;
            let consistent = &jump.after;
            events.resume(integrator.model(), t, consistent)?;
            events.reopen(&jump.reopened);
            if !crossed.impulses.is_empty() || crossed.switched {
                // An impact's state after it is a sample of its own, as a law's switch's is; a
                // switching surface's is the crossing's, just recorded.
                let before = recorder.len();
                recorder.record_reset(integrator.model(), t, consistent);
                rows.push_restart(&restarted, &recorder, before);
            }
            jumped = true;
            break;
        }
        if !jumped {
            let before = recorder.len();
            recorder.record_step(integrator.model(), integrator.t(), integrator.state(), |t, out| {
                integrator.interpolate(t, out)
            });
            rows.push_within(integrator, &recorder, before);
        }
    }
    rows.finish(integrator, recorder)
}

/// An event crossed ([`Events::cross`]): each closing contact's impulse and, if any pushed (or
/// the event is a switching surface's or a law's), the jump.
pub(crate) struct Crossed<M: LagrangeDirac>
where
    DefaultAllocator: Storage<M>,
{
    pub impulses: Vec<(usize, f64)>,
    pub jump: Option<Jump<M>>,
    /// Whether a law switched its mode there.
    pub switched: bool,
}

/// The jump of an impact or a switching surface: its saltation matrix at the state just
/// before it (`2n × 2n` on the positions and velocities) and its parameters' columns (`2n × P`),
/// the state just after it (where the integration restarts: consistent after an impact, the
/// state at the crossing after a switching surface) and the contacts it reopened.
pub(crate) struct Jump<M: LagrangeDirac>
where
    DefaultAllocator: Storage<M>,
{
    pub matrix: DMatrix<f64>,
    pub parameters: DMatrix<f64>,
    pub after: State<M>,
    pub reopened: Vec<usize>,
}

impl<M: Hybrid + Parameters> Events<'_, M>
where
    DefaultAllocator: Storage<M>,
{
    /// The impact at contact event `event`, just located (at [`Events::state`]): its impulses,
    /// and its jump, differentiated, if it pushed. A contact that comes to rest is an error
    /// ([`SimError::ContactCloses`]): resting switches the constraints, whose jump is not
    /// differentiated.
    ///
    /// A law's event switches the law's mode, as a solve does, and its jump is the rate's
    /// ([`law_jump`]); a switching surface's likewise ([`surface_jump`]). `what` names the
    /// computation that crosses (`"sensitivities"`, `"adjoint"`), for its refusals.
    pub(crate) fn cross(
        &mut self,
        model: &M,
        event: &Event,
        what: &'static str,
    ) -> Result<Crossed<M>, SimError> {
        let t = event.t;
        if let (Some(_), Some(declared)) = (self.law_of[event.index], self.declared_of[event.index]) {
            let before = self.state().clone();
            let mut after = before.clone();
            self.switch_law(model, event.index, t, &mut after)?;
            let modes: Vec<usize> = self.laws.iter().map(|law| law.mode).collect();
            let jump = law_jump(model, t, &before, &after, declared, &modes, (self.name(event), what))?;
            let (matrix, parameters) = (jump.matrix, jump.parameters);
            let jump = Jump { matrix, parameters, after, reopened: Vec::new() };
            return Ok(Crossed { impulses: Vec::new(), jump: Some(jump), switched: true });
        }
        if let (true, Some(surface)) = (self.switch_of[event.index], self.declared_of[event.index]) {
            let after = self.state().clone();
            let jump = surface_jump(model, t, &after, surface, (self.name(event), what))?;
            let (matrix, parameters) = (jump.matrix, jump.parameters);
            let jump = Jump { matrix, parameters, after, reopened: Vec::new() };
            return Ok(Crossed { impulses: Vec::new(), jump: Some(jump), switched: false });
        }
        let contact = self.contact_of[event.index].ok_or_else(|| SimError::InvalidOption {
            what,
            reason: format!(
                "the event `{}` is neither an impact nor a switching surface: its jump is not \
                 differentiated",
                self.name(event)
            ),
        })?;
        let pre = self.state().clone();
        let mut after = pre.clone();
        let impacts = self.impact(model, event.index, t, &mut after)?;
        if let Some(j) = impacts.resting {
            let contacts = self.contacts.as_ref().expect("contacts are watched");
            return Err(contacts.closes(j, t));
        }
        let reopened: Vec<usize> =
            impacts.impulses.iter().filter(|&&(_, impulse)| impulse > 0.0).map(|&(j, _)| j).collect();
        if reopened.is_empty() {
            return Ok(Crossed { impulses: impacts.impulses, jump: None, switched: false });
        }
        let closing: Vec<usize> = impacts.impulses.iter().map(|&(j, _)| j).collect();
        let Saltation { matrix, parameters, .. } = saltation(model, t, &pre.q, &pre.v, contact, &closing)?;
        let after = project(model, t, &after.q, &after.v, Consistency::default())?;
        let jump = Jump { matrix, parameters, after, reopened };
        Ok(Crossed { impulses: impacts.impulses, jump: Some(jump), switched: false })
    }
}

/// Each sensitivity just before the jump at `t`, carried across it, into `out`: positions and
/// velocities by its saltation matrix (and a parameter's column), momenta by the Legendre map
/// at the state after it ([`momenta`]), multipliers zero.
fn carry<M: Hybrid + Parameters, I: Sensitive<M>>(
    integrator: &I,
    jump: &Jump<M>,
    t: f64,
    out: &mut [State<M>],
    buffer: &mut State<M>,
    n: usize,
) where
    DefaultAllocator: Storage<M>,
{
    let mut x = DVector::<f64>::zeros(2 * n);
    for (j, s) in out.iter_mut().enumerate() {
        integrator.interpolate_sensitivity(j, t, buffer);
        x.rows_mut(0, n).copy_from_slice(buffer.q.as_slice());
        x.rows_mut(n, n).copy_from_slice(buffer.v.as_slice());
        let mut y = &jump.matrix * &x;
        if let Some(k) = integrator.sensitivity_parameter(j) {
            y += jump.parameters.column(k);
        }
        s.q.copy_from_slice(y.rows(0, n).as_slice());
        s.v.copy_from_slice(y.rows(n, n).as_slice());
        s.lambda.fill(0.0);
    }
    momenta(integrator, t, &jump.after, out);
}

/// The momenta's part of each sensitivity in `out`, from its positions' and velocities' by the
/// Legendre map at the state `after`: `s_p = L_vq s_q + L_vv s_v + ∂(∂L/∂v)/∂θ`.
fn momenta<M: Hybrid + Parameters, I: Sensitive<M>>(
    integrator: &I,
    t: f64,
    after: &State<M>,
    out: &mut [State<M>],
) where
    DefaultAllocator: Storage<M>,
{
    let model = integrator.model();
    let sizes = model.sizes();
    let shape = model.shape();
    let mut l_vq = <M::Algebra as crate::algebra::Algebra<M>>::zeros_qq(&shape);
    let mut l_vv = <M::Algebra as crate::algebra::Algebra<M>>::zeros_qq(&shape);
    model.l_vq(t, &after.q, &after.v, &mut l_vq);
    model.l_vv(t, &after.q, &after.v, &mut l_vv);
    let mut blocks = ResidualBlocks::<M>::with_sizes(&sizes);
    for (j, s) in out.iter_mut().enumerate() {
        s.p.fill(0.0);
        if let Some(k) = integrator.sensitivity_parameter(j) {
            model.residual_blocks_dtheta(k, t, &after.q, &after.v, &after.lambda, &mut blocks);
            s.p.copy_from(&blocks.dl_dv);
        }
        <M::Algebra as crate::algebra::Algebra<M>>::qq_mul(&l_vq, 1.0, s.q.as_slice(), s.p.as_mut_slice());
        <M::Algebra as crate::algebra::Algebra<M>>::qq_mul(&l_vv, 1.0, s.v.as_slice(), s.p.as_mut_slice());
    }
}
