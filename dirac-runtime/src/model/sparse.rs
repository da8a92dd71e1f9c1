//! The flat Jacobian in compressed sparse columns.

use nalgebra::DefaultAllocator;

use crate::model::lagrange_dirac::LagrangeDirac;
use crate::shape::dims::{Storage, VecY};

/// The flat Jacobian `∂f/∂y` in compressed sparse columns, for sparse linear algebra and for
/// callers that keep only the nonzeros. `#[derive(LagrangeDirac)]` implements it: the pattern
/// is every entry that is not structurally zero, and
/// [`jacobian_csc`](SparseJacobian::jacobian_csc) writes exactly those values, column by
/// column, with no zeroing and no scatter into a dense matrix.
///
/// The facade's guide (`dirac::guide`, "The equations without an integrator") has a runnable
/// example.
pub trait SparseJacobian: LagrangeDirac
where
    DefaultAllocator: Storage<Self>,
{
    /// Where each column's entries start in [`JACOBIAN_ROW_INDICES`](Self::JACOBIAN_ROW_INDICES);
    /// `NY + 1` entries, the last one the number of stored entries.
    const JACOBIAN_COLUMN_STARTS: &'static [usize];
    /// The row of each stored entry, column by column, increasing within a column.
    const JACOBIAN_ROW_INDICES: &'static [usize];

    /// Writes the stored entries of `∂f/∂y` at `(t, y)` into `values`, in the order of
    /// [`JACOBIAN_ROW_INDICES`](Self::JACOBIAN_ROW_INDICES).
    ///
    /// # Panics
    ///
    /// If `values.len()` is not the number of stored entries.
    fn jacobian_csc(&self, t: f64, y: &VecY<Self>, values: &mut [f64]);
}
