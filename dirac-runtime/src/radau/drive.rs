//! Inputs set from time and state inside the steps: Radau calls a drive before every
//! evaluation of the model, and with feedback adds the inputs' part of the Jacobian, by
//! finite differences through the inputs alone.

use nalgebra::DefaultAllocator;

use super::Radau;
use super::residual::{Drive, Residual};
use crate::algebra::Algebra;
use crate::blocks::{JacobianBlocks, ResidualBlocks};
use crate::dims::{Sizes, Storage, VecY};
use crate::error::SimError;
use crate::held::Held;
use crate::layout::Layout;
use crate::model::LagrangeDirac;
use crate::newton::NewtonSolver;
use crate::state::State;

/// The storage of the inputs' Jacobian columns: `ṗ` at the current inputs and at the inputs of
/// a perturbed state, and that state.
pub(crate) struct Feedback<M: LagrangeDirac>
where
    DefaultAllocator: Storage<M>,
{
    base: ResidualBlocks<M>,
    moved: ResidualBlocks<M>,
    perturbed: VecY<M>,
    state: State<M>,
    sizes: Sizes,
}

impl<M: LagrangeDirac> Feedback<M>
where
    DefaultAllocator: Storage<M>,
{
    fn new(sizes: Sizes) -> Self {
        Feedback {
            base: ResidualBlocks::with_sizes(&sizes),
            moved: ResidualBlocks::with_sizes(&sizes),
            perturbed: sizes.zeros_y::<M>(),
            state: State::with_sizes(sizes),
            sizes,
        }
    }

    /// Adds `∂ṗ/∂u · ∂u/∂(q, v)` to `∂ṗ/∂q` and `∂ṗ/∂v`: column by column, the change of `ṗ`
    /// at the state `y` when the inputs are those of `y` moved in one position or velocity.
    /// The inputs are left as the drive sets them at `y`.
    pub fn add_columns(
        &mut self,
        model: &mut Held<'_, M>,
        residual: &mut Residual<'_, M>,
        t: f64,
        y: &VecY<M>,
        jac: &mut JacobianBlocks<M, M::Algebra>,
    ) {
        let n = self.sizes.nq;
        let Layout { q: q0, v: v0, .. } = Layout::new(self.sizes);
        self.state.read_y(y);
        let s = &self.state;
        residual.apply(model, t, y);
        model.residual_blocks(t, &s.q, &s.v, &s.lambda, &mut self.base);
        for column in 0..2 * n {
            let slot = if column < n { q0 + column } else { v0 + column - n };
            let delta = f64::EPSILON.sqrt() * y[slot].abs().max(1.0);
            self.perturbed.copy_from(y);
            self.perturbed[slot] += delta;
            residual.apply(model, t, &self.perturbed);
            model.residual_blocks(t, &s.q, &s.v, &s.lambda, &mut self.moved);
            let block = if column < n { &mut jac.dpdot_dq } else { &mut jac.dpdot_dv };
            // Dense blocks, column-major (checked when the drive was set).
            let values = M::Algebra::qq_values_mut(block);
            let j = column % n;
            for i in 0..n {
                values[j * n + i] += (self.moved.momentum_rate[i] - self.base.momentum_rate[i]) / delta;
            }
        }
        residual.apply(model, t, y);
    }
}

impl<'m, M: LagrangeDirac, S: NewtonSolver<M, M::Algebra>> Radau<'m, M, S>
where
    DefaultAllocator: Storage<M>,
{
    /// Sets the model's inputs from time (and state) before every evaluation of the model, from
    /// now on: a source such as `u0 sin(ω t)` or a table read with linear interpolation. The
    /// Jacobian is that of the model at the inputs of the moment; a drive that feeds the state
    /// back should be set with [`Radau::drive_feedback`]. Needs an integrator built on
    /// `&mut model`; set it before `start`. The drive is borrowed for as long as the
    /// integrator lives: keep it in a variable (`let mut source = |t, _, m| …;`).
    pub fn drive(&mut self, drive: &'m mut dyn FnMut(f64, &State<M>, &mut M)) -> Result<(), SimError> {
        self.set_drive(drive, false)
    }

    /// Like [`Radau::drive`], for a drive that reads the state (continuous feedback,
    /// `u = κ(t, q, v)`): the Newton matrix also gets `∂ṗ/∂u · ∂κ/∂(q, v)`, by finite
    /// differences through the inputs alone (2n evaluations of the residual blocks at each
    /// Jacobian), so strong feedback converges as the closed loop does. Dense models only.
    pub fn drive_feedback(
        &mut self,
        drive: &'m mut dyn FnMut(f64, &State<M>, &mut M),
    ) -> Result<(), SimError> {
        if M::Algebra::dense_qq(&self.jac.dpdot_dq).is_none() {
            return Err(SimError::InvalidOption {
                what: "drive_feedback",
                reason: "its finite-difference Jacobian needs a model with dense blocks (of fixed size)"
                    .into(),
            });
        }
        self.set_drive(drive, true)
    }

    fn set_drive(&mut self, drive: Drive<'m, M>, feedback: bool) -> Result<(), SimError> {
        if self.model.get_mut().is_none() {
            return Err(SimError::SharedModel { t: self.t });
        }
        let sizes = self.model.sizes();
        self.residual.set_drive(drive, sizes);
        self.feedback = feedback.then(|| Box::new(Feedback::new(sizes)));
        self.need_jac = true;
        Ok(())
    }
}
