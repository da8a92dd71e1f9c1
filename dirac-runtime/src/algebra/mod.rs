//! How a model stores its matrices and solves its linear systems: the one seam between the
//! integrators and linear algebra.
//!
//! Every linear system an integrator meets is a saddle-point system in the velocities and
//! the multipliers,
//!
//! ```text
//! [ Σ c_k X_k + Σ d_k X_kᵀ + e I     Σ r_k B_kᵀ ] [x_v]   [b_v]
//! [ Σ (h_k | o_k) B_k                  corner  ] [x_λ] = [b_λ]
//! ```
//!
//! with `n × n` blocks `X_k` (`L_vv`, `L_vq`, force Jacobians), `m × n` blocks `B_k` (`A(q)`,
//! `∂(A v)/∂q`), row coefficients that may differ between holonomic and other rows, and a
//! diagonal corner: Radau's condensed Newton systems (real and complex), the variational
//! integrator's stage systems, the projections onto the constraints and the multipliers of a
//! consistent start. An [`Algebra`] says how blocks are stored and provides the solvers:
//! [`Dense`] keeps nalgebra matrices (on the stack for models of fixed size), [`Sparse`] keeps
//! the structural nonzeros of models made of arrays and factors with a sparse LU whose
//! ordering is computed once per model.

mod condensed;
mod dense;
pub mod sparse;
mod traits;

use nalgebra::{DMatrix, DefaultAllocator};

pub use self::condensed::SaddleCondensed;
pub use self::dense::{Dense, DenseCondensed, DenseSaddle};
pub use self::sparse::{Pattern, Sparse, SparseBlock, SparseSaddle, SparseShape};
pub use self::traits::{Algebra, JacobianBlocks, NewtonSolver, Saddle, SaddleTerms, Scalar};
use crate::dims::{Dimensions, Storage};
pub use crate::lu::Singular;

/// A dense copy of an `n × n` block, for set-up and failure analysis of small models.
pub fn dense_qq<M: Dimensions, A: Algebra<M>>(a: &A::Qq, n: usize) -> DMatrix<f64>
where
    DefaultAllocator: Storage<M>,
{
    let mut out = DMatrix::zeros(n, n);
    A::qq_entries(a, |i, j, x| out[(i, j)] += x);
    out
}

/// A dense copy of an `m × n` block.
pub fn dense_cq<M: Dimensions, A: Algebra<M>>(b: &A::Cq, m: usize, n: usize) -> DMatrix<f64>
where
    DefaultAllocator: Storage<M>,
{
    let mut out = DMatrix::zeros(m, n);
    A::cq_entries(b, |i, j, x| out[(i, j)] += x);
    out
}

/// The largest absolute value of a block's stored values (0 for an empty block; NaNs are
/// passed over, as `f64::max` passes them over, by a plain comparison that costs less).
#[inline]
pub fn amax(values: &[f64]) -> f64 {
    amax_by(values, |x| x.abs())
}

/// The largest of `size(x)` over `values` (0 for none; NaNs passed over, as by `amax`).
#[inline]
pub(crate) fn amax_by<T: Copy>(values: &[T], size: impl Fn(T) -> f64) -> f64 {
    values.iter().fold(0.0f64, |m, &x| {
        let s = size(x);
        if s > m { s } else { m }
    })
}
