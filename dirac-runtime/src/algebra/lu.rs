//! LU factorisation with partial pivoting of a dense square matrix, real or complex, in place
//! and without allocation: on the stack for a size the type fixes, on the heap (allocated
//! once, with the factorisation) for a size chosen at run time.

use nalgebra::allocator::Allocator;
use nalgebra::{ComplexField, DefaultAllocator, Dim, OMatrix, OVector};

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

/// Why a factorisation failed.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Singular {
    /// The column without a usable pivot.
    pub column: usize,
}

/// The factors `P A = L U` of a square matrix, stored in one matrix, with the row pivots.
pub struct Lu<T: ComplexField, D: Dim>
where
    DefaultAllocator: Allocator<D, D> + Allocator<D>,
{
    lu: OMatrix<T, D, D>,
    pivots: OVector<usize, D>,
    /// The reciprocals of `U`'s diagonal, so that the back substitution multiplies.
    inv_diagonal: OVector<T, D>,
}

impl<T: ComplexField<RealField = f64> + Copy, D: Dim> Lu<T, D>
where
    DefaultAllocator: Allocator<D, D> + Allocator<D>,
{
    /// Storage for the factorisation of an `n × n` matrix, to be filled by [`Lu::factor`].
    pub fn new(n: usize) -> Self {
        let d = D::from_usize(n);
        Lu {
            lu: OMatrix::<T, D, D>::zeros_generic(d, d),
            pivots: OVector::<usize, D>::from_fn_generic(d, nalgebra::Const::<1>, |i, _| i),
            inv_diagonal: OVector::<T, D>::from_element_generic(d, nalgebra::Const::<1>, T::one()),
        }
    }

    /// The storage to write the matrix into before calling [`Lu::factor`].
    pub fn matrix_mut(&mut self) -> &mut OMatrix<T, D, D> {
        &mut self.lu
    }

    /// Factors the matrix held in [`Lu::matrix_mut`] in place. A pivot below `tiny` times the
    /// largest entry of the matrix counts as zero. Entries are compared by `|re| + |im|`, as
    /// LAPACK's complex pivoting does: as good a choice as the modulus, without its square
    /// root.
    pub fn factor(&mut self) -> Result<(), Singular> {
        let n = D::try_to_usize().unwrap_or_else(|| self.lu.nrows());
        // Over the storage slice: nalgebra's matrix iterator costs more than the factorisation
        // of a small matrix.
        let scale = amax_by(self.lu.as_slice(), |x| x.norm1());
        let tiny = f64::EPSILON * 1e-3 * scale.max(f64::MIN_POSITIVE);
        for k in 0..n {
            let (mut p, mut best) = (k, self.lu[(k, k)].norm1());
            for i in k + 1..n {
                let x = self.lu[(i, k)].norm1();
                if x > best {
                    (p, best) = (i, x);
                }
            }
            if best.is_nan() || best <= tiny {
                return Err(Singular { column: k });
            }
            self.pivots[k] = p;
            if p != k {
                // Element by element: nalgebra's `swap_rows` costs more than a small matrix's
                // elimination.
                for j in 0..n {
                    let x = self.lu[(k, j)];
                    self.lu[(k, j)] = self.lu[(p, j)];
                    self.lu[(p, j)] = x;
                }
            }
            let inv_pivot = T::one() / self.lu[(k, k)];
            self.inv_diagonal[k] = inv_pivot;
            for i in k + 1..n {
                let factor = self.lu[(i, k)] * inv_pivot;
                self.lu[(i, k)] = factor;
                for j in k + 1..n {
                    let ukj = self.lu[(k, j)];
                    self.lu[(i, j)] -= factor * ukj;
                }
            }
        }
        Ok(())
    }

    /// Solves `A x = b` in place with the factors.
    pub fn solve(&self, b: &mut OVector<T, D>) {
        self.solve_in(b);
    }

    /// Solves `A x = b` in place with the factors, for `b` of the matrix's size.
    #[inline]
    pub fn solve_slice(&self, b: &mut [T]) {
        // Cut to the matrix's size, which a type of fixed size makes a constant: the
        // substitutions then index without bounds checks.
        let n = D::try_to_usize().unwrap_or_else(|| self.lu.nrows());
        self.solve_in(&mut b[..n]);
    }

    /// Solves `A x = b` in place with the factors, for `b` of the matrix's size, by columns:
    /// each substitution step subtracts a multiple of one contiguous column of the factors,
    /// which suits matrices too large to unroll (the sums run in another order than
    /// [`Lu::solve_slice`]'s, so the two agree to rounding).
    pub fn solve_by_columns(&self, b: &mut [T]) {
        let n = D::try_to_usize().unwrap_or_else(|| self.lu.nrows());
        let b = &mut b[..n];
        let a = self.lu.as_slice();
        for (k, &p) in self.pivots.iter().enumerate() {
            b.swap(k, p);
        }
        for (j, column) in a.chunks_exact(n).enumerate() {
            let (head, tail) = b.split_at_mut(j + 1);
            let bj = head[j];
            for (bi, &l) in tail.iter_mut().zip(&column[j + 1..]) {
                *bi -= l * bj;
            }
        }
        for (j, column) in a.chunks_exact(n).enumerate().rev() {
            let (head, tail) = b.split_at_mut(j);
            let bj = tail[0] * self.inv_diagonal[j];
            tail[0] = bj;
            for (bi, &u) in head.iter_mut().zip(&column[..j]) {
                *bi -= u * bj;
            }
        }
    }

    /// The substitutions, over any indexable `b`: a stack vector keeps its length known to the
    /// compiler, which then unrolls the loops.
    #[inline(always)]
    fn solve_in<B: core::ops::IndexMut<usize, Output = T> + ?Sized>(&self, b: &mut B) {
        let n = D::try_to_usize().unwrap_or_else(|| self.lu.nrows());
        for k in 0..n {
            let p = self.pivots[k];
            if p != k {
                let x = b[k];
                b[k] = b[p];
                b[p] = x;
            }
        }
        for i in 0..n {
            let mut s = b[i];
            for j in 0..i {
                s -= self.lu[(i, j)] * b[j];
            }
            b[i] = s;
        }
        for i in (0..n).rev() {
            let mut s = b[i];
            for j in i + 1..n {
                s -= self.lu[(i, j)] * b[j];
            }
            b[i] = s * self.inv_diagonal[i];
        }
    }
}

#[cfg(test)]
mod tests {
    use nalgebra::{Complex, Const, Matrix3, Vector3};

    use super::*;

    /// A system whose solution was chosen first: b = A x for x = (1, −2, 3).
    #[test]
    fn solves_real_systems_with_pivoting() {
        let a = Matrix3::new(0.0, 2.0, 1.0, 1.0, 1.0, 0.0, 3.0, 0.0, 1.0);
        let x = Vector3::new(1.0, -2.0, 3.0);
        let mut b = a * x;
        let mut lu = Lu::<f64, Const<3>>::new(3);
        lu.matrix_mut().copy_from(&a);
        lu.factor().expect("nonsingular");
        lu.solve(&mut b);
        assert!((b - x).amax() < 1e-14);
    }

    /// The column-oriented substitutions solve the same system, to rounding.
    #[test]
    fn solves_by_columns_with_pivoting() {
        let a = Matrix3::new(0.0, 2.0, 1.0, 1.0, 1.0, 0.0, 3.0, 0.0, 1.0);
        let x = Vector3::new(1.0, -2.0, 3.0);
        let mut b = a * x;
        let mut lu = Lu::<f64, nalgebra::Dyn>::new(3);
        lu.matrix_mut().copy_from(&a);
        lu.factor().expect("nonsingular");
        lu.solve_by_columns(b.as_mut_slice());
        assert!((b - x).amax() < 1e-14);
    }

    #[test]
    fn solves_complex_systems() {
        let c = |re, im| Complex::new(re, im);
        let a = Matrix3::new(
            c(1.0, 1.0),
            c(2.0, 0.0),
            c(0.0, 0.0),
            c(0.0, -1.0),
            c(1.0, 0.0),
            c(3.0, 2.0),
            c(1.0, 0.0),
            c(0.0, 0.0),
            c(1.0, -1.0),
        );
        let x = Vector3::new(c(1.0, 0.5), c(-2.0, 0.0), c(0.0, 3.0));
        let mut b = a * x;
        let mut lu = Lu::<Complex<f64>, Const<3>>::new(3);
        lu.matrix_mut().copy_from(&a);
        lu.factor().expect("nonsingular");
        lu.solve(&mut b);
        assert!((b - x).iter().all(|d| d.norm() < 1e-14));
    }

    #[test]
    fn reports_singular_matrices() {
        let mut lu = Lu::<f64, Const<3>>::new(3);
        lu.matrix_mut().copy_from(&Matrix3::new(1.0, 2.0, 3.0, 2.0, 4.0, 6.0, 0.0, 0.0, 1.0));
        assert_eq!(lu.factor(), Err(Singular { column: 1 }));
    }
}
