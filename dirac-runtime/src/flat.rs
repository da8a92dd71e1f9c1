//! The flat DAE `M ẏ = f(t, y)`, `y = (q, v, p, λ)`, assembled from a model's blocks.

use nalgebra::DefaultAllocator;

use crate::dims::{Dimensions, MatYY, Storage, VecY};
use crate::model::{JacobianBlocks, LagrangeDirac, ResidualBlocks};
use crate::state::State;

/// `f = (v, p − ∂L/∂v, ṗ, A v)` from [`LagrangeDirac::residual_blocks`].
pub fn residual_from_blocks<M: LagrangeDirac>(model: &M, t: f64, y: &VecY<M>, out: &mut VecY<M>)
where
    DefaultAllocator: Storage<M>,
{
    let n = M::NQ;
    let s = State::<M>::from_y(y);
    let mut blocks = ResidualBlocks::<M>::zeros();
    model.residual_blocks(t, &s.q, &s.v, &s.lambda, &mut blocks);
    out.rows_mut(0, n).copy_from(&s.v);
    out.rows_mut(n, n).copy_from(&(&s.p - &blocks.dl_dv));
    out.rows_mut(2 * n, n).copy_from(&blocks.momentum_rate);
    out.rows_mut(3 * n, M::NC).copy_from(&blocks.constraint_velocity);
}

/// `∂f/∂y` from [`LagrangeDirac::jacobian_blocks`]; the structurally zero blocks are not written.
pub fn jacobian_from_blocks<M: LagrangeDirac>(model: &M, t: f64, y: &VecY<M>, out: &mut MatYY<M>)
where
    DefaultAllocator: Storage<M>,
{
    let (n, m) = (M::NQ, <M as Dimensions>::NC);
    let s = State::<M>::from_y(y);
    let mut b = JacobianBlocks::<M>::zeros();
    model.jacobian_blocks(t, &s.q, &s.v, &s.lambda, &mut b);
    for i in 0..n {
        out[(i, n + i)] = 1.0;
        out[(n + i, 2 * n + i)] = 1.0;
    }
    out.view_mut((n, 0), (n, n)).copy_from(&(-&b.l_vq));
    out.view_mut((n, n), (n, n)).copy_from(&(-&b.l_vv));
    out.view_mut((2 * n, 0), (n, n)).copy_from(&b.dpdot_dq);
    out.view_mut((2 * n, n), (n, n)).copy_from(&b.dpdot_dv);
    out.view_mut((2 * n, 3 * n), (n, m)).copy_from(&b.a.transpose());
    out.view_mut((3 * n, 0), (m, n)).copy_from(&b.dav_dq);
    out.view_mut((3 * n, n), (m, n)).copy_from(&b.a);
}

/// The flat Jacobian `∂f/∂y` in compressed sparse columns, for sparse linear algebra and for
/// callers that keep only the nonzeros. `#[derive(LagrangeDirac)]` implements it: the pattern
/// is every entry that is not structurally zero, and
/// [`jacobian_csc`](SparseJacobian::jacobian_csc) writes exactly those values, column by
/// column, with no zeroing and no scatter into a dense matrix.
///
/// The facade's guide (`dirac::guide`, "The equations without an integrator") has a runnable
/// example.
pub trait SparseJacobian: LagrangeDirac
where
    DefaultAllocator: Storage<Self>,
{
    /// Where each column's entries start in [`JACOBIAN_ROW_INDICES`](Self::JACOBIAN_ROW_INDICES);
    /// `NY + 1` entries, the last one the number of stored entries.
    const JACOBIAN_COLUMN_STARTS: &'static [usize];
    /// The row of each stored entry, column by column, increasing within a column.
    const JACOBIAN_ROW_INDICES: &'static [usize];

    /// Writes the stored entries of `∂f/∂y` at `(t, y)` into `values`, in the order of
    /// [`JACOBIAN_ROW_INDICES`](Self::JACOBIAN_ROW_INDICES).
    ///
    /// # Panics
    ///
    /// If `values.len()` is not the number of stored entries.
    fn jacobian_csc(&self, t: f64, y: &VecY<Self>, values: &mut [f64]);
}
