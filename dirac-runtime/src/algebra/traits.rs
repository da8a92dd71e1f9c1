//! The traits of the seam between integrators and linear algebra, and the Jacobian blocks
//! stored as an algebra says.

use core::fmt;

use nalgebra::{Complex, ComplexField, DefaultAllocator, OMatrix};

use crate::algebra::lu::Singular;
use crate::shape::dims::{Dimensions, Storage, VecY};

/// The scalars of linear systems: `f64`, and `Complex<f64>` for Radau's complex stage system.
pub trait Scalar:
    ComplexField<RealField = f64> + SparseScalar + Copy + Send + Sync + fmt::Debug + 'static
{
}

/// What the sparse LU needs of a scalar besides nalgebra's arithmetic: faer's (feature
/// `sparse`); nothing without it.
#[cfg(feature = "sparse")]
pub trait SparseScalar: faer::traits::ComplexField {}
#[cfg(feature = "sparse")]
impl<T: faer::traits::ComplexField> SparseScalar for T {}

/// What the sparse LU needs of a scalar besides nalgebra's arithmetic: faer's (feature
/// `sparse`); nothing without it.
#[cfg(not(feature = "sparse"))]
pub trait SparseScalar {}
#[cfg(not(feature = "sparse"))]
impl<T> SparseScalar for T {}

impl Scalar for f64 {}
impl Scalar for Complex<f64> {}

/// The storage of a model's blocks and the solvers of its linear systems.
///
/// Implemented by [`Dense`](crate::algebra::Dense) and [`Sparse`](crate::algebra::Sparse); the derives choose one for each model.
pub trait Algebra<M: Dimensions>: Sized + 'static
where
    DefaultAllocator: Storage<M>,
{
    /// What building a model's storage needs: its sizes, or its sparsity pattern.
    type Shape: Clone + Send + Sync + fmt::Debug;
    /// An `n × n` block.
    type Qq: Clone;
    /// An `m × n` block.
    type Cq: Clone;
    /// A saddle-point system, assembled from blocks, factored and solved.
    type Saddle<T: Scalar>: Saddle<M, Self, T>;
    /// Radau's Newton solver: the condensed real and complex systems.
    type Condensed: NewtonSolver<M, Self>;

    /// A zero `n × n` block.
    fn zeros_qq(shape: &Self::Shape) -> Self::Qq;
    /// A zero `m × n` block.
    fn zeros_cq(shape: &Self::Shape) -> Self::Cq;
    /// Storage for a saddle-point system of this shape.
    fn saddle<T: Scalar>(shape: &Self::Shape) -> Self::Saddle<T>;
    /// Radau's Newton solver for this shape.
    fn condensed(shape: &Self::Shape) -> Self::Condensed;

    /// An `n × n` block as a dense matrix, if it is stored as one: the door to dense-only
    /// shortcuts (the variational integrator's separable path) from generic code.
    fn dense_qq(a: &Self::Qq) -> Option<&OMatrix<f64, M::Nq, M::Nq>>;
    /// An `m × n` block as a dense matrix, if it is stored as one.
    fn dense_cq(a: &Self::Cq) -> Option<&OMatrix<f64, M::Nc, M::Nq>>;

    /// The stored values of an `n × n` block (all entries of a dense one, column by column).
    fn qq_values(a: &Self::Qq) -> &[f64];
    /// The stored values of an `n × n` block, mutably.
    fn qq_values_mut(a: &mut Self::Qq) -> &mut [f64];
    /// The stored values of an `m × n` block.
    fn cq_values(a: &Self::Cq) -> &[f64];
    /// The stored values of an `m × n` block, mutably.
    fn cq_values_mut(a: &mut Self::Cq) -> &mut [f64];
    /// Calls `f(row, column, value)` for every stored entry of an `n × n` block.
    fn qq_entries(a: &Self::Qq, f: impl FnMut(usize, usize, f64));
    /// Calls `f(row, column, value)` for every stored entry of an `m × n` block.
    fn cq_entries(a: &Self::Cq, f: impl FnMut(usize, usize, f64));

    /// `y += c A x` for an `n × n` block.
    fn qq_mul<T: Scalar>(a: &Self::Qq, c: T, x: &[T], y: &mut [T]);
    /// `y += c Aᵀ x` for an `n × n` block.
    fn qq_tr_mul<T: Scalar>(a: &Self::Qq, c: T, x: &[T], y: &mut [T]);
    /// `y += c B x` for an `m × n` block (`x` of `n` entries, `y` of `m`).
    fn cq_mul<T: Scalar>(b: &Self::Cq, c: T, x: &[T], y: &mut [T]);
    /// `y += c Bᵀ x` for an `m × n` block (`x` of `m` entries, `y` of `n`).
    fn cq_tr_mul<T: Scalar>(b: &Self::Cq, c: T, x: &[T], y: &mut [T]);
}

/// The terms of a saddle-point system (see the [`algebra`](crate::algebra) documentation).
pub struct SaddleTerms<'a, M: Dimensions, A: Algebra<M>, T>
where
    DefaultAllocator: Storage<M>,
{
    /// `c_k X_k` in the top-left block.
    pub top: &'a [(T, &'a A::Qq)],
    /// `d_k X_kᵀ` in the top-left block.
    pub top_transposed: &'a [(T, &'a A::Qq)],
    /// `e I` in the top-left block.
    pub identity: T,
    /// `r_k B_kᵀ` in the top-right block.
    pub right: &'a [(T, &'a A::Cq)],
    /// `B_k` times `h_k` in the holonomic rows and `o_k` in the others, bottom-left.
    pub bottom: &'a [(T, T, &'a A::Cq)],
    /// The bottom-right diagonal: its value in the holonomic rows and in the others.
    pub corner: (T, T),
}

/// A saddle-point system: assembled from blocks, factored, solved as often as needed.
pub trait Saddle<M: Dimensions, A: Algebra<M>, T: Scalar>
where
    DefaultAllocator: Storage<M>,
{
    /// Writes the matrix of `terms`.
    fn assemble(&mut self, terms: &SaddleTerms<'_, M, A, T>);
    /// Factors the assembled matrix; `Singular` names the unknown without a pivot (velocities
    /// first, then multipliers).
    fn factor(&mut self) -> Result<(), Singular>;
    /// Replaces `x` (`n + m` entries, velocities then multipliers) by the solution.
    fn solve(&mut self, x: &mut [T]);
    /// Replaces the multipliers `lambda` by those of least norm with the same force where the
    /// last factorisation found the rows redundant (see
    /// [`Deflation`](crate::algebra::lu::Deflation)); leaves them otherwise.
    fn least_norm(&mut self, lambda: &mut [T]) {
        let _ = lambda;
    }
    /// Whether its factorisations deflate redundant rows.
    fn deflating(&self) -> bool {
        false
    }
    /// Measures the rows' redundancy again at the next factorisation: the model changed.
    fn remeasure(&mut self) {}
}

/// Solves the linear systems of a Newton iteration for one Jacobian and one pair of shifts:
/// the real shift `σ` and the complex shift `σ_c` of Radau's transformed stage system,
/// `(σ M − J) x = r` with `M = diag(I, 0, I, 0)`.
pub trait NewtonSolver<M: Dimensions, A: Algebra<M>>
where
    DefaultAllocator: Storage<M>,
{
    /// Factors `σ M − J` and `σ_c M − J` for the Jacobian `jac`.
    fn factor(
        &mut self,
        jac: &JacobianBlocks<M, A>,
        sigma: f64,
        sigma_c: Complex<f64>,
    ) -> Result<(), Singular>;
    /// Replaces `r` by the solution of `(σ M − J) x = r`.
    fn solve(&mut self, r: &mut VecY<M>);
    /// Replaces `re + i im` by the solution of `(σ_c M − J) x = re + i im`.
    fn solve_complex(&mut self, re: &mut VecY<M>, im: &mut VecY<M>);
    /// Replaces the multipliers of the state `y` by those of least norm with the same force
    /// where the last factorisation found the rows redundant; leaves them otherwise.
    fn least_norm(&mut self, y: &mut VecY<M>) {
        let _ = y;
    }
    /// Whether its factorisations deflate redundant rows.
    fn deflating(&self) -> bool {
        false
    }
    /// Measures the rows' redundancy again at the next factorisation: the model changed.
    fn remeasure(&mut self) {}
}

/// The Jacobian blocks of [`ResidualBlocks`](crate::ResidualBlocks), the input of a condensed Newton step, stored as
/// the model's [`Algebra`] `A` says (dense by default).
pub struct JacobianBlocks<M: Dimensions, A: Algebra<M> = super::Dense>
where
    DefaultAllocator: Storage<M>,
{
    /// `∂ṗ/∂q = L_qq + F_q + ∂(Aᵀλ)/∂q` (called K in the design notes).
    pub dpdot_dq: A::Qq,
    /// `∂ṗ/∂v = L_qv + F_v` (called D in the design notes).
    pub dpdot_dv: A::Qq,
    /// `L_vq = ∂(∂L/∂v)/∂q`.
    pub l_vq: A::Qq,
    /// `L_vv = ∂²L/∂v²`, singular for a degenerate Lagrangian.
    pub l_vv: A::Qq,
    /// The constraint rows `A(q)`.
    pub a: A::Cq,
    /// `∂(A(q, t) v + b(q, t))/∂q`.
    pub dav_dq: A::Cq,
    /// `B − A` ([`LagrangeDirac::slip_rows`](crate::LagrangeDirac::slip_rows)), read where
    /// `non_associated`: the momentum balance's constraint forces are then `Bᵀλ`, and the
    /// multipliers' column of the Jacobian `Bᵀ`.
    pub slip: A::Cq,
    /// Whether `slip` is part of the Jacobian (set by the integrator for a model that is
    /// [`NON_ASSOCIATED`](crate::LagrangeDirac::NON_ASSOCIATED)).
    pub non_associated: bool,
}

impl<M: Dimensions, A: Algebra<M>> JacobianBlocks<M, A>
where
    DefaultAllocator: Storage<M>,
{
    /// Zeroed blocks of this shape (from [`LagrangeDirac::shape`](crate::LagrangeDirac::shape)),
    /// ready for [`LagrangeDirac::jacobian_blocks`](crate::LagrangeDirac::jacobian_blocks).
    pub fn with_shape(shape: &A::Shape) -> Self {
        Self {
            dpdot_dq: A::zeros_qq(shape),
            dpdot_dv: A::zeros_qq(shape),
            l_vq: A::zeros_qq(shape),
            l_vv: A::zeros_qq(shape),
            a: A::zeros_cq(shape),
            dav_dq: A::zeros_cq(shape),
            slip: A::zeros_cq(shape),
            non_associated: false,
        }
    }

    /// Whether every block holds the same values as `other`'s (exactly: a Jacobian that does
    /// not change with the state, as a linear model's).
    pub fn same_values(&self, other: &Self) -> bool {
        [
            (&self.dpdot_dq, &other.dpdot_dq),
            (&self.dpdot_dv, &other.dpdot_dv),
            (&self.l_vq, &other.l_vq),
            (&self.l_vv, &other.l_vv),
        ]
        .into_iter()
        .all(|(a, b)| A::qq_values(a) == A::qq_values(b))
            && A::cq_values(&self.a) == A::cq_values(&other.a)
            && A::cq_values(&self.dav_dq) == A::cq_values(&other.dav_dq)
            && self.non_associated == other.non_associated
            && (!self.non_associated || A::cq_values(&self.slip) == A::cq_values(&other.slip))
    }

    /// Copies every block of `other` into these, without allocating.
    pub fn copy_from(&mut self, other: &Self) {
        for (to, from) in [
            (&mut self.dpdot_dq, &other.dpdot_dq),
            (&mut self.dpdot_dv, &other.dpdot_dv),
            (&mut self.l_vq, &other.l_vq),
            (&mut self.l_vv, &other.l_vv),
        ] {
            A::qq_values_mut(to).copy_from_slice(A::qq_values(from));
        }
        A::cq_values_mut(&mut self.a).copy_from_slice(A::cq_values(&other.a));
        A::cq_values_mut(&mut self.dav_dq).copy_from_slice(A::cq_values(&other.dav_dq));
        self.non_associated = other.non_associated;
        if other.non_associated {
            A::cq_values_mut(&mut self.slip).copy_from_slice(A::cq_values(&other.slip));
        }
    }
}
