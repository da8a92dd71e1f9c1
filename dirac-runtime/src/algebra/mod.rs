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
//!
//! The layer above the sizes (`shape`): it knows blocks and their dimensions, not the models
//! that fill them, so the model layer and everything above it may use it.

mod condensed;
mod dense;
/// LU factorisation on the stack, real or complex.
pub mod lu;
pub(crate) mod mass;
/// The linear systems of implicit steps: the seam and a full reference solver.
pub mod newton;
#[cfg(feature = "sparse")]
pub mod sparse;
#[cfg(all(test, feature = "sparse"))]
mod sparse_against_dense;
#[cfg(test)]
pub(crate) mod testing;
mod traits;

use nalgebra::{DMatrix, DefaultAllocator};

pub use self::condensed::SaddleCondensed;
pub use self::dense::{Dense, DenseCondensed, DenseSaddle};
pub use self::lu::{Singular, amax};
#[cfg(feature = "sparse")]
pub use self::sparse::{Pattern, Sparse, SparseBlock, SparseSaddle, SparseShape};
pub use self::traits::{Algebra, JacobianBlocks, NewtonSolver, Saddle, SaddleTerms, Scalar, SparseScalar};
use crate::shape::dims::{Dimensions, Storage};

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
