//! Sizes of a model: as nalgebra type-level dimensions, which fix where its vectors live, and
//! as numbers, which every model can report at run time.
//!
//! A model whose sizes are known when it compiles (every primitive model and every composite
//! of named subsystems) sets its dimensions to concrete `nalgebra::Const<N>`: its vectors and
//! matrices are stack arrays, and [`Fixed`](crate::shape::dims::Fixed) gives its sizes as constants. A model made of
//! arrays of subsystems sets them to `nalgebra::Dyn`: its vectors live on the heap, sized from
//! the model itself ([`Sizes`](crate::shape::dims::Sizes)). Generic runtime code never computes a size from a type; it
//! asks the model for its [`Sizes`](crate::shape::dims::Sizes) and builds its vectors with them.

use nalgebra::allocator::Allocator;
use nalgebra::{Const, DefaultAllocator, Dim, DimName, OMatrix, OVector};

/// The sizes of a Lagrange-Dirac model, as type-level dimensions.
///
/// Implemented by the derives; you do not implement it by hand.
pub trait Dimensions {
    /// `n`: the number of coordinates (and of velocities and momenta).
    type Nq: Dim;
    /// `m`: the number of constraint rows of `A(q)`, holonomic rows first.
    type Nc: Dim;
    /// The number of holonomic constraints `φ(q, t) = 0`; they are the first rows of `A`.
    type Nh: Dim;
    /// `n + m`: the size of the condensed Newton system in `(Δv, Δλ)`.
    type Nk: Dim;
    /// `3n + m`: the size of the flat state `y = (q, v, p, λ)`.
    type Ny: Dim;
}

/// Sizes known when the program compiles: every model whose dimensions are `Const`, which
/// keeps its vectors and matrices on the stack.
///
/// Generic code over such models may use `M::NQ` and nalgebra's `VecQ::<M>::zeros()`; code for
/// every model asks for [`LagrangeDirac::sizes`](crate::LagrangeDirac::sizes) instead.
pub trait Fixed: Dimensions<Nq: DimName, Nc: DimName, Nh: DimName, Nk: DimName, Ny: DimName> {
    /// `n` as a value.
    const NQ: usize;
    /// `m` as a value.
    const NC: usize;
    /// The number of holonomic constraints as a value.
    const NH: usize;
    /// All three.
    const SIZES: Sizes = Sizes { nq: Self::NQ, nc: Self::NC, nh: Self::NH };
}

impl<D> Fixed for D
where
    D: Dimensions<Nq: DimName, Nc: DimName, Nh: DimName, Nk: DimName, Ny: DimName> + ?Sized,
{
    const NQ: usize = <D::Nq as DimName>::DIM;
    const NC: usize = <D::Nc as DimName>::DIM;
    const NH: usize = <D::Nh as DimName>::DIM;
}

/// The sizes of a model as numbers: `n` coordinates, `m` constraint rows of which the first
/// `nh` are holonomic.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Sizes {
    /// `n`: coordinates, velocities and momenta.
    pub nq: usize,
    /// `m`: constraint rows and multipliers.
    pub nc: usize,
    /// Holonomic constraints, the first rows.
    pub nh: usize,
}

impl Sizes {
    /// These sizes, with every size that `M`'s dimensions fix taken from them: in code over a
    /// model of fixed size the compiler then sees constants, unrolls loops and drops bounds
    /// checks; for a model sized at run time they are these sizes unchanged.
    #[inline(always)]
    pub fn typed<M: Dimensions>(self) -> Sizes {
        Sizes {
            nq: M::Nq::try_to_usize().unwrap_or(self.nq),
            nc: M::Nc::try_to_usize().unwrap_or(self.nc),
            nh: M::Nh::try_to_usize().unwrap_or(self.nh),
        }
    }

    /// `n + m`: the unknowns of a condensed Newton system.
    pub const fn nk(&self) -> usize {
        self.nq + self.nc
    }

    /// `3n + m`: the length of the flat state.
    pub const fn ny(&self) -> usize {
        3 * self.nq + self.nc
    }

    /// A zero vector of `n` entries.
    #[inline]
    pub fn zeros_q<M: Dimensions>(&self) -> VecQ<M>
    where
        DefaultAllocator: Allocator<M::Nq>,
    {
        VecQ::<M>::zeros_generic(M::Nq::from_usize(self.nq), Const::<1>)
    }

    /// A zero vector of `m` entries.
    #[inline]
    pub fn zeros_c<M: Dimensions>(&self) -> VecC<M>
    where
        DefaultAllocator: Allocator<M::Nc>,
    {
        VecC::<M>::zeros_generic(M::Nc::from_usize(self.nc), Const::<1>)
    }

    /// A zero vector of one entry per holonomic constraint.
    pub fn zeros_h<M: Dimensions>(&self) -> VecH<M>
    where
        DefaultAllocator: Allocator<M::Nh>,
    {
        VecH::<M>::zeros_generic(M::Nh::from_usize(self.nh), Const::<1>)
    }

    /// A zero vector of `n + m` entries.
    pub fn zeros_k<M: Dimensions>(&self) -> VecK<M>
    where
        DefaultAllocator: Allocator<M::Nk>,
    {
        VecK::<M>::zeros_generic(M::Nk::from_usize(self.nk()), Const::<1>)
    }

    /// A zero vector of `3n + m` entries.
    pub fn zeros_y<M: Dimensions>(&self) -> VecY<M>
    where
        DefaultAllocator: Allocator<M::Ny>,
    {
        VecY::<M>::zeros_generic(M::Ny::from_usize(self.ny()), Const::<1>)
    }

    /// A zero `(3n + m) × (3n + m)` matrix.
    pub fn zeros_yy<M: Dimensions>(&self) -> MatYY<M>
    where
        DefaultAllocator: Allocator<M::Ny, M::Ny>,
    {
        let ny = M::Ny::from_usize(self.ny());
        MatYY::<M>::zeros_generic(ny, ny)
    }
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
/// A vector of `m` entries: multipliers λ, constraint values `A(q, t) v + b(q, t)`.
pub type VecC<M> = OVector<f64, <M as Dimensions>::Nc>;
/// A vector of holonomic constraint values φ(q).
pub type VecH<M> = OVector<f64, <M as Dimensions>::Nh>;
/// A vector of `n + m` entries: the unknowns `(Δv, Δλ)` of a condensed Newton step.
pub type VecK<M> = OVector<f64, <M as Dimensions>::Nk>;
/// A vector of `3n + m` entries: the flat state `y = (q, v, p, λ)`.
pub type VecY<M> = OVector<f64, <M as Dimensions>::Ny>;
/// An `(n + m) × (n + m)` dense matrix: a condensed Newton matrix.
pub type MatKK<M> = OMatrix<f64, <M as Dimensions>::Nk, <M as Dimensions>::Nk>;
/// A `(3n + m) × (3n + m)` dense matrix: the flat Jacobian `∂f/∂y`.
pub type MatYY<M> = OMatrix<f64, <M as Dimensions>::Ny, <M as Dimensions>::Ny>;
