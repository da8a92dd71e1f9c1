//! The parameter columns' flat `∂f/∂θ`, from the model's parameter derivatives, and the
//! embedded error estimate of one sensitivity.

use nalgebra::DefaultAllocator;

use crate::algebra::newton::NewtonSolver;
use crate::methods::radau::estimate::{scaled_error, zero_algebraic};
use crate::methods::radau::options::ErrorNorm;
use crate::methods::radau::tableau::{DD1, DD2, DD3};
use crate::model::blocks::{JacobianBlocks, ResidualBlocks};
use crate::model::state::State;
use crate::model::{LagrangeDirac, ParameterDerivatives};
use crate::shape::dims::{Storage, VecY};
use crate::shape::layout::Layout;
use crate::simulate::sensitivity::Wrt;

use super::Column;
use super::work::apply;

/// Where the parameters' derivatives are evaluated: one block at a time, or all together.
pub(super) struct Derivatives<'a, M: LagrangeDirac>
where
    DefaultAllocator: Storage<M>,
{
    pub(super) of: ParameterDerivatives<M>,
    pub(super) layout: &'a Layout,
    pub(super) blocks: &'a mut ResidualBlocks<M>,
    /// Every parameter's blocks, or empty to evaluate each column's alone.
    pub(super) all: &'a mut [ResidualBlocks<M>],
}

impl<M: LagrangeDirac> Derivatives<'_, M>
where
    DefaultAllocator: Storage<M>,
{
    /// Writes each parameter column's flat `∂f/∂θ` at `(t, s)` into `slot(column)`.
    pub(super) fn write(
        &mut self,
        model: &M,
        t: f64,
        s: &State<M>,
        columns: &mut [Column<M>],
        slot: impl Fn(&mut Column<M>) -> &mut VecY<M>,
    ) {
        if !self.all.is_empty() {
            (self.of.all)(model, t, &s.q, &s.v, &s.lambda, self.all);
        }
        for c in columns {
            if let Wrt::Parameter(p) = c.wrt {
                let blocks = if self.all.is_empty() {
                    (self.of.blocks)(model, p, t, &s.q, &s.v, &s.lambda, self.blocks);
                    &*self.blocks
                } else {
                    &self.all[p]
                };
                flat_dtheta(self.layout, blocks, slot(c));
            }
        }
    }
}

/// The flat `∂f/∂θ = (0, −∂(∂L/∂v)/∂θ, ∂ṗ/∂θ, ∂(A v + b)/∂θ)` from its blocks.
fn flat_dtheta<M: LagrangeDirac>(l: &Layout, b: &ResidualBlocks<M>, out: &mut VecY<M>)
where
    DefaultAllocator: Storage<M>,
{
    let o = out.as_mut_slice();
    o[l.q..l.v].fill(0.0);
    for (x, d) in o[l.v..l.p].iter_mut().zip(b.dl_dv.iter()) {
        *x = -d;
    }
    o[l.p..l.lambda].copy_from_slice(b.momentum_rate.as_slice());
    o[l.lambda..l.len].copy_from_slice(b.constraint_velocity.as_slice());
}

/// The embedded error estimate of one sensitivity, as the state's
/// ([`Estimator`](super::estimate::Estimator)) without its refinement: the weighted norm of
/// `(γ/h M − J)⁻¹ M (f_s(t_n) + Σ e_i Zs_i / h)`, `f_s = J s + ∂f/∂θ`.
#[allow(clippy::too_many_arguments)]
pub(super) fn estimate<M: LagrangeDirac, S: NewtonSolver<M, M::Algebra>>(
    l: &Layout,
    solver: &mut S,
    jac0: &JacobianBlocks<M, M::Algebra>,
    c: &Column<M>,
    e: &mut VecY<M>,
    h: f64,
    weights: &VecY<M>,
    error_norm: ErrorNorm,
) -> f64
where
    DefaultAllocator: Storage<M>,
{
    // s_n is c.s (not yet advanced).
    apply::<M>(l, jac0, &c.s, e);
    if matches!(c.wrt, Wrt::Parameter(_)) {
        *e += &c.g0;
    }
    for i in 0..l.len {
        e[i] += (DD1 * c.z[0][i] + DD2 * c.z[1][i] + DD3 * c.z[2][i]) / h;
    }
    zero_algebraic::<M>(l, e);
    solver.solve(e);
    scaled_error::<M>(e, weights, error_norm)
}
