//! The flat DAE `M ẏ = f(t, y)`, `y = (q, v, p, λ)`, assembled from a model's blocks: the
//! default [`LagrangeDirac::residual`](crate::LagrangeDirac::residual) and
//! [`LagrangeDirac::jacobian`](crate::LagrangeDirac::jacobian) of composites.

use nalgebra::DefaultAllocator;

use crate::blocks::{JacobianBlocks, ResidualBlocks};
use crate::dims::{Dimensions, MatYY, Storage, VecY};
use crate::layout::Layout;
use crate::state::State;

/// `f = (v, p − ∂L/∂v, ṗ, A v)` at `state` from its residual blocks.
pub fn residual<M: Dimensions>(state: &State<M>, blocks: &ResidualBlocks<M>, out: &mut VecY<M>)
where
    DefaultAllocator: Storage<M>,
{
    let n = M::NQ;
    out.rows_mut(Layout::<M>::Q, n).copy_from(&state.v);
    out.rows_mut(Layout::<M>::V, n).copy_from(&(&state.p - &blocks.dl_dv));
    out.rows_mut(Layout::<M>::P, n).copy_from(&blocks.momentum_rate);
    out.rows_mut(Layout::<M>::LAMBDA, M::NC).copy_from(&blocks.constraint_velocity);
}

/// `∂f/∂y` from the Jacobian blocks; the structurally zero blocks are not written.
pub fn jacobian<M: Dimensions>(b: &JacobianBlocks<M>, out: &mut MatYY<M>)
where
    DefaultAllocator: Storage<M>,
{
    let (n, m) = (M::NQ, M::NC);
    let (q, v, p, lambda) = (Layout::<M>::Q, Layout::<M>::V, Layout::<M>::P, Layout::<M>::LAMBDA);
    for i in 0..n {
        // q̇ = v and the Legendre map's p.
        out[(q + i, v + i)] = 1.0;
        out[(v + i, p + i)] = 1.0;
    }
    out.view_mut((v, q), (n, n)).copy_from(&(-&b.l_vq));
    out.view_mut((v, v), (n, n)).copy_from(&(-&b.l_vv));
    out.view_mut((p, q), (n, n)).copy_from(&b.dpdot_dq);
    out.view_mut((p, v), (n, n)).copy_from(&b.dpdot_dv);
    out.view_mut((p, lambda), (n, m)).copy_from(&b.a.transpose());
    out.view_mut((lambda, q), (m, n)).copy_from(&b.dav_dq);
    out.view_mut((lambda, v), (m, n)).copy_from(&b.a);
}
