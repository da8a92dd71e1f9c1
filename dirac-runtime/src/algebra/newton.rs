//! The linear systems of an implicit step, `(σ M − J) x = r` with `M = diag(I, 0, I, 0)`,
//! behind one seam ([`NewtonSolver`]): the condensed solver of the model's
//! [`Algebra`](crate::algebra::Algebra), which every integrator uses, and a full dense solver
//! kept as a reference and a benchmark baseline.
//!
//! Condensation (design notes §2.4) reduces the system to a saddle-point system in
//! `(x_v, x_λ)` of size `n + m` instead of `3n + m`; see
//! [`DenseCondensed`](crate::algebra::DenseCondensed) for the algebra.

use nalgebra::{Complex, ComplexField, DefaultAllocator, OMatrix, OVector};

use crate::algebra::Dense;
use crate::algebra::JacobianBlocks;
pub use crate::algebra::NewtonSolver;
use crate::algebra::lu::{Lu, Singular};
use crate::shape::dims::{Dimensions, Fixed, Sizes, Storage, VecY};
use crate::shape::layout::Layout;

/// The full `(3n + m)`-sized solver: what a generic DAE code factors. A reference for the
/// condensed solver and the baseline of its benchmark.
pub struct Full<M: Dimensions>
where
    DefaultAllocator: Storage<M>,
{
    real: Lu<f64, M::Ny>,
    complex: Lu<Complex<f64>, M::Ny>,
    sizes: Sizes,
}

impl<M: Dimensions> Full<M>
where
    DefaultAllocator: Storage<M>,
{
    /// The solver for a model of these sizes.
    pub fn new(sizes: Sizes) -> Self {
        Full { real: Lu::new(sizes.ny()), complex: Lu::new(sizes.ny()), sizes }
    }
}

impl<M: Fixed> Default for Full<M>
where
    DefaultAllocator: Storage<M>,
{
    fn default() -> Self {
        Self::new(M::SIZES)
    }
}

/// Writes `σ M − J` for `y = (q, v, p, λ)` into `s`.
fn full_matrix<M: Dimensions, T: ComplexField<RealField = f64> + Copy>(
    jac: &JacobianBlocks<M, Dense>,
    sigma: T,
    sizes: &Sizes,
    s: &mut OMatrix<T, M::Ny, M::Ny>,
) where
    DefaultAllocator: Storage<M>,
{
    let (n, m) = (sizes.nq, sizes.nc);
    let Layout { q, v, p, lambda, .. } = Layout::new(*sizes);
    let r = |x: f64| T::from_real(x);
    s.fill(T::zero());
    for i in 0..n {
        s[(q + i, q + i)] = sigma;
        s[(q + i, v + i)] = -T::one();
        s[(v + i, p + i)] = -T::one();
        s[(p + i, p + i)] = sigma;
        for j in 0..n {
            s[(v + i, q + j)] = r(jac.l_vq[(i, j)]);
            s[(v + i, v + j)] = r(jac.l_vv[(i, j)]);
            s[(p + i, q + j)] = -r(jac.dpdot_dq[(i, j)]);
            s[(p + i, v + j)] = -r(jac.dpdot_dv[(i, j)]);
        }
        for k in 0..m {
            let force = if jac.non_associated { jac.a[(k, i)] + jac.slip[(k, i)] } else { jac.a[(k, i)] };
            s[(p + i, lambda + k)] = -r(force);
            s[(lambda + k, q + i)] = -r(jac.dav_dq[(k, i)]);
            s[(lambda + k, v + i)] = -r(jac.a[(k, i)]);
        }
    }
}

impl<M: Dimensions> NewtonSolver<M, Dense> for Full<M>
where
    DefaultAllocator: Storage<M>,
{
    fn factor(
        &mut self,
        jac: &JacobianBlocks<M, Dense>,
        sigma: f64,
        sigma_c: Complex<f64>,
    ) -> Result<(), Singular> {
        full_matrix(jac, sigma, &self.sizes, self.real.matrix_mut());
        full_matrix(jac, sigma_c, &self.sizes, self.complex.matrix_mut());
        self.real.factor()?;
        self.complex.factor()
    }

    fn solve(&mut self, r: &mut VecY<M>) {
        self.real.solve(r);
    }

    fn solve_complex(&mut self, re: &mut VecY<M>, im: &mut VecY<M>) {
        let ny = <M::Ny as nalgebra::Dim>::from_usize(self.sizes.ny());
        let mut x = OVector::<Complex<f64>, M::Ny>::from_fn_generic(ny, nalgebra::Const::<1>, |i, _| {
            Complex::new(re[i], im[i])
        });
        self.complex.solve(&mut x);
        for i in 0..x.len() {
            re[i] = x[i].re;
            im[i] = x[i].im;
        }
    }
}

#[cfg(test)]
mod tests {
    use nalgebra::{Complex, DMatrix, DVector};

    use super::*;
    use crate::algebra::Algebra;
    use crate::algebra::testing::{self, THREE, Three};

    const SIZES: Sizes = THREE;

    fn blocks() -> JacobianBlocks<Three, Dense> {
        testing::blocks(7)
    }

    /// `σ M − J` as a dense complex matrix, written from the block equations independently.
    fn dense(b: &JacobianBlocks<Three, Dense>, sigma: Complex<f64>) -> DMatrix<Complex<f64>> {
        let c = |x: f64| Complex::new(x, 0.0);
        DMatrix::from_fn(10, 10, |i, j| {
            let (bi, ri) = (i / 3, i % 3);
            let (bj, rj) = (j / 3, j % 3);
            let eye = if ri == rj { c(1.0) } else { c(0.0) };
            match (bi, bj) {
                (0, 0) => eye * sigma,
                (0, 1) => -eye,
                (1, 0) => c(b.l_vq[(ri, rj)]),
                (1, 1) => c(b.l_vv[(ri, rj)]),
                (1, 2) => -eye,
                (2, 0) => -c(b.dpdot_dq[(ri, rj)]),
                (2, 1) => -c(b.dpdot_dv[(ri, rj)]),
                (2, 2) => eye * sigma,
                (2, 3) => -c(b.a[(0, ri)]),
                (3, 0) => -c(b.dav_dq[(0, rj)]),
                (3, 1) => -c(b.a[(0, rj)]),
                _ => c(0.0),
            }
        })
    }

    fn check<S: NewtonSolver<Three, Dense>>(mut solver: S) {
        let b = blocks();
        let (sigma, sigma_c) = (3.7, Complex::new(2.7, 3.1));
        solver.factor(&b, sigma, sigma_c).expect("nonsingular");
        let rhs = VecY::<Three>::from_fn(|i, _| (i as f64 * 0.37).sin());
        let mut x = rhs;
        solver.solve(&mut x);
        let residual = dense(&b, Complex::new(sigma, 0.0))
            * DVector::from_fn(10, |i, _| Complex::new(x[i], 0.0))
            - DVector::from_fn(10, |i, _| Complex::new(rhs[i], 0.0));
        assert!(residual.camax() < 1e-12, "real residual {residual}");
        let im_rhs = VecY::<Three>::from_fn(|i, _| (i as f64 * 0.91).cos());
        let (mut re, mut im) = (rhs, im_rhs);
        solver.solve_complex(&mut re, &mut im);
        let x = DVector::from_fn(10, |i, _| Complex::new(re[i], im[i]));
        let b_c = DVector::from_fn(10, |i, _| Complex::new(rhs[i], im_rhs[i]));
        let residual = dense(&b, sigma_c) * x - b_c;
        assert!(residual.camax() < 1e-12, "complex residual {residual}");
    }

    #[test]
    fn condensed_solver_solves_the_full_system() {
        check(<Dense as Algebra<Three>>::condensed(&SIZES));
    }

    #[test]
    fn full_solver_solves_the_full_system() {
        check(Full::<Three>::new(SIZES));
    }
}
