//! The joint-space dynamics of a mechanism in generalised coordinates, under the names robotics
//! libraries give them: the mass matrix, the gravity and bias torques, inverse dynamics. Each
//! comes from the model's own blocks (`L_vv`, `∂L/∂q`, `L_vq`), so it holds for any model of
//! fixed size, a robot read from a URDF or one written by hand.
//!
//! With `L = ½ vᵀ M(q) v − V(q)`, the Euler-Lagrange equations `d/dt ∂L/∂v − ∂L/∂q = τ` read
//! `M(q) a + b(q, v) = τ` with the bias `b = C(q, v) v + g(q) = L_vq v − ∂L/∂q` and the
//! gravity torques `g(q) = ∂V/∂q`. Constraints (closed loops, mimic joints) and the model's
//! forces (damping, inputs) are not part of these: they are the torques `τ` on the right.
//!
//! Each is the model's [`JointSpace`](crate::model::JointSpace) method: from its blocks for
//! any model, by the recursions of its kinematic tree for a robot read from a URDF (composite
//! rigid bodies for `M`, Newton-Euler for `g` and `b`, articulated bodies for forward
//! dynamics), generated for it when it compiles. [`blocks`](crate::model::joint_space::blocks)
//! computes them from the blocks whatever the model.
//!
//! `dirac::joint_space` shows them on a pendulum; the guide's "Robots from URDF files" on a robot.

use nalgebra::DefaultAllocator;

pub use crate::model::JointSpace;
pub use crate::model::joint_space::blocks;
use crate::model::{DenseModel, MatQQ};
use crate::shape::dims::{Storage, VecQ};

/// The joint-space mass (inertia) matrix `M(q) = ∂²L/∂v²`.
pub fn mass_matrix<M: DenseModel>(model: &M, t: f64, q: &VecQ<M>) -> MatQQ<M>
where
    DefaultAllocator: Storage<M>,
{
    let mut out = MatQQ::<M>::zeros();
    JointSpace::mass_matrix(model, t, q, &mut out);
    out
}

/// The gravity (potential) torques `g(q) = −∂L/∂q` at `v = 0`: what holds the mechanism still.
pub fn gravity_torques<M: DenseModel>(model: &M, t: f64, q: &VecQ<M>) -> VecQ<M>
where
    DefaultAllocator: Storage<M>,
{
    let mut out = VecQ::<M>::zeros();
    JointSpace::gravity_torques(model, t, q, &mut out);
    out
}

/// The bias torques `b(q, v) = C(q, v) v + g(q)`: `d/dt ∂L/∂v − ∂L/∂q` at zero acceleration,
/// `L_vq v + ∂²L/∂v∂t − ∂L/∂q` (Pinocchio's `nonLinearEffects`, RNEA at `a = 0`).
pub fn bias_torques<M: DenseModel>(model: &M, t: f64, q: &VecQ<M>, v: &VecQ<M>) -> VecQ<M>
where
    DefaultAllocator: Storage<M>,
{
    let mut out = VecQ::<M>::zeros();
    JointSpace::bias_torques(model, t, q, v, &mut out);
    out
}

/// Forward dynamics: the accelerations `a = M(q)⁻¹ (τ − b(q, v))` that the torques `tau`
/// give, with no constraint acting and none of the model's own forces (add them to `tau`);
/// `None` where the mass matrix is singular (a joint that moves no mass). For a robot from a
/// URDF fixed in the world, the articulated-body recursion (Pinocchio's `aba`), generated for it.
pub fn forward_dynamics<M: DenseModel>(
    model: &M,
    t: f64,
    q: &VecQ<M>,
    v: &VecQ<M>,
    tau: &VecQ<M>,
) -> Option<VecQ<M>>
where
    DefaultAllocator: Storage<M>,
{
    let mut out = VecQ::<M>::zeros();
    JointSpace::forward_dynamics(model, t, q, v, tau, &mut out).then_some(out)
}

/// Inverse dynamics: the torques `τ = M(q) a + b(q, v) − F(q, v, t)` that give the
/// acceleration `a`, beside the model's own forces `F` (damping, inputs at their current
/// values), with no constraint acting.
pub fn inverse_dynamics<M: DenseModel>(model: &M, t: f64, q: &VecQ<M>, v: &VecQ<M>, a: &VecQ<M>) -> VecQ<M>
where
    DefaultAllocator: Storage<M>,
{
    let mut force = VecQ::<M>::zeros();
    model.force(t, q, v, &mut force);
    mass_matrix(model, t, q) * a + bias_torques(model, t, q, v) - force
}
