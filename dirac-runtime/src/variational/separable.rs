//! The separable path of a variational step, for `L = ½ vᵀ M v − V(q, t)` with a constant,
//! nonsingular mass matrix and no forces: `M v = p_k + (h/2) ∂L/∂q(q_k) + A(q_k)ᵀ Λ`, so with
//! `M` factored once, stage 1 is Newton on `Λ` alone (SHAKE) and stage 2 a linear system in
//! `Γ` (RATTLE's velocity projection), both `m × m`.

use nalgebra::DefaultAllocator;

use super::general::{stage_one_constraint_jacobian, stage_one_constraints};
use super::work::Step;
use crate::dims::{Dimensions, MatCQ, MatQQ, Storage, VecQ};
use crate::error::SimError;
use crate::lu::Lu;
use crate::model::LagrangeDirac;

/// A constant, nonsingular mass matrix, ready to solve with: its inverse diagonal when it is
/// diagonal (point masses), its LU factors otherwise.
pub(crate) enum Mass<M: Dimensions>
where
    DefaultAllocator: Storage<M>,
{
    Diagonal(VecQ<M>),
    Dense(Lu<f64, M::Nq>),
}

impl<M: Dimensions> Mass<M>
where
    DefaultAllocator: Storage<M>,
{
    /// The mass matrix `matrix` ready to solve with, if it is nonsingular.
    pub fn new(matrix: &MatQQ<M>) -> Option<Self> {
        let n = M::NQ;
        let diagonal = (0..n).all(|i| (0..n).all(|j| i == j || matrix[(i, j)] == 0.0));
        if diagonal {
            let d = matrix.diagonal();
            return d.iter().all(|x| *x != 0.0 && x.is_finite()).then(|| Mass::Diagonal(d.map(|x| 1.0 / x)));
        }
        let mut lu = Lu::<f64, M::Nq>::new();
        lu.matrix_mut().copy_from(matrix);
        lu.factor().ok().map(|()| Mass::Dense(lu))
    }

    /// `x ← M⁻¹ x`.
    fn solve(&self, x: &mut VecQ<M>) {
        match self {
            Mass::Diagonal(inverse) => x.component_mul_assign(inverse),
            Mass::Dense(lu) => lu.solve(x),
        }
    }

    /// `M⁻¹ Aᵀ` for constraint rows `a`.
    fn solve_transpose(&self, a: &MatCQ<M>) -> nalgebra::OMatrix<f64, M::Nq, M::Nc> {
        let mut b = a.transpose();
        for j in 0..M::NC {
            let mut column = b.column(j).into_owned();
            self.solve(&mut column);
            b.set_column(j, &column);
        }
        b
    }
}

/// Both stages on the separable path.
pub(crate) fn separable_step<M: LagrangeDirac>(s: &mut Step<'_, M>, mass: &Mass<M>) -> Result<(), SimError>
where
    DefaultAllocator: Storage<M>,
{
    let (m, h) = (M::NC, s.h);
    let t1 = s.t + h;
    let mut v_free = &s.state.p + &s.work.dl_dq * (0.5 * h);
    mass.solve(&mut v_free);
    if m == 0 {
        s.work.v.copy_from(&v_free);
    } else {
        shake(s, mass, &v_free)?;
    }
    let q1 = &s.state.q + &s.work.v * h;
    let mut dl_dq1 = VecQ::<M>::zeros();
    s.model.dl_dq(t1, &q1, &s.work.v, &mut dl_dq1);
    // M v = p_k + (h/2) g_k + A_kᵀ Λ, so P(v) + (h/2) g_{k+1} needs no product with M.
    let target =
        &s.state.p + (&s.work.dl_dq + &dl_dq1) * (0.5 * h) + s.work.a0.transpose() * &s.work.big_lambda;
    let mut w = target.clone();
    mass.solve(&mut w);
    if m == 0 {
        s.state.v.copy_from(&w);
        s.state.p.copy_from(&target);
    } else {
        let mut a1 = MatCQ::<M>::zeros();
        s.model.constraint_matrix(&q1, &mut a1);
        let d = mass.solve_transpose(&a1);
        s.work.small.matrix_mut().copy_from(&(&a1 * &d));
        factor_small(s)?;
        let mut gamma = -(&a1 * &w);
        s.work.small.solve(&mut gamma);
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
    let h = s.h;
    let b = mass.solve_transpose(&s.work.a0);
    s.work.last_update = f64::INFINITY;
    for _ in 0..s.options.max_iterations {
        s.work.v.copy_from(&(v_free + &b * &s.work.big_lambda));
        let q1 = &s.state.q + &s.work.v * h;
        let qm = &s.state.q + &s.work.v * (0.5 * h);
        let mut r = stage_one_constraints(s.model, h, &q1, &qm, &s.work.v);
        let c = stage_one_constraint_jacobian(s.model, &q1, &qm, &s.work.v, h);
        s.work.small.matrix_mut().copy_from(&(c * &b));
        factor_small(s)?;
        s.work.small.solve(&mut r);
        s.work.big_lambda -= &r;
        s.stats.newton_iterations += 1;
        // Converged when the velocities stop moving: with a small mass a tiny impulse moves
        // them far, so the impulse's own update says nothing.
        let size = (&b * &r).amax();
        let scale = 1.0 + s.work.v.amax();
        let tolerance = s.options.tolerance;
        let stalled = size >= 0.5 * s.work.last_update && size <= 1e3 * tolerance * scale;
        s.work.last_update = size;
        if size <= tolerance * scale || stalled {
            s.work.v.copy_from(&(v_free + &b * &s.work.big_lambda));
            return Ok(());
        }
    }
    Err(s.diverged())
}

fn factor_small<M: LagrangeDirac>(s: &mut Step<'_, M>) -> Result<(), SimError>
where
    DefaultAllocator: Storage<M>,
{
    s.stats.factorizations += 1;
    s.work.small.factor().map_err(|e| SimError::SingularMatrix {
        t: s.t,
        h: s.h,
        detail: format!("the constraint `{}` is dependent on the others", M::constraint_names()[e.column]),
    })
}
