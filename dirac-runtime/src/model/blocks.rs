//! The block outputs of a model: what integrators evaluate at every Newton iteration, and
//! the Jacobian blocks a condensed Newton step is built from.

use nalgebra::DefaultAllocator;

pub use crate::algebra::JacobianBlocks;
use crate::shape::dims::{Dimensions, Fixed, Sizes, Storage, VecC, VecQ};

/// The blocks of the residual that integrators evaluate at every Newton iteration.
pub struct ResidualBlocks<M: Dimensions>
where
    DefaultAllocator: Storage<M>,
{
    /// The momentum rate `ṗ = ∂L/∂q + F + A(q)ᵀ λ` (paper eq. 3 with the constraint forces).
    pub momentum_rate: VecQ<M>,
    /// `∂L/∂v`, the right-hand side of the Legendre map `p = ∂L/∂v`.
    pub dl_dv: VecQ<M>,
    /// `A(q, t) v + b(q, t)`, zero on the constraint distribution Δ_Q (shifted by the motion
    /// a constraint prescribes).
    pub constraint_velocity: VecC<M>,
}

impl<M: Dimensions> ResidualBlocks<M>
where
    DefaultAllocator: Storage<M>,
{
    /// Zeroed blocks for a model of these sizes, ready for
    /// [`LagrangeDirac::residual_blocks`](crate::model::LagrangeDirac::residual_blocks).
    #[inline]
    pub fn with_sizes(sizes: &Sizes) -> Self {
        Self {
            momentum_rate: sizes.zeros_q::<M>(),
            dl_dv: sizes.zeros_q::<M>(),
            constraint_velocity: sizes.zeros_c::<M>(),
        }
    }
}

impl<M: Dimensions> ResidualBlocks<M>
where
    DefaultAllocator: Storage<M>,
{
    /// The sum of the three blocks' dot products with `other`'s: `wᵀ b` for blocks `b` and
    /// weights `w` of the same shape.
    pub fn dot(&self, other: &Self) -> f64 {
        self.momentum_rate.dot(&other.momentum_rate)
            + self.dl_dv.dot(&other.dl_dv)
            + self.constraint_velocity.dot(&other.constraint_velocity)
    }
}

impl<M: Fixed> ResidualBlocks<M>
where
    DefaultAllocator: Storage<M>,
{
    /// Zeroed blocks for a model of fixed size.
    pub fn zeros() -> Self {
        Self::with_sizes(&M::SIZES)
    }
}
