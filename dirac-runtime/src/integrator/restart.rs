//! What every integrator checks when it starts, when its model is changed between steps and
//! when it restarts, written once: [`Restarts`] keeps the one fact a restart needs from the
//! moment the model was handed out (how far the state then was from the constraints), and
//! its methods run the checks in the order every method needs them.

use nalgebra::DefaultAllocator;

use crate::analysis::diagnose::{
    CheckRoom, check_constraints_kept, check_finite_state, check_inertia, violated_equation,
    violated_legendre_map_in, worst_constraint,
};
use crate::analysis::init::{Consistency, project};
use crate::error::SimError;
use crate::integrator::held::Held;
use crate::model::state::State;
use crate::model::{LagrangeDirac, check_parameters};
use crate::shape::dims::Storage;

/// The restart bookkeeping an integrator keeps beside its model.
pub(crate) struct Restarts<M: LagrangeDirac>
where
    DefaultAllocator: Storage<M>,
{
    /// How far the state was from the constraints when the model was last handed out for a
    /// change ([`Integrator::model_mut`](crate::integrator::Integrator::model_mut)), relative to the size
    /// of their terms; checked against the changed model at the restart.
    changed_from: Option<f64>,
    /// Whether the model's rows may hold other velocities after a restart than at the start
    /// (its laws switch, or it was handed out for a change), so that the velocities only the
    /// forces fix are to be looked for again there.
    pub rows_switch: bool,
    /// Where the checks of a change and a restart evaluate: a restart allocates nothing.
    room: CheckRoom<M>,
}

impl<M: LagrangeDirac> Restarts<M>
where
    DefaultAllocator: Storage<M>,
{
    /// The bookkeeping of an integrator of `model`, with room for its checks.
    pub fn new(model: &M) -> Restarts<M> {
        Restarts { changed_from: None, rows_switch: false, room: CheckRoom::new(model) }
    }

    /// The checks of a start from `state` at `t0` towards `t_end`: a finite span, finite
    /// parameters, a finite state that satisfies the algebraic equations to `tolerance`; then
    /// forgets any change noted before.
    pub fn start(
        &mut self,
        model: &M,
        (t0, t_end): (f64, f64),
        state: &State<M>,
        tolerance: f64,
    ) -> Result<(), SimError> {
        if !t0.is_finite() || !t_end.is_finite() || t_end <= t0 {
            return Err(SimError::InvalidTimeSpan {
                reason: format!("from {t0} to {t_end}: need finite t0 < t_end"),
            });
        }
        check_state(model, t0, state, tolerance)?;
        // Set-up, once a run: a restart allocates nothing, and its model was checked here.
        check_inertia(model, t0, &state.q, &state.v)?;
        self.changed_from = None;
        self.rows_switch = crate::model::hybrid::has_laws(model);
        Ok(())
    }

    /// The model to change, if it is held exclusively, with the state's distance from the
    /// constraints noted for the restart's check.
    pub fn model_mut<'a>(
        &mut self,
        model: &'a mut Held<'_, M>,
        t: f64,
        state: &State<M>,
    ) -> Option<&'a mut M> {
        if model.get_mut().is_some() {
            let worst = worst_constraint(model.get(), t, state, &mut self.room);
            self.changed_from = Some(worst.map_or(0.0, |(_, _, relative)| relative));
            self.rows_switch = true;
        }
        model.get_mut()
    }

    /// The checks of a restart at the state reached after the model may have changed: the
    /// change moved no constraint off the state, the parameters are finite and the momenta
    /// still match the velocities (`p = ∂L/∂v`) to `tolerance`, or to `slack(i, p)` for
    /// momentum `i` of value `p` (the accuracy its integrator solved the map to), since a
    /// restart carries both over.
    pub fn resume(
        &mut self,
        model: &M,
        t: f64,
        state: &State<M>,
        (tolerance, slack): (f64, impl Fn(usize, f64) -> f64),
    ) -> Result<(), SimError> {
        if let Some(before) = self.changed_from.take() {
            check_constraints_kept(model, t, state, before, &mut self.room)?;
        }
        check_parameters(model)?;
        match violated_legendre_map_in(model, t, state, (tolerance, slack), &mut self.room) {
            Some((equation, residual)) => Err(SimError::MomentumChanged { t, equation, residual }),
            None => Ok(()),
        }
    }

    /// The checks of a restart at time `t` within the last step, from `last_step.0` to
    /// `last_step.1`, to a new `state` (an event's reset): the time lies in the step and the
    /// state is finite and consistent to `tolerance`. Forgets any change noted before: the
    /// new state is checked against the model as it is.
    pub fn jump(
        &mut self,
        model: &M,
        t: f64,
        last_step: (f64, f64),
        state: &State<M>,
        tolerance: f64,
    ) -> Result<(), SimError> {
        let (start, end) = last_step;
        // A timed switch's other side may begin a few round-offs past the step's end.
        if !(t >= start && t <= end + 128.0 * f64::EPSILON * end.abs()) {
            return Err(SimError::InvalidTimeSpan {
                reason: format!("a restart at {t} must lie within the last step, from {start} to {end}"),
            });
        }
        check_state(model, t, state, tolerance)?;
        self.changed_from = None;
        Ok(())
    }
}

/// What a start or a restart at `t` checks of the model and the state: finite parameters, a
/// finite state, and one that satisfies the algebraic equations to `tolerance` (relative to
/// the size of the quantities in them).
fn check_state<M: LagrangeDirac>(model: &M, t: f64, state: &State<M>, tolerance: f64) -> Result<(), SimError>
where
    DefaultAllocator: Storage<M>,
{
    check_parameters(model)?;
    check_finite_state(model, t, state)?;
    match violated_equation(model, t, state, tolerance) {
        Some((equation, residual)) => Err(SimError::StateNotConsistent { t, equation, residual }),
        None => Ok(()),
    }
}

/// How far `state` is from the model's constraints, relative to the size of their terms.
pub(crate) fn constraint_violation<M: LagrangeDirac>(model: &M, t: f64, state: &State<M>) -> f64
where
    DefaultAllocator: Storage<M>,
{
    worst_constraint(model, t, state, &mut CheckRoom::new(model)).map_or(0.0, |(_, _, relative)| relative)
}

/// Restarts `integrator` at `t` from `state`, the state interpolated at a crossing within the
/// last step: where the integrator's own check refuses it (off the constraints by more than a
/// restart allows), from the consistent state nearest to it, which `state` becomes.
pub(crate) fn restart_at_nearest<M: LagrangeDirac, I: crate::integrator::Integrator<M>>(
    integrator: &mut I,
    t: f64,
    state: &mut State<M>,
) -> Result<(), SimError>
where
    DefaultAllocator: Storage<M>,
{
    restart_nearest_with(integrator, t, state, |integrator, t, state, _| integrator.restart_at(t, state))
}

/// [`restart_at_nearest`] by `restart(integrator, t, state, projected)`, told whether `state`
/// was projected (what a restart that carries more than the state, sensitivities, adapts).
pub(crate) fn restart_nearest_with<M: LagrangeDirac, I: crate::integrator::Integrator<M>>(
    integrator: &mut I,
    t: f64,
    state: &mut State<M>,
    mut restart: impl FnMut(&mut I, f64, &State<M>, bool) -> Result<(), SimError>,
) -> Result<(), SimError>
where
    DefaultAllocator: Storage<M>,
{
    if restart(integrator, t, state, false).is_ok() {
        return Ok(());
    }
    *state = project(integrator.model(), t, &state.q, &state.v, Consistency::default())?;
    restart(integrator, t, state, true)
}
