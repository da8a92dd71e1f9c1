//! The linear systems of an implicit step, `(σ M − J) x = r` with `M = diag(I, 0, I, 0)`,
//! behind one seam ([`NewtonSolver`](crate::newton::NewtonSolver)), with the condensed solver every integrator uses and a
//! full solver kept as a reference and a benchmark baseline.
//!
//! Condensation (design notes §2.4): the `q` and `p` rows of `σ M − J` are identity blocks,
//!
//! ```text
//! q-row:  σ x_q − x_v                       = r_q
//! v-row:  L_vq x_q + L_vv x_v − x_p         = r_v
//! p-row:  σ x_p − K x_q − D x_v − Aᵀ x_λ    = r_p
//! λ-row:  −G x_q − A x_v                    = r_λ
//! ```
//!
//! (`K = ∂ṗ/∂q`, `D = ∂ṗ/∂v`, `G = ∂(Av)/∂q`), so with `x_q = (r_q + x_v)/σ` and
//! `x_p = L_vq x_q + L_vv x_v − r_v` the system reduces to the saddle-point system
//!
//! ```text
//! [ σ L_vv + L_vq − D − K/σ   −Aᵀ ] [x_v]   [ r_p + σ r_v − (L_vq − K/σ) r_q ]
//! [ A + G/σ                     0  ] [x_λ] = [ −r_λ − G r_q / σ                ]
//! ```
//!
//! of size `n + m` instead of `3n + m`. It is factored with its multiplier unknowns scaled,
//! `x_λ = σ x̃_λ`, and its constraint rows multiplied by σ,
//!
//! ```text
//! [ σ L_vv + L_vq − D − K/σ   −σ Aᵀ ] [x_v]   [ r_p + σ r_v − (L_vq − K/σ) r_q ]
//! [ σ A + G                     0   ] [x̃_λ] = [ −σ r_λ − G r_q                  ]
//! ```
//!
//! so that at small steps (large σ) the multipliers' pivots, `σ A L_vv⁻¹ Aᵀ`, are of the scale
//! of the velocities' `σ L_vv` instead of `σ⁻²` times smaller.

use nalgebra::{Complex, ComplexField, DefaultAllocator, OMatrix, OVector};

use crate::blocks::JacobianBlocks;
use crate::dims::{Dimensions, Storage, VecY};
use crate::layout::Layout;
use crate::lu::{Lu, Singular};
use crate::names::Named;

/// The unknown of a condensed system `(x_v, x_λ)` (or of a variational stage, `(v, Λ)`) at
/// `column`, for the message of a singular matrix: "no pivot for the velocity `vx`".
pub fn pivot_name<M: Dimensions + Named>(column: usize) -> String {
    let names = M::NAMES;
    if column < M::NQ {
        format!("no pivot for the velocity `{}`", names.velocity_names()[column])
    } else {
        format!("no pivot for the multiplier `{}`", names.constraint_names()[column - M::NQ])
    }
}

/// Solves the linear systems of a Newton iteration for one Jacobian and one pair of shifts:
/// the real shift `σ` and the complex shift `σ_c` of Radau's transformed stage system.
pub trait NewtonSolver<M: Dimensions>
where
    DefaultAllocator: Storage<M>,
{
    /// Factors `σ M − J` and `σ_c M − J` for the Jacobian `jac`.
    fn factor(&mut self, jac: &JacobianBlocks<M>, sigma: f64, sigma_c: Complex<f64>) -> Result<(), Singular>;
    /// Replaces `r` by the solution of `(σ M − J) x = r`.
    fn solve(&mut self, r: &mut VecY<M>);
    /// Replaces `re + i im` by the solution of `(σ_c M − J) x = re + i im`.
    fn solve_complex(&mut self, re: &mut VecY<M>, im: &mut VecY<M>);
}

/// The condensed saddle-point solver of size `n + m`, on the stack.
pub struct Condensed<M: Dimensions>
where
    DefaultAllocator: Storage<M>,
{
    jac: JacobianBlocks<M>,
    sigma: f64,
    sigma_c: Complex<f64>,
    real: Lu<f64, M::Nk>,
    complex: Lu<Complex<f64>, M::Nk>,
}

impl<M: Dimensions> Default for Condensed<M>
where
    DefaultAllocator: Storage<M>,
{
    fn default() -> Self {
        Condensed {
            jac: JacobianBlocks::zeros(),
            sigma: 1.0,
            sigma_c: Complex::new(1.0, 0.0),
            real: Lu::new(),
            complex: Lu::new(),
        }
    }
}

/// Writes the condensed matrix for shift `sigma` into `s`.
fn condensed_matrix<M: Dimensions, T: ComplexField<RealField = f64> + Copy>(
    jac: &JacobianBlocks<M>,
    sigma: T,
    s: &mut OMatrix<T, M::Nk, M::Nk>,
) where
    DefaultAllocator: Storage<M>,
{
    let (n, m) = (M::NQ, M::NC);
    let r = |x: f64| T::from_real(x);
    for j in 0..n {
        for i in 0..n {
            s[(i, j)] = sigma * r(jac.l_vv[(i, j)]) + r(jac.l_vq[(i, j)] - jac.dpdot_dv[(i, j)])
                - r(jac.dpdot_dq[(i, j)]) / sigma;
        }
        for k in 0..m {
            s[(n + k, j)] = sigma * r(jac.a[(k, j)]) + r(jac.dav_dq[(k, j)]);
            s[(j, n + k)] = -sigma * r(jac.a[(k, j)]);
        }
    }
    for k in 0..m {
        for l in 0..m {
            s[(n + k, n + l)] = T::zero();
        }
    }
}

/// Solves `(σ M − J) x = r` in place with the factored condensed matrix.
fn condensed_solve<M: Dimensions, T: ComplexField<RealField = f64> + Copy>(
    jac: &JacobianBlocks<M>,
    sigma: T,
    lu: &Lu<T, M::Nk>,
    x: &mut OVector<T, M::Ny>,
) where
    DefaultAllocator: Storage<M>,
{
    let (n, m) = (M::NQ, M::NC);
    let (q, v, p, lambda) = (Layout::<M>::Q, Layout::<M>::V, Layout::<M>::P, Layout::<M>::LAMBDA);
    let r = |v: f64| T::from_real(v);
    let mut b = OVector::<T, M::Nk>::zeros();
    for i in 0..n {
        let mut bi = x[p + i] + sigma * x[v + i];
        for j in 0..n {
            bi -= (r(jac.l_vq[(i, j)]) - r(jac.dpdot_dq[(i, j)]) / sigma) * x[q + j];
        }
        b[i] = bi;
    }
    for k in 0..m {
        let mut bk = -sigma * x[lambda + k];
        for j in 0..n {
            bk -= r(jac.dav_dq[(k, j)]) * x[q + j];
        }
        b[n + k] = bk;
    }
    lu.solve(&mut b);
    let mut xq = OVector::<T, M::Nq>::zeros();
    for i in 0..n {
        xq[i] = (x[q + i] + b[i]) / sigma;
    }
    for i in 0..n {
        let mut xp = -x[v + i];
        for j in 0..n {
            xp += r(jac.l_vq[(i, j)]) * xq[j] + r(jac.l_vv[(i, j)]) * b[j];
        }
        x[p + i] = xp;
    }
    for i in 0..n {
        x[q + i] = xq[i];
        x[v + i] = b[i];
    }
    for k in 0..m {
        x[lambda + k] = sigma * b[n + k];
    }
}

impl<M: Dimensions> NewtonSolver<M> for Condensed<M>
where
    DefaultAllocator: Storage<M>,
{
    fn factor(&mut self, jac: &JacobianBlocks<M>, sigma: f64, sigma_c: Complex<f64>) -> Result<(), Singular> {
        self.jac.copy_from(jac);
        self.sigma = sigma;
        self.sigma_c = sigma_c;
        condensed_matrix(jac, sigma, self.real.matrix_mut());
        condensed_matrix(jac, sigma_c, self.complex.matrix_mut());
        self.real.factor()?;
        self.complex.factor()
    }

    fn solve(&mut self, r: &mut VecY<M>) {
        condensed_solve(&self.jac, self.sigma, &self.real, r);
    }

    fn solve_complex(&mut self, re: &mut VecY<M>, im: &mut VecY<M>) {
        let mut x = OVector::<Complex<f64>, M::Ny>::from_fn(|i, _| Complex::new(re[i], im[i]));
        condensed_solve(&self.jac, self.sigma_c, &self.complex, &mut x);
        for i in 0..x.len() {
            re[i] = x[i].re;
            im[i] = x[i].im;
        }
    }
}

/// The full `(3n + m)`-sized solver: what a generic DAE code factors. A reference for the
/// condensed solver and the baseline of its benchmark.
pub struct Full<M: Dimensions>
where
    DefaultAllocator: Storage<M>,
{
    real: Lu<f64, M::Ny>,
    complex: Lu<Complex<f64>, M::Ny>,
}

impl<M: Dimensions> Default for Full<M>
where
    DefaultAllocator: Storage<M>,
{
    fn default() -> Self {
        Full { real: Lu::new(), complex: Lu::new() }
    }
}

/// Writes `σ M − J` for `y = (q, v, p, λ)` into `s`.
fn full_matrix<M: Dimensions, T: ComplexField<RealField = f64> + Copy>(
    jac: &JacobianBlocks<M>,
    sigma: T,
    s: &mut OMatrix<T, M::Ny, M::Ny>,
) where
    DefaultAllocator: Storage<M>,
{
    let (n, m) = (M::NQ, M::NC);
    let (q, v, p, lambda) = (Layout::<M>::Q, Layout::<M>::V, Layout::<M>::P, Layout::<M>::LAMBDA);
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
            s[(p + i, lambda + k)] = -r(jac.a[(k, i)]);
            s[(lambda + k, q + i)] = -r(jac.dav_dq[(k, i)]);
            s[(lambda + k, v + i)] = -r(jac.a[(k, i)]);
        }
    }
}

impl<M: Dimensions> NewtonSolver<M> for Full<M>
where
    DefaultAllocator: Storage<M>,
{
    fn factor(&mut self, jac: &JacobianBlocks<M>, sigma: f64, sigma_c: Complex<f64>) -> Result<(), Singular> {
        full_matrix(jac, sigma, self.real.matrix_mut());
        full_matrix(jac, sigma_c, self.complex.matrix_mut());
        self.real.factor()?;
        self.complex.factor()
    }

    fn solve(&mut self, r: &mut VecY<M>) {
        self.real.solve(r);
    }

    fn solve_complex(&mut self, re: &mut VecY<M>, im: &mut VecY<M>) {
        let mut x = OVector::<Complex<f64>, M::Ny>::from_fn(|i, _| Complex::new(re[i], im[i]));
        self.complex.solve(&mut x);
        for i in 0..x.len() {
            re[i] = x[i].re;
            im[i] = x[i].im;
        }
    }
}

#[cfg(test)]
mod tests {
    use nalgebra::{Complex, Const, DMatrix, DVector};

    use super::*;

    /// Sizes of a model with 3 coordinates and 1 constraint, for testing the solvers alone.
    struct Three;

    impl Dimensions for Three {
        type Nq = Const<3>;
        type Nc = Const<1>;
        type Nh = Const<0>;
        type Nk = Const<4>;
        type Ny = Const<10>;
    }

    fn blocks() -> JacobianBlocks<Three> {
        let mut seed = 7u64;
        let mut next = || {
            seed = seed.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
            (seed >> 11) as f64 / (1u64 << 53) as f64 - 0.5
        };
        let mut b = JacobianBlocks::<Three>::zeros();
        for x in b.dpdot_dq.iter_mut().chain(b.dpdot_dv.iter_mut()).chain(b.l_vq.iter_mut()) {
            *x = next();
        }
        for x in b.a.iter_mut().chain(b.dav_dq.iter_mut()) {
            *x = next();
        }
        // A degenerate L_vv: the third velocity has no inertia, as in the paper's system 2.
        b.l_vv[(0, 0)] = 2.0;
        b.l_vv[(1, 1)] = 1.5;
        b.l_vv[(0, 1)] = 0.3;
        b.l_vv[(1, 0)] = 0.3;
        b
    }

    /// `σ M − J` as a dense complex matrix, written from the block equations independently.
    fn dense(b: &JacobianBlocks<Three>, sigma: Complex<f64>) -> DMatrix<Complex<f64>> {
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

    fn check<S: NewtonSolver<Three> + Default>() {
        let b = blocks();
        let (sigma, sigma_c) = (3.7, Complex::new(2.7, 3.1));
        let mut solver = S::default();
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
        check::<Condensed<Three>>();
    }

    #[test]
    fn full_solver_solves_the_full_system() {
        check::<Full<Three>>();
    }
}
