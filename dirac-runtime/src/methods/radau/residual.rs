//! The flat residual of a model evaluated without allocating, for Radau's stages, with the
//! model's inputs set first when a drive sets them from time and state.

use nalgebra::DefaultAllocator;

pub(crate) use crate::integrator::drive::DriveFn;
use crate::integrator::drive::Stops;
use crate::integrator::held::Held;
use crate::model::LagrangeDirac;
use crate::model::blocks::ResidualBlocks;
use crate::model::flat::residual;
use crate::model::state::State;
use crate::shape::dims::{Sizes, Storage, VecY};

/// Evaluates a model's flat residual `f(t, y)` without allocating: through the model's own
/// [`LagrangeDirac::residual`](crate::model::LagrangeDirac::residual) when its sizes are fixed (its
/// temporaries are on the stack), else through its residual blocks into storage kept here.
pub(crate) struct Residual<'m, M: LagrangeDirac>
where
    DefaultAllocator: Storage<M>,
{
    /// `None` for a model of fixed size.
    scratch: Option<(State<M>, ResidualBlocks<M>)>,
    /// The drive of the inputs and the state it reads, when there is one.
    drive: Option<(DriveFn<'m, M>, State<M>)>,
    /// The times where the inputs jump or bend, and the end of the stretch between them that
    /// the integration is in: inputs at its end are read from the left.
    pub stops: Stops,
    pub stretch_end: f64,
}

impl<'m, M: LagrangeDirac> Residual<'m, M>
where
    DefaultAllocator: Storage<M>,
{
    /// The evaluator for a model of these sizes.
    pub fn new(sizes: &Sizes) -> Self {
        use nalgebra::Dim;
        let fixed = M::Nq::try_to_usize().is_some() && M::Nc::try_to_usize().is_some();
        let scratch = (!fixed).then(|| (State::with_sizes(*sizes), ResidualBlocks::with_sizes(sizes)));
        Residual { scratch, drive: None, stops: Stops::default(), stretch_end: f64::INFINITY }
    }

    /// Sets the inputs before every evaluation from now on.
    pub fn set_drive(&mut self, drive: DriveFn<'m, M>, sizes: Sizes) {
        self.drive = Some((drive, State::with_sizes(sizes)));
    }

    /// Whether a drive sets the model's inputs.
    pub fn driven(&self) -> bool {
        self.drive.is_some()
    }

    /// Sets the model's inputs for time `t` and state `y`, if a drive does.
    #[inline]
    pub fn apply(&mut self, model: &mut Held<'_, M>, t: f64, y: &VecY<M>) {
        if let Some((drive, state)) = &mut self.drive
            && let Some(model) = model.get_mut()
        {
            state.read_y(y);
            drive(self.stops.read_at(t, self.stretch_end), state, model);
        }
    }

    /// Sets the model's inputs for time `t` and `state`, if a drive does.
    pub fn apply_state(&mut self, model: &mut Held<'_, M>, t: f64, state: &State<M>) {
        if let Some((drive, _)) = &mut self.drive
            && let Some(model) = model.get_mut()
        {
            drive(self.stops.read_at(t, self.stretch_end), state, model);
        }
    }

    /// The time the model is read at for an evaluation at `t`: `t`, or just before the end of
    /// the stretch at its end (where a timed switch or an input's jump lies).
    #[inline]
    pub fn model_time(&self, t: f64) -> f64 {
        self.stops.read_at(t, self.stretch_end)
    }

    /// Writes `f(t, y)` into `out`, the inputs set first.
    #[inline]
    pub fn eval(&mut self, model: &mut Held<'_, M>, t: f64, y: &VecY<M>, out: &mut VecY<M>) {
        // At a stretch's end the model is read from the left, as its inputs are.
        let t = self.model_time(t);
        self.apply(model, t, y);
        let model = model.get();
        match &mut self.scratch {
            None => model.residual(t, y, out),
            Some((state, blocks)) => {
                state.read_y(y);
                model.residual_blocks(t, &state.q, &state.v, &state.lambda, blocks);
                residual(state, blocks, out);
            }
        }
    }
}
