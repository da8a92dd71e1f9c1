//! Inputs set from time and state inside the steps: Radau calls a drive before every
//! evaluation of the model, and with feedback adds the inputs' part of the Jacobian, from the
//! user's `∂u/∂(q, v)` and the generated `∂ṗ/∂u`, or by finite differences through the inputs
//! alone.

use nalgebra::DefaultAllocator;

use super::Radau;
use super::residual::{DriveFn, Residual};
use crate::algebra::Algebra;
use crate::algebra::newton::NewtonSolver;
use crate::error::SimError;
use crate::integrator::Drive;
use crate::integrator::held::Held;
use crate::model::blocks::{JacobianBlocks, ResidualBlocks};
use crate::model::state::State;
use crate::model::{InputsOutputs, LagrangeDirac};
use crate::shape::dims::{Sizes, Storage, VecC, VecQ, VecY};
use crate::shape::layout::Layout;

/// The feedback's `∂u/∂(q, v)`, written by the user as `n_u × 2n` values, column-major (the
/// columns of `q`, then those of `v`).
pub(crate) type FeedbackJacobian<'m, M> = &'m mut dyn FnMut(f64, &State<M>, &mut [f64]);

/// The model's `∂ṗ/∂u` ([`InputsOutputs::dpdot_du`]), kept when the feedback was set under
/// that bound.
type DpdotDu<M> = fn(&M, f64, &VecQ<M>, &VecQ<M>, &VecC<M>, &mut [f64]);

/// What a feedback with an exact Jacobian is set with: the user's `∂u/∂(q, v)`, the model's
/// `∂ṗ/∂u` and the number of inputs.
type ExactParts<'m, M> = (FeedbackJacobian<'m, M>, DpdotDu<M>, usize);

/// The user's `∂u/∂(q, v)` with the model's `∂ṗ/∂u`, and their storage.
struct Exact<'m, M: LagrangeDirac>
where
    DefaultAllocator: Storage<M>,
{
    jacobian: FeedbackJacobian<'m, M>,
    dpdot_du: DpdotDu<M>,
    du: Vec<f64>,
    gains: Vec<f64>,
}

/// The storage of the inputs' Jacobian columns: `ṗ` at the current inputs and at the inputs of
/// a perturbed state, and that state; with the user's `∂u/∂(q, v)`, it and `∂ṗ/∂u`.
pub(crate) struct Feedback<'m, M: LagrangeDirac>
where
    DefaultAllocator: Storage<M>,
{
    base: ResidualBlocks<M>,
    moved: ResidualBlocks<M>,
    perturbed: VecY<M>,
    state: State<M>,
    sizes: Sizes,
    exact: Option<Exact<'m, M>>,
}

impl<'m, M: LagrangeDirac> Feedback<'m, M>
where
    DefaultAllocator: Storage<M>,
{
    fn new(sizes: Sizes, exact: Option<ExactParts<'m, M>>) -> Self {
        let n = sizes.nq;
        Feedback {
            base: ResidualBlocks::with_sizes(&sizes),
            moved: ResidualBlocks::with_sizes(&sizes),
            perturbed: sizes.zeros_y::<M>(),
            state: State::with_sizes(sizes),
            sizes,
            exact: exact.map(|(jacobian, dpdot_du, nu)| Exact {
                jacobian,
                dpdot_du,
                du: vec![0.0; n * nu],
                gains: vec![0.0; nu * 2 * n],
            }),
        }
    }

    /// Zeroes `∂ṗ/∂q` and `∂ṗ/∂v` before the model writes them: the generated blocks set only
    /// their structural nonzeros, and [`Feedback::add_columns`] adds into the others too, which
    /// would otherwise keep the last evaluation's feedback and add it again at every new one.
    pub fn clear_columns(jac: &mut JacobianBlocks<M, M::Algebra>) {
        M::Algebra::qq_values_mut(&mut jac.dpdot_dq).fill(0.0);
        M::Algebra::qq_values_mut(&mut jac.dpdot_dv).fill(0.0);
    }

    /// Adds `∂ṗ/∂u · ∂u/∂(q, v)` to `∂ṗ/∂q` and `∂ṗ/∂v`, column by column: from the user's
    /// `∂u/∂(q, v)` and the generated `∂ṗ/∂u`, or as the change of `ṗ` at the state `y` when
    /// the inputs are those of `y` moved in one position or velocity. Expects the inputs set at
    /// `y`, and leaves them so.
    pub fn add_columns(
        &mut self,
        model: &mut Held<'_, M>,
        residual: &mut Residual<'_, M>,
        t: f64,
        y: &VecY<M>,
        jac: &mut JacobianBlocks<M, M::Algebra>,
    ) -> Result<(), SimError> {
        let n = self.sizes.nq;
        self.state.read_y(y);
        let s = &self.state;
        // Column `column` of `[∂ṗ/∂q ∂ṗ/∂v]` gets `entry(i)` added to row `i`; the blocks are
        // dense, column-major (checked when the drive was set).
        let mut add = |column: usize, entry: &dyn Fn(usize) -> f64| {
            let block = if column < n { &mut jac.dpdot_dq } else { &mut jac.dpdot_dv };
            let values = M::Algebra::qq_values_mut(block);
            let j = column % n;
            for i in 0..n {
                values[j * n + i] += entry(i);
            }
        };
        if let Some(Exact { jacobian, dpdot_du, du, gains }) = &mut self.exact {
            // ∂ṗ/∂u (n × n_u) times the user's ∂u/∂(q, v) (n_u × 2n), both column-major.
            dpdot_du(model.get(), t, &s.q, &s.v, &s.lambda, du);
            jacobian(t, s, gains);
            if gains.iter().any(|g| !g.is_finite()) {
                return Err(SimError::NonFinite {
                    t,
                    component: "the feedback Jacobian ∂u/∂(q, v) given to drive_feedback_with".into(),
                });
            }
            let nu = du.len() / n.max(1);
            for column in 0..2 * n {
                add(column, &|i| (0..nu).map(|k| du[k * n + i] * gains[column * nu + k]).sum());
            }
            return Ok(());
        }
        let Layout { q: q0, v: v0, .. } = Layout::new(self.sizes);
        model.residual_blocks(t, &s.q, &s.v, &s.lambda, &mut self.base);
        for column in 0..2 * n {
            let slot = if column < n { q0 + column } else { v0 + column - n };
            let delta = f64::EPSILON.sqrt() * y[slot].abs().max(1.0);
            self.perturbed.copy_from(y);
            self.perturbed[slot] += delta;
            residual.apply(model, t, &self.perturbed);
            model.residual_blocks(t, &s.q, &s.v, &s.lambda, &mut self.moved);
            let (moved, base) = (&self.moved.momentum_rate, &self.base.momentum_rate);
            add(column, &|i| (moved[i] - base[i]) / delta);
        }
        residual.apply(model, t, y);
        Ok(())
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
        self.set_drive(drive, None)
    }

    /// Like [`Radau::drive`], for a drive that reads the state (continuous feedback,
    /// `u = κ(t, q, v)`): the Newton matrix also gets `∂ṗ/∂u · ∂κ/∂(q, v)`, by finite
    /// differences through the inputs alone (2n evaluations of the residual blocks at each
    /// Jacobian), so strong feedback converges as the closed loop does. Dense models only.
    pub fn drive_feedback(
        &mut self,
        drive: &'m mut dyn FnMut(f64, &State<M>, &mut M),
    ) -> Result<(), SimError> {
        self.check_dense()?;
        self.set_drive(drive, Some(None))
    }

    /// Like [`Radau::drive_feedback`], with the feedback's Jacobian `∂u/∂(q, v)` from the
    /// user: `jacobian(t, state, out)` writes it as `n_u × 2n` values, column by column (the
    /// columns of the positions, then those of the velocities). The Newton matrix then gets
    /// `∂ṗ/∂u · ∂u/∂(q, v)` exactly, `∂ṗ/∂u` from the generated derivatives, at the cost of
    /// one evaluation of each per Jacobian. Dense models only.
    pub fn drive_feedback_with(
        &mut self,
        drive: &'m mut dyn FnMut(f64, &State<M>, &mut M),
        jacobian: FeedbackJacobian<'m, M>,
    ) -> Result<(), SimError>
    where
        M: InputsOutputs,
    {
        self.check_dense()?;
        let nu = self.model.input_names().len();
        self.set_drive(drive, Some(Some((jacobian, M::dpdot_du, nu))))
    }

    fn check_dense(&self) -> Result<(), SimError> {
        if M::Algebra::dense_qq(&self.jac.dpdot_dq).is_none() {
            return Err(SimError::InvalidOption {
                what: "drive_feedback",
                reason: "its Jacobian needs a model with dense blocks (of fixed size)".into(),
            });
        }
        Ok(())
    }

    /// Sets the drive; `feedback` is `None` for a drive without a Jacobian part, `Some(None)`
    /// for finite differences, `Some(Some(..))` for the user's `∂u/∂(q, v)`.
    fn set_drive(
        &mut self,
        drive: DriveFn<'m, M>,
        feedback: Option<Option<ExactParts<'m, M>>>,
    ) -> Result<(), SimError> {
        if self.model.get_mut().is_none() {
            return Err(SimError::SharedModel { t: self.t });
        }
        let sizes = self.model.sizes();
        self.residual.set_drive(drive, sizes);
        self.feedback = feedback.map(|exact| Box::new(Feedback::new(sizes, exact)));
        self.need_jac = true;
        Ok(())
    }
}

impl<'m, M: LagrangeDirac, S: NewtonSolver<M, M::Algebra>> Drive<'m, M> for Radau<'m, M, S>
where
    DefaultAllocator: Storage<M>,
{
    fn drive(&mut self, drive: &'m mut dyn FnMut(f64, &State<M>, &mut M)) -> Result<(), SimError> {
        Radau::drive(self, drive)
    }

    fn stop_at(&mut self, times: &[f64]) -> Result<(), SimError> {
        self.residual.stops.set(times)
    }
}
