//! The separable path of a variational step, for `L = ½ vᵀ M v − V(q, t)` with a constant,
//! nonsingular mass matrix and no forces: `M v = p_k + (h/2) ∂L/∂q(q_k) + A(q_k)ᵀ Λ`, so with
//! `M` factored once, stage 1 is Newton on `Λ` alone (SHAKE) and stage 2 a linear system in
//! `Γ` (RATTLE's velocity projection), both `m × m`. Dense models only: it reads their blocks
//! through [`Algebra::dense_cq`].

use nalgebra::{DefaultAllocator, OMatrix};

use super::general::{StagePoints, stage_one_constraints};
use super::work::Step;
use crate::algebra::Algebra;
use crate::algebra::lu::Lu;
use crate::algebra::mass::Mass;
use crate::error::SimError;
use crate::model::LagrangeDirac;
use crate::model::configuration;
use crate::shape::dims::{Dimensions, Storage, VecC, VecQ};

/// A dense `m × n` block.
type Cq<M> = OMatrix<f64, <M as Dimensions>::Nc, <M as Dimensions>::Nq>;

/// A block of a dense model, which the separable path is only taken for.
fn dense<M: LagrangeDirac>(b: &crate::model::MatCQ<M>) -> &Cq<M>
where
    DefaultAllocator: Storage<M>,
{
    M::Algebra::dense_cq(b).expect("the separable path is taken for dense models only")
}

/// Both stages on the separable path.
pub(crate) fn separable_step<M: LagrangeDirac>(s: &mut Step<'_, M>, mass: &Mass<M>) -> Result<(), SimError>
where
    DefaultAllocator: Storage<M>,
{
    let (m, h) = (s.work.sizes.typed::<M>().nc, s.h);
    let t1 = s.t + h;
    let mut v_free = &s.state.p + &s.work.dl_dq * (0.5 * h);
    mass.solve(&mut v_free);
    if m == 0 {
        s.work.v.copy_from(&v_free);
    } else {
        shake(s, mass, &v_free)?;
    }
    let mut q1 = s.work.sizes.zeros_q::<M>();
    configuration::advance::<M>(&s.state.q, h, &s.work.v, &mut q1);
    let mut dl_dq1 = s.work.sizes.zeros_q::<M>();
    s.model.dl_dq(t1, &q1, &s.work.v, &mut dl_dq1);
    // M v = p_k + (h/2) g_k + A_kᵀ Λ, so P(v) + (h/2) g_{k+1} needs no product with M.
    let a0 = dense::<M>(&s.work.a0);
    let target = &s.state.p + (&s.work.dl_dq + &dl_dq1) * (0.5 * h) + a0.transpose() * &s.work.big_lambda;
    let mut w = target.clone();
    mass.solve(&mut w);
    if m == 0 {
        s.state.v.copy_from(&w);
        s.state.p.copy_from(&target);
    } else {
        s.model.constraint_matrix(t1, &q1, &mut s.work.blocks.a1);
        let a1 = dense::<M>(&s.work.blocks.a1).clone();
        let d = mass.solve_transpose(&a1);
        let mut gamma = -(&a1 * &w);
        if M::PRESCRIBED {
            s.model.constraint_rate(t1, &q1, &mut s.work.vectors.rate);
            gamma -= &s.work.vectors.rate;
        }
        solve_small(s, &(&a1 * &d), Some(&a1), &mut gamma)?;
        s.work.gamma.copy_from(&gamma);
        s.state.v.copy_from(&(w + d * &gamma));
        s.state.p.copy_from(&(target + a1.transpose() * &gamma));
    }
    s.work.dl_dq.copy_from(&dl_dq1);
    Ok(())
}

/// Stage 1: Newton on `Λ` for `v = v_free + M⁻¹ A(q_k)ᵀ Λ` on the constraints.
fn shake<M: LagrangeDirac>(s: &mut Step<'_, M>, mass: &Mass<M>, v_free: &VecQ<M>) -> Result<(), SimError>
where
    DefaultAllocator: Storage<M>,
{
    let (h, sizes) = (s.h, s.work.sizes.typed::<M>());
    let b = mass.solve_transpose(dense::<M>(&s.work.a0));
    s.work.last_update = f64::INFINITY;
    for _ in 0..s.options.max_iterations {
        s.work.v.copy_from(&(v_free + &b * &s.work.big_lambda));
        let (w, model) = (&mut *s.work, s.model);
        let x = &mut w.vectors;
        configuration::advance::<M>(&s.state.q, h, &w.v, &mut x.q1);
        configuration::advance::<M>(&s.state.q, 0.5 * h, &w.v, &mut x.qm);
        let (t1, tm) = (s.t + h, s.t + 0.5 * h);
        model.constraint_matrix(t1, &x.q1, &mut w.blocks.a1);
        model.constraint_matrix(tm, &x.qm, &mut w.blocks.am);
        model.dav_dq(tm, &x.qm, &w.v, &mut w.blocks.gm);
        let mut r = sizes.zeros_c::<M>();
        let at = StagePoints { t: s.t, h, q1: &x.q1, qm: &x.qm };
        stage_one_constraints(
            model,
            &sizes,
            at,
            (&mut x.phi, &mut x.rate),
            &w.blocks.am,
            &w.v,
            r.as_mut_slice(),
        );
        // ∂/∂v of the constraints: A(q_{k+1}) in holonomic rows, A + (h/2) ∂(A v + b)/∂q at the
        // midpoint in the others.
        let (a1, am, gm) = (dense::<M>(&w.blocks.a1), dense::<M>(&w.blocks.am), dense::<M>(&w.blocks.gm));
        let mut c = am + gm * (0.5 * h);
        for j in 0..sizes.nh {
            c.row_mut(j).copy_from(&a1.row(j));
        }
        solve_small(s, &(c * &b), None, &mut r)?;
        s.work.big_lambda -= &r;
        s.stats.newton_iterations += 1;
        // Converged when the velocities stop moving, each against its own size and scale (a
        // roll's rate of 1e-12 on an inertia of 1e12 beside a slide's of 1): with a small mass a
        // tiny impulse moves them far, so the impulse's own update says nothing.
        let update = &b * &r;
        let size = (0..sizes.nq)
            .map(|i| update[i].abs() / (s.work.v[i].abs() + s.work.scale[i]))
            .fold(0.0, |m, x| if x > m || x.is_nan() { x } else { m });
        let tolerance = s.options.tolerance;
        let stalled = size >= 0.5 * s.work.last_update && size <= 1e3 * tolerance;
        s.work.last_update = size;
        if size <= tolerance || stalled {
            s.work.v.copy_from(&(v_free + &b * &s.work.big_lambda));
            return Ok(());
        }
    }
    Err(s.diverged())
}

/// Solves `matrix x = rhs` in place, factored in the work space's storage, where `matrix` is
/// `B M⁻¹ Aᵀ` for the rows `A` (`rows`, or the step's first rows `A(q_k)` if none) that the
/// unknowns act through: redundant rows deflated, the solution of least norm.
#[inline(always)]
fn solve_small<M: LagrangeDirac>(
    s: &mut Step<'_, M>,
    matrix: &OMatrix<f64, M::Nc, M::Nc>,
    rows: Option<&OMatrix<f64, M::Nc, M::Nq>>,
    rhs: &mut VecC<M>,
) -> Result<(), SimError>
where
    DefaultAllocator: Storage<M>,
{
    s.stats.factorizations += 1;
    let (n, m) = (s.work.sizes.nq, s.work.sizes.nc);
    let small = s.work.small.get_or_insert_with(|| Lu::new(m));
    small.matrix_mut().copy_from(matrix);
    let a = rows.unwrap_or_else(|| dense::<M>(&s.work.a0));
    match small.factor_schur(&mut s.work.small_deflation, (n, |i, k| a[(k, i)])) {
        Ok(()) => {
            s.work.small_deflation.project(rhs.as_mut_slice());
            small.solve(rhs);
            Ok(())
        }
        Err(e) => Err(SimError::SingularMatrix {
            t: s.t,
            h: s.h,
            detail: format!(
                "the constraint `{}` is dependent on the others",
                s.model.constraint_names()[e.column]
            ),
        }),
    }
}
