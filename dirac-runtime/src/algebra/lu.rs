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

/// What [`Lu::factor_saddle`] and [`Lu::factor_schur`] keep between factorisations of a
/// system whose multipliers may be redundant: whether some were found so, and an orthonormal
/// basis of the multipliers that act.
///
/// Redundant constraint rows (a closed loop with more rows than it takes away freedoms, a
/// constraint written twice) leave the multipliers determined only up to `N = ker Aᵀ`: the
/// saddle-point matrix is singular in exactly those columns. The factorisation then replaces
/// the zero corner by `−s P` with `P = I − W Wᴴ` the projector onto `N` (`W` an orthonormal
/// basis of the rows' span, read off the rows themselves) and `s` the block's scale, and the
/// rows' equations and right-hand sides by their parts along `W`: the velocities solve the
/// equations of the rows that act, the multipliers' part in `N` is zero (their least norm), and
/// the matrix is regular. The rows' rank is measured at the first factorisation (Gram-Schmidt,
/// twice, a row dependent when less than 1e-11 of its norm is left); where they are independent
/// nothing changes, unless a later factorisation finds the multipliers' columns exactly
/// dependent, or [`Deflation::remeasure`] asks for it (the integrators do at every restart).
/// Once deflating, the same rows (by index) make the basis at every factorisation, so that its
/// rank is the mechanism's, also where the positions drift a little off the loop.
/// A row that is zero by itself (a vanishing one-form) is not deflated: that stays singular.
pub struct Deflation<T: ComplexField, C: Dim>
where
    DefaultAllocator: Allocator<C, C> + Allocator<C>,
{
    basis: OMatrix<T, C, C>,
    /// Work space of [`Deflation::project`] and of the bottom-left block's projection.
    work: OVector<T, C>,
    /// Which multipliers take part (a saddle's with a zero corner; all of a Schur complement's).
    free: OVector<bool, C>,
    /// The rows (coordinates) whose entries make the basis, in order; the first `rank` count.
    picked: OVector<usize, C>,
    /// The number of the basis's columns.
    rank: usize,
    /// Whether the last factorisation was deflated (its rows were dependent).
    deflated: bool,
    /// Unknown before the first factorisation, then whether every factorisation deflates.
    active: Option<bool>,
}

impl<T: ComplexField<RealField = f64> + Copy, C: Dim> Deflation<T, C>
where
    DefaultAllocator: Allocator<C, C> + Allocator<C>,
{
    /// Room for `m` multipliers.
    pub fn new(m: usize) -> Self {
        let c = C::from_usize(m);
        let one = nalgebra::Const::<1>;
        Deflation {
            basis: OMatrix::<T, C, C>::zeros_generic(c, c),
            work: OVector::<T, C>::zeros_generic(c, one),
            free: OVector::<bool, C>::from_element_generic(c, one, true),
            picked: OVector::<usize, C>::from_element_generic(c, one, 0),
            rank: 0,
            deflated: false,
            active: None,
        }
    }

    /// Whether redundant rows have been met, so that every factorisation deflates.
    pub fn active(&self) -> bool {
        self.active == Some(true)
    }

    /// Measures the rows again at the next factorisation, as at the first: the model changed
    /// (a contact closed beside others), and rows found independent may be redundant now.
    /// Rows that turn dependent by round-off leave a pivot of round-off, not the exact zero
    /// that makes an independent set's factorisation measure them again.
    pub fn remeasure(&mut self) {
        self.active = None;
        self.rank = 0;
    }

    /// Replaces `lambda` (the multipliers, or a right-hand side's constraint rows) by its part
    /// along the rows that act, `W Wᴴ λ`, where the last factorisation found the rows
    /// redundant: for multipliers, those of least norm with the same force (to the change of
    /// the rows since that factorisation); for a right-hand side, the part the deflated system
    /// solves exactly. Nothing otherwise. Entries of multipliers that are not free keep their
    /// values.
    // Indexing the basis, the mask and `lambda` by the same `k` reads plainer than three zips.
    #[allow(clippy::needless_range_loop)]
    pub fn project(&mut self, lambda: &mut [T]) {
        if !self.deflated {
            return;
        }
        let m = self.basis.nrows();
        for k in 0..m {
            self.work[k] = if self.free[k] { T::zero() } else { lambda[k] };
        }
        for j in 0..self.rank {
            let mut c = T::zero();
            for k in 0..m {
                c += self.basis[(k, j)].conjugate() * lambda[k];
            }
            for k in 0..m {
                let b = self.basis[(k, j)];
                self.work[k] += b * c;
            }
        }
        lambda[..m].copy_from_slice(self.work.as_slice());
    }

    /// Orthonormalises candidate `i` (its entries `candidate(i, k)` over the free multipliers)
    /// against the basis, twice, into the basis's column `rank`; its norm before and after.
    fn orthogonalise(&mut self, m: usize, i: usize, candidate: &impl Fn(usize, usize) -> T) -> (f64, f64) {
        let (basis, rank) = (&mut self.basis, self.rank);
        for k in 0..m {
            basis[(k, rank)] = if self.free[k] { candidate(i, k).conjugate() } else { T::zero() };
        }
        let before = (0..m).map(|k| basis[(k, rank)].modulus_squared()).sum::<f64>().sqrt();
        for _ in 0..2 {
            for j in 0..rank {
                let mut dot = T::zero();
                for k in 0..m {
                    dot += basis[(k, j)].conjugate() * basis[(k, rank)];
                }
                for k in 0..m {
                    let b = basis[(k, j)];
                    basis[(k, rank)] -= dot * b;
                }
            }
        }
        (before, (0..m).map(|k| basis[(k, rank)].modulus_squared()).sum::<f64>().sqrt())
    }

    /// Takes the orthogonalised candidate `i` in column `rank` into the basis.
    fn accept(&mut self, m: usize, i: usize, norm: f64) {
        let inv = T::from_real(1.0 / norm);
        for k in 0..m {
            self.basis[(k, self.rank)] *= inv;
        }
        self.picked[self.rank] = i;
        self.rank += 1;
    }

    /// Measures the span of the `count` candidates (`candidate(i, k)`: row `i`'s entry in
    /// multiplier `k`) over the multipliers `free` says take part: the picked rows again where
    /// deflating (unless one of them has become dependent), else every row with the rank
    /// threshold. Whether the rows are redundant (and no row vanishes by itself).
    fn measure(
        &mut self,
        m: usize,
        count: usize,
        candidate: impl Fn(usize, usize) -> T,
        free: impl Fn(usize) -> bool,
    ) -> bool {
        let mut free_count = 0;
        for k in 0..m {
            self.free[k] = free(k);
            free_count += usize::from(self.free[k]);
        }
        let kept = self.rank;
        self.rank = 0;
        if self.active == Some(true) && kept > 0 {
            for idx in 0..kept {
                let i = self.picked[idx];
                let (before, after) = self.orthogonalise(m, i, &candidate);
                if !(after > 1e-13 * before && after > 0.0) {
                    self.rank = 0;
                    break;
                }
                self.accept(m, i, after);
            }
        }
        if self.rank == 0 {
            for i in 0..count {
                if self.rank == free_count {
                    break;
                }
                // Dependent when what is left is round-off of the candidate itself, whatever
                // its size: a row of small entries (a coordinate in other units) counts as much
                // as a large one, and a rank is rather overestimated (no deflation) than
                // underestimated.
                let (before, after) = self.orthogonalise(m, i, &candidate);
                if after > 1e-11 * before && after > 0.0 {
                    self.accept(m, i, after);
                }
            }
        }
        self.deflated = self.rank < free_count;
        // A row that is zero by itself (`e_k` in `N`: its one-form vanishes at this state) is
        // not redundant but undetermined: left singular, for the caller to name.
        for k in (0..m).filter(|&k| self.free[k]) {
            let acting: f64 = (0..self.rank).map(|j| self.basis[(k, j)].modulus_squared()).sum();
            if acting < 1e-9 {
                self.deflated = false;
            }
        }
        self.deflated
    }

    /// Deflates the measured system `s`: in a saddle (`saddle`), the bottom-left block's free
    /// rows become their part along `W` and the corner gains `−s P`; in a Schur complement,
    /// `s P` is added.
    fn apply<D: Dim>(&mut self, s: &mut OMatrix<T, D, D>, first: usize, m: usize, saddle: bool)
    where
        DefaultAllocator: Allocator<D, D>,
    {
        let (mut scale, rank) = (0.0f64, self.rank);
        let rows = if saddle { 0..first } else { 0..m };
        for k in (0..m).filter(|&k| self.free[k]) {
            for i in rows.clone() {
                scale = scale.max(s[(i, first + k)].norm1());
            }
        }
        if saddle {
            // The rows' equations along `N` are dependent (or, off the constraints, nearly so);
            // the corner replaces them by `P λ = 0`.
            for j in 0..first {
                for l in 0..rank {
                    let mut c = T::zero();
                    for k in (0..m).filter(|&k| self.free[k]) {
                        c += self.basis[(k, l)].conjugate() * s[(first + k, j)];
                    }
                    self.work[l] = c;
                }
                for k in (0..m).filter(|&k| self.free[k]) {
                    let mut c = T::zero();
                    for l in 0..rank {
                        c += self.basis[(k, l)] * self.work[l];
                    }
                    s[(first + k, j)] = c;
                }
            }
        }
        let scale = if scale > 0.0 { scale } else { 1.0 };
        let shift = if saddle { -scale } else { scale };
        for l in (0..m).filter(|&l| self.free[l]) {
            for k in (0..m).filter(|&k| self.free[k]) {
                let mut p = if k == l { T::one() } else { T::zero() };
                for j in 0..rank {
                    p -= self.basis[(k, j)] * self.basis[(l, j)].conjugate();
                }
                s[(first + k, first + l)] += p.scale(shift);
            }
        }
    }
}

impl<T: ComplexField<RealField = f64> + Copy, D: Dim> Lu<T, D>
where
    DefaultAllocator: Allocator<D, D> + Allocator<D>,
{
    /// Factors a saddle-point matrix whose first `n` unknowns are velocities and whose last
    /// are multipliers, deflating redundant multipliers (see [`Deflation`]). A singular
    /// velocity column, or a vanishing row, is an error as from [`Lu::factor`].
    ///
    /// Rows once found independent cost one [`Lu::factor`]: that path is inlined, the
    /// measurement out of line.
    #[inline]
    pub fn factor_saddle<C: Dim>(&mut self, n: usize, deflation: &mut Deflation<T, C>) -> Result<(), Singular>
    where
        DefaultAllocator: Allocator<C, C> + Allocator<C>,
    {
        let stopped = if deflation.active == Some(false) {
            match self.factor() {
                Err(Singular { column }) if column >= n => Some(column),
                other => {
                    deflation.deflated = false;
                    return other;
                }
            }
        } else {
            None
        };
        self.factor_saddle_measured(n, deflation, stopped)
    }

    /// [`Lu::factor_saddle`] where the rows may be redundant: measured the first time, at
    /// each factorisation once they were, and where the factorisation of rows so far
    /// independent `stopped` at a multiplier's column.
    #[inline(never)]
    fn factor_saddle_measured<C: Dim>(
        &mut self,
        n: usize,
        deflation: &mut Deflation<T, C>,
        stopped: Option<usize>,
    ) -> Result<(), Singular>
    where
        DefaultAllocator: Allocator<C, C> + Allocator<C>,
    {
        let m = D::try_to_usize().unwrap_or_else(|| self.lu.nrows()) - n;
        let measure = |deflation: &mut Deflation<T, C>, s: &OMatrix<T, D, D>| {
            deflation.measure(m, n, |i, k| s[(i, n + k)], |k| s[(n + k, n + k)] == T::zero())
        };
        if let Some(column) = stopped {
            self.restore(column);
            deflation.active = Some(true);
            measure(deflation, &self.lu);
        } else if deflation.active.is_none() {
            let redundant = measure(deflation, &self.lu);
            deflation.active = Some(redundant);
        } else {
            measure(deflation, &self.lu);
        }
        if deflation.deflated {
            deflation.apply(&mut self.lu, n, m, true);
        }
        self.factor()
    }

    /// Factors a Schur complement `B M⁻¹ Aᵀ` of `m` constraint rows, deflating it where the
    /// rows are redundant (see [`Deflation`]): `rows = (n, a)` gives their `n` columns,
    /// `a(i, k)` the entry of row `k` at coordinate `i` of `A`, whose span it measures.
    ///
    /// Rows once found independent cost one [`Lu::factor`]: that path is inlined, the
    /// measurement out of line.
    #[inline]
    pub fn factor_schur<C: Dim>(
        &mut self,
        deflation: &mut Deflation<T, C>,
        rows: (usize, impl Fn(usize, usize) -> T),
    ) -> Result<(), Singular>
    where
        DefaultAllocator: Allocator<C, C> + Allocator<C>,
    {
        if deflation.active == Some(false) {
            deflation.deflated = false;
            return self.factor();
        }
        self.factor_schur_measured(deflation, rows)
    }

    /// [`Lu::factor_schur`] where the rows may be redundant.
    #[inline(never)]
    fn factor_schur_measured<C: Dim>(
        &mut self,
        deflation: &mut Deflation<T, C>,
        (n, a): (usize, impl Fn(usize, usize) -> T),
    ) -> Result<(), Singular>
    where
        DefaultAllocator: Allocator<C, C> + Allocator<C>,
    {
        let m = D::try_to_usize().unwrap_or_else(|| self.lu.nrows());
        let redundant = deflation.measure(m, n, a, |_| true);
        if deflation.active.is_none() {
            deflation.active = Some(redundant);
        }
        if deflation.deflated {
            deflation.apply(&mut self.lu, 0, m, false);
        }
        self.factor()
    }

    /// Undoes the first `steps` elimination steps of a factorisation that stopped there, in
    /// reverse order, which gives back the matrix it started from (to rounding).
    fn restore(&mut self, steps: usize) {
        let n = D::try_to_usize().unwrap_or_else(|| self.lu.nrows());
        for l in (0..steps).rev() {
            for i in l + 1..n {
                let factor = self.lu[(i, l)];
                for j in l + 1..n {
                    let ulj = self.lu[(l, j)];
                    self.lu[(i, j)] += factor * ulj;
                }
                self.lu[(i, l)] = factor * self.lu[(l, l)];
            }
            let p = self.pivots[l];
            if p != l {
                for j in 0..n {
                    let x = self.lu[(l, j)];
                    self.lu[(l, j)] = self.lu[(p, j)];
                    self.lu[(p, j)] = x;
                }
            }
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

    /// `[H Aᵀ; A 0]` with the third row of `A` the sum of the first two, and a right-hand side
    /// whose rows agree (`g = A x₀`).
    fn redundant_saddle()
    -> (nalgebra::DMatrix<f64>, nalgebra::DMatrix<f64>, nalgebra::DMatrix<f64>, nalgebra::DVector<f64>) {
        let h = nalgebra::DMatrix::from_row_slice(3, 3, &[4.0, 1.0, 0.5, 1.0, 3.0, 0.2, 0.5, 0.2, 2.0]);
        let a = nalgebra::DMatrix::from_row_slice(3, 3, &[1.0, 2.0, 0.0, 0.0, 1.0, -1.0, 1.0, 3.0, -1.0]);
        let mut k = nalgebra::DMatrix::zeros(6, 6);
        k.view_mut((0, 0), (3, 3)).copy_from(&h);
        k.view_mut((0, 3), (3, 3)).copy_from(&a.transpose());
        k.view_mut((3, 0), (3, 3)).copy_from(&a);
        let x0 = nalgebra::DVector::from_row_slice(&[0.3, -0.7, 1.1]);
        let g = &a * &x0;
        let b = nalgebra::DVector::from_row_slice(&[1.0, -2.0, 0.5, g[0], g[1], g[2]]);
        (h, a, k, b)
    }

    /// The reference: the velocities from the first two rows alone (a regular system, solved by
    /// nalgebra's LU), the multipliers of least norm from the pseudo-inverse of `Aᵀ`.
    fn least_norm_reference(
        h: &nalgebra::DMatrix<f64>,
        a: &nalgebra::DMatrix<f64>,
        b: &nalgebra::DVector<f64>,
    ) -> nalgebra::DVector<f64> {
        let two = a.rows(0, 2).into_owned();
        let mut k = nalgebra::DMatrix::zeros(5, 5);
        k.view_mut((0, 0), (3, 3)).copy_from(h);
        k.view_mut((0, 3), (3, 2)).copy_from(&two.transpose());
        k.view_mut((3, 0), (2, 3)).copy_from(&two);
        let rhs = nalgebra::DVector::from_row_slice(&[b[0], b[1], b[2], b[3], b[4]]);
        let x = k.lu().solve(&rhs).expect("regular").rows(0, 3).into_owned();
        let force = b.rows(0, 3) - h * &x;
        let lambda = a.transpose().pseudo_inverse(1e-12).expect("an SVD") * force;
        nalgebra::DVector::from_iterator(6, x.iter().chain(lambda.iter()).copied())
    }

    #[test]
    fn deflates_redundant_multipliers_to_their_least_norm() {
        let (h, a, k, b) = redundant_saddle();
        let reference = least_norm_reference(&h, &a, &b);
        // Measured at the first factorisation; kept at the next.
        let mut lu = Lu::<f64, nalgebra::Dyn>::new(6);
        let mut deflation = Deflation::<f64, nalgebra::Dyn>::new(3);
        for _ in 0..2 {
            lu.matrix_mut().copy_from(&k);
            lu.factor_saddle(3, &mut deflation).expect("deflated");
            assert!(deflation.active());
            let mut x = b.clone();
            lu.solve_slice(x.as_mut_slice());
            assert!((&x - &reference).amax() < 1e-13, "{x} against {reference}");
        }
    }

    #[test]
    fn deflates_complex_saddles_of_real_rows() {
        // Radau's complex system scales the rows by a complex shift; the multipliers' span is
        // the same.
        let (h, a, _, b) = redundant_saddle();
        let sigma = Complex::new(0.7, 1.3);
        let c = |x: f64| Complex::new(x, 0.0);
        let mut k = nalgebra::DMatrix::<Complex<f64>>::zeros(6, 6);
        for i in 0..3 {
            for j in 0..3 {
                k[(i, j)] = sigma * c(h[(i, j)]);
                k[(i, 3 + j)] = sigma * c(a[(j, i)]);
                k[(3 + i, j)] = sigma * c(a[(i, j)]);
            }
        }
        let rhs: Vec<Complex<f64>> = b.iter().map(|&x| sigma * c(x)).collect();
        let reference = least_norm_reference(&h, &a, &b);
        let mut lu = Lu::<Complex<f64>, nalgebra::Dyn>::new(6);
        let mut deflation = Deflation::<Complex<f64>, nalgebra::Dyn>::new(3);
        lu.matrix_mut().copy_from(&k);
        lu.factor_saddle(3, &mut deflation).expect("deflated");
        let mut x = rhs;
        lu.solve_slice(&mut x);
        // σ K x = σ b: the real solution, the multipliers scaled back by nothing.
        for i in 0..6 {
            assert!((x[i] - c(reference[i])).norm() < 1e-13, "{i}: {} against {}", x[i], reference[i]);
        }
    }

    #[test]
    fn deflates_a_singular_schur_complement() {
        let (h, a, _, b) = redundant_saddle();
        let s = &a * h.clone().try_inverse().expect("regular") * a.transpose();
        let r = b.rows(3, 3).into_owned();
        let mut lu = Lu::<f64, nalgebra::Dyn>::new(3);
        let mut deflation = Deflation::<f64, nalgebra::Dyn>::new(3);
        lu.matrix_mut().copy_from(&s);
        lu.factor_schur(&mut deflation, (3, |i, k| a[(k, i)])).expect("deflated");
        let mut x = r.clone();
        deflation.project(x.as_mut_slice());
        lu.solve_slice(x.as_mut_slice());
        // The least-norm solution of the consistent singular system, by the pseudo-inverse.
        let reference = s.pseudo_inverse(1e-10).expect("an SVD") * r;
        assert!((&x - &reference).amax() < 1e-12, "{x} against {reference}");
    }

    #[test]
    fn measures_again_rows_that_turned_dependent() {
        // First factored with independent rows (the third row off the span of the others),
        // then, asked to measure again, with the redundant ones: a contact that closed beside
        // others, at the restart after it.
        let (h, a, k, b) = redundant_saddle();
        let mut independent = k.clone();
        independent[(5, 2)] += 0.5;
        independent[(2, 5)] += 0.5;
        let mut lu = Lu::<f64, nalgebra::Dyn>::new(6);
        let mut deflation = Deflation::<f64, nalgebra::Dyn>::new(3);
        lu.matrix_mut().copy_from(&independent);
        lu.factor_saddle(3, &mut deflation).expect("regular");
        assert!(!deflation.active());
        deflation.remeasure();
        lu.matrix_mut().copy_from(&k);
        lu.factor_saddle(3, &mut deflation).expect("deflated");
        assert!(deflation.active());
        let mut x = b.as_slice().to_vec();
        lu.solve_slice(&mut x);
        let reference = least_norm_reference(&h, &a, &b);
        for i in 0..6 {
            assert!((x[i] - reference[i]).abs() < 1e-12, "{i}: {} against {}", x[i], reference[i]);
        }
    }

    #[test]
    fn leaves_a_vanishing_row_singular() {
        // The third row zero by itself: its multiplier is undetermined, not redundant.
        let (_, mut a, _, _) = redundant_saddle();
        a.row_mut(2).fill(0.0);
        let mut k = nalgebra::DMatrix::zeros(6, 6);
        k.view_mut((0, 0), (3, 3)).fill_with_identity();
        k.view_mut((0, 3), (3, 3)).copy_from(&a.transpose());
        k.view_mut((3, 0), (3, 3)).copy_from(&a);
        let mut lu = Lu::<f64, nalgebra::Dyn>::new(6);
        let mut deflation = Deflation::<f64, nalgebra::Dyn>::new(3);
        lu.matrix_mut().copy_from(&k);
        assert_eq!(lu.factor_saddle(3, &mut deflation), Err(Singular { column: 5 }));
        assert!(!deflation.active());
    }

    #[test]
    fn restores_a_matrix_whose_factorisation_stopped() {
        let (_, _, k, _) = redundant_saddle();
        let mut lu = Lu::<f64, nalgebra::Dyn>::new(6);
        lu.matrix_mut().copy_from(&k);
        // A matrix whose last column is zero stops there after five full steps.
        let mut k = k;
        k.column_mut(5).fill(0.0);
        lu.matrix_mut().copy_from(&k);
        let Err(Singular { column }) = lu.factor() else { panic!("the last column has no pivot") };
        assert_eq!(column, 5);
        lu.restore(column);
        assert!((lu.matrix_mut().clone() - &k).amax() < 1e-15);
    }

    #[test]
    fn reports_singular_matrices() {
        let mut lu = Lu::<f64, Const<3>>::new(3);
        lu.matrix_mut().copy_from(&Matrix3::new(1.0, 2.0, 3.0, 2.0, 4.0, 6.0, 0.0, 0.0, 1.0));
        assert_eq!(lu.factor(), Err(Singular { column: 1 }));
    }
}
