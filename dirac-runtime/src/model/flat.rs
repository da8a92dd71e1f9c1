//! The flat DAE `M ẏ = f(t, y)`, `y = (q, v, p, λ)`, assembled from a model's blocks: the
//! default [`LagrangeDirac::residual`](crate::model::LagrangeDirac::residual) and
//! [`LagrangeDirac::jacobian`](crate::model::LagrangeDirac::jacobian) of composites and of
//! models whose second derivatives are large, and those models' `l_qq` and
//! `jacobian_csc`.

use nalgebra::DefaultAllocator;

use crate::algebra::Algebra;
use crate::model::blocks::{JacobianBlocks, ResidualBlocks};
use crate::model::sparse::SparseJacobian;
use crate::model::state::State;
use crate::model::{LagrangeDirac, MatQQ};
use crate::shape::dims::{Dimensions, MatYY, Sizes, Storage, VecQ, VecY};
use crate::shape::layout::Layout;

/// `f = (v, p − ∂L/∂v, ṗ, A v)` at `state` from its residual blocks.
#[inline]
pub fn residual<M: Dimensions>(state: &State<M>, blocks: &ResidualBlocks<M>, out: &mut VecY<M>)
where
    DefaultAllocator: Storage<M>,
{
    let l = Layout::new(state.sizes());
    let out = out.as_mut_slice();
    out[l.q..l.v].copy_from_slice(state.v.as_slice());
    for (i, x) in out[l.v..l.p].iter_mut().enumerate() {
        *x = state.p[i] - blocks.dl_dv[i];
    }
    out[l.p..l.lambda].copy_from_slice(blocks.momentum_rate.as_slice());
    out[l.lambda..l.len].copy_from_slice(blocks.constraint_velocity.as_slice());
}

/// `∂f/∂y` from the Jacobian blocks; the structurally zero blocks are not written.
pub fn jacobian<M: Dimensions, A: Algebra<M>>(sizes: &Sizes, b: &JacobianBlocks<M, A>, out: &mut MatYY<M>)
where
    DefaultAllocator: Storage<M>,
{
    let Layout { q, v, p, lambda, .. } = Layout::new(*sizes);
    for i in 0..sizes.nq {
        // q̇ = v and the Legendre map's p.
        out[(q + i, v + i)] = 1.0;
        out[(v + i, p + i)] = 1.0;
    }
    // Blocks are zeroed where they are written, then summed: a sparse block may store an entry
    // more than once.
    let mut zero = |r: usize, c: usize| out[(r, c)] = 0.0;
    A::qq_entries(&b.l_vq, |i, j, _| zero(v + i, q + j));
    A::qq_entries(&b.l_vv, |i, j, _| zero(v + i, v + j));
    A::qq_entries(&b.dpdot_dq, |i, j, _| zero(p + i, q + j));
    A::qq_entries(&b.dpdot_dv, |i, j, _| zero(p + i, v + j));
    A::cq_entries(&b.a, |k, j, _| {
        zero(p + j, lambda + k);
        zero(lambda + k, v + j);
    });
    A::cq_entries(&b.dav_dq, |k, j, _| zero(lambda + k, q + j));
    A::qq_entries(&b.l_vq, |i, j, x| out[(v + i, q + j)] -= x);
    A::qq_entries(&b.l_vv, |i, j, x| out[(v + i, v + j)] -= x);
    A::qq_entries(&b.dpdot_dq, |i, j, x| out[(p + i, q + j)] += x);
    A::qq_entries(&b.dpdot_dv, |i, j, x| out[(p + i, v + j)] += x);
    A::cq_entries(&b.a, |k, j, x| {
        out[(p + j, lambda + k)] += x;
        out[(lambda + k, v + j)] += x;
    });
    A::cq_entries(&b.dav_dq, |k, j, x| out[(lambda + k, q + j)] += x);
}

/// What a model whose second derivatives are large emits as its
/// [`LagrangeDirac::l_qq`], so that they are compiled once,
/// in its [`LagrangeDirac::jacobian_blocks`]:
/// `L_qq = ∂ṗ/∂q − F_q` at `λ = 0`, where the constraint forces' part of `∂ṗ/∂q` vanishes.
pub fn l_qq_from_blocks<M: LagrangeDirac>(model: &M, t: f64, q: &VecQ<M>, v: &VecQ<M>, out: &mut MatQQ<M>)
where
    DefaultAllocator: Storage<M>,
{
    let lambda = model.sizes().zeros_c::<M>();
    let mut blocks = JacobianBlocks::<M, M::Algebra>::with_shape(&model.shape());
    model.jacobian_blocks(t, q, v, &lambda, &mut blocks);
    // `force_dq` writes only its own pattern: what `out` held before must not be read back as
    // part of it (a caller reusing `out` would otherwise get `∂ṗ/∂q` less its last `L_qq`).
    M::Algebra::qq_values_mut(out).iter_mut().for_each(|x| *x = 0.0);
    model.force_dq(t, q, v, out);
    // Every `n × n` block of a model has the pattern of its shape.
    let dpdot_dq = M::Algebra::qq_values(&blocks.dpdot_dq);
    for (x, d) in M::Algebra::qq_values_mut(out).iter_mut().zip(dpdot_dq) {
        *x = d - *x;
    }
}

/// What a model whose second derivatives are large emits as its
/// [`SparseJacobian::jacobian_csc`]: the entries of its pattern read from the flat Jacobian
/// that [`LagrangeDirac::jacobian`] assembles from the
/// blocks (on the heap: it is not called while stepping).
///
/// # Panics
///
/// If `values.len()` is not the number of stored entries.
pub fn jacobian_csc_from_blocks<M: SparseJacobian>(model: &M, t: f64, y: &VecY<M>, values: &mut [f64])
where
    DefaultAllocator: Storage<M>,
{
    let rows = M::JACOBIAN_ROW_INDICES;
    assert_eq!(
        values.len(),
        rows.len(),
        "jacobian_csc: the output must hold one value per stored Jacobian entry"
    );
    let sizes = model.sizes();
    let state = State::<M>::from_y(sizes, y);
    let mut blocks = Box::new(JacobianBlocks::<M, M::Algebra>::with_shape(&model.shape()));
    model.jacobian_blocks(t, &state.q, &state.v, &state.lambda, &mut blocks);
    let mut dense = Box::new(sizes.zeros_yy::<M>());
    jacobian::<M, M::Algebra>(&sizes, &blocks, &mut dense);
    for (column, window) in M::JACOBIAN_COLUMN_STARTS.windows(2).enumerate() {
        for k in window[0]..window[1] {
            values[k] = dense[(rows[k], column)];
        }
    }
}
