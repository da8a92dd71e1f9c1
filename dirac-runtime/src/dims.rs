//! Sizes of a model as nalgebra type-level dimensions, and the allocator bound that goes with them.
//!
//! Stable Rust has no arithmetic on const generic parameters, so generic runtime code can never
//! compute `3n + m` itself. Every size it needs is therefore an associated type that the derive
//! macro (or an interconnection) sets to a concrete `nalgebra::Const<N>`.

use nalgebra::allocator::Allocator;
use nalgebra::{DimName, OMatrix, OVector};

/// The sizes of a Lagrange-Dirac model, as type-level dimensions.
///
/// Implemented by `#[derive(LagrangeDirac)]`; you do not implement it by hand.
pub trait Dimensions {
    /// `n`: the number of coordinates (and of velocities and momenta).
    type Nq: DimName;
    /// `m`: the number of constraint rows of `A(q)`, holonomic rows first.
    type Nc: DimName;
    /// The number of holonomic constraints `φ(q) = 0`; they are the first rows of `A(q)`.
    type Nh: DimName;
    /// `n + m`: the size of the condensed Newton system in `(Δv, Δλ)`.
    type Nk: DimName;
    /// `3n + m`: the size of the flat state `y = (q, v, p, λ)`.
    type Ny: DimName;
    /// `n` as a value.
    const NQ: usize = <Self::Nq as DimName>::DIM;
    /// `m` as a value.
    const NC: usize = <Self::Nc as DimName>::DIM;
    /// The number of holonomic constraints as a value.
    const NH: usize = <Self::Nh as DimName>::DIM;
}

/// Every nalgebra allocation a model of dimensions `D` needs, bundled into one bound.
///
/// Generic code over a model writes `where DefaultAllocator: Storage<M>` once instead of a
/// dozen `Allocator` bounds. It holds for every model the macros generate.
pub trait Storage<D: Dimensions + ?Sized>:
    Allocator<D::Nq>
    + Allocator<D::Nq, D::Nq>
    + Allocator<D::Nc>
    + Allocator<D::Nc, D::Nc>
    + Allocator<D::Nc, D::Nq>
    + Allocator<D::Nq, D::Nc>
    + Allocator<D::Nh>
    + Allocator<D::Nk>
    + Allocator<D::Nk, D::Nk>
    + Allocator<D::Ny>
    + Allocator<D::Ny, D::Ny>
{
}

impl<D, A> Storage<D> for A
where
    D: Dimensions + ?Sized,
    A: Allocator<D::Nq>
        + Allocator<D::Nq, D::Nq>
        + Allocator<D::Nc>
        + Allocator<D::Nc, D::Nc>
        + Allocator<D::Nc, D::Nq>
        + Allocator<D::Nq, D::Nc>
        + Allocator<D::Nh>
        + Allocator<D::Nk>
        + Allocator<D::Nk, D::Nk>
        + Allocator<D::Ny>
        + Allocator<D::Ny, D::Ny>,
{
}

/// A vector of `n` entries: positions, velocities, momenta, forces.
pub type VecQ<M> = OVector<f64, <M as Dimensions>::Nq>;
/// A vector of `m` entries: multipliers λ, constraint values `A(q) v`.
pub type VecC<M> = OVector<f64, <M as Dimensions>::Nc>;
/// A vector of holonomic constraint values φ(q).
pub type VecH<M> = OVector<f64, <M as Dimensions>::Nh>;
/// A vector of `n + m` entries: the unknowns `(Δv, Δλ)` of a condensed Newton step.
pub type VecK<M> = OVector<f64, <M as Dimensions>::Nk>;
/// A vector of `3n + m` entries: the flat state `y = (q, v, p, λ)`.
pub type VecY<M> = OVector<f64, <M as Dimensions>::Ny>;
/// An `n × n` matrix: second derivatives of L, force Jacobians.
pub type MatQQ<M> = OMatrix<f64, <M as Dimensions>::Nq, <M as Dimensions>::Nq>;
/// An `m × n` matrix: the constraint rows `A(q)` and `∂(A v)/∂q`.
pub type MatCQ<M> = OMatrix<f64, <M as Dimensions>::Nc, <M as Dimensions>::Nq>;
/// An `(n + m) × (n + m)` matrix: the condensed Newton matrix.
pub type MatKK<M> = OMatrix<f64, <M as Dimensions>::Nk, <M as Dimensions>::Nk>;
/// A `(3n + m) × (3n + m)` matrix: the flat Jacobian `∂f/∂y`.
pub type MatYY<M> = OMatrix<f64, <M as Dimensions>::Ny, <M as Dimensions>::Ny>;
