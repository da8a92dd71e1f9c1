//! The flat residual of a model evaluated without allocating, for Radau's stages.

use nalgebra::DefaultAllocator;

use crate::blocks::ResidualBlocks;
use crate::dims::{Sizes, Storage, VecY};
use crate::flat::residual;
use crate::model::LagrangeDirac;
use crate::state::State;

/// Evaluates a model's flat residual `f(t, y)` without allocating: through the model's own
/// [`LagrangeDirac::residual`](crate::LagrangeDirac::residual) when its sizes are fixed (its
/// temporaries are on the stack), else through its residual blocks into storage kept here.
pub(crate) struct Residual<M: LagrangeDirac>
where
    DefaultAllocator: Storage<M>,
{
    /// `None` for a model of fixed size.
    scratch: Option<(State<M>, ResidualBlocks<M>)>,
}

impl<M: LagrangeDirac> Residual<M>
where
    DefaultAllocator: Storage<M>,
{
    /// The evaluator for a model of these sizes.
    pub fn new(sizes: &Sizes) -> Self {
        use nalgebra::Dim;
        let fixed = M::Nq::try_to_usize().is_some() && M::Nc::try_to_usize().is_some();
        let scratch = (!fixed).then(|| (State::with_sizes(*sizes), ResidualBlocks::with_sizes(sizes)));
        Residual { scratch }
    }

    /// Writes `f(t, y)` into `out`.
    pub fn eval(&mut self, model: &M, t: f64, y: &VecY<M>, out: &mut VecY<M>) {
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
