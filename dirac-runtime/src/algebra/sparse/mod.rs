//! Sparse storage, for models made of arrays of subsystems: every block keeps only the values
//! of its structural nonzeros, in the order the model writes them (each subsystem's block,
//! then the interconnection's entries), and every system is factored by a sparse LU whose
//! ordering is computed once. Memory and work grow with the number of nonzeros, linearly in
//! the number of cells of a chain or ladder.

pub(crate) mod lu;
mod saddle;

use std::sync::{Arc, OnceLock};

use nalgebra::{DefaultAllocator, OMatrix};

use self::saddle::SaddleStructure;
pub use self::saddle::SparseSaddle;
use super::condensed::SaddleCondensed;
use super::traits::{Algebra, Scalar};
use crate::shape::dims::{Dimensions, Sizes, Storage};

/// Where the stored values of a sparse block sit: one `(row, column)` per value, in the
/// order the model writes them. An entry may appear more than once; its values add up.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Pattern {
    /// The block's rows.
    pub nrows: usize,
    /// The block's columns.
    pub ncols: usize,
    /// The row of each value.
    pub rows: Vec<usize>,
    /// The column of each value.
    pub cols: Vec<usize>,
}

impl Pattern {
    /// An empty pattern of a block of this size.
    pub fn new(nrows: usize, ncols: usize) -> Pattern {
        Pattern { nrows, ncols, rows: Vec::new(), cols: Vec::new() }
    }

    /// The number of stored values.
    pub fn len(&self) -> usize {
        self.rows.len()
    }

    /// Whether no value is stored.
    pub fn is_empty(&self) -> bool {
        self.rows.is_empty()
    }

    /// Appends the entry `(row, col)`.
    pub fn push(&mut self, row: usize, col: usize) {
        debug_assert!(row < self.nrows && col < self.ncols, "({row}, {col}) outside the block");
        self.rows.push(row);
        self.cols.push(col);
    }

    /// Appends the entries of a dense `rows.len() × ncols` block column by column (nalgebra's
    /// order), at the given rows and at the columns from `col0`.
    pub fn push_dense(&mut self, rows: impl Iterator<Item = usize> + Clone, col0: usize, ncols: usize) {
        for j in 0..ncols {
            for r in rows.clone() {
                self.push(r, col0 + j);
            }
        }
    }
}

/// The sizes and block patterns of a sparse model: what its algebra is built from. Made once
/// by [`LagrangeDirac::shape`](crate::LagrangeDirac::shape) and shared by every block.
///
/// A shape and its clones also share the pattern and ordering of their saddle-point systems,
/// found at the first system made from any of them: a model that keeps its shape and hands
/// out clones of it (as a [`Network`](crate::network::Network) does) has that symbolic
/// analysis done once for its consistent start, its integrators and its analyses together.
#[derive(Clone, Debug)]
pub struct SparseShape {
    /// The model's sizes.
    pub sizes: Sizes,
    /// The pattern of every `n × n` block.
    pub qq: Arc<Pattern>,
    /// The pattern of every `m × n` block.
    pub cq: Arc<Pattern>,
    saddle: SaddleCache,
}

/// The saddle systems' structure of a shape and its clones, once made.
#[derive(Clone, Default)]
struct SaddleCache(Arc<OnceLock<Arc<SaddleStructure>>>);

impl std::ops::Deref for SaddleCache {
    type Target = OnceLock<Arc<SaddleStructure>>;

    fn deref(&self) -> &Self::Target {
        &self.0
    }
}

impl std::fmt::Debug for SaddleCache {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(if self.0.get().is_some() { "SaddleCache(analysed)" } else { "SaddleCache(empty)" })
    }
}

impl SparseShape {
    /// The shape of a model of these sizes with these block patterns.
    pub fn new(sizes: Sizes, qq: Pattern, cq: Pattern) -> SparseShape {
        assert_eq!((qq.nrows, qq.ncols), (sizes.nq, sizes.nq), "an n × n pattern");
        assert_eq!((cq.nrows, cq.ncols), (sizes.nc, sizes.nq), "an m × n pattern");
        SparseShape { sizes, qq: Arc::new(qq), cq: Arc::new(cq), saddle: SaddleCache::default() }
    }
}

/// A block of a sparse model: the values of its pattern's entries.
#[derive(Clone, Debug)]
pub struct SparseBlock {
    pattern: Arc<Pattern>,
    /// The stored values, one per entry of the pattern.
    pub values: Vec<f64>,
}

impl SparseBlock {
    /// A block of zeros with this pattern.
    pub fn zeros(pattern: &Arc<Pattern>) -> SparseBlock {
        SparseBlock { pattern: Arc::clone(pattern), values: vec![0.0; pattern.len()] }
    }

    /// The block's pattern.
    pub fn pattern(&self) -> &Pattern {
        &self.pattern
    }

    /// `y += c A x`.
    fn mul<T: Scalar>(&self, c: T, x: &[T], y: &mut [T]) {
        let p = &*self.pattern;
        for ((&r, &col), &v) in p.rows.iter().zip(&p.cols).zip(&self.values) {
            y[r] += c * x[col].scale(v);
        }
    }

    /// `y += c Aᵀ x`.
    fn tr_mul<T: Scalar>(&self, c: T, x: &[T], y: &mut [T]) {
        let p = &*self.pattern;
        for ((&r, &col), &v) in p.rows.iter().zip(&p.cols).zip(&self.values) {
            y[col] += c * x[r].scale(v);
        }
    }

    fn entries(&self, mut f: impl FnMut(usize, usize, f64)) {
        let p = &*self.pattern;
        for ((&r, &col), &v) in p.rows.iter().zip(&p.cols).zip(&self.values) {
            f(r, col, v);
        }
    }
}

/// Sparse blocks and sparse LU factorisations.
#[derive(Clone, Copy, Debug, Default)]
pub struct Sparse;

impl<M: Dimensions> Algebra<M> for Sparse
where
    DefaultAllocator: Storage<M>,
{
    type Shape = SparseShape;
    type Qq = SparseBlock;
    type Cq = SparseBlock;
    type Saddle<T: Scalar> = SparseSaddle<T>;
    type Condensed = SaddleCondensed<M, Sparse>;

    fn zeros_qq(shape: &SparseShape) -> SparseBlock {
        SparseBlock::zeros(&shape.qq)
    }

    fn zeros_cq(shape: &SparseShape) -> SparseBlock {
        SparseBlock::zeros(&shape.cq)
    }

    fn saddle<T: Scalar>(shape: &SparseShape) -> SparseSaddle<T> {
        SparseSaddle::new(shape)
    }

    fn condensed(shape: &SparseShape) -> SaddleCondensed<M, Sparse> {
        SaddleCondensed::new(shape.sizes, shape)
    }

    fn dense_qq(_: &SparseBlock) -> Option<&OMatrix<f64, M::Nq, M::Nq>> {
        None
    }

    fn dense_cq(_: &SparseBlock) -> Option<&OMatrix<f64, M::Nc, M::Nq>> {
        None
    }

    fn qq_values(a: &SparseBlock) -> &[f64] {
        &a.values
    }

    fn qq_values_mut(a: &mut SparseBlock) -> &mut [f64] {
        &mut a.values
    }

    fn cq_values(a: &SparseBlock) -> &[f64] {
        &a.values
    }

    fn cq_values_mut(a: &mut SparseBlock) -> &mut [f64] {
        &mut a.values
    }

    fn qq_entries(a: &SparseBlock, f: impl FnMut(usize, usize, f64)) {
        a.entries(f);
    }

    fn cq_entries(a: &SparseBlock, f: impl FnMut(usize, usize, f64)) {
        a.entries(f);
    }

    fn qq_mul<T: Scalar>(a: &SparseBlock, c: T, x: &[T], y: &mut [T]) {
        a.mul(c, x, y);
    }

    fn qq_tr_mul<T: Scalar>(a: &SparseBlock, c: T, x: &[T], y: &mut [T]) {
        a.tr_mul(c, x, y);
    }

    fn cq_mul<T: Scalar>(b: &SparseBlock, c: T, x: &[T], y: &mut [T]) {
        b.mul(c, x, y);
    }

    fn cq_tr_mul<T: Scalar>(b: &SparseBlock, c: T, x: &[T], y: &mut [T]) {
        b.tr_mul(c, x, y);
    }
}
