//! The projections and multipliers of a consistent start for large models, through the
//! model's own saddle-point solver (sparse for models made of arrays): the same problems as
//! the dense path in [`init`](crate::analysis::init), whose singular value decompositions cost `(n + m)³`.
//!
//! 1. `φ(q, t) = 0` by Gauss-Newton with the minimal-norm correction `Δq = A_hᵀ y`,
//!    `[I A_hᵀ; A_h 0] [Δq; y] = [0; φ]`;
//! 2. `A(q, t) v + b(q, t) = 0` with the least change in the kinetic-energy norm,
//!    `[L_vv + εI Aᵀ; A 0] [Δv; y] = [0; −A v]`;
//! 3. the multipliers, `[L_vv −Aᵀ; A 0] [v̇; λ] = [∂L/∂q + F − L_vq v − ∂²L/∂v∂t; −∂(Av)/∂q v]`.

use nalgebra::DefaultAllocator;

use crate::algebra::lu::Singular;
use crate::algebra::{Algebra, Saddle, SaddleTerms, amax};
use crate::analysis::diagnose::{non_finite_entry, singular_cause};
use crate::error::SimError;
use crate::model::LagrangeDirac;
use crate::model::configuration;
use crate::shape::dims::{Sizes, Storage, VecQ};
use crate::shape::layout::{Unknown, Unknowns};

pub(crate) type SaddleOf<M> = <<M as LagrangeDirac>::Algebra as Algebra<M>>::Saddle<f64>;

/// Why a consistency system is singular: the unknown without a pivot, and what the model's
/// structure says.
pub(crate) fn not_determined<M: LagrangeDirac>(
    model: &M,
    t: f64,
    q: &VecQ<M>,
    v: &VecQ<M>,
    s: Singular,
) -> SimError
where
    DefaultAllocator: Storage<M>,
{
    let unknown = match Unknowns::new(model.sizes()).unknown(s.column) {
        Unknown::Velocity(i) => format!("velocity `{}`", model.velocity_names()[i]),
        Unknown::Multiplier(j) => format!("the multiplier of `{}`", model.constraint_names()[j]),
    };
    SimError::NotDetermined {
        t,
        cause: format!("nothing determines {unknown}; {}", singular_cause(model, t, q, v)),
    }
}

/// `[I A_hᵀ; A_h 0]`: the system of the smallest position correction onto the holonomic
/// constraints (the other constraints' rows hold only a unit diagonal).
pub(crate) fn assemble_positions<M: LagrangeDirac>(
    saddle: &mut SaddleOf<M>,
    a: &<M::Algebra as Algebra<M>>::Cq,
) where
    DefaultAllocator: Storage<M>,
{
    saddle.assemble(&SaddleTerms::<M, M::Algebra, f64> {
        top: &[],
        top_transposed: &[],
        identity: 1.0,
        right: &[(1.0, a)],
        bottom: &[(1.0, 0.0, a)],
        corner: (0.0, 1.0),
    });
}

/// `[L_vv + εI Aᵀ; A 0]`: the system of the velocity correction of least kinetic energy onto
/// the velocity constraints.
pub(crate) fn assemble_velocities<M: LagrangeDirac>(
    saddle: &mut SaddleOf<M>,
    l_vv: &<M::Algebra as Algebra<M>>::Qq,
    a: &<M::Algebra as Algebra<M>>::Cq,
) where
    DefaultAllocator: Storage<M>,
{
    saddle.assemble(&SaddleTerms::<M, M::Algebra, f64> {
        top: &[(1.0, l_vv)],
        top_transposed: &[],
        // A small multiple of I keeps the problem well posed where L_vv is singular off ker A.
        identity: 1e-10 * amax(M::Algebra::qq_values(l_vv)).max(1.0),
        right: &[(1.0, a)],
        bottom: &[(1.0, 1.0, a)],
        corner: (0.0, 0.0),
    });
}

/// Whether the model is sparse and its saddle-point matrix `[L_vv Aᵀ; A 0]` at `(t, q, v)`
/// factors without regularisation: then inertia and constraints fix every velocity, there is
/// no direction of `ker L_vv ∩ ker A` for the forces to fix, and the sparse path starts it.
pub(crate) fn velocities_determined<M: LagrangeDirac>(model: &M, t: f64, q: &VecQ<M>, v: &VecQ<M>) -> bool
where
    DefaultAllocator: Storage<M>,
{
    let shape = model.shape();
    let (mut lvv, mut a) = (M::Algebra::zeros_qq(&shape), M::Algebra::zeros_cq(&shape));
    if M::Algebra::dense_qq(&lvv).is_some() {
        return false;
    }
    model.l_vv(t, q, v, &mut lvv);
    model.constraint_matrix(t, q, &mut a);
    let finite = |x: &[f64]| x.iter().all(|x| x.is_finite());
    if !finite(M::Algebra::qq_values(&lvv)) || !finite(M::Algebra::cq_values(&a)) {
        return false;
    }
    let mut saddle: SaddleOf<M> = M::Algebra::saddle(&shape);
    saddle.assemble(&SaddleTerms::<M, M::Algebra, f64> {
        top: &[(1.0, &lvv)],
        top_transposed: &[],
        identity: 0.0,
        right: &[(1.0, &a)],
        bottom: &[(1.0, 1.0, &a)],
        corner: (0.0, 0.0),
    });
    saddle.factor().is_ok()
}

/// Projects `q` onto `φ(q, t) = 0`.
pub(crate) fn project_positions<M: LagrangeDirac>(
    model: &M,
    t: f64,
    q: &mut VecQ<M>,
    (tolerance, max_iterations): (f64, usize),
) -> Result<(), SimError>
where
    DefaultAllocator: Storage<M>,
{
    let (sizes, shape) = (model.sizes(), model.shape());
    let Sizes { nq: n, nc: m, nh: h } = sizes;
    if h == 0 {
        return Ok(());
    }
    let mut saddle: SaddleOf<M> = M::Algebra::saddle(&shape);
    let (mut phi, mut a) = (sizes.zeros_h::<M>(), M::Algebra::zeros_cq(&shape));
    let (mut x, at_rest) = (vec![0.0; n + m], sizes.zeros_q::<M>());
    for iteration in 0..=max_iterations {
        model.holonomic(t, q, &mut phi);
        non_finite_entry(model, t, "a holonomic constraint φ(q)", phi.as_slice(), false)?;
        model.constraint_matrix(t, q, &mut a);
        non_finite_entry(model, t, "the constraint rows A(q)", M::Algebra::cq_values(&a), false)?;
        if phi.amax() <= tolerance * amax(M::Algebra::cq_values(&a)) * (1.0 + q.amax()) {
            return Ok(());
        }
        if iteration == max_iterations {
            let j = phi.iamax();
            return Err(SimError::InconsistentInitialState {
                equation: format!("holonomic constraint `{}`", model.constraint_names()[j]),
                residual: phi[j].abs(),
                iterations: max_iterations,
            });
        }
        assemble_positions(&mut saddle, &a);
        saddle.factor().map_err(|s| not_determined(model, t, q, &at_rest, s))?;
        x.fill(0.0);
        x[n..n + h].copy_from_slice(phi.as_slice());
        saddle.solve(&mut x);
        configuration::advance_in_place::<M>(q, -1.0, &x[..n]);
        non_finite_entry(model, t, "a coordinate while projecting onto the constraints", q.as_slice(), true)?;
    }
    unreachable!("the last iteration returns")
}

/// Projects `v` onto `A(q, t) v + b(q, t) = 0`.
pub(crate) fn project_velocities<M: LagrangeDirac>(
    model: &M,
    t: f64,
    q: &VecQ<M>,
    v: &mut VecQ<M>,
    tolerance: f64,
) -> Result<(), SimError>
where
    DefaultAllocator: Storage<M>,
{
    let (sizes, shape) = (model.sizes(), model.shape());
    let Sizes { nq: n, nc: m, .. } = sizes;
    if m == 0 {
        return Ok(());
    }
    let mut a = M::Algebra::zeros_cq(&shape);
    model.constraint_matrix(t, q, &mut a);
    non_finite_entry(model, t, "the constraint rows A(q)", M::Algebra::cq_values(&a), false)?;
    let mut b = sizes.zeros_c::<M>();
    model.constraint_rate(t, q, &mut b);
    non_finite_entry(model, t, "the constraint rates b(q, t)", b.as_slice(), false)?;
    let mut av = b.as_slice().to_vec();
    M::Algebra::cq_mul(&a, 1.0, v.as_slice(), &mut av);
    let size_a = amax(M::Algebra::cq_values(&a));
    if amax(&av) <= tolerance * size_a * (1.0 + v.amax()) {
        return Ok(());
    }
    let mut lvv = M::Algebra::zeros_qq(&shape);
    model.l_vv(t, q, v, &mut lvv);
    non_finite_entry(model, t, "the mass matrix L_vv", M::Algebra::qq_values(&lvv), false)?;
    let mut saddle: SaddleOf<M> = M::Algebra::saddle(&shape);
    assemble_velocities(&mut saddle, &lvv, &a);
    saddle.factor().map_err(|s| not_determined(model, t, q, v, s))?;
    let mut x = vec![0.0; n + m];
    for (xr, avr) in x[n..].iter_mut().zip(&av) {
        *xr = -avr;
    }
    saddle.solve(&mut x);
    for i in 0..n {
        v[i] += x[i];
    }
    av.copy_from_slice(b.as_slice());
    M::Algebra::cq_mul(&a, 1.0, v.as_slice(), &mut av);
    let limit = 1e3 * tolerance * size_a * (1.0 + v.amax());
    let j = (0..m).fold(0, |b, j| if av[j].is_nan() || av[j].abs() > av[b].abs() { j } else { b });
    if av[j].is_nan() || av[j].abs() > limit {
        return Err(SimError::InconsistentInitialState {
            equation: format!("velocity constraint `{}`", model.constraint_names()[j]),
            residual: av[j].abs(),
            iterations: 1,
        });
    }
    Ok(())
}

/// The multipliers at a consistent `(t, q, v)`, from the momentum balance and the
/// differentiated constraints with right-hand sides `top` and `bottom`.
pub(crate) fn multipliers<M: LagrangeDirac>(
    model: &M,
    t: f64,
    (q, v): (&VecQ<M>, &VecQ<M>),
    (top, bottom): (&[f64], &[f64]),
) -> Result<Vec<f64>, SimError>
where
    DefaultAllocator: Storage<M>,
{
    let (sizes, shape) = (model.sizes(), model.shape());
    let Sizes { nq: n, nc: m, .. } = sizes;
    let (mut lvv, mut a) = (M::Algebra::zeros_qq(&shape), M::Algebra::zeros_cq(&shape));
    model.l_vv(t, q, v, &mut lvv);
    model.constraint_matrix(t, q, &mut a);
    let mut saddle: SaddleOf<M> = M::Algebra::saddle(&shape);
    saddle.assemble(&SaddleTerms::<M, M::Algebra, f64> {
        top: &[(1.0, &lvv)],
        top_transposed: &[],
        identity: 0.0,
        right: &[(-1.0, &a)],
        bottom: &[(1.0, 1.0, &a)],
        corner: (0.0, 0.0),
    });
    saddle.factor().map_err(|s| not_determined(model, t, q, v, s))?;
    let mut x = Vec::with_capacity(n + m);
    x.extend_from_slice(top);
    x.extend_from_slice(bottom);
    saddle.solve(&mut x);
    Ok(x.split_off(n))
}
