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
//! `dirac::joint_space` shows them on a pendulum; the guide's "Robots from URDF files" on a robot.

use nalgebra::DefaultAllocator;

use crate::model::{DenseModel, MatQQ};
use crate::shape::dims::{Storage, VecQ};

/// The joint-space mass (inertia) matrix `M(q) = ∂²L/∂v²`, evaluated at `v = 0`.
pub fn mass_matrix<M: DenseModel>(model: &M, t: f64, q: &VecQ<M>) -> MatQQ<M>
where
    DefaultAllocator: Storage<M>,
{
    let v = VecQ::<M>::zeros();
    let mut out = MatQQ::<M>::zeros();
    model.l_vv(t, q, &v, &mut out);
    out
}

/// The gravity (potential) torques `g(q) = −∂L/∂q` at `v = 0`: what holds the mechanism still.
pub fn gravity_torques<M: DenseModel>(model: &M, t: f64, q: &VecQ<M>) -> VecQ<M>
where
    DefaultAllocator: Storage<M>,
{
    let v = VecQ::<M>::zeros();
    let mut out = VecQ::<M>::zeros();
    model.dl_dq(t, q, &v, &mut out);
    -out
}

/// The bias torques `b(q, v) = C(q, v) v + g(q)`: `d/dt ∂L/∂v − ∂L/∂q` at zero acceleration,
/// `L_vq v + ∂²L/∂v∂t − ∂L/∂q` (Pinocchio's `nonLinearEffects`, RNEA at `a = 0`).
pub fn bias_torques<M: DenseModel>(model: &M, t: f64, q: &VecQ<M>, v: &VecQ<M>) -> VecQ<M>
where
    DefaultAllocator: Storage<M>,
{
    let mut l_vq = MatQQ::<M>::zeros();
    model.l_vq(t, q, v, &mut l_vq);
    let mut dl_dq = VecQ::<M>::zeros();
    model.dl_dq(t, q, v, &mut dl_dq);
    let mut l_vt = VecQ::<M>::zeros();
    model.l_vt(t, q, v, &mut l_vt);
    l_vq * v + l_vt - dl_dq
}

/// Inverse dynamics: the torques `τ = M(q) a + b(q, v) − F(q, v, t)` that give the
/// acceleration `a`, beside the model's own forces `F` (damping, inputs at their current
/// values), with no constraint acting.
pub fn inverse_dynamics<M: DenseModel>(model: &M, t: f64, q: &VecQ<M>, v: &VecQ<M>, a: &VecQ<M>) -> VecQ<M>
where
    DefaultAllocator: Storage<M>,
{
    let mut l_vv = MatQQ::<M>::zeros();
    model.l_vv(t, q, v, &mut l_vv);
    let mut force = VecQ::<M>::zeros();
    model.force(t, q, v, &mut force);
    l_vv * a + bias_torques(model, t, q, v) - force
}
