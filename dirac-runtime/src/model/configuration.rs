//! How configurations move: the one place where a method advances positions by a tangent
//! vector, `q ⊕ c δ` (a step `q + h v`, a Runge-Kutta stage `q + h Σ a_j k_j`, a projection's
//! correction), moves between two configurations, and measures how far apart two are,
//! `q₁ ⊖ q₀`.
//!
//! Every model's configuration space is a vector space today, so each operation is plain
//! vector arithmetic. A configuration that moves on a group (a rotation) will change these
//! functions, with `exp` and `log` of the group (Solà, Deray and Atchuthan, *A micro Lie
//! theory for state estimation in robotics*), and no integrator: the explicit and variational
//! methods and the projections call these, never `q += h v`.

use nalgebra::DefaultAllocator;

use crate::shape::dims::{Dimensions, Storage, VecQ};

/// `out = q ⊕ c δ`: the configuration reached from `q` along the tangent vector `δ`, scaled.
#[inline]
pub fn advance<M: Dimensions>(q: &VecQ<M>, c: f64, delta: &VecQ<M>, out: &mut VecQ<M>)
where
    DefaultAllocator: Storage<M>,
{
    out.copy_from(q);
    out.axpy(c, delta, 1.0);
}

/// `q ← q ⊕ c δ`, with `δ` given as the `n` velocity-like values of a saddle-point solve.
#[inline]
pub fn advance_in_place<M: Dimensions>(q: &mut VecQ<M>, c: f64, delta: &[f64])
where
    DefaultAllocator: Storage<M>,
{
    for (q, d) in q.iter_mut().zip(delta) {
        *q += c * d;
    }
}

/// `δ ← q ⊕ c δ`: [`advance`] with the result written over the tangent vector.
#[inline]
pub fn advance_onto<M: Dimensions>(q: &VecQ<M>, c: f64, delta: &mut VecQ<M>)
where
    DefaultAllocator: Storage<M>,
{
    for (d, q) in delta.iter_mut().zip(q.iter()) {
        *d = q + c * *d;
    }
}

/// A stage point of a Runge-Kutta step on the motion `(q, v)`: `q_out = q ⊕ s Σ c_j kq_j`, the
/// configuration reached along a combination of tangent vectors, and `v_out = v + s Σ c_j
/// kv_j` (velocities form a vector space on a group too, in its algebra), with `s` the step
/// and `c_j` a row of the method's table; the terms in order, those with `c_j = 0` skipped.
#[inline]
pub fn advance_by<M: Dimensions>(
    (q, v): (&VecQ<M>, &VecQ<M>),
    s: f64,
    c: &[f64],
    (kq, kv): (&[VecQ<M>], &[VecQ<M>]),
    (q_out, v_out): (&mut VecQ<M>, &mut VecQ<M>),
) where
    DefaultAllocator: Storage<M>,
{
    q_out.copy_from(q);
    v_out.copy_from(v);
    for ((&c, kq), kv) in c.iter().zip(kq).zip(kv) {
        if c != 0.0 {
            q_out.axpy(s * c, kq, 1.0);
            v_out.axpy(s * c, kv, 1.0);
        }
    }
}

/// The configuration a share `s ∈ [0, 1]` of the way from `q0` to `q1`, `q0 ⊕ s (q1 ⊖ q0)`:
/// `q0` at `s = 0` and `q1` at `s = 1`, exactly.
#[inline]
pub fn between<M: Dimensions>(q0: &VecQ<M>, q1: &VecQ<M>, s: f64, out: &mut VecQ<M>)
where
    DefaultAllocator: Storage<M>,
{
    for ((x, a), b) in out.iter_mut().zip(q0.iter()).zip(q1.iter()) {
        *x = a * (1.0 - s) + b * s;
    }
}

/// `out = q1 ⊖ q0`: the tangent vector that takes `q0` to `q1`, so that
/// `advance(q0, 1, q1 ⊖ q0)` is `q1` (to round-off).
#[inline]
pub fn difference<M: Dimensions>(q1: &VecQ<M>, q0: &VecQ<M>, out: &mut VecQ<M>)
where
    DefaultAllocator: Storage<M>,
{
    out.copy_from(q1);
    out.axpy(-1.0, q0, 1.0);
}

#[cfg(test)]
mod tests {
    use nalgebra::Const;

    use super::*;

    struct Two;
    impl Dimensions for Two {
        type Nq = Const<2>;
        type Nc = Const<0>;
        type Nh = Const<0>;
        type Nk = Const<2>;
        type Ny = Const<6>;
    }

    #[test]
    fn moves_and_differences_are_inverse_on_vectors() {
        // Reference: vector arithmetic done by hand.
        let (q, v) = (VecQ::<Two>::new(1.0, -2.0), VecQ::<Two>::new(0.5, 4.0));
        let mut moved = VecQ::<Two>::zeros();
        advance::<Two>(&q, 0.1, &v, &mut moved);
        assert_eq!(moved, VecQ::<Two>::new(1.05, -1.6));
        let mut back = VecQ::<Two>::zeros();
        difference::<Two>(&moved, &q, &mut back);
        assert!((back - v * 0.1).amax() < 1e-15);
        let (mut by, mut w) = (VecQ::<Two>::zeros(), VecQ::<Two>::zeros());
        advance_by::<Two>((&q, &v), 0.1, &[1.0, 0.0, -1.0], (&[v, q, v], &[q, q, q]), (&mut by, &mut w));
        assert_eq!((by, w), (q, v));
        let mut onto = v;
        advance_onto::<Two>(&q, 0.1, &mut onto);
        assert_eq!(onto, moved);
        let mut corrected = q;
        advance_in_place::<Two>(&mut corrected, -1.0, &[1.0, -2.0]);
        assert_eq!(corrected, VecQ::<Two>::zeros());
        let mut half = VecQ::<Two>::zeros();
        between::<Two>(&q, &moved, 0.0, &mut half);
        assert_eq!(half, q);
        between::<Two>(&q, &moved, 1.0, &mut half);
        assert_eq!(half, moved);
    }
}
