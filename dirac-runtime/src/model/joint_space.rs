//! The joint-space dynamics a model computes for [`crate::analysis::joint_space`]: the mass
//! matrix, the gravity and the bias torques. By default from the model's blocks; a robot read
//! from a URDF overrides them with the recursions of its kinematic tree, written out for it when
//! it compiles.

use nalgebra::DefaultAllocator;

use crate::algebra::Dense;
use crate::model::{LagrangeDirac, MatQQ};
use crate::shape::dims::{Fixed, Storage, VecQ};

/// A model's joint-space dynamics, `M(q) a + b(q, v) = τ` with `b = C(q, v) v + g(q)`.
///
/// Every model the derives make implements it. The provided methods read `M`, `g` and `b` off
/// the model's blocks (`L_vv`, `∂L/∂q`, `L_vq`); a robot from a URDF whose joints form a tree
/// fixed in the world replaces them with straight-line code of the composite rigid body
/// recursion (the mass matrix) and the recursive Newton-Euler one (gravity and bias torques),
/// its links' inertias and frames folded in as numbers, and says so with
/// [`JointSpace::RECURSIVE`].
pub trait JointSpace: LagrangeDirac<Algebra = Dense> + Fixed
where
    DefaultAllocator: Storage<Self>,
{
    /// Whether the methods run recursions generated for the model's kinematic tree rather than
    /// its blocks.
    const RECURSIVE: bool = false;

    /// Writes the mass matrix `M(q) = ∂²L/∂v²` into `out` (every entry).
    fn mass_matrix(&self, t: f64, q: &VecQ<Self>, out: &mut MatQQ<Self>) {
        blocks::mass_matrix(self, t, q, out);
    }

    /// Writes the gravity torques `g(q) = −∂L/∂q` at `v = 0` into `out`.
    fn gravity_torques(&self, t: f64, q: &VecQ<Self>, out: &mut VecQ<Self>) {
        blocks::gravity_torques(self, t, q, out);
    }

    /// Writes the bias torques `b(q, v) = L_vq v + ∂²L/∂v∂t − ∂L/∂q` into `out`.
    fn bias_torques(&self, t: f64, q: &VecQ<Self>, v: &VecQ<Self>, out: &mut VecQ<Self>) {
        blocks::bias_torques(self, t, q, v, out);
    }

    /// Writes the accelerations `a = M(q)⁻¹ (τ − b(q, v))` that the torques `tau` give, with no
    /// constraint acting, into `out`; `false` (and `out` not finite) where `M(q)` is singular.
    fn forward_dynamics(
        &self,
        t: f64,
        q: &VecQ<Self>,
        v: &VecQ<Self>,
        tau: &VecQ<Self>,
        out: &mut VecQ<Self>,
    ) -> bool {
        let mut mass = MatQQ::<Self>::zeros();
        self.mass_matrix(t, q, &mut mass);
        self.bias_torques(t, q, v, out);
        let rhs = tau - &*out;
        match mass.cholesky() {
            Some(factor) => {
                *out = factor.solve(&rhs);
                out.iter().all(|x| x.is_finite())
            }
            None => {
                out.fill(f64::NAN);
                false
            }
        }
    }
}

/// The joint-space dynamics from a model's blocks, whatever the model: what
/// [`JointSpace`]'s provided methods do, and what a recursion generated for a robot is
/// checked against.
pub mod blocks {
    use nalgebra::DefaultAllocator;

    use crate::algebra::Dense;
    use crate::model::{LagrangeDirac, MatQQ};
    use crate::shape::dims::{Fixed, Storage, VecQ};

    /// `M(q) = ∂²L/∂v²` at `v = 0`, into `out`.
    pub fn mass_matrix<M: LagrangeDirac<Algebra = Dense> + Fixed>(
        model: &M,
        t: f64,
        q: &VecQ<M>,
        out: &mut MatQQ<M>,
    ) where
        DefaultAllocator: Storage<M>,
    {
        out.fill(0.0);
        model.l_vv(t, q, &VecQ::<M>::zeros(), out);
    }

    /// `g(q) = −∂L/∂q` at `v = 0`, into `out`.
    pub fn gravity_torques<M: LagrangeDirac<Algebra = Dense> + Fixed>(
        model: &M,
        t: f64,
        q: &VecQ<M>,
        out: &mut VecQ<M>,
    ) where
        DefaultAllocator: Storage<M>,
    {
        out.fill(0.0);
        model.dl_dq(t, q, &VecQ::<M>::zeros(), out);
        out.neg_mut();
    }

    /// `b(q, v) = L_vq v + ∂²L/∂v∂t − ∂L/∂q`, into `out`.
    pub fn bias_torques<M: LagrangeDirac<Algebra = Dense> + Fixed>(
        model: &M,
        t: f64,
        q: &VecQ<M>,
        v: &VecQ<M>,
        out: &mut VecQ<M>,
    ) where
        DefaultAllocator: Storage<M>,
    {
        let mut l_vq = MatQQ::<M>::zeros();
        model.l_vq(t, q, v, &mut l_vq);
        let mut dl_dq = VecQ::<M>::zeros();
        model.dl_dq(t, q, v, &mut dl_dq);
        out.fill(0.0);
        model.l_vt(t, q, v, out);
        *out += l_vq * v - dl_dq;
    }
}
