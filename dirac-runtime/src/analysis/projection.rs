//! Projection of a state onto the constraint manifold: positions onto `φ(q, t) = 0`, velocities
//! onto `A(q, t) v + b(q, t) = 0`, by the smallest corrections. The variational integrator's samples
//! between steps and Radau's optional projection after accepted steps use it; its storage is
//! allocated once, so a projection allocates nothing.

use nalgebra::DefaultAllocator;

use crate::algebra::{Algebra, Saddle, SaddleTerms, amax};
use crate::model::LagrangeDirac;
use crate::model::MatCQ;
use crate::model::configuration;
use crate::shape::dims::{Sizes, Storage, VecC, VecH, VecK};

/// The storage of a projection.
pub(crate) struct Projector<M: LagrangeDirac>
where
    DefaultAllocator: Storage<M>,
{
    sizes: Sizes,
    /// The system `[I Aᵀ; A 0]`, with the identity in the rows a projection leaves out.
    saddle: <M::Algebra as Algebra<M>>::Saddle<f64>,
    a: MatCQ<M>,
    phi: VecH<M>,
    b: VecC<M>,
    x: VecK<M>,
}

impl<M: LagrangeDirac> Projector<M>
where
    DefaultAllocator: Storage<M>,
{
    pub fn new(model: &M) -> Self {
        let (sizes, shape) = (model.sizes(), model.shape());
        Projector {
            sizes,
            saddle: M::Algebra::saddle(&shape),
            a: M::Algebra::zeros_cq(&shape),
            phi: sizes.zeros_h::<M>(),
            b: sizes.zeros_c::<M>(),
            x: sizes.zeros_k::<M>(),
        }
    }

    /// Factors `[I Aᵀ; A 0]` for the rows `A` holds, or `[I Aᵀ; A_h 0]` with the identity in
    /// the corner of the other rows when `holonomic_only`; false where it is singular.
    fn factor(&mut self, holonomic_only: bool) -> bool {
        self.saddle.assemble(&SaddleTerms {
            top: &[],
            top_transposed: &[],
            identity: 1.0,
            right: &[(1.0, &self.a)],
            bottom: &[(1.0, if holonomic_only { 0.0 } else { 1.0 }, &self.a)],
            corner: (0.0, if holonomic_only { 1.0 } else { 0.0 }),
        });
        self.saddle.factor().is_ok()
    }

    /// Puts the positions `q` on the holonomic constraints and the velocities `v` on all of
    /// them, by minimal-norm corrections `Δ = −Aᵀ (A Aᵀ)⁻¹ r`; leaves them as they are where
    /// `A Aᵀ` is singular.
    pub fn project(
        &mut self,
        model: &M,
        t: f64,
        q: &mut crate::shape::dims::VecQ<M>,
        v: &mut crate::shape::dims::VecQ<M>,
    ) {
        let Sizes { nq: n, nh, .. } = self.sizes;
        for _ in 0..3 {
            model.holonomic(t, q, &mut self.phi);
            if nh == 0 || amax(self.phi.as_slice()) <= 1e-15 * (1.0 + amax(q.as_slice())) {
                break;
            }
            model.constraint_matrix(t, q, &mut self.a);
            if !self.factor(true) {
                return;
            }
            // [I Aᵀ; A_h 0] [x; y] = [0; φ] gives x = A_hᵀ (A_h A_hᵀ)⁻¹ φ.
            let x = self.x.as_mut_slice();
            x.fill(0.0);
            x[n..n + nh].copy_from_slice(self.phi.as_slice());
            self.saddle.solve(x);
            configuration::advance_in_place::<M>(q, -1.0, &x[..n]);
        }
        model.constraint_matrix(t, q, &mut self.a);
        if !self.factor(false) {
            return;
        }
        let x = self.x.as_mut_slice();
        x.fill(0.0);
        if M::PRESCRIBED {
            model.constraint_rate(t, q, &mut self.b);
            x[n..].copy_from_slice(self.b.as_slice());
        }
        M::Algebra::cq_mul(&self.a, 1.0, v.as_slice(), &mut x[n..]);
        self.saddle.solve(x);
        for i in 0..n {
            v[i] -= x[i];
        }
    }
}
