//! Projection of a state onto the constraint manifold: positions onto `φ(q) = 0`, velocities
//! onto `A(q) v = 0`, on the stack. The variational integrator's samples between steps and
//! Radau's optional projection after accepted steps use it.

use nalgebra::DefaultAllocator;

use crate::dims::{MatCQ, Storage, VecC, VecH, VecQ};
use crate::lu::Lu;
use crate::model::LagrangeDirac;

/// Puts the positions `q` on the holonomic constraints and the velocities `v` on all of them,
/// by minimal-norm corrections `Δ = −Aᵀ (A Aᵀ)⁻¹ r`; leaves them as they are where `A Aᵀ` is
/// singular. Stack only.
pub(crate) fn project<M: LagrangeDirac>(model: &M, q: &mut VecQ<M>, v: &mut VecQ<M>)
where
    DefaultAllocator: Storage<M>,
{
    let (m, nh) = (M::NC, M::NH);
    let mut a = MatCQ::<M>::zeros();
    let mut lu = Lu::<f64, M::Nc>::new();
    let mut phi = VecH::<M>::zeros();
    for _ in 0..3 {
        model.holonomic(q, &mut phi);
        if nh == 0 || phi.amax() <= 1e-15 * (1.0 + q.amax()) {
            break;
        }
        model.constraint_matrix(q, &mut a);
        // The holonomic rows' Gram matrix, with the identity on the other rows.
        let gram = &a * a.transpose();
        let matrix = lu.matrix_mut();
        for i in 0..m {
            for j in 0..m {
                matrix[(i, j)] = if i < nh && j < nh {
                    gram[(i, j)]
                } else if i == j {
                    1.0
                } else {
                    0.0
                };
            }
        }
        if lu.factor().is_err() {
            return;
        }
        let mut r = VecC::<M>::zeros();
        for j in 0..nh {
            r[j] = phi[j];
        }
        lu.solve(&mut r);
        *q -= a.transpose() * r;
    }
    model.constraint_matrix(q, &mut a);
    lu.matrix_mut().copy_from(&(&a * a.transpose()));
    if lu.factor().is_err() {
        return;
    }
    let mut r = &a * &*v;
    lu.solve(&mut r);
    *v -= a.transpose() * r;
}
