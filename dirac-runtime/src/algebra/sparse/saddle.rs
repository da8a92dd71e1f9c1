//! A saddle-point system of a sparse model: its pattern (the `n × n` entries with their
//! transposes and the diagonal, the `m × n` entries below and transposed to the right, the
//! corner's diagonal) built once, with the position of every block value in it, so that
//! assembling is one pass over the blocks' values.

use std::sync::Arc;

use super::lu::{Ordering, SparseLu};
use super::{Pattern, Sparse, SparseShape};
use crate::algebra::lu::Singular;
use crate::algebra::traits::{Saddle, SaddleTerms, Scalar};
use crate::shape::dims::{Dimensions, Sizes, Storage};
use nalgebra::DefaultAllocator;

/// A sparse saddle-point system with scalars `T`.
pub struct SparseSaddle<T: Scalar> {
    sizes: Sizes,
    lu: SparseLu<T>,
    structure: Arc<SaddleStructure>,
    /// The `m × n` pattern.
    cq: Arc<Pattern>,
}

/// What every saddle system of one shape has in common, computed once per shape (see
/// [`SparseShape`]) and shared by the systems of its integrators and analyses, real and
/// complex: the pattern and its ordering, and where each block value goes in it.
pub(crate) struct SaddleStructure {
    /// What it was made from: a shape whose public fields were changed after its structure
    /// was made gets one of its own.
    made_from: (Sizes, Arc<Pattern>, Arc<Pattern>),
    order: Arc<Ordering>,
    /// Where each `n × n` value goes, and where its transpose goes.
    qq_at: Vec<usize>,
    qq_transposed_at: Vec<usize>,
    /// Where each diagonal entry of the top-left block is.
    diagonal_at: Vec<usize>,
    /// Where each `m × n` value goes below and to the right.
    bottom_at: Vec<usize>,
    right_at: Vec<usize>,
    /// Where each diagonal entry of the corner is.
    corner_at: Vec<usize>,
}

/// The compressed columns of the entries `(col, row)`: column starts and sorted, distinct rows.
/// Bucketed by column first (a counting sort), then each short column sorted: linear in the
/// entries but for the columns' own lengths, where sorting every pair cost `O(e log e)`.
fn compress(k: usize, entries: Vec<(usize, usize)>) -> (Vec<usize>, Vec<usize>) {
    let mut start = vec![0; k + 1];
    for &(c, _) in &entries {
        start[c + 1] += 1;
    }
    for c in 0..k {
        start[c + 1] += start[c];
    }
    let (mut rows, mut fill) = (vec![0; entries.len()], start.clone());
    for (c, r) in entries {
        rows[fill[c]] = r;
        fill[c] += 1;
    }
    let mut col_ptr = vec![0; k + 1];
    let mut row_idx = Vec::with_capacity(rows.len());
    for c in 0..k {
        let column = &mut rows[start[c]..start[c + 1]];
        column.sort_unstable();
        let first = row_idx.len();
        for &r in column.iter() {
            if row_idx.len() == first || row_idx.last() != Some(&r) {
                row_idx.push(r);
            }
        }
        col_ptr[c + 1] = row_idx.len();
    }
    (col_ptr, row_idx)
}

impl SaddleStructure {
    /// The structure of the saddle systems of a model of this shape.
    fn new(shape: &SparseShape) -> Self {
        let sizes = shape.sizes;
        let (n, m, k) = (sizes.nq, sizes.nc, sizes.nk());
        let (qq, cq) = (&*shape.qq, &*shape.cq);
        // Entries as (column, row), to be sorted by column.
        let mut entries = Vec::with_capacity(2 * qq.len() + 2 * cq.len() + k);
        for (&i, &j) in qq.rows.iter().zip(&qq.cols) {
            entries.push((j, i));
            entries.push((i, j));
        }
        entries.extend((0..k).map(|i| (i, i)));
        for (&r, &c) in cq.rows.iter().zip(&cq.cols) {
            entries.push((c, n + r));
            entries.push((n + r, c));
        }
        let (col_ptr, row_idx) = compress(k, entries);
        let at = |row: usize, col: usize| -> usize {
            let rows = &row_idx[col_ptr[col]..col_ptr[col + 1]];
            col_ptr[col] + rows.binary_search(&row).expect("every entry is in the pattern")
        };
        let qq_at = qq.rows.iter().zip(&qq.cols).map(|(&i, &j)| at(i, j)).collect();
        let qq_transposed_at = qq.rows.iter().zip(&qq.cols).map(|(&i, &j)| at(j, i)).collect();
        let diagonal_at = (0..n).map(|i| at(i, i)).collect();
        let bottom_at = cq.rows.iter().zip(&cq.cols).map(|(&r, &c)| at(n + r, c)).collect();
        let right_at = cq.rows.iter().zip(&cq.cols).map(|(&r, &c)| at(c, n + r)).collect();
        let corner_at = (0..m).map(|r| at(n + r, n + r)).collect();
        SaddleStructure {
            made_from: (sizes, Arc::clone(&shape.qq), Arc::clone(&shape.cq)),
            order: Arc::new(Ordering::new(k, col_ptr, row_idx)),
            qq_at,
            qq_transposed_at,
            diagonal_at,
            bottom_at,
            right_at,
            corner_at,
        }
    }
}

impl<T: Scalar> SparseSaddle<T> {
    /// The system of a model of this shape, with its column ordering: the shape's structure,
    /// made at the first system of the shape (or of a clone of it) and shared by the others.
    pub fn new(shape: &SparseShape) -> Self {
        let shared = shape.saddle.get_or_init(|| Arc::new(SaddleStructure::new(shape)));
        let (sizes, qq, cq) = &shared.made_from;
        let structure = if *sizes == shape.sizes && Arc::ptr_eq(qq, &shape.qq) && Arc::ptr_eq(cq, &shape.cq) {
            Arc::clone(shared)
        } else {
            Arc::new(SaddleStructure::new(shape))
        };
        SparseSaddle {
            sizes: shape.sizes,
            lu: SparseLu::new(Arc::clone(&structure.order)),
            structure,
            cq: Arc::clone(&shape.cq),
        }
    }

    /// Whether `other` was built on the same structure (pattern and ordering) as this one.
    #[cfg(test)]
    pub(crate) fn shares_structure_with<U: Scalar>(&self, other: &SparseSaddle<U>) -> bool {
        Arc::ptr_eq(&self.structure, &other.structure)
    }

    /// How many times the factorisation had to find pivots (once at the first factorisation;
    /// again only when the reused ones had become too small).
    pub fn pivotings(&self) -> usize {
        self.lu.pivotings
    }

    /// The number of stored entries of the system.
    pub fn nonzeros(&self) -> usize {
        self.lu.row_idx().len()
    }
}

impl<M: Dimensions, T: Scalar> Saddle<M, Sparse, T> for SparseSaddle<T>
where
    DefaultAllocator: Storage<M>,
{
    fn assemble(&mut self, terms: &SaddleTerms<'_, M, Sparse, T>) {
        let v = &mut self.lu.values;
        v.fill(T::zero());
        for &(c, x) in terms.top {
            for (&at, &value) in self.structure.qq_at.iter().zip(&x.values) {
                v[at] += c.scale(value);
            }
        }
        for &(c, x) in terms.top_transposed {
            for (&at, &value) in self.structure.qq_transposed_at.iter().zip(&x.values) {
                v[at] += c.scale(value);
            }
        }
        for &at in &self.structure.diagonal_at {
            v[at] += terms.identity;
        }
        for &(c, b) in terms.right {
            for (&at, &value) in self.structure.right_at.iter().zip(&b.values) {
                v[at] += c.scale(value);
            }
        }
        let nh = self.sizes.nh;
        for &(ch, co, b) in terms.bottom {
            for ((&at, &value), &row) in self.structure.bottom_at.iter().zip(&b.values).zip(&self.cq.rows) {
                v[at] += (if row < nh { ch } else { co }).scale(value);
            }
        }
        for (r, &at) in self.structure.corner_at.iter().enumerate() {
            v[at] = if r < nh { terms.corner.0 } else { terms.corner.1 };
        }
    }

    fn factor(&mut self) -> Result<(), Singular> {
        self.lu.factor()
    }

    fn solve(&mut self, x: &mut [T]) {
        self.lu.solve(x);
    }
}
