//! Sparse LU with partial pivoting, for matrices whose pattern is fixed and whose values
//! change: faer orders the columns once (COLAMD) and finds the pivots (its Gilbert–Peierls
//! factorisation); every later factorisation reuses those pivots and the pattern of the
//! factors and only recomputes values, as KLU's refactorisation does. A refactorisation
//! allocates nothing; when a reused pivot has become too small against its column, the
//! pivots are found anew.

use std::sync::Arc;

use faer::dyn_stack::{MemBuffer, MemStack, StackReq};
use faer::perm::PermRef;
use faer::sparse::linalg::colamd;
use faer::sparse::linalg::lu::simplicial::{
    SimplicialLu, factorize_simplicial_numeric_lu, factorize_simplicial_numeric_lu_scratch,
};
use faer::sparse::{SparseColMatRef, SymbolicSparseColMatRef};

use crate::algebra::lu::Singular;
use crate::algebra::traits::Scalar;

/// A reused pivot smaller than this fraction of the largest entry below it in its column
/// calls for new pivots.
const PIVOT_TOLERANCE: f64 = 1e-3;

/// The factors `P A Q = L U` of a square sparse matrix with a fixed pattern.
/// A square matrix's pattern (compressed columns) and its fill-reducing column ordering:
/// computed once, and shared by every factorisation of a matrix with this pattern.
pub(crate) struct Ordering {
    n: usize,
    col_ptr: Vec<usize>,
    row_idx: Vec<usize>,
    col_perm: Vec<usize>,
    col_perm_inv: Vec<usize>,
}

impl Ordering {
    /// The ordering of the `n × n` pattern with these column starts and sorted rows.
    pub fn new(n: usize, col_ptr: Vec<usize>, row_idx: Vec<usize>) -> Self {
        let symbolic = SymbolicSparseColMatRef::new_checked(n, n, &col_ptr, None, &row_idx);
        let (mut col_perm, mut col_perm_inv) = (vec![0usize; n], vec![0usize; n]);
        let mut memory = MemBuffer::new(colamd::order_scratch::<usize>(n, n, row_idx.len()));
        colamd::order(
            &mut col_perm,
            &mut col_perm_inv,
            symbolic,
            colamd::Control::default(),
            MemStack::new(&mut memory),
        )
        .expect("the ordering's work space was sized for it");
        Ordering { n, col_ptr, row_idx, col_perm, col_perm_inv }
    }
}

pub(crate) struct SparseLu<T: Scalar> {
    n: usize,
    order: Arc<Ordering>,
    pub values: Vec<T>,
    row_perm: Vec<usize>,
    row_step: Vec<usize>,
    l_ptr: Vec<usize>,
    l_row: Vec<usize>,
    l_val: Vec<T>,
    u_ptr: Vec<usize>,
    u_row: Vec<usize>,
    u_val: Vec<T>,
    u_diag: Vec<T>,
    work: Vec<T>,
    pivoted: bool,
    faer_lu: SimplicialLu<usize, T>,
    faer_rows: (Vec<usize>, Vec<usize>),
    memory: MemBuffer,
    pub pivotings: usize,
}

impl<T: Scalar> SparseLu<T> {
    /// A factorisation of matrices with this pattern and ordering.
    pub fn new(order: Arc<Ordering>) -> Self {
        let n = order.n;
        let memory = MemBuffer::new(StackReq::any_of(&[
            factorize_simplicial_numeric_lu_scratch::<usize, T>(n, n),
            StackReq::new::<T>(n),
        ]));
        SparseLu {
            n,
            values: vec![T::zero(); order.row_idx.len()],
            order,
            row_perm: vec![0; n],
            row_step: vec![0; n],
            l_ptr: vec![0; n + 1],
            l_row: Vec::new(),
            l_val: Vec::new(),
            u_ptr: vec![0; n + 1],
            u_row: Vec::new(),
            u_val: Vec::new(),
            u_diag: vec![T::zero(); n],
            work: vec![T::zero(); n],
            pivoted: false,
            faer_lu: SimplicialLu::new(),
            faer_rows: (vec![0; n], vec![0; n]),
            memory,
            pivotings: 0,
        }
    }

    pub fn row_idx(&self) -> &[usize] {
        &self.order.row_idx
    }

    /// The pattern's rows (column by column) and the values to factor, written in their order.
    pub fn pattern_and_values(&mut self) -> (&[usize], &mut [T]) {
        (&self.order.row_idx, &mut self.values)
    }

    /// Factors the matrix held in `values`: with the last pivots when they still serve, else
    /// with new ones. A pivot below `ε · 10⁻³` times the largest entry is a zero one.
    pub fn factor(&mut self) -> Result<(), Singular> {
        let scale = self.values.iter().fold(0.0f64, |m, x| m.max(x.modulus()));
        let tiny = f64::EPSILON * 1e-3 * scale.max(f64::MIN_POSITIVE);
        if self.pivoted && self.refactor() {
            return self.check_pivots(tiny);
        }
        self.pivot()?;
        self.check_pivots(tiny)
    }

    /// The unknown (original column) whose pivot is zero or not a number, if any.
    fn check_pivots(&self, tiny: f64) -> Result<(), Singular> {
        match self.u_diag.iter().position(|d| d.modulus().is_nan() || d.modulus() <= tiny) {
            Some(j) => Err(Singular { column: self.order.col_perm[j] }),
            None => Ok(()),
        }
    }

    /// Finds pivots with faer's factorisation and takes its factors over.
    fn pivot(&mut self) -> Result<(), Singular> {
        self.pivotings += 1;
        self.pivoted = false;
        let n = self.n;
        let order = &*self.order;
        let symbolic = SymbolicSparseColMatRef::new_checked(n, n, &order.col_ptr, None, &order.row_idx);
        let a = SparseColMatRef::new(symbolic, &self.values);
        let col_perm = PermRef::new_checked(&order.col_perm, &order.col_perm_inv, n);
        let (fwd, inv) = &mut self.faer_rows;
        let result = factorize_simplicial_numeric_lu(
            fwd,
            inv,
            &mut self.faer_lu,
            a,
            col_perm,
            MemStack::new(&mut self.memory),
        );
        if let Err(e) = result {
            let column = match e {
                faer::sparse::linalg::LuError::SymbolicSingular { index } => order.col_perm[index],
                faer::sparse::linalg::LuError::Generic(_) => 0,
            };
            return Err(Singular { column });
        }
        self.take_factors();
        self.pivoted = true;
        Ok(())
    }

    /// Copies faer's factors into this factorisation's own storage, `U`'s rows sorted.
    fn take_factors(&mut self) {
        let n = self.n;
        self.row_perm.copy_from_slice(&self.faer_rows.0);
        self.row_step.copy_from_slice(&self.faer_rows.1);
        let (l, u) = (self.faer_lu.l_factor_unsorted(), self.faer_lu.u_factor_unsorted());
        self.l_row.clear();
        self.l_val.clear();
        self.u_row.clear();
        self.u_val.clear();
        let mut column: Vec<(usize, T)> = Vec::new();
        for j in 0..n {
            // L's first entry in a column is its unit diagonal.
            let (rows, vals) = (l.row_idx_of_col_raw(j), l.val_of_col(j));
            for (&i, &x) in rows.iter().zip(vals).skip(1) {
                self.l_row.push(i);
                self.l_val.push(x);
            }
            self.l_ptr[j + 1] = self.l_row.len();
            // U's last entry in a column is its diagonal.
            let (rows, vals) = (u.row_idx_of_col_raw(j), u.val_of_col(j));
            let last = rows.len() - 1;
            column.clear();
            column.extend(rows[..last].iter().copied().zip(vals[..last].iter().copied()));
            column.sort_unstable_by_key(|(i, _)| *i);
            for &(i, x) in &column {
                self.u_row.push(i);
                self.u_val.push(x);
            }
            self.u_ptr[j + 1] = self.u_row.len();
            self.u_diag[j] = vals[last];
        }
    }

    /// Recomputes the factors' values with the last pivots and patterns (left-looking, by
    /// column); false if a pivot has become too small, leaving the factors unusable.
    fn refactor(&mut self) -> bool {
        let (x, order) = (&mut self.work, &*self.order);
        for j in 0..self.n {
            let c = order.col_perm[j];
            for p in order.col_ptr[c]..order.col_ptr[c + 1] {
                x[self.row_step[order.row_idx[p]]] = self.values[p];
            }
            for p in self.u_ptr[j]..self.u_ptr[j + 1] {
                let k = self.u_row[p];
                let xk = x[k];
                for q in self.l_ptr[k]..self.l_ptr[k + 1] {
                    x[self.l_row[q]] -= self.l_val[q] * xk;
                }
                self.u_val[p] = xk;
                x[k] = T::zero();
            }
            let pivot = x[j];
            x[j] = T::zero();
            let mut largest = 0.0f64;
            for q in self.l_ptr[j]..self.l_ptr[j + 1] {
                let i = self.l_row[q];
                largest = largest.max(x[i].modulus());
                self.l_val[q] = x[i] / pivot;
                x[i] = T::zero();
            }
            self.u_diag[j] = pivot;
            let usable = pivot.modulus() >= PIVOT_TOLERANCE * largest;
            if !usable || !pivot.modulus().is_finite() {
                // The work column is clean again: every entry touched was zeroed.
                return false;
            }
        }
        true
    }

    /// Replaces `b` by the solution of `A x = b`.
    pub fn solve(&mut self, b: &mut [T]) {
        let n = self.n;
        let y = &mut self.work;
        for k in 0..n {
            y[k] = b[self.row_perm[k]];
        }
        for k in 0..n {
            let yk = y[k];
            for q in self.l_ptr[k]..self.l_ptr[k + 1] {
                y[self.l_row[q]] -= self.l_val[q] * yk;
            }
        }
        for k in (0..n).rev() {
            let yk = y[k] / self.u_diag[k];
            y[k] = yk;
            for p in self.u_ptr[k]..self.u_ptr[k + 1] {
                y[self.u_row[p]] -= self.u_val[p] * yk;
            }
        }
        for k in 0..n {
            b[self.order.col_perm[k]] = y[k];
            y[k] = T::zero();
        }
    }
}
