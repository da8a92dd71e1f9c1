//! The block outputs of a model: what integrators evaluate at every Newton iteration, and
//! the Jacobian blocks a condensed Newton step is built from.

use nalgebra::DefaultAllocator;

use crate::dims::{Dimensions, MatCQ, MatQQ, Storage, VecC, VecQ};

/// The blocks of the residual that integrators evaluate at every Newton iteration.
pub struct ResidualBlocks<M: Dimensions>
where
    DefaultAllocator: Storage<M>,
{
    /// The momentum rate `ṗ = ∂L/∂q + F + A(q)ᵀ λ` (paper eq. 3 with the constraint forces).
    pub momentum_rate: VecQ<M>,
    /// `∂L/∂v`, the right-hand side of the Legendre map `p = ∂L/∂v`.
    pub dl_dv: VecQ<M>,
    /// `A(q) v`, zero on the constraint distribution Δ_Q.
    pub constraint_velocity: VecC<M>,
}

impl<M: Dimensions> ResidualBlocks<M>
where
    DefaultAllocator: Storage<M>,
{
    /// Zeroed blocks, ready for [`LagrangeDirac::residual_blocks`](crate::LagrangeDirac::residual_blocks).
    pub fn zeros() -> Self {
        Self {
            momentum_rate: VecQ::<M>::zeros(),
            dl_dv: VecQ::<M>::zeros(),
            constraint_velocity: VecC::<M>::zeros(),
        }
    }
}

/// The Jacobian blocks of [`ResidualBlocks`], the input of a condensed Newton step.
pub struct JacobianBlocks<M: Dimensions>
where
    DefaultAllocator: Storage<M>,
{
    /// `∂ṗ/∂q = L_qq + F_q + ∂(Aᵀλ)/∂q` (called K in the design notes).
    pub dpdot_dq: MatQQ<M>,
    /// `∂ṗ/∂v = L_qv + F_v` (called D in the design notes).
    pub dpdot_dv: MatQQ<M>,
    /// `L_vq = ∂(∂L/∂v)/∂q`.
    pub l_vq: MatQQ<M>,
    /// `L_vv = ∂²L/∂v²`, singular for a degenerate Lagrangian.
    pub l_vv: MatQQ<M>,
    /// The constraint rows `A(q)`.
    pub a: MatCQ<M>,
    /// `∂(A(q) v)/∂q`.
    pub dav_dq: MatCQ<M>,
}

impl<M: Dimensions> JacobianBlocks<M>
where
    DefaultAllocator: Storage<M>,
{
    /// Zeroed blocks, ready for [`LagrangeDirac::jacobian_blocks`](crate::LagrangeDirac::jacobian_blocks).
    pub fn zeros() -> Self {
        Self {
            dpdot_dq: MatQQ::<M>::zeros(),
            dpdot_dv: MatQQ::<M>::zeros(),
            l_vq: MatQQ::<M>::zeros(),
            l_vv: MatQQ::<M>::zeros(),
            a: MatCQ::<M>::zeros(),
            dav_dq: MatCQ::<M>::zeros(),
        }
    }

    /// Copies every block of `other` into these, without allocating.
    pub fn copy_from(&mut self, other: &Self) {
        self.dpdot_dq.copy_from(&other.dpdot_dq);
        self.dpdot_dv.copy_from(&other.dpdot_dv);
        self.l_vq.copy_from(&other.l_vq);
        self.l_vv.copy_from(&other.l_vv);
        self.a.copy_from(&other.a);
        self.dav_dq.copy_from(&other.dav_dq);
    }
}
