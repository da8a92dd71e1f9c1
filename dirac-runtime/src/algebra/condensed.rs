//! Radau's condensed Newton solver for any algebra, on its saddle-point systems and block
//! products: the condensation of [`DenseCondensed`](super::DenseCondensed) (see there for the
//! algebra), with storage allocated once.

use nalgebra::{Complex, DefaultAllocator};

use super::traits::{Algebra, JacobianBlocks, NewtonSolver, Saddle, SaddleTerms, Scalar};
use crate::algebra::lu::Singular;
use crate::shape::dims::{Dimensions, Sizes, Storage, VecY};
use crate::shape::layout::Layout;

/// The condensed real and complex systems of Radau's stages, as saddle-point systems of the
/// algebra `A`.
pub struct SaddleCondensed<M: Dimensions, A: Algebra<M>>
where
    DefaultAllocator: Storage<M>,
{
    jac: JacobianBlocks<M, A>,
    sizes: Sizes,
    sigma: f64,
    sigma_c: Complex<f64>,
    real: A::Saddle<f64>,
    complex: A::Saddle<Complex<f64>>,
    /// Work space: the condensed right-hand side and the position increments.
    real_work: (Vec<f64>, Vec<f64>),
    complex_work: (Vec<Complex<f64>>, Vec<Complex<f64>>),
    complex_y: Vec<Complex<f64>>,
}

impl<M: Dimensions, A: Algebra<M>> SaddleCondensed<M, A>
where
    DefaultAllocator: Storage<M>,
{
    /// The solver for a model of these sizes and shape.
    pub fn new(sizes: Sizes, shape: &A::Shape) -> Self {
        let (n, k) = (sizes.nq, sizes.nk());
        SaddleCondensed {
            jac: JacobianBlocks::with_shape(shape),
            sizes,
            sigma: 1.0,
            sigma_c: Complex::new(1.0, 0.0),
            real: A::saddle(shape),
            complex: A::saddle(shape),
            real_work: (vec![0.0; k], vec![0.0; n]),
            complex_work: (vec![Complex::new(0.0, 0.0); k], vec![Complex::new(0.0, 0.0); n]),
            complex_y: vec![Complex::new(0.0, 0.0); sizes.ny()],
        }
    }
}

/// Writes `[σ L_vv + L_vq − D − K/σ, −σ Aᵀ; σ A + G, 0]` into `saddle`.
fn assemble<M: Dimensions, A: Algebra<M>, T: Scalar>(
    saddle: &mut A::Saddle<T>,
    jac: &JacobianBlocks<M, A>,
    sigma: T,
) where
    DefaultAllocator: Storage<M>,
{
    let one = T::one();
    let top = [(sigma, &jac.l_vv), (one, &jac.l_vq), (-one, &jac.dpdot_dv), (-one / sigma, &jac.dpdot_dq)];
    let right = [(-sigma, &jac.a), (-sigma, &jac.slip)];
    saddle.assemble(&SaddleTerms {
        top: &top,
        top_transposed: &[],
        identity: T::zero(),
        right: if jac.non_associated { &right } else { &right[..1] },
        bottom: &[(sigma, sigma, &jac.a), (one, one, &jac.dav_dq)],
        corner: (T::zero(), T::zero()),
    });
}

/// Solves `(σ M − J) y = r` in place in `y` with the factored condensed system.
fn solve<M: Dimensions, A: Algebra<M>, T: Scalar>(
    jac: &JacobianBlocks<M, A>,
    sigma: T,
    saddle: &mut A::Saddle<T>,
    sizes: &Sizes,
    y: &mut [T],
    (b, xq): (&mut [T], &mut [T]),
) where
    DefaultAllocator: Storage<M>,
{
    let n = sizes.nq;
    let Layout { v, p, lambda, .. } = Layout::new(*sizes);
    let (yq, rest) = y.split_at_mut(v);
    let (yv, rest) = rest.split_at_mut(p - v);
    let (yp, yl) = rest.split_at_mut(lambda - p);
    let one = T::one();
    // b_v = r_p + σ r_v − (L_vq − K/σ) r_q,  b_λ = −σ r_λ − G r_q
    let (bv, bl) = b.split_at_mut(n);
    for i in 0..n {
        bv[i] = yp[i] + sigma * yv[i];
    }
    A::qq_mul(&jac.l_vq, -one, yq, bv);
    A::qq_mul(&jac.dpdot_dq, one / sigma, yq, bv);
    for (bk, rk) in bl.iter_mut().zip(yl.iter()) {
        *bk = -sigma * *rk;
    }
    A::cq_mul(&jac.dav_dq, -one, yq, bl);
    saddle.solve(b);
    let (bv, bl) = b.split_at(n);
    for i in 0..n {
        xq[i] = (yq[i] + bv[i]) / sigma;
    }
    // x_p = L_vq x_q + L_vv x_v − r_v
    for i in 0..n {
        yp[i] = -yv[i];
    }
    A::qq_mul(&jac.l_vq, one, xq, yp);
    A::qq_mul(&jac.l_vv, one, bv, yp);
    yq.copy_from_slice(xq);
    yv.copy_from_slice(bv);
    for (yk, bk) in yl.iter_mut().zip(bl) {
        *yk = sigma * *bk;
    }
}

impl<M: Dimensions, A: Algebra<M>> NewtonSolver<M, A> for SaddleCondensed<M, A>
where
    DefaultAllocator: Storage<M>,
{
    fn factor(
        &mut self,
        jac: &JacobianBlocks<M, A>,
        sigma: f64,
        sigma_c: Complex<f64>,
    ) -> Result<(), Singular> {
        self.jac.copy_from(jac);
        self.sigma = sigma;
        self.sigma_c = sigma_c;
        assemble::<M, A, f64>(&mut self.real, jac, sigma);
        assemble::<M, A, Complex<f64>>(&mut self.complex, jac, sigma_c);
        self.real.factor()?;
        self.complex.factor()
    }

    fn solve(&mut self, r: &mut VecY<M>) {
        let (b, xq) = &mut self.real_work;
        solve::<M, A, f64>(&self.jac, self.sigma, &mut self.real, &self.sizes, r.as_mut_slice(), (b, xq));
    }

    fn solve_complex(&mut self, re: &mut VecY<M>, im: &mut VecY<M>) {
        let y = &mut self.complex_y;
        for (i, yi) in y.iter_mut().enumerate() {
            *yi = Complex::new(re[i], im[i]);
        }
        let (b, xq) = &mut self.complex_work;
        solve::<M, A, Complex<f64>>(&self.jac, self.sigma_c, &mut self.complex, &self.sizes, y, (b, xq));
        for (i, yi) in y.iter().enumerate() {
            re[i] = yi.re;
            im[i] = yi.im;
        }
    }

    fn least_norm(&mut self, y: &mut VecY<M>) {
        let lambda = Layout::new(self.sizes.typed::<M>()).lambda;
        self.real.least_norm(&mut y.as_mut_slice()[lambda..]);
    }

    fn deflating(&self) -> bool {
        self.real.deflating()
    }
}
