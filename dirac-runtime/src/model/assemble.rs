//! Moving a subsystem's vectors and blocks in and out of its composite, for code that
//! `#[derive(Interconnection)]` generates. Not part of the public API.
//!
//! A subsystem occupies a contiguous range of the composite's coordinates starting at
//! `Offsets::q`; its holonomic constraint rows start at `Offsets::h` and its other rows at
//! `Offsets::v` (holonomic rows of every subsystem come first in a composite).

use nalgebra::DefaultAllocator;

use nalgebra::OMatrix;

use crate::model::Named;
use crate::model::blocks::ResidualBlocks;
use crate::shape::dims::{Dimensions, Fixed, Storage, VecC, VecH, VecQ};

/// A dense `n × n` block of a model of fixed size.
type Qq<M> = OMatrix<f64, <M as Dimensions>::Nq, <M as Dimensions>::Nq>;
/// A dense `m × n` block of a model of fixed size.
type Cq<M> = OMatrix<f64, <M as Dimensions>::Nc, <M as Dimensions>::Nq>;

/// Where a subsystem sits in its composite.
#[derive(Clone, Copy, Debug)]
pub struct Offsets {
    /// First coordinate.
    pub q: usize,
    /// First holonomic constraint row.
    pub h: usize,
    /// First other constraint row.
    pub v: usize,
}

impl Offsets {
    /// The composite row of the subsystem's constraint row `r`.
    pub fn row<S: Fixed>(&self, r: usize) -> usize {
        if r < S::NH { self.h + r } else { self.v + (r - S::NH) }
    }
}

/// The subsystem's part of a composite vector of coordinates.
pub fn gather_q<S: Fixed, C: Dimensions>(x: &VecQ<C>, slot: &Offsets) -> VecQ<S>
where
    DefaultAllocator: Storage<S> + Storage<C>,
{
    let mut out = S::SIZES.zeros_q::<S>();
    for i in 0..S::NQ {
        out[i] = x[slot.q + i];
    }
    out
}

/// The subsystem's part of a composite vector of multipliers.
pub fn gather_c<S: Fixed, C: Dimensions>(x: &VecC<C>, slot: &Offsets) -> VecC<S>
where
    DefaultAllocator: Storage<S> + Storage<C>,
{
    let mut out = S::SIZES.zeros_c::<S>();
    for r in 0..S::NC {
        out[r] = x[slot.row::<S>(r)];
    }
    out
}

/// The subsystem's part of a composite vector of holonomic constraint values.
pub fn gather_h<S: Fixed, C: Dimensions>(x: &VecH<C>, slot: &Offsets) -> VecH<S>
where
    DefaultAllocator: Storage<S> + Storage<C>,
{
    let mut out = S::SIZES.zeros_h::<S>();
    for r in 0..S::NH {
        out[r] = x[slot.h + r];
    }
    out
}

/// The subsystem's part of composite residual blocks (weights of a vector-Jacobian product).
pub fn gather_blocks<S: Fixed, C: Dimensions>(x: &ResidualBlocks<C>, slot: &Offsets) -> ResidualBlocks<S>
where
    DefaultAllocator: Storage<S> + Storage<C>,
{
    ResidualBlocks {
        momentum_rate: gather_q::<S, C>(&x.momentum_rate, slot),
        dl_dv: gather_q::<S, C>(&x.dl_dv, slot),
        constraint_velocity: gather_c::<S, C>(&x.constraint_velocity, slot),
    }
}

/// Writes a subsystem vector of coordinates into the composite's.
pub fn scatter_q<S: Fixed, C: Dimensions>(x: &VecQ<S>, slot: &Offsets, out: &mut VecQ<C>)
where
    DefaultAllocator: Storage<S> + Storage<C>,
{
    for i in 0..S::NQ {
        out[slot.q + i] = x[i];
    }
}

/// Writes a subsystem vector over constraint rows into the composite's.
pub fn scatter_c<S: Fixed, C: Dimensions>(x: &VecC<S>, slot: &Offsets, out: &mut VecC<C>)
where
    DefaultAllocator: Storage<S> + Storage<C>,
{
    for r in 0..S::NC {
        out[slot.row::<S>(r)] = x[r];
    }
}

/// Writes a subsystem's holonomic constraint values into the composite's.
pub fn scatter_h<S: Fixed, C: Dimensions>(x: &VecH<S>, slot: &Offsets, out: &mut VecH<C>)
where
    DefaultAllocator: Storage<S> + Storage<C>,
{
    for r in 0..S::NH {
        out[slot.h + r] = x[r];
    }
}

/// Writes a subsystem's `n × n` block onto the composite's diagonal.
pub fn scatter_qq<S: Fixed, C: Dimensions>(x: &Qq<S>, slot: &Offsets, out: &mut Qq<C>)
where
    DefaultAllocator: Storage<S> + Storage<C>,
{
    for j in 0..S::NQ {
        for i in 0..S::NQ {
            out[(slot.q + i, slot.q + j)] = x[(i, j)];
        }
    }
}

/// Writes a subsystem's `m × n` block into the composite's rows and columns.
pub fn scatter_cq<S: Fixed, C: Dimensions>(x: &Cq<S>, slot: &Offsets, out: &mut Cq<C>)
where
    DefaultAllocator: Storage<S> + Storage<C>,
{
    for j in 0..S::NQ {
        for r in 0..S::NC {
            out[(slot.row::<S>(r), slot.q + j)] = x[(r, j)];
        }
    }
}

/// Where a subsystem's event functions' gradients go among a composite's: the composite's
/// sizes, where the subsystem's parameters start among the composite's, and where its events
/// start.
#[derive(Clone, Copy, Debug)]
pub struct EventRows {
    /// The composite's coordinates, constraint rows and parameters.
    pub nq: usize,
    pub nc: usize,
    pub parameters: usize,
    /// The subsystem's first parameter and first event among the composite's.
    pub first_parameter: usize,
    pub first_event: usize,
}

/// Writes a subsystem's event functions' gradients (`Hybrid::event_derivatives` over its own
/// arguments, `block`) into a composite's (`out`, zeroed before): each row's coordinates',
/// velocities' and multipliers' entries at the subsystem's `slot`, its time entry, and its
/// parameters' entries from `at.first_parameter`.
pub fn place_event_derivatives<S: Fixed + Named>(
    block: &[f64],
    slot: &Offsets,
    at: EventRows,
    out: &mut [f64],
) {
    let (n, m) = (S::NQ, S::NC);
    let count = S::NAMES.event_count();
    if count == 0 {
        return;
    }
    let width = block.len() / count;
    let total = 2 * at.nq + at.nc + 1 + at.parameters;
    for (e, row) in block.chunks_exact(width).enumerate() {
        let to = &mut out[(at.first_event + e) * total..(at.first_event + e + 1) * total];
        for c in 0..n {
            to[slot.q + c] = row[c];
            to[at.nq + slot.q + c] = row[n + c];
        }
        for r in 0..m {
            to[2 * at.nq + slot.row::<S>(r)] = row[2 * n + r];
        }
        to[2 * at.nq + at.nc] = row[2 * n + m];
        let first = 2 * at.nq + at.nc + 1 + at.first_parameter;
        to[first..first + width - (2 * n + m + 1)].copy_from_slice(&row[2 * n + m + 1..]);
    }
}

/// Writes a subsystem's dense column-major block of `rows` rows into a composite's dense
/// column-major block of `total_rows` rows, its first entry at `(row0, col0)`.
pub fn place_block(
    block: &[f64],
    rows: usize,
    total_rows: usize,
    (row0, col0): (usize, usize),
    out: &mut [f64],
) {
    if rows == 0 {
        return;
    }
    for (j, column) in block.chunks_exact(rows).enumerate() {
        let start = (col0 + j) * total_rows + row0;
        out[start..start + rows].copy_from_slice(column);
    }
}
