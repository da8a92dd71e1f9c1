//! Dense storage: every block a nalgebra matrix, every system factored by a dense LU. On the
//! stack for models of fixed size, where nothing beats it; on the heap, allocated once, for
//! models sized at run time that are still small enough for dense matrices.

use nalgebra::{Complex, ComplexField, DefaultAllocator, Dim, OMatrix, OVector};

use super::traits::{Algebra, JacobianBlocks, NewtonSolver, Saddle, SaddleTerms, Scalar};
use crate::algebra::lu::{Deflation, Lu, Singular};
use crate::shape::dims::{Dimensions, Fixed, Sizes, Storage, VecY};
use crate::shape::layout::Layout;

/// Dense blocks and dense LU factorisations.
#[derive(Clone, Copy, Debug, Default)]
pub struct Dense;

type Qq<M> = OMatrix<f64, <M as Dimensions>::Nq, <M as Dimensions>::Nq>;
type Cq<M> = OMatrix<f64, <M as Dimensions>::Nc, <M as Dimensions>::Nq>;

impl<M: Dimensions> Algebra<M> for Dense
where
    DefaultAllocator: Storage<M>,
{
    type Shape = Sizes;
    type Qq = Qq<M>;
    type Cq = Cq<M>;
    type Saddle<T: Scalar> = DenseSaddle<M, T>;
    type Condensed = DenseCondensed<M>;

    fn zeros_qq(s: &Sizes) -> Qq<M> {
        let n = M::Nq::from_usize(s.nq);
        Qq::<M>::zeros_generic(n, n)
    }

    fn zeros_cq(s: &Sizes) -> Cq<M> {
        Cq::<M>::zeros_generic(M::Nc::from_usize(s.nc), M::Nq::from_usize(s.nq))
    }

    fn saddle<T: Scalar>(s: &Sizes) -> DenseSaddle<M, T> {
        DenseSaddle { lu: Lu::new(s.nk()), deflation: Deflation::new(s.nc), sizes: *s }
    }

    fn condensed(s: &Sizes) -> DenseCondensed<M> {
        DenseCondensed::new(*s)
    }

    fn dense_qq(a: &Qq<M>) -> Option<&Qq<M>> {
        Some(a)
    }

    fn dense_cq(a: &Cq<M>) -> Option<&Cq<M>> {
        Some(a)
    }

    fn qq_values(a: &Qq<M>) -> &[f64] {
        a.as_slice()
    }

    fn qq_values_mut(a: &mut Qq<M>) -> &mut [f64] {
        a.as_mut_slice()
    }

    fn cq_values(a: &Cq<M>) -> &[f64] {
        a.as_slice()
    }

    fn cq_values_mut(a: &mut Cq<M>) -> &mut [f64] {
        a.as_mut_slice()
    }

    fn qq_entries(a: &Qq<M>, mut f: impl FnMut(usize, usize, f64)) {
        for j in 0..a.ncols() {
            for i in 0..a.nrows() {
                f(i, j, a[(i, j)]);
            }
        }
    }

    fn cq_entries(a: &Cq<M>, mut f: impl FnMut(usize, usize, f64)) {
        for j in 0..a.ncols() {
            for i in 0..a.nrows() {
                f(i, j, a[(i, j)]);
            }
        }
    }

    fn qq_mul<T: Scalar>(a: &Qq<M>, c: T, x: &[T], y: &mut [T]) {
        mul(a, c, x, y);
    }

    fn qq_tr_mul<T: Scalar>(a: &Qq<M>, c: T, x: &[T], y: &mut [T]) {
        tr_mul(a, c, x, y);
    }

    fn cq_mul<T: Scalar>(b: &Cq<M>, c: T, x: &[T], y: &mut [T]) {
        mul(b, c, x, y);
    }

    fn cq_tr_mul<T: Scalar>(b: &Cq<M>, c: T, x: &[T], y: &mut [T]) {
        tr_mul(b, c, x, y);
    }
}

/// `y += c A x`.
fn mul<T: Scalar, R: Dim, C: Dim>(a: &OMatrix<f64, R, C>, c: T, x: &[T], y: &mut [T])
where
    DefaultAllocator: nalgebra::allocator::Allocator<R, C>,
{
    for j in 0..a.ncols() {
        let xj = c * x[j];
        for i in 0..a.nrows() {
            y[i] += xj.scale(a[(i, j)]);
        }
    }
}

/// `y += c Aᵀ x`.
fn tr_mul<T: Scalar, R: Dim, C: Dim>(a: &OMatrix<f64, R, C>, c: T, x: &[T], y: &mut [T])
where
    DefaultAllocator: nalgebra::allocator::Allocator<R, C>,
{
    for j in 0..a.ncols() {
        let mut s = T::zero();
        for i in 0..a.nrows() {
            s += x[i].scale(a[(i, j)]);
        }
        y[j] += c * s;
    }
}

/// A saddle-point system factored by a dense LU of size `n + m`.
pub struct DenseSaddle<M: Dimensions, T: Scalar>
where
    DefaultAllocator: Storage<M>,
{
    lu: Lu<T, M::Nk>,
    deflation: Deflation<T, M::Nc>,
    sizes: Sizes,
}

impl<M: Dimensions, T: Scalar> Saddle<M, Dense, T> for DenseSaddle<M, T>
where
    DefaultAllocator: Storage<M>,
{
    // Inlined so that the terms, a constant array at each call, unroll.
    #[inline(always)]
    fn assemble(&mut self, terms: &SaddleTerms<'_, M, Dense, T>) {
        let Sizes { nq: n, nc: m, nh } = self.sizes.typed::<M>();
        let s = self.lu.matrix_mut();
        s.fill(T::zero());
        for &(c, x) in terms.top {
            for j in 0..n {
                for i in 0..n {
                    s[(i, j)] += c.scale(x[(i, j)]);
                }
            }
        }
        for &(c, x) in terms.top_transposed {
            for j in 0..n {
                for i in 0..n {
                    s[(i, j)] += c.scale(x[(j, i)]);
                }
            }
        }
        for i in 0..n {
            s[(i, i)] += terms.identity;
        }
        for &(c, b) in terms.right {
            for k in 0..m {
                for j in 0..n {
                    s[(j, n + k)] += c.scale(b[(k, j)]);
                }
            }
        }
        for &(ch, co, b) in terms.bottom {
            for k in 0..m {
                let c = if k < nh { ch } else { co };
                for j in 0..n {
                    s[(n + k, j)] += c.scale(b[(k, j)]);
                }
            }
        }
        for k in 0..m {
            s[(n + k, n + k)] = if k < nh { terms.corner.0 } else { terms.corner.1 };
        }
    }

    fn factor(&mut self) -> Result<(), Singular> {
        self.lu.factor_saddle(self.sizes.nq, &mut self.deflation)
    }

    fn solve(&mut self, x: &mut [T]) {
        self.deflation.project(&mut x[self.sizes.nq..]);
        self.lu.solve_slice(x);
    }

    fn least_norm(&mut self, lambda: &mut [T]) {
        self.deflation.project(lambda);
    }

    fn deflating(&self) -> bool {
        self.deflation.active()
    }

    fn remeasure(&mut self) {
        self.deflation.remeasure();
    }
}

/// The condensed saddle-point solver of size `n + m` (design notes §2.4), dense.
///
/// Condensation: the `q` and `p` rows of `σ M − J` are identity blocks,
///
/// ```text
/// q-row:  σ x_q − x_v                       = r_q
/// v-row:  L_vq x_q + L_vv x_v − x_p         = r_v
/// p-row:  σ x_p − K x_q − D x_v − Aᵀ x_λ    = r_p
/// λ-row:  −G x_q − A x_v                    = r_λ
/// ```
///
/// (`K = ∂ṗ/∂q`, `D = ∂ṗ/∂v`, `G = ∂(Av)/∂q`), so with `x_q = (r_q + x_v)/σ` and
/// `x_p = L_vq x_q + L_vv x_v − r_v` the system reduces to
///
/// ```text
/// [ σ L_vv + L_vq − D − K/σ   −σ Aᵀ ] [x_v]   [ r_p + σ r_v − (L_vq − K/σ) r_q ]
/// [ σ A + G                     0   ] [x̃_λ] = [ −σ r_λ − G r_q                  ]
/// ```
///
/// with the multipliers scaled, `x_λ = σ x̃_λ`, and the constraint rows multiplied by σ, so
/// that at small steps the multipliers' pivots are of the scale of the velocities'.
pub struct DenseCondensed<M: Dimensions>
where
    DefaultAllocator: Storage<M>,
{
    jac: JacobianBlocks<M, Dense>,
    real: Shifted<M, f64>,
    complex: Shifted<M, Complex<f64>>,
    sizes: Sizes,
}

/// The condensed system for one shift `σ`: its factors, `1/σ`, and the coupling
/// `L_vq − K/σ` that every solve applies to `r_q`, formed once with the factors.
struct Shifted<M: Dimensions, T: ComplexField<RealField = f64> + Copy>
where
    DefaultAllocator: Storage<M>,
{
    sigma: T,
    inv_sigma: T,
    coupling: OMatrix<T, M::Nq, M::Nq>,
    lu: Lu<T, M::Nk>,
    deflation: Deflation<T, M::Nc>,
}

impl<M: Dimensions, T: ComplexField<RealField = f64> + Copy> Shifted<M, T>
where
    DefaultAllocator: Storage<M>,
{
    fn new(sizes: &Sizes) -> Self {
        let n = M::Nq::from_usize(sizes.nq);
        Shifted {
            sigma: T::one(),
            inv_sigma: T::one(),
            coupling: OMatrix::<T, M::Nq, M::Nq>::zeros_generic(n, n),
            lu: Lu::new(sizes.nk()),
            deflation: Deflation::new(sizes.nc),
        }
    }

    /// Forms and factors the condensed matrix of `jac` for the shift `sigma`.
    fn factor(&mut self, jac: &JacobianBlocks<M, Dense>, sigma: T) -> Result<(), Singular> {
        self.sigma = sigma;
        self.inv_sigma = T::one() / sigma;
        let n = jac.l_vq.nrows();
        for j in 0..n {
            for i in 0..n {
                self.coupling[(i, j)] =
                    T::from_real(jac.l_vq[(i, j)]) - self.inv_sigma.scale(jac.dpdot_dq[(i, j)]);
            }
        }
        condensed_matrix(jac, sigma, &self.coupling, self.lu.matrix_mut());
        self.lu.factor_saddle(jac.l_vq.nrows(), &mut self.deflation)
    }
}

impl<M: Dimensions> DenseCondensed<M>
where
    DefaultAllocator: Storage<M>,
{
    /// The solver for a model of these sizes.
    pub fn new(sizes: Sizes) -> Self {
        DenseCondensed {
            jac: JacobianBlocks::with_shape(&sizes),
            real: Shifted::new(&sizes),
            complex: Shifted::new(&sizes),
            sizes,
        }
    }
}

impl<M: crate::shape::dims::Fixed> Default for DenseCondensed<M>
where
    DefaultAllocator: Storage<M>,
{
    fn default() -> Self {
        Self::new(M::SIZES)
    }
}

/// Writes the condensed matrix for shift `sigma` into `s`, with the coupling `L_vq − K/σ`
/// already formed.
fn condensed_matrix<M: Dimensions, T: ComplexField<RealField = f64> + Copy>(
    jac: &JacobianBlocks<M, Dense>,
    sigma: T,
    coupling: &OMatrix<T, M::Nq, M::Nq>,
    s: &mut OMatrix<T, M::Nk, M::Nk>,
) where
    DefaultAllocator: Storage<M>,
{
    let (n, m) = (jac.a.ncols(), jac.a.nrows());
    let r = |x: f64| T::from_real(x);
    for j in 0..n {
        for i in 0..n {
            s[(i, j)] = sigma.scale(jac.l_vv[(i, j)]) - r(jac.dpdot_dv[(i, j)]) + coupling[(i, j)];
        }
        for k in 0..m {
            s[(n + k, j)] = sigma.scale(jac.a[(k, j)]) + r(jac.dav_dq[(k, j)]);
            s[(j, n + k)] = -sigma.scale(jac.a[(k, j)]);
        }
    }
    // The multipliers' columns of a balance on `Bᵀλ`.
    if jac.non_associated {
        for j in 0..n {
            for k in 0..m {
                s[(j, n + k)] -= sigma.scale(jac.slip[(k, j)]);
            }
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
    jac: &JacobianBlocks<M, Dense>,
    shifted: &mut Shifted<M, T>,
    sizes: &Sizes,
    x: &mut OVector<T, M::Ny>,
) where
    DefaultAllocator: Storage<M>,
{
    let sizes = sizes.typed::<M>();
    let (n, m) = (sizes.nq, sizes.nc);
    let Layout { q, v, p, lambda, .. } = Layout::new(sizes);
    let (sigma, inv_sigma, coupling) = (shifted.sigma, shifted.inv_sigma, &shifted.coupling);
    let nk = M::Nk::from_usize(sizes.nk());
    let mut b = OVector::<T, M::Nk>::zeros_generic(nk, nalgebra::Const::<1>);
    for i in 0..n {
        b[i] = x[p + i] + sigma * x[v + i];
    }
    for j in 0..n {
        let xq = x[q + j];
        for i in 0..n {
            b[i] -= coupling[(i, j)] * xq;
        }
    }
    for k in 0..m {
        let mut bk = -sigma * x[lambda + k];
        for j in 0..n {
            bk -= x[q + j].scale(jac.dav_dq[(k, j)]);
        }
        b[n + k] = bk;
    }
    shifted.deflation.project(&mut b.as_mut_slice()[n..]);
    shifted.lu.solve(&mut b);
    let nq = M::Nq::from_usize(n);
    let mut xq = OVector::<T, M::Nq>::zeros_generic(nq, nalgebra::Const::<1>);
    for i in 0..n {
        xq[i] = (x[q + i] + b[i]) * inv_sigma;
    }
    for i in 0..n {
        x[p + i] = -x[v + i];
    }
    for j in 0..n {
        let (xqj, bj) = (xq[j], b[j]);
        for i in 0..n {
            x[p + i] += xqj.scale(jac.l_vq[(i, j)]) + bj.scale(jac.l_vv[(i, j)]);
        }
    }
    for i in 0..n {
        x[q + i] = xq[i];
        x[v + i] = b[i];
    }
    for k in 0..m {
        x[lambda + k] = sigma * b[n + k];
    }
}

impl<M: Dimensions> NewtonSolver<M, Dense> for DenseCondensed<M>
where
    DefaultAllocator: Storage<M>,
{
    fn factor(
        &mut self,
        jac: &JacobianBlocks<M, Dense>,
        sigma: f64,
        sigma_c: Complex<f64>,
    ) -> Result<(), Singular> {
        self.jac.copy_from(jac);
        self.real.factor(jac, sigma)?;
        self.complex.factor(jac, sigma_c)
    }

    fn solve(&mut self, r: &mut VecY<M>) {
        condensed_solve(&self.jac, &mut self.real, &self.sizes, r);
    }

    fn solve_complex(&mut self, re: &mut VecY<M>, im: &mut VecY<M>) {
        let ny = M::Ny::from_usize(self.sizes.ny());
        let mut x = OVector::<Complex<f64>, M::Ny>::from_fn_generic(ny, nalgebra::Const::<1>, |i, _| {
            Complex::new(re[i], im[i])
        });
        condensed_solve(&self.jac, &mut self.complex, &self.sizes, &mut x);
        for i in 0..x.len() {
            re[i] = x[i].re;
            im[i] = x[i].im;
        }
    }

    fn least_norm(&mut self, y: &mut VecY<M>) {
        let lambda = Layout::new(self.sizes.typed::<M>()).lambda;
        self.real.deflation.project(&mut y.as_mut_slice()[lambda..]);
    }

    fn deflating(&self) -> bool {
        self.real.deflation.active()
    }

    fn remeasure(&mut self) {
        self.real.deflation.remeasure();
        self.complex.deflation.remeasure();
    }
}

impl<M: Fixed> JacobianBlocks<M, Dense>
where
    DefaultAllocator: Storage<M>,
{
    /// Zeroed dense blocks for a model of fixed size.
    pub fn zeros() -> Self {
        Self::with_shape(&M::SIZES)
    }
}
