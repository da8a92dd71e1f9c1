//! A constant, nonsingular mass matrix factored once: what the variational integrator's
//! separable path and the explicit integrator's accelerations solve with, for models whose
//! `L_vv` does not change.

use nalgebra::{DefaultAllocator, OMatrix};

use crate::algebra::lu::Lu;
use crate::shape::dims::{Dimensions, Sizes, Storage, VecQ};

/// A dense `m × n` block.
type Cq<M> = OMatrix<f64, <M as Dimensions>::Nc, <M as Dimensions>::Nq>;

/// A constant, nonsingular mass matrix, ready to solve with: its inverse diagonal when it is
/// diagonal (point masses), its LU factors otherwise.
pub(crate) enum Mass<M: Dimensions>
where
    DefaultAllocator: Storage<M>,
{
    Diagonal(VecQ<M>),
    Dense(Lu<f64, M::Nq>),
}

impl<M: Dimensions> Mass<M>
where
    DefaultAllocator: Storage<M>,
{
    /// The mass matrix `matrix` ready to solve with, if it is nonsingular.
    pub fn new(sizes: &Sizes, matrix: &OMatrix<f64, M::Nq, M::Nq>) -> Option<Self> {
        let n = sizes.nq;
        let diagonal = (0..n).all(|i| (0..n).all(|j| i == j || matrix[(i, j)] == 0.0));
        if diagonal {
            let d = matrix.diagonal();
            return d.iter().all(|x| *x != 0.0 && x.is_finite()).then(|| Mass::Diagonal(d.map(|x| 1.0 / x)));
        }
        let mut lu = Lu::<f64, M::Nq>::new(n);
        lu.matrix_mut().copy_from(matrix);
        lu.factor().ok().map(|()| Mass::Dense(lu))
    }

    /// `x ← M⁻¹ x`.
    #[inline]
    pub(crate) fn solve(&self, x: &mut VecQ<M>) {
        match self {
            Mass::Diagonal(inverse) => x.component_mul_assign(inverse),
            Mass::Dense(lu) => lu.solve(x),
        }
    }

    /// `M⁻¹ Aᵀ` for constraint rows `a`.
    #[inline]
    pub(crate) fn solve_transpose(&self, a: &Cq<M>) -> OMatrix<f64, M::Nq, M::Nc> {
        let mut b = a.transpose();
        for j in 0..b.ncols() {
            let mut column = b.column(j).into_owned();
            self.solve(&mut column);
            b.set_column(j, &column);
        }
        b
    }
}
