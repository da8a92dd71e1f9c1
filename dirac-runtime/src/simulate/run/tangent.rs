//! What a run carries beside the state and through its jumps: forward sensitivities, or an
//! adjoint's tape ([`Tangent`]).

use nalgebra::DefaultAllocator;

use crate::error::SimError;
use crate::hybrid::event::Event;
use crate::hybrid::events::Events;
use crate::hybrid::jumps::{Crossed, Jump};
use crate::model::LagrangeDirac;
use crate::model::state::State;
use crate::output::recorder::Recorder;
use crate::shape::dims::Storage;

/// What a run carries beside the state and differentiates through its jumps: the forward
/// sensitivities of a run that asked for them, or the steps an adjoint's sweep goes back over.
/// Its crossings are the differentiated ones ([`Events::cross`]): impacts, law switches and
/// switching surfaces, each with its saltation; a run that carries one has no action, no
/// controller and no drive (refused when it compiles, [`Run::sensitivities`](super::Run::sensitivities)).
pub(crate) trait Tangent<M: LagrangeDirac, I>
where
    DefaultAllocator: Storage<M>,
{
    /// Crosses `event`, a contact's, a law's or a switching surface's, with its derivative
    /// ([`Events::cross`], which names what crosses in its refusals).
    fn cross(&mut self, model: &M, events: &mut Events<'_, M>, event: &Event)
    -> Result<Crossed<M>, SimError>;
    /// The run started from `from` at the integrator's time, its start recorded.
    fn started(&mut self, integrator: &I, recorder: &Recorder<M>, from: &State<M>) -> Result<(), SimError>;
    /// Before the run begins: what the integrator must do for it (a recording within a budget
    /// solves its stages to round-off).
    fn prepare(&mut self, integrator: &mut I) {
        let _ = integrator;
    }
    /// After the run, however it ended: the integrator as it was before [`Tangent::prepare`].
    fn restore(&mut self, integrator: &mut I) {
        let _ = integrator;
    }
    /// A step is about to be taken.
    fn before_step(&mut self, integrator: &I) {
        let _ = integrator;
    }
    /// A step of size `h` was taken.
    fn after_step(&mut self, integrator: &I, h: f64);
    /// The samples from `before` on were recorded within the last step.
    fn sampled(&mut self, integrator: &I, recorder: &Recorder<M>, before: usize);
    /// Carries what it holds across `jump` at `t` and restarts the integration there from the
    /// state after it, the consistent one nearest where the restart refuses it; returns that
    /// state.
    fn jump(&mut self, integrator: &mut I, t: f64, jump: Jump<M>) -> Result<State<M>, SimError>;
    /// The samples from `before` on were recorded where the integration restarted after a jump.
    fn restarted(&mut self, recorder: &Recorder<M>, before: usize);
}

/// A carried tangent, borrowed for the run's loop.
pub(crate) type TangentRef<'h, M, I> = &'h mut dyn Tangent<M, I>;
