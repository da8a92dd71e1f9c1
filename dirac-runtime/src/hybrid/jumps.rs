//! The jumps of impacts, law switches and switching surfaces with their derivatives
//! ([`Events::cross`]), and forward sensitivities carried across them: at each law's switch
//! every sensitivity jumps as at a surface, with the rates of the old mode and the new (see the
//! `law_jump` module). At each crossing of a surface every sensitivity's velocities jump by
//! `(v̇⁻ − v̇⁺) ∂t*/∂x s` plus, for a parameter, `(v̇⁻ − v̇⁺) ∂t*/∂θ` (the jump of the rate times
//! the crossing's shift; see the `surface` module), and at each impact every sensitivity
//! `s = ∂(q, v)/∂θ` just before it becomes `S s + c_θ` just after it (`S` the saltation matrix
//! ([`saltation`]), `c_θ` its column for the parameter `θ`, zero for an initial value), the
//! momenta's part following the Legendre map, `s_p = L_vq s_q + L_vv s_v + ∂(∂L/∂v)/∂θ`. The
//! multipliers' part restarts at zero and is completed, at the impact's sample after it, from
//! the next step, as at the start. A contact that comes to rest ends such a run in
//! [`SimError::ContactCloses`] (resting would switch the model's constraints, whose
//! sensitivities' jump is not carried).

use nalgebra::{DMatrix, DefaultAllocator};

use crate::analysis::init::{Consistency, project};
use crate::error::SimError;
use crate::hybrid::event::Event;
use crate::hybrid::events::Events;
use crate::hybrid::impact::{Saltation, saltation};
use crate::hybrid::law_jump::law_jump;
use crate::hybrid::surface::surface_jump;
use crate::model::state::State;
use crate::model::{Hybrid, LagrangeDirac, Parameters};
use crate::shape::dims::Storage;

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
            let modes: Vec<usize> = self
                .laws
                .iter()
                .flat_map(|law| std::iter::once(law.mode).chain(law.cone.map(|c| c.0)))
                .collect();
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
