//! The context an event's action sees, and the errors naming what slid or went unwatched.

use nalgebra::DefaultAllocator;

use super::Events;
use crate::error::SimError;
use crate::hybrid::laws;
use crate::integrator::Integrator;
use crate::integrator::restart::constraint_violation;
use crate::model::state::State;
use crate::model::{Hybrid, LagrangeDirac};
use crate::shape::dims::Storage;

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
