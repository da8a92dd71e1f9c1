//! The general path of a variational step: a Newton iteration on the `(n + m)` system of each
//! stage, for any Lagrangian (configuration-dependent or degenerate mass matrices included).

use nalgebra::DefaultAllocator;

use super::work::Step;
use crate::dims::{MatCQ, MatQQ, Storage, VecC, VecH, VecK, VecQ};
use crate::error::SimError;
use crate::model::LagrangeDirac;

/// Which unknowns a Newton update applies to.
#[derive(Clone, Copy)]
enum Stage {
    /// `(v, Λ)`.
    One,
    /// `(w, Γ)`: the new velocities and the stage-2 impulse.
    Two,
}

/// Both stages.
pub(crate) fn general_step<M: LagrangeDirac>(s: &mut Step<'_, M>) -> Result<(), SimError>
where
    DefaultAllocator: Storage<M>,
{
    s.work.last_update = f64::INFINITY;
    stage_one(s)?;
    s.work.last_update = f64::INFINITY;
    stage_two(s)
}

/// Stage 1: the new positions, through `(v, Λ)`.
fn stage_one<M: LagrangeDirac>(s: &mut Step<'_, M>) -> Result<(), SimError>
where
    DefaultAllocator: Storage<M>,
{
    let (n, m, h) = (M::NQ, M::NC, s.h);
    let (t0, t1, tm) = (s.t, s.t + h, s.t + 0.5 * h);
    let model = s.model;
    let mut r = VecK::<M>::zeros();
    for _ in 0..s.options.max_iterations {
        let (q, v) = (&s.state.q, &s.work.v);
        let q1 = q + v * h;
        let qm = q + v * (0.5 * h);
        let (mut lv0, mut lv1, mut lq0, mut f) =
            (VecQ::<M>::zeros(), VecQ::<M>::zeros(), VecQ::<M>::zeros(), VecQ::<M>::zeros());
        model.dl_dv(t0, q, v, &mut lv0);
        model.dl_dv(t1, &q1, v, &mut lv1);
        model.dl_dq(t0, q, v, &mut lq0);
        model.force(tm, &qm, v, &mut f);
        let momentum = (lv0 + lv1) * 0.5
            - (lq0 + f) * (0.5 * h)
            - s.work.a0.transpose() * &s.work.big_lambda
            - &s.state.p;
        r.rows_mut(0, n).copy_from(&momentum);
        let constraint = stage_one_constraints(model, h, &q1, &qm, v);
        r.rows_mut(n, m).copy_from(&constraint);

        let (mut lvv0, mut lvv1, mut lvq0, mut lvq1) =
            (MatQQ::<M>::zeros(), MatQQ::<M>::zeros(), MatQQ::<M>::zeros(), MatQQ::<M>::zeros());
        let (mut fq, mut fv) = (MatQQ::<M>::zeros(), MatQQ::<M>::zeros());
        model.l_vv(t0, q, v, &mut lvv0);
        model.l_vv(t1, &q1, v, &mut lvv1);
        model.l_vq(t0, q, v, &mut lvq0);
        model.l_vq(t1, &q1, v, &mut lvq1);
        model.force_dq(tm, &qm, v, &mut fq);
        model.force_dv(tm, &qm, v, &mut fv);
        let top = (lvv0 + lvv1 + lvq1 * h) * 0.5 - (lvq0.transpose() + fv + fq * (0.5 * h)) * (0.5 * h);
        let bottom = stage_one_constraint_jacobian(model, &q1, &qm, v, h);
        let jac = s.work.lu.matrix_mut();
        jac.fill(0.0);
        jac.view_mut((0, 0), (n, n)).copy_from(&top);
        jac.view_mut((0, n), (n, m)).copy_from(&(-s.work.a0.transpose()));
        jac.view_mut((n, 0), (m, n)).copy_from(&bottom);
        if newton_update(s, &mut r, Stage::One)? {
            return Ok(());
        }
    }
    Err(s.diverged())
}

/// `φ(q_{k+1})/h` for holonomic rows, `A(q_{k+½}) v` for the others.
pub(crate) fn stage_one_constraints<M: LagrangeDirac>(
    model: &M,
    h: f64,
    q1: &VecQ<M>,
    qm: &VecQ<M>,
    v: &VecQ<M>,
) -> VecC<M>
where
    DefaultAllocator: Storage<M>,
{
    let (m, nh) = (M::NC, M::NH);
    let mut out = VecC::<M>::zeros();
    if m == 0 {
        return out;
    }
    let mut phi = VecH::<M>::zeros();
    model.holonomic(q1, &mut phi);
    let mut am = MatCQ::<M>::zeros();
    model.constraint_matrix(qm, &mut am);
    let av = am * v;
    for j in 0..m {
        out[j] = if j < nh { phi[j] / h } else { av[j] };
    }
    out
}

/// The derivative of [`stage_one_constraints`] with respect to `v`.
pub(crate) fn stage_one_constraint_jacobian<M: LagrangeDirac>(
    model: &M,
    q1: &VecQ<M>,
    qm: &VecQ<M>,
    v: &VecQ<M>,
    h: f64,
) -> MatCQ<M>
where
    DefaultAllocator: Storage<M>,
{
    let (m, nh) = (M::NC, M::NH);
    let mut out = MatCQ::<M>::zeros();
    if m == 0 {
        return out;
    }
    let (mut a1, mut am, mut gm) = (MatCQ::<M>::zeros(), MatCQ::<M>::zeros(), MatCQ::<M>::zeros());
    model.constraint_matrix(q1, &mut a1);
    model.constraint_matrix(qm, &mut am);
    model.dav_dq(qm, v, &mut gm);
    for j in 0..m {
        for i in 0..M::NQ {
            out[(j, i)] = if j < nh { a1[(j, i)] } else { am[(j, i)] + 0.5 * h * gm[(j, i)] };
        }
    }
    out
}

/// Stage 2: the new momenta and velocities, through `(w, Γ)`.
fn stage_two<M: LagrangeDirac>(s: &mut Step<'_, M>) -> Result<(), SimError>
where
    DefaultAllocator: Storage<M>,
{
    let (n, m, h) = (M::NQ, M::NC, s.h);
    let (t0, t1, tm) = (s.t, s.t + h, s.t + 0.5 * h);
    let model = s.model;
    let (q, v) = (&s.state.q, &s.work.v);
    let q1 = q + v * h;
    let qm = q + v * (0.5 * h);
    let (mut lv0, mut lv1, mut lq1, mut f) =
        (VecQ::<M>::zeros(), VecQ::<M>::zeros(), VecQ::<M>::zeros(), VecQ::<M>::zeros());
    model.dl_dv(t0, q, v, &mut lv0);
    model.dl_dv(t1, &q1, v, &mut lv1);
    model.dl_dq(t1, &q1, v, &mut lq1);
    model.force(tm, &qm, v, &mut f);
    s.work.work += h * f.dot(v);
    let target = (lv0 + lv1) * 0.5 + (lq1 + f) * (0.5 * h);
    let mut a1 = MatCQ::<M>::zeros();
    model.constraint_matrix(&q1, &mut a1);
    s.state.v.copy_from(&s.work.v);
    let mut r = VecK::<M>::zeros();
    for _ in 0..s.options.max_iterations {
        let w = &s.state.v;
        let mut lv = VecQ::<M>::zeros();
        model.dl_dv(t1, &q1, w, &mut lv);
        let momentum = &lv - a1.transpose() * &s.work.gamma - &target;
        r.rows_mut(0, n).copy_from(&momentum);
        r.rows_mut(n, m).copy_from(&(&a1 * w));
        let mut lvv = MatQQ::<M>::zeros();
        model.l_vv(t1, &q1, w, &mut lvv);
        let jac = s.work.lu.matrix_mut();
        jac.fill(0.0);
        jac.view_mut((0, 0), (n, n)).copy_from(&lvv);
        jac.view_mut((0, n), (n, m)).copy_from(&(-a1.transpose()));
        jac.view_mut((n, 0), (m, n)).copy_from(&a1);
        if newton_update(s, &mut r, Stage::Two)? {
            model.dl_dv(t1, &q1, &s.state.v, &mut s.state.p);
            return Ok(());
        }
    }
    Err(s.diverged())
}

/// Factors the stage matrix in `work.lu`, applies the Newton update to the stage's unknowns
/// and says whether the iteration has converged.
fn newton_update<M: LagrangeDirac>(
    s: &mut Step<'_, M>,
    r: &mut VecK<M>,
    stage: Stage,
) -> Result<bool, SimError>
where
    DefaultAllocator: Storage<M>,
{
    let n = M::NQ;
    s.stats.factorizations += 1;
    if let Err(singular) = s.work.lu.factor() {
        return Err(s.singular(singular.column));
    }
    s.work.lu.solve(r);
    s.stats.newton_iterations += 1;
    let (x, mult) = match stage {
        Stage::One => (&mut s.work.v, &mut s.work.big_lambda),
        Stage::Two => (&mut s.state.v, &mut s.work.gamma),
    };
    let tolerance = s.options.tolerance;
    let mut converged = true;
    for i in 0..n {
        x[i] -= r[i];
        converged &= r[i].abs() <= tolerance * (1.0 + x[i].abs());
    }
    for j in 0..M::NC {
        mult[j] -= r[n + j];
        converged &= r[n + j].abs() <= tolerance * (1.0 + mult[j].abs());
    }
    if !r.iter().all(|x| x.is_finite()) {
        return Err(SimError::NonFinite {
            t: s.t,
            component: "a Newton update of the variational step".into(),
        });
    }
    Ok(converged)
}
