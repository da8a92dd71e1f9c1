//! The flat DAE `M ẏ = f(t, y)`, `y = (q, v, p, λ)`, assembled from a model's blocks: the
//! default [`LagrangeDirac::residual`](crate::model::LagrangeDirac::residual) and
//! [`LagrangeDirac::jacobian`](crate::model::LagrangeDirac::jacobian) of composites.

use nalgebra::DefaultAllocator;

use crate::algebra::Algebra;
use crate::model::blocks::{JacobianBlocks, ResidualBlocks};
use crate::model::state::State;
use crate::shape::dims::{Dimensions, MatYY, Sizes, Storage, VecY};
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
